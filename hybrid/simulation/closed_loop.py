"""Whole runs of the paper's and the 3-D experiment in compiled C, many at once as SIMD lanes.

:func:`prepare` turns an experiment into one row of numbers for the generated closed loop
(:mod:`hybrid.codegen.closed_loop`), or None when part of its controller runs in Python
(references given as code, a desired path, a force/torque sensor's reading) or the plant's sensor
has noise, a bias, a lag or a delay (the Python runner gives those); :func:`run` runs prepared
experiments, grouped by the loop they share, one native call per group; :func:`prepare_alike`
prepares a run from another that differs from it only in settings of :data:`ROW_SETTINGS` (a
sweep's runs, mostly). ``simulate`` and ``sweep`` use it; the Python runner
(:func:`hybrid.simulation.runner.run`) is the oracle it is tested against and the path that
explains a run that stopped.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache

import numpy as np

from hybrid.errors import HybridError, NativeBuildError
from hybrid.native import compiler, units
from hybrid.native.binding import one_block, workers
from hybrid.simulation.path_metrics import sampled_path_metrics
from hybrid.spec.interfaces import STATUS_CODES
from hybrid.spec.metrics import PATH_METRICS

log = logging.getLogger("hybrid")


@dataclass(frozen=True)
class Loop:
    """A compiled closed loop: its entry point, the blocks of a run's row and the metric names."""

    function: object
    ffi: object
    key: tuple  # (plant, variant): what it was built from
    lanes: int  # the runs it computes at once
    alone: bool  # the build for one run at a time
    blocks: tuple[tuple[str, int], ...]
    metrics: tuple[str, ...]
    nx: int
    nq: int
    outputs: tuple[str, ...]  # the output record's columns
    path_task: bool  # its runs follow a path
    tables: tuple[str, ...]  # the row's blocks that say where a run's tables start in the loop's tables

    def row(self, values: dict[str, np.ndarray]) -> np.ndarray:
        """A run's row from its blocks by name (each of the manifest's size)."""
        parts = [np.asarray(values[name], float).ravel() for name, _ in self.blocks]
        wrong = [f"{name} has {len(p)} numbers, not {size}" for (name, size), p in zip(self.blocks, parts)
                 if len(p) != size]
        if wrong:
            raise ValueError(f"a compiled loop's row: {'; '.join(wrong)}")
        return np.concatenate(parts)

    def replaced(self, row: np.ndarray, values: dict[str, np.ndarray]) -> np.ndarray:
        """A copy of the run's ``row`` with the blocks named in ``values`` replaced (each of its size)."""
        row = row.copy()
        for name, value in values.items():
            start, size = _spans(self.blocks)[name]
            part = np.asarray(value, float).ravel()
            if len(part) != size:
                raise ValueError(f"a compiled loop's row: {name} has {len(part)} numbers, not {size}")
            row[start:start + size] = part
        return row


@cache
def _spans(blocks: tuple[tuple[str, int], ...]) -> dict[str, tuple[int, int]]:
    """Where each block of a row starts, and its size, by name."""
    starts = np.cumsum([0] + [size for _, size in blocks]).tolist()
    return {name: (start, size) for (name, size), start in zip(blocks, starts)}


@cache
def _loop(plant, variant: tuple, lanes: int | None = None) -> Loop:
    """The compiled loop of a plant (:class:`~hybrid.plants.interface.LoopPlant`) and a controller step
    (:meth:`Controller.step_variant`, as sorted items); ``lanes=1``: the build for one run at a time."""
    unit = units.loop_unit(plant, dict(variant), lanes)
    module, loop = unit.module, unit.manifest["closed_loop"]
    return Loop(getattr(module.lib, loop["symbol"]), module.ffi, (plant, variant),
                int(getattr(module.lib, loop["lanes_symbol"])()), lanes == 1,
                tuple((b["name"], b["size"]) for b in loop["blocks"]), tuple(loop["metrics"]), loop["nx"], loop["nq"],
                tuple(loop["outputs"]), bool(loop.get("path_task", False)), tuple(loop.get("tables", ())))


@cache
def _available_loop(plant, variant: tuple, lanes: int | None = None) -> Loop | None:
    """:func:`_loop`, or None (said once) when it cannot be built here: its C needs GCC's or Clang's
    vector extensions, and without them every run takes the Python runner. A compiler that can build
    nothing (:class:`~hybrid.native.compiler.CompilerUnusable`) is the run's error: the Python runner
    needs it too."""
    try:
        return _loop(plant, variant, lanes)
    except compiler.CompilerUnusable:
        raise
    except NativeBuildError as exc:
        log.warning("hybrid: the compiled closed loop cannot be built (%s); runs take the Python runner",
                    str(exc).splitlines()[0])
        return None


