"""The compiled closed loop (runs as SIMD lanes) against the Python runner, and its vector math
against the C library."""

from __future__ import annotations

import math

import cffi
import numpy as np
import pytest
import sympy as sp
from hybrid.codegen.kernel import Arg, Kernel
from hybrid.codegen.lanes import INCLUDE, lanes_function, libm_maps

import hybrid
from hybrid import metrics
from hybrid.control.controller import Controller
from hybrid.native import loader
from hybrid.native.compiler import compiler, flags
from hybrid.plants.planar import PlanarPlant
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import run

CASES = {
    "paper": {},
    "plane": {"surface": hybrid.Plane((0.3, 0.0), (-1.0, 0.0)), "start_point": (0.3, 0.1)},
    "khatib": {"controller": "khatib", "model_error": 0.2},
    "raibert_craig": {"controller": "raibert_craig"},
    "friction": {"contact": hybrid.Contact(friction=0.35)},
    # (friction 0.35 at 0.05 m/s nearly sticks: RK4 at this step is then so sensitive that rounding
    # differences between two correct programs grow to 1e-4; a sweep and simulate share one program)
    "steps_down": {"F_d": hybrid.Step(12.0, 6.0, 0.4), "v_d": hybrid.Step(0.15, 0.05, 0.9)},
}


def _experiment(case: str):
    return hybrid.paper_experiment(duration=1.2, **CASES[case])


@pytest.mark.parametrize("case", sorted(CASES))
def test_compiled_runs_equal_the_python_runner(case):
    exp = _experiment(case)
    prepared = closed_loop.prepare(exp)
    assert prepared is not None
    got = closed_loop.run([prepared], record=True)[0]
    ref = run(exp, PlanarPlant(exp), Controller.from_experiment(exp), exp.initial_state())
    assert got.status == 0 and got.failed_sample == -1
    scale = np.abs(ref.state).max(axis=0) + 1e-3
    assert np.abs((got.states - ref.state) / scale).max() < 1e-7
    assert np.abs(got.taus - ref.tau).max() < 1e-6 * np.abs(ref.tau).max()
    for name, value in ref.metrics.items():
        if isinstance(value, float) and math.isnan(value):
            assert math.isnan(got.metrics[name]), name
        else:
            assert got.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10), name


@pytest.mark.parametrize("make", [lambda: _experiment("raibert_craig"),
                                  lambda: hybrid.tracing_experiment(duration=0.3, controller="khatib")])
def test_the_loops_output_record_is_the_plants_own(make):
    """The output record the compiled loop writes (with each step's first stage) equals, state for
    state, the record the plant's own unit computes from the recorded states (the committed SymPy
    unit for the paper's arm; the plant unit of the 3-D experiment), within rounding of each column."""
    exp = make()
    res = hybrid.simulate(exp)
    plant = exp.plant()
    assert res.record["outputs"] == plant.record["outputs"]
    want = plant.outputs(res.state)
    assert res.outputs.shape == want.shape and np.isfinite(res.outputs).all()
    scale = np.abs(want).max(axis=0) + 1e-12
    assert np.abs((res.outputs - want) / scale).max() < 1e-11


def test_a_stopped_runs_output_record_is_there_wherever_its_state_is():
    """A run its controller stops (a pose below a high singular_tol) records its output wherever it
    records its state, alone and in lanes, as the plant computes it there; NaN after."""
    from hybrid import sweeps

    exp = sweeps.apply(hybrid.paper_experiment(duration=2.0), {"singular_tol": 0.5})
    prepared = closed_loop.prepare(exp)
    for got in (closed_loop.run([prepared], record=True)[0], closed_loop.run([prepared] * 3, record=True)[1]):
        assert got.status != 0
        kept = np.isfinite(got.states).all(axis=1)
        assert 0 < kept.sum() < len(kept)
        np.testing.assert_array_equal(np.isfinite(got.outputs).all(axis=1), kept)
        want = exp.plant().outputs(got.states[kept])
        scale = np.abs(want).max(axis=0) + 1e-12
        assert np.abs((got.outputs[kept] - want) / scale).max() < 1e-11


@pytest.mark.parametrize("overrides", [{}, {"controller": "khatib", "contact": hybrid.Contact(friction=0.3)}])
def test_the_3d_experiment_in_c_equals_the_python_runner(overrides):
    """The UR5 on the sphere (conventions §10): the 6-joint plant and six-axis controller as lanes."""
    from hybrid.plants.rigid_body import RigidBodyPlant

    exp = hybrid.tracing_experiment(duration=0.8, **overrides)
    got = closed_loop.run([closed_loop.prepare(exp)], record=True)[0]
    plant = RigidBodyPlant(exp)
    ref = run(exp, plant, Controller.from_experiment(exp), exp.initial_state())
    assert got.status == 0
    assert np.abs((got.states - ref.state) / (np.abs(ref.state).max(axis=0) + 1e-3)).max() < 1e-7
    for name, value in ref.metrics.items():
        assert got.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name


