"""A kernel: one C function to emit, described independently of the symbolic backend.

Inputs and outputs are named column vectors of SymPy or CasADi SX expressions. What is
special about a kernel is stated as a property, never read off its name:

- ``batched``: its per-state inputs; a ``_batch`` entry point evaluates N states in one call;
- ``conditioning``: it computes a conditioning measure of ``J``, and returns
  ``HYBRID_SINGULAR`` when that measure is below the caller's ``singular_tol``;
- ``integrator``: it is a state derivative ``x' = f(x, ...)``; an RK4 entry point
  ``<integrator>`` advances ``x`` by fixed steps with the other inputs held.

The same description is written beside the C as the unit's manifest (JSON), from which the
Python side binds: sizes, shapes, units and parameter orders are stated here only.
"""

from __future__ import annotations

from dataclasses import dataclass


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
class Kernel:
    """One C function: ordered named inputs and outputs, a one-line doc, explicit properties.

    ``conditioning``, when set, is a one-element column holding the conditioning measure (not
    an output: the entry point compares it with ``singular_tol``). ``integrator`` names the RK4 entry
    point of a state derivative whose first input is the state ``x``.
    """

    name: str
    inputs: tuple[Arg, ...]
    outputs: tuple[Arg, ...]
    doc: str
    batched: tuple[str, ...] = ()
    conditioning: object = None
    integrator: str | None = None

    def sizes(self) -> dict[str, int]:
        return {a.name: a.size for a in (*self.inputs, *self.outputs)}

    def core_outputs(self) -> tuple[Arg, ...]:
        """What the backend computes: the outputs, then ``cond`` (a 1-column) when checked."""
        return self.outputs + ((Arg("cond", self.conditioning),) if self.conditioning is not None else ())
