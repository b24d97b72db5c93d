"""Contact from free space (conventions §4) and the first touch's metrics (§8): the start, the touch on
the paper's arm and the UR5, the metrics' definitions, and the compiled loop's C against them."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hybrid
from hybrid.plants.planar import PlanarPlant
from hybrid.simulation import closed_loop
from hybrid.simulation.metrics import first_touch, settling_time

GAP, SPEED = 0.005, 0.05
FACTORIES = {"paper": hybrid.paper_experiment, "ur5": hybrid.tracing_experiment}


def touching(name: str, **overrides):
    """A run from 5 mm off the surface at 0.05 m/s onto k_e = 1e5 N/m, 10 N, sliding at 0.1 m/s."""
    settings = dict(start_gap=GAP, approach_speed=SPEED, F_d=10.0, v_d=0.1, duration=0.8)
    return FACTORIES[name](**{**settings, **overrides})


def _equal(a: dict, b: dict, rel: float, abs_: float) -> None:
    assert a.keys() == b.keys()
    for k, v in b.items():
        assert a[k] == pytest.approx(v, rel=rel, abs=abs_, nan_ok=True), k


@pytest.mark.parametrize("name", sorted(FACTORIES))
def test_the_start_is_at_rest_off_the_surface(name):
    exp = touching(name)
    x0 = exp.initial_state()
    plant = exp.plant()
    row = dict(zip(plant.record["outputs"], plant.outputs(x0[None, :])[0]))
    assert row["penetration"] == pytest.approx(-GAP, abs=1e-12)  # the sensor tip 5 mm out
    assert row["N"] == 0.0
    n = exp.robot.n
    np.testing.assert_array_equal(x0[n:2 * n], 0.0)
    np.testing.assert_array_equal(x0[-len(x0[2 * n:]) // 2:], 0.0)  # the sensor tip at rest
    # the spring carries the tip mass's weight where the plant gives it gravity, else nothing
    weight = np.zeros(3) if name == "paper" else exp.sensor.mass * np.array(exp.robot.gravity)
    force = np.array([row[c] for c in plant.force_columns])
    np.testing.assert_allclose(force, weight[:len(force)], atol=1e-6)  # (the inverse kinematics' tolerance)
    # the arm is where the inverse kinematics put it: its tip at the sensor tip (less the spring's sag)
    tip = hybrid.arm_terms(exp.robot, x0[:n], x0[n:2 * n])["r"][:len(force)]
    np.testing.assert_allclose(tip, x0[2 * n:2 * n + len(force)] - weight[:len(force)] / exp.sensor.stiffness,
                               atol=1e-9)
    assert exp.build_controller().contact_loss == hybrid.ContactLoss(0.5, SPEED)


@pytest.mark.parametrize("name", sorted(FACTORIES))
def test_a_touch_at_5_cm_per_s_settles_without_a_loss(name):
    res = hybrid.simulate(touching(name))
    m = res.metrics
    # the approach: about gap / speed, the controller reaching its speed within a few samples
    assert GAP / SPEED < m["first_touch_time_s"] < GAP / SPEED + 0.02
    assert m["contact_losses"] == 0
    assert m["first_touch_settling_s"] < 0.3
    assert 0.0 < m["first_touch_overshoot_N"] < 1.0
    assert abs(m["steady_state_force_error_N"]) < 0.1
    # out of contact until the touch, then in contact for good
    touched = res.contact_force > 0
    i0 = np.flatnonzero(touched)[0]
    assert res.t[i0] == m["first_touch_time_s"] and touched[i0:].all()
    h = res.experiment.integration_step
    assert m["time_out_of_contact_s"] == pytest.approx(m["first_touch_time_s"] - h, abs=1e-12)


@pytest.mark.parametrize("name", sorted(FACTORIES))
def test_the_compiled_loop_and_the_python_runner_agree_on_the_touch(name):
    exp = touching(name, F_d=hybrid.Step(10.0, 15.0, 0.5))  # the window ends at the force step
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    assert closed_loop.prepare(exp) is not None
    _equal(compiled.metrics, python.metrics, 1e-6, 1e-10)
    assert compiled.metrics["first_touch_settling_s"] < 0.3


@pytest.mark.parametrize("overrides", [
    {},                                                            # the window to the end of the run
    {"F_d": hybrid.Step(10.0, 15.0, 0.5)},                        # to the force step
    {"duration": 0.05},                                            # no touch: NaN
    {"start_gap": 0.0, "approach_speed": 0.0, "duration": 0.6},    # the pressed start: touched at 0
    {"contact": hybrid.Contact(stiffness=1e7), "integration_step": 2e-5, "duration": 0.3},  # it bounces: losses
])
def test_the_metrics_in_c_equal_their_numpy_definitions_on_the_same_record(overrides):
    exp = touching("paper", **overrides)
    got = closed_loop.run([closed_loop.prepare(exp)], record=True)[0]
    assert got.status == 0
    plant = PlanarPlant(exp)
    # the loop's own output record (its rows within rounding of the plant's outputs of its states)
    np.testing.assert_allclose(got.outputs, plant.outputs(got.states), rtol=1e-12, atol=1e-9)
    col = {name: got.outputs[:, i] for i, name in enumerate(plant.record["outputs"])}
    t = np.arange(len(got.states)) * exp.integration_step
    ref = hybrid.metrics(t, col["Fc_n"], col["v_t"], exp.force_reference.sampled(t), exp.speed_reference.sampled(t),
                         force_step=exp.force_reference, speed_step=exp.speed_reference,
                         penetration=col["penetration"], contact_force=col["N"], tau=got.taus)
    _equal(got.metrics, ref, 1e-12, 1e-15)
    if overrides.get("duration") == 0.05:
        assert all(math.isnan(got.metrics[k]) for k in ("first_touch_time_s", "first_touch_overshoot_N",
                                                        "first_touch_settling_s"))
        assert got.metrics["contact_losses"] == 0
    if "contact" in overrides:
        assert got.metrics["contact_losses"] > 3


def test_a_nearly_rigid_surface_chatters_the_sensor_tip_not_the_measured_force():
    """The paper's Appendix in the elastic model: at k_e = 1e8 N/m the penalty contact's damping (50 N s/m)
    is 2 % of critical for the 25 g tip mass, so the tip bounces on the touch; the sensor's spring
    between it and the arm keeps the measured force smooth, so the touch's overshoot is that on 1e5 N/m."""
    soft = hybrid.simulate(touching("paper", v_d=0.0, duration=0.5))
    rigid = hybrid.simulate(touching("paper", v_d=0.0, duration=0.5, contact=hybrid.Contact(stiffness=1e8),
                                     integration_step=5e-6))
    assert soft.metrics["contact_losses"] == 0
    assert rigid.metrics["contact_losses"] >= 20
    bouncing = rigid.metrics["time_out_of_contact_s"] - rigid.metrics["first_touch_time_s"]
    assert 0.005 < bouncing < 0.05
    assert rigid.contact_force.max() > 5 * soft.contact_force.max()
    assert rigid.metrics["first_touch_overshoot_N"] == pytest.approx(soft.metrics["first_touch_overshoot_N"], abs=0.05)


