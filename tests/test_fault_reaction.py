"""The step's fault reaction: after consecutive faulted samples a safe state, until a reset.

The Python :class:`hybrid.Controller` and the standalone C its ``generate`` writes are driven by the same
random sequences of samples (on time, a non-finite wrench or joint state, late, repeated) and must agree
in status and torque at every sample; the safe state must come exactly after ``fault_samples``
consecutive faulted samples that moved time, hold until ``reset``, and its torque must stay within the
limits. In a loop with the plant (MuJoCo's integration where it is installed), a long sensor dropout
must end in a stop with no contact force above ``F_d + 5 N`` and no impact, where the same dropout
without the reaction lifts the tool off and brings it back.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_standalone_controller import CController

import hybrid
from hybrid.plants.registry import plant_for
from hybrid.simulation.runner import run
from hybrid.spec.controller_step import FAULT_STATE
from hybrid.spec.interfaces import HELD_STATUSES, STATUS_CODES, Dims

#: a torque limit [N m] low enough that the safe state's torque meets it at some joints
LIMIT = 40.0
KINDS = ("ok", "nan_wrench", "nan_q", "late", "repeated")


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    """A UR5 controller on the sphere, its standalone C, and recorded samples ``(t, q, qd, wrench)``."""
    return _pair(tmp_path_factory)


#: a torque step limit [N m per sample] that binds in the safe state
RATE = 0.5


@pytest.fixture(scope="module")
def rate_pair(tmp_path_factory):
    """As ``pair``, with the torque step limit ``RATE``."""
    return _pair(tmp_path_factory, torque_step_limit=RATE)


def _pair(tmp_path_factory, **limits):
    exp = hybrid.tracing_experiment(duration=0.3)
    base = exp.build_controller()
    reaction = hybrid.FaultReaction(fault_samples=3, stop_time=0.04, unload_time=0.05)
    py = hybrid.Controller(base.robot, base.surface, gains=exp.gains, torque_limit=LIMIT, fault_reaction=reaction,
                           **limits)
    folder = tmp_path_factory.mktemp("fault")
    py.generate(folder, "fr")
    r, plant = hybrid.simulate(exp), exp.plant()
    samples = []
    for k in range(exp.n_samples):
        x = r.state[k * exp.steps_per_sample]
        samples.append((k * exp.sample_time, x[:6].copy(), x[6:12].copy(), plant.sensor_wrench(x)))
    return py, CController(folder, "fr"), samples


def python_status(py, t, q, qd, w):
    """``(status name, torque)`` of one sample of the Python controller."""
    try:
        return "OK", py(t, q, qd, w)
    except hybrid.HybridError as exc:
        status = getattr(exc, "status", None) or "INPUT_NONFINITE"
        return status, np.asarray(exc.torque, float)


def _sample(samples, k: int, kind: str, clock: float):
    t, q, qd, w = samples[k % len(samples)]
    T = samples[1][0] - samples[0][0]
    t = clock + T
    if kind == "nan_wrench":
        w = np.full(6, np.nan)
    elif kind == "nan_q":
        q = q.copy()
        q[2] = np.nan
    elif kind == "late":
        t = clock + 2.3 * T
    elif kind == "repeated":
        t = clock
    return t, q, qd, np.resize(w, 6) if np.size(w) == 3 else w


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.sampled_from(KINDS), min_size=1, max_size=30))
def test_c_and_python_react_alike(pair, kinds):
    py, c, samples = pair
    py.reset()
    c.lib.fr_controller_reset(c.c)
    reaction = py.fault_reaction
    faults, stopped, clock, served = 0, False, 0.0, None
    T = samples[1][0] - samples[0][0]
    for k, kind in enumerate(["ok", *kinds]):
        t, q, qd, w = _sample(samples, k, kind, clock)
        status, tau = python_status(py, t, q, qd, w)
        code, tau_c = c.step(t, q, qd, w)
        assert c.name(code) == status, (k, kind)
        np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
        assert np.isfinite(tau).all() and np.all(np.abs(tau) <= LIMIT)
        # the reaction's rule, stated independently: a faulted sample that moved time counts one more, or the
        # sample instants since the last served where more; one on time ends the count, and the count reaching
        # fault_samples is the safe state for good
        if not stopped and status not in HELD_STATUSES:
            spanned = 0 if served is None else sum(served + i * T <= t + T / 2 for i in range(1, 10))
            faults = 0 if status == "OK" else min(max(faults + 1, spanned), reaction.fault_samples)
            stopped = faults >= reaction.fault_samples
        if status in ("OK", "SAMPLE_LATE", "SAMPLE_EARLY"):
            served = t
        assert (status == "SAFE_STOP") == stopped, (k, kind, status, faults)
        assert py.stopped == stopped
        np.testing.assert_allclose(py.fault_state, np.frombuffer(c.ffi.buffer(c.c.fault_state), float), rtol=1e-9,
                                   atol=1e-9)
        if kind != "repeated" and np.isfinite(t):
            clock = t


def test_the_safe_state_holds_until_reset(pair):
    py, c, samples = pair
    py.reset()
    fs = FAULT_STATE.names(Dims.sized(py.robot.joint_names, py.axis_names, 0, 0))
    t, q, qd, w = samples[0]
    py(t, q, qd, w)
    T = samples[1][0] - samples[0][0]
    for k in range(1, py.fault_reaction.fault_samples):
        with pytest.raises(hybrid.NonFiniteError) as err:
            py(k * T, q, qd, np.full(3, np.nan))
        assert np.isfinite(err.value.torque).all() and not py.stopped
    with pytest.raises(hybrid.SafeStopError) as entry:
        py(py.fault_reaction.fault_samples * T, q, qd, np.full(3, np.nan))
    np.testing.assert_array_equal(py.last["tau"], entry.value.torque)  # the torque applied, as C's c->tau
    for k in range(5):  # good samples do not end it
        with pytest.raises(hybrid.SafeStopError) as err:
            py((py.fault_reaction.fault_samples + 1 + k) * T, *samples[k][1:])
        assert err.value.status == "SAFE_STOP" and STATUS_CODES["SAFE_STOP"] == 11
    assert py.fault_state[fs.index("samples")] == 6
    py.reset()
    assert not py.stopped
    assert np.isfinite(py(*samples[0])).all()



def _held_states(py, c) -> tuple[bytes, bytes]:
    """Every state the safe state keeps between samples, Python's and C's, as bytes (bitwise)."""
    n = py.robot.n
    c_tau = np.frombuffer(c.ffi.buffer(c.c.tau), float)
    c_fault = np.frombuffer(c.ffi.buffer(c.c.fault_state), float)
    return (py.fault_state.tobytes() + py._last.tobytes() + np.float64(py._clock).tobytes(),
            c_fault.tobytes() + c_tau[:n].tobytes() + np.array([c.c.has_torque, c.c.t_last, c.c.has_clock]).tobytes())


@pytest.mark.parametrize("when", [0.0, -1.0, -3.5])
def test_no_time_passed_in_the_safe_state_changes_nothing(rate_pair, when):
    """In the safe state as in the law, a sample at which no time passed (repeated, or before the last) changes
    nothing, Python and C alike: its torque is the safe state's at that sample, rate-limited from the torque
    last written; else a burst of such samples (new measurements at an old time) walks the torque by the rate
    bound each, with no time passing."""
    py, c, samples = rate_pair
    n, T = py.robot.n, samples[1][0] - samples[0][0]
    rng = np.random.default_rng(int(-when * 10))
    py.reset()
    c.lib.fr_controller_reset(c.c)
    for k in range(2 + py.fault_reaction.fault_samples):
        t, q, qd, w = samples[k]
        w = np.resize(w, 6) if k < 2 else np.full(6, np.nan)
        status, tau = python_status(py, t, q, qd, w)
        code, tau_c = c.step(t, q, qd, w)
        assert c.name(code) == status
    assert status == "SAFE_STOP" and py.stopped
    clock, last = t, tau.copy()
    before = _held_states(py, c)
    for _ in range(20):  # each a new measurement, its hold torque far from the torque last written
        q_k, qd_k = q + rng.normal(0.0, 0.05, n), qd + rng.normal(0.0, 0.2, n)
        status, tau = python_status(py, clock + when * T, q_k, qd_k, w)
        code, tau_c = c.step(clock + when * T, q_k, qd_k, w)
        assert status == c.name(code) == "SAFE_STOP"
        np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
        assert np.all(np.abs(tau - last) <= RATE * (1 + 1e-12))
        assert _held_states(py, c) == before
    assert abs(tau - last).max() > 0.5 * RATE  # the bound binds: the torque would move on
    # the next sample on time advances the release by one sample, in both
    fs = FAULT_STATE.names(Dims.sized(py.robot.joint_names, py.axis_names, 0, 0))
    released = py.fault_state[fs.index("samples")]
    status, tau = python_status(py, clock + T, q, qd, w)
    code, tau_c = c.step(clock + T, q, qd, w)
    np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
    assert py.fault_state[fs.index("samples")] == released + 1
    np.testing.assert_allclose(py.fault_state, np.frombuffer(c.ffi.buffer(c.c.fault_state), float), rtol=1e-9)

def test_a_fault_shorter_than_the_count_is_served_as_before(pair):
    """A dropout of k refused samples is followed by a late one (timed from the last served): k + 1 faulted
    samples; below the count the law serves on, the count ends at the next sample on time."""
    py, _, samples = pair
    py.reset()
    T = samples[1][0] - samples[0][0]
    taus = [py(*samples[0])]
    k = py.fault_reaction.fault_samples - 1
    for i in range(1, k):
        with pytest.raises(hybrid.NonFiniteError) as err:
            py(i * T, *samples[i][1:3], np.full(3, np.nan))
        np.testing.assert_array_equal(err.value.torque, taus[0])  # the torque last written
    with pytest.raises(hybrid.SampleTimingError, match="late"):
        py(k * T, *samples[k][1:])
    assert py.fault_state[-3] == k and not py.stopped
    py((k + 1) * T, *samples[k + 1][1:])
    assert py.fault_state[-3] == 0 and not py.stopped


@pytest.mark.parametrize("gap", [1.4, 1.7, 2.0, 2.4, 2.6, 3.0, 40.0, 1e9, 1e300])
def test_a_gap_counts_the_samples_it_missed(pair, gap):
    """A faulted sample after a gap counts the sample instants it spans (those at or before the sample's time
    and half a period, counted one by one here),
    C and Python alike: a timestamp far ahead is a long fault at once, and the safe state then holds through
    every later sample, which its clock leaves behind; else a dropout after such a glitch was never counted."""
    py, c, samples = pair
    T, limit = samples[1][0] - samples[0][0], py.fault_reaction.fault_samples
    py.reset()
    c.lib.fr_controller_reset(c.c)
    for k in range(2):
        t, q, qd, w = _sample(samples, k, "ok", (k - 1) * T)
        assert python_status(py, t, q, qd, w)[0] == c.name(c.step(t, q, qd, w)[0]) == "OK"
    clock = t
    t, q, qd, w = _sample(samples, 2, "ok", clock)
    t = clock + gap * T
    missed = next((k for k in range(1, limit + 1) if clock + (k + 1) * T > t + T / 2), limit)
    status, tau = python_status(py, t, q, qd, w)
    code, tau_c = c.step(t, q, qd, w)
    assert status == c.name(code) == ("SAFE_STOP" if missed >= limit else "SAMPLE_LATE")
    assert py.fault_state[-3] == min(missed, limit) and py.stopped == (missed >= limit)
    np.testing.assert_allclose(py.fault_state, np.frombuffer(c.ffi.buffer(c.c.fault_state), float), rtol=1e-9)
    np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
    if missed < limit:
        return
    for k in range(3, 3 + 2 * limit):  # the clock as it was, the sensor lost: the safe state holds
        t, q, qd, w = _sample(samples, k, "nan_wrench", clock + (k - 3) * T)
        status, tau = python_status(py, t, q, qd, w)
        code, tau_c = c.step(t, q, qd, w)
        assert status == c.name(code) == "SAFE_STOP"
        np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
        assert np.isfinite(tau).all() and np.all(np.abs(tau) <= LIMIT)


def test_without_the_timing_check_every_faulted_sample_counts(pair):
    """With the timing check off the law serves every sample as one sample period, whatever its time, so
    every faulted sample counts, C and Python alike: a dropout after the clock jumped ahead (every later
    sample then before it) still ends in the safe state, after exactly ``fault_samples`` of them."""
    py, c, samples = pair
    T, limit = samples[1][0] - samples[0][0], py.fault_reaction.fault_samples
    tolerances = py.timing_tolerance, c.c.timing_tolerance
    py.timing_tolerance, c.c.timing_tolerance = None, -1.0
    try:
        for jump in (1e9, 0.0):  # the clock far ahead, and samples repeated at its time
            py.reset()
            c.lib.fr_controller_reset(c.c)
            t, q, qd, w = _sample(samples, 0, "ok", jump - T)
            assert python_status(py, t, q, qd, w)[0] == c.name(c.step(t, q, qd, w)[0]) == "OK"
            for k in range(1, limit + 1):
                t, q, qd, w = _sample(samples, k, "nan_wrench", (k - 1) * T if jump else -T)
                status = python_status(py, t, q, qd, w)[0]
                assert status == c.name(c.step(t, q, qd, w)[0])
                assert status == ("SAFE_STOP" if k == limit else "INPUT_NONFINITE")
                assert py.fault_state[-3] == k
    finally:
        py.timing_tolerance, c.c.timing_tolerance = tolerances


def _agree(py, c, samples, script) -> list[str]:
    """Run ``script`` (``(t in sample periods, kind, settings)``; settings, if any, set on both sides first:
    ``timing_tolerance`` None in Python is -1 in C) through both from a reset, the settings restored after;
    every status, torque and fault state equal. Returns the statuses."""
    T = samples[1][0] - samples[0][0]
    kept = {name: getattr(py, name) for name in ("timing_tolerance", "sample_time")}
    kept_c = {name: getattr(c.c, name) for name in ("timing_tolerance", "sample_time")}
    py.reset()
    c.lib.fr_controller_reset(c.c)
    statuses = []
    try:
        for k, (at, kind, settings) in enumerate(script):
            for name, value in (settings or {}).items():
                setattr(py, name, value)
                setattr(c.c, name, -1.0 if value is None else value)
            t, q, qd, w = _sample(samples, k, kind, at * T - T)
            status, tau = python_status(py, t, q, qd, w)
            code, tau_c = c.step(t, q, qd, w)
            assert c.name(code) == status, (k, status, c.name(code))
            np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
            np.testing.assert_allclose(py.fault_state, np.frombuffer(c.ffi.buffer(c.c.fault_state), float),
                                       rtol=1e-9, atol=1e-9)
            statuses.append(status)
    finally:
        for name, value in kept.items():
            setattr(py, name, value)
        for name, value in kept_c.items():
            setattr(c.c, name, value)
    return statuses


def test_the_gap_rule_holds_alike_where_the_timing_is_not_trusted(pair):
    """The gap counts its periods only with the timing checked and every number valid, C and Python alike:
    with the check off a timestamp far ahead counts one; a refused setting counts one whatever the gap; an
    invalid negative tolerance keeps the check's rule (a repeated sample counts nothing); and with the check
    off the safe state's clock moves forward only."""
    py, c, samples = pair
    limit = py.fault_reaction.fault_samples
    off = {"timing_tolerance": None}
    assert _agree(py, c, samples, [(0, "ok", off), (1e9, "nan_wrench", None)])[-1] == "INPUT_NONFINITE"
    assert py.fault_state[-3] == 1
    # a period too long for the stop (stop_time 0.04 s under two of 0.05 s): refused, counted once
    statuses = _agree(py, c, samples, [(0, "ok", None), (4, "ok", {"sample_time": 0.05})])
    assert statuses[-1] == "PARAMETER_INVALID" and py.fault_state[-3] == 1
    statuses = _agree(py, c, samples, [(0, "ok", None), *[(0, "ok", {"timing_tolerance": -0.5})] * (limit + 1)])
    assert set(statuses[1:]) == {"PARAMETER_INVALID"} and py.fault_state[-3] == 0
    script = [(0, "ok", off), *[(k, "nan_wrench", None) for k in range(1, limit + 1)], (-5, "ok", None),
              (limit + 1, "ok", {"timing_tolerance": 0.25}), (limit + 1, "ok", None), (limit + 2, "ok", None)]
    assert _agree(py, c, samples, script)[limit:] == ["SAFE_STOP"] * (len(script) - limit)


