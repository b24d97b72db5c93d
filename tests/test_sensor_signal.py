"""The plant's sensor signal (conventions §14): noise, bias, lag and delay, each against its definition;
a true force/torque sensor's reading; with every option off, the runs of before, bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hybrid
from hybrid.control.wrench_sensor import reading_of
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import run
from hybrid.simulation.sensing import SensorSignal

T = 0.01


class Recording:
    """A controller that records what it is given at each sample."""

    def __init__(self, controller):
        self.controller, self.given = controller, []

    def __call__(self, t, q, qdot, Fc):
        self.given.append(np.array(Fc, float))
        return self.controller(t, q, qdot, Fc)


def recorded(exp):
    """The run of ``exp`` through the Python runner, the readings its controller was given, and the
    plant's own force at each sample (what the sensor's spring-damper exerts on the robot)."""
    plant, ctrl = exp.plant(), Recording(exp.build_controller())
    res = run(exp, plant, ctrl, exp.initial_state())
    at_samples = res.state[::exp.steps_per_sample][:exp.n_samples]
    true = np.array([plant.sensor_wrench(x) for x in at_samples])
    return res, np.array(ctrl.given), true, at_samples


# ---------------------------------------------------------------------------- the signal alone


def test_noise_has_the_given_standard_deviations_and_repeats_with_its_seed():
    sensor = hybrid.Sensor(force_noise=0.3, moment_noise=0.02, seed=7)
    signal = SensorSignal(sensor, T)
    out = np.array([signal(np.zeros(6)) for _ in range(20000)])
    std = out.std(axis=0, ddof=1)
    # the sample std of 20,000 normal draws is within 1 % of sigma (6 standard errors: 3 %)
    np.testing.assert_allclose(std, [0.3] * 3 + [0.02] * 3, rtol=0.03)
    assert np.abs(out.mean(axis=0)).max() < 4 * 0.3 / math.sqrt(20000)
    again = SensorSignal(sensor, T)
    assert all(np.array_equal(again(np.zeros(6)), row) for row in out[:50])
    other = SensorSignal(hybrid.Sensor(force_noise=0.3, moment_noise=0.02, seed=8), T)
    assert not np.array_equal(other(np.zeros(6)), out[0])


def test_the_delay_shifts_by_whole_samples_and_holds_the_first_reading():
    readings = np.random.default_rng(3).normal(size=(40, 6))
    for d in (0, 1, 3):
        signal = SensorSignal(hybrid.Sensor(delay_samples=d), T)
        out = np.array([signal(w) for w in readings])
        want = readings[np.maximum(np.arange(40) - d, 0)]
        np.testing.assert_array_equal(out, want)


def test_the_lag_follows_its_design():
    f_b = 5.0
    signal = SensorSignal(hybrid.Sensor(bandwidth_hz=f_b), T)
    a = math.exp(-2 * math.pi * f_b * T)
    assert signal.pole == pytest.approx(a, rel=1e-15)
    # a unit step right after the first sample: the continuous lag's step response at the samples
    step = np.array([signal(np.full(6, float(k > 0))) for k in range(60)])
    t = np.arange(60) * T
    np.testing.assert_allclose(step[:, 0], 1 - np.exp(-2 * math.pi * f_b * t), rtol=0, atol=1e-12)
    # a sine: the discrete design's gain and phase, and close to the continuous lag's -3 dB at f_b
    for f in (1.0, f_b, 15.0):
        signal = SensorSignal(hybrid.Sensor(bandwidth_hz=f_b), T)
        k = np.arange(3000)
        x = np.sin(2 * math.pi * f * k * T)
        y = np.array([signal(np.full(6, v))[0] for v in x])
        z = np.exp(-2j * math.pi * f * T)
        H = (1 - a) / (1 - a * z)
        tail = slice(1000, None)  # the start's transient gone
        want = np.abs(H) * np.sin(2 * math.pi * f * k * T + np.angle(H))
        np.testing.assert_allclose(y[tail], want[tail], atol=1e-9)
        # (the discretisation departs from the continuous lag as f T grows: 0.3 % at 5 Hz, 4 % at 15 Hz)
        assert abs(H) == pytest.approx(1 / math.sqrt(1 + (f / f_b) ** 2), rel=0.05 if f > f_b else 0.01)
    # no lag: the reading itself
    plain = SensorSignal(hybrid.Sensor(bias=(0.5,) * 6), T)
    np.testing.assert_array_equal(plain(np.arange(6.0)), np.arange(6.0) + 0.5)


# ---------------------------------------------------------------------------- in a run


def test_in_a_run_the_controller_gets_the_lagged_biased_noisy_delayed_force():
    d, bias, f_b = 2, (0.4, -0.3, 0.0, 0.0, 0.0, 0.1), 8.0
    sensor = hybrid.Sensor(force_noise=0.25, moment_noise=0.01, bias=bias, bandwidth_hz=f_b, delay_samples=d, seed=4)
    exp = hybrid.paper_experiment(duration=1.0, sensor=sensor)
    res, given, true, _ = recorded(exp)
    assert np.isfinite(res.state).all()
    # rebuilt from the definition: lag, then bias, then the seeded noise, then the delay
    a, rng = math.exp(-2 * math.pi * f_b * T), np.random.default_rng(4)
    scale = np.repeat([0.25, 0.01], 3)
    y, made = true[0].copy(), []
    for k, w in enumerate(true):
        y = w.copy() if k == 0 else a * y + (1 - a) * w
        made.append(y + np.array(bias) + scale * rng.standard_normal(6))
    made = np.array(made)
    np.testing.assert_array_equal(given, made[np.maximum(np.arange(len(true)) - d, 0)])


def test_in_a_run_the_readings_error_has_the_given_noise():
    sigma = (0.3, 0.02)
    exp = hybrid.tracing_experiment(duration=1.0, sensor=hybrid.Sensor(force_noise=sigma[0], moment_noise=sigma[1]))
    _, given, true, _ = recorded(exp)
    error = given - true
    n = len(error) * 3  # 100 samples, three components each: the sample std within 4 %, 5 standard errors 20 %
    assert error[:, :3].std(ddof=1) == pytest.approx(sigma[0], rel=5 / math.sqrt(2 * n))
    assert error[:, 3:].std(ddof=1) == pytest.approx(sigma[1], rel=5 / math.sqrt(2 * n))


def test_a_true_wrench_sensors_reading_is_the_inverse_of_the_controllers_chain():
    tool = hybrid.Tool(0.6, (0.01, -0.02, 0.05))
    mount = dict(position=(0.0, 0.0, 0.03), rotation=((0.0, -1.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0)))
    true = hybrid.WrenchSensor(**mount, sign=-1, tool=tool, bias=(0.3, -0.2, 1.0, 0.01, 0.02, -0.03))
    exp = hybrid.tracing_experiment(duration=0.3, wrench_sensor=true)
    _, given, force, states = recorded(exp)
    robot = exp.robot
    for k in (0, 7, 29):
        x = states[k]
        terms = hybrid.arm_terms(robot, x[:6], x[6:12])
        want = reading_of(true, force[k], terms["r"], terms["rotation"], robot.gravity, robot)
        np.testing.assert_array_equal(given[k], want)
        # the controller's chain, believing the same sensor, gets the plant's force back
        back = hybrid.control.wrench_sensor.contact_wrench(true, given[k], terms["r"], terms["rotation"],
                                                           robot.gravity, robot)
        np.testing.assert_allclose(back, force[k], atol=1e-12)


def _close(a, b, rel):
    """``a`` equals ``b`` within ``rel`` of each array's largest magnitude."""
    for x, y in ((a.state, b.state), (a.tau, b.tau), (a.outputs, b.outputs)):
        assert np.abs(x - y).max() <= rel * np.abs(y).max()


