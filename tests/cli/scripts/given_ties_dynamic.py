#!/usr/bin/env python3
"""Issue 23: with tie rods GIVEN in a case, the facade's dynamic check rows
(which decide the dynamic verdict) are those of the tied analyses, never the
untied wall against the tied capacity: each governing dynamic row equals the
tied summary of its restitution value (d* demand, d_SLV of the tied
mechanism, verdict), and the NTC 2018 dynamic verdict is theirs.

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
        if abs(a - b) > REL_TOL * max(abs(a), abs(b)):
            fail.append(f"e = {s['e']}: {what} {a} vs tied {b}")
    if r["satisfied"] != s["satisfied_after"]:
        fail.append(f"e = {s['e']}: satisfied {r['satisfied']} vs tied {s['satisfied_after']}")
    if "with the ties" not in r["clause"]:
        fail.append(f"e = {s['e']}: the row does not say it is the tied analysis")
if fail:
    sys.exit("FAILED:\n  " + "\n  ".join(fail))
print(f"ok: {len(rows)} dynamic rows are the tied analyses")
