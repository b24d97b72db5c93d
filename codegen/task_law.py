"""The decoupling law in its general (spatial) form, conventions §9, for any serial arm and surface.

Task axes: the six rows of ``R = diag(R_L, R_L)`` (``t1, t2, n`` linear, then angular about
the same axes); a task uses ``m`` of them (``axes``): all six, the three linear ones
(position only), or the planar arm's ``(t1, n)`` = axes ``(0, 2)``. With ``R_m`` those rows,
``J_y = R_m J``, ``Lambda_y = (J_y B^-1 J_y^T)^-1`` and ``Jbar_y^T = Lambda_y J_y B^-1`` (for all six
axes, where ``R_m = R`` is a rotation, the code works with ``J`` and ``R^T a``, the same law):

    f_y  = Lambda_y (a - kappa R_m' v - R_m J' q') + Jbar_y^T (n - J^T F_c)
    F*   = R_m^T f_y                                   (a wrench, base axes)
    tau  = J_y^T f_y + (I - J_y^T Jbar_y^T) tau0       (= J^T F* + null-space torque)

For all six axes this is ``F* = Lambda (R^T (a - R' v) - J' q') + Jbar^T n - F_c`` of conventions
§9; applying ``tau`` gives ``R_m v' + R_m' v = a`` whatever ``tau0``. A square task
(``m = n``) is solved through the thin QR of ``J_y^T``, and ``tau = B q''* + n - J^T F_c`` by one
Newton-Euler pass (no ``B`` at all; ``tau0`` has no effect); a redundant one through the Cholesky
factors of ``B`` and of ``Lambda_y^-1``.
The conditioning guard is ``m / (|J_y|_F |J_y^+|_F)``: from the same QR where the task is square, from
the Cholesky factor of ``J_y J_y^T`` where it is redundant.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from hybrid.spec.axes import AXIS_NAMES

from . import body_frame as bf
from . import factor
from . import rigid_body as rb
from . import tip_kinematics as tk
from .kernel import Arg, Guard, Kernel, conditioning_guard
from .surfaces import FRAME_TOL, SurfaceSpec, task_frame

CONDITIONING = "m/(|J_y|_F |J_y^+|_F)"
#: below this ``|cos beta|`` the ZYX Euler angles (and ``T_A``) are singular
EULER_TOL = 1e-6


def frame_guard(sine) -> Guard:
    return Guard("frame", sine, "FRAME_UNDEFINED", FRAME_TOL,
                 "|e x n|, 0 without a normal (e parallel to the surface normal n, or grad phi 0 or not finite)")


def _blockdiag(A):
    Z = ca.SX.zeros(3, 3)
    return ca.vertcat(ca.horzcat(A, Z), ca.horzcat(Z, A))


def _rows(M, axes):
    return ca.vertcat(*(M[i, :] for i in axes))


@dataclass(frozen=True)
class ArmMotion:
    """The arm's symbolic kinematics at ``(q, q')``: the links and the tip in base axes, ``J`` (6 x n),
    ``J' q'`` and ``v = J q'``, all from the link transforms of the body-frame dynamics (:mod:`.body_frame`,
    :mod:`.tip_kinematics`): one kinematic pass for the law and the dynamics."""

    frames: tk.Placements
    J: ca.SX
    Jdqd: ca.SX
    v: ca.SX
    tree: bf.Tree


def arm_motion(chain: rb.Chain, q, qd) -> ArmMotion:
    tree = bf.link_transforms(chain, q)
    fr, vs = tk.placements(tree), bf.link_velocities(tree, qd)  # the Newton-Euler pass's velocities too
    return ArmMotion(fr, tk.frame_jacobian(tree, fr), tk.classical_acceleration(tree, fr, qd, vs),
                     tk.frame_velocity(tree, fr, vs), tree)


def task_rows(tf, axes) -> tuple[ca.SX, ca.SX]:
    """``R_m`` and ``R_m'``: the task ``axes``' rows of ``R = diag(R_L, R_L)`` and of its derivative."""
    return _rows(_blockdiag(tf.R), axes), _rows(_blockdiag(tf.Rd), axes)


def decoupling(chain: rb.Chain, arm: ArmMotion, params, qd, Rm, Rdm, a, Fc, tau0, curvature):
    """``(F*, tau, conditioning)`` of the law (module docstring) for the task rows ``Rm`` (m x 6)."""
    n, m = chain.n, Rm.shape[0]
    J, tree = arm.J, arm.tree
    b = a - curvature * (Rdm @ arm.v) - Rm @ arm.Jdqd
    full = m == 6  # R_m = R is a rotation: work with J itself (same conditioning) and rotate b and f
    Jy = J if full else Rm @ J
    if full:
        b = Rm.T @ b
    if m == n:
        Q, Rq = factor.thin_qr(Jy.T)
        cond = factor.frobenius_conditioning(Jy, Rq)
        # J_y square: q''* = J_y^-1 b = Q R^-T b; tau = B q''* + n - J^T F_c is one RNEA pass (no B),
        # the wrench on the tip in it; f_y = J_y^-T tau
        z = factor.forward_substitution([[Rq[j][i] for j in range(m)] for i in range(m)], b)  # R^T z = b
        qdd = sum((Q[i] * z[i] for i in range(m)), ca.SX.zeros(n, 1))
        tau = bf.rnea(tree, params, qd, qdd, f_ext=bf.tip_force(tree, Fc[:3], Fc[3:]))
        y = ca.vertcat(*(ca.dot(Q[i], tau) for i in range(m)))
        f_y = ca.vertcat(*factor.back_substitution_upper(Rq, y))
    else:
        # n(q, q') alone, as the posture torque has it too (the kernels' common subexpressions)
        B = bf.crba(tree, params)
        h = bf.rnea(tree, params, qd) - J.T @ Fc
        L = factor.cholesky(B)
        Y = factor.lower_columns_solve(L, Jy.T)           # L^-1 J_y^T, n x m
        K = factor.cholesky(Y.T @ Y)                      # Lambda_y^-1 = K K^T
        u = ca.vertcat(*factor.forward_substitution(L, h))
        u0 = ca.vertcat(*factor.forward_substitution(L, tau0))
        f_y = factor.factor_solve(K, b + Y.T @ u)
        g = factor.factor_solve(K, Y.T @ u0)
        tau = Jy.T @ (f_y - g) + tau0
        cond = factor.gram_conditioning(Jy)  # no QR to share here
    return (f_y if full else Rm.T @ f_y), tau, cond


def law_kernels(chain: rb.Chain, spec: SurfaceSpec, axes: tuple[int, ...]) -> tuple[Kernel, ...]:
    """``task_frame`` and ``decoupling_law`` of ``chain`` on ``spec`` for the task ``axes``."""
    n, m = chain.n, len(axes)
    if m > n:
        raise ValueError(f"a task of {m} axes needs at least {m} joints; the arm has {n}")
    q, qd, tau0 = (ca.SX.sym(s, n) for s in ("q", "qd", "tau0"))
    a, Fc = ca.SX.sym("a", m), ca.SX.sym("Fc", 6)
    params = ca.SX.sym("robot", len(rb.parameter_names(chain)))
    theta, e, opts = ca.SX.sym("surface", len(spec.parameters)), ca.SX.sym("e", 3), ca.SX.sym("opts", 1)

    arm = arm_motion(chain, q, qd)
    tf = task_frame(spec, arm.frames.tip_p, arm.v[:3], theta, e)
    Rm, Rdm = task_rows(tf, axes)
    F, tau, cond = decoupling(chain, arm, params, qd, Rm, Rdm, a, Fc, tau0, opts[0])

    names = tuple(j.name for j in chain.joints)
    a_q = Arg("q", q, rb.joint_units(chain, "q"), names=names)
    a_qd = Arg("qd", qd, rb.joint_units(chain, "qd"), names=names)
    a_p = Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain))
    a_s = Arg("surface", theta, "m (lengths), 1 (directions)", names=spec.parameters)
    a_e = Arg("e", e, "1", names=("e_x", "e_y", "e_z"))
    acc_units = tuple("m/s^2" if i < 3 else "rad/s^2" for i in axes)
    law = Kernel(
        "decoupling_law",
        (a_q, a_qd, Arg("a", a, acc_units, names=tuple(AXIS_NAMES[i] for i in axes)),
         Arg("Fc", Fc, ("N",) * 3 + ("N m",) * 3, names=("f_x", "f_y", "f_z", "m_x", "m_y", "m_z")),
         Arg("tau0", tau0, rb.joint_units(chain, "tau"), names=names), a_p, a_s, a_e,
         Arg("opts", opts, "1", names=("curvature",))),
        (Arg("F", F, ("N",) * 3 + ("N m",) * 3), Arg("tau", tau, rb.joint_units(chain, "tau"))),
        f"decoupling law F* [N, N m] (base axes) and tau = J^T F* + null-space tau0 [N m], task axes "
        f"{', '.join(AXIS_NAMES[i] for i in axes)} on a {spec.kind}",
        batched=("q", "qd", "a", "Fc", "tau0"), lanes=True,
        guards=(frame_guard(tf.sine), conditioning_guard(cond, CONDITIONING)),
        # measured: a redundant task's law (Cholesky factors) runs 15-18 % faster reordered and 3-5 % faster again
        # with its chains first, a square one's (one chain: QR, RNEA, back substitution) 10 % faster in CasADi's
        # own order
        order="longest_chain" if m < n else "printed")
    return frame_kernel(spec), law


def frame_kernel(spec: SurfaceSpec) -> Kernel:
    """``task_frame``: ``R_L`` (rows t1, t2, n) at a point ``p`` of ``spec``, its rate ``R_L'(p, p')``
    and the unit normal, for N points in one call."""
    p, pd = ca.SX.sym("p", 3), ca.SX.sym("pd", 3)
    theta, e = ca.SX.sym("surface", len(spec.parameters)), ca.SX.sym("e", 3)
    tf_p = task_frame(spec, p, pd, theta, e)
    return Kernel(
        "task_frame", (Arg("p", p, "m"), Arg("pd", pd, "m/s"),
                       Arg("surface", theta, "m (lengths), 1 (directions)", names=spec.parameters),
                       Arg("e", e, "1", names=("e_x", "e_y", "e_z"))),
        (Arg("R", rb.row_major(tf_p.R), "1", (3, 3)), Arg("Rd", rb.row_major(tf_p.Rd), "1/s", (3, 3)),
         Arg("normal", tf_p.normal, "1")),
        f"task frame R_L (rows t1, t2, n) at p on a {spec.kind}, its derivative R_L'(p, p'), and the "
        "unit normal n", batched=("p", "pd"), guards=(frame_guard(tf_p.sine),))


# ------------------------------------------------------------- operational space


def euler_zyx(Rot):
    """ZYX Euler angles ``(alpha, beta, gamma)`` of ``Rot = Rz(alpha) Ry(beta) Rx(gamma)``."""
    alpha = ca.atan2(Rot[1, 0], Rot[0, 0])
    beta = ca.atan2(-Rot[2, 0], ca.sqrt(Rot[0, 0] ** 2 + Rot[1, 0] ** 2))
    gamma = ca.atan2(Rot[2, 1], Rot[2, 2])
    return ca.vertcat(alpha, beta, gamma)


def euler_map(phi) -> ca.SX:
    """``T_A(phi)`` with ``w = T_A phi'`` (conventions §9)."""
    return euler_map_of(ca.sin(phi[0]), ca.cos(phi[0]), ca.sin(phi[1]), ca.cos(phi[1]))


