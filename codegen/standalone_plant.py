"""An experiment's plant as standalone C: the true arm, its sensor and the surface behind a struct the
caller owns, what a closed loop in C alone runs the controller of :mod:`codegen.standalone_controller`
against.

``<prefix>`` (the struct) holds the plant's run-time parameters (the arrays of the plant's state
derivative and output record, with the experiment's values after ``<prefix>_init``), the experiment's
timing (RK4 step ``h``, steps per control sample, sample time, duration), the state ``x`` and the
initial state ``x0`` that ``<prefix>_reset`` restores. Its functions:

- ``<prefix>_wrench(&p, wrench)``: the sensor's reading at ``x``, the force and moment on the robot at
  the tip (base axes; six numbers, the moment 0 and a planar arm's z force 0), what the controller's
  step takes;
- ``<prefix>_advance(&p, tau, nsteps)``: ``nsteps`` classical RK4 steps of ``h`` with the torque held
  (the formula of ``templates/rk4.c.j2``, the one every integrator of the project takes);
- ``<prefix>_signals(&p, s)``: the record columns the metrics read (normal force, tangential speed,
  penetration, the surface's normal force: :data:`codegen.closed_loop.SIGNALS`);
- ``<prefix>_outputs(&p, y)``: the plant's whole output record at ``x``;
- ``<prefix>_metric_name(i)``: the name of a run's metric ``i``, as :mod:`hybrid.spec.metrics` declares them
  (their indices, bands and window are the header's macros): what a closed loop in C reports. The struct's
  ``references`` are the force and speed steps they are taken against (:func:`hybrid.metrics`' ``force_step``
  and ``speed_step``: the experiment's references); a run along a path task adds the path's metrics
  (:data:`hybrid.spec.metrics.PATH_METRICS`) after the peak torques, with their tolerances as macros.

On a part (:mod:`hybrid.spec.part`) the surface is not a field: ``<prefix>_set_part(&p, data, count)`` points
the struct at the part's data file's numbers (the caller's, checked by ``hybrid_part.h``'s ``hybrid_part_data``),
and the contact acts on the part's expansion about the sensor tip, taken at the start of each RK4 step and at
each state read, as the Python plant takes it (:class:`hybrid.plants.rigid_body.RigidBodyPlant`).

The text is a pure function of its inputs (no dates, no paths, stable ordering).
"""

from __future__ import annotations

import json

import casadi as ca

from hybrid.spec.interfaces import STATUS_CODES
from hybrid.spec.metrics import (
    METRICS,
    PATH_AHEAD_M,
    PATH_BEHIND_M,
    PATH_END_TOL_M,
    PATH_METRICS,
    PATH_SETTLED_BAND,
    SETTLING_BAND,
    STEADY_WINDOW_S,
    TOUCH_BAND,
    metric_names,
)
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from .closed_loop import SIGNALS
from .emit import GENERATOR_VERSION, Unit, _casadi_cores, _sympy_cores, comment_safe
from .kernel import Kernel
from .standalone_controller import _number, array_field, configured, index_names
from .templates import render

#: the plant's statuses (their numbers are :data:`hybrid.spec.interfaces.STATUSES`', as every unit's) and what
#: each means for a plant
_MEANING = {
    "OK": "done",
    "NONFINITE": "the state would stop being finite: x is the last finite state, steps counts the steps done",
    "INPUT_NONFINITE": "the torque or the state is not finite: nothing changed",
}
#: a part's plant's further statuses
_PART_MEANING = {
    "FRAME_UNDEFINED": "the sensor tip is beyond the part's fitted band (no surface there): x is the last state "
                       "within it, steps counts the steps done; a record there is NaN where it reads the surface",
    "PARAMETER_INVALID": "no part's data given (set_part), or its grid's numbers are not a grid's: nothing changed",
}
#: parameter arrays held as named scalar fields (their elements' names), not arrays
_SCALARS = ("plant",)
#: what each named scalar of the plant's array is (the names of ``spatial_plant.PLANT_PARAMETERS``)
_SCALAR_DOC = {"m_s": "the sensor tip's mass", "K_s": "the sensor's stiffness", "D_s": "the sensor's damping",
               "k_e": "the contact's stiffness", "d_e": "the contact's damping", "gamma": "the friction coefficient",
               "v_eps": "the speed of the friction's tanh smoothing"}
#: what each parameter array holds, for the header
_DOC = {"robot": "the true arm's inertial parameters, joint friction and gravity",
        "arm": "the planar arm's lengths, masses, inertias, viscosities",
        "plant": "the sensor and the contact", "surface": "the surface's parameters",
        "e": "the task frame's reference direction (the output record's task axes)"}
