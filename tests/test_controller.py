"""The controller component: its loops against hand-computed samples, its law against Pinocchio + NumPy,
decoupling in closed loop, and the paper's controller against an independent NumPy one."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from conftest import blockdiag, pinocchio_terms, well_conditioned_states
from hybrid.codegen.model import PLANT_OUTPUTS

import hybrid
from hybrid import oracle

SPHERE = hybrid.Sphere((0.4, 0.1, 0.3), 0.15)
OUT = {name: i for i, name in enumerate(PLANT_OUTPUTS)}




def closed_loop(exp, plant, ctrl):
    """The sampled loop written out: ZOH torque, sensor reading at the sample instant."""
    x = exp.initial_state()
    m, out = exp.steps_per_sample, []
    traj = np.empty((m, len(x)))
    for k in range(exp.n_samples):
        o = plant.outputs(x[None, :])[0]
        tau = ctrl(k * exp.sample_time, x[:2].copy(), x[2:4].copy(), o[[OUT["Fc_x"], OUT["Fc_y"]]])
        assert plant.advance(x, tau, m, traj) == m
        out.append(plant.outputs(traj[-1:])[0])
    return np.array(out)


@pytest.mark.parametrize("settings", [{}, dict(controller="khatib", frame="desired", curvature=True),
                                      dict(integral=False, curvature=True)], ids=["paper", "khatib-desired", "curv"])
def test_from_experiment_in_an_independent_numpy_plant_gives_simulates_forces_and_speeds(settings):
    exp = hybrid.paper_experiment(duration=0.3, **settings)
    res = hybrid.simulate(exp)
    ours = closed_loop(exp, oracle.NumpyPlant(exp), hybrid.Controller.from_experiment(exp))
    at_samples = res.outputs[exp.steps_per_sample::exp.steps_per_sample]
    for col in ("Fc_n", "v_t"):  # the NumPy plant rounds differently: agreement to 1e-9, not bit for bit
        np.testing.assert_allclose(ours[:, OUT[col]], at_samples[:, OUT[col]], rtol=1e-9, atol=1e-9)


def test_paper_controller_equals_the_numpy_controller_on_random_samples(rng):
    """Every option of the experiment maps onto the component: same torques as the NumPy controller
    written from conventions §4 and §7, over sequences of random samples (the integrals carry over)."""
    for controller, frame, curvature, integral in itertools.product(("task", "khatib"), ("actual", "desired"),
                                                                    (False, True), (False, True)):
        exp = hybrid.paper_experiment(controller=controller, frame=frame, curvature=curvature, integral=integral)
        ours, theirs = hybrid.Controller.from_experiment(exp), oracle.NumpyController(exp)
        ours.timing_tolerance = None  # samples 1.7 sample times apart
        for k in range(40):
            t = k * exp.sample_time * 1.7  # across both reference steps
            q = np.array([rng.uniform(1.5, 2.8), rng.uniform(1.0, 2.5)])
            qd, Fc = rng.normal(0, 1, 2), rng.normal(0, 10, 2)
            np.testing.assert_allclose(ours(t, q, qd, Fc), theirs(t, q, qd, Fc), rtol=1e-9, atol=1e-9)


def loops_by_hand(y, f, z, yd, rate, gains, sigma, T, r_err=None, limit=np.inf, loss=None):
    """conventions §4 per axis, written from the text (z: one (int e, int int e) row per axis), with
    the options of the controller: position error r_err, anti-windup limit, contact-loss rule."""
    a, z_old, z = np.zeros(len(y)), z.copy(), z.copy()
    for i in range(len(y)):
        g = gains[i]
        if sigma[i]:
            e = yd[i] - f[i]
            z[i, 0] += T * e
            if loss is not None and f[i] < loss.threshold:  # the integral where the force law would agree
                z[i] = z_old[i]
                if g.KIf:
                    z[i, 0] = (g.KDf * loss.approach_speed - g.KPf * e) / g.KIf - T * e
                a[i] = -g.KDf * (y[i] + loss.approach_speed)
                continue
            if abs(g.KIf * z[i, 0]) > limit:
                z[i] = z_old[i]
            a[i] = -g.KPf * e - g.KDf * y[i] - g.KIf * z[i, 0]
        else:
            e = yd[i] - y[i]
            if r_err is None:
                z[i, 0] += T * e
                z[i, 1] += T * z[i, 0]
                if abs(g.KIv * z[i, 0] + g.KI2v * z[i, 1]) > limit:
                    z[i] = z_old[i]
            else:
                z[i, 0] = r_err[i]
                z[i, 1] += T * z[i, 0]
                if abs(g.KI2v * z[i, 1]) > limit:
                    z[i, 1] = z_old[i, 1]
            a[i] = rate[i] + g.KPv * e + g.KIv * z[i, 0] + g.KI2v * z[i, 1]
    return a, z


def zyx_angles(R):
    """ZYX Euler angles of a rotation matrix, R = Rz(alpha) Ry(beta) Rx(gamma)."""
    return np.array([np.arctan2(R[1, 0], R[0, 0]), -np.arcsin(np.clip(R[2, 0], -1, 1)), np.arctan2(R[2, 1], R[2, 2])])


def euler_map(phi):
    """T_A of conventions §9: w = T_A phi'."""
    sa, ca, sb, cb = np.sin(phi[0]), np.cos(phi[0]), np.sin(phi[1]), np.cos(phi[1])
    return np.array([[0, -sa, ca * cb], [0, ca, sa * cb], [1, 0, -sb]])


