"""Any serial arm from its URDF: terms of the generated C against Pinocchio, finite differences and physics."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from conftest import PANDA, UR5, example_robot, random_arm

import hybrid

pin = pytest.importorskip("pinocchio")

DATA = __import__("pathlib").Path(__file__).parent / "data"
SLIDER = (DATA / "slider_arm.urdf", "tool")
FINGERS = ("panda_finger_joint1", "panda_finger_joint2")


def urdf_path(spec):
    path, tip = spec
    return (path if not isinstance(path, str) else example_robot(path)), tip


def pinocchio_model(path, locked: dict, gravity):
    """Pinocchio's own URDF parser and reduction: an independent reading of the same file."""
    model = pin.buildModelFromUrdf(str(path))
    if locked:
        q_ref = pin.neutral(model)
        for name, value in locked.items():
            jid = model.getJointId(name)
            q_ref[model.joints[jid].idx_q] = value
        model = pin.buildReducedModel(model, [model.getJointId(n) for n in locked], q_ref)
    model.gravity.linear = np.asarray(gravity, float)
    return model


def pin_q(model, q):
    """Pinocchio's configuration of joint positions ``q`` (a continuous joint stores cos, sin)."""
    return pin.integrate(model, pin.neutral(model), np.asarray(q, float))


def pinocchio_terms(model, fid, q, qd, damping):
    data = model.createData()
    q = pin_q(model, q)
    pin.forwardKinematics(model, data, q, qd, np.zeros_like(qd))
    pin.updateFramePlacements(model, data)
    B = pin.crba(model, data, q)
    return {
        "r": data.oMf[fid].translation.copy(), "rotation": data.oMf[fid].rotation.copy(),
        "J": pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED),
        "Jdot_qdot": pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector.copy(),
        "B": np.triu(B) + np.triu(B, 1).T,
        "n": pin.nonLinearEffects(model, data, q, qd) + damping * qd,
    }


def random_joint_states(rng, robot, N):
    lo = np.where(np.isfinite(robot.limits.lower), robot.limits.lower, -np.pi)
    hi = np.where(np.isfinite(robot.limits.upper), robot.limits.upper, np.pi)
    return rng.uniform(lo, hi, (N, robot.n)), rng.normal(0, 1.5, (N, robot.n))


CASES = [
    pytest.param(UR5, {}, id="ur5"),
    pytest.param(PANDA, dict.fromkeys(FINGERS, 0.0), id="panda-fingers-at-0"),
    pytest.param(PANDA, dict.fromkeys(FINGERS, 0.03), id="panda-fingers-at-0.03"),
    pytest.param(SLIDER, {"gripper": 0.02}, id="slider-prismatic"),
]


@pytest.mark.parametrize("spec, locked", CASES)
@pytest.mark.parametrize("gravity", [(0.0, 0.0, -9.81), (0.0, 0.0, 0.0), (1.2, -3.4, -8.0)])
def test_terms_match_pinocchio(rng, spec, locked, gravity):
    path, tip = urdf_path(spec)
    # locking the Panda's fingers at 0 is what Robot.from_urdf does on its own (they are off the chain)
    robot = hybrid.Robot.from_urdf(path, tip=tip, gravity=gravity,
                                   locked={k: v for k, v in locked.items() if v} or None)
    robot = dataclasses.replace(robot, damping=tuple(rng.uniform(0, 2, robot.n)))  # viscosity on
    model = pinocchio_model(path, locked, gravity)
    assert model.nv == robot.n
    assert [model.names[i] for i in range(1, model.njoints)] == list(robot.joint_names)
    fid = model.getFrameId(tip)
    N = 1500
    q, qd = random_joint_states(rng, robot, N)
    ours = hybrid.arm_terms(robot, q, qd)  # one batched native call
    damping = np.array(robot.damping)
    worst = {}
    for i in range(N):
        ref = pinocchio_terms(model, fid, q[i], qd[i], damping)
        for key, value in ref.items():
            scale = max(np.abs(value).max(), 1.0)
            worst[key] = max(worst.get(key, 0.0), np.abs(ours[key][i] - value).max() / scale)
    assert max(worst.values()) <= 1e-10, worst


@pytest.mark.parametrize("spec", [UR5, PANDA, SLIDER], ids=["ur5", "panda", "slider"])
def test_single_state_equals_batch_and_shapes(rng, spec):
    robot = hybrid.Robot.from_urdf(*urdf_path(spec))
    q, qd = random_joint_states(rng, robot, 4)
    batch = hybrid.arm_terms(robot, q, qd)
    one = hybrid.arm_terms(robot, q[2], qd[2])
    n = robot.n
    shapes = {"r": (3,), "rotation": (3, 3), "J": (6, n), "Jdot_qdot": (6,), "B": (n, n), "n": (n,)}
    assert {k: v.shape for k, v in one.items()} == shapes
    for k in shapes:
        np.testing.assert_array_equal(one[k], batch[k][2])


