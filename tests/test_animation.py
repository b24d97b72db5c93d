"""Pictures of the arm doing the task (hybrid.animation): what each picture draws against independent
kinematics and the run's record, one picture per chosen sample, and the GIF written whole or not at all."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest
from conftest import pinocchio_model
from matplotlib import animation as mpl_animation
from PIL import Image

import hybrid
from hybrid import animation
from hybrid.models.chain_kinematics import joint_frames

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SPATIAL = ("x", "y", "z")
#: a test looks at an animation's pictures without playing it, as matplotlib warns
pytestmark = pytest.mark.filterwarnings("ignore:Animation was deleted without rendering:UserWarning")


@pytest.fixture(scope="module")
def ur5_run():
    """The UR5 on the sphere, a short run (20 control samples)."""
    return hybrid.simulate(hybrid.tracing_experiment(duration=0.2))


@pytest.fixture(scope="module")
def panda_run():
    """The Panda around its pillar (7 joints, a posture task), a short run."""
    return hybrid.simulate(hybrid.panda_experiment(duration=0.2))


@pytest.fixture(scope="module")
def planar_run():
    return hybrid.simulate(hybrid.paper_experiment(duration=0.2))


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def _row(res, sample: int) -> int:
    return sample * res.experiment.steps_per_sample


def _recorded(res, prefix: str, sample: int, axes=SPATIAL) -> np.ndarray:
    return np.array([res.output(f"{prefix}{a}")[_row(res, sample)] for a in axes])


def test_one_picture_per_chosen_sample(ur5_run, tmp_path):
    n = ur5_run.experiment.n_samples
    for every, expected in ((4, list(range(0, n + 1, 4))), (3, [*range(0, n + 1, 3), n])):
        anim = ur5_run.animate(every=every)
        assert [f.sample for f in anim.new_frame_seq()] == expected
    out = tmp_path / "run.gif"
    ur5_run.animate(every=4, out=out)
    with Image.open(out) as gif:  # the file holds one image per picture
        assert gif.format == "GIF" and gif.n_frames == len(range(0, n + 1, 4))


@pytest.mark.parametrize("which", ["ur5_run", "panda_run"])
def test_links_are_the_pinocchio_joint_origins(which, request):
    pin = pytest.importorskip("pinocchio")
    run = request.getfixturevalue(which)
    robot = run.experiment.robot
    urdf, tip, _ = robot.source
    model = pinocchio_model(urdf, robot.joint_names)  # the Panda's fingers locked, as the library holds them
    assert tuple(model.names[1:]) == robot.joint_names
    data = model.createData()
    for sample in (0, 7, run.experiment.n_samples):
        frame = animation.arm_frame(run, sample)
        q = run.q[_row(run, sample)]
        pin.forwardKinematics(model, data, q)
        pin.updateFramePlacements(model, data)
        joints = np.array([data.oMi[i].translation for i in range(1, model.njoints)])
        np.testing.assert_allclose(frame.links[0], np.zeros(3), atol=1e-12)  # the base
        np.testing.assert_allclose(frame.links[1:-1], joints, atol=1e-9)
        np.testing.assert_allclose(frame.links[-1], data.oMf[model.getFrameId(tip)].translation, atol=1e-9)


def test_last_link_ends_at_the_tip_the_library_computes(ur5_run):
    robot = ur5_run.experiment.robot
    for sample in (0, 5, 20):
        frame = animation.arm_frame(ur5_run, sample)
        row = _row(ur5_run, sample)
        terms = hybrid.arm_terms(robot, ur5_run.q[row], ur5_run.qdot[row])
        np.testing.assert_allclose(frame.links[-1], terms["r"], atol=1e-9)
        np.testing.assert_allclose(frame.links[-1], _recorded(ur5_run, "r_", sample), atol=1e-9)
        origins, rotations, _, _ = joint_frames(robot.chain, ur5_run.q[row])
        np.testing.assert_allclose(origins[-1] + rotations[-1] @ robot.chain.tip_translation, terms["r"], atol=1e-9)


def test_force_arrow_is_the_recorded_wrench(ur5_run):
    scale = 0.004
    frame = animation.arm_frame(ur5_run, 12, force_scale=scale)
    force = _recorded(ur5_run, "Fc_", 12)
    assert np.linalg.norm(force) > 1.0  # the arm presses: the arrow has a length
    np.testing.assert_allclose(frame.force, force, rtol=0, atol=1e-12)
    np.testing.assert_allclose(frame.force_arrow[0], _recorded(ur5_run, "s_", 12), atol=1e-12)
    np.testing.assert_allclose((frame.force_arrow[1] - frame.force_arrow[0]) / scale, force, atol=1e-9)
    # the default scale draws the run's largest force FORCE_ARROW long
    frames = animation.arm_frames(ur5_run, np.arange(ur5_run.experiment.n_samples + 1))
    longest = max(np.linalg.norm(f.force_arrow[1] - f.force_arrow[0]) for f in frames)
    assert longest <= animation.FORCE_ARROW + 1e-12


def test_task_axes_are_the_frame_the_record_is_in(ur5_run):
    """The drawn rows t1, t2, n turn the recorded F_c into the recorded task components; n is the
    sphere's normal at the arm tip."""
    for sample in (3, 15):
        frame = animation.arm_frame(ur5_run, sample)
        np.testing.assert_allclose(frame.task_axes @ frame.task_axes.T, np.eye(3), atol=1e-12)
        np.testing.assert_allclose(frame.task_axes @ frame.force, _recorded(ur5_run, "Fc_", sample, ("t", "t2", "n")),
                                   atol=1e-9)
        np.testing.assert_allclose(frame.task_axes[2], ur5_run.experiment.surface.normal_at(frame.links[-1]),
                                   atol=1e-12)


