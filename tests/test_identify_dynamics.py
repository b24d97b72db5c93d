"""A robot's dynamics identified from a log: a UR5 whose every link and viscosity was changed by up to 30 %
(physically, with ``with_link``) moves along a multi-sine (ten sines per joint, 0.3 to 3 Hz); its torques
are its regressor times its parameters. The nominal model is the unchanged UR5. Positions, velocities and
accelerations are the trajectory's exact ones; noise is added where a test says."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid
from hybrid.models import consistent_parameters as consistent_module
from hybrid.models import log_signals

#: the multi-sine's frequencies [Hz]: ten harmonics of 0.3 Hz, up to 3 Hz
FREQUENCIES = 0.3 * np.arange(1, 11)


def multisine(robot, rate: float, duration: float, seed: int, amplitude=None):
    """``t, q, qd, qdd`` of a multi-sine sampled at ``rate`` [Hz]: per joint ten sines of random phases
    and velocity amplitudes about 0.1-0.25 rad/s each, about a random mid-point."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(round(duration * rate))) / rate
    w = 2 * np.pi * FREQUENCIES
    a = rng.uniform(0.5, 1.0, (robot.n, len(w))) * 0.8 / np.sqrt(len(w)) / w
    if amplitude is not None:
        a = a * np.asarray(amplitude, float)[:, None]
    phase = t[:, None, None] * w + rng.uniform(0, 2 * np.pi, (robot.n, len(w)))
    q = rng.uniform(-1, 1, robot.n) + (a * np.sin(phase)).sum(-1)
    return t, q, (a * w * np.cos(phase)).sum(-1), (-a * w**2 * np.sin(phase)).sum(-1)


def torques(robot, q, qd, qdd) -> np.ndarray:
    Y, _ = hybrid.regressor(robot, q, qd, qdd)
    return Y @ hybrid.linear_parameters(robot)


@pytest.fixture(scope="module")
def arms():
    """The UR5 (the nominal model) and the true arm: each link's mass, centre of mass, inertia and the
    joint's viscosity changed by up to 30 % (the inertia kept a rigid body's)."""
    rng = np.random.default_rng(7)
    nominal = hybrid.ur5()
    true = nominal
    for joint, link, d in zip(nominal.joint_names, nominal.links, nominal.damping):
        A = rng.normal(0, 0.2, (3, 3))
        inertia = np.asarray(link.inertia) * rng.uniform(0.8, 1.3) + 1e-3 * (A @ A.T)
        true = true.with_link(joint, mass=link.mass * rng.uniform(0.7, 1.3),
                              com=np.asarray(link.com) + rng.uniform(-0.02, 0.02, 3),
                              inertia=inertia, damping=(d + 0.1) * rng.uniform(0.7, 1.3))
    return nominal, true


@pytest.fixture(scope="module")
def base(arms):
    return hybrid.base_parameters(arms[0])


def pseudo_inertias(pi, n: int) -> list[np.ndarray]:
    """Each link's ``[[0.5 tr(I_O) 1 - I_O, h], [h^T, m]]``, written out here from the parameters' meaning."""
    out = []
    for m, hx, hy, hz, xx, xy, xz, yy, yz, zz in np.asarray(pi)[:10 * n].reshape(n, 10):
        I_O = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        J = np.zeros((4, 4))
        J[:3, :3] = 0.5 * np.trace(I_O) * np.eye(3) - I_O
        J[:3, 3] = J[3, :3] = hx, hy, hz
        J[3, 3] = m
        out.append(J)
    return out


# ------------------------------------------------------------------ exact logs


