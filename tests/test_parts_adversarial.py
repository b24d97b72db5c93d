"""Parts at settings the part tests do not take: a torus (a saddle on its inner side), the inside of a bowl
(``flip``), a box with sharp edges, an open curved sheet, a scan with noise and without normals; files in
millimetres with a placement; path tasks, a sweep, the Panda; and input the fit must refuse.

Each surface is checked against something independent of the fit: the shape's own formula (an
:class:`~hybrid.ImplicitSurface`, a :class:`~hybrid.Cylinder`), the same part fitted another way (its file, its
placement, its other side), the Python runner for the compiled loop."""

from __future__ import annotations

import math
import time
import tracemalloc

import numpy as np
import pytest

import hybrid
from hybrid.geometry.parts import MeshSurface, PointCloudSurface

trimesh = pytest.importorskip("trimesh")

CENTRE = np.array([0.5, 0.0, 0.15])
#: the torus: major and minor radius [m], about CENTRE, its axis along base z
MAJOR, MINOR = 0.12, 0.04
#: the bowl: the lower half of a sphere of this radius [m] about BOWL_CENTRE, worked on its inside
BOWL_RADIUS, BOWL_CENTRE = 0.15, CENTRE + (0.0, 0.0, 0.15)
E = (1.0, 0.3, 0.2)  # a frame direction away from every normal the checks meet


def relative(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(a - b) / (np.abs(b).max(axis=0) + 1e-3)))


