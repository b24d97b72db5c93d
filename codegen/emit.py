"""Assemble the generated C units: kernels of one backend behind the project's calling convention.

Every public function of a unit ``hybrid_<backend>``:

- takes caller-owned ``double`` arrays (inputs ``const``), allocates nothing, touches no
  global state, so it is reentrant;
- takes the arm, surface and plant parameters as run-time arrays (one build serves
  every parameter value);
- returns an ``int`` status: ``HYBRID_OK``, ``HYBRID_SINGULAR`` (Jacobian conditioning
  below the caller's tolerance), ``HYBRID_NONFINITE`` (an output is NaN or infinite),
  ``HYBRID_FRAME_UNDEFINED`` (the task frame's reference direction is parallel to the
  surface normal) or ``HYBRID_EULER_SINGULAR`` (``cos beta = 0`` in ZYX Euler angles).

The text is a pure function of the symbolic model and the backend's version: no dates,
no paths, stable ordering, so regenerating gives the same bytes.
"""

from __future__ import annotations

import json
import re
import unicodedata
from dataclasses import dataclass
from importlib.metadata import version

from hybrid.spec.interfaces import KERNEL_STATUSES, STATUS_CODES
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from . import model
from .casadi_backend import kernel_sources
from .lanes import INCLUDE, lanes_function, libm_maps
from .model import Kernel
from .sympy_backend import kernel_body
from .templates import macro

BACKENDS = ("sympy", "casadi")
#: bumped whenever the emitted interface changes; recorded in every manifest and cache key
GENERATOR_VERSION = "5"
#: a unit's statuses as its C names them (the numbers of :data:`hybrid.spec.interfaces.STATUSES`)
STATUS = {f"HYBRID_{name}": STATUS_CODES[name] for name in KERNEL_STATUSES}


@dataclass(frozen=True)
class Unit:
    """One generated translation unit: ``<prefix>.c``, its header and its manifest."""

    prefix: str
    source: str
    header: str
    manifest: str

    @property
    def files(self) -> dict[str, str]:
        return {f"{self.prefix}.c": self.source, f"{self.prefix}.h": self.header,
                f"{self.prefix}.json": self.manifest}


def comment_safe(text: str) -> str:
    """``text`` that cannot end or break a C comment (names come from users' URDF files), in ASCII:
    accents are dropped and other non-ASCII characters become ``?`` (the manifest keeps each name
    exactly, JSON-escaped), so the source is plain ASCII whatever the compiler's charset."""
    letters = "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))
    kept = "".join(c if not c.isascii() else c if (c.isprintable() or c == "\n") and c != "\\" else " "
                   for c in letters)
    kept = re.sub(r"\?(?=\?)", "? ", kept.encode("ascii", "replace").decode("ascii"))  # no trigraph: no ??/ splice
    return kept.replace("*/", "* /").replace("/*", "/ *")


# ----------------------------------------------------------------- signatures


def _params(k: Kernel) -> list[str]:
    """Public C parameters of a kernel's entry point."""
    ps = [f"const double *{a.name}" for a in k.inputs]
    if k.takes_singular_tol:
        ps.append("double singular_tol")
    ps += [f"double *{a.name}" for a in k.outputs]
    return ps


def _sizes_doc(k: Kernel) -> str:
    ins = ", ".join(f"{a.name}[{a.size}]" for a in k.inputs)
    outs = ", ".join(f"{a.name}[{a.size}]" for a in k.outputs)
    return f"{k.doc}.\n   in: {ins}; out: {outs}"


def _integrator_params(k: Kernel) -> list[str]:
    x, *held = k.inputs
    return [f"double *{x.name}", *(f"const double *{a.name}" for a in held), "double h", "int nsteps",
            "double *trajectory", "int *steps_done"]


def _guards_doc(k: Kernel) -> str:
    return "".join(f". Returns {g.status} when {g.doc} < {g.tolerance}" for g in k.guards)


