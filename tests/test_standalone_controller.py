"""The controller as standalone C equals the Python Controller, sample for sample, and checks its calls.

Each case records a closed-loop run (``hybrid.simulate``), then feeds its samples (time, joint state,
the sensor's wrench) to both the Python :class:`hybrid.Controller` and the C that its ``generate``
wrote, compiled here with ``-std=c99 -Wall -Wextra -Werror -pedantic``: the torques agree to 1e-12
relative. The call's checks (non-finite inputs, samples off the clock, limits) are compared with
the Python controller's behaviour on the same samples.
"""

from __future__ import annotations

import re
import subprocess

import cffi
import numpy as np
import pytest

import hybrid

STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]


class CController:
    """A standalone controller compiled and loaded (cffi, ABI mode)."""

    def __init__(self, folder, prefix: str):
        header = (folder / f"{prefix}.h").read_text()
        lib = folder / f"lib{prefix}.so"
        subprocess.run(["gcc", *STRICT, "-O2", "-shared", "-fPIC", str(folder / f"{prefix}.c"), "-o", str(lib),
                        "-lm"], check=True, capture_output=True)
        ffi = cffi.FFI()
        body = header.split("*/", 1)[1]  # after the stamp
        body = "\n".join(line for line in body.splitlines()
                         if not re.match(r"\s*#(ifndef|endif|define \w+_H\b|include)", line))
        ffi.cdef(re.sub(r"/\*.*?\*/", "", body, flags=re.S))
        self.ffi, self.lib, self.prefix = ffi, ffi.dlopen(str(lib)), prefix
        self.c = ffi.new(f"{prefix}_controller *")
        self.nq = getattr(self.lib, f"{prefix.upper()}_NQ")
        getattr(self.lib, f"{prefix}_controller_init")(self.c)
        self.status_names = {getattr(self.lib, n): n.removeprefix(prefix.upper() + "_")
                             for n in dir(self.lib) if n.startswith(prefix.upper() + "_") and n.count("_") >= 1}

    def step(self, t, q, qd, wrench):
        tau = np.empty(self.nq)
        fp = self.ffi.from_buffer
        status = getattr(self.lib, f"{self.prefix}_controller_step")(
            self.c, float(t), fp("double[]", np.ascontiguousarray(q, float)),
            fp("double[]", np.ascontiguousarray(qd, float)), fp("double[]", np.ascontiguousarray(wrench, float)),
            fp("double[]", tau))
        return status, tau

    def name(self, status: int) -> str:
        return self.ffi.string(getattr(self.lib, f"{self.prefix}_status_name")(status)).decode()

    def set_array(self, field: str, values) -> None:
        arr = getattr(self.c, field)
        for i, v in enumerate(values):
            arr[i] = float(v)


def recorded_samples(exp, samples: int | None = None):
    """``(t, q, qd, wrench)`` at the control samples of a simulated run of ``exp``."""
    r = hybrid.simulate(exp)
    plant = exp.plant()
    nq, every = plant.nq, exp.steps_per_sample
    out = []
    for k in range(exp.n_samples if samples is None else samples):
        x = r.state[k * every]
        out.append((k * exp.sample_time, x[:nq].copy(), x[nq:2 * nq].copy(), plant.sensor_wrench(x)))
    return out


