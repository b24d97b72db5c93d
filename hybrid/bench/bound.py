"""The runs in lanes against the machine's floating-point bound: the measured peak (:mod:`hybrid.bench.peak`),
the loops' operations by kind (the generator's census, :func:`hybrid.codegen.census.loop_census`) and
what a run takes.

A run's floating-point bound is the sum over the kinds of its operations of their count over the kind's
peak throughput, per lane: each kind at its peak, one after the other. Where the machine runs kinds side by
side (its pairs say which), the busiest unit's share is a lower bound still: the unit bound. The chain
bound is the longest path of latencies through an RK4 step (its four stages, each waiting on the last)
times the steps, over the lanes of a group: what one group of lanes takes if nothing hides its latencies.
"""

from __future__ import annotations

import statistics
import time

import numpy as np

from hybrid.bench.harness import on_one_core
from hybrid.bench.peak import KINDS, PAIRS, machine_peak, shared
from hybrid.bench.targets import bound_row, census_row, peak_row
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.native import compiler, generator, units
from hybrid.simulation import closed_loop
from hybrid.sweeps import apply

#: the loops measured: what a row calls it, ``n`` of its runs (a group of lanes is timed), and the share of
#: its calls of tanh where a lane's argument is below 20 (the longer path): the paper's one tanh is the
#: contact's friction, sliding (callgrind: 0.1 calls of the longer path per RK4 step); the UR5's seven (six
#: joints' Coulomb friction near rest and the contact's) all take it (28 calls per step)
LOOPS = {
    "paper": (lambda n: [closed_loop.prepare(apply(paper_experiment(), {"model_error": m}))
                         for m in np.linspace(0.0, 0.5, n)], 0.0),
    "3-D": (lambda n: [closed_loop.prepare(tracing_experiment(model_error=m)) for m in np.linspace(0.0, 0.3, n)], 1.0)}


def lane_costs(peak: dict) -> dict[str, float]:
    """Each kind's time at its peak [ns per operation per lane]; a comparison and a select each half of
    the peak's pair of them."""
    lanes = peak["lanes"]
    cost = {k: peak["kinds"][k][0] / lanes for k in KINDS}
    cost["compare"] = cost["select"] = cost["select"] / 2
    return cost


def units_of(peak: dict) -> list[tuple[str, ...]]:
    """The kinds that share a unit, by the peak's pairs (a product with the fused multiply-adds always):
    each a tuple; comparisons, selects and bitwise operations, which run on any of several, in none."""
    groups = [{"fma", "mul"}, {"add"}, {"div"}, {"sqrt"}]
    for a, b in PAIRS:
        if shared(peak, a, b) > 0.5:
            ga, gb = (next(g for g in groups if k in g) for k in (a, b))
            if ga is not gb:
                ga |= gb
                groups.remove(gb)
    return [tuple(k for k in ("fma", "mul", "add", "div", "sqrt") if k in g) for g in groups]


def bounds(counts: dict, chain: float, steps: int, peak: dict) -> dict:
    """A run's bounds [ms] from its ``counts`` per RK4 step by kind, its ``chain`` per step [ns] and its
    ``steps``: ``sum`` (each kind at its peak in turn), ``unit`` (the busiest unit) and ``chain`` (a group's
    latencies, over its lanes); ``shares``, each kind's part of ``sum``; ``busiest``, the kinds of the
    busiest unit. The C library's calls lane by lane (none in the loops) are not in them."""
    cost = lane_costs(peak)
    per_kind = {k: counts.get(k, 0) * cost[k] for k in cost}
    total = sum(per_kind.values())
    unit_time = {u: sum(per_kind[k] for k in u) for u in units_of(peak)}
    busiest = max(unit_time, key=unit_time.get)
    return {"sum": steps * total / 1e6, "unit": steps * unit_time[busiest] / 1e6,
            "chain": steps * chain / peak["lanes"] / 1e6, "busiest": busiest,
            "shares": {k: t / total for k, t in per_kind.items() if t > 0}}


