"""An experiment's start state: the start point checked to be on the surface, the sensor pressing
into the springs with ``F_d(0)`` (or off the surface by ``start_gap``), the joints from the true arm's
inverse kinematics (:meth:`hybrid.Experiment.initial_state`)."""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.experiments.settings import START_TOL, free, pressed


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
    q0 = None if exp.posture is None else exp.posture.q_rest
    p0 = tuple(np.asarray(p0).tolist())
    if exp.start_gap > 0:
        # the sensor tip's weight hangs on its spring where the plant gives it gravity (the 3-D plant's)
        weight = exp.sensor.mass * np.array(exp.robot.gravity) if exp.robot.kind.sensor_weighs else np.zeros(3)
        return _free_start(exp.robot, geometry, p0, exp.elbow, q0, exp.frame_direction, exp.singular_tol, exp.start_gap,
                           tuple((weight[:len(p0)] / exp.sensor.stiffness).tolist()))
    return _pressed_start(exp.robot, geometry, p0, exp.elbow, q0, exp.frame_direction,
                          exp.singular_tol, exp.force_reference(0.0), exp.contact.stiffness, exp.sensor.stiffness)


def _probe(exp, p: np.ndarray) -> np.ndarray:
    """A plant state at rest with the sensor tip at ``p`` (one row)."""
    return np.concatenate([np.zeros(2 * exp.robot.n), p, np.zeros(len(p))])[None, :]


# the runs of a sweep mostly start alike: what they share is worked out once (from the values it reads)
@lru_cache(maxsize=1024)
def _pressed_start(robot, surface, p0, elbow, q0, frame_direction, singular_tol, F0, k_e, K_s) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = pressed(p0, normal, F0, k_e, K_s)
    return _at_rest(robot, normal, p0, s, r, elbow, q0, frame_direction, singular_tol)


@lru_cache(maxsize=1024)
def _free_start(robot, surface, p0, elbow, q0, frame_direction, singular_tol, gap, sag) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = free(p0, normal, gap, np.array(sag))
    return _at_rest(robot, normal, p0, s, r, elbow, q0, frame_direction, singular_tol, gap)


def _at_rest(robot, normal, p0, s, r, elbow, q0, frame_direction, singular_tol, gap: float = 0.0) -> np.ndarray:
    """The state at rest with the sensor tip at ``s`` and the arm tip at ``r`` (the start point ``p0`` on
    the surface, its ``normal``), the joints from the true arm's inverse kinematics."""
    # the tool's orientation is set where the task controls it (the planar arm's follows from r)
    rotation = robot.kind.tool_rotation(lambda: _tool_rotation(np.asarray(frame_direction), normal))
    where = (f"start_gap = {gap:g} m puts the arm tip at {np.round(r, 4).tolist()} m" if gap > 0 else
             f"the start point {np.round(p0, 4).tolist()} m")
    fix = ("give a smaller start_gap, or move the surface or start_point" if gap > 0 else
           "move the surface or start_point")
    try:
        q = robot.inverse_kinematics(np.append(r, 0.0) if len(r) == 2 else r, rotation, q0=q0, elbow=elbow)
    except HybridError as exc:
        if gap > 0:
            first, _, rest = str(exc).partition("\n")
            raise HybridError(f"{where}, which the arm cannot reach; {fix}\n  {first}"
                              + (f"\n{rest}" if rest else "")) from None
        raise HybridError(f"the start pose cannot be reached: {exc}") from None
    cond = float(robot.conditioning(q))
    if cond < max(singular_tol, 1e-3):
        raise HybridError(f"{where} puts the arm at or near a singularity (q = {np.round(q, 4).tolist()} rad, "
                          f"{robot.conditioning_name} = {cond:.2e}); {fix}")
    return np.concatenate([q, np.zeros(robot.n), s, np.zeros(len(s))])


def _tool_rotation(e: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """The tool's start orientation: its z axis along ``-n``, its x axis along ``t1 = e x n``."""
    x_tool = np.cross(e, normal)
    if np.linalg.norm(x_tool) < 1e-6:
        raise HybridError("the task frame's direction e is parallel to the surface normal at the start point: the "
                          "task frame is undefined there; choose another frame_direction or start_point")
    x_tool /= np.linalg.norm(x_tool)
    return np.column_stack([x_tool, np.cross(-normal, x_tool), -normal])
