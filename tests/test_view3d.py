"""A run in the browser (hybrid.view): the figure's pictures against independent kinematics and the run's
record, one picture per chosen sample, and the HTML file whole, self-contained and never over a user's file."""

from __future__ import annotations

import re
import sys

import numpy as np
import pytest

import hybrid
from hybrid import view3d

WITHOUT_PLOTLY = "the 3-D view needs plotly: pip install 'hybrid-decoupling[view]'"
go = pytest.importorskip("plotly.graph_objects", reason=WITHOUT_PLOTLY)
offline = pytest.importorskip("plotly.offline", reason=WITHOUT_PLOTLY)

SPATIAL = ("x", "y", "z")
#: the traces each picture changes, by name (the force arrow's name also says its scale)
PATH, ARM, SENSOR, FORCE, T1, T2, N = range(7)


@pytest.fixture(scope="module")
def ur5_run():
    """The UR5 on the sphere, a short run (20 control samples)."""
    return hybrid.simulate(hybrid.tracing_experiment(duration=0.2))


@pytest.fixture(scope="module")
def planar_run():
    return hybrid.simulate(hybrid.paper_experiment(duration=0.2))


def _row(res, sample: int) -> int:
    return sample * res.experiment.steps_per_sample


def _recorded(res, prefix: str, sample, axes=SPATIAL) -> np.ndarray:
    return np.column_stack([res.output(f"{prefix}{a}")[_row(res, np.asarray(sample))] for a in axes])


def _points(trace) -> np.ndarray:
    return np.column_stack([np.asarray(trace.x, float), np.asarray(trace.y, float), np.asarray(trace.z, float)])


def _picture(fig, sample: int) -> list:
    """The traces the figure shows at the control ``sample``: the frame named by it."""
    (frame,) = [f for f in fig.frames if f.name == str(sample)]
    return list(frame.data)


def test_one_picture_per_chosen_sample(ur5_run):
    n = ur5_run.experiment.n_samples
    for every, expected in ((4, list(range(0, n + 1, 4))), (3, [*range(0, n + 1, 3), n])):
        fig = ur5_run.view(every=every)
        assert [f.name for f in fig.frames] == [str(k) for k in expected]
        (slider,) = fig.layout.sliders
        assert [list(s.args[0]) for s in slider.steps] == [[str(k)] for k in expected]  # a slider step per picture
        assert [f"{float(s.label):.2f}" for s in slider.steps] == [f"{ur5_run.t[_row(ur5_run, k)]:.2f}"
                                                                   for k in expected]
    (menu,) = fig.layout.updatemenus
    assert [b.label for b in menu.buttons] == ["Play", "Pause"]
    assert all(f.traces == tuple(range(1, 8)) for f in fig.frames)  # each picture changes the moving traces
    # the figure shows the first picture until played
    np.testing.assert_array_equal(_points(fig.data[1 + ARM]), _points(fig.frames[0].data[ARM]))


def test_links_are_the_pinocchio_joint_origins(ur5_run):
    pin = pytest.importorskip("pinocchio")
    robot = ur5_run.experiment.robot
    urdf, tip, _ = robot.source
    model = pin.buildModelFromUrdf(urdf)
    data = model.createData()
    fig = hybrid.view(ur5_run, every=7)
    for sample in (0, 7, ur5_run.experiment.n_samples):
        links = _points(_picture(fig, sample)[ARM])
        pin.forwardKinematics(model, data, ur5_run.q[_row(ur5_run, sample)])
        pin.updateFramePlacements(model, data)
        joints = np.array([data.oMi[i].translation for i in range(1, model.njoints)])
        np.testing.assert_allclose(links[0], np.zeros(3), atol=1e-12)  # the base
        np.testing.assert_allclose(links[1:-1], joints, atol=1e-9)
        np.testing.assert_allclose(links[-1], data.oMf[model.getFrameId(tip)].translation, atol=1e-9)
        # the sensor: from the arm tip to the recorded sensor tip
        np.testing.assert_allclose(_points(_picture(fig, sample)[SENSOR]),
                                   [links[-1], _recorded(ur5_run, "s_", sample)[0]], atol=1e-12)


