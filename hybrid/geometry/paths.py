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
from hybrid.validate import _finite, _point, checked_keywords, unit_vector


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


@checked_keywords
@dataclass(frozen=True)
class CirclePath(Path):
    """A circle in a plane of constant z, run counter-clockwise seen from +z.

    The arc length ``s`` [m] is 0 on the circle's +x side and grows counter-clockwise: the point at
    ``s`` is ``center + radius (cos(s / radius), sin(s / radius), 0)``, base axes: the way the task axis
    ``t1`` runs (for ``e`` = base z) on a disc or a sphere touched from outside. The path of a disc
    (:func:`~hybrid.Circle`) and a sphere's latitude circle (:meth:`~hybrid.Sphere.latitude_circle`)
    are such circles.

    Parameters
    ----------
    center : sequence of float
        The centre [m], base axes: ``(x, y)`` for a path of the planar arm (in the base xy-plane), or
        ``(x, y, z)`` for one in space (the circle lies in the plane of that z).
    radius : float
        The radius [m], > 0.
    start : float
        The arc length [m] where a run starts unless told otherwise (default 0: the +x side).

    Raises
    ------
    HybridError
        A centre of other than 2 or 3 finite coordinates, a radius that is not positive, or a start
        that is not finite.

    Examples
    --------
    >>> import math
    >>> import hybrid
    >>> circle = hybrid.CirclePath(center=(0.5, 0.0), radius=0.2)
    >>> circle.point_at(0.0).round(6).tolist()
    [0.7, 0.0]
    >>> quarter = 0.2 * math.pi / 2  # a quarter turn [m]
    >>> (circle.point_at(quarter).round(6).tolist(),
    ...  circle.tangent_at(quarter).round(6).tolist())
    ([0.5, 0.2], [-1.0, 0.0])
    >>> # nearest to (0.5, 0.5): the circle's point (0.5, 0.2)
    >>> round(circle.arc_of((0.5, 0.5)), 6)
    0.314159
    """

    center: tuple[float, ...]
    radius: float
    start: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "center", _point("CirclePath", "center", self.center, (2, 3)))
        _finite("CirclePath", radius=self.radius, start=self.start)
        if self.radius <= 0:
            raise HybridError(f"CirclePath.radius = {self.radius} m; give a positive radius")

    def point_at(self, s: float) -> np.ndarray:
        """The circle's point at arc length ``s``.

        Parameters
        ----------
        s : float
            The arc length [m] from the +x side, counter-clockwise; any value (the circle repeats
            every ``2 pi radius``).

        Returns
        -------
        numpy.ndarray
            The point [m], base axes, with as many coordinates as ``center``.
        """
        ang = s / self.radius
        return np.array(self.center) + self.radius * self._radial(math.cos(ang), math.sin(ang))

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """The circle's points at many arc lengths at once (as :meth:`point_at` gives them one by one).

        Parameters
        ----------
        s : array_like
            The arc lengths [m], one-dimensional.

        Returns
        -------
        numpy.ndarray
            The points [m], base axes: one row per arc length, as many columns as ``center``.
        """
        ang = np.asarray(s, float) / self.radius
        return np.array(self.center) + self.radius * self._radial(np.cos(ang), np.sin(ang)).T

    def tangent_at(self, s: float) -> np.ndarray:
        """The unit tangent at arc length ``s``, in the direction of growing ``s`` (counter-clockwise).

        Parameters
        ----------
        s : float
            The arc length [m].

        Returns
        -------
        numpy.ndarray
            ``(-sin(s / radius), cos(s / radius), 0)``, base axes, with as many coordinates as ``center``.
        """
        ang = s / self.radius
        return self._radial(-math.sin(ang), math.cos(ang))

    def arc_of(self, p) -> float:
        """The arc length of the circle's point nearest ``p``: the angle of ``p`` about the centre,
        seen from +z, times the radius.

        Parameters
        ----------
        p : sequence of float
            A point [m], base axes (2 or 3 coordinates; its z is not read). At the centre the angle
            is taken as 0.

        Returns
        -------
        float
            The arc length [m], in ``(-pi radius, pi radius]``.
        """
        d = np.asarray(p, float)[:2] - np.asarray(self.center)[:2]
        return self.radius * math.atan2(d[1], d[0])

    def _radial(self, c, s):
        return np.array([c, s, 0.0 * c][:len(self.center)])


@checked_keywords
@dataclass(frozen=True)
class LinePath(Path):
    """A straight line through ``point`` along ``direction``: ``r(s) = point + s d``.

    The path of a vertical plane seen by the planar arm (its cross-section, run along the tangent
    ``t = (-n_y, n_x)``), and of a plane in space through a start point
    (:meth:`~hybrid.Plane.path_through`).

    Parameters
    ----------
    point : sequence of float
        The point at arc length 0 [m], base axes: ``(x, y)`` for a path of the planar arm, or
        ``(x, y, z)`` for one in space.
    direction : sequence of float
        The direction of growing arc length, base axes, with as many coordinates as ``point``; any
        length but zero: it is kept as the unit ``d = direction / |direction|``.
    start : float
        The arc length [m] where a run starts unless told otherwise (default 0: at ``point``).

    Raises
    ------
    HybridError
        A point or direction of other than 2 or 3 finite coordinates (or of different lengths), a
        direction of zero length, or a start that is not finite.

    Examples
    --------
    >>> import hybrid
    >>> line = hybrid.LinePath(point=(0.4, 0.0, 0.2),
    ...                        direction=(0.0, 2.0, 0.0))
    >>> line.direction
    (0.0, 1.0, 0.0)
    >>> line.point_at(0.05).tolist()
    [0.4, 0.05, 0.2]
    >>> # nearest to the line's point (0.4, -0.1, 0.2)
    >>> line.arc_of((0.5, -0.1, 0.3))
    -0.1
    """

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
        """The line's point at arc length ``s``: ``point + s d``.

        Parameters
        ----------
        s : float
            The arc length [m] from ``point``, along ``d`` (negative: behind ``point``).

        Returns
        -------
        numpy.ndarray
            The point [m], base axes, with as many coordinates as ``point``.
        """
        return np.array(self.point) + s * np.array(self.direction)

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """The line's points at many arc lengths at once (as :meth:`point_at` gives them one by one).

        Parameters
        ----------
        s : array_like
            The arc lengths [m], one-dimensional.

        Returns
        -------
        numpy.ndarray
            The points [m], base axes: one row per arc length, as many columns as ``point``.
        """
        return np.array(self.point) + np.outer(np.asarray(s, float), self.direction)

    def tangent_at(self, s: float) -> np.ndarray:
        """The unit tangent: ``d``, the same at every arc length.

        Parameters
        ----------
        s : float
            The arc length [m] (not read).

        Returns
        -------
        numpy.ndarray
            The unit direction ``d``, base axes.
        """
        return np.array(self.direction)

    def arc_of(self, p) -> float:
        """The arc length of the line's point nearest ``p`` (the foot of the perpendicular from ``p``):
        ``(p - point) . d``.

        Parameters
        ----------
        p : sequence of float
            A point [m], base axes, with as many coordinates as ``point``.

        Returns
        -------
        float
            The arc length [m].
        """
        return float((np.asarray(p, float) - self.point) @ np.array(self.direction))
