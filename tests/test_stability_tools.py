"""The stability map against the experiment's own judgement point by point, and suggested gains against
the poles they were asked for and the damping the simulated step shows; bad input refused in words."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from matplotlib.figure import Figure

import hybrid
from hybrid.stability.analysis import _poles, axis_alone
from hybrid.stability.experiment_loops import loop_numbers
from hybrid.stability.model import closed_loop
from hybrid.sweeps import apply

#: the paper's arm pressing on a wall at rest, stepping its force by 0.1 N at 0.1 s (no friction)
WALL = dict(surface=hybrid.Plane(point=(0.3, 0.0, 0.0), normal=(-1.0, 0.0, 0.0)), start_point=(0.3, 0.0),
            contact=hybrid.Contact(friction=0.0), speed_reference=hybrid.Step(0.0, 0.0, 0.0),
            force_reference=hybrid.Step(10.0, 10.1, 0.1), duration=1.5)


def test_every_point_of_a_map_is_the_experiments_own_verdict():
    exp = hybrid.paper_experiment(wrench_sensor=hybrid.WrenchSensor(cutoff=30.0))
    over = {"sensor.stiffness": [800.0, 6e3, 3e4], "sample_time": [0.002, 0.008, 0.025], "sensor.delay_samples": [0, 2],
            "KPf": [0.0, 1.0, 4.0], "model_error": [-0.2, 0.4], "sensor.bandwidth_hz": [10.0, 24.0],
            "wrench_sensor.cutoff": [5.0, 20.0]}
    smap = hybrid.stability_map(exp, over)
    table = smap.table
    assert len(table) == 3 * 3 * 2 * 3 * 2 * 2 * 2 and 0 < smap.stable_share < 1
    rng = np.random.default_rng(1)
    invalid = 0
    for i in rng.choice(len(table), 40, replace=False):
        row = table.iloc[i]
        settings = {name: row[name] for name in over}
        settings["sensor.delay_samples"] = int(settings["sensor.delay_samples"])
        T = settings.pop("sample_time")
        if settings["sensor.bandwidth_hz"] >= 0.5 / T or settings["wrench_sensor.cutoff"] >= 0.5 / T:
            assert np.isnan(row["spectral_radius"]) and not row["stable"]  # no such loop: a lag past Nyquist
            invalid += 1
            continue
        point = apply(dataclasses.replace(exp, allow_unstable=True),
                      {**settings, "sample_time": T, "integration_step": T / 100, "duration": 100 * T})
        own = hybrid.stability(point, margins=False).spectral_radius
        assert row["spectral_radius"] == pytest.approx(own, rel=1e-9), settings
        assert bool(row["stable"]) == hybrid.stability(point, margins=False).stable
    assert 0 < invalid < 40


def test_a_map_draws_its_boundary():
    exp = hybrid.paper_experiment()
    two = hybrid.stability_map(exp, {"sensor.stiffness": np.geomspace(1e3, 1e5, 12),
                                     "sample_time": np.geomspace(1e-3, 2e-2, 10)})
    fig = two.figure()
    assert isinstance(fig, Figure) and two.table["stable"].any() and not two.table["stable"].all()
    assert fig.axes[0].collections and len(fig.axes[0].collections) >= 2  # the map and its boundary
    assert fig.axes[0].get_xscale() == "log"
    three = hybrid.stability_map(exp, {"sensor.stiffness": [1e3, 1e4], "sample_time": [0.005, 0.01],
                                       "sensor.delay_samples": [0, 1, 2, 3, 4, 5, 6, 7]})
    assert len(three.figure().axes) == 6 + 1  # six panels at most, and the colour bar
    assert len(hybrid.stability_map(exp, {"KPf": [1.0, 2.0, 40.0]}).figure().axes) == 1


@pytest.mark.parametrize("over, match", [
    ({}, "give settings and their values"),
    ([("KPf", [1.0])], "give settings and their values"),
    ({"contact.friction": [0.1]}, "cannot vary 'contact.friction'"),
    ({"sensor.stiffness": [-1.0]}, "sensor.stiffness = -1 in the map"),
    ({"sample_time": [0.0, 0.01]}, "sample time > 0"),
    ({"KPf": ["a"]}, "list of finite numbers"),
    ({"KPf": []}, "non-empty"),
    ({"KPf": [np.nan]}, "finite numbers"),
    ({"sensor.delay_samples": [1.5]}, "delay_samples"),
    ({"model_error": [-1.0]}, "model error > -1"),
    ({"wrench_sensor.cutoff": [5.0]}, "has no wrench_sensor"),
    ({"KPf": np.ones(1001), "KDf": np.ones(1001)}, "over 1,000,000"),
])
def test_bad_maps_are_refused_with_the_fix(over, match):
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.stability_map(hybrid.paper_experiment(), over)


def test_a_map_refuses_what_the_experiment_would_ignore():
    with pytest.raises(hybrid.HybridError, match="integral=False"):
        hybrid.stability_map(hybrid.paper_experiment(integral=False), {"KIf": [1.0, 5.0]})
    told = hybrid.paper_experiment(controller_robot=hybrid.paper_experiment().controller_model(), model_error=0.1)
    with pytest.raises(hybrid.HybridError, match="controller_robot"):
        hybrid.stability_map(told, {"model_error": [0.0]})


def _force_axis(exp):
    st, p = loop_numbers(exp)
    sub, q = axis_alone(st, p, list(st.force).index(True))
    return _poles(closed_loop(sub, q)["A"])


@pytest.mark.parametrize("bandwidth, damping, ratio, T", [(3.0, 0.7, 0.25, 0.01), (8.0, 0.4, 0.5, 0.01),
                                                          (20.0, 0.6, 0.1, 0.002), (1.5, 0.9, 0.0, 0.005)])
def test_suggested_gains_place_the_poles_asked_for(bandwidth, damping, ratio, T):
    exp = hybrid.paper_experiment(sample_time=T, integration_step=T / 100)
    s = hybrid.suggest_gains(exp, bandwidth_hz=bandwidth, damping=damping, integral_ratio=ratio)
    wanted = s.poles["force"]
    # from the continuous poles' definition, independently: s = w (-zeta +- j sqrt(1 - zeta^2)), z = exp(s T)
    w = 2 * np.pi * bandwidth
    pair = np.exp(w * (-damping + 1j * np.sqrt(1 - damping ** 2)) * T)
    assert min(abs(wanted - pair)) < 1e-12 and (ratio == 0 or min(abs(wanted - np.exp(-ratio * w * T))) < 1e-12)
    found = _force_axis(dataclasses.replace(exp, gains=s.gains, allow_unstable=True))
    assert max(min(abs(found - z)) for z in wanted) < 1e-9
    assert s.stability.loop("n").stable and s.gains.KIf == (0.0 if ratio == 0 else s.gains.KIf) > -1


def _decrement_damping(t, e, period):
    """The damping ratio from the logarithmic decrement of ``e``'s first two positive peaks, a
    ``period`` [s] apart (each the largest value within half a period around it)."""
    first = np.argmax(np.where(t < t[0] + period, e, -np.inf))
    later = (t > t[first] + 0.5 * period) & (t < t[first] + 1.5 * period)
    second = np.flatnonzero(later)[np.argmax(e[later])]
    d = np.log(e[first] / e[second])
    return d / np.sqrt(4 * np.pi ** 2 + d * d)


@pytest.mark.parametrize("bandwidth, damping, T", [(4.0, 0.5, 0.01), (8.0, 0.2, 0.01), (25.0, 0.5, 0.01),
                                                   (15.0, 0.4, 0.002), (40.0, 0.3, 0.01)])
def test_the_simulated_step_has_the_damping_asked_for(bandwidth, damping, T):
    exp = hybrid.paper_experiment(**WALL, sample_time=T, integration_step=T / 100, integral=False)
    s = hybrid.suggest_gains(exp, bandwidth_hz=bandwidth, damping=damping, integral_ratio=0.0)
    res = hybrid.simulate(dataclasses.replace(exp, gains=s.gains))
    after = res.t >= 0.1
    t, error = res.t[after], res.force_normal[after] - res.force_normal[-1]
    period = 1.0 / (bandwidth * np.sqrt(1 - damping ** 2))
    zeta = _decrement_damping(t, error, period)  # the error starts below 0: its first peak is the overshoot
    assert zeta == pytest.approx(damping, rel=0.05)


@pytest.mark.parametrize("kwargs, match", [
    ({"bandwidth_hz": 60.0}, "at or above the Nyquist frequency 50 Hz"),
    ({"bandwidth_hz": -1.0}, "give a frequency in Hz"),
    ({"bandwidth_hz": {"position": 1.0}}, "mapping"),
    ({"bandwidth_hz": {}}, "mapping"),
    ({"bandwidth_hz": 5.0, "damping": 0.0}, "damping ratio"),
    ({"bandwidth_hz": 5.0, "integral_ratio": -1.0}, "integral_ratio"),
    ({"bandwidth_hz": 5.0, "damping": True}, "damping ratio"),
])
def test_bad_requests_are_refused_with_the_fix(kwargs, match):
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.suggest_gains(hybrid.paper_experiment(), **kwargs)


def test_an_unreachable_bandwidth_says_what_is_reachable():
    exp = hybrid.paper_experiment(sample_time=0.002, integration_step=1e-4)
    with pytest.raises(hybrid.HybridError, match=r"cannot be met .*the largest met is about ([\d.]+) Hz") as info:
        hybrid.suggest_gains(exp, bandwidth_hz=40.0, damping=0.3, integral_ratio=0.0)
    reachable = float(info.value.args[0].split("the largest met is about ")[1].split(" Hz")[0])
    assert hybrid.suggest_gains(exp, bandwidth_hz=reachable * 0.99, damping=0.3, integral_ratio=0.0).stability.stable
    with pytest.raises(hybrid.HybridError, match="integral=False"):
        hybrid.suggest_gains(hybrid.paper_experiment(integral=False), bandwidth_hz=3.0)


def test_both_loops_at_once():
    s = hybrid.suggest_gains(hybrid.paper_experiment(), bandwidth_hz={"force": 3.0, "velocity": 2.0})
    assert set(s.poles) == {"force", "velocity"} and s.stability.stable
    st, p = loop_numbers(dataclasses.replace(hybrid.paper_experiment(), gains=s.gains))
    sub, q = axis_alone(st, p, list(st.force).index(False))
    found = _poles(closed_loop(sub, q)["A"])
    assert max(min(abs(found - z)) for z in s.poles["velocity"]) < 1e-9


def test_the_command_line_judges_maps_and_refuses(capsys, tmp_path):
    import json

    import pandas as pd

    from hybrid.cli.main import main

    out = tmp_path / "s"
    assert main(["stability", "--set", "KPf=3", "--over", "sensor.stiffness=1e3:1e5:6:log",
                 "--over", "sensor.delay_samples=0,1", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    report = json.loads((out / "stability.json").read_text())
    own = hybrid.stability(hybrid.paper_experiment(KPf=3.0))
    assert report["loops"][1]["spectral_radius"] == pytest.approx(own.loop("n").spectral_radius, rel=1e-12)
    assert "force" in printed and "of the 12 points are stable" in printed
    table = pd.read_csv(out / "map.csv")
    assert list(table.columns) == ["sensor.stiffness", "sensor.delay_samples", "spectral_radius", "stable"]
    assert (out / "map.png").stat().st_size > 1000
    for args, words in ((["--over", "KPf=1"], "give --out DIR"),
                        (["--over", "KPf=1:2", "--out", str(out)], "NAME=START:STOP:COUNT"),
                        (["--over", "KPf=1", "--out", str(out)], "pass --force"),
                        (["--over", "KPf=-1:2:3:log", "--out", str(tmp_path / "t")], "positive"),
                        (["--over", "contact.friction=0.1", "--out", str(tmp_path / "t")], "cannot vary")):
        assert main(["stability", *args]) == 2
        assert words in capsys.readouterr().err
