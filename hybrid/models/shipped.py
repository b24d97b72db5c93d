"""The robots shipped with the package: their URDFs in ``hybrid/data`` and a factory each.

Both URDFs are example-robot-data's files, unchanged (their licences in ``hybrid/data/NOTICE.md``),
kept here so that the experiments run on a machine without that package. Only the URDFs are
shipped: :func:`hybrid.models.urdf.read_chain` reads the kinematic and inertial elements and
never opens the ``<visual>`` and ``<collision>`` meshes they name.
"""

from __future__ import annotations

from pathlib import Path

from hybrid.models.robot import Robot
from hybrid.validate import checked_keywords

_DATA = Path(__file__).resolve().parent.parent / "data"
#: the path of the UR5's URDF, shipped in the package (Universal Robots' description as example-robot-data ships it)
UR5_URDF = _DATA / "ur5_robot.urdf"
#: the path of the Panda's URDF, shipped in the package (Franka Emika's description as example-robot-data ships
#: it: arm, hand, fingers)
PANDA_URDF = _DATA / "panda.urdf"
#: the Panda's finger joints (prismatic, 0 to 0.04 m; the second mimics the first), locked closed
PANDA_FINGERS = {"panda_finger_joint1": 0.0, "panda_finger_joint2": 0.0}


@checked_keywords
def ur5() -> Robot:
    """The UR5 of example-robot-data: 6 joints, tip ``tool0``, gravity on.

    Returns
    -------
    Robot
        The arm of :data:`UR5_URDF` from its base to ``tool0``.

    Examples
    --------
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> robot.name, robot.n, robot.gravity
    ('ur5', 6, (0.0, 0.0, -9.81))
    >>> robot.joint_names[:2]
    ('shoulder_pan_joint', 'shoulder_lift_joint')
    """
    return Robot.from_urdf(UR5_URDF, tip="tool0")


@checked_keywords
def panda() -> Robot:
    """The Franka Emika Panda of example-robot-data: the arm's 7 joints, tip ``panda_hand_tcp`` (the
    hand's tool centre point, 0.1034 m beyond the flange, between the fingertips), gravity on.

    The fingers are locked closed and lumped into the hand, which the last joint carries. With 7
    joints and at most 6 task axes the arm is redundant: a :class:`~hybrid.Posture` task acts in
    the task's null space.

    Returns
    -------
    Robot
        The arm of :data:`PANDA_URDF` from its base to ``panda_hand_tcp``.

    Examples
    --------
    >>> import hybrid
    >>> robot = hybrid.panda()
    >>> robot.name, robot.n
    ('panda', 7)
    """
    return Robot.from_urdf(PANDA_URDF, tip="panda_hand_tcp", locked=PANDA_FINGERS)