@pytest.mark.parametrize("make", [
    lambda **kw: hybrid.tracing_experiment(duration=1.0, **kw),
    # the paper's sticking friction amplifies rounding to about 1e-10 (docs/studies/first_touch.md): its arm
    # frictionless here
    lambda **kw: hybrid.paper_experiment(duration=1.0, contact=hybrid.Contact(friction=0.0), **kw),
])
def test_a_noise_free_wrench_sensor_at_the_tip_gives_the_runs_of_before(make):
    before = hybrid.simulate(make(), compiled=False)
    got = hybrid.simulate(make(wrench_sensor=hybrid.WrenchSensor()))
    _close(got, before, 1e-12)
    for name, value in before.metrics.items():
        assert got.metrics[name] == pytest.approx(value, rel=1e-10, abs=1e-12, nan_ok=True), name


def test_a_tool_the_controller_does_not_know_of_biases_the_force_by_its_weight():
    """On the sphere's latitude 60 degrees from the top the normal's z is 0.5: a 0.5 kg tool the
    controller ignores reads as 0.5 * 9.81 * 0.5 N pulling the normal force down, so it presses that
    much harder; believing the tool, it does not."""
    tool = hybrid.Tool(0.5, (0.0, 0.0, 0.04))
    common = dict(duration=1.5, F_d=10.0, v_d=0.1, wrench_sensor=hybrid.WrenchSensor(tool=tool))
    ignorant = hybrid.simulate(hybrid.tracing_experiment(controller_wrench_sensor=hybrid.WrenchSensor(), **common))
    knowing = hybrid.simulate(hybrid.tracing_experiment(**common))
    weight_n = 0.5 * 9.81 * 0.5
    assert ignorant.metrics["steady_state_force_error_N"] == pytest.approx(-weight_n, abs=0.05)
    assert abs(knowing.metrics["steady_state_force_error_N"]) < 0.05


