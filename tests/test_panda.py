"""The shipped Panda, and the posture task in the null space of a redundant arm's task."""

from __future__ import annotations

from dataclasses import replace

import casadi as ca
import numpy as np
import pytest
from conftest import (
    PANDA,
    UR5,
    example_robot,
    pinocchio_panda,
    task_acceleration_gap,
    well_conditioned_states,
)
from hybrid.codegen import controller_step, robot_unit

import hybrid
from hybrid.models.chain_terms import robot_terms
from hybrid.models.shipped import PANDA_URDF, UR5_URDF
from hybrid.native import units
from hybrid.plants.rigid_body import RigidBodyPlant
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import run
from hybrid.spec.controller_step import CONTROLLER_STEP

EXACT = dict(model_error=0.0, viscous_compensation=1.0, contact=hybrid.Contact(friction=0.0))
SPHERE = hybrid.Sphere((0.4, 0.1, 0.3), 0.15)
#: the Panda's usual ready pose (within its joint limits)
READY = np.array([0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785])




def test_the_shipped_panda_is_example_robot_datas():
    assert PANDA_URDF.read_bytes() == example_robot(PANDA[0]).read_bytes()
    panda = hybrid.panda()
    assert panda.n == 7 and panda.joint_names == tuple(f"panda_joint{i}" for i in range(1, 8))
    assert panda == hybrid.Robot.from_urdf(example_robot(PANDA[0]), tip=PANDA[1])  # fingers off the chain: at 0
    assert hybrid.ur5() == hybrid.Robot.from_urdf(UR5_URDF, tip=UR5[1])


def test_the_shipped_urdfs_are_package_data():
    """Installed with the package (``hybrid.data``'s files), with their licences."""
    from importlib.resources import files

    data = files("hybrid.data")
    notice = (data / "NOTICE.md").read_text()
    for name in ("panda.urdf", "ur5_robot.urdf"):
        assert (data / name).is_file() and f"`{name}`" in notice
    assert "Apache License" in notice and "BSD 2-Clause License" in notice


# ----------------------------------------------------------------------------- the posture task




@pytest.fixture(scope="module")
def at_rest():
    """The Panda pressing 10 N on the sphere at rest (no speed reference), exact model, and a rest
    posture on its self-motion (the same tip pose, 0.4 rad away along the null space)."""
    exp = hybrid.tracing_experiment(robot=hybrid.panda(), **EXACT, F_d=10.0, v_d=0.0, curvature=True,
                                    duration=1.5)
    x0 = exp.initial_state()
    q0 = x0[:7]
    terms = robot_terms(exp.robot, q0, np.zeros(7))
    null = np.linalg.svd(terms["J"])[2][-1]
    null *= -np.sign(null[3])  # the SVD's sign is arbitrary: joint 4 decreasing, the same run everywhere
    q_rest = exp.robot.inverse_kinematics(terms["r"], terms["rotation"], q0=q0 + 0.4 * null)
    return exp, x0, q_rest


def posture_controller(exp, posture):
    """The experiment's own controller (:meth:`hybrid.Experiment.build_controller`) with ``posture``."""
    return replace(exp, posture=posture).build_controller()


def run_checked(exp, x0, posture, q_rest):
    """A run in which, at every sample, Pinocchio's arm under the controller's torque and the sensor's
    force gives the task acceleration ``R v' + R' v``; returns its largest difference from the loops'
    ``a`` and ``|q_rest - q|`` per sample."""
    panda = pinocchio_panda()
    ctrl = posture_controller(exp, posture)
    worst, error = [0.0], []

    def controller(t, q, qdot, Fc):
        tau = ctrl(t, q, qdot, Fc)
        worst[0] = max(worst[0], task_acceleration_gap(panda, exp, ctrl, q, qdot, Fc, tau)[0])
        error.append(np.linalg.norm(q_rest - q))
        return tau

    run(exp, RigidBodyPlant(exp), controller, x0)
    assert len(error) == exp.n_samples
    return worst[0], np.array(error)