def test_force_arrow_is_the_recorded_force_scaled(ur5_run):
    scale = 0.004
    fig = ur5_run.view(every=6, force_scale=scale)
    assert fig.data[1 + FORCE].name == "F_c (4 mm/N)"
    for sample in (6, 12, 18):
        arrow = _points(_picture(fig, sample)[FORCE])
        force = _recorded(ur5_run, "Fc_", sample)[0]
        assert np.linalg.norm(force) > 1.0  # the arm presses: the arrow has a length
        np.testing.assert_allclose(arrow[0], _recorded(ur5_run, "s_", sample)[0], atol=1e-12)
        np.testing.assert_allclose(arrow[1] - arrow[0], scale * force, atol=1e-12)


def test_task_axes_are_the_frame_the_record_is_in(ur5_run):
    """The drawn axes t1, t2, n from the arm tip turn the recorded F_c into the recorded task components;
    n is the sphere's normal at the arm tip."""
    fig = ur5_run.view(every=5)
    for sample in (5, 15):
        picture = _picture(fig, sample)
        tip = _recorded(ur5_run, "r_", sample)[0]
        rows = []
        for k in (T1, T2, N):
            start, end = _points(picture[k])
            np.testing.assert_allclose(start, tip, atol=1e-9)
            rows.append((end - start) / hybrid.animation.AXIS_LENGTH)
        rows = np.array(rows)
        np.testing.assert_allclose(rows @ rows.T, np.eye(3), atol=1e-9)
        np.testing.assert_allclose(rows @ _recorded(ur5_run, "Fc_", sample)[0],
                                   _recorded(ur5_run, "Fc_", sample, ("t", "t2", "n"))[0], atol=1e-9)
        np.testing.assert_allclose(rows[2], ur5_run.experiment.surface.normal_at(tip), atol=1e-9)


def test_the_path_so_far_and_the_sphere(ur5_run):
    fig = ur5_run.view(every=10)
    for sample in (0, 10, 20):
        np.testing.assert_allclose(_points(_picture(fig, sample)[PATH]),
                                   _recorded(ur5_run, "s_", np.arange(sample + 1)), atol=1e-12)
    sphere = ur5_run.experiment.surface
    wire = _points(fig.data[0])
    wire = wire[np.isfinite(wire).all(axis=1)]
    assert len(wire) > 100
    np.testing.assert_allclose(np.linalg.norm(wire - sphere.center, axis=1), sphere.radius, atol=1e-12)


def test_a_part_is_drawn_by_its_mesh():
    """A part given as a mesh is drawn as its triangles, as given."""
    trimesh = pytest.importorskip("trimesh")
    from hybrid.geometry.parts import MeshSurface

    centre, sphere = np.array([0.5, 0.0, 0.2]), hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
    mesh = trimesh.creation.icosphere(subdivisions=3, radius=0.15)
    mesh.apply_translation(centre)
    part = MeshSurface(mesh.vertices, mesh.faces, spacing=0.012)
    res = hybrid.simulate(hybrid.tracing_experiment(
        surface=part, duration=0.05, start_point=tuple(sphere.project(np.array([0.5, -0.05, 0.35])))))
    drawn = hybrid.view(res).data[0]
    assert drawn.type == "mesh3d"
    np.testing.assert_array_equal(_points(drawn), mesh.vertices)
    np.testing.assert_array_equal(np.column_stack([drawn.i, drawn.j, drawn.k]), mesh.faces)


def test_a_long_path_is_thinned(ur5_run, monkeypatch):
    monkeypatch.setattr(view3d, "PATH_POINTS", 4)  # 21 samples: every 6th, and the last
    fig = ur5_run.view(every=20)
    np.testing.assert_allclose(_points(_picture(fig, 20)[PATH]),
                               _recorded(ur5_run, "s_", [0, 6, 12, 18, 20]), atol=1e-12)
    np.testing.assert_allclose(_points(_picture(fig, 0)[PATH]), _recorded(ur5_run, "s_", [0]), atol=1e-12)


def test_equal_scales_spanning_the_arm(ur5_run):
    fig = ur5_run.view(every=5)
    scene = fig.layout.scene
    assert scene.aspectmode == "cube"
    ranges = np.array([scene.xaxis.range, scene.yaxis.range, scene.zaxis.range])
    np.testing.assert_allclose(np.diff(ranges, axis=1), np.diff(ranges[:1], axis=1).repeat(3, 0), rtol=1e-12)
    for frame in fig.frames:
        links = _points(frame.data[ARM])
        assert ((links >= ranges[:, 0]) & (links <= ranges[:, 1])).all()


