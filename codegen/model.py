"""The paper's equations in SymPy: arm dynamics, task frames, decoupling law, plant.

Every function here returns plain SymPy expressions of named input symbols. The
backends turn a :class:`Kernel` (named input arrays, named output arrays) into C.

Conventions are those of docs/conventions.md §3: planar serial arm of
revolute joints, task axis 0 tangent (velocity), axis 1 normal pointing from the
surface to the robot (force), ``F_c`` the force on the robot in the base frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

from .kernel import Arg, Kernel, conditioning_guard

#: names of the per-link arm parameters, in the order they appear in the ``arm`` array, and their units
LINK_PARAMETERS = ("L", "m", "d", "I", "V")
LINK_PARAMETER_UNITS = ("m", "kg", "m", "kg m^2", "N m s/rad")
#: sensor, contact and friction parameters of the plant, in ``plant`` array order
PLANT_PARAMETERS = ("m_s", "K_s", "D_s", "k_e", "d_e", "gamma", "v_eps")
PLANT_PARAMETER_UNITS = ("kg", "N/m", "N s/m", "N/m", "N s/m", "1", "m/s")
#: surface parameters, in ``surface`` array order
SURFACE_PARAMETERS = {"plane": ("p_x", "p_y", "n_x", "n_y"), "circle": ("c_x", "c_y", "rho")}
#: options of the decoupling law, in ``opts`` array order
LAW_OPTIONS = ("curvature",)
#: columns of the plant's output record, in order (see :func:`plant_outputs`)
PLANT_OUTPUTS = (
    "r_x", "r_y",            # arm tip position [m]
    "v_t", "v_n",            # arm tip task velocity y = R(r) r' [m/s]
    "Fc_x", "Fc_y",          # sensor force on the robot, base frame [N]
    "Fc_t", "Fc_n",          # the same in the task frame R(r) F_c [N]
    "s_x", "s_y",            # sensor tip position [m]
    "penetration",           # sensor tip penetration into the surface [m]
    "N",                     # normal contact force of the surface [N]
    "friction",              # tangential friction force on the sensor tip [N]
    "sensor_v_t",            # sensor tip tangential (sliding) speed [m/s]
)


def arm_parameter_names(n_links: int) -> tuple[str, ...]:
    """Names of the ``arm`` array: ``L1..Ln, m1..mn, d1..dn, I1..In, V1..Vn, g``."""
    return tuple(f"{p}{i + 1}" for p in LINK_PARAMETERS for i in range(n_links)) + ("g",)


def arm_parameter_units(n_links: int) -> tuple[str, ...]:
    """SI units of the ``arm`` array, element by element."""
    return tuple(u for u in LINK_PARAMETER_UNITS for _ in range(n_links)) + ("m/s^2",)


def vector(name: str, n: int) -> sp.Matrix:
    """Column of symbols ``name0 .. name{n-1}``, the elements of C array ``name``."""
    return sp.Matrix([sp.Symbol(f"{name}{i}", real=True) for i in range(n)])


def flat(m: sp.Matrix) -> sp.Matrix:
    """Row-major flattening of a matrix into a column."""
    return sp.Matrix(list(m))


# --------------------------------------------------------------------------- arm


@dataclass(frozen=True)
class ArmModel:
    """Symbolic planar serial arm: ``r = kin(q)``, ``J``, ``J' q'``, ``B(q)``, ``n(q, q')``."""

    n: int
    q: sp.Matrix
    qd: sp.Matrix
    params: sp.Matrix
    r: sp.Matrix
    J: sp.Matrix
    Jdqd: sp.Matrix
    B: sp.Matrix
    nvec: sp.Matrix


def _expand_angle_sums(e: sp.Expr) -> sp.Expr:
    """Rewrite sin/cos of joint-angle sums by the addition formulas.

    The emitted code then needs one ``sincos`` per joint, not one per partial sum.
    """
    return e.replace(
        lambda x: isinstance(x, (sp.sin, sp.cos)) and x.args[0].is_Add,
        lambda x: sp.expand_trig(x),
    )


@cache
def planar_arm(n_links: int = 2) -> ArmModel:
    """Derive the planar serial arm with ``n_links`` revolute joints.

    Link ``i`` has length ``L_i``, mass ``m_i`` with its centre at ``d_i`` along the link,
    inertia ``I_i`` about that centre, joint viscosity ``V_i``; gravity ``g`` acts along
    ``-y`` (0 for the SCARA). ``B`` comes from the kinetic energy, ``n`` from the
    Christoffel symbols of ``B`` plus viscosity and gravity.
    """
    q, qd = vector("q", n_links), vector("qd", n_links)
    params = vector("arm", 5 * n_links + 1)
    L, m, d, Inert, V = (params[k * n_links:(k + 1) * n_links] for k in range(5))
    g = params[5 * n_links]

    phi = [sum(q[: i + 1], sp.S.Zero) for i in range(n_links)]
    joint = [sp.Matrix([0, 0])]
    com = []
    for i in range(n_links):
        u = sp.Matrix([sp.cos(phi[i]), sp.sin(phi[i])])
        com.append(joint[i] + d[i] * u)
        joint.append(joint[i] + L[i] * u)
    r = joint[-1]
    J = r.jacobian(q)
    Jdqd = (J * qd).jacobian(q) * qd

    B = sp.zeros(n_links, n_links)
    potential = sp.S.Zero
    for i in range(n_links):
        Jv = com[i].jacobian(q)
        Jw = sp.Matrix([[1 if j <= i else 0 for j in range(n_links)]])
        B += m[i] * Jv.T * Jv + Inert[i] * Jw.T * Jw
        potential += m[i] * g * com[i][1]
    B = B.applyfunc(lambda e: sp.collect(sp.trigsimp(sp.expand(e)), list(m) + list(Inert)))

    coriolis = sp.zeros(n_links, 1)
    for i in range(n_links):
        coriolis[i] = sum(
            sp.Rational(1, 2) * (B[i, j].diff(q[k]) + B[i, k].diff(q[j]) - B[j, k].diff(q[i]))
            * qd[j] * qd[k]
            for j in range(n_links) for k in range(n_links)
        )
    gravity = sp.Matrix([potential.diff(qi) for qi in q])
    nvec = coriolis + sp.Matrix([V[i] * qd[i] for i in range(n_links)]) + gravity

    def tidy(M):
        return M.applyfunc(_expand_angle_sums)

    return ArmModel(n_links, q, qd, params, tidy(r), tidy(J), tidy(Jdqd), tidy(B), tidy(nvec))


def inverse_2x2(M: sp.Matrix) -> tuple[sp.Matrix, sp.Expr]:
    """``(adj(M) / det(M), det(M))`` without SymPy's pivoting."""
    det = M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
    inv_det = 1 / det
    adj = sp.Matrix([[M[1, 1], -M[0, 1]], [-M[1, 0], M[0, 0]]])
    return adj * inv_det, det


#: the conditioning measure of the planar kernels
PLANAR_CONDITIONING = "2|det J|/|J|_F^2"


def conditioning(J: sp.Matrix, det: sp.Expr) -> sp.Expr:
    """Scale-free distance of ``J`` from singularity: ``2 |det J| / ||J||_F^2`` in [0, 1].

    It is 1 for an isotropic Jacobian and 0 at a singularity (``q2 = 0`` or ``pi``).
    """
    return 2 * det / sum(e**2 for e in J)


# ---------------------------------------------------------------------- task frames


def task_frame(kind: str, r: sp.Matrix, rd: sp.Matrix, surface: sp.Matrix):
    """Task-frame rotation ``R(r)`` (rows: tangent, normal) and its derivative ``R'(r, r')``.

    Plane (point ``p``, normal ``n``, normalised here): ``R`` is constant, ``R' = 0``.
    Circle (centre ``c``, radius ``rho``): ``n = (r - c)/|r - c|`` points away from the
    centre, ``t = (-n_y, n_x)`` runs counter-clockwise; ``R'`` is the exact time
    derivative along ``r'``, which carries the curvature ``1/|r - c|``.
    """
    if kind == "plane":
        nx, ny = surface[2], surface[3]
        norm = sp.sqrt(nx**2 + ny**2)
        n = sp.Matrix([nx / norm, ny / norm])
    elif kind == "circle":
        delta = r - sp.Matrix(surface[:2])
        n = delta / sp.sqrt(delta.dot(delta))
    else:
        raise ValueError(f"unknown surface kind {kind!r}")
    R = sp.Matrix([[-n[1], n[0]], [n[0], n[1]]])
    if kind == "plane":
        return R, sp.zeros(2, 2)
    # d n/dt = (I - n n^T) r' / |r - c|
    rho_r = sp.sqrt(delta.dot(delta))
    nd = (rd - n * n.dot(rd)) / rho_r
    Rd = sp.Matrix([[-nd[1], nd[0]], [nd[0], nd[1]]])
    return R, Rd


def surface_symbols(kind: str) -> sp.Matrix:
    return vector("surface", len(SURFACE_PARAMETERS[kind]))


# --------------------------------------------------------------- decoupling law


def operational_space(arm: ArmModel):
    """``B_o = J^{-T} B J^{-1}`` and ``n_o = J^{-T} n - B_o J' q'`` (planar, ``T = I``)."""
    Jinv, det = inverse_2x2(arm.J)
    Bo = Jinv.T * arm.B * Jinv
    no = Jinv.T * arm.nvec - Bo * arm.Jdqd
    return Bo, no, conditioning(arm.J, det)


def decoupling_law(kind: str, arm: ArmModel):
    """The corrected decoupling law of conventions §2 for a planar two-link arm.

    ``F* = B_o R^T (a - kappa R' r') + n_o - F_c`` and ``tau = J^T F*``, evaluated as
    ``q''* = J^{-1} (R^T (a - kappa R' r') - J' q')``, ``tau = B q''* + n - J^T F_c``,
    ``F* = J^{-T} tau``: the same quantity at a fraction of the operations.
    ``kappa`` (``opts[0]``) switches the curvature term; the paper runs with 0.
    """
    if arm.n != 2:
        raise NotImplementedError("the planar task law needs a non-redundant arm (2 joints)")
    a, Fc = vector("a", 2), vector("Fc", 2)
    surface, opts = surface_symbols(kind), vector("opts", len(LAW_OPTIONS))
    rd = arm.J * arm.qd
    R, Rd = task_frame(kind, arm.r, rd, surface)
    Jinv, det = inverse_2x2(arm.J)
    accel = R.T * (a - opts[0] * Rd * rd) - arm.Jdqd
    qdd = Jinv * accel
    tau = arm.B * qdd + arm.nvec - arm.J.T * Fc
    F = Jinv.T * tau
    inputs = (("q", arm.q), ("qd", arm.qd), ("a", a), ("Fc", Fc), ("arm", arm.params),
              ("surface", surface), ("opts", opts))
    return inputs, F, tau, conditioning(arm.J, det)


# ------------------------------------------------------------------------ plant


def plant(kind: str, arm: ArmModel):
    """Arm + 2-D elastic sensor + rigid unilateral surface with Coulomb friction.

    State ``x = (q, q', s, s')``: joints and the sensor tip ``s`` (mass ``m_s``) tied to
    the arm tip ``r`` by an isotropic spring-damper of zero rest length, so the sensor
    reads ``F_c = K_s (s - r) + D_s (s' - r')`` (the force on the robot). The surface
    pushes the sensor tip with ``N = max(0, k_e delta + d_e delta')`` while it
    penetrates (``delta > 0``), and friction ``-gamma N tanh(v_t / v_eps)`` opposes sliding.
    """
    n = arm.n
    x = vector("x", 2 * n + 4)
    tau, pp, surface = vector("tau", n), vector("plant", len(PLANT_PARAMETERS)), surface_symbols(kind)
    m_s, K_s, D_s, k_e, d_e, gamma, v_eps = pp
    q, qd = x[:n, 0], x[n:2 * n, 0]
    s, sd = x[2 * n:2 * n + 2, 0], x[2 * n + 2:2 * n + 4, 0]
    sub = dict(zip(list(arm.q) + list(arm.qd), list(q) + list(qd)))

    def at_state(M):
        return M.xreplace(sub)

    r, J, B, nvec = at_state(arm.r), at_state(arm.J), at_state(arm.B), at_state(arm.nvec)
    rd = J * qd
    Fc = K_s * (s - r) + D_s * (sd - rd)

    Rs, _ = task_frame(kind, s, sd, surface)
    t_s, n_s = Rs[0, :].T, Rs[1, :].T
    if kind == "circle":
        delta = surface[2] - sp.sqrt((s - sp.Matrix(surface[:2])).dot(s - sp.Matrix(surface[:2])))
    else:
        delta = -(s - sp.Matrix(surface[:2])).dot(n_s)
    delta_d = -n_s.dot(sd)
    N = sp.Piecewise((sp.Max(0, k_e * delta + d_e * delta_d), delta > 0), (0, True))
    v_slide = t_s.dot(sd)
    friction = -gamma * N * sp.tanh(v_slide / v_eps)
    F_env = N * n_s + friction * t_s

    Binv, _ = inverse_2x2(B)
    qdd = Binv * (tau + J.T * Fc - nvec)
    sdd = (F_env - Fc) / m_s
    xdot = sp.Matrix.vstack(qd, qdd, sd, sdd)

    R, _ = task_frame(kind, r, rd, surface)
    outputs = sp.Matrix([
        r[0], r[1], *(R * rd), Fc[0], Fc[1], *(R * Fc), s[0], s[1],
        delta, N, friction, v_slide,
    ])
    inputs = (("x", x), ("tau", tau), ("arm", arm.params), ("plant", pp), ("surface", surface))
    return inputs, xdot, outputs


# ----------------------------------------------------------------------- kernels

#: units of the plant outputs, in PLANT_OUTPUTS order
PLANT_OUTPUT_UNITS = ("m", "m", "m/s", "m/s", "N", "N", "N", "N", "m", "m", "m", "N", "N", "m/s")


@cache
def kernels(n_links: int = 2) -> tuple[Kernel, ...]:
    """All kernels of one generated unit, in emission order."""
    arm = planar_arm(n_links)
    n = n_links
    q, qd = Arg("q", arm.q, "rad"), Arg("qd", arm.qd, "rad/s")
    armp = Arg("arm", arm.params, arm_parameter_units(n), names=arm_parameter_names(n))
    qa = (q, qd, armp)

    def surf(kind):
        return Arg("surface", surface_symbols(kind), "m", names=SURFACE_PARAMETERS[kind])

    Bo, no, cond = operational_space(arm)
    out = [
        Kernel("arm_kinematics", qa,
               (Arg("r", arm.r, "m"), Arg("J", flat(arm.J), "m/rad", (2, n)), Arg("Jdqd", arm.Jdqd, "m/s^2")),
               "tip position r = kin(q) [m], Jacobian J(q) (row-major), J'(q, q') q' [m/s^2]"),
        Kernel("arm_dynamics", qa, (Arg("B", flat(arm.B), "kg m^2", (n, n)), Arg("n", arm.nvec, "N m")),
               "joint-space inertia B(q) [kg m^2] (row-major) and n(q, q') [N m]"),
        Kernel("operational_space", qa, (Arg("Bo", flat(Bo), "kg", (2, 2)), Arg("no", no, "N")),
               "B_o = J^-T B J^-1 [kg], n_o = J^-T n - B_o J' q' [N]",
               guards=(conditioning_guard(sp.Matrix([cond]), PLANAR_CONDITIONING),)),
    ]
    for kind in ("plane", "circle"):
        r, rd = vector("r", 2), vector("rd", 2)
        R, Rd = task_frame(kind, r, rd, surface_symbols(kind))
        out.append(Kernel(f"task_frame_{kind}", (Arg("r", r, "m"), Arg("rd", rd, "m/s"), surf(kind)),
                          (Arg("R", flat(R), "1", (2, 2)), Arg("Rd", flat(Rd), "1/s", (2, 2))),
                          f"task-frame rotation R(r) and R'(r, r') [1/s] of a {kind} (row-major)"))
        law_in, F, tau, cond = decoupling_law(kind, arm)
        units = {"q": "rad", "qd": "rad/s", "a": "m/s^2", "Fc": "N", "arm": armp.unit, "surface": "m", "opts": "1"}
        names = {"arm": arm_parameter_names(n), "surface": SURFACE_PARAMETERS[kind], "opts": LAW_OPTIONS}
        out.append(Kernel(f"decoupling_law_{kind}",
                          tuple(Arg(k, m, units[k], names=names.get(k)) for k, m in law_in),
                          (Arg("F", F, "N"), Arg("tau", tau, "N m")),
                          f"decoupling law F*(r, r', a) [N] and tau = J^T F* [N m] on a {kind}",
                          batched=("q", "qd", "a", "Fc"), lanes=True,
                          guards=(conditioning_guard(sp.Matrix([cond]), PLANAR_CONDITIONING),)))
        Fc = vector("Fc", 2)
        rr = arm.J * arm.qd
        Rm, _ = task_frame(kind, arm.r, rr, surface_symbols(kind))
        out.append(Kernel(f"task_measurement_{kind}", (q, qd, Arg("Fc", Fc, "N"), armp, surf(kind)),
                          (Arg("r", arm.r, "m"), Arg("rd", rr, "m/s"), Arg("v", Rm * rr, "m/s"),
                           Arg("f", Rm * Fc, "N")),
                          "what a controller measures: r, r', task velocity R r', task force R F_c"))
        p_in, xdot, outputs = plant(kind, arm)
        x_units = ("rad",) * n + ("rad/s",) * n + ("m", "m", "m/s", "m/s")
        xs = Arg("x", p_in[0][1], x_units, names=plant_state_names(n))
        pins = (xs, Arg("tau", p_in[1][1], "N m"), armp,
                Arg("plant", p_in[3][1], PLANT_PARAMETER_UNITS, names=PLANT_PARAMETERS), surf(kind))
        xd_units = ("rad/s",) * n + ("rad/s^2",) * n + ("m/s", "m/s", "m/s^2", "m/s^2")
        out.append(Kernel(f"plant_rhs_{kind}", pins, (Arg("xdot", xdot, xd_units),),
                          f"plant state derivative x' = f(x, tau) on a {kind}",
                          integrator=f"plant_advance_{kind}"))
        out.append(Kernel(f"plant_outputs_{kind}", pins[:1] + pins[2:],
                          (Arg("y", outputs, PLANT_OUTPUT_UNITS, names=PLANT_OUTPUTS),),
                          "plant output record (PLANT_OUTPUTS)", batched=("x",), lanes=True))
    return tuple(out)


def plant_state_names(n_links: int) -> tuple[str, ...]:
    """Names of the plant state ``x = (q, q', s, s')``."""
    return (tuple(f"q{i + 1}" for i in range(n_links)) + tuple(f"qd{i + 1}" for i in range(n_links))
            + ("s_x", "s_y", "sd_x", "sd_y"))
