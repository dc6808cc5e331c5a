#!/usr/bin/env python3
"""bench_python.py: the per-call overhead of a rocking analysis called from Python.

The benchmark of bench_rocking.cpp (2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3, k = 1e6 kN/m^3,
two-sided, Housner e, the Sturno E-W record at scale 0.2, 16 392 samples) called as
``assess.rocking(...)`` with the record as a numpy array. Each call's CPU time (of its thread:
time.thread_time, so that the machine's other jobs do not count) is split into the
library's share, measured inside the module around prepare_rocking, run_rocking and
rocking_json (the functions `assess rocking` calls; ``assess._assess._last_library_seconds``),
and the rest: what Python costs per call (the wrapper, the arguments converted, the record's
array copied into the library, the GIL released and taken back, the JSON turned into a dict).
Measured on the same calls, so the allocator's state (an analysis of this record takes about
100 page faults for its three 128 kB buffers) falls on both alike.
Also a record of 2 samples, where the library does almost nothing. Prints the median and the
smallest over ``n`` calls.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [n]
"""
import os
import statistics
import sys
import time

import numpy as np

import assess
from assess import _assess

ROOT = os.environ.get("ASSESS_DATA_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
WALL = dict(thickness=0.25, height=3.0, unit_weight=12.06)


def case(label, acc, dt, n, history=False):
    total, library = [], []
    for _ in range(n):
        t0 = time.thread_time()
        assess.rocking("smooth", record=acc, dt=dt, unit="m/s^2", k=1e6, history=history, **WALL)
        total.append(time.thread_time() - t0)
        library.append(_assess._last_library_seconds())
    over = [t - l for t, l in zip(total, library)]
    print("%-46s call %8.1f us, library %8.1f us, overhead median %5.1f us, smallest %5.1f us" % (
        label, statistics.median(total) * 1e6, statistics.median(library) * 1e6, statistics.median(over) * 1e6,
        min(over) * 1e6))


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    rec = assess.records.read(os.path.join(ROOT, "spectra", "records", "RSN292_ITALY_A-STU270.AT2"))
    print("assess %s, Python %s, numpy %s, %d calls each" % (assess.__version__, sys.version.split()[0],
                                                            np.__version__, n))
    acc = rec["acc"] * 0.2
    case("Sturno x 0.2 (16 392 samples, smooth block)", acc, rec["dt"], n)
    case("the same, history=True (numpy t, theta, theta_dot)", acc, rec["dt"], n, history=True)
    case("2 samples of 0 (the wall never lifts)", np.zeros(2), 0.01, 10 * n)


if __name__ == "__main__":
    main()