# ---------------------------------------------------------------------------- every option off


def test_with_every_option_off_the_runs_are_those_of_before_bit_for_bit():
    off = dict(sensor=hybrid.Sensor(force_noise=0.0, moment_noise=0.0, bias=(0.0,) * 6, bandwidth_hz=None,
                                    delay_samples=0, seed=11),
               wrench_sensor=None, controller_wrench_sensor=None, start_gap=0.0, approach_speed=0.0)
    for make, duration in ((hybrid.paper_experiment, 1.0), (hybrid.tracing_experiment, 0.5)):
        plain, spelled = make(duration=duration), make(duration=duration, **off)
        assert closed_loop.prepare(spelled) is not None  # the compiled loop still runs it
        assert spelled.build_controller().contact_loss is None
        for compiled in (True, False):
            a, b = hybrid.simulate(plain, compiled=compiled), hybrid.simulate(spelled, compiled=compiled)
            for x, y in ((a.state, b.state), (a.tau, b.tau), (a.outputs, b.outputs)):
                assert np.array_equal(x, y)
            assert a.metrics.keys() == b.metrics.keys()
            assert all(a.metrics[k] == b.metrics[k] or (math.isnan(a.metrics[k]) and math.isnan(b.metrics[k]))
                       for k in a.metrics)


@pytest.mark.parametrize("sensor", [hybrid.Sensor(force_noise=0.1), hybrid.Sensor(moment_noise=0.01),
                                    hybrid.Sensor(bias=(0.1, 0, 0, 0, 0, 0)), hybrid.Sensor(bandwidth_hz=20.0),
                                    hybrid.Sensor(delay_samples=1)])
def test_any_option_on_takes_the_python_runner(sensor):
    assert closed_loop.prepare(hybrid.paper_experiment(sensor=sensor)) is None
    assert closed_loop.prepare(hybrid.paper_experiment(wrench_sensor=hybrid.WrenchSensor())) is None


def test_a_sweep_runs_them_in_python_and_the_others_compiled():
    base = hybrid.paper_experiment(duration=0.4)
    table = hybrid.sweep(base, {"sensor.delay_samples": [0, 2], "sensor.force_noise": [0.0, 0.2]}, workers=1)
    assert (table["status"] == "ok").all()
    plain = table[(table["sensor.delay_samples"] == 0) & (table["sensor.force_noise"] == 0.0)].iloc[0]
    compiled = hybrid.simulate(base).metrics
    assert all(plain[k] == v or (math.isnan(v) and math.isnan(plain[k])) for k, v in compiled.items())
    for _, row in table.iterrows():
        exp = hybrid.sweeps.apply(base, {"sensor.delay_samples": row["sensor.delay_samples"],
                                         "sensor.force_noise": row["sensor.force_noise"]})
        want = hybrid.simulate(exp).metrics
        assert row["rms_force_error_N"] == want["rms_force_error_N"]
    assert table["rms_force_error_N"].nunique() == 4


