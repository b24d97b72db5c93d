"""Whole runs of the paper's and the 3-D experiment in compiled C, many at once as SIMD lanes.

:func:`prepare` turns an experiment into one row of numbers for the generated closed loop
(:mod:`codegen.closed_loop`), or None when part of its controller runs in Python (references
given as code, a desired path) or it asks for the NumPy reference; :func:`run` runs prepared
experiments, grouped by the loop they share, one native call per group. ``simulate`` and
``sweep`` use it; the Python runner (:func:`hybrid.simulation.run`) is the reference it is tested
against and the path that explains a run that stopped.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from functools import cache

import numpy as np

from .controller import Controller
from .errors import NativeBuildError
from .experiment import Experiment
from .plants import NativePlant, SpatialPlant

log = logging.getLogger("hybrid")


@dataclass(frozen=True)
class Loop:
    """A compiled closed loop: its entry point, the blocks of a run's row and the metric names."""

    function: object
    ffi: object
    key: tuple  # (plant, variant): what it was built from
    lanes: int
    blocks: tuple[tuple[str, int], ...]
    metrics: tuple[str, ...]
    nx: int
    nq: int

    def row(self, values: dict[str, np.ndarray]) -> np.ndarray:
        """A run's row from its blocks by name (each of the manifest's size)."""
        parts = [np.asarray(values[name], float).ravel() for name, _ in self.blocks]
        wrong = [f"{name} has {len(p)} numbers, not {size}" for (name, size), p in zip(self.blocks, parts)
                 if len(p) != size]
        if wrong:
            raise ValueError(f"a compiled loop's row: {'; '.join(wrong)}")
        return np.concatenate(parts)


@cache
def _loop(plant: tuple, variant: tuple, lanes: int | None = None) -> Loop:
    """The compiled loop of a plant (``("planar", surface kind)`` or ``("spatial", chain, name, surface
    spec)``) and a controller step (:meth:`Controller.step_variant`, as sorted items); ``lanes=1``: the
    build for one run at a time."""
    from importlib.metadata import version

    from codegen.robot_unit import c_identifier

    from .robot import _chain_key, _compiled

    v = dict(variant)
    kind = plant[1] if plant[0] == "planar" else f"{plant[2]}_{plant[3].kind}"
    prefix = c_identifier(f"hybrid_{v['name']}_{kind}_{v['step']}_loop{'_one' if lanes == 1 else ''}")
    plant_key = list(plant) if plant[0] == "planar" else ["spatial", _chain_key(plant[1]), plant[3].key()]
    key = {"chain": _chain_key(v["chain"]), "surface": v["spec"].key(), "axes": list(v["axes"]), "plant": plant_key,
           **{k: v[k] for k in ("desired_frame", "position_error", "step")}, "sympy": version("sympy"),
           "lanes": lanes}
    unit = _compiled(prefix, key, lambda: _build(prefix, plant, v, lanes))
    module, loop = unit.module, unit.manifest["closed_loop"]
    return Loop(getattr(module.lib, loop["symbol"]), module.ffi, (plant, variant),
                int(getattr(module.lib, loop["lanes_symbol"])()),
                tuple((b["name"], b["size"]) for b in loop["blocks"]), tuple(loop["metrics"]), loop["nx"], loop["nq"])


@cache
def _available_loop(plant: tuple, variant: tuple, lanes: int | None = None) -> Loop | None:
    """:func:`_loop`, or None (said once) when it cannot be built here: its C needs GCC's or Clang's
    vector extensions, and without them every run takes the Python runner."""
    try:
        return _loop(plant, variant, lanes)
    except NativeBuildError as exc:
        log.warning("hybrid: the compiled closed loop cannot be built (%s); runs take the Python runner",
                    str(exc).splitlines()[0])
        return None


def _build(prefix: str, plant: tuple, v: dict, lanes: int | None):
    from codegen.closed_loop import LoopSpec, build_closed_loop_unit
    from codegen.controller_step import controller_kernels

    steps = {k.name: k for k in controller_kernels(v["chain"], v["spec"], v["axes"], v["desired_frame"],
                                                      v["position_error"])}
    if plant[0] == "planar":
        from codegen import model

        kernels = {k.name: k for k in model.kernels(2)}
        rhs, outputs, force = kernels[f"plant_rhs_{plant[1]}"], kernels[f"plant_outputs_{plant[1]}"], ("Fc_x", "Fc_y")
        what = f"the paper's closed loop on a {plant[1]}"
    else:
        from codegen.spatial_plant import plant_kernels

        kernels = {k.name: k for k in plant_kernels(plant[1], plant[3])}
        rhs, outputs, force = kernels["plant_rhs"], kernels["plant_outputs"], ("Fc_x", "Fc_y", "Fc_z")
        what = f"the 3-D experiment's closed loop: {plant[2]} on a {plant[3].kind}"
    info = {"plant": plant[0], "surface": plant[1] if plant[0] == "planar" else plant[3].kind, "step": v["step"],
            "robot": v["name"]}
    return build_closed_loop_unit(LoopSpec(rhs, outputs, steps[v["step"]], force), prefix, f"{what}: {v['step']}",
                                  info, lanes)


