#!/usr/bin/env python3
"""A fragility curve from Python: the overturning of a free-standing wall at L'Aquila.

Multiple-stripe analysis with records selected from the library at each return period,
lognormal fits (Baker 2015) with bootstrap bounds, and the annual risk of overturning on
the site's hazard curve (docs/user/fragility.md): the dict of `assess fragility CASE --json`,
plotted against the PGA on the site's ground with the stripes' fractions.

Usage: python3 fragility_curve.py [CASE] [--records N] [--out DIR]
       (default CASE tests/data/fragility/free_wall.json, 3 records per stripe)
"""
import argparse
import math
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import assess  # noqa: E402

G = 9.80665  # m/s^2


def phi(x):
    return 0.5 * (1.0 + math.erf(x / math.sqrt(2.0)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", nargs="?", default="tests/data/fragility/free_wall.json")
    ap.add_argument("--records", type=int, default=3, help="records per stripe (default 3)")
    ap.add_argument("--stripes", default="30,72,140,475,975,2475", help="return periods (years)")
    ap.add_argument("--out", default=".", help="folder of fragility.png (default .)")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        f = assess.fragility(a.case, stripes=[float(s) for s in a.stripes.split(",")], records=a.records,
                             bootstrap=100, out=tmp)
    g = f["governing"]
    print("governing: %s, restitution %s: median %.3f g, beta %.3f; overturning once in %.0f years, "
          "P in VN = %.3f (%s)" % (g["limit_state"], g["restitution"], g["theta_m_s2"] / G, g["beta"],
                                   g["return_period_years"], g["probability_in_VN"], g["status"]))
    fig, ax = plt.subplots(figsize=(7, 4.8))
    im = np.linspace(0.005, 1.2, 300)  # PGA on the site's ground (g)
    for curve in f["curves"]:
        if curve.get("status") != "ok":
            continue
        median, beta = curve["theta_m_s2"] / G, curve["beta"]
        line, = ax.plot(im, [phi(math.log(x / median) / beta) for x in im],
                        label="%s, e %s: median %.3f g, beta %.2f" % (curve["limit_state"], curve["restitution"],
                                                                     median, beta))
        for s in curve["stripes"]:  # the stripes' fractions k/n at their PGA
            ax.plot(s["im_m_s2"] / G, s["k"] / s["n"], "o", ms=4, color=line.get_color())
    ax.set(xlabel="PGA on the site's ground (g)", ylabel="P(limit state exceeded | PGA) (-)",
           title="Fragility of %s" % os.path.basename(a.case))
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(a.out, "fragility.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
