"""A start the arm can reach within its joint limits (``Experiment.q0``, the limits' check), and runs
that say when they leave the robot's limits (``JointLimitWarning``, ``SimulationResult.limit_violations``)."""

from __future__ import annotations

import json
import warnings
from dataclasses import replace

import numpy as np
import pytest
from conftest import example_robot

import hybrid
from hybrid.models.urdf import JointLimits
from hybrid.simulation.limits import limit_violations

#: the Kinova Jaco2 (6 joints, two fingers off the chain) of example-robot-data
JACO = ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector")
#: a table under the Jaco2, and the point it starts pressing on
TABLE, START = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.0, 1.0)), (0.4, 0.0, 0.1)


@pytest.fixture(scope="module")
def jaco():
    return hybrid.Robot.from_urdf(example_robot(JACO[0]), tip=JACO[1])


def jaco_experiment(robot, **settings):
    return hybrid.Experiment(robot=robot, surface=TABLE, start_point=START, frame_direction=(1.0, 0.0, 0.0),
                             **settings)


def within(robot, q) -> bool:
    return bool(np.all((robot.limits.lower <= q) & (q <= robot.limits.upper)))


def tip_pose(robot, q):
    terms = hybrid.arm_terms(robot, np.asarray(q, float), np.zeros(robot.n))
    return terms["r"], terms["rotation"]


def assert_pressing_at_start(robot, q):
    """The tip frame of ``q`` on the normal through the start point (the arm tip pressed a little into the
    surface, the sensor between), its z axis along -n."""
    normal, point = np.array(TABLE.normal), np.array(START)
    r, rotation = tip_pose(robot, q)
    offset = r - point
    assert np.linalg.norm(np.cross(offset, normal)) < 1e-6 and abs(offset @ normal) < 0.05
    np.testing.assert_allclose(rotation[:, 2], -normal, atol=1e-6)


# ------------------------------------------------------------------------------------- the start


def test_the_jaco2s_start_is_within_its_limits_or_refused_naming_the_joint(jaco):
    q = jaco_experiment(jaco).initial_state()[:jaco.n]
    assert within(jaco, q)
    assert_pressing_at_start(jaco, q)
    # the same pose from the middle of the ranges, the inverse kinematics' own default seed, is a branch
    # outside joint 2's range [0.82, 5.46] rad: a q0 there is refused, naming the joint, its value and range
    outside = jaco.inverse_kinematics(*tip_pose(jaco, q))
    np.testing.assert_allclose(tip_pose(jaco, outside)[0], tip_pose(jaco, q)[0], atol=1e-8)
    assert not within(jaco, outside)
    j = int(np.flatnonzero((outside < jaco.limits.lower) | (outside > jaco.limits.upper))[0])
    with pytest.raises(hybrid.HybridError, match="outside its limits") as info:
        jaco_experiment(jaco, q0=tuple(outside)).initial_state()
    message = str(info.value)
    assert jaco.joint_names[j] in message and f"{outside[j]:.4g}" in message and "q0" in message
    assert f"{jaco.limits.lower[j]:.4g}" in message and f"{jaco.limits.upper[j]:.4g}" in message
    # a q0 near a start within the limits is taken: the start near it, within the limits
    near = q + 0.05
    q_near = jaco_experiment(jaco, q0=tuple(near)).initial_state()[:jaco.n]
    assert within(jaco, q_near) and np.abs(q_near - near).max() < 0.2
    assert_pressing_at_start(jaco, q_near)


def test_q0_picks_the_inverse_kinematics_branch():
    exp = hybrid.tracing_experiment()
    robot = exp.robot
    q_default = exp.initial_state()[:robot.n]
    pose = tip_pose(robot, q_default)
    # another solution of the same tip pose, from seeds spread over the joint ranges
    rng = np.random.default_rng(3)
    for seed in rng.uniform(-np.pi, np.pi, (40, robot.n)):
        try:
            other = robot.inverse_kinematics(*pose, q0=seed)
        except hybrid.HybridError:
            continue
        if np.abs(other - q_default).max() > 0.5 and within(robot, other):
            break
    else:
        pytest.fail("no second branch of the UR5's start pose found")
    q_other = replace(exp, q0=tuple(other)).initial_state()[:robot.n]
    np.testing.assert_allclose(q_other, other, atol=1e-6)
    assert np.abs(q_other - q_default).max() > 0.5
    for a, b in zip(tip_pose(robot, q_other), pose):  # the same pose by forward kinematics
        np.testing.assert_allclose(a, b, atol=1e-8)


def test_q0_is_saved_with_the_experiment():
    exp = hybrid.tracing_experiment(q0=(0.1, -1.2, 1.5, -1.9, -1.6, 0.3))
    back = hybrid.Experiment.from_dict(json.loads(json.dumps(exp.to_dict())))
    assert back == exp and back.q0 == exp.q0
    np.testing.assert_array_equal(back.initial_state(), exp.initial_state())
    # without a seed the saved settings are as before the setting existed
    assert "q0" not in hybrid.tracing_experiment().to_dict()
    assert hybrid.Experiment.from_dict(hybrid.tracing_experiment().to_dict()).q0 is None


@pytest.mark.parametrize("q0", [(0.1, 0.2), (0.0,) * 7, (np.nan,) * 6, "0 0 0 0 0 0", ("a",) * 6,
                                (True,) * 6, 1.0, ((0.0,) * 6,)])
