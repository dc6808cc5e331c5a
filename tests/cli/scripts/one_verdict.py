#!/usr/bin/env python3
"""One verdict everywhere (issue 28, item 1).

usage: one_verdict.py ASSESS OUT_DIR CASE.json [CASE.json ...]

For every case (single façade cases and building cases) runs `assess run CASE
--json` and `assess run CASE --html`, and checks that
  - JSON: no object pairs a D/C with a verdict that contradicts it: "dc" with
    "satisfied", "max_dc" with "satisfied", "dc_slv" with "slv_satisfied";
    D/C <= 1 with false, D/C > 1 with true, null D/C (a collapse, +inf) with
    true are all defects (an object that says it has no verdict is exempt);
  - HTML: every D/C cell is green only with a number <= 1 and red only with a
    number > 1 or "∞", and the outcome in the same row agrees with its colour;
  - HTML: each method box of the verdict box counts exactly the rows of the
    checks tables ("checks" tables of the body and of the tabulati di calcolo) of that code
    and method, and its failing count the red rows among them;
  - building JSON: each approach's counts equal its mechanisms' verdicts.
Exit 0 when every case passes, 1 otherwise (every defect printed).
"""
import html.parser
import json
import os
import re
import subprocess
import sys

ASSESS, OUT = sys.argv[1], sys.argv[2]
CASES = sys.argv[3:]
os.makedirs(OUT, exist_ok=True)
defects = []


def number(text):
    t = text.strip().replace("★", "").strip()
    if t == "∞":
        return float("inf")
    try:
        return float(t.replace(",", "."))
    except ValueError:
        return None


def walk(x, path, case):
    if isinstance(x, dict):
        for dc_key, ok_key in (("dc", "satisfied"), ("max_dc", "satisfied"), ("dc_slv", "slv_satisfied")):
            if dc_key in x and ok_key in x and isinstance(x[ok_key], bool) and x.get("no_verdict") is not True:
                dc, ok = x[dc_key], x[ok_key]
                if isinstance(dc, (int, float)) and ((dc < 1 and not ok and dc <= 1) or (dc > 1 and ok)):
                    if not (dc <= 1 and not ok and x.get("no_verdict", 0)):
                        defects.append(f"{case}: JSON {path}: {dc_key} {dc:.4f} with {ok_key} {ok}")
                if dc is None and ok:
                    defects.append(f"{case}: JSON {path}: {dc_key} null (collapse) with {ok_key} true")
        for k, v in x.items():
            walk(v, path + "/" + k, case)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            walk(v, f"{path}[{i}]", case)


class Tables(html.parser.HTMLParser):
    """Rows of every table (cells with their classes and text), and the verdict boxes' method lines."""

    def __init__(self):
        super().__init__()
        self.tables, self.stack, self.cell, self.methods = [], [], None, []
        self.method = None

    owner = ""  # the mechanism of a building whose section holds the element ("" for a single case)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        m = re.match(r"(M\d+)(?:-|$)", a.get("id", "")) if re.match(r"h[2-6]$", tag) else None
        if m:
            self.owner = m.group(1)
        elif re.match(r"h2$", tag) and "id" in a:
            self.owner = ""
        if tag == "table":
            self.tables.append({"class": a.get("class", ""), "rows": [], "owner": self.owner})
            self.stack.append(self.tables[-1])
        elif tag == "tr" and self.stack:
            self.stack[-1]["rows"].append([])
        elif tag in ("td", "th") and self.stack:
            self.cell = {"class": a.get("class", ""), "text": "", "tag": tag}
        elif tag == "span" and self.cell is not None and "note" in a.get("class", ""):
            self.cell["in_note"] = True
        elif tag == "div" and "method" in a.get("class", "").split() and "data-method" in a:
            self.method = {"method": a["data-method"], "class": a.get("class", ""), "text": "", "code": self.code,
                           "owner": self.owner}
            self.methods.append(self.method)
        elif tag == "div" and "verdict" in a.get("class", "").split() and "data-code" in a:
            self.code = a["data-code"]

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None and self.stack and self.stack[-1]["rows"]:
            self.stack[-1]["rows"][-1].append(self.cell)
            self.cell = None
        elif tag == "table" and self.stack:
            self.stack.pop()
        elif tag == "div" and self.method is not None and self.method["text"]:
            self.method = None

    def handle_data(self, data):
        if self.cell is not None and not self.cell.get("in_note"):
            self.cell["text"] += data
        if self.method is not None:
            self.method["text"] += data

    code = ""


