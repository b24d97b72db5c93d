"""Paths along a surface: where the desired contact point ``r_d(t)`` runs.

A path is parametrised by its arc length ``s`` [m]; the desired point moves along it at the
speed reference, ``s(t) = s_0 + int_0^t v_d``, in the direction of the task axis ``t1`` (for
``e = z``: counter-clockwise seen from +z). A path of 2 coordinates lies in the base xy-plane
(the paper's arm); one of 3 is in space.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import _finite, _point, unit_vector


class Path:
    """The base of every path, and the protocol a path of your own follows (subclass it and give):

    - ``point_at(s)``: the point [m] at arc length ``s`` [m] (3 coordinates; 2 in the planar arm's
      plane);
    - ``points_at(s)``: the points at an array of arc lengths, one row each;
    - ``tangent_at(s)``: the unit tangent, in the direction of growing ``s``;
    - ``arc_of(p)``: the arc length of the path's point nearest ``p``;
    - ``start``: the arc length where a run starts unless told otherwise (default 0).

    A path on a surface may also give ``normal_at(s)``, ``curvature_at(s)`` and ``length``
    (:class:`~hybrid.WaypointPath`, :class:`~hybrid.RasterPath`, :class:`~hybrid.SpiralPath`). An
    experiment given it as ``path`` moves its desired point along it at the speed reference; its tip follows
    the path only where the path runs along the task axis ``t1`` (:mod:`hybrid.experiments.followed`), and it
    refuses any other. Given as a :class:`~hybrid.PathTask`'s path (``path_task``), any path on the
    surface with a ``length`` (and ``closed``) is followed: the task frame turns with it."""

    start: float = 0.0


@dataclass(frozen=True)
class CirclePath(Path):
    """The circle of radius ``radius`` [m] about ``center`` [m] in a plane of constant z, run
    counter-clockwise seen from +z; arc length 0 at the +x side, ``start`` [m] where a run starts."""

    center: tuple[float, ...]
    radius: float
    start: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "center", _point("CirclePath", "center", self.center, (2, 3)))
        _finite("CirclePath", radius=self.radius, start=self.start)
        if self.radius <= 0:
            raise HybridError(f"CirclePath.radius = {self.radius} m; give a positive radius")

    def point_at(self, s: float) -> np.ndarray:
        ang = s / self.radius
        return np.array(self.center) + self.radius * self._radial(math.cos(ang), math.sin(ang))

    def points_at(self, s: np.ndarray) -> np.ndarray:
        ang = np.asarray(s, float) / self.radius
        return np.array(self.center) + self.radius * self._radial(np.cos(ang), np.sin(ang)).T

    def tangent_at(self, s: float) -> np.ndarray:
        ang = s / self.radius
        return self._radial(-math.sin(ang), math.cos(ang))

    def arc_of(self, p) -> float:
        d = np.asarray(p, float)[:2] - np.asarray(self.center)[:2]
        return self.radius * math.atan2(d[1], d[0])

    def _radial(self, c, s):
        return np.array([c, s, 0.0 * c][:len(self.center)])


@dataclass(frozen=True)
class LinePath(Path):
    """The straight line through ``point`` [m] along the unit ``direction``; arc length 0 at ``point``."""

    point: tuple[float, ...]
    direction: tuple[float, ...]
    start: float = 0.0

    def __post_init__(self):
        point = _point("LinePath", "point", self.point, (2, 3))
        object.__setattr__(self, "point", point)
        object.__setattr__(self, "direction", unit_vector(
            "LinePath", "direction", _point("LinePath", "direction", self.direction, (len(point),))))
        _finite("LinePath", start=self.start)

    def point_at(self, s: float) -> np.ndarray:
        return np.array(self.point) + s * np.array(self.direction)

    def points_at(self, s: np.ndarray) -> np.ndarray:
        return np.array(self.point) + np.outer(np.asarray(s, float), self.direction)

    def tangent_at(self, s: float) -> np.ndarray:
        return np.array(self.direction)

    def arc_of(self, p) -> float:
        return float((np.asarray(p, float) - self.point) @ np.array(self.direction))
