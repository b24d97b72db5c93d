"""The stability tools at the settings a demanding user reaches for, each judged against something
independent: the nonlinear simulation, the model's own definitions, SciPy, the experiment's own check.

Other arms, tasks and schemes (the UR5, the redundant Panda, a subset of the axes, Khatib's scheme), the
edges of the settings (tiny and huge sample times, long delays, a lag near the Nyquist frequency), bad
input to the map and the suggested gains (a clear :class:`hybrid.HybridError`, never another exception),
and what the check costs an experiment.
"""

from __future__ import annotations

import dataclasses
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.stability.analysis import axis_alone
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


# ------------------------------------------------------------------ the model against the simulation, at the edges

#: the paper's arm pressing on a wall at rest, the controller's model exact (the model's assumptions)
PAPER_WALL = dict(surface=hybrid.Plane(point=(0.3, 0.0, 0.0), normal=(-1.0, 0.0, 0.0)), start_point=(0.3, 0.0),
                  contact=hybrid.Contact(friction=0.0), speed_reference=hybrid.Step(0.0, 0.0, 0.0), **EXACT)
#: the Panda (7 joints, its posture task in the null space) pressing on a wall where its pillar would be
PANDA_WALL = dict(surface=hybrid.Plane((0.42, 0.0, 0.78), (-1.0, 0.0, 0.0)), start_point=(0.42, 0.0, 0.78), path=None,
                  contact=hybrid.Contact(friction=0.0), speed_reference=hybrid.Step(0.0, 0.0, 0.0))


def _slow_gains():
    """Gains placed for a 25 ms sample (the paper's do not hold there), the velocity loop's too."""
    base = hybrid.paper_experiment(sample_time=0.025, integration_step=1e-5, duration=1.0, allow_unstable=True,
                                   fault_reaction=hybrid.FaultReaction(stop_time=0.05), **PAPER_WALL)
    return hybrid.suggest_gains(base, bandwidth_hz={"force": 2.0, "velocity": 1.0}).gains


EDGES = {
    "0.1 ms samples": (hybrid.paper_experiment, 1e-6, dict(sample_time=1e-4, integration_step=1e-6, duration=0.3)),
    "10 us samples": (hybrid.paper_experiment, 1e-6, dict(sample_time=1e-5, integration_step=1e-6, duration=0.2)),
    "25 ms samples": (hybrid.paper_experiment, 1e-6, dict(sample_time=0.025, integration_step=1e-5, duration=1.0,
                                                         fault_reaction=hybrid.FaultReaction(stop_time=0.05))),
    "10 samples late, lag near Nyquist": (hybrid.paper_experiment, 1e-6, dict(
        sensor=hybrid.Sensor(delay_samples=10, bandwidth_hz=49.0), KPf=0.2, KDf=20.0, KIf=0.5, duration=1.0,
        integration_step=1e-5)),
    "first-order filter at 5 Hz": (hybrid.paper_experiment, 1e-6, dict(
        wrench_sensor=hybrid.WrenchSensor(cutoff=5.0, order=1), duration=0.5, integration_step=1e-5)),
    "second-order filter at 40 Hz": (hybrid.paper_experiment, 1e-6, dict(
        wrench_sensor=hybrid.WrenchSensor(cutoff=40.0, order=2), duration=0.5, integration_step=1e-5)),
    "Panda, exact model": (hybrid.panda_experiment, 1e-5, dict(duration=0.3, integration_step=1e-5, **EXACT)),
}


@pytest.mark.parametrize("case", EDGES)
def test_the_step_response_is_the_simulations_at_the_edges(case):
    factory, tolerance, settings = EDGES[case]
    settings = dict(settings)
    if factory is hybrid.paper_experiment:
        settings.update(PAPER_WALL)
    else:
        settings.update(PANDA_WALL)
    if case == "25 ms samples":
        settings["gains"] = _slow_gains()
    simulated, model = simulated_force_step(factory, 1e-3 if factory is hybrid.paper_experiment else 1e-2, **settings)
    scale = np.abs(model).max()
    assert scale > 0.5
    np.testing.assert_allclose(model, simulated, rtol=0, atol=tolerance * scale)