class Ramp:
    """A reference with a rate: the velocity loops' feedforward."""

    def __call__(self, t):
        return 0.1 + 0.5 * t

    def rate(self, t):
        return 0.5


def hand_torque(scheme, J, Jdqd, B, n, gravity, R, Rd, qd, a, Fc, yd, sigma, gains):
    """The scheme's torque from Pinocchio's terms, written from conventions §7 and §9."""
    if scheme in ("task", "khatib"):
        contact = blockdiag(R).T @ (sigma * yd) if scheme == "khatib" else Fc
        return oracle.spatial_decoupling_law(J, Jdqd, B, n, R, Rd, qd, a, contact, np.zeros(len(qd)), range(6), True)[1]
    Jy = blockdiag(R) @ J
    motion = sigma == 0
    if scheme == "raibert_craig":
        qdd = np.linalg.solve(Jy, np.where(motion, a, 0.0))
    else:  # Fisher & Mujtaba: the pseudo-inverse of the selected rows
        qdd = np.linalg.pinv(Jy[motion]) @ a[motion]
    m_d = np.array([1.0 / g.KPf for g in gains])
    w = np.where(motion, 0.0, -yd + m_d * a)
    return np.diag(B) * qdd + Jy.T @ w + gravity


OPTION_CASES = {
    "plain": {},
    "position-error": dict(position_error=True),
    "anti-windup": dict(integral_limit=0.05),
    "contact-loss": dict(contact_loss=hybrid.ContactLoss(threshold=2.0, approach_speed=0.03)),
}