def test_a_tolerance_of_minus_one_is_refused_in_python(pair):
    """-1 is the standalone C's "no timing check"; a Controller's is None: a -1 set on it refuses the next
    sample (nothing changed), where it was taken as a tolerance that made every sample early."""
    py, _, samples = pair
    py.reset()
    py(*samples[0])
    kept = py.timing_tolerance
    try:
        py.timing_tolerance = -1.0
        with pytest.raises(hybrid.ParameterError, match="timing_tolerance"):
            py(*samples[1])
    finally:
        py.timing_tolerance = kept
    assert np.isfinite(py(*samples[1])).all()


def test_a_bad_fault_reaction_is_refused():
    for bad in ({"fault_samples": 0}, {"fault_samples": 2.5}, {"stop_time": 0.0}, {"unload_time": -1.0},
                {"stop_time": float("nan")}, {"fault_samples": True}):
        with pytest.raises(hybrid.HybridError, match="FaultReaction"):
            hybrid.FaultReaction(**bad)
    with pytest.raises(hybrid.HybridError, match="fault_reaction"):
        hybrid.Controller(hybrid.ur5(), hybrid.Sphere((0.4, 0.0, 0.0), 0.2), fault_reaction=3)


def _plant():
    try:
        import mujoco  # noqa: F401
    except ImportError:
        return "generated"
    return "mujoco"


