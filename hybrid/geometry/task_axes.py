"""The task axes and the task frame's direction (the axes' names: :data:`hybrid.spec.axes.AXIS_NAMES`).

The task frame's rows are ``t1, t2, n`` (linear axes 0-2), then the rotations about them (3-5):
``t1 = e x n / |e x n|`` for the frame's direction ``e``, ``t2 = n x t1``, ``n`` the surface's
normal towards the robot. A task uses some of the six axes, in a given order.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Surface
from hybrid.validate import shown, unit_vector

#: named task-axis selections: all six, position only, the planar arm's (t1, n)
AXES = {"all": (0, 1, 2, 3, 4, 5), "position": (0, 1, 2), "planar": (0, 2)}


def check_axes(robot, axes) -> tuple[int, ...]:
    """``axes`` as a tuple of distinct task-axis indices the robot can serve, in the given order
    (``a[k]`` is the acceleration along ``axes[k]``)."""
    if axes is None:
        axes = robot.default_axes
    if isinstance(axes, str) and axes == "all":
        if robot.n < 6:
            raise HybridError(f"a {robot.n}-joint arm cannot control all six task axes; pass axes="
                              "'planar' (t1, n) for an arm moving in the base xy-plane, 'position' "
                              "(t1, t2, n), or a tuple of axis indices 0-5")
    if isinstance(axes, str):
        if axes not in AXES:
            raise HybridError(f"axes = {axes!r}; name one of {', '.join(AXES)} or give indices 0-5")
        axes = AXES[axes]
    items = tuple(axes) if isinstance(axes, (tuple, list)) else None
    if items is None or not all(isinstance(i, (int, np.integer)) and not isinstance(i, bool) for i in items):
        raise HybridError(f"axes = {shown(axes, 60)}; give a tuple of distinct task-axis indices 0-5 "
                          "(t1, t2, n, then rotations), or 'all', 'position', 'planar'")
    out = tuple(int(i) for i in items)  # in the user's order: a[k] acts on axis axes[k]
    if not out or len(set(out)) != len(out) or not all(0 <= i <= 5 for i in out):
        raise HybridError(f"axes = {shown(axes, 60)}; give distinct task-axis indices 0-5")
    if len(out) > robot.n:
        raise HybridError(f"{len(out)} task axes need at least {len(out)} joints; the arm has {robot.n}")
    return out


def spatial_surface(surface):
    """``surface``, checked to be one."""
    if not isinstance(surface, Surface):
        raise HybridError(f"surface must be a hybrid Plane, Circle, Sphere, Cylinder or ImplicitSurface, "
                          f"got {type(surface).__name__}")
    return surface


def frame_direction_of(e) -> np.ndarray:
    """The task frame's direction ``e`` (3, base axes; ``frame_direction``) as a unit vector, checked."""
    try:
        arr = np.asarray(e, dtype=float)
        if arr.shape != (3,):
            raise ValueError
        return np.array(_unit_direction(tuple(arr.tolist())))
    except (TypeError, ValueError, OverflowError, HybridError):
        raise HybridError(f"frame_direction = {shown(e, 60)}; give a nonzero direction (e_x, e_y, e_z) in base "
                          "axes") from None


@lru_cache(maxsize=256)
def _unit_direction(e: tuple) -> tuple:
    return unit_vector("decoupling_law", "frame_direction", e)


def frame_rows(normal, e) -> np.ndarray:
    """The task frame's rows ``t1 = e x n / |e x n|``, ``t2 = n x t1``, ``n`` (3 x 3, base axes) for the unit
    normal ``n`` and the direction ``e``; a normal of 2 coordinates is in the base xy-plane.

    Raises
    ------
    HybridError
        ``e`` parallel to ``n``: the frame is undefined.
    """
    n = np.zeros(3)
    n[:len(normal)] = normal
    c = np.cross(np.asarray(e, float), n)
    if np.linalg.norm(c) < 1e-12:
        raise HybridError("the task frame's direction e is parallel to the surface normal: the frame is undefined; "
                          "choose another frame_direction")
    t1 = c / np.linalg.norm(c)
    return np.array([t1, np.cross(n, t1), n])
