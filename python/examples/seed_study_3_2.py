#!/usr/bin/env python3
"""The seed's §3.2 study from Python: smooth against rigid blocks over 4 walls x 4 records x 10 scales.

Runs mechanisms/campaign-seed-3.2.json (docs/campaign-seed-3.2.md; 16 000 analyses with 50
realisations, about 30 s on 2 cores) through assess.campaign, then summarises the rows with
pandas as the page's table "moved / overturned / mean D/C" by model and scale, and plots
(a) the fraction of overturned walls and (b) the mean energy D/C against the scale factor per
model and wall, (c) the code's displacement ratio SDe(Ts)/du* against the dynamic D/C (Fig. 5b).

Usage: python3 seed_study_3_2.py [--realisations N] [--threads N] [--out DIR]
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

import assess  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--spec", default="mechanisms/campaign-seed-3.2.json")
    ap.add_argument("--realisations", type=int, default=None, help="fewer realisations for a quick look (paper: 50)")
    ap.add_argument("--threads", type=int, default=None, help="worker threads (default all cores)")
    ap.add_argument("--out", default=".", help="folder of seed-3.2.png (default .)")
    a = ap.parse_args()
    with open(a.spec, encoding="utf-8") as f:
        spec = json.load(f)
    if a.realisations:
        spec["realisations"] = a.realisations
    # The spec's record paths ("spectra/records/...") are found from the working directory, then in
    # the data directory ($ASSESS_DATA_DIR, the installed share/assess, the source tree).
    rows = pd.DataFrame(assess.campaign(spec, threads=a.threads))
    ok = rows[rows["status"] == "ok"] if "status" in rows else rows
    print("%d analyses (%d failed)" % (len(rows), len(rows) - len(ok)))

    moved = ok.assign(moved=ok["theta_max_rad"] > 0)
    table = moved.groupby(["model", "scale"]).agg(moved=("moved", "mean"), overturned=("overturned", "mean"),
                                                 mean_dc=("dc_energy", "mean"))
    print(table.to_string(float_format=lambda v: "%.3f" % v))

    fig, (fa, fb, fc) = plt.subplots(1, 3, figsize=(16, 4.8))
    for (model, wall), g in ok.groupby(["model", "wall"]):
        by_scale = g.groupby("scale")
        style = "-" if model == "smooth" else "--"
        fa.plot(by_scale["overturned"].mean(), style, marker="o", ms=3, label="%s %s" % (model, wall))
        fb.plot(by_scale["dc_energy"].mean(), style, marker="o", ms=3, label="%s %s" % (model, wall))
    for model, g in ok.groupby("model"):
        fc.scatter(g["dc_energy"], g["dc_displacement"], s=3, alpha=0.4, label=model)
    fc.plot([0, 3], [0, 3], "k", lw=0.8)
    fa.set(title="(a) overturned", xlabel="scale factor (-)", ylabel="fraction (-)")
    fb.set(title="(b) energy D/C (mean)", xlabel="scale factor (-)", ylabel="D/C (-)")
    fc.set(title="(c) code against dynamic (Fig. 5b)", xlabel="dynamic energy D/C (-)",
           ylabel=r"SDe(Ts)/du$^*$ (-)", xlim=(0, 3), ylim=(0, 3))
    for ax in (fa, fb, fc):
        ax.grid(True, lw=0.3)
    fa.legend(fontsize=6)
    fc.legend(fontsize=8)
    fig.suptitle("Seed §3.2: %d analyses, %d realisations (assess %s)" % (len(rows), spec["realisations"],
                                                                          assess.__version__))
    fig.tight_layout()
    path = os.path.join(a.out, "seed-3.2.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
