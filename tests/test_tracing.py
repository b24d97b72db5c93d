"""The 3-D experiment (conventions §10) checked against physics and against Pinocchio."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import UR5, example_robot

import hybrid
from hybrid import oracle
from hybrid.models.shipped import UR5_URDF
from hybrid.plants.rigid_body import RigidBodyPlant
from hybrid.simulation.runner import run

EXACT = dict(model_error=0.0, viscous_compensation=1.0, contact=hybrid.Contact(friction=0.0))


def last(res, y, span=0.3):
    return y[res.t >= res.t[-1] - span]


@pytest.fixture(scope="module")
def exact_runs():
    runs = {}
    for name, kw in {"plain": dict(integral=False), "curvature": dict(integral=False, curvature=True),
                     "integral": dict(integral=True)}.items():
        exp = hybrid.tracing_experiment(**EXACT, **kw)
        runs[name] = (exp, hybrid.simulate(exp))
    return runs


def test_missing_curvature_leaves_the_centripetal_force_error(exact_runs):
    """Exact model, no friction, no integral: F_c,n settles m_d v^2 / rho_r short (the normal curvature
    of a sphere is 1 / radius in every direction; rho_r the arm tip's distance from the centre)."""
    exp, res = exact_runs["plain"]
    rho_r = np.linalg.norm(last(res, res.outputs[:, :3]) - np.array(exp.surface.center), axis=1)
    predicted = np.mean(last(res, res.velocity_tangential) ** 2 / exp.gains.KPf / rho_r)
    error = np.mean(last(res, res.force_reference - res.force_normal))
    assert error == pytest.approx(predicted, rel=0.1)
    assert predicted > 0.25


@pytest.mark.parametrize("fix", ["curvature", "integral"])
def test_curvature_term_or_integral_action_removes_it(exact_runs, fix):
    _, res = exact_runs[fix]
    assert abs(np.mean(last(res, res.force_reference - res.force_normal))) < 0.03


def latitude_drift(exp, res):
    """How far the arm tip has left its latitude circle at the end (along t2, the meridian) [m]."""
    r = last(res, res.outputs[:, :3]) - np.array(exp.surface.center)
    polar = np.arccos(r[:, 2] / np.linalg.norm(r, axis=1))
    latitude = np.arccos((exp.followed_path().center[2] - exp.surface.center[2]) / exp.surface.radius)
    return abs(np.mean(polar) - latitude) * np.mean(np.linalg.norm(r, axis=1))


def test_the_t2_drift_vanishes_with_the_double_integral(exact_runs):
    """The latitude circle is no geodesic: without R' the t2 loop must supply its geodesic curvature;
    PI only (integral=False) leaves a position drift along t2, PI^2 removes it."""
    pi_only = latitude_drift(*exact_runs["plain"])
    pi2 = latitude_drift(*exact_runs["integral"])
    assert pi_only > 1e-3
    assert pi2 < 0.2 * pi_only


def test_closed_loop_task_acceleration_equals_the_command():
    """Exact model: at every sample, Pinocchio's arm under the applied torque and the sensor's force
    accelerates the task coordinates exactly as the loops command (R v' + R' v = a)."""
    pin = pytest.importorskip("pinocchio")
    exp = hybrid.tracing_experiment(**EXACT, curvature=True, duration=0.3)
    model = pin.buildModelFromUrdf(str(UR5_URDF))
    data, fid, damping = model.createData(), model.getFrameId("tool0"), np.array(exp.robot.damping)
    ctrl = hybrid.Controller.from_experiment(exp)
    worst, samples = [0.0], [0]

    def controller(t, q, qdot, Fc):
        tau = ctrl(t, q, qdot, Fc)
        pin.forwardKinematics(model, data, q, qdot, np.zeros(6))
        pin.updateFramePlacements(model, data)
        J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)
        Jdqd = pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector
        qdd = pin.aba(model, data, q, qdot, tau + J[:3].T @ Fc[:3] - damping * qdot)
        v, vdot = J @ qdot, J @ qdd + Jdqd
        R, Rd = oracle.spatial_frame(exp.surface, data.oMf[fid].translation, v[:3], (0, 0, 1))
        Z = np.zeros((3, 3))
        y_dot = np.block([[R, Z], [Z, R]]) @ vdot + np.block([[Rd, Z], [Z, Rd]]) @ v
        worst[0] = max(worst[0], np.abs(y_dot - ctrl.last["a"]).max())
        samples[0] += 1
        return tau

    plant = RigidBodyPlant(exp)
    run(exp, plant, controller, exp.initial_state())
    assert samples[0] == exp.n_samples
    assert worst[0] < 1e-7


def test_three_schemes_run_and_differ():
    m = {c: hybrid.simulate(hybrid.tracing_experiment(controller=c, duration=1.0)).metrics
         for c in ("task", "khatib", "raibert_craig")}
    for scheme in m.values():
        assert scheme["contact_losses"] == 0 and np.isfinite(scheme["rms_force_error_N"])
    # no dynamic decoupling: Raibert & Craig's force loop fights the arm's dynamics
    assert m["raibert_craig"]["rms_force_error_N"] > 2 * m["task"]["rms_force_error_N"]


def test_the_shipped_ur5_is_example_robot_datas():
    assert UR5_URDF.read_bytes() == example_robot(UR5[0]).read_bytes()


@pytest.mark.parametrize("kwargs, words", [
    (dict(bogus=1), "unknown setting"),
    (dict(start_point=(0.9, 0.9, 0.9)), "off the surface"),
    (dict(surface=hybrid.Sphere((2.0, 0.0, 0.2), 0.15)), "cannot be reached"),
    (dict(surface=hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.0, 1.0))), "start_point"),
    (dict(controller="pid"), "unknown controller"),
    (dict(integration_step=1e-2), "too large for the contact"),
])
def test_bad_settings_are_named(kwargs, words):
    with pytest.raises(hybrid.HybridError, match=words):
        hybrid.simulate(hybrid.tracing_experiment(**kwargs))


@pytest.mark.parametrize("kwargs, words", [
    (dict(latitude=0.0), "latitude"), (dict(latitude=200.0), "latitude"),
    (dict(frame_direction="abc"), "frame_direction"), (dict(frame_direction=(0, 1)), "frame_direction"),
])
def test_bad_tracing_settings_are_named(kwargs, words):
    with pytest.raises(hybrid.HybridError, match=words):
        hybrid.tracing_experiment(**kwargs)
