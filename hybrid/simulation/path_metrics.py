"""The metrics of a run along a path task (:class:`hybrid.PathTask`), from the follower replayed on the run.

The generated follower (:mod:`hybrid.spec.path_follow`) is given the arm tip's position and the contact
force at each control sample, as the controller was: its progress, phase and references are the
controller's. The sensor tip, which touches the part, trails the arm tip by the sensor's deflection (under
friction, up to centimetres at large forces): its distance from the path is that of the path's point
nearest it, found from the table's nodes behind and ahead of the arm tip's progress.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.path_task import PathFollower
from hybrid.spec.metrics import PATH_AHEAD_M, PATH_BEHIND_M, PATH_END_TOL_M, PATH_METRICS, PATH_SETTLED_BAND
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_PHASES, PATH_SETTINGS, PATH_STATE

FOLLOW, UNLOAD = PATH_PHASES.index("follow"), PATH_PHASES.index("unload")


def follower_of(res) -> PathFollower:
    """A follower of the run's path task as its controller had it (the surface it was told, its sample period
    and touch force)."""
    return _follower(res.experiment)


def _follower(exp) -> PathFollower:
    """The follower of ``exp``'s path task as its controller has it (:func:`follower_of`)."""
    touch = exp.touch_threshold if exp.approach_speed > 0 else None
    return PathFollower(exp.path_task, exp.told_surface(), exp.sample_time, touch)


def path_series(res, follower: PathFollower | None = None) -> dict[str, np.ndarray]:
    """At each control sample of the run ``res``: the follower's outputs by name
    (:data:`~hybrid.spec.path_follow.PATH_OUTPUT`: ``s``, ``phase``, ``speed``, ``normal_reference``, ``done``,
    ... as the controller had them, from the arm tip), but the tool's spin references (the record has no tip
    rotation); ``path_error``, the sensor tip's distance from the path [m]; ``tip_speed`` (the sensor tip's
    speed along the path's tangent [m/s]), ``normal_force`` (the measured force along the path's normal [N])
    and ``t`` [s]. ``follower``: the run's (:func:`follower_of`), reset here."""
    return sampled_series(res.experiment, *_at_samples(res), follower)


def sampled_series(exp, names, rows: np.ndarray, states: np.ndarray, nq: int,
                   follower: PathFollower | None = None) -> dict[str, np.ndarray]:
    """:func:`path_series` of a run of ``exp`` from its output record (columns ``names``) and its states at
    each control sample (``rows``, ``states``; ``nq`` joints)."""
    follower = _follower(exp) if follower is None else follower
    follower.reset()
    arm_tips, tips = (rows[:, [names.index(c) for c in (f"{x}_x", f"{x}_y", f"{x}_z")]] for x in ("r", "s"))
    forces = rows[:, [names.index(c) for c in ("Fc_x", "Fc_y", "Fc_z")]]
    tip_velocity = states[:, 2 * nq + 3:2 * nq + 6]
    out = np.empty((len(rows), len(PATH_OUTPUT)))
    # where the sensor's reading is lost the controller's follower is refused the sample: it holds what it had
    t = np.arange(len(rows)) * exp.sample_time
    sensor = exp.sensor
    lost = (t >= sensor.dropout_at) & (t < sensor.dropout_at + sensor.dropout_duration) if sensor.drops_out else \
        np.zeros(len(rows), bool)
    for k, (p, f) in enumerate(zip(arm_tips, forces)):
        if lost[k]:
            out[k] = follower.served
            continue
        out[k] = follower.follow(p, f)
        follower.advance()
    series = {name: out[:, i] for i, name in enumerate(PATH_OUTPUT)
              if name not in ("spin_t1", "spin_t2", "tool_angle_error")}
    series["path_error"] = _sensor_tip_errors(follower, tips, series["s"])
    tangent = out[:, [PATH_OUTPUT.index(c) for c in ("t_x", "t_y", "t_z")]]
    normal = out[:, [PATH_OUTPUT.index(c) for c in ("n_x", "n_y", "n_z")]]
    series["tip_speed"] = np.einsum("ij,ij->i", tip_velocity, tangent)
    series["normal_force"] = np.einsum("ij,ij->i", forces, normal)
    series["t"] = t
    return series