def test_an_exact_log_with_velocities_and_accelerations_gives_the_base_parameters(arms, base):
    """Taken as it is (``smooth=False``), the least squares and the consistent estimate are the true base
    parameters to 1e-6 of the largest (rounding and the solver's accuracy); the identified robot's own
    inverse dynamics (``arm_terms``, not the regressor) are the true arm's."""
    nominal, true = arms
    t, q, qd, qdd = multisine(nominal, 100.0, 20.0, seed=1)
    found = hybrid.identify_dynamics(nominal, t, q, torques(true, q, qd, qdd), qd=qd, qdd=qdd, smooth=False)
    want = base.of(hybrid.linear_parameters(true))
    assert found.names == tuple(base.names[i] for i in base.independent)
    assert (found.samples, found.log_samples, found.cutoff_hz) == (2000, 2000, None)
    assert np.abs(found.estimate - want).max() < 1e-6 * np.abs(want).max()
    assert np.abs(found.consistent - want).max() < 1e-6 * np.abs(want).max()
    np.testing.assert_allclose(found.nominal, base.of(hybrid.linear_parameters(nominal)))
    assert np.abs(found.nominal - want).max() > 1e-2 * np.abs(want).max()  # the nominal model is another
    assert found.residual_rms.max() < 1e-9 and found.std.max() < 1e-6 * np.abs(want).max()
    assert found.poorly_excited == () and 1.0 < found.condition < 1e4
    _, qh, qdh, qddh = multisine(nominal, 100.0, 2.0, seed=2)
    terms = hybrid.arm_terms(found.robot, qh, qdh)
    identified = np.einsum("kij,kj->ki", terms["B"], qddh) + terms["n"]
    tau = torques(true, qh, qdh, qddh)
    np.testing.assert_allclose(identified, tau, rtol=0, atol=1e-5 * np.abs(tau).max())


def test_the_default_filter_on_a_1khz_log_of_positions_and_torques(arms, base):
    """Only ``t``, ``q``, ``tau``: the default cutoff (20 Hz) filters both and the accelerations are
    differences of the filtered ``q``. The base parameters come within 3e-5 of the largest: the filter's
    attenuation of the torques' content near its cutoff (products and harmonics of the 3 Hz sines; 6e-6
    measured) is not quite the regressor's of the filtered motion. The consistent estimate is the least
    squares' to 1e-6 (the data are rich, the true arm physical), and the samples are the log's less the
    filter's edges, thinned to about 40 Hz."""
    nominal, true = arms
    t, q, qd, qdd = multisine(nominal, 1000.0, 20.0, seed=1)
    found = hybrid.identify_dynamics(nominal, t, q, torques(true, q, qd, qdd))
    want = base.of(hybrid.linear_parameters(true))
    assert found.cutoff_hz == log_signals.DEFAULT_CUTOFF_HZ == 20.0
    assert np.abs(found.estimate - want).max() < 3e-5 * np.abs(want).max()
    assert np.abs(found.consistent - found.estimate).max() < 1e-6 * np.abs(want).max()
    edge, step = 290, 25  # the slowest pole of the 20 Hz filter at 1 kHz decays to 1e-6 in 288 samples, + 4
    assert abs(found.samples - (20_000 - 2 * edge) / step) < 5 and found.log_samples == 20_000
    # the identified robot is a controller's model (the same structure as the arm's)
    exp = hybrid.tracing_experiment(robot=true, duration=0.2, controller_robot=found.robot)
    assert exp.controller_model() == found.robot and hybrid.simulate(exp).metrics["rms_force_error_N"] < 1.0
    # with qd, qdd given they are filtered alike, and come as close
    again = hybrid.identify_dynamics(nominal, t, q, torques(true, q, qd, qdd), qd=qd, qdd=qdd)
    assert np.abs(again.estimate - want).max() < 3e-5 * np.abs(want).max()


@pytest.mark.parametrize("share, speed", [(0.01, 0.05), (0.05, 0.02), (0.02, 0.1)])
def test_the_default_filter_on_an_arm_with_coulomb_friction(arms, base, share, speed):
    """Coulomb friction (a share of each joint's effort limit, at a smooth-sign speed ``v_s``) turns the
    torque sharply where a joint's speed crosses zero: content up to the 20 Hz cutoff, which the filter
    takes from the torques. The Coulomb columns are filtered alike, so an exact log of ``t``, ``q``,
    ``tau`` alone gives the true base parameters as closely as without friction (3e-5 of the largest), the
    frictions to 1e-3, and none named poorly excited; the regressor of the filtered motion alone left the
    frictions 2-16 % off, an inertia 3 times off and 17 parameters named poorly excited."""
    import dataclasses

    nominal, true = arms
    effort = np.asarray(nominal.limits.effort)
    nominal = dataclasses.replace(nominal, coulomb_speed=(speed,) * 6)
    true = dataclasses.replace(true, coulomb=tuple(share * effort), coulomb_speed=(speed,) * 6)
    t, q, qd, qdd = multisine(nominal, 1000.0, 20.0, seed=1)
    found = hybrid.identify_dynamics(nominal, t, q, torques(true, q, qd, qdd))
    want = base.of(hybrid.linear_parameters(true))
    assert np.abs(found.estimate - want).max() < 3e-5 * np.abs(want).max() and found.poorly_excited == ()
    np.testing.assert_allclose(found.robot.coulomb, true.coulomb, rtol=1e-3)
    np.testing.assert_allclose(found.robot.damping, true.damping, rtol=1e-3)


