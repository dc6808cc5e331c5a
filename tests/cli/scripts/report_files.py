#!/usr/bin/env python3
"""The relazione's files (issue 28, items 7, 9 and 10; issue 36, items 1 and 6).

usage: report_files.py ASSESS OUT_DIR CASE.json [MAX_BODY_PAGES]

Writes the case's relazione as HTML, PDF and Word in one run — the body and,
beside each file, its tabulati di calcolo (NAME-tabulati.EXT) — and checks for
each of the two documents:
  - PDF: A4; bookmarks (an outline with the numbered sections); the contents
    (sommario) with the page of each section equal to the page the PDF's
    bookmark gives; every table cell's text of the HTML appears in the PDF's
    text (nothing lost at the margin: the page is not shrunk, cells wrap);
  - Word (written by the library itself, issue 36 item 7; read back with
    python-docx): Word headings with the numbered
    sections (Premessa, Conclusioni), tables as tables (as many as the HTML's),
    the figures embedded as pictures, the verdict sentence of the conclusion;
    and, on the file's own XML (issue 36, item 6), the page as the PDF's: A4,
    margins 16/15/18/15 mm, a footer with the PAGE and NUMPAGES fields ("pag.
    x di y"), every verdict word and D/C in the green or red character style
    (the Word colours of the PDF's), a caption for every captioned table;
  - the body at most MAX_BODY_PAGES pages (issue 36, item 1), the tabulati
    numbered "T1", "T2" ...
Exit 0 when all hold, 77 (skipped) without chromium, pdftotext or python-docx.
"""
import html
import collections
import html.parser
import os
import re
import shutil
import subprocess
import sys

ASSESS, OUT, CASE = sys.argv[1:4]
for tool in ("chromium", "pdftotext", "pdfinfo", "pdftohtml"):
    if not shutil.which(tool):
        print(f"{tool} not found: skipped")
        sys.exit(77)
try:
    import docx  # python3-docx
except ImportError:
    print("python3-docx not found: skipped")
    sys.exit(77)

MAX_BODY = int(sys.argv[4]) if len(sys.argv) > 4 else 0
os.makedirs(OUT, exist_ok=True)
stem = os.path.join(OUT, os.path.splitext(os.path.basename(CASE))[0])
run = subprocess.run([ASSESS, "run", CASE, "--html", stem + ".html", "--pdf", stem + ".pdf", "--docx", stem + ".docx"],
                     capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"assess run failed ({run.returncode}): {run.stderr[:500]}")
errors = []


