"""An experiment's start state: the start point checked to be on the surface, the sensor pressing
into the springs with ``F_d(0)`` (or off the surface by ``start_gap``), the joints from the true arm's
inverse kinematics (:meth:`hybrid.Experiment.initial_state`), within the joint limits.

The inverse kinematics begins at the experiment's ``q0``, else at the posture's rest, else at the
middle of the joint ranges. A solution outside the URDF's position limits is first turned by whole
turns into them (a revolute joint's pose repeats every ``2 pi``); failing that, and without a ``q0``
of the user's, the search begins again from further seeds within the limits (the middle of the
ranges where it began at the rest, points spread over the ranges) and takes the first solution
within them. A start that still leaves them is refused, naming the joint.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.experiments.settings import START_TOL, free, pressed
from hybrid.validate import shown


def check_seed(robot, q0) -> tuple[float, ...] | None:
    """An experiment's ``q0`` checked against its ``robot``: one finite joint position per joint [rad or m],
    as a tuple (None: no seed)."""
    if q0 is None:
        return None
    if not robot.kind.seeded:
        raise HybridError(f"q0 = {shown(q0, 60)}: the planar arm's start is in closed form and takes no seed; "
                          "leave q0 out and choose the branch with elbow=+1 or elbow=-1")
    try:
        ok = not isinstance(q0, (str, bytes)) and all(not isinstance(v, (bool, np.bool_)) for v in q0)
        q = np.asarray(q0, dtype=float) if ok else np.array([])
    except (TypeError, ValueError):
        q = np.array([])
    if q.shape != (robot.n,) or not np.isfinite(q).all():
        raise HybridError(f"q0 = {shown(q0, 60)}; give one finite joint position per joint [rad or m], {robot.n} "
                          f"for {', '.join(robot.joint_names)}, or None (the start's default seed)")
    return tuple(map(float, q))


@dataclass(frozen=True)
class StartState:
    """A run's start ``x0 = (q, q', s, s')`` by its parts (:meth:`hybrid.Experiment.start_state`).

    Attributes
    ----------
    q, qdot : ndarray
        The joints' positions [rad or m] and velocities [rad/s or m/s] (at rest: zero).
    sensor_tip, sensor_velocity : ndarray
        The sensor tip ``s`` [m] and its velocity [m/s], base axes (the planar arm's: in its plane).
    """

    q: np.ndarray
    qdot: np.ndarray
    sensor_tip: np.ndarray
    sensor_velocity: np.ndarray

    @classmethod
    def of(cls, x0: np.ndarray, nq: int) -> StartState:
        """The parts of the state ``x0`` of an arm of ``nq`` joints (copies)."""
        x0 = np.asarray(x0, dtype=float)
        d = (len(x0) - 2 * nq) // 2
        return cls(x0[:nq].copy(), x0[nq:2 * nq].copy(), x0[2 * nq:2 * nq + d].copy(), x0[2 * nq + d:].copy())

    @property
    def array(self) -> np.ndarray:
        """``x0`` as one array, the order the plants and :meth:`hybrid.Experiment.initial_state` use."""
        return np.concatenate([self.q, self.qdot, self.sensor_tip, self.sensor_velocity])


def start_state(exp) -> np.ndarray:
    """The start state ``x0 = (q, q', s, s')`` of the experiment ``exp`` (shared between its runs: copy it
    before changing it)."""
    geometry = exp._geometry()
    path = exp.followed_path() if exp.start_point is None else None
    given = np.asarray(exp.start_point) if path is None else path.point_at(path.start)  # a path's start too
    nearest = geometry.project(given)
    p0 = nearest if nearest is not None and path is None else given  # as exp.start() gives it
    if nearest is not None:
        gap = float(np.linalg.norm(given - nearest))
    else:  # without a closed-form projection the plant's own record says how far the point is
        plant = exp.plant()
        gap = abs(float(plant.outputs(_probe(exp, p0))[0][plant.record["outputs"].index("penetration")]))
        if not math.isfinite(gap):  # no distance: the normal says why (grad phi vanishes, phi undefined)
            geometry.normal_at(tuple(given.tolist()))
            raise HybridError(f"the surface's phi is undefined at the start point {np.round(given, 4).tolist()} m; "
                              "give a point where phi is a finite number")
    if not gap <= START_TOL:
        what = "start_point" if exp.start_point is not None else "the path's start"
        hint = f", e.g. {np.round(nearest, 4).tolist()}" if nearest is not None else ""
        raise HybridError(f"{what} {np.round(given, 4).tolist()} m is {gap * 1000:.1f} mm off the surface; give a "
                          f"point on it (within {START_TOL * 1000:g} mm){hint}")
    seeds = (exp.q0, None if exp.posture is None else exp.posture.q_rest, _bounds(exp.robot))
    p0 = tuple(np.asarray(p0).tolist())
    # the tool's tilt and lead at a path task's start (its axis from -n, where the task turns it)
    angles = (0.0, 0.0) if exp.path_task is None else exp.path_task.angles_at(exp.path_task.path.start)
    if exp.start_gap > 0:
        # the sensor tip's weight hangs on its spring where the plant gives it gravity (the 3-D plant's)
        weight = exp.sensor.mass * np.array(exp.robot.gravity) if exp.robot.kind.sensor_weighs else np.zeros(3)
        return _free_start(exp.robot, geometry, p0, exp.elbow, seeds, (exp.frame_direction, angles),
                           exp.singular_tol, exp.start_gap, tuple((weight[:len(p0)] / exp.sensor.stiffness).tolist()))
    return _pressed_start(exp.robot, geometry, p0, exp.elbow, seeds, (exp.frame_direction, angles),
                          exp.singular_tol, exp.force_reference(0.0), exp.contact.stiffness, exp.sensor.stiffness)


def _bounds(robot) -> tuple | None:
    """The robot's joint position limits as ``(lower, upper)`` tuples (part of the starts' cache key: a
    robot's limits are not part of its identity), None where it has none."""
    limits = robot.limits
    if limits is None or not np.isfinite(np.concatenate([limits.lower, limits.upper])).any():
        return None
    return tuple(map(float, limits.lower)), tuple(map(float, limits.upper))


def _probe(exp, p: np.ndarray) -> np.ndarray:
    """A plant state at rest with the sensor tip at ``p`` (one row)."""
    return np.concatenate([np.zeros(2 * exp.robot.n), p, np.zeros(len(p))])[None, :]


# the runs of a sweep mostly start alike: what they share is worked out once (from the values it reads)
@lru_cache(maxsize=1024)
def _pressed_start(robot, surface, p0, elbow, seeds, tool, singular_tol, F0, k_e, K_s) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = pressed(p0, normal, F0, k_e, K_s)
    return _at_rest(robot, normal, p0, s, r, elbow, seeds, tool, singular_tol)


@lru_cache(maxsize=1024)
def _free_start(robot, surface, p0, elbow, seeds, tool, singular_tol, gap, sag) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = free(p0, normal, gap, np.array(sag))
    return _at_rest(robot, normal, p0, s, r, elbow, seeds, tool, singular_tol, gap)


def _at_rest(robot, normal, p0, s, r, elbow, seeds, tool, singular_tol, gap: float = 0.0) -> np.ndarray:
    """The state at rest with the sensor tip at ``s`` and the arm tip at ``r`` (the start point ``p0`` on
    the surface, its ``normal``), the joints from the true arm's inverse kinematics; ``seeds``: the user's
    ``q0``, the posture's rest (each or None) and the joint position limits (:func:`_bounds`); ``tool``: the
    task frame's direction and the tool's tilt and lead there [rad]."""
    frame_direction, (tilt, lead) = tool
    given, rest, bounds = seeds
    # the tool's orientation is set where the task controls it (the planar arm's follows from r)
    rotation = robot.kind.tool_rotation(lambda: _tool_rotation(np.asarray(frame_direction), normal, tilt, lead))
    where = (f"start_gap = {gap:g} m puts the arm tip at {np.round(r, 4).tolist()} m" if gap > 0 else
             f"the start point {np.round(p0, 4).tolist()} m")
    fix = ("give a smaller start_gap, or move the surface or start_point" if gap > 0 else
           "move the surface or start_point")
    goal = np.append(r, 0.0) if len(r) == 2 else r
    try:
        q = robot.inverse_kinematics(goal, rotation, q0=given if given is not None else rest, elbow=elbow)
    except HybridError as exc:
        if given is not None or bounds is None or (q := _within(robot, goal, rotation, rest, bounds)) is None:
            first, _, more = str(exc).partition("\n")
            if gap > 0:
                raise HybridError(f"{where}, which the arm cannot reach; {fix}\n  {first}"
                                  + (f"\n{more}" if more else "")) from None
            if given is None:
                first = first.replace("give q0 near a solution", "give q0 (Experiment(q0=...)), joint positions "
                                      "near a solution")
            raise HybridError(f"the start pose cannot be reached: {first}" + (f"\n{more}" if more else "")) from None
    if bounds is not None and _outside(q, bounds) is not None:
        q = _turned(robot, q, bounds)
        if _outside(q, bounds) is not None and given is None:
            found = _within(robot, goal, rotation, rest, bounds)
            q = q if found is None else found
        _check_within(robot, q, bounds, given, where)
    cond = float(robot.conditioning(q))
    if cond < max(singular_tol, 1e-3):
        raise HybridError(f"{where} puts the arm at or near a singularity (q = {np.round(q, 4).tolist()} rad, "
                          f"{robot.conditioning_name} = {cond:.2e}); {fix}")
    return np.concatenate([q, np.zeros(robot.n), s, np.zeros(len(s))])


def _outside(q: np.ndarray, bounds) -> int | None:
    """The first joint of ``q`` outside the position limits ``bounds``, None where all are within."""
    lower, upper = bounds
    out = np.flatnonzero(~((np.array(lower) <= q) & (q <= np.array(upper))))
    return int(out[0]) if len(out) else None


def _turned(robot, q: np.ndarray, bounds) -> np.ndarray:
    """``q`` with each revolute joint outside its range turned by whole turns into it where a turn does
    (the same pose)."""
    q = np.array(q)
    for i, (joint, lo, hi) in enumerate(zip(robot.chain.joints, *bounds)):
        if joint.kind == "revolute" and not lo <= q[i] <= hi and math.isfinite(lo):
            turned = q[i] + 2 * np.pi * math.ceil((lo - q[i]) / (2 * np.pi))  # the smallest turn at or above lo
            if turned <= hi:
                q[i] = turned
    return q


#: how many seeds spread over the joint ranges the start's search tries after the middle and the rest
SPREAD_SEEDS = 12


def _within(robot, goal, rotation, rest, bounds) -> np.ndarray | None:
    """The first solution of the inverse kinematics within the position limits ``bounds`` from further
    seeds: the middle of the ranges (where the first search began at the posture's ``rest``), points
    spread over the ranges (the same ones every time); None where none is."""
    lower, upper = (np.clip(np.array(b), -np.pi, np.pi) for b in bounds)  # a continuous joint's: one turn
    spread = np.random.default_rng(0).uniform(lower, upper, (SPREAD_SEEDS, len(lower)))
    # the first search began at the rest, else at the middle (the inverse kinematics' default seed)
    for seed in [*([] if rest is None else [0.5 * (lower + upper)]), *spread]:
        try:
            q = _turned(robot, robot.inverse_kinematics(goal, rotation, q0=seed), bounds)
        except HybridError:
            continue
        if _outside(q, bounds) is None:
            return q
    return None


def _check_within(robot, q: np.ndarray, bounds, given, where: str) -> None:
    """Refuse a start ``q`` outside the position limits ``bounds``: the joint, its value and its range."""
    i = _outside(q, bounds)
    if i is None:
        return
    unit = "m" if robot.chain.joints[i].kind == "prismatic" else "rad"
    found = ("from q0" if given is not None else
             f"from the middle of the ranges, the posture's rest or {SPREAD_SEEDS} seeds spread over them")
    raise HybridError(f"{where} puts joint {robot.joint_names[i]!r} at {q[i]:.4g} {unit}, outside its limits "
                      f"[{bounds[0][i]:.4g}, {bounds[1][i]:.4g}] {unit} (no start within the limits {found}); give "
                      f"q0 (Experiment(q0=...)), joint positions near a start within them, or move the start "
                      f"point\n  the start found: q = {np.round(q, 4).tolist()}")


def _tool_rotation(e: np.ndarray, normal: np.ndarray, tilt: float = 0.0, lead: float = 0.0) -> np.ndarray:
    """The tool's start orientation: its z axis along ``-n``, its x axis along ``t1 = e x n``; then turned by
    ``lead`` about ``t2 = n x t1`` and by ``tilt`` about ``t1`` [rad] (a path task's, as its follower turns
    the tool's axis)."""
    x_tool = np.cross(e, normal)
    if np.linalg.norm(x_tool) < 1e-6:
        raise HybridError("the task frame's direction e is parallel to the surface normal at the start point: the "
                          "task frame is undefined there; choose another frame_direction or start_point")
    x_tool /= np.linalg.norm(x_tool)
    frame = np.column_stack([x_tool, np.cross(-normal, x_tool), -normal])
    return _turn(x_tool, tilt) @ _turn(np.cross(normal, x_tool), lead) @ frame


def _turn(k: np.ndarray, angle: float) -> np.ndarray:
    """The rotation by ``angle`` [rad] about the unit axis ``k`` (Rodrigues)."""
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