@dataclass(frozen=True)
class Prepared:
    """An experiment ready for the compiled loop: which loop, its integration settings, its row."""

    experiment: Experiment
    loop: Loop
    settings: tuple
    row: np.ndarray


def prepare(exp, x0: np.ndarray | None = None) -> Prepared | None:
    """``exp`` (the paper's experiment or a 3-D one) as a row of the compiled loop, after the checks
    ``simulate`` makes of the settings (a refused experiment raises their HybridError; the record's
    memory is ``simulate``'s to check: a sweep keeps none); None when it cannot run there. A given
    start state ``x0`` is the caller's, checked (``simulate`` passes its own)."""
    from .simulation import check_path, initial_state
    from .tracing import TracingExperiment, initial_tracing_state

    spatial = isinstance(exp, TracingExperiment)
    if not (spatial or isinstance(exp, Experiment)) or getattr(exp, "backend", "") == "numpy":
        return None
    ctrl = Controller.from_experiment(exp)
    if not ctrl.runs_in_c:
        return None
    if spatial:
        x0 = initial_tracing_state(exp, SpatialPlant(exp)) if x0 is None else x0
        plant, given = ("spatial", exp.robot.chain, exp.robot.name, exp.surface.lift().spec()), SpatialPlant.inputs(exp)
    else:
        if x0 is None:
            x0 = initial_state(exp)
            check_path(exp)
        plant, given = ("planar", exp.surface.kind), NativePlant.inputs(exp)
    loop = _available_loop(plant, tuple(sorted(ctrl.step_variant().items())))
    if loop is None:
        return None
    fs, vs = exp.force_reference, exp.speed_reference
    values = {"x0": x0, "force_step": (fs.before, fs.after, fs.at), "speed_step": (vs.before, vs.after, vs.at),
              **{f"plant.{k}": v for k, v in given.items()},
              **{f"controller.{k}": v for k, v in ctrl.step_inputs().items()}}
    settings = (exp.n_samples, exp.steps_per_sample, exp.step, exp.sample_time, exp.singular_tol)
    return Prepared(exp, loop, settings, loop.row(values))


@dataclass
class Outcome:
    """One compiled run: ``status`` (0 ok, else the C status code), the sample where it stopped
    (-1), its metrics by name (NaN for a run that stopped), and with ``record`` its states and
    torques per step (NaN after a stop)."""

    status: int
    failed_sample: int
    metrics: dict
    states: np.ndarray | None = None
    taus: np.ndarray | None = None


def run(prepared: list[Prepared], record: bool = False) -> list[Outcome]:
    """Run every prepared experiment; outcomes in the same order."""
    groups: dict = {}
    for i, p in enumerate(prepared):
        groups.setdefault((id(p.loop), p.settings), []).append(i)
    outcomes: list = [None] * len(prepared)
    for members in groups.values():
        first = prepared[members[0]]
        loop, (n_samples, per_sample, h, sample_time, tol) = first.loop, first.settings
        n = len(members)
        if n == 1:  # one run alone: the one-lane build (same row, same arithmetic), built on first use
            loop = _available_loop(*loop.key, lanes=1) or loop
        runs = np.ascontiguousarray(np.stack([prepared[i].row for i in members]))
        metrics = np.empty((n, len(loop.metrics)))
        status, failed = np.empty(n, np.intc), np.empty(n, np.intc)
        steps = n_samples * per_sample + 1
        # every row is written: NaN from where a run stopped
        states = np.empty((n, steps, loop.nx)) if record else None
        taus = np.empty((n, steps, loop.nq)) if record else None
        ffi = loop.ffi
        loop.function(n, ffi.from_buffer("double[]", runs), n_samples, per_sample, h, sample_time, tol,
                      ffi.from_buffer("double[]", metrics), ffi.from_buffer("int[]", status),
                      ffi.from_buffer("int[]", failed),
                      ffi.from_buffer("double[]", states) if record else ffi.NULL,
                      ffi.from_buffer("double[]", taus) if record else ffi.NULL)
        for j, i in enumerate(members):
            m = dict(zip(loop.metrics, metrics[j].tolist() if status[j] == 0 else [math.nan] * len(loop.metrics)))
            if status[j] == 0:
                m["contact_losses"] = int(m["contact_losses"])
            outcomes[i] = Outcome(int(status[j]), int(failed[j]), m, states[j] if record else None,
                                  taus[j] if record else None)
    return outcomes
