"""Featherstone's recursive algorithms in body coordinates, as CasADi SX expressions.

R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer 2008: spatial algebra (ch. 2), the
kinematic tree's transforms ``X_i = X_J(q_i) X_T(i)`` (ch. 4), the recursive Newton-Euler
algorithm (ch. 5, table 5.1), the composite-rigid-body algorithm (ch. 6, table 6.2) and the
articulated-body algorithm (ch. 7, table 7.1), each in body coordinates.

Every link's spatial quantities are in its own frame (:class:`BodyFrames`): the URDF's link axes,
the origin on the joint axis. A motion vector is ``(w, v)``, the angular velocity and the velocity
of the body point at the frame's origin; a force vector ``(n, f)``, the moment about the origin and
the force. The transform from a link's parent is a constant rotation (URDF rotations snapped to
exact 0 and +-1 where they are, a turn about the joint axis taken into the joint angle) and
translation, then the joint's rotation about, or translation along, its axis; a joint axis along a
unit vector of its frame makes the motion subspace ``S_i`` a unit vector and the joint's rotation
one plane's. The inertias are constant in their frames and the transforms sparse, so CasADi's
symbolic zeros remove most of the products the base-frame algorithms of :mod:`.rigid_body` form
(both give the same ``B``, ``n`` and ``q''`` to rounding).

- :func:`link_transforms`: the chain placed at ``q`` (a :class:`Tree`);
- :func:`link_velocities`: every link's spatial velocity;
- :func:`rnea`: inverse dynamics ``tau = B q'' + n(q, q') - sum J_i^T f_ext_i``, gravity and viscosity in;
- :func:`crba`: the joint-space inertia ``B(q)``;
- :func:`aba`: forward dynamics ``q''`` in ``O(n)``, without ``B`` (for 6 or 7 joints CRBA, RNEA and
  a factorisation of ``B`` take fewer operations);
- :func:`tip_position`, :func:`tip_velocity`, :func:`tip_force`, :func:`to_base`, :func:`from_base`:
  the tip and vectors between a link's axes and the base's.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import casadi as ca
import numpy as np

from .factor import reciprocal
from .rigid_body import (
    INERTIAL,
    Chain,
    Inertia,
    _snapped,
    _unit_axis,
    _vec,
    cross,
    gravity,
    joint_friction,
    split_rotation,
    turned_rotation,
)


@dataclass(frozen=True)
class LinkTransform:
    """``X_i = X_J(q_i) X_T(i)``, from the parent's coordinates to link ``i``'s: the link's axes are
    the columns of ``A = R_T R_J`` in the parent's axes and its origin is at ``p`` there. ``R_T``
    is the joint origin's constant rotation, ``R_J`` the joint's rotation (the identity for a
    prismatic joint, whose travel is in ``p``). Rotations are applied one after the other: each is
    sparse, their product may not be."""

    R_T: ca.SX
    R_J: ca.SX
    p: ca.SX

    def rotate_in(self, x) -> ca.SX:
        """``A^T x``: a parent-axes vector in the link's axes."""
        return self.R_J.T @ (self.R_T.T @ x)

    def rotate_out(self, x) -> ca.SX:
        """``A x``: a link-axes vector in the parent's axes."""
        return self.R_T @ (self.R_J @ x)

    def motion(self, m):
        """``X m``: the parent's motion vector ``(w, v)`` in the link's coordinates."""
        w, v = m
        return self.rotate_in(w), self.rotate_in(v - cross(self.p, w))

    def force(self, f):
        """``X^T f``: the link's force vector ``(n, f)`` in the parent's coordinates."""
        n, f = f
        fp = self.rotate_out(f)
        return self.rotate_out(n) + cross(self.p, fp), fp

    def inertia(self, inertia: Inertia) -> Inertia:
        """``X^T I X``: the link's rigid-body inertia in the parent's coordinates (Featherstone
        eq. 2.63): ``h' = A h + m p``, ``I' = A I A^T - p~ (A h)~ - (A h)~ p~ - m p~ p~``."""
        m, p = inertia.m, self.p
        h = self.rotate_out(inertia.h)
        Irot = _rotate_symmetric(self, inertia.I)
        k = m * p
        # -p~ h~ - h~ p~ - m p~ p~ = 2 (p.h) 1 + m |p|^2 1 - (h p^T + p h^T) - m p p^T
        diag = 2 * ca.dot(p, h) + ca.dot(k, p)
        rows = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(i, 3):
                e = Irot[i, j] - (h[i] * p[j] + p[i] * h[j]) - k[i] * p[j]
                rows[i][j] = rows[j][i] = e + diag if i == j else e
        return Inertia(m, h + k, _matrix(rows))

    def articulated(self, a: ArticulatedInertia) -> ArticulatedInertia:
        """``X^T I^A X``: an articulated-body inertia in the parent's coordinates. With the blocks
        rotated into the parent's axes (``A'``, ``B'``, ``C'``), the shift of origin by ``p`` gives
        ``C = C'``, ``B = B' + p~ C'``, ``A = A' - B' p~ + p~ B'^T - p~ C' p~``."""
        Ar, Br, Cr = (_rotate_symmetric(self, a.A), _rotate(self, a.B), _rotate_symmetric(self, a.C))
        P = _skew(self.p)
        PC = P @ Cr
        Y, M = P @ Br.T, PC @ P  # -B' p~ + p~ B'^T = Y + Y^T
        return ArticulatedInertia(_symmetric(lambda i, j: Ar[i, j] + Y[i, j] + Y[j, i] - M[i, j]), Br + PC, Cr)


