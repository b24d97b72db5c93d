"""What a first use costs: ``import hybrid`` against ``import numpy``, and the first paper run, the
``paper`` command and the first sweep, each in fresh processes with an empty cache."""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from hybrid.bench.targets import COLD_PAPER, FIRST_SIMULATE, FIRST_SWEEP, IMPORT


def import_benchmarks(rep: int, add) -> None:
    """``import hybrid`` against ``import numpy``, each in fresh processes (the best of ``rep``, after
    one that writes the bytecode), less a bare interpreter's start: the import's own cost, and its ratio
    to NumPy's. Both read their modules' bytecode from a private cache (``PYTHONPYCACHEPREFIX``), as an
    installed package does: an environment that writes none (``PYTHONDONTWRITEBYTECODE``) would
    otherwise compile a checkout's sources at every import, but not an installed NumPy's."""
    with tempfile.TemporaryDirectory() as prefix:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = prefix

        def best(code: str) -> float:
            times = []
            for _ in range(rep + 1):
                t0 = time.perf_counter()
                subprocess.run([sys.executable, "-c", code], check=True, env=env)
                times.append(time.perf_counter() - t0)
            return min(times[1:])

        bare = best("pass")
        numpy_s, hybrid_s = best("import numpy") - bare, best("import hybrid") - bare
    ratio = hybrid_s / numpy_s
    add(IMPORT, hybrid_s * 1e3, "ms", ratio=f"{ratio:.2f}x import numpy ({numpy_s * 1e3:.0f} ms)", ratio_value=ratio)


#: a fresh process's import of hybrid and its first paper run, each timed inside it (one JSON line)
FIRST_RUN = ("import json, time; t0 = time.perf_counter(); import hybrid; t1 = time.perf_counter(); "
             "hybrid.simulate(hybrid.paper_experiment()); t2 = time.perf_counter(); "
             "print(json.dumps({'import_s': t1 - t0, 'simulate_s': t2 - t1}))")

#: a fresh process's first sweep of the paper's experiment and the same sweep again, warm (one JSON line; the
#: grid of the sweeps' rows, :func:`hybrid.bench.runs.paper_sweep_grid`: {runs} runs over every core)
FIRST_SWEEP_RUN = ("import json, time; import hybrid; from hybrid.bench.runs import paper_sweep_grid; "
                   "exp, grid = hybrid.paper_experiment(), paper_sweep_grid({runs}); "
                   "t0 = time.perf_counter(); hybrid.sweep(exp, grid); t1 = time.perf_counter(); "
                   "hybrid.sweep(exp, grid); t2 = time.perf_counter(); "
                   "print(json.dumps({{'first_s': t1 - t0, 'warm_s': t2 - t1}}))")


def _fresh(args: list[str]) -> tuple[float, str, list[str]]:
    """``python ARGS`` in a fresh process with an empty cache, in an empty temporary folder: its wall
    time [s], its stdout, and the names of what it left in the folder's ``out``."""
    with tempfile.TemporaryDirectory() as tmp:
        cache = Path(tmp) / "cache"
        cache.mkdir()
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, *args], check=True, capture_output=True, text=True, cwd=tmp,
                              env={**os.environ, "HYBRID_CACHE_DIR": str(cache)})
        wall = time.perf_counter() - t0
        out = Path(tmp) / "out"
        return wall, proc.stdout, sorted(p.name for p in out.iterdir()) if out.is_dir() else []


def cold_benchmarks(quick: bool, add) -> None:
    """What a first use costs, each in a fresh process with an empty cache (the median of 3; with
    ``quick``, one): the first paper ``simulate`` (timed inside the process, its import apart), the
    ``paper`` command's wall time, and a first sweep against the same sweep again in that process."""
    first, imports, paper, sweeps = [], [], [], []
    for _ in range(1 if quick else 3):
        times = json.loads(_fresh(["-c", FIRST_RUN])[1].strip().splitlines()[-1])
        first.append(times["simulate_s"])
        imports.append(times["import_s"])
        wall, _, written = _fresh(["-m", "hybrid", "paper", "--out", "out"])
        paper.append(wall)
        code = FIRST_SWEEP_RUN.format(runs=1000 if quick else 10000)
        sweeps.append(json.loads(_fresh(["-c", code])[1].strip().splitlines()[-1]))
    imported = statistics.median(imports)
    add(FIRST_SIMULATE, statistics.median(first), "s",
        ratio=f"the same process's import hybrid: {imported * 1e3:.0f} ms", import_s=imported)
    add(COLD_PAPER, statistics.median(paper), "s",
        ratio=f"{len(written)} files written (figures, metrics, time series)")
    # the sweep's loop is committed (generated/loops): a first sweep compiles it, and generates nothing
    cold, warm = (statistics.median(s[k] for s in sweeps) for k in ("first_s", "warm_s"))
    runs = "1,000 runs (quick)" if quick else "10,000 runs"
    add(FIRST_SWEEP, cold, "s", ratio=f"{cold / warm:.2f}x the same sweep warm ({warm:.2f} s, {runs})",
        of_warm=cold / warm)
