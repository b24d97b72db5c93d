"""The body-frame algorithms (codegen.body_frame) on chains the shipped arms do not have: joint axes along
negative unit vectors, joint origins turned by a rounded quarter turn about the axis, general rotations
and axes, prismatic joints. Checked against the base-axes algorithms (codegen.rigid_body), an
independent derivation (Pinocchio checks both on the UR5 and the Panda: tests/test_pinocchio.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hybrid.spec.chain import Chain, Joint, parameter_names, rotation_rpy

ca = pytest.importorskip("casadi")
bf = pytest.importorskip("hybrid.codegen.body_frame")
rb = pytest.importorskip("hybrid.codegen.rigid_body")

#: a quarter turn as a URDF may round it (cos of it is 9.5e-11, not snapped to 0)
QUARTER = 1.5707963267


def _chain(rng, kinds, axes, rpys) -> Chain:
    joints = tuple(Joint(f"j{i}", kind, rotation_rpy(*rpy), tuple(rng.normal(0, 0.2, 3)), axis)
                   for i, (kind, axis, rpy) in enumerate(zip(kinds, axes, rpys)))
    return Chain(joints, rotation_rpy(0.1, 0.2, 0.3), (0.01, 0.02, 0.1))


def _chains(rng) -> dict[str, Chain]:
    unit = [(0, -1.0, 0), (0, 0, 1.0), (-1.0, 0, 0), (0, 1.0, 0), (0, 0, -1.0), (1.0, 0, 0)]
    general = [tuple(v / np.linalg.norm(v)) for v in rng.normal(size=(6, 3))]
    return {
        "unit axes, rounded turns": _chain(rng, ["revolute"] * 6, unit, [
            (0, QUARTER, 0), (0, 0, QUARTER), (QUARTER, 0, 0), (0, -QUARTER, 0), (0.3, 0, 0), (0, 0, -QUARTER)]),
        "general axes and rotations, prismatic joints": _chain(
            rng, ["revolute", "prismatic", "revolute", "revolute", "prismatic", "revolute"], general,
            [tuple(rng.normal(size=3)) for _ in range(6)]),
        "unit axes, a prismatic joint": _chain(rng, ["revolute", "revolute", "prismatic", "revolute"],
                                               unit[:4], [(0, 0, 0), (QUARTER, 0, 0), (0, 0, 0), (0, QUARTER, 0)]),
    }


@pytest.mark.parametrize("axis", [(1.0, 0, 0), (0, -1.0, 0), (0, 0, 1.0)])
@pytest.mark.parametrize("turns", [(0, 0, 1), (1, 0, 0), (0, 1, 0), (0, -1, 0), (2, 1, 0), (1, 1, 1)])
def test_split_rotation_takes_the_turn_about_the_axis_out(axis, turns):
    """``R_T = P Rot(axis, theta)`` (to rounding) always; a rotation about the joint axis alone becomes a
    signed permutation ``P`` and the small turn left (a rounded quarter turn's 9.5e-11 rad); a general
    rotation is left whole."""
    R = np.array(rotation_rpy(*(QUARTER * t for t in turns)))
    P, theta = rb.split_rotation(R, axis)
    assert np.abs(P @ rb._turn(np.array(axis), theta) - R).max() < 1e-15
    k = int(np.argmax(np.abs(axis)))
    if sum(t != 0 for t in turns) == 1 and turns[k] != 0:  # rpy's roll, pitch, yaw turn about x, y, z
        assert set(np.unique(P)) <= {-1.0, 0.0, 1.0} and 0 < abs(theta) < 1e-9
    P, theta = rb.split_rotation(rotation_rpy(0.3, 0.2, 0.1), axis)
    assert theta == 0.0 and np.allclose(P, rotation_rpy(0.3, 0.2, 0.1))


def test_body_frame_dynamics_equal_the_base_axes_algorithms():
    rng = np.random.default_rng(5)
    for name, chain in _chains(rng).items():
        n = chain.n
        q, qd, qdd = (ca.SX.sym(s, n) for s in ("q", "qd", "qdd"))
        params, F = ca.SX.sym("robot", len(parameter_names(chain))), ca.SX.sym("F", 6)
        frames = rb.forward_kinematics(chain, q)
        J = rb.frame_jacobian(frames)
        tree = bf.link_transforms(chain, q)
        f_ext = bf.tip_force(tree, F[:3], F[3:])
        tau = rb.rnea(chain, frames, params, qd, qdd) - J.T @ F
        f = ca.Function("f", [q, qd, qdd, params, F], [
            rb.crba(chain, frames, params), bf.crba(tree, params), tau, bf.rnea(tree, params, qd, qdd, f_ext),
            frames.tip_p, bf.tip_position(tree), J[:3, :] @ qd, bf.tip_velocity(tree, bf.link_velocities(tree, qd)),
            bf.aba(tree, params, qd, tau, f_ext)])
        for _ in range(20):
            values = []
            for _ in range(n):
                A = rng.normal(size=(3, 3))
                Ic = A @ A.T + 0.1 * np.eye(3)
                values += [rng.uniform(0.5, 3), *rng.normal(0, 0.1, 3), *Ic[np.triu_indices(3)]]
            # viscosities, Coulomb frictions, offsets, smooth-sign speeds; gravity
            values += [*rng.uniform(0, 1, n), *rng.uniform(0, 2, n), *rng.normal(0, 1, n), *rng.uniform(0.05, 1, n),
                       0.1, -0.3, -9.81]
            x = (rng.uniform(-2, 2, n), rng.normal(size=n), rng.normal(size=n), values, rng.normal(size=6))
            out = [np.array(v).ravel() for v in f(*x)]
            for k, (want, got) in enumerate(zip(out[0:8:2], out[1:8:2])):
                assert np.abs(got - want).max() < 1e-13 * np.abs(want).max(), (name, k)
            # the ABA inverts the RNEA
            assert np.abs(out[8] - x[2]).max() < 1e-12 * np.abs(x[2]).max(), name


def test_tip_kinematics_from_the_link_transforms_equal_the_base_axes_ones():
    """The tip's placement, ``J``, ``J q'`` and ``J' q'`` from the body-frame transforms (codegen.tip_kinematics)
    equal the base-axes forward kinematics' (codegen.rigid_body) to rounding."""
    tk = pytest.importorskip("hybrid.codegen.tip_kinematics")
    rng = np.random.default_rng(7)
    for name, chain in _chains(rng).items():
        n = chain.n
        q, qd = ca.SX.sym("q", n), ca.SX.sym("qd", n)
        frames, tree = rb.forward_kinematics(chain, q), bf.link_transforms(chain, q)
        placed, vs = tk.placements(tree), bf.link_velocities(tree, qd)
        J = rb.frame_jacobian(frames)
        f = ca.Function("f", [q, qd], [
            frames.tip_p, placed.tip_p, frames.tip_R, placed.tip_R, J, tk.frame_jacobian(tree, placed),
            J @ qd, tk.frame_velocity(tree, placed, vs),
            rb.frame_classical_acceleration(frames, qd), tk.classical_acceleration(tree, placed, qd, vs)])
        for _ in range(20):
            out = [np.array(v).ravel() for v in f(rng.uniform(-3, 3, n), rng.normal(0, 2, n))]
            for k, (want, got) in enumerate(zip(out[0::2], out[1::2])):
                assert np.abs(got - want).max() < 1e-13 * np.abs(want).max(), (name, k)