#: runs whose metrics' windows open and close at every kind of place: between samples, among a sample's
#: rows, at a first touch before the force step and after it, a force step after the speed step
WINDOWS = {
    "steps_down": {"F_d": hybrid.Step(12.0, 6.0, 0.4), "v_d": hybrid.Step(0.15, 0.05, 0.9)},
    "steps_among_rows": {"F_d": hybrid.Step(10.0, 20.0, 0.40037), "v_d": hybrid.Step(0.3, 0.6, 1.00513)},
    "touch_before_the_step": {"start_gap": 0.003, "approach_speed": 0.05},
    "touch_unsettled": {"start_gap": 0.003, "approach_speed": 0.05, "F_d": hybrid.Step(10.0, 20.0, 0.09)},
    "touch_after_the_step": {"start_gap": 0.01, "approach_speed": 0.02, "F_d": hybrid.Step(5.0, 12.0, 0.30011),
                             "duration": 1.5},
    "force_step_last": {"F_d": hybrid.Step(10.0, 15.0, 0.90123), "v_d": hybrid.Step(0.3, 0.5, 0.5)},
}


@pytest.mark.parametrize("case", sorted(WINDOWS))
def test_metrics_in_c_equal_the_numpy_definitions_on_the_same_record(case):
    exp = hybrid.paper_experiment(**{"duration": 1.2, **WINDOWS[case]})
    got = closed_loop.run([closed_loop.prepare(exp)], record=True)[0]
    plant = PlanarPlant(exp)
    record = plant.outputs(got.states)
    t = np.arange(len(got.states)) * exp.integration_step
    col = {name: record[:, i] for i, name in enumerate(plant.record["outputs"])}
    ref = metrics(t, col["Fc_n"], col["v_t"], exp.force_reference.sampled(t), exp.speed_reference.sampled(t),
                  force_step=exp.force_reference, speed_step=exp.speed_reference, penetration=col["penetration"],
                  contact_force=col["N"], tau=got.taus)
    assert ref.keys() == got.metrics.keys()
    for name, value in ref.items():
        assert (math.isnan(value) and math.isnan(got.metrics[name])) or \
            got.metrics[name] == pytest.approx(value, rel=1e-9, abs=1e-12), name


def test_lanes_do_not_depend_on_their_neighbours_and_a_stopped_run_stops_alone():
    """Nineteen runs (more than one group of lanes, the last one partly filled), one diverging: each
    run's numbers are bitwise the same beside other neighbours, and equal its own run alone (the
    build for one run at a time) within rounding; the diverging one reports where it stopped."""
    exps = [hybrid.paper_experiment(duration=0.6, model_error=m, contact=hybrid.Contact(friction=f))
            for m in (0.0, 0.15, 0.3) for f in (0.0, 0.1, 0.2, 0.3, 0.35, 0.4)]
    exps.insert(7, hybrid.paper_experiment(duration=0.6, model_error=5.0, allow_unstable=True))
    prepared = [closed_loop.prepare(e) for e in exps]
    together = closed_loop.run(prepared, record=True)
    reordered = closed_loop.run(prepared[::-1], record=True)[::-1]  # other lanes, other neighbours
    for i, p in enumerate(prepared):
        other = reordered[i]
        assert (other.status, other.failed_sample) == (together[i].status, together[i].failed_sample)
        np.testing.assert_array_equal(other.states, together[i].states)  # NaN where NaN
        np.testing.assert_array_equal(other.taus, together[i].taus)
        assert other.metrics == pytest.approx(together[i].metrics, rel=0, abs=0, nan_ok=True)
        alone = closed_loop.run([p], record=True)[0]  # the build for one run at a time
        assert alone.status == together[i].status and alone.failed_sample == together[i].failed_sample
        np.testing.assert_allclose(together[i].states, alone.states, rtol=1e-12, atol=1e-15)  # NaN where NaN
        np.testing.assert_allclose(together[i].outputs, alone.outputs, rtol=1e-12, atol=1e-15)
        if alone.status == 0:
            assert np.isfinite(alone.states).all() and np.isfinite(alone.taus).all()
            for name, value in alone.metrics.items():
                assert together[i].metrics[name] == pytest.approx(value, rel=1e-12, abs=1e-15, nan_ok=True)
    stopped = together[7]
    assert stopped.status != 0 and 0 <= stopped.failed_sample < exps[7].n_samples
    assert all(math.isnan(v) for v in stopped.metrics.values())
    # its record stops being finite within the sample where it stopped, and stays NaN (no restarted state)
    k, m = stopped.failed_sample, exps[7].steps_per_sample
    first = np.flatnonzero(np.isnan(stopped.states).any(axis=1))[0]
    assert k * m <= first <= (k + 1) * m and np.isfinite(stopped.states[:first]).all()
    assert np.isnan(stopped.states[first:]).all() and np.isnan(stopped.taus[first:]).all()
    with pytest.raises(hybrid.SimulationError) as info:
        hybrid.simulate(exps[7])
    sample_time = exps[7].sample_time
    assert abs(info.value.time - stopped.failed_sample * sample_time) <= sample_time + 1e-12
    assert all(o.status == 0 for i, o in enumerate(together) if i != 7)


