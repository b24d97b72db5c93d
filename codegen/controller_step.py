"""One control sample in generated C: measurement, the task-frame loops, the decoupling law.

The loops of NOTES section 4, one per task axis ``i`` in the loop frame ``R_f`` (rows of
``R = diag(R_L, R_L)`` at the arm tip, or at a desired point), with ``sigma_i = 1`` on a
force-controlled axis. Integrals advance once per sample period ``T``, current error
included (``z1 += T e``, ``z2 += T z1``):

    velocity axis:  e = y_d - y,   a = y_d' + KP e + KI z1 + KI2 z2      (PI^2, feedforward)
    force axis:     e = y_d - f,   a = -KP e - KD y - KI z1               (impedance + integral)

with ``y = R_f v`` the task velocity and ``f = R_f F_c`` the task wrench. The law then gets
``a`` (in the desired frame ``R_d``, rotated into ``R(r)`` with ``R_d'``'s term, as the
paper's Figure 3) and the contact term: the measured ``F_c`` (the task law) or Khatib's
feedforward ``R^T Sigma F_d`` of the desired force. Run-time switches are 0/1 numbers
blended arithmetically, exact for 0 and 1, so one build serves every selection and scheme.
"""

from __future__ import annotations

import casadi as ca

from . import rigid_body as rb
from .kernel import Arg, Guard, Kernel, conditioning_guard
from .surfaces import SurfaceSpec, task_frame
from .task_law import AXIS_NAMES, CONDITIONING, arm_motion, decoupling, frame_guard, task_rows

#: per-axis loop gains, in this order in the ``gains`` array
LOOP_GAINS = ("KP", "KI", "KI2", "KD")
#: the ``options`` array: switches (0/1) and the sample period
OPTIONS = ("curvature", "sample_time", "khatib", "desired_frame")


def loops(y, f, z, yd, yd_rate, gains, sigma, T):
    """Task accelerations ``a`` and the integrals after this sample (module docstring).

    ``z`` holds ``(z1, z2)`` per axis; the double integral is kept at 0 on force axes.
    """
    a, z_next = [], []
    for i in range(y.shape[0]):
        KP, KI, KI2, KD = (gains[len(LOOP_GAINS) * i + k] for k in range(len(LOOP_GAINS)))
        s = sigma[i]
        e = s * (yd[i] - f[i]) + (1 - s) * (yd[i] - y[i])
        z1 = z[2 * i] + T * e
        z2 = (1 - s) * (z[2 * i + 1] + T * z1)
        a_velocity = yd_rate[i] + KP * e + KI * z1 + KI2 * z2
        a_force = -KP * e - KD * y[i] - KI * z1
        a.append(s * a_force + (1 - s) * a_velocity)
        z_next += [z1, z2]
    return ca.vertcat(*a), ca.vertcat(*z_next)