def test_the_figure_draws_the_frame_data(ur5_run):
    frames = animation.arm_frames(ur5_run, [0, 10])
    picture = animation.ArmPicture(ur5_run, frames, animation.default_force_scale(ur5_run))
    picture.draw(frames[1])
    np.testing.assert_array_equal(np.array(picture.arm.get_data_3d()).T, frames[1].links)
    np.testing.assert_array_equal(np.array(picture.force.get_data_3d()).T, frames[1].force_arrow)
    np.testing.assert_array_equal(np.array(picture.path.get_data_3d()).T, frames[1].path)
    assert len(frames[1].path) == 11  # samples 0 to 10
    assert "t = 0.10 s" in picture.clock.get_text()


def test_a_mesh_part_is_drawn_by_its_facets_under_the_path():
    """A run on a part given as a mesh draws facets of that mesh (each drawn triangle one of its facets),
    among them every facet at the sensor tip's path (those of the vertex nearest each point of it)."""
    pytest.importorskip("scipy")
    x, y = np.meshgrid(np.linspace(-0.1, 0.1, 21), np.linspace(-0.1, 0.1, 21), indexing="ij")
    vertices = np.column_stack([0.5 + x.ravel(), y.ravel(), 0.25 - (x ** 2 + y ** 2).ravel()])  # a shallow dome
    corner = np.arange(x.size).reshape(x.shape)[:-1, :-1].ravel()
    faces = np.vstack([np.column_stack([corner, corner + 21, corner + 22]), np.column_stack([corner, corner + 22,
                                                                                          corner + 1])])
    part = hybrid.MeshSurface(vertices, faces, spacing=0.015)
    run = hybrid.simulate(hybrid.tracing_experiment(surface=part, start_point=tuple(part.project([0.5, 0.05, 0.26])),
                                                    frame_direction=(1.0, 0.0, 0.0), duration=0.3))
    picture = animation.ArmPicture(run, animation.arm_frames(run, [0]), 0.01)
    # a 3-D line collection keeps its segments in base coordinates until it is drawn (then projected)
    (drawn,) = [c for c in picture.ax.collections if len(getattr(c, "_segments3d", ()))]
    triangles = np.round(np.array(drawn._segments3d), 12)
    facets = {tuple(np.round(t, 12).ravel()) for t in part.vertices[part.faces]}
    assert all(tuple(t.ravel()) in facets for t in triangles)
    path = np.column_stack([run.output(c) for c in ("s_x", "s_y", "s_z")])
    nearest = np.unique(np.argmin(np.linalg.norm(path[:, None] - part.vertices[None], axis=2), axis=1))
    under = {tuple(np.round(part.vertices[f], 12).ravel()) for f in part.faces if np.isin(f, nearest).any()}
    assert under <= {tuple(t.ravel()) for t in triangles} and len(under) >= 6
    assert not any(c.get_label() == "contact points" for c in picture.ax.collections)


