"""Metrics of a run (conventions §8), named with their units, from any time series."""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.experiments.paper import Step
from hybrid.simulation.path_metrics import path_metrics
from hybrid.spec.metrics import FIRST_TOUCH, METRIC_NAMES, PEAK_TORQUE, SETTLING_BAND, STEADY_WINDOW_S, TOUCH_BAND
from hybrid.validate import checked_keywords, shown


def settling_time(t: np.ndarray, y: np.ndarray, target: float, band: float) -> float:
    """Time from ``t[0]`` after which ``|y - target| <= band`` for good (NaN if never)."""
    outside = np.flatnonzero(np.abs(y - target) > band)
    if len(outside) == 0:
        return 0.0
    if outside[-1] == len(y) - 1:
        return float("nan")
    return float(t[outside[-1] + 1] - t[0])


def _step_of(t: np.ndarray, ref: np.ndarray) -> Step:
    """The first jump of a sampled reference, as a :class:`Step` (no jump: a constant)."""
    jumps = np.flatnonzero(np.diff(ref) != 0)
    if len(jumps) == 0:
        return Step(float(ref[0]), float(ref[0]), float(t[0]))
    return Step(float(ref[0]), float(ref[jumps[0] + 1]), float(t[jumps[0] + 1]))


def _series(name: str, x, n: int) -> np.ndarray:
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise HybridError(f"metrics: {name} must be numbers, one per time sample") from None
    if arr.ndim != 1 or len(arr) != n:
        raise HybridError(f"metrics: {name} must have one value per time sample ({n}), got shape {arr.shape}")
    return _finite_series(name, arr)


def _finite_series(name: str, arr: np.ndarray) -> np.ndarray:
    """``arr``, refused where it holds a NaN or an infinity: every metric would silently be NaN."""
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.flatnonzero(bad.reshape(len(arr), -1).any(axis=1))[0])
        raise HybridError(f"metrics: {name} holds NaN or infinite values (first at sample {i}); give finite "
                          "series (a run that stopped has none: take its finite part)")
    return arr