KIND_OF = {"lineare (resistenza)": "linear", "non lineare (spostamento)": "nonlinear", "dinamica non lineare": "dynamic",
           "linear (strength)": "linear", "non-linear (displacement)": "nonlinear", "non-linear dynamic": "dynamic"}


def check_html(case, path):
    p = Tables()
    p.feed(open(path, encoding="utf-8").read())
    # Issue 36: the other candidates' checks are in the tabulati di calcolo beside the relazione.
    p.owner = ""
    p.feed(open(path[:-len(".html")] + "-tabulati.html", encoding="utf-8").read())
    counts = {}
    for t in p.tables:
        for row in t["rows"]:
            dc_cells = [c for c in row if "dc-ok" in c["class"] or "dc-fail" in c["class"]]
            for c in dc_cells:
                v = number(c["text"])
                if v is None:
                    defects.append(f"{case}: HTML D/C cell '{c['text']}' is not a number")
                    continue
                if "dc-ok" in c["class"] and not v <= 1:
                    defects.append(f"{case}: HTML green D/C {c['text']}")
                if "dc-fail" in c["class"] and v <= 1:
                    defects.append(f"{case}: HTML red D/C {c['text']} <= 1")
            outcome = [c for c in row if c["tag"] == "td" and (c["class"] in ("ok", "fail"))]
            # A row with one D/C and one outcome: the outcome is that check's (the building's summary rows
            # carry a D/C per approach and the adopted method's outcome: columns of their own).
            for c in dc_cells if len(dc_cells) == 1 else []:
                for o in outcome[-1:]:
                    if ("dc-ok" in c["class"]) != (o["class"] == "ok"):
                        defects.append(f"{case}: HTML D/C {c['text']} ({c['class']}) beside outcome '{o['text']}' ({o['class']})")
            if "checks" in t["class"].split() and row and row[0]["tag"] == "td":
                code = row[0]["text"].replace(" ", "")
                name = row[1]["text"]
                kind = next((v for k, v in KIND_OF.items() if k in name), None)
                # "non lineare (spostamento)" contains "lineare (resistenza)"? no; but check the longest first.
                for k in sorted(KIND_OF, key=len, reverse=True):
                    if k in name:
                        kind = KIND_OF[k]
                        break
                failing = any("dc-fail" in c["class"] for c in row)
                key = (t["owner"], code, kind)
                n, f = counts.get(key, (0, 0))
                counts[key] = (n + 1, f + (1 if failing else 0))
    for m in p.methods:
        nums = re.findall(r"(?:verifiche|checks): (\d+), (?:non soddisfatte|not satisfied): (\d+)", m["text"])
        if not nums:
            continue
        n, f = int(nums[0][0]), int(nums[0][1])
        rows = counts.get((m["owner"], m["code"], m["method"]), (0, 0))
        if (n, f) != rows:
            defects.append(f"{case}: HTML verdict box {m['owner']} {m['code']} {m['method']}: counts {n}/{f} but the tables show {rows[0]}/{rows[1]}")


for case in CASES:
    stem = os.path.splitext(os.path.basename(case))[0]
    run = subprocess.run([ASSESS, "run", case, "--json"], capture_output=True, text=True)
    if run.returncode != 0 and "/site: missing" in run.stderr:
        continue  # a mechanism without a site: `assess kinematic`'s, no verdict to give
    if run.returncode != 0:
        defects.append(f"{case}: exit {run.returncode}: {run.stderr.strip()[:300]}")
        continue
    doc = json.loads(run.stdout)
    walk(doc, "", case)
    if "mechanisms" in doc:  # a building: the approach counts are the mechanisms' verdicts
        for g in doc.get("governing", []):
            sat = fail = 0
            for m in doc["mechanisms"]:
                for s in m.get("safety_indices", []):
                    if s.get("code") == g["code"] and s.get("approach") == g["approach"] and s.get("checks", 0) > 0:
                        if s.get("satisfied") is True:
                            sat += 1
                        elif s.get("failing", 0) > 0:
                            fail += 1
            if (sat, fail) != (g.get("satisfied_count"), g.get("failing")):
                defects.append(f"{case}: building {g['code']} {g['approach']}: counts {g.get('satisfied')}/{g.get('failing')} "
                               f"but the mechanisms give {sat}/{fail}")
    out = os.path.join(OUT, stem + ".html")
    run = subprocess.run([ASSESS, "run", case, "--html", out], capture_output=True, text=True)
    if run.returncode != 0:
        defects.append(f"{case}: --html exit {run.returncode}: {run.stderr.strip()[:300]}")
        continue
    check_html(case, out)

for d in defects:
    print(d)
print(f"{len(CASES)} cases, {len(defects)} defects")
sys.exit(1 if defects else 0)
