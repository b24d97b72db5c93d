"""Assemble the generated C units: kernels of one backend behind the project's calling convention.

Every public function of a unit ``hybrid_<backend>``:

- takes caller-owned ``double`` arrays (inputs ``const``), allocates nothing, touches no
  global state, so it is reentrant;
- takes the arm, surface and plant parameters as run-time arrays (one build serves
  every parameter value);
- returns an ``int`` status: ``HYBRID_OK``, ``HYBRID_SINGULAR`` (Jacobian conditioning
  below the caller's tolerance) or ``HYBRID_NONFINITE`` (an output is NaN or infinite).

The text is a pure function of the symbolic model and the backend's version: no dates,
no paths, stable ordering, so regenerating gives the same bytes.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from importlib.metadata import version
from pathlib import Path

from . import model
from .model import Kernel

BACKENDS = ("sympy", "casadi")
STAMP = "/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: "
STATUS = {"HYBRID_OK": 0, "HYBRID_SINGULAR": 1, "HYBRID_NONFINITE": 2}
#: kernels evaluated over N states by a ``_batch`` entry point, with their per-state inputs
BATCHED = {"decoupling_law": ("q", "qd", "a", "Fc"), "plant_outputs": ("x",)}


@dataclass(frozen=True)
class Unit:
    """One generated translation unit: ``hybrid_<backend>.c`` and its header."""

    backend: str
    source: str
    header: str

    @property
    def files(self) -> dict[str, str]:
        return {f"hybrid_{self.backend}.c": self.source, f"hybrid_{self.backend}.h": self.header}


def stamp(body: str) -> str:
    """Prefix ``body`` with the do-not-edit line carrying its hash."""
    return f"{STAMP}{hashlib.sha256(body.encode()).hexdigest()} */\n{body}"


def is_hand_edited(text: str) -> bool:
    """True when a generated file's body no longer matches the hash in its first line."""
    first, _, body = text.partition("\n")
    if not first.startswith(STAMP):
        return True
    return first[len(STAMP):].split()[0] != hashlib.sha256(body.encode()).hexdigest()


# ----------------------------------------------------------------- signatures


def _has_cond(k: Kernel) -> bool:
    return any(n == "cond" for n, _ in k.outputs)


def _base(k: Kernel) -> str:
    return k.name.rsplit("_", 1)[0] if k.name.endswith(("_plane", "_circle")) else k.name


def _params(k: Kernel) -> list[str]:
    """Public C parameters of a kernel's entry point."""
    ps = [f"const double *{n}" for n, _ in k.inputs]
    if _has_cond(k):
        ps.append("double singular_tol")
    ps += [f"double *{n}" for n, _ in k.outputs if n != "cond"]
    return ps


def _sizes_doc(k: Kernel) -> str:
    ins = ", ".join(f"{n}[{m.shape[0]}]" for n, m in k.inputs)
    outs = ", ".join(f"{n}[{m.shape[0]}]" for n, m in k.outputs if n != "cond")
    return f"{k.doc}.\n   in: {ins}; out: {outs}"


def prototypes(prefix: str, kernels: tuple[Kernel, ...]) -> list[tuple[str, str]]:
    """``(doc, prototype)`` of every public function, in order."""
    out = []
    for k in kernels:
        out.append((_sizes_doc(k) + (
            ". Returns HYBRID_SINGULAR when 2|det J|/|J|_F^2 < singular_tol" if _has_cond(k) else ""),
            f"int {prefix}_{k.name}({', '.join(_params(k))});"))
        if _base(k) in BATCHED:
            per = BATCHED[_base(k)]
            ps = ["int n", *_params(k), "int *status"]
            out.append((f"{k.name} over n states: {', '.join(per)} and the outputs are n rows "
                        "(row-major); status[i] per state; returns how many states failed",
                        f"int {prefix}_{k.name}_batch({', '.join(ps)});"))
        if k.name.startswith("plant_rhs_"):
            kind = k.name.rsplit("_", 1)[1]
            nx = k.input_sizes()["x"]
            out.append((f"advance the plant state x[{nx}] by nsteps classical RK4 steps of h [s] with tau "
                        f"held constant (zero-order hold); if trajectory is not NULL it receives the "
                        f"state after each step (nsteps x {nx}, row-major). On HYBRID_NONFINITE, x "
                        "keeps the last finite state and *steps_done says how many steps completed",
                        f"int {prefix}_plant_advance_{kind}(double *x, const double *tau, const double *arm, "
                        "const double *plant, const double *surface, double h, int nsteps, "
                        "double *trajectory, int *steps_done);"))
    return out


