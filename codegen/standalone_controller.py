"""The controller as standalone C: one control sample behind a struct the caller owns.

``<prefix>_controller`` holds everything one sample reads and keeps: the configuration (the step's
run-time parameters, which may change between samples), the references the caller computes, the
loops' integrals, the torque last written, the sample clock, and the last sample's loop outputs.
``<prefix>_controller_step(&c, t, q, qd, wrench, tau)`` runs one sample of the step kernel of
:mod:`codegen.controller_step` (measurement, loops, law, torque limits) and checks the call:

- a non-finite ``t``, ``q``, ``qd`` or ``wrench``: ``INPUT_NONFINITE``, ``tau`` the torque last
  written (0 before any), nothing changes;
- the law failing (its guards, a non-finite output): that status, ``tau`` the torque last written,
  the integrals and the last torque unchanged; the clock follows ``t``;
- ``t`` off the sample clock (its interval since the last sample outside ``(1 +- tolerance) T``, or
  0, or negative): ``SAMPLE_LATE``, ``SAMPLE_EARLY``, ``SAMPLE_REPEATED``, ``SAMPLE_BACKWARDS``,
  ``tau`` the law's at this sample within the limits, the integrals unchanged; the clock follows a
  forward ``t`` (so the next sample on time is accepted).

The Python :class:`hybrid.Controller` does the same (raising where this returns a status), and
the text is a pure function of its inputs (no dates, no paths, stable ordering).
"""

from __future__ import annotations

import json
import re

import casadi as ca

from hybrid.spec.controller_step import CONTROLLER_STEP, OPTION_DOCS, STATE_NEXT
from hybrid.spec.interfaces import REFERENCE, STATE, STATUS_CODES, STATUSES
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from .emit import GENERATOR_VERSION, Unit, _casadi_cores, comment_safe
from .kernel import Kernel

#: what the step's wrench argument is, unless the unit's info says otherwise
_WRENCH = "the force and moment on the robot at the tip frame's origin, base axes [N, N m]"
#: the C expression of each per-sample input the call fills from its own arguments and the struct's state
_CALL = {"q": "q", "qd": "qd", "Fc": "wrench", "last_torque": "last", "t": "tv"}
#: the inputs held as named scalar fields (their elements' names), not an array
_SCALARS = ("options",)


def statuses() -> dict[str, int]:
    """Every status of the standalone step by its short name (:data:`hybrid.spec.interfaces.STATUSES`)."""
    return {s.name: s.code for s in STATUSES}


def status_name_source(prefix: str, names) -> str:
    """The C function ``<prefix>_status_name`` naming each of the statuses ``names`` (their numbers are
    :data:`hybrid.spec.interfaces.STATUSES`'), ``"UNKNOWN"`` another number."""
    cases = "".join(f'    case {STATUS_CODES[n]}: return "{n}";\n' for n in names)
    return (f"const char *{prefix}_status_name(int status) {{\n    switch (status) {{\n{cases}"
            '    default: return "UNKNOWN";\n    }\n}\n')


def _number(v: float) -> str:
    text = repr(float(v))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(f"a configuration value must be finite, got {text}")
    return text


