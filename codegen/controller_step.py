"""One control sample in generated C: measurement, the task-frame loops, the control law.

The loops of conventions §4, one per task axis ``i`` in the loop frame ``R_f`` (rows of
``R = diag(R_L, R_L)`` at the arm tip, or at a desired point), with ``sigma_i = 1`` on a
force-controlled axis. Integrals advance once per sample period ``T``, current error
included (``z1 += T e``, ``z2 += T z1``):

    velocity axis:  e = y_d - y,   a = y_d' + KP e + KI z1 + KI2 z2      (PI^2, feedforward)
    force axis:     e = y_d - f,   a = -KP e - KD y - KI z1               (impedance + integral)

with ``y = R_f v`` the task velocity and ``f = R_f F_c`` the task wrench. The references
``y_d(t)`` are steps evaluated in C at the sample time ``t`` (constants are steps without a
jump) plus what the caller adds (``yd_extra``: references given as code). Options (0/1 switches
and numbers in the ``options`` array, blended arithmetically, exact for 0 and 1, so one build
serves every selection, scheme and option, but the two that change what is computed: the
desired frame and the position error are compiled in):

- ``position_error``: the paper's last equations: on velocity axes ``z1`` is the position error
  ``r_E = R_f T(r) (r_d - r)`` (``r = (p, phi_ZYX)``, the angle error wrapped to (-pi, pi]) and
  ``z2`` its integral, so ``KI`` and ``KI2`` act as ``KP_p`` and ``KI_p``.
- ``integral_limit``: anti-windup by conditional integration: a sample whose integral action
  (``KI z1 + KI2 z2``; ``KI2 z2`` with ``position_error``) would exceed it in magnitude keeps the
  axis's integrals as they were.
- ``loss_threshold``, ``approach_speed``: a force axis whose measured force falls below the
  threshold is out of contact (before the first touch, or after a loss): it approaches at
  ``approach_speed`` (``a = -KD (y + approach_speed)``, the impedance's own damping) until the force
  returns, its integral kept at ``z1 = (KD approach_speed - KP e) / KI - T e``, where the force law
  (after the integral's advance) commands the same acceleration: at the touch ``a`` changes by
  ``(KP + KI T)`` times the force's own change in that sample, no more (with ``KI = 0`` the
  integral is held, and the jump is ``KD approach_speed - KP e``).

The law then gets ``a`` (in the desired frame ``R_d``, rotated into ``R(r)`` with ``R_d'``'s
term, as the paper's Figure 3). ``controller_step`` is the decoupling law with the measured
``F_c`` (the task law) or Khatib's feedforward ``R^T Sigma F_d`` of the desired force.
``controller_posture_step`` (generated for a redundant task, ``m < n``) adds a posture task's
null-space torque (the ``posture`` array: ``q_rest``, ``K_p``, ``K_d`` per joint), the inverse
dynamics of a joint PD's acceleration ``w``:

    tau0 = B(q) w + n(q, q'),   w = K_p (q_rest - q) - K_d q'      [K_p in 1/s^2, K_d in 1/s]

which the law projects into the task's null space, ``(I - J_y^T Jbar_y^T) tau0``. Applied to the
arm (its model exact) this gives ``q'' = Jbar_y b + (I - Jbar_y J_y) w`` (``b`` the law's, see
:mod:`codegen.task_law`): the task acceleration stays ``a`` and the null space moves as the
projected PD, alike for light wrist and heavy shoulder joints (the weighting by ``B``), with
gravity and the velocity terms cancelled there too (``n``: the law alone cancels them in the task
space only, and leaves the null space to fall). Every step takes the ``posture`` array and the
others ignore it, so the law without a posture is ``controller_step``'s own code, bit for bit (a
step computing ``tau0`` from zero gains would agree within rounding only: the C compiler's fused
multiply-adds follow the code around them). A square task (``m = n``) has no null space.
``raibert_craig_step`` maps the same loops without dynamic decoupling (conventions §7):

    tau = diag(B) q''_m + J_y^T Sigma w + g(q),   w_i = -F_d,i + a_i / KP_i  (m_d a_i, force axes)

with ``q''_m = J_y^+ Sigma^A a`` (Raibert & Craig: the inverse of the task Jacobian) or
``q''_m = (Sigma^A J_y)^+ Sigma^A a`` (Fisher & Mujtaba's pseudo-inverse of the selected rows).
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from hybrid.spec.controller_step import CONTROLLER_STEP, ESTIMATE, LOOP_GAINS, NO_LIMIT, OPTIONS, WRENCH
from hybrid.spec.interfaces import Dims

from . import body_frame as bf
from . import factor
from . import rigid_body as rb
from .kernel import Arg, Guard, Kernel, conditioning_guard, declared
from .rigid_body import cross
from .surfaces import SurfaceSpec, TaskFrame, task_frame
from .task_law import (
    AXIS_NAMES,
    CONDITIONING,
    EULER_TOL,
    arm_motion,
    decoupling,
    euler_map_of,
    euler_zyx,
    frame_guard,
    task_rows,
)


@dataclass(frozen=True)
class LoopInputs:
    """What the loops read at one sample (symbols or expressions), per task axis."""

    y: object        # task velocity in the loop frame
    f: object        # task wrench in the loop frame
    z: object        # integrals (z1, z2) per axis
    yd: object       # references
    yd_rate: object  # their rates (feedforward)
    r_err: object    # position error R_f T (r_d - r)
    gains: object    # (KP, KI, KI2, KD) per axis
    sigma: object    # 1 on force axes
    opts: dict       # OPTIONS by name


def loops(x: LoopInputs):
    """Task accelerations ``a`` and the integrals after this sample (module docstring)."""
    o = x.opts
    T, pe = o["sample_time"], o["position_error"]
    a, z_next = [], []
    for i in range(x.y.shape[0]):
        KP, KI, KI2, KD = (x.gains[len(LOOP_GAINS) * i + k] for k in range(len(LOOP_GAINS)))
        s, z1, z2 = x.sigma[i], x.z[2 * i], x.z[2 * i + 1]
        e = s * (x.yd[i] - x.f[i]) + (1 - s) * (x.yd[i] - x.y[i])
        pe_i = pe * (1 - s)  # the position error serves velocity axes only
        z1n = pe_i * x.r_err[i] + (1 - pe_i) * (z1 + T * e)
        z2n = (1 - s) * (z2 + T * z1n)
        # anti-windup: keep the integrals when the integral action would leave the limit
        held = ca.fabs((1 - pe_i) * KI * z1n + KI2 * z2n) > o["integral_limit"]
        # out of contact on a force axis: approach the surface, the integral where the force law would agree
        lost = s * (x.f[i] < o["loss_threshold"])
        keep = ca.logic_or(held, lost)  # both 0 or 1: fmax's value, without its call (which spills every register)
        z1n = keep * ((1 - pe_i) * z1 + pe_i * z1n) + (1 - keep) * z1n
        z2n = keep * (1 - s) * z2 + (1 - keep) * z2n
        tracked = (KD * o["approach_speed"] - KP * e) / ca.if_else(KI != 0, KI, 1) - T * e
        z1n = ca.if_else(lost * (KI != 0), tracked, z1n)
        a_velocity = x.yd_rate[i] + KP * e + KI * z1n + KI2 * z2n
        a_force = (1 - lost) * (-KP * e - KD * x.y[i] - KI * z1n) - lost * KD * (x.y[i] + o["approach_speed"])
        a.append(s * a_force + (1 - s) * a_velocity)
        z_next += [z1n, z2n]
    return ca.vertcat(*a), ca.vertcat(*z_next)


def posture_torque(chain: rb.Chain, arm, params, q, qd, posture):
    """``tau0 = B(q) w + n(q, q')``, ``w = K_p (q_rest - q) - K_d q'``, of the ``posture`` array: the
    inverse dynamics of the PD's joint acceleration ``w`` (module docstring).

    ``B`` makes the gains a joint acceleration's, so one pair suits every joint (plain torque gains
    would be stiff for the wrist and soft for the shoulder); ``n`` makes the null space's own motion
    the projected PD alone (without it the null space sags under gravity, which the law compensates
    in the task space only). Both are the law's own ``B`` and ``n``, computed once (the kernels'
    common subexpressions)."""
    n = chain.n
    q_rest, kp, kd = posture[:n], posture[n:2 * n], posture[2 * n:]
    w = kp * (q_rest - q) - kd * qd
    return bf.crba(arm.tree, params) @ w + bf.rnea(arm.tree, params, qd)


def _clamped(x, lo, hi):
    """``x`` within ``[lo, hi]`` by comparisons (``fmin``/``fmax`` would make a NaN a number)."""
    return ca.if_else(x > hi, hi, ca.if_else(x < lo, lo, x))


def limited(tau, z, z_next, last, limits):
    """The torque within its limits, the integrals after the sample, and whether it saturated.

    ``last`` holds the last sample's torque and a flag (1 once a torque was applied: the first sample
    after a start has no rate to limit); ``limits`` the largest ``|tau_j|`` and the largest change of
    ``tau_j`` in one sample (the rate bound first, then the magnitude's). A saturated sample keeps the
    integrals as they were (conditional integration: the loops do not wind up against a torque the
    arm does not get). A limit of the largest double (``DBL_MAX``) is none: it changes no finite torque."""
    out = bounded(tau, last, limits)
    saturated = ca.sum1(out != tau) > 0
    return out, ca.if_else(saturated, z, z_next), saturated


def bounded(tau, last, limits):
    """``tau`` within ``limits`` (:func:`limited`'s bounds: the rate's from ``last`` once started, then the
    magnitude's); a torque that is not finite stays as it is (and is reported so)."""
    n = tau.shape[0]
    prev, started, tau_max, rate_max = last[:n], last[n], limits[:n], limits[n:]
    out = []
    for j in range(n):
        lo, hi = ca.if_else(started, prev[j] - rate_max[j], -tau_max[j]), ca.if_else(started, prev[j] + rate_max[j],
                                                                                          tau_max[j])
        finite = ca.fabs(tau[j]) <= NO_LIMIT  # the largest double: false for infinities and NaN
        out.append(ca.if_else(finite, _clamped(_clamped(tau[j], lo, hi), -tau_max[j], tau_max[j]), tau[j]))
    return ca.vertcat(*out)


def sensor_wrench(tip_R, reading, sensor, gravity):
    """The raw ``reading`` of a force/torque sensor as ``(w_t, F)``: the environment's wrench on the tool
    in sensor axes about the sensor origin (sign, bias and the tool's weight taken off), and the wrench on
    the robot at the tip origin in base axes (``hybrid.control.wrench_sensor``'s steps 1 and 2)."""
    r = sensor[0:3]
    Rm = ca.reshape(sensor[3:12], 3, 3).T  # row-major
    sign, mass, com, bias = sensor[12], sensor[13], sensor[14:17], sensor[17:23]
    R_s = tip_R @ Rm
    f_g = mass * (R_s.T @ gravity)
    w_t = sign * reading - bias - ca.vertcat(f_g, ca.cross(com, f_g))
    f = R_s @ w_t[:3]
    return w_t, ca.vertcat(f, R_s @ w_t[3:] + ca.cross(tip_R @ r, f))


def low_pass(x, state, sensor, sample_time):
    """The Butterworth low-pass of order ``sensor[24]`` (1 or 2) at ``sensor[23]`` Hz (none at 0) on each
    component of ``x``, in transposed direct form II (``state``: two numbers per component), by the
    bilinear transform with the cutoff prewarped (-3 dB exactly at the cutoff). The state's last number is
    1 once the filter has started: before, it takes the steady state of ``x`` (no start-up transient).
    Returns ``(y, state after)``."""
    cutoff, second = sensor[23], sensor[24] > 1.5
    K = ca.tan(ca.pi * cutoff * sample_time)
    n1, n2 = 1 / (1 + K), 1 / (1 + ca.sqrt(2) * K + K * K)
    b0 = ca.if_else(second, K * K * n2, K * n1)
    b1 = ca.if_else(second, 2 * K * K * n2, K * n1)
    b2 = ca.if_else(second, K * K * n2, 0)
    a1 = ca.if_else(second, 2 * (K * K - 1) * n2, (K - 1) * n1)
    a2 = ca.if_else(second, (1 - ca.sqrt(2) * K + K * K) * n2, 0)
    on, started = cutoff > 0, state[2 * x.shape[0]]
    ys, nxt = [], []
    for i in range(x.shape[0]):
        s1 = ca.if_else(started, state[2 * i], (1 - b0) * x[i])
        s2 = ca.if_else(started, state[2 * i + 1], (b2 - a2) * x[i])
        y = b0 * x[i] + s1
        ys.append(ca.if_else(on, y, x[i]))
        nxt += [ca.if_else(on, b1 * x[i] - a1 * y + s2, 0), ca.if_else(on, b2 * x[i] - a2 * y, 0)]
    return ca.vertcat(*ys), ca.vertcat(*nxt, 1)


def estimated_frame(state, s, F, v, e, T):
    """The task frame from an estimate of the normal (``hybrid.control.estimation``), and the state after
    this sample: ``s`` holds the estimator's tuning (its ``parameters_named``), ``F`` the contact force on
    the robot and ``v`` the tip's velocity (base axes)."""
    w_force, w_velocity, correct, tau_f, inv_tau_v, rate_gain, f_min, v_min = (s[i] for i in range(8))
    c_prior, gate, info_prior, inv_tau_c, v_noise, acquisition, excitation, from_force, max_curvature = (
        s[i] for i in range(11, 20))
    alpha = 1 - ca.exp(-T / tau_f)
    kappa = rate_gain * alpha / (2 - alpha)  # the alpha-beta tracker's beta / alpha
    started = state[9]
    F_size = ca.norm_2(F)
    touching_at_all = F_size > f_min
    rate = started * state[3:6]
    # the prediction: the normal turns on at its estimated rate (no lag on a steadily curving surface); the start
    # is the given one, or the force's direction at the first touch
    start = ca.if_else(ca.logic_and(from_force, touching_at_all), F / ca.if_else(touching_at_all, F_size, 1), s[8:11])
    m = ca.if_else(started, state[0:3], start) + T * rate
    n_pred = m / ca.norm_2(m)
    c, info = ca.if_else(started, state[10], c_prior), ca.if_else(started, state[11], info_prior)
    F_rate = started * (F - state[6:9]) / T
    # the compliance: the tip's normal velocity against the normal force's rate (recursive least squares), in
    # contact; the force's own rate along it (the estimate's tilt, turning with the sliding, stays out), less
    # the excitation (a dead zone: it leans the compliance a little high, which the velocity correction bears
    # better than low)
    along = ca.dot(F, F_rate) / ca.if_else(touching_at_all, F_size * F_size, 1)
    f_n = ca.if_else(touching_at_all, ca.dot(n_pred, F) * along, 0)
    f_n = f_n - _clamped(f_n, -excitation, excitation)
    info = ca.exp(-T * inv_tau_c) * info + f_n * f_n
    c = ca.fmax(c + f_n * (-ca.dot(n_pred, v) - c * f_n) / info, 0)
    # the contact point's velocity: the tip's, and the rate of the tool's deflection under the force
    deflection_rate = c * F_rate
    v_c = v + deflection_rate
    vn = ca.dot(n_pred, v_c)
    v_t = v_c - vn * n_pred
    speed = ca.norm_2(v_t)
    sliding = speed > v_min
    # the friction on the tool is against the contact point's sliding, or (while it sticks) the tip's pull:
    # without it the force is along the normal
    tip_t = v - ca.dot(n_pred, v) * n_pred
    tip_speed = ca.norm_2(tip_t)
    pushed = tip_speed > v_min
    sigma = gate * ca.dot(n_pred, F_rate) * (c + v_noise / ca.sqrt(info))
    # (alone, the force estimate takes the contact point's normal velocity into it, as far as the deflection's
    # rate lets it: the friction's direction then holds the tilt along the motion)
    gated = speed * speed / ca.if_else(sliding, speed * speed + sigma * sigma, 1)
    sliding_dir = v_t + (1 - w_velocity) * gated * vn * n_pred
    u = ca.if_else(sliding, sliding_dir / ca.if_else(sliding, ca.norm_2(sliding_dir), 1),
                   ca.if_else(pushed, tip_t / ca.if_else(pushed, tip_speed, 1), ca.SX.zeros(3, 1)))
    F_perp = F - correct * ca.dot(F, u) * u
    magnitude = ca.norm_2(F_perp)
    touching = magnitude > f_min
    n_force = F_perp / ca.if_else(touching, magnitude, 1)
    # the corrections: towards the force's direction, and the normal turned orthogonal to the contact point's
    # velocity (in contact; giving way to a fast-changing deflection, the velocity's least certain part)
    velocity_on = ca.logic_and(sliding, touching)
    d_velocity = -w_velocity * inv_tau_v * T * vn / ca.if_else(velocity_on, speed * speed + sigma * sigma, 1) * v_t
    d = w_force * touching * alpha * (n_force - n_pred) + ca.if_else(velocity_on, d_velocity, ca.SX.zeros(3, 1))
    m = n_pred + d
    n = m / ca.norm_2(m)
    # the rate takes the correction up to the acquisition's size: a larger one converges, it does not track
    d = d * ca.fmin(1, alpha * acquisition / ca.fmax(ca.norm_2(d), 1e-300))
    rate = rate + kappa / T * (d - ca.dot(d, n) * n)
    # no faster than the sliding along the sharpest curvature it follows
    rate = rate * ca.fmin(1, max_curvature * tip_speed / ca.fmax(ca.norm_2(rate), 1e-300))
    # (waiting for the first touch, the state stays at its start)
    waiting = ca.logic_and(ca.logic_and(1 - started, from_force), 1 - touching_at_all)
    n = ca.if_else(waiting, s[8:11], n)
    nxt = ca.if_else(waiting, ca.vertcat(s[8:11], ca.SX.zeros(3, 1), F, 0, c_prior, info_prior),
                     ca.vertcat(n, rate - ca.dot(rate, n) * n, F, 1, c, info))
    return normal_frame(n, ca.if_else(waiting, ca.SX.zeros(3, 1), rate), e), nxt


#: below this ``|e x n|`` the estimated frame takes its direction from a fallback orthogonal to ``e`` (an
#: estimate along ``e``, e.g. its start, has no frame of ``e``'s own)
FALLBACK_SINE = 1e-3


def normal_frame(n, rate, e) -> TaskFrame:
    """The task frame of the unit normal ``n`` and its rate (docs/conventions.md §9's rows from ``n``
    and ``e``, differentiated along ``n'``, taken tangent); with ``n`` within :data:`FALLBACK_SINE` of
    ``+-e``, the rows from a direction orthogonal to ``e`` (base x made orthogonal, or base y when ``e``
    is near x) instead."""
    rate_t = rate - ca.dot(rate, n) * n
    e_unit = e / ca.norm_2(e)
    near_x = ca.fabs(e_unit[0]) > 0.9
    a = ca.vertcat(1 - near_x, near_x, 0)
    e_alt = a - ca.dot(a, e_unit) * e_unit
    parallel = ca.norm_2(cross(e_unit, n)) < FALLBACK_SINE
    e_unit = ca.if_else(parallel, e_alt / ca.norm_2(e_alt), e_unit)
    c = cross(e_unit, n)
    sine = ca.norm_2(c)
    t1 = c / sine
    t2 = cross(n, t1)
    u = cross(e_unit, rate_t) / sine
    t1d = u - ca.dot(t1, u) * t1
    t2d = cross(rate_t, t1) + cross(n, t1d)
    return TaskFrame(ca.vertcat(t1.T, t2.T, n.T), ca.vertcat(t1d.T, t2d.T, rate_t.T), sine, n)


def _wrapped(angle):
    """``angle`` in [-pi, pi) (cheaper than atan2 of its sine and cosine)."""
    return angle - 2 * ca.pi * ca.floor((angle + ca.pi) / (2 * ca.pi))


def _euler_map_of(Rot):
    """``T_A(phi)`` (conventions §9) from the rotation itself: the sines and cosines of ``alpha,
    beta`` are ratios of its entries, so no trigonometric call is needed."""
    cb = ca.sqrt(Rot[0, 0] ** 2 + Rot[1, 0] ** 2)
    inv = 1 / cb
    return euler_map_of(Rot[1, 0] * inv, Rot[0, 0] * inv, -Rot[2, 0], cb), cb


def references(t, steps, extra):
    """Per axis ``before`` until ``at``, ``after`` from then on (``steps`` = (before, after, at) per
    axis), plus ``extra`` (the values of references evaluated by the caller)."""
    m = extra.shape[0]
    return ca.vertcat(*(ca.if_else(t >= steps[3 * i + 2], steps[3 * i + 1], steps[3 * i]) for i in range(m))) + extra


def controller_kernels(chain: rb.Chain, spec: SurfaceSpec, axes: tuple[int, ...], desired_frame: bool = False,
                       position_error: bool = False, wrench_sensor: bool = False) -> tuple[Kernel, ...]:
    """``controller_step`` (one sample: measure, loops, decoupling law), ``raibert_craig_step`` (the
    same loops, no decoupling) and ``task_measurement`` of ``chain`` on ``spec`` for the task ``axes``,
    then for a redundant task (fewer axes than joints) ``controller_posture_step`` (the decoupling
    law with the posture task in its null space).

    ``desired_frame``, ``position_error`` and ``wrench_sensor`` (the wrench input is a force/torque
    sensor's raw reading, turned into ``F_c`` by :func:`sensor_wrench` and :func:`low_pass`) change what
    is computed, so they are compiled in (a variant each); the other options are run-time numbers."""
    n, m = chain.n, len(axes)
    names = tuple(j.name for j in chain.joints)
    axis_names = tuple(AXIS_NAMES[i] for i in axes)
    dims = Dims(names, axis_names, rb.parameter_names(chain), spec.parameters)
    sym = {p.name: ca.SX.sym(p.name, p.size_of(dims)) for p in CONTROLLER_STEP.inputs}
    q, qd, Fc, z, last, filt, est, t = (sym[k] for k in ("q", "qd", "Fc", "integrals", "last_torque", "filter",
                                                         "estimate", "t"))
    yd_extra, yd_rate, target = sym["yd_extra"], sym["yd_rate"], sym["target"]
    steps, gains, sigma, params, theta = (sym[k] for k in ("steps", "gains", "selection", "robot", "surface"))
    e, opts, posture, limits, sensor = (sym[k] for k in ("e", "options", "posture", "limits", "sensor"))
    o = {name: opts[i] for i, name in enumerate(OPTIONS)}
    o["position_error"] = float(position_error)
    curvature = o["curvature"]

    arm = arm_motion(chain, q, qd)
    p, v = arm.frames.tip_p, arm.v
    reading = Fc
    if wrench_sensor:  # the reading becomes the wrench on the robot at the tip, filtered
        _, raw_Fc = sensor_wrench(arm.frames.tip_R, reading, sensor, params[-3:])
        Fc, filt_next = low_pass(raw_Fc, filt, sensor, o["sample_time"])
    else:
        filt_next = ca.SX.zeros(filt.shape[0], 1)
    if spec.estimated:  # the frame from the estimate of the normal (the surface's parameters are the tuning)
        if desired_frame or position_error:
            raise ValueError("an estimated surface has no desired point's frame or position error")
        tf, est_next = estimated_frame(est, theta, Fc[:3], v[:3], e, o["sample_time"])
    else:
        tf, est_next = task_frame(spec, p, v[:3], theta, e), ca.SX.zeros(len(ESTIMATE), 1)
    Rm, Rdm = task_rows(tf, axes)
    # the loop frame: at the tip, or at the desired point target = (p_d, p_d', phi_d)
    tf_f = task_frame(spec, target[:3], target[3:6], theta, e) if desired_frame else tf
    Rf, Rdf = task_rows(tf_f, axes) if desired_frame else (Rm, Rdm)
    y, f = Rf @ v, Rf @ Fc
    yd = references(t, steps, yd_extra)
    r_err, cos_beta = ca.SX.zeros(len(axes), 1), None
    if position_error:
        phi = euler_zyx(arm.frames.tip_R)
        TA, cos_beta = _euler_map_of(arm.frames.tip_R)
        r_err = Rf @ ca.vertcat(target[:3] - p, TA @ _wrapped(target[6:9] - phi))
    a_f, z_next = loops(LoopInputs(y, f, z, yd, yd_rate, r_err, gains, sigma, o))
    if desired_frame:  # R(r) R_d^T (a - R_d' r'), the law's own curvature term off
        a, law_curvature = Rm @ (Rf.T @ (a_f - curvature * (Rdf @ v))), 0
    else:
        a, law_curvature = a_f, curvature
    contact = o["khatib"] * (Rm.T @ (sigma * yd)) + (1 - o["khatib"]) * Fc
    _, tau, cond = decoupling(chain, arm, params, qd, Rm, Rdm, a, contact, ca.SX.zeros(n, 1), law_curvature)
    tau_rc, cond_rc = _raibert_craig(chain, arm, params, Rm, a, yd, gains, sigma, o["pseudoinverse"])

    wrench_units = ("N",) * 3 + ("N m",) * 3
    inputs = declared(CONTROLLER_STEP.inputs, dims, {**sym, "Fc": reading}, {
        "q": rb.joint_units(chain, "q"), "qd": rb.joint_units(chain, "qd"), "Fc": wrench_units,
        "last_torque": (*rb.joint_units(chain, "tau"), "1"), "robot": rb.parameter_units(chain)})
    a_q, a_qd, a_fc, a_robot, a_s, a_e, a_sensor = (next(a for a in inputs if a.name == k) for k in (
        "q", "qd", "Fc", "robot", "surface", "e", "sensor"))
    guards = (frame_guard(tf.sine),)
    if desired_frame:
        guards += (Guard("loop_frame", tf_f.sine, "FRAME_UNDEFINED", frame_guard(tf.sine).tolerance,
                         "|e x n| at the desired point (the loop frame)"),)
    if position_error and max(axes) >= 3:  # T(r) enters the position error of an angular axis
        guards += (Guard("euler", cos_beta, "EULER_SINGULAR", EULER_TOL,
                         "|cos beta| of the tip's ZYX Euler angles (the position error's T(r))"),)
    def outputs(torque):
        torque, z_kept, saturated = limited(torque, z, z_next, last, limits)
        return declared(CONTROLLER_STEP.outputs, dims, {
            "tau": torque, "integrals_next": z_kept, "a": a_f, "y": y, "f": f, "saturated": saturated,
            "filter_next": filt_next, "estimate_next": est_next, "contact_wrench": Fc}, {
            "tau": rb.joint_units(chain, "tau"), "a": tuple("m/s^2" if i < 3 else "rad/s^2" for i in axes),
            "y": tuple("m/s" if i < 3 else "rad/s" for i in axes), "f": tuple("N" if i < 3 else "N m" for i in axes),
            "contact_wrench": wrench_units})

    what = (f"one control sample on a {spec.kind}: task velocity y = R_f v and wrench f = R_f F_c in the loop "
            "frame, the loops' task acceleration a and integrals after the sample, and the torque tau of ")
    per_state = CONTROLLER_STEP.per_sample
    step = Kernel("controller_step", inputs, outputs(tau),
                  what + f"the decoupling law (task axes {', '.join(axis_names)})", batched=per_state,
                  guards=(*guards, conditioning_guard(cond, CONDITIONING)), order="fewest_alive")
    raibert_craig = Kernel("raibert_craig_step", inputs, outputs(tau_rc),
                           what + f"Raibert & Craig's scheme (task axes {', '.join(axis_names)})", batched=per_state,
                           guards=(*guards, conditioning_guard(cond_rc, CONDITIONING)), order="fewest_alive")
    posture_step = ()
    if m < n:  # a square task has no null space: its law ignores tau0
        tau0 = posture_torque(chain, arm, params, q, qd, posture)
        _, tau_posture, _ = decoupling(chain, arm, params, qd, Rm, Rdm, a, contact, tau0, law_curvature)
        posture_step = (Kernel("controller_posture_step", inputs, outputs(tau_posture),
                               what + f"the decoupling law with a posture task in its null space (task axes "
                               f"{', '.join(axis_names)})", batched=per_state,
                               guards=(*guards, conditioning_guard(cond, CONDITIONING)), order="fewest_alive"),)
    # an estimated surface's frame as the estimate stands (the measurement is of one instant)
    tf_now = normal_frame(ca.if_else(est[9], est[0:3], theta[8:11]), est[3:6], e) if spec.estimated else tf
    R6 = ca.diagcat(tf_now.R, tf_now.R)
    # the sensor's stages before the filter (which keeps a state): the measurement is of one instant
    compensated, at_tip = (sensor_wrench(arm.frames.tip_R, reading, sensor, params[-3:]) if wrench_sensor
                           else (reading, reading))
    measurement = Kernel(
        "task_measurement", (a_q, a_qd, a_fc, a_s, a_e, a_robot, a_sensor,
                             Arg("estimate", est, "as the step's estimate", names=ESTIMATE)),
        (Arg("p", p, "m"), Arg("v", v, "m/s, rad/s", names=("vx", "vy", "vz", "wx", "wy", "wz")),
         Arg("task_velocity", R6 @ v, "m/s, rad/s", names=AXIS_NAMES),
         Arg("task_wrench", R6 @ at_tip, "N, N m", names=AXIS_NAMES),
         Arg("compensated", compensated, ("N",) * 3 + ("N m",) * 3, names=WRENCH),
         Arg("contact_wrench", at_tip, ("N",) * 3 + ("N m",) * 3, names=WRENCH),
         Arg("R", ca.vec(arm.frames.tip_R.T), "1", names=tuple(f"R_{i}{j}" for i in range(1, 4) for j in range(1, 4)))),
        "what the controller measures: tip position p, the tip frame's rotation R (row by row; its third column "
        "the tool's axis) and twist v = (p', w) in base axes; the sensor's "
        "reading less its bias and the tool's weight (sensor axes) and the wrench on the robot at the tip F_c "
        "(base axes, before the filter); on all six task axes at the tip the task velocity R v and the task "
        "wrench R F_c", batched=("q", "qd", "Fc"), guards=(frame_guard(tf_now.sine),))
    return (step, raibert_craig, measurement, *posture_step)


def _raibert_craig(chain: rb.Chain, arm, params, Rm, a, yd, gains, sigma, pseudoinverse):
    """``(tau, conditioning)`` of Raibert & Craig's mapping (module docstring)."""
    n, m = chain.n, Rm.shape[0]
    Jy = Rm @ arm.J
    Q, Rq = factor.thin_qr(Jy.T)
    motion = (1 - sigma) * a
    # J_y^+ b = Q R^-T b (J_y^-1 when square)
    z = factor.forward_substitution([[Rq[j][i] for j in range(m)] for i in range(m)], motion)
    qdd_inverse = sum((Q[i] * z[i] for i in range(m)), ca.SX.zeros(n, 1))
    # (Sigma^A J_y)^+ Sigma^A a = J_y^T Sigma^A (Sigma^A J_y J_y^T Sigma^A + Sigma)^-1 Sigma^A a: the
    # identity on the force rows keeps the matrix invertible and their multipliers at 0
    keep = 1 - sigma
    M = (keep @ keep.T) * (Jy @ Jy.T) + ca.diag(sigma)
    qdd_selected = Jy.T @ (keep * factor.cholesky_solve(M, motion))
    qdd = pseudoinverse * qdd_selected + (1 - pseudoinverse) * qdd_inverse
    B = bf.crba(arm.tree, params)
    gravity = bf.rnea(arm.tree, params, ca.SX.zeros(n, 1))
    KP = ca.vertcat(*(gains[len(LOOP_GAINS) * i] for i in range(m)))
    w = ca.vertcat(*(ca.if_else(sigma[i], -yd[i] + a[i] / KP[i], 0) for i in range(m)))  # m_d a = a / KP
    tau = ca.diag(B) * qdd + Jy.T @ w + gravity
    return tau, factor.frobenius_conditioning(Jy, Rq)
