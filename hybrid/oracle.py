"""The NumPy oracle: the paper's equations in plain NumPy, written independently of codegen/.

It is what the tests check the generated C against, and the "what a user would
otherwise write" path of the benchmarks. Closed forms for the two-link arm follow
conventions §3; the law follows conventions §2 literally (forming ``B_o`` and ``n_o``).
All functions take one state; parameters are the arrays of the generated C.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from hybrid.errors import HybridError, NonFiniteError, SingularConfigurationError
from hybrid.models.planar_arm import dynamics, kinematics  # the arm's closed form in NumPy
from hybrid.plants.planar import planar_record
from hybrid.simulation.results import SimulationResult
from hybrid.simulation.runner import run
from hybrid.validate import shown

SURFACE_KINDS = ("plane", "circle")


def conditioning(q, arm):
    """Distance of ``J(q)`` from singularity, ``2 |det J| / ||J||_F^2`` in [0, 1] (about ``|sin q2|``)."""
    J = kinematics(q, (0.0, 0.0), arm)[1]
    return 2.0 * abs(np.linalg.det(J)) / float(np.sum(J * J))


def frame(kind, r, rd, surface):
    """Task-frame rotation ``R(r)`` (rows: tangent, normal) and ``R'(r, r')``."""
    if kind == "plane":
        n = np.asarray(surface[2:4], float) / np.hypot(surface[2], surface[3])
        nd = np.zeros(2)
    elif kind == "circle":
        d = np.asarray(r, float) - surface[:2]
        dist = np.hypot(*d)
        n = d / dist
        nd = (rd - n * (n @ rd)) / dist
    else:
        raise ValueError(kind)
    R = np.array([[-n[1], n[0]], [n[0], n[1]]])
    Rd = np.array([[-nd[1], nd[0]], [nd[0], nd[1]]])
    return R, Rd


def operational_space(q, qd, arm):
    """``B_o = J^-T B J^-1`` and ``n_o = J^-T n - B_o J' q'``."""
    _, J, Jdqd = kinematics(q, qd, arm)
    B, n = dynamics(q, qd, arm)
    Jinv = np.linalg.inv(J)
    Bo = Jinv.T @ B @ Jinv
    return Bo, Jinv.T @ n - Bo @ Jdqd


def decoupling_law(kind, q, qd, a, Fc, arm, surface, curvature):
    """``(F*, tau)`` of conventions §2: ``F* = B_o R^T (a - R' r') + n_o - F_c``."""
    r, J, _ = kinematics(q, qd, arm)
    rd = J @ qd
    R, Rd = frame(kind, r, rd, surface)
    Bo, no = operational_space(q, qd, arm)
    F = Bo @ R.T @ (np.asarray(a) - (Rd @ rd if curvature else 0.0)) + no - Fc
    return F, J.T @ F


def sensor_force(x, arm, plant):
    """Force of the sensor on the robot ``F_c = K_s (s - r) + D_s (s' - r')`` [N]."""
    q, qd, s, sd = x[0:2], x[2:4], x[4:6], x[6:8]
    r, J, _ = kinematics(q, qd, arm)
    return plant[1] * (s - r) + plant[2] * (sd - J @ qd)


def contact(kind, s, sd, plant, surface):
    """Penetration ``delta`` [m], normal force ``N`` [N], friction [N], slide speed [m/s], frame at s."""
    _, _, _, k_e, d_e, gamma, v_eps = plant
    R, _ = frame(kind, s, sd, surface)
    t, n = R[0], R[1]
    if kind == "circle":
        delta = surface[2] - np.hypot(*(s - surface[:2]))
    else:
        delta = -(s - surface[:2]) @ n
    N = max(0.0, k_e * delta - d_e * (n @ sd)) if delta > 0 else 0.0
    v = t @ sd
    return delta, N, -gamma * N * np.tanh(v / v_eps), v, t, n


def plant_rhs(kind, x, tau, arm, plant, surface):
    """State derivative of arm + elastic sensor + surface, state ``(q, q', s, s')``."""
    q, qd, s, sd = x[0:2], x[2:4], x[4:6], x[6:8]
    _, J, _ = kinematics(q, qd, arm)
    B, n = dynamics(q, qd, arm)
    Fc = sensor_force(x, arm, plant)
    _, N, f, _, t, nrm = contact(kind, s, sd, plant, surface)
    qdd = np.linalg.solve(B, tau + J.T @ Fc - n)
    sdd = (N * nrm + f * t - Fc) / plant[0]
    return np.concatenate([qd, qdd, sd, sdd])


def plant_advance(kind, x, tau, arm, plant, surface, h, nsteps, trajectory=None):
    """``nsteps`` RK4 steps of ``h`` [s] with ``tau`` held; fills ``trajectory`` rows if given."""
    x = np.array(x, float)
    for k in range(nsteps):
        k1 = plant_rhs(kind, x, tau, arm, plant, surface)
        k2 = plant_rhs(kind, x + 0.5 * h * k1, tau, arm, plant, surface)
        k3 = plant_rhs(kind, x + 0.5 * h * k2, tau, arm, plant, surface)
        k4 = plant_rhs(kind, x + h * k3, tau, arm, plant, surface)
        x = x + h / 6 * (k1 + 2 * (k2 + k3) + k4)
        if trajectory is not None:
            trajectory[k] = x
    return x


def plant_outputs(kind, x, arm, plant, surface):
    """The plant's output record, in the order of ``codegen.model.PLANT_OUTPUTS``."""
    q, qd, s, sd = x[0:2], x[2:4], x[4:6], x[6:8]
    r, J, _ = kinematics(q, qd, arm)
    rd = J @ qd
    R, _ = frame(kind, r, rd, surface)
    Fc = sensor_force(x, arm, plant)
    delta, N, f, v, _, _ = contact(kind, s, sd, plant, surface)
    return np.array([*r, *(R @ rd), *Fc, *(R @ Fc), *s, delta, N, f, v])