def _matrix(rows) -> ca.SX:
    return ca.vertcat(*(ca.horzcat(*row) for row in rows))


def _symmetric(entry) -> ca.SX:
    """The symmetric 3x3 matrix of ``entry(i, j)`` for ``i <= j`` (each entry formed once)."""
    rows = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            rows[i][j] = rows[j][i] = entry(i, j)
    return _matrix(rows)


def _skew(p) -> ca.SX:
    return _matrix([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])


def _rotate(X: LinkTransform, M) -> ca.SX:
    """``A M A^T`` (a link-axes tensor in the parent's axes)."""
    M = X.R_J @ M @ X.R_J.T
    return X.R_T @ M @ X.R_T.T


def _elementary_axis(R) -> int | None:
    """``k`` when ``R`` turns about the base axis ``k`` (row and column ``k`` exactly ``e_k``)."""
    for k in range(3):
        if R[k, k].is_one() and all(R[k, j].is_zero() and R[j, k].is_zero() for j in range(3) if j != k):
            return k
    return None


def _turn_symmetric(R, M) -> ca.SX:
    """``R M R^T`` for a symmetric ``M``, each entry of the result formed once. A joint's turn about a base
    axis ``k`` by the angle of cosine ``c`` and sine ``s`` changes the plane ``(i, j)`` only:
    ``M'_ii = M_ii - t``, ``M'_jj = M_jj + t`` with ``t = s^2 (M_ii - M_jj) + 2 c s M_ij``,
    ``M'_ij = c s (M_ii - M_jj) + M_ij - 2 s^2 M_ij``, ``M'_ik = c M_ik - s M_jk``,
    ``M'_jk = s M_ik + c M_jk``."""
    k = None if R.is_constant() else _elementary_axis(R)  # a signed permutation: no product
    if k is None:
        RM = R @ M
        return _symmetric(lambda i, j: ca.dot(RM[i, :].T, R[j, :].T))
    i, j = (k + 1) % 3, (k + 2) % 3
    c, s = R[i, i], R[j, i]
    s2, cs, d, twice = s * s, c * s, M[i, i] - M[j, j], 2 * M[i, j]
    t = s2 * d + cs * twice
    out = {(i, i): M[i, i] - t, (j, j): M[j, j] + t, (i, j): cs * d + M[i, j] - s2 * twice,
           (i, k): c * M[i, k] - s * M[j, k], (j, k): s * M[i, k] + c * M[j, k], (k, k): M[k, k]}
    return _symmetric(lambda r, q: out[(r, q)] if (r, q) in out else out[(q, r)])


