"""The stability tools at the settings a demanding user reaches for, each judged against something
independent: the nonlinear simulation, the model's own definitions, SciPy, the experiment's own check.

Other arms, tasks and schemes (the UR5, the redundant Panda, a subset of the axes, Khatib's scheme), the
edges of the settings (tiny and huge sample times, long delays, a lag near the Nyquist frequency), bad
input to the map and the suggested gains (a clear :class:`hybrid.HybridError`, never another exception),
and what the check costs an experiment.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.stability.experiment_loops import loop_numbers
from hybrid.stability.model import closed_loop

sys.path.insert(0, str(Path(__file__).parent))
from test_stability_boundary import force_error, grows, plane_experiment  # noqa: E402

#: the UR5 pressing on a wall in front of it at rest, gravity on, no friction (the model's assumptions)
UR5_WALL = dict(surface=hybrid.Plane((0.5, 0.0, 0.2), (-1.0, 0.0, 0.0)), start_point=(0.5, 0.1, 0.2),
                contact=hybrid.Contact(friction=0.0), speed_reference=hybrid.Step(0.0, 0.0, 0.0))
#: the controller's model exact
EXACT = dict(model_error=0.0, viscous_compensation=1.0)


def model_force_step(exp, at: float) -> np.ndarray:
    """The model's normal force at each sample for a unit step of ``F_d`` at ``at`` [s]."""
    st, p = loop_numbers(exp)
    m = closed_loop(st, p)
    force_axis = list(st.force).index(True)
    normal = list(st.sensed).index(force_axis)
    X, r = np.zeros(m["A"].shape[0]), np.zeros(st.n)
    out = []
    for k in range(exp.n_samples):
        r[force_axis] = 1.0 if k * exp.sample_time >= at - 1e-12 else 0.0
        out.append((m["force"] @ np.concatenate([X, r]))[normal])
        X = m["A"] @ X + m["B"] @ r
    return np.array(out)


def simulated_force_step(factory, step: float, at: float = 0.05, **settings) -> tuple[np.ndarray, np.ndarray]:
    """The simulated normal force's response to a step of ``step`` [N] at ``at``, per newton, at each sample
    (the run without the step subtracted: the start is at rest to its own tolerance only), and the model's."""
    exp = factory(force_reference=hybrid.Step(10.0, 10.0 + step, at), **settings)
    still = factory(force_reference=hybrid.Step(10.0, 10.0, at), **settings)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", hybrid.RedundancyWarning)
        runs = [hybrid.simulate(e) for e in (exp, still)]
    rows = np.searchsorted(runs[0].t, np.arange(exp.n_samples) * exp.sample_time - 1e-12)
    simulated = (runs[0].force_normal[rows] - runs[1].force_normal[rows]) / step
    return simulated, model_force_step(exp, at)


# ------------------------------------------------------------------------------------------ Khatib's scheme

def test_khatibs_loops_are_modelled_as_they_run():
    # Khatib's law feeds the desired force forward where the task law cancels the measured one: on the UR5
    # the model's step response is the simulation's to 1e-5 of its size (the task law's model: 3 % off)
    simulated, model = simulated_force_step(hybrid.tracing_experiment, 1e-2, controller="khatib", duration=0.3,
                                            integration_step=1e-5, **UR5_WALL, **EXACT)
    scale = np.abs(model).max()
    assert scale > 0.5
    np.testing.assert_allclose(model, simulated, rtol=0, atol=1e-5 * scale)


def test_khatibs_scheme_turns_unstable_where_the_task_law_holds():
    # the paper's arm on a 1.12e4 N/m sensor, 10 ms: the task law's loops hold, Khatib's grow, as predicted
    sensor = hybrid.Sensor(stiffness=11220.0)
    task, khatib = (plane_experiment(sensor=sensor, controller=c) for c in ("task", "khatib"))
    assert hybrid.stability(task, margins=False).stable and not grows(force_error(task))
    assert not hybrid.stability(khatib, margins=False).stable and grows(force_error(khatib))
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.paper_experiment(sensor=sensor, controller="khatib")
    hybrid.paper_experiment(sensor=sensor)


# ------------------------------------------------------------------------------------ bad input, in words

