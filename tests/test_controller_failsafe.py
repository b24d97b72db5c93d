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
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
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
        elif before[k] is None:
            assert after[k] is None, k
        else:  # bitwise: -0.0 and NaN payloads too
            assert np.asarray(before[k]).tobytes() == np.asarray(after[k]).tobytes(), k


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


@pytest.mark.parametrize("T2", [0.004, 0.02])
def test_a_sample_time_changed_between_samples_is_the_period_in_python_as_in_c(live, T2):
    """The C's ``sample_time`` field is the period its step advances by; the controller's attribute is the same:
    changed in both after a few samples, the samples on time at the new period give the same torques and every
    state (the integrals, the sensor's filter, the estimate) alike."""
    py, c, samples = _fresh(live)
    T = py.sample_time
    _run(py, c, samples[:3])
    try:
        py.sample_time = c.c.sample_time = T2
        t = samples[2][0]
        for _, q, qd, w in samples[3:7]:
            t += T2
            _run(py, c, [(t, q, qd, w)])
            now_py, now_c = python_state(py), c_state(c)
            for name in ("integrals", "filter", "estimate"):
                np.testing.assert_allclose(now_py[name], now_c[name], rtol=1e-12, atol=1e-12, err_msg=name)
    finally:
        py.sample_time = T


# --------------------------------------------------------------------------- parameters that cannot lift a limit

NAN = float("nan")


def _field(c, name: str, index: int | None, value: float) -> None:
    if index is None:
        setattr(c.c, name, value)
    else:
        getattr(c.c, name)[index] = value


@pytest.mark.parametrize("name, index, value", [
    ("limits", 0, NAN), ("limits", 1, -50.0), ("limits", 6, NAN), ("limits", 7, -1.0), ("limits", 2, np.inf),
    ("timing_tolerance", None, NAN), ("timing_tolerance", None, -0.25), ("singular_tol", None, NAN),
    ("integral_limit", None, NAN), ("integral_limit", None, -1.0), ("sample_time", None, 0.0),
    ("curvature", None, 0.5), ("t_last", None, NAN), ("sensor", 23, NAN), ("sensor", 23, "nyquist"),
    ("gains", 0, NAN), ("posture", 8, -1.0), ("selection", 0, 2.0), ("robot", 0, np.inf)])
def test_an_invalid_parameter_refuses_the_sample(live, name, index, value):
    """Each run-time field a caller may change: a value outside its check refuses the sample in C, the
    torque the last one written (within the last valid limits) and nothing changed; set back, it runs."""
    py, c, samples = _fresh(live)
    _run(py, c, samples[:3])
    T = c.c.sample_time
    if value == "nyquist":
        value = 0.5 / T  # the Nyquist frequency itself: the filter's pole on the unit circle
    old = getattr(c.c, name) if index is None else getattr(c.c, name)[index]
    _field(c, name, index, value)
    before = c_state(c)
    for _ in range(2):
        st, tau = c.step(*samples[3])
        assert c.name(st) == "PARAMETER_INVALID"
        np.testing.assert_array_equal(tau, before["tau"])
        assert_same(before, c_state(c))
    _field(c, name, index, old)
    st, tau = c.step(*samples[3])
    assert c.name(st) == "OK"


def test_a_valid_change_between_samples_is_served(live):
    """The checks refuse what is invalid only: a tighter limit and a lower cutoff are taken at once."""
    py, c, samples = _fresh(live)
    _run(py, c, samples[:3])
    c.c.limits[0] = 1.0
    c.c.sensor[23] = 5.0
    st, tau = c.step(*samples[3])
    assert c.name(st) == "OK" and abs(tau[0]) <= 1.0


def test_python_refuses_a_setting_changed_to_an_invalid_value(live):
    py, c, samples = _fresh(live)
    _run(py, c, samples[:3])
    before = python_state(py)
    for name, value in (("timing_tolerance", NAN), ("singular_tol", -1.0), ("sample_time", NAN)):
        old = getattr(py, name)
        setattr(py, name, value)
        with pytest.raises(hybrid.ParameterError, match=name) as err:
            py(*samples[3])
        assert err.value.status == "PARAMETER_INVALID"
        np.testing.assert_array_equal(err.value.torque, before["last_torque"][:-1])
        assert_same(before, python_state(py))
        setattr(py, name, old)
    # the arrays the compiled step reads change only through the checks: they are read-only
    with pytest.raises(ValueError):
        py.step_inputs()["limits"][0] = NAN
    with pytest.raises(hybrid.HybridError, match="Nyquist"):
        py.set_wrench_sensor(hybrid.WrenchSensor(cutoff=0.5 / py.sample_time))
    _run(py, c, samples[3:4])  # nothing of it changed the controller



