"""Hybrid control schemes, as registered classes: what the loops' output becomes.

Every scheme shares the task-frame loops (NOTES section 4); they differ in how the loops'
accelerations and the contact force become joint torques (NOTES section 7). A scheme is
named by its ``name`` in :data:`SCHEMES` (``Controller(..., scheme="khatib")``) and carries its
behaviour as explicit properties, which the generated controller step reads.
"""

from __future__ import annotations

from typing import ClassVar

from .errors import HybridError

#: every registered scheme, by name
SCHEMES: dict[str, type[Scheme]] = {}


def register(cls: type[Scheme]) -> type[Scheme]:
    """Class decorator: make ``cls`` selectable by its ``name``."""
    SCHEMES[cls.name] = cls
    return cls


class Scheme:
    """A hybrid force/velocity control scheme.

    ``feeds_desired_force``: the law's contact term is the desired force ``R^T Sigma F_d``
    (fed forward) rather than the measured ``F_c`` (cancelled).
    """

    name: ClassVar[str]
    feeds_desired_force: ClassVar[bool] = False

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"

    def __eq__(self, other) -> bool:
        return type(self) is type(other)

    def __hash__(self) -> int:
        return hash(type(self))


@register
class TaskDecoupling(Scheme):
    """De Luca & Manes: ``F* = Bbar_o R^T (a - R' y) + n_o - F_c`` decouples the task axes and
    cancels the *measured* contact force, so every axis is the integrator ``y' = a``."""

    name = "task"


@register
class Khatib(Scheme):
    """Khatib 1987, as the paper uses it: the same law and loops with the *desired* normal force
    ``R^T Sigma F_d`` fed forward in place of the measured ``F_c`` (dynamically consistent)."""

    name = "khatib"
    feeds_desired_force = True


def scheme_of(scheme) -> Scheme:
    """A :class:`Scheme` from an instance or a registered name."""
    if isinstance(scheme, Scheme):
        return scheme
    if isinstance(scheme, str) and scheme in SCHEMES:
        return SCHEMES[scheme]()
    raise HybridError(f"unknown scheme {scheme!r:.40}; choose one of {', '.join(SCHEMES)} or pass a "
                      "hybrid.schemes.Scheme")
