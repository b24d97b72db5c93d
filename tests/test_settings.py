"""Experiment settings are checked strictly at construction; every combination runs or says why not."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hybrid


@pytest.mark.parametrize("overrides, match", [
    ({"integral": "no"}, "integral = 'no'; give True or False"),
    ({"curvature": 1}, "curvature = 1; give True or False"),
    ({"controller": ["task"]}, "controller = \\['task'\\]; give its name as a string"),
    ({"sensor": {"mass": 0.1}}, "sensor = .*; give a hybrid.Sensor"),
    ({"gains": None}, "gains = None; give a hybrid.Gains"),
    ({"F_d": "ten"}, "force_reference = 'ten'; give a hybrid.Step"),
    ({"v_d": [0.1, 0.2]}, r"speed_reference = \[0.1, 0.2\]; give a hybrid.Step"),
    ({"F_d": float("nan")}, "force_reference is nan"),
    ({"start_point": (0.3, 0.0, 0.0)}, "start_point must be two numbers"),
    ({"start_point": "origin"}, "start_point must be two numbers"),
    ({"elbow": True}, "elbow = True"),
    ({"elbow": 1.0}, "elbow = 1.0"),
    ({"model_error": "10%"}, "model_error must be a real number"),
    ({"duration": 0.105}, "not a whole number of samples of 0.01 s; give duration = 0.1 s"),
])
def test_settings_are_type_checked(overrides, match):
    with pytest.raises(hybrid.HybridError, match=match) as info:
        hybrid.paper_experiment(**overrides)
    assert len(str(info.value).splitlines()) == 1 and len(str(info.value)) < 300


def test_a_number_is_a_constant_reference():
    exp = hybrid.paper_experiment(F_d=12, v_d=0.2, duration=0.1)
    assert exp.force_reference == hybrid.Step(12.0, 12.0, 0.0)
    res = hybrid.simulate(exp)
    assert np.all(res.force_reference == 12.0) and math.isnan(res.metrics["force_overshoot_N"])


def test_step_metrics_outside_the_run_are_nan_not_missing():
    full = hybrid.simulate(hybrid.paper_experiment(duration=0.05)).metrics
    assert set(full) == set(hybrid.simulate(hybrid.paper_experiment()).metrics)
    assert math.isnan(full["force_overshoot_N"]) and math.isnan(full["speed_overshoot_after_speed_step_m_per_s"])


def test_start_point_off_the_surface_is_refused():
    with pytest.raises(hybrid.HybridError, match="start_point \\[0.25, 0.0\\] m is 50.0 mm off the surface"):
        hybrid.simulate(hybrid.paper_experiment(start_point=(0.25, 0.0)))


def test_a_run_that_cannot_fit_is_refused_before_any_work():
    exp = hybrid.paper_experiment(duration=1e6)  # 1e10 RK4 steps
    with pytest.raises(hybrid.HybridError,
                       match="10,000,000,001 RK4 steps, whose record needs .* GiB; this machine has"):
        hybrid.simulate(exp)


# every combination of settings either runs or raises a HybridError: never another exception
SETTINGS = st.fixed_dictionaries({}, optional={
    "controller": st.sampled_from(["task", "khatib", "raibert", 3]),
    "integral": st.sampled_from([True, False, "yes", 0]),
    "curvature": st.sampled_from([True, False, None]),
    "frame": st.sampled_from(["actual", "desired", "base"]),
    "model_error": st.one_of(st.floats(-2, 3), st.just(float("inf"))),
    "viscous_compensation": st.floats(-1, 2),
    "start_point": st.sampled_from([(0.3, 0.0), (0.3, 0.001), (0.7, 0.0), (0.5, 0.2), (0.0, 0.0), (1,)]),
    "elbow": st.sampled_from([1, -1, 0, 2]),
    "F_d": st.one_of(st.floats(-50, 100), st.builds(hybrid.Step, st.floats(-5, 40), st.floats(-5, 40),
                                                   st.floats(0.0, 0.2))),
    "v_d": st.one_of(st.floats(-1, 2), st.just("fast")),
    "duration": st.sampled_from([0.03, 0.05, 0.051, -0.1, 0.0]),
    "integration_step": st.sampled_from([1e-4, 2e-4, 5e-4, 1e-3, 3e-3, 0.0]),
    "sample_time": st.sampled_from([1e-2, 5e-3, 0.0101]),
    "KPv": st.floats(0, 500), "KPf": st.floats(0, 20), "KDf": st.floats(0, 500),
    "singular_tol": st.sampled_from([1e-3, 0.5, 0.99, 1.5, -0.1]),
    "backend": st.sampled_from(["sympy", "casadi", "numpy", "fortran"]),
    "surface": st.sampled_from([hybrid.Circle((0.5, 0.0), 0.2), hybrid.Plane((0.3, 0.0), (-1.0, 0.0)),
                                hybrid.Sphere((0.5, 0, 0), 0.2), "circle"]),
})


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(SETTINGS)
def test_every_setting_combination_runs_or_raises_a_hybrid_error(overrides):
    if overrides.get("backend") == "numpy":
        overrides["duration"] = 0.02  # the NumPy plant is slow; the point is what it raises
    try:
        res = hybrid.simulate(hybrid.paper_experiment(**overrides))
    except hybrid.HybridError as exc:
        assert str(exc).strip(), "an error must say something"
        return
    assert np.isfinite(res.state).all()


@pytest.mark.parametrize("overrides", [{"KPv": 1e300}, {"model_error": 2.0}, {"v_d": 100.0}, {"foo": 1},
                                       {"sensor": hybrid.Sensor(mass=1e-300)}])
def test_first_lines_of_messages_are_short(overrides):
    """The first line names the value and the fix; the details, if any, follow on their own lines."""
    with pytest.raises(hybrid.HybridError) as info:
        hybrid.simulate(hybrid.paper_experiment(**overrides))
    first = str(info.value).splitlines()[0]
    assert 20 < len(first) <= 250, first


class _Untouched:
    """A setting that fails whatever reads it (its attributes, comparisons, conversions)."""

    def __getattribute__(self, name):
        raise AssertionError(f"a check read .{name} of a physics setting")

    def _read(self, *args):
        raise AssertionError("a check used a physics setting")

    __eq__ = __ne__ = __lt__ = __le__ = __gt__ = __ge__ = __bool__ = __float__ = __int__ = __index__ = _read
    __hash__ = __format__ = __repr__ = __str__ = __add__ = __radd__ = __mul__ = __rmul__ = __neg__ = _read


WITH_PHYSICS_BASES = [hybrid.paper_experiment(), hybrid.tracing_experiment(frame="desired"), hybrid.panda_experiment(),
                      hybrid.tracing_experiment(start_gap=0.002, approach_speed=0.05,
                                                wrench_sensor=hybrid.WrenchSensor())]


@pytest.mark.parametrize("base", WITH_PHYSICS_BASES)
def test_only_four_checks_read_an_experiments_physics(base, monkeypatch):
    """What Experiment.with_physics rests on: of the checks, only these four read PHYSICS."""
    import dataclasses

    from hybrid.experiments import experiment

    for name in ("check_common_types", "check_sensing", "check_timing", "check_stable"):
        monkeypatch.setattr(experiment, name, lambda exp: None)
    dataclasses.replace(base, **{name: _Untouched() for name in experiment.PHYSICS})


@pytest.mark.parametrize("changes", [
    {"model_error": 0.3}, {"model_error": -0.0, "viscous_compensation": 0}, {"model_error": -1.0},
    {"model_error": "10%"}, {"viscous_compensation": -0.5}, {"model_error": float("nan")},
    {"contact": hybrid.Contact(friction=0.3)}, {"contact": hybrid.Contact(stiffness=1e12)},
    {"sensor": hybrid.Sensor(stiffness=500.0, mass=0.05)}, {"sensor": hybrid.Sensor(delay_samples=2)},
    {"sensor": hybrid.Sensor(bias=(0.1, 0, 0, 0, 0, 0))}, {"sensor": "sensor"}, {"contact": None},
    {"model_error": 5.0, "contact": hybrid.Contact(stiffness=1e12)},
])
@pytest.mark.parametrize("base", WITH_PHYSICS_BASES)
def test_with_physics_makes_what_replace_makes_or_raises_what_it_raises(base, changes):
    import dataclasses

    try:
        want = dataclasses.replace(base, **changes)
    except hybrid.HybridError as exc:
        with pytest.raises(hybrid.HybridError) as info:
            base.with_physics(**changes)
        assert str(info.value) == str(exc)
        return
    got = base.with_physics(**changes)
    assert got == want and got.__dict__.keys() == want.__dict__.keys()
    assert all(type(got.__dict__[k]) is type(v) for k, v in want.__dict__.items())
    with pytest.raises(ValueError, match="not PHYSICS"):
        base.with_physics(gains=hybrid.Gains())


def test_a_subclass_that_checks_its_physics_itself_is_made_whole():
    import dataclasses

    @dataclasses.dataclass(frozen=True, kw_only=True)
    class Careful(hybrid.Experiment):
        def __post_init__(self):
            super().__post_init__()
            if self.model_error > 0.2:
                raise hybrid.HybridError("Careful: model_error > 0.2")

    careful = Careful(**{f.name: getattr(hybrid.paper_experiment(duration=0.02), f.name)
                         for f in dataclasses.fields(hybrid.Experiment)})
    assert not Careful.physics_alone() and hybrid.Experiment.physics_alone()
    with pytest.raises(hybrid.HybridError, match="Careful"):
        careful.with_physics(model_error=0.3)
    table = hybrid.sweep(careful, {"model_error": [0.1, 0.3]}, workers=1)
    assert list(table["status"]) == ["ok", "invalid"] and table["error"][1] == "Careful: model_error > 0.2"
