#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Timing of roughroll.solve(..., threads=k): one batch of creep points on 1 and 2 threads.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_batch.py [REPEATS]
Prints the median wall time (and CPU time of the process, all threads) of each (REPEATS runs, interleaved so that both see the same load
on the machine), the ratio, and checks that both return the same numbers. Not a test: the
numbers go to docs/performance.md ("Python: the batch call on threads").
"""

import statistics
import sys
import time
from pathlib import Path

import roughroll

DATA = Path(__file__).resolve().parents[1] / "data"


def main(repeats):
    scenes = [roughroll.read_scene(DATA / n) for n in ("fig2a-T0.5.toml", "fig2a-T1.toml", "fig2b-A1.toml",
                                                      "unequal-kernels.toml")]
    items = [(s, s.friction * k / 12) for s in scenes for k in range(1, 12)]  # 44 points
    times = {1: [], 2: []}
    cpu = {1: [], 2: []}
    results = {}
    for _ in range(repeats):
        for threads in (1, 2):
            start, start_cpu = time.perf_counter(), time.process_time()
            results[threads] = roughroll.solve(items, threads=threads)
            times[threads].append(time.perf_counter() - start)
            cpu[threads].append(time.process_time() - start_cpu)
    strip = lambda p: {k: v for k, v in p.to_dict().items() if k != "seconds"}
    same = [strip(p) for p in results[1]] == [strip(p) for p in results[2]]
    m1, m2 = statistics.median(times[1]), statistics.median(times[2])
    print(f"{len(items)} points (extrapolated, n = 128), {repeats} runs each")
    for k, m in ((1, m1), (2, m2)):
        print(f"threads={k}  median {m:.3f} s wall, {statistics.median(cpu[k]):.3f} s CPU (all threads)")
    print(f"ratio 1/2  {m1 / m2:.2f}   same numbers: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 5))