# ------------------------------------------------------------------ noisy logs


@pytest.mark.parametrize("rate", [100.0, 1000.0, 10_000.0])
def test_noisy_logs_from_100hz_to_10khz(arms, base, rate):
    """Noise on ``q`` (2e-5 rad, an encoder's) and on ``tau`` (1 % of each joint's torque range) per
    sample, 30 s: the prediction along another trajectory is within 3 % of each joint's torque range
    (1.3 % measured at 100 Hz), the true base parameters within 4 standard deviations of the estimate for
    nearly all and within one for many (the deviations are the estimate's, not ten times smaller: the
    samples used are thinned to the filtered noise's rate), every link's pseudo-inertia of the consistent
    estimate is positive definite, and the consistent estimate is near the least squares'."""
    nominal, true = arms
    rng = np.random.default_rng(int(rate))
    t, q, qd, qdd = multisine(nominal, rate, 30.0, seed=3)
    tau = torques(true, q, qd, qdd)
    span = tau.max(axis=0) - tau.min(axis=0)
    found = hybrid.identify_dynamics(nominal, t, q + rng.normal(0, 2e-5, q.shape),
                                     tau + rng.normal(0, 0.01, tau.shape) * span)
    _check_noisy(found, nominal, true, base)


def test_a_noisy_1khz_log_with_coarse_positions(arms, base):
    """The library's own case (1 kHz) with five times the position noise (1e-4 rad): the accelerations'
    noise (0.12 rad/s^2 after the filter) biases the fit a little; the prediction still holds to 3 %."""
    nominal, true = arms
    rng = np.random.default_rng(11)
    t, q, qd, qdd = multisine(nominal, 1000.0, 30.0, seed=4)
    tau = torques(true, q, qd, qdd)
    span = tau.max(axis=0) - tau.min(axis=0)
    found = hybrid.identify_dynamics(nominal, t, q + rng.normal(0, 1e-4, q.shape),
                                     tau + rng.normal(0, 0.01, tau.shape) * span)
    _check_noisy(found, nominal, true, base, coverage=False)


def _check_noisy(found, nominal, true, base, coverage: bool = True) -> None:
    want = base.of(hybrid.linear_parameters(true))
    _, qh, qdh, qddh = multisine(nominal, 200.0, 10.0, seed=9)
    held = torques(true, qh, qdh, qddh)
    span = held.max(axis=0) - held.min(axis=0)
    predicted = found.torque(qh, qdh, qddh)
    assert (np.sqrt(((predicted - held) ** 2).mean(axis=0)) < 0.03 * span).all()
    terms = hybrid.arm_terms(found.robot, qh[:50], qdh[:50])  # the robot is the model .torque is
    np.testing.assert_allclose(np.einsum("kij,kj->ki", terms["B"], qddh[:50]) + terms["n"], predicted[:50],
                               rtol=0, atol=1e-9 * np.abs(held).max())
    if coverage:
        z = np.abs(found.estimate - want) / found.std
        assert (z < 4).mean() >= 0.95 and (z < 1).mean() >= 0.4, z
    for J in pseudo_inertias(found.parameters, nominal.n):
        assert np.linalg.eigvalsh(J).min() > 0
    assert (np.asarray(found.robot.damping) >= 0).all()
    assert (np.abs(found.consistent - found.estimate) < 3 * found.std).all()
    assert found.robot.links != nominal.links and isinstance(found.robot, hybrid.Robot)


def test_a_joint_hardly_moved_is_named_poorly_excited(arms):
    """The last joint moved a hundred times less than the others: its viscosity has a standard deviation
    over 10 % of its size (33 % measured) and is named; moved as much as the others, it is not (0.3 %)."""
    nominal, true = arms
    rng = np.random.default_rng(5)
    for amplitude, named in ((1.0, False), (0.01, True)):
        t, q, qd, qdd = multisine(nominal, 1000.0, 20.0, seed=6, amplitude=[1, 1, 1, 1, 1, amplitude])
        tau = torques(true, q, qd, qdd)
        found = hybrid.identify_dynamics(nominal, t, q, tau + rng.normal(0, 0.01, tau.shape), consistent=False)
        assert ("damping[wrist_3_joint]" in found.poorly_excited) is named
        size = np.maximum(np.abs(found.estimate), np.abs(found.nominal))  # (the size has a floor too)
        assert set(found.poorly_excited) <= {n for n, s, v in zip(found.names, found.std, size) if s > 0.1 * v}


