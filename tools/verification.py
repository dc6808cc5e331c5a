#!/usr/bin/env python3
"""docs/verification.md from docs/verification.json (issue 36, item 2).

The project's verification record is one file, docs/verification.json: every
test with what it checks, its reference and its tolerance (the table of
docs/verification.md), and the reference comparisons the relazione's NTC 2018
§10.2 chapter cites, in Italian and English, each naming the tests it rests on.
The library embeds the JSON at build time (libassess/CMakeLists.txt) and the
chapter prints it; this script writes the Markdown page from it.

usage: verification.py [--check] [ROOT]
  writes ROOT/docs/verification.md (ROOT: the source tree, default the parent
  of this script's folder); --check compares instead and exits 1 when the page
  differs from the JSON, or when a comparison names a test the table lacks.
"""
import json
import os
import sys


def render(data):
    out = ["# " + data["title"], ""]
    out += data["intro"]
    out += ["", "| test | checks | reference | tolerance |", "|---|---|---|---|"]
    for t in data["tests"]:
        out.append(f"| {t['test']} | {t['checks']} | {t['reference']} | {t['tolerance']} |")
    out += ["", "## " + data["relazione_title"], ""]
    out += data["relazione_intro"]
    out += ["", "| area | compared | reference | tolerance | tests |", "|---|---|---|---|---|"]
    for c in data["relazione"]:
        en = c["en"]
        tests = ", ".join(f"`{t}`" for t in c["tests"])
        out.append(f"| {en['area']} | {en['compared']} | {en['reference']} | {en['tolerance']} | {tests} |")
    return "\n".join(out) + "\n"


def problems(data):
    names = " ".join(t["test"] for t in data["tests"])
    bad = []
    for c in data["relazione"]:
        for t in c["tests"]:
            if t not in names:
                bad.append(f"comparison '{c['en']['area']}' names the test '{t}', which the table lacks")
        for lang in ("it", "en"):
            for k in ("area", "compared", "reference", "tolerance"):
                if not c.get(lang, {}).get(k):
                    bad.append(f"comparison '{c['en'].get('area', '?')}' has no {lang} '{k}'")
    return bad


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = args[0] if args else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(root, "docs", "verification.json"), encoding="utf-8") as f:
        data = json.load(f)
    page = render(data)
    md = os.path.join(root, "docs", "verification.md")
    bad = problems(data)
    if "--check" in sys.argv:
        with open(md, encoding="utf-8") as f:
            if f.read() != page:
                bad.append("docs/verification.md differs from docs/verification.json: run tools/verification.py")
        for b in bad:
            print(b)
        print(f"{len(data['tests'])} tests, {len(data['relazione'])} comparisons of the relazione")
        sys.exit(1 if bad else 0)
    for b in bad:
        print(b)
    with open(md, "w", encoding="utf-8") as f:
        f.write(page)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
