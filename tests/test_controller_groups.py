"""The Controller's settings in three groups (Tracking, Limits, Sensing): the same controller as the flat
keywords, on random settings; the groups cover the flat keywords exactly, with the same defaults; a setting
given both ways, a group of the wrong type or a bad number in a group is refused; the records read back."""

from __future__ import annotations

import dataclasses
import inspect

import numpy as np
import pytest

import hybrid
from hybrid.control.controller_settings import GROUPS

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
Q = np.array([0.0, -1.2, 1.5, -1.9, -1.57, 0.0])
#: the keywords that are not settings of a group: what the task is
TASK = ("robot", "surface", "scheme", "axes", "selection")


def flat_signature() -> inspect.Signature:
    """The controller's own keywords, without the groups (the function under the decorators)."""
    return inspect.signature(inspect.unwrap(hybrid.Controller.__init__))


def test_the_groups_cover_the_flat_keywords_once_with_the_same_defaults():
    flat = {k: p.default for k, p in flat_signature().parameters.items() if k != "self" and k not in TASK}
    grouped = [f for cls in GROUPS.values() for f in dataclasses.fields(cls)]
    assert sorted(f.name for f in grouped) == sorted(flat)  # each flat keyword in exactly one group
    for f in grouped:
        assert f.default == flat[f.name], f"{f.name}: the group's default {f.default!r} is not {flat[f.name]!r}"
    advertised = inspect.signature(hybrid.Controller).parameters
    assert set(GROUPS) <= set(advertised) and set(flat) <= set(advertised)


def random_settings(rng) -> dict:
    """Settings of every group drawn at random (each a value the controller takes)."""
    choose = lambda *options: options[rng.integers(len(options))]  # noqa: E731
    sensor = choose(None, hybrid.WrenchSensor(cutoff=float(rng.uniform(5.0, 20.0)), order=2))
    return {
        "gains": choose(None, hybrid.Gains(KPv=float(rng.uniform(5, 40)), KPf=float(rng.uniform(0.5, 3)))),
        "force_reference": float(rng.uniform(5, 20)),
        "velocity_reference": choose(0.0, float(rng.uniform(-0.2, 0.2)), hybrid.Step(0.0, 0.1, 0.02)),
        "integral": bool(rng.integers(2)), "curvature": bool(rng.integers(2)),
        "frame_direction": choose(None, (0.0, 1.0, 0.2)),
        "sample_time": choose(0.01, 0.002, 0.005), "timing_tolerance": choose(None, 0.1, 0.25),
        "torque_limit": choose("urdf", None, float(rng.uniform(20, 200))),
        "torque_step_limit": choose(None, float(rng.uniform(0.5, 5))),
        "integral_limit": choose(None, float(rng.uniform(0.1, 10))),
        "singular_tol": choose(1e-3, 1e-4), "fault_reaction": choose(None, hybrid.FaultReaction(fault_samples=3)),
        "wrench_sensor": sensor,
        "contact_loss": choose(None, hybrid.ContactLoss(threshold=float(rng.uniform(0.1, 1.0)),
                                                         approach_speed=0.02)),
    }


def split(settings: dict) -> dict:
    """``settings`` as the three records."""
    return {keyword: cls(**{k: v for k, v in settings.items() if k in {f.name for f in dataclasses.fields(cls)}})
            for keyword, cls in GROUPS.items()}


def run(ctrl, rng_seed: int, samples: int = 6) -> np.ndarray:
    """The torques of a few samples on time, from states and wrenches drawn with ``rng_seed``."""
    rng = np.random.default_rng(rng_seed)
    wrench = 6 if ctrl.wrench_sensor is not None else 3
    return np.array([ctrl(k * ctrl.sample_time, Q + rng.normal(0, 0.02, 6), rng.normal(0, 0.1, 6),
                          rng.normal(0, 5, wrench)) for k in range(samples)])