@dataclass(frozen=True)
class Prepared:
    """An experiment ready for the compiled loop: which loop, its integration settings, its row, and its
    tables by the block that places them (a path task's ``path.table``, :data:`~hybrid.spec.path_follow.PATH_TABLE`
    rows; a part's ``part.coefficients``)."""

    experiment: object
    loop: Loop
    settings: tuple
    row: np.ndarray
    tables: tuple = ()


def loop_of(exp, ctrl=None) -> tuple:
    """``(plant, variant)``: what the compiled loop of ``exp`` is built from (its loop plant, and its
    controller's step variant as sorted items, with ``path_task`` where it follows one and ``part`` where its
    surface is a part); ``ctrl``: its controller, when built already."""
    ctrl = ctrl or exp.build_controller()
    variant = ctrl.step_variant() | ({"path_task": True} if ctrl.path_references is not None else {}) | \
        ({"part": True} if exp.surface.local else {})
    return exp.plant_class.loop_plant(exp), tuple(sorted(variant.items()))


def prepare(exp, x0: np.ndarray | None = None, lanes: int | None = None, ctrl=None) -> Prepared | None:
    """``exp`` (the paper's experiment or a 3-D one) as a row of the compiled loop, after the checks
    ``simulate`` makes of the settings (a refused experiment raises their HybridError; the record's
    memory is checked as :meth:`~hybrid.Experiment.checked_start` checks it without a plant's record:
    a sweep keeps none); None when it cannot run there: part of its
    controller runs in Python, or its sensor's signal is not the sensor's force itself (noise, bias, lag,
    delay: :mod:`hybrid.simulation.sensing`; a dropout runs here, the loop's fault reaction as the
    controller's). A given start state ``x0`` is the caller's, checked
    (``simulate`` passes its own). ``lanes=1`` prepares the build for one run at a time (a run alone;
    only what it needs is compiled), else the lanes build. ``ctrl``: the experiment's controller, when
    built already (it is read, not run)."""
    ctrl = ctrl or exp.build_controller()
    if not ctrl.runs_in_c or not exp.sensor.clean:
        return None
    if exp.controller_surface is not None and (exp.surface.local or exp.controller_surface.local):
        return None  # a part the controller is told apart from the plant's: the Python runner
    if x0 is None:
        x0 = exp.checked_start()
    given = _plant_blocks(exp)
    # the build for the lanes it will run in (lanes=1: a run alone); :func:`run` takes the other if it must
    loop = _available_loop(*loop_of(exp, ctrl), lanes)
    if loop is None:
        return None
    fs, vs = exp.force_reference, exp.speed_reference
    sensor = exp.sensor
    start = sensor.dropout_at if sensor.drops_out else np.inf
    values = {"x0": x0, "force_step": (fs.before, fs.after, fs.at), "speed_step": (vs.before, vs.after, vs.at),
              "dropout": (start, start + sensor.dropout_duration),
              "timing_tolerance": -1.0 if ctrl.timing_tolerance is None else ctrl.timing_tolerance,
              **given, **{f"controller.{k}": v for k, v in ctrl.step_inputs(at_start=True).items()}}
    path, tables = ctrl.path_references, {}
    if path is not None:  # its table's place in the loop's tables is the run's (run() writes it)
        tables["path.table"] = path.follower.table
        values |= {"path.settings": path.follower.settings, "path.table": 0.0, "path.retreat_gains": path.retreat_gains}
    if exp.surface.local:  # a part: its grid's numbers, and its coefficients among the loop's tables
        grid, tables["part.coefficients"] = exp.surface.data()
        values |= {"part.grid": grid, "part.coefficients": 0.0}
    settings = (exp.n_samples, exp.steps_per_sample, exp.integration_step, exp.sample_time, exp.singular_tol)
    return Prepared(exp, loop, settings, loop.row(values), tuple(tables[b] for b in loop.tables))


def build_side_by_side(experiments, lanes: int | None = 1) -> None:
    """Build the compiled loops of ``experiments`` at once, one compiler per core (the compiler runs
    outside the GIL): a command that runs several experiments waits for the slowest build, not for
    their sum. An experiment that cannot be prepared is left to its run to report."""
    from concurrent.futures import ThreadPoolExecutor

    def one(exp) -> None:
        try:
            prepare(exp, lanes=lanes)
        except HybridError:
            pass

    try:
        compiler.ready_for_threads()
    except NativeBuildError:
        return  # each run says why it takes the Python runner
    distinct = {}  # one experiment per loop: two threads never build the same one
    for exp in experiments:
        try:
            distinct.setdefault(loop_of(exp), exp)
        except HybridError:
            pass
    with ThreadPoolExecutor(max_workers=max(1, min(len(distinct), workers()))) as pool:
        list(pool.map(one, distinct.values()))