@pytest.mark.parametrize("duration, change", [
    (0.2, {}), (0.5, {}),
    # a release that takes for ever: the hold acts in full from the entry, and the arm stops
    (0.5, {"fault_reaction": hybrid.FaultReaction(unload_time=1000.0)}),
    # an estimated normal started off: a velocity into the part at the entry presses no deeper
    (0.5, {"controller_surface": hybrid.EstimatedSurface(initial_normal=(0.0, 0.3, 1.0))}),
])
def test_a_long_sensor_dropout_ends_in_a_stop_without_impact(duration, change):
    """0.2 and 0.5 s of NaN wrench in contact at 20 N: the safe state stops the arm and releases the pressing;
    without a reaction (a count never reached) the last torque, held, lifts the tool and brings it back."""
    start = 1.0
    exp = hybrid.tracing_experiment(sensor=hybrid.Sensor(dropout_at=start, dropout_duration=duration), **change)
    done = hybrid.simulate(exp, _plant())
    N, Fd = done.output("N"), exp.force_reference.sampled(done.t)
    after = done.t >= start
    assert N[after].max() <= Fd[after].max() + 5.0
    # no impact: the contact force never rises again after the fault began
    assert np.all(np.diff(N[after]) <= 1e-3 * Fd.max())
    assert np.abs(done.qdot[-1]).max() < 0.01  # stopped
    if duration < 0.5 or change:
        return
    # the check above can fail: the same dropout served by the last torque for ever
    never = dataclasses.replace(exp, fault_reaction=hybrid.FaultReaction(fault_samples=10**9))
    held = hybrid.simulate(never, _plant())
    N = held.output("N")
    assert N[held.t >= start].min() == 0.0  # lifted off
    assert N[held.t >= start].max() > Fd.max() + 5.0  # and brought back with an impact


