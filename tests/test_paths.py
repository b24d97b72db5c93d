"""Paths on any surface (WaypointPath, RasterPath, SpiralPath) against independent truth, their
refusals, and the experiment's refusal of a path its tip does not follow."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hybrid
from hybrid.geometry.paths import Path

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
CYLINDER = hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.6, 0.8), 0.1)
PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
ELLIPSOID = hybrid.ImplicitSurface("(x/a)**2 + (y/b)**2 + (z/c)**2 - 1", {"a": 0.3, "b": 0.2, "c": 0.1})


def phi(surface, points) -> np.ndarray:
    """``phi`` at each point, evaluated point by point by the surface's own function."""
    f = surface.phi_function()
    return np.array([f(p)[0] for p in points])


def on_sphere(directions, sphere=SPHERE) -> np.ndarray:
    d = np.asarray(directions, dtype=float)
    return np.asarray(sphere.center) + sphere.radius * d / np.linalg.norm(d, axis=1)[:, None]


def polyline_length(path, n: int = 4000) -> float:
    """The length of the path's polyline through points evenly spaced in arc length, extrapolated
    (Richardson) to infinitely many: an integral of the curve independent of the path's own table."""
    def chords(m):
        p = path.points_at(np.linspace(0.0, path.length, m + 1))
        return np.linalg.norm(np.diff(p, axis=0), axis=1).sum()
    return (4 * chords(2 * n) - chords(n)) / 3


def central(f, s, h):
    """The first and second derivatives of ``f`` at ``s`` by fourth-order central differences."""
    a, b, c, d, e = (np.asarray(f(s + k * h)) for k in (-2, -1, 0, 1, 2))
    return (a - 8 * b + 8 * d - e) / (12 * h), (-a + 16 * b - 30 * c + 16 * d - e) / (12 * h * h)


# ------------------------------------------------------------------------- waypoints


def test_a_great_circle_through_waypoints_is_the_great_circle():
    # coplanar waypoints through the centre: the spline stays in their plane, the radial projection too,
    # so the path is the great circle itself, of length R * angle and curvature vector -n / R
    angles = np.radians([0.0, 20.0, 50.0, 65.0, 100.0])
    u, v = np.array([0.0, 0.6, 0.8]), np.array([1.0, 0.0, 0.0])
    path = hybrid.WaypointPath(SPHERE, on_sphere(np.outer(np.cos(angles), u) + np.outer(np.sin(angles), v)))
    assert path.length == pytest.approx(SPHERE.radius * angles[-1], rel=1e-9)
    for s in np.linspace(0.0, path.length, 7):
        assert np.allclose(path.curvature_at(s), -path.normal_at(s) / SPHERE.radius, atol=1e-5 / SPHERE.radius)
    around = np.radians([0.0, 100.0, 200.0, 290.0])
    closed = hybrid.WaypointPath(SPHERE, on_sphere(np.outer(np.cos(around), u) + np.outer(np.sin(around), v)),
                                 closed=True)
    assert closed.length == pytest.approx(2 * math.pi * SPHERE.radius, rel=1e-9)