#: what the model leaves out at first order (the docs): a model error's gravity, the null space moving under a
#: posture task or falling under gravity, an estimated normal's dynamics, the first touch's transient
FIRST_ORDER = {
    "Panda, model error": (hybrid.panda_experiment, dict(**PANDA_WALL)),
    "Panda, Khatib": (hybrid.panda_experiment, dict(controller="khatib", **PANDA_WALL, **EXACT)),
    "Panda, position axes": (hybrid.panda_experiment, dict(axes="position", **PANDA_WALL, **EXACT)),
    "UR5, a controller_robot": (hybrid.tracing_experiment, dict(
        controller_robot=hybrid.tracing_experiment().robot.with_model_error(0.2, 0.5), **UR5_WALL)),
    "UR5, an estimated normal": (hybrid.tracing_experiment, dict(controller_surface=hybrid.EstimatedSurface(),
                                                                  **UR5_WALL, **EXACT)),
    "UR5, from a gap": (hybrid.tracing_experiment, dict(start_gap=0.002, approach_speed=0.02, **UR5_WALL, **EXACT)),
}


@pytest.mark.parametrize("case", FIRST_ORDER)
def test_the_step_response_holds_to_first_order_where_the_model_leaves_terms_out(case):
    factory, settings = FIRST_ORDER[case]
    at, duration = (0.6, 0.9) if "gap" in case else (0.05, 0.3)
    simulated, model = simulated_force_step(factory, 1e-2, at=at, duration=duration, integration_step=1e-5,
                                            **settings)
    scale = np.abs(model).max()
    assert scale > 0.5
    np.testing.assert_allclose(model, simulated, rtol=0, atol=1e-3 * scale)


@pytest.mark.filterwarnings("ignore::hybrid.RedundancyWarning")  # the UR5 on fewer axes than joints
def test_every_kind_of_experiment_gets_a_verdict():
    # a path task's loops are those of an experiment pressing at the path's start, in the frame it starts in
    plane = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
    raster = hybrid.RasterPath(plane, plane.project(np.array([0.45, -0.05, 0.1])), (1.0, 0.0, 0.0), pass_length=0.08,
                               spacing=0.01, passes=3)
    for gap in ({}, {"start_gap": 0.005, "approach_speed": 0.02}):
        task = hybrid.tracing_experiment(surface=plane, path_task=hybrid.PathTask(raster), duration=1.0, **gap)
        pressing = hybrid.tracing_experiment(surface=plane, start_point=tuple(task.start()), F_d=task.force_reference,
                                             frame_direction=tuple(task.frame_direction), duration=1.0, **gap)
        ours, theirs = (hybrid.stability(e) for e in (task, pressing))
        assert ours.stable and ours.spectral_radius == pytest.approx(theirs.spectral_radius, rel=1e-12)
        assert [x.axis for x in ours.loops] == ["t1", "t2", "n", "rot_t1", "rot_t2", "rot_n"]
    # the desired frame is the actual one at the start; one axis alone; the Panda's six of seven joints
    assert hybrid.stability(hybrid.tracing_experiment(frame="desired")).spectral_radius == \
        hybrid.stability(hybrid.tracing_experiment()).spectral_radius
    alone = hybrid.stability(hybrid.tracing_experiment(axes=(2,)))
    assert [x.axis for x in alone.loops] == ["n"] and alone.spectral_radius == alone.loops[0].spectral_radius
    assert hybrid.stability(hybrid.panda_experiment()).stable
    # a path task's cross-track gain past what the sample rate allows is refused before the loops are judged
    with pytest.raises(hybrid.HybridError, match="cross_track_gain"):
        hybrid.tracing_experiment(surface=plane, path_task=hybrid.PathTask(raster, cross_track_gain=60.0))
    # without a force axis there are no contact loops to judge: said so
    with pytest.raises(hybrid.HybridError, match="no force axis"):
        hybrid.stability(hybrid.tracing_experiment(axes=(0, 1)))


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
    ({"KPf": [1.0, 2.0], "gains.KPf": [3.0]}, "'KPf' and 'gains.KPf' name the same setting"),
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


def test_a_map_is_the_same_table_bit_for_bit_every_time():
    exp = hybrid.tracing_experiment(wrench_sensor=hybrid.WrenchSensor(cutoff=20.0))
    over = {"sensor.stiffness": np.geomspace(500.0, 5e4, 7), "sample_time": [0.002, 0.01],
            "sensor.delay_samples": [0, 2], "KDf": [40.0, 90.0], "wrench_sensor.cutoff": [10.0, 30.0]}
    first = hybrid.stability_map(exp, over).table
    hybrid.stability_map(exp, {"KPf": [1.0, 5.0], "sensor.mass": [0.01, 0.05]})  # other work between
    again = hybrid.stability_map(exp, dict(reversed(list(over.items())))).table
    again = again[list(first.columns)].sort_values(list(over)).reset_index(drop=True)
    first = first.sort_values(list(over)).reset_index(drop=True)
    assert first.equals(again)
    np.testing.assert_array_equal(first["spectral_radius"].to_numpy(), again["spectral_radius"].to_numpy())


