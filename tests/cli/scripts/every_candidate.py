#!/usr/bin/env python3
"""Issue 24, point 3: every check that enters a verdict is in a table of the
relazione, and the dynamic analysis covers every candidate that governs a code
or fails a kinematic check.

A two-storey facade (hinge level searched, both levels fail their kinematic
checks at the site) with a dynamic section and automatic record selection:
  1. each other candidate's dynamic results equal those of a run of the same
     case with that hinge level given ("hinge_level": i) and the period range
     the candidates share (issue 32: one selection over the union of their
     ranges, docs/theory/record-selection.md §2.7), the way an engineer would
     run it alone: same records and scales, same d* demand, D/C and verdict per
     restitution value (relative tolerance 1e-12, or equal);
  2. the dynamic verdict of the facade is the worst over every candidate
     analysed: the NTC 2018 dynamic method's largest D/C is the largest over the
     governing and the other candidates' summaries, its failing count theirs;
  3. the HTML relazione: the rows of the checks tables (body and appendix)
     are exactly the checks counted in the verdict (sum over the codes of
     "overall[].checks"), and no code row is missing from them.

Usage: every_candidate.py ASSESS WORKDIR
"""
import copy
import json
import os
import re
import subprocess
import sys

ASSESS, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
REL_TOL = 1e-12  # (-) on d* demand (m) and D/C (-): the same computation must give the same number

CASE = {
    "schema_version": 1,
    "project": "Two-storey facade, hinge level searched, dynamic (issue 24 test)",
    "site": {"lat": 43.1355, "lon": 13.0678, "soil": "B", "topography": "T1", "VN_years": 50, "use_class": "II"},
    "mechanism": {
        "type": "simple_overturning",
        "storeys": [
            {"height": 4.0, "thickness": 0.6, "floor_weight": 40.0, "floor_distance_from_inner_face": 0.2},
            {"height": 3.5, "thickness": 0.45, "floor_weight": 25.0, "floor_distance_from_inner_face": 0.15},
        ],
        "unit_weight": 18.0,
        "length": 5.0,
    },
    "building": {"height_m": 7.5, "storeys": 2},
    "knowledge_level": "LC2",
    "codes": ["NTC2008", "NTC2018"],
    "dynamic": {"model": "rigid", "restitution": [-0.5, 0.0], "polarity": "both", "select": {"count": 7}},
}

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def close(a, b, what):
    ok = (a == b) or (a is not None and b is not None and abs(a - b) <= REL_TOL * max(abs(a), abs(b)))
    check(ok, f"{what}: {a} vs {b}")


def run(case, name, extra=()):
    path = os.path.join(WORK, name + ".json")
    with open(path, "w") as f:
        json.dump(case, f, indent=1)
    env = dict(os.environ)
    p = subprocess.run([ASSESS, "run", path, "--json", *extra], capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"{name}: exit {p.returncode}: {p.stderr}")
    return json.loads(p.stdout)


html = os.path.join(WORK, "facade.html")
full = run(CASE, "facade", ["--html", html])
dyn = full["dynamic"]
others = dyn.get("other_candidates", [])
cands = full["kinematic"]["candidates"]
check(len(cands) == 2, f"2 candidates expected, got {len(cands)}")
check(len(others) == 1, f"1 other candidate analysed dynamically expected, got {len(others)}")

