"""The Panda experiment (:func:`hybrid.panda_experiment`): the shipped Panda around a pillar on six task
axes, its spare joint held by the posture task; checked against Pinocchio, the arm's limits, the
Python runner and its own file."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from conftest import pinocchio_panda, task_acceleration_gap

import hybrid
from hybrid.models.chain_terms import robot_terms
from hybrid.plants.rigid_body import RigidBodyPlant
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import run

#: the controller's model exact and given R' (the law then makes R v' + R' v the loops' a); the
#: contact keeps its friction: it acts on the sensor tip, and the arm feels only the sensor's
#: spring-damper force, which is what the controller reads at the sample
EXACT = dict(model_error=0.0, viscous_compensation=1.0, curvature=True)




@pytest.fixture(scope="module")
def default_run():
    exp = hybrid.panda_experiment()
    return exp, hybrid.simulate(exp)




def run_checked(exp, x0, q_rest):
    """A run from ``x0`` in which, at every sample, Pinocchio's arm under the controller's torque and
    the sensor's force gives the task acceleration ``R v' + R' v``. Returns its largest difference
    from the loops' ``a``, and per sample the null-space part of ``q_rest - q``: its component along
    the self-motion ``z`` (``J z = 0``) in the inertia metric, ``z^T B e / z^T B z`` [rad], which the
    posture task, projected with the inertia-weighted inverse, drives to 0 (the part of ``e``
    B-orthogonal to ``z`` is the task's to set)."""
    panda = pinocchio_panda()
    pin, model, data, _ = panda
    ctrl = exp.build_controller()
    worst, null = [0.0], []

    def controller(t, q, qdot, Fc):
        tau = ctrl(t, q, qdot, Fc)
        gap, J = task_acceleration_gap(panda, exp, ctrl, q, qdot, Fc, tau)
        worst[0] = max(worst[0], gap)
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        z = np.linalg.svd(J)[2][-1]
        null.append(z @ B @ (q_rest - q) / (z @ B @ z))
        return tau

    run(exp, RigidBodyPlant(exp), controller, x0)
    assert len(null) == exp.n_samples
    return worst[0], np.array(null)


def test_the_task_acceleration_is_the_command_while_the_posture_takes_the_spare_joint_back():
    """Exact model: the task acceleration is the loops' ``a`` at every sample of the whole run. The
    start is moved 0.4 rad along the start pose's self-motion (the experiment's own start, from
    inverse kinematics begun at the rest posture, has 0.01 rad of null-space error to remove): the
    posture takes that back as its critically damped PD at 5 rad/s does, to a twentieth by 1.5 s
    while the tip slides on; the faster path after 1.5 s drags it, to under a quarter of its start.
    Without the posture the spare motion falls under gravity, beyond a radian."""
    exp = hybrid.panda_experiment(**EXACT)
    q_rest = np.array(exp.posture.q_rest)
    x0 = exp.initial_state()
    q0 = x0[:7].copy()
    terms = robot_terms(exp.robot, q0, np.zeros(7))
    z = np.linalg.svd(terms["J"])[2][-1]
    z *= -np.sign(z[6])  # the SVD's sign is arbitrary: joint 7 decreasing, away from its upper limit
    x0[:7] = exp.robot.inverse_kinematics(terms["r"], terms["rotation"], q0=q0 + 0.4 * z)

    worst, null = run_checked(exp, x0, q_rest)
    assert worst < 1e-7
    assert null[0] > 0.3
    t = np.arange(len(null)) * exp.sample_time
    first = t < 1.5
    pd = null[0] * (1 + 5 * t) * np.exp(-5 * t)  # the critically damped PD from rest
    assert np.abs(null - pd)[first].max() < 0.05 * null[0]
    assert abs(null[round(1.5 / exp.sample_time)]) < 0.05 * null[0]
    assert np.abs(null[~first]).max() < 0.25 * null[0]

    worst_off, null_off = run_checked(replace(exp, posture=None), x0, q_rest)
    assert worst_off < 1e-7
    assert np.abs(null_off).max() > 1.0


def test_the_default_run_reports_every_metric_within_the_arms_limits(default_run):
    """The metrics of the other experiments, one peak torque per joint, all finite (both references
    step within the run); in contact throughout, on its references at the end; every joint 0.5 rad
    inside its limits, below 30 % of its speed limit and 60 % of its rating; the Jacobian's
    conditioning above 0.18 at every sample; the tip 55 degrees around the pillar at the end."""
    exp, res = default_run
    m = res.metrics
    tracing = hybrid.simulate(hybrid.tracing_experiment()).metrics
    assert set(tracing) <= set(m) and set(m) - set(tracing) == {"peak_torque_joint7_Nm"}  # the UR5 has 6
    assert np.isfinite(list(m.values())).all()
    assert m["contact_losses"] == 0 and m["time_out_of_contact_s"] == 0.0
    assert abs(m["steady_state_force_error_N"]) < 0.01 and abs(m["steady_state_speed_error_m_per_s"]) < 1e-3

    limits, samples = exp.robot.limits, res.q[::exp.steps_per_sample]
    assert len(samples) == exp.n_samples + 1
    assert np.minimum(res.q - limits.lower, limits.upper - res.q).min() > 0.5
    assert (np.abs(res.qdot).max(axis=0) < 0.3 * limits.velocity).all()
    peaks = np.array([m[f"peak_torque_joint{j + 1}_Nm"] for j in range(7)])
    assert (peaks < 0.6 * limits.effort).all()
    assert exp.robot.conditioning(samples).min() > 0.18

    # the arm tip, whose speed the loops set, runs 1.5 cm inside the surface (the sensor spring's 15 N)
    d = res.outputs[[0, -1], :2] - np.array(exp.surface.point)[:2]
    turned = np.mod(np.arctan2(d[1, 1], d[1, 0]) - np.arctan2(d[0, 1], d[0, 0]), 2 * np.pi)
    assert np.linalg.norm(d[1]) == pytest.approx(0.25 - 0.015, abs=1e-3)
    assert np.degrees(turned) == pytest.approx(np.degrees(0.225 / np.linalg.norm(d[1])), abs=0.5)


def test_the_arm_stays_clear_of_the_pillar(default_run):
    """Every joint of the arm (Pinocchio's frames of links 2 to 7, and the midpoints between them)
    stays more than 0.1 m outside the pillar over the whole run; only the hand reaches towards it."""
    exp, res = default_run
    pin, model, data, _ = pinocchio_panda()
    frames = [model.getFrameId(f"panda_link{i}") for i in range(2, 8)]
    axis, radius = np.array(exp.surface.point)[:2], exp.surface.radius
    gaps = []
    for q in res.q[::exp.steps_per_sample]:
        pin.framesForwardKinematics(model, data, q)
        p = np.array([data.oMf[f].translation for f in frames])
        points = np.concatenate([p, 0.5 * (p[1:] + p[:-1])])
        gaps.append(np.linalg.norm(points[:, :2] - axis, axis=1).min() - radius)
    assert min(gaps) > 0.1


def test_the_compiled_loop_and_the_python_runner_agree_and_the_result_loads_back(default_run, tmp_path):
    exp, res = default_run
    assert closed_loop.prepare(exp, exp.initial_state()) is not None  # else both runs would be Python's
    slow = hybrid.simulate(exp, compiled=False)
    scale = np.abs(slow.state).max(axis=0) + 1e-3
    assert np.abs((res.state - slow.state) / scale).max() < 1e-7
    assert res.metrics["rms_force_error_N"] == pytest.approx(slow.metrics["rms_force_error_N"], rel=1e-6)

    back = hybrid.SimulationResult.load(res.save(tmp_path / "panda"))
    assert back.experiment == exp  # the Panda, the pillar, its path and the posture as they were
    for name in ("t", "state", "tau", "outputs", "force_reference", "speed_reference"):
        np.testing.assert_array_equal(getattr(back, name), getattr(res, name))
    assert back.record == res.record
    assert list(back.metrics) == list(res.metrics)
    np.testing.assert_array_equal(list(back.metrics.values()), list(res.metrics.values()))
    np.testing.assert_array_equal(hybrid.simulate(back.experiment).state, res.state)  # the same run again


def test_the_factory_takes_the_settings_the_others_take():
    exp = hybrid.panda_experiment()
    assert exp.robot == hybrid.panda() and len(exp.build_controller().axes) == 6
    assert exp.posture == hybrid.Posture(exp.posture.q_rest)
    assert exp.integration_step == 1e-4 and exp.sample_time == 1e-2
    np.testing.assert_allclose(exp.start(), exp.followed_path().point_at(exp.followed_path().start), atol=1e-12)

    tuned = hybrid.panda_experiment(KPv=50.0, F_d=12.0, v_d=hybrid.Step(0.02, 0.04, 1.0), posture=None)
    assert tuned.gains == replace(hybrid.Gains(), KPv=50.0) and tuned.posture is None
    assert tuned.force_reference == hybrid.Step(12.0, 12.0, 0.0) and tuned.speed_reference.after == 0.04

    # another pillar: the path is the circle around it, through the default start moved onto it
    pillar = hybrid.Cylinder((0.75, 0.05, 0.0), (0.0, 0.0, 1.0), 0.3)
    moved = hybrid.panda_experiment(surface=pillar)
    start = np.array(moved.start_point)
    assert pillar.project(start) == pytest.approx(start) and start[2] == pytest.approx(0.78)
    path = moved.followed_path()
    assert path.radius == 0.3 and np.allclose(path.point_at(path.start), start)
    through = hybrid.panda_experiment(start_point=tuple(exp.surface.project((0.45, -0.1, 0.75))))
    assert np.allclose(through.followed_path().point_at(through.followed_path().start), through.start_point)

    with pytest.raises(hybrid.HybridError, match="unknown setting.*for panda_experiment"):
        hybrid.panda_experiment(latitude=30.0)
    tilted = hybrid.Cylinder((0.7, 0.0, 0.0), (1.0, 0.0, 1.0), 0.25)  # no circle around it to follow
    assert hybrid.panda_experiment(surface=tilted).followed_path() is None
    with pytest.raises(hybrid.HybridError, match="frame='desired' follows the experiment's path"):
        hybrid.panda_experiment(surface=tilted, frame="desired")