@pytest.mark.parametrize("option", list(OPTION_CASES))
@pytest.mark.parametrize("scheme", ["task", "khatib", "raibert_craig", "fisher_mujtaba"])
def test_ur5_loops_and_torque_sample_by_sample(rng, robots, scheme, option):
    """Six loops (two force axes, per-axis gains, a ramp with feedforward, each option) against the
    hand-written loops on Pinocchio's measurement, and the torque against the scheme written by hand."""
    import pinocchio as pin

    robot, model, fid = robots["ur5"]
    data = model.createData()
    T = 0.01
    gains = {"t1": hybrid.Gains(KPv=30.0, KIv=150.0, KI2v=600.0), "rot_t1": hybrid.Gains(KPf=3.0, KDf=40.0, KIf=9.0)}
    kw = dict(OPTION_CASES[option])
    phi_d = rng.uniform(-1, 1, 3)
    p_d = np.array([0.45, 0.1, 0.46])

    def path(t):
        return p_d, np.zeros(3), phi_d

    ctrl = hybrid.Controller(robot, SPHERE, scheme, selection=("n", "rot_t1"), gains=gains, sample_time=T,
                             force_reference={"n": hybrid.Step(10.0, 20.0, 0.05), "rot_t1": 0.3},
                             velocity_reference={"t1": Ramp(), "rot_n": -0.2}, curvature=True, path=path,
                             torque_limit=None, **kw)  # random states: the law's torque, unbounded
    per_axis = [gains.get(n, hybrid.Gains()) for n in ctrl.axis_names]
    sigma = np.array([0, 0, 1, 1, 0, 0])
    z = np.zeros((6, 2))
    for k, (q, qd, (J, Jdqd, B, n, p)) in enumerate(well_conditioned_states(rng, robot, model, fid, SPHERE, 12)):
        t = k * T
        Fc = rng.normal(0, 10, 6)
        tau = ctrl(t, q, qd, Fc)
        v = J @ qd
        R, Rd = oracle.spatial_frame(SPHERE, p, v[:3], (0, 0, 1))
        y, f = blockdiag(R) @ v, blockdiag(R) @ Fc
        yd = np.array([Ramp()(t), 0.0, 10.0 if t < 0.05 else 20.0, 0.3, 0.0, -0.2])
        rate = np.array([0.5, 0, 0, 0, 0, 0])
        r_err = None
        if kw.get("position_error"):
            pin.framesForwardKinematics(model, data, q)
            phi = zyx_angles(data.oMf[fid].rotation)
            dphi = np.angle(np.exp(1j * (phi_d - phi)))
            r_err = blockdiag(R) @ np.concatenate([p_d - p, euler_map(phi) @ dphi])
        a, z = loops_by_hand(y, f, z, yd, rate, per_axis, sigma, T, r_err, kw.get("integral_limit", np.inf),
                             kw.get("contact_loss"))
        np.testing.assert_allclose(ctrl.last["y"], y, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(ctrl.last["f"], f, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(ctrl.last["a"], a, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(ctrl.state, z, rtol=1e-12, atol=1e-14)
        gravity = pin.computeGeneralizedGravity(model, data, q)
        tau_ref = hand_torque(scheme, J, Jdqd, B, n, gravity, R, Rd, qd, a, Fc, yd, sigma, per_axis)
        np.testing.assert_allclose(tau, tau_ref, rtol=1e-9, atol=1e-9 * np.abs(tau_ref).max())


def test_khatib_and_task_torques_coincide_when_the_force_is_the_feedforward(rng, robots):
    robot, model, fid = robots["panda"]
    q, qd, (J, _, _, _, p) = well_conditioned_states(rng, robot, model, fid, SPHERE, 1)[0]
    ctrls = [hybrid.Controller(robot, SPHERE, s, force_reference=15.0) for s in ("task", "khatib")]
    R, _ = oracle.spatial_frame(SPHERE, p, J[:3] @ qd, (0, 0, 1))
    Fc_ff = np.concatenate([R[2] * 15.0, np.zeros(3)])  # R^T Sigma F_d
    taus = [c(0.0, q, qd, Fc_ff) for c in ctrls]
    np.testing.assert_allclose(taus[0], taus[1], rtol=1e-11, atol=1e-11)


def test_closed_loop_task_acceleration_equals_the_loops_command(robots):
    """Exact model, UR5 in Pinocchio under zero-order hold with a spring pulling at the tip: at
    every sample the arm's task acceleration R v' + R' v equals the loops' a (decoupling)."""
    import pinocchio as pin

    robot, model, fid = robots["ur5"]
    data = model.createData()
    damping = np.array(robot.damping)
    ctrl = hybrid.Controller(robot, SPHERE, force_reference=5.0, velocity_reference=0.1, curvature=True,
                             torque_limit=None)  # decoupling holds for the torque the law asks for
    anchor = np.array([0.5, 0.2, 0.4])

    def wrench(q):
        pin.framesForwardKinematics(model, data, q)
        return np.concatenate([200.0 * (anchor - data.oMf[fid].translation), np.zeros(3)])

    def qdd(q, qd, tau):
        J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)
        return pin.aba(model, data, q, qd, tau + J.T @ wrench(q) - damping * qd)

    q, qd, h = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2]), np.zeros(6), 1e-3
    worst = 0.0
    for k in range(30):
        Fc = wrench(q)
        tau = ctrl(k * ctrl.sample_time, q, qd, Fc)
        J, Jdqd, _, _, p = pinocchio_terms(model, fid, q, qd, damping)
        v, vdot = J @ qd, J @ qdd(q, qd, tau) + Jdqd
        R, Rd = oracle.spatial_frame(SPHERE, p, v[:3], (0, 0, 1))
        worst = max(worst, np.abs(blockdiag(R) @ vdot + blockdiag(Rd) @ v - ctrl.last["a"]).max())
        for _ in range(10):  # RK4 on (q, q') with tau held
            k1 = (qd, qdd(q, qd, tau))
            k2 = (qd + h / 2 * k1[1], qdd(q + h / 2 * k1[0], qd + h / 2 * k1[1], tau))
            k3 = (qd + h / 2 * k2[1], qdd(q + h / 2 * k2[0], qd + h / 2 * k2[1], tau))
            k4 = (qd + h * k3[1], qdd(q + h * k3[0], qd + h * k3[1], tau))
            q = q + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            qd = qd + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    assert np.abs(ctrl.last["a"]).max() > 0.1  # the loops were busy
    assert worst < 1e-8