def _layout_doc(n_links: int) -> str:
    rows = [
        ("arm", model.arm_parameter_names(n_links)),
        ("plant", model.PLANT_PARAMETERS),
        *((f"surface ({k})", v) for k, v in model.SURFACE_PARAMETERS.items()),
        ("opts (decoupling law)", model.LAW_OPTIONS),
        ("y (plant outputs)", model.PLANT_OUTPUTS),
    ]
    return "\n".join(f"   {name}[{len(v)}] = {{{', '.join(v)}}}" for name, v in rows)


def header(prefix: str, kernels: tuple[Kernel, ...], n_links: int) -> str:
    guard = prefix.upper() + "_H"
    status = "\n".join(f"#define {k} {v}" for k, v in STATUS.items())
    protos = "\n\n".join(f"/* {doc}. */\n{p}" for doc, p in prototypes(prefix, kernels))
    return f"""#ifndef {guard}
#define {guard}

/* Parameter arrays (SI units: m, kg, kg m^2, N m s/rad, N/m, N s/m, m/s):
{_layout_doc(n_links)}
   Matrices are row-major. */

/* cdef-begin */
{status}

{protos}
/* cdef-end */

#endif
"""


# ------------------------------------------------------------------- wrappers


def _wrappers(prefix: str, kernels: tuple[Kernel, ...]) -> str:
    """Public entry points: status checks, batch loops and the RK4 integrator."""
    out = [f"""#include "{prefix}.h"

static int all_finite(const double *v, int n) {{
    int i;
    for (i = 0; i < n; ++i) {{
        if (!isfinite(v[i])) return 0;
    }}
    return 1;
}}
"""]
    for k in kernels:
        ins = [n for n, _ in k.inputs]
        outs = [(n, m.shape[0]) for n, m in k.outputs if n != "cond"]
        core_args = ins + [n for n, _ in outs] + (["cond"] if _has_cond(k) else [])
        lines = [f"int {prefix}_{k.name}({', '.join(_params(k))}) {{"]
        if _has_cond(k):
            lines.append("    double cond[1];")
        lines.append(f"    {k.name}_core({', '.join(core_args)});")
        if _has_cond(k):
            lines.append("    if (!(fabs(cond[0]) >= singular_tol)) return HYBRID_SINGULAR;")
        finite = " && ".join(f"all_finite({n}, {s})" for n, s in outs)
        lines.append(f"    return ({finite}) ? HYBRID_OK : HYBRID_NONFINITE;\n}}\n")
        out.append("\n".join(lines))
        if _base(k) in BATCHED:
            per = set(BATCHED[_base(k)])
            sizes = {**k.input_sizes(), **k.output_sizes()}
            args = []
            for p in _params(k):
                name = p.split("*")[-1] if "*" in p else p.split()[-1]
                shifted = name in per or (name in sizes and p.startswith("double *"))
                args.append(f"{name} + (long)i * {sizes[name]}" if shifted else name)
            out.append(f"""int {prefix}_{k.name}_batch(int n, {', '.join(_params(k))}, int *status) {{
    int i, failed = 0;
    for (i = 0; i < n; ++i) {{
        status[i] = {prefix}_{k.name}({', '.join(args)});
        failed += status[i] != HYBRID_OK;
    }}
    return failed;
}}
""")
        if k.name.startswith("plant_rhs_"):
            kind = k.name.rsplit("_", 1)[1]
            nx = k.input_sizes()["x"]
            out.append(f"""int {prefix}_plant_advance_{kind}(double *x, const double *tau, const double *arm, const double *plant, const double *surface, double h, int nsteps, double *trajectory, int *steps_done) {{
    double k1[{nx}], k2[{nx}], k3[{nx}], k4[{nx}], xt[{nx}];
    int i, step;
    for (step = 0; step < nsteps; ++step) {{
        plant_rhs_{kind}_core(x, tau, arm, plant, surface, k1);
        for (i = 0; i < {nx}; ++i) xt[i] = x[i] + 0.5 * h * k1[i];
        plant_rhs_{kind}_core(xt, tau, arm, plant, surface, k2);
        for (i = 0; i < {nx}; ++i) xt[i] = x[i] + 0.5 * h * k2[i];
        plant_rhs_{kind}_core(xt, tau, arm, plant, surface, k3);
        for (i = 0; i < {nx}; ++i) xt[i] = x[i] + h * k3[i];
        plant_rhs_{kind}_core(xt, tau, arm, plant, surface, k4);
        for (i = 0; i < {nx}; ++i) xt[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        if (!all_finite(xt, {nx})) {{
            if (steps_done) *steps_done = step;
            return HYBRID_NONFINITE;
        }}
        for (i = 0; i < {nx}; ++i) x[i] = xt[i];
        if (trajectory) {{
            for (i = 0; i < {nx}; ++i) trajectory[(long)step * {nx} + i] = x[i];
        }}
    }}
    if (steps_done) *steps_done = nsteps;
    return HYBRID_OK;
}}
""")
    return "\n".join(out)