def _rotate_symmetric(X: LinkTransform, M) -> ca.SX:
    """``A M A^T`` for a symmetric ``M``: the joint's turn, then the joint origin's rotation."""
    return _turn_symmetric(X.R_T, _turn_symmetric(X.R_J, M))


@dataclass(frozen=True)
class ArticulatedInertia:
    """A 6x6 symmetric articulated-body inertia ``[[A, B], [B^T, C]]`` (angular rows first):
    the force ``(n, f) = (A w + B v, B^T w + C v)`` of the motion ``(w, v)``."""

    A: ca.SX
    B: ca.SX
    C: ca.SX

    @staticmethod
    def of(inertia: Inertia) -> ArticulatedInertia:
        """A rigid body's: ``A = I``, ``B = h~``, ``C = m 1``."""
        return ArticulatedInertia(inertia.I, _skew(inertia.h), inertia.m * ca.SX.eye(3))

    def apply(self, m):
        w, v = m
        return self.A @ w + self.B @ v, self.B.T @ w + self.C @ v

    def __add__(self, other: ArticulatedInertia) -> ArticulatedInertia:
        return ArticulatedInertia(self.A + other.A, self.B + other.B, self.C + other.C)

    def less(self, U, d_inv) -> ArticulatedInertia:
        """``I - U d_inv U^T`` for a force vector ``U = (U_n, U_f)`` and a scalar ``d_inv``."""
        (Un, Uf), (Dn, Df) = U, (U[0] * d_inv, U[1] * d_inv)
        return ArticulatedInertia(_symmetric(lambda r, s: self.A[r, s] - Un[r] * Dn[s]), self.B - Un @ Df.T,
                                  _symmetric(lambda r, s: self.C[r, s] - Uf[r] * Df[s]))


def _motion_subspace(joint) -> tuple:
    a = _vec(joint.axis)
    zero = ca.SX.zeros(3, 1)
    return (a, zero) if joint.kind == "revolute" else (zero, a)


@dataclass(frozen=True)
class BodyFrames:
    """Where the algorithms put each link's frame, as numbers of the chain alone.

    Link ``i``'s axes are its joint frame's after the joint's motion (the URDF's link axes), its
    origin is the joint frame's slid by ``slide[i]`` along the joint axis ``a_i``: a revolute
    joint's axis is a line of the link, so any point on it may be the origin. Each link after the
    first puts its origin at the point of its axis nearest its parent's origin (as the modified
    Denavit-Hartenberg convention does): the parent-to-link translation ``p_i`` then has no
    component along the axis, one product fewer in each use of it. (The first link's translation
    is from the base, at rest: it costs nothing, and is left.) ``rotation[i]`` is the joint
    origin's rotation ``P_i`` with the turn ``turn[i]`` about the axis taken out
    (:func:`split_rotation`), ``translation[i]`` the parent-to-link ``p_i`` in the parent's axes at
    ``q = 0`` (a prismatic joint adds its travel), ``tip`` the tip frame's origin in the last
    link's."""

    rotation: tuple[np.ndarray, ...]
    turn: tuple[float, ...]
    translation: tuple[np.ndarray, ...]
    slide: tuple[float, ...]
    tip: np.ndarray


@cache
def body_frames(chain: Chain) -> BodyFrames:
    """The :class:`BodyFrames` of ``chain``."""
    rotations, turns, translations, slides = [], [], [], []
    parent_slide = np.zeros(3)  # the parent's origin, moved along its axis, in its axes
    for i, j in enumerate(chain.joints):
        if j.kind == "revolute":
            P, theta = split_rotation(j.rotation, j.axis)
        else:
            P, theta = _snapped(j.rotation), 0.0
        p = _snapped(j.translation) - parent_slide
        u = P @ _snapped(j.axis)  # the joint axis in the parent's axes
        d = 0.0
        if i > 0 and j.kind == "revolute" and _unit_axis(u) is not None:
            d = -float(p @ u)  # exact: u is a signed unit vector, the other components are untouched
            p = p + d * u
        rotations.append(P)
        turns.append(theta)
        translations.append(_snapped(p))
        slides.append(d)
        parent_slide = d * _snapped(j.axis)
    return BodyFrames(tuple(rotations), tuple(turns), tuple(translations), tuple(slides),
                      _snapped(np.asarray(chain.tip_translation, float) - parent_slide))