def test_a_dropout_loses_the_readings_in_its_window_only():
    from hybrid.simulation.sensing import SensorSignal

    T = 0.01
    signal = SensorSignal(hybrid.Sensor(dropout_at=0.05, dropout_duration=0.03), T)
    got = [signal(np.full(6, float(k))) for k in range(12)]
    lost = [k for k, g in enumerate(got) if np.isnan(g).all()]
    assert lost == [k for k in range(12) if 0.05 <= k * T < 0.08]
    assert all(np.array_equal(g, np.full(6, float(k))) for k, g in enumerate(got) if k not in lost)
    assert not hybrid.Sensor(dropout_duration=0.1).ideal
    for bad in ({"dropout_at": -0.1}, {"dropout_duration": float("nan")}, {"dropout_at": "soon"},
                {"dropout_duration": True}):
        with pytest.raises(hybrid.HybridError, match="dropout"):
            hybrid.Sensor(**bad)


@pytest.mark.parametrize("make, dropout", [(hybrid.tracing_experiment, (1.0, 0.5)),
                                           (hybrid.tracing_experiment, (1.0, 0.02)),
                                           (hybrid.paper_experiment, (0.8, 0.3))])
def test_the_compiled_loop_reacts_as_the_controller(make, dropout):
    """The compiled loop's fault reaction is the controller's: a run with a dropout (long enough for the safe
    state, and too short for it) equals the Python runner's within rounding. Rounding is measured, not
    assumed: at rest against the part in the safe state, sticking friction amplifies it, and the Python
    runner from a start one ulp away differs as much (the largest of three such starts: one alone may land
    closer than rounding lands elsewhere)."""
    exp = make(sensor=hybrid.Sensor(dropout_at=dropout[0], dropout_duration=dropout[1]))
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    nudged = []
    for joint in range(3 if exp.robot.n > 2 else 2):
        x0 = exp.initial_state()
        x0[joint] = np.nextafter(x0[joint], 1.0)
        nudged.append(run(exp, plant_for(exp, "generated"), exp.build_controller(), x0))

    def spread(a, b):
        return np.abs(np.asarray(a) - np.asarray(b)).max()

    for what in (lambda r: r.q, lambda r: r.output("N"), lambda r: r.tau):
        rounding = max(spread(what(r), what(python)) for r in nudged)
        assert spread(what(compiled), what(python)) <= 10 * rounding + 1e-9
    for name, value in python.metrics.items():
        if np.isfinite(value):
            tol = 10 * max(abs(r.metrics[name] - value) for r in nudged) + 1e-9 * max(1.0, abs(value))
            assert abs(compiled.metrics[name] - value) <= tol, name
    # the runs differ from one without the dropout by more than rounding (the checks above can fail)
    rounding = max(spread(r.output("N"), python.output("N")) for r in nudged)
    assert spread(compiled.output("N"), hybrid.simulate(make()).output("N")) > 100 * rounding + 1e-6