def census_of(prepared, peak: dict, tanh_below: float) -> dict:
    """The generator's census of ``prepared``'s loop (the first run's) per RK4 step, its chain in ns from
    the peak's latencies, and the steps of a run."""
    exp = prepared.experiment
    plant, variant = prepared.loop.key
    spec = units.loop_spec(plant, dict(variant))
    cycle = peak["cycle"]
    latency = {k: peak["kinds"][k][1] for k in ("fma", "mul", "add", "div", "sqrt")} | {"cycle": cycle}
    gcc = compiler.is_gcc(compiler.compiler()[1])
    census = generator.api().loop_census(spec, exp.steps_per_sample, gcc, latency, tanh_below)
    return census | {"steps": exp.n_samples * exp.steps_per_sample}


def peak_benchmarks(quick: bool, add) -> dict:
    """The machine's peak at the lanes' width, a row per kind; returns the peak."""
    peak = machine_peak(repeat=11 if quick else 41)
    lanes, cycle = peak["lanes"], peak["cycle"]
    beside = {b: a for a, b in PAIRS}
    for kind in KINDS:
        many, one = peak["kinds"][kind]
        text = (f"{lanes} lanes: {many:.3f} ns a vector operation ({many / cycle:.2f} cycles), "
                f"{lanes / many:.1f} per ns; latency {one:.2f} ns ({one / cycle:.1f} cycles)")
        if kind in beside:
            other = beside[kind]
            text += (f"; beside {other}: {'shares its unit' if shared(peak, other, kind) > 0.5 else 'its own unit'} "
                     f"({2 * peak['kinds'][f'{other}_{kind}'][0] / cycle:.1f} cycles a pair)")
        add(peak_row(kind), many / lanes, "ns", ratio=text, cycles=many / cycle, latency_ns=one)
    return peak


def _run_ms(groups: dict[str, list], repeat: int) -> dict[str, float]:
    """Each loop's time a run [ms] on one core: one group of lanes a timing (short, so that fewer are
    interrupted on a shared machine), the loops in turns, the median of ``repeat`` timings each."""
    times: dict[str, list[float]] = {name: [] for name in groups}
    one = {name: runs[:runs[0].loop.lanes] for name, runs in groups.items()}  # one group each

    def measure() -> float:
        for _ in range(repeat):
            for name, runs in one.items():
                t0 = time.perf_counter()
                closed_loop.run(runs)
                times[name].append((time.perf_counter() - t0) / len(runs) * 1e3)
        return 0.0

    if on_one_core(measure) is None:
        measure()
    return {name: statistics.median(t) for name, t in times.items()}


def bound_benchmarks(quick: bool, add) -> None:
    """The peak's rows, then for each of :data:`LOOPS` its census (a row: its vector operations per RK4 step)
    and a run in lanes against its floating-point bound (a row: the run over the bound)."""
    peak = peak_benchmarks(quick, add)
    groups = {name: make(max(peak["lanes"], 2)) for name, (make, _) in LOOPS.items()}  # a group of lanes
    for runs in groups.values():
        closed_loop.run(runs)  # built and loaded before it is timed
    taken = _run_ms(groups, 5 if quick else 41)
    for name, (_, below) in LOOPS.items():
        census = census_of(groups[name][0], peak, below)
        counts = census["counts"]
        b = bounds(counts, census["chain"], census["steps"], peak)
        kinds = ", ".join(f"{k} {v:,.1f}" for k, v in counts.items() if v)
        add(census_row(name), census["total"], "ops",
            ratio=f"{kinds}; chain {census['chain'] / peak['cycle']:,.0f} cycles a step", counts=counts,
            chain_ns=census["chain"])
        run = taken[name]
        shares = ", ".join(f"{k} {s:.0%}" for k, s in sorted(b["shares"].items(), key=lambda x: -x[1]) if s >= 0.01)
        add(bound_row(name), run / b["sum"], "x", run_ms=run, **{f"{k}_ms": b[k] for k in ("sum", "unit", "chain")},
            ratio=(f"{run:.3f} ms a run against {b['sum']:.3f} ms ({shares}); {run / b['unit']:.2f}x the busiest "
                   f"unit's {b['unit']:.3f} ms ({' + '.join(b['busiest'])}); the chain of one group "
                   f"{b['chain']:.3f} ms ({b['chain'] / b['unit']:.2f}x the busiest unit's)"))
