"""Closed-loop behaviour checked against physics, not against recorded numbers."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hybrid.codegen.model import PLANT_OUTPUTS

import hybrid
from hybrid import oracle
from hybrid.plants import planar as plants
from hybrid.simulation.metrics import settling_time

EXACT = dict(model_error=0.0, viscous_compensation=1.0, contact=hybrid.Contact(friction=0.0))


def last(res, y, span=0.2):
    return y[res.t >= res.t[-1] - span]


def test_output_names_mirror_the_model():
    assert plants.planar_record()["outputs"] == PLANT_OUTPUTS


@pytest.mark.parametrize("speed", [0.4, 0.6])
def test_missing_centripetal_term_gives_the_predicted_force_error(speed):
    """No integral, no curvature, exact model: F_c,n settles m_d v^2 / rho_r short of F_d."""
    exp = hybrid.paper_experiment(integral=False, v_d=hybrid.Step(0.3, speed, 1.0), **EXACT)
    res = hybrid.simulate(exp)
    m_d = 1.0 / exp.gains.KPf
    rho_r = np.hypot(*(last(res, res.outputs[:, :2]) - exp.section.center).T)  # arm tip's circle
    predicted = np.mean(m_d * last(res, res.velocity_tangential) ** 2 / rho_r)
    error = np.mean(last(res, res.force_reference - res.force_normal))
    assert error == pytest.approx(predicted, abs=0.03)
    assert error > 0.5 * m_d * speed**2 / exp.surface.radius  # clearly there


@pytest.mark.parametrize("fix", [dict(curvature=True), dict(integral=True)])
def test_curvature_term_or_integral_action_removes_the_force_error(fix):
    exp = hybrid.paper_experiment(**{"integral": False, **EXACT, **fix})
    res = hybrid.simulate(exp)
    assert abs(res.metrics["steady_state_force_error_N"]) < 0.05


def test_no_steady_force_error_on_a_plane():
    exp = hybrid.paper_experiment(integral=False, surface=hybrid.Plane((0.3, 0.0), (-1.0, 0.0)),
                                  start_point=(0.3, 0.1), duration=1.6, **EXACT)
    res = hybrid.simulate(exp)
    assert abs(res.metrics["steady_state_force_error_N"]) < 0.05


def test_halving_the_step_changes_the_force_by_less_than_10_mN():
    a = hybrid.simulate(hybrid.paper_experiment())
    b = hybrid.simulate(hybrid.paper_experiment(integration_step=5e-5))
    assert np.max(np.abs(a.force_normal - b.force_normal[::2])) < 0.01


def test_sensor_tip_stays_on_the_surface_in_the_paper_run():
    for ctrl in ("task", "khatib"):
        res = hybrid.simulate(hybrid.paper_experiment(controller=ctrl))
        assert res.metrics["contact_losses"] == 0
        assert np.all(res.contact_force[1:] > 0) and np.all(res.penetration > 0)
        assert res.metrics["max_penetration_m"] < 1e-3


def test_controllers_coincide_when_the_force_equals_its_feedforward():
    """With F_c = R^T Sigma F_d the task law's -F_c and Khatib's -R^T Sigma F_d are one term."""
    exps = {c: hybrid.paper_experiment(controller=c) for c in ("task", "khatib")}
    ctrls = {c: hybrid.Controller.from_experiment(e) for c, e in exps.items()}
    q, qdot = np.array([2.2, 1.9]), np.array([0.3, -0.4])
    n = ctrls["task"].measure(q, qdot, np.zeros(2))
    R_L = hybrid.task_frame(exps["task"].surface, n.p[:2], n.v[:2])[0]
    Fc_ff = R_L[1] * exps["task"].force_reference(0.0)
    tau = {c: ctrl(0.0, q, qdot, Fc_ff) for c, ctrl in ctrls.items()}
    np.testing.assert_allclose(tau["task"], tau["khatib"], rtol=1e-12)
    # ...and differ by exactly J^T (F_ff - F_c) when the measured force is off (fresh integrators)
    for ctrl in ctrls.values():
        ctrl.reset()
    Fc = Fc_ff + np.array([1.5, -0.7])
    diff = ctrls["khatib"](0.0, q, qdot, Fc) - ctrls["task"](0.0, q, qdot, Fc)
    J = hybrid.arm_terms(exps["task"].controller_model().closed_form, q, qdot)["J"]
    np.testing.assert_allclose(diff, J.T @ (Fc - Fc_ff), rtol=1e-9)


def test_khatib_is_more_sensitive_to_the_orthogonal_disturbance():
    """The paper's claim: with friction, the force step disturbs Khatib's speed more."""
    drop = {c: hybrid.simulate(hybrid.paper_experiment(controller=c)).metrics[
        "speed_drop_after_force_step_m_per_s"] for c in ("task", "khatib")}
    assert drop["khatib"] > 1.5 * drop["task"]


def test_compiled_and_numpy_paths_agree():
    exp = hybrid.paper_experiment(duration=0.05)
    a = hybrid.simulate(exp)
    b = oracle.simulate(hybrid.paper_experiment(duration=0.05))
    # joints and positions to rounding; the sensor tip's sliding speed passes through the
    # stiff stiction region of tanh(v / 1e-3) at the start, which amplifies rounding
    np.testing.assert_allclose(a.state[:, :7], b.state[:, :7], rtol=1e-9, atol=1e-10)
    np.testing.assert_allclose(a.state[:, 7], b.state[:, 7], atol=1e-5)
    for name in ("r_x", "r_y", "v_t", "v_n", "Fc_n", "penetration", "N"):
        np.testing.assert_allclose(a.output(name), b.output(name), rtol=1e-8, atol=1e-8)


def test_runs_are_deterministic_and_round_trip(tmp_path):
    exp = hybrid.paper_experiment(controller="khatib", duration=0.3, frame="desired")
    a, b = hybrid.simulate(exp), hybrid.simulate(exp)
    np.testing.assert_array_equal(a.state, b.state)
    loaded = hybrid.SimulationResult.load(a.save(tmp_path / "r.npz"))
    assert loaded.experiment == exp and json.dumps(loaded.metrics) == json.dumps(a.metrics)  # NaN == NaN here
    np.testing.assert_array_equal(loaded.outputs, a.outputs)
    header = (a.save_csv(tmp_path / "r.csv")).read_text().splitlines()[0]
    assert "t_s" in header and "Fc_n_N" in header


def test_desired_frame_with_exact_curvature_matches_the_actual_frame_on_track():
    """On the desired path, R(r_d) = R(r): both frames give the same first torque."""
    exps = [hybrid.paper_experiment(frame=f, curvature=True) for f in ("actual", "desired")]
    taus = [hybrid.simulate(hybrid.paper_experiment(frame=e.frame, curvature=True, duration=0.01)).tau[0]
            for e in exps]
    np.testing.assert_allclose(taus[0], taus[1], rtol=1e-6)


def test_task_axis_metrics_on_a_synthetic_step():
    t = np.linspace(0, 1, 1001)
    y = 1 - np.exp(-t / 0.1)
    assert settling_time(t, y, 1.0, 0.02) == pytest.approx(0.1 * np.log(50), abs=2e-3)


def test_metrics_of_any_series_read_the_steps_from_the_references():
    """hybrid.metrics on a run's bare time series (steps inferred) equals the run's own metrics; on a
    synthetic second-order force response the overshoot is the analytic one."""
    res = hybrid.simulate(hybrid.paper_experiment(duration=1.2))
    m = hybrid.metrics(res.t, res.force_normal, res.velocity_tangential, res.force_reference,
                       res.speed_reference, penetration=res.penetration, contact_force=res.contact_force,
                       tau=res.tau)
    # (the run's own metrics were computed in C as it ran: equal to rounding)
    assert list(m) == list(res.metrics)
    for name, value in m.items():
        assert res.metrics[name] == pytest.approx(value, rel=1e-9, abs=1e-12, nan_ok=True), name
    zeta, wn = 0.3, 40.0
    t = np.linspace(0, 2, 20001)
    s = np.clip(t - 0.5, 0, None)
    wd = wn * np.sqrt(1 - zeta**2)
    unit = 1 - np.exp(-zeta * wn * s) * (np.cos(wd * s) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * s))
    F = 10 + 10 * unit
    m = hybrid.metrics(t, F, np.full_like(t, 0.3), np.where(t >= 0.5, 20.0, 10.0), np.full_like(t, 0.3))
    assert m["force_overshoot_percent"] == pytest.approx(100 * np.exp(-zeta * np.pi / np.sqrt(1 - zeta**2)), rel=1e-3)
    assert np.isnan(m["speed_overshoot_after_speed_step_m_per_s"]) and np.isnan(m["contact_losses"])
    with pytest.raises(hybrid.HybridError, match="one value per time sample"):
        hybrid.metrics(t, F[:-1], F, F, F)


def test_metrics_refuse_what_is_not_a_series():
    t = np.linspace(0, 1, 11)
    for kwargs in (dict(force_step=0.5), dict(tau=np.zeros((5, 2)))):
        with pytest.raises(hybrid.HybridError, match="metrics"):
            hybrid.metrics(t, t, t, t, t, **kwargs)
    with pytest.raises(hybrid.HybridError, match="metrics"):
        hybrid.metrics(t, ["a"] * 11, t, t, t)
    down = hybrid.metrics(t, np.where(t < 0.5, 10.0, 0.0), t, np.where(t < 0.5, 10.0, 0.0), t)
    assert down["force_settling_time_2pct_s"] == 0.0  # a step to 0 N settles (band from the step size)


@pytest.mark.parametrize("make", [hybrid.paper_experiment, hybrid.tracing_experiment, hybrid.panda_experiment],
                         ids=["paper", "ur5", "panda"])
def test_the_start_state_by_its_parts(make):
    exp = make()
    x0, parts = exp.initial_state(), exp.start_state()
    n, d = exp.robot.n, (len(x0) - 2 * exp.robot.n) // 2
    assert np.array_equal(parts.q, x0[:n]) and np.array_equal(parts.qdot, x0[n:2 * n])
    assert np.array_equal(parts.sensor_tip, x0[2 * n:2 * n + d])
    assert np.array_equal(parts.sensor_velocity, x0[2 * n + d:])
    assert np.array_equal(parts.array, x0)
    assert np.allclose(parts.sensor_tip, exp.start(), atol=1e-3)  # the sensor tip presses at the start point
    parts.q[0] += 1.0  # the parts are copies
    assert np.array_equal(exp.start_state().q, x0[:n])
