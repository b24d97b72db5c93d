"""The joint-torque regressor ``tau = Y(q, q', q'') pi`` of a robot, from its generated C.

A robot's ``robot`` array holds each link's centre of mass and its inertia about it: the dynamics are
not linear in those. They are linear in ``pi``: per link the mass ``m``, the first moment ``m c`` and
the inertia ``I_O = I_c + m (|c|^2 1 - c c^T)`` about the joint frame's origin (joint-frame axes), then
the joints' viscosities, Coulomb frictions and offsets (:func:`linear_parameters` maps a robot to them).
The regressor is compiled once per kinematic structure (:mod:`hybrid.codegen.regressor`); gravity and
the Coulomb friction's smooth-sign speeds are inputs of it.
"""

from __future__ import annotations

import numpy as np

from hybrid.models.robot import Robot, as_robot
from hybrid.native import units
from hybrid.native.binding import is_batch
from hybrid.spec.chain import linear_parameter_names


def linear_parameters(robot: Robot) -> np.ndarray:
    """The parameters ``pi`` of ``tau = Y pi`` of ``robot``, in the order of :func:`regressor`'s names.

    Parameters
    ----------
    robot : Robot
        The arm.

    Returns
    -------
    numpy.ndarray
        Per link ``m`` [kg], ``m c`` (3) [kg m] and ``I_O`` (``xx, xy, xz, yy, yz, zz``) [kg m^2] about
        the joint frame's origin in its axes, then the joints' viscosities, Coulomb frictions and
        offsets: ``13 n`` numbers.

    Raises
    ------
    HybridError
        ``robot`` is not a robot.

    Examples
    --------
    >>> import hybrid
    >>> pi = hybrid.linear_parameters(hybrid.ur5())
    >>> pi.shape, bool(pi[0] == hybrid.ur5().links[0].mass)
    ((78,), True)
    """
    robot = as_robot(robot)
    out = []
    for link in robot.links:
        m, c, Ic = link.mass, np.asarray(link.com, float), np.asarray(link.inertia, float)
        I_O = Ic + m * (c @ c * np.eye(3) - np.outer(c, c))  # parallel axes: about the frame's origin
        out.extend([m, *(m * c), I_O[0, 0], I_O[0, 1], I_O[0, 2], I_O[1, 1], I_O[1, 2], I_O[2, 2]])
    return np.array([*out, *robot.damping, *robot.coulomb, *robot.offset], dtype=float)


def regressor(robot: Robot, q, qd, qdd) -> tuple[np.ndarray, tuple[str, ...]]:
    """The joint-torque regressor ``Y`` of ``robot``: ``tau = Y(q, q', q'') pi`` is its inverse dynamics
    (``B q'' + n``: inertia, Coriolis and centrifugal terms, gravity, joint friction), ``pi`` its
    :func:`linear_parameters`.

    ``Y`` is the Jacobian of the recursive Newton-Euler algorithm with respect to ``pi``, exact since the
    dynamics are linear in ``pi``: per link the mass, the first moment ``m c`` and the inertia about the
    joint frame's origin, and the joints' viscosities, Coulomb frictions and offsets. (They are not
    linear in the ``robot`` array's centres of mass and inertias about them.) ``Y`` depends on the
    robot's structure, gravity and Coulomb friction's smooth-sign speeds only: its Coulomb column of
    joint ``i`` is ``tanh(q'_i / v_s,i)``, its offset column 1.

    Parameters
    ----------
    robot : Robot
        The arm (its structure, gravity and ``coulomb_speed``; its inertial and friction parameters are
        not read).
    q, qd, qdd : array_like
        Joint positions [rad or m], velocities and accelerations, one per joint; or ``(N, n)`` each for N
        states in one native call.

    Returns
    -------
    Y : numpy.ndarray
        ``(n, 13 n)``, or ``(N, n, 13 n)`` for N states.
    names : tuple of str
        The parameters ``pi`` of its columns (``"m[joint]"``, ``"mcx[joint]"``, ..., ``"IOzz[joint]"``,
        then ``"damping[joint]"``, ``"coulomb[joint]"`` and ``"offset[joint]"``).

    Raises
    ------
    HybridError
        ``robot`` is not a robot, or a state of the wrong size or not finite.

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> q, qd, qdd = [0.0, -1.5, 1.5, 0.0, 1.5, 0.0], [0.1] * 6, [0.2] * 6
    >>> Y, names = hybrid.regressor(robot, q, qd, qdd)
    >>> Y.shape, names[:2], names[-1]
    ((6, 78), ('m[shoulder_pan_joint]', 'mcx[shoulder_pan_joint]'), 'offset[wrist_3_joint]')
    >>> terms = hybrid.arm_terms(robot, q, qd)
    >>> bool(np.allclose(Y @ hybrid.linear_parameters(robot), terms["B"] @ qdd + terms["n"]))
    True
    """
    robot = as_robot(robot)
    fn = units.regressor_unit(robot.chain, robot.name).function("regressor")
    call = fn.batch if is_batch(q) else fn
    speeds = np.array(robot.coulomb_speed)
    return call(q, qd, qdd, np.array(robot.gravity), speeds)["Y"], linear_parameter_names(robot.chain)
