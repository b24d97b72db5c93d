"""The :class:`~hybrid.Controller`'s settings in three groups, each a record: :class:`Tracking` (the gains
and references), :class:`Limits` (the timing and the limits) and :class:`Sensing` (the sensor and the
estimate).

A controller takes each group as one keyword (``tracking=``, ``limits=``, ``sensing=``) or its fields as
flat keywords of their own names; one setting given both ways is refused. The records check their own
numbers, so a bad one is refused where it is written, not at the first sample.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from typing import Any

from hybrid.control.fault import FaultReaction
from hybrid.control.loops import Gains
from hybrid.control.options import ContactLoss, Posture
from hybrid.control.path_task import PathTask
from hybrid.control.wrench_sensor import WrenchSensor
from hybrid.errors import HybridError
from hybrid.validate import _finite, check_call, check_singular_tol, checked_keywords, shown


def _boolean(name: str, value) -> None:
    if not isinstance(value, bool):
        raise HybridError(f"{name} = {shown(value)}; give True or False")


def _frame(name: str, value) -> None:
    if not isinstance(value, str) or value not in ("actual", "desired"):
        raise HybridError(f"{name} = {shown(value)}; give 'actual' or 'desired'")


def _path(name: str, value) -> None:
    if value is not None and not callable(value):
        raise HybridError(f"{name} = {shown(value, 60)}; give a function path(t) returning the desired point and its "
                          "velocity (p_d [m], p_d' [m/s]), or None")


def _sample_time(name: str, value) -> None:
    _finite("Controller", sample_time=value)
    if value <= 0:
        raise HybridError(f"sample_time = {value} s; give a positive sample period")


def _integral_limit(name: str, value) -> None:
    if value is not None:
        _finite("Controller", integral_limit=value)
        if value < 0:
            raise HybridError(f"integral_limit = {value}; give a magnitude >= 0 or None")


def _timing_tolerance(name: str, value) -> None:
    if value is not None:
        _finite("Controller", timing_tolerance=value)
        if not 0 < value < 1:
            raise HybridError(f"timing_tolerance = {value}; give a fraction of the sample time between 0 and 1 "
                              "(0.25: a sample may come 25 % early or late), or None")


def _instance_of(cls: type, also: str = "") -> Callable[[str, Any], None]:
    """A check that a setting is None or a ``cls``."""
    def check(name: str, value) -> None:
        if value is not None and not isinstance(value, cls):
            raise HybridError(f"{name} = {shown(value, 60)}; give a hybrid.{cls.__name__}(...) or None{also}")
    return check


#: each setting's own check (the others are checked where the robot, axes or surface give their meaning: the
#: gains, references, limits per joint, the posture and the path task)
CHECKS: dict[str, Callable[[str, Any], None]] = {
    "integral": _boolean, "curvature": _boolean, "position_error": _boolean, "frame": _frame, "path": _path,
    "sample_time": _sample_time, "integral_limit": _integral_limit, "timing_tolerance": _timing_tolerance,
    "singular_tol": lambda name, value: check_singular_tol("Controller", value),
    "fault_reaction": _instance_of(FaultReaction, " (its defaults)"),
    "wrench_sensor": _instance_of(WrenchSensor), "contact_loss": _instance_of(ContactLoss),
}


def check_settings(values: Mapping[str, Any]) -> None:
    """Refuse the first of ``values`` (settings by name) that its own check refuses."""
    for name, value in values.items():
        if name in CHECKS:
            CHECKS[name](name, value)


class _Group:
    """What the three records share: their fields' checks, and the fields as keywords."""

    def __post_init__(self) -> None:
        check_settings(self.as_keywords())

    def as_keywords(self) -> dict[str, Any]:
        """The record's fields, as the controller's flat keywords.

        Returns
        -------
        dict
            Each field's value by its name.
        """
        return {f.name: getattr(self, f.name) for f in fields(self)}