def test_a_bad_q0_is_refused(q0):
    with pytest.raises(hybrid.HybridError, match=r"q0 = .*one finite joint position per joint"):
        hybrid.tracing_experiment(q0=q0)


def test_the_planar_arm_takes_no_q0():
    with pytest.raises(hybrid.HybridError, match="elbow"):
        hybrid.paper_experiment(q0=(0.5, 1.0))


# ------------------------------------------------------------------------------------- redundancy


def test_a_redundant_arm_without_a_posture_is_warned():
    with pytest.warns(hybrid.RedundancyWarning, match=r"7 joints for 6 task axes.*hybrid\.Posture") as record:
        hybrid.panda_experiment(posture=None)
    assert record[0].filename == __file__  # told at the caller's line
    with pytest.warns(hybrid.RedundancyWarning, match="6 joints for 3 task axes") as record:
        replace(hybrid.tracing_experiment(), axes="position")
    assert record[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error", hybrid.RedundancyWarning)
        hybrid.panda_experiment()  # with its posture
        hybrid.tracing_experiment()  # 6 joints, 6 axes
        hybrid.paper_experiment()


# ------------------------------------------------------------------------------------- the run's limits


def test_limit_violations_of_made_up_series(jaco):
    """Joint 2 leaves its upper bound from row 3 to 5 by at most 0.2 rad; joint 5 runs at twice its speed limit
    in row 7 alone; joint 1's torque sits at its limit (saturated) in rows 8-9: the truth by construction."""
    lim, n, rows = jaco.limits, jaco.n, 10
    t = np.arange(rows) * 0.01
    q = np.tile(0.5 * (np.clip(lim.lower, -1, 1) + np.clip(lim.upper, -1, 1)), (rows, 1))
    q[3:6, 1] = lim.upper[1] + np.array([0.1, 0.2, 0.05])
    qdot = np.zeros((rows, n))
    qdot[7, 4] = -2 * lim.velocity[4]
    tau = np.zeros((rows, n))
    tau[0] = np.nan  # a torque not computed
    tau[8:, 0] = lim.effort[0]
    found = limit_violations(jaco, t, q, qdot, tau)
    assert set(found) == {"position", "velocity", "effort"}
    p, v, e = found["position"], found["velocity"], found["effort"]
    assert (p.joint, p.limit, p.first_time, p.fraction) == (jaco.joint_names[1], lim.upper[1], t[3], 0.3)
    assert p.value == pytest.approx(lim.upper[1] + 0.2)
    assert (v.joint, v.value, v.limit, v.first_time, v.fraction) == (
        jaco.joint_names[4], 2 * lim.velocity[4], lim.velocity[4], t[7], 0.1)
    assert (e.joint, e.value, e.limit, e.first_time, e.fraction) == (
        jaco.joint_names[0], lim.effort[0], lim.effort[0], t[8], 0.2)
    assert limit_violations(jaco, t, q[:3], qdot[:3], tau[:3] * 0.5) == {}


def test_a_run_beyond_a_velocity_limit_warns_and_says_where():
    ur5 = hybrid.ur5()
    lim = ur5.limits
    slow = replace(ur5, limits=JointLimits(lim.lower, lim.upper, lim.velocity * 0.1, lim.effort))
    with pytest.warns(hybrid.JointLimitWarning) as record:
        result = hybrid.simulate(hybrid.tracing_experiment(robot=slow, duration=1.0))
    # the truth from the run's own joint rates
    ratio = np.abs(result.qdot) / slow.limits.velocity
    worst = int(np.unravel_index(np.argmax(ratio), ratio.shape)[1])
    assert ratio.max() > 1
    found = result.limit_violations["velocity"]
    assert found.joint == ur5.joint_names[worst]
    assert found.value == pytest.approx(np.abs(result.qdot[:, worst]).max())
    assert found.first_time == result.t[np.argmax(ratio[:, worst] > 1)]
    assert found.fraction == pytest.approx(np.mean((ratio > 1).any(axis=1)))
    message = str(record[0].message)
    assert ur5.joint_names[worst] in message and "velocity" in message and f"{found.first_time:.3f} s" in message


def test_a_torque_held_at_its_limit_counts_as_out():
    """The controller saturates its torque at the URDF's effort: a run that asks for more is at the limit."""
    ur5 = hybrid.ur5()
    lim = ur5.limits
    weak = replace(ur5, limits=JointLimits(lim.lower, lim.upper, lim.velocity, lim.effort * 0.2))
    with pytest.warns(hybrid.JointLimitWarning, match="effort.*saturated") as record:
        result = hybrid.simulate(hybrid.tracing_experiment(robot=weak, duration=0.5))
    assert record[0].filename == __file__  # told at the caller's line
    at = np.abs(result.tau) >= weak.limits.effort * (1 - 1e-9)
    assert at.any()
    found = result.limit_violations["effort"]
    assert found.value == pytest.approx(found.limit) and found.fraction == pytest.approx(at.any(axis=1).mean())


@pytest.mark.parametrize("factory", [hybrid.paper_experiment, hybrid.tracing_experiment, hybrid.panda_experiment])
def test_the_default_experiments_stay_within_their_limits(factory):
    with warnings.catch_warnings():
        warnings.simplefilter("error", hybrid.JointLimitWarning)
        result = hybrid.simulate(factory())
    lim = result.experiment.robot.limits
    assert np.all((lim.lower <= result.q) & (result.q <= lim.upper))
    assert np.all(np.abs(result.qdot) <= lim.velocity) and np.all(np.abs(result.tau) < lim.effort)
    assert result.limit_violations == {}
