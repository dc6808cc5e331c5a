#!/usr/bin/env python3
"""`assess run` and `assess rocking` on the same wall and motion give the same
numbers (issue 21): a free-standing wall 0.4 m x 4 m, 18 kN/m^3, rigid and
smooth (k = 1e6 kN/m^3), one- and two-sided, both polarities, under a 0.2 s
one-sine pulse of 2.5 g (plain file, dt 1 ms, g) and El Centro (AT2, x 1.5);
the run on the catalogue's simple overturning and on the same wall typed as an
explicit chain of one block (the chain that rotates as one body).

The run builds its rocking body from the kinematic chain, `assess rocking`
from (thickness, height, unit weight): W, R, alpha and I0 agree to round-off
(1e-16 relative), which the impacts amplify (measured: at most 3e-12
relative on theta_max). Tolerances: theta_max, energy D/C and the
displacement of the centroid 1e-10 relative; impacts, overturning and the
reason the analysis ended equal.

usage: run_vs_rocking.py ASSESS_EXE SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

REL_TOL = 1e-10  # - (theta_max, energy D/C, centroid displacement)


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("FAILED: " + " ".join(cmd) + "\n" + p.stderr)
    return json.loads(p.stdout)


def close(a, b):
    return abs(a - b) <= REL_TOL * max(abs(a), abs(b)) + 1e-300


def main():
    exe, src = sys.argv[1], sys.argv[2]
    records = [
        ("pulse", os.path.join(src, "tests/data/pulse_one_sine_0.2s_2.5g.txt"), ["--dt", "0.001", "--unit", "g"],
         {"dt": 0.001, "unit": "g"}, 1.0),
        ("elcentro", os.path.join(src, "spectra/records/elCentro.AT2"), [], {}, 1.5),
    ]
    failures, worst, count = [], 0.0, 0
    with tempfile.TemporaryDirectory() as tmp:
        for model in ("rigid", "smooth"):
            for sided in ("one-sided", "two-sided"):
                for e in (["0", "-0.65"] if sided == "one-sided" else ["housner"]):
                    for reverse in (False, True):
                        for name, path, rk_args, case_rec, scale in records:
                            dyn = {"model": model, "sidedness": sided,
                                   "restitution": float(e) if e != "housner" else "housner",
                                   "polarity": "reversed" if reverse else "normal",
                                   "records": [dict({"file": path, "scale": scale}, **case_rec)]}
                            if model == "smooth":
                                dyn["k"] = 1.0e6
                            case = {"project": "run vs rocking",
                                    "site": {"lat": 42.3498, "lon": 13.3995, "soil": "B"},
                                    "mechanism": {"type": "simple_overturning", "unit_weight": 18.0, "length": 1.0,
                                                  "hinge_level": 0,
                                                  "storeys": [{"height": 4.0, "thickness": 0.4}]},
                                    "dynamic": dyn}
                            cf = os.path.join(tmp, "case.json")
                            with open(cf, "w") as f:
                                json.dump(case, f)
                            r = run([exe, "run", cf, "--json"], src)["dynamic"]["analyses"][0]
                            # The same wall as an explicit chain of one block (issue 21, item 4).
                            case["mechanism"] = {"type": "blocks",
                                                 "blocks": [{"name": "wall", "unit_weight": 18.0, "length": 1.0,
                                                             "polygon": [[-0.4, 0], [0, 0], [0, 4], [-0.4, 4]]}],
                                                 "constraints": [{"type": "ground_hinge", "block": "wall",
                                                                  "point": [0, 0]}]}
                            with open(cf, "w") as f:
                                json.dump(case, f)
                            rb = run([exe, "run", cf, "--json"], src)["dynamic"]["analyses"][0]
                            cmd = [exe, "rocking", "--model", model, "--thickness", "0.4", "--height", "4",
                                   "--unit-weight", "18", "--restitution", e, "--record", path, "--scale",
                                   str(scale), "--json"] + rk_args
                            if model == "smooth":
                                cmd += ["--k", "1e6"]
                            if sided == "one-sided":
                                cmd.append("--one-sided")
                            if reverse:
                                cmd.append("--reverse")
                            k = run(cmd, src)
                            label = f"{model} {sided} e={e} {'reversed' if reverse else 'normal'} {name}"
                            count += 1
                            for a, b, what in ((r["theta_max"], k["theta_max"], "theta_max"),
                                               (r["dc"], k["dc"], "energy D/C"),
                                               (r["d_control"], k["d_max"], "centroid displacement"),
                                               (rb["theta_max"], k["theta_max"], "theta_max (explicit block)"),
                                               (rb["dc"], k["dc"], "energy D/C (explicit block)"),
                                               (rb["d_control"], k["d_max"], "centroid displacement (explicit block)")):
                                rel = abs(a - b) / max(abs(a), abs(b), 1e-300)
                                worst = max(worst, rel)
                                if not close(a, b):
                                    failures.append(f"{label}: {what} run {a!r} vs rocking {b!r} (rel {rel:.2e})")
                            for key in ("impacts", "overturned", "end"):
                                for rr, which in ((r, "run"), (rb, "run (explicit block)")):
                                    if rr[key] != k[key]:
                                        failures.append(f"{label}: {key} {which} {rr[key]} vs rocking {k[key]}")
                            print(f"{label}: theta_max {r['theta_max']:.12g} = {k['theta_max']:.12g}, "
                                  f"D/C {r['dc']:.10g}, impacts {r['impacts']}, end {r['end']}")
    print(f"{count} pairs, largest relative difference {worst:.2e} (tolerance {REL_TOL:g})")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
