"""The fit of a part's surface itself: the solver's coarse grids against the B-spline they stand for and against
the diagonal preconditioner alone, the default band of a small part, a transform in single precision, and the
warning of a fit that follows its part poorly (each poor case flagged, the good fits not)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import hybrid
import hybrid.geometry.part_fit as part_fit
from hybrid.geometry.bspline import SplineGrid
from hybrid.geometry.fit_solver import coarse_shape, coarsened, refined
from hybrid.geometry.parts import DEFAULT_BAND, MeshSurface, PointCloudSurface

trimesh = pytest.importorskip("trimesh")

CENTRE = np.array([0.5, 0.0, 0.2])


def sphere(radius: float, subdivisions: int = 3):
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=radius)
    return mesh.vertices + CENTRE, mesh.faces


def near_sphere(radius: float, count: int, within: float, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Points within ``within`` [m] of the sphere about CENTRE and their distances from it (signed, outwards)."""
    rng = np.random.default_rng(seed)
    n = rng.normal(size=(count, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    off = rng.uniform(-within, within, count)
    return CENTRE + (radius + off)[:, None] * n, off


# ------------------------------------------------------------------------------------------------- the solver


def test_a_coarse_b_spline_refined_is_the_same_function(rng):
    """The subdivision the solver's coarse grids use: a random spline on a grid of 2 h, its coefficients refined to
    the grid of h (origin 2 h further on), evaluated by SplineGrid at random points: phi, its gradient and its
    Hessian equal; and coarsening is refining's transpose."""
    h, shape = 0.01, (13, 11, 12)
    coarse = rng.normal(size=coarse_shape(shape))
    origin = np.array([0.1, -0.2, 0.3])
    fine = SplineGrid(origin, h, refined(coarse, shape))
    wide = SplineGrid(origin - 2 * h, 2 * h, coarse)
    points = origin + rng.uniform(0, 1, (500, 3)) * (np.array(shape) - 3) * h
    for a, b in zip(fine.evaluate(points), wide.evaluate(points)):
        np.testing.assert_allclose(a, b, rtol=1e-10, atol=1e-12 * np.abs(b).max())
    f = rng.normal(size=shape)
    assert np.sum(refined(coarse, shape) * f) == pytest.approx(np.sum(coarse * coarsened(f)), rel=1e-12)


@pytest.fixture(scope="module")
def fits():
    """A sphere of 0.15 m in 1,280 facets at 12 mm, fitted with the coarse grids and with the diagonal alone (as
    the fit was solved before), each solve's iterations counted."""
    vertices, faces = sphere(0.15)
    iterations = {}
    solve = part_fit.conjugate_gradients

    def counted(*args):
        x, k, converged = solve(*args)
        iterations[part_fit.LEVELS] = k
        return x, k, converged

    grids = {}
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(part_fit, "conjugate_gradients", counted)
        for levels in (part_fit.LEVELS, 0):
            patch.setattr(part_fit, "LEVELS", levels)
            grids[levels] = MeshSurface(vertices, faces, spacing=0.012)
    return grids[part_fit.LEVELS], grids[0], iterations


def test_the_coarse_grids_give_the_diagonals_fit_in_far_fewer_iterations(fits):
    """The same least squares solved to the same tolerance: within 2 cm of the part phi within 10 micrometres of
    the diagonal's solution (3.3 measured; the fit's own error there is 0.64 mm RMS) and the normal within 0.03
    degrees (0.008), in fewer than half its iterations."""
    fast, slow, iterations = fits
    assert iterations[part_fit.LEVELS] * 2 < iterations[0]
    points, _ = near_sphere(0.15, 5000, 0.02)
    (phi, g, _), (phi_0, g_0, _) = fast.evaluate(points), slow.evaluate(points)
    assert np.abs(phi - phi_0).max() <= 1e-5
    cos = np.einsum("ij,ij->i", g, g_0) / np.linalg.norm(g, axis=1) / np.linalg.norm(g_0, axis=1)
    assert np.degrees(np.arccos(np.clip(cos, -1, 1))).max() <= 0.03


# ----------------------------------------------------------------------------------------- the default band


def test_a_small_parts_default_band_is_a_quarter_of_its_size():
    """A sphere 2 cm across: its band a quarter of its bounding box's diagonal (not 3 cm, a grid four times the
    part's size), the surface still the sphere's within the band; a 0.3 m part keeps the 3 cm."""
    vertices, faces = sphere(0.01, subdivisions=4)
    small = MeshSurface(vertices, faces)
    diagonal = float(np.linalg.norm(np.ptp(vertices, axis=0)))
    assert small.band == pytest.approx(diagonal / 4)
    assert small.spacing == pytest.approx(diagonal / 50)
    assert np.prod(small.grid.coefficients.shape) <= 70 ** 3  # (123 ** 3 with the 3 cm band)
    points, off = near_sphere(0.01, 2000, small.band)
    phi = small.evaluate(points)[0]
    assert np.isfinite(phi).all()
    assert np.abs(phi - off).max() <= 1e-4
    large = MeshSurface(*sphere(0.15), spacing=0.01)
    assert large.band == DEFAULT_BAND


# ---------------------------------------------------------------------------- a transform in single precision


def placement(dtype=float) -> np.ndarray:
    T = trimesh.transformations.rotation_matrix(0.7, [1.0, 2.0, 3.0])
    T[:3, 3] = (0.5, -0.1, 0.2)
    return T.astype(dtype)


def test_a_transform_in_single_precision_is_taken_as_the_rotation_it_rounds():
    """A rotation in float32 (orthonormal to 5e-8), or written with 7 digits and read as doubles: taken,
    orthonormalised (the placed part keeps its vertices' distances to 1e-12), the same part as the double
    transform's within the rounding."""
    vertices, faces = sphere(0.15, subdivisions=2)
    vertices = vertices - CENTRE
    exact = MeshSurface(vertices, faces, transform=placement(), spacing=0.02, band=0.04)
    R = placement(np.float32).astype(float)[:3, :3]
    assert np.abs(R.T @ R - np.eye(3)).max() > 1e-9  # refused before as not a rigid motion
    points, _ = near_sphere(0.15, 300, 0.02)
    points = points - CENTRE + placement()[:3, 3]
    for given in (placement(np.float32), np.round(placement(), 7)):
        part = MeshSurface(vertices, faces, transform=given, spacing=0.02, band=0.04)
        moved = part.vertices
        assert np.abs(np.linalg.norm(moved - moved[0], axis=1)
                      - np.linalg.norm(vertices - vertices[0], axis=1)).max() <= 1e-12
        np.testing.assert_allclose(moved, exact.vertices, atol=1e-7)
        assert np.abs(part.evaluate(points)[0] - exact.evaluate(points)[0]).max() <= 1e-6


@pytest.mark.parametrize("change, message", [
    (lambda T: T @ np.diag([1.001, 1.0, 1.0, 1.0]), "1e-06"),  # a scale of 0.1 % (doubles)
    (lambda T: (T @ np.diag([1.001, 1.0, 1.0, 1.0])).astype(np.float32), "1.2e-05"),  # and in single precision
    (lambda T: T @ np.array([[1, 1e-4, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]), "rigid motion"),  # shear
    (lambda T: T @ np.diag([1.0, 1.0, -1.0, 1.0]), "reflection"),
    (lambda T: T.astype(np.float16), "single or double precision"),
])
def test_a_transform_that_is_not_a_rigid_motion_is_refused_in_any_precision(change, message):
    vertices, faces = sphere(0.15, subdivisions=1)
    with pytest.raises(hybrid.HybridError, match=message):
        MeshSurface(vertices - CENTRE, faces, transform=change(placement()), spacing=0.02)


# ------------------------------------------------------------------------------------------------- poor fits


def torus(minor: float):
    mesh = trimesh.creation.torus(major_radius=0.12, minor_radius=minor, major_sections=96, minor_sections=24)
    return mesh.vertices + CENTRE, mesh.faces


def cap(count: int = 6000, seed: int = 3):
    """Points on the upper part of a sphere of 0.15 m (0.3 mm of noise) and its outward normals."""
    rng = np.random.default_rng(seed)
    n = rng.normal(size=(count, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    n = n[n[:, 2] > 0.2]
    return CENTRE + 0.15 * n + 3e-4 * rng.normal(size=n.shape), n


EYE = CENTRE + (0.0, 0.0, 1.0)


def good_fits():
    box = trimesh.creation.box(extents=(0.16, 0.16, 0.1))
    points, normals = cap()
    return {
        "a sphere's mesh": lambda: MeshSurface(*sphere(0.15), spacing=0.012),
        "a box's twelve facets (its corners rounded)": lambda: MeshSurface(box.vertices, box.faces, spacing=0.008),
        "a torus": lambda: MeshSurface(*torus(0.04), spacing=0.008, band=0.024),
        "a noisy scan's estimated normals": lambda: PointCloudSurface(points, viewpoint=EYE, spacing=0.012),
        "the same smoothed": lambda: PointCloudSurface(points, viewpoint=EYE, spacing=0.012, smoothing=20.0),
        "a scan with its normals": lambda: PointCloudSurface(points, normals, spacing=0.012),
        "a scan's points each twice, with normals": lambda: PointCloudSurface(np.vstack([points, points]),
                                                                               np.vstack([normals, normals]),
                                                                               spacing=0.012),
    }


@pytest.mark.parametrize("name", list(good_fits()))
def test_a_good_fit_is_not_warned_of(name):
    with warnings.catch_warnings():
        warnings.simplefilter("error", hybrid.PartFitWarning)
        part = good_fits()[name]()
    fit = part.fit
    assert fit.poor() is None
    assert 0 <= fit.distance_median_m <= fit.distance_max_m
    assert 0 <= fit.normal_angle_median_deg <= fit.normal_angle_max_deg


def poor_fits():
    box = trimesh.creation.box(extents=(0.16, 0.16, 0.1))
    points, normals = cap()
    return {
        # a tube of 1 cm's radius at a spacing of 3 cm: its normal some 4.5 degrees off
        "a spacing too coarse for the curvature": (lambda: MeshSurface(*torus(0.01), spacing=0.03, band=0.09),
                                                   "degrees"),
        # facets of 3.6 cm on a radius of 15 cm, fitted at 1 cm: the smooth surface through their corners lies 3 mm
        # off their middles
        "a mesh's facets too coarse for its curvature": (lambda: MeshSurface(*sphere(0.15, subdivisions=2),
                                                                             spacing=0.01), "facets"),
        "huge smoothing": (lambda: MeshSurface(box.vertices, box.faces, spacing=0.008, smoothing=100.0), "mm from"),
        "a sphere smoothed 5e4 times the default": (lambda: MeshSurface(*sphere(0.15), spacing=0.012,
                                                                        smoothing=1e4), "mm from"),
        # the part scanned twice, the scans 4 mm apart (not registered): each point's neighbours span both
        "two layers, normals estimated": (lambda: PointCloudSurface(np.vstack([points, points + 0.004 * normals]),
                                                                    viewpoint=EYE, spacing=0.012), "doubled"),
        "two layers a cell apart": (lambda: PointCloudSurface(np.vstack([points, points + 0.012 * normals]),
                                                              np.vstack([normals, normals]), spacing=0.012),
                                    "one layer"),
    }


@pytest.mark.parametrize("name", list(poor_fits()))
def test_a_poor_fit_is_warned_of_with_its_error_and_the_fix(name):
    """Each warned of once, at the caller's line, naming the measured error (in the fit's report) and the fix."""
    make, fix = poor_fits()[name]
    with pytest.warns(hybrid.PartFitWarning, match="follows the part poorly") as record:
        part = make()
    assert len(record) == 1 and record[0].filename == __file__
    message = str(record[0].message)
    assert fix in message
    fit = part.fit
    assert (fit.distance_median_m > 0.25 * fit.spacing_m) or (fit.normal_angle_median_deg > 4.0)
    measured = (f"{fit.distance_median_m * 1e3:.3g} mm" if "mm from" in message
                else f"{fit.normal_angle_median_deg:.3g} degrees")
    assert measured in message
    assert math.isfinite(fit.distance_rms_m)


# ------------------------------------------------------------------------------------ the facets' corner normals

def test_corner_normals_are_their_definition_and_a_fan_costs_its_pairs_not_a_table():
    """Each corner's normal is the area-weighted mean of the normals of the facets at its vertex within the crease
    angle of its own, computed here corner by corner (a cylinder: its caps' centres fans of 300 facets, its rims
    creases of 90 degrees). A uv sphere's poles are fans of 100 facets: the memory goes with the facets at each
    vertex squared (70 MB here), not with the corners times the largest fan (1.2 GB; a 210,000-facet uv sphere's
    fit took 15 GB)."""
    import tracemalloc

    from hybrid.geometry.meshes import CREASE_DEG, corner_normals, face_areas, face_normals

    mesh = trimesh.creation.cylinder(0.1, 0.2, sections=300)
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    normals, areas = face_normals(v, f), face_areas(v, f)
    want = np.empty((len(f), 3, 3))
    for i, face in enumerate(f):
        for k, vertex in enumerate(face):
            at = np.flatnonzero((f == vertex).any(axis=1))
            near = at[normals[at] @ normals[i] >= math.cos(math.radians(CREASE_DEG))]
            mean = areas[near] @ normals[near]
            want[i, k] = mean / np.linalg.norm(mean)
    np.testing.assert_allclose(corner_normals(v, f), want, atol=1e-12)
    assert np.abs(want[:, :, 2]).max() == pytest.approx(1.0) and np.abs(want[:, :, 2]).min() < 1e-12  # creases kept
    mesh = trimesh.creation.uv_sphere(0.15, count=[100, 100])
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    tracemalloc.start()
    try:
        corner_normals(v, f)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 0.3e9