def test_first_touch_on_series_by_hand():
    t = np.arange(12) * 0.1
    F = np.array([0, 0, 0, 3, 9, 11, 10.6, 10.2, 9.8, 10.1, 10.0, 10.0])
    contact = F > 0
    Fd = np.full(12, 10.0)
    got = first_touch(t, F, Fd, contact, hybrid.Step(10.0, 10.0, 0.0))
    assert got["first_touch_time_s"] == t[3]
    assert got["first_touch_overshoot_N"] == pytest.approx(1.0)
    # outside 10 +- 0.5 last at index 6 (10.6): settled from index 7, 0.4 s after the touch
    assert got["first_touch_settling_s"] == pytest.approx(0.4)
    # a force step at t = 0.6 s ends the window there: the peak is 11, and it has not settled by then
    cut = first_touch(t, F, np.where(t < 0.6, 10.0, 20.0), contact, hybrid.Step(10.0, 20.0, 0.6))
    assert cut["first_touch_overshoot_N"] == pytest.approx(1.0) and math.isnan(cut["first_touch_settling_s"])
    # a step before the touch: the window runs to the end, on the reference at the touch (20 N, band 1 N)
    early = first_touch(t, 2 * F, np.where(t < 0.2, 10.0, 20.0), contact, hybrid.Step(10.0, 20.0, 0.2))
    assert early["first_touch_overshoot_N"] == pytest.approx(2.0)
    assert early["first_touch_settling_s"] == pytest.approx(0.4)
    assert all(math.isnan(v) for v in first_touch(t, F, Fd, np.zeros(12, bool), hybrid.Step(10, 10, 0)).values())
    # through hybrid.metrics: every name, and contact losses after the touch only
    m = hybrid.metrics(t, F, np.zeros(12), Fd, np.zeros(12), contact_force=np.where(np.arange(12) == 8, 0.0, F))
    assert m["contact_losses"] == 1 and m["first_touch_time_s"] == t[3]
    assert settling_time(t[3:], F[3:], 10.0, 0.5) == got["first_touch_settling_s"]