@pytest.mark.parametrize("name, value", [("torque_limit", 1.0), ("torque_step_limit", 0.1), ("integral_limit", 0.0)])
def test_a_bound_assigned_after_construction_is_refused_not_ignored(paper, name, value):
    """The compiled step holds the bounds it was built with: one assigned later (a tighter torque limit) would be
    read back but not applied. It is refused, and the torques are a controller's built with the old bound."""
    exp, _, samples = paper
    ctrl, twin = exp.build_controller(), exp.build_controller()
    built = getattr(ctrl, name)
    with pytest.raises(hybrid.HybridError, match=name):
        setattr(ctrl, name, value)
    if isinstance(built, np.ndarray):
        with pytest.raises(ValueError):  # nor changed in place: the array is read-only
            getattr(ctrl, name)[0] = value
    np.testing.assert_array_equal(getattr(ctrl, name), built)
    for sample in samples[:4]:
        np.testing.assert_array_equal(ctrl(*sample), twin(*sample))
    # a controller built with the bound applies it
    tight = hybrid.Controller(ctrl.robot, exp.surface, gains=exp.gains, sample_time=exp.sample_time,
                              force_reference=exp.force_reference, velocity_reference=exp.speed_reference,
                              **{name: value})
    torques = np.array([tight(*sample) for sample in samples[:4]])
    if name == "torque_limit":
        assert np.abs(torques).max() <= value
    elif name == "torque_step_limit":
        assert np.abs(np.diff(torques, axis=0)).max() <= value * (1 + 1e-12)


def test_python_refuses_invalid_parameters_at_construction(live):
    py = live[0]
    for kw, match in ((dict(torque_limit=NAN), "torque_limit"), (dict(torque_limit=-1.0), "torque_limit"),
                      (dict(torque_step_limit=NAN), "torque_step_limit"), (dict(timing_tolerance=NAN), "timing"),
                      (dict(singular_tol=NAN), "singular_tol"), (dict(integral_limit=NAN), "integral_limit"),
                      (dict(integral_limit=-1.0), "integral_limit"),
                      (dict(wrench_sensor=hybrid.WrenchSensor(cutoff=50.0)), "Nyquist")):
        with pytest.raises(hybrid.HybridError, match=match):
            hybrid.Controller(py.robot, py.surface, sample_time=0.01, **kw)


# --------------------------------------------------------------------------- the property

DBL_MAX = np.finfo(float).max
#: the statuses whose torque is the law's at the sample (within the limits); the others hold the last one
LAW = ("OK", "SAMPLE_LATE", "SAMPLE_EARLY", "SAMPLE_REPEATED", "SAMPLE_BACKWARDS")
#: numbers a caller may give by accident, and ordinary ones
ANY = st.one_of(st.sampled_from([NAN, np.inf, -np.inf, -1.0, -0.0, 0.0, 1e-300, 0.3, 0.99, 1.0, 1e300, DBL_MAX]),
                st.floats(-1e3, 1e3), st.floats(allow_nan=True, allow_infinity=True))


#: valid values of each parameter the property draws (None: the Controller's "none" or "off")
GOOD = {"torque_limit": st.one_of(st.floats(0.01, 500.0), st.just(np.inf), st.just(DBL_MAX)),
        "torque_step_limit": st.one_of(st.floats(0.01, 50.0), st.just(DBL_MAX), st.none()),
        "timing_tolerance": st.one_of(st.floats(0.01, 0.9), st.none()),
        "integral_limit": st.one_of(st.floats(0.0, 1e3), st.none()),
        "singular_tol": st.floats(0.0, 0.01)}


@pytest.fixture(scope="module")
def paper(tmp_path_factory):
    from test_standalone_controller import recorded_samples

    exp = hybrid.paper_experiment()
    folder = tmp_path_factory.mktemp("failsafe_paper")
    exp.build_controller().generate(folder, "pp")
    return exp, CController(folder, "pp"), recorded_samples(exp, 12)


def _c_valid(limits, tol, ilim, stol) -> bool:
    """The standalone C's rule, written out: limits and the anti-windup limit finite and >= 0, the timing
    tolerance in [0, 1) or -1 (off), the singular tolerance in [0, 1)."""
    fin = all(np.isfinite(v) for v in (*limits, ilim))
    return fin and min(*limits, ilim) >= 0 and (tol == -1 or 0 <= tol < 1) and 0 <= stol < 1


