"""A sensor's bias and tool identified from readings at rest, against readings written from physics with
Pinocchio's kinematics (the sensor a Pinocchio frame); the compensated wrench at new poses is what counts."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid
from hybrid.control.wrench_sensor import Tool, WrenchSensor, contact_wrench
from hybrid.spec.chain import rotation_rpy

pin = pytest.importorskip("pinocchio")

MASS, COM = 0.5, np.array([0.02, -0.01, 0.08])  # the tool: its centre of mass off the sensor's axis
BIAS = np.array([1.7, -0.9, 2.4, 0.06, -0.035, 0.021])
R_MOUNT, R_RPY = np.array([0.012, -0.021, 0.037]), (0.3, -0.5, 1.1)  # the sensor in tip axes
G = np.array([0.0, 0.0, -9.81])
WEIGHT = MASS * 9.81  # N
MOMENT = WEIGHT * np.linalg.norm(COM)  # N m: the largest moment of the tool's weight about the sensor
#: a pose with the tool pointing down: wrist 3 turns about the vertical
DOWN = np.array([0.0, -np.pi / 2, np.pi / 2, -np.pi / 2, -np.pi / 2, 0.0])


class Arm:
    """The UR5 in Pinocchio with the sensor as one of its frames, and the readings physics gives."""

    def __init__(self, frame: str | None):
        self.model = pin.buildModelFromUrdf(str(hybrid.UR5_URDF))
        self.tip = self.model.getFrameId("tool0")
        if frame is None:
            parent = self.model.frames[self.tip]
            mount = pin.SE3(np.array(rotation_rpy(*R_RPY)), R_MOUNT)
            self.model.addFrame(pin.Frame("sensor", parent.parentJoint, self.tip, parent.placement * mount,
                                          pin.FrameType.OP_FRAME))
            self.sensor = WrenchSensor(position=R_MOUNT, rotation=rotation_rpy(*R_RPY))
        else:
            self.sensor = WrenchSensor(frame=frame)
        self.frame = self.model.getFrameId(frame or "sensor")
        self.data = self.model.createData()

    def poses(self, rng, K: int) -> np.ndarray:
        return rng.uniform(-np.pi, np.pi, (K, 6))

    def placements(self, q):
        pin.framesForwardKinematics(self.model, self.data, q)
        return self.data.oMf[self.tip].copy(), self.data.oMf[self.frame].copy()

    def readings(self, qs, sign: int = 1) -> np.ndarray:
        """At rest, nothing in contact: the sensor holds the tool up against its weight ``m g`` at ``COM``."""
        out = []
        for q in qs:
            g_s = self.placements(q)[1].rotation.T @ G  # gravity in sensor axes
            weight = MASS * g_s
            on_sensor = np.concatenate([weight, np.cross(COM, weight)])  # the tool's wrench on the sensor
            out.append(sign * (BIAS + on_sensor))
        return np.array(out)

    def compensated(self, sensor, qs, readings) -> np.ndarray:
        out = []
        for q, w in zip(qs, readings):
            tip = self.placements(q)[0]
            out.append(contact_wrench(sensor, w, tip.translation, tip.rotation, G, hybrid.ur5()))
        return np.array(out)


@pytest.fixture(scope="module")
def robot():
    return hybrid.ur5()


@pytest.mark.parametrize("frame", [None, "ee_link"], ids=["offset mount", "URDF frame"])
@pytest.mark.parametrize("noise", [0.0, 1.0], ids=["exact", "noisy"])
def test_the_identified_sensor_compensates_the_tool_and_the_bias_at_new_poses(robot, rng, frame, noise):
    arm = Arm(frame)
    q = arm.poses(rng, 30)
    w = arm.readings(q)
    w_noisy = w + noise * rng.normal(0, 1, w.shape) * [0.02, 0.02, 0.02, 0.001, 0.001, 0.001]
    found = hybrid.identify_tool(robot, arm.sensor, q, w_noisy)
    sensor = found.sensor(arm.sensor)
    assert sensor.tool == found.tool and sensor.bias == found.bias and sensor.sign == arm.sensor.sign
    assert found.condition < 5
    new = arm.poses(rng, 20)
    F = arm.compensated(sensor, new, arm.readings(new))
    before = arm.compensated(arm.sensor, new, arm.readings(new))
    assert np.linalg.norm(before[:, :3], axis=1).max() > WEIGHT  # uncompensated, the test would fail
    assert np.linalg.norm(F[:, :3], axis=1).max() < 0.01 * WEIGHT
    assert np.linalg.norm(F[:, 3:], axis=1).max() < 0.01 * MOMENT
    if noise == 0:
        assert abs(found.tool.mass - MASS) < 1e-12
        np.testing.assert_allclose(found.tool.com, COM, atol=1e-12)
        np.testing.assert_allclose(found.bias, BIAS, atol=1e-12)
        assert found.residual_force_N < 1e-12 and found.residual_moment_Nm < 1e-12
    else:
        assert abs(found.tool.mass - MASS) < 0.005 * MASS
        assert np.linalg.norm(np.array(found.tool.com) - COM) < 0.001
        # the residuals are the noise: sqrt(3) sigma per pose, less what the fit absorbs (4 force and 6 moment
        # parameters of 90 numbers each), to within 4 standard deviations of the chi-square
        for got, sigma, p in ((found.residual_force_N, 0.02, 4), (found.residual_moment_Nm, 0.001, 6)):
            assert abs(got / (sigma * np.sqrt(3 * (90 - p) / 90)) - 1) < 4 / np.sqrt(2 * (90 - p))


def test_a_sensor_of_the_opposite_sign(robot, rng):
    arm = Arm(None)
    q = arm.poses(rng, 12)
    w = arm.readings(q, sign=-1)
    minus = WrenchSensor(position=R_MOUNT, rotation=rotation_rpy(*R_RPY), sign=-1)
    found = hybrid.identify_tool(robot, minus, q, w)
    assert abs(found.tool.mass - MASS) < 1e-12
    np.testing.assert_allclose(found.bias, BIAS, atol=1e-12)
    new = arm.poses(rng, 5)
    assert np.abs(arm.compensated(found.sensor(minus), new, arm.readings(new, sign=-1))).max() < 1e-12
    with pytest.raises(hybrid.HybridError, match=r"^readings: the tool's mass comes out -0.5 kg, below zero; the "
                                                 r"readings or the sensor's sign \(\+1\) are likely wrong"):
        hybrid.identify_tool(robot, arm.sensor, q, w)


def test_a_sensor_without_a_tool_within_its_noise_is_a_bias_alone(robot, rng):
    arm = Arm(None)
    q = arm.poses(rng, 12)
    noise = rng.normal(0, 1e-3, (12, 6))
    for _ in range(20):  # until the noise gives a mass below zero
        found = hybrid.identify_tool(robot, arm.sensor, q, BIAS + noise)
        if found.tool.mass == 0:
            break
        noise = rng.normal(0, 1e-3, (12, 6))
    assert found.tool == Tool()
    np.testing.assert_allclose(found.bias, BIAS, atol=2e-3)


def test_turning_about_the_vertical_is_one_orientation_and_near_it_is_ill_conditioned(robot):
    arm = Arm(None)
    turns = np.tile(DOWN, (8, 1))
    turns[:, 5] = np.linspace(-3, 3, 8)  # wrist 3 about the vertical
    with pytest.raises(hybrid.HybridError, match=r"^q: the 8 poses hold the sensor at 1 orientation to gravity; "
                                                 r"give at least 3"):
        hybrid.identify_tool(robot, arm.sensor, turns, arm.readings(turns))
    pan = np.tile(arm.poses(np.random.default_rng(1), 1), (8, 1))
    pan[:, 0] = np.linspace(-3, 3, 8)  # the base about the vertical, the rest held
    with pytest.raises(hybrid.HybridError, match=r"at 1 orientation to gravity"):
        hybrid.identify_tool(robot, arm.sensor, pan, arm.readings(pan))
    tilted = turns.copy()
    tilted[:, 4] += 0.02  # wrist 3's axis 0.02 rad off the vertical: gravity in a narrow cone
    with pytest.raises(hybrid.HybridError, match=r"^q: the poses do not excite the tool's centre of mass \(the "
                                                 r"regressor's condition number is \d+, above max_condition = 100\)"):
        hybrid.identify_tool(robot, arm.sensor, tilted, arm.readings(tilted))
    two = np.vstack([np.tile(DOWN, (4, 1)), np.tile(DOWN + [0, 0, 0, 0, 1.0, 0], (4, 1))])
    with pytest.raises(hybrid.HybridError, match=r"at 2 orientations to gravity"):
        hybrid.identify_tool(robot, arm.sensor, two, arm.readings(two))


def test_turning_about_one_horizontal_axis_identifies_the_tool(robot):
    arm = Arm(None)
    turns = np.tile(DOWN + [0, 0, 0, 0, np.pi / 2, 0], (6, 1))  # wrist 3's axis horizontal
    turns[:, 5] = np.linspace(-3, 3, 6)
    found = hybrid.identify_tool(robot, arm.sensor, turns, arm.readings(turns))
    assert found.condition < 3
    assert abs(found.tool.mass - MASS) < 1e-12
    np.testing.assert_allclose(found.tool.com, COM, atol=1e-12)


def test_tare_zeroes_the_compensated_wrench_with_the_tool_as_it_is(robot, rng):
    arm = Arm(None)
    known = WrenchSensor(position=R_MOUNT, rotation=rotation_rpy(*R_RPY), tool=Tool(MASS, tuple(COM)),
                         bias=(5.0,) * 6)
    q = arm.poses(rng, 6)
    w = arm.readings(q)
    tared = hybrid.tare(known, robot, q[0], w[0])
    assert tared.tool == known.tool and tared.frame == known.frame
    np.testing.assert_allclose(tared.bias, BIAS, atol=1e-12)  # the right tool: the true bias
    assert np.abs(arm.compensated(tared, q, w)).max() < 1e-12  # zero here, and at the other poses
    bare = hybrid.tare(arm.sensor, robot, q[1], w[1])  # no tool: the bias takes its weight at this pose
    assert np.abs(arm.compensated(bare, q[1:2], w[1:2])).max() < 1e-12
    assert np.abs(arm.compensated(bare, q[2:], w[2:])).max() > 0.1
    minus = WrenchSensor(position=R_MOUNT, rotation=rotation_rpy(*R_RPY), sign=-1, tool=Tool(MASS, tuple(COM)))
    np.testing.assert_allclose(hybrid.tare(minus, robot, q[2], -w[2]).bias, BIAS, atol=1e-12)


@pytest.mark.parametrize(("change", "match"), [
    (lambda q, w: (q[:2], w[:2]), r"^q holds 2 poses; give at least 3"),
    (lambda q, w: (q[:, :5], w), r"^q has shape \(6, 5\); give 6 poses of 6 joint positions"),
    (lambda q, w: (q, w[:5]), r"^readings has shape \(5, 6\); give one reading per pose"),
    (lambda q, w: (q, w[:, :3]), r"^readings has shape \(6, 3\)"),
    (lambda q, w: (q, np.where(np.arange(6) == 4, np.nan, w)), r"^readings\[0, 4\] = nan; give finite numbers"),
    (lambda q, w: (np.where(q == q[2, 1], np.inf, q), w), r"^q\[2, 1\] = inf; give finite numbers"),
    (lambda q, w: ("poses", w), r"^q = 'poses'; give 5 poses"),
])
def test_bad_input_is_refused_with_the_value_and_the_fix(robot, rng, change, match):
    arm = Arm(None)
    q = arm.poses(rng, 6)
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.identify_tool(robot, arm.sensor, *change(q, arm.readings(q)))


def test_bad_robot_sensor_or_tare_input_is_refused(robot, rng):
    arm = Arm(None)
    q = arm.poses(rng, 6)
    w = arm.readings(q)
    weightless = hybrid.Robot(robot.name, robot.chain, robot.links, robot.damping, (0.0, 0.0, 0.0), robot.limits)
    with pytest.raises(hybrid.HybridError, match=r"^robot.gravity = \(0.0, 0.0, 0.0\); the tool is weighed"):
        hybrid.identify_tool(weightless, arm.sensor, q, w)
    with pytest.raises(hybrid.HybridError, match=r"^sensor = .*; give a hybrid.WrenchSensor"):
        hybrid.identify_tool(robot, "ft300", q, w)
    with pytest.raises(hybrid.HybridError, match=r"^robot = .*; give a hybrid.Robot"):
        hybrid.tare(arm.sensor, "ur5", q[0], w[0])
    with pytest.raises(hybrid.HybridError, match=r"^reading has shape \(6, 6\); give the raw reading"):
        hybrid.tare(arm.sensor, robot, q[0], w)
    with pytest.raises(hybrid.HybridError, match=r"^max_condition = 0.5; give a number >= 1"):
        hybrid.identify_tool(robot, arm.sensor, q, w, max_condition=0.5)
