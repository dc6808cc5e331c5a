#!/usr/bin/env python3
"""No value is printed for a quantity that was not computed (issue 36, item 5).

usage: not_computed.py ASSESS OUT_DIR CASE.json...

Writes each case's relazione as HTML (the body and its tabulati) and checks
every table of both: in a column of a result (D/C, ζE, PGA_C, TR_C, α0, a0*,
d0*, d_SLV, d_SLC, T_SLV, T_SLC, Ts, du*), a cell that reads zero ("0,000")
must say why in its own note (a wall that never lifted has a computed zero
displacement: "nessun sollevamento"); a quantity that was not computed is
printed "—", never as a number. The placeholders of a result object (a D/C of
0.000 where no analysis was run: the house's summary once printed one) are
what this catches. Exit 0 when all hold.
"""
import html.parser
import os
import re
import subprocess
import sys

ASSESS, OUT = sys.argv[1:3]
CASES = sys.argv[3:]
os.makedirs(OUT, exist_ok=True)
RESULT = re.compile(r"^(D/C|ζE|PGA_C|TR_C|α0|a0\*|d0\*|d_SLV|d_SLC|T_SLV|T_SLC|Ts|du\*)\b")
ZERO = re.compile(r"^[★\s]*0(?:,0+)?$")
errors = []


class Tables(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.tables, self.cell, self.in_note, self.caption = [], None, False, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table":
            self.tables.append({"head": [], "rows": [], "caption": ""})
        elif tag == "caption" and self.tables:
            self.caption = ""
        elif tag == "tr" and self.tables:
            self.tables[-1]["rows"].append([])
        elif tag in ("td", "th") and self.tables:
            self.cell = {"tag": tag, "text": "", "note": ""}
        elif tag == "span" and self.cell is not None and "note" in a.get("class", ""):
            self.in_note = True

    def handle_endtag(self, tag):
        if tag == "span" and self.in_note:
            self.in_note = False
        elif tag == "caption" and self.caption is not None:
            self.tables[-1]["caption"] = self.caption
            self.caption = None
        elif tag in ("td", "th") and self.cell is not None:
            t = self.tables[-1]
            (t["head"] if self.cell["tag"] == "th" else t["rows"][-1]).append(self.cell)
            self.cell = None

    def handle_data(self, data):
        if self.caption is not None:
            self.caption += data
        if self.cell is not None:
            self.cell["note" if self.in_note else "text"] += data


checked = 0
for case in CASES:
    stem = os.path.join(OUT, os.path.splitext(os.path.basename(case))[0])
    run = subprocess.run([ASSESS, "run", case, "--html", stem + ".html"], capture_output=True, text=True)
    if run.returncode != 0:
        errors.append(f"{case}: assess run failed ({run.returncode}): {run.stderr[:300]}")
        continue
    for f in (stem + ".html", stem + "-tabulati.html"):
        p = Tables()
        with open(f, encoding="utf-8") as h:
            p.feed(h.read())
        for t in p.tables:
            cols = [i for i, c in enumerate(t["head"]) if RESULT.match(c["text"].strip())]
            for row in t["rows"]:
                for i in cols:
                    if i >= len(row):
                        continue
                    checked += 1
                    c = row[i]
                    if ZERO.match(c["text"].strip()) and not c["note"].strip():
                        errors.append(f"{os.path.basename(f)}: '{t['head'][i]['text'].strip()}' reads "
                                      f"'{c['text'].strip()}' without a note, in '{t['caption'][:60]}' "
                                      f"(row '{row[0]['text'].strip()[:40]}')")
for e in errors:
    print(e)
print(f"{len(CASES)} cases, {checked} result cells, {len(errors)} zeros without a reason")
sys.exit(1 if errors else 0)