@pytest.mark.parametrize("over, match", [
    ({"KPf": [True, False]}, "list of finite numbers"),
    ({"KPf": [1.0, True]}, "list of finite numbers"),
    ({"KPf": np.array([True, False])}, "list of finite numbers"),
    ({"KPf": ["1", "2"]}, "list of finite numbers"),
    ({"KPf": "12"}, "list of finite numbers"),
    ({"KPf": {1.0, 2.0}}, "list of finite numbers"),
    ({"KPf": [1.0, None]}, "list of finite numbers"),
    ({"KPf": [[1.0], [2.0, 3.0]]}, "list of finite numbers"),
    ({"KPf": [-np.inf]}, "list of finite numbers"),
    ({"sensor.delay_samples": [1e6]}, "beyond the 100 samples"),
    ({"sensor.delay_samples": [2, 10**9]}, "beyond the 100 samples"),
    ({"sensor.stiffness": [1e300]}, "the map's point sensor.stiffness = 1e"),
    ({"contact.stiffness": [1e3, 1e300]}, "the map's point contact.stiffness = 1e"),
])
def test_bad_map_values_are_refused_in_words_before_anything_is_made(over, match):
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.stability_map(hybrid.paper_experiment(), over)


def test_a_map_of_every_point_invalid_one_point_or_repeated_values():
    exp = hybrid.paper_experiment()
    invalid = hybrid.stability_map(exp, {"sensor.bandwidth_hz": [50.0, 70.0], "KPf": [1.0, 2.0]})
    assert invalid.table["spectral_radius"].isna().all() and invalid.stable_share == 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no warning of NaN leaks out of the figure
        invalid.figure()
        hybrid.stability_map(exp, {"sensor.bandwidth_hz": [50.0, 70.0]}).figure()
    one = hybrid.stability_map(exp, {"KPf": [2.0], "KDf": [90.0]})
    assert len(one.table) == 1 and one.table["spectral_radius"][0] == hybrid.stability(exp).spectral_radius
    one.figure()
    repeated = hybrid.stability_map(exp, {"KPf": [3.0, 3.0, 1.0, 3.0]}).table["spectral_radius"].to_numpy()
    assert repeated[0] == repeated[1] == repeated[3] != repeated[2]


def test_a_sweep_takes_allow_unstable_and_says_why_a_row_is_refused():
    rows = hybrid.sweep(hybrid.paper_experiment(duration=0.05), {"sensor.stiffness": [1e3, 2e4],
                                                                 "allow_unstable": [False, True],
                                                                 "sensor.delay_samples": [0, 101]}, workers=1)
    status = {(k, a, d): (s, e) for k, a, d, s, e in rows[["sensor.stiffness", "allow_unstable", "sensor.delay_samples",
                                                          "status", "error"]].itertuples(index=False)}
    assert status[(1e3, False, 0)][0] == status[(1e3, True, 0)][0] == status[(2e4, True, 0)][0] == "ok"
    assert status[(2e4, False, 0)][0] == "invalid" and "force loop on n is unstable" in status[(2e4, False, 0)][1]
    assert status[(1e3, False, 101)][0] == "invalid" and "beyond the 100 samples" in status[(1e3, False, 101)][1]
    assert status[(1e3, True, 101)][0] == "ok"


def test_the_command_line_refuses_odd_values_before_making_them(tmp_path, capsys):
    import time

    from hybrid.cli.main import main

    for over in ("KPf=nan", "KPf=1,inf", "KPf=1:nan:3", "KPf=1:inf:3:log", "KPf=1:2:100000000000", "KPf=1:2:0"):
        start = time.perf_counter()
        assert main(["stability", "--over", over, "--out", str(tmp_path / "o")]) == 2
        assert time.perf_counter() - start < 5.0  # nothing of the grid's size made
        assert "finite numbers" in capsys.readouterr().err
        assert not (tmp_path / "o").exists()
    assert main(["stability", "--over", "sensor.delay_samples=0,1e7", "--out", str(tmp_path / "d")]) == 2
    assert "beyond the 100 samples" in capsys.readouterr().err