@pytest.mark.parametrize("seed", range(6))
def test_grouped_equals_flat_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    settings = random_settings(rng)
    flat = hybrid.Controller(hybrid.ur5(), SPHERE, **settings)
    groups = hybrid.Controller(hybrid.ur5(), SPHERE, **split(settings))
    # the groups read back as given, and a controller built from them is the same controller again
    again = hybrid.Controller(hybrid.ur5(), SPHERE, tracking=flat.tracking, limits=flat.limits, sensing=flat.sensing)
    for ctrl in (groups, again):
        for name, value in flat.step_inputs().items():
            np.testing.assert_array_equal(ctrl.step_inputs()[name], value, err_msg=name)
        assert (ctrl.sample_time, ctrl.timing_tolerance, ctrl.singular_tol) == \
            (flat.sample_time, flat.timing_tolerance, flat.singular_tol)
    np.testing.assert_array_equal(run(groups, seed), run(flat, seed))
    np.testing.assert_array_equal(run(again, seed), run(hybrid.Controller(hybrid.ur5(), SPHERE, **settings), seed))


def test_groups_mix_with_flat_keywords_of_other_groups():
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, limits=hybrid.Limits(sample_time=0.002), force_reference=12.0)
    assert ctrl.sample_time == 0.002 and ctrl.tracking.force_reference == 12.0
    assert ctrl.limits == hybrid.Limits(sample_time=0.002)


@pytest.mark.parametrize("keyword, group", [("sample_time", hybrid.Limits()), ("gains", hybrid.Tracking()),
                                            ("contact_loss", hybrid.Sensing())])
def test_a_setting_given_twice_is_refused(keyword, group):
    keywords = {"sample_time": 0.01, "gains": hybrid.Gains(), "contact_loss": None}
    name = {hybrid.Limits: "limits", hybrid.Tracking: "tracking", hybrid.Sensing: "sensing"}[type(group)]
    with pytest.raises(hybrid.HybridError, match=f"^{keyword} is given twice, as a keyword and in {name}="):
        hybrid.Controller(hybrid.ur5(), SPHERE, **{keyword: keywords[keyword], name: group})


def test_a_group_of_the_wrong_kind_is_refused():
    with pytest.raises(hybrid.HybridError, match=r"^limits = .*give a hybrid.Limits"):
        hybrid.Controller(hybrid.ur5(), SPHERE, limits=hybrid.Tracking())
    with pytest.raises(hybrid.HybridError, match=r"^sensing = .*give a hybrid.Sensing"):
        hybrid.Controller(hybrid.ur5(), SPHERE, sensing={"contact_loss": None})


@pytest.mark.parametrize("cls, field, value", [
    (hybrid.Limits, "sample_time", 0.0), (hybrid.Limits, "sample_time", float("nan")),
    (hybrid.Limits, "timing_tolerance", 1.5), (hybrid.Limits, "integral_limit", -1.0),
    (hybrid.Limits, "singular_tol", 2.0), (hybrid.Limits, "fault_reaction", 5),
    (hybrid.Tracking, "integral", 1), (hybrid.Tracking, "frame", "tool"),
    (hybrid.Sensing, "wrench_sensor", "ati"), (hybrid.Sensing, "contact_loss", 0.5)])
def test_a_bad_number_is_refused_in_its_record_as_by_the_flat_keyword(cls, field, value):
    with pytest.raises(hybrid.HybridError) as in_record:
        cls(**{field: value})
    with pytest.raises(hybrid.HybridError) as flat:
        hybrid.Controller(hybrid.ur5(), SPHERE, **{field: value})
    assert str(in_record.value) == str(flat.value)


def test_the_records_read_back_what_changed_between_samples():
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, wrench_sensor=hybrid.WrenchSensor(cutoff=10.0))
    ctrl.sample_time, ctrl.timing_tolerance = 0.005, None
    sensor = hybrid.WrenchSensor(cutoff=12.0)
    ctrl.set_wrench_sensor(sensor)
    assert ctrl.limits.sample_time == 0.005 and ctrl.limits.timing_tolerance is None
    assert ctrl.sensing.wrench_sensor is sensor
    with pytest.raises(dataclasses.FrozenInstanceError):
        ctrl.limits.sample_time = 0.01  # a record is a copy: the controller's settings change on the controller
