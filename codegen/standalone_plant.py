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
  (the formula of :func:`codegen.emit.rk4_step`, the one every integrator of the project takes);
- ``<prefix>_signals(&p, s)``: the record columns the metrics read (normal force, tangential speed,
  penetration, the surface's normal force: :data:`codegen.closed_loop.SIGNALS`);
- ``<prefix>_outputs(&p, y)``: the plant's whole output record at ``x``.

The text is a pure function of its inputs (no dates, no paths, stable ordering).
"""

from __future__ import annotations

import json

import casadi as ca

from hybrid.spec.interfaces import STATUS_CODES
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from .closed_loop import SIGNALS
from .emit import GENERATOR_VERSION, Unit, _casadi_cores, _sympy_cores, comment_safe, rk4_step
from .kernel import Kernel
from .standalone_controller import _index_macros, _number, array_statement, init_statements, status_name_source

#: the plant's statuses (their numbers are :data:`hybrid.spec.interfaces.STATUSES`', as every unit's) and what
#: each means for a plant
_MEANING = {
    "OK": "done",
    "NONFINITE": "the state would stop being finite: x is the last finite state, steps counts the steps done",
    "INPUT_NONFINITE": "the torque or the state is not finite: nothing changed",
}
#: parameter arrays held as named scalar fields (their elements' names), not arrays
_SCALARS = ("plant",)
#: what each named scalar of the plant's array is (the names of ``spatial_plant.PLANT_PARAMETERS``)
_SCALAR_DOC = {"m_s": "the sensor tip's mass", "K_s": "the sensor's stiffness", "D_s": "the sensor's damping",
               "k_e": "the contact's stiffness", "d_e": "the contact's damping", "gamma": "the friction coefficient",
               "v_eps": "the speed of the friction's tanh smoothing"}
#: what each parameter array holds, for the header
_DOC = {"robot": "the true arm's inertial parameters, joint viscosities and gravity",
        "arm": "the planar arm's lengths, masses, inertias, viscosities",
        "plant": "the sensor and the contact", "surface": "the surface's parameters",
        "e": "the task frame's reference direction (the output record's task axes)"}


def _unit_text(unit) -> str:
    return unit if isinstance(unit, str) else ", ".join(dict.fromkeys(unit))


def build_standalone_plant(rhs: Kernel, outputs: Kernel, force_columns: tuple[str, ...], prefix: str, what: str,
                           info: dict, values: dict, backend: str = "casadi") -> Unit:
    """C source, header and manifest of the standalone plant ``prefix`` (also its files' stem).

    ``rhs`` is the state derivative ``x' = f(x, tau, ...)``, ``outputs`` the record ``y(x, ...)``,
    ``force_columns`` the record's columns of the sensor's force on the robot (base axes).
    ``values`` holds what ``_init`` writes: every parameter input by name (a sequence of numbers),
    ``x0`` (the initial state), ``h``, ``steps_per_sample``, ``sample_time`` and ``duration``.
    ``backend``: how the kernels are printed (``"sympy"`` or ``"casadi"``; CasADi expressions always
    take CasADi).
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

    # ------------------------------------------------------------------ the struct
    fields, macros = [], []

    def array_field(name: str, size: int, unit, names, doc: str) -> None:
        layout = f" = {{{comment_safe(', '.join(names))}}}" if names else ""
        fields.append(f"    /* {comment_safe(doc)} [{comment_safe(_unit_text(unit))}]{layout} */\n"
                      f"    double {name}[{size}];")
        if names:
            macros.extend(_index_macros(prefix, name, names))

    fields.append("    /* ---- the plant's run-time parameters (the experiment's after init; any may change "
                  "between steps) */")
    for a in params:
        if a.name in _SCALARS and a.names:
            units = list(a.unit) if not isinstance(a.unit, str) else [a.unit] * a.size
            fields += [f"    double {n}; /* {comment_safe(_SCALAR_DOC.get(n, a.name))} [{comment_safe(u)}] */"
                       for n, u in zip(a.names, units)]
        else:
            array_field(a.name, a.size, a.unit, a.names, _DOC.get(a.name, a.name))
    fields.append("    /* ---- the experiment's timing: what a closed loop around this plant runs */")
    fields.append("    double h; /* the RK4 step [s] */")
    fields.append("    int steps_per_sample; /* RK4 steps per control sample (the torque held over them) */")
    fields.append("    double sample_time; /* the control sample time, steps_per_sample * h [s] */")
    fields.append("    double duration; /* the experiment's duration [s] */")
    fields.append("    /* ---- the state */")
    array_field("x", nx, x.unit, x.names, "the state")
    array_field("x0", nx, x.unit, None, "the initial state reset restores (the experiment's start, at rest, "
                                        "pressing with the force reference's first value)")
    fields.append("    long steps; /* RK4 steps since init or reset (the time is steps * h) */")
    struct = "typedef struct {\n" + "\n".join(fields) + f"\n}} {prefix};"
    macros += _index_macros(prefix, "signals", wanted[len(force_columns):])
    macros += _index_macros(prefix, "y", y.names)

    status_lines = "\n".join(f"#define {P}_{name} {STATUS_CODES[name]} /* {comment_safe(meaning)} */"
                             for name, meaning in _MEANING.items())
    defines = [f"#define {P}_NX {nx} /* state */", f"#define {P}_NQ {nq} /* joints */",
               f"#define {P}_NSIGNALS {len(SIGNALS)} /* signals */", f"#define {P}_NY {ny} /* output record */"]
    header = f"""#ifndef {P}_H
#define {P}_H
/* {prefix}: {comment_safe(what)}.
   Standalone C99: no allocation, no globals, no I/O; reentrant (every state is in the struct).
   Emitted by hybrid's codegen (generator version {GENERATOR_VERSION}); interface: {prefix}.json.

   {prefix} p;
   {prefix}_init(&p);                        (the experiment's parameters, timing and start state)
   {prefix}_wrench(&p, wrench);              (the sensor's reading: what the controller's step takes)
   status = {prefix}_advance(&p, tau, n);    (n RK4 steps of p.h, tau held; {P}_OK is 0)

   wrench: the force and moment on the robot at the tip frame's origin, base axes [N, N m]. */

{chr(10).join(defines)}
{status_lines}
{chr(10).join(macros)}

{struct}

/* the experiment's parameters, timing and initial state; x = x0 */
void {prefix}_init({prefix} *p);
/* a new run: x = x0, steps = 0 (the parameters as they are) */
void {prefix}_reset({prefix} *p);
/* the sensor's reading at x: the force and moment on the robot at the tip, base axes [6] */
int {prefix}_wrench(const {prefix} *p, double *wrench);
/* advance x by nsteps classical RK4 steps of h with tau [{P}_NQ] held (zero-order hold) */
int {prefix}_advance({prefix} *p, const double *tau, int nsteps);
/* the record columns the metrics read at x [{P}_NSIGNALS] = {{{comment_safe(', '.join(SIGNALS))}}} */
int {prefix}_signals(const {prefix} *p, double *signals);
/* the plant's output record at x [{P}_NY] (the {P}_Y_ indices above) */
int {prefix}_outputs(const {prefix} *p, double *y);
/* the status's name ("OK", "NONFINITE", ...), "UNKNOWN" for another number */
const char *{prefix}_status_name(int status);

#endif
"""

    # ------------------------------------------------------------------ the functions
    init = init_statements("p", params, values, _SCALARS)
    x0 = [float(v) for v in values["x0"]]
    if len(x0) != nx:
        raise ValueError(f"x0 takes {nx} values, got {len(x0)}")
    init.append(array_statement("p", "x0", x0))
    per = int(values["steps_per_sample"])
    init += [f"    p->h = {_number(values['h'])};", f"    p->steps_per_sample = {per};",
             f"    p->sample_time = {_number(values['sample_time'])};",
             f"    p->duration = {_number(values['duration'])};"]
    scalars = [a for a in params if a.name in _SCALARS and a.names]

    def packed(a) -> str:
        return a.name if a.name in {s.name for s in scalars} else f"p->{a.name}"

    packs = "".join(f"    double {a.name}[{a.size}];\n" for a in scalars)
    pack = "".join(f"    {a.name}[{i}] = p->{n};\n" for a in scalars for i, n in enumerate(a.names))
    held = ", ".join(packed(a) for a in rhs.inputs[2:])
    shown = ", ".join(packed(a) for a in outputs.inputs[1:])
    force = "".join(f"    wrench[{i}] = y[{y.names.index(c)}];\n" for i, c in enumerate(force_columns))
    force += "".join(f"    wrench[{i}] = 0.0;\n" for i in range(len(force_columns), 6))
    signals = "".join(f"    signals[{i}] = y[{y.names.index(c)}];\n" for i, c in enumerate(SIGNALS))
    rk4 = rk4_step(f"{rhs.name}_core({{state}}, tau, {held}, {{k}});", "p->x", nx, "xt", " " * 8)
    if backend == "casadi" or any(isinstance(a.expr, ca.SX) for a in (*rhs.inputs, *rhs.outputs)):
        cores, tools = _casadi_cores(prefix, (rhs, outputs)), f"CasADi {ca.__version__}"
    else:
        cores, tools = _sympy_cores((rhs, outputs)), "SymPy"
    source = f"""/* {prefix}: {comment_safe(what)}.
   Emitted by hybrid's codegen (generator version {GENERATOR_VERSION}, {tools}).
   Compile: cc -std=c99 -O2 -c {prefix}.c (link with -lm). */
#include <math.h>
#include "{prefix}.h"

{cores}
static int all_finite(const double *v, int n) {{
    int i;
    for (i = 0; i < n; ++i) {{
        if (!isfinite(v[i])) return 0;
    }}
    return 1;
}}

void {prefix}_reset({prefix} *p) {{
    int i;
    for (i = 0; i < {nx}; ++i) p->x[i] = p->x0[i];
    p->steps = 0;
}}

void {prefix}_init({prefix} *p) {{
    int i;
{chr(10).join(init)}
    {prefix}_reset(p);
}}

/* the output record at x */
static int record(const {prefix} *p, double *y) {{
{packs}{pack}    {outputs.name}_core(p->x, {shown}, y);
    return all_finite(y, {ny}) ? {P}_OK : {P}_NONFINITE;
}}

int {prefix}_outputs(const {prefix} *p, double *y) {{
    return record(p, y);
}}

int {prefix}_wrench(const {prefix} *p, double *wrench) {{
    double y[{ny}];
    int status = record(p, y);
{force}    return status;
}}

int {prefix}_signals(const {prefix} *p, double *signals) {{
    double y[{ny}];
    int status = record(p, y);
{signals}    return status;
}}

int {prefix}_advance({prefix} *p, const double *tau, int nsteps) {{
    double k1[{nx}], k2[{nx}], k3[{nx}], k4[{nx}], xt[{nx}];
    const double h = p->h;
{packs}    int i, step;
    if (!all_finite(tau, {nq}) || !all_finite(p->x, {nx})) return {P}_INPUT_NONFINITE;
{pack}    for (step = 0; step < nsteps; ++step) {{
{rk4}
        if (!all_finite(xt, {nx})) return {P}_NONFINITE;
        for (i = 0; i < {nx}; ++i) p->x[i] = xt[i];
        ++p->steps;
    }}
    return {P}_OK;
}}

{status_name_source(prefix, _MEANING)}"""
    fields_doc = [{"name": a.name, "size": a.size, **({"names": list(a.names)} if a.names else {}),
                   "unit": a.unit if isinstance(a.unit, str) else list(a.unit)} for a in params]
    data = {"do_not_edit": MANIFEST_STAMP, "unit": prefix, "generator": GENERATOR_VERSION, "tools": tools,
            **info, "nx": nx, "nq": nq, "state": list(x.names or ()),
            "state_units": [x.unit] * nx if isinstance(x.unit, str) else list(x.unit),
            "outputs": list(y.names), "output_units": [y.unit] * ny if isinstance(y.unit, str) else list(y.unit),
            "signals": list(SIGNALS), "wrench": [*force_columns, *(["0"] * (6 - len(force_columns)))],
            "status": {f"{P}_{k}": STATUS_CODES[k] for k in _MEANING},
            "status_meaning": {f"{P}_{k}": m for k, m in _MEANING.items()},
            "struct": prefix, "fields": fields_doc, "scalars": {a.name: list(a.names) for a in scalars},
            "functions": [f"{prefix}_{f}" for f in ("init", "reset", "wrench", "advance", "signals", "outputs",
                                                     "status_name")],
            "configuration": {**{a.name: [float(v) for v in values[a.name]] for a in params}, "x0": x0,
                              "h": float(values["h"]), "steps_per_sample": per,
                              "sample_time": float(values["sample_time"]), "duration": float(values["duration"])}}
    data["body_sha256"] = json_body_hash(data)
    return Unit(prefix, stamp(source), stamp(header), json.dumps(data, indent=1) + "\n")
