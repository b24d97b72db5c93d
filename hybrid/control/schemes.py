"""Hybrid control schemes, as registered classes: what the loops' output becomes.

Every scheme shares the task-frame loops (conventions §4); they differ in how the loops'
accelerations and the contact force become joint torques (conventions §7). A scheme is
named by its ``name`` in :data:`SCHEMES` (``Controller(..., scheme="khatib")``) and carries its
behaviour as explicit properties, which the generated controller step reads.
"""

from __future__ import annotations

from typing import ClassVar

from hybrid.errors import HybridError
from hybrid.validate import checked_keywords, shown

#: every registered scheme, by name
SCHEMES: dict[str, type[Scheme]] = {}


def register(cls: type[Scheme]) -> type[Scheme]:
    """Class decorator: make ``cls`` selectable by its ``name``; made with an argument, it refuses it by name (a
    scheme takes none: :func:`~hybrid.validate.checked_keywords`)."""
    SCHEMES[cls.name] = cls
    return checked_keywords(cls)


@checked_keywords
class Scheme:
    """A hybrid force/velocity control scheme.

    A scheme is chosen by an instance or by its ``name`` (``Controller(..., scheme="khatib")``); its
    behaviour is in its class attributes:

    Attributes
    ----------
    name : str
        Its name in :data:`SCHEMES`.
    step : str
        The generated function that runs one sample (see :mod:`codegen.controller_step`).
    feeds_desired_force : bool
        The law's contact term is the desired force ``R^T Sigma F_d`` (fed forward) rather than the
        measured ``F_c`` (cancelled).
    pseudoinverse : bool
        Motion axes mapped by the pseudo-inverse of the selected Jacobian rows.
    needs_force_gain : bool
        Force axes need ``KPf > 0`` (their command is ``m_d a = a / KPf``).

    Examples
    --------
    >>> import hybrid
    >>> sorted(hybrid.SCHEMES)
    ['fisher_mujtaba', 'khatib', 'raibert_craig', 'task']
    >>> hybrid.SCHEMES["khatib"]() == hybrid.Khatib()
    True
    """

    name: ClassVar[str]
    step: ClassVar[str] = "controller_step"
    feeds_desired_force: ClassVar[bool] = False
    pseudoinverse: ClassVar[bool] = False
    needs_force_gain: ClassVar[bool] = False

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"

    def __eq__(self, other) -> bool:
        return type(self) is type(other)

    def __hash__(self) -> int:
        return hash(type(self))


@register
class TaskDecoupling(Scheme):
    r"""De Luca & Manes: :math:`F^* = \bar B_o R^T (a - \dot R\, y) + n_o - F_c` decouples the task axes and
    cancels the *measured* contact force, so every axis is the integrator ``y' = a``.

    Examples
    --------
    The default scheme of a controller:

    >>> import hybrid
    >>> scheme = hybrid.TaskDecoupling()
    >>> scheme.name, scheme.feeds_desired_force
    ('task', False)
    """

    name = "task"


@register
class Khatib(Scheme):
    r"""Khatib 1987, as the paper uses it: the same law and loops with the *desired* normal force
    :math:`R^T \Sigma F_d` fed forward in place of the measured ``F_c`` (dynamically consistent).

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Khatib().name, hybrid.Khatib().feeds_desired_force
    ('khatib', True)
    """

    name = "khatib"
    feeds_desired_force = True


@register
class RaibertCraig(Scheme):
    r"""Raibert & Craig 1981: the selected motion axes' accelerations mapped to joints through the
    inverse task Jacobian and scaled by the joints' own inertias :math:`\operatorname{diag}(B)`, the force
    axes' commands :math:`-F_d + m_d a` through :math:`J^T`, gravity compensated; no dynamic decoupling."""

    name = "raibert_craig"
    step = "raibert_craig_step"
    needs_force_gain = True


@register
class FisherMujtaba(RaibertCraig):
    r"""Raibert & Craig with Fisher & Mujtaba's (1992) correction: the motion axes mapped by the
    pseudo-inverse of the *selected* rows of the task Jacobian, :math:`(\Sigma^A J_y)^+`."""

    name = "fisher_mujtaba"
    pseudoinverse = True


def scheme_of(scheme) -> Scheme:
    """A :class:`Scheme` from an instance or a registered name."""
    if isinstance(scheme, Scheme):
        return scheme
    if isinstance(scheme, str) and scheme in SCHEMES:
        return SCHEMES[scheme]()
    raise HybridError(f"unknown scheme {shown(scheme, 40)}; choose one of {', '.join(SCHEMES)} or pass a "
                      "hybrid.Scheme")
