#!/usr/bin/env python3
"""bench_python.py: the per-call overhead of a rocking analysis called from Python.

The benchmark of bench_rocking.cpp (2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3, k = 1e6 kN/m^3,
two-sided, Housner e, the Sturno E-W record at scale 0.2, 16 392 samples) called as
``assess.rocking(...)`` with the record as a numpy array, against the library doing the
same work in C++ (prepare_rocking, run_rocking, rocking_json: the module's private
``_library_rocking_seconds``, the same code path without Python). The difference is what
Python costs per call: the arguments converted, the record's array copied into the
library, the GIL released and taken back, the JSON turned into a dict. A record of 2 samples
(the wall never lifts: the library does almost nothing) shows the overhead alone. Best of
``repeats`` runs of ``n`` calls each.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [repeats] [n]
"""
import os
import sys
import time

import numpy as np

import assess
from assess import _assess

ROOT = os.environ.get("ASSESS_DATA_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
WALL = dict(thickness=0.25, height=3.0, unit_weight=12.06)


def best(f, repeats, n):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f(n)
        times.append((time.perf_counter() - t0) / n)
    return min(times)


def case(label, acc, dt, repeats, n):
    def python(n):
        for _ in range(n):
            assess.rocking("smooth", record=acc, dt=dt, unit="m/s^2", k=1e6, **WALL)

    def library(n):
        _assess._library_rocking_seconds(n, "smooth", WALL["thickness"], WALL["height"], WALL["unit_weight"],
                                         acc, dt, 1e6)

    py = best(python, repeats, n)
    lib = best(library, repeats, n)
    print("%-44s python %9.1f us  library %9.1f us  overhead %6.1f us per call" % (
        label, py * 1e6, lib * 1e6, (py - lib) * 1e6))
    return py - lib


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    rec = assess.records.read(os.path.join(ROOT, "spectra", "records", "RSN292_ITALY_A-STU270.AT2"))
    print("assess %s, Python %s, numpy %s" % (assess.__version__, sys.version.split()[0], np.__version__))
    # The record scaled once in the array, scale 1 in both calls: the same accelerations bit for bit.
    case("Sturno x 0.2 (16 392 samples, smooth block)", rec["acc"] * 0.2, rec["dt"], repeats, n)
    case("2 samples of 0 (the wall never lifts)", np.zeros(2), 0.01, repeats, 50 * n)


if __name__ == "__main__":
    main()
