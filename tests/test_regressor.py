"""The joint-torque regressor ``tau = Y pi`` of the generated C against Pinocchio's on the same URDF, and
``Y pi`` against the library's inverse dynamics, on the UR5 and the Panda."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import hybrid

pin = pytest.importorskip("pinocchio")

#: Pinocchio's dynamic parameters of a body (``m, m c, Ixx, Ixy, Iyy, Ixz, Iyz, Izz`` about the body's
#: origin, its axes: ``Inertia.toDynamicParameters``) in the order of hybrid's per-link ``pi``
#: (``m, m c, IOxx, IOxy, IOxz, IOyy, IOyz, IOzz``): the same quantities, the products of inertia
#: ``xz`` and ``yy`` swapped
FROM_PINOCCHIO = np.array([0, 1, 2, 3, 4, 5, 7, 6, 8, 9])


def _states(rng, robot, N: int):
    n = robot.n
    return (rng.uniform(robot.limits.lower, robot.limits.upper, (N, n)), rng.normal(0, 1, (N, n)),
            rng.normal(0, 3, (N, n)))


def _relative(got, want) -> float:
    return float(np.abs(np.asarray(got) - want).max() / np.abs(want).max())


def test_parameters_are_pinocchios(robots):
    """The map from the robot's (mass, centre of mass, inertia about it) to ``pi``: Pinocchio's bodies
    (read from the URDF by Pinocchio, fixed links merged) in the same joint frames."""
    for robot, model, _ in robots.values():
        pi = hybrid.linear_parameters(robot)
        want = np.concatenate([model.inertias[i + 1].toDynamicParameters()[FROM_PINOCCHIO]
                               for i in range(robot.n)])
        assert _relative(pi[:10 * robot.n], want) < 1e-12
        np.testing.assert_array_equal(pi[10 * robot.n:], [*robot.damping, *robot.coulomb, *robot.offset])


def test_regressor_against_pinocchio(rng, robots):
    """``Y`` against ``pin.computeJointTorqueRegressor`` (its columns put in hybrid's order; the
    friction's columns are ``diag(q')``, ``diag(tanh(q' / v_s))`` and the identity) to 1e-10, one state at a
    time and N in one call; ``Y pi`` is the inverse dynamics ``B q'' + n`` of :func:`hybrid.arm_terms`, of
    robots given Coulomb friction, offsets and smooth-sign speeds of their own."""
    for robot, model, _ in robots.values():
        n, data = robot.n, model.createData()
        robot = dataclasses.replace(robot, coulomb=rng.uniform(0, 3, n), offset=rng.normal(0, 1, n),
                                    coulomb_speed=rng.uniform(0.01, 0.5, n))
        qs, qds, qdds = _states(rng, robot, 20)
        qds[:5] *= 0.02  # speeds within the smooth sign's too
        Ys, names = hybrid.regressor(robot, qs, qds, qdds)
        assert Ys.shape == (20, n, 13 * n) and len(names) == 13 * n
        assert names[10 * n:] == tuple(f"{p}[{j}]" for p in ("damping", "coulomb", "offset") for j in robot.joint_names)
        pi = hybrid.linear_parameters(robot)
        for q, qd, qdd, Y_batch in zip(qs, qds, qdds, Ys):
            Y, _ = hybrid.regressor(robot, q, qd, qdd)
            np.testing.assert_array_equal(Y, Y_batch)
            Y_pin = pin.computeJointTorqueRegressor(model, data, q, qd, qdd)
            want = np.hstack([Y_pin[:, 10 * i:10 * (i + 1)][:, FROM_PINOCCHIO] for i in range(n)]
                             + [np.diag(qd), np.diag(np.tanh(qd / np.array(robot.coulomb_speed))), np.eye(n)])
            np.testing.assert_allclose(Y, want, rtol=0, atol=1e-10 * max(1.0, np.abs(want).max()))
            terms = hybrid.arm_terms(robot, q, qd)
            tau = terms["B"] @ qdd + terms["n"]
            np.testing.assert_allclose(Y @ pi, tau, rtol=0, atol=1e-10 * max(1.0, np.abs(tau).max()))


def test_regressor_reads_structure_and_gravity_only(rng, robots):
    """Another robot of the same structure has the same ``Y`` (its parameters are in ``pi``), and ``Y``
    changes with gravity as the gravity torque does: ``Y(q, 0, 0) pi`` is the gravity torque."""
    robot = robots["ur5"][0]
    other = robot.with_link(robot.joint_names[2], mass=3.0, com=(0.1, 0.0, 0.2), coulomb=2.0, offset=-0.5)
    q, qd, qdd = (x[0] for x in _states(rng, robot, 1))
    np.testing.assert_array_equal(hybrid.regressor(robot, q, qd, qdd)[0], hybrid.regressor(other, q, qd, qdd)[0])
    sideways = dataclasses.replace(robot, gravity=(3.0, -2.0, -9.0))
    zero = np.zeros(robot.n)
    Y, _ = hybrid.regressor(sideways, q, zero, zero)
    np.testing.assert_allclose(Y @ hybrid.linear_parameters(sideways), hybrid.arm_terms(sideways, q, zero)["n"],
                               rtol=0, atol=1e-12)


def test_base_parameters_give_the_full_torques(rng, robots):
    """The base parameters (from ``Y`` at the function's own random states) give the torques of the full
    ones at other states to 1e-10; every dropped column is its combination of the kept ones there; the
    kept columns are independent, as many as the rank of Pinocchio's regressor stacked over those states
    (plus a viscosity, a Coulomb friction and an offset per joint); the choice and the combinations do not
    depend on the states."""
    for robot, model, _ in robots.values():
        n, data = robot.n, model.createData()
        base = hybrid.base_parameters(robot)
        pi = hybrid.linear_parameters(robot)
        qs, qds, qdds = _states(rng, robot, 100)
        Y, _ = hybrid.regressor(robot, qs, qds, qdds)
        tau = Y @ pi
        np.testing.assert_allclose(base.regressor(Y) @ base.of(pi), tau, rtol=0, atol=1e-10 * np.abs(tau).max())
        W = Y.reshape(-1, 13 * n)
        kept, dropped = W[:, list(base.independent)], W[:, list(base.dependent)]
        assert np.abs(kept @ base.beta - dropped).max() < 1e-10 * np.abs(W).max()
        singular = np.linalg.svd(kept, compute_uv=False)
        assert singular[-1] > 1e-6 * singular[0]
        W_pin = np.vstack([pin.computeJointTorqueRegressor(model, data, *x) for x in zip(qs, qds, qdds)])
        s = np.linalg.svd(W_pin, compute_uv=False)
        assert len(base.independent) == int((s > 1e-10 * s[0]).sum()) + 3 * n
        other = hybrid.base_parameters(robot, states=150, seed=1)
        assert other.independent == base.independent
        np.testing.assert_allclose(other.beta, base.beta, rtol=0, atol=1e-12)
        assert len(base.base_names()) == len(base.independent)
        with pytest.raises(hybrid.HybridError, match="give the"):
            base.of(pi[:-1])
