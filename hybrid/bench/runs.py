"""The paper's runs: one through ``simulate`` against its share of a batch in the compiled loop,
sweeps on every core, the same for the 3-D experiment (UR5 on the sphere), and the 3-D closed loop's
generated operations."""

from __future__ import annotations

import time

import numpy as np

from hybrid.bench.harness import WARM_UP, median_ns
from hybrid.bench.targets import (
    LOOP_OPS,
    LOOP_OPS_REFERENCE,
    LOOP_RUN,
    ONE_RUN,
    SWEEP_3D,
    SWEEP_1000,
    SWEEP_10000,
    TRACE_ONE,
    TRACE_RUN,
)
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.native import generator, units
from hybrid.native.binding import workers
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import simulate
from hybrid.sweeps import apply, sweep


def paper_sweep_grid(runs: int) -> dict[str, list]:
    """The paper sweeps' grid of ``runs`` runs: the model error, both schemes, two frictions."""
    return {"model_error": list(np.linspace(0.0, 0.5, runs // 4)), "controller": ["task", "khatib"],
            "contact.friction": [0.1, 0.2]}


def sweep_benchmarks(quick: bool, add) -> None:
    """One paper run through ``simulate``, against its share of a lanes batch; the compiled loop per
    run on one core; sweeps of 1,000 and 10,000 paper runs over every core (with ``quick``: 100 runs,
    the totals scaled)."""

    exp = paper_experiment()
    for _ in range(WARM_UP):
        simulate(exp)
    one = median_ns(lambda: simulate(exp), 1, 15 if quick else 61) / 1e6
    prepared = [closed_loop.prepare(apply(exp, {"model_error": m})) for m in np.linspace(0.0, 0.5, 128)]
    closed_loop.run(prepared)  # the lanes build, loaded before it is timed
    lanes = prepared[0].loop.lanes
    share = median_ns(lambda: closed_loop.run(prepared), 1, 3 if quick else 7) / 1e6 / len(prepared)
    add(ONE_RUN, one, "ms", ratio=f"{one / share:.1f}x the per-run share of a lanes batch", of_share=one / share)
    add(LOOP_RUN, share, "ms", ratio=f"{lanes} runs a group of lanes")
    # the sweeps' own mix of runs in lanes (both schemes, both frictions): their bound
    mix = [closed_loop.prepare(apply(exp, {"model_error": m, "controller": c, "contact.friction": f}))
           for m in np.linspace(0.0, 0.5, 32) for c in ("task", "khatib") for f in (0.1, 0.2)]
    closed_loop.run(mix)
    mix_share = median_ns(lambda: closed_loop.run(mix), 1, 3 if quick else 5) / 1e6 / len(mix)
    for total, name in ((1000, SWEEP_1000), (10000, SWEEP_10000)):
        n = 100 if quick else total
        grid = paper_sweep_grid(n)
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
    one = median_ns(lambda: simulate(exp), 1, 3 if quick else 15) / 1e6
    share = median_ns(lambda: closed_loop.run(trace), 1, 3) / 1e6 / len(trace)
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
    kernel_function = generator.api().kernel_function
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
