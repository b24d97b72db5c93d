"""A path on a surface through waypoints: a cubic spline through them, every point of it moved onto
the surface, parametrised by arc length (:class:`WaypointPath`)."""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.surface_path import SurfacePath, check_surface
from hybrid.geometry.surface_points import project_points
from hybrid.validate import _finite, checked_keywords

#: the farthest a waypoint may be from the surface before it is refused [m]
WAYPOINT_TOL = 5e-3
#: waypoints nearer each other than this (on the surface) [m] coincide
COINCIDENT_TOL = 1e-6


def cubic_spline(u: np.ndarray, y: np.ndarray, closed: bool) -> np.ndarray:
    """The second derivatives ``M`` (one row per knot) of the C2 cubic spline through the points ``y``
    at the knots ``u``: natural (``M = 0`` at both ends), or periodic when ``closed`` (``y`` then lists
    each point once and the spline returns to ``y[0]`` at ``u[-1]``)."""
    h = np.diff(u)
    n = len(h) if closed else len(y)
    A = np.zeros((n, n))
    rhs = np.zeros((n, y.shape[1]))
    ys = np.vstack([y, y[:1]]) if closed else y
    slope = np.diff(ys, axis=0) / h[:, None]
    if not closed:
        A[0, 0] = A[-1, -1] = 1.0
    for i in range(0 if closed else 1, n if closed else n - 1):
        before, after = (i - 1) % n, (i + 1) % n
        A[i, before] += h[i - 1]
        A[i, i] += 2.0 * (h[i - 1] + h[i])
        A[i, after] += h[i]
        rhs[i] = 6.0 * (slope[i] - slope[i - 1])
    M = np.linalg.solve(A, rhs)
    return np.vstack([M, M[:1]]) if closed else M


