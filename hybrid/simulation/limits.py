"""Where a run left the robot's joint limits: position, velocity and effort, from its recorded series.

The limits are the robot's (:attr:`hybrid.Robot.limits`, the URDF's); a joint without one (a
continuous joint's position, a limit the URDF leaves out) is never out. The effort is the applied
torque: the controller saturates it at its ``torque_limit`` (by default the URDF's effort), so a
torque at the limit counts as out (the arm asked for more than it has). :func:`limit_violations`
works them out (:attr:`hybrid.SimulationResult.limit_violations`); :func:`warn_limit_violations`
says so after a run (:class:`hybrid.JointLimitWarning`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.spec.chain import JOINT_UNITS
from hybrid.user_warnings import JointLimitWarning, warn

#: the kinds of limit, in the order they are told
KINDS = ("position", "velocity", "effort")
#: how close to the effort limit a torque counts as at it (relative: the saturated torque, to rounding)
AT_EFFORT = 1e-9


@dataclass(frozen=True)
class LimitViolation:
    """How a run left one kind of joint limit.

    Attributes
    ----------
    kind : ``"position"``, ``"velocity"`` or ``"effort"``.
    fraction : the fraction of the recorded rows (integration steps) with any joint out, in (0, 1].
    joint : the name of the joint furthest out (position: by how far beyond its range; velocity and
        effort: by its value over its limit).
    value : that joint's furthest value [rad or m, rad/s or m/s, N m or N] (its magnitude for velocity
        and effort).
    limit : the limit it passed (the bound of the range it left; velocity and effort: the limit's
        magnitude).
    first_time : [s] when that joint first left it.
    unit : the unit of ``value`` and ``limit``.
    """

    kind: str
    fraction: float
    joint: str
    value: float
    limit: float
    first_time: float
    unit: str

    def __str__(self) -> str:
        unit = self.unit
        if self.kind == "position":
            beyond = f"{abs(self.value - self.limit):.3g} {unit} beyond its limit {self.limit:.4g} {unit}"
        elif self.kind == "effort" and self.value >= self.limit * (1 - AT_EFFORT):
            beyond = "at its limit: the torque saturated"
        else:
            beyond = f"{self.value / self.limit:.0%} of its limit {self.limit:.4g} {unit}"
        return (f"{self.kind}: joint {self.joint!r} reached {self.value:.4g} {unit}, {beyond}, first at "
                f"t = {self.first_time:.3f} s; a joint out of its {self.kind} limit for {self.fraction:.1%} of the run")


def limit_violations(robot, t: np.ndarray, q: np.ndarray, qdot: np.ndarray, tau: np.ndarray) -> dict:
    """``{kind: LimitViolation}`` for each kind of the ``robot``'s limits the series left (empty: the run
    stayed within them); rows of ``q``, ``qdot``, ``tau`` at the times ``t`` (NaN rows are skipped:
    a torque not yet computed)."""
    limits = robot.limits
    if limits is None or len(t) == 0:
        return {}
    lower, upper = np.asarray(limits.lower, float), np.asarray(limits.upper, float)
    # how far out each row's joint is, and the bound it passed: 0 where within (or NaN)
    below, above = np.nan_to_num(lower - q), np.nan_to_num(q - upper)
    beyond = {"position": np.maximum(np.maximum(below, above), 0.0),
              "velocity": np.nan_to_num(np.abs(qdot) / np.asarray(limits.velocity, float)),
              "effort": np.nan_to_num(np.abs(tau) / np.asarray(limits.effort, float))}
    out = {"position": beyond["position"] > 0, "velocity": beyond["velocity"] > 1.0,
           "effort": beyond["effort"] >= 1.0 - AT_EFFORT}
    found = {}
    for kind in KINDS:
        rows = out[kind].any(axis=1)
        if not rows.any():
            continue
        score = np.where(out[kind], beyond[kind], -np.inf)
        row, j = np.unravel_index(np.argmax(score), score.shape)
        first = int(np.argmax(out[kind][:, j]))
        if kind == "position":
            value = float(q[row, j])
            limit = float(lower[j] if below[row, j] > 0 else upper[j])
        else:
            series, bound = (qdot, limits.velocity) if kind == "velocity" else (tau, limits.effort)
            value, limit = float(abs(series[row, j])), float(bound[j])
        unit = JOINT_UNITS[robot.chain.joints[j].kind][{"position": "q", "velocity": "qd", "effort": "tau"}[kind]]
        found[kind] = LimitViolation(kind, float(rows.mean()), robot.joint_names[j], value, limit, float(t[first]),
                                     unit)
    return found


def warn_limit_violations(result) -> None:
    """Warn (:class:`hybrid.JointLimitWarning`) where the run ``result`` left its robot's limits: the worst
    joint of each kind, its limit, how far and when first."""
    found = result.limit_violations
    if found:
        lines = "\n  ".join(str(v) for v in found.values())
        warn(f"the run left the robot's joint limits (result.limit_violations has the numbers):\n  {lines}\n"
             "  a real arm would stop or saturate there; lower the references or gains, or move the path "
             "(a redundant arm: give a posture)", JointLimitWarning)
