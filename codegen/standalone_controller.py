"""The controller as standalone C: one control sample behind a struct the caller owns.

``<prefix>_controller`` holds everything one sample reads and keeps: the configuration (the step's
run-time parameters, which may change between samples), the references the caller computes, the
loops' integrals, the torque last written, the sample clock, and the last sample's loop outputs.
``<prefix>_controller_step(&c, t, q, qd, wrench, tau)`` runs one sample of the step kernel of
:mod:`codegen.controller_step` (measurement, loops, law, torque limits) and checks the call:

- a run-time parameter (any configuration field, ``timing_tolerance``, ``singular_tol``) that its
  declared check refuses (:data:`hybrid.spec.interfaces.CHECKS`, stated on the ports of
  :data:`hybrid.spec.controller_step.CONTROLLER_STEP`: a NaN, a negative limit or tolerance, a
  filter cutoff at or above Nyquist), or a sample clock ``t_last`` that is not finite:
  ``PARAMETER_INVALID``, ``tau`` the torque last written (within the last valid limits; 0 before
  any), nothing changes: a limit is never lifted, nor its sign flipped;

- a non-finite ``t``, ``q``, ``qd`` or ``wrench``: ``INPUT_NONFINITE``, ``tau`` the torque last
  written (0 before any), nothing changes;
- the law failing (its guards, a non-finite output): that status, ``tau`` the torque last written,
  nothing changes (the clock neither: the next sample is timed from the last one served);
- ``t`` late or early (its interval since the last sample outside ``(1 +- tolerance) T``):
  ``SAMPLE_LATE``, ``SAMPLE_EARLY``, ``tau`` the law's at this sample within the limits, the
  integrals unchanged, the other states (last torque, filter, estimate) advanced; the clock follows
  ``t`` (so the next sample on time is accepted);
- ``t`` equal to the last sample's or before it: ``SAMPLE_REPEATED``, ``SAMPLE_BACKWARDS``, ``tau``
  the law's at this sample within the limits (rate-limited from the torque last written), and
  nothing changes: no time passed, so no state (integrals, last torque, filter, estimate, clock,
  the loop outputs) may advance as if a sample period had.

A faulted sample (any status above but ``SAMPLE_REPEATED`` and ``SAMPLE_BACKWARDS``, at which no time
passed) counts in ``fault_state``; a sample served on time ends the count. After ``fault_samples``
consecutive ones the step is in its safe state (:mod:`codegen.safe_stop`) until a reset:
``SAFE_STOP`` at every sample, ``tau`` the safe-stop kernel's (from the struct's numbers, or the
generated configuration's where the struct holds one its check refuses; from the last finite joint
positions and zero velocities where the sample's are not finite; before any finite ones since the
reset, the torque last written, the arm then stopped where the first finite ones bring it), the law no
longer served.

The Python :class:`hybrid.Controller` does the same (raising where this returns a status), and
the text is a pure function of its inputs (no dates, no paths, stable ordering).
"""

from __future__ import annotations

import json
import re

import casadi as ca

from hybrid.spec.controller_step import (
    CONTROLLER_STEP,
    FAULT_DOCS,
    LOOP_GAINS,
    OPTION_DOCS,
    SAFE_STOP,
    SETTING_CHECKS,
    STATE_NEXT,
)
from hybrid.spec.interfaces import (
    CHECKS,
    HELD_STATUSES,
    PARAMETER,
    REFERENCE,
    STATE,
    STATUSES,
    TIMING_STATUSES,
    Dims,
)
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_SETTINGS, PATH_STATE
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from .emit import GENERATOR_VERSION, Unit, _casadi_cores, comment_safe
from .kernel import Kernel
from .templates import render

