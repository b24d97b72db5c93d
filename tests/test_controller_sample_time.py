"""A sample time changed between samples is the period of everything after it: the loops' integrals advance by
it (as the loops' equations say, and bit for bit as in a controller built with it and brought to the same
state), the C that ``generate`` writes and a copy take it, a path task's follower runs on it; one that is no
sample time, or one the estimate or the path task cannot be sampled at, refuses the sample and changes nothing.
(The standalone C with its ``sample_time`` changed alike: tests/test_controller_failsafe.py.)"""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

import hybrid
from hybrid.spec.controller_step import OPTIONS
from hybrid.spec.path_follow import PATH_SETTINGS

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
Q = np.array([0.0, -1.2, 1.5, -1.9, -1.57, 0.0])
#: the references: 0.1 m/s along t1, 15 N on the normal, 0 on the other axes (the task axes' order)
YD = np.array([0.1, 0.0, 15.0, 0.0, 0.0, 0.0])
SETTINGS = {"force_reference": 15.0, "velocity_reference": 0.1, "torque_step_limit": 20.0,
            "gains": hybrid.Gains(KPv=20.0, KIv=150.0, KI2v=800.0)}


def samples(seed: int, count: int) -> list[tuple]:
    """``count`` measurements ``(q, qdot, wrench)`` near the pose ``Q``, pressing on the sphere about 15 N."""
    rng = np.random.default_rng(seed)
    return [(Q + rng.normal(0, 0.01, 6), rng.normal(0, 0.05, 6), np.array([0.0, 0.0, -15.0]) + rng.normal(0, 2, 3))
            for _ in range(count)]


def expected_integrals(before: np.ndarray, last: dict, T: float) -> np.ndarray:
    """The loops' integrals after a sample (conventions §4, no anti-windup or contact loss set): ``z1 + T e``
    and ``z2 + T z1'`` on a velocity axis (``e = v_d - y``), ``z1 + T e`` and 0 on the force axis
    (``e = F_d - f``); kept as they were where a limit bounded the torque."""
    if last["saturated"]:
        return before
    force = np.array([0.0, 0.0, 1.0, 0.0, 0.0, 0.0])
    e = force * (YD - last["f"]) + (1 - force) * (YD - last["y"])
    z1 = before[:, 0] + T * e
    return np.column_stack([z1, (1 - force) * (before[:, 1] + T * z1)])


@pytest.mark.parametrize("k", [1, 4])
@pytest.mark.parametrize("T1, T2", [(0.01, 0.002), (0.002, 0.01), (0.005, 0.0125)])
def test_a_changed_sample_time_is_the_period_of_the_samples_after_it(T1, T2, k):
    """After ``k`` samples at ``T1`` the period becomes ``T2``: the integrals then advance by ``T2`` as the loops'
    equations say (not by ``T1``), and the torques are, bit for bit, those of a controller built with ``T2``
    and given the same integrals and last torque; the C ``generate`` writes starts at ``T2``, a reset keeps it."""
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, sample_time=T1, **SETTINGS)
    measured = samples(k, k + 6)
    for j, (q, qd, w) in enumerate(measured[:k]):
        ctrl(j * T1, q, qd, w)
    ctrl.sample_time = T2
    twin = hybrid.Controller(hybrid.ur5(), SPHERE, sample_time=T2, **SETTINGS)
    twin.reset(torque=ctrl.last["tau"])
    twin.state = ctrl.state
    at = OPTIONS.index("sample_time")
    assert ctrl.step_inputs()["options"][at] == ctrl.step_inputs(at_start=True)["options"][at] == T2
    t, discriminated = (k - 1) * T1, False
    for q, qd, w in measured[k:]:
        t += T2
        before = ctrl.state
        tau = ctrl(t, q, qd, w)
        np.testing.assert_array_equal(tau, twin(t, q, qd, w))
        np.testing.assert_array_equal(ctrl.state, twin.state)
        expected = expected_integrals(before, ctrl.last, T2)
        np.testing.assert_allclose(ctrl.state, expected, rtol=1e-12, atol=1e-15)
        discriminated |= not np.allclose(expected_integrals(before, ctrl.last, T1), expected, rtol=1e-6, atol=0)
    assert discriminated, "the integrals at T1 would have been told apart from those at T2"
    ctrl.reset()
    assert ctrl.sample_time == T2 and ctrl.step_inputs(at_start=True)["options"][at] == T2


def built(kind: str, **limits):
    """A controller whose step reads the sample time beyond its integrals: a path task's follower, or an estimated
    surface with a sensor's filter."""
    if kind == "path_task":
        path = hybrid.RasterPath(PLANE, PLANE.project(np.array([0.45, -0.05, 0.1])), (1.0, 0.0, 0.0), 0.08, 0.01, 3)
        return hybrid.Controller(hybrid.ur5(), PLANE, path_task=hybrid.PathTask(path, speed=0.05, force=8.0),
                                 **limits)
    return hybrid.Controller(hybrid.ur5(), hybrid.EstimatedSurface(initial_normal=(0.0, 0.3, 1.0),
                                                                   force_time_constant=0.02),
                             wrench_sensor=hybrid.WrenchSensor(cutoff=10.0, order=2), torque_step_limit=50.0, **limits)


