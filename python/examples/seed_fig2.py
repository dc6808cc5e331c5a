#!/usr/bin/env python3
"""The seed's Fig. 2 from Python: smooth against rigid rocking of the paper's wall.

Lipo & de Felice (2017), the block 2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3, two-sided
(docs/seed-fig2.md; the C++ program examples/seed_fig2.cpp draws the same (a) and (b)):
 (a) moment-rotation curves of the smooth block on a Winkler foundation for several
     moduli k, and of Housner's rigid block;
 (b) the free-rocking period against the amplitude theta0/theta_u (no dissipation);
 (c) the same wall under the Sturno record (Irpinia 1980, E-W) scaled to 0.3: the
     rotation histories of the smooth (k = 1e6 kN/m^3) and the rigid block (the seed's §3.2
     observation: the smooth block moves, and here overturns, where the rigid one barely lifts).

Usage: python3 seed_fig2.py [--out DIR] [--scale F]   (writes DIR/fig2.png and prints the table of docs/seed-fig2.md)
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import assess  # noqa: E402

WALL = dict(thickness=0.25, height=3.0, unit_weight=12.06)  # m, m, kN/m^3
KS = [5e4, 1e5, 1e6, 1e7]  # kN/m^3 (= 5e7 ... 1e10 N/m^3, the curves of Fig. 2)
AMPLITUDES = [0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95]
STURNO = "spectra/records/RSN292_ITALY_A-STU270.AT2"


def free_period(model, theta0):
    """Period of free rocking from theta0 (no dissipation): 4 x the time of the first crossing of theta = 0."""
    r = model.free(theta0, 60.0)
    return 4.0 * r["t"][np.argmax(r["theta"] <= 0.0)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=".", help="folder of fig2.png (default .)")
    ap.add_argument("--scale", type=float, default=0.3, help="factor on the Sturno record in (c) (default 0.3)")
    ap.add_argument("--data", default=os.environ.get("ASSESS_DATA_DIR", "."),
                    help="the project's folder, for the record (default $ASSESS_DATA_DIR or .)")
    a = ap.parse_args()
    models = [("k = %.0e kN/m$^3$" % k, assess.RockingModel("smooth", k=k, restitution="none", **WALL)) for k in KS]
    models.append(("rigid", assess.RockingModel("rigid", restitution=1.0, **WALL)))

    fig, (fa, fb, fc) = plt.subplots(1, 3, figsize=(16, 4.8))
    print("%-18s %11s %9s %14s %15s %10s %10s" % ("model", "theta_cr", "theta_u", "peak M (N m/m)",
                                                  "capacity (J/m)", "T(0.5) s", "T(0.9) s"))
    for name, m in models:
        th = np.linspace(0.0, m.theta_u, 301)
        fa.plot(th, m.moment(th), label=name)
        T = [free_period(m, f * m.theta_u) for f in AMPLITUDES]
        fb.plot(AMPLITUDES, T, marker="o", ms=3, label=name)
        print("%-18s %11.4g %9.5f %14.1f %15.2f %10.3f %10.3f" % (
            name.replace("$^3$", "^3"), m.theta_cr, m.theta_u, 1e3 * m.peak_moment, 1e3 * m.capacity,
            T[AMPLITUDES.index(0.5)], T[AMPLITUDES.index(0.9)]))
    fa.set(title="(a) moment-rotation (seed Eq. 1)", xlabel=r"$\theta$ (rad)", ylabel="M (kN m/m)")
    fb.set(title="(b) free-rocking period", xlabel=r"$\theta_0/\theta_u$ (-)", ylabel="T (s)")

    record = os.path.join(a.data, STURNO)
    for model, k in (("smooth", 1e6), ("rigid", None)):
        r = assess.rocking(model, record=record, k=k, scale=a.scale, history=True, **WALL)
        label = "%s: $\\theta_{max}/\\theta_u$ = %.2f%s" % (model, r["theta_max_over_theta_u"],
                                                          ", overturned" if r["overturned"] else "")
        fc.plot(r["t"], r["theta"] / r["theta_u"], lw=0.8, label=label)
    fc.set(title="(c) Sturno WE x %g" % a.scale, xlabel="t (s)", ylabel=r"$\theta/\theta_u$ (-)", xlim=(0, 40))
    for ax in (fa, fb, fc):
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Seed Fig. 2: 2b = 0.25 m, 2h = 3 m, 12.06 kN/m$^3$ (assess %s)" % assess.__version__)
    fig.tight_layout()
    path = os.path.join(a.out, "fig2.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