def test_least_squares_alone_keeps_the_unseen_parameters_nominal(arms, base):
    """``consistent=False``: no program is solved; the full parameters are the nominal ones but for the
    parameters kept as base ones, which make the estimate; ``torque`` is the least squares'."""
    nominal, true = arms
    t, q, qd, qdd = multisine(nominal, 100.0, 20.0, seed=1)
    found = hybrid.identify_dynamics(nominal, t, q, torques(true, q, qd, qdd), qd=qd, qdd=qdd, smooth=False,
                                     consistent=False)
    assert found.consistent is None and found.consistent_residual_rms is None
    np.testing.assert_allclose(base.of(found.parameters), found.estimate, rtol=1e-12, atol=1e-12)
    dependent = list(base.dependent)
    np.testing.assert_array_equal(found.parameters[dependent], hybrid.linear_parameters(nominal)[dependent])
    Y, _ = hybrid.regressor(nominal, q[:5], qd[:5], qdd[:5])
    np.testing.assert_allclose(found.torque(q[:5], qd[:5], qdd[:5]), base.regressor(Y) @ found.estimate)


def test_the_program_moves_an_unphysical_estimate_into_the_physical_set(arms, base):
    """An estimate made unphysical (a viscosity negative) comes back physical: every pseudo-inertia
    positive definite, the viscosity 0, and the fit between two bounds: no better than the least squares
    with the viscosity held at 0 (``x = e - P_k e_k / P_kk``, ``P = (R^T R)^-1``: the best of a larger
    set), no worse than the true arm's parameters (physical, so among those the program chose from)."""
    nominal, true = arms
    t, q, qd, qdd = multisine(nominal, 100.0, 20.0, seed=1)
    Y, names = hybrid.regressor(nominal, q, qd, qdd)
    W = base.regressor(Y).reshape(-1, len(base.independent))
    R = np.linalg.qr(W, mode="r")
    estimate = np.linalg.lstsq(W, torques(true, q, qd, qdd).ravel(), rcond=None)[0]
    k = [base.names[i] for i in base.independent].index("damping[elbow_joint]")
    bad = estimate.copy()
    bad[k] = -0.05
    pi = consistent_module.consistent_parameters(nominal, base, R, bad, noise_variance=1e-6, rows=W.shape[0],
                                                 torque_rms=np.ones(6), speed_rms=np.ones(6))
    assert abs(pi[names.index("damping[elbow_joint]")]) < 1e-9
    for J in pseudo_inertias(pi, nominal.n):
        assert np.linalg.eigvalsh(J).min() > 0
    P = np.linalg.inv(R.T @ R)
    held = bad - P[:, k] * bad[k] / P[k, k]

    def misfit(x):
        return np.linalg.norm(R @ (x - bad))

    assert misfit(held) <= misfit(base.of(pi)) * (1 + 1e-6)
    assert misfit(base.of(pi)) <= misfit(base.of(hybrid.linear_parameters(true)))


# ------------------------------------------------------------------ with_linear_parameters


def test_with_linear_parameters_is_the_inverse_of_linear_parameters(arms):
    nominal, true = arms
    for robot in (nominal, true, hybrid.panda()):
        pi = hybrid.linear_parameters(robot)
        again = hybrid.with_linear_parameters(robot, pi)
        np.testing.assert_allclose(hybrid.linear_parameters(again), pi, rtol=1e-12, atol=1e-15)
        for a, b in zip(again.links, robot.links):
            assert a.mass == pytest.approx(b.mass)
            np.testing.assert_allclose(a.com, b.com, atol=1e-12)
            np.testing.assert_allclose(a.inertia, b.inertia, atol=1e-12)
        assert again.damping == robot.damping and again.chain == robot.chain and again.source is None