def test_planar_arm_against_its_closed_form(planar_run):
    arm = planar_run.experiment.arm
    for sample in (0, 9):
        frame = animation.arm_frame(planar_run, sample)
        q1, q2 = planar_run.q[_row(planar_run, sample)]
        elbow = arm.L1 * np.array([np.cos(q1), np.sin(q1)])
        tip = elbow + arm.L2 * np.array([np.cos(q1 + q2), np.sin(q1 + q2)])
        np.testing.assert_allclose(frame.links, [[0, 0], [0, 0], elbow, tip], atol=1e-12)
        np.testing.assert_allclose(frame.links[-1], _recorded(planar_run, "r_", sample, ("x", "y")), atol=1e-9)
        np.testing.assert_allclose(frame.force, _recorded(planar_run, "Fc_", sample, ("x", "y")), atol=1e-12)
        np.testing.assert_allclose(frame.task_axes @ frame.force,
                                   _recorded(planar_run, "Fc_", sample, ("t", "n")), atol=1e-9)
    fig = animation.still(planar_run, 5)
    assert fig.axes[0].name == "rectilinear"


def test_gif_is_written_atomically_and_never_over_a_users_file(ur5_run, tmp_path, monkeypatch):
    mine = tmp_path / "mine.gif"
    mine.write_bytes(b"a user's file")
    with pytest.raises(hybrid.HybridError, match="mine.gif exists; choose another name or pass overwrite=True"):
        ur5_run.animate(every=10, out=mine)
    assert mine.read_bytes() == b"a user's file"

    def full_disk(self):
        raise OSError(28, "No space left on device")

    with monkeypatch.context() as m:  # the writer fails half-way: the old file stays, no temporary is left
        m.setattr(mpl_animation.PillowWriter, "finish", full_disk)
        with pytest.raises(hybrid.HybridError, match="writing .*mine.gif failed \\(No space left on device\\)"):
            ur5_run.animate(every=10, out=mine, overwrite=True)
    assert mine.read_bytes() == b"a user's file"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.gif"]

    ur5_run.animate(every=10, out=mine, overwrite=True)
    with Image.open(mine) as gif:
        assert gif.format == "GIF" and gif.n_frames == 3  # samples 0, 10, 20
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.gif"]


@pytest.mark.parametrize("every", [0, -3, 2.5, True, "5"])
def test_bad_every_names_the_fix(ur5_run, every):
    with pytest.raises(hybrid.HybridError, match=r"every = .*; give a whole number of control samples >= 1") as info:
        ur5_run.animate(every=every)
    assert len(str(info.value).splitlines()) == 1


def test_bad_output_names_the_fix(ur5_run, tmp_path, monkeypatch):
    with pytest.raises(hybrid.HybridError, match=r"run\.avi.*give a file name ending in \.gif or \.mp4"):
        ur5_run.animate(out=tmp_path / "run.avi")
    with pytest.raises(hybrid.HybridError, match="not a file name"):
        ur5_run.animate(out="")
    monkeypatch.setattr(mpl_animation.writers, "is_available", lambda name: False)
    with pytest.raises(hybrid.HybridError, match=r"run\.mp4.*install ffmpeg.*give a \.gif"):
        ur5_run.animate(out=tmp_path / "run.mp4")
    assert list(tmp_path.iterdir()) == []


def test_bad_samples_and_scales(ur5_run):
    last = ur5_run.experiment.n_samples
    with pytest.raises(hybrid.HybridError, match=f"give control sample numbers from 0 to {last}"):
        animation.arm_frames(ur5_run, [0, last + 1])
    with pytest.raises(hybrid.HybridError, match="give control sample numbers"):
        animation.arm_frames(ur5_run, [])
    with pytest.raises(hybrid.HybridError, match="force_scale = -1; give a positive number"):
        animation.arm_frame(ur5_run, 0, force_scale=-1)
    np.testing.assert_array_equal(animation.arm_frame(ur5_run, -1).links, animation.arm_frame(ur5_run, last).links)
