"""B(q) and n(q, q') of the generated C against Pinocchio's rigid-body algorithms."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from conftest import random_arm

import hybrid

pin = pytest.importorskip("pinocchio")


def pinocchio_model(arm: hybrid.Arm):
    """The same arm built link by link: revolute z joints, links along x, gravity along -y."""
    model = pin.Model()
    parent = 0
    for i, (L_prev, m, d, inertia) in enumerate(
            [(0.0, arm.m1, arm.d1, arm.I1), (arm.L1, arm.m2, arm.d2, arm.I2)]):
        placement = pin.SE3(np.eye(3), np.array([L_prev, 0.0, 0.0]))
        parent = model.addJoint(parent, pin.JointModelRZ(), placement, f"joint{i + 1}")
        body = pin.Inertia(m, np.array([d, 0.0, 0.0]), np.diag([inertia, inertia, inertia]))
        model.appendBodyToJoint(parent, body, pin.SE3.Identity())
    model.gravity.linear = np.array([0.0, -arm.gravity, 0.0])
    return model


def test_inertia_and_bias_against_pinocchio(rng):
    for _ in range(100):
        arm = random_arm(rng)
        model = pinocchio_model(arm)
        data = model.createData()
        q, qd = rng.uniform(-np.pi, np.pi, 2), rng.normal(0, 2, 2)
        terms = hybrid.arm_terms(arm, q, qd)
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        n = pin.nonLinearEffects(model, data, q, qd) + np.array([arm.V1, arm.V2]) * qd
        np.testing.assert_allclose(terms["B"], B, rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(terms["n"], n, rtol=1e-10, atol=1e-10)


def _relative(got, want) -> float:
    """The largest difference, relative to the largest entry of ``want``."""
    return float(np.abs(np.asarray(got) - want).max() / np.abs(want).max())


def with_friction(robot, rng):
    """``robot`` with random viscosities, Coulomb frictions, offsets and smooth-sign speeds."""
    n = robot.n
    return dataclasses.replace(robot, damping=tuple(rng.uniform(0, 2, n)), coulomb=rng.uniform(0, 3, n),
                               offset=rng.normal(0, 1, n), coulomb_speed=rng.uniform(0.05, 2.0, n))


def friction(robot, qd):
    """The joints' friction torques from their formula, ``F_v q' + F_c tanh(q' / v_s) + tau_0``."""
    return (np.array(robot.damping) * qd + np.array(robot.coulomb) * np.tanh(qd / np.array(robot.coulomb_speed))
            + np.array(robot.offset))


def test_body_frame_algorithms_against_pinocchio(rng, robots):
    """Featherstone's algorithms in body coordinates (codegen.body_frame: RNEA with q'' and a force on
    the tip, CRBA, ABA) on the UR5 and the Panda with their real inertial parameters, against
    Pinocchio's rnea, crba and aba on the same URDF, their joint friction (viscous, Coulomb with a smooth
    sign, an offset; random) added as its formula; the base-axes RNEA and CRBA (codegen.rigid_body) too."""
    ca = pytest.importorskip("casadi")
    from hybrid.codegen import body_frame as bf
    from hybrid.codegen import rigid_body as rb

    for robot, model, fid in robots.values():
        n, data = robot.n, model.createData()
        robot = with_friction(robot, rng)
        q, qd, qdd, tau, F = (ca.SX.sym(name, size) for name, size in
                              (("q", n), ("qd", n), ("qdd", n), ("tau", n), ("F", 3)))
        params = ca.SX.sym("robot", len(robot.as_array()))
        tree = bf.link_transforms(robot.chain, q)
        f_ext = bf.tip_force(tree, F)
        frames = rb.forward_kinematics(robot.chain, q)
        f = ca.Function("f", [q, qd, qdd, tau, F, params],
                        [bf.rnea(tree, params, qd, qdd, f_ext), bf.crba(tree, params),
                         bf.aba(tree, params, qd, tau, f_ext), bf.tip_position(tree),
                         bf.tip_velocity(tree, bf.link_velocities(tree, qd)),
                         rb.rnea(robot.chain, frames, params, qd, qdd), rb.crba(robot.chain, frames, params)])
        for _ in range(50):
            x = (rng.uniform(robot.limits.lower, robot.limits.upper), rng.normal(0, 1, n), rng.normal(0, 3, n),
                 rng.normal(0, 20, n), rng.normal(0, 20, 3))
            inverse, B, forward, r, rd, inverse_base, B_base = (np.array(v).squeeze() for v in f(*x, robot.as_array()))
            pin.forwardKinematics(model, data, x[0], x[1])
            pin.updateFramePlacements(model, data)
            J = pin.computeFrameJacobian(model, data, x[0], fid, pin.LOCAL_WORLD_ALIGNED)[:3]
            assert _relative(r, data.oMf[fid].translation) < 1e-14
            assert _relative(rd, J @ x[1]) < 1e-13
            want = pin.rnea(model, data, x[0], x[1], x[2]) + friction(robot, x[1])
            assert _relative(inverse, want - J.T @ x[4]) < 1e-13
            assert _relative(inverse_base, want) < 1e-13
            want = pin.crba(model, data, x[0])
            want = np.triu(want) + np.triu(want, 1).T
            assert _relative(B, want) < 1e-13
            assert _relative(B_base, want) < 1e-13
            want = pin.aba(model, data, x[0], x[1], x[3] + J.T @ x[4] - friction(robot, x[1]))
            assert _relative(forward, want) < 1e-12


def test_spatial_plant_rhs_against_pinocchio_aba(rng, robots):
    """The 3-D plant's state derivative (conventions §10, the generated C) on random states of the UR5
    and the Panda with their real parameters: the joint accelerations against Pinocchio's ABA on the
    same URDF under tau + J_p^T F_c - joint friction, the sensor tip's from its forces written out here."""
    from hybrid.native import units

    exp = hybrid.tracing_experiment()
    sphere, plant = exp.surface, exp.plant_array()
    m_s, K_s, D_s, k_e, d_e, gamma, v_eps = plant
    center, radius = np.array(sphere.center), sphere.radius
    for robot, model, fid in robots.values():
        n, data = robot.n, model.createData()
        robot = with_friction(robot, rng)
        g = np.array(robot.gravity)
        rhs = units.plant_unit(robot.chain, robot.name, sphere.spec()).function("plant_rhs")
        contacts = 0
        for _ in range(200):
            q, qd, tau = rng.uniform(robot.limits.lower, robot.limits.upper), rng.normal(0, 1, n), rng.normal(0, 20, n)
            # the sensor tip within a few millimetres of the sphere: in contact about half of the time
            u = rng.normal(size=3)
            s = center + (radius + rng.uniform(-3e-3, 3e-3)) * u / np.linalg.norm(u)
            sd = rng.normal(0, 0.3, 3)
            xdot = rhs(np.concatenate([q, qd, s, sd]), tau, robot.as_array(), plant, sphere.as_array())["xdot"]

            pin.forwardKinematics(model, data, q, qd)
            pin.updateFramePlacements(model, data)
            J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)[:3]
            Fc = K_s * (s - data.oMf[fid].translation) + D_s * (sd - J @ qd)
            qdd = pin.aba(model, data, q, qd, tau + J.T @ Fc - friction(robot, qd))
            normal = (s - center) / np.linalg.norm(s - center)
            delta = radius - np.linalg.norm(s - center)
            N = max(0.0, k_e * delta - d_e * normal @ sd) if delta > 0 else 0.0
            slide = sd - (normal @ sd) * normal
            w = np.sqrt(slide @ slide + (1e-9 * v_eps) ** 2)
            sdd = (N * normal - gamma * N * np.tanh(w / v_eps) / w * slide - Fc) / m_s + g
            contacts += N > 0

            np.testing.assert_array_equal(xdot[:n], qd)
            assert _relative(xdot[n:2 * n], qdd) < 1e-12
            np.testing.assert_array_equal(xdot[2 * n:2 * n + 3], sd)
            assert _relative(xdot[2 * n + 3:], sdd) < 1e-12
        assert 50 < contacts < 150