@checked_keywords
def metrics(t, force_normal, velocity_tangential, force_reference, speed_reference, *, force_step=None,
            speed_step=None, penetration=None, contact_force=None, tau=None) -> dict:
    """The metrics of one run (conventions §8) from its time series, named with their units.

    Any run's series will do: a simulation's (a :class:`~hybrid.SimulationResult`'s ``metrics`` are
    these), a real arm's log, or series of your own. Every series has one value per sample of ``t``.

    Parameters
    ----------
    t : array_like
        The sample times [s]: at least two, increasing, finite.
    force_normal : array_like
        The measured normal force ``(R(r) F_c)_n`` [N] (positive: pressing on the surface).
    velocity_tangential : array_like
        The arm tip's speed along the task axis ``t1``, ``(R(r) r')_t`` [m/s].
    force_reference : array_like
        The force reference ``F_d(t)`` [N] at the same instants.
    speed_reference : array_like
        The speed reference ``v_d(t)`` [m/s] at the same instants.
    force_step, speed_step : Step, optional
        The references' :class:`~hybrid.Step`, which set the windows of the step metrics. None (the
        default): read from the series' first jump (a series that never jumps: a constant, with no
        step).
    penetration : array_like, optional
        The sensor tip's penetration into the surface ``delta`` [m]; without it ``max_penetration_m``
        is NaN.
    contact_force : array_like, optional
        The surface's normal force ``N`` on the sensor tip [N] (not the measured force): in contact
        where ``N > 0``, a contact loss where it drops to 0. Without it the contact losses, the time out
        of contact and the first touch are NaN.
    tau : array_like, optional
        The joint torques [N m, or N on a prismatic joint], one row per sample; without it there are
        no peak torques.

    Returns
    -------
    dict
        Every metric, by name (its unit in its name: ``_N``, ``_s``, ``_m_per_s``, ...), always: one after a
        step that falls outside the run, or whose series was not given, is NaN. In order: force overshoot
        and 2 % settling after the force step, speed drop after it, force deviation and speed overshoot
        after the speed step, steady-state errors (the mean of ``F_d - F`` and ``v_d - v`` over the last
        0.2 s), RMS errors, the largest penetration, contact losses and time out of contact, the first
        touch (its time, the force's overshoot after it and its 5 % settling; :func:`first_touch`), and
        with ``tau`` the peak torque of each joint (``peak_torque_joint1_Nm``, ...).

    Raises
    ------
    HybridError
        Times that are not at least two increasing finite values, a series of another length than
        ``t`` or holding NaN or infinite values, or a step that is not a :class:`~hybrid.Step`.

    Examples
    --------
    A force that follows its step from 10 N to 20 N at 0.4 s with a lag of 50 ms, at a speed that
    settles on its constant reference:

    >>> import numpy as np
    >>> import hybrid
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> F_d = np.where(t < 0.4, 10.0, 20.0)
    >>> F = np.where(t < 0.4, 10.0,
    ...              20.0 - 10.0 * np.exp(-(t - 0.4) / 0.05))
    >>> v_d = np.full_like(t, 0.3)
    >>> v = 0.3 - 0.01 * np.exp(-t / 0.1)
    >>> m = hybrid.metrics(t, F, v, F_d, v_d)
    >>> (round(m["force_settling_time_2pct_s"], 3),
    ...  round(m["rms_force_error_N"], 3))
    (0.17, 1.733)
    >>> # the speed has no step
    >>> m["speed_overshoot_after_speed_step_m_per_s"]
    nan
    """
    try:
        t = np.asarray(t, dtype=float)
    except (TypeError, ValueError):
        t = np.zeros(0)
    if t.ndim != 1 or len(t) < 2 or not np.all(np.diff(t) > 0):
        raise HybridError("metrics: t must be at least two increasing, finite sample times [s]")
    F, v, Fd, vd = (_series(name, x, len(t)) for name, x in (
        ("force_normal", force_normal), ("velocity_tangential", velocity_tangential),
        ("force_reference", force_reference), ("speed_reference", speed_reference)))
    for name, step in (("force_step", force_step), ("speed_step", speed_step)):
        if step is not None and not isinstance(step, Step):
            raise HybridError(f"metrics: {name} = {shown(step, 40)}; give a hybrid.Step(before, after, at) or None")
    fs = force_step if force_step is not None else _step_of(t, Fd)
    vs = speed_step if speed_step is not None else _step_of(t, vd)
    end = t[-1]
    # the window after the force step ends at the speed step (the next disturbance), if later
    f_end = vs.at if vs.at > fs.at else end
    after_f = (t >= fs.at) & (t < f_end)
    after_v = t >= vs.at
    last = t >= end - STEADY_WINDOW_S
    nan = float("nan")
    m = dict.fromkeys(METRIC_NAMES, nan)  # in the declared order
    if after_f.any() and fs.after != fs.before:
        step = fs.after - fs.before
        peak = F[after_f].max() if step >= 0 else F[after_f].min()
        m["force_overshoot_N"] = float((peak - fs.after) * np.sign(step))
        m["force_overshoot_percent"] = float(100 * m["force_overshoot_N"] / abs(step))
        # 2 % of the final value (of the step's size when the force steps to 0)
        band = SETTLING_BAND * (abs(fs.after) or abs(step))
        m["force_settling_time_2pct_s"] = settling_time(t[after_f], F[after_f], fs.after, band)
        m["speed_drop_after_force_step_m_per_s"] = float(np.max(vd[after_f] - v[after_f]))
    if after_v.any() and vs.after != vs.before:
        m["force_deviation_after_speed_step_N"] = float(np.max(np.abs(F[after_v] - Fd[after_v])))
        m["speed_overshoot_after_speed_step_m_per_s"] = float(np.max(v[after_v]) - vs.after)
    m["steady_state_force_error_N"] = float(np.mean(Fd[last] - F[last]))
    m["steady_state_speed_error_m_per_s"] = float(np.mean(vd[last] - v[last]))
    m["rms_force_error_N"] = float(np.sqrt(np.mean((Fd - F) ** 2)))
    m["rms_speed_error_m_per_s"] = float(np.sqrt(np.mean((vd - v) ** 2)))
    m["max_penetration_m"] = nan if penetration is None else float(_series("penetration", penetration, len(t)).max())
    if contact_force is not None:
        in_contact = _series("contact_force", contact_force, len(t)) > 0
        m["contact_losses"] = int(np.count_nonzero(in_contact[:-1] & ~in_contact[1:]))
        m["time_out_of_contact_s"] = float(np.sum(np.diff(t)[~in_contact[1:]]))
        m.update(first_touch(t, F, Fd, in_contact, fs))
    if tau is not None:
        try:
            torques = np.asarray(tau, dtype=float)
        except (TypeError, ValueError):
            torques = np.zeros(0)
        if torques.ndim not in (1, 2) or len(torques) != len(t):
            raise HybridError(f"metrics: tau must have one row of joint torques per time sample ({len(t)}), "
                              f"got shape {torques.shape}")
        torques = _finite_series("tau", torques.reshape(len(t), -1))
        for j in range(torques.shape[1]):
            m[PEAK_TORQUE.format(j=j + 1)] = float(np.max(np.abs(torques[:, j])))
    return m


