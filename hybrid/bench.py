"""``python -m hybrid bench``: how fast the generated law and the runner are, against alternatives.

Medians over repeated runs; ratios are computed within the same run. Timings are
information, never pass/fail.
"""

from __future__ import annotations

import json
import os
import platform
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from functools import cache, partial
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from hybrid import files, reference
from hybrid.cli import common
from hybrid.control.controller import Controller
from hybrid.control.law import decoupling_law
from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments.panda import panda_experiment
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.surfaces import Circle, Sphere
from hybrid.models.planar_arm import paper_arm
from hybrid.models.robot import Robot
from hybrid.models.terms import arm_terms
from hybrid.native import compiler, loader, units
from hybrid.native.binding import workers
from hybrid.native.units import planar_unit
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import simulate
from hybrid.sweeps import apply, sweep

ONE_STATE = "F* from Python, one state (law(q, qdot, a, Fc))"
BATCHED = "F* from Python, batched, per state (N = 1e5, SIMD lanes, both cores)"
NUMPY_LAW = "F* in plain NumPy (hybrid.reference)"


def in_c(backend: str) -> str:
    return f"F* in C, {backend} backend, per call"


HARNESS = r"""
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "%(prefix)s.h"
static double now(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec + 1e-9 * ts.tv_nsec; }
int main(int argc, char **argv) {
    long ncalls = argc > 1 ? atol(argv[1]) : 1000000, i;
    int rep, reps = argc > 2 ? atoi(argv[2]) : 7;
    double sink = 0.0;
%(arrays)s
    for (rep = 0; rep < reps; ++rep) {
        double t0 = now();
        for (i = 0; i < ncalls; ++i) {
            %(first)s[0] = %(first0)r + 1e-9 * (double)(i & 1023);   /* a new state each call */
            %(symbol)s(%(args)s);
            sink += %(out)s[0];
        }
        printf("%%.3f\n", (now() - t0) / (double)ncalls * 1e9);
    }
    fprintf(stderr, "%%g\n", sink);
    return 0;
}
"""


def harness_source(prefix: str, entry: dict, values: dict, singular_tol: float = 1e-3) -> str:
    """A C program timing one call of the manifest function ``entry`` on the input ``values``."""
    decl = []
    for a in entry["inputs"]:
        v = np.asarray(values[a["name"]], float).ravel()
        if v.size != a["size"]:
            raise ValueError(f"{a['name']} needs {a['size']} values, got {v.size}")
        decl.append(f"    double {a['name']}[{a['size']}] = {{{', '.join(repr(float(x)) for x in v)}}};")
    decl += [f"    double {a['name']}[{a['size']}];" for a in entry["outputs"]]
    args = [a["name"] for a in entry["inputs"]] + ([repr(singular_tol)] if entry["singular_tol"] else [])
    args += [a["name"] for a in entry["outputs"]]
    first = entry["inputs"][0]["name"]
    return HARNESS % {"prefix": prefix, "arrays": "\n".join(decl), "symbol": entry["symbol"], "args": ", ".join(args),
                      "first": first, "first0": float(np.asarray(values[first]).ravel()[0]),
                      "out": entry["outputs"][0]["name"]}


def c_harness_ns(src_dir: Path, prefix: str, entry: dict, values: dict, calls: int, repeat: int) -> float:
    """Per-call time of a generated function inside C, by a compiled loop (the runtime's flags)."""
    cc, ident = compiler.compiler()
    with tempfile.TemporaryDirectory() as tmp:
        main = Path(tmp) / "bench.c"
        main.write_text(harness_source(prefix, entry, values))
        exe = Path(tmp) / "bench"
        flags = [f for f in compiler.flags(ident) if f != "-fPIC"]
        subprocess.run([cc, *flags, f"-I{src_dir}", str(main), str(src_dir / f"{prefix}.c"),
                        "-o", str(exe), "-lm"], check=True, capture_output=True)
        out = subprocess.run([str(exe), str(calls), str(repeat)], check=True, capture_output=True, text=True)
    return statistics.median(float(x) for x in out.stdout.split())


def _progress(i: int, total: int, what: str) -> None:
    print(f"[{i}/{total}] {what} ...", file=sys.stderr, flush=True)


#: calls of a run through ``simulate`` before it is timed: in a fresh process the first is about twice
#: as slow (the C library's allocator maps the record's memory afresh, page by page) and the next ten a
#: tenth slower
WARM_UP = 5


def _median_ns(fn, number: int, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number * 1e9)
    return statistics.median(times)


def _versions() -> dict:
    out = {"python": platform.python_version(), "machine": platform.machine(), "system": platform.platform()}
    try:
        cpu = [ln for ln in Path("/proc/cpuinfo").read_text().splitlines() if ln.startswith("model name")]
        out["cpu"] = cpu[0].split(":", 1)[1].strip() if cpu else platform.processor()
    except OSError:
        out["cpu"] = platform.processor()
    out["cores"] = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    try:
        flags = next(ln for ln in Path("/proc/cpuinfo").read_text().splitlines() if ln.startswith("flags")).split()
        out["simd"] = next((f for f in ("avx512f", "avx2", "avx", "sse4_2") if f in flags), "")
    except (OSError, StopIteration):
        pass
    for pkg in ("numpy", "cffi", "sympy", "casadi", "pin"):
        try:
            out[pkg] = version(pkg)
        except PackageNotFoundError:
            pass
    out["cc"] = compiler.compiler()[1]
    return out


IMPORT = "import hybrid in a fresh process, from bytecode, less the interpreter's start"


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


FIRST_SIMULATE = "first paper simulate (hybrid.simulate(hybrid.paper_experiment())), fresh process and cache"
COLD_PAPER = "python -m hybrid paper --out DIR, fresh process and cache (wall time)"
#: a fresh process's import of hybrid and its first paper run, each timed inside it (one JSON line)
FIRST_RUN = ("import json, time; t0 = time.perf_counter(); import hybrid; t1 = time.perf_counter(); "
             "hybrid.simulate(hybrid.paper_experiment()); t2 = time.perf_counter(); "
             "print(json.dumps({'import_s': t1 - t0, 'simulate_s': t2 - t1}))")


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
    ``quick``, one): the first paper ``simulate`` (timed inside the process, its import apart), and
    the ``paper`` command's wall time."""
    first, imports, paper = [], [], []
    for _ in range(1 if quick else 3):
        times = json.loads(_fresh(["-c", FIRST_RUN])[1].strip().splitlines()[-1])
        first.append(times["simulate_s"])
        imports.append(times["import_s"])
        wall, _, written = _fresh(["-m", "hybrid", "paper", "--out", "out"])
        paper.append(wall)
    imported = statistics.median(imports)
    add(FIRST_SIMULATE, statistics.median(first), "s", ratio=f"the same process's import hybrid: {imported * 1e3:.0f} ms",
        import_s=imported)
    add(COLD_PAPER, statistics.median(paper), "s", ratio=f"{len(written)} files written (figures, metrics, time series)")