def measurement(kind: str, seed: int) -> tuple:
    rng = np.random.default_rng(seed)
    q, qd = Q + rng.normal(0, 0.01, 6), rng.normal(0, 0.05, 6)
    return q, qd, rng.normal(0, 5, 6) if kind != "path_task" else np.array([0.0, -4.8, -6.4])


@pytest.mark.parametrize("kind", ["path_task", "estimated_sensor"])
def test_a_copy_takes_the_changed_sample_time_and_runs_on_it(kind):
    """Changed, then copied or pickled: every copy runs on the new period as the original does, bit for bit, a
    path task's follower included (its settings, which the C ``generate`` writes, hold the new period at once)."""
    slow = hybrid.FaultReaction(stop_time=0.2)
    ctrl = built(kind, sample_time=0.01, fault_reaction=slow)
    ctrl(0.0, *measurement(kind, 0))
    ctrl.sample_time = 0.015
    if kind == "path_task":
        follower = ctrl.path_references.follower
        assert follower.settings[PATH_SETTINGS.index("sample_time")] == 0.015
    made = {"copy": copy.copy(ctrl), "deepcopy": copy.deepcopy(ctrl), "pickle": pickle.loads(pickle.dumps(ctrl))}
    for j in range(1, 6):
        t, m = 0.015 * j, measurement(kind, j)
        tau = ctrl(t, *m)
        for how, c in made.items():
            assert c.sample_time == 0.015, how
            np.testing.assert_array_equal(c(t, *m), tau, err_msg=f"{how}, sample {j}")
            np.testing.assert_array_equal(c.state, ctrl.state, err_msg=how)
    if kind == "path_task":  # the follower ran at the new period: its progress is the speed times it, per sample
        assert ctrl.path_task["travelled"] > 0.0


def held(ctrl) -> tuple:
    """What a refused sample keeps (the fault reaction counts it: tests/test_fault_reaction.py)."""
    return ctrl.state, ctrl.last["tau"], ctrl.last["integrals"]


@pytest.mark.parametrize("kind, longer, why", [
    ("path_task", 0.03, "PathTask's gains"),  # cross_track_gain 20 1/s x 0.03 s = 0.6 > 0.5
    ("estimated_sensor", 0.025, "EstimatedSurface's force_time_constant")])  # 0.025 s > 0.02 s
def test_a_sample_time_the_path_task_or_the_estimate_cannot_take_refuses_the_sample(kind, longer, why):
    """Refused as at construction (the controller built with it is refused), by a ParameterError naming the
    sample time: nothing changed; set back, the next sample is served."""
    slow = hybrid.FaultReaction(stop_time=0.2)
    with pytest.raises(hybrid.HybridError):
        built(kind, sample_time=longer, fault_reaction=slow)
    ctrl = built(kind, sample_time=0.01, fault_reaction=slow)
    ctrl(0.0, *measurement(kind, 0))
    before = held(ctrl)
    ctrl.sample_time = longer
    for _ in range(2):
        with pytest.raises(hybrid.ParameterError, match=f"sample_time = {longer}; give a period the {why}") as err:
            ctrl(longer, *measurement(kind, 1))
        assert err.value.name == "sample_time" and len(str(err.value).partition("\n")[0]) <= 240
        for a, b in zip(held(ctrl), before):
            np.testing.assert_array_equal(a, b)
    ctrl.sample_time = 0.01
    ctrl(0.01, *measurement(kind, 1))


@pytest.mark.parametrize("value", ["0.01", None, True, 10**400, np.inf, -0.01, 0.0, [0.01]],
                         ids=["text", "None", "bool", "huge", "inf", "negative", "zero", "list"])
def test_a_sample_time_that_is_no_period_refuses_the_sample(value):
    """Not a positive number (text, None, a bool, beyond any double, a list ...): a ParameterError, not Python's
    TypeError, and nothing changed; the step keeps the last period, and runs on it once one is set again."""
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, sample_time=0.01, **SETTINGS)
    measured = samples(7, 3)
    ctrl(0.0, *measured[0])
    before = held(ctrl)
    ctrl.sample_time = value
    with pytest.raises(hybrid.ParameterError, match="sample_time") as err:
        ctrl(0.01, *measured[1])
    assert err.value.status == "PARAMETER_INVALID"
    np.testing.assert_array_equal(err.value.torque, before[1])
    for a, b in zip(held(ctrl), before):
        np.testing.assert_array_equal(a, b)
    assert ctrl.step_inputs()["options"][OPTIONS.index("sample_time")] == 0.01
    ctrl.sample_time = 0.01
    ctrl(0.01, *measured[1])
