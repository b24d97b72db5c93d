"""The tip frame's kinematics from the body-frame tree: its placement, ``J`` and ``J' q'``.

The dynamics in body coordinates (:mod:`.body_frame`) already place every link relative to its parent
(:func:`.body_frame.link_transforms`) and move it (:func:`.body_frame.link_velocities`); the tip frame's
placement, its frame Jacobian and its classical acceleration follow from the same transforms, so one
kinematic pass serves the kinematics and the dynamics of a kernel.

- :func:`placements`: each link's axes and origin in base coordinates, and the tip frame's;
- :func:`frame_jacobian`: ``J`` (6 x n, linear rows first, base axes: Pinocchio's
  ``LOCAL_WORLD_ALIGNED``);
- :func:`frame_velocity`: ``J q'``, the tip's twist, from the last link's velocity;
- :func:`classical_acceleration`: ``J' q'``, the tip origin's classical acceleration at ``q'' = 0``, no
  gravity, from the links' velocities and bias accelerations in their own coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from . import body_frame as bf
from .rigid_body import _const, _vec, cross


@dataclass(frozen=True)
class Placements:
    """A tree's links in base axes: ``R[i]`` link ``i``'s axes (columns), ``z[i]`` its joint axis and
    ``r[i]`` the tip frame's origin from link ``i``'s; ``tip_R`` and ``tip_p`` the tip frame's axes and
    origin."""

    R: tuple
    z: tuple
    r: tuple
    tip_R: ca.SX
    tip_p: ca.SX


def placements(tree: bf.Tree) -> Placements:
    """Every link's axes in base axes, from the base out (``R_i = R_{i-1} R_T R_J``: the joint origin's
    rotation ``R_T`` is a signed permutation where the chain allows it, a product that costs nothing),
    then the tip's origin from each link's, from the tip in (``r_{i-1} = r_i + R_{i-1} p_i``, the tip's
    own ``r_n = R_n t``): one sum a link, and no difference of two origins."""
    R, Rs, zs = ca.SX.eye(3), [], []
    for X, joint in zip(tree.X, tree.chain.joints):
        R = R @ X.R_T
        zs.append(R @ _vec(joint.axis))
        R = R @ X.R_J
        Rs.append(R)
    r = [None] * tree.n
    r[-1] = R @ tree.tip
    for i in reversed(range(1, tree.n)):
        r[i - 1] = r[i] + Rs[i - 1] @ tree.X[i].p
    tip_R = R @ _const(tree.chain.tip_rotation)
    return Placements(tuple(Rs), tuple(zs), tuple(r), tip_R, tree.X[0].p + r[0])


def frame_jacobian(tree: bf.Tree, frames: Placements) -> ca.SX:
    """``J`` (6 x n): column ``i`` is ``(z_i x r_i, z_i)`` for a revolute joint, ``(z_i, 0)`` for a
    prismatic one (:class:`Placements`)."""
    cols = []
    for joint, z, r in zip(tree.chain.joints, frames.z, frames.r):
        if joint.kind == "revolute":
            cols.append(ca.vertcat(cross(z, r), z))
        else:
            cols.append(ca.vertcat(z, ca.SX.zeros(3, 1)))
    return ca.horzcat(*cols)


def frame_velocity(tree: bf.Tree, frames: Placements, velocities) -> ca.SX:
    """``J q'`` (6): the tip origin's velocity ``v + w x t`` and the angular velocity ``w``, base axes, of the
    last link's velocity ``(w, v)`` (:func:`.body_frame.link_velocities`), ``t`` the tip's origin in its
    coordinates."""
    w, v = velocities[-1]
    R = frames.R[-1]
    return ca.vertcat(R @ (v + cross(w, tree.tip)), R @ w)


def bias_accelerations(tree: bf.Tree, qd, velocities) -> list:
    """Every link's spatial acceleration at ``q'' = 0`` without gravity, its own coordinates:
    ``c_i = X_i c_{i-1} + v_i x S_i q'_i``, ``c_0 = 0``."""
    zero = ca.SX.zeros(3, 1)
    acc, out = (zero, zero), []
    for i, X in enumerate(tree.X):
        acc = bf._add(X.motion(acc), bf._motion_cross(velocities[i], bf._scale(tree.S[i], qd[i])))
        out.append(acc)
    return out


def classical_acceleration(tree: bf.Tree, frames: Placements, qd, velocities=None) -> ca.SX:
    """``J'(q, q') q'`` (6): the tip origin's classical linear acceleration and the angular acceleration at
    ``q'' = 0``, no gravity, base axes: ``a + alpha x t + w x (v + w x t)`` and ``alpha`` of the last link's
    velocity ``(w, v)`` and bias acceleration ``(alpha, a)``, ``t`` the tip's origin in its coordinates."""
    vs = velocities or bf.link_velocities(tree, qd)
    (w, v), (alpha, a) = vs[-1], bias_accelerations(tree, qd, vs)[-1]
    t = tree.tip
    R = frames.R[-1]
    return ca.vertcat(R @ (a + cross(alpha, t) + cross(w, v + cross(w, t))), R @ alpha)
