"""How the benchmarks measure: medians of repeated timings, warm-ups, one core, and C timed inside C.

A measurement is the median, over ``repeat`` runs, of the time of ``number`` calls divided by
``number``: per call, in ns unless a row says otherwise. A generated function is timed inside C by
a compiled loop with the runtime's flags, on a new state each call (the program: ``c/harness.c.j2``).
"""

from __future__ import annotations

import os
import statistics
import subprocess
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from hybrid.bench.templates import render
from hybrid.native import compiler, loader

#: calls of a run through ``simulate`` before it is timed: in a fresh process the first is about twice
#: as slow (the C library's allocator maps the record's memory afresh, page by page) and the next ten a
#: tenth slower
WARM_UP = 5


def median_ns(fn, number: int, repeat: int) -> float:
    """The median over ``repeat`` timings of ``number`` calls of ``fn()``, per call [ns]."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number * 1e9)
    return statistics.median(times)


def paired_ratio(slow: list[float], fast: list[float]) -> float:
    """The median of ``slow[k] / fast[k]`` over rounds ``k``, each round timing both sides back to back: a
    machine whose speed drifts between rounds (another program on the shared cores) moves both sides of a
    round alike, where the ratio of the two sides' medians can pair a slow round with a fast one.

    Examples
    --------
    >>> paired_ratio([10.0, 30.0, 12.0], [2.0, 5.0, 3.0])
    5.0
    """
    if len(slow) != len(fast) or not slow:
        raise ValueError("paired_ratio needs as many rounds of each side, at least one")
    return statistics.median(s / f for s, f in zip(slow, fast))


def on_one_core(measure: Callable[[], float]) -> float | None:
    """``measure()`` with the calling thread pinned to one of its CPUs, its CPUs given back after (a
    batch splits over the CPUs the caller may run on: here it runs on the caller's thread alone); None
    where the system cannot pin a thread."""
    if not hasattr(os, "sched_setaffinity"):
        return None
    cpus = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(cpus)})
    try:
        return measure()
    finally:
        os.sched_setaffinity(0, cpus)


def harness_source(prefix: str, entry: dict, values: dict, singular_tol: float = 1e-3) -> str:
    """A C program timing one call of the manifest function ``entry`` on the input ``values``."""
    inputs = []
    for a in entry["inputs"]:
        v = np.asarray(values[a["name"]], float).ravel()
        if v.size != a["size"]:
            raise ValueError(f"{a['name']} needs {a['size']} values, got {v.size}")
        inputs.append({"name": a["name"], "size": a["size"], "value": [float(x) for x in v]})
    outputs = [{"name": a["name"], "size": a["size"]} for a in entry["outputs"]]
    arguments = ([a["name"] for a in inputs] + ([singular_tol] if entry["singular_tol"] else [])
                 + [a["name"] for a in outputs])
    return render("harness.c.j2", prefix=prefix, symbol=entry["symbol"], inputs=inputs, outputs=outputs,
                  arguments=arguments, first=inputs[0]["name"], first0=inputs[0]["value"][0])


def c_harness_ns(src_dir: Path, prefix: str, entry: dict, values: dict, calls: int, repeat: int) -> float:
    """Per-call time of a generated function inside C, by a compiled loop (the runtime's flags)."""
    return c_program_ns(harness_source(prefix, entry, values), src_dir, prefix, calls, repeat)


def c_program_ns(source: str, src_dir: Path, prefix: str, calls: int, repeat: int, *args: str,
                 include: tuple[Path, ...] = ()) -> float:
    """The median of the per-call times [ns] a timing program (``source``, compiled with the unit ``prefix``
    of ``src_dir`` and the runtime's flags) prints, run for ``calls`` calls ``repeat`` times (then ``args``)."""
    out = c_program_output(source, (src_dir / f"{prefix}.c",), (str(calls), str(repeat), *args),
                           include=(src_dir, *include))
    return statistics.median(float(x) for x in out.split())


def c_program_output(source: str, sources: tuple[Path, ...], args: tuple[str, ...],
                     include: tuple[Path, ...] = ()) -> str:
    """What the C program ``source`` prints, compiled with ``sources`` and the runtime's flags (the
    generated C's folder, for its shared headers, and ``include`` on the include path), run with ``args``."""
    cc, ident = compiler.compiler()
    with tempfile.TemporaryDirectory() as tmp:
        main = Path(tmp) / "bench.c"
        main.write_text(source)
        exe = Path(tmp) / "bench"
        flags = [f for f in compiler.flags(ident) if f != "-fPIC"]
        # the unit's folder, and the generated C's (the SIMD lanes' header a unit includes)
        folders = [f"-I{d}" for d in (*include, loader.source_dir())]
        subprocess.run([cc, *flags, *folders, str(main), *map(str, sources), "-o", str(exe), "-lm"],
                       check=True, capture_output=True)
        return subprocess.run([str(exe), *args], check=True, capture_output=True, text=True).stdout