def euler_map_of(sa, ca_, sb, cb) -> ca.SX:
    """``T_A`` from the sines and cosines of ``alpha`` and ``beta``."""
    return ca.vertcat(ca.horzcat(0, -sa, ca_ * cb), ca.horzcat(0, ca_, sa * cb), ca.horzcat(1, 0, -sb))


def euler_map_rate(phi, phid) -> ca.SX:
    """``T_A'(phi, phi')``: ``dT_A/dalpha alpha' + dT_A/dbeta beta'``."""
    sa, ca_, sb, cb = ca.sin(phi[0]), ca.cos(phi[0]), ca.sin(phi[1]), ca.cos(phi[1])
    ad, bd = phid[0], phid[1]
    return ca.vertcat(ca.horzcat(0, -ca_ * ad, -sa * cb * ad - ca_ * sb * bd),
                      ca.horzcat(0, -sa * ad, ca_ * cb * ad - sa * sb * bd),
                      ca.horzcat(0, 0, -cb * bd))


def euler_rates(phi, w) -> ca.SX:
    """``phi' = T_A^-1 w`` in closed form (singular at ``cos beta = 0``)."""
    sa, ca_, sb, cb = ca.sin(phi[0]), ca.cos(phi[0]), ca.sin(phi[1]), ca.cos(phi[1])
    gamma_d = (ca_ * w[0] + sa * w[1]) / cb
    return ca.vertcat(w[2] + sb * gamma_d, -sa * w[0] + ca_ * w[1], gamma_d)


