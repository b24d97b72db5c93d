"""Coverage patterns on a surface: a raster of parallel passes (:class:`RasterPath`) and an
Archimedean spiral (:class:`SpiralPath`).

Each is drawn in the surface's tangent plane at a point of it, in closed form (lines, circular arcs,
a spiral), and moved onto the surface point by point (:class:`~hybrid.geometry.surface_path.SurfacePath`).
Lengths, spacing and pitch are those of the drawing in the tangent plane: on a plane they are the
path's own; on a curved surface the projection stretches them a little.
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.surface_path import SurfacePath, check_surface
from hybrid.geometry.surface_points import project_points
from hybrid.geometry.waypoints import WAYPOINT_TOL
from hybrid.validate import _finite, _point, checked_keywords

LINE, ARC = 0, 1


def tangent_plane(owner: str, surface, point, direction) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The surface point nearest ``point`` (refused farther than :data:`WAYPOINT_TOL`), and there the unit
    ``direction`` within the tangent plane ``d``, ``c = n x d`` and the normal ``n``."""
    check_surface(owner, surface)
    given = np.array(_point(owner, "origin" if owner == "RasterPath" else "center", point, (3,)))
    way = np.array(_point(owner, "direction", direction, (3,)))
    (origin,), (n,) = project_points(surface, given[None, :], owner)
    off = float(np.linalg.norm(origin - given))
    if off > WAYPOINT_TOL:
        raise HybridError(f"{owner}: the point {np.round(given, 6).tolist()} m is {off * 1e3:.2f} mm off the surface; "
                          f"give a point within {WAYPOINT_TOL * 1e3:g} mm of it, e.g. {np.round(origin, 6).tolist()}")
    d = way - (way @ n) * n
    if not np.linalg.norm(d) > 1e-9 * max(np.linalg.norm(way), 1e-300):
        raise HybridError(f"{owner}.direction = {way.tolist()} is along the surface's normal {np.round(n, 6).tolist()} "
                          "there; give a direction along the surface")
    d = d / np.linalg.norm(d)
    return origin, d, np.cross(n, d), n


def _positive(owner: str, **values) -> None:
    _finite(owner, **values)
    for name, v in values.items():
        if not v > 0:
            raise HybridError(f"{owner}.{name} = {v}; give a positive {name}")


def _count(owner: str, name: str, value) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise HybridError(f"{owner}.{name} = {value!r}; give a whole number of at least 1")
    return int(value)


def _plain(value):
    """A given number or point as JSON-ready data (None stays None)."""
    if value is None:
        return None
    return np.asarray(value, dtype=float).tolist()


class _PlanarPieces(SurfacePath):
    """A path drawn in the tangent plane at ``origin`` (axes ``d``, ``c``) as lines and circular arcs,
    each parametrised by its own arc length in the plane."""

    def _drawn(self, origin, d, c, pieces) -> None:
        # per piece: kind, start or centre (a, b), direction (a, b) of a line, radius, turning sign, start angle
        self._origin, self._axes = origin, np.array([d, c])
        self._kind = np.array([p[0] for p in pieces])
        self._at = np.array([p[1] for p in pieces], dtype=float)
        self._way = np.array([p[2] for p in pieces], dtype=float)
        self._radius = np.array([p[3] for p in pieces], dtype=float)
        self._sign = np.array([p[4] for p in pieces], dtype=float)
        self._angle = np.array([p[5] for p in pieces], dtype=float)
        lengths = np.array([p[6] for p in pieces], dtype=float)
        self._tabulate(np.concatenate([[0.0], np.cumsum(lengths)]))

    def _base(self, piece, u):
        local = (u - self._knots[piece])[:, None]
        line = self._at[piece] + local * self._way[piece]
        r = self._radius[piece][:, None]
        theta = self._angle[piece][:, None] + local / r
        arc = self._at[piece] + r * np.hstack([self._sign[piece][:, None] * np.sin(theta), -np.cos(theta)])
        ab = np.where((self._kind[piece] == LINE)[:, None], line, arc)
        return self._origin + ab @ self._axes