@pytest.mark.parametrize("spec", [UR5, PANDA, SLIDER], ids=["ur5", "panda", "slider"])
def test_jdot_qdot_by_finite_differences_and_B_positive_definite(rng, spec):
    robot = hybrid.Robot.from_urdf(*urdf_path(spec))
    q, qd = random_joint_states(rng, robot, 50)
    h = 1e-6
    for qi, qdi in zip(q, qd):
        plus = hybrid.arm_terms(robot, qi + h * qdi, qdi)["J"]
        minus = hybrid.arm_terms(robot, qi - h * qdi, qdi)["J"]
        fd = (plus - minus) @ qdi / (2 * h)
        terms = hybrid.arm_terms(robot, qi, qdi)
        np.testing.assert_allclose(terms["Jdot_qdot"], fd, rtol=1e-6, atol=1e-6)
        # rotation is orthonormal, B symmetric positive definite
        np.testing.assert_allclose(terms["rotation"] @ terms["rotation"].T, np.eye(3), atol=1e-12)
        assert np.array_equal(terms["B"], terms["B"].T)
        assert np.linalg.eigvalsh(terms["B"])[0] > 0


def test_planar_arm_through_the_recursive_path_equals_the_closed_form(rng):
    # link lengths are compiled in (one build per geometry); masses, inertias, viscosity, gravity are not
    for base in (hybrid.paper_arm(), random_arm(rng), random_arm(rng)):
        for _ in range(15):
            arm = dataclasses.replace(random_arm(rng), L1=base.L1, L2=base.L2)
            robot = hybrid.Robot.planar(arm)
            q, qd = rng.uniform(-np.pi, np.pi, 2), rng.normal(0, 2, 2)
            _compare_planar(arm, robot, q, qd)