@dataclass(frozen=True)
class Tree:
    """A serial chain placed at ``q`` in its :class:`BodyFrames`: the transforms ``X_i`` and the
    motion subspaces ``S_i``."""

    chain: Chain
    frames: BodyFrames
    X: tuple[LinkTransform, ...]
    S: tuple[tuple, ...]

    @property
    def n(self) -> int:
        return self.chain.n

    @property
    def tip(self) -> ca.SX:
        """The tip frame's origin in the last link's coordinates."""
        return ca.SX(ca.DM(self.frames.tip))


def link_transforms(chain: Chain, q) -> Tree:
    """The parent-to-link transforms ``X_i = X_J(q_i) X_T(i)`` at the joint positions ``q``, in the
    chain's :func:`body_frames`."""
    frames = body_frames(chain)
    X, S = [], []
    for i, j in enumerate(chain.joints):
        R_T, p = ca.SX(ca.DM(frames.rotation[i])), ca.SX(ca.DM(frames.translation[i]))
        if j.kind == "revolute":
            R_J = turned_rotation(j.axis, q[i], frames.turn[i])
        else:
            R_J, p = ca.SX.eye(3), p + R_T @ (_vec(j.axis) * q[i])
        X.append(LinkTransform(R_T, R_J, p))
        S.append(_motion_subspace(j))
    return Tree(chain, frames, tuple(X), tuple(S))


def _scale(m, s):
    return m[0] * s, m[1] * s


def _add(a, b):
    return a[0] + b[0], a[1] + b[1]


def _dot(m, f):
    return ca.dot(m[0], f[0]) + ca.dot(m[1], f[1])


def _motion_cross(m1, m2):
    """``m1 x m2`` of motion vectors."""
    (w1, v1), (w2, v2) = m1, m2
    return cross(w1, w2), cross(w1, v2) + cross(v1, w2)


def link_velocities(tree: Tree, qd) -> list:
    """Every link's spatial velocity ``v_i = X_i v_{i-1} + S_i q'_i`` (``v_0 = 0``), its own coordinates."""
    zero = ca.SX.zeros(3, 1)
    v, out = (zero, zero), []
    for i, X in enumerate(tree.X):
        v = _add(X.motion(v), _scale(tree.S[i], qd[i]))
        out.append(v)
    return out


@dataclass(frozen=True)
class Link:
    """A link's inertial parameters in its own frame: mass ``m``, centre of mass ``c`` and the
    inertia ``Ic`` about it (the ``robot`` array's, run-time symbols)."""

    m: object
    c: ca.SX
    Ic: ca.SX

    def newton_euler(self, w, alpha, a):
        """The force ``(n, f)`` (moment about the origin) that gives the link the angular velocity ``w`` and
        acceleration ``alpha`` and its origin the acceleration ``a`` (the classical one, not the spatial):
        by Newton and Euler about the centre of mass, ``f = m a_c`` with ``a_c = a + alpha x c + w x (w x c)``,
        and ``n = Ic alpha + w x Ic w + c x f``."""
        f = self.m * (a + cross(alpha, self.c) + cross(w, cross(w, self.c)))
        return self.Ic @ alpha + cross(w, self.Ic @ w) + cross(self.c, f), f

    def inertia(self) -> Inertia:
        """The spatial inertia about the frame's origin: ``h = m c``, ``I = Ic - m c~ c~``."""
        h = self.m * self.c
        hc = [h[i] * self.c[i] for i in range(3)]
        return Inertia(self.m, h, _symmetric(lambda i, j: self.Ic[i, j] + (
            sum(hc[k] for k in range(3) if k != i) if i == j else -h[i] * self.c[j])))