@checked_keywords
class RasterPath(_PlanarPieces):
    """Parallel passes across a part with round turns between them, on ``surface``.

    The first pass starts at ``origin`` and runs ``pass_length`` along ``direction`` (within the
    tangent plane there); each next pass runs back, ``spacing`` to the side ``n x direction`` (``n``
    the surface's normal at ``origin``, towards the robot). Between passes the path turns beyond the
    pass's end on circles of ``turn_radius``. Tangent-continuous (C1) everywhere; the curvature steps
    where a turn meets a pass. Drawn in the tangent plane at ``origin`` and moved onto the surface:
    on a plane the lengths are the path's own, on a curved surface the projection stretches them a
    little. An open path: its arc length runs from 0 at ``origin`` to ``length`` at the last pass's end.

    Parameters
    ----------
    surface : Surface
        The surface the path is drawn on: a :class:`~hybrid.Plane`, :class:`~hybrid.Sphere`,
        :class:`~hybrid.Cylinder`, :func:`~hybrid.Circle` or :class:`~hybrid.ImplicitSurface`.
    origin : sequence of float
        Where the first pass starts [m], base axes (3 coordinates), within 5 mm of the surface (it is
        moved onto it).
    direction : sequence of float
        The direction of the first pass, base axes (3 coordinates); its part along the surface's
        normal at ``origin`` is dropped (refused when nothing is left).
    pass_length : float
        The length of each pass [m], > 0.
    spacing : float
        The distance between neighbouring passes [m], > 0.
    passes : int
        The number of passes, a whole number >= 1.
    turn_radius : float, optional
        The radius of the turns [m], > 0 and at most ``spacing / 2``. None (the default):
        ``spacing / 2``, each turn a semicircle; smaller: two quarter circles joined by a straight piece
        ``spacing - 2 turn_radius`` long.
    start : float
        The arc length [m] where a run starts unless told otherwise (default 0: at ``origin``).

    Attributes
    ----------
    pass_arcs : tuple of (float, float)
        Each pass's ``(s_begin, s_end)`` [m] along the path, in order.
    length : float
        The path's length along the surface [m].

    Raises
    ------
    HybridError
        A surface that is not a hybrid surface, a length, spacing or turn radius that is not positive
        (or a turn radius above half the spacing), a number of passes that is not a whole number >= 1,
        an ``origin`` off the surface, or a ``direction`` along its normal.

    Examples
    --------
    Three passes of 10 cm, 2 cm apart, on a horizontal plane; each turn is a semicircle of 1 cm:

    >>> import hybrid
    >>> plane = hybrid.Plane(point=(0.4, 0.0, 0.2),
    ...                      normal=(0.0, 0.0, 1.0))
    >>> raster = hybrid.RasterPath(plane, origin=(0.35, -0.05, 0.2),
    ...                            direction=(1.0, 0.0, 0.0),
    ...                            pass_length=0.1, spacing=0.02,
    ...                            passes=3)
    >>> raster
    RasterPath(Plane, 3 passes of 0.1 m, spacing 0.02 m,
               length=0.362832 m)
    >>> [(round(a, 6), round(b, 6)) for a, b in raster.pass_arcs]
    [(0.0, 0.1), (0.131416, 0.231416), (0.262832, 0.362832)]
    >>> # the second pass starts 2 cm to the side
    >>> raster.point_at(raster.pass_arcs[1][0]).round(6).tolist()
    [0.45, -0.03, 0.2]
    """

    def __init__(self, surface, origin, direction, pass_length: float, spacing: float, passes: int,
                 turn_radius: float | None = None, start: float = 0.0):
        self._owner = owner = "RasterPath"
        _positive(owner, pass_length=pass_length, spacing=spacing)
        passes = _count(owner, "passes", passes)
        radius = spacing / 2 if turn_radius is None else turn_radius
        _positive(owner, turn_radius=radius)
        if radius > spacing / 2 * (1 + 1e-12):
            raise HybridError(f"RasterPath.turn_radius = {radius} m is more than half the spacing ({spacing} m); give "
                              f"at most {spacing / 2} m")
        _finite(owner, start=start)
        self.surface, self.closed, self.start = surface, False, float(start)
        self.pass_length, self.spacing, self.passes, self.turn_radius = pass_length, spacing, passes, radius
        given = {"origin": origin, "direction": direction}
        origin, d, c, _ = tangent_plane(owner, surface, origin, direction)
        self._given = {**{k: _plain(v) for k, v in given.items()}, "pass_length": float(pass_length),
                       "spacing": float(spacing), "passes": passes, "turn_radius": _plain(turn_radius),
                       "start": self.start}
        gap = max(spacing - 2 * radius, 0.0)
        pieces, is_pass = [], []
        for k in range(passes):
            sign = 1.0 if k % 2 == 0 else -1.0
            a0, b = (0.0 if sign > 0 else pass_length), k * spacing
            pieces.append((LINE, (a0, b), (sign, 0.0), 1.0, 1.0, 0.0, pass_length))
            is_pass.append(True)
            if k == passes - 1:
                break
            end = a0 + sign * pass_length
            if gap == 0.0:  # one semicircle
                pieces.append((ARC, (end, b + radius), (0, 0), radius, sign, 0.0, math.pi * radius))
                is_pass.append(False)
                continue
            pieces += [(ARC, (end, b + radius), (0, 0), radius, sign, 0.0, 0.5 * math.pi * radius),
                       (LINE, (end + sign * radius, b + radius), (0.0, 1.0), 1.0, 1.0, 0.0, gap),
                       (ARC, (end, b + radius + gap), (0, 0), radius, sign, 0.5 * math.pi, 0.5 * math.pi * radius)]
            is_pass += [False] * 3
        self._drawn(origin, d, c, pieces)
        self.pass_arcs = tuple((self.arc_at_knot(i), self.arc_at_knot(i + 1)) for i, p in enumerate(is_pass) if p)

    def __repr__(self):
        return (f"RasterPath({type(self.surface).__name__}, {self.passes} passes of {self.pass_length:g} m, "
                f"spacing {self.spacing:g} m, length={self.length:.6g} m)")