@checked_keywords
@dataclass(frozen=True)
class Tracking(_Group):
    """The gains and references: what the controller's loops track, and how (conventions §4).

    Parameters
    ----------
    gains : Gains or dict, optional
        :class:`~hybrid.Gains` for every task axis (velocity axes use ``KPv, KIv, KI2v``; force axes
        ``KPf, KDf, KIf``), or ``{axis name: Gains}`` for some axes, the others keeping the defaults.
    force_reference, velocity_reference : number, Step, callable or dict, optional
        The force axes' ``F_d`` [N, N m] and the velocity axes' ``v_d`` [m/s, rad/s]: one value (a number,
        a :class:`~hybrid.Step` or ``f(t)``) for the normal force and the speed along ``t1`` (the other
        axes' references are 0), or ``{axis name: value}``. Default: 10 N on the normal when it is a force
        axis, every other reference 0.
    integral : bool
        With ``False`` the integral actions ``KI2v, KIf`` are 0.
    curvature : bool
        Give ``R'`` to the law (with ``frame="desired"``: the loop frame's ``R_d'``).
    frame : {"actual", "desired"}
        The loops in ``R(r)`` at the tip, or in ``R(r_d)`` at the desired point (the paper's Figure 3),
        which needs ``path``.
    path : callable, optional
        ``path(t) -> (p_d, p_d')`` [m, m/s], or ``(p_d, p_d', phi_d)`` with the desired ZYX Euler angles
        [rad]: the desired point, for ``frame="desired"`` and ``position_error``.
    frame_direction : 3 numbers, optional
        The task frame's direction ``e`` (base axes): ``t1 = e x n / |e x n|``; default base z. With a
        path task, the path's at its start (``n x t``; another is refused): it sets ``e`` each sample.
    position_error : bool
        Velocity axes use the position error ``R T(r) (r_d - r)`` and its integral in place of the
        velocity error's integrals (``KIv, KI2v`` act as ``KP_p, KI_p``); needs ``path``.
    posture : Posture, optional
        A task in the null space of the task (off by default). It needs a redundant task (fewer axes than
        joints: a 7-joint Panda, or a UR5 on ``axes="position"``) and a scheme with a null space
        (``"task"``, ``"khatib"``); otherwise it is refused. Its numbers are run-time inputs of the
        compiled step; without it the step is the law's own code, bit for bit.
    path_task : PathTask, optional
        A path across the surface the tip follows (:class:`~hybrid.PathTask`): its follower sets the
        references and ``e`` at each sample, added to those given here.

    Examples
    --------
    >>> import hybrid
    >>> tracking = hybrid.Tracking(force_reference=15.0,
    ...                            velocity_reference=0.1)
    >>> sphere = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> ctrl = hybrid.Controller(hybrid.ur5(), sphere,
    ...                          tracking=tracking)
    >>> ctrl.tracking.force_reference
    15.0
    """

    gains: Gains | Mapping | None = None
    force_reference: Any = None
    velocity_reference: Any = None
    integral: bool = True
    curvature: bool = False
    frame: str = "actual"
    path: Callable | None = None
    frame_direction: Any = None
    position_error: bool = False
    posture: Posture | None = None
    path_task: PathTask | None = None


@checked_keywords
@dataclass(frozen=True)
class Limits(_Group):
    """The timing and the limits: the sample clock, the bounds on the torque and the integrals, the
    conditioning the law accepts, and what a run of faults leads to.

    Parameters
    ----------
    sample_time : float
        The period ``T`` [s] at which the integrals, the sensor's filter and the estimate advance (default
        0.01). A controller's ``sample_time`` may change between samples: the samples after it run at the
        new period.
    timing_tolerance : float or None
        A sample is on time when ``t`` advanced by ``T`` within this fraction of it (default 0.25). A
        late, early, repeated or backwards sample raises :class:`~hybrid.SampleTimingError` carrying the
        torque to apply (the law's at this sample, within the limits) and leaves the integrals as they
        were; a late or early one advances the rest (the last torque, the sensor's filter, the estimate,
        the clock), while at a repeated or backwards one no time passed, so nothing changes at all. A
        refused sample changes nothing either, the clock included. None: every sample is served as on
        time.
    torque_limit : "urdf", None, float or sequence of float
        The largest ``|tau_j|`` [N m or N]: ``"urdf"`` (the default: the URDF's ``effort`` limits, none
        where it gives none or 0, and for the planar arm), None (no limit), one number for every joint
        or one per joint.
    torque_step_limit : None, float or sequence of float
        The largest change of ``tau_j`` from one sample to the next [N m or N per sample]; None (the
        default): no limit. The first sample after a start or a reset is not rate-limited, unless
        ``reset(torque=...)`` gave the torque the arm had. A sample a limit bounded keeps the loops'
        integrals (no wind-up).
    integral_limit : float or None
        Anti-windup: the largest integral action per axis [m/s^2 or rad/s^2]; a sample that would exceed
        it keeps the axis's integrals (conditional integration). None (the default): off.
    singular_tol : float
        The conditioning in [0, 1) below which a sample raises
        :class:`~hybrid.SingularConfigurationError` (default 1e-3).
    fault_reaction : FaultReaction or None
        After its ``fault_samples`` consecutive faulted samples (refused, late or early; a dropout of
        ``k`` samples followed by a late one counts ``k + 1``; with the timing check on, a faulted sample
        counts at least the sample periods since the last one served) every sample raises
        :class:`~hybrid.SafeStopError` until a reset, carrying the safe state's torque: the arm stopped
        and held by its model, then the torque released. None: :class:`~hybrid.FaultReaction`'s
        defaults (5 samples, a 50 ms stop, 0.2 s of release). Its ``stop_time`` must be at least two
        sample times.

    Examples
    --------
    >>> import hybrid
    >>> limits = hybrid.Limits(sample_time=0.002,
    ...                        torque_step_limit=2.0)
    >>> sphere = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> ctrl = hybrid.Controller(hybrid.ur5(), sphere,
    ...                          limits=limits)
    >>> ctrl.sample_time, ctrl.limits.torque_step_limit
    (0.002, 2.0)
    >>> hybrid.Limits(sample_time=0.0)
    Traceback (most recent call last):
    ...
    hybrid.errors.HybridError: sample_time = 0.0 s; give a positive
    sample period
    """

    sample_time: float = 0.01
    timing_tolerance: float | None = 0.25
    torque_limit: Any = "urdf"
    torque_step_limit: Any = None
    integral_limit: float | None = None
    singular_tol: float = 1e-3
    fault_reaction: FaultReaction | None = None


