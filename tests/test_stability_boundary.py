"""The stability boundary :func:`hybrid.stability_map` predicts holds in the nonlinear simulation.

A grid of the sensor's stiffness, the sample time and the reading's delay (whole samples) on the paper's arm
pressing a plane: every point is predicted (the sampled loops' spectral radius) and simulated with
``allow_unstable=True``, and each run is classified from its small-signal behaviour after a small step of
the force reference (:func:`grows`). Every point away from the predicted boundary (no grid neighbour with
the other prediction) converges when predicted stable and grows when predicted unstable; a boundary shifted
by two grid steps would not pass (:func:`test_a_boundary_two_steps_off_is_caught`). Ten points of the UR5 on a
box run on MuJoCo with MuJoCo's own contact, and behave as predicted too.

The settings keep to what the model holds (its module's docstring): a plane (no curvature), no friction (at
rest the smoothed Coulomb law is a viscous term of ``gamma N / v_eps`` on the sensor tip, which the model
leaves out), no tangential motion (the operating point stays), the paper's model error (the model has the
controller's inertia and compensated viscosity). ``docs/studies/stability_boundary.md`` gives the numbers.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest

import hybrid

#: the grid: the sensor's stiffness [N/m], the sample time [s] (each a whole number of 0.1 ms integration
#: steps, and of samples in STEP_AT and DURATION), the reading's delay [samples]
STIFFNESS = tuple(np.geomspace(1e3, 1e5, 11).tolist())
SAMPLE_TIMES = (0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.008, 0.010, 0.012, 0.015, 0.020)
DELAYS = (0, 1, 2, 3)
AXES = {"sensor.stiffness": STIFFNESS, "sample_time": SAMPLE_TIMES, "sensor.delay_samples": DELAYS}

#: the force held [N], its small step [N] and when [s]: a step of 5 % keeps a stable loop's contact (and its
#: response linear); a run whose force error reaches the force held has lost the contact or doubled the force
PRELOAD, STEP, STEP_AT, DURATION = 10.0, 0.5, 0.12, 2.4


def plane_experiment(**changes) -> hybrid.Experiment:
    """The paper's arm pressing a plane with 10 N at rest (its loops, gains, model error, sensor), the force
    reference stepping by :data:`STEP` at :data:`STEP_AT`; unstable loops allowed."""
    return hybrid.paper_experiment(surface=hybrid.Plane(point=(0.3, 0.0), normal=(-1.0, 0.0)), start_point=(0.3, 0.0),
                                   force_reference=hybrid.Step(PRELOAD, PRELOAD + STEP, STEP_AT),
                                   speed_reference=hybrid.Step(0.0, 0.0, 0.0), contact=hybrid.Contact(friction=0.0),
                                   duration=DURATION, allow_unstable=True, **changes)


def at_point(base: hybrid.Experiment, stiffness: float, sample_time: float, delay: int) -> hybrid.Experiment:
    """``base`` at one point of the grid."""
    sensor = dataclasses.replace(base.sensor, stiffness=stiffness, delay_samples=delay)
    return dataclasses.replace(base, sensor=sensor, sample_time=sample_time)


def force_error(exp: hybrid.Experiment, plant: str = "generated", step_at: float = STEP_AT) -> np.ndarray | None:
    """The normal force's error ``F_n - F_d`` [N] at each control sample from the step on; None for a run that
    diverged (a state gone NaN: :class:`hybrid.SimulationError`)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", hybrid.JointLimitWarning)  # a growing run may swing the arm far
            res = hybrid.simulate(exp, plant=plant)
    except hybrid.SimulationError:
        return None
    every = exp.steps_per_sample
    error = (res.force_normal - res.force_reference)[::every][:exp.n_samples]
    return error[res.sample_t >= step_at - exp.sample_time / 2]


def grows(error: np.ndarray | None) -> bool:
    """Whether a run's force error after the step grows: it diverged, or it reached :data:`PRELOAD` (the
    contact lost, or the force doubled: out of the small-signal range a 5 % step keeps a stable loop in), or
    its envelope over the last quarter of the run exceeds that over the first (which holds the step itself)."""
    if error is None or not np.isfinite(error).all():
        return True
    size = np.abs(error)
    if size.max() >= PRELOAD:
        return True
    quarter = len(size) // 4
    return bool(size[-quarter:].max() > size[:quarter].max())