def _python(py, t, q, qd, w):
    """``(status, torque)`` of the Python controller: its torque, or the error's (None: it has none)."""
    try:
        return "OK", py(t, q, qd, w)
    except (hybrid.SampleTimingError, hybrid.ParameterError, hybrid.SafeStopError) as err:
        return err.status, err.torque
    except hybrid.HybridError:
        return "REFUSED", None


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_random_parameters_and_calls_never_lift_a_limit(paper, data):
    exp, c, samples = paper
    nq = 2
    # most draws valid, some of the parameters anything at all
    broken = data.draw(st.sets(st.sampled_from(sorted(GOOD)), max_size=2), "broken")

    def drawn(name):
        return data.draw(st.one_of(st.none(), ANY) if name in broken else GOOD[name], name)

    tau_max = [drawn("torque_limit") for _ in range(nq)]
    rate_max = [drawn("torque_step_limit") for _ in range(nq)]
    tol, ilim, stol = drawn("timing_tolerance"), drawn("integral_limit"), drawn("singular_tol")
    stol = 1e-3 if stol is None else stol
    try:
        py = hybrid.Controller(exp.build_controller().robot, exp.surface, gains=exp.gains,
                               sample_time=exp.sample_time, force_reference=exp.force_reference,
                               velocity_reference=exp.speed_reference, torque_limit=tau_max,
                               torque_step_limit=rate_max, timing_tolerance=tol, integral_limit=ilim,
                               singular_tol=stol)
    except hybrid.HybridError:
        py = None
    c.c = c.ffi.new("pp_controller *")
    c.lib.pp_controller_init(c.c)
    generated = np.frombuffer(c.ffi.buffer(c.c.limits), float).copy()  # the safe state's, where ours are refused
    if py is not None:  # the C configured as the Python controller (generate writes these numbers)
        limits = py.step_inputs()["limits"]
        c_tol, c_ilim = -1.0 if py.timing_tolerance is None else py.timing_tolerance, py.step_inputs()["options"][3]
    else:  # the numbers as given (None is the C's own "off")
        limits = [DBL_MAX if v is None else v for v in (*tau_max, *rate_max)]
        c_tol, c_ilim = -1.0 if tol is None else tol, 1e300 if ilim is None else ilim
    c.set_array("limits", limits)
    c.c.timing_tolerance, c.c.integral_limit, c.c.singular_tol = c_tol, c_ilim, stol
    valid = _c_valid(limits, c_tol, c_ilim, stol)
    if py is not None:
        assert valid  # what Python accepts, the C accepts
    T, t_prev = exp.sample_time, 0.0
    for k in range(8):
        t_next = data.draw(st.sampled_from([t_prev + T, t_prev + T, t_prev, t_prev - T, t_prev + 0.5 * T,
                                            t_prev + 3 * T, NAN, np.inf, 1e300]), "t")
        _, q, qd, w = samples[k]
        q, qd, w = q.copy(), qd.copy(), w.copy()
        where = data.draw(st.sampled_from(["", "q", "qd", "w"]), "bad input")
        if where:
            {"q": q, "qd": qd, "w": w}[where][0] = data.draw(st.sampled_from([NAN, np.inf, 1e300]))
        last, had = np.frombuffer(c.ffi.buffer(c.c.tau), float).copy(), bool(c.c.has_torque)
        st_c, tau = c.step(t_next, q, qd, w)
        name = c.name(st_c)
        assert np.isfinite(tau).all(), name
        if not valid:
            assert name in ("PARAMETER_INVALID", "SAFE_STOP")
        if name == "SAFE_STOP":  # after five faulted samples: within the limits (the generated ones where ours
            # are refused), rate-limited from the torque last written
            bounds = np.asarray(limits if valid else generated)
            assert (np.abs(tau) <= bounds[:nq]).all()
            with np.errstate(over="ignore"):
                assert (np.abs(tau - last) <= bounds[nq:] * (1 + 1e-12) + 1e-12 * np.abs(last)).all() or not had
        elif name in LAW:
            assert valid
            assert (np.abs(tau) <= np.asarray(limits[:nq])).all()
            if had:
                with np.errstate(over="ignore"):  # DBL_MAX: no limit
                    bound = np.asarray(limits[nq:]) * (1 + 1e-12) + 1e-12 * np.abs(last)
                assert (np.abs(tau - last) <= bound).all()
        else:
            np.testing.assert_array_equal(tau, last)  # the torque last written
        if py is not None:
            name_py, tau_py = _python(py, t_next, q, qd, w)
            if name in (*LAW, "SAFE_STOP") or name_py in (*LAW, "SAFE_STOP"):
                assert name_py == name
                np.testing.assert_allclose(tau, tau_py, rtol=1e-12, atol=1e-12 * max(1.0, np.abs(tau).max()))
            else:
                assert name_py == "REFUSED", (name, name_py)
        if name in LAW and name not in ("SAMPLE_REPEATED", "SAMPLE_BACKWARDS"):
            t_prev = t_next