def test_desired_frame_at_the_tip_is_the_actual_frame(rng, robots):
    """With the desired point where the tip is, the rotated loops equal the actual-frame loops."""
    robot, model, fid = robots["ur5"]
    q, qd, (J, _, _, _, p) = well_conditioned_states(rng, robot, model, fid, SPHERE, 1)[0]

    def path(t):
        return p, J[:3] @ qd

    kw = dict(force_reference=8.0, velocity_reference=0.2, curvature=True)
    actual, desired = hybrid.Controller(robot, SPHERE, **kw), hybrid.Controller(robot, SPHERE, frame="desired",
                                                                                 path=path, **kw)
    Fc = rng.normal(0, 5, 6)
    np.testing.assert_allclose(desired(0.0, q, qd, Fc), actual(0.0, q, qd, Fc), rtol=1e-9, atol=1e-9)


def test_measure_and_state(robots):
    robot, model, fid = robots["ur5"]
    ctrl = hybrid.Controller(robot, SPHERE, timing_tolerance=None)  # a sample replayed
    q, qd = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2]), np.full(6, 0.1)
    Fc = np.array([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    m = ctrl.measure(q, qd, Fc)
    J, _, _, _, p = pinocchio_terms(model, fid, q, qd, np.zeros(6))
    R, _ = oracle.spatial_frame(SPHERE, p, J[:3] @ qd, (0, 0, 1))
    np.testing.assert_allclose(m.p, p, atol=1e-12)
    np.testing.assert_allclose(m.task_velocity, blockdiag(R) @ J @ qd, atol=1e-12)
    np.testing.assert_allclose(m.task_wrench, blockdiag(R) @ Fc, atol=1e-12)
    ctrl(0.0, q, qd, Fc)
    saved = ctrl.state
    first = ctrl(0.01, q, qd, Fc)
    ctrl.state = saved  # restoring the integrals replays the sample exactly
    np.testing.assert_array_equal(ctrl(0.01, q, qd, Fc), first)
    ctrl.reset()
    assert not ctrl.state.any()


@pytest.mark.parametrize("kwargs, words", [
    (dict(selection=("up",)), "not one of the task axes"),
    (dict(scheme="hybrid"), "unknown scheme"),
    (dict(force_reference={"t1": 3.0}), "not a force-controlled axis"),
    (dict(velocity_reference="fast"), "give a number"),
    (dict(gains={"n": 3}), "hybrid.Gains"),
    (dict(frame="desired"), "needs path"),
    (dict(sample_time=0.0), "positive sample period"),
    (dict(curvature=1), "True or False"),
    (dict(axes="planar"), None),  # a UR5 can serve a planar task: no error
])
def test_bad_settings_are_named(robots, kwargs, words):
    robot = robots["ur5"][0]
    if words is None:
        hybrid.Controller(robot, SPHERE, **kwargs)
        return
    with pytest.raises(hybrid.HybridError, match=words):
        hybrid.Controller(robot, SPHERE, **kwargs)


def test_bad_samples_are_named(robots):
    ctrl = hybrid.Controller(robots["ur5"][0], SPHERE)
    q, qd = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2]), np.zeros(6)
    with pytest.raises(hybrid.HybridError, match="Fc"):
        ctrl(0.0, q, qd, [1.0, 2.0, 3.0, 4.0])
    with pytest.raises(hybrid.NonFiniteError):
        ctrl(0.0, q * np.nan, qd, np.zeros(6))
    with pytest.raises(hybrid.SingularConfigurationError):
        ctrl(0.0, np.zeros(6), qd, np.zeros(6))  # the UR5 stretched out
    with pytest.raises(hybrid.HybridError, match="state must be"):
        ctrl.state = np.zeros(3)


