"""The 3-D experiment's plant (conventions §10) as generated C: any serial arm, a 3-D elastic force
sensor at its tip, penalty contact on any surface, Coulomb friction against the sliding velocity.

State ``x = (q, q', s, s')``: the joints and the sensor tip ``s`` (mass ``m_s``, base axes) tied
to the arm tip ``r`` by an isotropic spring-damper of zero rest length. The sensor reads the
force on the robot ``F_c = K_s (s - r) + D_s (s' - r')`` (no moment). The surface ``phi(s) = 0``
pushes the sensor tip along its normal ``n = grad phi / |grad phi|`` with
``N = max(0, k_e delta + d_e delta')`` while it penetrates by ``delta = -phi / |grad phi|`` (the
signed distance for the built-in surfaces, its first-order estimate for others), and friction
``-gamma N tanh(|v_s| / v_eps) v_s / |v_s|`` opposes the sliding velocity ``v_s = (I - n n^T) s'``.
Gravity (the robot array's) acts on the arm and on the sensor mass. ``B q'' = tau + J_p^T F_c - n``
is solved by a square-root-free Cholesky factorisation of ``B``; ``B`` and ``n - J_p^T F_c`` come
from Featherstone's algorithms in body coordinates (:mod:`.body_frame`: the composite-rigid-body
algorithm, and Newton-Euler with the sensor's force on the last link), the tip's position and
velocity from the same link transforms. The emitter adds the RK4 entry point.
"""

from __future__ import annotations

import casadi as ca

from . import body_frame as bf
from . import rigid_body as rb
from .factor import ldl_solve
from .kernel import Arg, Kernel
from .surfaces import SurfaceSpec, phi_sx, task_frame

#: the ``plant`` array: sensor mass, stiffness, damping; contact stiffness, damping; friction
#: coefficient and the speed of its tanh smoothing (the planar plant's, in the same order)
PLANT_PARAMETERS = ("m_s", "K_s", "D_s", "k_e", "d_e", "gamma", "v_eps")
PLANT_PARAMETER_UNITS = ("kg", "N/m", "N s/m", "N/m", "N s/m", "1", "m/s")
#: the output record: arm tip, its task velocity (t1, t2, n), the sensor's force in base and task
#: axes, the sensor tip, the penetration, the normal and friction forces, the sliding speed
OUTPUTS = ("r_x", "r_y", "r_z", "v_t", "v_t2", "v_n", "Fc_x", "Fc_y", "Fc_z", "Fc_t", "Fc_t2", "Fc_n",
           "s_x", "s_y", "s_z", "penetration", "N", "friction", "sensor_v_slide")
OUTPUT_UNITS = ("m",) * 3 + ("m/s",) * 3 + ("N",) * 6 + ("m",) * 4 + ("N", "N", "m/s")


def plant_kernels(chain: rb.Chain, spec: SurfaceSpec) -> tuple[Kernel, ...]:
    """``plant_rhs`` (``x'``, with the RK4 entry point ``plant_advance``) and ``plant_outputs``."""
    n = chain.n
    x, tau = ca.SX.sym("x", 2 * n + 6), ca.SX.sym("tau", n)
    params = ca.SX.sym("robot", len(rb.parameter_names(chain)))
    pp = ca.SX.sym("plant", len(PLANT_PARAMETERS))
    theta, e = ca.SX.sym("surface", len(spec.parameters)), ca.SX.sym("e", 3)
    m_s, K_s, D_s, k_e, d_e, gamma, v_eps = (pp[i] for i in range(len(PLANT_PARAMETERS)))
    q, qd, s, sd = x[:n], x[n:2 * n], x[2 * n:2 * n + 3], x[2 * n + 3:]

    tree = bf.link_transforms(chain, q)
    vs = bf.link_velocities(tree, qd)
    r, rd = bf.tip_position(tree), bf.tip_velocity(tree, vs)
    Fc = K_s * (s - r) + D_s * (sd - rd)
    grad = ca.gradient(phi_sx(spec, s, theta), s)
    norm = ca.norm_2(grad)
    n_s = grad / norm
    delta, delta_d = -phi_sx(spec, s, theta) / norm, -ca.dot(n_s, sd)
    # N = max(0, k_e delta + d_e delta') in contact, written with comparisons that let a NaN through
    # (``delta > 0`` and ``fmax`` would make it 0): where the surface's formula is undefined at s the state
    # goes NaN and the run stops there, instead of running on without a contact force
    push = k_e * delta + d_e * delta_d
    N = ca.if_else(delta <= 0, 0, ca.if_else(push < 0, 0, push))
    slide = sd - ca.dot(n_s, sd) * n_s
    # |v_s| kept away from 0 by far less than v_eps: tanh(w / v_eps) / w stays finite (1 / v_eps)
    w = ca.sqrt(ca.dot(slide, slide) + (1e-9 * v_eps) ** 2)
    friction = gamma * N * ca.tanh(w / v_eps)
    g = rb.gravity(chain, params)
    sdd = (N * n_s - friction / w * slide - Fc) / m_s + g
    B = bf.crba(tree, params)
    # n(q, q') - J_p^T F_c: the sensor's force on the arm enters the Newton-Euler pass
    bias = bf.rnea(tree, params, qd, f_ext=bf.tip_force(tree, Fc), velocities=vs)
    qdd = ldl_solve(B, tau - bias)
    xdot = ca.vertcat(qd, qdd, sd, sdd)

    tf = task_frame(spec, r, rd, theta, e)
    record = ca.vertcat(r, tf.R @ rd, Fc, tf.R @ Fc, s, delta, N, friction, w)
    names = tuple(j.name for j in chain.joints)
    state_names = (*names, *(f"{j}_rate" for j in names), "s_x", "s_y", "s_z", "sd_x", "sd_y", "sd_z")
    state_units = (*rb.joint_units(chain, "q"), *rb.joint_units(chain, "qd"), "m", "m", "m", "m/s", "m/s", "m/s")
    a_x = Arg("x", x, state_units, names=state_names)
    a_p = Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain))
    a_pp = Arg("plant", pp, PLANT_PARAMETER_UNITS, names=PLANT_PARAMETERS)
    a_s = Arg("surface", theta, "m (lengths), 1 (directions)", names=spec.parameters)
    a_e = Arg("e", e, "1", names=("e_x", "e_y", "e_z"))
    rhs = Kernel(
        "plant_rhs", (a_x, Arg("tau", tau, rb.joint_units(chain, "tau"), names=names), a_p, a_pp, a_s),
        (Arg("xdot", xdot, tuple(f"{u}/s" for u in state_units)),),
        f"the 3-D plant's state derivative on a {spec.kind}: arm, sensor tip, penalty contact, friction",
        integrator="plant_advance")
    outputs = Kernel(
        "plant_outputs", (a_x, a_p, a_pp, a_s, a_e), (Arg("y", record, OUTPUT_UNITS, names=OUTPUTS),),
        "the plant's output record (arm tip task frame R_L(r) with rows t1, t2, n)", batched=("x",))
    return rhs, outputs
