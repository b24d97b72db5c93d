"""The kinematic structure of a serial arm as plain data: joints, the tip frame, parameter names.

A :class:`Chain` is what the code generator compiles into a robot's C (joint origins, axes,
types); the inertial parameters, joint friction and gravity stay run-time numbers, named here in
the order of the generated code's ``robot`` array (a constant model compiles them in as well:
:func:`parameter_digest` names the numbers it holds).
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

#: the per-link inertial parameters in the ``robot`` array, in order: mass [kg], centre of mass
#: in the joint frame [m], inertia about the centre of mass in the joint frame's axes [kg m^2]
INERTIAL = ("m", "cx", "cy", "cz", "Ixx", "Ixy", "Ixz", "Iyy", "Iyz", "Izz")
INERTIAL_UNITS = ("kg", "m", "m", "m") + ("kg m^2",) * 6

#: the per-joint friction parameters in the ``robot`` array, each a block of one per joint, in order:
#: the viscosity ``F_v``, the Coulomb friction ``F_c`` and the constant offset ``tau_0`` (effort
#: units), whose torque on joint ``i`` is ``F_v q'_i + F_c tanh(q'_i / v_s) + tau_0`` (the first
#: three are linear parameters of the dynamics), and the smooth sign's speed ``v_s`` (joint rate units)
FRICTION = ("damping", "coulomb", "offset", "coulomb_speed")
#: the friction parameters the dynamics are linear in (the regressor's columns after the links')
LINEAR_FRICTION = FRICTION[:3]
#: the default speed [rad/s or m/s] of the Coulomb friction's smooth sign ``tanh(q' / v_s)``: 0.99 of the
#: friction acts from ``2.6 v_s``, and the joint's linear slope about rest is ``F_c / v_s``
COULOMB_SPEED = 0.05


@dataclass(frozen=True)
class Joint:
    """One moving joint of the chain (fixed joints are merged into the next origin).

    ``rotation`` (3x3, row-major tuples) and ``translation`` [m] place this joint's frame in
    its parent's frame at ``q = 0``; ``axis`` is a unit vector in this joint's frame.
    """

    name: str
    kind: str  # "revolute" (also URDF "continuous") or "prismatic"
    rotation: tuple[tuple[float, float, float], ...]
    translation: tuple[float, float, float]
    axis: tuple[float, float, float]


@dataclass(frozen=True)
class Chain:
    """The kinematic structure of a serial arm: moving joints from the root, then the tip frame.

    ``tip_rotation`` and ``tip_translation`` place the tip frame in the last joint's frame.
    """

    joints: tuple[Joint, ...]
    tip_rotation: tuple[tuple[float, float, float], ...]
    tip_translation: tuple[float, float, float]

    @property
    def n(self) -> int:
        return len(self.joints)


def parameter_names(chain: Chain) -> tuple[str, ...]:
    """Names of the ``robot`` array: per link the :data:`INERTIAL` set, then the :data:`FRICTION`
    blocks (one entry per joint each), then gravity ``g_x, g_y, g_z`` [m/s^2] in base axes."""
    return (tuple(f"{p}[{j.name}]" for j in chain.joints for p in INERTIAL)
            + friction_names(chain, FRICTION) + ("g_x", "g_y", "g_z"))


def friction_names(chain: Chain, blocks) -> tuple[str, ...]:
    """``block[joint]`` for each of ``blocks`` (names of :data:`FRICTION`), each over the joints."""
    return tuple(f"{p}[{j.name}]" for p in blocks for j in chain.joints)


#: the per-link parameters the dynamics are linear in (the regressor's): mass [kg], first moment
#: ``m c`` [kg m] and the inertia about the joint frame's origin [kg m^2], all in the joint frame
LINEAR = ("m", "mcx", "mcy", "mcz", "IOxx", "IOxy", "IOxz", "IOyy", "IOyz", "IOzz")
LINEAR_UNITS = ("kg",) + ("kg m",) * 3 + ("kg m^2",) * 6


def linear_parameter_names(chain: Chain) -> tuple[str, ...]:
    """Names of the parameters ``pi`` of ``tau = Y(q, q', q'') pi``: per link the :data:`LINEAR` set,
    then the :data:`LINEAR_FRICTION` blocks (viscosities, Coulomb frictions, offsets)."""
    return (tuple(f"{p}[{j.name}]" for j in chain.joints for p in LINEAR)
            + friction_names(chain, LINEAR_FRICTION))


def linear_parameter_units(chain: Chain) -> tuple[str, ...]:
    start = len(INERTIAL) * chain.n
    return LINEAR_UNITS * chain.n + parameter_units(chain)[start:start + len(LINEAR_FRICTION) * chain.n]


#: SI units of a joint's position, rate, acceleration and effort, by joint kind
JOINT_UNITS = {"revolute": {"q": "rad", "qd": "rad/s", "qdd": "rad/s^2", "tau": "N m"},
               "prismatic": {"q": "m", "qd": "m/s", "qdd": "m/s^2", "tau": "N"}}


def joint_units(chain: Chain, what: str) -> tuple[str, ...]:
    """The unit of ``what`` (``q``, ``qd``, ``qdd``, ``tau``) for each joint."""
    return tuple(JOINT_UNITS[j.kind][what] for j in chain.joints)


def parameter_units(chain: Chain) -> tuple[str, ...]:
    viscosity = {"revolute": "N m s/rad", "prismatic": "N s/m"}
    return (INERTIAL_UNITS * chain.n + tuple(viscosity[j.kind] for j in chain.joints)
            + joint_units(chain, "tau") * 2 + joint_units(chain, "qd") + ("m/s^2",) * 3)


def rotation_rpy(roll: float, pitch: float, yaw: float) -> tuple[tuple[float, float, float], ...]:
    """URDF's fixed-axis roll-pitch-yaw: ``Rz(yaw) Ry(pitch) Rx(roll)``, as row tuples."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    return ((cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
            (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
            (-sp, cp * sr, cp * cr))


def exact_values(values) -> tuple[str, ...]:
    """A ``robot`` array's numbers as exact text (:meth:`float.hex`), for a key telling any two arrays
    apart: numbers one ulp apart differ, and so do ``0.0`` and ``-0.0``, which compare equal."""
    return tuple(float(v).hex() for v in values)


def parameter_digest(values) -> str:
    """The SHA-256 of a ``robot`` array's :func:`exact_values`: what a constant model's manifest records of
    the numbers compiled into it, and what a caller compares with its own array's."""
    return hashlib.sha256(",".join(exact_values(values)).encode()).hexdigest()