def prototypes(prefix: str, kernels: tuple[Kernel, ...]) -> list[tuple[str, str]]:
    """``(doc, prototype)`` of every public function, in order."""
    out = []
    for k in kernels:
        out.append((_sizes_doc(k) + _guards_doc(k),
                    f"int {prefix}_{k.name}({', '.join(_params(k))});"))
        if k.batched:
            ps = ["int nstates", *_params(k), "int *status"]
            out.append((f"{k.name} over nstates states: {', '.join(k.batched)} and the outputs are nstates rows "
                        "(row-major); status[i] per state; returns how many states failed",
                        f"int {prefix}_{k.name}_batch({', '.join(ps)});"))
        if k.integrator:
            x, nx = k.inputs[0].name, k.inputs[0].size
            out.append((f"advance the state {x}[{nx}] by nsteps classical RK4 steps of h [s] with the other "
                        f"inputs held constant (zero-order hold); if trajectory is not NULL it receives the "
                        f"state after each step (nsteps x {nx}, row-major). On HYBRID_NONFINITE, {x} "
                        "keeps the last finite state and *steps_done says how many steps completed",
                        f"int {prefix}_{k.integrator}({', '.join(_integrator_params(k))});"))
    return out


def _layout_doc(kernels: tuple[Kernel, ...]) -> str:
    seen, rows = set(), []
    for k in kernels:
        for a in (*k.inputs, *k.outputs):
            if a.names and (a.name, a.names) not in seen:
                seen.add((a.name, a.names))
                rows.append(f"   {a.name}[{a.size}] = {{{comment_safe(', '.join(a.names))}}}")
    return "\n".join(rows)


def status_defines() -> str:
    """The status codes as C macros."""
    return "\n".join(f"#define {k} {v}" for k, v in STATUS.items())


def rk4_step(rhs: str, x: str, n: int, out: str, indent: str, i: str = "i") -> str:
    """C statements of one classical RK4 step of ``x`` (``n`` elements, index ``i``): ``rhs`` is the call
    writing the derivative at ``{state}`` into ``{k}`` (a format string); the stages go to ``k1 .. k4`` and
    ``xt``, the new state to ``out``. Every integrator we emit takes this one formula, the macro of
    ``templates/rk4.c.j2`` (so they agree to the bit)."""
    return str(macro("rk4.c.j2", "rk4_step")(rhs, x, n, out, indent, i))


def header(prefix: str, kernels: tuple[Kernel, ...], defines: dict | None = None) -> str:
    guard = prefix.upper() + "_H"
    consts = "".join(f"#define {prefix.upper()}_{k} {v}\n" for k, v in (defines or {}).items())
    status = status_defines()
    protos = "\n\n".join(f"/* {comment_safe(doc)}. */\n{p}" for doc, p in prototypes(prefix, kernels))
    return f"""#ifndef {guard}
#define {guard}

/* Arrays of mixed quantities, element by element (SI units; see {prefix}.json for each unit):
{_layout_doc(kernels)}
   Matrices are row-major. */
{consts}
/* cdef-begin */
{status}

{protos}
/* cdef-end */

#endif
"""


def manifest(prefix: str, kernels: tuple[Kernel, ...], tools: str, info: dict) -> str:
    """The unit's interface as JSON: every function's symbol, arguments, sizes, units, properties."""
    functions = []
    for k in kernels:
        f = {"name": k.name, "symbol": f"{prefix}_{k.name}", "doc": k.doc,
             "inputs": [a.describe() for a in k.inputs], "outputs": [a.describe() for a in k.outputs],
             "guards": [g.describe() for g in k.guards], "singular_tol": k.takes_singular_tol,
             "batched": ({"symbol": f"{prefix}_{k.name}_batch", "per_state": list(k.batched), "lanes": k.lanes}
                         if k.batched else None),
             "integrator": ({"symbol": f"{prefix}_{k.integrator}", "state": k.inputs[0].name}
                            if k.integrator else None)}
        functions.append(f)
    data = {"do_not_edit": MANIFEST_STAMP, "unit": prefix, "generator": GENERATOR_VERSION, "tools": tools,
            "status": STATUS, **info, "functions": functions}
    data["body_sha256"] = json_body_hash(data)
    return json.dumps(data, indent=1) + "\n"


# ------------------------------------------------------------------- wrappers