# ------------------------------------------------------------ spatial (conventions §9)


def _gradient_and_hessian(surface, p):
    """``grad phi`` and its Hessian at ``p``, written out for each kind (SymPy for an implicit one)."""
    p = np.asarray(p, float)
    if surface.kind == "plane":
        return np.asarray(surface.normal, float), np.zeros((3, 3))
    if surface.kind == "sphere":
        d = p - np.asarray(surface.center)
        r = np.linalg.norm(d)
        return d / r, (np.eye(3) - np.outer(d, d) / r**2) / r
    if surface.kind == "cylinder":
        u = np.asarray(surface.axis)
        P = np.eye(3) - np.outer(u, u)
        d = P @ (p - np.asarray(surface.point))
        r = np.linalg.norm(d)
        return d / r, (P - np.outer(d, d) / r**2) / r
    grad, hess = _implicit_derivatives(surface)
    return np.array(grad(*p), dtype=float), np.array(hess(*p), dtype=float)


@cache
def _implicit_derivatives(surface):
    """``grad phi`` and its Hessian of an implicit surface (or of any other surface's formula),
    differentiated and compiled to NumPy by SymPy."""
    import sympy as sp

    xyz = sp.symbols("x y z", real=True)
    if hasattr(surface, "phi"):
        phi = surface.phi.xreplace({sp.Symbol(k, real=True): v for k, v in surface.parameters.items()})
    else:
        phi = surface.formula(xyz, [sp.Float(v) for v in surface.as_array()], sp.sqrt)
    grad = [sp.diff(phi, s) for s in xyz]
    hess = [[sp.diff(g, s) for s in xyz] for g in grad]
    return sp.lambdify(xyz, grad, "numpy"), sp.lambdify(xyz, hess, "numpy")


def spatial_frame(surface, p, pd, e):
    """``R_L`` (rows ``t1, t2, n``) and ``R_L'`` of conventions §9, differentiated by hand:
    ``n' = (I - n n^T) H p' / |grad phi|``, ``t1' = (I - t1 t1^T)(e x n') / |e x n|``,
    ``t2' = n' x t1 + n x t1'``."""
    g, H = _gradient_and_hessian(surface, p)
    n = g / np.linalg.norm(g)
    nd = (np.eye(3) - np.outer(n, n)) @ H @ np.asarray(pd, float) / np.linalg.norm(g)
    e = np.asarray(e, float) / np.linalg.norm(e)
    c = np.cross(e, n)
    t1 = c / np.linalg.norm(c)
    t1d = (np.eye(3) - np.outer(t1, t1)) @ np.cross(e, nd) / np.linalg.norm(c)
    t2 = np.cross(n, t1)
    t2d = np.cross(nd, t1) + np.cross(n, t1d)
    return np.array([t1, t2, n]), np.array([t1d, t2d, nd])


def spatial_decoupling_law(J, Jdqd, B, n, R_L, Rd_L, qd, a, Fc, tau0, axes, curvature):
    """``(F*, tau)`` of conventions §9 from the arm's terms, written literally with inverses:
    ``f_y = Lambda_y (a - R_m' v - R_m J' q') + Jbar_y^T (n - J^T F_c)``, ``F* = R_m^T f_y``,
    ``tau = J_y^T f_y + (I - J_y^T Jbar_y^T) tau0``, ``J_y = R_m J``."""
    Z = np.zeros((3, 3))
    R = np.block([[R_L, Z], [Z, R_L]])[list(axes)]
    Rd = np.block([[Rd_L, Z], [Z, Rd_L]])[list(axes)]
    v = J @ qd
    Jy = R @ J
    Binv = np.linalg.inv(B)
    Lam = np.linalg.inv(Jy @ Binv @ Jy.T)
    JbarT = Lam @ Jy @ Binv
    f = Lam @ (np.asarray(a) - (Rd @ v if curvature else 0.0) - R @ Jdqd) + JbarT @ (n - J.T @ Fc)
    tau = Jy.T @ f + (np.eye(len(qd)) - Jy.T @ JbarT) @ tau0
    return R.T @ f, tau