def test_an_experiment_with_sensors_is_saved_and_read_back(tmp_path):
    exp = hybrid.tracing_experiment(
        duration=0.1, sensor=hybrid.Sensor(force_noise=0.1, bandwidth_hz=30.0, delay_samples=1, seed=3),
        wrench_sensor=hybrid.WrenchSensor(tool=hybrid.Tool(0.2, (0, 0, 0.03)), bias=(0.1,) * 6),
        controller_wrench_sensor=hybrid.WrenchSensor(tool=hybrid.Tool(0.2, (0, 0, 0.03)), cutoff=20.0))
    assert hybrid.Experiment.from_dict(exp.to_dict()) == exp
    res = hybrid.simulate(exp)
    back = hybrid.SimulationResult.load(res.save(tmp_path / "run"))
    assert back.experiment == exp
    np.testing.assert_array_equal(back.state, res.state)


# ---------------------------------------------------------------------------- bad input


def _refused(match: str, make, *args, **kwargs):
    with pytest.raises(hybrid.HybridError, match=match) as info:
        make(*args, **kwargs)
    first = str(info.value).splitlines()[0]
    assert len(first) <= 200, first
    return first


@pytest.mark.parametrize("kwargs, match", [
    ({"delay_samples": 1.5}, r"delay_samples = 1\.5; give a whole number of control samples"),
    ({"delay_samples": -1}, r"delay_samples = -1; give a whole number"),
    ({"force_noise": -0.1}, r"force_noise = -0\.1; give a standard deviation >= 0"),
    ({"moment_noise": -1e-3}, r"moment_noise = -0\.001; give a standard deviation >= 0"),
    ({"bandwidth_hz": 0.0}, r"bandwidth_hz = 0\.0; give the lag's corner frequency in Hz \(> 0\)"),
    ({"bias": (1.0, 2.0)}, r"bias = \(1\.0, 2\.0\); give 6 finite numbers"),
    ({"seed": -2}, r"seed = -2; give a whole number >= 0"),
])
def test_bad_signal_settings_are_refused(kwargs, match):
    _refused(match, hybrid.Sensor, **kwargs)


def test_a_bandwidth_at_or_above_nyquist_is_refused():
    for f in (50.0, 80.0):
        first = _refused(r"bandwidth_hz = .* Hz is at or above the Nyquist frequency 50 Hz", hybrid.paper_experiment,
                         sensor=hybrid.Sensor(bandwidth_hz=f))
        assert "give a bandwidth below it" in first
    hybrid.paper_experiment(sensor=hybrid.Sensor(bandwidth_hz=49.0))
    _refused(r"cutoff = 60 Hz is at or above the Nyquist", hybrid.paper_experiment,
             wrench_sensor=hybrid.WrenchSensor(cutoff=60.0))


def test_bad_force_torque_sensor_settings_are_refused():
    _refused(r"Tool mass = -0\.5; give the tool's mass in kg, a number >= 0", hybrid.Tool, -0.5)
    _refused(r"controller_wrench_sensor .* give wrench_sensor too", hybrid.paper_experiment,
             controller_wrench_sensor=hybrid.WrenchSensor())
    _refused(r"Sensor bias = .* with a wrench_sensor: the true sensor's bias is wrench_sensor=",
             hybrid.paper_experiment, sensor=hybrid.Sensor(bias=(1.0, 0, 0, 0, 0, 0)),
             wrench_sensor=hybrid.WrenchSensor())
    _refused(r"wrench_sensor = 3; give a hybrid.WrenchSensor", hybrid.paper_experiment, wrench_sensor=3)
    _refused(r"WrenchSensor frame = 'tool0' names a URDF frame", hybrid.paper_experiment,
             wrench_sensor=hybrid.WrenchSensor(frame="tool0"))


def test_an_experiment_with_a_sensor_signal_is_not_written_as_standalone_c(tmp_path):
    """The standalone plant gives its sensor's force as the reading: it cannot be such a run."""
    for exp in (hybrid.paper_experiment(sensor=hybrid.Sensor(force_noise=0.1)),
                hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=1)),
                hybrid.tracing_experiment(wrench_sensor=hybrid.WrenchSensor())):
        first = _refused(r"an experiment with a sensor signal \(noise, bias, lag, delay\) or a wrench_sensor runs in "
                         r"Python only", exp.generate, tmp_path / "c")
        assert "leave them out" in first
    assert not (tmp_path / "c").exists()
