"""A sensor mounted at a URDF frame: its pose in tip axes against Pinocchio's frame placements."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid
from hybrid.control.wrench_sensor import WrenchSensor
from hybrid.models.urdf import rigid_offset

pin = pytest.importorskip("pinocchio")

CASES = [  # (file, tip, frames rigidly attached to it: a sibling, the parent, a child, a grandparent ...)
    (hybrid.UR5_URDF, "tool0", ("ee_link", "wrist_3_link", "tool0")),
    (hybrid.PANDA_URDF, "panda_hand_tcp", ("panda_hand", "panda_link8", "panda_hand_tcp")),
    (hybrid.PANDA_URDF, "panda_link8", ("panda_hand", "panda_hand_tcp")),
]


@pytest.mark.parametrize(("path", "tip", "frames"), CASES, ids=lambda v: getattr(v, "name", str(v)))
def test_the_offset_is_pinocchios_placement_of_the_frame_in_the_tip(path, tip, frames, rng):
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    offsets = {f: rigid_offset(path, tip, f) for f in frames}
    for _ in range(5):  # rigid: the same at every q
        q = rng.uniform(model.lowerPositionLimit, model.upperPositionLimit)
        pin.framesForwardKinematics(model, data, q)
        for f, (r, R) in offsets.items():
            M = data.oMf[model.getFrameId(tip)].inverse() * data.oMf[model.getFrameId(f)]
            np.testing.assert_allclose(r, M.translation, atol=1e-12)
            np.testing.assert_allclose(R, M.rotation, atol=1e-12)
    r, R = rigid_offset(path, tip, tip)
    assert np.array_equal(r, np.zeros(3)) and np.array_equal(R, np.eye(3))


def test_the_mount_of_a_sensor_named_by_frame_is_the_offset():
    robot = hybrid.ur5()
    r, R = WrenchSensor(frame="ee_link").mount(robot)
    r0, R0 = rigid_offset(hybrid.UR5_URDF, "tool0", "ee_link")
    assert np.array_equal(r, r0) and np.array_equal(R, R0)
    assert not np.allclose(R, np.eye(3))  # ee_link is turned from tool0: the test sees the rotation


def test_a_locked_joint_counts_as_fixed():
    model = pin.buildModelFromUrdf(str(hybrid.PANDA_URDF))
    data = model.createData()
    q = pin.neutral(model)
    q[model.joints[model.getJointId("panda_finger_joint1")].idx_q] = 0.03
    pin.framesForwardKinematics(model, data, q)
    M = data.oMf[model.getFrameId("panda_hand_tcp")].inverse() * data.oMf[model.getFrameId("panda_leftfinger")]
    r, R = rigid_offset(hybrid.PANDA_URDF, "panda_hand_tcp", "panda_leftfinger", {"panda_finger_joint1": 0.03})
    np.testing.assert_allclose(r, M.translation, atol=1e-12)
    np.testing.assert_allclose(R, M.rotation, atol=1e-12)


@pytest.mark.parametrize(("path", "tip", "frame", "match"), [
    (hybrid.UR5_URDF, "tool0", "base_link",
     r"^frame = 'base_link' is not rigidly attached to the tip 'tool0'; give a frame joined to it by fixed joints "
     r"only\n  the sensor must be rigidly attached to the tip's link: .*moves with joint 'wrist_3_joint' \(revolute\)"),
    (hybrid.UR5_URDF, "tool0", "forearm_link", r"moves with joint 'wrist_3_joint'"),
    (hybrid.PANDA_URDF, "panda_hand_tcp", "panda_leftfinger",
     r"moves with joint 'panda_finger_joint1' \(prismatic\); a joint held still can be locked"),
    (hybrid.UR5_URDF, "tool0", "ee_lnk",
     r"^frame = 'ee_lnk' is not a link of ur5_robot.urdf; .*did you mean 'ee_link'"),
    (hybrid.UR5_URDF, "tool1", "ee_link", r"^tip = 'tool1' is not a link of ur5_robot.urdf; .*did you mean 'tool0'"),
])
def test_a_frame_not_rigidly_attached_or_not_in_the_file_is_refused(path, tip, frame, match):
    with pytest.raises(hybrid.URDFError, match=match):
        rigid_offset(path, tip, frame)


def test_a_sensor_frame_on_a_robot_not_read_from_a_urdf_is_refused():
    robot = hybrid.Robot.planar(hybrid.paper_arm())
    with pytest.raises(hybrid.HybridError, match="was not read from a URDF; give position and rotation"):
        WrenchSensor(frame="ee_link").mount(robot)
