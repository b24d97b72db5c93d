"""The arm's kinematic and dynamic terms and Khatib's operational space, from the generated C.

For the paper's planar :class:`~hybrid.Arm` the committed closed-form unit computes them; for a
:class:`~hybrid.Robot` its generated rigid-body unit (:mod:`hybrid.native.units`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.chain_terms import robot_terms
from hybrid.models.planar_arm import Arm, check_arm
from hybrid.models.robot import Robot
from hybrid.native.binding import one_state
from hybrid.native.units import planar_unit
from hybrid.validate import SINGULAR_TOL, check_singular_tol, checked_keywords


@checked_keywords
def arm_terms(arm: Arm | Robot, q, qdot, *, backend: str = "sympy") -> dict[str, np.ndarray]:
    """Kinematic and dynamic terms of ``arm`` at one state, from the generated C.

    Parameters
    ----------
    arm : Arm or Robot
        The paper's planar arm (its parameters) or any robot.
    q : array_like
        Joint positions [rad or m]: one per joint, or for a :class:`Robot` ``(N, n)`` for N states in
        one native call (every output then gaining a leading N axis).
    qdot : array_like
        Joint velocities [rad/s or m/s], of the shape of ``q``.
    backend : str
        The planar arm's committed unit: ``"sympy"`` (default) or ``"casadi"``.

    Returns
    -------
    dict of str to numpy.ndarray
        For the planar :class:`Arm`: ``r`` [m], ``J`` (2x2), ``Jdot_qdot`` [m/s^2], ``B`` (2x2)
        [kg m^2], ``n`` [N m]. For a :class:`Robot` with ``n`` joints: ``r`` (3) [m] and ``rotation``
        (3x3) of the tip frame in base axes, the frame Jacobian ``J`` (6 x n, linear rows first, base
        axes), ``Jdot_qdot`` (6, the classical acceleration at ``q'' = 0``), ``B`` (n x n), ``n`` (n):
        Coriolis/centrifugal, gravity, joint friction.

    Raises
    ------
    HybridError
        ``arm`` is neither, or a state of the wrong size or not finite.

    Examples
    --------
    >>> import hybrid
    >>> terms = hybrid.arm_terms(hybrid.paper_arm(), [0.0, 1.5708],
    ...                          [0.0, 0.0])
    >>> sorted(terms)
    ['B', 'J', 'Jdot_qdot', 'n', 'r']
    >>> terms["r"].round(4).tolist()
    [0.45, 0.32]
    """
    if isinstance(arm, Robot):
        return robot_terms(arm, q, qdot)
    check_arm(arm)
    unit = planar_unit(backend)
    q, qdot, p = one_state("q", q), one_state("qdot", qdot), arm.as_array()
    kin = unit.function("arm_kinematics")(q, qdot, p)
    dyn = unit.function("arm_dynamics")(q, qdot, p)
    return {"r": kin["r"], "J": kin["J"], "Jdot_qdot": kin["Jdqd"], "B": dyn["B"], "n": dyn["n"]}


@checked_keywords
def operational_space(arm: Arm | Robot, q, qdot, *, backend: str = "sympy", singular_tol: float = SINGULAR_TOL,
                      coordinates: str = "twist"):
    """Khatib's operational-space model.

    With ``coordinates="twist"`` (default), ``B_o = Lambda = (J B^-1 J^T)^-1`` and ``n_o = Jbar^T n -
    Lambda J' q'`` for the twist ``v = (p', w)``, base axes: ``Lambda v' + n_o = F + F_c``. With
    ``coordinates="euler_zyx"``, the paper's ``r = (p, phi)`` with ZYX Euler angles:
    ``B_o(r) = T^T Lambda T``, ``n_o(r, r') = T^T (Lambda T' r' + n_o,twist)``, ``T = diag(I, T_A)``
    and ``T'``, so that ``B_o r'' + n_o = T^T (F + F_c)``.

    Parameters
    ----------
    arm : Arm or Robot
        The paper's planar arm (its parameters), or a robot of 6 joints or more.
    q : array_like
        Joint positions [rad or m], one per joint.
    qdot : array_like
        Joint velocities [rad/s or m/s], one per joint.
    backend : str
        The planar arm's committed unit: ``"sympy"`` (default) or ``"casadi"``.
    singular_tol : float
        The smallest distance from singularity accepted.
    coordinates : str
        A robot's coordinates: ``"twist"`` (default) or ``"euler_zyx"``.

    Returns
    -------
    tuple of numpy.ndarray or OperationalSpace
        Planar :class:`Arm`: ``(B_o, n_o)``, ``B_o(r)`` [kg] (2x2) and ``n_o(r, r')`` [N].
        :class:`Robot`: an :class:`OperationalSpace`.

    Raises
    ------
    SingularConfigurationError
        The arm is at (or too near) a singularity.
    HybridError
        A robot of fewer than 6 joints, or unknown ``coordinates``.

    Examples
    --------
    >>> import hybrid
    >>> B_o, n_o = hybrid.operational_space(hybrid.paper_arm(),
    ...                                     [0.0, 1.5708], [0.0, 0.0])
    >>> B_o.shape, n_o.shape
    ((2, 2), (2,))
    >>> q = [0.0, -1.5, 1.5, 0.0, 1.5, 0.0]
    >>> model = hybrid.operational_space(hybrid.ur5(), q, [0.0] * 6)
    >>> model.coordinates, model.B_o.shape
    ('twist', (6, 6))
    """
    if isinstance(arm, Robot):
        return robot_operational_space(arm, q, qdot, singular_tol, coordinates)
    check_arm(arm)
    check_singular_tol("operational_space", singular_tol)
    out = planar_unit(backend).function("operational_space")(
        one_state("q", q), one_state("qdot", qdot), arm.as_array(), singular_tol=singular_tol)
    return out["Bo"], out["no"]


@checked_keywords
@dataclass(frozen=True)
class OperationalSpace:
    """A robot's operational-space model at one state (see :func:`operational_space`).

    Parameters
    ----------
    coordinates : str
        ``"twist"`` or ``"euler_zyx"``.
    B_o : numpy.ndarray
        The operational-space inertia (6 x 6).
    n_o : numpy.ndarray
        The operational-space forces (6).
    r, rdot : numpy.ndarray or None
        In Euler coordinates, the pose ``r = (p, alpha, beta, gamma)`` and its rate.
    T, Tdot : numpy.ndarray or None
        In Euler coordinates, ``T`` (6 x 6, ``v = T r'``) and its rate.

    Examples
    --------
    >>> import hybrid
    >>> q = [0.0, -1.5, 1.5, 0.0, 1.5, 0.0]
    >>> model = hybrid.operational_space(hybrid.ur5(), q, [0.0] * 6,
    ...                                  coordinates="euler_zyx")
    >>> type(model).__name__, model.coordinates, model.T.shape
    ('OperationalSpace', 'euler_zyx', (6, 6))
    """

    coordinates: str
    B_o: np.ndarray
    n_o: np.ndarray
    r: np.ndarray | None = None
    rdot: np.ndarray | None = None
    T: np.ndarray | None = None
    Tdot: np.ndarray | None = None


def robot_operational_space(robot: Robot, q, qdot, singular_tol: float, coordinates: str) -> OperationalSpace:
    check_singular_tol("operational_space", singular_tol)
    if coordinates not in ("twist", "euler_zyx"):
        raise HybridError(f"coordinates = {coordinates!r}; give 'twist' or 'euler_zyx'")
    if robot.n < 6:
        raise HybridError(f"the 6-D operational space needs at least 6 joints; this arm has {robot.n}")
    unit = robot.unit
    if coordinates == "twist":
        out = unit.function("operational_space")(q, qdot, robot.as_array(), singular_tol=singular_tol)
        return OperationalSpace("twist", out["Lambda"], out["no"])
    out = unit.function("operational_space_euler")(q, qdot, robot.as_array(), singular_tol=singular_tol)
    return OperationalSpace("euler_zyx", out["Bo"], out["no"], out["r"], out["rd"], out["T"], out["Td"])
