"""Assemble the generated C units: kernels of one backend behind the project's calling convention.

Every public function of a unit ``hybrid_<backend>``:

- takes caller-owned ``double`` arrays (inputs ``const``), allocates nothing, touches no
  global state, so it is reentrant;
- takes the arm, surface and plant parameters as run-time arrays (one build serves
  every parameter value);
- returns an ``int`` status: ``HYBRID_OK``, ``HYBRID_SINGULAR`` (Jacobian conditioning
  below the caller's tolerance), ``HYBRID_NONFINITE`` (an output is NaN or infinite),
  ``HYBRID_FRAME_UNDEFINED`` (the task frame's reference direction is parallel to the
  surface normal, or the surface has none there) or ``HYBRID_EULER_SINGULAR`` (``cos beta = 0`` in ZYX Euler angles).

The C is ``templates/unit.c.j2`` and ``unit.h.j2``'s (their shared pieces in ``unit_common.c.j2``);
this module builds their context and the manifest. The text is a pure function of the symbolic model
and the backend's version: no dates, no paths, stable ordering, so regenerating gives the same bytes.
"""

from __future__ import annotations

import json
import re
import unicodedata
from dataclasses import dataclass
from importlib.metadata import version

from hybrid.spec.interfaces import KERNEL_STATUSES, PRINTERS, STATUS_CODES
from hybrid.spec.stamp import MANIFEST_STAMP, json_body_hash, stamp

from . import model
from .casadi_backend import kernel_sources
from .kernel import Arg, Kernel
from .lanes import LANES_HEADER, lanes_function, libm_maps
from .sympy_backend import kernel_body
from .templates import macro, render

BACKENDS = PRINTERS  # a unit of the paper's arm in closed form, by its printer
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


# ------------------------------------------------------------------- the C


def _layout(kernels: tuple[Kernel, ...]) -> list[Arg]:
    """The arrays of mixed quantities (those with element names) the header lists, each once."""
    seen, rows = set(), []
    for k in kernels:
        for a in (*k.inputs, *k.outputs):
            if a.names and (a.name, a.names) not in seen:
                seen.add((a.name, a.names))
                rows.append(a)
    return rows


def header(prefix: str, kernels: tuple[Kernel, ...], defines: dict | None = None) -> str:
    """The unit's header (``templates/unit.h.j2``): its arrays' element names, its constants ``defines``
    (``<PREFIX>_<name>``), its statuses and every public function's prototype."""
    return render("unit.h.j2", prefix=prefix, kernels=kernels, layout=_layout(kernels), defines=defines or {},
                  status=STATUS, comment=comment_safe)


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


# ---------------------------------------------------------------------- cores


def _sympy_cores(kernels: tuple[Kernel, ...]) -> str:
    """The kernels' cores as SymPy prints them, each behind its signature."""
    return str(macro("unit_common.c.j2", "sympy_cores")(kernels, [kernel_body(k) for k in kernels]))


def _casadi_cores(prefix: str, kernels: tuple[Kernel, ...]) -> str:
    """The kernels' CasADi functions, and each kernel's core calling its function."""
    code, table = kernel_sources(list(kernels), prefix)
    return str(macro("unit_common.c.j2", "casadi_cores")(code, kernels, table))


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
    # the lanes kernels' functions, printed by codegen/lanes.py, and the C library's functions they call
    lanes = {k.name: lanes_function(k, f"{k.name}_lanes", fixed=tuple(a.name for a in k.inputs
                                                                      if a.name not in k.batched))
             for k in kernels if k.batched and k.lanes}
    source = render("unit.c.j2", prefix=prefix, backend=backend, tool=tool, generator=GENERATOR_VERSION, what=what,
                    comment=comment_safe, cores=cores, kernels=kernels, lanes_functions=lanes,
                    lanes_header=LANES_HEADER, libm_maps=libm_maps())
    return Unit(prefix, stamp(source), stamp(header(prefix, kernels, defines)),
                manifest(prefix, kernels, tool, info or {}))


def build_unit(backend: str, n_links: int = 2) -> Unit:
    """Generate the C source, header and manifest of one backend for the planar arm."""
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {BACKENDS}")
    return assemble(f"hybrid_{backend}", backend, model.kernels(n_links),
                    f"hybrid force/velocity control kernels for a planar {n_links}-link arm, "
                    "derived by codegen/model.py")