def test_planar_arm_in_its_plane(planar_run):
    arm = planar_run.experiment.arm
    fig = planar_run.view(every=3)
    assert [t.name for t in fig.data[-2:]] == ["t", "n"]
    for sample in (0, 9):
        q1, q2 = planar_run.q[_row(planar_run, sample)]
        elbow = arm.L1 * np.array([np.cos(q1), np.sin(q1), 0.0])
        tip = elbow + arm.L2 * np.array([np.cos(q1 + q2), np.sin(q1 + q2), 0.0])
        np.testing.assert_allclose(_points(_picture(fig, sample)[ARM]), [[0, 0, 0], [0, 0, 0], elbow, tip],
                                   atol=1e-12)
    section = planar_run.experiment.section
    circle = _points(fig.data[0])
    np.testing.assert_allclose(np.linalg.norm(circle[:, :2] - section.center, axis=1), section.radius, atol=1e-12)
    assert (circle[:, 2] == 0).all()


#: a script tag that loads code from the network
REMOTE_SCRIPT = re.compile(r"<script[^>]*\bsrc\s*=\s*[\"']?(https?:)?//", re.I)


def test_html_is_self_contained_atomic_and_never_over_a_users_file(ur5_run, tmp_path, monkeypatch):
    out = tmp_path / "run.html"
    fig = ur5_run.view(every=10, out=out)
    html = out.read_text()
    assert offline.get_plotlyjs() in html  # plotly.js inside, whole
    assert not REMOTE_SCRIPT.search(html), REMOTE_SCRIPT.search(html).group(0)
    assert [f.name for f in fig.frames] == ["0", "10", "20"]
    for frame in fig.frames:  # every picture is in the file
        assert f'"name":"{frame.name}"' in html
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.html"]

    mine = tmp_path / "mine.html"
    mine.write_text("a user's file")
    with pytest.raises(hybrid.HybridError, match="mine.html exists; choose another name or pass overwrite=True"):
        ur5_run.view(every=10, out=mine)
    assert mine.read_text() == "a user's file"

    def full_disk(self, file, **options):
        with open(file, "w") as f:
            f.write("<html>half")
        raise OSError(28, "No space left on device")

    with monkeypatch.context() as m:  # the writer fails half-way: the old file stays, no temporary is left
        m.setattr(go.Figure, "write_html", full_disk)
        with pytest.raises(hybrid.HybridError, match="writing .*mine.html failed \\(No space left on device\\)"):
            ur5_run.view(every=10, out=mine, overwrite=True)
    assert mine.read_text() == "a user's file"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.html", "run.html"]

    ur5_run.view(every=10, out=mine, overwrite=True)
    assert mine.read_text() == html  # the same figure, the same file
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.html", "run.html"]


def test_without_plotly_the_error_says_what_to_install(ur5_run, monkeypatch):
    for name in [m for m in sys.modules if m == "plotly" or m.startswith("plotly.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "plotly", None)  # import plotly fails
    with pytest.raises(hybrid.HybridError, match=r"needs plotly.*pip install 'hybrid-decoupling\[view\]'") as info:
        ur5_run.view()
    assert len(str(info.value).splitlines()) == 1


@pytest.mark.parametrize(("arguments", "message"), [
    ({"every": 0}, r"every = 0; give a whole number of control samples >= 1"),
    ({"every": 2.5}, r"every = 2.5; give a whole number"),
    ({"force_scale": -1}, r"force_scale = -1; give a positive number"),
    ({"fps": 0}, r"fps = 0; give a positive number"),
    ({"title": 3}, r"title = 3; give text"),
    ({"out": "run.png"}, r"out = 'run\.png'; give a file name ending in \.html"),
    ({"out": ""}, r"not a file name"),
])
def test_bad_input_names_the_fix(ur5_run, arguments, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(hybrid.HybridError, match=message) as info:
        ur5_run.view(**arguments)
    assert len(str(info.value).splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_a_result_is_needed():
    with pytest.raises(hybrid.HybridError, match=r"result = 5; give a run's result"):
        hybrid.view(5)