def test_reference_controller_example_runs_and_is_the_law():
    """The controller block of docs/reference/controller.md runs as written; its torque is the 6-D law's
    for the loops' a."""
    import re
    from pathlib import Path

    page = Path(__file__).resolve().parent.parent / "docs" / "reference" / "controller.md"
    blocks = re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)
    block = next(b for b in blocks if "hybrid.Controller(" in b)
    ns: dict = {}
    exec(compile(block, str(page), "exec"), ns)
    ctrl, q, qdot, Fc = ns["ctrl"], ns["q"], ns["qdot"], ns["Fc"]
    law = hybrid.decoupling_law(ctrl.robot, ctrl.surface, curvature=True)
    np.testing.assert_allclose(ns["tau"], law.torque(q, qdot, ctrl.last["a"], Fc), rtol=1e-9, atol=1e-9)
    assert ns["res3"].metrics["contact_losses"] == 0 and np.isfinite(ns["m"]["rms_force_error_N"])


def test_default_references_follow_the_selection_and_bad_samples_are_named():
    arm, circle = hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2)
    for selection in ((), ("t1",), ("t1", "n")):
        hybrid.Controller(arm, circle, selection=selection)  # no reference given: no error
    ctrl = hybrid.Controller(arm, circle)
    q, qd, Fc = np.array([2.2, 1.9]), np.array([0.3, -0.4]), np.array([-8.0, 3.0])
    for t in (np.nan, np.inf, None, "a", [1.0, 2.0]):
        with pytest.raises(hybrid.HybridError, match="t = "):
            ctrl(t, q, qd, Fc)
    bad_ref = hybrid.Controller(arm, circle, velocity_reference=lambda t: "fast")
    with pytest.raises(hybrid.HybridError, match="reference"):
        bad_ref(0.0, q, qd, Fc)
    with pytest.raises(hybrid.HybridError, match="state must be"):
        ctrl.state = "abc"
    with pytest.raises(hybrid.HybridError, match="selection"):
        hybrid.Controller(arm, circle, selection=[np.array([1, 2])])


def test_the_first_touch_hands_over_without_a_jump(robots):
    """Out of contact the force axis approaches; at the touch its acceleration changes by (KPf + KIf T)
    times the force's change in that sample: the integral was kept where the force law agrees."""
    robot = robots["ur5"][0]
    g = hybrid.Gains()
    ctrl = hybrid.Controller(robot, SPHERE, gains=g, contact_loss=hybrid.ContactLoss(0.5, 0.02), torque_limit=None)
    q, qd = np.array([0.0, 0.63, -2.25, -1.0, -1.57, 0.0]), np.zeros(6)
    n = np.array([ctrl.measure(q, qd, np.eye(6)[k]).task_wrench[2] for k in range(3)])  # the normal, base axes
    k_n = ctrl.axes.index(2)
    forces = [0.0, 0.1, 0.3, 0.7]  # N along the normal: below the threshold, then touching
    a = []
    for k, f in enumerate(forces):
        ctrl(k * ctrl.sample_time, q, qd, np.concatenate([f * n, np.zeros(3)]))
        a.append(ctrl.last["a"][k_n])
    y = ctrl.last["y"][k_n]
    np.testing.assert_allclose(a[:3], -g.KDf * (y + 0.02), rtol=1e-12)
    jump = (g.KPf + g.KIf * ctrl.sample_time) * (forces[3] - forces[2])
    assert a[3] - a[2] == pytest.approx(jump, rel=1e-9)