#: what the step's wrench argument is, unless the unit's info says otherwise
_WRENCH = "the force and moment on the robot at the tip frame's origin, base axes [N, N m]"
#: the C expression of each per-sample input the call fills from its own arguments and the struct's state
_CALL = {"q": "q", "qd": "qd", "Fc": "wrench", "last_torque": "last", "t": "tv"}
#: the inputs held as named scalar fields (their elements' names), not an array
_SCALARS = ("options", "fault")
#: what each named scalar field holds
_SCALAR_DOCS = {**OPTION_DOCS, **FAULT_DOCS}


def statuses() -> dict[str, int]:
    """Every status of the standalone step by its short name (:data:`hybrid.spec.interfaces.STATUSES`)."""
    return {s.name: s.code for s in STATUSES}


def _number(v: float) -> str:
    text = repr(float(v))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(f"a configuration value must be finite, got {text}")
    return text


def _macro(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_").upper()


def _unit_text(unit) -> str:
    return unit if isinstance(unit, str) else ", ".join(dict.fromkeys(unit))


def index_names(prefix: str, field: str, names) -> list[str]:
    """The macros ``<PREFIX>_<FIELD>_<NAME>`` naming an array's elements' indices, in order (none when two
    names clash)."""
    made = [f"{prefix.upper()}_{field.upper()}_{_macro(n)}" for n in names or ()]
    return made if len(set(made)) == len(made) else []


def array_field(prefix: str, name: str, size: int, unit, names, doc: str) -> dict:
    """An array field of a standalone struct as ``templates/standalone_common.c.j2`` takes it: its name, size,
    unit (one text), doc, element names and the macros naming their indices."""
    return {"name": name, "size": size, "unit": _unit_text(unit), "doc": doc, "names": list(names or ()),
            "macros": index_names(prefix, name, names)}


def configured(prefix: str, a, doc: str, values, scalars=None) -> dict:
    """The field of the parameter input ``a`` with the configuration's ``values`` (C numbers): an array, or
    the named scalar fields ``scalars`` (each a name, a doc and a unit or None) holding its elements."""
    numbers = [_number(v) for v in values]
    if len(numbers) != a.size:
        raise ValueError(f"{a.name} takes {a.size} values, got {len(numbers)}")
    field = array_field(prefix, a.name, a.size, a.unit, None if scalars else a.names, doc)
    return {**field, "numbers": numbers, "scalars": scalars}


def parameter_checks(dims: Dims, sample_time: str = "c->sample_time") -> list[dict]:
    """The C tests of every run-time parameter the struct holds, from the declaration's checks
    (:data:`hybrid.spec.interfaces.CHECKS`): runs of an array's elements under one check (``field``,
    ``start``, ``stop``, ``valid``) and the scalar fields (``field`` without a range). ``valid`` is a C
    expression of ``x`` (the element) that is true when it is a value its check allows."""
    def valid(check: str) -> str:
        return re.sub(r"\bT\b", sample_time, CHECKS[check].c)

    runs: list[dict] = []
    for p in CONTROLLER_STEP.inputs:
        if not p.check or p.role != PARAMETER:
            continue
        checks = p.checks(dims)
        if p.name in _SCALARS:
            runs += [{"field": name, "valid": valid(k)} for name, k in zip(p.element_names(dims), checks) if k]
            continue
        start = 0
        for i in range(1, len(checks) + 1):
            if i == len(checks) or checks[i] != checks[start]:
                if checks[start]:
                    runs.append({"field": p.name, "start": start, "stop": i, "valid": valid(checks[start])})
                start = i
    return runs + [{"field": name, "valid": valid(k)} for name, k in SETTING_CHECKS.items()]


def build_standalone_controller(step: Kernel, stop: Kernel, prefix: str, what: str, info: dict, values: dict,
                                stem: str | None = None, path: dict | None = None, part: dict | None = None) -> Unit:
    """C source, header and manifest of the standalone controller around ``step``, with ``stop`` (the
    :data:`~hybrid.spec.controller_step.SAFE_STOP` kernel, ``codegen.safe_stop``) its fault reaction:
    its symbols start ``prefix``, its files ``stem`` (default ``prefix``).

    ``values`` holds the configuration ``_init`` writes: every parameter input of ``step`` by name
    (a sequence of numbers), ``timing_tolerance`` and ``singular_tol``. The C is
    ``templates/standalone_controller.h.j2`` and ``.c.j2``'s; their context is the struct's fields by
    section, the statuses and the step kernel's arguments.

    ``path``, for a path task (:mod:`hybrid.spec.path_follow`): ``measure`` (the ``task_measurement`` kernel,
    whose tip position and contact force the follower is given), ``axes`` (the positions of ``t1``, ``t2`` and
    ``n`` among the task axes), ``table`` and ``settings`` (the generated path's numbers), ``retreat_gains``
    (the normal axis's loop gains in the retreat); the C then includes the follower's header
    (``hybrid_path.h``, shipped beside it) and its struct carries the path. ``values`` are the
    controller's at the path's start.

    ``part``, for a part's surface (:mod:`hybrid.spec.part`): ``measure`` (the ``task_measurement`` kernel, whose
    tip position the part is expanded about); the C then includes the evaluator's header (``hybrid_part.h``,
    shipped beside it), its struct points at the part's grid and coefficients (the caller's, given by
    ``<prefix>_controller_set_part`` from the part's data file's numbers), and each sample sets the surface's
    parameters to the part's expansion about the tip.
    """
    declared = [p.name for p in (*CONTROLLER_STEP.inputs, *CONTROLLER_STEP.outputs)]
    if [a.name for a in (*step.inputs, *step.outputs)] != declared:
        raise ValueError(f"a controller step's arguments are not its declaration's {declared}")
    if [a.name for a in (*stop.inputs, *stop.outputs)] != [p.name for p in (*SAFE_STOP.inputs, *SAFE_STOP.outputs)]:
        raise ValueError("the safe-stop kernel's arguments are not its declaration's")
    inputs = {a.name: a for a in step.inputs}
    params = [inputs[n] for n in CONTROLLER_STEP.parameters]
    caller = CONTROLLER_STEP.named(REFERENCE)
    # the state the struct keeps as it is (the last torque is the struct's tau and has_torque; the integrals
    # advance only on a sample on time)
    kept = [inputs[n] for n in CONTROLLER_STEP.named(STATE) if n not in ("last_torque", "integrals")]
    nq, m = inputs["q"].size, inputs["yd_extra"].size
    dims = Dims.sized(("",) * nq, ("",) * m, inputs["robot"].size, inputs["surface"].size)
    out = {a.name: a for a in step.outputs}
    loop_out = [out[n] for n in out if n not in (*STATE_NEXT.values(), "saturated")]
    doc = {p.name: p.doc for p in (*CONTROLLER_STEP.inputs, *CONTROLLER_STEP.outputs)}
    P = prefix.upper()
    stem = stem or prefix
    codes = statuses()

    def field(a) -> dict:
        return array_field(prefix, a.name, a.size, a.unit, a.names, doc[a.name])

    configuration = [
        configured(prefix, a, doc[a.name], values[a.name],
                   [{"name": n, "doc": _SCALAR_DOCS.get(n, n), "unit": None} for n in a.names]
                   if a.name in _SCALARS and a.names else None) for a in params]
    packed = [f for f in configuration if f["scalars"]]
    if "sample_time" not in inputs["options"].names:
        raise ValueError("the controller step's options have no sample_time")
    sections = {"configuration": configuration, "references": [field(inputs[n]) for n in caller],
                "state": [field(a) for a in (inputs["integrals"], *kept)], "loop_outputs": [field(a) for a in loop_out]}
    sections["kept"] = sections["state"][1:]
    stop_state = next(a for a in stop.inputs if a.name == "fault_state")
    context = {"prefix": prefix, "stem": stem, "what": what, "generator": GENERATOR_VERSION, "comment": comment_safe,
               "statuses": STATUSES, "nq": nq, "m": m, **sections,
               "fault_state": array_field(prefix, stop_state.name, stop_state.size, stop_state.unit, stop_state.names,
                                          SAFE_STOP.port("fault_state").doc)}
    kernels = (step, stop)
    if path is not None:
        measure = path["measure"]
        kernels += (measure,)
        t1, t2, n = path["axes"]
        spins = path.get("spins")
        context["path"] = {"measure": measure, "measure_outs": measure.core_outputs(), "t1": t1, "t2": t2, "n": n,
                           "spins": spins,
                           "measure_call": {"q": "q", "qd": "qd", "Fc": "wrench"},
                           "gains_at": len(LOOP_GAINS) * n,
                           "force_gains": [_number(x) for x in values["gains"][len(LOOP_GAINS) * n:
                                                                             len(LOOP_GAINS) * (n + 1)]],
                           "retreat_gains": [_number(float(x)) for x in path["retreat_gains"]],
                           "start_e": [_number(x) for x in values["e"]],
                           "sizes": {"settings": len(PATH_SETTINGS), "state": len(PATH_STATE), "out": len(PATH_OUTPUT)},
                           "table": [_number(float(x)) for x in path["table"]],
                           "settings": [_number(float(x)) for x in path["settings"]]}
    else:
        context["path"] = None
    context["part"] = None
    if part is not None:
        measure = part["measure"]
        if measure not in kernels:
            kernels += (measure,)
        context["part"] = {"measure": measure, "measure_outs": measure.core_outputs(), "size": inputs["surface"].size,
                           "measure_call": {"q": "q", "qd": "qd", "Fc": "wrench"}}
    header = render("standalone_controller.h.j2", **context, wrench=info.get("wrench", _WRENCH),
                    tau_unit=_unit_text(out["tau"].unit))
    source = render("standalone_controller.c.j2", **context, tools=f"CasADi {ca.__version__}",
                    cores=_casadi_cores(prefix, kernels), step=step, outs=step.core_outputs(), packed=packed,
                    call=_CALL, state_next=STATE_NEXT, held=HELD_STATUSES, tau=out["tau"], stop=stop,
                    served=[s for s in TIMING_STATUSES if s not in HELD_STATUSES],
                    fault=next(f for f in configuration if f["name"] == "fault"),
                    fault_samples=_number(values["fault"][0]),
                    saturated=out["saturated"],
                    checks=parameter_checks(dims),
                    timing_tolerance=_number(values["timing_tolerance"]),
                    singular_tol=_number(values["singular_tol"]))
    fields_doc = [{"name": a.name, "size": a.size, **({"names": list(a.names)} if a.names else {}),
                   "unit": a.unit if isinstance(a.unit, str) else list(a.unit)}
                  for a in (*params, *(inputs[n] for n in caller))]
    data = {"do_not_edit": MANIFEST_STAMP, "unit": stem, **({"prefix": prefix} if stem != prefix else {}),
            "generator": GENERATOR_VERSION,
            "tools": f"CasADi {ca.__version__}", **info, "nq": nq, "m": m,
            "status": {f"{P}_{k}": v for k, v in codes.items()},
            "status_meaning": {f"{P}_{s.name}": s.meaning for s in STATUSES},
            "struct": f"{prefix}_controller", "fields": fields_doc,
            "scalars": {a.name: list(a.names) for a in params if a.name in _SCALARS},
            "functions": [f"{prefix}_controller_init", f"{prefix}_controller_reset",
                          *([f"{prefix}_controller_set_part"] if part is not None else []),
                          f"{prefix}_controller_step", f"{prefix}_status_name"],
            "configuration": {k: ([float(x) for x in v] if not isinstance(v, (int, float)) else float(v))
                              for k, v in sorted(values.items())}}
    data["body_sha256"] = json_body_hash(data)
    return Unit(stem, stamp(source), stamp(header), json.dumps(data, indent=1) + "\n")