def _compare_planar(arm, robot, q, qd):
    """The recursive terms of the planar chain equal the closed form (in-plane rows of J)."""
    closed = hybrid.arm_terms(arm, q, qd)
    rec = hybrid.arm_terms(robot, q, qd)
    for key in ("B", "n"):
        np.testing.assert_allclose(rec[key], closed[key], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rec["r"][:2], closed["r"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rec["J"][:2], closed["J"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rec["Jdot_qdot"][:2], closed["Jdot_qdot"], rtol=1e-12, atol=1e-12)
    # planar: no z motion, rotation about z only
    assert np.abs(rec["J"][2:5]).max() == 0 and np.allclose(rec["J"][5], 1.0)


@pytest.mark.parametrize("spec", [UR5, SLIDER], ids=["ur5", "slider"])
def test_inverse_and_forward_dynamics(rng, spec):
    path, tip = urdf_path(spec)
    robot = hybrid.Robot.from_urdf(path, tip, locked={"gripper": 0.0} if spec is SLIDER else None)
    unit = robot.unit
    model = pinocchio_model(path, {"gripper": 0.0} if spec is SLIDER else {}, robot.gravity)
    data = model.createData()
    p = robot.as_array()
    damping = np.array(robot.damping)
    for _ in range(100):
        q, qd = (x[0] for x in random_joint_states(rng, robot, 1))
        qdd = rng.normal(0, 2, robot.n)
        tau = unit.function("inverse_dynamics")(q, qd, qdd, p)["tau"]
        qp = pin_q(model, q)
        np.testing.assert_allclose(tau, pin.rnea(model, data, qp, qd, qdd) + damping * qd, rtol=1e-10, atol=1e-10)
        back = unit.function("forward_dynamics")(q, qd, tau, p)["qdd"]
        np.testing.assert_allclose(back, qdd, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(back, pin.aba(model, data, qp, qd, tau - damping * qd), rtol=1e-9, atol=1e-9)


def test_inertial_parameters_are_run_time_inputs(rng):
    """B is linear in the inertial parameters; a model error or a changed link never regenerates."""
    path, tip = urdf_path(UR5)
    robot = hybrid.Robot.from_urdf(path, tip, gravity=(0, 0, 0))
    heavy = robot.with_model_error(0.25, viscous_compensation=0.5)
    assert heavy.unit is robot.unit  # the same compiled code
    q, qd = random_joint_states(rng, robot, 20)
    a, b = hybrid.arm_terms(robot, q, qd), hybrid.arm_terms(heavy, q, qd)
    np.testing.assert_allclose(b["B"], 1.25 * a["B"], rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(b["n"], 1.25 * a["n"], rtol=1e-10, atol=1e-12)  # no damping in the UR5 file
    # replace one link's parameters and compare with Pinocchio given the same link
    inertia = np.array([[0.02, 0.001, 0.0], [0.001, 0.03, 0.002], [0.0, 0.002, 0.04]])
    changed = robot.with_link("elbow_joint", mass=3.0, com=(0.01, 0.02, 0.2), inertia=inertia)
    model = pinocchio_model(path, {}, (0, 0, 0))
    jid = model.getJointId("elbow_joint")
    model.inertias[jid] = pin.Inertia(3.0, np.array([0.01, 0.02, 0.2]), inertia)
    fid = model.getFrameId(tip)
    ours = hybrid.arm_terms(changed, q, qd)
    for i in range(len(q)):
        ref = pinocchio_terms(model, fid, q[i], qd[i], np.zeros(robot.n))
        np.testing.assert_allclose(ours["B"][i], ref["B"], rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(ours["n"][i], ref["n"], rtol=1e-10, atol=1e-10)


def test_robot_description(rng):
    path, tip = urdf_path(PANDA)
    robot = hybrid.Robot.from_urdf(path, tip)
    assert robot.n == 7 and robot.joint_names == tuple(f"panda_joint{i}" for i in range(1, 8))
    model = pin.buildModelFromUrdf(str(path))
    np.testing.assert_array_equal(robot.limits.lower, model.lowerPositionLimit[:7])
    np.testing.assert_array_equal(robot.limits.upper, model.upperPositionLimit[:7])
    np.testing.assert_array_equal(robot.damping, model.damping[:7])
    np.testing.assert_array_equal(robot.coulomb, model.friction[:7])
    assert len(robot.as_array()) == len(robot.parameter_names()) == 14 * 7 + 3
    slider = hybrid.Robot.from_urdf(DATA / "slider_arm.urdf", "tool")
    assert slider.joint_names == ("slide", "shoulder", "elbow")  # the gripper is off the chain
    assert slider.chain.joints[0].kind == "prismatic" and np.isinf(slider.limits.upper[2])


def test_joint_friction_is_checked_and_kept():
    """Coulomb friction, offsets and smooth-sign speeds: one per joint, physical, refused otherwise (and on the
    planar arm's closed form); kept through the model error's share, a link change and a save and read."""
    import dataclasses

    from hybrid.experiments.serialisation import robot_from_dict, robot_to_dict

    robot = hybrid.ur5()
    assert robot.coulomb == (0.0,) * 6 and robot.offset == (0.0,) * 6
    rough = dataclasses.replace(robot, coulomb=[1.0] * 6, offset=np.arange(6.0), coulomb_speed=[0.1] * 6)
    np.testing.assert_allclose(rough.rest_viscosity, np.array(robot.damping) + 10.0)
    assert robot_from_dict(robot_to_dict(rough)) == rough
    assert robot_to_dict(robot)["digest"] == robot_to_dict(dataclasses.replace(robot, coulomb=(0.0,) * 6))["digest"]
    model = rough.with_model_error(0.0, 0.5)
    assert model.coulomb == (0.5,) * 6 and model.offset == tuple(np.arange(6.0) * 0.5)
    assert rough.with_link(robot.joint_names[1], coulomb=2.0).coulomb[1] == 2.0
    for bad, match in (({"coulomb": [-1.0] * 6}, "Coulomb friction >= 0"), ({"coulomb": [1.0] * 5}, "coulomb"),
                       ({"coulomb_speed": [0.0] * 6}, "speed > 0"), ({"offset": [np.nan] * 6}, "offset")):
        with pytest.raises(hybrid.HybridError, match=match):
            dataclasses.replace(robot, **bad)
    with pytest.raises(hybrid.HybridError, match="closed form has joint viscosity only"):
        dataclasses.replace(hybrid.Robot.planar(hybrid.paper_arm()), coulomb=(1.0, 1.0))


def test_an_integration_step_too_long_for_the_coulomb_friction_is_refused():
    """About rest the smooth sign is a viscosity F_c / v_s: a sharp one on the UR5's wrist is a mode faster than
    the integration step resolves, refused saying the step or the speed to use; a gentler one runs."""
    import dataclasses

    sharp = dataclasses.replace(hybrid.ur5(), coulomb=(2.0,) * 6, coulomb_speed=(1e-4,) * 6)
    with pytest.raises(hybrid.HybridError, match="too large for the joints' Coulomb friction"):
        hybrid.tracing_experiment(robot=sharp, controller_robot=sharp)
    gentle = dataclasses.replace(sharp, coulomb_speed=(0.2,) * 6)
    hybrid.tracing_experiment(robot=gentle, controller_robot=gentle)
    # a viscosity alone as fast (given in the wrong units) is refused likewise, before its run turns NaN
    thick = dataclasses.replace(hybrid.ur5(), damping=(1e4,) * 6)
    with pytest.raises(hybrid.HybridError, match=r"too large for the joints' viscosity: its fastest mode is .* check "
                                                 r"the Robot's damping"):
        hybrid.tracing_experiment(robot=thick, controller_robot=thick)