def near_boundary(stable: np.ndarray) -> np.ndarray:
    """The points of a grid of predictions with a neighbour (one step along one axis) of the other prediction."""
    near = np.zeros(stable.shape, bool)
    for axis in range(stable.ndim):
        differs = np.diff(stable.astype(int), axis=axis) != 0
        lower, upper = [slice(None)] * stable.ndim, [slice(None)] * stable.ndim
        lower[axis], upper[axis] = slice(None, -1), slice(1, None)
        near[tuple(lower)] |= differs
        near[tuple(upper)] |= differs
    return near


def disagreements(stable: np.ndarray, grew: np.ndarray) -> np.ndarray:
    """The points away from the predicted boundary whose run did not behave as predicted."""
    return ~near_boundary(stable) & (stable == grew)


def shifted(stable: np.ndarray, axis: int, steps: int) -> np.ndarray:
    """The predictions moved ``steps`` grid steps along ``axis`` (the edge's repeated): a boundary off by that."""
    index = np.clip(np.arange(stable.shape[axis]) + steps, 0, stable.shape[axis] - 1)
    return np.take(stable, index, axis=axis)


def predicted(base: hybrid.Experiment, axes: dict) -> tuple[np.ndarray, np.ndarray]:
    """The spectral radius and the verdict at each point of the grid ``axes`` (its shape)."""
    table = hybrid.stability_map(base, axes).table
    shape = tuple(len(v) for v in axes.values())
    return table["spectral_radius"].to_numpy().reshape(shape), table["stable"].to_numpy().reshape(shape)


def described(axes: dict, where: np.ndarray, radius: np.ndarray) -> list[str]:
    """The settings and predicted radius at each point of ``where`` (a boolean grid)."""
    names = list(axes)
    return [", ".join(f"{n} = {axes[n][i]:g}" for n, i in zip(names, index)) + f": radius {radius[index]:.4f}"
            for index in zip(*np.nonzero(where))]


@pytest.fixture(scope="module")
def grid():
    """Every point of the grid predicted and simulated: ``radius``, ``stable``, ``grew`` (grid-shaped)."""
    base = plane_experiment()
    radius, stable = predicted(base, AXES)
    grew = np.zeros(stable.shape, bool)
    for index in np.ndindex(stable.shape):
        exp = at_point(base, STIFFNESS[index[0]], SAMPLE_TIMES[index[1]], DELAYS[index[2]])
        grew[index] = grows(force_error(exp))
    return {"radius": radius, "stable": stable, "grew": grew}


def test_the_velocity_loop_is_stable_on_the_whole_grid():
    """The grid's boundary is the force loop's: the velocity loop (t1) is predicted stable at every point, so
    the force error shows each point's verdict."""
    base = plane_experiment()
    points = [at_point(base, k, t, d) for k in STIFFNESS for t in SAMPLE_TIMES for d in DELAYS]
    assert all(hybrid.stability(exp, margins=False).loop("t1").stable for exp in points)


def test_every_point_away_from_the_boundary_behaves_as_predicted(grid):
    stable, grew, radius = grid["stable"], grid["grew"], grid["radius"]
    assert stable.size >= 200 and np.isfinite(radius).all()
    away = ~near_boundary(stable)
    # both sides are there, and well away from the boundary
    assert (away & stable).sum() >= 50 and (away & ~stable).sum() >= 50
    # each run is long enough to show its verdict: over half its samples after the step the predicted
    # radius shrinks an error four times or more, or grows it so
    samples = (DURATION - STEP_AT) / np.array(SAMPLE_TIMES)[None, :, None]
    change = radius ** (samples / 2)
    assert (change[away & stable] <= 0.25).all() and (change[away & ~stable] >= 4).all()
    wrong = disagreements(stable, grew)
    assert not wrong.any(), "runs that did not behave as predicted, away from the boundary:\n" + \
        "\n".join(described(AXES, wrong, radius))