# 1. Each other candidate equals its run alone (hinge level given).
for o in others:
    i = o["candidate_index"]
    alone_case = copy.deepcopy(CASE)
    alone_case["mechanism"]["hinge_level"] = i
    # The candidates share one selection over the union of their ranges (issue 32).
    sel, gsel = o["dynamic"]["selection"], dyn["selection"]
    check([sel["T_min"], sel["T_max"]] == [gsel["T_min"], gsel["T_max"]], f"{o['candidate']}: the shared range")
    check(gsel["shared_note"].startswith("one selection for the 2 candidates analysed dynamically"),
          f"shared note: {gsel['shared_note']}")
    alone_case["dynamic"]["select"]["period_range_s"] = [sel["T_min"], sel["T_max"]]
    alone = run(alone_case, f"alone_{i}")
    check(alone["kinematic"]["candidates"][0]["label"] == o["candidate"],
          f"candidate label {o['candidate']} vs {alone['kinematic']['candidates'][0]['label']}")
    a, b = o["dynamic"], alone["dynamic"]
    check([r["name"] for r in a["records"]] == [r["name"] for r in b["records"]], f"records of {o['candidate']}")
    for ra, rb in zip(a["records"], b["records"]):
        close(ra["scale"], rb["scale"], f"{o['candidate']} scale of {ra['name']}")
    check(len(a["summary"]) == len(b["summary"]) == 2, "two restitution values")
    for sa, sb in zip(a["summary"], b["summary"]):
        for key in ("d_demand", "dc_slv", "mean_dc", "max_d_star"):
            close(sa[key], sb[key], f"{o['candidate']} {sa['restitution']} {key}")
        check(sa["slv_satisfied"] == sb["slv_satisfied"], f"{o['candidate']} {sa['restitution']} verdict")
    # Its dynamic rows are in the facade's checks.
    rows = [c for c in full["checks"] if c["kind"] == "dynamic" and c["candidate"] == o["candidate"]]
    check(len(rows) == 2, f"{o['candidate']}: 2 dynamic rows in the checks, got {len(rows)}")

# 2. The dynamic verdict is the worst over every candidate analysed.
summaries = list(dyn["summary"]) + [s for o in others for s in o["dynamic"]["summary"]]
# A collapse is D/C = +inf, null in the JSON (issue 28).
def dc_of(x):
    return float("inf") if x is None else x


worst = max(dc_of(s["dc_slv"]) for s in summaries)
failing = sum(1 for s in summaries if s["slv_satisfied"] is False)
dyn_rows = [c for c in full["checks"] if c["kind"] == "dynamic"]
check(len(dyn_rows) == len(summaries), f"dynamic rows {len(dyn_rows)} vs summaries {len(summaries)}")
close(max(dc_of(c["dc"]) for c in dyn_rows), worst, "largest dynamic D/C")
check(sum(1 for c in dyn_rows if not c["satisfied"]) == failing, "failing dynamic rows")
overall = {o["code"]: o for o in full["overall"]}
close(max(dc_of(c["dc"]) for c in full["checks"] + [k for c in cands for k in c["checks"]] if c["code"] == "NTC2018"),
      dc_of(overall["NTC2018"]["max_dc"]), "NTC 2018 largest D/C over every check")

# 3. The relazione's checks tables hold exactly the checks the verdict counts.
text = open(html, encoding="utf-8").read()
# Issue 36: the other candidates' checks are in the tabulati di calcolo beside the relazione.
text += open(html[:-len(".html")] + "-tabulati.html", encoding="utf-8").read()
tables = re.findall(r'<table class="checks">(.*?)</table>', text, re.S)
body_rows = 0
per_code = {}
for t in tables:
    tbody = t.split("<tbody>")[1]
    for tr in re.findall(r"<tr>(.*?)</tr>", tbody, re.S):
        first = re.search(r"<td[^>]*>(.*?)</td>", tr, re.S).group(1)
        code = first.replace(" ", "")
        per_code[code] = per_code.get(code, 0) + 1
        body_rows += 1
for code, o in overall.items():
    check(per_code.get(code, 0) == o["checks"],
          f"{code}: {per_code.get(code, 0)} rows in the checks tables, the verdict counts {o['checks']}")
check(len(tables) >= 1, f"a checks table expected, got {len(tables)}")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print(f"ok: {len(others)} other candidate(s) equal to their runs alone; {body_rows} check rows in "
      f"{len(tables)} tables = the verdict's counts {dict((c, o['checks']) for c, o in overall.items())}")