def experiment_row(duration: float, how: str) -> str:
    """The name of the paper experiment's end-to-end row (``how``: compiled, NumPy)."""
    return f"paper experiment end to end ({duration:g} s simulated), {how}"


def select_groups(groups: list, only: str | None) -> list:
    """The ``(label, run)`` groups whose label contains ``only`` (any case); all of them for None."""
    if only is None:
        return list(groups)
    if not only.strip():
        raise HybridError("--only needs part of a benchmark group's label, e.g. --only sweep")
    chosen = [g for g in groups if only.casefold() in g[0].casefold()]
    if not chosen:
        raise HybridError(f"--only {only!r}: no benchmark group's label contains it; the groups: "
                          + "; ".join(label for label, _ in groups))
    return chosen


def benchmark_groups(quick: bool, rep: int, add) -> list[tuple[str, Callable[[], None]]]:
    """Every benchmark as ``(progress label, run)`` groups in the order they run; ``run()`` adds the
    group's rows through ``add``."""

    @cache
    def planar():  # the paper's arm, its law and one state: built by the first group that needs them
        arm, circle = paper_arm(), Circle((0.5, 0.0), 0.2)
        q, qd, a, Fc = (np.array(v) for v in ([2.2, 1.9], [0.3, -0.4], [0.1, 1.0], [-8.0, 3.0]))
        return SimpleNamespace(arm=arm, law=decoupling_law(arm, circle, curvature=True), q=q, qd=qd, a=a, Fc=Fc,
                               p=arm.as_array(), s=circle.cross_section().as_array())

    @cache
    def kernel():  # the planar law's generated kernel (SymPy)
        return {kk.name: kk for kk in units.generator("model").kernels(2)}["decoupling_law_circle"]

    def law_in_c(b: str) -> None:
        P = planar()
        values = {"q": P.q, "qd": P.qd, "a": P.a, "Fc": P.Fc, "arm": P.p, "surface": P.s, "opts": [1.0]}
        entry = planar_unit(b).entry("decoupling_law_circle")
        add(in_c(b), c_harness_ns(loader.source_dir(), f"hybrid_{b}", entry, values,
                                  200_000 if quick else 2_000_000, rep))

    def one_state() -> None:
        P = planar()
        add(ONE_STATE, _median_ns(lambda: P.law(P.q, P.qd, P.a, P.Fc), 20000, rep))

    def batched() -> None:
        law, N = planar().law, 100_000
        rng = np.random.default_rng(0)
        Q = np.column_stack([rng.uniform(-3, 3, N), rng.uniform(0.3, 2.8, N)])
        QD, A, FC = rng.normal(size=(N, 2)), rng.normal(size=(N, 2)), rng.normal(size=(N, 2))
        add(BATCHED, _median_ns(lambda: law(Q, QD, A, FC), 1, rep) / N)

    def numpy_law() -> None:
        P = planar()
        add(NUMPY_LAW, _median_ns(
            lambda: reference.decoupling_law("circle", P.q, P.qd, P.a, P.Fc, P.p, P.s, True), 2000, rep))

    def lambdified() -> None:
        import sympy as sp

        P, kern = planar(), kernel()
        fn = sp.lambdify([a.expr for a in kern.inputs], kern.outputs[0].expr, modules="numpy", cse=True)
        col = [v.reshape(-1, 1) for v in (P.q, P.qd, P.a, P.Fc, P.p, P.s, np.array([1.0]))]
        add("F* by SymPy lambdify (NumPy, CSE)", _median_ns(lambda: fn(*col), 2000, rep))

    def casadi_call() -> None:
        P = planar()
        cf = units.generator("casadi_backend").kernel_function(kernel())
        add("F* by a CasADi Function call", _median_ns(lambda: cf(P.q, P.qd, P.a, P.Fc, P.p, P.s, 1.0), 2000, rep))

    def pinocchio() -> None:
        P = planar()
        pin_ns = _pinocchio_ns(P.arm, P.q, P.qd, P.a, P.Fc, P.s, rep)
        if pin_ns is not None:
            add("F* by Pinocchio (crba, nle) + NumPy", pin_ns)

    dur = 0.2 if quick else 2.0

    def experiment(how: str) -> None:
        exp = paper_experiment(duration=dur)
        if how == "compiled":
            add(experiment_row(dur, how), _median_ns(lambda: simulate(exp), 1, 3 if quick else 9) / 1e6, "ms")
        else:
            add(experiment_row(dur, how), _median_ns(lambda: reference.simulate(exp), 1, 1 if quick else 3) / 1e6,
                "ms")

    def regenerate() -> None:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", "from hybrid.codegen.regenerate import expected_files; expected_files()"],
                       check=True, cwd=Path(__file__).resolve().parent.parent)
        add("regenerate from scratch (both backends, fresh process)", (time.perf_counter() - t0) * 1e3, "ms")

    def spatial(name: str, path: str, tip: str) -> None:
        spatial_law_benchmarks(name, path, tip, rep, quick, add)
        controller_benchmarks(name, path, tip, rep, quick, add)

    groups = [("import hybrid against import numpy, fresh processes",
               partial(import_benchmarks, 5 if quick else 21, add)),
              ("first use: the paper's simulate and paper command, fresh process and cache",
               partial(cold_benchmarks, quick, add)),
              *((f"F* in C ({b} backend)", partial(law_in_c, b)) for b in ("sympy", "casadi")),
              ("F* from Python, single state", one_state),
              ("F* from Python, batched", batched),
              ("F* in plain NumPy", numpy_law),
              ("F* by SymPy lambdify", lambdified),
              ("F* by a CasADi Function call", casadi_call),
              ("F* by Pinocchio + NumPy", pinocchio),
              ("paper experiment, compiled", partial(experiment, "compiled")),
              ("paper experiment, NumPy plant and controller", partial(experiment, "NumPy")),
              ("regenerate from scratch", regenerate)]
    groups += [(f"{name}: generation, compilation, terms in C, from Python and by Pinocchio",
                partial(robot_benchmarks, name, path, tip, rep, quick, add)) for name, (path, tip) in ROBOTS.items()]
    groups += [(f"{name}: the 6-D decoupling law in C, from Python, batched (both cores, one core), "
                "by Pinocchio + NumPy; the controller step", partial(spatial, name, path, tip))
               for name, (path, tip) in ROBOTS.items()]
    groups += [("paper runs: one through simulate, in the compiled loop, sweeps on every core",
                partial(sweep_benchmarks, quick, add)),
               ("3-D runs (UR5 on the sphere): one through simulate, in the compiled loop, a sweep on every core",
                partial(trace_benchmarks, quick, add)),
               ("the 3-D closed loop's generated operations per RK4 step", partial(loop_operation_benchmarks, add)),
               ("the standalone controller (generated C): each step call timed, code size, compile time",
                partial(standalone_benchmarks, quick, add))]
    return groups