def test_results_pickle_and_experiments_keep_allow_unstable():
    import pickle

    report = hybrid.stability(hybrid.tracing_experiment())
    back = pickle.loads(pickle.dumps(report))
    assert str(back) == str(report) and back.table().equals(report.table())
    smap = hybrid.stability_map(hybrid.paper_experiment(), {"KPf": [1.0, 2.0]})
    assert pickle.loads(pickle.dumps(smap)).table.equals(smap.table)
    suggestion = hybrid.suggest_gains(hybrid.paper_experiment(), bandwidth_hz=3.0)
    assert pickle.loads(pickle.dumps(suggestion)).gains == suggestion.gains
    stiff = hybrid.Sensor(stiffness=2e4)
    allowed = hybrid.paper_experiment(sensor=stiff, allow_unstable=True)
    data = allowed.to_dict()
    assert hybrid.Experiment.from_dict(data) == allowed == pickle.loads(pickle.dumps(allowed))
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.Experiment.from_dict({**data, "allow_unstable": False})
    older = {k: v for k, v in hybrid.paper_experiment().to_dict().items() if k != "allow_unstable"}
    assert hybrid.Experiment.from_dict(older).allow_unstable is False


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


@pytest.mark.parametrize("not_an_experiment", ["paper", None, {"sample_time": 0.01}, hybrid.paper_experiment])
@pytest.mark.parametrize("call", [
    lambda x: hybrid.stability(x),
    lambda x: hybrid.stability_map(x, {"sample_time": [0.01]}),
    lambda x: hybrid.suggest_gains(x, bandwidth_hz=3.0),
    lambda x: hybrid.tune(x, "rms_force_error_N", [{"model_error": 0.1}]),
], ids=["stability", "stability_map", "suggest_gains", "tune"])
def test_what_is_not_an_experiment_is_refused_in_words(call, not_an_experiment):
    # before anything reads its settings (an AttributeError otherwise)
    with pytest.raises(hybrid.HybridError, match=f"takes an experiment.*got {type(not_an_experiment).__name__}"):
        call(not_an_experiment)


@pytest.mark.parametrize("margins", ["no", 0, None, np.float64(1.0)])
def test_margins_asked_for_by_something_not_a_bool_are_refused(margins):
    # "no" would read as true: the margins worked out though the caller asked for none
    with pytest.raises(hybrid.HybridError, match="give True .* or False"):
        hybrid.stability(hybrid.paper_experiment(), margins=margins)
    for flag in (True, False, np.bool_(False)):
        assert np.isnan(hybrid.stability(hybrid.paper_experiment(), margins=flag).loop("n").gain_margin_db) != flag


def test_numpy_numbers_and_any_mapping_ask_for_the_same_gains():
    from types import MappingProxyType

    exp = hybrid.paper_experiment()
    plain = hybrid.suggest_gains(exp, bandwidth_hz=3.0, damping=0.8, integral_ratio=0.25).gains
    for f, zeta, ratio in ((np.int64(3), np.float32(0.8), np.float64(0.25)), (np.float32(3.0), 0.8, np.int8(0))):
        got = hybrid.suggest_gains(exp, bandwidth_hz=f, damping=zeta, integral_ratio=ratio).gains
        same = hybrid.suggest_gains(exp, bandwidth_hz=float(f), damping=float(zeta), integral_ratio=float(ratio)).gains
        assert got == same
    assert hybrid.suggest_gains(exp, bandwidth_hz=MappingProxyType({"force": 3.0}), damping=0.8).gains == plain


# --------------------------------------------------------------------------------------------- consistency