#: the metrics' references, in the struct's ``references`` (hybrid.metrics' force_step, then speed_step)
REFERENCES = ("force_before", "force_after", "force_at", "speed_before", "speed_after", "speed_at")


def _whole(value: float, scale: int) -> int:
    """``value * scale`` as a whole number ``k`` whose ``k / scale`` in C is ``value`` to the bit."""
    k = round(value * scale)
    if k / scale != value:
        raise ValueError(f"{value} is not a whole number of 1/{scale}")
    return k


def _references(prefix: str, numbers) -> dict:
    """The struct's ``references`` field with its numbers (:data:`REFERENCES`)."""
    numbers = [_number(v) for v in numbers]
    if len(numbers) != len(REFERENCES):
        raise ValueError(f"references takes {len(REFERENCES)} values, got {len(numbers)}")
    doc = ("the references the run's metrics are taken against (hybrid.metrics' force_step and speed_step: the "
           "experiment's force_reference and speed_reference; along a path task its force at the start and 0): "
           "each step's value before, after, and its time")
    return {**array_field(prefix, "references", len(REFERENCES), ("N", "N", "s", "m/s", "m/s", "s"), REFERENCES,
                          doc), "numbers": numbers}


def build_standalone_plant(rhs: Kernel, outputs: Kernel, force_columns: tuple[str, ...], prefix: str, what: str,
                           info: dict, values: dict, backend: str = "casadi", part: bool = False,
                           path: bool = False) -> Unit:
    """C source, header and manifest of the standalone plant ``prefix`` (also its files' stem).

    ``rhs`` is the state derivative ``x' = f(x, tau, ...)``, ``outputs`` the record ``y(x, ...)``,
    ``force_columns`` the record's columns of the sensor's force on the robot (base axes).
    ``values`` holds what ``_init`` writes: every parameter input by name (a sequence of numbers),
    ``x0`` (the initial state), ``h``, ``steps_per_sample``, ``sample_time``, ``duration`` and
    ``references`` (the metrics' force and speed steps, :data:`REFERENCES`).
    ``backend``: how the kernels are printed (``"sympy"`` or ``"casadi"``; CasADi expressions always
    take CasADi).

    ``part``: the surface is a part's (its ``surface`` input the quadric's parameters, the state's ``s_x``,
    ``s_y``, ``s_z`` the sensor tip): the C includes the evaluator's header (``hybrid_part.h``, shipped
    beside it) and expands the part about the tip where the kernels read the surface; ``values`` has no
    ``surface``. ``path``: the experiment follows a path task, whose metrics the header declares too.
    """
    x, tau = rhs.inputs[0], rhs.inputs[1]
    y = outputs.outputs[0]
    nx, nq, ny = x.size, tau.size, y.size
    if outputs.inputs[0].name != x.name or outputs.inputs[0].size != nx:
        raise ValueError("the output record's first input is not the state")
    params, sizes = [], {}
    for a in (*rhs.inputs[2:], *outputs.inputs[1:]):
        if a.name not in sizes:
            params.append(a)
        if sizes.setdefault(a.name, a.size) != a.size:
            raise ValueError(f"plant input {a.name} has two sizes")
    wanted = (*force_columns, *SIGNALS)
    missing = [c for c in wanted if c not in (y.names or ())]
    if missing:
        raise ValueError(f"the plant records no {', '.join(missing)}")
    if len(force_columns) > 6:
        raise ValueError("a wrench has six numbers")
    P = prefix.upper()

    def scalars(a) -> list[dict] | None:  # the named scalar fields holding a parameter array's elements
        if a.name not in _SCALARS or not a.names:
            return None
        units = list(a.unit) if not isinstance(a.unit, str) else [a.unit] * a.size
        return [{"name": n, "doc": _SCALAR_DOC.get(n, a.name), "unit": u} for n, u in zip(a.names, units)]

    held = [a for a in params if not (part and a.name == "surface")]  # a part's surface: its expansion, each step
    configuration = [configured(prefix, a, _DOC.get(a.name, a.name), values[a.name], scalars(a)) for a in held]
    packed = [f for f in configuration if f["scalars"]]
    x0 = [float(v) for v in values["x0"]]
    if len(x0) != nx:
        raise ValueError(f"x0 takes {nx} values, got {len(x0)}")
    per = int(values["steps_per_sample"])
    if backend == "casadi" or any(isinstance(a.expr, ca.SX) for a in (*rhs.inputs, *rhs.outputs)):
        cores, tools = _casadi_cores(prefix, (rhs, outputs)), f"CasADi {ca.__version__}"
    else:
        cores, tools = _sympy_cores((rhs, outputs)), "SymPy"
    meanings = _MEANING | (_PART_MEANING if part else {})
    statuses = [{"name": name, "code": STATUS_CODES[name], "meaning": meaning} for name, meaning in meanings.items()]
    expanded = None  # on a part: where the state holds the sensor tip, and the surface's size
    if part:  # the sensor tip's three coordinates, one after the other in the state
        tip = [list(x.names or ()).index(n) if n in (x.names or ()) else -1 for n in ("s_x", "s_y", "s_z")]
        if tip[0] < 0 or tip != list(range(tip[0], tip[0] + 3)):
            raise ValueError("a part's plant needs the sensor tip's s_x, s_y, s_z in its state, in order")
        expanded = {"tip": tip[0], "size": sizes["surface"]}
    context = {"prefix": prefix, "what": what, "generator": GENERATOR_VERSION, "comment": comment_safe,
               "statuses": statuses, "configuration": configuration, "nx": nx, "nq": nq, "ny": ny, "part": expanded,
               "x0": {**array_field(prefix, "x0", nx, x.unit, None, "the initial state reset restores (the "
                                    "experiment's start, at rest, pressing with the force reference's first value)"),
                      "numbers": [_number(v) for v in x0]}}
    # the record's columns named by index macros besides the struct's arrays: the signals, the whole record
    records = [{"macros": index_names(prefix, "signals", SIGNALS)},
               {"macros": index_names(prefix, "y", y.names)}]
    # the bands and the window as whole numbers (a header's macros are integers for every tool that reads it)
    names = (*metric_names(nq), *(m.name for m in PATH_METRICS if path))
    context |= {"metrics": METRICS, "metric_names": names, "settling_band": _whole(SETTLING_BAND, 100),
                "touch_band": _whole(TOUCH_BAND, 100), "steady_window_ms": _whole(STEADY_WINDOW_S, 1000),
                "path_metrics": PATH_METRICS if path else (),
                "path_tolerances": {"end_tol_um": _whole(PATH_END_TOL_M, 10 ** 6),
                                    "settled_percent": _whole(PATH_SETTLED_BAND, 100),
                                    "behind_mm": _whole(PATH_BEHIND_M, 1000), "ahead_mm": _whole(PATH_AHEAD_M, 1000)},
                "references": _references(prefix, values["references"])}
    header = render("standalone_plant.h.j2", **context, signals=SIGNALS, records=records,
                    x=array_field(prefix, "x", nx, x.unit, x.names, "the state"))
    source = render("standalone_plant.c.j2", **context, tools=tools, cores=cores, packed=packed, rhs=rhs,
                    outputs=outputs, force=[y.names.index(c) for c in force_columns],
                    signal_columns=[y.names.index(c) for c in SIGNALS], h=_number(values["h"]),
                    steps_per_sample=per, sample_time=_number(values["sample_time"]),
                    duration=_number(values["duration"]))
    fields_doc = [{"name": a.name, "size": a.size, **({"names": list(a.names)} if a.names else {}),
                   "unit": a.unit if isinstance(a.unit, str) else list(a.unit)} for a in held]
    data = {"do_not_edit": MANIFEST_STAMP, "unit": prefix, "generator": GENERATOR_VERSION, "tools": tools,
            **info, "nx": nx, "nq": nq, "state": list(x.names or ()),
            "state_units": [x.unit] * nx if isinstance(x.unit, str) else list(x.unit),
            "outputs": list(y.names), "output_units": [y.unit] * ny if isinstance(y.unit, str) else list(y.unit),
            "signals": list(SIGNALS), "wrench": [*force_columns, *(["0"] * (6 - len(force_columns)))],
            "status": {f"{P}_{k}": STATUS_CODES[k] for k in meanings},
            "status_meaning": {f"{P}_{k}": m for k, m in meanings.items()},
            "struct": prefix, "fields": fields_doc,
            "scalars": {f["name"]: [s["name"] for s in f["scalars"]] for f in packed},
            "functions": [f"{prefix}_{f}" for f in ("init", "reset", *(("set_part",) if part else ()), "wrench",
                                                     "advance", "signals", "outputs", "status_name", "metric_name")],
            "metrics": list(names),
            "configuration": {**{a.name: [float(v) for v in values[a.name]] for a in held}, "x0": x0,
                              "h": float(values["h"]), "steps_per_sample": per,
                              "sample_time": float(values["sample_time"]), "duration": float(values["duration"]),
                              "references": [float(v) for v in values["references"]]}}
    data["body_sha256"] = json_body_hash(data)
    return Unit(prefix, stamp(source), stamp(header), json.dumps(data, indent=1) + "\n")