def test_posture_keeps_the_task_acceleration_and_brings_the_null_space_to_rest(at_rest):
    """Exact model, 7 joints, six task axes: the posture's torque moves the one free direction only.
    The task acceleration is the loops' ``a`` at every sample, and the rest posture, on the start
    pose's self-motion, is reached as the critically damped PD reaches it (5 rad/s: 0.4 rad to 2e-3
    in 1.5 s). Without it the null space falls under gravity (the law cancels it in the task only)."""
    exp, x0, q_rest = at_rest
    worst, error = run_checked(exp, x0, hybrid.Posture(q_rest, stiffness=25.0, damping=10.0), q_rest)
    assert worst < 1e-7
    assert error[0] > 0.35
    t = np.arange(len(error)) * exp.sample_time
    pd = error[0] * (1 + 5 * t) * np.exp(-5 * t)  # the critically damped PD from rest
    assert np.abs(error - pd).max() < 0.1 * error[0]
    assert error[-1] < 0.01 * error[0]
    worst_off, error_off = run_checked(exp, x0, None, q_rest)
    assert worst_off < 1e-7
    assert error_off.max() > 2.0  # the null space falls: radians away


def test_the_compiled_loop_runs_the_posture_task_as_the_python_runner_does(at_rest):
    """Two postures in one compiled call (one build: the posture's numbers are run-time inputs), each
    against the Python runner with the same controller."""
    exp, x0, q_rest = at_rest
    exps = [replace(exp, duration=0.5, posture=hybrid.Posture(q_rest, k, 2 * np.sqrt(k))) for k in (25.0, 64.0)]
    prepared = [closed_loop.prepare(e, x0) for e in exps]
    assert all(p is not None and p.loop is prepared[0].loop for p in prepared)
    outcomes = closed_loop.run(prepared, record=True)
    for e, got in zip(exps, outcomes):
        want = run(e, RigidBodyPlant(e), e.build_controller(), x0)
        assert got.status == 0
        assert np.abs((got.states - want.state) / (np.abs(want.state).max(axis=0) + 1e-3)).max() < 1e-7
    ends = [np.linalg.norm(q_rest - got.states[-1, :7]) for got in outcomes]
    assert ends[1] < ends[0] < 0.5 * np.linalg.norm(q_rest - x0[:7])  # stiffer: nearer the rest posture


