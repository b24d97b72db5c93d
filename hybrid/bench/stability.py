"""The sampled loops' stability: a map of 10^4 points of the paper's experiment (sensor stiffness x sample
time), one verdict as the experiment's check makes it, and one report with its margins."""

from __future__ import annotations

import time

import numpy as np

from hybrid.bench.harness import median_ns
from hybrid.bench.targets import STABILITY_MAP, STABILITY_REPORT
from hybrid.experiments.paper import paper_experiment
from hybrid.stability.analysis import stability
from hybrid.stability.maps import stability_map


def stability_benchmarks(quick: bool, add) -> None:
    """A map of 100 sensor stiffnesses (1e3-1e5 N/m) x 100 sample times (0.5-20 ms) of the paper's
    experiment, timed whole (its starts and the batched model); the report of :func:`hybrid.stability`
    with its margins, and without (what the check of every experiment costs once its start is known)."""
    exp = paper_experiment()
    over = {"sensor.stiffness": np.geomspace(1e3, 1e5, 100), "sample_time": np.geomspace(5e-4, 2e-2, 100)}
    stability_map(exp, {k: v[:3] for k, v in over.items()})  # its first use: SciPy, the native arm terms
    times = []
    for _ in range(2 if quick else 3):
        t0 = time.perf_counter()
        smap = stability_map(exp, over)
        times.append(time.perf_counter() - t0)
    add(STABILITY_MAP, float(np.median(times)), "s", ratio=f"{len(smap.table):,} points, "
        f"{smap.stable_share:.0%} stable; {np.median(times) / len(smap.table) * 1e6:.0f} us a point")
    full = median_ns(lambda: stability(exp), 1, 3 if quick else 7) / 1e6
    bare = median_ns(lambda: stability(exp, margins=False), 5, 5 if quick else 15) / 1e6
    add(STABILITY_REPORT, full, "ms", ratio=f"without the margins {bare:.2f} ms")
