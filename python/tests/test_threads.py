# Long calls release the GIL: two threads run analyses in parallel. Wall
# times on a shared machine vary with its load, so each configuration is
# timed three times, interleaved, and the best of each is compared; and the
# speed-up is judged against what the machine gives two threads at that
# moment: SHA-256 of a large buffer, which CPython computes without the GIL.
# When the machine does not give two cores (speed-up of the reference below
# 1.5, another job running) the test is skipped, not passed. CTest runs it
# alone (RUN_SERIAL, python/CMakeLists.txt).
import hashlib
import os
import threading
import time

import pytest

import assess
from conftest import STURNO, WALL

N = 100
BUFFER = bytes(2 << 20)


def rocking_work(items):
    return [assess.rocking("rigid", record=STURNO, scale=s, **WALL)["theta_max"] for s in items]


def hash_work(items):
    return [hashlib.sha256(BUFFER).digest()[0] for _ in items]


def in_threads(work, threads):
    items = [0.2 + 0.01 * i for i in range(N)]
    chunks = [items[i::threads] for i in range(threads)]
    results = [None] * threads

    def run(i):
        results[i] = work(chunks[i])

    t0 = time.perf_counter()
    ts = [threading.Thread(target=run, args=(i,)) for i in range(threads)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    return time.perf_counter() - t0, sorted(x for r in results for x in r)


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="needs two cores")
def test_two_threads_take_clearly_less_wall_time_than_one():
    times = {(w, n): [] for w in ("rocking", "hash") for n in (1, 2)}
    for _ in range(3):
        for work, name in ((rocking_work, "rocking"), (hash_work, "hash")):
            t1, r1 = in_threads(work, 1)
            t2, r2 = in_threads(work, 2)
            assert r1 == r2  # the same results whatever the threads
            times[name, 1].append(t1)
            times[name, 2].append(t2)
    speedup = min(times["rocking", 1]) / min(times["rocking", 2])
    reference = min(times["hash", 1]) / min(times["hash", 2])
    print("100 analyses: one thread %.3f s, two threads %.3f s: speed-up %.2f (the machine's now: %.2f)" % (
        min(times["rocking", 1]), min(times["rocking", 2]), speedup, reference))
    if reference < 1.5:
        pytest.skip("the machine gives two threads a speed-up of %.2f now (loaded): nothing to compare" % reference)
    # An analysis holds the GIL while its result becomes a Python dict (a few
    # percent of its 4 ms): measured speed-ups 1.47-1.9 where the reference gave
    # 1.94. A call that kept the GIL gives at most 1.05.
    assert speedup > 1.25 and speedup > 0.65 * reference
