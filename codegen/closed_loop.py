"""The whole closed loop in one C function: many runs at once, one per SIMD lane.

``<prefix>_closed_loop`` runs ``nruns`` experiments that share a plant, a controller step and the
integration settings, ``HL_W`` at a time (see :mod:`codegen.lanes`): per control sample, the
sensor's reading, one controller step (measurement, loops, law, its guards), then
``steps_per_sample`` classical RK4 steps of the plant with the torque held (zero-order hold). The
metrics of conventions §8 are updated on the fly, row by row (the definitions of
:func:`hybrid.metrics`): a row's with its step's first stage, which gives the signals they read, the
last row's after the last step. A sample among whose rows no edge of a metric's window falls (the
steps of the references, the end's last 0.2 s, the first touch's window) has its windows, counts and
peak torques taken once; its rows update only what their signals change. The joints' sin and cos are
computed at a step's start only when its joints have moved more than 2^-8 rad since they last were;
the stages rotate from there.
Per-step states and torques are written only when asked.

Everything a run may vary is a run-time number in its row of ``runs`` (the initial state, the
plant's parameter arrays, the controller's, the reference steps the metrics read); the manifest
lists the row's blocks by name. A run whose controller step trips a guard or gives a non-finite
output, or whose state stops being finite, gets that status and the sample where it happened; the
others go on.

A run whose sensor drops out (its row's ``dropout``: the window ``[start, end)`` [s] of the samples
whose reading is lost; ``inf, inf``: none) reacts to faults as the standalone step does
(:mod:`codegen.standalone_controller`): a lost reading or a failing law is a refused sample (the
torque last written, nothing advances), the sample after one is late when the run's
``timing_tolerance`` checks timing (the law's torque, the integrals kept), and ``fault_samples``
consecutive faulted samples enter the safe state for the rest of the run (the ``safe_stop`` kernel,
:mod:`codegen.safe_stop`). A run without a dropout stops at such a sample, as before.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import sympy as sp

from hybrid.spec.controller_step import CONTROLLER_STEP, FAULT, FAULT_STATE, LOOP_GAINS
from hybrid.spec.interfaces import STATE
from hybrid.spec.metrics import METRIC_NAMES, SETTLING_BAND, STEADY_WINDOW_S, TOUCH_BAND, metric_names
from hybrid.spec.part import PART_GRID
from hybrid.spec.path_follow import PATH_SETTINGS, path_axes

from .emit import STATUS, Unit, comment_safe, manifest, stamp
from .kernel import Arg, Kernel
from .lanes import LANES_HEADER, lanes_function, libm_maps
from .part_grid import part_header
from .path_follow import path_header
from .templates import render

#: the record columns the loop reads besides the force: normal force, tangential speed, penetration and
#: the surface's normal force (``hybrid.metrics``' force_normal, velocity_tangential, penetration,
#: contact_force)
SIGNALS = ("Fc_n", "v_t", "penetration", "N")


@dataclass(frozen=True)
class LoopSpec:
    """What one closed loop is made of: the plant's state derivative ``rhs(x, tau, ...)`` and output
    record ``outputs(x, ...)``, the controller ``step`` (:mod:`codegen.controller_step`), the
    record columns of the sensor's force on the robot (base axes) and the step's fault reaction
    ``stop`` (:mod:`codegen.safe_stop`); for a path task its task ``axes`` (the loop then follows each run's
    path: :mod:`hybrid.spec.path_follow`); ``part`` where the surface is a part (each run's fitted grid,
    expanded about the tip at each sample for the controller and about the sensor tip at each step for the
    plant: :mod:`hybrid.spec.part`); for either, the controller's ``task_measurement`` kernel (``measure``)."""

    rhs: Kernel
    outputs: Kernel
    step: Kernel
    force_columns: tuple[str, ...]
    stop: Kernel
    measure: Kernel | None = None
    axes: tuple[int, ...] | None = None
    part: bool = False

    @property
    def follows_path(self) -> bool:
        """Whether the loop follows a path task (its runs' rows carry their paths)."""
        return self.axes is not None


def _rows(expr, index: list[int]):
    if isinstance(expr, ca.SX):
        return expr[index]
    return sp.Matrix([expr[i] for i in index])