def _core_signature(k: Kernel) -> str:
    ps = [f"const double *{n}" for n, _ in k.inputs] + [f"double *{n}" for n, _ in k.outputs]
    return f"static void {k.name}_core({', '.join(ps)})"


def _sympy_cores(kernels: tuple[Kernel, ...]) -> str:
    from .sympy_backend import kernel_body

    return "\n".join(f"{_core_signature(k)} {{\n{kernel_body(k)}\n}}\n" for k in kernels)


def _casadi_cores(prefix: str, kernels: tuple[Kernel, ...]) -> str:
    from .casadi_backend import kernel_sources

    code, table = kernel_sources(list(kernels), prefix)
    cores = [code]
    for k in kernels:
        fn, sz_w = table[k.name]
        cores.append(f"""{_core_signature(k)} {{
    const double *arg[{len(k.inputs)}];
    double *res[{len(k.outputs)}];
    double w[{max(sz_w, 1)}];
    {" ".join(f"arg[{i}] = {n};" for i, (n, _) in enumerate(k.inputs))}
    {" ".join(f"res[{i}] = {n};" for i, (n, _) in enumerate(k.outputs))}
    (void){fn}(arg, res, 0, w, 0);
}}
""")
    return "\n".join(cores)


def build_unit(backend: str, n_links: int = 2) -> Unit:
    """Generate the C source and header of one backend."""
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {BACKENDS}")
    prefix = f"hybrid_{backend}"
    kernels = model.kernels(n_links)
    tool = f"SymPy {version('sympy')}" + (f", CasADi {version('casadi')}" if backend == "casadi" else "")
    cores = _sympy_cores(kernels) if backend == "sympy" else _casadi_cores(prefix, kernels)
    source = f"""/* {prefix}: hybrid force/velocity control kernels for a planar {n_links}-link arm.
   Derived by codegen/model.py, emitted by the {backend} backend ({tool}).
   Compile: cc -std=c99 -O2 -c {prefix}.c (link with -lm). */
#include <math.h>

{cores}
{_wrappers(prefix, kernels)}"""
    return Unit(backend, stamp(source), stamp(header(prefix, kernels, n_links)))


def generated_dir() -> Path:
    """The repository's ``generated/`` folder."""
    return Path(__file__).resolve().parent.parent / "generated"