def test_simulate_runs_the_compiled_loop_and_the_python_runner_agrees():
    exp = hybrid.paper_experiment(duration=0.8, model_error=0.25)
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    np.testing.assert_allclose(compiled.state, python.state, rtol=1e-7, atol=1e-9)
    for name, value in python.metrics.items():
        assert compiled.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name
    # a sweep's row is the compiled loop's own number, to the last bit
    row = hybrid.sweep(exp, {"model_error": [0.25]}, workers=1).iloc[0]
    assert all(row[k] == v or (math.isnan(v) and math.isnan(row[k])) for k, v in compiled.metrics.items())


def test_a_3d_record_too_big_for_memory_is_refused_before_the_run(monkeypatch):
    import hybrid.validate as validate

    monkeypatch.setattr(validate, "MEMORY_FRACTION", 1e-12)
    with pytest.raises(hybrid.HybridError, match="record needs"):
        hybrid.simulate(hybrid.tracing_experiment(duration=0.1))


def test_what_runs_in_python_is_not_compiled():
    assert closed_loop.prepare(hybrid.paper_experiment(frame="desired")) is None
    assert closed_loop.prepare(hybrid.tracing_experiment(frame="desired")) is None


# ------------------------------------------------------------------------------- vector math


def _build(source: str, cdef: str, name: str, folder):
    """Compile and load a lanes test unit with the project's flags."""
    import importlib.util
    import os

    ffi = cffi.FFI()
    ffi.cdef(cdef)
    ffi.set_source(name, source, extra_compile_args=list(flags(compiler()[1])), libraries=["m"],
                   include_dirs=[str(loader.source_dir())])  # the lanes' header
    os.environ.setdefault("CC", compiler()[0])
    so = ffi.compile(tmpdir=str(folder))
    spec = importlib.util.spec_from_file_location(name, so)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def vector_math(tmp_path_factory):
    """sin, cos, tanh, exp and sqrt of a lanes kernel, over n numbers (whole groups of lanes)."""
    x = sp.Symbol("x0", real=True)
    kernel = Kernel("f", (Arg("x", sp.Matrix([x])),),
                    (Arg("y", sp.Matrix([sp.sin(x), sp.cos(x), sp.tanh(x), sp.exp(x / 64), sp.sqrt(sp.Abs(x))])),),
                    "vector math")
    # (split with no fixed input: a _pre function that computes what depends on nothing)
    source = INCLUDE + libm_maps() + lanes_function(kernel, fixed=()) + """
int lanes(void) { return HL_W; }
void f_many(int n, const double *x, double *y) {
    int i, l, j;
    hl_v pre[F_LANES_NPRE];
    f_lanes_pre(pre);
    for (i = 0; i + HL_W <= n; i += HL_W) {
        hl_v in[1], out[5];
        for (l = 0; l < HL_W; ++l) in[0][l] = x[i + l];
        f_lanes(in, pre, out);
        for (j = 0; j < 5; ++j) for (l = 0; l < HL_W; ++l) y[(long)j * n + i + l] = out[j][l];
    }
}
"""
    module = _build(source, "int lanes(void); void f_many(int n, const double *x, double *y);", "_lanes_math",
                    tmp_path_factory.mktemp("lanes"))

    def evaluate(values: np.ndarray) -> np.ndarray:
        w = module.lib.lanes()
        xs = np.ascontiguousarray(np.resize(values, -(-len(values) // w) * w), float)
        out = np.empty((5, len(xs)))
        module.lib.f_many(len(xs), module.ffi.from_buffer("double[]", xs), module.ffi.from_buffer("double[]", out))
        return xs, out

    return evaluate


def test_sin_and_cos_near_a_point_are_within_2e_52(tmp_path):
    """The RK4 stages take sin and cos by rotating from the step's start (``near``): near it, within
    2 * 2^-52 of the C library's (absolute: relative to a result near a zero it is more); farther, or
    large, or not finite, what ``hl_sincos`` gives."""
    x = sp.Symbol("x0", real=True)
    kernel = Kernel("g", (Arg("x", sp.Matrix([x])),), (Arg("y", sp.Matrix([sp.sin(x), sp.cos(x)])),), "near")
    source = INCLUDE + libm_maps() + lanes_function(kernel, near=1) + """
int lanes(void) { return HL_W; }
void g_many(int n, const double *x, const double *x0, double *y) {
    int i, l, j;
    for (i = 0; i + HL_W <= n; i += HL_W) {
        hl_v in[1], out[2], base[3];
        for (l = 0; l < HL_W; ++l) in[0][l] = x[i + l], base[0][l] = x0[i + l];
        hl_sincos(base[0], base + 1, base + 2);
        g_lanes(in, out, base);
        for (j = 0; j < 2; ++j) for (l = 0; l < HL_W; ++l) y[(long)j * n + i + l] = out[j][l];
    }
}
"""
    module = _build(source, "int lanes(void); void g_many(int n, const double *x, const double *x0, double *y);",
                    "_lanes_near", tmp_path)
    rng = np.random.default_rng(9)
    n = 8 * 1500
    x0 = np.concatenate([rng.uniform(-4, 4, n // 2), rng.uniform(-1e5, 1e5, n // 4), rng.uniform(-1e7, 1e7, n // 4)])
    # within the rotation's span (2^-7), very near, at, beyond it, far
    d = rng.uniform(-2.0**-7, 2.0**-7, n) * rng.choice([1.0, 1e-6, 0.0, 8.0, 24.0], n)
    x = x0 + d
    x[:10] = [np.nan, np.inf, -np.inf, 1e300, x0[4] + 2.0**-7, x0[5] - 2.0**-7, 0.0, -0.0,
              x0[8] + 2.0**-7 * (1 + 2.0**-40), x0[9] - 2.0**-4]
    y = np.empty((2, n))
    module.lib.g_many(n, *(module.ffi.from_buffer("double[]", a) for a in (np.ascontiguousarray(x),
                                                                           np.ascontiguousarray(x0), y)))
    with np.errstate(invalid="ignore"):
        for got, want in zip(y, (np.sin(x), np.cos(x))):
            finite = np.isfinite(x)
            assert np.isnan(got[~finite]).all()
            assert (np.abs(got - want)[finite] <= 2 * np.spacing(1.0)).all()
            assert (got == want).mean() > 0.5


def test_vector_math_is_within_an_ulp_or_two_of_the_c_library(vector_math):
    rng = np.random.default_rng(5)
    x = np.concatenate([rng.uniform(-4, 4, 4000), rng.uniform(-1e5, 1e5, 4000), rng.uniform(-1e-3, 1e-3, 1000),
                        np.arange(-64, 65) * np.pi / 4, [0.0, -0.0, 0.625, -0.625, 19.9, 20.5, 700.0]])
    xs, y = vector_math(x)
    with np.errstate(over="ignore"):
        ref = [np.sin(xs), np.cos(xs), np.tanh(xs), np.exp(xs / 64)]
    for got, want, absolute in zip(y, ref, (True, True, False, False)):
        # sin, cos: within an ulp of 1 (their own ulp near a zero, after the reduction); tanh, exp: 2 ulps
        limit = np.spacing(1.0) if absolute else 2 * np.spacing(np.abs(want))
        assert (got == want).sum() > 0.5 * len(xs)
        with np.errstate(invalid="ignore"):  # inf - inf where exp overflows on both sides
            assert ((np.abs(got - want) <= limit) | (got == want)).all()
    assert (y[4] == np.sqrt(np.abs(xs))).all()
    assert np.signbit(y[0][xs == 0]).tolist() == np.signbit(xs[xs == 0]).tolist()


def test_large_and_non_finite_arguments_take_the_c_library(vector_math):
    x = np.array([1e6, -3e9, 1e300, 12345678.9, np.inf, -np.inf, np.nan, 0.5])
    xs, y = vector_math(x)
    with np.errstate(invalid="ignore"):
        np.testing.assert_array_equal(y[0], np.sin(xs))
        np.testing.assert_array_equal(y[1], np.cos(xs))
        np.testing.assert_array_equal(y[2], np.tanh(xs))


def test_tanh_skips_exp_only_where_it_is_exactly_one(vector_math):
    # groups of lanes all at |x| >= 20 take the shortcut (+-1 without exp); the values just below it
    # take the formula: both must be the C library's +-1 there, and within 2 ulps elsewhere
    slid = np.array([20.0, -20.0, 25.0, -1e4, 1e300, np.inf, -np.inf, 20.000001] * 2)
    near = np.array([19.0, -19.5, 18.0, 19.999999, -17.0, 10.0, -15.0, 5.0] * 2)
    for x in (slid, near):
        xs, y = vector_math(x)
        np.testing.assert_allclose(y[2], np.tanh(xs), rtol=2 * np.spacing(1.0), atol=0)
    assert (vector_math(slid)[1][2] == np.sign(slid)).all()
