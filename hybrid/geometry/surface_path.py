"""A curve drawn on a surface, parametrised by its arc length: the base of
:class:`~hybrid.WaypointPath`, :class:`~hybrid.RasterPath` and :class:`~hybrid.SpiralPath`.

A subclass gives a base curve ``B(u)`` in pieces (a spline's segments, a raster's passes and
turns), each a smooth function of its parameter ``u`` defined a little beyond its ends. The path is
``C(u) = proj(B(u))``, every point moved onto the surface (:func:`project_points`), so every sample
lies on it to rounding error. Its arc length ``s(u)`` is tabulated once, piece by piece, by
Gauss-Legendre quadrature of ``|C'(u)|`` on short sub-intervals; ``u(s)`` is the table's cubic
Hermite interpolant polished by one Newton step on the quadrature, so ``point_at(s)`` is at arc
length ``s`` to about 1e-12 of the length. ``C'`` and ``C''`` are fourth-order central differences
of ``C`` within one piece (its formula continued past the piece's ends, never across a joint).
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.paths import Path
from hybrid.geometry.surface_points import project_points
from hybrid.geometry.surfaces import Surface

#: Gauss-Legendre nodes and weights on [-1, 1] for each sub-interval of the arc-length table
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)
#: the longest sub-interval of the table [m] (the Hermite interpolant's error is about its fourth power)
TABLE_STEP = 2e-3
#: the difference steps of C' and C'' [m along the base curve; at most 1/2000 and 1/50 of the piece]:
#: small against a turn's radius (the error is about (step / radius)^4), large enough that rounding
#: (about 1e-16 / step and 1e-16 / step^2) stays below 1e-10
FIRST_STEP, SECOND_STEP = 2e-5, 5e-4


def check_surface(owner: str, surface) -> None:
    """A path is drawn on a 3-D surface with a formula (``phi``) of its own."""
    if not isinstance(surface, Surface) or surface.spec().estimated:
        raise HybridError(f"{owner}.surface = {str(surface)[:60]}; give a hybrid surface (Plane, Sphere, Cylinder, "
                          "Circle or ImplicitSurface) the path is drawn on")


class SurfacePath(Path):
    """A curve on ``surface``, parametrised by arc length ``s`` in ``[0, length]`` (any ``s`` on a closed one,
    taken modulo ``length``).

    Besides the :class:`Path` protocol (:meth:`point_at`, :meth:`points_at`, :meth:`tangent_at`,
    :meth:`arc_of`) it gives :meth:`normal_at` (the surface's unit normal, towards the robot),
    :meth:`curvature_at` (the curvature vector ``d^2 r / ds^2``; its component along ``normal_at(s)`` is
    the surface's normal curvature along the path), all four at once (:meth:`frames_at`), where its
    pieces meet (:attr:`joints`) and what it was made from (:meth:`arguments`). Points, tangents and
    normals are in base axes.

    Attributes
    ----------
    surface : Surface
        The surface the path is drawn on.
    closed : bool
        Whether the path returns to its start (its arc length then wraps around ``length``).
    length : float
        The path's length [m], along the surface.
    start : float
        The arc length [m] where a run starts unless told otherwise.
    """

    surface: Surface
    closed: bool
    start: float = 0.0
    dim = 3

    # ------------------------------------------------------------------ what a subclass gives

    def _base(self, piece: np.ndarray, u: np.ndarray) -> np.ndarray:
        """The base curve's points (N x 3) at the parameters ``u`` of the pieces ``piece``."""
        raise NotImplementedError

    # ------------------------------------------------------------------ the table

    def _tabulate(self, knots) -> None:
        """The arc-length table over the pieces ``[knots[i], knots[i + 1]]`` of the base curve."""
        self._knots = np.asarray(knots, dtype=float)
        n = len(self._knots) - 1
        pieces = np.arange(n)
        # each piece's length along the base curve, roughly, sets its difference steps and sub-intervals
        frac = np.linspace(0.0, 1.0, 17)
        u = self._knots[:-1, None] + np.outer(np.diff(self._knots), frac)
        base = self._base(np.repeat(pieces, len(frac)), u.ravel()).reshape(n, len(frac), 3)
        rough = np.linalg.norm(np.diff(base, axis=1), axis=2).sum(axis=1)
        if not np.all(rough > 0):
            raise HybridError(f"{self._owner}: a piece of the path has zero length; give distinct points")
        per_u = rough / np.diff(self._knots)  # base-curve metres per unit of u
        self._h1 = np.minimum(FIRST_STEP, 5e-4 * rough) / per_u
        self._h2 = np.minimum(SECOND_STEP, 2e-2 * rough) / per_u
        counts = np.maximum(8, np.ceil(rough / TABLE_STEP).astype(int))
        piece = np.repeat(pieces, counts)
        start = np.concatenate([[0], np.cumsum(counts)[:-1]])
        k = np.arange(len(piece)) - np.repeat(start, counts)
        width = np.diff(self._knots)[piece] / counts[piece]
        ua = self._knots[piece] + k * width
        ub = np.where(k == counts[piece] - 1, self._knots[piece + 1], ua + width)
        ds = self._integral(piece, ua, ub)
        self._piece, self._ua, self._ub = piece, ua, ub
        self._sa = np.concatenate([[0.0], np.cumsum(ds)])
        self._va = self._speed(piece, ua)
        self._vb = self._speed(piece, ub)
        self.length = float(self._sa[-1])
        self._corners = self._points(piece, ua)[0]

    def _points(self, piece, u) -> tuple[np.ndarray, np.ndarray]:
        """``C(u)`` on the surface and the surface's normals there."""
        return project_points(self.surface, self._base(piece, u), self._owner)

    def _derivatives(self, piece, u, second: bool = False):
        """``C(u)``, the normals, ``C'(u)`` and (with ``second``) ``C''(u)`` by central differences."""
        piece, u = np.asarray(piece), np.asarray(u, dtype=float)
        h1, h2 = self._h1[piece], self._h2[piece]
        steps = [np.zeros_like(u), -2 * h1, -h1, h1, 2 * h1] + ([-2 * h2, -h2, h2, 2 * h2] if second else [])
        m = len(u)
        C, normals = self._points(np.tile(piece, len(steps)), np.concatenate([u + d for d in steps]))
        C = C.reshape(len(steps), m, 3)
        d1 = (C[1] - 8 * C[2] + 8 * C[3] - C[4]) / (12 * h1)[:, None]
        if not second:
            return C[0], normals[:m], d1, None
        d2 = (-C[5] + 16 * C[6] - 30 * C[0] + 16 * C[7] - C[8]) / (12 * h2 ** 2)[:, None]
        return C[0], normals[:m], d1, d2

    def _speed(self, piece, u) -> np.ndarray:
        return np.linalg.norm(self._derivatives(piece, u)[2], axis=1)

    def _integral(self, piece, ua, ub) -> np.ndarray:
        """``int_ua^ub |C'(u)| du`` on each piece (Gauss-Legendre)."""
        half, mid = 0.5 * (ub - ua), 0.5 * (ub + ua)
        nodes = (mid[:, None] + half[:, None] * _GL_X).ravel()
        speed = self._speed(np.repeat(piece, len(_GL_X)), nodes).reshape(len(ua), len(_GL_X))
        return half * (speed @ _GL_W)

    def arc_at_knot(self, i: int) -> float:
        """The arc length where the ``i``-th piece of the path starts.

        Parameters
        ----------
        i : int
            The piece, from 0 (a waypoint path's pieces run between its waypoints; a raster's are its
            passes and turns); the number of pieces gives the path's end.

        Returns
        -------
        float
            The arc length [m] (0 for ``i = 0``, ``length`` for the end).
        """
        return float(self._sa[np.searchsorted(self._ua, self._knots[i])])

    # ------------------------------------------------------------------ arc length to parameter

    def _wrapped(self, s) -> np.ndarray:
        s = np.atleast_1d(np.asarray(s, dtype=float))
        if not np.isfinite(s).all():
            raise HybridError(f"{self._owner}: the arc length {s[~np.isfinite(s)][0]} is not finite; give a finite s")
        if self.closed:
            return np.mod(s, self.length)
        tol = 1e-9 * self.length
        outside = (s < -tol) | (s > self.length + tol)
        if outside.any():
            raise HybridError(f"{self._owner}: the arc length {s[outside][0]:.6g} m is beyond the path "
                              f"(0 to {self.length:.6g} m); give s within it (an open path ends)")
        return np.clip(s, 0.0, self.length)

    def _parameter(self, s) -> tuple[np.ndarray, np.ndarray]:
        """The pieces and parameters ``u`` at the arc lengths ``s``."""
        s = self._wrapped(s)
        j = np.clip(np.searchsorted(self._sa, s, side="right") - 1, 0, len(self._ua) - 1)
        piece, ua, ub, sa = self._piece[j], self._ua[j], self._ub[j], self._sa[j]
        ds = self._sa[j + 1] - sa
        t = (s - sa) / ds
        h00, h10, h01, h11 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, -2 * t**3 + 3 * t**2, t**3 - t**2
        u = h00 * ua + h10 * ds / self._va[j] + h01 * ub + h11 * ds / self._vb[j]
        # one Newton step on the quadrature from the sub-interval's start: the interpolant's error squared
        u = u - (sa + self._integral(piece, ua, u) - s) / self._speed(piece, u)
        return piece, u

    # ------------------------------------------------------------------ the Path protocol

    def points_at(self, s) -> np.ndarray:
        """The path's points at many arc lengths at once (as :meth:`point_at` gives them one by one).

        Parameters
        ----------
        s : array_like
            The arc lengths [m], each in ``[0, length]`` (any value on a closed path: taken modulo
            ``length``).

        Returns
        -------
        numpy.ndarray
            The points on the surface [m], base axes: one row of 3 per arc length.

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        return self._points(*self._parameter(s))[0]

    def point_at(self, s: float) -> np.ndarray:
        """The path's point at arc length ``s``, on the surface.

        Parameters
        ----------
        s : float
            The arc length [m], in ``[0, length]`` (any value on a closed path: taken modulo ``length``).

        Returns
        -------
        numpy.ndarray
            The point [m], base axes (3).

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        return self.points_at(s)[0]

    def tangent_at(self, s: float) -> np.ndarray:
        """The unit tangent at arc length ``s``: along the surface, in the direction of growing ``s``.

        Parameters
        ----------
        s : float
            The arc length [m], in ``[0, length]`` (any value on a closed path: taken modulo ``length``).

        Returns
        -------
        numpy.ndarray
            The unit tangent, base axes (3).

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        d1 = self._derivatives(*self._parameter(s))[2][0]
        return d1 / np.linalg.norm(d1)

    def normal_at(self, s: float) -> np.ndarray:
        """The surface's unit normal ``n`` at the path's point at arc length ``s``.

        Parameters
        ----------
        s : float
            The arc length [m], in ``[0, length]`` (any value on a closed path: taken modulo ``length``).

        Returns
        -------
        numpy.ndarray
            The unit normal, from the surface towards the robot, base axes (3).

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        return self._derivatives(*self._parameter(s))[1][0]

    def curvature_at(self, s: float) -> np.ndarray:
        """The curvature vector ``d^2 r / ds^2`` at arc length ``s``.

        Its length is the path's curvature; its component along :meth:`normal_at` is the surface's
        normal curvature along the path (``-1 / rho`` on a sphere of radius ``rho``, touched from outside),
        the rest the path's turn within the surface (its geodesic curvature).

        Parameters
        ----------
        s : float
            The arc length [m], in ``[0, length]`` (any value on a closed path: taken modulo ``length``).

        Returns
        -------
        numpy.ndarray
            The curvature vector [1/m], base axes (3), normal to :meth:`tangent_at`.

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        _, _, d1, d2 = self._derivatives(*self._parameter(s), second=True)
        d1, d2 = d1[0], d2[0]
        speed2 = float(d1 @ d1)
        return (d2 - (d2 @ d1) / speed2 * d1) / speed2

    def arguments(self) -> dict:
        """What the path was made from, but its surface, as JSON-ready data.

        Returns
        -------
        dict
            The arguments given, by name (points as lists of numbers): its class takes them back,
            ``type(path)(path.surface, **path.arguments())`` is the same path.
        """
        return dict(self._given)

    @property
    def joints(self) -> np.ndarray:
        """The arc lengths [m] where the path's pieces meet (its curvature may jump there), from 0 to
        ``length``: one more than the pieces (:meth:`arc_at_knot` of each)."""
        return np.array([self.arc_at_knot(i) for i in range(len(self._knots))])

    def frames_at(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The points, tangents, normals and curvature vectors at many arc lengths at once (as
        :meth:`point_at`, :meth:`tangent_at`, :meth:`normal_at` and :meth:`curvature_at` give them one
        by one).

        Parameters
        ----------
        s : array_like
            The arc lengths [m], each in ``[0, length]`` (any value on a closed path: taken modulo
            ``length``).

        Returns
        -------
        points, tangents, normals, curvatures : numpy.ndarray
            One row of 3 per arc length, base axes: the points [m], the unit tangents, the surface's
            unit normals (towards the robot) and the curvature vectors ``d^2 r / ds^2`` [1/m].

        Raises
        ------
        HybridError
            An arc length that is not finite, or beyond the ends of an open path.
        """
        C, normals, d1, d2 = self._derivatives(*self._parameter(s), second=True)
        speed2 = np.einsum("ij,ij->i", d1, d1)
        kappa = (d2 - (np.einsum("ij,ij->i", d2, d1) / speed2)[:, None] * d1) / speed2[:, None]
        return C, d1 / np.sqrt(speed2)[:, None], normals, kappa

    def arc_of(self, p) -> float:
        """The arc length of the path's point nearest ``p``.

        A local search: Newton's steps along the path from its tabulated point nearest ``p``, to the
        foot of the perpendicular from ``p`` there (on an open path, at most its ends).

        Parameters
        ----------
        p : sequence of float
            A point [m], base axes (3 coordinates).

        Returns
        -------
        float
            The arc length [m], in ``[0, length]`` (``[0, length)`` on a closed path).

        Raises
        ------
        HybridError
            A point that is not three finite coordinates.
        """
        p = np.asarray(p, dtype=float)
        if p.shape != (3,) or not np.isfinite(p).all():
            raise HybridError(f"{self._owner}.arc_of: give a point of three finite coordinates, got {p.tolist()}")
        s = float(self._sa[int(np.argmin(np.linalg.norm(self._corners - p, axis=1)))])
        for _ in range(20):
            piece, u = self._parameter(s)
            C, _, d1, d2 = self._derivatives(piece, u, second=True)
            speed2 = float(d1[0] @ d1[0])
            t = d1[0] / math.sqrt(speed2)
            kappa = (d2[0] - (d2[0] @ d1[0]) / speed2 * d1[0]) / speed2
            r = C[0] - p
            step = -float(r @ t) / max(1.0 + float(r @ kappa), 0.1)
            s = s + step
            if not self.closed:
                s = min(max(s, 0.0), self.length)
            if abs(step) < 1e-13 * max(self.length, 1.0):
                break
        return float(np.mod(s, self.length)) if self.closed else s