@checked_keywords
@dataclass(frozen=True)
class Sensing(_Group):
    """The sensor and the estimate: how the contact wrench reaches the controller, and what it does
    where the contact is lost.

    Parameters
    ----------
    wrench_sensor : WrenchSensor or None
        A :class:`~hybrid.WrenchSensor`: the wrench given at each sample is then its raw reading (six
        numbers, sensor axes), which the step turns into ``F_c`` (its sign, bias, the tool's weight at
        the current orientation, the mount's lever, the filter; conventions §12). None (the default):
        the wrench given is ``F_c`` itself, in base axes.
    contact_loss : ContactLoss or None
        A :class:`~hybrid.ContactLoss` rule for force axes: below its ``threshold`` [N] they hold their
        integrals and approach the surface at its ``approach_speed`` [m/s]. None (the default): off.

    Notes
    -----
    A surface the controller estimates rather than knows is the surface argument itself
    (:class:`~hybrid.EstimatedSurface`).

    Examples
    --------
    >>> import hybrid
    >>> loss = hybrid.ContactLoss(threshold=0.5, approach_speed=0.02)
    >>> sensing = hybrid.Sensing(contact_loss=loss)
    >>> sphere = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> ctrl = hybrid.Controller(hybrid.ur5(), sphere,
    ...                          sensing=sensing)
    >>> ctrl.sensing.contact_loss.threshold
    0.5
    """

    wrench_sensor: WrenchSensor | None = None
    contact_loss: ContactLoss | None = None


#: the groups, by the keyword that takes each
GROUPS: dict[str, type[_Group]] = {"tracking": Tracking, "limits": Limits, "sensing": Sensing}


def grouped(init: Callable) -> Callable:
    """A decorator of the controller's ``__init__``: it takes each group as a keyword (``tracking=``,
    ``limits=``, ``sensing=``) besides the flat keywords, and refuses one setting given both ways, and a call
    that does not fit the signature (:func:`~hybrid.validate.check_call`)."""
    flat = inspect.signature(init)

    @functools.wraps(init)
    def wrapper(self, *args, **kwargs):
        check_call("Controller", wrapper.__signature__, (self, *args), kwargs)
        for keyword, cls in GROUPS.items():
            group = kwargs.pop(keyword, None)
            if group is None:
                continue
            if not isinstance(group, cls):
                raise HybridError(f"{keyword} = {shown(group, 60)}; give a hybrid.{cls.__name__}(...) or None")
            given = group.as_keywords()
            twice = [name for name in given if name in kwargs]
            if twice:
                raise HybridError(f"{twice[0]} is given twice, as a keyword and in {keyword}=; give it once")
            kwargs.update(given)
        init(self, *args, **kwargs)

    parameters = list(flat.parameters.values())
    at = next(i for i, p in enumerate(parameters) if p.kind is p.KEYWORD_ONLY and p.name not in ("axes", "selection"))
    groups = [inspect.Parameter(k, inspect.Parameter.KEYWORD_ONLY, default=None) for k in GROUPS]
    wrapper.__signature__ = flat.replace(parameters=parameters[:at] + groups + parameters[at:])
    return wrapper


#: every setting of the three groups, by name
SETTINGS = frozenset(f.name for cls in GROUPS.values() for f in fields(cls))
#: the settings that may change after the controller is built (read back as they are now)
_LIVE = ("sample_time", "timing_tolerance", "singular_tol", "wrench_sensor")


class GroupedSettings:
    """The settings a controller was given, read back as the three records (those that may change between
    samples, the sample time, the tolerances and the sensor, as they are now)."""

    _settings: dict[str, Any]

    def _group(self, cls: type[_Group]):
        return cls(**{f.name: getattr(self, f.name) if f.name in _LIVE else self._settings[f.name]
                      for f in fields(cls)})

    @property
    def tracking(self) -> Tracking:
        """The gains and references this controller was given (:class:`Tracking`)."""
        return self._group(Tracking)

    @property
    def limits(self) -> Limits:
        """The timing and limits (:class:`Limits`): the sample time and tolerances as they are now."""
        return self._group(Limits)

    @property
    def sensing(self) -> Sensing:
        """The sensor and the contact-loss rule (:class:`Sensing`), the sensor as last set."""
        return self._group(Sensing)
