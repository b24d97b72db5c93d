"""Bad input gets a HybridError that names the value and the fix; nothing crashes."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import threading
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import hybrid
from hybrid import oracle
from hybrid.stability.analysis import predicted_note

ROOT = Path(__file__).resolve().parent.parent
ARM = hybrid.paper_arm()
CIRCLE = hybrid.Circle((0.5, 0.0), 0.2)
GOOD = ([2.2, 1.9], [0.3, -0.4], [0.1, 1.0], [-8.0, 3.0])


@pytest.fixture(scope="module")
def law():
    return hybrid.decoupling_law(ARM, CIRCLE)


@pytest.mark.parametrize("args, match", [
    (([1.0, 2.0, 3.0], *GOOD[1:]), "q must have shape"),
    ((GOOD[0], "fast", *GOOD[2:]), "qdot must be numbers"),
    ((*GOOD[:2], [[0.1, 1.0]] * 3, GOOD[3]), r"a must have shape \(2,\), got \(3, 2\)"),
    ((*GOOD[:3], [1j, 2.0]), "Fc must be real"),
    ((np.zeros((0, 2)), *GOOD[1:]), "N >= 1"),
])
def test_bad_shapes_and_dtypes(law, args, match):
    with pytest.raises(hybrid.HybridError, match=match):
        law(*args)


@pytest.mark.parametrize("as_input", [list, np.array], ids=["lists", "arrays"])
def test_non_finite_state_is_named(law, as_input):
    # arrays take the one-state fast path, lists the general one: both must name the cause
    args = [as_input(x) for x in (GOOD[0], [np.nan, 0.0], *GOOD[2:])]
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input qdot"):
        law(*args)
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input qdot"):
        law.torque(*args)
    with pytest.raises(hybrid.HybridError, match="state 1 of 2"):
        law(np.array([GOOD[0]] * 2), np.array([[0.0, 0.0], [np.inf, 0.0]]), np.array([GOOD[2]] * 2),
            np.array([GOOD[3]] * 2))


@pytest.mark.parametrize("q2", [0.0, 1e-7, np.pi, -np.pi + 1e-8])
@pytest.mark.parametrize("as_input", [list, np.array], ids=["lists", "arrays"])
def test_singular_jacobian(law, q2, as_input):
    args = [as_input(x) for x in ([0.3, q2], *GOOD[1:])]
    with pytest.raises(hybrid.SingularConfigurationError, match="singular.*q2 near 0 or pi"):
        law(*args)
    with pytest.raises(hybrid.SingularConfigurationError, match="singular"):
        law.evaluate(*args)


@pytest.mark.parametrize("make, match", [
    (lambda: hybrid.Circle((0.5, 0.0), 0.0), "positive radius"),
    (lambda: hybrid.Circle((0.5, np.nan), 0.2), "not finite"),
    (lambda: hybrid.Plane((0.4, 0.0), (0.0, 0.0)), "zero length"),
    (lambda: replace(ARM, m2=-1.0), "m2 = -1.0 is negative"),
    (lambda: replace(ARM, L1=0.0), "link lengths must be positive"),
    (lambda: replace(ARM, I1=0.0, I2=0.0, m2=0.0), "not positive definite"),
    (lambda: replace(ARM, V1=float("inf")), "V1 is inf"),
    (lambda: hybrid.decoupling_law(ARM, "circle"), "Circle or hybrid.Plane"),
    (lambda: hybrid.paper_experiment(controller="raibert"), "unknown controller 'raibert'"),
    (lambda: hybrid.paper_experiment(surface="sphere"), "unknown surface"),
    (lambda: hybrid.paper_experiment(sample_time=0.01005), "not a whole multiple of integration_step"),
    (lambda: hybrid.paper_experiment(integration_step=1e-3, sample_time=1e-2), "too large for the contact"),
    (lambda: hybrid.paper_experiment(duration=0.0), "positive duration"),
    (lambda: hybrid.paper_experiment(duration=-1.0), "positive duration"),
    (lambda: hybrid.paper_experiment(KDf=1.0), "force loop on n is unstable"),
    (lambda: hybrid.paper_experiment(KPv=400.0), "velocity loop on t1 is unstable"),
    (lambda: hybrid.paper_experiment(KPf=-2.0), "KPf = -2.0 is negative"),
    (lambda: hybrid.paper_experiment(kpv=40), "unknown setting\\(s\\) kpv"),
    (lambda: hybrid.simulate(hybrid.paper_experiment(surface=hybrid.Circle((2.0, 0.0), 0.2),
                                                     start_point=(1.8, 0.0))), "out of the arm's reach"),
    (lambda: hybrid.simulate(hybrid.paper_experiment(surface=hybrid.Circle((0.75, 0.0), 0.2),
                                                     start_point=(0.55, 0.0))), "leaves the arm's workspace"),
    (lambda: hybrid.simulate("paper"), "takes an experiment"),
])
def test_bad_parameters(make, match):
    with pytest.raises(hybrid.HybridError, match=match):
        make()


def test_concurrent_calls_match_serial(law):
    rng = np.random.default_rng(1)
    states = [(np.array([rng.uniform(-3, 3), rng.uniform(0.3, 2.8)]), *rng.normal(size=(3, 2)))
              for _ in range(400)]
    batches = [np.array(states[k:k + 50]).transpose(1, 0, 2) for k in range(0, len(states), 50)]
    serial = [law(*s) for s in states] + [law.evaluate(*b) for b in batches]
    results = [None] * len(serial)

    def work(idx):
        for i in idx:  # the batched path releases the GIL inside the C call
            results[i] = law(*states[i]) if i < len(states) else law.evaluate(*batches[i - len(states)])

    threads = [threading.Thread(target=work, args=(range(k, len(serial), 4),)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(serial, results):
        np.testing.assert_array_equal(a, b)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.floats(allow_nan=True, allow_infinity=True, width=64), min_size=8, max_size=8),
       st.floats(0.05, 5.0), st.floats(0.0, 5.0))
def test_law_gives_finite_values_or_a_hybrid_error(law, values, m2, d2):
    local = hybrid.decoupling_law(replace(ARM, m2=m2, d2=min(d2, ARM.L2)), CIRCLE, curvature=True)
    v = np.array(values).reshape(4, 2)
    try:
        F, tau = local.evaluate(*v)
    except hybrid.HybridError:
        return
    assert np.isfinite(F).all() and np.isfinite(tau).all()


def run_cli(*args, env=None):
    return subprocess.run([sys.executable, "-m", "hybrid", *args], cwd=ROOT, capture_output=True, text=True,
                          env={**os.environ, **(env or {})})


def test_cli_bad_usage_is_one_line_and_status_2():
    proc = run_cli("paper")
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "--out" in proc.stderr
    assert "Traceback" not in proc.stderr
    proc = run_cli("fly")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


def test_cli_refuses_to_overwrite(tmp_path):
    target = tmp_path / "notes.txt"
    target.write_text("mine")
    proc = run_cli("paper", "--out", str(target))
    assert proc.returncode == 2 and "existing file" in proc.stderr and target.read_text() == "mine"
    (tmp_path / "res").mkdir()
    (tmp_path / "res" / "metrics.json").write_text("{}")
    proc = run_cli("paper", "--out", str(tmp_path / "res"))
    assert proc.returncode == 2 and "--force" in proc.stderr
    assert (tmp_path / "res" / "metrics.json").read_text() == "{}"


def test_bench_refuses_to_overwrite_its_json(tmp_path):
    target = tmp_path / "bench.json"
    target.write_text("mine")
    proc = run_cli("bench", "--quick", "--json", str(target))
    assert proc.returncode == 2 and "--force" in proc.stderr and target.read_text() == "mine"


def test_missing_compiler_says_what_to_install(tmp_path):
    code = ("import hybrid, hybrid.native.loader as n\ntry:\n    n.load('sympy')\n"
            "except hybrid.NativeBuildError as exc:\n    print('NativeBuildError:', exc)")
    env = {k: v for k, v in os.environ.items() if k != "CC"}
    proc = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                          env={**env, "PATH": str(tmp_path), "HYBRID_CACHE_DIR": str(tmp_path / "cache")})
    assert proc.stdout.startswith("NativeBuildError: no C compiler found") and "apt-get install gcc" in proc.stdout


def test_corrupt_cache_entry_is_rebuilt(tmp_path):
    env = {**os.environ, "HYBRID_CACHE_DIR": str(tmp_path)}
    code = ("import hybrid, numpy as np; law = hybrid.decoupling_law(hybrid.paper_arm(), "
            "hybrid.Circle((0.5, 0), 0.2)); print(law([2.2, 1.9], [0.3, -0.4], [0.1, 1.0], [-8.0, 3.0]))")
    first = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, env=env)
    libraries = list(tmp_path.rglob("*.so"))
    assert len(libraries) == 2  # the cffi unit and the one-state entry point
    for so in libraries:
        so.write_bytes(so.read_bytes()[:1000])  # a partial file, as a crash mid-copy would leave
    second = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, env=env)
    assert second.returncode == 0, second.stderr
    assert first.stdout == second.stdout


def _conditioning_at_samples(res):
    """``2 |det J| / |J|_F^2`` at each control sample of a run, from the NumPy oracle."""
    exp = res.experiment
    return np.array([oracle.conditioning(q, exp.arm.as_array())
                     for q in res.q[::exp.steps_per_sample][:exp.n_samples]])


@pytest.mark.parametrize("backend, duration, tol", [("sympy", 2.0, 0.9), ("numpy", 0.5, 0.99)])
def test_singularity_mid_run_stops_at_the_first_sample_past_the_tolerance(backend, duration, tol):
    # the paper's arm stretches towards full extension as it slides (conditioning 1.0 -> 0.43)
    simulate = oracle.simulate if backend == "numpy" else hybrid.simulate
    nominal = simulate(hybrid.paper_experiment(duration=duration))
    cond = _conditioning_at_samples(nominal)
    k = int(np.argmax(cond < tol))
    assert k > 0, "the tolerance must be crossed after the start"
    exp = hybrid.paper_experiment(duration=duration, singular_tol=tol)
    with pytest.raises(hybrid.SimulationError) as info:
        simulate(exp)
    err, t_stop = info.value, k * exp.sample_time
    q = nominal.q[k * exp.steps_per_sample]
    assert isinstance(err.__cause__, hybrid.SingularConfigurationError)
    assert f"at t = {t_stop:.4f} s" in str(err) and str(np.round(q, 5).tolist()) in str(err)
    assert err.time == pytest.approx(t_stop)
    # the run up to the stop is kept, and it is the nominal run's (the compiled loop ran that one,
    # the Python runner the one that stopped: equal to rounding)
    np.testing.assert_allclose(err.partial.state, nominal.state[:len(err.partial.state)], rtol=1e-7, atol=1e-7)
    assert len(err.partial.t) == k * exp.steps_per_sample + 1


def test_diverging_run_stops_with_time_place_and_cause():
    # a controller that believes the arm 3x heavier triples every loop gain: predicted unstable, refused,
    # and run anyway with allow_unstable it diverges, the error saying it was predicted so
    with pytest.raises(hybrid.HybridError, match=r"(?s)force loop on n is unstable.*allow_unstable=True.*model_error"):
        hybrid.paper_experiment(model_error=2.0)
    exp = hybrid.paper_experiment(model_error=2.0, allow_unstable=True)
    with pytest.raises(hybrid.SimulationError, match=r"NaN or infinite at t = \d") as info:
        hybrid.simulate(exp)
    err = info.value
    assert 0 < err.time < exp.duration and f"t = {err.time:.5f} s" in str(err)
    assert "predicted unstable" in str(err) and "allow_unstable=True" in str(err)
    part = err.partial
    assert np.isfinite(part.state).all() and part.t[-1] == pytest.approx(err.time - exp.integration_step)
    assert np.abs(part.qdot[-1]).max() > 1e6 * max(np.abs(part.qdot[:100]).max(), 1e-3)
    # the model's claim, checked on its own: the exact model with tripled gains fails the check alike
    tripled = {name: 3.0 * value for name, value in vars(exp.gains).items()}
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.paper_experiment(model_error=0.0, **tripled)
    assert predicted_note(hybrid.paper_experiment()) == ""


def test_run_driven_through_a_singularity_between_samples_says_where():
    # F_d -> 0 lifts the sensor off; the leftover force integral drifts the free arm to full extension,
    # crossing q2 = 0 within one 10 ms sample, where the law's torque is unbounded
    with pytest.raises(hybrid.SimulationError, match="NaN or infinite") as info:
        hybrid.simulate(hybrid.paper_experiment(F_d=hybrid.Step(10.0, 0.0, 0.4)))
    err = info.value
    found = re.search(r"passed near a singularity \(2\|det J\|/\|J\|_F\^2 = ([\d.e-]+) at t = ([\d.]+) s\)", str(err))
    assert found, str(err)
    t_near = float(found.group(2))
    assert t_near < err.time
    q2 = err.partial.q[np.argmin(np.abs(err.partial.t - t_near)), 1]
    assert abs(np.sin(q2)) < 0.01  # the arm really was at full extension then


@pytest.mark.parametrize("value", [-0.1, 1.0, np.nan, "tight"])
def test_bad_singular_tolerance(value):
    with pytest.raises(hybrid.HybridError, match="singular_tol"):
        hybrid.paper_experiment(singular_tol=value)
    with pytest.raises(hybrid.HybridError, match="singular_tol"):
        hybrid.decoupling_law(ARM, CIRCLE, singular_tol=value)


def test_contact_loss_is_reported_not_raised():
    # commanding a pull (F_d = -1 N) from t = 0.4 s lifts the sensor off the surface
    res = hybrid.simulate(hybrid.paper_experiment(F_d=hybrid.Step(10.0, -1.0, 0.4), duration=0.8))
    assert res.t[-1] == pytest.approx(0.8) and np.isfinite(res.state).all()
    separated = res.penetration < 0  # sensor tip above the surface: no surface force can act
    assert separated.any() and (res.contact_force[separated] == 0).all()
    assert res.metrics["contact_losses"] >= 1
    assert res.metrics["time_out_of_contact_s"] >= np.count_nonzero(separated[1:]) * res.experiment.integration_step
    assert not separated[res.t < 0.4].any()
