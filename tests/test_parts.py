"""Parts as surfaces (hybrid.MeshSurface, hybrid.PointCloudSurface): a sphere and a cylinder as meshes and as a
point cloud against their formulas, the fit's report against trimesh's own closest points, the surface's
continuity across the facets' edges, the generated evaluator against NumPy, the UR5 in closed loop on a mesh
against the same run on the formula, and the refusals."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import hybrid
from hybrid.geometry.parts import MeshSurface, PointCloudSurface

trimesh = pytest.importorskip("trimesh")

CENTRE, RADIUS = np.array([0.5, 0.0, 0.2]), 0.15
SPHERE = hybrid.Sphere(tuple(CENTRE), RADIUS)
AXIS_POINT, AXIS, CYLINDER_RADIUS = np.array([0.5, 0.0, 0.2]), np.array([0.0, 1.0, 0.0]), 0.1
CYLINDER = hybrid.Cylinder(tuple(AXIS_POINT), tuple(AXIS), CYLINDER_RADIUS)


def sphere_mesh():
    """An icosphere of facets about 5.7 mm across (20,480 of them), about the sphere's centre."""
    mesh = trimesh.creation.icosphere(subdivisions=5, radius=RADIUS)
    mesh.apply_translation(CENTRE)
    return mesh


@pytest.fixture(scope="module")
def mesh_sphere():
    mesh = sphere_mesh()
    return mesh, MeshSurface(mesh.vertices, mesh.faces, spacing=0.006)


@pytest.fixture(scope="module")
def mesh_cylinder():
    """A cylinder of 110 sides (5.7 mm facets) and 0.3 m long along base y, its caps on."""
    mesh = trimesh.creation.cylinder(radius=CYLINDER_RADIUS, height=0.3, sections=110)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
    mesh.apply_translation(AXIS_POINT)
    return mesh, MeshSurface(mesh.vertices, mesh.faces, spacing=0.006)