# ------------------------------------------------- the paper's closed loop in NumPy


class NumpyPlant:
    """The paper's plant (arm, 2-D sensor, surface) stepped by :func:`plant_advance` (the runner's
    plant interface: see :class:`hybrid.plants.Plant`)."""

    def __init__(self, exp):
        self.kind, self.h = exp.section.kind, exp.integration_step
        self.arm, self.plant, self.surface = exp.arm.as_array(), exp.plant_array(), exp.section.as_array()
        self.record, self.nq = planar_record(), 2

    def sensor_wrench(self, x):
        """The sensor's force at the state ``x``, as a wrench (f, m)."""
        Fc = np.zeros(6)
        Fc[:2] = sensor_force(x, self.arm, self.plant)
        return Fc

    conditioning_name = "2|det J|/|J|_F^2"

    def conditioning(self, q):
        out = np.array([conditioning(qi, self.arm) for qi in np.atleast_2d(q)])
        return out if np.ndim(q) == 2 else out[0]

    def advance(self, x, tau, nsteps, trajectory):
        for k in range(nsteps):
            nxt = plant_advance(self.kind, x, tau, self.arm, self.plant, self.surface, self.h, 1)
            if not np.isfinite(nxt).all():
                return k  # like the C: x keeps the last finite state
            x[:] = trajectory[k] = nxt
        return nsteps

    def outputs(self, states):
        return np.array([plant_outputs(self.kind, x, self.arm, self.plant, self.surface) for x in states])


class NumpyController:
    """The paper's sampled controller written from conventions §4 and §7 (tangent velocity loop
    PI^2, normal force loop impedance + integral; integrals advanced once per sample, current
    error included), on the closed forms above: ``tau = controller(t, q, qdot, Fc)``."""

    def __init__(self, exp):
        self.exp, self.g, self.T = exp, exp.effective_gains(), exp.sample_time
        self.kind = exp.section.kind
        self.arm, self.surface = exp.controller_model().closed_form.as_array(), exp.section.as_array()
        self.int_v = self.int2_v = self.int_f = 0.0

    def loops(self, t, v, f):
        """``a = (a_t, a_n)`` from the task velocity ``v`` and task force ``f``."""
        g, T, exp = self.g, self.T, self.exp
        e_v = exp.speed_reference(t) - v[0]
        self.int_v += T * e_v
        self.int2_v += T * self.int_v
        e_f = exp.force_reference(t) - f[1]
        self.int_f += T * e_f
        a_t = g.KPv * e_v + g.KIv * self.int_v + g.KI2v * self.int2_v  # v_d' = 0 between steps
        a_n = -g.KPf * e_f - g.KDf * v[1] - g.KIf * self.int_f
        return np.array([a_t, a_n])

    def __call__(self, t, q, qdot, Fc):
        exp, Fc = self.exp, np.asarray(Fc, float)[:2]  # the planar force of a (f, m) wrench
        r, J, _ = kinematics(q, qdot, self.arm)
        rdot = J @ qdot
        R, _ = frame(self.kind, r, rdot, self.surface)
        if exp.frame == "desired":
            # loops in R(r_d); the law, in R(r), gets R(r) R_d^T (a - R_d' r')
            rd_point, rd_vel = exp.desired_point(t)
            R_d, Rdot_d = frame(self.kind, rd_point, rd_vel, self.surface)
            a = self.loops(t, R_d @ rdot, R_d @ Fc)
            if exp.curvature:
                a = a - Rdot_d @ rdot
            a = R @ (R_d.T @ a)
        else:
            a = self.loops(t, R @ rdot, R @ Fc)
        if exp.controller == "khatib":
            Fc = R[1] * exp.force_reference(t)  # R^T Sigma F_d: the desired normal force
        # the same tests as the generated C, so both paths stop at the same sample
        if not conditioning(q, self.arm) >= exp.singular_tol:
            raise SingularConfigurationError(f"decoupling_law: the Jacobian is singular or nearly so at q={q}")
        curvature = exp.curvature and exp.frame == "actual"
        _, tau = decoupling_law(self.kind, q, qdot, a, Fc, self.arm, self.surface, curvature)
        if not np.isfinite(tau).all():
            raise NonFiniteError(f"decoupling_law: result is NaN or infinite at q={q}, qdot={qdot}")
        return tau


#: the schemes the NumPy closed loop implements
SCHEMES = ("task", "khatib")


def simulate(exp) -> SimulationResult:
    """The paper's experiment ``exp`` run by the NumPy plant and controller (the same runner, the
    same zero-order hold): what the generated code is tested against."""
    if exp.controller not in SCHEMES:
        raise HybridError(f"the NumPy oracle runs {' and '.join(SCHEMES)} only, not {shown(exp.controller)}")
    plant = NumpyPlant(exp)
    return run(exp, plant, NumpyController(exp), exp.checked_start(plant.record))
