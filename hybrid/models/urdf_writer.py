"""A robot written as a URDF file that :meth:`hybrid.Robot.from_urdf` reads back as the same robot.

Each moving joint under its name, the link it moves named after it (``<joint>_link``) with the robot's
mass, centre of mass and inertia about it (joint-frame axes), the joint's friction and limits, and the
tip frame as a fixed joint to a massless link ``tip``: ``Robot.from_urdf(path, tip="tip")`` gives the
robot again, its chain's rotations to rounding (they go through roll, pitch and yaw). The friction is
``<dynamics damping friction>`` (viscosity and Coulomb friction, as any URDF reader takes them) and two
attributes of the library's own, ``offset`` and ``coulomb_speed``, which other readers (Pinocchio's,
MuJoCo's) pass over.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from hybrid.models.robot import Robot, as_robot

#: the name of the tip frame's link
TIP = "tip"


def rpy_of(R) -> tuple[float, float, float]:
    """The URDF roll, pitch, yaw of the rotation ``R = Rz(yaw) Ry(pitch) Rx(roll)``
    (:func:`hybrid.spec.chain.rotation_rpy`'s inverse; at gimbal lock the roll is taken as 0)."""
    R = [[float(v) for v in row] for row in R]
    pitch = math.atan2(-R[2][0], math.hypot(R[0][0], R[1][0]))
    if math.hypot(R[0][0], R[1][0]) < 1e-12:
        return 0.0, pitch, math.atan2(-R[0][1], R[1][1])
    return math.atan2(R[2][1], R[2][2]), pitch, math.atan2(R[1][0], R[0][0])


def _numbers(values) -> str:
    return " ".join(repr(float(v) + 0.0) for v in values)


def _origin(translation, rotation) -> str:
    return f'<origin xyz="{_numbers(translation)}" rpy="{_numbers(rpy_of(rotation))}"/>'


def robot_urdf_text(robot: Robot, *, least_mass: float = 0.0) -> str:
    """The URDF of ``robot`` (see the module's description).

    Parameters
    ----------
    robot : Robot
        The arm (a serial chain: the planar arm's closed form too, as its chain).
    least_mass : float
        A link's mass written at least this [kg], and a link without inertia given this much about each
        axis [kg m^2] (MuJoCo refuses a moving body without them; the default 0 writes the robot as it is).

    Returns
    -------
    str
        The URDF's text.
    """
    robot = as_robot(robot)
    limits = robot.limits
    parts = [f'<?xml version="1.0"?>\n<robot name="{escape(robot.name)}">', '  <link name="base"/>']
    parent = "base"
    for i, (joint, link) in enumerate(zip(robot.chain.joints, robot.links)):
        child = f"{joint.name}_link"
        lower, upper, velocity, effort = ((-math.inf if k == "lower" else math.inf) if limits is None
                                          else float(np.asarray(getattr(limits, k))[i])
                                          for k in ("lower", "upper", "velocity", "effort"))
        bounded = math.isfinite(lower) and math.isfinite(upper)
        kind = joint.kind if bounded or joint.kind == "prismatic" else "continuous"
        attributes = [f'{k}="{v!r}"' for k, v in (("lower", lower), ("upper", upper)) if bounded]
        attributes += [f'{k}="{v!r}"' for k, v in (("effort", effort), ("velocity", velocity)) if math.isfinite(v)]
        I = np.asarray(link.inertia, float) + least_mass * np.eye(3) * (not np.any(link.inertia))  # noqa: E741
        inertia = " ".join(f'{k}="{float(I[a, b]) + 0.0!r}"' for k, (a, b) in zip(
            ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"), ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))))
        parts += [f'  <joint name="{escape(joint.name)}" type="{kind}">',
                  f'    <parent link="{escape(parent)}"/><child link="{escape(child)}"/>',
                  f"    {_origin(joint.translation, joint.rotation)}",
                  f'    <axis xyz="{_numbers(joint.axis)}"/>',
                  f'    <dynamics damping="{float(robot.damping[i])!r}" friction="{float(robot.coulomb[i])!r}" '
                  f'offset="{float(robot.offset[i])!r}" coulomb_speed="{float(robot.coulomb_speed[i])!r}"/>',
                  *([f"    <limit {' '.join(attributes)}/>"] if attributes or kind != "continuous" else []),
                  "  </joint>",
                  f'  <link name="{escape(child)}">',
                  f'    <inertial><origin xyz="{_numbers(link.com)}"/>'
                  f'<mass value="{max(float(link.mass), least_mass)!r}"/>'
                  f"<inertia {inertia}/></inertial>",
                  "  </link>"]
        parent = child
    parts += [f'  <joint name="{TIP}_joint" type="fixed">',
              f'    <parent link="{escape(parent)}"/><child link="{TIP}"/>',
              f"    {_origin(robot.chain.tip_translation, robot.chain.tip_rotation)}",
              "  </joint>", f'  <link name="{TIP}"/>', "</robot>"]
    return "\n".join(parts) + "\n"