def test_a_closed_path_round_a_cylinder_is_its_circle():
    axis, c = np.asarray(CYLINDER.axis), np.asarray(CYLINDER.point)
    e1 = np.cross(axis, [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    ang = np.radians([0.0, 80.0, 150.0, 260.0])
    pts = c + 0.05 * axis + CYLINDER.radius * (np.outer(np.cos(ang), e1) + np.outer(np.sin(ang), e2))
    path = hybrid.WaypointPath(CYLINDER, pts, closed=True)
    assert path.length == pytest.approx(2 * math.pi * CYLINDER.radius, rel=1e-9)


@pytest.mark.parametrize("surface", [PLANE, SPHERE, CYLINDER, ELLIPSOID], ids=lambda s: type(s).__name__)
@pytest.mark.parametrize("closed", [False, True])
def test_waypoint_path_lies_on_the_surface_and_passes_its_points(surface, closed):
    if surface is PLANE:
        n = np.asarray(PLANE.normal)
        a = np.cross(n, [1.0, 0.0, 0.0])
        b = np.cross(n, a)
        given = np.asarray(PLANE.point) + np.outer([0.0, 0.05, 0.08, 0.02], a) + np.outer([0.0, 0.01, 0.06, 0.09], b)
    elif surface is ELLIPSOID:
        t = np.radians([10.0, 40.0, 75.0, 120.0])
        given = np.column_stack([0.3 * np.cos(t) * 0.8, 0.2 * np.sin(t) * 0.8, np.full(4, 0.1 * 0.6)])
        given /= np.sqrt((given[:, 0] / 0.3) ** 2 + (given[:, 1] / 0.2) ** 2 + (given[:, 2] / 0.1) ** 2)[:, None]
    elif surface is SPHERE:
        given = on_sphere([[1, 0, 1], [1, 1, 1], [0, 1, 1.2], [-1, 0.5, 1]])
    else:
        given = np.array([CYLINDER.project(p) for p in ([0.62, 0.0, 0.1], [0.55, 0.12, 0.05],
                                                        [0.4, 0.05, -0.02], [0.45, -0.1, 0.1])])
    path = hybrid.WaypointPath(surface, given, closed=closed)
    s = np.linspace(0.0, path.length, 801)
    assert np.max(np.abs(phi(surface, path.points_at(s)))) < 1e-9
    for i, p in enumerate(given):
        assert np.linalg.norm(path.point_at(path.arc_of_waypoint(i)) - p) < 1e-9
        assert path.arc_of(p) == pytest.approx(path.arc_of_waypoint(i), abs=1e-9)
    assert path.length == pytest.approx(polyline_length(path), rel=1e-9)
    for si in np.linspace(0.05, 0.95, 5) * path.length:
        d1, d2 = central(path.point_at, si, 1e-4 * path.length)
        assert np.allclose(path.tangent_at(si), d1 / np.linalg.norm(d1), atol=1e-7)
        assert abs(path.tangent_at(si) @ path.normal_at(si)) < 1e-9
        assert np.allclose(path.curvature_at(si), d2, atol=1e-4 * max(1.0, np.linalg.norm(d2)))
    if closed:
        for si in (0.0, 0.3 * path.length):
            assert np.allclose(path.point_at(si + path.length), path.point_at(si), atol=1e-12)
        # C1 and C2 across the joint: tangent and curvature just before the end and just after the start
        end, begin = path.length - 1e-9, 1e-9
        assert np.allclose(path.tangent_at(end), path.tangent_at(begin), atol=1e-6)
        kappa = np.linalg.norm(path.curvature_at(begin))
        assert np.allclose(path.curvature_at(end), path.curvature_at(begin), atol=1e-5 * kappa)


def test_the_curvature_is_continuous_at_the_waypoints():
    path = hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1], [1, 1, 1], [0, 1, 1.2], [-1, 0.5, 1]]))
    for i in (1, 2):
        s = path.arc_of_waypoint(i)
        before, after = path.curvature_at(s - 1e-9), path.curvature_at(s + 1e-9)
        assert np.allclose(before, after, atol=1e-5 * np.linalg.norm(after))


