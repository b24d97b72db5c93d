"""Recursive rigid-body algorithms of a serial chain, as CasADi SX expressions.

Conventions of docs/conventions.md §9. Every spatial quantity is in base axes,
about the base origin (Featherstone's "world coordinates"): a motion vector is
``(w, v_O)``, the angular velocity and the velocity of the body point at the base origin;
a force vector ``(n_O, f)``. Joint ``i``'s motion subspace is then ``S_i = (z_i, p_i x z_i)``
(revolute) or ``(0, z_i)`` (prismatic), with ``z_i`` its axis and ``p_i`` a point on it.

- :func:`forward_kinematics`: the joint frames and the tip frame;
- :func:`frame_jacobian`: the tip frame's ``J`` (6 x n, linear rows first, base axes:
  Pinocchio's ``LOCAL_WORLD_ALIGNED``);
- :func:`frame_classical_acceleration`: ``J' q'``, the tip origin's classical acceleration at ``q'' = 0``;
- :func:`crba`: the joint-space inertia ``B(q)`` by the composite-rigid-body algorithm;
- :func:`rnea`: inverse dynamics ``tau = B q'' + n(q, q')`` by recursive Newton-Euler,
  gravity and joint friction included;

:mod:`.body_frame` has the same algorithms in body coordinates and :mod:`.tip_kinematics` the tip's
kinematics from its transforms (fewer operations: the kernels'); these are their reference.

The kinematic structure (joint origins, axes, types) is numbers compiled into the
expressions; the inertial parameters, joint friction and gravity are symbols, so one
build serves every model error and parameter sweep.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from hybrid.spec.chain import (  # noqa: F401  (the chain's data, re-exported for the generator)
    FRICTION,
    INERTIAL,
    INERTIAL_UNITS,
    JOINT_UNITS,
    LINEAR,
    Chain,
    Joint,
    joint_units,
    linear_parameter_names,
    linear_parameter_units,
    parameter_names,
    parameter_units,
)

#: rounding below which a transform's entry is taken as exactly 0 or +-1 (cos(pi/2) = 6e-17)
_SNAP = 1e-15


def row_major(M) -> ca.SX:
    """A matrix flattened row by row (CasADi stores by column) into an output column."""
    return ca.reshape(M.T, -1, 1)


def _snap(x: float) -> float:
    for exact in (0.0, 1.0, -1.0):
        if abs(x - exact) < _SNAP:
            return exact
    return float(x)


def _const(rows) -> ca.SX:
    return ca.SX(ca.DM([[_snap(v) for v in row] for row in rows]))


def _vec(v) -> ca.SX:
    return ca.SX(ca.DM([_snap(x) for x in v]))


def axis_rotation(axis, c, s) -> ca.SX:
    """Rotation about the unit ``axis`` by the angle of cosine ``c`` and sine ``s``, zeros kept exact."""
    x, y, z = (_snap(a) for a in axis)
    rows = []
    for i, (ai, row_k) in enumerate(((x, (0.0, -z, y)), (y, (z, 0.0, -x)), (z, (-y, x, 0.0)))):
        row = []
        for j, aj in enumerate((x, y, z)):
            e = (1.0 if i == j else 0.0) * c + row_k[j] * s + ai * aj * (1 - c)
            row.append(e)
        rows.append(ca.horzcat(*row))
    return ca.vertcat(*rows)


#: how far from a signed permutation a joint origin's rotation, its turn about the joint axis taken
#: out, may be (rounding) for the turn to be taken into the joint's rotation
_PERMUTATION_TOL = 1e-13


def _snapped(M) -> np.ndarray:
    return np.vectorize(_snap)(np.asarray(M, float))


def _unit_axis(axis) -> int | None:
    """``k`` when ``axis`` is exactly +-``e_k``."""
    a = _snapped(axis)
    nonzero = np.flatnonzero(a)
    return int(nonzero[0]) if len(nonzero) == 1 and abs(a[nonzero[0]]) == 1.0 else None


def _turn(axis, angle: float) -> np.ndarray:
    """The rotation by ``angle`` about the unit ``axis`` +-``e_k``."""
    k = _unit_axis(axis)
    c, s = math.cos(angle), math.sin(angle)
    i, j = (k + 1) % 3, (k + 2) % 3
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R if axis[k] > 0 else R.T


def split_rotation(rotation, axis) -> tuple[np.ndarray, float]:
    """``R_T = P Rot(axis, theta)``: a joint origin's rotation as a signed permutation ``P`` (exact
    0 and +-1) after a turn ``theta`` about the joint's own unit axis, which the joint's rotation
    takes in (``R_T R_J(q) = P R_J(q + theta)``: ``P`` costs no product). A URDF's ``rpy`` of a
    rounded pi/2 about the axis (the UR5's) leaves entries of 5e-12 that would otherwise be
    multiplied out. ``theta = 0`` and ``P = R_T`` (snapped) when there is no such split."""
    M, snapped = np.asarray(rotation, float), _snapped(rotation)
    k = _unit_axis(axis)
    if np.isin(snapped, (0.0, 1.0, -1.0)).all() or k is None:
        return snapped, 0.0
    a = _snapped(axis)
    k1, k2 = (k + 1) % 3, (k + 2) % 3
    best = None
    for r, sign in ((r, sign) for r in range(3) for sign in (1.0, -1.0)):
        # the turn phi about e_k that takes R_T's column k1 onto the base axis +-e_r
        phi = math.atan2(sign * M[r, k2], sign * M[r, k1])
        theta = -phi if a[k] > 0 else phi
        P = M @ _turn(a, -theta)
        exact = _snapped(np.round(P))
        if np.abs(P - exact).max() < _PERMUTATION_TOL and (best is None or abs(theta) < abs(best[1])):
            best = exact, theta
    return best if best is not None else (snapped, 0.0)


def turned_rotation(axis, q, theta: float = 0.0) -> ca.SX:
    """``Rot(axis, q + theta)`` by the sine and cosine of ``q`` (the ones an RK4 stage rotates from)."""
    c, s = ca.cos(q), ca.sin(q)
    if theta:
        ct, st = math.cos(theta), math.sin(theta)
        c, s = c * ct - s * st, s * ct + c * st
    return axis_rotation(axis, c, s)


def cross(a, b) -> ca.SX:
    """``a x b`` of two 3-columns."""
    return ca.vertcat(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@dataclass
class Frames:
    """Joint frames in base axes: rotations ``R``, origins ``p``, axes ``z``, motion subspaces ``S``."""

    R: list
    p: list
    z: list
    S: list  # (angular, linear) pairs
    tip_R: ca.SX
    tip_p: ca.SX


def forward_kinematics(chain: Chain, q) -> Frames:
    """Place every joint frame and the tip frame for the joint positions ``q``."""
    R, p = ca.SX.eye(3), ca.SX.zeros(3, 1)
    out = Frames([], [], [], [], None, None)
    for i, j in enumerate(chain.joints):
        p = p + R @ _vec(j.translation)
        if j.kind == "revolute":  # the joint origin's turn about the axis joins the joint's
            P, theta = split_rotation(j.rotation, j.axis)
            R = R @ ca.SX(ca.DM(P))
            z = R @ _vec(j.axis)
            R = R @ turned_rotation(j.axis, q[i], theta)
            S = (z, cross(p, z))
        else:
            R = R @ _const(j.rotation)
            z = R @ _vec(j.axis)
            p = p + z * q[i]
            S = (ca.SX.zeros(3, 1), z)
        out.R.append(R)
        out.p.append(p)
        out.z.append(z)
        out.S.append(S)
    out.tip_p = p + R @ _vec(chain.tip_translation)
    out.tip_R = R @ _const(chain.tip_rotation)
    return out


def frame_jacobian(frames: Frames) -> ca.SX:
    """``J`` (6 x n): the tip origin's velocity and the angular velocity, base axes."""
    cols = []
    for w, v in frames.S:
        cols.append(ca.vertcat(v + cross(w, frames.tip_p), w))
    return ca.horzcat(*cols)


def _motion_cross(m1, m2):
    """Spatial motion cross product ``m1 x m2`` of (angular, linear) pairs."""
    w1, v1 = m1
    w2, v2 = m2
    return cross(w1, w2), cross(w1, v2) + cross(v1, w2)


def _add(a, b):
    return a[0] + b[0], a[1] + b[1]


def _scale(m, s):
    return m[0] * s, m[1] * s


def _dot(m, f):
    return ca.dot(m[0], f[0]) + ca.dot(m[1], f[1])


def velocities_and_bias(frames: Frames, qd):
    """Spatial velocities ``v_i`` and bias accelerations ``c_i`` (at ``q'' = 0``, no gravity) of every
    link: ``v_i = v_{i-1} + S_i q'_i``, ``c_i = c_{i-1} + v_i x S_i q'_i``. Shared by ``J' q'`` and
    the Newton-Euler pass, which adds ``sum S_j q''_j`` and gravity to them."""
    zero = ca.SX.zeros(3, 1)
    v, c = (zero, zero), (zero, zero)
    vs, bias = [], []
    for i, S in enumerate(frames.S):
        v = _add(v, _scale(S, qd[i]))
        c = _add(c, _motion_cross(v, _scale(S, qd[i])))
        vs.append(v)
        bias.append(c)
    return vs, bias


def frame_classical_acceleration(frames: Frames, qd) -> ca.SX:
    """``J'(q, q') q'`` (6): the tip origin's classical linear acceleration and the angular
    acceleration at ``q'' = 0``, no gravity."""
    vs, accs = velocities_and_bias(frames, qd)
    (w, v), (alpha, a) = vs[-1], accs[-1]
    p = frames.tip_p
    v_tip = v + cross(w, p)
    return ca.vertcat(a + cross(alpha, p) + cross(w, v_tip), alpha)


@dataclass
class Inertia:
    """A (composite) rigid-body inertia about a frame's origin, in its axes (the base's here, a
    link's in :mod:`.body_frame`): mass ``m``, first moment ``h = m c`` and rotational inertia
    ``I_O`` about the origin (3x3)."""

    m: object
    h: ca.SX
    I: ca.SX  # noqa: E741

    def __add__(self, other: Inertia) -> Inertia:
        return Inertia(self.m + other.m, self.h + other.h, self.I + other.I)

    def apply(self, motion):
        """The momentum (force vector) ``I v`` of the motion ``v = (w, v_O)``."""
        w, v = motion
        return self.I @ w + cross(self.h, v), self.m * v - cross(self.h, w)

    def wrench(self, motion, acc):
        """The spatial force ``I a + v x* (I v)`` that gives the body the acceleration ``acc``."""
        w, v = motion
        ia, (n_mom, f_mom) = self.apply(acc), self.apply(motion)
        return ia[0] + cross(w, n_mom) + cross(v, f_mom), ia[1] + cross(w, f_mom)

    def newton_euler(self, w, alpha, a):
        """The same force from the angular velocity ``w`` and acceleration ``alpha`` and the origin's
        classical acceleration ``a``: ``(I alpha + w x I w + h x a, m a + alpha x h + w x (w x h))``."""
        f = self.m * a + cross(alpha, self.h) + cross(w, cross(w, self.h))
        return self.I @ alpha + cross(w, self.I @ w) + cross(self.h, a), f


@dataclass
class Body:
    """A link's inertia kept in its own frame: mass ``m``, centre of mass ``c`` (base axes, about
    the origin) and the constant inertia ``Ic`` about it in link axes, with the link's rotation
    ``R``. Applying it rotates the motion in and the moment out (cheaper than forming ``R Ic R^T``
    when it is applied only a few times, as in Newton-Euler)."""

    m: object
    c: ca.SX
    Ic: ca.SX
    R: ca.SX

    def apply(self, motion):
        """The momentum ``I v`` of ``v = (w, v_O)``: ``(R Ic R^T w + c x h, h)`` with ``h = m (v_O + w x c)``."""
        w, v = motion
        h = self.m * (v + cross(w, self.c))
        return self.R @ (self.Ic @ (self.R.T @ w)) + cross(self.c, h), h

    def about_origin(self) -> Inertia:
        """The same inertia as an :class:`Inertia` about the base origin (parallel axes:
        ``I_O = R Ic R^T + m (|c|^2 1 - c c^T)``), which composites add up."""
        c = self.c
        I_O = self.R @ self.Ic @ self.R.T + self.m * (ca.dot(c, c) * ca.SX.eye(3) - c @ c.T)
        return Inertia(self.m, self.m * c, I_O)

    def wrench(self, motion, acc):
        """``I a + v x* (I v)`` by Newton and Euler about the centre of mass (fewer operations):
        ``F = m a_c`` with ``a_c = a_O + alpha x c + w x v_c``, and about the origin
        ``c x F + R (Ic alpha_L + w_L x Ic w_L)`` with ``alpha_L, w_L`` in link axes."""
        (w, v), (alpha, a) = motion, acc
        v_c = v + cross(w, self.c)
        F = self.m * (a + cross(alpha, self.c) + cross(w, v_c))
        w_l, alpha_l = self.R.T @ w, self.R.T @ alpha
        return self.R @ (self.Ic @ alpha_l + cross(w_l, self.Ic @ w_l)) + cross(self.c, F), F


def link_bodies(chain: Chain, frames: Frames, params) -> list[Body]:
    """Each link's :class:`Body` from the ``robot`` parameters."""
    out = []
    k = len(INERTIAL)
    for i in range(chain.n):
        m, cx, cy, cz, ixx, ixy, ixz, iyy, iyz, izz = (params[i * k + j] for j in range(k))
        R = frames.R[i]
        Ic = ca.vertcat(ca.horzcat(ixx, ixy, ixz), ca.horzcat(ixy, iyy, iyz), ca.horzcat(ixz, iyz, izz))
        out.append(Body(m, frames.p[i] + R @ ca.vertcat(cx, cy, cz), Ic, R))
    return out


def link_inertias(chain: Chain, frames: Frames, params) -> list[Inertia]:
    """Each link's inertia in base axes about the base origin (for composites, as in the CRBA)."""
    return [b.about_origin() for b in link_bodies(chain, frames, params)]


def gravity(chain: Chain, params) -> ca.SX:
    """Gravity ``g`` [m/s^2] in base axes: the ``robot`` array's last three entries."""
    base = (len(INERTIAL) + len(FRICTION)) * chain.n
    return ca.vertcat(*(params[base + i] for i in range(3)))


def joint_friction(chain: Chain, params, qd, linear: bool = False) -> list:
    """Each joint's friction torque ``F_v q' + F_c tanh(q' / v_s) + tau_0`` (the :data:`FRICTION` blocks of
    the ``robot`` array): viscous, Coulomb with a smooth sign of speed ``v_s > 0``, and an offset. With
    ``linear``, the Coulomb term is the product itself, with no branch on ``F_c``: linear in ``F_c``."""
    base, n = len(INERTIAL) * chain.n, chain.n
    Fv, Fc, tau0, vs = ([params[base + b * n + i] for i in range(n)] for b in range(len(FRICTION)))
    # F_c = 0 (every shipped arm's) gives exactly 0 without the smooth sign: the C branches past its
    # division and tanh (a hundred instructions each joint), where 0 * tanh would compute them
    coulomb = [Fc[i] * ca.tanh(qd[i] / vs[i]) for i in range(n)]
    if not linear:
        coulomb = [ca.if_else(Fc[i] != 0, c, 0) for i, c in enumerate(coulomb)]
    return [Fv[i] * qd[i] + coulomb[i] + tau0[i] for i in range(n)]


def crba(chain: Chain, frames: Frames, params, inertias: list[Inertia] | None = None) -> ca.SX:
    """``B(q)`` (n x n, symmetric) by the composite-rigid-body algorithm:
    ``B_ij = S_j . (Ic_i S_i)`` for ``j <= i``, ``Ic_i`` the inertia of links ``i..n``."""
    inertias = inertias or link_inertias(chain, frames, params)
    B = [[None] * chain.n for _ in range(chain.n)]
    composite = None
    for i in reversed(range(chain.n)):
        composite = inertias[i] if composite is None else composite + inertias[i]
        F = composite.apply(frames.S[i])
        for j in range(i + 1):
            B[i][j] = B[j][i] = _dot(frames.S[j], F)
    return ca.vertcat(*(ca.horzcat(*row) for row in B))


def rnea(chain: Chain, frames: Frames, params, qd, qdd=None, bodies=None) -> ca.SX:
    """``tau = B q'' + n(q, q')`` by recursive Newton-Euler (``q'' = 0`` when ``qdd`` is None):
    Coriolis/centrifugal, gravity and joint friction (:func:`joint_friction`). ``bodies`` (anything with
    ``wrench``) reuses inertias already formed, e.g. the CRBA's."""
    friction, g = joint_friction(chain, params, qd), gravity(chain, params)
    inertias = bodies or link_bodies(chain, frames, params)
    vs, bias = velocities_and_bias(frames, qd)
    # a_i = c_i + sum_{j <= i} S_j q''_j + a_0, with gravity as the base's fictitious acceleration
    # a_0 = (0, -g): in base axes it is the same vector for every link
    accs, acc = [], (ca.SX.zeros(3, 1), -g)
    for i in range(chain.n):
        if qdd is not None:
            acc = _add(acc, _scale(frames.S[i], qdd[i]))
        accs.append(_add(bias[i], acc))
    tau = [None] * chain.n
    total = None
    for i in reversed(range(chain.n)):
        f = inertias[i].wrench(vs[i], accs[i])
        total = f if total is None else _add(total, f)
        tau[i] = _dot(frames.S[i], total) + friction[i]
    return ca.vertcat(*tau)
