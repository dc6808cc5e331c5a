#!/usr/bin/env python3
"""The outputs quoted in docs/user are the tool's (issue 24): every fenced
block of docs/user/*.md that starts with "$ assess run CASE" (no options) is
compared with `assess run CASE` at 120 columns: each quoted line that is not a
comment must appear in the output, spaces collapsed; "..." (or "…") in a
quoted line stands for any text of that output line, so that an elided line's
figures are checked too (issue 41: a D/C of 1.587 was quoted where the tool
printed ∞).

usage: doc_outputs.py ASSESS_EXE SOURCE_DIR
"""
import glob
import os
import re
import subprocess
import sys


def norm(line):
    return re.sub(r"\s+", " ", line).strip()


def main():
    exe, src = sys.argv[1], sys.argv[2]
    failures, checked = [], 0
    for doc in sorted(glob.glob(os.path.join(src, "docs", "user", "*.md"))):
        text = open(doc, encoding="utf-8").read()
        for block in re.findall(r"```(?:sh|text|console)?\n(.*?)```", text, flags=re.S):
            lines = block.splitlines()
            if not lines or not re.fullmatch(r"\$ assess run \S+\.json", lines[0].strip()):
                continue
            case = lines[0].split()[3]
            p = subprocess.run([exe, "run", case], cwd=src, capture_output=True, text=True,
                               env=dict(os.environ, COLUMNS="120"))
            out = [norm(l) for l in p.stdout.splitlines()]
            for l in lines[1:]:
                if not l.strip() or l.lstrip().startswith("#") or l.strip() in ("...", "…"):
                    continue
                checked += 1
                parts = re.split(r"\.\.\.|…", norm(l))
                pattern = re.compile(".*".join(re.escape(x.strip()) for x in parts))
                if not any(pattern.fullmatch(o) or pattern.search(o) and len(parts) > 1 for o in out):
                    failures.append(f"{os.path.basename(doc)} ({case}): not in the output: {l.strip()}")
    print(f"{checked} quoted lines checked")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
