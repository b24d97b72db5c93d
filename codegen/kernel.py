"""A kernel: one C function to emit, described independently of the symbolic backend.

Inputs and outputs are named column vectors of SymPy or CasADi SX expressions. What is
special about a kernel is stated as a property, never read off its name:

- ``batched``: its per-state inputs; a ``_batch`` entry point evaluates N states in one call;
- ``guards``: measures it computes beside its outputs (the conditioning of ``J``, the
  task frame's definition, the Euler angles' distance from their singularity), each with the
  status it returns when the measure falls below its tolerance (the caller's
  ``singular_tol``, or a constant);
- ``integrator``: it is a state derivative ``x' = f(x, ...)``; an RK4 entry point
  ``<integrator>`` advances ``x`` by fixed steps with the other inputs held;
- ``lanes``: its ``_batch`` entry point evaluates the states as SIMD lanes (:mod:`codegen.lanes`),
  several at once, equal to the one-state entry point's numbers within rounding.

The same description is written beside the C as the unit's manifest (JSON), from which the
Python side binds: sizes, shapes, units and parameter orders are stated here only.
"""

from __future__ import annotations

from dataclasses import dataclass

from hybrid.spec.interfaces import KERNEL_STATUSES

from .schedule import ORDERS


@dataclass(frozen=True)
class Arg:
    """A named array argument: a column of expressions, row-major when ``shape`` is a matrix.

    ``unit`` is its SI unit (``"rad"``, ``"N m"``), or one unit per element for arrays of
    mixed quantities, whose element names are then in ``names``.
    """

    name: str
    expr: object
    unit: str | tuple[str, ...] = ""
    shape: tuple[int, ...] | None = None
    names: tuple[str, ...] | None = None

    @property
    def size(self) -> int:
        return int(self.expr.shape[0])

    def describe(self) -> dict:
        out = {"name": self.name, "size": self.size, "shape": list(self.shape or (self.size,)),
               "unit": self.unit if isinstance(self.unit, str) else list(self.unit)}
        if self.names:
            out["names"] = list(self.names)
        return out


@dataclass(frozen=True)
class Guard:
    """A measure computed beside a kernel's outputs; below ``tolerance`` the entry point returns
    ``status`` (a name of :data:`hybrid.spec.interfaces.KERNEL_STATUSES`; ``HYBRID_<status>`` in a unit's C)
    instead of ``OK``. ``tolerance`` is ``"singular_tol"`` (a run-time argument of the entry point) or a
    number compiled in."""

    name: str
    expr: object  # a one-element column
    status: str
    tolerance: str | float
    doc: str

    def __post_init__(self):
        if self.status not in KERNEL_STATUSES or self.status == "OK":
            raise ValueError(f"guard {self.name}: status {self.status!r} is not a kernel's failure status "
                             f"({', '.join(KERNEL_STATUSES[1:])})")

    def describe(self) -> dict:
        return {"name": self.name, "status": f"HYBRID_{self.status}", "tolerance": self.tolerance, "doc": self.doc}

    @property
    def c_tolerance(self) -> str:
        """The tolerance in C: the ``singular_tol`` argument, or the number."""
        return self.tolerance if isinstance(self.tolerance, str) else repr(float(self.tolerance))


def conditioning_guard(expr, doc: str) -> Guard:
    """The conditioning of ``J`` compared with the caller's ``singular_tol``."""
    return Guard("cond", expr, "SINGULAR", "singular_tol", doc)


@dataclass(frozen=True)
class Kernel:
    """One C function: ordered named inputs and outputs, a one-line doc, explicit properties.

    ``guards`` are checked in order after the outputs are computed (they are not outputs).
    ``integrator`` names the RK4 entry point of a state derivative whose first input is the state ``x``.
    """

    name: str
    inputs: tuple[Arg, ...]
    outputs: tuple[Arg, ...]
    doc: str
    batched: tuple[str, ...] = ()
    guards: tuple[Guard, ...] = ()
    integrator: str | None = None
    lanes: bool = False
    #: the order its C statements are printed in (:data:`.schedule.ORDERS`), each where it measured faster:
    #: ``"fewest_alive"`` (the RNEA, the CRBA, the controller's steps), ``"longest_chain"`` (a redundant task's
    #: law); ``"printed"``, CasADi's, which the lanes' printer follows too (what the Python runner's plant
    #: evaluates keeps it: the compiled loops round alike)
    order: str = "printed"

    def __post_init__(self):
        if self.order not in ORDERS:
            raise ValueError(f"kernel {self.name}: order {self.order!r} is not one of {', '.join(ORDERS)}")

    def sizes(self) -> dict[str, int]:
        return {a.name: a.size for a in (*self.inputs, *self.outputs)}

    @property
    def takes_singular_tol(self) -> bool:
        return any(g.tolerance == "singular_tol" for g in self.guards)

    def core_outputs(self) -> tuple[Arg, ...]:
        """What the backend computes: the outputs, then each guard's measure (a 1-column)."""
        return self.outputs + tuple(Arg(g.name, g.expr) for g in self.guards)


def declared(ports, dims, exprs: dict, units: dict | None = None) -> tuple[Arg, ...]:
    """The arguments of the declared ``ports`` (:mod:`hybrid.spec.interfaces`) for ``dims``, in their
    order, from their expressions by name: the declaration's names, element names and units (``units``
    states an argument's units element by element where the kernel knows more, e.g. a joint's kind). An
    expression of another size than the declared is refused: the kernel and its declaration disagree."""
    units = units or {}
    args = []
    for p in ports:
        expr = exprs[p.name]
        size = p.size_of(dims)
        if int(expr.shape[0]) != size:
            raise ValueError(f"{p.name}: the kernel computes {int(expr.shape[0])} numbers, the declaration says "
                             f"{p.size} = {size}")
        args.append(Arg(p.name, expr, units.get(p.name, p.unit), names=p.element_names(dims)))
    return tuple(args)
