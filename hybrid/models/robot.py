"""Any serial arm as a validated dataclass: structure, inertial parameters, and its compiled terms.

A :class:`Robot` holds the kinematic chain (compiled into the generated C) and the run-time
parameters (inertial parameters, joint friction, gravity: the ``robot`` array). It is data:
its C is generated and compiled on first use and kept in a cache keyed by the kinematic
structure (:mod:`hybrid.native.units`), so changing only inertial parameters or gravity never
regenerates.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.kinds import SERIAL_CHAIN, ClosedFormArm
from hybrid.models.planar_arm import Arm
from hybrid.models.urdf import JointLimits, LinkInertia, read_chain
from hybrid.native import units
from hybrid.native.binding import Unit
from hybrid.spec import chain as rb
from hybrid.spec.chain import COULOMB_SPEED
from hybrid.validate import _finite, check_model_error, checked_keywords, finite_array, inertia_problem, shown


def _gravity(g) -> tuple[float, float, float]:
    try:
        arr = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        arr = np.array([])
    if arr.shape != (3,) or not np.isfinite(arr).all():
        raise HybridError(f"gravity = {shown(g)}; give three finite numbers (g_x, g_y, g_z) in m/s^2, base axes")
    return tuple(map(float, arr))


@checked_keywords
@dataclass(frozen=True)
class Robot:
    """A serial arm: its kinematic chain, inertial parameters, joint friction, gravity and joint limits.

    Joint ``i``'s friction torque is ``F_v q'_i + F_c tanh(q'_i / v_s) + tau_0`` (``damping``,
    ``coulomb``, ``coulomb_speed``, ``offset``): viscous, Coulomb with a smooth sign, and a constant
    offset. The plant feels it; a controller told this robot compensates it.

    Build it with :meth:`from_urdf` or :meth:`planar`. Terms come from :func:`hybrid.arm_terms`.

    Parameters
    ----------
    name : str
        The robot's name (it names its generated code).
    chain : hybrid.spec.chain.Chain
        The kinematic structure (compiled into the generated C).
    links : tuple of LinkInertia
        Each joint's link: mass [kg], centre of mass [m] and inertia [kg m^2] in the joint's frame.
    damping : tuple of float
        The joints' viscosities [N m s/rad or N s/m].
    gravity : tuple of float
        Gravity in base axes [m/s^2].
    limits : JointLimits or None
        The joints' position, velocity and effort limits (a URDF's).
    closed_form : Arm or None
        The paper's planar arm when the robot is that arm (:meth:`planar`): its terms, plant and
        inverse kinematics then also exist in closed form, and its chain, links, viscosities and
        gravity are derived from it (one place for its numbers).
    source : tuple or None
        Where :meth:`from_urdf` read it.
    coulomb : tuple of float
        The joints' Coulomb friction ``F_c`` [N m or N], ``>= 0`` (a URDF's ``<dynamics friction>``);
        empty: none.
    offset : tuple of float
        The joints' constant friction offset ``tau_0`` [N m or N] (e.g. a torque reading's bias); empty:
        none.
    coulomb_speed : tuple of float
        The speed ``v_s > 0`` [rad/s or m/s] of each joint's smooth sign ``tanh(q' / v_s)``; empty:
        :data:`COULOMB_SPEED` each. A smaller one is closer to a true sign and a stiffer plant (the
        experiment's check says when its integration step is too long for it).

    Raises
    ------
    HybridError
        A link or friction value per joint missing, a value not physical (a negative mass, viscosity or
        Coulomb friction, an inertia not symmetric or not a rigid body's), or a last link without mass
        and inertia; Coulomb friction or offsets on the planar arm's closed form.

    Examples
    --------
    >>> import hybrid
    >>> robot = hybrid.Robot.planar(hybrid.paper_arm())
    >>> robot.n, robot.joint_names
    (2, ('joint1', 'joint2'))
    >>> robot.inverse_kinematics([0.3, 0.4]).round(4).tolist()
    [0.248, 1.7626]
    """

    name: str
    chain: rb.Chain
    links: tuple[LinkInertia, ...]
    damping: tuple[float, ...]
    gravity: tuple[float, float, float] = (0.0, 0.0, -9.81)
    limits: JointLimits | None = field(default=None, compare=False)  # arrays: information, not identity
    closed_form: Arm | None = None
    #: where :meth:`from_urdf` read it, ``(path, tip, ((locked joint, position), ...))``, for a plant
    #: that reads the file itself (MuJoCo); None for a robot built otherwise
    source: tuple | None = field(default=None, compare=False, repr=False)
    coulomb: tuple[float, ...] = ()
    offset: tuple[float, ...] = ()
    coulomb_speed: tuple[float, ...] = ()

    def __post_init__(self):
        if self.closed_form is not None:  # the planar arm's parameters are its closed form's, in one place
            if not isinstance(self.closed_form, Arm):
                raise HybridError(f"closed_form = {shown(self.closed_form, 60)}; give a hybrid.Arm or None")
            chain, links, damping, gravity = _planar_parts(self.closed_form)
            for name, value in (("chain", chain), ("links", links), ("damping", damping), ("gravity", gravity)):
                object.__setattr__(self, name, value)
        else:  # a closed form's parts come from an Arm, which checked the same (B(q) positive definite)
            self._check_parts()
        self._check_friction()
        # the one place that tells the kinds apart: what depends on it, the kind does (hybrid.models.kinds)
        object.__setattr__(self, "kind", SERIAL_CHAIN if self.closed_form is None else ClosedFormArm(self.closed_form))
        params = np.concatenate([*(link.as_array() for link in self.links), self.damping, self.coulomb, self.offset,
                                 self.coulomb_speed, self.gravity])
        params.setflags(write=False)  # frozen: built once, read-only like the fields it comes from
        object.__setattr__(self, "_params", params)

    def _check_parts(self) -> None:
        """The links, viscosities and gravity: one of each per joint, physical values."""
        object.__setattr__(self, "gravity", _gravity(self.gravity))
        if len(self.links) != self.chain.n or len(self.damping) != self.chain.n:
            raise HybridError(f"Robot needs one link and one damping per joint ({self.chain.n}), got "
                              f"{len(self.links)} and {len(self.damping)}")
        for name, link in zip(self.joint_names, self.links):
            _check_link(name, link)
        last = self.links[-1] if self.links else None
        if last is not None and last.mass == 0 and not np.any(last.inertia):
            raise HybridError(f"the link moved by the last joint '{self.joint_names[-1]}' has no mass and no "
                              "inertia, so B(q) is singular; give it mass or inertia")
        for name, d in zip(self.joint_names, self.damping):
            _finite(f"Robot damping[{name}]", damping=d)
            if d < 0:
                raise HybridError(f"damping of joint '{name}' is {d}; give a viscosity >= 0")

    def _check_friction(self) -> None:
        """Coulomb friction, offsets and smooth-sign speeds: one per joint (empty: none, the default speed),
        Coulomb friction >= 0, speeds > 0; none on the planar arm's closed form, whose terms know viscosity
        only."""
        n = self.chain.n
        for name, default in (("coulomb", 0.0), ("offset", 0.0), ("coulomb_speed", COULOMB_SPEED)):
            value = getattr(self, name)
            arr = np.full(n, default) if isinstance(value, tuple) and not value else finite_array(
                f"Robot {name}", value, (n,))
            object.__setattr__(self, name, tuple(float(v) + 0.0 for v in arr))
        for joint, c, v in zip(self.joint_names, self.coulomb, self.coulomb_speed):
            if c < 0:
                raise HybridError(f"coulomb of joint '{joint}' is {c}; give a Coulomb friction >= 0")
            if v <= 0:
                raise HybridError(f"coulomb_speed of joint '{joint}' is {v}; give the smooth sign's speed > 0")
        if self.closed_form is not None and (any(self.coulomb) or any(self.offset)):
            raise HybridError("the planar arm's closed form has joint viscosity only; give Coulomb friction and "
                              "offsets to a serial-chain Robot (hybrid.Robot(name, chain, links, damping, ...))")

    # ------------------------------------------------------------- construction

    @classmethod
    def from_urdf(cls, path, tip: str = "tool0", gravity=(0.0, 0.0, -9.81), locked: dict | None = None) -> Robot:
        """The serial chain of the URDF at ``path`` from its root link to the link ``tip``.

        Fixed joints are merged; joints off the chain, and those named in ``locked``, are held at 0
        or at the given position and the links they carry are lumped into the link they hang from.

        Parameters
        ----------
        path : str or pathlib.Path
            The URDF file.
        tip : str
            The link the chain ends at (the tip frame).
        gravity : array_like
            Gravity in base axes [m/s^2].
        locked : dict or None
            ``{joint name: position}`` of joints held still.

        Returns
        -------
        Robot
            The chain, its links' inertial parameters, joint friction and limits as the file gives them.

        Raises
        ------
        URDFError
            The file cannot describe a controllable serial arm to ``tip``.
        HybridError
            ``tip`` is not a string, or ``locked`` not a dict.

        Examples
        --------
        >>> import hybrid
        >>> robot = hybrid.Robot.from_urdf(hybrid.UR5_URDF,
        ...                                tip="tool0")
        >>> robot.n
        6
        """
        if not isinstance(tip, str):
            raise HybridError(f"tip must be a link name (a string), got {tip!r}")
        if locked is not None and not isinstance(locked, dict):
            raise HybridError(f"locked must be a {{joint name: position}} dict, got {type(locked).__name__}")
        parsed = read_chain(path, tip, locked)
        source = (str(Path(path).resolve()), tip, tuple(sorted((locked or {}).items())))
        return cls(parsed.name, parsed.chain, parsed.links, parsed.damping, gravity, parsed.limits, source=source,
                   coulomb=parsed.coulomb, offset=parsed.offset, coulomb_speed=parsed.coulomb_speed)

    @classmethod
    def planar(cls, arm: Arm) -> Robot:
        """The paper's planar arm (conventions §3) as a serial chain: revolute joints about base z,
        links along x, the tip at ``L2`` beyond joint 2, gravity ``arm.gravity`` along ``-y``.

        Parameters
        ----------
        arm : Arm
            The arm's parameters (e.g. :func:`hybrid.paper_arm`).

        Returns
        -------
        Robot
            The arm, with ``closed_form`` its parameters.
        """
        if not isinstance(arm, Arm):
            raise HybridError(f"arm must be a hybrid.Arm, got {type(arm).__name__}")
        return _planar(cls, arm)

    # -------------------------------------------------------------- properties

    @property
    def n(self) -> int:
        """Number of joints."""
        return self.chain.n

    @property
    def rest_viscosity(self) -> np.ndarray:
        """Each joint's friction slope about rest, ``F_v + F_c / v_s`` [N m s/rad or N s/m]: the viscosity
        the joint's friction acts as for speeds well below ``v_s``."""
        return np.asarray(self.damping) + np.asarray(self.coulomb) / np.asarray(self.coulomb_speed)

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(j.name for j in self.chain.joints)

    def parameter_names(self) -> tuple[str, ...]:
        """Names of the ``robot`` array of the generated C.

        Returns
        -------
        tuple of str
            One name per entry of :meth:`as_array`.
        """
        return rb.parameter_names(self.chain)

    def as_array(self) -> np.ndarray:
        """The ``robot`` array of the generated C.

        Returns
        -------
        numpy.ndarray
            Per link ``m, c (3), I (6)``, then per joint the viscosities, Coulomb frictions, offsets and
            smooth-sign speeds, then gravity (read-only).
        """
        return self._params

    # ------------------------------------------------------------ model changes

    def with_model_error(self, inertial: float = 0.1, viscous_compensation: float = 0.5) -> Robot:
        """The controller's model of this arm.

        Parameters
        ----------
        inertial : float
            The relative error of the masses and inertias: ``(1 + inertial)`` times the true ones
            (centres of mass unchanged).
        viscous_compensation : float
            The share of the joints' friction (viscosities, Coulomb frictions and offsets) the model knows.

        Returns
        -------
        Robot
            The model.
        """
        changed = self.kind.with_model_error(self, inertial, viscous_compensation)
        if changed is not None:
            return changed
        k = check_model_error(inertial, viscous_compensation)
        links = tuple(LinkInertia(lk.mass * k, lk.com, tuple(tuple(v * k for v in r) for r in lk.inertia))
                      for lk in self.links)
        share = {name: tuple(v * viscous_compensation for v in getattr(self, name))
                 for name in ("damping", "coulomb", "offset")}
        return dataclasses.replace(self, links=links, **share)

    def with_link(self, joint: str, *, mass: float | None = None, com=None, inertia=None,
                  damping: float | None = None, coulomb: float | None = None, offset: float | None = None) -> Robot:
        """This robot with the body moved by ``joint`` given new parameters (the others kept).

        The planar arm's parameters are its ``closed_form``'s: change them there
        (``Robot.planar(dataclasses.replace(arm, m2=...))``).

        Parameters
        ----------
        joint : str
            The joint whose link changes.
        mass : float or None
            The link's mass [kg].
        com : array_like or None
            Its centre of mass (3) [m], in the joint's frame.
        inertia : array_like or None
            Its inertia (3 x 3, about the centre of mass) [kg m^2], in the joint's frame.
        damping : float or None
            The joint's viscosity [N m s/rad or N s/m].
        coulomb, offset : float or None
            The joint's Coulomb friction and friction offset [N m or N].

        Returns
        -------
        Robot
            The changed robot.

        Raises
        ------
        HybridError
            No joint of that name, a value not physical, or the planar arm (change its ``Arm``).
        """
        self.kind.check_link_change()
        if joint not in self.joint_names:
            raise HybridError(f"no joint named {joint!r}; the joints are {', '.join(self.joint_names)}")
        i = self.joint_names.index(joint)
        old = self.links[i]
        com = old.com if com is None else tuple(finite_array(f"com of {joint}", com, (3,)))
        if inertia is not None:
            inertia = tuple(map(tuple, finite_array(f"inertia of {joint}", inertia, (3, 3))))
        inertia = old.inertia if inertia is None else inertia
        new = LinkInertia(old.mass if mass is None else mass, com, inertia)
        links = self.links[:i] + (new,) + self.links[i + 1:]
        friction = {name: getattr(self, name)[:i] + (value,) + getattr(self, name)[i + 1:]
                    for name, value in (("damping", damping), ("coulomb", coulomb), ("offset", offset))
                    if value is not None}
        return dataclasses.replace(self, links=links, **friction)

    # ---------------------------------------------------------------- compiled

    @property
    def default_axes(self) -> str:
        """The task axes a controller of this robot uses unless told: the planar arm's ``(t1, n)``,
        else all six."""
        return self.kind.default_axes

    @property
    def conditioning_name(self) -> str:
        """The measure :meth:`conditioning` computes."""
        return self.kind.conditioning_name

    def conditioning(self, q) -> np.ndarray:
        """The Jacobian's distance from singularity at ``q``, in (0, 1].

        ``m / (|J|_F |J^+|_F)`` (``m = min(6, n)``) of the tip's frame Jacobian, about
        ``sigma_min / sigma_max``; the planar arm's ``2 |det J| / |J|_F^2`` (about ``|sin q2|``).

        Parameters
        ----------
        q : array_like
            Joint positions, one state (n) or one per row (N x n).

        Returns
        -------
        float or numpy.ndarray
            The measure, one per state.
        """
        return self.kind.conditioning(self, q)

    def reach(self) -> tuple[float, float] | None:
        """Smallest and largest distance of the tip from the base, when known in closed form.

        Returns
        -------
        tuple of float or None
            ``(smallest, largest)`` [m], or None.
        """
        return self.kind.reach()

    def inverse_kinematics(self, position, rotation=None, q0=None, tol: float = 1e-10, elbow: int = 1) -> np.ndarray:
        """Joint positions putting the tip frame at ``position`` (and ``rotation``, when given).

        Solved by damped least squares from ``q0``; the planar arm solves in closed form (its
        orientation follows from the position).

        Parameters
        ----------
        position : array_like
            The tip's position [m], base axes (2 coordinates for the planar arm).
        rotation : array_like or None
            The tip frame's axes in base axes (3 x 3), or None: any orientation.
        q0 : array_like or None
            Where the iteration starts (default: mid-range of the limits).
        tol : float
            The tolerance on the pose's error.
        elbow : int
            The planar arm's elbow: +1 for ``q2 > 0``, -1 for ``q2 < 0``.

        Returns
        -------
        numpy.ndarray
            The joint positions [rad or m].

        Raises
        ------
        HybridError
            The pose is not reached (out of reach, or a poor ``q0``).
        """
        return self.kind.inverse_kinematics(self, position, rotation, q0, tol, elbow)

    @property
    def unit(self) -> Unit:
        """The compiled kernels of this robot's structure (generated and compiled on first use, cached
        by the structure: robots that differ only in their parameters share it)."""
        return units.robot_unit(self.chain, self.name)

    @property
    def constant_unit(self) -> Unit:
        """The compiled kernels of this robot with its parameters (:meth:`as_array`) compiled in as numbers:
        a constant model, for a deployed arm whose parameters do not change.

        Its functions are :attr:`unit`'s without the ``robot`` array (a call given one is refused); they
        compute fewer operations where the numbers make products trivial (zeros, ones, a joint without
        Coulomb friction). Generated and compiled on first use, cached by the structure and the exact
        numbers (a parameter changed by one ulp is another model); its manifest records the numbers
        (``manifest["model"]``).

        Examples
        --------
        >>> import numpy as np
        >>> import hybrid
        >>> ur5 = hybrid.ur5()
        >>> q, qd = np.full(6, 0.3), np.full(6, -0.2)
        >>> qdd = np.full(6, 0.1)
        >>> fixed_id = ur5.constant_unit.function("inverse_dynamics")
        >>> fixed = fixed_id(q, qd, qdd)["tau"]
        >>> given_id = ur5.unit.function("inverse_dynamics")
        >>> given = given_id(q, qd, qdd, ur5.as_array())["tau"]
        >>> bool(np.allclose(fixed, given, rtol=1e-12, atol=0.0))
        True
        """
        return units.constant_robot_unit(self.chain, self.name, self.as_array())


def structure_difference(robot: Robot, other: Robot) -> str | None:
    """How ``other``'s kinematic structure (what its C is compiled from) differs from ``robot``'s, in words,
    or None when it is the same: the kind (the planar arm's closed form or a serial chain), the joints'
    number, names and types, a joint's origin or axis, the tip frame."""
    if (robot.closed_form is None) != (other.closed_form is None):
        kinds = ["the planar arm's closed form" if r.closed_form is not None else "a serial chain"
                 for r in (robot, other)]
        return f"the robot is {kinds[0]} and the other {kinds[1]}"
    a, b = robot.chain, other.chain
    if a.n != b.n:
        return f"{a.n} joints against {b.n}"
    for i, (ja, jb) in enumerate(zip(a.joints, b.joints)):
        for what, x, y in (("name", ja.name, jb.name), ("type", ja.kind, jb.kind), ("origin rotation", ja.rotation,
                           jb.rotation), ("origin translation", ja.translation, jb.translation),
                           ("axis", ja.axis, jb.axis)):
            if x != y:
                return f"joint {i + 1} ({ja.name}): {what} {x} against {y}"
    if a.tip_rotation != b.tip_rotation or a.tip_translation != b.tip_translation:
        return f"the tip frame: {a.tip_translation} {a.tip_rotation} against {b.tip_translation} {b.tip_rotation}"
    return None


def as_robot(robot) -> Robot:
    """``robot``, or the paper's planar arm when given its parameters (an :class:`Arm`); anything else is
    a HybridError."""
    if isinstance(robot, Arm):
        return Robot.planar(robot)
    if not isinstance(robot, Robot):
        raise HybridError(f"robot must be a hybrid.Robot (e.g. hybrid.ur5(), hybrid.Robot.from_urdf) or the paper's "
                          f"hybrid.Arm, got {type(robot).__name__}")
    return robot


@lru_cache(maxsize=256)
def _planar(cls, arm: Arm) -> Robot:
    """:meth:`Robot.planar`, once per arm (a robot is immutable: the runs of a sweep share it)."""
    bounds = [np.full(2, v) for v in (-math.inf, math.inf, math.inf, math.inf)]
    for b in bounds:
        b.setflags(write=False)  # the robot is shared by every caller with an equal arm
    chain, links, damping, gravity = _planar_parts(arm)
    return cls("planar_arm", chain, links, damping, gravity, JointLimits(*bounds), arm)


@lru_cache(maxsize=256)
def _planar_parts(arm: Arm) -> tuple:
    """The planar arm as a serial chain: revolute joints about base z, links along x, the tip ``L2``
    beyond joint 2; its links' inertias, its viscosities and gravity (along ``-y``)."""
    eye = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    joints = tuple(rb.Joint(f"joint{i + 1}", "revolute", eye, (L, 0.0, 0.0), (0.0, 0.0, 1.0))
                   for i, L in enumerate((0.0, arm.L1)))
    chain = rb.Chain(joints, eye, (arm.L2, 0.0, 0.0))
    links = tuple(LinkInertia(m, (d, 0.0, 0.0), ((inertia, 0.0, 0.0), (0.0, inertia, 0.0), (0.0, 0.0, inertia)))
                  for m, d, inertia in ((arm.m1, arm.d1, arm.I1), (arm.m2, arm.d2, arm.I2)))
    return chain, links, (float(arm.V1), float(arm.V2)), (0.0, -float(arm.gravity), 0.0)


def _check_link(joint: str, link: LinkInertia) -> None:
    if not isinstance(link, LinkInertia):
        raise HybridError(f"link of joint '{joint}' must be a LinkInertia, got {type(link).__name__}")
    _finite(f"link of joint '{joint}'", mass=link.mass)
    if link.mass < 0:
        raise HybridError(f"mass of the link moved by '{joint}' is {link.mass} kg; give a mass >= 0")
    I = finite_array(f"inertia of the link moved by '{joint}'", link.inertia, (3, 3))  # noqa: E741
    finite_array(f"centre of mass of the link moved by '{joint}'", link.com, (3,))
    if np.abs(I - I.T).max() > 1e-12 * max(1.0, np.abs(I).max()):
        raise HybridError(f"inertia of the link moved by '{joint}' is not symmetric; give a symmetric 3x3 tensor")
    problem = inertia_problem(I)
    if problem:
        raise HybridError(f"inertia of the link moved by '{joint}' {problem}; give a rigid body's inertia")