def signals_kernel(spec: LoopSpec) -> Kernel:
    """The record columns the loop reads (force, then :data:`SIGNALS`), alone: the rest of the
    output record is not computed at every step."""
    y = spec.outputs.outputs[0]
    wanted = (*spec.force_columns, *SIGNALS)
    missing = [c for c in wanted if c not in y.names]
    if missing:
        raise ValueError(f"the plant records no {', '.join(missing)}; it records {', '.join(y.names)}")
    index = [y.names.index(c) for c in wanted]
    return Kernel("loop_signals", spec.outputs.inputs, (Arg("s", _rows(y.expr, index), names=wanted),),
                  "the record columns the closed loop reads")


def stepping_kernel(spec: LoopSpec) -> Kernel:
    """The state derivative, the record columns the loop reads (:func:`signals_kernel`) and the whole
    output record at one state, together: the first stage of an RK4 step gives the row's signals and
    record with what they share with it (the kinematics, the contact) computed once. (The record is
    computed whether or not it is kept: every build then has the same arithmetic, a run alone and a
    batch of lanes alike.)"""
    rhs, signals = spec.rhs, signals_kernel(spec)
    have = {a.name for a in rhs.inputs}
    extra = tuple(a for a in signals.inputs[1:] if a.name not in have)
    outputs = (rhs.outputs[0], signals.outputs[0], spec.outputs.outputs[0])
    return Kernel("plant_rhs_signals", rhs.inputs + extra, outputs,
                  "the plant's state derivative, the record columns the closed loop reads and the whole record")


def tip_measurement_kernel(measure: Kernel) -> Kernel:
    """What a path's follower and a part's expansion read of the controller's measurement
    (``task_measurement``): the tip's position ``p`` and rotation ``R`` (row by row), from the joints and the
    controller's model of the arm alone (the contact force the follower reads is the loop's reading itself)."""
    inputs = tuple(a for a in measure.inputs if a.name in ("q", "robot"))
    outputs = tuple(a for a in measure.outputs if a.name in ("p", "R"))
    return Kernel("tip_measurement", inputs, outputs, "the tip's position p and rotation R (row by row), base axes")


def blocks(spec: LoopSpec) -> list[tuple[str, int]]:
    """``(name, size)`` of each block of a run's row: the initial state, the plant's parameter arrays
    (``plant.<input>``), the controller's (``controller.<input>``), the force and speed steps
    ``(before, after, at)`` the metrics read, then the sensor's ``dropout`` window ``(start, end)`` [s]
    and the controller's ``timing_tolerance`` (-1: no timing check); for a path task, the follower's
    settings (``path.settings``, :data:`~hybrid.spec.path_follow.PATH_SETTINGS`), where its table starts in
    the loop's ``tables`` (``path.table``, a count of numbers) and the normal axis's loop gains in the
    retreat (``path.retreat_gains``, :data:`~hybrid.spec.controller_step.LOOP_GAINS`)."""
    x = spec.rhs.inputs[0]
    out, sizes = [("x0", x.size)], {}
    for a in (*spec.rhs.inputs[2:], *spec.outputs.inputs[1:]):
        if sizes.setdefault(a.name, a.size) != a.size:
            raise ValueError(f"plant input {a.name} has two sizes")
    out += [(f"plant.{n}", s) for n, s in sizes.items()]
    out += [(f"controller.{a.name}", a.size) for a in _parameters(spec.step)]
    out += [("force_step", 3), ("speed_step", 3), ("dropout", 2), ("timing_tolerance", 1)]
    if spec.follows_path:
        out += [("path.settings", len(PATH_SETTINGS)), ("path.table", 1), ("path.retreat_gains", len(LOOP_GAINS))]
    if spec.part:
        out += [("part.grid", len(PART_GRID)), ("part.coefficients", 1)]
    return out


#: the blocks of a run's row that say where its table starts in the loop's ``tables`` (a count of numbers)
TABLE_BLOCKS = ("path.table", "part.coefficients")


def _fixed(spec: LoopSpec, kernel: Kernel, first: int) -> tuple[str, ...]:
    """The inputs of a plant's ``kernel`` from its ``first`` on that a run holds fixed: all but a part's surface,
    which the loop expands about the sensor tip at each step."""
    return tuple(a.name for a in kernel.inputs[first:] if not (spec.part and a.name == "surface"))


def _parameters(step: Kernel) -> list[Arg]:
    """The step's parameters (:data:`hybrid.spec.controller_step.CONTROLLER_STEP`'s), in order: a run's row holds
    them; the loop itself drives the inputs that change at every sample."""
    if [a.name for a in step.inputs] != [p.name for p in CONTROLLER_STEP.inputs]:
        raise ValueError(f"the controller step's inputs {[a.name for a in step.inputs]} are not its declaration's")
    return [a for a in step.inputs if a.name in CONTROLLER_STEP.parameters]