def test_the_map_is_the_experiments_own_verdict_over_every_setting_on_the_3d_arms():
    from hybrid.sweeps import apply

    over = {"sample_time": [0.002, 0.01], "contact.stiffness": [2e3, 1e5], "contact.damping": [0.0, 200.0],
            "sensor.mass": [0.01, 0.1], "sensor.damping": [0.0, 20.0], "sensor.stiffness": [800.0, 5000.0],
            "model_error": [-0.3, 0.5], "sensor.bandwidth_hz": [5.0, 40.0], "wrench_sensor.cutoff": [10.0, 45.0],
            "KPv": [20.0, 60.0], "KIv": [0.0, 300.0], "KI2v": [0.0, 2000.0], "KPf": [0.5, 4.0], "KDf": [30.0, 120.0],
            "KIf": [0.0, 40.0]}
    rng = np.random.default_rng(7)
    for factory in (hybrid.tracing_experiment, hybrid.panda_experiment):
        exp = factory(wrench_sensor=hybrid.WrenchSensor(cutoff=25.0, order=1), sensor=hybrid.Sensor(bandwidth_hz=30.0))
        table = hybrid.stability_map(exp, over).table
        assert len(table) == 2 ** len(over) and 0.1 < table["stable"].mean() < 0.9
        for i in rng.choice(len(table), 12, replace=False):
            settings = {name: float(table[name].iloc[i]) for name in over}
            point = apply(dataclasses.replace(exp, allow_unstable=True), {**settings, "integration_step": 1e-5})
            own = hybrid.stability(point, margins=False)
            assert table["spectral_radius"].iloc[i] == pytest.approx(own.spectral_radius, rel=1e-9), settings
            assert bool(table["stable"].iloc[i]) == own.stable


@pytest.mark.parametrize("factory", [hybrid.tracing_experiment, hybrid.panda_experiment])
def test_the_margins_are_where_the_3d_arms_check_starts_refusing(factory):
    report = hybrid.stability(factory(**EXACT))
    force = report.loop("n")
    k = 10 ** (force.gain_margin_db / 20)
    assert force.gain_margin_db == min(x.gain_margin_db for x in report.loops)  # the force loop's is the least
    factory(model_error=(k - 1) * 0.99, viscous_compensation=1.0)
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        factory(model_error=(k - 1) * 1.01, viscous_compensation=1.0)
    d = force.delay_margin_samples
    assert 0 < d < 20
    factory(sensor=hybrid.Sensor(delay_samples=d), **EXACT)
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        factory(sensor=hybrid.Sensor(delay_samples=d + 1), **EXACT)


def test_the_ur5s_gain_margin_holds_in_its_simulation():
    # the UR5 on a wall: a controller's model 10 % short of the gain margin settles after a force step, one 10 %
    # past it grows (its gravity error, which the model leaves out, does not move the boundary that far)
    wall = dict(UR5_WALL, duration=2.4, force_reference=hybrid.Step(10.0, 10.5, 0.12), viscous_compensation=1.0,
                allow_unstable=True)
    k = 10 ** (hybrid.stability(hybrid.tracing_experiment(model_error=0.0, **wall)).loop("n").gain_margin_db / 20)
    for scale, grown in ((0.9, False), (1.1, True)):
        exp = hybrid.tracing_experiment(model_error=(k - 1) * scale, **wall)
        assert hybrid.stability(exp, margins=False).stable != grown
        assert grows(force_error(exp)) == grown


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
        # the pair asked for, from its definition: s = w (-zeta + j sqrt(1 - zeta^2)), z = exp(s T)
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


def test_the_tiniest_and_largest_sample_times_get_a_verdict():
    exact = hybrid.paper_experiment(sample_time=1e-5, integration_step=1e-6, duration=0.01, **EXACT)
    fine = hybrid.stability(exact)
    # nearly continuous, the velocity loop (a PI² on the double integrator the law makes, the model exact) loses
    # no stability as its gain rises, and loses it as it falls below KI2v / (KPv KIv) (Routh's criterion)
    g = exact.gains
    assert fine.stable and fine.loop("t1").gain_margin_db == pytest.approx(20 * np.log10(g.KPv * g.KIv / g.KI2v),
                                                                           abs=0.01)
    # no rising limit within the thousandfold gain it looks at: the loop with its gain that much larger is stable
    from hybrid.stability.analysis import MOST_GAIN, axis_alone

    st, p = loop_numbers(hybrid.paper_experiment(sample_time=1e-5, integration_step=1e-6, duration=0.01))
    sub, q = axis_alone(st, p, list(st.force).index(True))
    assert abs(np.linalg.eigvals(closed_loop(sub, dict(q, gain=q["gain"] * MOST_GAIN))["A"])).max() < 1.0
    coarse = hybrid.stability(hybrid.paper_experiment(sample_time=0.025, duration=1.0, allow_unstable=True,
                                                      fault_reaction=hybrid.FaultReaction(stop_time=0.05)))
    assert not coarse.stable and np.isfinite(coarse.spectral_radius)


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