def run_benchmarks(quick: bool = False, only: str | None = None) -> dict:
    """Every benchmark, or with ``only`` those of the groups whose progress label contains it (any
    case); returns ``{"machine": ..., "results": [{name, median, unit, ...}]}``."""
    rep = 3 if quick else 7
    results = []

    def add(name, ns, unit="ns", **extra):
        results.append({"name": name, "median": ns, "unit": unit, **extra})

    chosen = select_groups(benchmark_groups(quick, rep, add), only)
    for k, (label, run) in enumerate(chosen, 1):
        _progress(k, len(chosen), label)
        run()
    relative_ratios(results)
    mark_targets(results)
    return {"machine": _versions(), "quick": quick, "results": results}


def relative_ratios(results: list[dict]) -> None:
    """The ratio columns that compare rows of different groups (those of rows that ran)."""
    by = {r["name"]: r for r in results}
    if ONE_STATE in by:
        ours_py = by[ONE_STATE]["median"]
        for r in results:
            if r["name"].startswith("F* in plain") or r["name"].startswith("F* by"):
                r["ratio"] = f"{r['median'] / ours_py:.0f}x slower than one compiled call"
    comp = next((r for r in results if r["name"].startswith("paper experiment") and r["name"].endswith("compiled")),
                None)
    slow = next((r for r in results if r["name"].startswith("paper experiment") and r["name"].endswith("NumPy")), None)
    if comp and slow:
        slow["ratio"] = f"{slow['median'] / comp['median']:.0f}x slower than compiled"


def mark_targets(results: list[dict]) -> None:
    """Give each row that has a target the target and whether it is ``met``. A row that did not run has
    none, and neither has one whose target compares it with a row that did not run. The experiment's
    target is for the full run (2 s simulated): a quick run has no such row."""
    by = {r["name"]: r for r in results}
    comp, slow = experiment_row(2.0, "compiled"), experiment_row(2.0, "NumPy")
    # (row, target, met(row), the other rows it reads)
    targets = [*((in_c(b), "<= 60 ns", lambda r: r["median"] <= 60) for b in ("sympy", "casadi")),
               (ONE_STATE, "<= 1 us, >= 70x NumPy",
                lambda r: r["median"] <= 1000 and by[NUMPY_LAW]["median"] / r["median"] >= 70, NUMPY_LAW),
               (BATCHED, "<= 10 ns", lambda r: r["median"] <= 10),
               (comp, "<= 25 ms, >= 100x NumPy",
                lambda r: r["median"] <= 25 and by[slow]["median"] / r["median"] >= 100, slow),
               (IMPORT, "<= 2.5x import numpy", lambda r: r["ratio_value"] <= 2.5),
               (FIRST_SIMULATE, "<= 1.5 s", lambda r: r["median"] <= 1.5),
               (COLD_PAPER, "<= 8 s", lambda r: r["median"] <= 8)]
    robot_targets = [(f"panda: {TERMS_IN_C}", "<= 1 us", lambda r: r["median"] <= 1000),
                     (f"panda: {GEN_COMPILE}", "<= 30 s", lambda r: r["median"] <= 30),
                     (f"ur5: {LAW_IN_C}", "<= 0.6 us", lambda r: r["median"] <= 600),
                     (f"panda: {LAW_IN_C}", "<= 1.5 us", lambda r: r["median"] <= 1500),
                     (f"ur5: {LAW_ONE}", "<= 1.5 us, >= 20x Pinocchio + NumPy",
                      lambda r: r["median"] <= 1500 and r.get("speedup", 0) >= 20),
                     (f"ur5: {LAW_BATCHED}", "<= 0.5 us", lambda r: r["median"] <= 500),
                     (f"ur5: {LAW_BATCHED_ONE_CORE}", "<= 120 ns", lambda r: r["median"] <= 120),
                     (f"ur5: {STEP_ONE}", "<= 2 us", lambda r: r["median"] <= 2000),
                     (f"ur5: {STANDALONE_STEP}", "<= 0.6 us", lambda r: r["median"] <= 600),
                     (f"ur5: {STANDALONE_P999}", "<= 2x the median", lambda r: r["of_median"] <= 2),
                     (ONE_RUN, "<= 2.3 ms", lambda r: r["median"] <= 2.3),
                     (SWEEP_1000, "<= 1 s", lambda r: r["median"] <= 1),
                     (SWEEP_10000, "<= 2.8 s", lambda r: r["median"] <= 2.8),
                     (TRACE_ONE, "<= 25 ms", lambda r: r["median"] <= 25),
                     (SWEEP_3D, "<= 3 s", lambda r: r["median"] <= 3),
                     (LOOP_OPS, f"<= 2/3 of {LOOP_OPS_REFERENCE:,}",
                      lambda r: r["median"] <= 2 / 3 * LOOP_OPS_REFERENCE)]
    for name, target, ok, *reads in targets + robot_targets:
        if name in by and all(other in by for other in reads):
            by[name].update(target=target, met=bool(ok(by[name])))


