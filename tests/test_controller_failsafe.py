"""A control step that fails safe: a sample at which no time passed, or that is refused, changes nothing.

One controller with every state of the step live (the loops' integrals, the torque last written, a
force/torque sensor's filter, an estimated surface's normal, the sample clock) runs as the Python
:class:`hybrid.Controller` and as the standalone C its ``generate`` wrote. After a few samples on time,
a sample repeated (the same ``t``), one backwards, and refused ones (a complex or non-finite wrench, a
singular pose) must leave every state bitwise as it was, in both; the C's and Python's torques agree.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_standalone_controller import CController

import hybrid
from hybrid.spec.controller_step import CONTROLLER_STEP
from hybrid.spec.interfaces import STATE

#: the torque step limit [N m per sample]: loose enough that the samples on time are not bounded by it
RATE = 200.0
#: the C struct's fields that hold the step's state between samples
C_STATE = ("integrals", "filter", "estimate", "tau", "has_torque", "t_last", "has_clock", "a", "y", "f",
           "contact_wrench", "saturated")


@pytest.fixture(scope="module")
def live(tmp_path_factory):
    """A UR5 controller whose every state advances, its C, and recorded samples ``(t, q, qd, reading)``."""
    exp = hybrid.tracing_experiment(duration=0.1)
    base = exp.build_controller()
    py = hybrid.Controller(base.robot, hybrid.EstimatedSurface(initial_normal=(0.0, 0.3, 1.0)), gains=exp.gains,
                           wrench_sensor=hybrid.WrenchSensor(cutoff=15.0, order=2), torque_step_limit=RATE)
    folder = tmp_path_factory.mktemp("failsafe")
    py.generate(folder, "fs")
    r, plant = hybrid.simulate(exp), exp.plant()
    samples = []
    for k in range(8):
        x = r.state[k * exp.steps_per_sample]
        samples.append((k * exp.sample_time, x[:6].copy(), x[6:12].copy(), plant.sensor_wrench(x)))
    return py, folder, samples


def _fresh(live):
    py, folder, samples = live
    py.reset()
    return py, CController(folder, "fs"), samples


def python_state(py) -> dict:
    """Every state the Python controller keeps between samples (copies), the clock and the last sample."""
    held = {name: py._held[py._at[name]].copy() for name in CONTROLLER_STEP.named(STATE)}
    last = py.last
    return {**held, "clock": py._clock, "last": None if last is None else
            {k: np.asarray(v).copy() for k, v in last.items() if v is not None}}


def c_state(c) -> dict:
    out = {}
    for name in C_STATE:
        value = getattr(c.c, name)
        out[name] = (np.frombuffer(c.ffi.buffer(value), float).copy() if isinstance(value, c.ffi.CData)
                     else value)
    return out


def assert_same(before: dict, after: dict) -> None:
    assert before.keys() == after.keys()
    for k in before:
        if isinstance(before[k], dict):
            assert_same(before[k], after[k])
        elif isinstance(before[k], np.ndarray):
            assert before[k].tobytes() == after[k].tobytes(), k  # bitwise: -0.0 and NaN payloads too
        else:
            assert before[k] == after[k], k


def _run(py, c, samples):
    for t, q, qd, w in samples:
        tau = py(t, q, qd, w)
        status, tau_c = c.step(t, q, qd, w)
        assert c.name(status) == "OK"
        np.testing.assert_allclose(tau_c, tau, rtol=1e-12, atol=1e-12 * np.abs(tau).max())


def test_every_state_is_live(live):
    """The check below can fail: samples on time move each state."""
    py, c, samples = _fresh(live)
    _run(py, c, samples[:2])
    before_py, before_c = python_state(py), c_state(c)
    _run(py, c, samples[2:3])
    after_py, after_c = python_state(py), c_state(c)
    for k in ("integrals", "last_torque", "filter", "estimate"):
        assert before_py[k].tobytes() != after_py[k].tobytes(), k
    for k in ("integrals", "filter", "estimate", "tau", "t_last"):
        assert np.asarray(before_c[k]).tobytes() != np.asarray(after_c[k]).tobytes(), k


@pytest.mark.parametrize("when, status", [(0.0, "SAMPLE_REPEATED"), (-0.5, "SAMPLE_BACKWARDS")])
def test_no_time_passed_nothing_changes(live, when, status):
    py, c, samples = _fresh(live)
    _run(py, c, samples[:4])
    T = samples[1][0] - samples[0][0]
    t = samples[3][0] + when * T
    _, q, qd, w = samples[4]  # a new measurement at an old time
    before_py, before_c = python_state(py), c_state(c)
    for _ in range(2):  # twice: the second call sees the same state again
        with pytest.raises(hybrid.SampleTimingError) as err:
            py(t, q, qd, w)
        st, tau_c = c.step(t, q, qd, w)
        assert err.value.status == status and c.name(st) == status
        assert_same(before_py, python_state(py))
        assert_same(before_c, c_state(c))
        # the torque is the law's at this sample, within the limits: rate-limited from the torque last written
        np.testing.assert_allclose(tau_c, err.value.torque, rtol=1e-12, atol=1e-12)
        assert np.all(np.abs(tau_c - before_c["tau"]) <= RATE * (1 + 1e-12))
    # the next sample on time is served as if the repeated one had not come
    t, q, qd, w = samples[4]
    _run(py, c, [(t, q, qd, w)])


@pytest.mark.parametrize("bad", ["complex wrench", "nan wrench", "inf q", "singular"])
def test_a_refused_sample_changes_nothing(live, bad):
    py, c, samples = _fresh(live)
    _run(py, c, samples[:4])
    t, q, qd, w = samples[4]
    if bad == "complex wrench":
        w_py, w_c = w.astype(complex) + 1e-3j, None  # C takes doubles only
    elif bad == "nan wrench":
        w_py = w_c = np.where(np.arange(6) == 2, np.nan, w)
    elif bad == "inf q":
        q = np.where(np.arange(6) == 0, np.inf, q)
        w_py = w_c = w
    else:  # the UR5 stretched out: its wrist singular
        q, w_py, w_c = np.zeros(6), w, w
    before_py, before_c = python_state(py), c_state(c)
    for _ in range(2):
        with pytest.raises(hybrid.HybridError) as err:
            py(t, q, qd, w_py)
        assert not isinstance(err.value, hybrid.SampleTimingError)
        assert_same(before_py, python_state(py))
        if w_c is not None:
            st, tau_c = c.step(t, q, qd, w_c)
            assert c.name(st) in ("INPUT_NONFINITE", "SINGULAR", "NONFINITE")
            np.testing.assert_array_equal(tau_c, before_c["tau"])  # the torque last written
            assert_same(before_c, c_state(c))
    # the clock did not move: the next sample is two sample times after the last one served, late in both
    t, q, qd, w = samples[5]
    with pytest.raises(hybrid.SampleTimingError) as err:
        py(t, q, qd, w)
    st, tau_c = c.step(t, q, qd, w)
    assert err.value.status == c.name(st) == "SAMPLE_LATE"
    np.testing.assert_allclose(tau_c, err.value.torque, rtol=1e-12, atol=1e-12)