@pytest.mark.parametrize("change, words", [
    ({"m[elbow_joint]": -1.0}, r"gives the link moved by 'elbow_joint' a mass of -1 kg; give physical parameters"),
    ({"m[elbow_joint]": 0.0}, r"'elbow_joint' a first moment .* without mass"),
    ({"IOxx[elbow_joint]": 50.0}, r"'elbow_joint' an inertia about its centre of mass that has principal moments"),
    ({"IOxx[elbow_joint]": -50.0}, r"'elbow_joint' an inertia about its centre of mass that is not positive"),
    ({"damping[elbow_joint]": -0.5}, r"gives joint 'elbow_joint' a damping of -0.5; give a damping >= 0"),
])
def test_with_linear_parameters_refuses_what_no_body_has(arms, change, words):
    nominal, _ = arms
    _, names = hybrid.regressor(nominal, np.zeros(6), np.zeros(6), np.zeros(6))
    pi = hybrid.linear_parameters(nominal)
    for name, value in change.items():
        pi[names.index(name)] = value
    with pytest.raises(hybrid.HybridError, match=words):
        hybrid.with_linear_parameters(nominal, pi)
    with pytest.raises(hybrid.HybridError, match=f"pi must be {len(names)} finite numbers"):
        hybrid.with_linear_parameters(nominal, pi[:-1])
    with pytest.raises(hybrid.HybridError, match="closed form"):
        hybrid.with_linear_parameters(hybrid.paper_arm(), hybrid.linear_parameters(hybrid.paper_arm()))


# ------------------------------------------------------------------ refusals


@pytest.fixture(scope="module")
def log(arms):
    nominal, true = arms
    t, q, qd, qdd = multisine(nominal, 1000.0, 5.0, seed=1)
    return t, q, torques(true, q, qd, qdd)


def test_bad_logs_are_refused_saying_what_to_do(arms, log):
    nominal, _ = arms
    t, q, tau = log

    def refused(match, *args, **kw):
        with pytest.raises(hybrid.HybridError, match=match) as e:
            hybrid.identify_dynamics(nominal, *args, **kw)
        assert len(str(e.value).splitlines()[0]) <= 240

    # 292 dropped at each end, then 54 samples 25 apart (1 kHz thinned to twice the 20 Hz cutoff)
    refused(r"the log has 400 samples; filtering at 20 Hz drops 292 at each end and the fit needs 54 more 25 apart "
            r"\(twice the cutoff\): give at least 1934 samples \(a longer log\), or a higher cutoff_hz",
            t[:400], q[:400], tau[:400])
    refused(r"t, q, tau have 5000, 5000, 4999 samples; give one row of each per time", t, q, tau[:-1])
    bad = q.copy()
    bad[412, 2] = np.nan
    refused(r"q\[412, 2\] = nan \(sample 412, joint elbow_joint\); give finite numbers", t, bad, tau)
    late = t.copy()
    late[100] = late[98]
    refused(r"t\[100\] = 0.098 is before t\[99\] = 0.099; give strictly increasing times", late, q, tau)
    late[100] = late[99]
    refused(r"t\[100\] = 0.099 repeats t\[99\] = 0.099; give strictly increasing times", late, q, tau)
    gap = np.concatenate([t[:2000], t[2000:] + 0.01])
    refused(r"the log's times are not uniform: .* resample the log onto uniform times", gap, q, tau)
    jitter = t + np.random.default_rng(0).uniform(-0.005, 0.005, len(t)) * 1e-3  # within 1 % of a step: taken
    epoch = t + 1.7e9  # a clock's epoch: uniform to its rounding (4e-7 s)
    for times in (jitter, epoch):
        assert hybrid.identify_dynamics(nominal, times, q, tau, consistent=False).sample_time == pytest.approx(1e-3)
    refused(r"cutoff_hz = 600 Hz is not below the log's Nyquist frequency 500 Hz", t, q, tau, cutoff_hz=600.0)
    refused(r"cutoff_hz = -1; give the filter's cutoff in Hz, a positive number", t, q, tau, cutoff_hz=-1)
    refused(r"cutoff_hz = 10.0 with smooth=False; give one of them", t, q, tau, cutoff_hz=10.0, smooth=False)
    refused(r"tau has shape \(5000, 5\); give an \(N, 6\) array", t, q, tau[:, :5])
    refused(r"t has shape \(5000, 1\); give the samples' times", t[:, None], q, tau)
    with pytest.raises(hybrid.HybridError, match="robot must be"):
        hybrid.identify_dynamics("ur5", t, q, tau)
    # the filter settles slowly near the Nyquist frequency as near 0: the fix there is a lower cutoff
    refused(r"filtering at 499 Hz drops \d+ at each end .* \(a longer log\), or a lower cutoff_hz$", t, q, tau,
            cutoff_hz=499.0)
    refused(r"the log is sampled at 1 Hz \(a step of 1 s\), too slowly .* give the times in seconds", t * 1000, q, tau)


