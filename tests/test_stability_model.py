"""The sampled loops' small-signal model against the nonlinear simulation, and its parts against
independent statements of them (SciPy's matrix exponential, the definitions of the margins)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.linalg import expm as scipy_expm

import hybrid
from hybrid.stability.analysis import axis_alone, gain_margin
from hybrid.stability.experiment_loops import loop_numbers
from hybrid.stability.model import closed_loop, expm

#: the step of the force reference: small, so the run stays in its small-signal range [N]
EPS = 1e-3


def _pressed(**changes) -> hybrid.Experiment:
    """The paper's arm pressing on a wall at rest (no friction, no curvature: the model's assumptions)."""
    settings = dict(surface=hybrid.Plane(point=(0.3, 0.0, 0.0), normal=(-1.0, 0.0, 0.0)), start_point=(0.3, 0.0),
                    contact=hybrid.Contact(friction=0.0), force_reference=hybrid.Step(10.0, 10.0 + EPS, 0.05),
                    speed_reference=hybrid.Step(0.0, 0.0, 0.0), duration=0.5, integration_step=1e-5)
    settings.update(changes)
    return hybrid.paper_experiment(**settings)


def _model_response(exp, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """The model's normal force and velocities at the samples, for a unit step of F_d at 0.05 s."""
    st, p = loop_numbers(exp)
    m = closed_loop(st, p)
    X, r = np.zeros(m["A"].shape[0]), np.zeros(st.n)
    force, velocity = [], []
    for k in range(samples):
        r[list(st.force).index(True)] = 1.0 if k * exp.sample_time >= 0.05 - 1e-12 else 0.0
        v = np.concatenate([X, r])
        force.append(m["force"] @ v)
        velocity.append(m["velocity"] @ v)
        X = m["A"] @ X + m["B"] @ r
    return np.array(force), np.array(velocity)


CASES = {
    "exact": {"model_error": 0.0, "viscous_compensation": 1.0},
    "model error": {},
    "stiff sensor": {"sensor": hybrid.Sensor(stiffness=5000.0)},
    "lag and delay": {"sensor": hybrid.Sensor(bandwidth_hz=20.0, delay_samples=1)},
    "filtered": {"wrench_sensor": hybrid.WrenchSensor(cutoff=15.0, order=2)},
    "2 ms samples": {"sample_time": 0.002, "KI2v": 500.0},
}


@pytest.mark.parametrize("case", CASES)
def test_the_step_response_is_the_simulations_small_signal_response(case):
    exp = _pressed(**CASES[case])
    res = hybrid.simulate(exp)
    at = np.searchsorted(res.t, np.arange(exp.n_samples) * exp.sample_time - 1e-12)
    simulated_force = (res.force_normal[at] - res.force_normal[0]) / EPS
    simulated_v = np.column_stack([res.velocity_tangential[at], res.velocity_normal[at]]) / EPS
    force, velocity = _model_response(exp, exp.n_samples)
    scale = np.abs(force[:, -1]).max()
    assert scale > 0.5  # the step moved the force
    np.testing.assert_allclose(force[:, -1], simulated_force, rtol=0, atol=1e-6 * scale)
    np.testing.assert_allclose(velocity, simulated_v, rtol=0, atol=1e-6 * np.abs(velocity).max())


def _rough(robot, share):
    """``robot`` with Coulomb friction and viscosities on its joints, each ``share`` of a set (no offset: it
    would move the start off rest, about which the model holds)."""
    n = robot.n
    return dataclasses.replace(robot, damping=tuple(share * np.linspace(2.0, 0.5, n)),
                               coulomb=tuple(share * np.linspace(3.0, 0.5, n)),
                               coulomb_speed=(1.0,) * n)


#: the arms and the agreement asked: about rest the Coulomb friction is the viscosity F_c / v_s, the controller
#: told half of it; the start's own tolerance leaves about 1e-6 in either case (a model blind to the Coulomb
#: friction is 2e-2 off)
ARMS = {"exact": ({"model_error": 0.0, "viscous_compensation": 1.0}, 1e-6),
        "coulomb friction": ({"robot": _rough(hybrid.ur5(), 1.0), "controller_robot": _rough(hybrid.ur5(), 0.5)}, 2e-6)}