#: how the loop keeps each state of the step: the integrals and the last torque it advances; a force/torque
#: sensor's filter and an estimated surface's state stay zero (the loop's runs have neither:
#: ``Controller.runs_in_c``). A state declared besides these is refused, never silently held at zero
_LOOP_STATES = {"integrals": "advanced", "last_torque": "advanced", "filter": "unused", "estimate": "unused"}


def _driver(spec: LoopSpec, stepping: Kernel) -> dict:
    """The context of the loop's driver (``templates/closed_loop.c.j2``) for ``spec``: where each block of a
    run's row starts, the kernels' arguments and the metrics' places."""
    rhs, step = spec.rhs, spec.step
    unknown = [n for n in CONTROLLER_STEP.named(STATE) if n not in _LOOP_STATES]
    if unknown:
        raise ValueError(f"the closed loop does not keep the step's state {', '.join(unknown)}: say how in "
                         "codegen/closed_loop.py's _LOOP_STATES and templates/closed_loop.c.j2")
    nx, nq = rhs.inputs[0].size, rhs.inputs[1].size
    sizes = {a.name: a.size for a in step.inputs}
    offset, at = {}, 0
    for name, size in blocks(spec):
        offset[name] = at
        at += size
    nf = len(spec.force_columns)
    names = spec.outputs.outputs[0].names
    force, signals = ([names.index(c) for c in cols] for cols in (spec.force_columns, stepping.outputs[1].names))
    plant = {a.name: offset["plant." + a.name] for a in (*rhs.inputs[2:], *spec.outputs.inputs[1:])}
    path = None
    if spec.follows_path:  # where the follower's numbers and the parameters it changes are in a run's row
        (t1, t2, n), spins = path_axes(spec.axes)
        path = {"t1": t1, "t2": t2, "n": n, "spins": spins, "gains_at": len(LOOP_GAINS) * n, "ngains": len(LOOP_GAINS),
                "settings": offset["path.settings"], "table": offset["path.table"],
                "retreat_gains": offset["path.retreat_gains"], "e": offset["controller.e"],
                "selection": offset["controller.selection"], "gains": offset["controller.gains"],
                "robot": offset["controller.robot"]}
    part = None
    if spec.part:  # where the grid and the surfaces the loop expands are in a run's row, and the sensor tip in x
        part = {"grid": offset["part.grid"], "coefficients": offset["part.coefficients"],
                "controller": offset["controller.surface"], "tip": rhs.inputs[0].names.index("s_x"),
                "size": sizes["surface"]}
    return dict(
        step=step, outs=step.core_outputs(), path=path, part=part, robot=offset["controller.robot"],
        guards=step.guards, nx=nx, nq=nq, nb=at, m=sizes["integrals"] // 2, ns=nf + len(SIGNALS),
        nm=len(metric_names(nq)), ny=stepping.outputs[2].size, force=force, signals=signals,
        iF=nf, iv=nf + 1, ipen=nf + 2, iN=nf + 3, fs=offset["force_step"], vs=offset["speed_step"], x0=offset["x0"],
        dropout=offset["dropout"], tol=offset["timing_tolerance"], stop=spec.stop,
        stop_params=[offset["controller." + a.name] for a in spec.stop.inputs if a.name in _STOP_ROW],
        fault=offset["controller.fault"], FS=_fault_state_places(nq),
        FO={name: i for i, name in enumerate(FAULT)}, nfs=len(FAULT_STATE.items) * nq + len(FAULT_STATE.tail),
        # where the run's arrays each kernel holds fixed start in its row
        held=[plant[n] for n in _fixed(spec, rhs, 2)], shown=[plant[n] for n in _fixed(spec, spec.outputs, 1)],
        both=[plant[n] for n in _fixed(spec, stepping, 2)],
        params=[offset["controller." + a.name] for a in _parameters(step)],
        per_sample=[a for a in step.inputs if a.name in CONTROLLER_STEP.per_sample],
        M={name: i for i, name in enumerate(METRIC_NAMES)}, settling_band=repr(SETTLING_BAND),
        steady_window_s=repr(STEADY_WINDOW_S), touch_band=repr(TOUCH_BAND))


def _fault_state_places(nq: int) -> dict[str, int]:
    """Where each item of :data:`hybrid.spec.controller_step.FAULT_STATE` starts (its joints' block, or
    its one number)."""
    places = {k: i * nq for i, k in enumerate(FAULT_STATE.items)}
    return places | {k: len(FAULT_STATE.items) * nq + i for i, k in enumerate(FAULT_STATE.tail)}