def _macro(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_").upper()


def init_statements(struct: str, params, values: dict, scalars: tuple[str, ...]) -> list[str]:
    """C statements giving the fields of ``struct`` (a pointer's name) the configuration's ``values``: one
    field per parameter input, or its elements' named fields for the inputs in ``scalars``."""
    lines = []
    for a in params:
        vals = [float(v) for v in values[a.name]]
        if len(vals) != a.size:
            raise ValueError(f"{a.name} takes {a.size} values, got {len(vals)}")
        if a.name in scalars and a.names:
            lines += [f"    {struct}->{n} = {_number(v)};" for n, v in zip(a.names, vals)]
        else:
            lines.append(array_statement(struct, a.name, vals))
    return lines


def array_statement(struct: str, field: str, vals) -> str:
    """The C block copying the numbers ``vals`` into the array ``struct->field`` (``i`` declared)."""
    numbers = ", ".join(_number(v) for v in vals)
    return (f"    {{\n        static const double v[{len(vals)}] = {{{numbers}}};\n"
            f"        for (i = 0; i < {len(vals)}; ++i) {struct}->{field}[i] = v[i];\n    }}")


def _index_macros(prefix: str, field: str, names) -> list[str]:
    """``#define <PREFIX>_<FIELD>_<NAME> index`` for an array's elements (none when two names clash)."""
    made = [f"{prefix.upper()}_{field.upper()}_{_macro(n)}" for n in names]
    if len(set(made)) < len(made):
        return []
    return [f"#define {m} {i}" for i, m in enumerate(made)]


def build_standalone_controller(step: Kernel, prefix: str, what: str, info: dict, values: dict,
                                stem: str | None = None) -> Unit:
    """C source, header and manifest of the standalone controller around ``step``: its symbols start
    ``prefix``, its files ``stem`` (default ``prefix``).

    ``values`` holds the configuration ``_init`` writes: every parameter input of ``step`` by name
    (a sequence of numbers), ``timing_tolerance`` and ``singular_tol``.
    """
    declared = [p.name for p in (*CONTROLLER_STEP.inputs, *CONTROLLER_STEP.outputs)]
    if [a.name for a in (*step.inputs, *step.outputs)] != declared:
        raise ValueError(f"a controller step's arguments are not its declaration's {declared}")
    inputs = {a.name: a for a in step.inputs}
    params = [inputs[n] for n in CONTROLLER_STEP.parameters]
    caller = CONTROLLER_STEP.named(REFERENCE)
    # the state the struct keeps as it is (the last torque is the struct's tau and has_torque; the integrals
    # advance only on a sample on time)
    kept = [inputs[n] for n in CONTROLLER_STEP.named(STATE) if n not in ("last_torque", "integrals")]
    nq, m = inputs["q"].size, inputs["yd_extra"].size
    out = {a.name: a for a in step.outputs}
    tau, z_next, saturated = out["tau"], out["integrals_next"], out["saturated"]
    loop_out = [out[n] for n in out if n not in (*STATE_NEXT.values(), "saturated")]
    doc = {p.name: p.doc for p in (*CONTROLLER_STEP.inputs, *CONTROLLER_STEP.outputs)}
    P = prefix.upper()
    stem = stem or prefix
    codes = statuses()

    # ------------------------------------------------------------------ the struct
    fields, macros = [], []

    def array_field(a, doc: str) -> None:
        unit = a.unit if isinstance(a.unit, str) else ", ".join(dict.fromkeys(a.unit))
        layout = f" = {{{comment_safe(', '.join(a.names))}}}" if a.names else ""
        fields.append(f"    /* {comment_safe(doc)} [{comment_safe(unit)}]{layout} */\n    double {a.name}[{a.size}];")
        if a.names:
            macros.extend(_index_macros(prefix, a.name, a.names))

    fields.append("    /* ---- configuration: the run-time parameters, any of which may change between samples */")
    for a in params:
        if a.name in _SCALARS:
            fields += [f"    double {n}; /* {comment_safe(OPTION_DOCS.get(n, n))} */" for n in a.names]
        else:
            array_field(a, doc[a.name])
    fields.append("    double timing_tolerance; /* a sample is on time when t advanced by sample_time within this "
                  "fraction of it [1]; < 0: no timing check */")
    fields.append("    double singular_tol; /* the task Jacobian's least conditioning [1] */")
    fields.append("    /* ---- references the caller computes each sample (0 after init): added to the steps' "
                  "values */")
    for name in caller:
        array_field(inputs[name], doc[name])
    fields.append("    /* ---- state kept between samples (zero after init and reset) */")
    for a in (inputs["integrals"], *kept):
        array_field(a, doc[a.name])
    tau_unit = ", ".join(dict.fromkeys(tau.unit if isinstance(tau.unit, tuple) else (tau.unit,)))
    fields.append(f"    double tau[{nq}]; /* the torque last written [{comment_safe(tau_unit)}] */")
    fields.append("    int has_torque; /* 1: tau is the arm's torque, the next sample is rate-limited from it "
                  "(a tau that is not finite is discarded) */")
    fields.append("    double t_last; /* the sample clock: the last sample's t [s] */")
    fields.append("    int has_clock; /* 1: t_last is set (the next sample's timing is checked) */")
    fields.append("    /* ---- the last sample's loop outputs (loop frame) */")
    for a in loop_out:
        array_field(a, doc[a.name])
    fields.append("    int saturated; /* 1: a torque limit bounded the last sample's torque (integrals kept) */")
    struct = "typedef struct {\n" + "\n".join(fields) + f"\n}} {prefix}_controller;"

    status_lines = "\n".join(f"#define {P}_{s.name} {s.code} /* {comment_safe(s.meaning)} */" for s in STATUSES)
    defines = [f"#define {P}_NQ {nq} /* joints */", f"#define {P}_M {m} /* task axes */"]
    header = f"""#ifndef {stem.upper()}_H
#define {stem.upper()}_H
/* {prefix}: {comment_safe(what)}.
   Standalone C99: no allocation, no globals, no I/O; reentrant (every state is in the struct).
   Emitted by hybrid's codegen (generator version {GENERATOR_VERSION}); interface: {stem}.json.

   {prefix}_controller c;
   {prefix}_controller_init(&c);                                   (the configuration's values)
   status = {prefix}_controller_step(&c, t, q, qd, wrench, tau);   (one sample; {P}_OK is 0)

   wrench: {comment_safe(info.get("wrench", _WRENCH))}. */

{chr(10).join(defines)}
{status_lines}
{chr(10).join(macros)}

{struct}

/* the configuration's values, and the state of a new run */
void {prefix}_controller_init({prefix}_controller *c);
/* a new run: the state zero (the configuration and the caller's references as they are) */
void {prefix}_controller_reset({prefix}_controller *c);
/* one control sample at time t [s] from q, qd [{P}_NQ] and wrench [6]: writes tau [{P}_NQ] (always finite)
   and returns a status ({P}_OK, or one of the others above) */
int {prefix}_controller_step({prefix}_controller *c, double t, const double *q, const double *qd,
                             const double *wrench, double *tau);
/* the status's name ("OK", "SAMPLE_LATE", ...), "UNKNOWN" for another number */
const char *{prefix}_status_name(int status);

#endif
"""

    # ------------------------------------------------------------------ the functions
    init = init_statements("c", params, values, _SCALARS)
    init.append(f"    c->timing_tolerance = {_number(values['timing_tolerance'])};")
    init.append(f"    c->singular_tol = {_number(values['singular_tol'])};")
    for name in caller:
        init.append(f"    for (i = 0; i < {inputs[name].size}; ++i) c->{name}[i] = 0.0;")
    scalars = {a.name: a for a in params if a.name in _SCALARS}
    packs = "".join(f"    double {name}[{a.size}];\n" for name, a in scalars.items())
    pack = "".join(f"    {name}[{i}] = c->{n};\n" for name, a in scalars.items() for i, n in enumerate(a.names))
    call = ", ".join([*(_CALL.get(a.name, a.name if a.name in _SCALARS else f"c->{a.name}") for a in step.inputs),
                      *(f"o_{a.name}" for a in step.core_outputs())])
    outs = "".join(f"    double o_{a.name}[{a.size}];\n" for a in step.core_outputs())
    guards = "".join(
        f"    if (status == {P}_OK && fabs(o_{g.name}[0]) < "
        f"{'c->singular_tol' if g.tolerance == 'singular_tol' else g.c_tolerance}) "
        f"status = {P}_{g.status.removeprefix('HYBRID_')};\n" for g in step.guards)
    finite = " || ".join(f"!all_finite(o_{a.name}, {a.size})" for a in step.core_outputs())

    def zeroed(arrays) -> str:
        return "".join(f"    for (i = 0; i < {a.size}; ++i) c->{a.name}[i] = 0.0;\n" for a in arrays)

    def copied(pairs) -> str:  # (field, the output it takes)
        return "".join(f"    for (i = 0; i < {a.size}; ++i) c->{a.name}[i] = o_{o}[i];\n" for a, o in pairs)

    keep, advance = copied((a, a.name) for a in loop_out), copied((a, STATE_NEXT[a.name]) for a in kept)
    if "sample_time" not in scalars["options"].names:
        raise ValueError("the controller step's options have no sample_time")
    source = f"""/* {prefix}: {comment_safe(what)}.
   Emitted by hybrid's codegen (generator version {GENERATOR_VERSION}, CasADi {ca.__version__}).
   Compile: cc -std=c99 -O2 -c {stem}.c (link with -lm). */
#include <math.h>
#include "{stem}.h"

{_casadi_cores(prefix, (step,))}
static int all_finite(const double *v, int n) {{
    int i;
    for (i = 0; i < n; ++i) {{
        if (!isfinite(v[i])) return 0;
    }}
    return 1;
}}

void {prefix}_controller_reset({prefix}_controller *c) {{
    int i;
    for (i = 0; i < {2 * m}; ++i) c->integrals[i] = 0.0;
{zeroed(kept)}    for (i = 0; i < {nq}; ++i) c->tau[i] = 0.0;
{zeroed(loop_out)}    c->has_torque = 0;
    c->t_last = 0.0;
    c->has_clock = 0;
    c->saturated = 0;
}}

void {prefix}_controller_init({prefix}_controller *c) {{
    int i;
{chr(10).join(init)}
    {prefix}_controller_reset(c);
}}

/* the timing of a sample at t against the sample clock */
static int timing(const {prefix}_controller *c, double t) {{
    double dt;
    if (!c->has_clock || c->timing_tolerance < 0.0) return {P}_OK;
    dt = t - c->t_last;
    if (dt < 0.0) return {P}_SAMPLE_BACKWARDS;
    if (dt == 0.0) return {P}_SAMPLE_REPEATED;
    if (dt < c->sample_time * (1.0 - c->timing_tolerance)) return {P}_SAMPLE_EARLY;
    if (dt > c->sample_time * (1.0 + c->timing_tolerance)) return {P}_SAMPLE_LATE;
    return {P}_OK;
}}

int {prefix}_controller_step({prefix}_controller *c, double t, const double *q, const double *qd,
                             const double *wrench, double *tau) {{
    double last[{nq + 1}], tv[1];
{packs}{outs}    int i, status = {P}_OK, on_time;
    if (!isfinite(t) || !all_finite(q, {nq}) || !all_finite(qd, {nq}) || !all_finite(wrench, 6)) {{
        for (i = 0; i < {nq}; ++i) tau[i] = c->tau[i];
        return {P}_INPUT_NONFINITE;
    }}
    /* a torque written into the struct that is not a number cannot bound the next: it is discarded */
    if (c->has_torque && !all_finite(c->tau, {nq})) {{
        for (i = 0; i < {nq}; ++i) c->tau[i] = 0.0;
        c->has_torque = 0;
    }}
    on_time = timing(c, t);
    for (i = 0; i < {nq}; ++i) last[i] = c->tau[i];
    last[{nq}] = c->has_torque ? 1.0 : 0.0;
    tv[0] = t;
{pack}    {step.name}_core({call});
{guards}    if (status == {P}_OK && ({finite})) status = {P}_NONFINITE;
    /* the clock follows every sample that moves forward */
    if (!c->has_clock || t > c->t_last) c->t_last = t;
    c->has_clock = 1;
    if (status != {P}_OK) {{
        for (i = 0; i < {nq}; ++i) tau[i] = c->tau[i];
        return status;
    }}
    for (i = 0; i < {nq}; ++i) tau[i] = c->tau[i] = o_{tau.name}[i];
    c->has_torque = 1;
    c->saturated = o_{saturated.name}[0] != 0.0;
{advance}{keep}    if (on_time != {P}_OK) return on_time;
    for (i = 0; i < {2 * m}; ++i) c->integrals[i] = o_{z_next.name}[i];
    return {P}_OK;
}}

{status_name_source(prefix, codes)}"""
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
            "functions": [f"{prefix}_controller_init", f"{prefix}_controller_reset", f"{prefix}_controller_step",
                          f"{prefix}_status_name"],
            "configuration": {k: ([float(x) for x in v] if not isinstance(v, (int, float)) else float(v))
                              for k, v in sorted(values.items())}}
    data["body_sha256"] = json_body_hash(data)
    return Unit(stem, stamp(source), stamp(header), json.dumps(data, indent=1) + "\n")