def _sampled_hold_radius(ratio: float) -> float:
    """The spectral radius of the safe state's hold on one joint of an exactly modelled arm, ``q'' = w`` with
    ``w = -q / tau_s^2 - 2 q' / tau_s`` held over each sample (zero-order hold), at ``T / tau_s = ratio``."""
    T = ratio  # tau_s = 1
    A = np.array([[1.0, T], [0.0, 1.0]])
    B = np.array([[T * T / 2], [T]])
    return float(np.abs(np.linalg.eigvals(A + B @ np.array([[-1.0, -2.0]]))).max())


def test_a_stop_shorter_than_two_samples_is_refused(pair):
    """The sampled hold is unstable at stop_time <= sample_time (the arm is thrown, not stopped): the Controller
    refuses a stop_time under two sample times, where the hold is stable, and the C refuses such a field."""
    assert _sampled_hold_radius(1.0) >= 1.0 > _sampled_hold_radius(0.5)
    robot, sphere = hybrid.ur5(), hybrid.Sphere((0.4, 0.0, 0.0), 0.2)
    for stop_time in (0.001, 0.01, 0.0199):
        with pytest.raises(hybrid.HybridError, match="two sample times"):
            hybrid.Controller(robot, sphere, sample_time=0.01, fault_reaction=hybrid.FaultReaction(stop_time=stop_time))
    hybrid.Controller(robot, sphere, sample_time=0.01, fault_reaction=hybrid.FaultReaction(stop_time=0.02))
    py, c, samples = pair
    c.lib.fr_controller_reset(c.c)
    t, q, qd, w = samples[0]
    good = c.c.stop_time
    try:
        c.c.stop_time = 1.5 * c.c.sample_time
        code, _ = c.step(t, q, qd, np.resize(w, 6))
        assert c.name(code) == "PARAMETER_INVALID"
    finally:
        c.c.stop_time = good
    assert c.name(c.step(t, q, qd, np.resize(w, 6))[0]) == "OK"