def links(tree: Tree, params) -> list[Link]:
    """Each link's :class:`Link` from the ``robot`` parameters, its centre of mass in the tree's
    frame (``c - slide_i a_i``)."""
    out, k = [], len(INERTIAL)
    for i, joint in enumerate(tree.chain.joints):
        m, cx, cy, cz, ixx, ixy, ixz, iyy, iyz, izz = (params[i * k + j] for j in range(k))
        Ic = _matrix([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        c = ca.vertcat(cx, cy, cz)
        if tree.frames.slide[i]:
            c = c - tree.frames.slide[i] * _vec(joint.axis)
        out.append(Link(m, c, Ic))
    return out


def rnea(tree: Tree, params, qd, qdd=None, f_ext=None, velocities=None, bodies=None, friction=None) -> ca.SX:
    """``tau = B q'' + n(q, q') - sum_i J_i^T f_ext_i`` by the recursive Newton-Euler algorithm in
    body coordinates (Featherstone table 5.1, with Luh, Walker and Paul's accelerations; ``q'' = 0``
    when ``qdd`` is None): Coriolis and centrifugal terms, gravity (the base's fictitious acceleration
    ``-g``) and joint friction (:func:`.rigid_body.joint_friction`). ``f_ext`` maps a link's index to the
    force ``(n, f)`` the environment exerts on it, in its coordinates. ``velocities`` reuses
    :func:`link_velocities`' angular velocities. ``bodies`` (anything with ``newton_euler``, one per link
    in the tree's frames) stands for the links of ``params``, whose friction and gravity are still read;
    ``friction`` (the joints' torques) stands for :func:`.rigid_body.joint_friction`'s.

    The forward pass carries each link's angular velocity ``w`` and acceleration ``alpha`` and its
    origin's classical acceleration ``a`` (not the spatial one): the origin's velocity is never needed,
    and the parent's ``alpha x p + w x (w x p)`` is cheaper than carrying it (``p`` has one or two
    components where the links' frames follow the joints)."""
    n = tree.n
    g = gravity(tree.chain, params)
    friction = friction or joint_friction(tree.chain, params, qd)
    bodies = bodies or links(tree, params)
    zero = ca.SX.zeros(3, 1)
    w, alpha, a, forces = zero, zero, -g, []
    for i, X in enumerate(tree.X):
        (Sw, Sv), p = tree.S[i], X.p
        w_in = X.rotate_in(w)  # the parent's angular velocity in the link's axes
        a = X.rotate_in(a + cross(alpha, p) + cross(w, cross(w, p))) + cross(w_in, 2 * qd[i] * Sv)
        alpha = X.rotate_in(alpha) + cross(w_in, qd[i] * Sw)
        if qdd is not None:
            a, alpha = a + qdd[i] * Sv, alpha + qdd[i] * Sw
        w = velocities[i][0] if velocities else w_in + qd[i] * Sw
        f = bodies[i].newton_euler(w, alpha, a)
        if f_ext and i in f_ext:
            f = (f[0] - f_ext[i][0], f[1] - f_ext[i][1])
        forces.append(f)
    tau = [None] * n
    for i in reversed(range(n)):
        tau[i] = _dot(tree.S[i], forces[i]) + friction[i]
        if i > 0:
            forces[i - 1] = _add(forces[i - 1], tree.X[i].force(forces[i]))
    return ca.vertcat(*tau)


def crba(tree: Tree, params) -> ca.SX:
    """``B(q)`` (n x n, symmetric) by the composite-rigid-body algorithm in body coordinates
    (Featherstone table 6.2): the composite inertia ``I^c_i`` of links ``i..n`` in link ``i``'s
    coordinates, ``F = I^c_i S_i``, ``B_ii = S_i^T F``, then ``B_ij = S_j^T F`` with ``F`` carried
    to each ancestor ``j`` by ``X_{j+1}^T``."""
    n = tree.n
    inertias = [b.inertia() for b in links(tree, params)]
    B = [[None] * n for _ in range(n)]
    composite = None
    for i in reversed(range(n)):
        composite = inertias[i] if composite is None else tree.X[i + 1].inertia(composite) + inertias[i]
        F = composite.apply(tree.S[i])
        B[i][i] = _dot(tree.S[i], F)
        for j in reversed(range(i)):
            F = tree.X[j + 1].force(F)
            B[i][j] = B[j][i] = _dot(tree.S[j], F)
    return _matrix(B)


def aba(tree: Tree, params, qd, tau, f_ext=None, velocities=None) -> ca.SX:
    """``q''`` of ``B q'' + n(q, q') = tau + sum_i J_i^T f_ext_i`` by the articulated-body algorithm
    in body coordinates (Featherstone table 7.1), with gravity (the base's acceleration ``-g``) and
    joint friction (``tau_i`` less joint ``i``'s friction drives it); ``f_ext`` as :func:`rnea`'s."""
    n = tree.n
    friction, g = joint_friction(tree.chain, params, qd), gravity(tree.chain, params)
    bodies = links(tree, params)
    vs = velocities or link_velocities(tree, qd)
    IA, pA, c = [], [], []
    for i in range(n):
        inertia = bodies[i].inertia()
        IA.append(ArticulatedInertia.of(inertia))
        w, v = vs[i]
        mom_n, mom_f = inertia.apply(vs[i])
        p = (cross(w, mom_n) + cross(v, mom_f), cross(w, mom_f))  # v x* (I v)
        if f_ext and i in f_ext:
            p = (p[0] - f_ext[i][0], p[1] - f_ext[i][1])
        pA.append(p)
        c.append(_motion_cross(vs[i], _scale(tree.S[i], qd[i])))
    U, Dinv, u = [None] * n, [None] * n, [None] * n
    for i in reversed(range(n)):
        U[i] = IA[i].apply(tree.S[i])
        Dinv[i] = reciprocal(_dot(tree.S[i], U[i]))
        u[i] = tau[i] - friction[i] - _dot(tree.S[i], pA[i])
        if i > 0:  # I^a = I^A - U D^-1 U^T, p^a = p^A + I^a c + U D^-1 u, carried to the parent
            Ia = IA[i].less(U[i], Dinv[i])
            pa = _add(_add(pA[i], Ia.apply(c[i])), _scale(U[i], Dinv[i] * u[i]))
            IA[i - 1] = IA[i - 1] + tree.X[i].articulated(Ia)
            pA[i - 1] = _add(pA[i - 1], tree.X[i].force(pa))
    zero = ca.SX.zeros(3, 1)
    acc, qdd = (zero, -g), [None] * n
    for i in range(n):
        acc = _add(tree.X[i].motion(acc), c[i])
        qdd[i] = Dinv[i] * (u[i] - _dot(U[i], acc))
        acc = _add(acc, _scale(tree.S[i], qdd[i]))
    return ca.vertcat(*qdd)


def to_base(tree: Tree, x, link: int | None = None) -> ca.SX:
    """A vector in link ``link``'s axes (the last link's by default) in base axes."""
    for X in reversed(tree.X[:tree.n if link is None else link + 1]):
        x = X.rotate_out(x)
    return x


def from_base(tree: Tree, x, link: int | None = None) -> ca.SX:
    """A vector in base axes in link ``link``'s axes (the last link's by default)."""
    for X in tree.X[:tree.n if link is None else link + 1]:
        x = X.rotate_in(x)
    return x


def tip_position(tree: Tree) -> ca.SX:
    """The tip frame's origin in base coordinates."""
    p = tree.tip
    for X in reversed(tree.X):
        p = X.p + X.rotate_out(p)
    return p


def tip_velocity(tree: Tree, velocities) -> ca.SX:
    """The velocity of the tip frame's origin in base axes, from :func:`link_velocities`."""
    w, v = velocities[-1]
    return to_base(tree, v + cross(w, tree.tip))


def tip_force(tree: Tree, force, moment=None) -> dict:
    """A force (base axes) on the last link at the tip frame's origin, and a moment (base axes), as
    ``f_ext`` of :func:`rnea` and :func:`aba`: ``{n - 1: (m + tip x f, f)}`` in the last link's
    coordinates."""
    f = from_base(tree, force)
    n = cross(tree.tip, f)
    return {tree.n - 1: (n if moment is None else from_base(tree, moment) + n, f)}