@pytest.mark.filterwarnings("ignore::hybrid.JointLimitWarning")  # the swinging run leaves them
def test_a_posture_tasks_null_space_loop_is_not_judged_as_the_docs_say():
    # the Panda's posture PD, sampled at 10 ms, holds with a damping of 180 (180 * T = 1.8 < 2) and swings at 220:
    # its task loops are predicted stable either way (docs/howto/stability.rst, where the model stops holding)
    base = hybrid.panda_experiment(duration=2.0)
    for damping, swings in ((180.0, False), (220.0, True)):
        exp = dataclasses.replace(base, posture=dataclasses.replace(base.posture, damping=damping))
        assert hybrid.stability(exp, margins=False).stable
        speed = np.abs(hybrid.simulate(exp).qdot).max()
        assert (speed > 3.0) == swings and (speed < 1.0) != swings, (damping, speed)


def test_the_gain_margin_holds_when_the_gain_falls_too():
    # a PI² velocity loop needs KPv KIv above KI2v: with KI2v at 0.75 KPv KIv the paper's arm loses its velocity
    # loop with a controller's model lighter than the arm, however much the gain may rise; the margin is the
    # smaller way, and the simulation (a speed step) settles 10 % inside it and grows 10 % past it
    g = hybrid.paper_experiment().gains
    gains = dataclasses.replace(g, KI2v=0.75 * g.KPv * g.KIv)
    wall = dict(PAPER_WALL, gains=gains, speed_reference=hybrid.Step(0.0, 0.02, 0.1), duration=6.0,
                allow_unstable=True)
    k = 10 ** (hybrid.stability(hybrid.paper_experiment(**wall)).loop("t1").gain_margin_db / 20)
    for scale, grown in ((1.1, False), (0.9, True)):
        exp = hybrid.paper_experiment(**dict(wall, model_error=scale / k - 1))
        assert hybrid.stability(exp, margins=False).stable != grown
        error = np.abs(hybrid.simulate(exp).velocity_tangential - 0.02)[exp.steps_per_sample * 20:]
        quarter = len(error) // 4
        assert (error[-quarter:].max() > error[:quarter].max()) == grown
    # the tuning's batched check keeps the same margin: just inside it holds, just past it does not
    from hybrid.stability.margin_check import MarginCheck
    base = hybrid.paper_experiment(**wall)
    for db, holds in ((0.98, True), (1.02, False)):
        check = MarginCheck.of([base], 20 * np.log10(k) * db, 0)
        assert (check.radius({"KI2v": np.array([gains.KI2v])})[0, 0] < 1.0) == holds


def _phase_margin_on_a_grid(exp, axis: int) -> float:
    """The phase margin [deg] of ``exp``'s loop on ``axis`` alone, from its frequency response on a fine grid
    (NumPy): the smallest angle between the loop ``L = c (zI - A)^-1 b`` and +1 (it closes with ``u = c X``)
    where ``|L|`` crosses 1, each crossing refined by bisection."""
    st, p = loop_numbers(exp)
    sub, q = axis_alone(st, p, axis)
    m = closed_loop(sub, q)
    A, b, c = m["A_open"], m["B_open"][:, 0], m["command"][0, :m["A_open"].shape[-1]]

    def loop(w: float) -> complex:
        return c @ np.linalg.solve(np.exp(1j * w) * np.eye(len(A)) - A, b)

    w = np.concatenate([np.geomspace(1e-6, 1e-2, 2000), np.linspace(1e-2, np.pi, 4000)])
    above = np.array([abs(loop(x)) > 1 for x in w])
    phases = []
    for i in np.flatnonzero(above[:-1] != above[1:]):
        lo, hi = w[i], w[i + 1]
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if (abs(loop(mid)) > 1) == above[i] else (lo, mid)
        phases.append(abs(np.degrees(np.angle(loop(lo)))))
    return min(phases) if phases else np.inf


@pytest.mark.parametrize("settings", [
    {}, {"sample_time": 0.005, "sensor": hybrid.Sensor(stiffness=300.0, mass=0.2)},
    {"sample_time": 0.002, "sensor": hybrid.Sensor(stiffness=2e4, delay_samples=1)},
    {"sample_time": 0.001, "sensor": hybrid.Sensor(stiffness=5e3, bandwidth_hz=50.0)}])
def test_the_phase_margins_are_those_of_the_loops_frequency_response(settings):
    # python-control finds the crossings as a polynomial's roots, some spurious (|L| = 13 there on the paper's
    # velocity loop, which read 68.5 deg for 71.5): the margins are the response's own
    exp = hybrid.paper_experiment(**settings)
    for i, loop in enumerate(hybrid.stability(exp).loops):
        assert loop.phase_margin_deg == pytest.approx(_phase_margin_on_a_grid(exp, i), abs=1e-4)