@pytest.fixture(scope="module")
def cloud_sphere():
    rng = np.random.default_rng(5)
    n = rng.normal(size=(30000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    return PointCloudSurface(CENTRE + RADIUS * n, n, spacing=0.006)


def contacts(surface, rng, count: int = 200, offset: float = 0.001):
    """Points ``offset`` off ``surface`` (a Sphere, or a Cylinder at least 7.5 cm, 12 cells, from the mesh's rims:
    the fit rounds a machined edge, and its smoothing spreads that over a few cells) and tangent velocities."""
    if isinstance(surface, hybrid.Sphere):
        n = rng.normal(size=(count, 3))
        n /= np.linalg.norm(n, axis=1, keepdims=True)
        p = CENTRE + (RADIUS + offset) * n
    else:
        angle, along = rng.uniform(0, 2 * math.pi, count), rng.uniform(-0.075, 0.075, count)
        n = np.column_stack([np.cos(angle), np.zeros(count), np.sin(angle)])
        p = AXIS_POINT + along[:, None] * AXIS + (CYLINDER_RADIUS + offset) * n
    v = np.cross(n, rng.normal(size=(count, 3)))
    return p, 0.1 * v / np.linalg.norm(v, axis=1, keepdims=True)


def frame_errors(exact, part, rng):
    """The largest angle [deg] between the frames, and the largest error of R' relative to the rate the shape's
    curvature gives (``|v| / radius``: on a cylinder moving along its axis R' is 0)."""
    e = np.array([1.0, 0.3, 0.2]) / np.linalg.norm([1.0, 0.3, 0.2])
    p, v = contacts(exact, rng, count=400)
    # where the frame is well defined: the normal at least 30 degrees from e (t1 = e x n / |e x n|)
    normals = np.array([exact.normal_at(x) for x in p])
    keep = np.linalg.norm(np.cross(normals, e), axis=1) >= 0.5
    p, v = p[keep], v[keep]
    R, Rd = hybrid.task_frame(exact, p, v, frame_direction=tuple(e))
    Rp, Rdp = hybrid.task_frame(part, p, v, frame_direction=tuple(e))
    cos = np.clip((np.einsum("nij,nij->n", R, Rp) - 1) / 2, -1.0, 1.0)
    radius = RADIUS if isinstance(exact, hybrid.Sphere) else CYLINDER_RADIUS
    rate = np.linalg.norm(Rdp - Rd, axis=(1, 2)) / (np.linalg.norm(v, axis=1) / radius)
    return float(np.degrees(np.arccos(cos)).max()), float(rate.max())


@pytest.mark.parametrize("which", ["mesh sphere", "mesh cylinder", "cloud sphere"])
def test_a_part_gives_its_shapes_frame_and_curvature(which, request, rng):
    """The task frame within 0.5 degrees of the formula's, and its rate R' (the curvature term) within 5 %."""
    part = {"mesh sphere": lambda: request.getfixturevalue("mesh_sphere")[1],
            "mesh cylinder": lambda: request.getfixturevalue("mesh_cylinder")[1],
            "cloud sphere": lambda: request.getfixturevalue("cloud_sphere")}[which]()
    exact = CYLINDER if "cylinder" in which else SPHERE
    angle, rate = frame_errors(exact, part, rng)
    assert angle <= 0.5
    assert rate <= 0.05


def test_a_cloud_without_normals_is_oriented_by_its_viewpoint(rng):
    n = rng.normal(size=(20000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    # a cloud of the upper half, seen from above (its estimated normals turned towards the scanner)
    top = n[n[:, 2] > 0.2]
    part = PointCloudSurface(CENTRE + RADIUS * top, viewpoint=CENTRE + [0.0, 0.0, 1.0], spacing=0.008)
    p = CENTRE + (RADIUS + 0.002) * np.array([0.3, 0.1, 0.95]) / np.linalg.norm([0.3, 0.1, 0.95])
    assert part.normal_at(p) @ SPHERE.normal_at(p) >= math.cos(math.radians(0.5))
    assert part.fit.normal_angle_rms_deg <= 1.0


def test_the_fits_report_agrees_with_trimeshs_closest_points(mesh_sphere, rng):
    """On 10^4 random points near the part, |phi| against trimesh's own distance to the mesh: within the fit's
    reported distance error on the part, and a tenth of a millimetre within the band."""
    mesh, part = mesh_sphere
    n = rng.normal(size=(10000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    points = CENTRE + (RADIUS + rng.uniform(-0.01, 0.01, (10000, 1))) * n
    _, distance, _ = trimesh.proximity.closest_point(mesh, points)
    phi = part.evaluate(points)[0]
    assert np.isfinite(phi).all()
    error = np.abs(np.abs(phi) - distance)
    assert error.max() <= 1e-4
    on = np.abs(distance) < 1e-3  # near the mesh: the reported error holds
    assert error[on].max() <= part.fit.distance_max_m + 2e-5
    # the report itself: at the mesh's vertices and centroids, |phi| / |grad phi| against 0 (they lie on it)
    centroids = mesh.triangles_center
    phi_c, grad_c, _ = part.evaluate(centroids)
    assert np.max(np.abs(phi_c) / np.linalg.norm(grad_c, axis=1)) <= part.fit.distance_max_m * (1 + 1e-9)


def test_the_surface_is_smooth_across_the_facets_edges(mesh_sphere):
    """Across each edge of 500 facets, the gradient's central difference equals the Hessian's product with the step
    (no jump of the normal at an edge: the fit is continuous to the second derivative)."""
    mesh, part = mesh_sphere
    edges = mesh.edges_unique[:500]
    a, b = mesh.vertices[edges[:, 0]], mesh.vertices[edges[:, 1]]
    mid = (a + b) / 2
    normal = (mid - CENTRE) / np.linalg.norm(mid - CENTRE, axis=1, keepdims=True)
    across = np.cross(normal, b - a)
    across /= np.linalg.norm(across, axis=1, keepdims=True)
    step = 1e-5
    _, g_plus, _ = part.evaluate(mid + step * across)
    _, g_minus, _ = part.evaluate(mid - step * across)
    _, _, H = part.evaluate(mid)
    difference = (g_plus - g_minus) / (2 * step)
    expected = np.einsum("nij,nj->ni", H, across)
    # the third derivative (piecewise continuous) bounds the difference's error: step * |H| / spacing
    bound = step * np.abs(H).max() / part.spacing * 10
    assert np.abs(difference - expected).max() <= bound


def test_the_generated_evaluator_equals_numpy(mesh_sphere, rng):
    _, part = mesh_sphere
    n = rng.normal(size=(300, 3))
    points = CENTRE + (RADIUS + rng.uniform(-0.02, 0.02, (300, 1))) * n / np.linalg.norm(n, axis=1, keepdims=True)
    phi, grad, hess = part.evaluate(points)
    for p, f, g, h in zip(points, phi, grad, hess):
        got = part.parameters_at(p)
        want = np.array([*p, f, *g, h[0, 0], h[0, 1], h[0, 2], h[1, 1], h[1, 2], h[2, 2]])
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)
    assert np.isnan(part.parameters_at(CENTRE)).all()  # the centre: beyond the band


def test_the_evaluator_gives_the_same_numbers_on_vectors_and_without(mesh_sphere, rng, tmp_path):
    """hybrid_part.h built on this machine's vectors, on SSE2's (pairs) and as plain C (HYBRID_PART_PLAIN_C, not
    optimised), each strict C99: the same status and numbers to the bit as the runtime's build, at points on the
    band, beyond it, off the grid and not finite."""
    import ctypes
    import shutil
    import subprocess

    from hybrid.native import loader

    if shutil.which("gcc") is None:
        pytest.skip("needs gcc")
    _, part = mesh_sphere
    grid, coefficients = (np.ascontiguousarray(a, float) for a in part.data())
    n = rng.normal(size=(3000, 3))
    points = CENTRE + rng.uniform(0.0, 0.4, (3000, 1)) * n / np.linalg.norm(n, axis=1, keepdims=True)
    points[:3] = [np.nan, 0.0, 0.0], [0.0, np.inf, 0.0], [0.5, 0.0, 0.35]
    module = loader.part_evaluator()
    runtime, runtime_status = np.zeros((len(points), 13)), np.zeros(len(points), np.int32)
    for i, p in enumerate(points):
        runtime_status[i] = module.lib.hybrid_part_expansion_entry(
            *(module.ffi.from_buffer("double[]", a) for a in (grid, coefficients, np.ascontiguousarray(p), runtime[i])))
    assert 500 < np.sum(runtime_status == 0) < len(points) - 500  # many points on the band, many not
    source = tmp_path / "each.c"
    source.write_text('#include "hybrid_part.h"\nvoid each(const double *g, const double *c, const double *p, '
                      'double *out, int *status, int n) {\n    int i;\n    for (i = 0; i < n; ++i) '
                      'status[i] = hybrid_part_expansion(g, c, p + 3 * i, out + 13 * i);\n}\n')
    pointer = ctypes.POINTER(ctypes.c_double)
    for name, flags in {"native": ["-O3", "-march=native"], "sse2": ["-O2"],
                        "plain": ["-O0", "-DHYBRID_PART_PLAIN_C"]}.items():
        library = tmp_path / f"{name}.so"
        done = subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", *flags, "-shared",
                               "-fPIC", f"-I{loader.source_dir()}", str(source), "-o", str(library), "-lm"],
                              capture_output=True, text=True)
        assert done.returncode == 0 and not done.stderr, done.stderr
        out, status = np.zeros((len(points), 13)), np.zeros(len(points), np.int32)
        ctypes.CDLL(str(library)).each(*(a.ctypes.data_as(pointer) for a in (grid, coefficients, points, out)),
                                       status.ctypes.data_as(ctypes.POINTER(ctypes.c_int)), ctypes.c_int(len(points)))
        np.testing.assert_array_equal(status, runtime_status, err_msg=name)
        np.testing.assert_array_equal(out.view(np.uint64), runtime.view(np.uint64), err_msg=name)


def test_the_ur5_on_a_mesh_runs_as_on_the_formula(mesh_sphere):
    """The UR5 tracing the sphere, then the same run on the sphere's mesh: the normal force's RMS error within 5 %
    of the formula's run, the tip's path alike."""
    _, part = mesh_sphere
    start = SPHERE.project(np.array([0.5, -0.05, 0.35]))
    runs = [hybrid.simulate(hybrid.tracing_experiment(surface=s, duration=1.5, start_point=tuple(start)))
            for s in (SPHERE, part)]
    exact, mesh = (r.metrics for r in runs)
    assert mesh["rms_force_error_N"] == pytest.approx(exact["rms_force_error_N"], rel=0.05)
    assert mesh["contact_losses"] == 0
    assert abs(mesh["steady_state_force_error_N"]) <= 0.05
    tip = [r.outputs[:, [r.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]] for r in runs]
    assert np.abs(tip[0] - tip[1]).max() <= 1e-3


def test_the_estimator_on_a_part_compares_as_on_the_formula(mesh_sphere):
    """A controller estimating the surface (EstimatedSurface) while the plant's is the sphere's mesh: the
    estimate's angle to the sphere's own normal (the formula, not the fit) at the sensor tip, the result's
    comparison against the part's normal and the force error all as in the run on the formula."""
    _, part = mesh_sphere
    start = SPHERE.project(np.array([0.5, -0.05, 0.35]))
    runs = [hybrid.simulate(hybrid.tracing_experiment(surface=s, duration=1.5, start_point=tuple(start),
                                                      controller_surface=hybrid.EstimatedSurface()))
            for s in (SPHERE, part)]
    exact, mesh = runs
    columns = [mesh.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]
    tip = mesh.outputs[::mesh.experiment.steps_per_sample][:mesh.experiment.n_samples, columns]
    formula = np.array([SPHERE.normal_at(p) for p in tip])
    against_formula = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", mesh.normal_estimate, formula), -1, 1)))
    late = mesh.sample_t >= 0.5  # after the first touch has settled, as the metrics take it
    # the part's normal is within the fit's 0.2 degrees of the formula's: the comparisons agree to that
    assert np.abs(against_formula - mesh.normal_angle_error_deg)[late].max() <= 0.2
    assert np.abs(mesh.normal_angle_error_deg - exact.normal_angle_error_deg)[late].max() <= 0.2
    for name in ("normal_angle_error_deg", "max_normal_angle_error_deg"):
        assert mesh.metrics[name] == pytest.approx(exact.metrics[name], abs=0.1), name
    assert mesh.metrics["rms_force_error_N"] == pytest.approx(exact.metrics["rms_force_error_N"], rel=0.05)


# ------------------------------------------------------------------------------------------ bad input

CUBE_V = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * 0.05
CUBE_F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],
                   [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])


@pytest.mark.parametrize("vertices, faces, message", [
    (CUBE_V, np.empty((0, 3), int), "no facets"),
    (np.where(np.arange(24).reshape(8, 3) == 4, np.nan, CUBE_V), CUBE_F, "finite"),
    (CUBE_V, np.vstack([CUBE_F, [[0, 1, 3]]]), "not a manifold"),
    (CUBE_V, np.vstack([CUBE_F[:-1], CUBE_F[-1:, ::-1]]), "inconsistently oriented"),
    (CUBE_V, np.vstack([CUBE_F, [[0, 0, 1]]]), "no area"),
    (CUBE_V * 1000, CUBE_F, "scale"),
    (CUBE_V, CUBE_F + 20, "vertex"),
])
def test_bad_meshes_are_refused(vertices, faces, message):
    with pytest.raises(hybrid.HybridError, match=message):
        MeshSurface(vertices, faces, spacing=0.01)


def test_bad_files_and_clouds_are_refused(tmp_path, monkeypatch):
    text = tmp_path / "part.stl"
    text.write_text("this is not a mesh")
    with pytest.raises(hybrid.HybridError, match="part.stl"):
        MeshSurface.from_file(text)
    with pytest.raises(hybrid.HybridError, match="not a mesh file"):
        MeshSurface.from_file(tmp_path / "part.txt")
    with pytest.raises(hybrid.HybridError, match="cannot be read"):
        MeshSurface.from_file(tmp_path / "missing.stl")
    import hybrid.geometry.meshes as meshes

    monkeypatch.setattr(meshes, "MAX_FILE_BYTES", 10)
    with pytest.raises(hybrid.HybridError, match="MB"):
        MeshSurface.from_file(text)
    rng = np.random.default_rng(0)
    n = rng.normal(size=(200, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    with pytest.raises(hybrid.HybridError, match="apart"):  # 200 points on a sphere of 0.15 m: too sparse
        PointCloudSurface(CENTRE + RADIUS * n, n, spacing=0.005)
    with pytest.raises(hybrid.HybridError, match="viewpoint"):
        PointCloudSurface(CENTRE + RADIUS * n)
    with pytest.raises(hybrid.HybridError, match="at least 100"):
        PointCloudSurface(CENTRE + RADIUS * n[:50], n[:50])
    with pytest.raises(hybrid.HybridError, match="rigid motion"):
        MeshSurface(CUBE_V, CUBE_F, transform=np.diag([2.0, 1.0, 1.0, 1.0]), spacing=0.01)


def test_a_tip_beyond_the_band_is_refused_with_the_reason(mesh_sphere):
    _, part = mesh_sphere
    ctrl = hybrid.Controller(hybrid.ur5(), part)
    q = np.zeros(6)
    with pytest.raises(hybrid.TaskFrameError, match="beyond the fitted band"):
        ctrl(0.0, q, np.zeros(6), np.zeros(3))


def test_a_run_on_a_part_is_saved_and_read_with_its_part(tmp_path):
    """The experiment's file holds what the part is made of; read, it is fitted again to the same surface."""
    mesh = trimesh.creation.icosphere(subdivisions=3, radius=RADIUS)
    mesh.apply_translation(CENTRE)
    part = MeshSurface(mesh.vertices, mesh.faces, spacing=0.012)
    exp = hybrid.tracing_experiment(surface=part, duration=0.1,
                                    start_point=tuple(SPHERE.project(np.array([0.5, -0.05, 0.35]))))
    res = hybrid.simulate(exp)
    res.save(tmp_path / "run.npz")
    back = hybrid.SimulationResult.load(tmp_path / "run.npz")
    assert back.experiment.surface == part
    np.testing.assert_array_equal(back.state, res.state)
    assert hybrid.simulate(back.experiment).metrics == pytest.approx(res.metrics, nan_ok=True)


def test_a_raster_across_a_part_runs_as_across_its_shape(mesh_sphere):
    """A raster drawn on the sphere's mesh (projected onto the fitted surface) and followed with a whole task: the
    path metrics of the same task on the sphere itself."""
    _, part = mesh_sphere
    runs = {}
    for surface in (SPHERE, part):
        origin = surface.project(np.array([0.47, -0.03, 0.345]))
        path = hybrid.RasterPath(surface, origin, (1.0, 0.0, 0.0), 0.06, 0.01, 3)
        task = hybrid.PathTask(path, speed=0.08, force=10.0, retreat_distance=0.01)
        runs[surface.kind] = hybrid.simulate(hybrid.tracing_experiment(surface=surface, path_task=task,
                                                                      duration=4.0)).metrics
    exact, mesh = runs["sphere"], runs["mesh"]
    assert mesh["path_error_rms_m"] <= 1e-3 and mesh["path_contact_losses"] == 0
    assert mesh["path_travelled_m"] == pytest.approx(exact["path_travelled_m"], abs=1e-3)
    assert mesh["path_force_rms_error_N"] == pytest.approx(exact["path_force_rms_error_N"], rel=0.05, abs=0.01)


def test_mujocos_own_contact_against_the_mesh_gives_the_same_task(mesh_sphere):
    """An independent check: MuJoCo's collision and soft contact against the mesh's own facets (the sensor tip a
    sphere of 1 mm), not the fitted surface and its penalty, as the plant of a first touch and a pass. The force
    settles on its reference as on the library's plant; the tip rides a tip radius off the fitted surface; the
    differences (an earlier touch by the tip's radius, a ripple of the flat facets, MuJoCo's soft contact
    breaking for single steps) are its contact model's. The sphere is convex: one mesh geom, whose hull MuJoCo
    collides is the part (``tests/test_parts_mujoco.py`` takes parts that are not)."""
    pytest.importorskip("mujoco", reason="MuJoCo's check needs MuJoCo: pip install 'hybrid-decoupling[mujoco]'")
    from hybrid.plants.mujoco_contact import TIP_RADIUS, hull_is_part

    _, part = mesh_sphere
    assert hull_is_part(part.vertices, part.faces)
    start = SPHERE.project(np.array([0.5, -0.05, 0.35]))
    exp = hybrid.tracing_experiment(surface=part, start_point=tuple(start), duration=1.5, start_gap=0.003,
                                    approach_speed=0.02, force_reference=10.0,
                                    speed_reference=hybrid.Step(0.0, 0.1, 0.5))
    ours, theirs = hybrid.simulate(exp), hybrid.simulate(exp, plant="mujoco_contact")
    late = theirs.t > 1.2
    assert theirs.force_normal[late].mean() == pytest.approx(10.0, abs=0.1)
    assert theirs.force_normal[late].std() <= 0.1
    assert theirs.metrics["first_touch_time_s"] < ours.metrics["first_touch_time_s"]  # the tip's radius earlier
    tip = theirs.state[late][:, 12:15]
    height = part.evaluate(tip)[0]
    assert np.all(np.abs(height - TIP_RADIUS) <= 0.5e-3)
    assert abs(theirs.metrics["steady_state_speed_error_m_per_s"]) <= 0.01
    # MuJoCo's contact as set: at rest its overlap is the penalty's, the force over the contact's stiffness
    names = theirs.record["outputs"]
    normal, overlap = (theirs.outputs[late, names.index(c)] for c in ("N", "penetration"))
    assert overlap.mean() == pytest.approx(normal.mean() / exp.contact.stiffness, rel=0.25)
    assert normal.mean() == pytest.approx(theirs.force_normal[late].mean(), abs=0.5)  # the tip's weight besides
    with pytest.raises(hybrid.HybridError, match="MeshSurface"):
        hybrid.simulate(hybrid.tracing_experiment(duration=0.01), plant="mujoco_contact")


def relative(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(a - b) / (np.abs(b).max(axis=0) + 1e-3)))


def test_a_run_on_a_part_in_c_equals_the_python_runner(mesh_sphere, mesh_cylinder):
    """The compiled loop expands the part as the Controller and the rigid-body plant do (the same generated
    evaluator, about the measured tip at each sample and about the sensor tip at each step): runs on two parts
    side by side as lanes (each its own grid) equal their Python runs, and a path on a part too."""
    from hybrid.simulation import closed_loop

    sphere, cylinder = mesh_sphere[1], mesh_cylinder[1]
    exps = [hybrid.tracing_experiment(surface=sphere, duration=1.0,
                                      start_point=tuple(sphere.project(np.array([0.5, -0.05, 0.35])))),
            hybrid.tracing_experiment(surface=cylinder, duration=1.0, frame_direction=(0.0, 1.0, 0.0),
                                      start_point=tuple(cylinder.project(np.array([0.5, 0.02, 0.31]))))]
    prepared = [closed_loop.prepare(e) for e in exps]
    assert all(p is not None and "part.coefficients" in p.loop.tables for p in prepared)
    assert prepared[0].loop is prepared[1].loop  # one build serves every part
    together = closed_loop.run(prepared, record=True)
    for exp, got in zip(exps, together):
        python = hybrid.simulate(exp, compiled=False)
        assert got.status == 0
        assert relative(got.states, python.state) < 1e-8
        for name, value in python.metrics.items():
            assert got.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name
    origin = sphere.project(np.array([0.47, -0.03, 0.345]))
    task = hybrid.PathTask(hybrid.RasterPath(sphere, origin, (1.0, 0.0, 0.0), 0.04, 0.01, 2), retreat_distance=0.01)
    exp = hybrid.tracing_experiment(surface=sphere, path_task=task, duration=2.0)
    assert closed_loop.prepare(exp).loop.path_task
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    assert relative(compiled.state, python.state) < 1e-8
    for name, value in python.metrics.items():
        assert compiled.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name


def test_a_tip_leaving_the_band_stops_the_run_alike_in_c_and_in_python():
    """A part fitted with a narrow band and a start far enough that the tip leaves it: both runners stop at the
    same sample with the same first line."""
    mesh = sphere_mesh()
    narrow = MeshSurface(mesh.vertices, mesh.faces, spacing=0.008, band=0.01)
    start = SPHERE.project(np.array([0.5, -0.05, 0.35]))
    exp = hybrid.tracing_experiment(surface=narrow, duration=1.0, start_point=tuple(start),
                                    sensor=hybrid.Sensor(stiffness=300.0))  # the arm tip 3 cm behind the sensor's
    errors = []
    for compiled in (True, False):
        with pytest.raises(hybrid.SimulationError) as info:
            hybrid.simulate(exp, compiled=compiled)
        errors.append(info.value)
    assert errors[0].time == errors[1].time
    assert str(errors[0]).splitlines()[0] == str(errors[1]).splitlines()[0]
    assert "band" in str(errors[0])


def test_the_standalone_c_on_a_part_equals_the_controller(mesh_sphere, tmp_path):
    """The controller generated as standalone C for a part, given the part's data by its caller, gives the
    Controller's torques along a run (it compiles warning-free with the strict flags); without the data it
    refuses every sample, and a tip beyond the band is refused as the Controller refuses it."""
    from test_standalone_controller import CController, recorded_samples

    _, part = mesh_sphere
    exp = hybrid.tracing_experiment(surface=part, duration=0.4,
                                    start_point=tuple(part.project(np.array([0.5, -0.05, 0.35]))))
    py = exp.build_controller()
    written = py.generate(tmp_path, "part_task")
    assert "hybrid_part.h" in {p.name for p in written}
    c = CController(tmp_path, "part_task")
    samples = recorded_samples(exp)
    t, q, qd, wrench = samples[0]
    status, _ = c.step(t, q, qd, wrench)
    assert c.name(status) == "PARAMETER_INVALID"  # no part given yet
    grid, coefficients = part.data()
    c.c.part_grid = c.ffi.from_buffer("double[]", grid)
    c.c.part_coefficients = c.ffi.from_buffer("double[]", coefficients)
    worst = 0.0
    for t, q, qd, wrench in samples:
        tau_py = py(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0, c.name(status)
        worst = max(worst, float(np.max(np.abs(tau_c - tau_py)) / max(1.0, np.max(np.abs(tau_py)))))
    assert worst <= 1e-11
    np.testing.assert_allclose(np.frombuffer(c.ffi.buffer(c.c.surface), float), py.step_inputs()["surface"],
                               rtol=1e-12, atol=1e-12)
    far = np.zeros(6)  # the UR5 stretched out: its tip far beyond the part's band
    status, _ = c.step(t + exp.sample_time, far, np.zeros(6), np.zeros(6))
    assert c.name(status) == "FRAME_UNDEFINED"


def test_a_part_nobody_here_designed_is_touched_and_followed():
    """A CAD-derived mesh from example-robot-data (the Panda's fifth link, its collision mesh of 300 facets)
    laid in the UR5's reach: fitted within its report's bounds (a millimetre from its flat facets, which the
    smooth surface through its vertices rounds), touched from 3 mm and followed at 5 cm/s, the force held on its
    10 N."""
    from conftest import example_robot

    link = example_robot("panda_description/meshes/collision/link5.stl")
    place = trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0])
    place[:3, 3] = (0.45, 0.0, 0.15)
    part = MeshSurface.from_file(link, transform=place, spacing=0.005)
    assert part.fit.distance_rms_m <= 1e-3 and part.fit.normal_angle_rms_deg <= 5.0
    top = part.project(np.array([0.45, 0.0, 0.25]))
    exp = hybrid.tracing_experiment(surface=part, start_point=tuple(top), duration=1.5, frame_direction=(1.0, 0.0, 0.0),
                                    start_gap=0.003, approach_speed=0.02, force_reference=10.0,
                                    speed_reference=hybrid.Step(0.0, 0.05, 0.5))
    res = hybrid.simulate(exp)
    m = res.metrics
    assert m["contact_losses"] == 0 and math.isfinite(m["first_touch_time_s"])
    late = res.t > 1.2
    assert res.force_normal[late].mean() == pytest.approx(10.0, abs=0.2)
    assert res.force_normal[late].std() <= 0.2
    tip = res.state[:, 12:15]
    assert np.linalg.norm(tip[-1] - tip[0]) >= 0.04  # it went along the part


def test_a_saved_part_is_read_in_a_fresh_process_and_a_part_crosses_processes(tmp_path):
    """A saved experiment on a part is read where nothing has loaded the parts' module yet; a part pickles (a
    sweep's processes take it) and a sweep over two workers gives each run's numbers as one worker does."""
    import json
    import pickle
    import subprocess
    import sys

    mesh = trimesh.creation.icosphere(subdivisions=3, radius=RADIUS)
    mesh.apply_translation(CENTRE)
    part = MeshSurface(mesh.vertices, mesh.faces, spacing=0.012)
    exp = hybrid.tracing_experiment(surface=part, duration=0.1,
                                    start_point=tuple(part.project(np.array([0.5, -0.05, 0.35]))))
    saved = tmp_path / "exp.json"
    saved.write_text(json.dumps(exp.to_dict()))
    code = ("import json, sys, hybrid; e = hybrid.Experiment.from_dict(json.loads(open(sys.argv[1]).read())); "
            "print(type(e.surface).__name__, e.surface.digest())")
    done = subprocess.run([sys.executable, "-c", code, str(saved)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.split() == ["MeshSurface", part.digest()]
    copy = pickle.loads(pickle.dumps(part))
    assert copy == part and np.array_equal(copy.parameters_at(CENTRE + [0, 0, RADIUS]),
                                           part.parameters_at(CENTRE + [0, 0, RADIUS]))
    grid = {"contact.friction": [0.1, 0.3]}
    one, two = (hybrid.sweep(exp, grid, workers=w) for w in (1, 2))
    assert (one["status"] == "ok").all()
    assert one["rms_force_error_N"].tolist() == two["rms_force_error_N"].tolist()


def test_a_cloud_is_read_back_the_same_and_a_sweep_holds_a_part_once():
    from hybrid.simulation import closed_loop

    rng = np.random.default_rng(3)
    n = rng.normal(size=(6000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    cloud = PointCloudSurface(CENTRE + RADIUS * n, 3.0 * n, spacing=0.012, band=0.02)  # normals of any length
    from hybrid.experiments.serialisation import surface_from_dict, surface_to_dict

    assert surface_from_dict(surface_to_dict(cloud)) == cloud
    exp = hybrid.tracing_experiment(surface=cloud, duration=0.05,
                                    start_point=tuple(cloud.project(np.array([0.5, -0.05, 0.35]))))
    prepared = [closed_loop.prepare(dataclasses.replace(exp, contact=hybrid.Contact(friction=f))) for f in (0.1, 0.2)]
    runs = np.stack([p.row for p in prepared])
    tables = closed_loop._tables(prepared[0].loop, runs, [p.tables for p in prepared])
    assert tables.size == cloud.data()[1].size  # one copy of the grid for both runs


def test_a_part_refuses_what_it_cannot_do(mesh_sphere, monkeypatch):
    _, part = mesh_sphere
    with pytest.raises(hybrid.HybridError, match="frame='actual'"):
        hybrid.Controller(hybrid.ur5(), part, position_error=True, path=lambda t: (np.zeros(3), np.zeros(3)))
    with pytest.raises(hybrid.TaskFrameError, match="beyond the fitted band"):
        hybrid.task_frame(part, [CENTRE + [0.0, 0.0, 0.5]], [[0.1, 0.0, 0.0]])
    import hybrid.validate as validate

    monkeypatch.setattr(validate, "MEMORY_FRACTION", 1e-9)
    with pytest.raises(hybrid.HybridError, match="coarser spacing"):
        MeshSurface(part.vertices, part.faces, spacing=0.01)


def test_the_evaluator_refuses_a_grid_that_is_not_one(mesh_sphere):
    """A caller's grid whose cell counts are not whole numbers in range is refused, not read past its end."""
    from hybrid.native import loader

    _, part = mesh_sphere
    module = loader.part_evaluator()
    grid, coefficients = (np.array(a) for a in part.data())
    out = np.empty(13)
    point = np.ascontiguousarray(CENTRE + [0.0, 0.0, RADIUS])
    for cells in (10.5, 1e300, 0.0, -3.0):
        bad = grid.copy()
        bad[4] = cells
        status = module.lib.hybrid_part_expansion_entry(*(module.ffi.from_buffer("double[]", a)
                                                          for a in (bad, coefficients, point, out)))
        assert status != 0, cells


def test_inputs_of_the_wrong_kind_are_refused_with_the_reason(mesh_sphere):
    _, part = mesh_sphere
    for call, message in [(lambda: MeshSurface(CUBE_V, [["a", "b", "c"]]), "real numbers"),
                          (lambda: MeshSurface(CUBE_V, [[0, 1, None]] * 12), "whole numbers"),
                          (lambda: MeshSurface(CUBE_V + 1j, CUBE_F), "real numbers"),
                          (lambda: MeshSurface(CUBE_V, CUBE_F, spacing=1e-300), "at least"),
                          (lambda: MeshSurface(CUBE_V, CUBE_F, flip="yes"), "True or False"),
                          (lambda: MeshSurface.from_file(None), "path"),
                          (lambda: part.parameters_at([0.5, 0.0]), "point"),
                          (lambda: part.evaluate([[0.5, 0.0]]), "N x 3"),
                          (lambda: PointCloudSurface(CUBE_V.repeat(20, axis=0), viewpoint="up"), "viewpoint"),
                          (lambda: PointCloudSurface(CUBE_V.repeat(20, axis=0), viewpoint=(0, 0, 1),
                                                     neighbours="x"), "neighbours")]:
        with pytest.raises(hybrid.HybridError, match=message):
            call()