def compare(exp, tmp_path, name: str, samples: int | None = None) -> float:
    """The largest relative torque difference between the Python controller and its C over a run."""
    py = exp.build_controller()
    py.generate(tmp_path, name)
    c = CController(tmp_path, name)
    worst = 0.0
    for t, q, qd, wrench in recorded_samples(exp, samples):
        if py.path is not None:  # the caller's references: the desired point
            c.set_array("target", py._desired(t))
        tau_py = py(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0, c.name(status)
        worst = max(worst, float(np.max(np.abs(tau_c - tau_py)) / max(1.0, np.max(np.abs(tau_py)))))
    np.testing.assert_allclose(np.frombuffer(c.ffi.buffer(c.c.integrals), float), py.state.ravel(),
                               rtol=1e-12, atol=1e-14)
    return worst


@pytest.mark.parametrize("overrides", [
    {}, {"controller": "khatib"}, {"controller": "raibert_craig"}, {"controller": "fisher_mujtaba"},
    {"frame": "desired", "curvature": True}, {"curvature": True}])
def test_paper_arm_c_equals_python(tmp_path, overrides):
    exp = hybrid.paper_experiment(**overrides)
    assert compare(exp, tmp_path, "paper") < 1e-12


@pytest.mark.parametrize("overrides", [{}, {"controller": "raibert_craig"}])
def test_ur5_sphere_c_equals_python(tmp_path, overrides):
    exp = hybrid.tracing_experiment(duration=0.6, **overrides)
    assert compare(exp, tmp_path, "ur5") < 1e-12


def test_panda_posture_c_equals_python(tmp_path):
    exp = hybrid.panda_experiment(duration=0.4)
    assert exp.posture is not None
    assert compare(exp, tmp_path, "panda") < 1e-12


def test_position_error_c_equals_python(tmp_path):
    exp = hybrid.paper_experiment(duration=0.5, frame="desired")
    base = exp.build_controller()
    ctrl = hybrid.Controller(base.robot, exp.surface, gains=exp.gains, sample_time=exp.sample_time,
                             force_reference=exp.force_reference, velocity_reference=exp.speed_reference,
                             position_error=True, frame="desired", path=base.path)
    ctrl.generate(tmp_path, "pe")
    c = CController(tmp_path, "pe")
    for t, q, qd, wrench in recorded_samples(exp):
        c.set_array("target", ctrl._desired(t))
        tau_py = ctrl(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0
        np.testing.assert_allclose(tau_c, tau_py, rtol=1e-12, atol=1e-12 * np.max(np.abs(tau_py)))


# --------------------------------------------------------------------------- the call's checks


@pytest.fixture(scope="module")
def paper_pair(tmp_path_factory):
    exp = hybrid.paper_experiment()
    folder = tmp_path_factory.mktemp("paper_checks")
    py = exp.build_controller()
    py.generate(folder, "chk")
    return exp, folder, recorded_samples(exp, 30)


def _fresh(paper_pair, **settings):
    exp, folder, samples = paper_pair
    if not settings:
        return exp.build_controller(), CController(folder, "chk"), samples
    py = hybrid.Controller(exp.build_controller().robot, exp.surface, gains=exp.gains, sample_time=exp.sample_time,
                           force_reference=exp.force_reference, velocity_reference=exp.speed_reference, **settings)
    c = CController(folder, "chk")
    return py, c, samples


def _ok(c, py, t, q, qd, w):
    status, tau_c = c.step(t, q, qd, w)
    try:
        tau_py, name = py(t, q, qd, w), "OK"
    except hybrid.SampleTimingError as exc:
        tau_py, name = exc.torque, exc.status
    assert c.name(status) == name
    np.testing.assert_allclose(tau_c, tau_py, rtol=1e-12)
    return tau_c


@pytest.mark.parametrize("dt_factor, status", [(1.5, "SAMPLE_LATE"), (0.5, "SAMPLE_EARLY"), (0.0, "SAMPLE_REPEATED"),
                                               (-1.0, "SAMPLE_BACKWARDS"), (1.2, "OK"), (0.8, "OK")])
def test_sample_timing(paper_pair, dt_factor, status):
    py, c, samples = _fresh(paper_pair)
    T = paper_pair[0].sample_time
    for t, q, qd, w in samples[:5]:
        _ok(c, py, t, q, qd, w)
    z_before = py.state.copy()
    c_before = np.frombuffer(c.ffi.buffer(c.c.integrals), float).reshape(-1, 2).copy()
    t, q, qd, w = samples[5]
    t_off = samples[4][0] + dt_factor * T
    st, tau = c.step(t_off, q, qd, w)
    assert c.name(st) == status
    assert np.isfinite(tau).all()
    integrals = np.frombuffer(c.ffi.buffer(c.c.integrals), float).reshape(-1, 2)
    if status == "OK":
        py(t_off, q, qd, w)
        assert not np.array_equal(py.state, z_before)
    else:
        with pytest.raises(hybrid.SampleTimingError) as err:
            py(t_off, q, qd, w)
        assert err.value.status == status
        np.testing.assert_allclose(err.value.torque, tau, rtol=1e-12)
        np.testing.assert_array_equal(py.state, z_before)  # the integrals as they were
        np.testing.assert_array_equal(integrals, c_before)
    np.testing.assert_allclose(integrals, py.state, rtol=1e-12)
    # after a late or early sample the clock follows it: the next sample on time is accepted
    if status in ("SAMPLE_LATE", "SAMPLE_EARLY", "OK"):
        t2 = t_off + T
        assert c.name(c.step(t2, q, qd, w)[0]) == "OK"
        py(t2, q, qd, w)
        np.testing.assert_allclose(np.frombuffer(c.ffi.buffer(c.c.integrals), float), py.state.ravel(), rtol=1e-12)


def test_timing_check_off(paper_pair):
    py, _, samples = _fresh(paper_pair, timing_tolerance=None)
    t, q, qd, w = samples[0]
    py(t, q, qd, w)
    py(t, q, qd, w)  # a repeated sample is no error without the check
    with pytest.raises(hybrid.HybridError, match="timing_tolerance"):
        hybrid.Controller(py.robot, paper_pair[0].surface, timing_tolerance=1.5)


@pytest.mark.parametrize("bad", ["t", "q", "qd", "wrench"])
def test_nonfinite_input_holds_the_last_torque(paper_pair, bad):
    py, c, samples = _fresh(paper_pair)
    for t, q, qd, w in samples[:3]:
        last = _ok(c, py, t, q, qd, w)
    t, q, qd, w = samples[3]
    args = {"t": t, "q": q.copy(), "qd": qd.copy(), "wrench": w.copy()}
    if bad == "t":
        args["t"] = float("nan")
    else:
        args[bad][0] = np.inf
    z = np.frombuffer(c.ffi.buffer(c.c.integrals), float).copy()
    held = py.state.ravel().copy()
    st, tau = c.step(args["t"], args["q"], args["qd"], args["wrench"])
    assert c.name(st) == "INPUT_NONFINITE"
    np.testing.assert_array_equal(tau, last)
    np.testing.assert_array_equal(np.frombuffer(c.ffi.buffer(c.c.integrals), float), z)
    with pytest.raises(hybrid.HybridError):
        py(args["t"], args["q"], args["qd"], args["wrench"])
    # both hold their state; the two implementations agree within rounding
    np.testing.assert_array_equal(py.state.ravel(), held)
    np.testing.assert_allclose(py.state.ravel(), z, rtol=1e-12, atol=1e-18)
    # and the next sample on time goes on as if the bad one had not come
    t, q, qd, w = samples[4]
    st, _ = c.step(t, q, qd, w)
    assert c.name(st) == "SAMPLE_LATE"  # two sample times after the last good one


def test_singular_holds_the_last_torque(paper_pair):
    py, c, samples = _fresh(paper_pair)
    for t, q, qd, w in samples[:3]:
        last = _ok(c, py, t, q, qd, w)
    t, q, qd, w = samples[3]
    st, tau = c.step(t, np.array([q[0], 0.0]), qd, w)  # the elbow stretched
    assert c.name(st) == "SINGULAR"
    np.testing.assert_array_equal(tau, last)
    with pytest.raises(hybrid.SingularConfigurationError):
        py(t, np.array([q[0], 0.0]), qd, w)
    t, q, qd, w = samples[4]
    _ok(c, py, t, q, qd, w)  # the refused sample left the clock: this one is late, in both


def test_torque_limits_saturate_without_windup(paper_pair, tmp_path):
    exp, _, samples = paper_pair
    free = exp.build_controller()
    peak = np.max([np.abs(free(t, q, qd, w)) for t, q, qd, w in samples], axis=0)
    limit, step_limit = 0.5 * peak, 0.05 * peak
    py = hybrid.Controller(free.robot, exp.surface, gains=exp.gains, sample_time=exp.sample_time,
                           force_reference=exp.force_reference, velocity_reference=exp.speed_reference,
                           torque_limit=limit, torque_step_limit=step_limit)
    py.generate(tmp_path, "lim")
    c = CController(tmp_path, "lim")
    last, saturated = None, 0
    for t, q, qd, w in samples:
        z = py.state.copy()
        st, tau = c.step(t, q, qd, w)
        assert st == 0
        tau_py = py(t, q, qd, w)
        np.testing.assert_allclose(tau, tau_py, rtol=1e-12)
        assert (np.abs(tau) <= limit * (1 + 1e-15)).all()
        if last is not None:
            assert (np.abs(tau - last) <= step_limit * (1 + 1e-12)).all()
        if py.last["saturated"]:
            saturated += 1
            np.testing.assert_array_equal(py.state, z)  # no wind-up
        assert bool(c.c.saturated) == py.last["saturated"]
        last = tau
    assert saturated > 0


def test_limits_default_to_the_urdf_effort():
    robot = hybrid.ur5()
    ctrl = hybrid.Controller(robot, hybrid.Sphere((0.5, 0.0, 0.2), 0.2))
    np.testing.assert_array_equal(ctrl.torque_limit, robot.limits.effort)
    assert np.isinf(hybrid.Controller(hybrid.paper_arm(), hybrid.Circle((1.0, 0.0), 0.5)).torque_limit).all()
    for bad in (0.0, -1, "many", [1.0, 2.0]):
        with pytest.raises(hybrid.HybridError, match="torque_limit"):
            hybrid.Controller(robot, hybrid.Sphere((0.5, 0.0, 0.2), 0.2), torque_limit=bad)


def test_generated_bytes_are_deterministic_and_name_checked(tmp_path):
    ctrl = hybrid.paper_experiment().build_controller()
    a, b = tmp_path / "a", tmp_path / "b"
    ctrl.generate(a, "same")
    ctrl.generate(b, "same")
    for name in ("same.c", "same.h", "same.json"):
        assert (a / name).read_bytes() == (b / name).read_bytes()
    for bad in ("1abc", "a-b", "ünï", ""):
        with pytest.raises(hybrid.HybridError, match="cannot name C symbols"):
            ctrl.generate(tmp_path / "c", bad)
    other = hybrid.paper_experiment(KPv=60.0).build_controller()
    with pytest.raises(hybrid.HybridError, match="--force"):
        other.generate(a, "same")
    other.generate(a, "same", force=True)
    assert (a / "same.c").read_bytes() != (b / "same.c").read_bytes()


def test_a_non_finite_reference_leaves_the_clock_as_in_c(paper_pair):
    """The law failing on its references (a NaN the caller gives) leaves the clock in Python as in C: the
    next sample is timed from the last one served, late in both."""
    exp, folder, samples = paper_pair
    state = {"bad": False}

    def speed(t):
        return float("nan") if state["bad"] else 0.3

    py = hybrid.Controller(exp.build_controller().robot, exp.surface, gains=exp.gains, sample_time=exp.sample_time,
                           force_reference=exp.force_reference, velocity_reference=speed)
    py.generate(folder / "ref", "ref")
    c = CController(folder / "ref", "ref")
    for k, (t, q, qd, w) in enumerate(samples[:5]):
        state["bad"] = k == 3
        c.set_array("yd_extra", [speed(t), 0.0])  # the caller computes a reference given as code
        if state["bad"]:
            with pytest.raises(hybrid.HybridError, match="not finite"):
                py(t, q, qd, w)
            assert c.name(c.step(t, q, qd, w)[0]) == "NONFINITE"
        else:
            _ok(c, py, t, q, qd, w)  # sample 4 is late in both: the clock kept sample 2


def test_a_non_finite_torque_in_the_struct_is_discarded(paper_pair):
    _, folder, samples = paper_pair
    c = CController(folder, "chk")
    c.set_array("tau", [float("nan"), 1.0])
    c.c.has_torque = 1
    status, tau = c.step(*samples[0])
    assert c.name(status) == "OK" and np.isfinite(tau).all()


def test_a_urdf_effort_of_zero_is_no_limit(tmp_path):
    text = hybrid.UR5_URDF.read_text().replace('effort="150.0"', 'effort="0"', 1)
    urdf = tmp_path / "ur5.urdf"
    urdf.write_text(text)
    robot = hybrid.Robot.from_urdf(urdf, tip="tool0")
    ctrl = hybrid.Controller(robot, hybrid.Sphere((0.5, 0.0, 0.2), 0.15))
    assert np.isinf(ctrl.torque_limit[0]) and (ctrl.torque_limit[1:] > 0).all()
    with pytest.raises(hybrid.HybridError, match="finite sample time"):
        ctrl(10 ** 400, np.zeros(6), np.zeros(6), np.zeros(6))
