"""What a controller is told besides its robot and surface: the references it tracks, a posture task for a
redundant arm, the rule for a force axis out of contact.

:class:`Reference` is a signal ``y_d(t)`` (a number, a :class:`~hybrid.Step`, or code), :class:`Posture`
the null-space task and :func:`check_posture` its check against an arm and a task, :class:`ContactLoss`
the approach of a force axis that lost contact (conventions §4).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.spec.axes import AXIS_NAMES
from hybrid.validate import _finite, checked_keywords, shown


@checked_keywords
@dataclass(frozen=True)
class ContactLoss:
    """What a force axis does when its measured force is below ``threshold`` [N or N m] (before the
    first touch, or after a loss of contact): it approaches the surface at ``approach_speed`` [m/s or
    rad/s] (through the impedance's damping ``KDf``) until the force comes back, its integral kept
    where the force law commands the same acceleration, so the hand-over at the touch has no jump
    (conventions §4).

    Parameters
    ----------
    threshold : float
        The force below which an axis counts as out of contact [N or N m].
    approach_speed : float
        The speed at which it approaches the surface [m/s or rad/s], >= 0.

    Raises
    ------
    HybridError
        A value not finite, or a negative speed.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.ContactLoss(threshold=1.0, approach_speed=0.05)
    ContactLoss(threshold=1.0, approach_speed=0.05)
    """

    threshold: float = 0.5
    approach_speed: float = 0.02

    def __post_init__(self):
        _finite("ContactLoss", threshold=self.threshold, approach_speed=self.approach_speed)
        if self.approach_speed < 0:
            raise HybridError(f"ContactLoss approach_speed = {self.approach_speed}; give a speed >= 0")


def _gain(name: str, value, n: int) -> tuple[float, ...]:
    """A posture gain: one number >= 0 for every joint, or one per joint."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        arr = np.full(1, np.nan)
    if arr.ndim > 1 or (arr.ndim == 1 and arr.size != n) or not np.isfinite(arr).all() or (arr < 0).any():
        raise HybridError(f"Posture {name} = {shown(value, 60)}; give one finite number >= 0 for every joint, or "
                          f"{n} of them (one per joint)")
    return tuple(float(v) for v in np.broadcast_to(arr, (n,)))


@checked_keywords
@dataclass(frozen=True)
class Posture:
    r"""A posture task for a redundant arm: the joints pulled towards ``q_rest`` [rad or m] in the
    task's null space by the inverse dynamics (the controller's model) of a joint PD,

    .. math::

        \tau_0 = B(q)\, w + n(q, \dot q), \qquad w = K_p (q_\mathrm{rest} - q) - K_d \dot q

    (:math:`K_p`: ``stiffness``, :math:`K_d`: ``damping``), which the decoupling law projects,
    :math:`(I - J_y^T \bar J_y^T)\, \tau_0`: the task acceleration stays
    the loops' ``a``, and the joint motion the task leaves free follows the projected PD ``w``.

    ``stiffness`` ``K_p`` [1/s^2] and ``damping`` ``K_d`` [1/s], one number for every joint or one
    per joint, are a joint acceleration's gains: weighted by ``B(q)`` one pair suits a light wrist
    and a heavy shoulder joint alike (plain torque gains [N m/rad] would not); ``sqrt(K_p)`` is the
    null-space motion's natural frequency [rad/s] and ``K_d / (2 sqrt(K_p))`` its damping ratio (the
    defaults: 5 rad/s, critically damped). ``n`` (gravity, velocity terms, joint friction) is cancelled
    in the null space too, where the law alone leaves it: without a posture a redundant arm's null
    space falls under gravity, and with gains 0 it coasts.

    Parameters
    ----------
    q_rest : tuple of float
        The rest posture, one joint position per joint [rad or m].
    stiffness : float or tuple of float
        ``K_p`` [1/s^2], >= 0: one number for every joint, or one per joint.
    damping : float or tuple of float
        ``K_d`` [1/s], >= 0: one number for every joint, or one per joint.

    Raises
    ------
    HybridError
        A rest posture or gain not finite, a negative gain, or gains not one per joint.

    Examples
    --------
    >>> import hybrid
    >>> rest = (0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785)
    >>> posture = hybrid.Posture(rest)
    >>> posture.stiffness, posture.damping
    (25.0, 10.0)
    >>> posture.as_array().shape
    (21,)
    """

    q_rest: tuple[float, ...]
    stiffness: float | tuple[float, ...] = 25.0
    damping: float | tuple[float, ...] = 10.0

    def __post_init__(self):
        try:
            q = np.asarray(self.q_rest, dtype=float)
        except (TypeError, ValueError):
            q = np.full(1, np.nan)
        if q.ndim != 1 or q.size == 0 or not np.isfinite(q).all():
            raise HybridError(f"Posture q_rest = {shown(self.q_rest, 60)}; give the rest posture, one finite joint "
                              "position per joint [rad or m]")
        object.__setattr__(self, "q_rest", tuple(float(v) for v in q))
        for name in ("stiffness", "damping"):
            value = _gain(name, getattr(self, name), q.size)
            object.__setattr__(self, name, value if np.ndim(getattr(self, name)) else value[0])

    def as_array(self) -> np.ndarray:
        """The generated step's ``posture`` array.

        Returns
        -------
        numpy.ndarray
            ``q_rest``, then ``K_p`` and ``K_d`` per joint.
        """
        n = len(self.q_rest)
        return np.concatenate([self.q_rest, _gain("stiffness", self.stiffness, n), _gain("damping", self.damping, n)])


@checked_keywords
@dataclass(frozen=True)
class Reference:
    """A reference signal ``y_d(t)`` and its rate ``y_d'(t)`` (the velocity loops' feedforward).

    A number is constant and a :class:`~hybrid.Step` jumps once: both are evaluated in the
    compiled step (``step`` = (before, after, at)), with rate 0 between jumps (as the paper's).
    Any other callable ``f(t)`` is evaluated in Python at each sample; its ``rate(t)`` method, when
    it has one, gives the feedforward (else 0). Build it with :meth:`of`.

    Parameters
    ----------
    step : tuple of float or None
        ``(before, after, at)`` of a constant or a step, evaluated in the compiled step; None for code.
    value : callable or None
        ``f(t)``, evaluated in Python; None for a constant or a step.
    rate : callable or None
        ``f.rate(t)``, the feedforward; None: 0.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Reference.of("force_reference", 10.0)
    Reference(step=(10.0, 10.0, 0.0), value=None, rate=None)
    >>> step = hybrid.Step(10.0, 20.0, 0.4)
    >>> hybrid.Reference.of("force_reference", step).step
    (10.0, 20.0, 0.4)
    """

    step: tuple[float, float, float] | None
    value: Callable[[float], float] | None
    rate: Callable[[float], float] | None

    @classmethod
    def of(cls, name: str, ref) -> Reference:
        """The reference ``ref`` given for the setting ``name``.

        Parameters
        ----------
        name : str
            The setting it is given for (named by the error when refused).
        ref : float, Step, callable or Reference
            A number (constant), a :class:`~hybrid.Step`, or a callable ``f(t)``.

        Returns
        -------
        Reference
            The signal.

        Raises
        ------
        HybridError
            Anything else, or a number that is not finite.
        """
        if isinstance(ref, Reference):
            return ref
        if isinstance(ref, (int, float, np.integer, np.floating)) and not isinstance(ref, bool):
            _finite("Controller", **{name: ref})
            return cls((float(ref), float(ref), 0.0), None, None)
        if isinstance(ref, Step):
            return cls((ref.before, ref.after, ref.at), None, None)
        if callable(ref):
            rate = getattr(ref, "rate", None)
            return cls(None, ref, rate if callable(rate) else None)
        raise HybridError(f"{name} = {shown(ref, 60)}; give a number, a hybrid.Step or a callable f(t)")


def check_posture(robot, axes: tuple[int, ...], scheme, posture) -> Posture | None:
    """``posture`` checked against the arm, its task ``axes`` and the scheme (see :class:`Posture`)."""
    if posture is None:
        return None
    if not isinstance(posture, Posture):
        raise HybridError(f"posture = {shown(posture, 60)}; give a hybrid.Posture(q_rest, stiffness, damping) or None")
    n, m = robot.n, len(axes)
    if len(posture.q_rest) != n:
        raise HybridError(f"Posture q_rest has {len(posture.q_rest)} joint positions; the arm has {n} joints "
                          f"({', '.join(robot.joint_names)})")
    if m >= n:
        names = ", ".join(AXIS_NAMES[i] for i in axes)
        raise HybridError(f"a posture task acts in the task's null space, and this task has none: {m} task axes "
                          f"({names}) for {n} joints; drop posture, or give a task of fewer axes than joints "
                          "(e.g. axes='position')")
    if scheme.step != "controller_step":
        raise HybridError(f"the {scheme.name} scheme maps the loops without a null-space projection, so a "
                          "posture task would disturb the task: use it with the 'task' or 'khatib' scheme")
    limits = robot.limits
    if limits is not None:
        q = np.array(posture.q_rest)
        outside = [f"{name} = {v:g} (limits {lo:g} to {hi:g})" for name, v, lo, hi in
                   zip(robot.joint_names, q, limits.lower, limits.upper) if not lo <= v <= hi]
        if outside:
            raise HybridError(f"Posture q_rest is outside the joint limits: {'; '.join(outside)}; give a rest "
                              "posture within them")
    return posture


def call_user(f, t: float, name: str):
    """``f(t)``, a user's callback: whatever it raises becomes a HybridError naming it and the time (the
    original kept as the cause)."""
    try:
        return f(t)
    except HybridError:
        raise
    except Exception as exc:  # any failure of the user's code, RecursionError included
        raise HybridError(f"{name} failed at t = {t} s: {type(exc).__name__}: {str(exc)[:80]}\n"
                          "  (the original error is this one's cause)") from exc