#: the URDF arms of the robot benchmarks (files of the example-robot-data package) and their tips
ROBOTS = {"ur5": ("ur5_robot.urdf", "tool0"), "panda": ("panda.urdf", "panda_hand_tcp")}
TERMS_IN_C = "r, rotation, J, J'q', B, n in C, per call (robot_terms)"
LAW_IN_C = "6-D F* on a sphere in C, per call (curvature on)"
LAW_ONE = "6-D F* from Python, one state (law(q, qdot, a, Fc))"
LAW_BATCHED = "6-D F* from Python, batched, per state (N = 1e5, both cores)"
LAW_BATCHED_ONE_CORE = "6-D F* from Python, batched, per state (N = 1e5, one core)"
ONE_RUN = "paper run through hybrid.simulate (2 s simulated)"
SWEEP_1000 = "1,000 paper runs by hybrid.sweep (both cores)"
SWEEP_10000 = "10,000 paper runs by hybrid.sweep (both cores)"
LOOP_RUN = "paper run in the compiled closed loop, as SIMD lanes, one core, per run"
TRACE_ONE = "3-D run (UR5 on the sphere, 3 s simulated) through hybrid.simulate"
TRACE_RUN = "3-D run (UR5 on the sphere, 3 s simulated) in the compiled loop, as SIMD lanes, one core, per run"
SWEEP_3D = "1,000 3-D runs (UR5 on the sphere) by hybrid.sweep (both cores)"
LOOP_OPS = "3-D closed loop (UR5 on the sphere), generated operations per RK4 step"
#: LOOP_OPS before the body-frame algorithms: 4 x 2,593 (the plant's right-hand side) + 3,488 / 100 (the
#: controller step, once a sample of 100 steps) = 10,406.9. A reference count, like a baseline: the target
#: is a share of it
LOOP_OPS_REFERENCE = 10_407
STEP_IN_C = "controller step in C (measurement, six loops, law), per sample"
STEP_ONE = "controller step from Python, per sample (ctrl(t, q, qdot, Fc))"
SPHERE = (0.45, 0.1, 0.3, 0.15)
GEN_COMPILE = "generate + compile, fresh cache and process"


def _shipped_urdf(name: str) -> Path | None:
    try:
        from importlib.metadata import distribution

        dist = distribution("example-robot-data")
    except PackageNotFoundError:
        return None
    return next((Path(dist.locate_file(f)) for f in dist.files or () if str(f).endswith("/" + name)), None)


def _pinocchio_terms(pin, path: Path, robot, tip: str):
    """``terms(q, qd) -> (tip placement, J, J' q', B, n)`` by Pinocchio from Python, on its own
    reading of the URDF (joints off our chain held at 0, as Robot.from_urdf does)."""
    model = pin.buildModelFromUrdf(str(path))
    if model.nq != robot.n:
        extra = [model.getJointId(n) for n in model.names[1:] if n not in robot.joint_names]
        model = pin.buildReducedModel(model, extra, pin.neutral(model))
    data, fid, damping = model.createData(), model.getFrameId(tip), np.array(robot.damping)

    def terms(q, qd):
        pin.forwardKinematics(model, data, q, qd, np.zeros(robot.n))
        pin.updateFramePlacements(model, data)
        J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)
        acc = pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        return data.oMf[fid], J, acc, B, pin.nonLinearEffects(model, data, q, qd) + damping * qd

    return terms


def robot_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """Terms of a URDF arm: in C, from Python (one state, batched), by Pinocchio; generation time, code size."""

    path = _shipped_urdf(urdf)
    if path is None:
        print(f"  (skipped {name}: pip install example-robot-data)", file=sys.stderr)
        return
    script = (f"import numpy as np, hybrid; r = hybrid.Robot.from_urdf({str(path)!r}, tip={tip!r}); "
              "hybrid.arm_terms(r, np.zeros(r.n), np.zeros(r.n))")
    with tempfile.TemporaryDirectory() as cache:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", script], check=True, env={**os.environ, "HYBRID_CACHE_DIR": cache})
        add(f"{name}: {GEN_COMPILE}", time.perf_counter() - t0, "s")
    robot = Robot.from_urdf(path, tip=tip)
    unit = robot.unit
    source = (unit.folder / f"{unit.manifest['unit']}.c").read_text()
    add(f"{name}: generated C size", len(source.encode()) / 1024, "KiB", ratio=f"{source.count(chr(10))} lines")
    rng = np.random.default_rng(1)
    q, qd = rng.uniform(-1, 1, robot.n), rng.normal(size=robot.n)
    entry = unit.entry("robot_terms")
    add(f"{name}: {TERMS_IN_C}", c_harness_ns(unit.folder, unit.manifest["unit"], entry,
                                              {"q": q, "qd": qd, "robot": robot.as_array()},
                                              50_000 if quick else 500_000, rep))
    ours = _median_ns(lambda: arm_terms(robot, q, qd), 500 if quick else 5000, rep)
    add(f"{name}: the same from Python, one state (arm_terms)", ours)
    N = 10_000
    Q, QD = rng.uniform(-1, 1, (N, robot.n)), rng.normal(size=(N, robot.n))
    add(f"{name}: the same from Python, batched, per state (N = 1e4)", _median_ns(
        lambda: arm_terms(robot, Q, QD), 1, rep) / N)
    try:
        import pinocchio as pin
    except ImportError:
        return
    pinocchio_terms = _pinocchio_terms(pin, path, robot, tip)
    theirs = _median_ns(lambda: pinocchio_terms(q, qd), 500 if quick else 5000, rep)
    add(f"{name}: the same by Pinocchio from Python", theirs, ratio=f"{theirs / ours:.2f}x the time of arm_terms")


def _pinocchio_ns(arm, q, qd, a, Fc, s, rep):
    try:
        import pinocchio as pin
    except ImportError:
        return None
    model = pin.Model()
    parent = 0
    for i, (L, m, d, inertia) in enumerate([(0.0, arm.m1, arm.d1, arm.I1), (arm.L1, arm.m2, arm.d2, arm.I2)]):
        parent = model.addJoint(parent, pin.JointModelRZ(), pin.SE3(np.eye(3), np.array([L, 0, 0])), f"j{i}")
        model.appendBodyToJoint(parent, pin.Inertia(m, np.array([d, 0, 0]), np.diag([inertia] * 3)),
                                pin.SE3.Identity())
    frame = model.addFrame(pin.Frame("tip", parent, 0, pin.SE3(np.eye(3), np.array([arm.L2, 0, 0])),
                                     pin.FrameType.OP_FRAME))
    data = model.createData()
    V = np.array([arm.V1, arm.V2])

    def law():
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        n = pin.nonLinearEffects(model, data, q, qd) + V * qd
        pin.forwardKinematics(model, data, q, qd, np.zeros(2))
        J = pin.computeFrameJacobian(model, data, q, frame, pin.LOCAL_WORLD_ALIGNED)[:2]
        pin.updateFramePlacements(model, data)
        r = data.oMf[frame].translation[:2]
        Jdqd = pin.getFrameClassicalAcceleration(model, data, frame, pin.LOCAL_WORLD_ALIGNED).linear[:2]
        rd = J @ qd
        R, Rd = reference.frame("circle", r, rd, s)
        Jinv = np.linalg.inv(J)
        Bo = Jinv.T @ B @ Jinv
        return Bo @ R.T @ (a - Rd @ rd) + Jinv.T @ n - Bo @ Jdqd - Fc

    return _median_ns(law, 2000, rep)