def test_a_boundary_two_steps_off_is_caught(grid):
    """The comparison can fail: the boundary moved two grid steps along any axis, either way, disagrees with
    the runs at points away from its own boundary; so does a model whose reading is one sample later than the
    run's (the predictions at delay ``d + 1`` against the runs at ``d``)."""
    stable, grew = grid["stable"], grid["grew"]
    for axis in range(stable.ndim):
        for steps in (-2, 2):
            wrong = shifted(stable, axis, steps)
            assert (wrong != stable).any()
            assert disagreements(wrong, grew).any(), f"a boundary moved {steps} steps along {list(AXES)[axis]}"
    assert disagreements(stable[:, :, 1:], grew[:, :, :-1]).any()


# ------------------------------------------------------------------------- MuJoCo's own contact

#: the box the UR5 presses on its top (a convex mesh: MuJoCo collides with its facets), centre and half-size [m]
BOX_CENTER, BOX_HALF = (0.5, 0.0, 0.2), 0.08
#: ten points of the grid (stiffness [N/m], sample time [s], delay [samples]), none at the UR5's predicted
#: boundary: five predicted stable, five unstable
MUJOCO_POINTS = {"stable": [(STIFFNESS[0], 0.010, 0), (STIFFNESS[2], 0.005, 2), (STIFFNESS[5], 0.002, 1),
                            (STIFFNESS[8], 0.001, 0), (STIFFNESS[1], 0.006, 3)],
                 "unstable": [(STIFFNESS[10], 0.001, 3), (STIFFNESS[6], 0.004, 2), (STIFFNESS[4], 0.010, 3),
                              (STIFFNESS[2], 0.020, 2), (STIFFNESS[8], 0.006, 0)]}
#: the force reference's step on MuJoCo [s]: after the approach and the first touch have settled
MUJOCO_STEP_AT, MUJOCO_DURATION = 0.6, 1.2


def box_experiment() -> hybrid.Experiment:
    """The UR5 (the 3-D experiment's loops, gains and model error) at rest on the top of a box, a tip radius
    above it (MuJoCo's sensor tip is a sphere), approaching it, pressing 10 N, the force reference stepping by
    :data:`STEP` at :data:`MUJOCO_STEP_AT`."""
    from hybrid.plants.mujoco_contact import TIP_RADIUS

    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * BOX_HALF + BOX_CENTER
    faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],
             [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    box = hybrid.MeshSurface(corners, faces, spacing=0.01, band=0.03)
    top = (BOX_CENTER[0], BOX_CENTER[1], BOX_CENTER[2] + BOX_HALF)
    return hybrid.tracing_experiment(surface=box, start_point=top, start_gap=TIP_RADIUS, approach_speed=0.02,
                                     force_reference=hybrid.Step(PRELOAD, PRELOAD + STEP, MUJOCO_STEP_AT),
                                     speed_reference=hybrid.Step(0.0, 0.0, 0.0), contact=hybrid.Contact(friction=0.0),
                                     duration=MUJOCO_DURATION, allow_unstable=True)


def test_mujocos_own_contact_behaves_as_predicted():
    """Five points predicted stable and five unstable, away from the boundary, on MuJoCo with its own collision
    and soft contact (:mod:`hybrid.plants.mujoco_contact`): its contact holds a force with the overlap the
    penalty's stiffness gives, but moves as if the sensor tip were ``1 / (1 - d)`` times heavier along the
    normal (``d`` its impedance); the verdict is the same with that mass at each of these points."""
    pytest.importorskip("mujoco")
    pytest.importorskip("trimesh")
    from hybrid.plants.mujoco_contact import IMPEDANCE

    base = box_experiment()
    radius, stable = predicted(base, AXES)
    heavy = hybrid.stability_map(base, {**AXES, "sensor.mass": [base.sensor.mass / (1 - IMPEDANCE)]}).table
    heavy_stable = heavy["stable"].to_numpy().reshape(stable.shape)
    near = near_boundary(stable)
    for verdict, points in MUJOCO_POINTS.items():
        assert len(points) == 5
        for k, t, d in points:
            index = (STIFFNESS.index(k), SAMPLE_TIMES.index(t), DELAYS.index(d))
            assert stable[index] == (verdict == "stable") == heavy_stable[index] and not near[index]
            error = force_error(at_point(base, k, t, d), plant="mujoco_contact", step_at=MUJOCO_STEP_AT)
            assert grows(error) == (verdict == "unstable"), (k, t, d, radius[index])