@pytest.mark.parametrize("change, words", [
    (lambda q, tau: (np.degrees(q), tau), r"q\[\d+, \d\] = .* beyond the joint's limits .* \(numpy.radians of"),
    (lambda q, tau: (q, 1000 * tau), r"torques are 1.\d+e\+03 times the nominal model's .*give them in N m"),
    (lambda q, tau: (q, tau / 1000), r"torques are 0.00\d+ times the nominal model's .*give them in N m"),
    (lambda q, tau: (q, 0 * tau), r"torques are 0 times the nominal model's"),
    (lambda q, tau: (q, -tau), r"torques are -1.\d+ times the nominal model's .*\(their sign is flipped\)"),
    (lambda q, tau: (q, tau * [1, 1, -1, 1, 1, 1]), r"joint elbow_joint's logged torques run .* \(-tau\[:, 2\]\)$"),
    (lambda q, tau: (q, tau * [1, 1, 1, 1, -1, 1]), r"joint wrist_2_joint's logged torques run against"),
])
def test_a_log_in_other_units_or_conventions_is_refused(arms, log, change, words):
    """Positions in degrees, torques in other units or of the opposite sign (all, or one joint's) would be
    fitted to confident nonsense (the least squares fit any scale; the consistent program found masses a
    thousand times the arm's): refused against the nominal model, whose torques along the log the true
    arm's are 0.9-1.2 times (every link 30 % off, friction the URDF lacks)."""
    nominal, _ = arms
    t, q, tau = log
    q, tau = change(q, tau)
    with pytest.raises(hybrid.HybridError, match=words) as e:
        hybrid.identify_dynamics(nominal, t, q, tau, consistent=False)
    assert len(str(e.value).splitlines()[0]) <= 240


@pytest.mark.parametrize("make", [hybrid.ur5, hybrid.panda])
def test_real_arms_far_from_their_urdf_are_not_refused_as_other_units(make):
    """The other way: arms perturbed by 30 % with friction of 1-4 % of their efforts (the wrists' torques then
    mostly friction the nominal model has not: their torques 4-10 times the model's, correlated with it by
    0.1-0.5), and with a payload of 3 kg off the last joint's axis, pass the checks."""
    import dataclasses

    nominal = make()
    effort = np.asarray(nominal.limits.effort)
    for seed in range(3):
        rng = np.random.default_rng(seed)
        real = dataclasses.replace(hybrid.perturbed_robot(nominal, 0.3, seed=seed),
                                   damping=tuple(rng.uniform(0.005, 0.02, nominal.n) * effort),
                                   coulomb=tuple(rng.uniform(0.01, 0.04, nominal.n) * effort))
        last = real.links[-1]
        com = (last.mass * np.asarray(last.com) + 3.0 * np.array([0.05, 0.0, 0.05])) / (last.mass + 3.0)
        carrying = real.with_link(nominal.joint_names[-1], mass=last.mass + 3.0, com=com)  # (a point mass)
        t, q, qd, qdd = multisine(nominal, 500.0, 5.0, seed=seed)
        for arm in (real, carrying):
            tau = torques(arm, q, qd, qdd)
            found = hybrid.identify_dynamics(nominal, t, q, tau, consistent=False)
            assert found.residual_rms.max() < 1e-2 * np.abs(tau).max()


@pytest.mark.parametrize("seconds", [1.0, 1.5])
def test_a_log_too_short_for_independent_samples_is_refused(arms, seconds):
    """A log long enough for the filter's edges but not for the fit's samples twice the cutoff apart was
    thinned closer: their noise correlated, the standard deviations came out several times too small (of the
    UR5's 54 base parameters 23-32 more than 3 of them off, at 1 s; parameters not named poorly excited 30 %
    off and more). Refused; at the length it asks for, the estimate is within its standard deviations."""
    nominal, true = arms
    rng = np.random.default_rng(0)
    t, q, qd, qdd = multisine(nominal, 1000.0, seconds, seed=4)
    effort = np.asarray(nominal.limits.effort)
    tau = torques(true, q, qd, qdd) + rng.normal(0, 1, q.shape) * 0.005 * effort
    with pytest.raises(hybrid.HybridError, match=r"the fit needs 54 more 25 apart .*: give at least 1934 samples"):
        hybrid.identify_dynamics(nominal, t, q, tau, consistent=False)
    t, q, qd, qdd = multisine(nominal, 1000.0, 1.934, seed=4)
    tau = torques(true, q, qd, qdd) + rng.normal(0, 1, q.shape) * 0.005 * effort
    found = hybrid.identify_dynamics(nominal, t, q, tau, consistent=False)
    want = found.base.of(hybrid.linear_parameters(true))
    assert (np.abs(found.estimate - want) > 3 * found.std).sum() <= 2


