#!/usr/bin/env python3
"""Every internal reference of the relazione resolves (issue 36, item 5).

usage: references.py ASSESS OUT_DIR CASE.json...

Writes each case's relazione as HTML (the body NAME.html and the tabulati
NAME-tabulati.html beside it) and checks, in both documents:
  - every link within a page (href="#x") names an id of that page;
  - every link into the other document (href="NAME-tabulati.html#x" and back)
    names an id of that document, and the section number its text cites
    ("§T3.2") is the number of the heading it links to;
  - every section number cited in the text ("§T3.2" in the body, "§4.1" in
    the tabulati), linked or not, is a heading of the document it names;
  - every reference written in words resolves: "in appendice" to a heading
    "Appendice ..." of the body or of the tabulati, "(Ipotesi e letture
    adottate)" to that heading, "si veda la sezione delle catene" to the tie
    rods' section, "sezione del meccanismo" to the mechanisms' sections,
    "tabulati" to a written tabulati file;
  - no reference is left unresolved ("{§}").
Exit 0 when all hold.
"""
import html
import html.parser
import os
import re
import subprocess
import sys

ASSESS, OUT = sys.argv[1:3]
CASES = sys.argv[3:]
os.makedirs(OUT, exist_ok=True)
errors = []


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.links, self.headings = set(), [], {}  # id -> (number, text)
        self.text = []
        self.link = None   # [href, text]
        self.head = None   # [id, number, text]
        self.secno = False
        self.skip = 0      # inside <style>, <svg>, <pre>

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in ("style", "svg", "pre", "title"):
            self.skip += 1
        if self.skip:
            return
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "a" and "href" in a:
            self.link = [a["href"], ""]
        if re.fullmatch(r"h[1-6]", tag) and "id" in a:
            self.head = [a["id"], "", ""]
        if tag == "span" and a.get("class") == "secno" and self.head is not None:
            self.secno = True

    def handle_endtag(self, tag):
        if tag in ("style", "svg", "pre", "title"):
            self.skip = max(0, self.skip - 1)
            return
        if self.skip:
            return
        if tag == "a" and self.link is not None:
            self.links.append(tuple(self.link))
            self.link = None
        if tag == "span" and self.secno:
            self.secno = False
        if re.fullmatch(r"h[1-6]", tag) and self.head is not None:
            self.headings[self.head[0]] = (self.head[1].strip(), self.head[2].strip())
            self.head = None

    def handle_data(self, data):
        if self.skip:
            return
        self.text.append(data)
        if self.link is not None:
            self.link[1] += data
        if self.head is not None:
            if self.secno:
                self.head[1] += data
            else:
                self.head[2] += data


def parse(path):
    p = Page()
    with open(path, encoding="utf-8") as f:
        p.feed(f.read())
    p.alltext = html.unescape(" ".join(p.text))
    return p


def check(case):
    stem = os.path.join(OUT, os.path.splitext(os.path.basename(case))[0])
    body_file, tab_file = stem + ".html", stem + "-tabulati.html"
    run = subprocess.run([ASSESS, "run", case, "--html", body_file], capture_output=True, text=True)
    if run.returncode != 0:
        errors.append(f"{case}: assess run failed ({run.returncode}): {run.stderr[:300]}")
        return 0
    if not os.path.exists(tab_file):
        errors.append(f"{case}: no tabulati beside the relazione ({tab_file})")
        return 0
    docs = {"body": parse(body_file), "tab": parse(tab_file)}
    files = {os.path.basename(body_file): "body", os.path.basename(tab_file): "tab"}
    numbers = {k: {n for n, _ in d.headings.values() if n} for k, d in docs.items()}
    checked = 0
    for name, d in docs.items():
        other = "tab" if name == "body" else "body"
        for href, text in d.links:
            checked += 1
            target_file, _, anchor = href.partition("#")
            target = name if target_file == "" else files.get(target_file)
            if target is None:
                errors.append(f"{case} ({name}): link to an unknown file '{href}'")
                continue
            if anchor not in docs[target].ids:
                errors.append(f"{case} ({name}): link '{href}' ('{text.strip()}') names no id of the {target}")
                continue
            # A section number, not a clause a heading's title cites ("NTC 2018 §2.4", "D.M. §10.2").
            cited = re.findall(r"§\s*(T?\d+(?:\.\d+)*)", re.sub(r"(NTC|D\.M\.|Circ\.) [^)]*", "", text))
            if cited and anchor in docs[target].headings and cited[0] != docs[target].headings[anchor][0]:
                errors.append(f"{case} ({name}): '{text.strip()}' cites §{cited[0]} but its target '#{anchor}' is "
                              f"§{docs[target].headings[anchor][0]}")
        if "{§}" in d.alltext:
            errors.append(f"{case} ({name}): an unresolved reference '{{§}}'")
        # Section numbers cited in the text: "§T3.2" names the tabulati, "§3.2" after "relazione" the body.
        for m in re.finditer(r"§\s*(T\d+(?:\.\d+)*)", d.alltext):
            checked += 1
            if m.group(1) not in numbers["tab"]:
                errors.append(f"{case} ({name}): §{m.group(1)} is no section of the tabulati")
        for m in re.finditer(r"(?:[Rr]elazione|[Rr]eport)[^§.]{0,40}§\s*(\d+(?:\.\d+)*)", d.alltext):
            checked += 1
            if m.group(1) not in numbers["body"]:
                errors.append(f"{case} ({name}): §{m.group(1)} is no section of the relazione")
        # References in words.
        heads = [t for dd in docs.values() for _, t in dd.headings.values()]
        rules = [
            (r"in appendice", lambda: any(t.startswith("Appendice") for t in heads), "a heading 'Appendice ...'"),
            (r"\(Ipotesi e letture adottate\)", lambda: any("letture adottate" in t for t in heads),
             "the heading of the readings adopted"),
            (r"sezione delle catene", lambda: any("atene" in t for t in heads), "the tie rods' section"),
            (r"sezione del meccanismo", lambda: any(re.match(r"M\d+ — ", t) for t in heads) or
             any(t.startswith("Meccanismo di collasso") for t in heads), "a mechanism's section"),
            (r"tabulati", lambda: os.path.exists(tab_file), "the tabulati file"),
        ]
        for pattern, holds, what in rules:
            if re.search(pattern, d.alltext):
                checked += 1
                if not holds():
                    errors.append(f"{case} ({name}): '{pattern}' but no {what}")
    return checked


total = 0
for case in CASES:
    total += check(case)
for e in errors:
    print(e)
print(f"{len(CASES)} cases, {total} references checked, {len(errors)} unresolved")
sys.exit(1 if errors else 0)