def _number(v: float) -> str:
    """A median as the table shows it: four significant digits, a count of 10,000 or more in full."""
    return f"{v:.0f}" if 1e4 <= abs(v) < 1e9 else f"{v:.4g}"


def format_table(report: dict) -> str:
    rows = report["results"]
    w = max((len(r["name"]) for r in rows), default=len("benchmark"))
    t = max((len(r.get("target", "")) for r in rows), default=0) + 6
    lines = [f"{'benchmark':<{w}}  {'median':>13}  {'target':<{t}}  ratio"]
    for r in rows:
        target = f"{r['target']}: {'met' if r['met'] else 'MISSED'}" if "target" in r else ""
        lines.append(f"{r['name']:<{w}}  {_number(r['median']):>9} {r['unit']:<3}  {target:<{t}}  "
                     f"{r.get('ratio', '')}")
    m = report["machine"]
    lines.append(f"\n{m.get('cpu')}, {m.get('cores')} cores, {m.get('simd') or 'no'} SIMD | Python {m['python']} | "
                 f"numpy {m.get('numpy')} | {m['cc']}")
    return "\n".join(lines)


DESCRIPTION = ("Time the generated law, the runner and alternatives. Medians over repeated runs, with "
               "ratios computed within the same run and each target said met or missed; timings are information, "
               "never pass/fail. Takes minutes (--quick: fewer repeats and a shorter experiment).")


def add_parser(sub) -> None:
    p = common.command(sub, "bench", DESCRIPTION, _run)
    p.add_argument("--quick", action="store_true", help="fewer repeats, a shorter experiment")
    p.add_argument("--only", metavar="SUBSTRING",
                   help="run only the benchmark groups whose progress label contains SUBSTRING (any case)")
    p.add_argument("--json", metavar="FILE", help="also write the results as JSON to this file")
    p.add_argument("--force", action="store_true", help="let --json replace an existing file")
    common.add_verbose(p)


def _run(args) -> int:

    if args.json is not None and not args.json.strip():
        raise HybridError("--json needs a file name")
    if args.json and Path(args.json).is_dir():
        raise HybridError(f"--json {args.json} is a folder; give a file name")
    if args.json and Path(args.json).exists() and not args.force:
        raise HybridError(f"--json {args.json} exists; choose another name or add --force to replace it")
    report = run_benchmarks(args.quick, args.only)
    print(format_table(report))
    if args.json:

        files.write_text(Path(args.json), json.dumps(report, indent=2) + "\n", overwrite=True)
    return 0


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


