"""B(q) and n(q, q') of the generated C against Pinocchio's rigid-body algorithms."""

from __future__ import annotations

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
