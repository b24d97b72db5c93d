"""Whether an experiment's sensor tip follows the path it is given.

The experiment's controller drives the tip along the task axis ``t1 = e x n / |e x n|`` at the
speed reference (in the frame at the tip, or at the desired point for ``frame="desired"``); the path
sets the start, the desired point and the workspace check, but does not steer the tip. As ``t1`` is
normal to ``e`` (the frame's direction), the tip stays in the plane through its start normal to
``e``, running along ``t1``: on the planar arm, along the surface's cross-section. A path elsewhere
would be accepted and silently not followed, so :func:`check_followed` refuses it.

A path task (:class:`hybrid.PathTask`, the experiment's ``path_task``) follows any path: the task frame turns
with it. :func:`task_references` sets what the experiment's references and direction are then, and
:func:`check_reach` refuses a path the arm cannot reach.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from hybrid.control.path_task import PathTask
from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments.settings import START_TOL
from hybrid.models.robot import as_robot
from hybrid.validate import shown

#: the times along the run [s] where the path is compared with the tip's motion
SAMPLES = 129
#: the least cosine between the path's tangent and t1 (the direction check: it runs with t1, not against)
ALONG = 0.0
#: how far [m] a path's point may be out of the plane the tip stays in (rounding, not a pattern's bend:
#: a path on the surface in that plane runs along t1; one out of it, however little, turns elsewhere)
PLANE_TOL = 1e-6

_WHAT_WORKS = ("give a path the tip follows: leave path out (the surface's own, through the start), or e.g. "
               "sphere.latitude_circle(), cylinder.circle_at(point), a LinePath along t1 on a plane, or choose "
               "frame_direction normal to the path's plane; to follow any path on the surface (a WaypointPath, "
               "RasterPath, SpiralPath or one's own), give path_task=hybrid.PathTask(path, speed=..., force=...) "
               "instead of path")


#: the references of an experiment without a path task, where none is given
DEFAULT_FORCE, DEFAULT_SPEED = Step(10.0, 20.0, 0.4), Step(0.3, 0.6, 1.0)


class TaskStep(Step):
    """A reference an experiment worked out from its path task: equal to, hashed and shown as the
    :class:`~hybrid.Step` it is, and worked out again in a copy of the experiment with another path task
    (``dataclasses.replace(exp, path_task=...)``, a sweep over the task's settings)."""

    def __eq__(self, other):
        if isinstance(other, Step):
            return (self.before, self.after, self.at) == (other.before, other.after, other.at)
        return NotImplemented

    __hash__ = Step.__hash__

    def __repr__(self) -> str:
        return repr(Step(self.before, self.after, self.at))


class TaskDirection(tuple):
    """The frame direction an experiment worked out from its path task (a tuple of three numbers), worked out
    again in a copy of the experiment with another path task."""

    __slots__ = ()


def task_references(exp) -> None:
    """The experiment's ``force_reference``, ``speed_reference`` and ``frame_direction``: with a path task,
    its force at the start (the start presses with it), 0 and the path's direction at its start, the task
    giving them along the path (a value given otherwise is refused); without one, the defaults where none
    is given."""
    task = exp.path_task
    # what a copy of an experiment holds from its former path task is worked out again from its own
    for name in ("force_reference", "speed_reference", "frame_direction"):
        if isinstance(getattr(exp, name), (TaskStep, TaskDirection)):
            object.__setattr__(exp, name, None)
    if task is None:
        for name, default in (("force_reference", DEFAULT_FORCE), ("speed_reference", DEFAULT_SPEED),
                              ("frame_direction", (0.0, 0.0, 1.0))):
            if getattr(exp, name) is None:
                object.__setattr__(exp, name, default)
        return
    if not isinstance(task, PathTask):
        raise HybridError(f"path_task = {shown(task, 60)}; give a hybrid.PathTask(path, speed=..., force=...) or None")
    if exp.robot is not None and as_robot(exp.robot).kind.force_size != 3:
        raise HybridError("path_task: the planar arm's tip runs along its surface's cross-section; a path task is for "
                          "an arm in space (hybrid.tracing_experiment, hybrid.panda_experiment)")
    if exp.path is not None or exp.start_point is not None:
        raise HybridError("path_task runs its own path from its start: leave path and start_point out")
    force = task.force_at(task.path.start)
    derived = {"force_reference": TaskStep(force, force, 0.0), "speed_reference": TaskStep(0.0, 0.0, 0.0)}
    for name, value in derived.items():
        given = getattr(exp, name)
        if given is not None and given != value and not (not isinstance(given, Step) and given == value.before):
            raise HybridError(f"{name} = {given}: with a path_task the task gives the force and the speed along the "
                              "path; leave force_reference and speed_reference out (give them in the PathTask)")
        object.__setattr__(exp, name, value)
    # the task frame's direction: the path's at its start (the controller's follower sets it each sample)
    object.__setattr__(exp, "frame_direction",
                       TaskDirection(task.frame_direction(told_surface(exp), exp.frame_direction)))


def told_surface(exp):
    """The surface the experiment's controller is told: its ``controller_surface``, else the true one (what
    the controller's frames and a path task's follower are on)."""
    return exp.surface if exp.controller_surface is None else exp.controller_surface


def check_followed(exp) -> None:
    """Refuse an experiment whose given ``path`` the tip does not follow: a point of the path (sampled
    over the run) out of the plane through the start normal to ``e`` by more than :data:`PLANE_TOL`
    (on the planar arm: off the surface's cross-section by more than :data:`START_TOL`), or its tangent
    against ``t1``. A path in that plane but off the surface (a straight line over a bumpy part) is
    followed as seen along the surface's normal, and accepted."""
    path = exp.path
    if path is None:
        return
    start = np.asarray(exp.start(), dtype=float)
    t = np.linspace(0.0, exp.duration, SAMPLES)
    s = path.arc_of(start) + exp.speed_reference.integral(t)
    if hasattr(path, "length") and not getattr(path, "closed", True):
        s = np.clip(s, 0.0, path.length)  # an open path's end: the workspace check reads the run past it
    points = np.asarray(path.points_at(s), dtype=float)
    tangents = np.array([path.tangent_at(float(si)) for si in s])
    geometry = exp._geometry()
    if points.shape[1] == 2:  # the planar arm: along the cross-section, its tangent (-n_y, n_x)
        off = np.array([np.linalg.norm(p - geometry.project(p)) for p in points])
        normals = np.array([geometry.normal_at(geometry.project(p)) for p in points])
        t1 = np.column_stack([-normals[:, 1], normals[:, 0]])
        where = "off the surface's cross-section, which the planar arm's tip runs along"
    else:
        e = np.asarray(exp.frame_direction, dtype=float)
        off = np.abs((points - start) @ e)
        t1 = np.cross(e, _normals(exp.surface, points))
        t1 /= np.maximum(np.linalg.norm(t1, axis=1), 1e-300)[:, None]
        where = (f"out of the plane through the start normal to e = frame_direction = {np.round(e, 6).tolist()}, "
                 "where the tip stays (it moves along t1 = e x n / |e x n|)")
    name = type(path).__name__
    far = np.flatnonzero(~(off <= (START_TOL if points.shape[1] == 2 else PLANE_TOL)))
    if len(far):
        i = far[0]
        raise HybridError(f"path = {name} is not followed: at t = {t[i]:.3f} s its point "
                          f"{np.round(points[i], 4).tolist()} m is {off[i] * 1e3:.3g} mm {where}\n  {_WHAT_WORKS}")
    cos = np.einsum("ij,ij->i", tangents, t1)
    defined = np.linalg.norm(t1, axis=1) > 0.5
    against = np.flatnonzero(defined & ~(cos > ALONG))
    if len(against):
        i = against[0]
        angle = math.degrees(math.acos(max(-1.0, min(1.0, float(cos[i])))))
        raise HybridError(f"path = {name} is not followed: at t = {t[i]:.3f} s it runs {angle:.0f} degrees from t1 "
                          f"= {np.round(t1[i], 4).tolist()}, the direction the tip moves in\n  {_WHAT_WORKS}")


def _normals(surface, points: np.ndarray) -> np.ndarray:
    """The surface's unit normals ``grad phi / |grad phi|`` at (or near) the points, 0 where undefined."""
    try:
        phi = surface.phi_function()
    except HybridError:  # a surface without a formula of its own gives its normals itself
        return np.array([surface.normal_at(tuple(p)) for p in points])
    with np.errstate(all="ignore"):
        grads = np.array([phi(p)[1] for p in points], dtype=float)
        return np.nan_to_num(grads / np.linalg.norm(grads, axis=1)[:, None])


#: the longest step [m] between the points of a path task's path the reach check solves the arm's pose at
REACH_STEP = 0.01


def check_reach(exp, q_start: np.ndarray) -> None:
    """Refuse a path task whose path leaves the arm's reach: the true arm's inverse kinematics (position only)
    at points along it at most :data:`REACH_STEP` apart, each from the last one's joints (the first from the
    start's), as the arm would go. Worked out once for a robot, task and start (a sweep's runs share them)."""
    _check_reach(exp.robot, exp.path_task, tuple(np.asarray(q_start, dtype=float).tolist()))


@lru_cache(maxsize=64)
def _check_reach(robot, task: PathTask, q_start: tuple) -> None:
    path = task.path
    length, closed = task.extent()
    s0 = float(np.mod(path.start, length)) if closed else float(path.start)
    end = s0 + length if closed else length
    s = np.linspace(s0, end, max(2, int(math.ceil((end - s0) / REACH_STEP)) + 1))
    s = np.mod(s, length) if closed else s
    q = np.asarray(q_start, dtype=float)
    for si, p in zip(s, np.asarray(path.points_at(s), dtype=float)):
        try:
            q = robot.inverse_kinematics(p, None, q0=q)
        except HybridError:
            raise HybridError(f"path_task: the path leaves the arm's reach near s = {si:.4g} m (point "
                              f"{np.round(p, 4).tolist()} m: no joint positions put the tip there from the path's "
                              "way up to it); move the part or the path, or shorten it") from None
