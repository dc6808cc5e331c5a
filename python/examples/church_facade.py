#!/usr/bin/env python3
"""The church façade of Lipo & de Felice (2017, §4): its verdicts and its D/C side by side.

The same assessment as `assess run mechanisms/church-facade.json --json` (the dict is that
JSON): strength (linear kinematic), displacement (non-linear kinematic) and dynamic (rocking
under records selected from the library) checks of NTC 2008 and NTC 2018, printed approach
by approach, and their D/C plotted side by side (the seed's Fig. 8). A D/C that is not a
number (an overturning in the dynamic analyses) is drawn as a failure, never as a value.

Usage: python3 church_facade.py [CASE] [--out DIR]   (default CASE mechanisms/church-facade.json)
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import assess  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", nargs="?", default="mechanisms/church-facade.json")
    ap.add_argument("--out", default=".", help="folder of church-dc.png (default .)")
    a = ap.parse_args()
    r = assess.run(a.case)

    print(r["project"])
    for o in r.get("overall", []):
        print("  %s: %s (%d of %d checks failing)" % (o["code"], "SATISFIED" if o["satisfied"] else "NOT SATISFIED",
                                                      o["failing"], o["checks"]))
    rows = r["comparison"]
    labels, values, colours = [], [], []
    top = max([row["dc"] for row in rows if row.get("dc") is not None] + [1.0]) * 1.1
    for row in rows:
        label = "%s %s %s" % (row["code"], row["approach"], row.get("clause", ""))
        dc = row.get("dc")
        print("  %-52.52s D/C %-7s %s %s" % (label, "-" if dc is None else "%.3f" % dc,
                                             "satisfied" if row["satisfied"] else "NOT satisfied", row.get("note", "")))
        labels.append(label)
        values.append(top if dc is None else dc)  # not a number: drawn to the edge as a failure
        colours.append("tab:green" if row["satisfied"] else "tab:red")
    for s in r.get("safety_indices", []):
        z = s.get("zeta_E")
        print("  zetaE %s %-12s %s" % (s["code"], s["approach"], "-" if z is None else "%.3f" % z))

    fig, ax = plt.subplots(figsize=(10, 0.42 * len(rows) + 1.6))
    y = list(range(len(rows)))
    ax.barh(y, values, color=colours)
    for yi, row in zip(y, rows):
        if row.get("dc") is None:
            ax.text(top, yi, " overturned / no D/C", va="center", fontsize=7)
    ax.axvline(1.0, color="k", lw=1)
    ax.set_yticks(y)
    ax.set_yticklabels(labels, fontsize=7)
    ax.invert_yaxis()
    ax.set(xlabel="D/C (-)", title="%s: every approach side by side" % os.path.basename(a.case))
    fig.tight_layout()
    path = os.path.join(a.out, "church-dc.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