@checked_keywords
class WaypointPath(SurfacePath):
    """A C2 path on ``surface`` through ``points`` [m], in their order; ``closed`` joins the last point
    to the first (periodic: C2 there too).

    Each point is first moved onto the surface (refused farther than 5 mm from it). The path is the
    cubic spline through them in their chord length (natural at the ends of an open path), every
    point of it moved onto the surface, parametrised by arc length from the first point; it passes
    through every (projected) point. Its pieces (:attr:`joints`) run from one waypoint to the next.

    Parameters
    ----------
    surface : Surface
        The surface the path is drawn on: a :class:`~hybrid.Plane`, :class:`~hybrid.Sphere`,
        :class:`~hybrid.Cylinder`, :func:`~hybrid.Circle` or :class:`~hybrid.ImplicitSurface`.
    points : sequence of (x, y, z)
        The waypoints [m], base axes: at least two (three for a closed path), each within 5 mm of the
        surface, no two in a row the same.
    closed : bool
        Whether the path returns to its first point (leave the first point out at the end); default
        False.
    start : float
        The arc length [m] where a run starts unless told otherwise (default 0: the first point).

    Attributes
    ----------
    points : numpy.ndarray
        The waypoints moved onto the surface [m], one row each.
    knots : numpy.ndarray
        The spline's parameter at each waypoint: the chord lengths between the projected waypoints,
        summed from 0 [m] (a closed path's last is back at the first point).
    length : float
        The path's length along the surface [m].

    Raises
    ------
    HybridError
        A surface that is not a hybrid surface (or is estimated), too few points, points that are
        not three finite coordinates, a point farther than 5 mm from the surface, two points in a row
        the same, or a start that is not finite.

    Examples
    --------
    >>> import hybrid
    >>> plane = hybrid.Plane(point=(0.4, 0.0, 0.2),
    ...                      normal=(0.0, 0.0, 1.0))
    >>> points = [(0.35, -0.05, 0.2), (0.45, 0.0, 0.2),
    ...           (0.35, 0.05, 0.2)]
    >>> path = hybrid.WaypointPath(plane, points)
    >>> path
    WaypointPath(Plane, 3 points, closed=False, length=0.229601 m)
    >>> # the arc length [m] at the middle waypoint
    >>> s = path.arc_of_waypoint(1)
    >>> path.point_at(s).round(6).tolist(), path.normal_at(s).tolist()
    ([0.45, 0.0, 0.2], [0.0, 0.0, 1.0])
    >>> # there the path runs along base +y (symmetric about y = 0)
    >>> round(float(path.tangent_at(s)[1]), 6)
    1.0
    """

    def __init__(self, surface, points, closed: bool = False, start: float = 0.0):
        self._owner = "WaypointPath"
        check_surface(self._owner, surface)
        _finite("WaypointPath", start=start)
        if not isinstance(closed, (bool, np.bool_)):
            raise HybridError(f"WaypointPath.closed = {closed!r}; give True or False")
        try:
            given = np.array(points, dtype=float)
        except (TypeError, ValueError):
            raise HybridError(f"WaypointPath.points = {str(points)[:60]}; give a list of (x, y, z) points "
                              "in m") from None
        least = 3 if closed else 2
        if given.ndim != 2 or given.shape[1] != 3 or len(given) < least:
            raise HybridError(f"WaypointPath.points has shape {given.shape}; give at least {least} points of three "
                              f"coordinates (x, y, z) in m{' for a closed path' if closed else ''}")
        bad = np.flatnonzero(~np.isfinite(given).all(axis=1))
        if len(bad):
            raise HybridError(f"WaypointPath.points[{bad[0]}] = {given[bad[0]].tolist()} is not finite; give finite "
                              "coordinates")
        self.surface, self.closed, self.start = surface, bool(closed), float(start)
        projected, _ = project_points(surface, given, "WaypointPath")
        off = np.linalg.norm(projected - given, axis=1)
        if off.max() > WAYPOINT_TOL:
            i = int(np.argmax(off))
            raise HybridError(f"WaypointPath.points[{i}] = {np.round(given[i], 6).tolist()} m is {off[i] * 1e3:.2f} mm "
                              f"off the surface; give points within {WAYPOINT_TOL * 1e3:g} mm of it, e.g. "
                              f"{np.round(projected[i], 6).tolist()}")
        ring = np.vstack([projected, projected[:1]]) if self.closed else projected
        chord = np.linalg.norm(np.diff(ring, axis=0), axis=1)
        if chord.min() < COINCIDENT_TOL:
            i = int(np.argmin(chord))
            last = self.closed and i == len(projected) - 1
            raise HybridError(f"WaypointPath.points[{i}] and points[{(i + 1) % len(projected)}] coincide (at "
                              f"{np.round(projected[i], 6).tolist()} m); "
                              + ("leave the first point out at the end: closed=True returns to it" if last
                                 else "give each point once"))
        self.points = projected
        self._given = {"points": given.tolist(), "closed": self.closed, "start": self.start}
        self.knots = np.concatenate([[0.0], np.cumsum(chord)])
        self._M = cubic_spline(self.knots, projected, self.closed)
        self._ring = ring
        self._tabulate(self.knots)

    def _base(self, piece, u):
        u0, u1 = self.knots[piece], self.knots[piece + 1]
        h = (u1 - u0)[:, None]
        a, b = (u1 - u)[:, None], (u - u0)[:, None]
        Mi, Mj, yi, yj = self._M[piece], self._M[piece + 1], self._ring[piece], self._ring[piece + 1]
        return (Mi * a**3 + Mj * b**3) / (6 * h) + (yi / h - Mi * h / 6) * a + (yj / h - Mj * h / 6) * b

    def arc_of_waypoint(self, i: int) -> float:
        """The arc length at a waypoint.

        Parameters
        ----------
        i : int
            The waypoint, from 0 in the order given (on a closed path, the number of points is the
            first point again, at the end of the lap).

        Returns
        -------
        float
            The arc length [m] of the (projected) waypoint along the path.
        """
        return self.arc_at_knot(i)

    def __repr__(self):
        return (f"WaypointPath({type(self.surface).__name__}, {len(self.points)} points, closed={self.closed}, "
                f"length={self.length:.6g} m)")