class Cells(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.cells, self.cur, self.tables, self.toc, self.in_toc, self.li = [], None, 0, [], False, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table":
            self.tables += 1
        if tag in ("td", "th"):
            self.cur = ""
        if tag == "span" and self.cur is not None:
            self.cur += " "  # a note: its own line
        if tag == "nav":
            self.in_toc = True
        if tag == "li" and self.in_toc:
            self.li = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cur is not None:
            self.cells.append(self.cur)
            self.cur = None
        if tag == "nav":
            self.in_toc = False
        if tag == "li" and self.li is not None:
            self.toc.append(self.li)
            self.li = None

    def handle_data(self, data):
        if self.cur is not None:
            self.cur += data
        if self.li is not None:
            self.li += data


def check(h, p, w, tabulati):
    first_error = len(errors)
    page = open(h, encoding="utf-8").read()
    cells = Cells()
    cells.feed(page)
    
    # PDF: A4, bookmarks, text of every cell, contents' pages.
    info = subprocess.run(["pdfinfo", p], capture_output=True, text=True).stdout
    if "(A4)" not in info:
        errors.append("the PDF is not A4")
    pages = int(re.search(r"Pages:\s+(\d+)", info).group(1))
    text = subprocess.run(["pdftotext", p, "-"], capture_output=True, text=True).stdout
    # pdftotext joins a word broken at a hyphen at the end of a line without the hyphen: compare without hyphens.
    squeezed = re.sub(r"[\s-]+", "", text)
    # Every word of every cell (a wrapped cell's lines may interleave with its neighbours' in the extracted text).
    lost = []
    for c in cells.cells:
        for word in c.split():
            # A word may break at a hyphen, its pieces on two lines (a date in a wrapped cell).
            for piece in word.split("-"):
                # A narrow cell may also break a word inside (Chromium's overflow-wrap), the
                # neighbouring column's text between its two parts: accept two parts found.
                broken = any(piece[:k] in squeezed and piece[k:] in squeezed for k in range(2, len(piece) - 1))
                if piece and piece not in squeezed and not broken and word not in lost:
                    lost.append(word)
    if lost:
        errors.append(f"{len(lost)} words of table cells not found in the PDF's text, e.g. {lost[:5]!r}")
    xml = subprocess.run(["pdftohtml", "-xml", "-i", "-q", "-stdout", p], capture_output=True, text=True).stdout
    outline = [(int(m.group(1)), html.unescape(m.group(2))) for m in re.finditer(r'<item page="(\d+)">(.*?)</item>', xml)]
    # One bookmark per heading of the HTML (h2-h6; the h1 is the title), in the same order
    # (report/pdf_bookmarks.cpp writes them from the headings' named destinations).
    headings = [re.sub(r"<[^>]+>", "", m) for m in re.findall(r"<h[2-6](?! class=\"toc-heading\")[^>]*>(.*?)</h[2-6]>", page, flags=re.S)]
    if len(outline) != len(headings):
        errors.append(f"the PDF has {len(outline)} bookmarks, the HTML {len(headings)} headings")
    elif [re.sub(r"\s+", "", html.unescape(h)) for h in headings] != [re.sub(r"\s+", "", t) for _, t in outline]:
        errors.append("the PDF's bookmarks are not the HTML's headings in order")
    pages_of = {re.sub(r"\s+", "", t): n for n, t in outline}
    checked = 0
    for entry in cells.toc:
        m = re.match(r"\s*(\S+)\s+(.*?)\s*(\d+)\s*$", entry)
        if not m:
            errors.append(f"contents entry without a page: {entry!r}")
            continue
        key = re.sub(r"\s+", "", m.group(1) + m.group(2))
        if key in pages_of:
            checked += 1
            if pages_of[key] != int(m.group(3)):
                errors.append(f"contents: '{m.group(1)} {m.group(2)}' on page {m.group(3)}, the bookmark says {pages_of[key]}")
    if checked < 8:
        errors.append(f"only {checked} contents entries matched a bookmark")
    if len(re.findall(r"^(?:pag\. \d+ di|page \d+ of) " + str(pages) + "$", text, flags=re.M)) != pages:
        errors.append("not every page carries 'pag. x di y'")
    # Printed at its type size, never shrunk to fit (issue 28, item 9): Chromium scales every page
    # down when one element is wider than the page. The commonest height of a word's box is that of
    # the 8.5 pt table text (about 10 pt) or of the 10.5 pt body (about 12 pt); a page shrunk to 75 %
    # gives 7.5 pt. Tolerance: 9.0 pt (pdftotext -bbox, word boxes rounded to 0.5 pt).
    bbox = subprocess.run(["pdftotext", "-bbox", p, "-"], capture_output=True, text=True).stdout
    heights = collections.Counter(round((float(b) - float(a)) * 2) / 2 for a, b in
                                  re.findall(r'yMin="([\d.]+)" xMax="[\d.]+" yMax="([\d.]+)"', bbox))
    commonest = heights.most_common(1)[0][0] if heights else 0.0
    if commonest < 9.0:
        errors.append(f"the PDF is shrunk to fit: the commonest word height is {commonest} pt (expected about 10 pt)")
    # The contents' page numbers are printed (laid over the first print, report_files.cpp): each page
    # number of the HTML contents appears as a word on the PDF's first pages.
    front = subprocess.run(["pdftotext", "-f", "1", "-l", "4", p, "-"], capture_output=True, text=True).stdout
    tokens = set(front.split())
    missing = sorted({m.group(1) for e in cells.toc for m in [re.search(r"(\d+)\s*$", e)] if m} - tokens, key=int)
    if missing:
        errors.append(f"contents' page numbers not printed on the first pages: {missing[:10]}")
    # ... and on their rows: every number in the right-hand column of the first pages (x > 500 pt,
    # above the footer) shares its baseline with a word on the left (its entry's title). Laid over a
    # print that Chromium had shrunk to fit, the numbers fell between the lines (report_files.cpp
    # numbers_on_rows). Tolerance 0.5 pt.
    front_bbox = subprocess.run(["pdftotext", "-bbox", "-f", "1", "-l", "4", p, "-"], capture_output=True, text=True).stdout
    for k, pg in enumerate(front_bbox.split("<page ")[1:], start=1):
        words = [(float(a), float(c), float(d), t) for a, c, d, t in
                 re.findall(r'<word xMin="([\d.]+)" yMin="[\d.]+" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)</word>', pg)]
        for x0, x1, y, t in words:
            if t.isdigit() and x0 > 500 and y < 800 and not any(abs(y2 - y) < 0.5 and x2 < 450 for _, x2, y2, _ in words):
                errors.append(f"page {k}: the number {t} at x = {x0:.1f} pt, y = {y:.1f} pt lies on no row of the contents")
                break
    
    # Word: headings, tables, pictures, the verdict.
    d = docx.Document(w)
    heads = [par.text for par in d.paragraphs if par.style.name.startswith("Heading")]
    if not tabulati:
        if not any("Premessa" in t or "Introduction" in t for t in heads):
            errors.append(f"Word: no heading 'Premessa' among {heads[:8]}")
        if not any("Conclusioni" in t or "Conclusions" in t for t in heads):
            errors.append("Word: no heading 'Conclusioni'")
        body = "\n".join(par.text for par in d.paragraphs)
        if not re.search(r"(VERIFICATO|NON VERIFICATO|SATISFIED|NOT SATISFIED)", body):
            errors.append("Word: no verdict in the text")
    if not any(re.match(r"T\d+ " if tabulati else r"\d+ ", t) for t in heads):
        errors.append(f"Word: headings are not numbered ({'T1, T2' if tabulati else '1, 2'} ...)")
    if len(d.tables) != cells.tables:
        errors.append(f"Word: {len(d.tables)} tables, the HTML has {cells.tables}")
    figures = len(re.findall(r"<figure", page))
    pictures = len(d.inline_shapes)
    if pictures < figures:
        errors.append(f"Word: {pictures} pictures, the HTML has {figures} figures")
    # The page as the PDF's (issue 36, item 6), read on the file's own XML.
    sect = d.sections[-1]._sectPr
    ns = {"w": "http://schemas.openxmlformats.org/wordprocessingml/2006/main"}
    size = sect.find("w:pgSz", ns)
    mar = sect.find("w:pgMar", ns)
    q = "{%s}" % ns["w"]
    if size is None or (size.get(q + "w"), size.get(q + "h")) != ("11906", "16838"):
        errors.append("Word: the page is not A4 (w:pgSz 11906 x 16838 twips)")
    twips = lambda mm: round(mm * 1440 / 25.4)
    want = {"top": twips(16), "right": twips(15), "bottom": twips(18), "left": twips(15)}
    if mar is None or any(abs(int(mar.get(q + k, "0")) - v) > 1 for k, v in want.items()):
        errors.append(f"Word: margins are not the PDF's 16/15/18/15 mm ({dict(mar.attrib) if mar is not None else None})")
    footer = d.sections[-1].footer._element.xml
    if "PAGE" not in footer or "NUMPAGES" not in footer:
        errors.append("Word: no page number (PAGE of NUMPAGES) in the footer")
    if not re.search(r"pag\.|page", footer):
        errors.append("Word: the footer does not read 'pag. x di y'")
    # Every verdict word and every D/C coloured as in the PDF: the HTML's coloured text in the Word's styled runs.
    coloured = {"ok": set(), "fail": set()}
    for m in re.finditer(r'class="(?:[^"]* )?(dc-ok|dc-fail|ok|fail)(?: [^"]*)?">(?:<[^>]+>)*([^<]+)<', page.replace("<wbr>", "")):
        coloured["ok" if m.group(1) in ("ok", "dc-ok") else "fail"].add(html.unescape(m.group(2)).strip())
    styled = {"ok": set(), "fail": set()}
    xml = d.element.xml
    for m in re.finditer(r'<w:rStyle w:val="Verdetto(OK|KO)"/>.*?<w:t[^>]*>([^<]*)</w:t>', xml, re.S):
        styled["ok" if m.group(1) == "OK" else "fail"].add(html.unescape(m.group(2)).strip())
    for tone in ("ok", "fail"):
        missing = sorted(t for t in coloured[tone] if t and t not in styled[tone])
        if missing:
            errors.append(f"Word: {len(missing)} {'green' if tone == 'ok' else 'red'} texts of the HTML without the Word colour, e.g. {missing[:4]}")
    captions = len(re.findall(r"<caption>", page))
    table_captions = len(re.findall(r'<w:pStyle w:val="TableCaption"/>', xml))
    if table_captions < captions:
        errors.append(f"Word: {table_captions} table captions, the HTML has {captions}")
    print(f"{'tabulati' if tabulati else 'relazione'}: {pages} pages, {len(outline)} bookmarks, {checked} contents "
          f"entries on their pages, {len(cells.cells)} cells in the PDF's text, Word: {len(heads)} headings, "
          f"{len(d.tables)} tables, {pictures} pictures, {table_captions} table captions, "
          f"{len(styled['ok'])}/{len(styled['fail'])} green/red texts")
    for i in range(first_error, len(errors)):
        errors[i] = f"{os.path.basename(p)}: {errors[i]}"
    return pages


pages_body = check(stem + ".html", stem + ".pdf", stem + ".docx", False)
pages_tab = check(stem + "-tabulati.html", stem + "-tabulati.pdf", stem + "-tabulati.docx", True)
if MAX_BODY and pages_body > MAX_BODY:
    errors.append(f"the body has {pages_body} pages, at most {MAX_BODY} expected")
for e in errors:
    print(e)
print(f"{CASE}: relazione {pages_body} pages, tabulati {pages_tab} pages")
sys.exit(1 if errors else 0)