def alone_is_bitwise(law, batch: tuple[np.ndarray, ...], rows: tuple[int, ...] | None = None) -> bool:
    """Whether ``law`` gives each of ``rows`` of the per-state arrays ``batch`` alone (a batch of one)
    the same bits as inside the whole batch (default rows: the first, second, middle (where two cores
    split it) and last)."""
    N = len(batch[0])
    whole = law(*batch)
    for i in sorted(set(rows if rows is not None else (0, 1, N // 2, N - 1))):
        alone = law(*(x[i:i + 1] for x in batch))
        if alone.shape[0] != 1 or alone[0].tobytes() != whole[i].tobytes():
            return False
    return True


def spatial_law_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """The general law of conventions §9 for a URDF arm on a sphere: in C, from Python, batched,
    against Pinocchio + NumPy; the generated operation count."""
    kernel_function = units.generator("casadi_backend").kernel_function
    law_kernels = units.generator("task_law").law_kernels

    path = _shipped_urdf(urdf)
    if path is None:
        return
    robot = Robot.from_urdf(path, tip=tip)
    sphere = Sphere(SPHERE[:3], SPHERE[3])
    law = decoupling_law(robot, sphere, curvature=True)
    unit = units.law_unit(robot.chain, robot.name, sphere.spec(), law.axes)
    rng = np.random.default_rng(2)
    q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5][:robot.n])
    qd, a, Fc = rng.normal(0, 0.5, robot.n), rng.normal(size=6), rng.normal(0, 5, 6)
    ops = kernel_function(law_kernels(robot.chain, sphere.spec(), law.axes)[1]).n_instructions()
    values = {"q": q, "qd": qd, "a": a, "Fc": Fc, "tau0": np.zeros(robot.n), "robot": robot.as_array(),
              "surface": sphere.as_array(), "e": [0.0, 0.0, 1.0], "opts": [1.0]}
    in_c = c_harness_ns(unit.folder, unit.manifest["unit"], unit.entry("decoupling_law"), values,
                        50_000 if quick else 500_000, rep)
    add(f"{name}: {LAW_IN_C}", in_c, ratio=f"{ops} generated operations")
    ours = _median_ns(lambda: law(q, qd, a, Fc), 2000 if quick else 20000, rep)
    N = 10_000 if quick else 100_000
    Q, QD = np.tile(q, (N, 1)) + rng.normal(0, 0.05, (N, robot.n)), rng.normal(0, 0.5, (N, robot.n))
    A, FC = rng.normal(size=(N, 6)), rng.normal(0, 5, (N, 6))
    batched = _median_ns(lambda: law(Q, QD, A, FC), 1, rep) / N
    one_core = on_one_core(lambda: _median_ns(lambda: law(Q, QD, A, FC), 1, rep) / N)
    bitwise = alone_is_bitwise(law, (Q, QD, A, FC))

    def batched_rows():
        add(f"{name}: {LAW_BATCHED}", batched, bitwise=bitwise,
            ratio=f"bitwise: {'yes' if bitwise else 'no'} (a state alone in a batch of one, against the same state "
                  "inside this batch)")
        if one_core is not None:
            add(f"{name}: {LAW_BATCHED_ONE_CORE}", one_core,
                ratio=f"{one_core / in_c:.2f}x a call in C, {one_core / batched:.2f}x the time on both cores")

    try:
        import pinocchio as pin
    except ImportError:
        add(f"{name}: {LAW_ONE}", ours)
        batched_rows()
        return
    pinocchio_terms = _pinocchio_terms(pin, path, robot, tip)

    def pinocchio_law():
        placement, J, Jdqd, B, n = pinocchio_terms(q, qd)
        R, Rd = reference.spatial_frame(sphere, placement.translation, J[:3] @ qd, (0.0, 0.0, 1.0))
        return reference.spatial_decoupling_law(J, Jdqd, B, n, R, Rd, qd, a, Fc, np.zeros(robot.n), range(6), True)

    theirs = _median_ns(pinocchio_law, 300 if quick else 3000, rep)
    add(f"{name}: {LAW_ONE}", ours, speedup=theirs / ours, ratio=f"{theirs / ours:.0f}x faster than Pinocchio + NumPy")
    batched_rows()
    add(f"{name}: 6-D F* by Pinocchio (crba, nle, frame terms) + NumPy", theirs)


def controller_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """One sample of :class:`hybrid.Controller` (task scheme, six axes, step references) on a sphere:
    in C, and from Python."""
    kernel_function = units.generator("casadi_backend").kernel_function
    controller_kernels = units.generator("controller_step").controller_kernels

    path = _shipped_urdf(urdf)
    if path is None:
        return
    robot = Robot.from_urdf(path, tip=tip)
    sphere = Sphere(SPHERE[:3], SPHERE[3])
    # the same sample again and again: no sample clock to keep
    ctrl = Controller(robot, sphere, force_reference=Step(10.0, 20.0, 0.5), velocity_reference=Step(0.15, 0.3, 1.5),
                      timing_tolerance=None)
    q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5][:robot.n])
    qd, Fc = np.full(robot.n, 0.1), np.array([1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    ctrl._native()  # a controller builds its step at its first sample: built here, not timed
    step = ctrl._step  # the function the controller binds
    m = len(ctrl.axes)
    values = {"q": q, "qd": qd, "Fc": Fc, "integrals": np.zeros(2 * m), "last_torque": np.zeros(robot.n + 1),
              "filter": np.zeros(13), "estimate": np.zeros(10),
              "t": [0.3], "yd_extra": np.zeros(m), "yd_rate": np.zeros(m), "target": np.zeros(9),
              **ctrl.step_inputs()}
    ops = kernel_function(controller_kernels(robot.chain, sphere.spec(), ctrl.axes)[0]).n_instructions()
    add(f"{name}: {STEP_IN_C}", c_harness_ns(step.unit.folder, step.unit.manifest["unit"], step.entry, values,
                                             50_000 if quick else 500_000, rep), ratio=f"{ops} generated operations")
    add(f"{name}: {STEP_ONE}", _median_ns(lambda: ctrl(0.3, q, qd, Fc), 2000 if quick else 20000, rep))


def sweep_benchmarks(quick: bool, add) -> None:
    """One paper run through ``simulate``, against its share of a lanes batch; the compiled loop per
    run on one core; sweeps of 1,000 and 10,000 paper runs over every core (with ``quick``: 100 runs,
    the totals scaled)."""

    exp = paper_experiment()
    for _ in range(WARM_UP):
        simulate(exp)
    one = _median_ns(lambda: simulate(exp), 1, 15 if quick else 61) / 1e6
    prepared = [closed_loop.prepare(apply(exp, {"model_error": m})) for m in np.linspace(0.0, 0.5, 128)]
    closed_loop.run(prepared)  # the lanes build, loaded before it is timed
    lanes = prepared[0].loop.lanes
    share = _median_ns(lambda: closed_loop.run(prepared), 1, 3 if quick else 7) / 1e6 / len(prepared)
    add(ONE_RUN, one, "ms", ratio=f"{one / share:.1f}x the per-run share of a lanes batch", of_share=one / share)
    add(LOOP_RUN, share, "ms", ratio=f"{lanes} runs a group of lanes")
    # the sweeps' own mix of runs in lanes (both schemes, both frictions): their bound
    mix = [closed_loop.prepare(apply(exp, {"model_error": m, "controller": c, "contact.friction": f}))
           for m in np.linspace(0.0, 0.5, 32) for c in ("task", "khatib") for f in (0.1, 0.2)]
    closed_loop.run(mix)
    mix_share = _median_ns(lambda: closed_loop.run(mix), 1, 3 if quick else 5) / 1e6 / len(mix)
    for total, name in ((1000, SWEEP_1000), (10000, SWEEP_10000)):
        n = 100 if quick else total
        grid = {"model_error": list(np.linspace(0.0, 0.5, n // 4)), "controller": ["task", "khatib"],
                "contact.friction": [0.1, 0.2]}
        t0 = time.perf_counter()
        table = sweep(exp, grid)
        per_run = (time.perf_counter() - t0) / len(table)
        _add_sweep(add, name, total, per_run, len(table), mix_share / 1e3)


def trace_benchmarks(quick: bool, add) -> None:
    """The 3-D experiment (UR5 on the sphere): one run through ``simulate``, against its share of a
    lanes batch; the compiled loop per run on one core; a sweep of 1,000 runs over every core (with
    ``quick``: 100, the total scaled)."""
    trace = [closed_loop.prepare(tracing_experiment(model_error=m)) for m in np.linspace(0.0, 0.3, 16)]
    closed_loop.run(trace)  # the lanes build, loaded before it is timed
    exp = trace[0].experiment
    for _ in range(WARM_UP):  # the build for one run at a time, likewise
        simulate(exp)
    one = _median_ns(lambda: simulate(exp), 1, 3 if quick else 15) / 1e6
    share = _median_ns(lambda: closed_loop.run(trace), 1, 3) / 1e6 / len(trace)
    add(TRACE_ONE, one, "ms", ratio=f"{one / share:.1f}x the per-run share of a lanes batch", of_share=one / share)
    add(TRACE_RUN, share, "ms", ratio=f"{trace[0].loop.lanes} runs a group of lanes")
    n = 100 if quick else 1000
    grid = {"model_error": list(np.linspace(0.0, 0.3, n // 4)), "contact.friction": [0.1, 0.2], "F_d": [15.0, 20.0]}
    t0 = time.perf_counter()
    table = sweep(tracing_experiment(), grid)
    per_run = (time.perf_counter() - t0) / len(table)
    _add_sweep(add, SWEEP_3D, 1000, per_run, len(table), share / 1e3)


def _add_sweep(add, name: str, total: int, per_run: float, measured: int, share: float) -> None:
    """A sweep's row: ``total`` runs at ``per_run`` [s] each (``measured`` timed), against the bound
    of its lanes, a run's ``share`` [s] of a group of lanes on one core over the cores a sweep runs on
    (what is left is Python, forking, the table)."""
    of_bound = per_run / (share / workers())
    add(name, per_run * total, "s", of_bound=of_bound,
        ratio=f"{per_run * 1e3:.2f} ms a run, measured on {measured} runs; {of_bound:.2f}x the lanes bound "
              f"({share * 1e3:.2f} ms a run over {workers()} cores)")


def loop_operations(exp) -> dict:
    """The generated operations (CasADi's ``n_instructions``) of ``exp``'s compiled closed loop
    (:func:`hybrid.native.units.loop_unit`'s kernels): ``rhs``, the plant's state derivative (4
    evaluations an RK4 step); ``step``, the controller step (one a sample); ``steps_per_sample``; and
    ``per_step``, an RK4 step's count with its share of the sample's step: 4 rhs + step / steps_per_sample."""
    kernel_function = units.generator("casadi_backend").kernel_function
    spec = units.loop_spec(exp.plant_class.loop_plant(exp), exp.build_controller().step_variant())
    rhs, step = (kernel_function(k).n_instructions() for k in (spec.rhs, spec.step))
    per = exp.steps_per_sample
    return {"rhs": rhs, "step": step, "steps_per_sample": per, "per_step": 4 * rhs + step / per}


def loop_operation_benchmarks(add) -> None:
    """The 3-D experiment's closed loop (UR5 on the sphere): its generated operations per RK4 step,
    against the count before the body-frame algorithms (:data:`LOOP_OPS_REFERENCE`)."""
    ops = loop_operations(tracing_experiment())
    add(LOOP_OPS, ops["per_step"], "ops",
        ratio=(f"rhs {ops['rhs']:,} ops x 4 + step {ops['step']:,} ops / {ops['steps_per_sample']} steps a sample; "
               f"{ops['per_step'] / LOOP_OPS_REFERENCE:.2f}x the count before the body-frame algorithms"),
        **{k: ops[k] for k in ("rhs", "step", "steps_per_sample")})


# --------------------------------------------------------------------------- the standalone controller

#: the arms of the standalone-controller rows: their experiments (the controller and a run to replay)
STANDALONE = {"paper": paper_experiment, "ur5": tracing_experiment, "panda": panda_experiment}
STANDALONE_STEP = "standalone controller step in C (NAME_controller_step), per call"
STANDALONE_P999 = "standalone controller step in C, p99.9 of the calls"
STANDALONE_SIZE = "standalone controller, .text of the compiled object"
STANDALONE_COMPILE = "standalone controller, compile time of the generated C"

DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "%(prefix)s.h"
#define W (2 * %(PREFIX)s_NQ + 6 + %(target)d)  /* a sample: q, qd, wrench (and the desired point) */
static long long now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}
/* argv: samples file, number of samples, sample time, calls, output file: the calls' durations [ns],
   then those of back-to-back clock reads (the timer's own cost) */
int main(int argc, char **argv) {
    long n, calls, i, k, warm, pairs = 100000;
    double T, *s, tau[%(PREFIX)s_NQ], sink = 0.0;
    long long *d, t0, t1;
    %(prefix)s_controller c;
    FILE *f;
    int st;
    if (argc != 6) return 2;
    n = atol(argv[2]); T = atof(argv[3]); calls = atol(argv[4]);
    s = malloc(sizeof(double) * W * n);
    d = malloc(sizeof(long long) * (calls + pairs));
    if (!s || !d || !(f = fopen(argv[1], "rb")) || fread(s, sizeof(double) * W, n, f) != (size_t)n) return 2;
    fclose(f);
    memset(d, 0, sizeof(long long) * (calls + pairs));  /* the pages touched before timing */
    for (i = 0; i < pairs; ++i) { t0 = now_ns(); t1 = now_ns(); d[calls + i] = t1 - t0; }
    %(prefix)s_controller_init(&c);
    /* one pass through the samples untimed, then the timed calls. Each pass is the recorded run again:
       a new run (reset, untimed) from t = 0, t advancing by T every call, so every call is on time */
    warm = n;
    for (i = -warm; i < calls; ++i) {
        k = (i + warm) %% n;
        const double *x = s + W * k;
        double t = (double)k * T;
        if (k == 0) %(prefix)s_controller_reset(&c);
%(set_target)s
        t0 = now_ns();
        st = %(prefix)s_controller_step(&c, t, x, x + %(PREFIX)s_NQ, x + 2 * %(PREFIX)s_NQ, tau);
        t1 = now_ns();
        if (st != %(PREFIX)s_OK) {
            fprintf(stderr, "call %%ld (sample %%ld, t = %%.6f s): status %%s\n", i, k, t, %(prefix)s_status_name(st));
            return 3;
        }
        if (i >= 0) d[i] = t1 - t0;
        sink += tau[0];
    }
    if (!(f = fopen(argv[5], "wb")) || fwrite(d, sizeof(long long), calls + pairs, f) != (size_t)(calls + pairs))
        return 2;
    fclose(f);
    fprintf(stderr, "%%g\n", sink);
    return 0;
}
"""


def recorded_samples(exp) -> tuple[np.ndarray, bool]:
    """The control samples of a simulated run of ``exp``, one row each: q, qd, the sensor's wrench,
    and (when the controller follows a path) the desired point the caller writes into ``target``;
    and whether that last part is there."""
    run, plant, ctrl = simulate(exp), exp.plant(), exp.build_controller()
    nq, every = plant.nq, exp.steps_per_sample
    rows = []
    for k in range(exp.n_samples):
        x = run.state[k * every]
        row = [x[:nq], x[nq:2 * nq], plant.sensor_wrench(x)]
        if ctrl.path is not None:
            row.append(ctrl._desired(k * exp.sample_time))
        rows.append(np.concatenate(row))
    return np.array(rows), ctrl.path is not None


def text_bytes(obj: Path) -> int:
    """The size of the code in an ELF object: its ``.text`` sections (``.text``, ``.text.hot``, ...) [bytes]."""
    data = obj.read_bytes()
    if data[:4] != b"\x7fELF":
        raise HybridError(f"{obj.name} is not an ELF object")
    wide, order = data[4] == 2, "<" if data[5] == 1 else ">"
    if wide:
        shoff, = struct.unpack_from(order + "Q", data, 0x28)
        shentsize, shnum, shstrndx = struct.unpack_from(order + "HHH", data, 0x3A)
    else:
        shoff, = struct.unpack_from(order + "I", data, 0x20)
        shentsize, shnum, shstrndx = struct.unpack_from(order + "HHH", data, 0x2E)

    def section(i):  # (name offset, offset, size)
        base = shoff + i * shentsize
        if wide:
            name, = struct.unpack_from(order + "I", data, base)
            off, size = struct.unpack_from(order + "QQ", data, base + 0x18)
        else:
            name, = struct.unpack_from(order + "I", data, base)
            off, size = struct.unpack_from(order + "II", data, base + 0x10)
        return name, off, size

    strtab = section(shstrndx)[1]
    total = 0
    for i in range(shnum):
        name, _, size = section(i)
        label = data[strtab + name:data.index(b"\0", strtab + name)].decode()
        if label == ".text" or label.startswith(".text."):
            total += size
    return total


def standalone_step(folder: Path, prefix: str, samples: np.ndarray, target: bool, sample_time: float,
                    flags: list[str], calls: int) -> dict:
    """Compile the generated controller ``folder/prefix.c`` with ``flags`` (timed), and time ``calls``
    calls of its step, one by one, replaying ``samples`` on the sample clock. Returns the compile time
    [s], the object's ``.text`` [bytes], the timer's overhead and the calls' median, p99, p99.9 and
    maximum [ns], the overhead subtracted."""
    cc, _ = compiler.compiler()
    tag = "".join(c for c in "_".join(flags) if c.isalnum() or c == "_")
    obj, exe, out = (folder / f"{prefix}_{tag}{ext}" for ext in (".o", "", ".durations"))
    t0 = time.perf_counter()
    subprocess.run([cc, *flags, "-c", str(folder / f"{prefix}.c"), "-o", str(obj)], check=True, capture_output=True)
    compile_s = time.perf_counter() - t0
    nq = (samples.shape[1] - 6 - (9 if target else 0)) // 2
    set_target = (f"        memcpy(c.target, x + {2 * nq + 6}, sizeof c.target);" if target else "")
    driver = folder / f"{prefix}_driver.c"
    driver.write_text(DRIVER % {"prefix": prefix, "PREFIX": prefix.upper(), "target": 9 if target else 0,
                                "set_target": set_target})
    subprocess.run([cc, *flags, f"-I{folder}", str(driver), str(obj), "-o", str(exe), "-lm"],
                   check=True, capture_output=True)
    data = folder / f"{prefix}_samples.bin"
    np.ascontiguousarray(samples, "<f8").tofile(data)
    proc = subprocess.run([str(exe), str(data), str(len(samples)), repr(sample_time), str(calls), str(out)],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise HybridError(f"the {prefix} controller's timing driver failed (exit {proc.returncode}): "
                          f"{proc.stderr.strip() or 'no message'}")
    d = np.fromfile(out, "<i8")
    timer = float(np.median(d[calls:]))
    step = d[:calls] - timer
    p50, p99, p999 = np.percentile(step, [50, 99, 99.9], method="higher")
    return {"compile_s": compile_s, "text": text_bytes(obj), "timer_ns": timer, "median": float(p50),
            "p99": float(p99), "p99.9": float(p999), "max": float(step.max())}


def _spread(r: dict) -> str:
    return f"p99 {r['p99']:.0f}, p99.9 {r['p99.9']:.0f}, max {r['max']:.0f} ns"


def standalone_benchmarks(quick: bool, add) -> None:
    """The controller as standalone C (:meth:`hybrid.Controller.generate`) for each arm of ``STANDALONE``:
    its step's per-call times replaying a recorded run (median, p99, p99.9, maximum), its code size and
    compile time, with the runtime's flags and with plain ``-O2``. With ``quick``: the paper's arm, 1e4 calls."""
    calls = 10_000 if quick else 1_000_000
    bench_flags = [f for f in compiler.flags(compiler.compiler()[1]) if f != "-fPIC"]
    builds = {" ".join(bench_flags): bench_flags, "-O2": ["-O2"]}
    for name, factory in STANDALONE.items():
        if quick and name != "paper":
            continue
        exp = factory()
        samples, target = recorded_samples(exp)
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            exp.build_controller().generate(folder, name)
            got = {label: standalone_step(folder, name, samples, target, exp.sample_time, flags, calls)
                   for label, flags in builds.items()}
        (label, main), (other_label, other) = got.items()
        note = (f"{calls:,} calls, each timed alone by clock_gettime less the timer's own {main['timer_ns']:.0f} ns "
                f"(back-to-back reads); a {len(samples)}-sample run replayed, reset between passes; {label}")

        add(f"{name}: {STANDALONE_STEP}", main["median"], ratio=f"{_spread(main)}; {note}",
            **{k: main[k] for k in ("p99", "p99.9", "max", "timer_ns")}, calls=calls, flags=label)
        add(f"{name}: {STANDALONE_P999}", main["p99.9"], ratio=f"{main['p99.9'] / main['median']:.2f}x the median",
            of_median=main["p99.9"] / main["median"])
        add(f"{name}: {STANDALONE_STEP}, {other_label}", other["median"], ratio=_spread(other),
            **{k: other[k] for k in ("p99", "p99.9", "max", "timer_ns")}, calls=calls, flags=other_label)
        add(f"{name}: {STANDALONE_SIZE}", main["text"] / 1024, "KiB",
            ratio=f"{main['text']:,} bytes; {other_label}: {other['text']:,} bytes", bytes=main["text"],
            bytes_other=other["text"])
        add(f"{name}: {STANDALONE_COMPILE}", main["compile_s"], "s",
            ratio=f"{label}; {other_label}: {other['compile_s']:.2f} s", other_s=other["compile_s"])
