#!/usr/bin/env python3
"""Times qhull (SciPy's ConvexHull, 6-D) on the wrench sets the `grasp` benchmark writes.

Usage: python3 tools/grasp/qhull_bench.py build/bench/grasp-3x8.csv [more.csv ...]
Each file has the header `set,fx,fy,fz,tx,ty,tz`, one row per wrench. For every file and each
qhull option string (QJ, as GraspIt! and the issue's anchor; and Qt Qx, the reference tests'),
it warms up for 0.5 s, then times batches of about 50 ms cycling through the file's sets, and
prints one line per file and option:
  qhull FILE OPTIONS median_ms=M sets=K
and first, per set, `check FILE SET EPSILON VOLUME` (options Qt Qx), which the benchmark compares
with its own results.
The median is per ConvexHull call (hull, volume and facet equations: SciPy computes them all).
`gradle bench -Ponly=grasp` runs it itself when python3 has scipy (or HANDSIM_PYTHON names one).
"""
import sys
import time

import numpy as np
from scipy.spatial import ConvexHull


def load(path):
    data = np.loadtxt(path, delimiter=',', skiprows=1)
    sets = []
    for s in np.unique(data[:, 0]):
        sets.append(np.ascontiguousarray(data[data[:, 0] == s, 1:]))
    return sets


def median_ms(sets, options, warmup=0.5, batch_s=0.05, samples=11):
    k = 0
    end = time.perf_counter() + warmup
    calls = 0
    t0 = time.perf_counter()
    while time.perf_counter() < end or calls < 2:
        ConvexHull(sets[k % len(sets)], qhull_options=options)
        k += 1
        calls += 1
    per = (time.perf_counter() - t0) / calls
    batch = max(1, int(batch_s / per))
    times = []
    for _ in range(samples):
        t = time.perf_counter()
        for _ in range(batch):
            ConvexHull(sets[k % len(sets)], qhull_options=options)
            k += 1
        times.append((time.perf_counter() - t) / batch)
    times.sort()
    return times[len(times) // 2] * 1e3


def main():
    for path in sys.argv[1:]:
        sets = load(path)
        for i, w in enumerate(sets):   # the values, for the benchmark to compare: epsilon (0 if none) and volume
            h = ConvexHull(w, qhull_options='Qt Qx')
            eps = float(-h.equations[:, -1].max())
            print(f'check {path} {i} {max(eps, 0.0)!r} {float(h.volume)!r}', flush=True)
        for options in ('QJ', 'Qt Qx'):
            print(f'qhull {path} {options.replace(" ", "_")} median_ms={median_ms(sets, options):.4f} sets={len(sets)}', flush=True)


if __name__ == '__main__':
    main()