def around(rng, n: int) -> np.ndarray:
    """``n`` angles once round, each within 0.3 of its share from the even spacing (a loop, no cusp)."""
    return 2 * math.pi * (np.arange(n) + rng.uniform(-0.3, 0.3, n)) / n


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**32 - 1), st.booleans(), st.sampled_from(["sphere", "cylinder"]))
def test_random_waypoints(seed, closed, kind):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 7))
    if kind == "sphere":
        surface = SPHERE
        ang = around(rng, n) if closed else np.cumsum(rng.uniform(0.3, 0.8, n))
        polar = rng.uniform(0.4, 1.0, n)
        pts = on_sphere(np.column_stack([np.sin(polar) * np.cos(ang), np.sin(polar) * np.sin(ang), np.cos(polar)]))
    else:
        surface = hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.0, 1.0), 0.1)
        ang = around(rng, n) if closed else np.cumsum(rng.uniform(0.3, 0.8, n))
        pts = np.column_stack([0.5 + 0.1 * np.cos(ang), 0.1 * np.sin(ang), rng.uniform(-0.05, 0.05, n)])
    chord = np.linalg.norm(np.diff(np.vstack([pts, pts[:1]]) if closed else pts, axis=0), axis=1)
    if chord.min() < 0.01:
        return
    path = hybrid.WaypointPath(surface, pts, closed=closed)
    assert np.max(np.abs(phi(surface, path.points_at(np.linspace(0, path.length, 301))))) < 1e-9
    for i, p in enumerate(pts):
        assert np.linalg.norm(path.point_at(path.arc_of_waypoint(i)) - p) < 1e-9
    assert path.length == pytest.approx(polyline_length(path, 2000), rel=1e-8)


# ------------------------------------------------------------------------- raster and spiral


@pytest.mark.parametrize("turn_radius", [None, 0.004])
def test_raster_on_a_plane(turn_radius):
    origin, direction = np.asarray(PLANE.point), np.array([1.0, 0.0, 0.0])
    length, spacing, passes = 0.1, 0.02, 4
    raster = hybrid.RasterPath(PLANE, origin, direction, length, spacing, passes, turn_radius=turn_radius)
    r = spacing / 2 if turn_radius is None else turn_radius
    turn = math.pi * r + (spacing - 2 * r)
    assert raster.length == pytest.approx(passes * length + (passes - 1) * turn, rel=1e-9)
    d = direction - (direction @ PLANE.normal) * np.asarray(PLANE.normal)
    d /= np.linalg.norm(d)
    side = np.cross(PLANE.normal, d)
    assert len(raster.pass_arcs) == passes
    for k, (a, b) in enumerate(raster.pass_arcs):
        assert b - a == pytest.approx(length, rel=1e-9)
        pts = raster.points_at(np.linspace(a, b, 21)) - origin
        assert np.allclose(pts @ side, k * spacing, atol=1e-9)  # each pass spacing further to the side
        along = pts @ d
        assert np.allclose(np.sort(along), np.linspace(0.0, length, 21), atol=1e-9)
    s = np.linspace(0.0, raster.length, 2001)
    assert np.max(np.abs(phi(PLANE, raster.points_at(s)))) < 1e-9
    # tangent-continuous (C1) at every joint of a pass and a turn
    for a, b in raster.pass_arcs:
        for joint in (a, b):
            if 0 < joint < raster.length:
                assert np.allclose(raster.tangent_at(joint - 1e-9), raster.tangent_at(joint + 1e-9), atol=1e-6)


@pytest.mark.parametrize("surface", [SPHERE, CYLINDER, ELLIPSOID], ids=lambda s: type(s).__name__)
def test_raster_and_spiral_lie_on_curved_surfaces(surface):
    top = {SPHERE: on_sphere([[0.2, 0.1, 1.0]])[0], CYLINDER: None, ELLIPSOID: np.array([0.0, 0.0, 0.1])}[surface]
    if top is None:
        top = CYLINDER.project([0.62, 0.0, 0.1])
    for path in (hybrid.RasterPath(surface, top, (1.0, 0.0, 0.0), 0.06, 0.01, 3),
                 hybrid.SpiralPath(surface, top, 0.006, 2.5, start_radius=0.002)):
        s = np.linspace(0.0, path.length, 1201)
        assert np.max(np.abs(phi(surface, path.points_at(s)))) < 1e-9
        assert path.length == pytest.approx(polyline_length(path), rel=1e-9)
        for si in (0.2 * path.length, 0.7 * path.length):
            d1, _ = central(path.point_at, si, 1e-4)
            assert np.allclose(path.tangent_at(si), d1 / np.linalg.norm(d1), atol=1e-7)