def test_the_shortest_stop_allowed_stops_the_arm():
    """At stop_time = two sample times the paper's arm, its sensor lost for good in contact, comes to rest."""
    exp = hybrid.paper_experiment(sensor=hybrid.Sensor(dropout_at=0.8, dropout_duration=10.0))
    exp = dataclasses.replace(exp, fault_reaction=hybrid.FaultReaction(stop_time=2 * exp.sample_time))
    ctrl = exp.build_controller()
    done = run(exp, plant_for(exp, "generated"), ctrl, exp.initial_state())
    assert ctrl.stopped and done.t[-1] >= exp.duration - exp.sample_time
    assert np.abs(done.qdot[-1]).max() < 0.01


def test_a_safe_state_entered_before_any_joint_position_stops_the_arm_where_it_is(pair):
    """Joint positions lost from the start (an encoder not yet read) until the safe state: no position is known
    to stop at, so the torque last written stays; the first finite positions are where the arm stops, not the
    zero configuration. Python and C alike; the hold's torque is then the one of a fault entered there."""
    py, c, samples = pair
    T = samples[1][0] - samples[0][0]
    n, lost = py.robot.n, py.fault_reaction.fault_samples
    tau0 = np.linspace(-3.0, 3.0, n)
    t, q, qd, w = samples[0]
    w = np.resize(w, 6)
    py.reset(torque=tau0)
    c.lib.fr_controller_reset(c.c)
    c.set_array("tau", tau0)
    c.c.has_torque = 1
    for k in range(lost):
        status, tau = python_status(py, k * T, np.full(n, np.nan), qd, w)
        code, tau_c = c.step(k * T, np.full(n, np.nan), qd, w)
        assert c.name(code) == status
        np.testing.assert_array_equal(tau, tau0)  # nothing known to stop at: the torque last written
        np.testing.assert_array_equal(tau_c, tau0)
    assert status == "SAFE_STOP"
    status, tau = python_status(py, lost * T, q, qd, w)
    code, tau_c = c.step(lost * T, q, qd, w)
    np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(py.fault_state, np.frombuffer(c.ffi.buffer(c.c.fault_state), float), rtol=1e-9)
    q_stop = py.fault_state[2 * n:3 * n]
    np.testing.assert_allclose(q_stop, q + py.fault_reaction.stop_time * qd, rtol=1e-12)
    # independently: a controller whose safe state is entered at these very positions holds them alike
    other = hybrid.Controller(py.robot, py.surface, gains=dict(zip(py.axis_names, py.gains)), torque_limit=LIMIT,
                              fault_reaction=py.fault_reaction)
    other.reset(torque=tau0)
    other(0.0, q, qd, w)
    for k in range(1, lost + 1):
        status_o, _ = python_status(other, k * T, q, qd, np.full(6, np.nan))
    assert status_o == "SAFE_STOP"
    np.testing.assert_allclose(other.fault_state[2 * n:3 * n], q_stop, rtol=1e-12)