@pytest.mark.filterwarnings("ignore::hybrid.RedundancyWarning")  # the UR5 on its normal axis alone
@pytest.mark.parametrize("kwargs, match", [
    ({"bandwidth_hz": {"velocity": 2.0}}, "no velocity axis"),
    ({"bandwidth_hz": 1e-6}, "none is met from 1e-07 Hz up to it.*give another bandwidth_hz or damping"),
    ({"bandwidth_hz": np.float64(np.nan)}, "give a frequency in Hz"),
    ({"bandwidth_hz": np.bool_(True)}, "give a frequency in Hz"),
    ({"bandwidth_hz": 3.0, "damping": np.bool_(True)}, "damping ratio"),
])
def test_bad_gain_requests_are_refused_in_words(kwargs, match):
    exp = hybrid.tracing_experiment(axes=(2,)) if "velocity" in str(kwargs) else hybrid.paper_experiment()
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.suggest_gains(exp, **kwargs)


def test_numpy_numbers_and_any_mapping_ask_for_the_same_gains():
    from types import MappingProxyType

    exp = hybrid.paper_experiment()
    plain = hybrid.suggest_gains(exp, bandwidth_hz=3.0, damping=0.8, integral_ratio=0.25).gains
    for f, zeta, ratio in ((np.int64(3), np.float32(0.8), np.float64(0.25)), (np.float32(3.0), 0.8, np.int8(0))):
        got = hybrid.suggest_gains(exp, bandwidth_hz=f, damping=zeta, integral_ratio=ratio).gains
        same = hybrid.suggest_gains(exp, bandwidth_hz=float(f), damping=float(zeta), integral_ratio=float(ratio)).gains
        assert got == same
    assert hybrid.suggest_gains(exp, bandwidth_hz=MappingProxyType({"force": 3.0}), damping=0.8).gains == plain


def test_suggested_gains_on_the_3d_arms_place_both_loops_and_are_accepted():
    from hybrid.stability.analysis import _poles, axis_alone

    for factory in (hybrid.tracing_experiment, hybrid.panda_experiment):
        s = hybrid.suggest_gains(factory(), bandwidth_hz={"force": 4.0, "velocity": 2.0}, damping=0.7)
        placed = factory(gains=s.gains)  # accepted by the experiment's own check
        st, p = loop_numbers(placed)
        for i in range(st.n):
            found = _poles(closed_loop(*axis_alone(st, p, i))["A"])
            wanted = s.poles["force" if st.force[i] else "velocity"]
            off = max(min(abs(found - z)) for z in wanted)
            # the loop placed (n, and t1 for the velocity loops) exactly; the other velocity axes differ from t1
            # only in the arm's viscosity and gravity along them
            assert off < (1e-9 if i in (0, 2) else 1e-2), (factory.__name__, i, off)
        # from the poles' definition: the pair's damping and frequency, read back from the loop's dominant pole
        w = 2 * np.pi * 4.0
        assert min(abs(s.poles["force"] - np.exp(w * (-0.7 + 1j * np.sqrt(1 - 0.49)) * placed.sample_time))) < 1e-12


# ------------------------------------------------------------------------------------------ the edges

def test_a_delay_beyond_what_the_model_takes_is_refused_at_once():
    import time

    start = time.perf_counter()
    for d in (101, 10**4, 10**9):
        with pytest.raises(hybrid.HybridError, match=f"delay_samples = {d} is beyond the 100 samples"):
            hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=d))
    assert time.perf_counter() - start < 2.0  # (10^4 samples took minutes and gigabytes, 10^9 ran out of memory)
    late = hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=10**4), allow_unstable=True)
    with pytest.raises(hybrid.HybridError, match="beyond the 100 samples"):
        hybrid.stability(late)
    # at the bound itself, judged: the paper's loops do not hold a reading a second late
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=100))


def test_a_printed_radius_tells_stable_from_unstable():
    # a radius within 5e-5 of 1 printed to four digits reads "1": the stable side must not, nor the refusal's
    reports = [hybrid.stability(hybrid.paper_experiment(sample_time=1e-5, integration_step=1e-6, duration=0.01)),
               hybrid.stability(hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=100), allow_unstable=True),
                                margins=False)]
    for report in reports:
        lines = str(report).splitlines()
        head = float(lines[0].split("spectral radius ")[1].rstrip(")"))
        assert (head < 1.0) == report.stable and ("UNSTABLE" not in lines[0]) == report.stable
        for line, loop in zip(lines[1:], report.loops):
            assert (float(line.split("radius ")[1].split()[0]) < 1.0) == loop.stable, line
    with pytest.raises(hybrid.HybridError) as refusal:
        hybrid.paper_experiment(sensor=hybrid.Sensor(delay_samples=100))
    assert float(str(refusal.value).split("spectral radius ")[1].split()[0]) > 1.0
