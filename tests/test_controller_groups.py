"""The Controller's settings in three groups (Tracking, Limits, Sensing): the same controller as the flat
keywords, on random settings; the groups cover the flat keywords exactly, with the same defaults; a setting
given both ways, a group of the wrong type or a bad number in a group is refused; the records read back. A
controller copied or pickled is the same controller, its run carried over: on the same samples it gives the
torques, bit for bit, of a twin that was never copied, and the copies run on independently."""

from __future__ import annotations

import copy
import dataclasses
import inspect
import pickle

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


# --------------------------------------------------------------------------- copies and pickles


def events(ctrl, seed: int, count: int) -> list[tuple]:
    """``count`` samples ``(t, q, qdot, wrench)`` drawn with ``seed``: on time, with a late one (two periods on)
    and one whose q is not finite (refused) among them, so the clock and the fault reaction's state move too."""
    rng = np.random.default_rng(seed)
    n, wrench = ctrl.robot.n, 6 if ctrl.wrench_sensor is not None else ctrl.robot.kind.force_size
    q0 = Q if n == 6 else np.array([2.2, 1.9])
    out, t = [], 0.0
    for k in range(count):
        q = q0 + rng.normal(0, 0.02, n)
        if k == 3:
            q[0] = np.nan
        out.append((t, q, rng.normal(0, 0.1, n), rng.normal(0, 5, wrench)))
        t += ctrl.sample_time * (2 if k == 5 else 1)
    return out


def served(ctrl, sample: tuple) -> tuple:
    """What a sample gives: its torque, or the error's kind and the torque it carries."""
    try:
        return ("torque", ctrl(*sample))
    except hybrid.HybridError as exc:
        return (type(exc).__name__, exc.torque)


def assert_same_run(copies: dict, twin, samples: list) -> None:
    """Each copy and the twin give the same results on ``samples``, bit for bit, the copies taking turns."""
    for k, sample in enumerate(samples):
        kind, expected = served(twin, sample)
        for how, ctrl in copies.items():
            got_kind, got = served(ctrl, sample)
            assert got_kind == kind, f"{how}, sample {k}: {got_kind}, the twin {kind}"
            np.testing.assert_array_equal(got, expected, err_msg=f"{how}, sample {k}")
    for how, ctrl in copies.items():
        np.testing.assert_array_equal(ctrl.state, twin.state, err_msg=how)
        np.testing.assert_array_equal(ctrl.fault_state, twin.fault_state, err_msg=how)
        for name, value in twin.last.items():
            np.testing.assert_array_equal(ctrl.last[name], value, err_msg=f"{how}: last[{name!r}]")


def copies_of(ctrl) -> dict:
    return {"pickle": pickle.loads(pickle.dumps(ctrl)), "deepcopy": copy.deepcopy(ctrl), "copy": copy.copy(ctrl),
            "original": ctrl}


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("split", [0, 2, 7])
def test_a_copy_or_pickle_is_the_same_controller_with_its_run(seed, split):
    """Copied before its first sample (a force of 3 numbers is then read into a view of the step's buffer) or
    after some, on random settings of every group; a live setting changed before the copy is carried too."""
    settings = random_settings(np.random.default_rng(seed))
    twin, ctrl = (hybrid.Controller(hybrid.ur5(), SPHERE, **settings) for _ in range(2))
    samples = events(twin, seed, 12)
    for c in (twin, ctrl):
        c.singular_tol = 2e-3
        for sample in samples[:split]:
            served(c, sample)
    made = copies_of(ctrl)
    for how, c in made.items():
        np.testing.assert_array_equal(c.state, twin.state, err_msg=how)  # the integrals carried over
        assert c.singular_tol == 2e-3 and c.last is None if split == 0 else c.last is not None
    assert_same_run(made, twin, samples[split:])


def path_point(t: float):
    """A desired point moving along base x (at the module's top level: a pickle names it)."""
    return (np.array([0.5 + 0.05 * t, 0.02, 0.36]), np.array([0.05, 0.0, 0.0]))


def speed(t: float) -> float:
    """A speed reference along t1 given as code [m/s]."""
    return 0.1 * t


PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))


def raster():
    return hybrid.RasterPath(PLANE, PLANE.project(np.array([0.45, -0.05, 0.1])), (1.0, 0.0, 0.0), 0.08, 0.01, 3)


@pytest.mark.parametrize("build", [
    lambda: hybrid.Controller(hybrid.ur5(), PLANE, path_task=hybrid.PathTask(raster(), speed=0.05, force=8.0)),
    lambda: hybrid.Controller(hybrid.ur5(), hybrid.EstimatedSurface(initial_normal=(0.0, 0.3, 1.0)),
                              wrench_sensor=hybrid.WrenchSensor(cutoff=15.0, order=2), torque_step_limit=50.0),
    lambda: hybrid.Controller(hybrid.ur5(), SPHERE, frame="desired", path=path_point, position_error=True,
                              velocity_reference={"t1": speed}, torque_limit=None),
    lambda: hybrid.Controller(hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2), "khatib",
                              fault_reaction=hybrid.FaultReaction(fault_samples=2)),
], ids=["path_task", "estimated_sensor", "desired_path", "planar_faults"])
def test_every_kind_of_run_is_carried_by_a_copy(build):
    """A path task's progress, an estimate and a sensor's filter, references and a path given as code, a
    planar arm that enters its safe state: all carried, bit for bit."""
    twin, ctrl = build(), build()
    samples = events(twin, 11, 14)
    results = [served(c, s) for s in samples[:8] for c in (twin, ctrl)]
    assert sum(kind == "torque" for kind, _ in results) >= 4, "a run the law served"
    moved = np.any(ctrl.state != 0.0) or ctrl.stopped or (ctrl.path_task or {}).get("travelled", 0.0) > 0.0
    assert moved, "a run whose integrals or path moved, or that stopped"
    assert_same_run(copies_of(ctrl), twin, samples[8:])


def test_a_set_sensor_and_a_reset_are_carried_and_each_copy_runs_alone():
    sensor = hybrid.WrenchSensor(cutoff=10.0)
    twin, ctrl = (hybrid.Controller(hybrid.ur5(), SPHERE, wrench_sensor=sensor) for _ in range(2))
    samples = events(twin, 3, 10)
    for c in (twin, ctrl):
        served(c, samples[0])
        c.set_wrench_sensor(hybrid.WrenchSensor(cutoff=12.0, order=2))
        served(c, samples[1])
    made = copies_of(ctrl)
    assert all(c.sensing.wrench_sensor == hybrid.WrenchSensor(cutoff=12.0, order=2) for c in made.values())
    made["copy"].reset()  # a reset of one is not the others'
    assert_same_run({k: v for k, v in made.items() if k != "copy"}, twin, samples[2:])


def test_a_run_that_does_not_fit_its_controller_is_refused():
    """A pickle's run whose buffers are not the controller's (as another version's may be) is refused by name,
    not poured into buffers of other sizes."""
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE)
    served(ctrl, events(ctrl, 0, 1)[0])
    rebuild, args, run = ctrl.__reduce__()
    for name, short in (("held", run["held"][:-1]), ("fault", run["fault"][:-1]), ("params", run["params"][1:])):
        with pytest.raises(hybrid.HybridError, match="^this controller's run does not fit"):
            rebuild(*args).__setstate__({**run, name: short})
