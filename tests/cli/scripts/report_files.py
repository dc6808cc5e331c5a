#!/usr/bin/env python3
"""The relazione's files (issue 28, items 7, 9 and 10).

usage: report_files.py ASSESS OUT_DIR CASE.json

Writes the case's relazione as HTML, PDF and Word in one run and checks:
  - PDF: A4; bookmarks (an outline with the numbered sections); the contents
    (sommario) with the page of each section equal to the page the PDF's
    bookmark gives; every table cell's text of the HTML appears in the PDF's
    text (nothing lost at the margin: the page is not shrunk, cells wrap);
  - Word (read back with python-docx): Word headings with the numbered
    sections (Premessa, Conclusioni), tables as tables (as many as the HTML's),
    the figures embedded as pictures, the verdict sentence of the conclusion.
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
for tool in ("chromium", "pdftotext", "pdfinfo", "pdftohtml", "pandoc"):
    if not shutil.which(tool):
        print(f"{tool} not found: skipped")
        sys.exit(77)
try:
    import docx  # python3-docx
except ImportError:
    print("python3-docx not found: skipped")
    sys.exit(77)

os.makedirs(OUT, exist_ok=True)
stem = os.path.join(OUT, os.path.splitext(os.path.basename(CASE))[0])
h, p, w = stem + ".html", stem + ".pdf", stem + ".docx"
run = subprocess.run([ASSESS, "run", CASE, "--html", h, "--pdf", p, "--docx", w], capture_output=True, text=True)
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
            if piece and piece not in squeezed and word not in lost:
                lost.append(word)
if lost:
    errors.append(f"{len(lost)} words of table cells not found in the PDF's text, e.g. {lost[:5]!r}")
xml = subprocess.run(["pdftohtml", "-xml", "-i", "-q", "-stdout", p], capture_output=True, text=True).stdout
outline = [(int(m.group(1)), html.unescape(m.group(2))) for m in re.finditer(r'<item page="(\d+)">(.*?)</item>', xml)]
if len(outline) < 10:
    errors.append(f"the PDF has {len(outline)} bookmarks, expected the sections")
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

# Word: headings, tables, pictures, the verdict.
d = docx.Document(w)
heads = [par.text for par in d.paragraphs if par.style.name.startswith("Heading")]
if not any("Premessa" in t or "Introduction" in t for t in heads):
    errors.append(f"Word: no heading 'Premessa' among {heads[:8]}")
if not any("Conclusioni" in t or "Conclusions" in t for t in heads):
    errors.append("Word: no heading 'Conclusioni'")
if not any(re.match(r"\d+ ", t) for t in heads):
    errors.append("Word: headings are not numbered")
if len(d.tables) != cells.tables:
    errors.append(f"Word: {len(d.tables)} tables, the HTML has {cells.tables}")
figures = len(re.findall(r"<figure", page))
pictures = len(d.inline_shapes)
if pictures < figures:
    errors.append(f"Word: {pictures} pictures, the HTML has {figures} figures")
body = "\n".join(par.text for par in d.paragraphs)
if not re.search(r"(VERIFICATO|NON VERIFICATO|SATISFIED|NOT SATISFIED)", body):
    errors.append("Word: no verdict in the text")

for e in errors:
    print(e)
print(f"{CASE}: {pages} pages, {len(outline)} bookmarks, {checked} contents entries on their pages, "
      f"{len(cells.cells)} cells in the PDF's text, Word: {len(heads)} headings, {len(d.tables)} tables, {pictures} pictures")
sys.exit(1 if errors else 0)