def _plant_blocks(exp) -> dict[str, np.ndarray]:
    """The plant's parameter blocks of a run's row."""
    return {f"plant.{k}": v for k, v in exp.plant_class.inputs(exp).items()}


#: the settings in which runs may differ and still share a prepared run (:func:`prepare_alike`), and
#: the parts of its row each reaches: ``"model"`` the controller's model of the arm, ``"plant"`` the
#: plant's parameters, ``"start"`` the start state. None of them reaches the rest: the loop (the
#: controller's step, the plant's structure), its integration settings, the references, the
#: controller's other inputs; nor whether the run is for the compiled loop at all (the sensor's
#: noise, bias, lag and delay are not here). Any other setting makes a run prepared whole.
ROW_SETTINGS = {
    "model_error": ("model",), "viscous_compensation": ("model",),
    # the start presses into the contact's and the sensor's springs, and the sensor's mass hangs on its
    # spring in a start from free space; damping and friction act only once the arm moves
    "contact.stiffness": ("plant", "start"), "contact.damping": ("plant",), "contact.friction": ("plant",),
    "contact.friction_smoothing": ("plant",),
    "sensor.mass": ("plant", "start"), "sensor.stiffness": ("plant", "start"), "sensor.damping": ("plant",),
}


def prepare_alike(template: Prepared, exp, parts: Iterable[str], kept: dict | None = None) -> Prepared:
    """``exp`` prepared as :func:`prepare` prepares it, from ``template``: a prepared run (by
    :func:`prepare`, without a given start state) whose experiment differs from ``exp`` only in
    settings of :data:`ROW_SETTINGS` that reach ``parts``. Only those parts of the row are made again,
    by the functions ``prepare`` calls (the same numbers), in its order (a part that raises raises what
    ``prepare`` would). ``kept``, a dict kept between calls, holds the parts made, by what they are
    made of, for runs that share them (a grid's runs share their values)."""
    parts = frozenset(parts)
    kept = {} if kept is None else kept
    values = {}
    if "model" in parts:  # the controller's ``robot`` input is its model's array (Controller.step_inputs)
        # by the arm and the settings the model is made of, their types and bits (-0.0 is not 0.0 there)
        settings = (exp.model_error, exp.viscous_compensation)
        key = ("model", id(exp.robot), id(exp.controller_robot),
               *((type(v), np.float64(v).tobytes()) for v in settings))
        values.update(_kept(kept, key, lambda: {"controller.robot": exp.controller_model().as_array()}, exp.robot,
                            exp.controller_robot))
    if parts & {"start", "plant"}:  # made of the template's settings, the sensor and the contact
        key = ("plant", parts, id(template), id(exp.sensor), id(exp.contact))
        values.update(_kept(kept, key, lambda: _plant_values(exp, parts), template, exp.sensor, exp.contact))
    row = template.loop.replaced(template.row, values)
    return Prepared(exp, template.loop, template.settings, row, template.tables)


def _plant_values(exp, parts: frozenset) -> dict[str, np.ndarray]:
    """The start state and the plant's blocks of a run's row, as ``parts`` asks."""
    values = {"x0": exp.initial_state()} if "start" in parts else {}
    return {**values, **(_plant_blocks(exp) if "plant" in parts else {})}


def _kept(kept: dict, key: tuple, make, *objects):
    """``make()``, kept in ``kept`` by ``key`` (with the ``objects`` whose ids it holds: no id is reused)."""
    if key not in kept:
        kept[key] = make(), objects
    return kept[key][0]


@dataclass
class Outcome:
    """One compiled run: ``status`` (0 ok, else the C status code), the sample where it stopped
    (-1), its metrics by name (NaN for a run that stopped; a path task's
    :data:`~hybrid.spec.metrics.PATH_METRICS` too), and with ``record`` its states, torques
    and output record per step (NaN after a stop)."""

    status: int
    failed_sample: int
    metrics: dict
    states: np.ndarray | None = None
    taus: np.ndarray | None = None
    outputs: np.ndarray | None = None


def _records(n: int, steps: int, widths: tuple[int, ...]) -> list[np.ndarray]:
    """``n x steps x width`` arrays for each of ``widths``, views of one block (:func:`one_block`: a
    run's torques alone hold its states and outputs too)."""
    return [a.reshape(n, steps, w) for a, w in zip(one_block(n * steps, widths), widths)]