def controller_kernels(chain: rb.Chain, spec: SurfaceSpec, axes: tuple[int, ...]) -> tuple[Kernel, ...]:
    """``controller_step`` (one sample: measure, loops, law) and ``task_measurement`` of ``chain``
    on ``spec`` for the task ``axes``."""
    n, m = chain.n, len(axes)
    q, qd = ca.SX.sym("q", n), ca.SX.sym("qd", n)
    Fc, z = ca.SX.sym("Fc", 6), ca.SX.sym("integrals", 2 * m)
    yd, yd_rate, target = ca.SX.sym("yd", m), ca.SX.sym("yd_rate", m), ca.SX.sym("target", 6)
    gains, sigma = ca.SX.sym("gains", len(LOOP_GAINS) * m), ca.SX.sym("selection", m)
    params = ca.SX.sym("robot", len(rb.parameter_names(chain)))
    theta, e, opts = ca.SX.sym("surface", len(spec.parameters)), ca.SX.sym("e", 3), ca.SX.sym("options", len(OPTIONS))
    curvature, T, khatib, desired = (opts[i] for i in range(len(OPTIONS)))

    arm = arm_motion(chain, q, qd)
    p, v = arm.frames.tip_p, arm.v
    tf = task_frame(spec, p, v[:3], theta, e)
    Rm, Rdm = task_rows(tf, axes)
    # the loop frame: at the tip, or at the desired point target = (p_d, p_d')
    tf_f = task_frame(spec, desired * target[:3] + (1 - desired) * p,
                      desired * target[3:] + (1 - desired) * v[:3], theta, e)
    Rf, Rdf = task_rows(tf_f, axes)
    y, f = Rf @ v, Rf @ Fc
    a_f, z_next = loops(y, f, z, yd, yd_rate, gains, sigma, T)
    # in the desired frame: R(r) R_d^T (a - R_d' r'), the law's own curvature term off
    a = desired * (Rm @ (Rf.T @ (a_f - curvature * (Rdf @ v)))) + (1 - desired) * a_f
    contact = khatib * (Rm.T @ (sigma * yd)) + (1 - khatib) * Fc
    _, tau, cond = decoupling(chain, arm, params, qd, Rm, Rdm, a, contact, ca.SX.zeros(n, 1),
                              curvature * (1 - desired))

    names = tuple(j.name for j in chain.joints)
    axis_names = tuple(AXIS_NAMES[i] for i in axes)
    velocity_units = tuple("m/s" if i < 3 else "rad/s" for i in axes)
    force_units = tuple("N" if i < 3 else "N m" for i in axes)
    a_q = Arg("q", q, rb.joint_units(chain, "q"), names=names)
    a_qd = Arg("qd", qd, rb.joint_units(chain, "qd"), names=names)
    a_fc = Arg("Fc", Fc, ("N",) * 3 + ("N m",) * 3, names=("f_x", "f_y", "f_z", "m_x", "m_y", "m_z"))
    a_s = Arg("surface", theta, "m (lengths), 1 (directions)", names=spec.parameters)
    a_e = Arg("e", e, "1", names=("e_x", "e_y", "e_z"))
    integral_names = tuple(f"{k}_{ax}" for ax in axis_names for k in ("z1", "z2"))
    frame_guards = (frame_guard(tf.sine), Guard(
        "loop_frame", tf_f.sine, "HYBRID_FRAME_UNDEFINED", frame_guard(tf.sine).tolerance,
        "|e x n| at the loop frame's point (the desired point with desired_frame)"))
    step = Kernel(
        "controller_step",
        (a_q, a_qd, a_fc,
         Arg("integrals", z, "per axis: unit of e times s, then times s^2", names=integral_names),
         Arg("yd", yd, "m/s, rad/s (velocity axes); N, N m (force axes)", names=axis_names),
         Arg("yd_rate", yd_rate, "m/s^2, rad/s^2 (velocity axes; unused on force axes)", names=axis_names),
         Arg("target", target, "m, m/s", names=("p_x", "p_y", "p_z", "pd_x", "pd_y", "pd_z")),
         Arg("gains", gains, "per axis KP, KI, KI2, KD (see codegen/controller_step.py)",
             names=tuple(f"{g}_{ax}" for ax in axis_names for g in LOOP_GAINS)),
         Arg("selection", sigma, "1 (1: force-controlled axis)", names=axis_names),
         Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain)), a_s, a_e,
         Arg("options", opts, "1, s, 1, 1", names=OPTIONS)),
        (Arg("tau", tau, rb.joint_units(chain, "tau")),
         Arg("integrals_next", z_next, "as integrals"),
         Arg("a", a_f, tuple("m/s^2" if i < 3 else "rad/s^2" for i in axes), names=axis_names),
         Arg("y", y, velocity_units, names=axis_names), Arg("f", f, force_units, names=axis_names)),
        f"one control sample on a {spec.kind}: task velocity y = R_f v and wrench f = R_f F_c in the loop "
        "frame, the loops' task acceleration a and integrals after the sample, and the torque tau of the "
        f"decoupling law (task axes {', '.join(axis_names)})",
        batched=("q", "qd", "Fc", "integrals", "yd", "yd_rate", "target"),
        guards=(*frame_guards, conditioning_guard(cond, CONDITIONING)))
    R6 = ca.diagcat(tf.R, tf.R)
    measurement = Kernel(
        "task_measurement", (a_q, a_qd, a_fc, a_s, a_e),
        (Arg("p", p, "m"), Arg("v", v, "m/s, rad/s", names=("vx", "vy", "vz", "wx", "wy", "wz")),
         Arg("task_velocity", R6 @ v, "m/s, rad/s", names=AXIS_NAMES),
         Arg("task_wrench", R6 @ Fc, "N, N m", names=AXIS_NAMES)),
        "what the controller measures: tip position p and twist v = (p', w) in base axes, and on all six "
        "task axes at the tip the task velocity R v and the task wrench R F_c",
        batched=("q", "qd", "Fc"), guards=(frame_guard(tf.sine),))
    return step, measurement