def _wrappers(prefix: str, kernels: tuple[Kernel, ...]) -> str:
    """Public entry points: status checks, batch loops and the RK4 integrators."""
    out = [f"""#include "{prefix}.h"

static int all_finite(const double *v, int n) {{
    int i;
    for (i = 0; i < n; ++i) {{
        if (!isfinite(v[i])) return 0;
    }}
    return 1;
}}
"""]
    if any(k.lanes for k in kernels):  # GCC and Clang (vector extensions); any other compiler: plain C
        out.append(f"#if defined(__GNUC__)\n#define HYBRID_LANES 1\n{INCLUDE}\n{libm_maps()}#else\n"
                   "#define HYBRID_LANES 0\n#endif\n")
    for k in kernels:
        core_args = [a.name for a in (*k.inputs, *k.core_outputs())]
        lines = [f"int {prefix}_{k.name}({', '.join(_params(k))}) {{"]
        lines += [f"    double {g.name}[1];" for g in k.guards]
        lines.append(f"    {k.name}_core({', '.join(core_args)});")
        for g in k.guards:  # a NaN measure is not "below": it is reported as non-finite, below
            lines.append(f"    if (fabs({g.name}[0]) < {g.c_tolerance}) return {g.status};")
        finite = " && ".join(f"all_finite({a.name}, {a.size})" for a in k.core_outputs())
        lines.append(f"    return ({finite}) ? HYBRID_OK : HYBRID_NONFINITE;\n}}\n")
        out.append("\n".join(lines))
        if k.batched and k.lanes:  # lanes where the compiler has vector extensions, else one by one
            out.append(f"#if HYBRID_LANES\n{_lanes_batch(prefix, k)}#else\n{_scalar_batch(prefix, k)}#endif\n")
        elif k.batched:
            out.append(_scalar_batch(prefix, k))
        if k.integrator:
            x, nx = k.inputs[0].name, k.inputs[0].size
            held = ", ".join(a.name for a in k.inputs[1:])
            rhs = k.name + "_core"
            out.append(f"""int {prefix}_{k.integrator}({', '.join(_integrator_params(k))}) {{
    double k1[{nx}], k2[{nx}], k3[{nx}], k4[{nx}], xt[{nx}];
    int i, step;
    for (step = 0; step < nsteps; ++step) {{
{rk4_step(f"{rhs}({{state}}, {held}, {{k}});", x, nx, "xt", " " * 8)}
        if (!all_finite(xt, {nx})) {{
            if (steps_done) *steps_done = step;
            return HYBRID_NONFINITE;
        }}
        for (i = 0; i < {nx}; ++i) {x}[i] = xt[i];
        if (trajectory) {{
            for (i = 0; i < {nx}; ++i) trajectory[(long)step * {nx} + i] = {x}[i];
        }}
    }}
    if (steps_done) *steps_done = nsteps;
    return HYBRID_OK;
}}
""")
    return "\n".join(out)


def _scalar_batch(prefix: str, k: Kernel) -> str:
    """The ``_batch`` entry point as a loop over the one-state entry point."""
    per, sizes = set(k.batched), k.sizes()
    args = []
    for p in _params(k):
        name = p.split("*")[-1] if "*" in p else p.split()[-1]
        shifted = name in per or (name in sizes and p.startswith("double *"))
        args.append(f"{name} + (long)i * {sizes[name]}" if shifted else name)
    return f"""int {prefix}_{k.name}_batch(int nstates, {', '.join(_params(k))}, int *status) {{
    int i, failed = 0;
    for (i = 0; i < nstates; ++i) {{
        status[i] = {prefix}_{k.name}({', '.join(args)});
        failed += status[i] != HYBRID_OK;
    }}
    return failed;
}}
"""