#: the safe-stop kernel's fixed inputs a run's row holds (its sample time is the loop's)
_STOP_ROW = ("robot", "fault", "limits")


#: the most lines of C the two stage functions may have to be inlined into the loop where lanes are many
#: (``templates/closed_loop_unit.c.j2``'s HL_STAGE; the paper's plant: about 900; the UR5's: about 11,000)
_INLINE_LINES = 3000
#: the parts a unit compiles in at once, one compiler each (``templates/closed_loop_unit.c.j2``'s HL_PART;
#: :mod:`hybrid.native.compiler`), as the manifest's ``parts`` names them
N_PARTS = 2


#: the lanes of the build for one run at a time, each the same run: two (the 128-bit vectors of every
#: x86-64 and ARM processor). One lane alone is slower by about a tenth (the paper's run and the 3-D
#: one): GCC turns a vector of one into scalar and integer code (the masks, selects and absolute values
#: go through integer registers, the selects become branches), where two stay in vector registers.
ONE_RUN_LANES = 2


def build_closed_loop_unit(spec: LoopSpec, prefix: str, what: str, info: dict,
                           lanes: int | None = None) -> Unit:
    """C source, header and manifest of the closed loop ``spec``, deterministic in its inputs; ``lanes``
    fixes the lane count instead of the instruction set's, and 1 is the build for one run at a time (as
    fast as one run goes: :data:`ONE_RUN_LANES` lanes, each the same run). The C is
    ``templates/closed_loop_unit.c.j2`` (which includes the driver, ``closed_loop.c.j2``) and
    ``closed_loop_unit.h.j2``'s; the lanes functions in it are :func:`codegen.lanes.lanes_function`'s."""
    nq = spec.rhs.inputs[1].size
    rhs = Kernel("plant_rhs", spec.rhs.inputs, spec.rhs.outputs, spec.rhs.doc)
    held, shown = _fixed(spec, spec.rhs, 2), _fixed(spec, spec.outputs, 1)
    params = tuple(a.name for a in _parameters(spec.step))
    stepping = stepping_kernel(spec)
    stages = [lanes_function(k, name, fixed, "HL_STAGE", near=nq, apart=True) for k, name, fixed in (
        (rhs, "plant_rhs_lanes", held), (stepping, "plant_rhs_signals_lanes", held + shown))]
    lines = sum(stage.count("\n") + 1 for stage in stages)
    # a path's follower, a part's evaluator, and for either the tip's measurement in lanes (the arm's model held)
    extra = {"follower": path_header() if spec.follows_path else None,
             "part": part_header() if spec.part else None,
             "measure_lanes": None if spec.measure is None else lanes_function(
                 tip_measurement_kernel(spec.measure), "tip_measurement_lanes", ("robot",), "HL_APART", apart=True)}
    body = render("closed_loop_unit.c.j2", **_driver(spec, stepping), prefix=prefix, what=what, comment=comment_safe,
                  width=ONE_RUN_LANES if lanes == 1 else lanes, lanes_header=LANES_HEADER, status=STATUS,
                  libm_maps=libm_maps(), small=int(lines <= _INLINE_LINES), stages=stages,
                  outputs_lanes=lanes_function(spec.outputs, "plant_outputs_lanes", shown, "HL_APART", apart=True),
                  step_lanes=lanes_function(spec.step, spec.step.name + "_lanes", params, "HL_APART", apart=True),
                  stop_lanes=lanes_function(spec.stop, "safe_stop_lanes", (*_STOP_ROW, "sample_time"), "HL_APART",
                                            apart=True), extra=extra)
    header = render("closed_loop_unit.h.j2", prefix=prefix)
    loop = {"symbol": f"{prefix}_closed_loop", "lanes_symbol": f"{prefix}_lanes",
            "blocks": [{"name": n, "size": s} for n, s in blocks(spec)],
            "state": list(spec.rhs.inputs[0].names or ()), "nx": spec.rhs.inputs[0].size, "nq": nq,
            "metrics": list(metric_names(nq)),
            "signals": [*spec.force_columns, *SIGNALS],
            "outputs": list(stepping.outputs[2].names), "path_task": spec.follows_path, "part": spec.part,
            "tables": [b for b in TABLE_BLOCKS if b in dict(blocks(spec))]}
    text = manifest(prefix, (), f"CasADi {ca.__version__}", {**info, "parts": N_PARTS, "closed_loop": loop})
    return Unit(prefix, stamp(body), stamp(header), text)
