"""The joint-torque regressor ``tau = Y(q, q', q'') pi`` of a robot, from its generated C.

A robot's ``robot`` array holds each link's centre of mass and its inertia about it: the dynamics are
not linear in those. They are linear in ``pi``: per link the mass ``m``, the first moment ``m c`` and
the inertia ``I_O = I_c + m (|c|^2 1 - c c^T)`` about the joint frame's origin (joint-frame axes), then
the joints' viscosities, Coulomb frictions and offsets (:func:`linear_parameters` maps a robot to them,
:func:`with_linear_parameters` back). The regressor is compiled once per kinematic structure
(:mod:`hybrid.codegen.regressor`); gravity and the Coulomb friction's smooth-sign speeds are inputs of it.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.robot import Robot, as_robot
from hybrid.models.urdf import LinkInertia
from hybrid.native import units
from hybrid.native.binding import is_batch
from hybrid.spec.chain import LINEAR, linear_parameter_names
from hybrid.validate import checked_keywords, inertia_problem

#: the parameters of ``pi`` per link (:data:`hybrid.spec.chain.LINEAR`): mass, first moment, inertia about the
#: joint frame's origin
LINK_PARAMETERS = len(LINEAR)
#: the joint parameters (by the name before ``[``) that are physical only when >= 0: friction opposes motion
NONNEGATIVE = ("damping", "coulomb")


@checked_keywords
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


@checked_keywords
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
    >>> q = [0.0, -1.5, 1.5, 0.0, 1.5, 0.0]
    >>> qd, qdd = [0.1] * 6, [0.2] * 6
    >>> Y, names = hybrid.regressor(robot, q, qd, qdd)
    >>> Y.shape, names[:2]
    ((6, 78), ('m[shoulder_pan_joint]', 'mcx[shoulder_pan_joint]'))
    >>> names[-1]
    'offset[wrist_3_joint]'
    >>> terms = hybrid.arm_terms(robot, q, qd)
    >>> tau = Y @ hybrid.linear_parameters(robot)
    >>> bool(np.allclose(tau, terms["B"] @ qdd + terms["n"]))
    True
    """
    robot = as_robot(robot)
    fn = units.regressor_unit(robot.chain, robot.name).function("regressor")
    call = fn.batch if is_batch(q) else fn
    speeds = np.array(robot.coulomb_speed)
    return call(q, qd, qdd, np.array(robot.gravity), speeds)["Y"], linear_parameter_names(robot.chain)


def coulomb_columns(n: int) -> np.ndarray:
    """The columns of an ``n``-joint arm's :func:`regressor` that hold its joints' Coulomb friction's smooth
    sign ``tanh(q'_i / v_s,i)`` (after the links' parameters and the viscosities)."""
    return LINK_PARAMETERS * n + n + np.arange(n)


@checked_keywords
def with_linear_parameters(robot: Robot, pi) -> Robot:
    """``robot`` with the parameters ``pi`` of :func:`linear_parameters`: its inverse.

    Per link the mass ``m``, the centre of mass ``c = (m c) / m`` and the inertia about it
    ``I_c = I_O - m (|c|^2 1 - c c^T)``; each parameter after the links' sets the :class:`Robot` field its
    name begins with (``damping[joint]``: the joint's viscosity), joint by joint.

    Parameters
    ----------
    robot : Robot
        The arm: its structure, gravity and limits are kept.
    pi : array_like
        The parameters, in the order of :func:`regressor`'s names.

    Returns
    -------
    Robot
        The arm with those parameters (not tied to a URDF file any more: ``source`` is None).

    Raises
    ------
    HybridError
        ``pi`` of the wrong length or not finite, or not physical: a negative mass, a first moment
        without mass, an inertia about the centre of mass no rigid body has (its pseudo-inertia not
        positive semi-definite), a negative viscosity or Coulomb friction; or the paper's planar arm (its
        parameters are its ``Arm``'s).

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> pi = hybrid.linear_parameters(robot)
    >>> again = hybrid.with_linear_parameters(robot, pi)
    >>> bool(np.allclose(hybrid.linear_parameters(again), pi))
    True
    >>> pi[0] = -1.0
    >>> hybrid.with_linear_parameters(robot, pi)
    Traceback (most recent call last):
    ...
    hybrid.errors.HybridError: pi gives the link moved by ...
    """
    robot = as_robot(robot)
    robot.kind.check_link_change()
    names = linear_parameter_names(robot.chain)
    try:
        pi = np.asarray(pi, dtype=float)
    except (TypeError, ValueError):
        pi = np.array([])
    if pi.shape != (len(names),) or not np.isfinite(pi).all():
        raise HybridError(f"pi must be {len(names)} finite numbers (hybrid.regressor's parameters of this robot), got "
                          f"shape {pi.shape}")
    fix = "give physical parameters (hybrid.identify_dynamics(..., consistent=True) finds them)"
    links = []
    for joint, p in zip(robot.joint_names, pi[:LINK_PARAMETERS * robot.n].reshape(robot.n, LINK_PARAMETERS)):
        m, h = float(p[0]), p[1:4]
        xx, xy, xz, yy, yz, zz = p[4:]
        I_O = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        scale = max(abs(m), float(np.abs(h).max()), 1e-300)
        if m < 0 or (m == 0 and np.abs(h).max() > 1e-12 * scale):
            what = f"a mass of {m:.6g} kg" if m < 0 else f"a first moment {h.tolist()} kg m without mass"
            raise HybridError(f"pi gives the link moved by '{joint}' {what}; {fix}")
        c = h / m if m > 0 else np.zeros(3)
        I_c = I_O - m * (c @ c * np.eye(3) - np.outer(c, c))  # parallel axes: from the frame's origin to c
        problem = inertia_problem(I_c)
        if problem:
            raise HybridError(f"pi gives the link moved by '{joint}' an inertia about its centre of mass that "
                              f"{problem} (its pseudo-inertia is not positive semi-definite); {fix}")
        links.append(LinkInertia(m, tuple(map(float, c)), tuple(tuple(map(float, row)) for row in I_c)))
    fields = {}
    for k, name in enumerate(names[LINK_PARAMETERS * robot.n:], start=LINK_PARAMETERS * robot.n):
        fields.setdefault(name.partition("[")[0], []).append(float(pi[k]))
    for field, values in fields.items():
        if field in NONNEGATIVE and min(values) < 0:
            joint = robot.joint_names[next(i for i, v in enumerate(values) if v < 0)]
            raise HybridError(f"pi gives joint '{joint}' a {field} of {min(values):.6g}; give a {field} >= 0 ({fix})")
    return dataclasses.replace(robot, links=tuple(links), source=None, **{f: tuple(v) for f, v in fields.items()})