def _lanes_batch(prefix: str, k: Kernel) -> str:
    """The ``_batch`` entry point of a ``lanes`` kernel: ``HL_W`` states per call of its lanes
    function, what the states share computed once; the last group is filled up with the last state,
    so every state takes the same arithmetic wherever it sits in the batch."""
    per = set(k.batched)
    fixed = [a for a in k.inputs if a.name not in per]
    states = [a for a in k.inputs if a.name in per]
    outs = k.core_outputs()
    name = f"{k.name}_lanes"

    def gather(row: str) -> str:
        return "\n".join(f"            for (j = 0; j < {a.size}; ++j) {{\n"
                         f"                for (l = 0; l < HL_W; ++l) l_{a.name}[j][l] = {a.name}[({row}) * {a.size} + j];\n"
                         "            }" for a in states)

    scatter = "\n".join(f"            for (j = 0; j < {a.size}; ++j) {a.name}[(i + l) * {a.size} + j] = o_{a.name}[j][l];"
                        for a in k.outputs)
    guards = "".join(f"        hl_i g{n} = hl_fabs(o_{g.name}[0]) < {g.c_tolerance};\n"
                     for n, g in enumerate(k.guards))
    pick = "".join(f"g{n}[l] ? {g.status} : " for n, g in enumerate(k.guards))
    bad = " | ".join(f"hl_not_finite(o_{a.name}, {a.size})" for a in outs)
    decl = " ".join(f"hl_v l_{a.name}[{a.size}] = {{{{0}}}};" for a in states) + " " + " ".join(
        f"hl_v o_{a.name}[{a.size}];" for a in outs)
    shared = " ".join(f"hl_v f_{a.name}[{a.size}];" for a in fixed)
    splat = "\n".join(f"    for (j = 0; j < {a.size}; ++j) f_{a.name}[j] = hl_splat({a.name}[j]);" for a in fixed)
    call_pre = ", ".join([*(f"f_{a.name}" for a in fixed), "pre"])
    call = ", ".join([*(f"l_{a.name}" for a in states), "pre", *(f"o_{a.name}" for a in outs)])
    return f"""{lanes_function(k, name, fixed=tuple(a.name for a in fixed))}
int {prefix}_{k.name}_batch(int nstates, {', '.join(_params(k))}, int *status) {{
    {shared}
    hl_v pre[{name.upper()}_NPRE];
    {decl}
    long i;
    int j, l, st, failed = 0;
{splat}
    {name}_pre({call_pre});
    for (i = 0; i < nstates; i += HL_W) {{
        hl_i bad;
        if (i + HL_W <= nstates) {{
{gather("i + l")}
        }} else {{
{gather("i + l < nstates ? i + l : nstates - 1")}
        }}
        {name}({call});
{guards}        bad = {bad};
        for (l = 0; l < HL_W && i + l < nstates; ++l) {{
{scatter}
            st = {pick}bad[l] ? HYBRID_NONFINITE : HYBRID_OK;
            status[i + l] = st;
            failed += st != HYBRID_OK;
        }}
    }}
    return failed;
}}
"""


def _core_signature(k: Kernel) -> str:
    ps = [f"const double *{a.name}" for a in k.inputs] + [f"double *{a.name}" for a in k.core_outputs()]
    return f"static void {k.name}_core({', '.join(ps)})"


def _sympy_cores(kernels: tuple[Kernel, ...]) -> str:
    return "\n".join(f"{_core_signature(k)} {{\n{kernel_body(k)}\n}}\n" for k in kernels)


def _casadi_cores(prefix: str, kernels: tuple[Kernel, ...]) -> str:
    code, table = kernel_sources(list(kernels), prefix)
    cores = [code]
    for k in kernels:
        fn, sz_w = table[k.name]
        outs = k.core_outputs()
        cores.append(f"""{_core_signature(k)} {{
    const double *arg[{max(len(k.inputs), 1)}];
    double *res[{len(outs)}];
    double w[{max(sz_w, 1)}];
    {" ".join(f"arg[{i}] = {a.name};" for i, a in enumerate(k.inputs))}
    {" ".join(f"res[{i}] = {a.name};" for i, a in enumerate(outs))}
    (void){fn}(arg, res, 0, w, 0);
}}
""")
    return "\n".join(cores)


def tools(backend: str) -> str:
    """The symbolic tools (and versions) behind a backend's output."""
    return f"SymPy {version('sympy')}" + (f", CasADi {version('casadi')}" if backend == "casadi" else "")


def assemble(prefix: str, backend: str, kernels: tuple[Kernel, ...], what: str, *,
             info: dict | None = None, tool: str | None = None, defines: dict | None = None) -> Unit:
    """One unit from ``kernels``: C source, header and manifest, each a pure function of its inputs."""
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {BACKENDS}")
    cores = _sympy_cores(kernels) if backend == "sympy" else _casadi_cores(prefix, kernels)
    tool = tool or tools(backend)
    source = f"""/* {prefix}: {comment_safe(what)}.
   Emitted by the {backend} backend of hybrid's codegen ({tool}), generator version {GENERATOR_VERSION}.
   Compile: cc -std=c99 -O2 -c {prefix}.c (link with -lm). */
#include <math.h>

{cores}
{_wrappers(prefix, kernels)}"""
    return Unit(prefix, stamp(source), stamp(header(prefix, kernels, defines)),
                manifest(prefix, kernels, tool, info or {}))


def build_unit(backend: str, n_links: int = 2) -> Unit:
    """Generate the C source, header and manifest of one backend for the planar arm."""
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {BACKENDS}")
    return assemble(f"hybrid_{backend}", backend, model.kernels(n_links),
                    f"hybrid force/velocity control kernels for a planar {n_links}-link arm, "
                    "derived by codegen/model.py")