def assert_same_metrics(got: dict, want: dict) -> None:
    for name, value in want.items():
        assert got[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name


def frame_errors(exact, part, p, v):
    """The largest angle [deg] between the exact and the part's task frames at ``p`` (moving at ``v``), and the
    largest error of the part's rate R' relative to ``|v| / radius`` for each point's radius ``radius``."""
    R, Rd = hybrid.task_frame(exact, p, v, frame_direction=E)
    Rp, Rdp = hybrid.task_frame(part, p, v, frame_direction=E)
    cos = np.clip((np.einsum("nij,nij->n", R, Rp) - 1) / 2, -1.0, 1.0)
    return np.degrees(np.arccos(cos)), np.linalg.norm(Rdp - Rd, axis=(1, 2))


def tangent_velocities(normals, rng, speed=0.1):
    v = np.cross(normals, rng.normal(size=normals.shape))
    return speed * v / np.linalg.norm(v, axis=1, keepdims=True)


def away_from_e(normals):
    """The points whose normal is at least 30 degrees from E (the frame is defined well there)."""
    e = np.array(E) / np.linalg.norm(E)
    return np.linalg.norm(np.cross(normals, e), axis=1) >= 0.5


# ------------------------------------------------------------------------------------------------ the parts


@pytest.fixture(scope="module")
def torus():
    mesh = trimesh.creation.torus(major_radius=MAJOR, minor_radius=MINOR, major_sections=96, minor_sections=32)
    mesh.apply_translation(CENTRE)
    return MeshSurface(mesh.vertices, mesh.faces, spacing=0.008, band=0.024)


@pytest.fixture(scope="module")
def bowl():
    """The lower half of an icosphere (an open mesh, its facets facing out), worked from the inside."""
    ico = trimesh.creation.icosphere(subdivisions=4, radius=BOWL_RADIUS)
    half = trimesh.Trimesh(ico.vertices, ico.faces[ico.triangles_center[:, 2] < 0.0])
    half.remove_unreferenced_vertices()
    half.apply_translation(BOWL_CENTRE)
    return MeshSurface(half.vertices, half.faces, flip=True, spacing=0.01, band=0.03)


@pytest.fixture(scope="module")
def block():
    """A box of 16 x 16 x 10 cm, twelve facets: sharp edges, flat faces."""
    mesh = trimesh.creation.box(extents=(0.16, 0.16, 0.1))
    mesh.apply_translation(CENTRE)
    return MeshSurface(mesh.vertices, mesh.faces, spacing=0.008, band=0.024)


#: the sheet: a patch of a cylinder of radius 0.3 m about an axis along y, 0.2 m wide, its top at z = 0.2 m
SHEET_AXIS, SHEET_RADIUS = (0.5, 0.0, -0.1), 0.3


@pytest.fixture(scope="module")
def sheet():
    """An open curved panel (a single sheet: no inside), facets of 2.2 cm x 6.7 mm."""
    angle, y = np.meshgrid(np.linspace(-0.33, 0.33, 31), np.linspace(-0.1, 0.1, 31), indexing="ij")
    v = np.column_stack([SHEET_AXIS[0] + SHEET_RADIUS * np.sin(angle).ravel(), y.ravel(),
                         SHEET_AXIS[2] + SHEET_RADIUS * np.cos(angle).ravel()])
    k = np.arange(31 * 31).reshape(31, 31)
    a, b, c, d = k[:-1, :-1].ravel(), k[1:, :-1].ravel(), k[1:, 1:].ravel(), k[:-1, 1:].ravel()
    faces = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    return MeshSurface(v, faces, spacing=0.01, band=0.03)


SCAN_CENTRE, SCAN_RADIUS = np.array([0.5, 0.0, 0.2]), 0.15


@pytest.fixture(scope="module")
def scan():
    """The upper part of a sphere scanned from above: 0.3 mm of noise, no normals (estimated, turned to the
    scanner)."""
    rng = np.random.default_rng(3)
    n = rng.normal(size=(20000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    n = n[n[:, 2] > 0.2]
    points = SCAN_CENTRE + SCAN_RADIUS * n + 3e-4 * rng.normal(size=n.shape)
    return PointCloudSurface(points, viewpoint=SCAN_CENTRE + (0.0, 0.0, 1.0), spacing=0.012, band=0.03,
                             smoothing=20.0)


# ----------------------------------------------------------------------------------- against the formulas


def test_a_torus_gives_its_frame_and_curvature_on_both_of_its_sides(torus, rng):
    """A torus's outer side is convex, its inner side a saddle: the frame within 0.3 degrees of the formula's and
    R' within 5 % of |v| / r, the minor radius, everywhere around it."""
    exact = hybrid.ImplicitSurface("sqrt((sqrt((x-a)**2+(y-b)**2)-R)**2+(z-c)**2)-r",
                                   {"a": CENTRE[0], "b": CENTRE[1], "c": CENTRE[2], "R": MAJOR, "r": MINOR})
    u, w = rng.uniform(0, 2 * math.pi, 400), rng.uniform(0, 2 * math.pi, 400)
    normals = np.column_stack([np.cos(u) * np.cos(w), np.sin(u) * np.cos(w), np.sin(w)])
    ring = np.column_stack([np.cos(u), np.sin(u), np.zeros_like(u)])
    p = CENTRE + MAJOR * ring + (MINOR + 0.001) * normals
    keep = away_from_e(normals)
    inner = keep & (np.cos(w) < -0.5)  # the saddle: the side facing the axis
    assert inner.sum() >= 20
    v = tangent_velocities(normals, rng)
    angle, rate = frame_errors(exact, torus, p[keep], v[keep])
    assert angle.max() <= 0.3
    assert (rate / (0.1 / MINOR)).max() <= 0.05


def test_the_inside_of_a_bowl_is_a_part_worked_from_its_other_side(bowl, rng):
    """``flip=True`` on an open hemisphere: phi > 0 inside, the normal towards the centre, the frame within
    0.3 degrees of the concave sphere's formula and R' within 8 % of |v| / R, 4.5 cm and more below the rim."""
    exact = hybrid.ImplicitSurface("R - sqrt((x-a)**2+(y-b)**2+(z-c)**2)", {
        "a": BOWL_CENTRE[0], "b": BOWL_CENTRE[1], "c": BOWL_CENTRE[2], "R": BOWL_RADIUS})
    n = rng.normal(size=(600, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    n = n[n[:, 2] < -0.3]  # 4.5 cm and more below the rim
    inward = -n
    p = BOWL_CENTRE + (BOWL_RADIUS - 0.001) * n
    assert np.all(bowl.evaluate(p)[0] > 0)
    bottom = BOWL_CENTRE - (0.0, 0.0, BOWL_RADIUS - 0.002)
    assert bowl.normal_at(bottom) @ (0.0, 0.0, 1.0) >= math.cos(math.radians(0.1))
    keep = away_from_e(inward)
    angle, rate = frame_errors(exact, bowl, p[keep], tangent_velocities(inward[keep], rng))
    assert angle.max() <= 0.3
    assert (rate / (0.1 / BOWL_RADIUS)).max() <= 0.08


def test_flip_turns_the_fitted_surface_over():
    """The same mesh fitted for either side: phi and its derivatives change sign (within the fit's own error,
    the samples being drawn anew), its zero set stays."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=150.0)  # millimetres
    out = MeshSurface(mesh.vertices, mesh.faces, scale=1e-3, spacing=0.02, band=0.04)
    inside = MeshSurface(mesh.vertices, mesh.faces, scale=1e-3, spacing=0.02, band=0.04, flip=True)
    rng = np.random.default_rng(0)
    n = rng.normal(size=(500, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    p = (0.15 + rng.uniform(-0.02, 0.02, (500, 1))) * n
    (phi, g, H), (phi_f, g_f, H_f) = out.evaluate(p), inside.evaluate(p)
    assert np.abs(phi + phi_f).max() <= 5e-4
    assert np.abs(g + g_f).max() <= 0.02
    assert np.abs(H + H_f).max() <= 0.1 * np.abs(H).max()
    off = np.linalg.norm(p, axis=1) - 0.15
    clear = np.abs(off) >= 0.002  # farther from the sphere than the fit's error: on the side the facets say
    assert (np.sign(phi[clear]) == np.sign(off[clear])).all() and (np.sign(phi_f[clear]) == -np.sign(off[clear])).all()


def test_a_box_keeps_its_flat_faces_and_rounds_its_edges(block):
    """On a box of twelve facets (20 cells across at 8 mm): the top face's middle (8 cells and more from its
    edges) within 0.1 mm of its plane, the normal within 0.5 degrees, the curvature below 3 1/m (the rounded
    edges' pull reaches across the face: 1.6 1/m and 0.23 degrees measured there, 4.4 1/m and 1.2 degrees 4 cells
    from the edges); the edge itself rounded (the normal turned by tens of degrees); the report does not hide
    the corners."""
    top = CENTRE[2] + 0.05
    grid = np.linspace(-0.016, 0.016, 9)
    x, y = np.meshgrid(grid, grid)
    middle = CENTRE + np.column_stack([x.ravel(), y.ravel(), np.full(x.size, 0.051)])
    phi, g, H = block.evaluate(middle)
    assert np.abs(phi - 0.001).max() <= 1e-4
    assert np.degrees(np.arccos(g[:, 2] / np.linalg.norm(g, axis=1))).max() <= 0.5
    assert np.abs(H).max() <= 3.0
    edge = block.evaluate([[CENTRE[0] + 0.08, 0.0, top + 0.001]])[1][0]
    assert np.degrees(np.arccos(edge[2] / np.linalg.norm(edge))) >= 20.0
    assert block.fit.distance_max_m >= 1e-3


def test_an_open_sheet_follows_its_cylinder(sheet, rng):
    """An open panel (one sheet, its boundary free): the surface within 0.1 mm of the cylinder it was cut from
    and the frame within 0.2 degrees, R' within 5 % of |v| / R, 3 cm and more from its free edges."""
    exact = hybrid.Cylinder(SHEET_AXIS, (0.0, 1.0, 0.0), SHEET_RADIUS)
    angle, y = rng.uniform(-0.23, 0.23, 300), rng.uniform(-0.07, 0.07, 300)
    normals = np.column_stack([np.sin(angle), np.zeros_like(angle), np.cos(angle)])
    on = np.array(SHEET_AXIS) + SHEET_RADIUS * normals + np.outer(y, (0.0, 1.0, 0.0))
    assert np.abs(sheet.evaluate(on)[0]).max() <= 1e-4
    p = on + 0.001 * normals
    keep = away_from_e(normals)
    error, rate = frame_errors(exact, sheet, p[keep], tangent_velocities(normals[keep], rng))
    assert error.max() <= 0.2
    assert (rate / (0.1 / SHEET_RADIUS)).max() <= 0.05


def test_a_noisy_scan_without_normals_is_oriented_and_smoothed(scan, rng):
    """0.3 mm of noise, the normals estimated and turned towards the scanner, the second differences weighted
    20: every estimated normal the scanner sees at less than 80 degrees from it outwards (at a grazing view the
    noise can turn one over: 23 of 8154 at the cloud's rim, all beyond 84 degrees); the frame within 1 degree of
    the sphere's, R' within 35 % of |v| / R (27 % measured; 67 % at the default weight), the surface within 1 mm
    of the sphere (the weight shrinks it: 0.7 mm measured)."""
    sphere = hybrid.Sphere(tuple(SCAN_CENTRE), SCAN_RADIUS)
    outward = (scan.points - SCAN_CENTRE) / np.linalg.norm(scan.points - SCAN_CENTRE, axis=1, keepdims=True)
    sight = SCAN_CENTRE + (0.0, 0.0, 1.0) - scan.points
    seen = np.einsum("ij,ij->i", outward, sight / np.linalg.norm(sight, axis=1, keepdims=True)) >= math.cos(
        math.radians(80.0))
    assert seen.mean() >= 0.8
    assert np.all(np.einsum("ij,ij->i", scan.normals[seen], outward[seen]) > math.cos(math.radians(30.0)))
    assert np.mean(np.einsum("ij,ij->i", scan.normals, outward) > 0) >= 0.99
    n = rng.normal(size=(400, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    n = n[n[:, 2] > 0.5]
    assert np.abs(scan.evaluate(SCAN_CENTRE + SCAN_RADIUS * n)[0]).max() <= 1e-3
    keep = away_from_e(n)
    p = SCAN_CENTRE + (SCAN_RADIUS + 0.001) * n[keep]
    angle, rate = frame_errors(sphere, scan, p, tangent_velocities(n[keep], rng))
    assert angle.max() <= 1.0
    assert (rate / (0.1 / SCAN_RADIUS)).max() <= 0.35


# ------------------------------------------------------------------------------------- files and placement


@pytest.mark.parametrize("suffix", ["stl", "obj", "ply"])
def test_a_file_in_millimetres_placed_is_the_part_its_arrays_give(suffix, tmp_path):
    """A mesh in millimetres written by trimesh (STL and PLY hold single precision), read with ``scale`` and
    ``transform``: the same surface as the arrays it was written from, within the file's rounding (1e-8 m)."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=150.0)
    place = trimesh.transformations.rotation_matrix(0.7, [1.0, 2.0, 3.0])
    place[:3, 3] = (0.5, 0.0, 0.2)
    settings = dict(transform=place, scale=1e-3, spacing=0.02, band=0.04)
    arrays = MeshSurface(mesh.vertices, mesh.faces, **settings)
    path = tmp_path / f"part.{suffix}"
    mesh.export(path)
    read = MeshSurface.from_file(path, **settings)
    assert len(read.faces) == len(mesh.faces)
    rng = np.random.default_rng(1)
    n = rng.normal(size=(300, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    p = np.array([0.5, 0.0, 0.2]) + (0.15 + rng.uniform(-0.02, 0.02, (300, 1))) * n
    (phi, g, _), (phi_r, g_r, _) = arrays.evaluate(p), read.evaluate(p)
    assert np.abs(phi - phi_r).max() <= 1e-8
    assert np.abs(g - g_r).max() <= 1e-6


def test_a_placed_part_is_the_part_moved():
    """A part placed by a rotation and a translation: phi at the moved points is phi of the unmoved part at the
    points (within 0.05 mm: the grid stays along the base axes) and its gradient turns with it."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=150.0)
    here = MeshSurface(mesh.vertices, mesh.faces, scale=1e-3, spacing=0.02, band=0.04)
    T = trimesh.transformations.rotation_matrix(0.7, [1.0, 2.0, 3.0])
    T[:3, 3] = (0.5, -0.1, 0.2)
    there = MeshSurface(mesh.vertices, mesh.faces, transform=T, scale=1e-3, spacing=0.02, band=0.04)
    rng = np.random.default_rng(2)
    n = rng.normal(size=(300, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    p = (0.15 + rng.uniform(-0.02, 0.02, (300, 1))) * n
    (phi, g, _), (phi_t, g_t, _) = here.evaluate(p), there.evaluate(p @ T[:3, :3].T + T[:3, 3])
    assert np.abs(phi - phi_t).max() <= 5e-5
    assert np.abs(g @ T[:3, :3].T - g_t).max() <= 0.01


# ------------------------------------------------------------------------------------------- closed loops


def test_parts_of_every_kind_side_by_side_in_c_equal_their_python_runs(torus, bowl, scan):
    """A torus, the inside of a bowl and a noisy scan as three lanes of one compiled loop (each its own grid):
    each lane's run equals its Python run (states within 1e-8, metrics within 1e-6), the force held."""
    from hybrid.simulation import closed_loop

    # (15 N on the torus: 20 N would press the arm tip 20 mm into its tube of 4 cm's radius, past half the way to
    # its middle, which is refused)
    exps = [hybrid.tracing_experiment(surface=torus, frame_direction=(1.0, 0.0, 0.0), duration=0.6, F_d=15.0,
                                      start_point=tuple(torus.project(CENTRE + (MAJOR, 0.0, MINOR + 0.005)))),
            hybrid.tracing_experiment(surface=bowl, frame_direction=(1.0, 0.0, 0.0), duration=0.6,
                                      start_point=tuple(bowl.project(BOWL_CENTRE + (0.03, 0.0, -0.14)))),
            hybrid.tracing_experiment(surface=scan, duration=0.6,
                                      start_point=tuple(scan.project((0.5, -0.05, 0.345))))]
    prepared = [closed_loop.prepare(e) for e in exps]
    assert all(p is not None for p in prepared)
    assert prepared[0].loop is prepared[1].loop is prepared[2].loop
    for exp, got in zip(exps, closed_loop.run(prepared, record=True)):
        python = hybrid.simulate(exp, compiled=False)
        assert got.status == 0
        assert relative(got.states, python.state) < 1e-8
        assert_same_metrics(got.metrics, python.metrics)
        assert python.metrics["contact_losses"] == 0
        assert abs(python.metrics["steady_state_force_error_N"]) <= 1.0


def test_path_tasks_on_a_torus_and_across_a_box(torus, block):
    """A path through waypoints around the torus's top and a raster across the box's top face: compiled equals
    Python, the tip on the path within a millimetre, the path run to its end."""
    ring = [torus.project(CENTRE + (MAJOR * math.cos(a), MAJOR * math.sin(a), MINOR + 0.005))
            for a in np.radians([-20.0, 0.0, 25.0, 45.0])]
    paths = [(torus, hybrid.WaypointPath(torus, ring)),
             (block, hybrid.RasterPath(block, block.project(CENTRE + (-0.03, 0.03, 0.052)), (1.0, 0.0, 0.0), 0.06,
                                       0.015, 3))]
    for surface, path in paths:
        task = hybrid.PathTask(path, speed=0.08, force=10.0, retreat_distance=0.01)
        exp = hybrid.tracing_experiment(surface=surface, path_task=task, duration=3.6)
        compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
        # (from rest on a flat face the sensor tip's slide starts in the friction's steep part: the runners'
        # rounding differs there by up to 1e-7 of that column's range, as it does on an analytic plane)
        assert relative(compiled.state, python.state) < 1e-6
        assert_same_metrics(compiled.metrics, python.metrics)
        m = python.metrics
        assert m["path_error_max_m"] <= 1e-3 and m["path_contact_losses"] == 0
        assert m["path_travelled_m"] == pytest.approx(path.length, abs=2e-3)
        assert math.isfinite(m["path_time_s"])


def test_running_off_an_open_sheets_free_edge_stops_both_runners_alike(sheet):
    """Along the sheet towards its free edge at y = -0.1 m: the surface goes on a little beyond it (the fit's
    band), then the tip leaves the band and both runners stop at the same sample with the same message."""
    exp = hybrid.tracing_experiment(surface=sheet, start_point=tuple(sheet.project((0.5, 0.0, 0.201))),
                                    frame_direction=(1.0, 0.0, 0.0), duration=1.0, speed_reference=0.15)
    errors = []
    for compiled in (True, False):
        with pytest.raises(hybrid.SimulationError) as info:
            hybrid.simulate(exp, compiled=compiled)
        errors.append(info.value)
    assert errors[0].time == errors[1].time
    assert str(errors[0]).splitlines()[:2] == str(errors[1]).splitlines()[:2]
    assert "band" in str(errors[0])


def test_a_friction_sweep_on_a_part_gives_each_runs_own_metrics(bowl):
    """``hybrid.sweep`` over the contact's friction on a part (in this process): each row the metrics of that
    run made alone by the Python runner. (Friction 0.8 is left out: there the sensor tip's cross-track velocity
    chatters and the runners part by millimetres per second in it, on an analytic sphere too.)"""
    import dataclasses

    base = hybrid.tracing_experiment(surface=bowl, frame_direction=(1.0, 0.0, 0.0), duration=0.4,
                                     start_point=tuple(bowl.project(BOWL_CENTRE + (0.03, 0.0, -0.14))))
    rows = hybrid.sweep(base, {"contact.friction": [0.0, 0.2, 0.5]}, workers=1)
    assert rows["status"].tolist() == ["ok"] * 3
    for _, row in rows.iterrows():
        alone = hybrid.simulate(dataclasses.replace(base, contact=dataclasses.replace(
            base.contact, friction=row["contact.friction"])), compiled=False).metrics
        for name in ("rms_force_error_N", "rms_speed_error_m_per_s", "steady_state_force_error_N"):
            assert row[name] == pytest.approx(alone[name], rel=1e-6, abs=1e-10), name


def test_the_panda_on_a_pillars_mesh_runs_as_on_the_pillar():
    """The Panda experiment on the mesh of its own pillar (128 sides, fitted at 2 cm): the cylinder's force and
    speed errors within 1 %, the sensor tip's path within 0.3 mm of the cylinder's run (the fit's own error at
    2 cm: 0.12 mm); compiled equals Python."""
    pillar = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)
    mesh = trimesh.creation.cylinder(radius=0.25, height=0.3, sections=128)
    mesh.apply_translation((0.67, 0.0, 0.78))
    part = MeshSurface(mesh.vertices, mesh.faces, spacing=0.02, band=0.04)
    start = tuple(pillar.project((0.42, 0.0, 0.78)).tolist())
    runs = {}
    for surface in (pillar, part):
        exp = hybrid.panda_experiment(surface=surface, start_point=start, path=pillar.circle_at(start), duration=1.0)
        runs[surface.kind] = hybrid.simulate(exp)
    exact, mesh_run = runs["cylinder"], runs["mesh"]
    for name in ("rms_force_error_N", "rms_speed_error_m_per_s"):
        assert mesh_run.metrics[name] == pytest.approx(exact.metrics[name], rel=0.01), name
    assert mesh_run.metrics["contact_losses"] == 0
    tip = [r.state[:, [r.record["state"].index(c) for c in ("s_x", "s_y", "s_z")]] for r in (exact, mesh_run)]
    assert np.abs(tip[0] - tip[1]).max() <= 3e-4
    python = hybrid.simulate(mesh_run.experiment, compiled=False)
    assert relative(mesh_run.state, python.state) < 1e-8


def test_a_path_task_on_a_part_is_saved_and_read_with_its_part(tmp_path):
    """A run with a waypoint path on a part, saved and read in this process: the experiment's part and the path's
    part fitted again to the same surfaces, the states as saved, the run made again the same."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=0.15)
    mesh.apply_translation(SCAN_CENTRE)
    part = MeshSurface(mesh.vertices, mesh.faces, spacing=0.02, band=0.03)
    points = [part.project(p) for p in ((0.47, -0.04, 0.345), (0.5, 0.0, 0.352), (0.54, 0.03, 0.345))]
    task = hybrid.PathTask(hybrid.WaypointPath(part, points), speed=0.08, force=10.0)
    res = hybrid.simulate(hybrid.tracing_experiment(surface=part, path_task=task, duration=0.5))
    res.save(tmp_path / "run.npz")
    back = hybrid.SimulationResult.load(tmp_path / "run.npz")
    assert back.experiment.surface == part
    assert back.experiment.path_task.path.surface == part
    np.testing.assert_array_equal(back.state, res.state)
    assert_same_metrics(hybrid.simulate(back.experiment).metrics, res.metrics)


# ---------------------------------------------------------------------------------------------- refusals

CUBE_V = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * 0.05
CUBE_F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],
                   [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])


def test_a_grid_of_gigabytes_is_refused_before_it_is_allocated():
    """A 17 cm part at a tenth of a millimetre (4e9 coefficients), or with a band of metres: refused within a
    second, having allocated less than 200 MB, with the spacing that fits."""
    for settings in (dict(spacing=1e-4), dict(spacing=0.01, band=100.0)):
        tracemalloc.start()
        start = time.perf_counter()
        try:
            with pytest.raises(hybrid.HybridError, match=r"coefficients .*give spacing >="):
                MeshSurface(CUBE_V, CUBE_F, **settings)
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
        assert time.perf_counter() - start <= 2.0
        assert peak <= 200e6


@pytest.mark.parametrize("settings, message", [
    (dict(spacing="0.01"), "spacing must be a real number"),
    (dict(spacing=float("nan")), "spacing is nan"),
    (dict(spacing=-0.01), "length of at least"),
    (dict(spacing=0.01, band=0.0), "band = 0"),
    (dict(spacing=0.01, smoothing=-1.0), "weight >= 0"),
    (dict(spacing=0.01, smoothing=None), "smoothing must be a real number"),
    (dict(spacing=0.01, scale=0.0), "metres per mesh unit"),
    (dict(spacing=0.01, scale=1000.0), "give scale"),
    (dict(spacing=0.01, transform=np.diag([1.0, 1.0, -1.0, 1.0])), "rigid motion"),
    (dict(spacing=0.01, transform=np.vstack([np.eye(4)[:3], [0.0, 0.0, 1.0, 1.0]])), "rigid motion"),
    (dict(spacing=0.01, transform=np.eye(3)), "4 x 4"),
    (dict(spacing=0.01, transform="identity"), "4 x 4"),
])
def test_settings_of_a_mesh_are_refused_with_the_fix(settings, message):
    with pytest.raises(hybrid.HybridError, match=message):
        MeshSurface(CUBE_V, CUBE_F, **settings)


@pytest.mark.parametrize("faces, message", [
    (CUBE_F + 0.5, "whole numbers"),
    (CUBE_F - 1, "indices from 0 to 7"),
    (CUBE_F.ravel(), "triangles"),
    ([[0, 1, 2], [0, 1]], "arrays of real numbers"),
])
def test_faces_that_are_not_triangles_of_indices_are_refused(faces, message):
    with pytest.raises(hybrid.HybridError, match=message):
        MeshSurface(CUBE_V, faces, spacing=0.01)


def test_files_that_are_not_a_parts_mesh_are_refused(tmp_path):
    """Each with a HybridError naming the file and what is wrong: empty, a point cloud, a directory, a header
    promising 1e11 vertices, two boxes sharing an edge, a facet of no area, a facet turned over."""
    box = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    (tmp_path / "empty.stl").write_bytes(b"")
    trimesh.PointCloud(np.random.default_rng(0).normal(size=(100, 3)) * 0.1).export(tmp_path / "cloud.ply")
    (tmp_path / "folder.stl").mkdir()
    (tmp_path / "huge.ply").write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 99999999999\n"
                                        b"property float x\nend_header\n" + bytes(100))
    trimesh.util.concatenate([box, box.copy().apply_translation([0.1, 0.1, 0.0])]).export(tmp_path / "two.stl")

    def obj(name, faces):
        lines = [f"v {x} {y} {z}" for x, y, z in box.vertices] + [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
        (tmp_path / name).write_text("\n".join(lines) + "\n")

    obj("flat.obj", np.vstack([box.faces, [[0, 0, 1]]]))
    turned = box.faces.copy()
    turned[0] = turned[0, ::-1]
    obj("turned.obj", turned)
    for name, message in [("empty.stl", "no triangles"), ("cloud.ply", "no triangles"), ("folder.stl", "folder.stl"),
                          ("huge.ply", "huge.ply"), ("two.stl", "not a manifold"), ("flat.obj", "no area"),
                          ("turned.obj", "inconsistently oriented")]:
        with pytest.raises(hybrid.HybridError, match=message):
            MeshSurface.from_file(tmp_path / name, spacing=0.01)


@pytest.mark.parametrize("make, message", [
    (lambda p, n: PointCloudSurface(p * 1000.0, n), "give its points in metres"),
    (lambda p, n: PointCloudSurface(np.vstack([p, [[5.0, 5.0, 5.0]]]), np.vstack([n, [[0.0, 0.0, 1.0]]]),
                                    spacing=0.01), "give spacing >="),
    (lambda p, n: PointCloudSurface(np.zeros((500, 3)), np.tile([0.0, 0.0, 1.0], (500, 1))), "0 m across"),
    (lambda p, n: PointCloudSurface(p, n[:10]), "one per point"),
    (lambda p, n: PointCloudSurface(p, 0 * n), "no length"),
    (lambda p, n: PointCloudSurface(p, viewpoint=(0.0, 0.0, 1.0), neighbours=3), "whole number >= 6"),
    (lambda p, n: PointCloudSurface(p.ravel(), n.ravel()), "N x 3"),
])
def test_clouds_the_fit_cannot_use_are_refused(make, message):
    rng = np.random.default_rng(0)
    n = rng.normal(size=(3000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    with pytest.raises(hybrid.HybridError, match=message):
        make(0.1 * n, n)


def test_a_point_off_the_part_is_refused_by_everything_that_reads_the_part(torus):
    """The torus's centre (on its axis, 8 cm from the part, beyond the band): the normal, the task frame, a path
    and a run refuse it with a HybridError; the projection and the expansion say None and NaN."""
    far = CENTRE + (0.0, 0.0, 0.0)
    with pytest.raises(hybrid.HybridError, match="beyond the fitted band"):
        torus.normal_at(far)
    with pytest.raises(hybrid.TaskFrameError):
        hybrid.task_frame(torus, far, (0.1, 0.0, 0.0), frame_direction=(1.0, 0.0, 0.0))
    with pytest.raises(hybrid.HybridError, match="domain"):
        hybrid.WaypointPath(torus, [torus.project(CENTRE + (MAJOR, 0.0, MINOR)), far])
    with pytest.raises(hybrid.HybridError, match="beyond the fitted band"):
        hybrid.simulate(hybrid.tracing_experiment(surface=torus, duration=0.05, start_point=tuple(far)))
    assert torus.project(far) is None
    assert np.isnan(torus.parameters_at(far)).all()


def test_a_file_whose_reader_is_missing_names_the_package(tmp_path, monkeypatch):
    """A format trimesh reads through another package (COLLADA's .dae: pycollada) where that package is missing: the
    refusal names the package to install (trimesh's own words), not only that the file is not a mesh."""
    box = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    box.export(tmp_path / "part.stl")

    def without_reader(*args, **kwargs):
        raise ImportError("missing `pip install pycollada`")

    monkeypatch.setattr(trimesh, "load", without_reader)
    with pytest.raises(hybrid.HybridError, match=r"part.stl needs a package .*pip install pycollada.*install it"):
        MeshSurface.from_file(tmp_path / "part.stl", spacing=0.01)
    monkeypatch.undo()
    assert len(MeshSurface.from_file(tmp_path / "part.stl", spacing=0.01).faces) == 12
