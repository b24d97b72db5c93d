"""The base parameters identified from joint torques: the torques are the library's inverse dynamics
(``B q'' + n`` of :func:`hybrid.arm_terms`, not the regressor) of a UR5 whose every link and viscosity
was changed at random, and the nominal model is the unchanged UR5."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid


def _states(rng, robot, N: int):
    n = robot.n
    return (rng.uniform(robot.limits.lower, robot.limits.upper, (N, n)), rng.normal(0, 1, (N, n)),
            rng.normal(0, 3, (N, n)))


def _torques(robot, q, qd, qdd) -> np.ndarray:
    terms = hybrid.arm_terms(robot, q, qd)
    return np.einsum("kij,kj->ki", terms["B"], qdd) + terms["n"]


@pytest.fixture(scope="module")
def arms():
    """The UR5 (the nominal model) and the true arm: each link's mass, centre of mass, inertia and the
    joint's viscosity changed by up to a few tens of percent (inertias kept physical)."""
    rng = np.random.default_rng(7)
    nominal = hybrid.ur5()
    true = nominal
    for joint, link, d in zip(nominal.joint_names, nominal.links, nominal.damping):
        A = rng.normal(0, 0.2, (3, 3))
        inertia = np.asarray(link.inertia) * rng.uniform(0.8, 1.3) + 1e-3 * (A @ A.T)
        true = true.with_link(joint, mass=link.mass * rng.uniform(0.8, 1.3),
                              com=np.asarray(link.com) + rng.uniform(-0.02, 0.02, 3),
                              inertia=inertia, damping=(d + 0.1) * rng.uniform(0.5, 1.5))
    return nominal, true


def test_noise_free_torques_give_the_true_base_parameters(arms):
    """To 1e-6 relative (the torques are exact: the fit is to rounding); the prediction is the true
    arm's inverse dynamics at other states, one at a time and N at once; the nominal model is
    reported beside the estimate and differs from it."""
    nominal, true = arms
    rng = np.random.default_rng(1)
    q, qd, qdd = _states(rng, nominal, 150)
    found = hybrid.identify_dynamics(nominal, q, qd, qdd, _torques(true, q, qd, qdd))
    base = hybrid.base_parameters(nominal)
    want = base.of(hybrid.linear_parameters(true))
    assert found.names == tuple(base.names[i] for i in base.independent) and found.samples == 150
    assert np.abs(found.estimate - want).max() < 1e-6 * np.abs(want).max()
    np.testing.assert_allclose(found.nominal, base.of(hybrid.linear_parameters(nominal)))
    assert np.abs(found.nominal - want).max() > 1e-2 * np.abs(want).max()
    assert found.residual_rms.shape == (nominal.n,) and found.residual_rms.max() < 1e-9
    assert 1.0 <= found.condition < 1e4 and found.std.max() < 1e-6 * np.abs(want).max()
    held = _states(rng, nominal, 50)
    tau = _torques(true, *held)
    np.testing.assert_allclose(found.torque(*held), tau, rtol=0, atol=1e-8 * np.abs(tau).max())
    np.testing.assert_allclose(found.torque(*(x[0] for x in held)), tau[0], rtol=0, atol=1e-8 * np.abs(tau).max())


def test_noisy_torques(arms):
    """With Gaussian torque noise the true base parameters lie within 4 standard deviations of the
    estimate for nearly all (a fit whose uncertainty is right), the residual RMS is the noise's level
    and so is the prediction's RMS error against noisy torques at held-out states (the fit does not
    follow the noise)."""
    nominal, true = arms
    rng = np.random.default_rng(2)
    sigma = 0.5  # N m
    q, qd, qdd = _states(rng, nominal, 600)
    tau = _torques(true, q, qd, qdd) + rng.normal(0, sigma, q.shape)
    found = hybrid.identify_dynamics(nominal, q, qd, qdd, tau)
    want = hybrid.base_parameters(nominal).of(hybrid.linear_parameters(true))
    z = np.abs(found.estimate - want) / found.std
    assert (z < 4).mean() >= 0.95, z
    assert (z < 1).mean() >= 0.4, z  # nor are the deviations inflated (about 68 % within one)
    np.testing.assert_allclose(found.residual_rms, sigma, rtol=0.1)
    held = _states(rng, nominal, 300)
    true_tau = _torques(true, *held)
    measured = true_tau + rng.normal(0, sigma, true_tau.shape)
    predicted = found.torque(*held)
    assert abs(np.sqrt(((predicted - measured) ** 2).mean()) / sigma - 1) < 0.1
    # the estimate's own error: about sigma sqrt(p / (N n)), well under the noise
    assert np.sqrt(((predicted - true_tau) ** 2).mean()) < 0.25 * sigma


def test_refusals(arms):
    """Samples at one position do not excite the base parameters of gravity and of the inertia's
    variation with the position: refused naming them; bad arrays are refused with the fix."""
    nominal, true = arms
    rng = np.random.default_rng(3)
    q, qd, qdd = _states(rng, nominal, 100)
    tau = _torques(true, q, qd, qdd)
    one = np.tile(q[0], (100, 1))
    with pytest.raises(hybrid.HybridError, match=r"do not excite the base parameters .*\]; excite the arm more") as e:
        hybrid.identify_dynamics(nominal, one, qd, qdd, _torques(true, one, qd, qdd))
    names = str(e.value).split("base parameters ")[1].split("; ")[0].split(", ")
    assert names and set(names) <= set(hybrid.identify_dynamics(nominal, q, qd, qdd, tau).names)
    with pytest.raises(hybrid.HybridError, match="same length"):
        hybrid.identify_dynamics(nominal, q, qd, qdd, tau[:-1])
    bad = qd.copy()
    bad[4, 2] = np.nan
    with pytest.raises(hybrid.HybridError, match=r"qd\[4, 2\] = nan; give finite numbers"):
        hybrid.identify_dynamics(nominal, q, bad, qdd, tau)
    p = len(hybrid.base_parameters(nominal).independent)
    with pytest.raises(hybrid.HybridError, match=f"give at least {p} samples"):
        hybrid.identify_dynamics(nominal, q[:10], qd[:10], qdd[:10], tau[:10])
    with pytest.raises(hybrid.HybridError, match=r"tau has shape \(100, 5\); give an \(N, 6\) array"):
        hybrid.identify_dynamics(nominal, q, qd, qdd, tau[:, :5])
    with pytest.raises(hybrid.HybridError, match="give a hybrid.Robot|robot must be"):
        hybrid.identify_dynamics("ur5", q, qd, qdd, tau)