def run(prepared: list[Prepared], record: bool = False) -> list[Outcome]:
    """Run every prepared experiment; outcomes in the same order."""
    groups: dict = {}
    for i, p in enumerate(prepared):
        groups.setdefault((id(p.loop), p.settings), []).append(i)
    outcomes: list = [None] * len(prepared)
    for members in groups.values():
        first = prepared[members[0]]
        loop = first.loop
        if len(members) == 1:  # one run alone: its own build (same row, same arithmetic), built on first use
            loop = _available_loop(*loop.key, lanes=1) or loop
        elif loop.alone:  # runs prepared one by one, run together: the lanes build
            loop = _available_loop(*loop.key) or loop
        # a path task's runs without a record keep the state and the record at each sample for its metrics: a
        # group of lanes at a time, its memory that of the lanes' runs, not the sweep's
        size = loop.lanes if loop.path_task and not record else len(members)
        for at in range(0, len(members), size):
            batch = members[at:at + size]
            for i, outcome in zip(batch, _run_group(loop, [prepared[i] for i in batch], first.settings, record)):
                outcomes[i] = outcome
    return outcomes


def _run_group(loop: Loop, prepared: list[Prepared], settings: tuple, record: bool) -> list[Outcome]:
    """The runs ``prepared`` of ``loop`` (its integration ``settings``) in one native call."""
    n_samples, per_sample, h, sample_time, tol = settings
    n = len(prepared)
    runs = np.ascontiguousarray(np.stack([p.row for p in prepared]))
    tables = _tables(loop, runs, [p.tables for p in prepared])
    metrics = np.empty((n, len(loop.metrics)))
    status, failed = np.empty(n, np.intc), np.empty(n, np.intc)
    steps = n_samples * per_sample + 1
    # every row is written: NaN from where a run stopped
    states, taus, outputs = _records(n, steps, (loop.nx, loop.nq, len(loop.outputs))) if record else (None,) * 3
    # a path task's metrics read the state and the record at each control sample: the record's, where it is kept
    samples = np.empty((n, n_samples, loop.nx + len(loop.outputs))) if loop.path_task and not record else None
    ffi = loop.ffi
    loop.function(n, _buffer(ffi, runs), _buffer(ffi, tables), n_samples, per_sample, h, sample_time, tol,
                  _buffer(ffi, metrics), ffi.from_buffer("int[]", status), ffi.from_buffer("int[]", failed),
                  *(_buffer(ffi, a) for a in (states, taus, outputs, samples)))
    done = []
    for j, p in enumerate(prepared):
        ok = status[j] == STATUS_CODES["OK"]
        m = dict(zip(loop.metrics, metrics[j].tolist() if ok else [math.nan] * len(loop.metrics)))
        if ok:
            m["contact_losses"] = int(m["contact_losses"])
        if loop.path_task:
            sampled = ((states[j][::per_sample][:n_samples], outputs[j][::per_sample][:n_samples]) if record else
                       (samples[j][:, :loop.nx], samples[j][:, loop.nx:]))
            m |= _path_metrics(p.experiment, loop, *sampled, ok)
        done.append(Outcome(int(status[j]), int(failed[j]), m, states[j] if record else None,
                            taus[j] if record else None, outputs[j] if record else None))
    return done


def _buffer(ffi, a: np.ndarray | None):
    """``a`` as a C array of doubles (NULL for None)."""
    return ffi.NULL if a is None else ffi.from_buffer("double[]", a)


def _tables(loop: Loop, runs: np.ndarray, tables: list[tuple]) -> np.ndarray | None:
    """The tables of a group's runs (each run's, in the order of ``loop.tables``), one after the other, each
    table once however many runs share it (a sweep's runs on one part share its grid), each run's placing block
    set to where its own starts (a count of numbers); None for a loop without tables."""
    if not loop.tables:
        return None
    distinct, start, at = [], {}, 0
    for run in tables:
        for t in run:
            if id(t) not in start:
                start[id(t)] = at
                distinct.append(t.ravel())
                at += t.size
    for k, name in enumerate(loop.tables):
        runs[:, _spans(loop.blocks)[name][0]] = [start[id(run[k])] for run in tables]
    return np.ascontiguousarray(np.concatenate(distinct), dtype=float)


def _path_metrics(exp, loop: Loop, states: np.ndarray, outputs: np.ndarray, ok: bool) -> dict:
    """A path task's metrics from the state and the output record at each control sample (NaN for a run
    that stopped)."""
    if not ok:
        return dict.fromkeys((m.name for m in PATH_METRICS), math.nan)
    return sampled_path_metrics(exp, loop.outputs, outputs, states, loop.nq)
