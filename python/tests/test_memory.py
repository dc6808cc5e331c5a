# No leak over 10 000 calls: the resident set size after 10 000 analyses
# (with their numpy histories, and 1 000 errors) is within 4 MB of the one
# after a warm-up (a leak of the history would be 10 000 x 7 kB = 70 MB).
import numpy as np

import assess
from conftest import WALL


def rss_kb():
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    import resource

    return pages * resource.getpagesize() // 1024


def calls(record, n):
    for i in range(n):
        r = assess.rocking("smooth", record=record, dt=0.01, k=1e6, history=True, scale=1.0 + (i % 7), tail=2.0,
                           **WALL)
        assert r["t"].size > 0
        if i % 10 == 0:
            try:
                assess.rocking("smooth", record=record, dt=0.01, **WALL)  # no k: an InputError
            except assess.InputError:
                pass


def test_rss_stable_over_10000_calls():
    t = np.arange(0.0, 2.0, 0.01)
    record = 0.3 * np.sin(2 * np.pi * 2.0 * t)  # 200 samples, 0.3 g at 2 Hz: the wall rocks
    calls(record, 1000)
    before = rss_kb()
    calls(record, 10000)
    after = rss_kb()
    print("RSS %d kB -> %d kB after 10 000 calls" % (before, after))
    assert after - before < 4096