@pytest.mark.parametrize("kind", ["complex", "bool", "text"])
def test_torques_that_are_not_real_numbers_are_refused_in_their_first_line(arms, log, kind):
    """A cast to float would drop complex torques' imaginary part and take booleans as 0 and 1: refused, the
    array shown on one line (its repr spans several) before what to give."""
    nominal, _ = arms
    t, q, tau = log
    text = tau.astype(object)
    text[7, 2] = "about 1"
    bad = {"complex": tau + 1j, "bool": tau > 0, "text": text}[kind]
    with pytest.raises(hybrid.HybridError) as e:
        hybrid.identify_dynamics(nominal, t, q, bad)
    first = str(e.value).splitlines()[0]
    assert first.startswith("tau = array(") and first.endswith("; give an (N, 6) array of real numbers, one row per "
                                                                "sample"), first


def test_a_table_of_the_joints_in_another_order_is_refused(arms, log):
    """A DataFrame's columns are taken by position: named after the joints in another order they would be
    other joints' values."""
    pd = pytest.importorskip("pandas")
    nominal, _ = arms
    t, q, tau = log
    names = list(nominal.joint_names)
    frame = pd.DataFrame(q, columns=names)
    assert hybrid.identify_dynamics(nominal, t, frame, tau, consistent=False).samples > 0
    with pytest.raises(hybrid.HybridError, match=r"q's columns .* are the robot's joints in another order; give them"):
        hybrid.identify_dynamics(nominal, t, frame[names[::-1]], tau, consistent=False)
    with pytest.raises(hybrid.HybridError, match=r"tau's columns .* in another order"):
        hybrid.identify_dynamics(nominal, t, q, pd.DataFrame(tau, columns=[f"tau[{j}]" for j in names])
                                 [[f"tau[{j}]" for j in names[1:] + names[:1]]], consistent=False)


def test_many_unexcited_parameters_are_named_in_a_short_first_line(arms, log):
    """The arm at rest excites none but gravity's: the first line names a few and counts the rest, the next
    names them all."""
    nominal, _ = arms
    t, q, _ = log
    still = np.broadcast_to(q[0], q.shape)
    with pytest.raises(hybrid.HybridError, match=r"do not excite the base parameters .* and \d+ more; excite") as e:
        hybrid.identify_dynamics(nominal, t, still, torques(nominal, still, 0 * still, 0 * still))
    first, *rest = str(e.value).splitlines()
    assert len(first) <= 240 and len(rest) == 1
    named = rest[0].split(": ", 1)[1].split(", ")
    assert rest[0].strip().startswith(f"all {len(named)}:") and "damping[wrist_3_joint]" in named


def test_the_planar_arms_closed_form_says_how_to_identify_a_robot():
    """The closed form's parameters are its Arm's: the fit is reported, ``.robot`` says to identify the serial
    chain, whose ``.robot`` is the arm again."""
    import dataclasses

    planar = hybrid.Robot.planar(hybrid.paper_arm())
    t, q, qd, qdd = multisine(planar, 200.0, 10.0, seed=2)
    tau = torques(planar, q, qd, qdd)
    found = hybrid.identify_dynamics(planar, t, q, tau, qd=qd, qdd=qdd, smooth=False)
    with pytest.raises(hybrid.HybridError, match=r"closed form takes no identified parameters.*closed_form=None\)$"):
        _ = found.robot
    serial = dataclasses.replace(planar, closed_form=None)
    again = hybrid.identify_dynamics(serial, t, q, tau, qd=qd, qdd=qdd, smooth=False).robot
    np.testing.assert_allclose(torques(again, q, qd, qdd), tau, atol=1e-6 * np.abs(tau).max())


def test_a_log_that_does_not_excite_every_base_parameter_is_refused_naming_them(arms, log):
    """One joint held still: the base parameters of its motion are not excited, and named."""
    nominal, true = arms
    t, q, _ = log
    still = q.copy()
    still[:, 5] = 0.3
    qd, qdd = (log_signals.derivative(still, t[1] - t[0], k) for k in (1, 2))
    inner = slice(log_signals.STENCIL, -log_signals.STENCIL)
    with pytest.raises(hybrid.HybridError, match=r"do not excite the base parameters .*\]; excite the arm more") as e:
        hybrid.identify_dynamics(nominal, t[inner], still[inner], torques(true, still[inner], qd[inner], qdd[inner]))
    names = str(e.value).split("base parameters ")[1].split("; ")[0].split(", ")
    assert "damping[wrist_3_joint]" in names and all(n.endswith("[wrist_3_joint]") for n in names)


