#!/usr/bin/env python3
"""Issues 23, 29: with EXISTING tie rods in a case (the stato di fatto), the
facade's dynamic check rows (which decide the dynamic verdict) are those of
the tied analyses, never the untied wall against the tied capacity: each
governing dynamic row equals the tied summary of its restitution value (d*
demand, d_SLV of the tied mechanism, verdict), and the NTC 2018 dynamic
verdict is theirs. The analyses listed in the dynamic section are the tied
ones too: each run's peak rotation and tie outcome equal the ties section's
run (the stato di fatto's: no intervention, one state).

Usage: given_ties_dynamic.py ASSESS CASE
"""
import json
import subprocess
import sys

REL_TOL = 1e-12  # (-) on d* (m) and D/C: the same numbers copied
p = subprocess.run([sys.argv[1], "run", sys.argv[2], "--json"], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit(p.stderr)
j = json.loads(p.stdout)
tied = j["ties"]["dynamic"]
if not tied["applies"]:
    sys.exit("the tied dynamics does not apply to the test case")
rows = [c for c in j["checks"] if c["kind"] == "dynamic"]
fail = []
if len(rows) != len(tied["summaries"]):
    fail.append(f"{len(rows)} dynamic rows, {len(tied['summaries'])} tied summaries")
for r, s in zip(rows, tied["summaries"]):
    for a, b, what in ((r["demand"], s["d_demand_after_m"], "demand"), (r["capacity"], s["d_SLV_after_m"], "capacity")):
        if a is None or b is None:  # a collapse: an unbounded demand, null in JSON
            if a is not b:
                fail.append(f"e = {s['e']}: {what} {a} vs tied {b}")
        elif abs(a - b) > REL_TOL * max(abs(a), abs(b)):
            fail.append(f"e = {s['e']}: {what} {a} vs tied {b}")
    if r["satisfied"] != s["satisfied_after"]:
        fail.append(f"e = {s['e']}: satisfied {r['satisfied']} vs tied {s['satisfied_after']}")
    if "with the tie rods" not in r["clause"]:
        fail.append(f"e = {s['e']}: the row does not say it is the tied analysis")
runs = j["dynamic"]["analyses"]
if len(runs) != len(tied["runs"]):
    fail.append(f"{len(runs)} runs in the dynamic section, {len(tied['runs'])} tied runs")
if tied["runs"] != tied["runs_before"]:
    fail.append("without an intervention the two states' runs differ")
for r, t in zip(runs, tied["runs"]):
    if abs(r["theta_max"] - t["theta_max"]) > REL_TOL * max(abs(r["theta_max"]), abs(t["theta_max"])):
        fail.append(f"run {t['run']}: theta_max {r['theta_max']} vs tied {t['theta_max']}")
    if "ties" not in r or len(r["ties"]) == 0:
        fail.append(f"run {t['run']}: the dynamic section's run has no tie outcome")
if fail:
    sys.exit("FAILED:\n  " + "\n  ".join(fail))
print(f"ok: {len(rows)} dynamic rows are the tied analyses")
