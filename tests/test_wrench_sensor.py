"""A force/torque sensor on the controller's side: its reading turned into the contact wrench.

References: the frames from Pinocchio (the sensor a frame of the UR5's model), the tool's weight and the
lever written here from statics, the filter's frequency response measured on a sine, and the controller
without a sensor (a sensor at the tip with nothing on it changes nothing but rounding).
"""

from __future__ import annotations

import numpy as np
import pytest

import hybrid
from hybrid.control.wrench_sensor import contact_wrench, filter_coefficients, reading_of

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)


def rot(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


MOUNT = dict(position=(0.01, -0.02, 0.05), rotation=rot((1, 2, 3), 0.7))
TOOL = hybrid.Tool(0.5, (0.02, -0.01, 0.08))


@pytest.fixture(scope="module")
def ur5_pin():
    import pinocchio as pin

    robot = hybrid.ur5()
    model = pin.buildModelFromUrdf(str(hybrid.UR5_URDF))
    tip = model.getFrameId("tool0")
    placement = pin.SE3(np.asarray(MOUNT["rotation"]), np.array(MOUNT["position"]))
    frame = pin.Frame("sensor", model.frames[tip].parentJoint, tip, model.frames[tip].placement * placement,
                      pin.FrameType.OP_FRAME)
    sid = model.addFrame(frame)
    return robot, model, tip, sid


def test_reading_to_contact_wrench_against_pinocchio_and_statics(rng, ur5_pin):
    import pinocchio as pin

    robot, model, tip, sid = ur5_pin
    data = model.createData()
    sensor = hybrid.WrenchSensor(**MOUNT, tool=TOOL, bias=(0.3, -0.2, 0.5, 0.01, 0.02, -0.03))
    g = np.array(robot.gravity)
    ctrl = hybrid.Controller(robot, SPHERE, wrench_sensor=sensor, timing_tolerance=None)
    for _ in range(20):
        q = rng.uniform(-np.pi, np.pi, 6)
        pin.framesForwardKinematics(model, data, q)
        R_s, p_s = data.oMf[sid].rotation, data.oMf[sid].translation
        p = data.oMf[tip].translation
        F = rng.normal(0, 10, 6)  # the environment's wrench on the robot at the tip, base axes
        # statics, sensor axes: the tool side pushes on the sensor with the environment's wrench and the weight
        f_env = R_s.T @ F[:3]
        m_env = R_s.T @ (F[3:] + np.cross(p - p_s, F[:3]))
        weight = TOOL.mass * (R_s.T @ g)
        reading = np.concatenate([f_env + weight, m_env + np.cross(TOOL.com, weight)]) + np.array(sensor.bias)
        seen = ctrl.measure(q, np.zeros(6), reading)
        np.testing.assert_allclose(seen.contact_wrench, F, atol=1e-10)
        np.testing.assert_allclose(seen.compensated, np.concatenate([f_env, m_env]), atol=1e-10)
        np.testing.assert_allclose(reading_of(sensor, F, p, data.oMf[tip].rotation, g), reading, atol=1e-10)
        np.testing.assert_allclose(contact_wrench(sensor, reading, p, data.oMf[tip].rotation, g), F, atol=1e-10)
        flipped = hybrid.WrenchSensor(**MOUNT, tool=TOOL, bias=sensor.bias, sign=-1)
        np.testing.assert_allclose(contact_wrench(flipped, -reading, p, data.oMf[tip].rotation, g), F, atol=1e-10)


@pytest.mark.parametrize("order", [1, 2])
def test_filter_is_minus_3_db_at_its_cutoff(order):
    T, fc = 1e-3, 40.0
    b0, b1, b2, a1, a2 = filter_coefficients(fc, order, T)
    for f, want in ((fc, 1 / np.sqrt(2)), (0.0, 1.0)):
        z = np.exp(-2j * np.pi * f * T)
        assert abs((b0 + b1 * z + b2 * z * z) / (1 + a1 * z + a2 * z * z)) == pytest.approx(want, rel=1e-12)
    # and the controller's filter, measured on a sine through its step (steady state, after the transient)
    robot = hybrid.paper_arm()
    sensor = hybrid.WrenchSensor(cutoff=fc, order=order)
    ctrl = hybrid.Controller(robot, hybrid.Circle((1.0, 0.0), 0.5), wrench_sensor=sensor, sample_time=T)
    q = np.array([2.2, 1.9])
    # the reading's x axis in base axes at this pose (the sensor turns with the tip)
    d = ctrl.measure(q, np.zeros(2), np.array([1.0, 0, 0, 0, 0, 0])).contact_wrench[:3]
    t = np.arange(4000) * T
    x = 10 + np.sin(2 * np.pi * fc * t)
    y = []
    for tk, xk in zip(t, x):
        ctrl(tk, q, np.zeros(2), np.array([xk, 0, 0, 0, 0, 0]))
        y.append(ctrl.last["contact_wrench"][:3] @ d)
    y = np.array(y)[2000:] - 10
    amplitude = np.sqrt(2 * np.mean(y ** 2))
    assert amplitude == pytest.approx(1 / np.sqrt(2), rel=1e-2)
    assert ctrl.last is not None


def test_a_bare_sensor_at_the_tip_is_no_sensor(rng):
    """With the sensor at the tip (reading in tip axes), no tool, no bias, no filter, the controller is the
    one without a sensor over a recorded run of the 3-D experiment (to rounding)."""
    exp = hybrid.tracing_experiment(duration=0.3)
    r = hybrid.simulate(exp)
    plant = exp.plant()
    plain = exp.build_controller()
    base = exp.build_controller()
    with_sensor = hybrid.Controller(base.robot, exp.surface, base.scheme, axes=base.axes, selection=("n",),
                                    gains=exp.gains, force_reference=exp.force_reference,
                                    velocity_reference=exp.speed_reference, sample_time=exp.sample_time,
                                    curvature=exp.curvature, wrench_sensor=hybrid.WrenchSensor())
    for k in range(exp.n_samples):
        x = r.state[k * exp.steps_per_sample]
        F = plant.sensor_wrench(x)
        R = hybrid.arm_terms(base.robot, x[:6], x[6:12])["rotation"]
        a = plain(k * exp.sample_time, x[:6], x[6:12], F)
        b = with_sensor(k * exp.sample_time, x[:6], x[6:12], np.concatenate([R.T @ F[:3], R.T @ F[3:]]))
        np.testing.assert_allclose(b, a, rtol=1e-12, atol=1e-12 * np.abs(a).max())


def test_the_standalone_c_reads_the_sensor_as_python(tmp_path, rng):
    from test_standalone_controller import CController

    sensor = hybrid.WrenchSensor(**MOUNT, tool=TOOL, bias=(0.3, -0.2, 0.5, 0.01, 0.02, -0.03), cutoff=15.0, order=2)
    exp = hybrid.tracing_experiment(duration=0.3)
    base = exp.build_controller()
    py = hybrid.Controller(base.robot, exp.surface, selection=("n",), gains=exp.gains,
                           force_reference=exp.force_reference, velocity_reference=exp.speed_reference,
                           wrench_sensor=sensor)
    py.generate(tmp_path, "ur5sensor")
    c = CController(tmp_path, "ur5sensor")
    r = hybrid.simulate(exp)
    plant = exp.plant()
    for k in range(exp.n_samples):
        x = r.state[k * exp.steps_per_sample]
        terms = hybrid.arm_terms(base.robot, x[:6], x[6:12])
        reading = reading_of(sensor, plant.sensor_wrench(x), terms["r"], terms["rotation"], base.robot.gravity)
        reading = reading + rng.normal(0, 0.2, 6)
        tau = py(k * exp.sample_time, x[:6], x[6:12], reading)
        status, tau_c = c.step(k * exp.sample_time, x[:6], x[6:12], reading)
        assert status == 0
        np.testing.assert_allclose(tau_c, tau, rtol=1e-12, atol=1e-12 * np.abs(tau).max())


def test_bad_sensors_are_refused():
    robot = hybrid.ur5()
    for kw, match in (({"rotation": np.eye(3) * 2}, "rotation"), ({"sign": 0}, "sign"), ({"cutoff": -1.0}, "cutoff"),
                      ({"order": 3}, "order"), ({"bias": (1, 2)}, "bias"), ({"tool": 1.0}, "tool")):
        with pytest.raises(hybrid.HybridError, match=match):
            hybrid.WrenchSensor(**kw)
    with pytest.raises(hybrid.HybridError, match="mass"):
        hybrid.Tool(-0.1)
    with pytest.raises(hybrid.HybridError, match="Nyquist"):
        hybrid.Controller(robot, SPHERE, wrench_sensor=hybrid.WrenchSensor(cutoff=50.0), sample_time=0.01)
    ctrl = hybrid.Controller(robot, SPHERE)
    with pytest.raises(hybrid.HybridError, match="wrench_sensor"):
        ctrl.set_wrench_sensor(hybrid.WrenchSensor())