@pytest.mark.parametrize("arm", ARMS)
def test_the_3d_arms_loops_follow_their_simulation_too(arm):
    # the UR5 pressing on a wall in front of it, gravity on: the terms held over a sample include gravity's.
    # Its start is at rest to the start's own tolerance, not exactly: the run without the step is subtracted,
    # and the step is 10 mN (its product with that transient, second order, stays below 1e-6 of it)
    step = 10 * EPS
    settings = dict(surface=hybrid.Plane((0.5, 0.0, 0.2), (-1.0, 0.0, 0.0)), start_point=(0.5, 0.1, 0.2),
                    contact=hybrid.Contact(friction=0.0), duration=0.3,
                    speed_reference=hybrid.Step(0.0, 0.0, 0.0), integration_step=1e-5, **ARMS[arm][0])
    exp = hybrid.tracing_experiment(force_reference=hybrid.Step(10.0, 10.0 + step, 0.05), **settings)
    still = hybrid.tracing_experiment(force_reference=hybrid.Step(10.0, 10.0, 0.05), **settings)
    runs = [hybrid.simulate(e) for e in (exp, still)]
    at = np.searchsorted(runs[0].t, np.arange(exp.n_samples) * exp.sample_time - 1e-12)
    simulated = (runs[0].force_normal[at] - runs[1].force_normal[at]) / step
    st = loop_numbers(exp)[0]
    force, _ = _model_response(exp, exp.n_samples)
    normal = list(st.sensed).index(list(st.force).index(True))
    scale = np.abs(force[:, normal]).max()
    assert scale > 0.5
    np.testing.assert_allclose(force[:, normal], simulated, rtol=0, atol=ARMS[arm][1] * scale)


def test_the_batched_exponential_is_scipys():
    rng = np.random.default_rng(4)
    for scale in (1e-6, 1.0, 50.0, 2e3):
        M = rng.normal(size=(40, 9, 9)) * scale / 9 - np.eye(9) * scale * rng.random((40, 1, 1))
        ours, theirs = expm(M), np.stack([scipy_expm(m) for m in M])
        size = np.abs(theirs).max(axis=(1, 2), keepdims=True)
        assert (np.abs(ours - theirs) <= 1e-11 * size).all()


def test_a_non_finite_matrix_gives_a_non_finite_exponential_not_an_error():
    M = np.full((2, 3, 3), np.inf)
    assert not np.isfinite(expm(M)).all()


def test_the_gain_margin_is_where_the_loop_turns_unstable():
    # raising the loop's gain by the margin puts a pole on the unit circle: the model's controller
    # model error (1 + e) is that gain, and the check refuses the experiment just past it
    exp = hybrid.paper_experiment(model_error=0.0, viscous_compensation=1.0)
    st, p = loop_numbers(exp)
    sub, q = axis_alone(st, p, list(st.force).index(True))
    k = gain_margin(sub, q)
    reported = hybrid.stability(exp).loop("n").gain_margin_db
    assert reported == pytest.approx(20 * math.log10(k), rel=1e-9)

    def radius(scale):
        poles = np.linalg.eigvals(closed_loop(sub, dict(q, gain=q["gain"] * scale))["A"])
        return abs(poles).max()
    assert radius(k * (1 - 1e-6)) < 1.0 <= radius(k * (1 + 1e-6))
    hybrid.paper_experiment(model_error=(k - 1) * 0.99, viscous_compensation=1.0)
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.paper_experiment(model_error=(k - 1) * 1.05, viscous_compensation=1.0)


def test_the_delay_margin_is_the_last_delay_that_stays_stable():
    exp = hybrid.paper_experiment(sensor=hybrid.Sensor(stiffness=3000.0))
    d = hybrid.stability(exp).loop("n").delay_margin_samples
    assert 0 < d < 20
    late = hybrid.Sensor(stiffness=3000.0, delay_samples=d)
    assert hybrid.stability(hybrid.paper_experiment(sensor=late)).stable
    later = hybrid.Sensor(stiffness=3000.0, delay_samples=d + 1)
    assert not hybrid.stability(hybrid.paper_experiment(sensor=later, allow_unstable=True)).loop("n").stable


def test_a_run_predicted_unstable_is_refused_or_run_and_marked():
    stiff = hybrid.Sensor(stiffness=2e4)
    with pytest.raises(hybrid.HybridError) as info:
        hybrid.paper_experiment(sensor=stiff)
    first = str(info.value).splitlines()[0]
    assert "force loop on n is unstable" in first and "allow_unstable=True" in first and len(first) <= 240
    allowed = hybrid.paper_experiment(sensor=stiff, allow_unstable=True, duration=0.3)
    assert hybrid.Experiment.from_dict(allowed.to_dict()) == allowed
    try:
        res = hybrid.simulate(allowed)
        assert not res.predicted_stable
    except hybrid.SimulationError as err:
        assert "predicted unstable" in str(err)
    assert hybrid.simulate(hybrid.paper_experiment(duration=0.05)).predicted_stable
    with pytest.raises(hybrid.HybridError, match="allow_unstable = 'yes'"):
        hybrid.paper_experiment(allow_unstable="yes")


def test_the_report_names_every_axis_and_prints():
    report = hybrid.stability(hybrid.tracing_experiment())
    assert [x.axis for x in report.loops] == ["t1", "t2", "n", "rot_t1", "rot_t2", "rot_n"]
    assert [x.loop for x in report.loops] == ["velocity"] * 2 + ["force"] + ["velocity"] * 3
    # the axes barely couple through the arm: the whole's radius is the largest loop's, to a few parts in 1e4
    assert report.stable and report.spectral_radius == pytest.approx(max(x.spectral_radius for x in report.loops),
                                                                     rel=1e-3)
    assert "rot_n" in str(report) and len(report.table()) == 6
    with pytest.raises(hybrid.HybridError, match="no task axis 'z'"):
        report.loop("z")
