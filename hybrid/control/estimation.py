"""A surface the controller is not told: the task frame from an online estimate of the normal.

:class:`EstimatedSurface` stands for the surface in a :class:`hybrid.Controller`: the compiled step
estimates the unit normal ``n`` from what it measures at each sample (conventions §13) and builds the
task frame from it (the rows ``t1 = e x n / |e x n|``, ``t2 = n x t1``, ``n``; an estimate within 1e-3
of ``+-e``, e.g. a start along it, takes ``e`` made orthogonal to it instead), with the frame's rate from
the estimate's rate, so the law's curvature term still acts. Two estimators, and their sum:

- **force** (after Yoshikawa & Sudou, 1993): the contact force on the robot is the normal force along
  ``n`` plus friction along the sliding direction; without its component along the sliding velocity
  (the friction correction) it points along ``n``. The estimate moves towards that direction with the
  time constant ``force_time_constant`` [s] while the force exceeds ``contact_threshold`` [N] (it
  holds through a loss of contact). With the friction removed along the tangent of the estimate, it
  cannot see a tilt along the motion; alone, the sliding direction it removes keeps the contact point's
  normal velocity (gated as below), which holds that tilt;
- **velocity** (after Karayiannidis et al., 2014): the contact point's velocity is tangent to the
  surface, so the estimate is turned orthogonal to it, ``n' = -(n . u) (u - (n . u) n) / tau_v`` with
  ``u = v / |v_t|``: the normal's tilt along the motion decays with ``velocity_time_constant`` [s] at
  any speed. It sees only the motion's direction (the tilt about it is the force's);
- **fusion** (the default): both corrections each sample; each sees what the other cannot.

The start is ``initial_normal``, or by default (None) the contact force's direction at the first sample
in contact (base z until then): the friction tilts it by at most the friction angle, along the motion,
which the velocity correction sees.

**The tool's compliance is learnt, not told.** The contact point's velocity is the tip's plus the rate of
the tool's (and sensor's) deflection, ``c F'``; unaccounted for, a compliant tool's deflection under a
changing force looks like a slope (a force step of 10 N at 1 mm/N moves the tip 1 cm along the normal
within 0.1 s, faster than it slides). Of the ways to do without a told ``c`` (gate the velocity
correction on ``|F'|`` alone, reject the normal velocity any compliance could explain, or estimate ``c``)
only the estimate keeps the velocity correction in the steady state, where friction on a curved part
turns the force at a steady rate (``mu N v / R``: a 1-2 degree bias along the motion if left in) and a
gate or a rejection would either pass that or blind the correction. So ``c`` is a recursive least
squares fit of the tip's normal velocity on the normal force's rate, ``n . v = -c (n . F)
(F . F') / |F|^2`` (the force's rate along itself: the tilt of the estimate, turning with the sliding,
stays out of it), in contact, the rate taken beyond ``excitation`` [N/s] (a dead zone: the small changes
are the sliding's and the force loop's, and the deflection's part of them is too small to tell; it
leans ``c`` a little high, which the correction bears better than low), starting at ``compliance``
(None: 0) with the weight ``compliance_information`` [N^2/s^2] (a sample at 10 N/s's), forgetting with
``compliance_time_constant`` [s] (none by default: a tool's compliance does not change). A touch or a
force step teaches it within a sample or two (the fit's weight is the force rate squared), so a
compliance given 0.1x to 10x off, or none, ends the same. The velocity correction gives way while the
deflection's normal rate is large against the sliding speed: ``deflection_gate`` times ``(c +
velocity_noise / sqrt(information)) |n . F'|`` enters its denominator (the learnt ``c`` is within a few
percent, the sensor's damping and sampling make the rest).

The estimate is a tracker (alpha-beta): it predicts the normal on at its estimated rate ``n'`` before
each correction, and the rate takes ``rate_gain`` times the critically damped share of the correction,
up to ``acquisition`` (a correction larger than that, e.g. from a start far off, converges and does not
track), and is bounded by the tip's sliding speed times ``max_curvature`` [1/m] (a rate fed by noise at a
slow, sticking contact would run away), so a steadily curving surface is followed without lag, and the
task frame's rate (the law's curvature term) comes from ``n'``. While the contact point sticks (its
sliding speed below ``min_speed`` [m/s]) but the tip moves, the friction is removed along the tip's
direction of motion (static friction holds against the tip's pull); with the tip at rest too, the
friction correction holds. The velocity correction acts only in contact and above ``min_speed``.

**Where it holds** (the UR5 of the 3-D experiment, its defaults; examples/studies/estimation_study.py's
envelope, each factor alone about the sphere at friction 0.2 and 0.15 m/s with the force step at 0.5 s;
docs/studies/estimated_surface.md): within 2 degrees after 0.5 s and 1.5x the exact surface's force
error from any start up to 90 degrees off, with a compliance given 0.1x-10x off or none, at 0.05-0.5 m/s,
friction up to 0.5 and a radius down to 6 cm (the normal turning at 2.5 rad/s against the 30 ms time
constants). It degrades at slower sliding (0.02 m/s: the force step costs 4-5 degrees for 0.2 s, the
deflection then faster than the sliding), during the force step at a contact that sticks through it
(friction 0.5 on the cylinder at 0.15 m/s: up to 21 degrees for 0.3 s), on a sensor much softer or
stiffer than the default's (2 mm/N: 9 degrees in the force step), and above all with sensor noise: the
force's rate differentiated from a reading of 0.1 N noise (14 N/s a sample) blurs the deflection's rate
and the compliance's fit (9 degrees after 0.5 s, 3 after 1 s; 0.3 N: 18 degrees and 2x the force error;
with the true compliance told and held, 4 and 11 degrees; a low-pass on the reading does not cure it, its
lag turning the deflection's rate).

:func:`estimate_step` is the NumPy statement of one sample (the generated step's oracle).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Surface
from hybrid.spec.surface import SurfaceSpec
from hybrid.validate import checked_keywords, shown

#: the estimators by name: (weight of the force estimate, of the velocity estimate, friction correction)
METHODS = {"force": (1.0, 0.0, 1.0), "force_uncorrected": (1.0, 0.0, 0.0), "velocity": (0.0, 1.0, 0.0),
           "fusion": (1.0, 1.0, 1.0)}


@checked_keywords
@dataclass(frozen=True)
class EstimatedSurface(Surface):
    """A surface the controller is not told: the task frame from an online estimate of its normal.

    The module docstring states the estimator and what each setting does.

    Every setting has a default that works on the 3-D experiment (the module docstring's envelope); the
    compliance is learnt, and the start taken from the first touch.

    Parameters
    ----------
    method : str
        ``"fusion"`` (default), ``"force"``, ``"velocity"`` or ``"force_uncorrected"`` (the force's
        direction as it is, friction and all: biased by the friction angle).
    initial_normal : tuple of float or None
        The estimate's start (base axes; made unit), e.g. the normal a drawing gives; None (default):
        the contact force's direction at the first sample in contact (base z until then).
    force_time_constant, velocity_time_constant : float
        The estimators' time constants [s], > 0 (the force's at least one sample time).
    rate_gain : float or None
        >= 0: 1 the tracker's critically damped rate gain, 0 no rate (a lag on curved parts).
        Default: 1 for ``"fusion"``, 0 for one estimator alone (whose correction sees one direction only:
        a rate fed by it would turn the estimate about the directions it cannot see).
    contact_threshold : float
        [N], >= 0: the force estimate holds below it.
    min_speed : float
        [m/s], >= 0: the velocity estimate and the friction correction hold below it.
    compliance : float or None
        [m/N], >= 0, or None (default: 0): the start of the learnt compliance of the tool (and sensor)
        between the tip and the contact.
    compliance_information : float
        [N^2/s^2], > 0: the weight of that start in the fit (a sample's weight is the normal force's
        rate squared).
    compliance_time_constant : float
        [s], > 0, or inf (default): the fit's forgetting.
    excitation : float
        [N/s], >= 0: the fit's dead zone on the normal force's rate.
    deflection_gate : float
        >= 0: how far the velocity correction gives way to the deflection's normal rate (its innovation
        ``v_n |v_t| / (|v_t|^2 + sigma^2)`` instead of ``v_n / |v_t|``, ``sigma = deflection_gate (c +
        velocity_noise / sqrt(information)) |n . F'|``); 0: never.
    velocity_noise : float
        [m/s], >= 0: the tip velocity's uncertainty: the learnt compliance's is
        ``velocity_noise / sqrt(information)``.
    acquisition : float
        > 0: the largest correction the tracker's rate takes (as a multiple of the force's step
        ``1 - exp(-T / force_time_constant)``: 0.1 about 6 degrees at full gain).
    max_curvature : float
        [1/m], >= 0: the estimate's rate is at most the tip's sliding speed times this.

    Raises
    ------
    HybridError
        An unknown method, or a setting out of its range.

    Examples
    --------
    Give it to a controller (or an experiment's ``controller_surface``) in place of the surface:

    >>> import hybrid
    >>> estimated = hybrid.EstimatedSurface(initial_normal=(0, 0, 1))
    >>> estimated.method, estimated.rate_gain, estimated.start_normal
    ('fusion', 1.0, (0.0, 0.0, 1.0))
    """

    method: str = "fusion"
    initial_normal: tuple[float, float, float] | None = None
    force_time_constant: float = 0.03
    velocity_time_constant: float = 0.03
    rate_gain: float | None = None
    contact_threshold: float = 1.0
    min_speed: float = 0.01
    compliance: float | None = None
    deflection_gate: float = 5.0
    compliance_time_constant: float = float("inf")
    compliance_information: float = 100.0
    velocity_noise: float = 0.01
    acquisition: float = 0.1
    excitation: float = 5.0
    max_curvature: float = 20.0
    kind = "estimated"
    parameters_named = ("w_force", "w_velocity", "correct_friction", "force_time_constant",
                        "inverse_velocity_time_constant", "rate_gain", "contact_threshold", "min_speed", "n0_x", "n0_y",
                        "n0_z", "compliance", "deflection_gate", "compliance_information",
                        "inverse_compliance_time_constant", "velocity_noise", "acquisition", "excitation",
                        "start_from_force", "max_curvature")

    def __post_init__(self):
        if not isinstance(self.method, str) or self.method not in METHODS:
            raise HybridError(f"EstimatedSurface method = {shown(self.method, 40)}; choose one of {', '.join(METHODS)}")
        if self.initial_normal is not None:
            try:
                n = np.asarray(self.initial_normal, dtype=float)
            except (TypeError, ValueError):
                n = np.full(1, np.nan)
            if n.shape != (3,) or not np.isfinite(n).all() or not np.abs(n).max() > 0:
                raise HybridError(f"EstimatedSurface initial_normal = {shown(self.initial_normal, 60)}; give a nonzero "
                                  "direction (3 finite numbers, base axes) from the surface towards the robot, or "
                                  "None (the first touch's force)")
            n = n / np.abs(n).max()  # first to 1 at most: the norm of a huge or tiny one neither overflows nor is 0
            object.__setattr__(self, "initial_normal", tuple(float(v) for v in n / np.linalg.norm(n)))
        if self.rate_gain is None:
            object.__setattr__(self, "rate_gain", 1.0 if self.method == "fusion" else 0.0)
        for name, positive in (("force_time_constant", True), ("velocity_time_constant", True),
                               ("rate_gain", False),
                               ("contact_threshold", False), ("min_speed", False), ("compliance", False),
                               ("deflection_gate", False), ("compliance_time_constant", True),
                               ("compliance_information", True), ("velocity_noise", False), ("acquisition", True),
                               ("excitation", False), ("max_curvature", False)):
            value = getattr(self, name)
            if value is None and name == "compliance":
                continue
            ok = not isinstance(value, bool) and isinstance(value, (int, float, np.integer, np.floating)) \
                and (np.isfinite(value) or (name == "compliance_time_constant" and value == np.inf)) \
                and (value > 0 if positive else value >= 0)
            if not ok:
                raise HybridError(f"EstimatedSurface {name} = {shown(value, 40)}; give a finite number "
                                  f"{'> 0' if positive else '>= 0'}"
                                  + {"compliance": " or None (learnt from 0)",
                                     "compliance_time_constant": " or inf (no forgetting)"}.get(name, ""))
            object.__setattr__(self, name, float(value))

    def spec(self) -> SurfaceSpec:
        """What the code generator needs: an estimated surface (no formula).

        Returns
        -------
        SurfaceSpec
            Its kind and the tuning's names.
        """
        return SurfaceSpec(self.kind, self.parameters_named, estimated=True)

    def as_array(self) -> np.ndarray:
        """The tuning as the generated step reads it.

        Returns
        -------
        numpy.ndarray
            One value per name of :data:`parameters_named`.
        """
        w_force, w_velocity, correct = METHODS[self.method]
        return np.array([w_force, w_velocity, correct, self.force_time_constant, 1.0 / self.velocity_time_constant,
                         self.rate_gain,
                         self.contact_threshold, self.min_speed, *self.start_normal, self.compliance or 0.0,
                         self.deflection_gate, self.compliance_information, 1.0 / self.compliance_time_constant,
                         self.velocity_noise, self.acquisition, self.excitation,
                         float(self.initial_normal is None), self.max_curvature])

    @property
    def start_normal(self) -> tuple[float, float, float]:
        """The estimate before its first sample: ``initial_normal``, or base z until the first touch when
        None."""
        return (0.0, 0.0, 1.0) if self.initial_normal is None else self.initial_normal

    def normal_at(self, p):
        """An estimated surface has no normal of its own: the controller estimates it.

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            Never: this raises.

        Raises
        ------
        HybridError
            Always: give the experiment the true surface, and this one as ``controller_surface``.
        """
        raise HybridError("an EstimatedSurface has no normal of its own: the controller estimates it; give the "
                          "experiment the true surface (the plant's), and this one as controller_surface")

    def check_sampling(self, sample_time: float) -> None:
        """Refuse time constants shorter than the sample time (the discrete estimate would overshoot).

        Parameters
        ----------
        sample_time : float
            The controller's sample time [s].

        Raises
        ------
        HybridError
            ``force_time_constant`` is shorter than ``sample_time``.
        """
        for name in ("force_time_constant",):
            if getattr(self, name) < sample_time:
                raise HybridError(f"EstimatedSurface {name} = {getattr(self, name):g} s is shorter than the sample "
                                  f"time {sample_time:g} s; give at least one sample time")


def estimate_step(state: np.ndarray, tuning: np.ndarray, F, v, T: float) -> np.ndarray:
    """One sample of the estimator (module docstring) in NumPy: the state :data:`ESTIMATE` after it,
    from the contact force ``F`` on the robot and the tip velocity ``v`` [base axes], ``tuning`` an
    :class:`EstimatedSurface`'s ``as_array()`` and ``T`` the sample time [s]."""
    w_force, w_velocity, correct, tau_f, inv_tau_v, rate_gain, f_min, v_min = tuning[:8]
    c_prior, gate, info_prior, inv_tau_c, v_noise, acquisition, excitation, from_force, max_curvature = tuning[11:20]
    alpha = 1 - np.exp(-T / tau_f)
    kappa = rate_gain * alpha / (2 - alpha)
    started = state[9] != 0
    F, v = np.asarray(F, float), np.asarray(v, float)
    F_size = np.linalg.norm(F)
    if not started and from_force and not F_size > f_min:  # it starts at the first touch
        return np.concatenate([tuning[8:11], np.zeros(3), F, [0.0, c_prior, info_prior]])
    rate = state[3:6] if started else np.zeros(3)
    m = (state[:3] if started else F / F_size if from_force else tuning[8:11]) + T * rate
    n_pred = m / np.linalg.norm(m)
    c, info = (state[10], state[11]) if started else (c_prior, info_prior)
    F_rate = (F - state[6:9]) / T if started else np.zeros(3)
    # the compliance: the tip's normal velocity against the normal force's rate (recursive least squares,
    # forgetting with tau_c), in contact; the force's own rate along it (the estimate's tilt, turning with the
    # sliding, stays out), less the excitation (a dead zone: it leans the compliance a little high, which the
    # velocity correction bears better than low)
    f_n = (n_pred @ F) * (F @ F_rate) / (F_size * F_size) if F_size > f_min else 0.0
    f_n = f_n - np.clip(f_n, -excitation, excitation)
    info = np.exp(-T * inv_tau_c) * info + f_n * f_n
    c = max(c + f_n * (-(n_pred @ v) - c * f_n) / info, 0.0)
    # the contact point's velocity: the tip's and the tool's deflection's rate
    deflection_rate = c * F_rate
    v_c = v + deflection_rate
    vn = n_pred @ v_c
    v_t = v_c - vn * n_pred
    speed = np.linalg.norm(v_t)
    sliding = speed > v_min
    # the friction's direction: against the contact point's sliding, else (it sticks) against the tip's motion
    tip_t = v - (n_pred @ v) * n_pred
    tip_speed = np.linalg.norm(tip_t)
    # (alone, the force estimate takes the contact point's normal velocity into it, as far as the deflection's
    # rate lets it: the friction's direction then holds the tilt along the motion)
    sigma = gate * (n_pred @ F_rate) * (c + v_noise / np.sqrt(info))
    if sliding:
        u = v_t + (1 - w_velocity) * speed * speed / (speed * speed + sigma * sigma) * vn * n_pred
        u = u / np.linalg.norm(u)
    elif tip_speed > v_min:
        u = tip_t / tip_speed
    else:
        u = np.zeros(3)
    F_perp = F - correct * (F @ u) * u
    magnitude = np.linalg.norm(F_perp)
    touching = magnitude > f_min
    n_force = F_perp / magnitude if touching else F_perp
    d = w_force * touching * alpha * (n_force - n_pred)
    if sliding and touching:
        d = d - w_velocity * inv_tau_v * T * vn / (speed * speed + sigma * sigma) * v_t
    m = n_pred + d
    n = m / np.linalg.norm(m)
    # the rate takes the correction up to the acquisition's size: a larger one converges, it does not track
    d = d * min(1.0, alpha * acquisition / max(np.linalg.norm(d), 1e-300))
    rate = rate + kappa / T * (d - (d @ n) * n)
    # no faster than the sliding along the sharpest curvature it follows
    rate = rate * min(1.0, max_curvature * tip_speed / max(np.linalg.norm(rate), 1e-300))
    return np.concatenate([n, rate - (rate @ n) * n, F, [1.0, c, info]])