@pytest.mark.parametrize("start_radius", [0.0, 0.01])
def test_spiral_on_a_plane(start_radius):
    center, pitch, turns = np.asarray(PLANE.point), 0.008, 3.0
    spiral = hybrid.SpiralPath(PLANE, center, pitch, turns, start_radius=start_radius)
    b = pitch / (2 * math.pi)

    def integral(phi_):  # int sqrt(r^2 + b^2) dtheta with r = b phi: the Archimedean spiral's arc length
        return 0.5 * b * (phi_ * math.sqrt(1 + phi_ * phi_) + math.asinh(phi_))

    phi0 = start_radius / b
    assert spiral.length == pytest.approx(integral(phi0 + 2 * math.pi * turns) - integral(phi0), rel=1e-9)
    rel = spiral.points_at(np.linspace(0.0, spiral.length, 3001)) - center
    n = np.asarray(PLANE.normal)
    d = np.array([1.0, 0.0, 0.0]) - n[0] * n  # the start's direction: base x within the plane
    d /= np.linalg.norm(d)
    c = np.cross(n, d)
    rho = np.hypot(rel @ d, rel @ c)
    keep = rho > 1e-4  # the angle is defined away from the centre
    rho, angle = rho[keep], np.unwrap(np.arctan2(rel @ c, rel @ d)[keep])
    assert np.allclose(rho - pitch * angle / (2 * math.pi), start_radius, atol=1e-9)
    assert angle[-1] == pytest.approx(2 * math.pi * turns, abs=1e-6)  # counter-clockwise about the normal


# ------------------------------------------------------------------------- refusals


@pytest.mark.parametrize(("make", "words"), [
    (lambda: hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1]])), "at least 2 points"),
    (lambda: hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1], [0, 1, 1]]), closed=True), "at least 3 points"),
    (lambda: hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1], [1, 0, 1], [0, 1, 1]])), "coincide"),
    (lambda: hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1], [0, 1, 1], [1, 0, 1]]), closed=True),
     "leave the first point out"),
    (lambda: hybrid.WaypointPath(SPHERE, [SPHERE.center, (0.6, 0.0, 0.3)]), "domain"),
    (lambda: hybrid.WaypointPath(SPHERE, [*on_sphere([[1, 0, 1]]), (0.5, 0.0, 0.36)]), "points[1]"),
    (lambda: hybrid.WaypointPath(SPHERE, [(0.6, 0.0, math.nan), (0.6, 0.1, 0.3)]), "not finite"),
    (lambda: hybrid.WaypointPath("sphere", [(0.6, 0.0, 0.3), (0.6, 0.1, 0.3)]), "hybrid surface"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, (1, 0, 0), 0.1, 0.0, 3), "spacing"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, (1, 0, 0), -0.1, 0.02, 3), "pass_length"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, (1, 0, 0), 0.1, 0.02, 0), "passes"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, (1, 0, 0), 0.1, math.nan, 2), "spacing"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, (1, 0, 0), 0.1, 0.02, 2, turn_radius=0.02), "turn_radius"),
    (lambda: hybrid.RasterPath(PLANE, PLANE.point, PLANE.normal, 0.1, 0.02, 2), "normal"),
    (lambda: hybrid.SpiralPath(PLANE, PLANE.point, 0.0, 2), "pitch"),
    (lambda: hybrid.SpiralPath(PLANE, PLANE.point, 0.01, -1), "turns"),
    (lambda: hybrid.SpiralPath(PLANE, np.asarray(PLANE.point) + 0.01 * np.asarray(PLANE.normal), 0.01, 2),
     "off the surface"),
])
def test_bad_input_is_refused(make, words):
    with pytest.raises(hybrid.HybridError, match=words.replace("[", r"\[").replace("]", r"\]")):
        make()