# ------------------------------------------------------------------------------- bad input


def _refused(match: str, **overrides):
    with pytest.raises(hybrid.HybridError, match=match) as info:
        exp = hybrid.paper_experiment(**overrides)
        exp.initial_state()
    first = str(info.value).splitlines()[0]
    assert len(first) <= 200, first
    return first


def test_bad_starts_from_free_space_are_refused():
    _refused(r"start_gap = -0\.01 m; give a start gap >= 0 \(0: start on the surface, pressed\)", start_gap=-0.01,
             approach_speed=0.05)
    _refused(r"approach_speed = -0\.05 m/s; give a approach speed >= 0", approach_speed=-0.05)
    _refused(r"start_gap = 0\.005 m needs an approach speed .* give approach_speed > 0", start_gap=0.005)
    _refused(r"touch_threshold = 0 N; give the force below which", touch_threshold=0.0, approach_speed=0.05)
    _refused(r"Experiment\.start_gap must be a real number", start_gap="5 mm", approach_speed=0.05)
    # off the disc at (0.3, 0) m along its normal (-1, 0): the arm reaches 0.13-0.77 m from its base, so
    # 0.3 m puts the arm tip at the base and 1.2 m beyond its reach
    first = _refused(r"start_gap = 0\.3 m puts the arm tip at \[0\.0, 0\.0\] m, which the arm cannot reach; give "
                     r"a smaller start_gap", start_gap=0.3, approach_speed=0.05)
    assert "start_point" in first
    _refused(r"start_gap = 1\.2 m puts the arm tip at \[-0\.9, 0\.0\] m, which the arm cannot reach",
             start_gap=1.2, approach_speed=0.05)
    for gap in (0.3, 1.2):  # simulate and a sweep refuse it alike
        with pytest.raises(hybrid.HybridError, match="start_gap"):
            hybrid.simulate(hybrid.paper_experiment(start_gap=gap, approach_speed=0.05, duration=0.1))
    table = hybrid.sweep(hybrid.paper_experiment(approach_speed=0.05, duration=0.1), {"start_gap": [0.001, 0.3]},
                         workers=1)
    assert table["status"].tolist() == ["ok", "invalid"] and "start_gap = 0.3 m" in table["error"].iloc[1]


def test_the_studys_example_runs_and_gives_the_studys_numbers():
    """The Python block of docs/studies/first_touch.md runs as written; its first run is the study's (the paper's
    arm, 1e5 N/m, 0.05 m/s): 0.46 N of overshoot, 0.16 s to settle, no loss."""
    import re
    from pathlib import Path

    page = Path(__file__).resolve().parent.parent / "docs" / "studies" / "first_touch.md"
    block = next(b for b in re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S) if "start_gap=" in b)
    ns: dict = {}
    exec(compile(block, str(page), "exec"), ns)
    m = ns["m"]
    assert m["first_touch_overshoot_N"] == pytest.approx(0.46, abs=0.005)
    assert m["first_touch_settling_s"] == pytest.approx(0.16, abs=0.005) and m["contact_losses"] == 0
    assert math.isfinite(ns["noisy"].metrics["first_touch_overshoot_N"])
    # the controller believes the true tool and bias: it holds the force as without a sensor, less what its
    # 20 Hz filter's lag costs at 0.3 m/s on the sphere (0.1 N)
    assert abs(ns["res"].metrics["steady_state_force_error_N"]) < 0.15


def test_the_figure_of_the_touch_is_drawn(tmp_path):
    from hybrid.plots import plot_first_touch, save

    runs = {"free": hybrid.simulate(touching("paper", duration=0.3)),
            "never": hybrid.simulate(touching("paper", duration=0.05))}  # a run that never touches is left out
    fig = plot_first_touch(runs, "a touch")
    assert [ax.get_ylabel() for ax in fig.axes] == ["measured normal force [N]",
                                                    "surface's normal force\non the sensor tip [N]"]
    assert [ln.get_label() for ln in fig.axes[1].get_lines()] == ["free"]
    path = save(fig, tmp_path / "touch")[0]
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