def test_the_stencil_is_exact_to_degree_eight():
    """The central differences' weights differentiate polynomials of degree 8 exactly (rounding aside),
    and a sinusoid to (w h)^8 / 630 (first derivative)."""
    h = 0.01
    x = np.arange(40) * h
    for degree in range(9):
        p = np.polynomial.Polynomial(np.random.default_rng(degree).normal(size=degree + 1))
        for order in (1, 2):
            got = log_signals.derivative(p(x)[:, None], h, order)[4:-4, 0]
            np.testing.assert_allclose(got, p.deriv(order)(x[4:-4]), rtol=1e-7, atol=1e-7)
    w = 2 * np.pi * 3.0
    got = log_signals.derivative(np.sin(w * x)[:, None], h, 1)[4:-4, 0]
    assert np.abs(got - w * np.cos(w * x[4:-4])).max() / w < 1.1 * (w * h) ** 8 / 630


def test_the_pandas_log_of_the_benchmark():
    """The benchmark's log (the Panda 20 % heavier than its model, ten sines per joint up to 3 Hz), 20 s of
    it: the default filter recovers its base parameters within 1e-4 of the largest and its identified
    robot is physical."""
    from hybrid.bench.identification import panda_log

    robot, t, q, tau = panda_log(20_000)
    found = hybrid.identify_dynamics(robot, t, q, tau)
    want = found.base.of(hybrid.linear_parameters(robot.with_model_error(inertial=0.2)))
    assert np.abs(found.estimate - want).max() < 1e-4 * np.abs(want).max()
    assert np.abs(found.consistent - want).max() < 1e-4 * np.abs(want).max()
    assert all(np.linalg.eigvalsh(J).min() > 0 for J in pseudo_inertias(found.parameters, robot.n))


def test_a_robot_written_as_a_urdf_reads_back_as_itself(tmp_path, arms):
    """The UR5 changed, the Panda and the paper's arm (as a chain): the chain equal (the joints' frames,
    axes, names, the tip), the parameters, viscosities and limits equal to rounding."""
    from hybrid.models.urdf_writer import robot_urdf_text

    for robot in (arms[1], hybrid.panda(), hybrid.Robot.planar(hybrid.paper_arm())):
        path = tmp_path / f"{robot.name}.urdf"
        path.write_text(robot_urdf_text(robot))
        again = hybrid.Robot.from_urdf(path, tip="tip", gravity=robot.gravity)
        assert again.name == robot.name and again.chain == robot.chain
        np.testing.assert_allclose(again.as_array(), robot.as_array(), rtol=1e-12, atol=1e-15)
        for field in ("lower", "upper", "velocity", "effort"):
            np.testing.assert_array_equal(getattr(again.limits, field), getattr(robot.limits, field))


def test_a_long_log_takes_a_few_times_its_own_memory():
    """A log of 20 kHz is thinned to a few hundred samples a second: its signals are filtered a column at a time
    and differentiated at the samples kept alone, so the peak is a few copies of ``q`` (it was six), and the
    derivatives at the kept rows are those of the whole filtered log."""
    import tracemalloc

    from scipy import signal

    robot = hybrid.ur5()
    t, q, _, _ = multisine(robot, 20000.0, 10.0, seed=3)
    tau = q.copy()
    log_signals.log_signals(robot.joint_names, t[:50000], q[:50000], tau[:50000], least=60)  # imports, caches
    tracemalloc.start()
    try:
        signals = log_signals.log_signals(robot.joint_names, t, q, tau, least=60)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 4 * q.nbytes, peak / q.nbytes
    h = t[1] - t[0]
    whole = signal.sosfiltfilt(signal.butter(log_signals.ORDER, signals.cutoff_hz, fs=1 / h, output="sos"), q, axis=0)
    np.testing.assert_allclose(signals.q, whole[signals.rows], rtol=0, atol=1e-12)
    for order, got in ((1, signals.qd), (2, signals.qdd)):
        np.testing.assert_allclose(got, log_signals.derivative(whole, h, order)[signals.rows], rtol=1e-9,
                                   atol=1e-9 * np.abs(got).max())
