"""MuJoCo's own contact against parts that are not convex (``plant="mujoco_contact"``): a dish worked from its
concave side, touched and passed across with MuJoCo as the plant, against the library's plant on the same part and
against the dish's sphere; the convex hull, which MuJoCo's mesh geom collides, shown wrong there; MuJoCo's
contact with the flex of facets against trimesh's exact distances; and the refusals."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import hybrid
from hybrid.geometry.parts import MeshSurface

trimesh = pytest.importorskip("trimesh")
pytest.importorskip("mujoco", reason="MuJoCo's check needs MuJoCo: pip install 'hybrid-decoupling[mujoco]'")

from hybrid.plants import mujoco_contact  # noqa: E402  (after the skip: MuJoCo's check)

#: the dish: the cap of a sphere of radius 0.25 m within 8 cm of its lowest point's vertical (13 mm deep), its
#: bottom at (0.5, 0, 0.3) m
DISH_CENTRE, DISH_RADIUS, DISH_RIM = np.array([0.5, 0.0, 0.55]), 0.25, 0.08


def dish_mesh():
    """The dish's facets (an icosphere's, 9.4 mm across, 532 of them), their normals facing away from the tool."""
    ico = trimesh.creation.icosphere(subdivisions=5, radius=DISH_RADIUS)
    centres = ico.triangles_center
    cap = trimesh.Trimesh(ico.vertices, ico.faces[(np.hypot(centres[:, 0], centres[:, 1]) < DISH_RIM)
                                                  & (centres[:, 2] < 0.0)])
    cap.remove_unreferenced_vertices()
    cap.apply_translation(DISH_CENTRE)
    return cap


@pytest.fixture(scope="module")
def dish():
    cap = dish_mesh()
    return cap, MeshSurface(cap.vertices, cap.faces, flip=True, spacing=0.01)


def dish_experiment(part, **overrides):
    """A first touch from 3 mm at 8 mm off the dish's bottom and a pass across the bottom at 0.1 m/s from 0.5 s (the
    task axis t1 along base x: ``e`` = base y, as the dish's normal is base z at its bottom)."""
    start = part.project(DISH_CENTRE + (-0.03, 0.0, -DISH_RADIUS + 0.01))
    settings = {"surface": part, "start_point": tuple(start), "duration": 1.5, "start_gap": 0.003,
                "approach_speed": 0.02, "force_reference": 10.0, "frame_direction": (0.0, 1.0, 0.0),
                "speed_reference": hybrid.Step(0.0, 0.1, 0.5)}
    return hybrid.tracing_experiment(**{**settings, **overrides})


def bulge(cap) -> float:
    """How far [m] a flat facet lies in front of the sphere its corners lie on (on the concave side, towards the
    tool), at most: the sphere's radius less the distance of the facet's plane from the centre."""
    n = cap.face_normals
    depth = np.abs(np.einsum("ij,ij->i", cap.triangles[:, 0] - DISH_CENTRE, n))
    return float(DISH_RADIUS - depth.min())


def fit_error_of(part) -> float:
    """The fitted surface's largest distance [m] from the dish's sphere within 5 cm of its bottom, where the tip
    goes."""
    rng = np.random.default_rng(0)
    radial, angle = 0.05 * np.sqrt(rng.uniform(size=500)), rng.uniform(0.0, 2 * math.pi, 500)
    xy = radial[:, None] * np.column_stack([np.cos(angle), np.sin(angle)])
    points = np.column_stack([xy, -np.sqrt(DISH_RADIUS ** 2 - (xy ** 2).sum(axis=1))]) + DISH_CENTRE
    return float(np.abs(part.evaluate(points)[0]).max())


@pytest.fixture(scope="module")
def dish_runs(dish):
    cap, part = dish
    exp = dish_experiment(part)
    return exp, hybrid.simulate(exp), hybrid.simulate(exp, plant="mujoco_contact")


def column(res, name: str) -> np.ndarray:
    return res.outputs[:, res.record["outputs"].index(name)]


