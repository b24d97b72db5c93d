"""The metrics of a run along a path task (:class:`hybrid.PathTask`), from the follower replayed on the run.

The generated follower (:mod:`hybrid.spec.path_follow`) is given the sensor tip's position at each control
sample, as the controller's was given the arm tip's: its progress, its distance from the path (in the
surface's tangent plane) and its references are the run's along the path.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.path_task import PathFollower
from hybrid.spec.metrics import PATH_METRICS
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_SETTINGS

#: how near [m] the path's end the sensor tip completes it (it trails the arm tip the follower steers by the
#: sensor's deflection under friction, a fraction of a millimetre)
END_TOL = 1e-3


def path_series(res) -> dict[str, np.ndarray]:
    """At each control sample of the run ``res``: the follower's outputs by name
    (:data:`~hybrid.spec.path_follow.PATH_OUTPUT`: ``s``, ``path_error``, ``speed``, ``force``, ``done``, ...)
    for the sensor tip, and ``tip_speed``, the tip's speed along the path's tangent [m/s]."""
    exp = res.experiment
    surface = exp.surface if exp.controller_surface is None else exp.controller_surface
    follower = PathFollower(exp.path_task, surface)
    names = res.record["outputs"]
    tip = [names.index(c) for c in ("s_x", "s_y", "s_z")]
    rows = res.outputs[::exp.steps_per_sample][:exp.n_samples]
    nq = res.record["nq"]
    tip_velocity = res.state[::exp.steps_per_sample][:exp.n_samples, 2 * nq + 3:2 * nq + 6]
    out = np.empty((len(rows), len(PATH_OUTPUT)))
    for k, p in enumerate(rows[:, tip]):
        out[k] = follower.follow(p)
        follower.advance()
    series = {name: out[:, i] for i, name in enumerate(PATH_OUTPUT)}
    tangent = out[:, [PATH_OUTPUT.index(c) for c in ("t_x", "t_y", "t_z")]]
    series["tip_speed"] = np.einsum("ij,ij->i", tip_velocity, tangent)
    return series


def path_metrics(res) -> dict[str, float]:
    """:data:`~hybrid.spec.metrics.PATH_METRICS` of a run along a path task (module docstring)."""
    exp = res.experiment
    series = path_series(res)
    t = res.sample_t[:len(series["s"])]
    distance = exp.path_task.table(exp.surface)[1][PATH_SETTINGS.index("distance")]
    done = np.flatnonzero(series["travelled"] >= distance - END_TOL)
    force = res.force_normal[::exp.steps_per_sample][:len(t)]
    err = series["path_error"]
    values = {"path_error_rms_m": float(np.sqrt(np.mean(err ** 2))), "path_error_max_m": float(err.max()),
              "path_time_s": float(t[done[0]]) if len(done) else float("nan"),
              "path_travelled_m": float(series["travelled"][-1]),
              "path_force_rms_error_N": float(np.sqrt(np.mean((force - series["force"]) ** 2))),
              "path_speed_rms_error_m_per_s": float(np.sqrt(np.mean((series["tip_speed"] - series["speed"]) ** 2)))}
    return {m.name: values[m.name] for m in PATH_METRICS}