def test_posture_numbers_never_recompile_and_off_takes_the_law_without_it(robots):
    robot = robots["panda"][0]
    q = np.array([0.1, -0.6, 0.2, -2.2, 0.1, 1.7, 0.6])
    off = hybrid.Controller(robot, SPHERE)
    on = [hybrid.Controller(robot, SPHERE, posture=hybrid.Posture(q, k, 1.0)) for k in (1.0, 9.0)]
    assert off.step_variant()["step"] == "controller_step"
    assert on[0].step_variant()["step"] == "controller_posture_step"
    qd, Fc = np.full(7, 0.2), np.array([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    taus = [c(0.0, q + 0.1, qd, Fc) for c in (off, *on)]
    assert all(c._step.unit is off._step.unit for c in on)  # (a controller builds its step at its first sample)
    assert np.abs(taus[1] - taus[0]).max() > 1e-3 and np.abs(taus[2] - taus[1]).max() > 1e-3


def test_posture_off_is_bitwise_the_law_without_a_null_space_torque(rng, robots, monkeypatch):
    """Without a posture the torque is, bit for bit, that of the posture step generated with ``tau0``
    identically 0: the law's own code. (Zero posture numbers in a step that computes ``tau0`` would
    agree only within rounding: the compiler's fused multiply-adds follow the code around them.)"""
    robot, model, fid = robots["panda"]
    spec, axes = SPHERE.spec(), tuple(range(6))
    prefix = "hybrid_test_zero_tau0_controller"

    def make():
        with monkeypatch.context() as patch:
            patch.setattr(controller_step, "posture_torque", lambda chain, *args: ca.SX.zeros(chain.n, 1))
            return robot_unit.build_controller_unit(robot.chain, spec, axes, prefix,
                                                    units.robot_info(robot.chain, robot.name), {})

    zero_tau0 = units.compiled(prefix, {"chain": units.chain_key(robot.chain), "surface": spec.key(),
                                        "tau0": "zero"}, make).function("controller_posture_step")
    for scheme in ("task", "khatib"):
        ctrl = hybrid.Controller(robot, SPHERE, scheme, force_reference=hybrid.Step(10.0, 20.0, 0.05),
                                 velocity_reference=0.1, curvature=True)
        last = np.zeros(robot.n + 1)  # the last torque and whether there is one (the rate limit's)
        for k, (q, qd, _) in enumerate(well_conditioned_states(rng, robot, model, fid, SPHERE, 8)):
            Fc = rng.normal(0, 10, 6)
            z = ctrl.state.ravel()
            tau = ctrl(k * 0.01, q, qd, Fc)
            # every per-sample input zero (sizes as the step declares them) but the sample's own
            sizes = dict(zero_tau0.inputs)
            sample = {**{n: np.zeros(sizes[n]) for n in CONTROLLER_STEP.per_sample}, "q": q, "qd": qd, "Fc": Fc,
                      "integrals": z, "last_torque": last, "t": np.array([k * 0.01])}
            want = zero_tau0(*(sample[n] for n in CONTROLLER_STEP.per_sample), *ctrl.step_inputs().values(),
                             singular_tol=ctrl.singular_tol)["tau"]
            assert tau.tobytes() == want.tobytes()
            last = np.append(tau, 1.0)


def test_a_task_without_null_space_or_a_scheme_without_projection_refuses_a_posture(robots):
    ur5, panda = robots["ur5"][0], robots["panda"][0]
    with pytest.raises(hybrid.HybridError, match="null space, and this task has none: 6 task axes"):
        hybrid.Controller(ur5, SPHERE, posture=hybrid.Posture(np.zeros(6)))
    # three position axes leave the UR5 three free directions: accepted
    hybrid.Controller(ur5, SPHERE, axes="position", posture=hybrid.Posture(np.zeros(6)))
    for scheme in ("raibert_craig", "fisher_mujtaba"):
        with pytest.raises(hybrid.HybridError, match="without a null-space projection"):
            hybrid.Controller(panda, SPHERE, scheme, posture=hybrid.Posture(READY))


@pytest.mark.parametrize("kwargs, words", [
    (dict(q_rest=np.zeros(6)), "has 6 joint positions; the arm has 7"),
    (dict(q_rest=np.zeros(7)), "outside the joint limits: panda_joint4 = 0"),
    (dict(q_rest=np.full(7, np.nan)), "one finite joint position per joint"),
    (dict(q_rest=READY, stiffness=-1.0), "stiffness = -1.0; give one finite number >= 0"),
    (dict(q_rest=READY, damping=np.ones(3)), "or 7 of them"),
    (dict(q_rest="rest"), "one finite joint position"),
])
def test_bad_postures_are_named(robots, kwargs, words):
    with pytest.raises(hybrid.HybridError, match=words):
        hybrid.Controller(robots["panda"][0], SPHERE, posture=hybrid.Posture(**kwargs))


def test_posture_takes_one_gain_or_one_per_joint():
    p = hybrid.Posture([0.0, 0.1], stiffness=[4.0, 9.0])
    assert p.stiffness == (4.0, 9.0) and p.damping == 10.0
    np.testing.assert_array_equal(p.as_array(), [0.0, 0.1, 4.0, 9.0, 10.0, 10.0])
    with pytest.raises(hybrid.HybridError, match="posture = "):
        hybrid.Controller(hybrid.panda(), SPHERE, posture=np.zeros(7))