def test_a_first_touch_on_a_concave_part_with_mujocos_contact_is_the_librarys(dish, dish_runs):
    """The same approach until MuJoCo's tip sphere meets the facets: its centre then one tip radius off them, where
    the library's point tip meets the fitted surface. Bounds: the tip's centre at MuJoCo's touch lies TIP_RADIUS
    above the facets it meets, which lie between the sphere and its bulge (each flat facet in front of the sphere
    through its corners) and the fitted surface within ``fit_error`` of the sphere; the library's touch at the
    fitted surface within one step's approach; the touch earlier by that height over the approach's speed, within
    two record steps."""
    cap, part = dish
    exp, ours, theirs = dish_runs
    r = mujoco_contact.TIP_RADIUS
    s_f = bulge(cap)
    fit_error = fit_error_of(part)
    assert fit_error < 0.05e-3 and 0.02e-3 < s_f < 0.1e-3  # the geometry the bounds below take
    times = {}
    for res in (ours, theirs):
        i = int(np.flatnonzero(column(res, "N") > 0)[0])
        times[res is theirs] = res.t[i]
        height = part.evaluate(res.state[i:i + 1, 12:15])[0][0]
        step = exp.approach_speed * exp.integration_step
        if res is theirs:
            assert r - fit_error - step <= height <= r + s_f + fit_error + step
            touch_height = height
        else:
            assert -step - fit_error <= height <= step
    # until then the two runs are one (the same plant's arm, the same sensor, no contact)
    before = theirs.t < times[True]
    assert np.abs(ours.state[before] - theirs.state[before]).max() <= 1e-9
    # the approach's speed along the normal over the 10 ms before MuJoCo's touch
    i = int(np.searchsorted(theirs.t, times[True]))
    earlier = part.evaluate(theirs.state[i - 100:i - 99, 12:15])[0][0]
    speed = (earlier - touch_height) / (theirs.t[i] - theirs.t[i - 100])
    assert times[False] - times[True] == pytest.approx(touch_height / speed, abs=2 * exp.integration_step)
    assert ours.metrics["first_touch_time_s"] == times[False] and theirs.metrics["first_touch_time_s"] == times[True]


def test_a_pass_across_a_concave_part_with_mujocos_contact_is_the_librarys(dish, dish_runs):
    """The pass across the dish's bottom (5 cm, through its concave middle) with MuJoCo's contact against the facets:
    the force on its 10 N as on the library's plant (0.1 N), the speed alike, the tip on the library's path, and
    its height above the library's tip as the two contacts give it. Bounds: the library's tip sits ``N / k_e``
    into the fitted surface; MuJoCo's a tip radius off the facets less its overlap, at most ``N / k_e`` (less where
    it touches two or three facets at once, each contact bearing its share), the facets within the bulge and the
    fit's error of the fitted surface."""
    cap, part = dish
    exp, ours, theirs = dish_runs
    r, k_e = mujoco_contact.TIP_RADIUS, exp.contact.stiffness
    late = theirs.t > 0.8
    for res in (ours, theirs):
        assert res.force_normal[late].mean() == pytest.approx(10.0, abs=0.1)
        assert res.force_normal[late].std() <= 0.1
        assert abs(res.metrics["steady_state_speed_error_m_per_s"]) <= 0.01
    tips = [res.state[late][:, 12:15] for res in (ours, theirs)]
    assert np.ptp(tips[1][:, 0]) >= 0.05  # across the bottom
    assert np.abs(tips[0][:, :2] - tips[1][:, :2]).max() <= 0.5e-3  # the same path
    phi = [part.evaluate(tip)[0] for tip in tips]
    N = [column(res, "N")[late] for res in (ours, theirs)]
    overlap = column(theirs, "penetration")[late]
    assert np.all(overlap <= 1.25 * N[1] / k_e)  # MuJoCo's soft contact as set (within its damping's share)
    assert np.abs(phi[0] + N[0] / k_e).max() <= 2e-6  # the library's penalty: N = k_e delta, delta = -phi
    fit_error = fit_error_of(part)
    rise = phi[1] - phi[0]
    low = r + N[0] / k_e - 1.25 * N[1] / k_e - fit_error
    high = r + N[0] / k_e + bulge(cap) + fit_error
    assert np.all((low <= rise) & (rise <= high)), (rise.min(), rise.max(), low.min(), high.max())
    # MuJoCo's tip against the dish's own sphere: a tip radius off it less the overlap, plus the bulge
    above = DISH_RADIUS - np.linalg.norm(tips[1] - DISH_CENTRE, axis=1)
    assert np.all((r - overlap - 1e-6 <= above) & (above <= r + bulge(cap) + 1e-6))