_SEEDED = [PATH_STATE.index(k) for k in ("s", "row", "started", "phase")]


def _sensor_tip_errors(follower: PathFollower, tips: np.ndarray, s_arm: np.ndarray) -> np.ndarray:
    """The sensor tips' distances [m] from the path (in the surface's tangent plane), each from the node nearest
    it within ``PATH_BEHIND_M`` and ``PATH_AHEAD_M`` of the arm tip's progress, then the follower's Newton steps."""
    nodes, points = follower.table[:, 0], follower.table[:, 1:4]
    state = np.zeros_like(follower.state)
    errors = np.empty(len(tips))
    error = PATH_OUTPUT.index("path_error")
    for k, (p, s) in enumerate(zip(tips, s_arm)):
        lo, hi = np.searchsorted(nodes, [s - PATH_BEHIND_M, s + PATH_AHEAD_M])
        near = lo + int(np.argmin(np.linalg.norm(points[lo:max(hi, lo + 1)] - p, axis=1)))
        state[:] = 0.0
        state[_SEEDED] = nodes[near], min(near, len(nodes) - 2), 1.0, FOLLOW
        follower.state[:] = state
        errors[k] = follower.follow(p, np.zeros(3))[error]
    return errors


def path_metrics(res) -> dict[str, float]:
    """:data:`~hybrid.spec.metrics.PATH_METRICS` of a run along a path task (module docstring): the path
    error over the samples on the path (following it, and releasing the force at its end), the force and
    speed errors and the contact losses while following it, the largest force from the release on."""
    return sampled_path_metrics(res.experiment, *_at_samples(res))


def _at_samples(res) -> tuple:
    """The record's columns, its rows and states at each control sample of ``res``, and its joints."""
    m, n = res.experiment.steps_per_sample, res.experiment.n_samples
    return res.record["outputs"], res.outputs[::m][:n], res.state[::m][:n], res.record["nq"]


def sampled_path_metrics(exp, names, rows: np.ndarray, states: np.ndarray, nq: int) -> dict[str, float]:
    """:func:`path_metrics` of a run of ``exp`` from its output record (columns ``names``) and its states at
    each control sample (``rows``, ``states``; ``nq`` joints): the compiled loop's record of them."""
    follower = _follower(exp)
    series = sampled_series(exp, names, rows, states, nq, follower)
    t, phase = series["t"], series["phase"]
    on = (phase == FOLLOW) | (phase == UNLOAD)
    follow = phase == FOLLOW
    distance = follower.settings[PATH_SETTINGS.index("distance")]
    done = np.flatnonzero(series["travelled"] >= distance - PATH_END_TOL_M)
    err = series["path_error"][on] if on.any() else np.full(1, np.nan)
    # once in contact: from the first time the force is within PATH_SETTLED_BAND of its reference (the touch's transient
    # is the first-touch metrics')
    force_error = series["normal_force"] - series["normal_reference"]
    settled = np.flatnonzero(follow & (np.abs(force_error) <= PATH_SETTLED_BAND * np.abs(series["normal_reference"])))
    pressing = follow & (np.arange(len(t)) >= (settled[0] if len(settled) else len(t)))
    force_error = force_error[pressing]
    speed_error = (series["tip_speed"] - series["speed"])[follow]
    touching = series["normal_force"] > 0
    lost = follow[1:] & touching[:-1] & ~touching[1:]
    after = phase >= UNLOAD
    values = {"path_error_rms_m": float(np.sqrt(np.mean(err ** 2))), "path_error_max_m": float(err.max()),
              "path_time_s": float(t[done[0]]) if len(done) else float("nan"),
              "path_travelled_m": float(series["travelled"].max()),  # (it falls back in a retreat past the end)
              "path_force_rms_error_N": _rms(force_error), "path_speed_rms_error_m_per_s": _rms(speed_error),
              "path_contact_losses": int(np.count_nonzero(lost)),
              "path_end_peak_force_N": float(series["normal_force"][after].max()) if after.any() else float("nan")}
    return {m.name: values[m.name] for m in PATH_METRICS}


def _rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x ** 2))) if len(x) else float("nan")