def first_touch(t: np.ndarray, F: np.ndarray, Fd: np.ndarray, in_contact: np.ndarray, force_step: Step) -> dict:
    """The first touch (conventions §8): its time ``t[i0]``, the first sample in contact; the force's
    overshoot after it, ``max F - F_d(t[i0])`` from the touch until the force reference next changes
    (the force step, when later; else the run's end, included); and the time from the touch until the
    force stays within ``TOUCH_BAND`` (5 %) of ``|F_d(t[i0])|`` in that window (NaN if it does not).
    All NaN for a run that never touches. A run that starts in contact touches at ``t[0]``."""
    touched = np.flatnonzero(in_contact)
    if len(touched) == 0:
        return dict.fromkeys(FIRST_TOUCH, float("nan"))
    i0 = touched[0]
    target = Fd[i0]
    later = force_step.after != force_step.before and force_step.at > t[i0]
    window = (t >= t[i0]) & (t < force_step.at) if later else t >= t[i0]
    return {"first_touch_time_s": float(t[i0]), "first_touch_overshoot_N": float(F[window].max() - target),
            "first_touch_settling_s": settling_time(t[window], F[window], target, TOUCH_BAND * abs(target))}


#: the normal-estimate metrics leave out the first this many seconds (the estimate's settling)
ESTIMATE_SETTLING_S = 0.5


def estimate_metrics(t_samples, angle_error_deg) -> dict:
    """``normal_angle_error_deg`` (RMS) and ``max_normal_angle_error_deg`` of an estimated surface's normal
    over the control samples after the first :data:`ESTIMATE_SETTLING_S` seconds."""
    t, err = np.asarray(t_samples, float), np.asarray(angle_error_deg, float)
    late = t >= ESTIMATE_SETTLING_S
    if not late.any():
        return {"normal_angle_error_deg": float("nan"), "max_normal_angle_error_deg": float("nan")}
    return {"normal_angle_error_deg": float(np.sqrt(np.mean(err[late] ** 2))),
            "max_normal_angle_error_deg": float(np.max(err[late]))}


def run_metrics(res) -> dict:
    """The metrics of a :class:`~hybrid.SimulationResult`, with its experiment's reference steps (and
    an estimated surface's normal-angle errors, when the controller estimated it; a path task's
    :data:`~hybrid.spec.metrics.PATH_METRICS`, when it followed one)."""
    values = _series_metrics(res)
    if res.normal_estimate is not None:
        values.update(estimate_metrics(res.sample_t, res.normal_angle_error_deg))
    if getattr(res.experiment, "path_task", None) is not None:
        values.update(path_metrics(res))
    return values


def _series_metrics(res) -> dict:
    exp = res.experiment
    return metrics(res.t, res.force_normal, res.velocity_tangential, res.force_reference, res.speed_reference,
                   force_step=exp.force_reference, speed_step=exp.speed_reference, penetration=res.penetration,
                   contact_force=res.contact_force, tau=res.tau)