def test_the_convex_hull_would_have_failed_on_the_concave_part(dish, dish_runs, monkeypatch):
    """MuJoCo's mesh geom collides the dish through its convex hull, which fills the dish to its rim, 13 mm above
    the bottom: the tip riding 1 mm above the facets is inside it, and the hull's nearest way out is down through
    the facets. At the tips of MuJoCo's pass on the facets (overlap at most 1.25 N / k_e, 0.13 mm) the hull's
    contact would overlap by nearly two tip radii, ten times that bound and the other way; from the first state,
    3 mm above the bottom, it would press the tip in."""
    exp, _, theirs = dish_runs
    late = np.flatnonzero(theirs.t > 0.8)[::50]
    pen = theirs.record["outputs"].index("penetration")
    faithful = mujoco_contact.MujocoContactPlant(exp, exp.robot)
    assert faithful.window is not None
    assert np.array_equal(faithful.outputs(theirs.state[late])[:, pen], column(theirs, "penetration")[late])
    monkeypatch.setattr(mujoco_contact, "hull_is_part", lambda vertices, faces: True)
    hull = mujoco_contact.MujocoContactPlant(exp, exp.robot)
    assert hull.window is None
    wrong = hull.outputs(theirs.state[late])[:, pen]
    bound = 1.25 * column(theirs, "N")[late] / exp.contact.stiffness
    assert np.all(wrong >= 10 * bound)
    assert np.all(wrong >= 1.5 * mujoco_contact.TIP_RADIUS)
    start = exp.initial_state()[None]
    assert faithful.outputs(start)[0, pen] == 0.0 and hull.outputs(start)[0, pen] >= exp.start_gap


def test_mujocos_contact_with_the_facets_is_their_exact_distance(dish, rng):
    """MuJoCo's overlap with the flex of facets, read at sensor tips all over the dish (the window of facets moved
    between them: the dish's 532 facets are more than the flex's 256) and on both sides of contact, against
    trimesh's exact distance from the tip to the facets: ``TIP_RADIUS - distance`` to rounding."""
    cap, part = dish
    exp = dish_experiment(part, duration=0.01)
    plant = mujoco_contact.MujocoContactPlant(exp, exp.robot)
    assert plant.window is not None and plant.window.slots == mujoco_contact.WINDOW_SLOTS < len(cap.faces)
    n = rng.normal(size=(300, 3))
    n[:, 2] = -np.abs(n[:, 2]) - 3.0
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    tips = DISH_CENTRE + (DISH_RADIUS - rng.uniform(0.8e-3, 1.2e-3, (300, 1))) * n
    states = np.repeat(exp.initial_state()[None], len(tips), axis=0)
    states[:, 12:15] = tips
    got = plant.outputs(states)[:, exp.plant().record["outputs"].index("penetration")]
    want = np.maximum(0.0, mujoco_contact.TIP_RADIUS - distance_to_facets(cap.triangles, tips))
    assert np.count_nonzero(want > 0) >= 80 and np.count_nonzero(want == 0) >= 80
    assert np.abs(got - want).max() <= 1e-9


def test_which_parts_mujocos_mesh_geom_takes_as_they_are():
    """The mesh geom (its convex hull) only for a closed convex mesh seen from outside, against trimesh's own test
    of convexity; two separate convex pieces are not one convex part (their hull bridges them)."""
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.1)
    two = trimesh.util.concatenate([sphere, sphere.copy().apply_translation((0.3, 0.0, 0.0))])
    dented = sphere.vertices.copy()
    dented[np.argmax(dented[:, 2])] *= 0.99
    meshes = {"sphere": sphere, "box": trimesh.creation.box((0.1, 0.2, 0.3)),
              "cylinder": trimesh.creation.cylinder(0.1, 0.3, sections=64), "torus": trimesh.creation.torus(0.15, 0.05)}
    cases = {name: (m.vertices, m.faces) for name, m in meshes.items()}
    cases.update({"inside out": (sphere.vertices, sphere.faces[:, ::-1]), "dented": (dented, sphere.faces),
                  "open": (sphere.vertices, sphere.faces[sphere.triangles_center[:, 2] < 0]),
                  "two": (two.vertices, two.faces)})
    taken = {name: mujoco_contact.hull_is_part(v, f) for name, (v, f) in cases.items()}
    assert taken == {"sphere": True, "box": True, "cylinder": True, "inside out": False, "dented": False,
                     "torus": False, "open": False, "two": False}
    for name in ("sphere", "box", "cylinder", "inside out", "dented", "torus", "open"):
        assert taken[name] == trimesh.Trimesh(*cases[name], process=False).is_convex, name