def test_a_sample_time_that_makes_the_stop_too_short_refuses_the_sample(pair):
    """The stop_time's bound reads the sample time: changed at run time to more than half the stop_time, the
    sample is refused (PARAMETER_INVALID, the torque last written) in Python as in C; changed back, served."""
    py, c, samples = pair
    py.reset()
    c.lib.fr_controller_reset(c.c)
    T = py.sample_time
    first = python_status(py, *samples[0])
    assert first[0] == c.name(c.step(*samples[0][:3], np.resize(samples[0][3], 6))[0]) == "OK"
    longer = 0.6 * py.fault_reaction.stop_time
    py.sample_time = c.c.sample_time = longer
    try:
        t, q, qd, w = samples[1]
        status, tau = python_status(py, longer, q, qd, w)
        code, tau_c = c.step(longer, q, qd, np.resize(w, 6))
        assert status == c.name(code) == "PARAMETER_INVALID"
        np.testing.assert_array_equal(tau, first[1])
        np.testing.assert_allclose(tau_c, tau, rtol=1e-9, atol=1e-9)
    finally:
        py.sample_time = c.c.sample_time = T
    status, _ = python_status(py, T, *samples[1][1:])
    assert status == c.name(c.step(T, *samples[1][1:3], np.resize(samples[1][3], 6))[0]) != "PARAMETER_INVALID"