def test_a_path_leaving_the_surfaces_domain_is_refused():
    root = hybrid.ImplicitSurface("z - sqrt(x)", {})
    with pytest.raises(hybrid.HybridError, match="domain"):
        hybrid.RasterPath(root, (0.01, 0.0, 0.1), (-1.0, 0.0, 0.0), 0.05, 0.01, 2)
    with pytest.raises(hybrid.HybridError, match="beyond the path"):
        hybrid.WaypointPath(SPHERE, on_sphere([[1, 0, 1], [0, 1, 1]])).point_at(1.0)


# ------------------------------------------------------------------------- the experiment


class Meridian(Path):
    """A user's own path: the sphere's meridian through its +x side, up towards the top."""

    def point_at(self, s):
        a = 0.6 + s / SPHERE.radius
        return np.asarray(SPHERE.center) + SPHERE.radius * np.array([math.cos(a), 0.0, math.sin(a)])

    def points_at(self, s):
        return np.array([self.point_at(si) for si in np.atleast_1d(s)])

    def tangent_at(self, s):
        a = 0.6 + s / SPHERE.radius
        return np.array([-math.sin(a), 0.0, math.cos(a)])

    def arc_of(self, p):
        d = np.asarray(p) - SPHERE.center
        return SPHERE.radius * (math.atan2(d[2], d[0]) - 0.6)


class Latitude(Meridian):
    """A user's own path along the sphere's latitude circle through the same point, as t1 runs."""

    def point_at(self, s):
        rho = SPHERE.radius * math.cos(0.6)
        a = s / rho
        return np.asarray(SPHERE.center) + np.array([rho * math.cos(a), rho * math.sin(a),
                                                     SPHERE.radius * math.sin(0.6)])

    def tangent_at(self, s):
        a = s / (SPHERE.radius * math.cos(0.6))
        return np.array([-math.sin(a), math.cos(a), 0.0])

    def arc_of(self, p):
        d = np.asarray(p) - SPHERE.center
        return SPHERE.radius * math.cos(0.6) * math.atan2(d[1], d[0])


@pytest.mark.parametrize("frame", ["actual", "desired"])
def test_the_experiment_refuses_a_path_its_tip_does_not_follow(frame):
    start = on_sphere([[math.cos(0.6), 0.0, math.sin(0.6)]])[0]
    ahead = on_sphere([[math.cos(0.6), 0.3, math.sin(0.6) + 0.1], [0.2, 0.8, 0.9]])
    refused = [Meridian(), hybrid.WaypointPath(SPHERE, [start, *ahead]),
               hybrid.RasterPath(SPHERE, start, (0.0, 1.0, 0.0), 0.05, 0.01, 3),
               hybrid.SpiralPath(SPHERE, start, 0.005, 2)]
    for path in refused:
        with pytest.raises(hybrid.HybridError, match="not followed") as err:
            hybrid.tracing_experiment(path=path, frame=frame, start_point=tuple(start))
        assert "latitude_circle" in str(err.value)  # what works
    backwards = hybrid.LinePath(tuple(start), (0.0, 1.0, 0.0))  # along -t1 = +y: the tip runs the other way
    with pytest.raises(hybrid.HybridError, match="degrees from t1"):
        hybrid.tracing_experiment(surface=hybrid.Plane(start, (0, 0, 1)), path=backwards, frame=frame,
                                  frame_direction=(1.0, 0.0, 0.0), start_point=tuple(start))
    # a path along t1 is followed, a user's own included
    for path in (Latitude(), SPHERE.latitude_circle(90 - math.degrees(0.6))):
        exp = hybrid.tracing_experiment(path=path, frame=frame, start_point=tuple(start))
        r_d, _ = exp.desired_point(0.0)
        assert np.linalg.norm(r_d - start) < 1e-9
    with pytest.raises(hybrid.HybridError, match="a path of one.s own is not written"):
        hybrid.tracing_experiment(path=Latitude(), start_point=tuple(start)).to_dict()