def test_a_tip_pressed_through_the_facets_is_refused(dish):
    """A soft contact (k_e = 1e4 N/m) under 10 N would press the tip 1 mm into the facets, its whole radius: the
    flex has no inside, so the run is refused once the overlap passes half the radius, with the fix."""
    _, part = dish
    exp = dish_experiment(part, duration=0.6)
    soft = dataclasses.replace(exp, contact=dataclasses.replace(exp.contact, stiffness=1e4))
    with pytest.raises(hybrid.HybridError, match=r"^plant='mujoco_contact': the sensor tip pressed 0\.5.* mm into "
                                                 r"the part's facets .*stiffer contact"):
        hybrid.simulate(soft, plant="mujoco_contact")


def test_facets_finer_than_the_window_holds_are_refused():
    """More facets within the tip's reach than the flex holds: refused with the fix, not a window that misses some."""
    fine = trimesh.creation.icosphere(subdivisions=6, radius=0.004)
    window = mujoco_contact.FacetWindow(fine.triangles)
    with pytest.raises(hybrid.HybridError, match="more than 256 of the part's facets lie within 2 mm of the sensor "
                                                 "tip; give a coarser mesh"):
        window.move(np.array([0.0, 0.0, 0.004]), np.zeros((3 * window.slots, 3)), 2e-3)


def distance_to_facets(triangles: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Each point's distance [m] from the nearest of ``triangles`` (trimesh's closest point on each triangle; its
    nearest-facet search over a mesh is not exact)."""
    pairs = np.repeat(points, len(triangles), axis=0)
    nearest = trimesh.triangles.closest_point(np.tile(triangles, (len(points), 1, 1)), pairs)
    return np.linalg.norm(nearest - pairs, axis=1).reshape(len(points), -1).min(axis=1)


def test_a_cad_part_as_it_comes_is_checked_on_its_own_facets():
    """The Panda's fifth link from example-robot-data (its collision mesh, 300 facets; not convex, its hull up to
    0.19 mm off it) touched from 3 mm and followed at 5 cm/s with MuJoCo as the plant: MuJoCo's tip rides exactly
    TIP_RADIUS less its overlap off the facets (trimesh's distances, to rounding), the force on its 10 N as on the
    library's plant. Bounds: the tip above the library's by TIP_RADIUS and the two overlaps (as on the dish), the
    facets within the fit's largest distance from the fitted surface (1.9 mm: coarse flat facets, which the smooth
    surface through their corners rounds); the force within 0.3 N of 10 N, and within 0.4 N RMS of its mean: the
    tip crosses edges between facets up to 10 degrees apart, which the library's fitted surface has rounded."""
    from conftest import example_robot

    link = example_robot("panda_description/meshes/collision/link5.stl")
    place = trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0])
    place[:3, 3] = (0.45, 0.0, 0.15)
    part = MeshSurface.from_file(link, transform=place, spacing=0.005)
    assert not mujoco_contact.hull_is_part(part.vertices, part.faces)
    top = part.project(np.array([0.45, 0.0, 0.25]))
    exp = hybrid.tracing_experiment(surface=part, start_point=tuple(top), duration=1.5, frame_direction=(1.0, 0.0, 0.0),
                                    start_gap=0.003, approach_speed=0.02, force_reference=10.0,
                                    speed_reference=hybrid.Step(0.0, 0.05, 0.5))
    ours, theirs = hybrid.simulate(exp), hybrid.simulate(exp, plant="mujoco_contact")
    late = theirs.t > 1.0
    for res in (ours, theirs):
        assert res.force_normal[late].mean() == pytest.approx(10.0, abs=0.3)
        assert res.force_normal[late].std() <= 0.4
    tips = [res.state[late][:, 12:15] for res in (ours, theirs)]
    assert np.linalg.norm(tips[1][-1] - tips[1][0]) >= 0.02  # along the part
    overlap, k_e = column(theirs, "penetration")[late], exp.contact.stiffness
    every = slice(None, None, 50)
    off = distance_to_facets(part.vertices[part.faces], tips[1][every])
    assert np.abs(overlap[every] - np.maximum(0.0, mujoco_contact.TIP_RADIUS - off)).max() <= 1e-9
    N = [column(res, "N")[late] for res in (ours, theirs)]
    rise = part.evaluate(tips[1])[0] - part.evaluate(tips[0])[0]
    base = mujoco_contact.TIP_RADIUS + N[0] / k_e
    spread = part.fit.distance_max_m
    assert np.all((base - 1.25 * N[1] / k_e - spread <= rise) & (rise <= base + spread))