def operational_space_kernels(chain: rb.Chain) -> tuple[Kernel, ...]:
    """``Lambda`` and ``n_o`` in twist coordinates, and ``B_o, n_o, T, T'`` in ``r = (p, phi_ZYX)``."""
    n = chain.n
    q, qd = ca.SX.sym("q", n), ca.SX.sym("qd", n)
    params = ca.SX.sym("robot", len(rb.parameter_names(chain)))
    tree = bf.link_transforms(chain, q)
    fr, vs = tk.placements(tree), bf.link_velocities(tree, qd)
    J = tk.frame_jacobian(tree, fr)
    Jdqd = tk.classical_acceleration(tree, fr, qd, vs)
    B = bf.crba(tree, params)
    bias = bf.rnea(tree, params, qd)
    L = factor.cholesky(B)
    Y = factor.lower_columns_solve(L, J.T)
    K = factor.cholesky(Y.T @ Y)
    # Lambda = (K K^T)^-1, column by column; mu = Lambda (J B^-1 n - J' q') = Jbar^T n - Lambda J' q'
    Lam = ca.horzcat(*(factor.factor_solve(K, ca.DM.eye(6)[:, j]) for j in range(6)))
    Lam = 0.5 * (Lam + Lam.T)
    u = ca.vertcat(*factor.forward_substitution(L, bias))
    mu = factor.factor_solve(K, Y.T @ u - Jdqd)
    guard = conditioning_guard(factor.gram_conditioning(J), CONDITIONING)
    v = tk.frame_velocity(tree, fr, vs)
    phi = euler_zyx(fr.tip_R)
    phid = euler_rates(phi, v[3:])
    TA = euler_map(phi)
    TAd = euler_map_rate(phi, phid)
    T = ca.diagcat(ca.SX.eye(3), TA)
    Td = ca.diagcat(ca.SX.zeros(3, 3), TAd)
    r, rd = ca.vertcat(fr.tip_p, phi), ca.vertcat(v[:3], phid)
    Bo = T.T @ Lam @ T
    no = T.T @ (Lam @ (Td @ rd) + mu)
    names = tuple(j.name for j in chain.joints)
    a_q = Arg("q", q, rb.joint_units(chain, "q"), names=names)
    a_qd = Arg("qd", qd, rb.joint_units(chain, "qd"), names=names)
    a_p = Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain))
    twist = Kernel(
        "operational_space", (a_q, a_qd, a_p),
        (Arg("Lambda", rb.row_major(Lam), "kg, kg m, kg m^2", (6, 6)), Arg("no", mu, "N, N m")),
        "operational-space inertia Lambda = (J B^-1 J^T)^-1 and n_o = Jbar^T n - Lambda J' q' in twist "
        "coordinates v = (p', w), base axes", guards=(guard,))
    euler = Kernel(
        "operational_space_euler", (a_q, a_qd, a_p),
        (Arg("r", r, "m, rad", names=("x", "y", "z", "alpha", "beta", "gamma")),
         Arg("rd", rd, "m/s, rad/s"), Arg("Bo", rb.row_major(Bo), "kg, kg m, kg m^2", (6, 6)),
         Arg("no", no, "N, N m"), Arg("T", rb.row_major(T), "1", (6, 6)), Arg("Td", rb.row_major(Td), "1/s", (6, 6))),
        "the paper's coordinates r = (p, phi_ZYX): B_o(r) = T^T Lambda T, n_o(r, r') = T^T (Lambda T' r' + "
        "n_o,twist), T = diag(I, T_A) and T'(r, r')",
        guards=(guard, Guard("euler", ca.cos(phi[1]), "EULER_SINGULAR", EULER_TOL,
                             "|cos beta| (ZYX Euler angles at their singularity, beta = +-pi/2)")))
    return twist, euler