@checked_keywords
class SpiralPath(SurfacePath):
    """An Archimedean spiral on ``surface`` about ``center``, outwards.

    In the tangent plane at ``center`` the spiral's radius is ``start_radius + pitch * angle / (2 pi)``
    [m] at the angle [rad] from ``direction``, counter-clockwise about the surface's normal ``n``
    (towards the robot), for ``turns`` turns; every point of it is moved onto the surface. On a plane
    the lengths are the path's own; on a curved surface the projection stretches them a little. An
    open path: its arc length runs from 0 at the spiral's start to ``length`` at its outer end.

    Parameters
    ----------
    surface : Surface
        The surface the path is drawn on: a :class:`~hybrid.Plane`, :class:`~hybrid.Sphere`,
        :class:`~hybrid.Cylinder`, :func:`~hybrid.Circle` or :class:`~hybrid.ImplicitSurface`.
    center : sequence of float
        The spiral's centre [m], base axes (3 coordinates), within 5 mm of the surface (it is moved
        onto it).
    pitch : float
        The distance between neighbouring turns [m], > 0.
    turns : float
        The number of turns, > 0 (need not be whole).
    start_radius : float
        The radius where the spiral starts [m], >= 0 (default 0: at the centre).
    direction : sequence of float, optional
        The direction from the centre to the spiral's start, base axes (3 coordinates); its part along
        the normal at ``center`` is dropped. None (the default): base x, or base y where the normal is
        within about 26 degrees of base x either way (``|n_x| >= 0.9``).
    start : float
        The arc length [m] where a run starts unless told otherwise (default 0: the spiral's start).

    Attributes
    ----------
    center : numpy.ndarray
        The centre moved onto the surface [m].
    length : float
        The path's length along the surface [m].

    Raises
    ------
    HybridError
        A surface that is not a hybrid surface, a pitch or number of turns that is not positive, a
        negative start radius, a ``center`` off the surface, or a ``direction`` along its normal.

    Examples
    --------
    Three turns 1 cm apart from the centre of a horizontal plane, starting along base x:

    >>> import hybrid
    >>> plane = hybrid.Plane(point=(0.4, 0.0, 0.2),
    ...                      normal=(0.0, 0.0, 1.0))
    >>> spiral = hybrid.SpiralPath(plane, center=(0.4, 0.0, 0.2),
    ...                            pitch=0.01, turns=3)
    >>> spiral
    SpiralPath(Plane, pitch 0.01 m, 3 turns, length=0.28603 m)
    >>> import numpy as np
    >>> end = spiral.point_at(spiral.length)
    >>> # the outer end: 3 pitches from the centre [m]
    >>> round(float(np.linalg.norm(end - spiral.center)), 6)
    0.03
    """

    def __init__(self, surface, center, pitch: float, turns: float, start_radius: float = 0.0,
                 direction=None, start: float = 0.0):
        self._owner = owner = "SpiralPath"
        _positive(owner, pitch=pitch, turns=turns)
        _finite(owner, start_radius=start_radius, start=start)
        if start_radius < 0:
            raise HybridError(f"SpiralPath.start_radius = {start_radius} m; give 0 or a positive radius")
        self.surface, self.closed, self.start = surface, False, float(start)
        self.pitch, self.turns, self.start_radius = pitch, turns, start_radius
        given = {"center": center, "direction": direction}
        if direction is None:  # base x, or base y where the normal is along base x
            check_surface(owner, surface)
            p = np.array(_point(owner, "center", center, (3,)))
            (_,), (n,) = project_points(surface, p[None, :], owner)
            direction = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
        self.center, self._d, self._c, _ = tangent_plane(owner, surface, center, direction)
        self._given = {**{k: _plain(v) for k, v in given.items()}, "pitch": float(pitch), "turns": float(turns),
                       "start_radius": float(start_radius), "start": self.start}
        self._tabulate([0.0, 2 * math.pi * turns])

    def _base(self, piece, u):
        rho = (self.start_radius + self.pitch * u / (2 * math.pi))[:, None]
        return self.center + rho * (np.cos(u)[:, None] * self._d + np.sin(u)[:, None] * self._c)

    def __repr__(self):
        return (f"SpiralPath({type(self.surface).__name__}, pitch {self.pitch:g} m, {self.turns:g} turns, "
                f"length={self.length:.6g} m)")
