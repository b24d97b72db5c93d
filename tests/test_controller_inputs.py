"""What the controller and the metrics take: the documented types and shapes, or a HybridError whose
first line names the value and the fix; a user's callback that fails is named, with the time."""

from __future__ import annotations

import dataclasses
import signal

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hybrid

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
Q_UR5 = np.array([0.0, -1.2, 1.6, -1.9, -1.57, 0.0])


@pytest.fixture(scope="module")
def _ur5():
    return hybrid.Controller(hybrid.ur5(), SPHERE, timing_tolerance=None)  # samples at any time


@pytest.fixture(scope="module")
def _paper():
    return hybrid.Controller(hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2), timing_tolerance=None)


# each test starts a new run: the refusals of the tests before would count as consecutive faults
@pytest.fixture
def ur5_ctrl(_ur5):
    _ur5.reset()
    return _ur5


@pytest.fixture
def paper_ctrl(_paper):
    _paper.reset()
    return _paper


def first_line(exc: BaseException) -> str:
    return str(exc).splitlines()[0]


# ------------------------------------------------------------------ silent conversions refused


@pytest.mark.parametrize("t", ["0.5", b"0.5", True, np.bool_(False), None, [0.1], 1j])
def test_a_sample_time_must_be_a_number(ur5_ctrl, t):
    with pytest.raises(hybrid.HybridError, match="give the sample time in seconds"):
        ur5_ctrl(t, Q_UR5, np.zeros(6), np.zeros(6))


def test_numbers_of_every_kind_are_sample_times(ur5_ctrl):
    taus = [ur5_ctrl(t, Q_UR5, np.zeros(6), np.zeros(6)) for t in (0, 0.01, np.float32(0.02), np.int64(0))]
    assert all(np.isfinite(tau).all() for tau in taus)


@pytest.mark.parametrize("Fc", [np.zeros(2), [1.0, 2.0], np.zeros(4), np.zeros((2, 3)), np.zeros(7), "force"])
def test_a_spatial_arm_takes_a_force_of_3_or_a_wrench_of_6(ur5_ctrl, Fc):
    with pytest.raises(hybrid.HybridError, match="3 numbers, base axes.*or the wrench"):
        ur5_ctrl(0.0, Q_UR5, np.zeros(6), Fc)


@pytest.mark.parametrize("Fc", [np.zeros(3), [1.0, 2.0, 3.0], np.zeros(5)])
def test_the_planar_arm_takes_a_force_in_its_plane_or_a_wrench(paper_ctrl, Fc):
    with pytest.raises(hybrid.HybridError, match="2 numbers, base axes"):
        paper_ctrl(0.0, np.array([2.2, 1.9]), np.zeros(2), Fc)


def test_the_force_without_moments_is_the_wrench_with_zero_moments(ur5_ctrl, paper_ctrl):
    for ctrl, q, f in ((ur5_ctrl, Q_UR5, [1.0, -2.0, 9.0]), (paper_ctrl, np.array([2.2, 1.9]), [-8.0, 3.0])):
        ctrl.reset()
        short = ctrl(0.0, q, np.zeros(len(q)), np.array(f))
        ctrl.reset()
        full = ctrl(0.0, q, np.zeros(len(q)), np.array([*f, *np.zeros(6 - len(f))]))
        np.testing.assert_array_equal(short, full)


@pytest.mark.parametrize("point", [(0.5, 0.1), (0.5, 0.1, 0.3, 0.0), "here", (0.5, np.nan, 0.3)])
def test_a_path_gives_points_of_the_arms_space(point):
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, frame="desired", path=lambda t: (point, (0.1, 0.0, 0.0)))
    with pytest.raises(hybrid.HybridError, match="must be 3 finite numbers"):
        ctrl(0.0, Q_UR5, np.zeros(6), np.zeros(6))


# ------------------------------------------------------------------ a user's callback that fails


def _recurse(t):
    return _recurse(t)


@pytest.mark.parametrize("bad, kind", [(lambda t: 1 / 0, "ZeroDivisionError"), (_recurse, "RecursionError"),
                                       (lambda t: {}["missing"], "KeyError"), (lambda t: None, "gave None"),
                                       (lambda t: "fast", "gave 'fast'")])
def test_a_failing_reference_is_named_with_its_time(bad, kind):
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, velocity_reference=bad)
    with pytest.raises(hybrid.HybridError, match="the t1 reference (failed|gave).* at t = 0.03 s") as info:
        ctrl(0.03, Q_UR5, np.zeros(6), np.zeros(6))
    assert kind in str(info.value)
    if "gave" not in kind:
        assert type(info.value.__cause__).__name__ == kind  # the original, kept


def test_a_failing_rate_and_path_are_named():
    class Ramp:
        def __call__(self, t):
            return 0.1 * t

        def rate(self, t):
            raise ValueError("no rate here")

    with pytest.raises(hybrid.HybridError, match="the t1 rate failed at t = 0.0 s: ValueError"):
        hybrid.Controller(hybrid.ur5(), SPHERE, velocity_reference=Ramp())(0.0, Q_UR5, np.zeros(6), np.zeros(6))
    broken = hybrid.Controller(hybrid.ur5(), SPHERE, frame="desired", path=lambda t: [][1])
    with pytest.raises(hybrid.HybridError, match="the path failed at t = 0.0 s: IndexError"):
        broken(0.0, Q_UR5, np.zeros(6), np.zeros(6))


# -------------------------------------------------------------------------------- NaN in metrics


@pytest.mark.parametrize("series", ["force_normal", "velocity_tangential", "force_reference", "speed_reference",
                                    "penetration", "contact_force", "tau"])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_metrics_refuse_non_finite_series(series, value):
    t = np.linspace(0.0, 1.0, 101)
    given = {"force_normal": np.full(101, 10.0), "velocity_tangential": np.full(101, 0.3),
             "force_reference": np.full(101, 10.0), "speed_reference": np.full(101, 0.3),
             "penetration": np.full(101, 1e-4), "contact_force": np.full(101, 10.0), "tau": np.ones((101, 2))}
    given[series][57] = value
    with pytest.raises(hybrid.HybridError, match=f"{series} holds NaN or infinite values \\(first at sample 57\\)"):
        hybrid.metrics(t, **given)


def test_metrics_refuse_non_finite_times():
    with pytest.raises(hybrid.HybridError, match="increasing, finite sample times"):
        hybrid.metrics([0.0, np.nan, 1.0], [1.0] * 3, [1.0] * 3, [1.0] * 3, [1.0] * 3)


# ------------------------------------------------------------------------------ short first lines


def test_errors_that_carry_a_state_keep_it_off_the_first_line():
    robot = hybrid.ur5()
    law = hybrid.decoupling_law(robot, SPHERE)
    cases = []
    for call in (lambda: law(np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6)),  # stretched out: singular
                 lambda: hybrid.decoupling_law(robot, hybrid.Plane((0, 0, 0.1), (0, 0, 1)))(
                     Q_UR5, np.zeros(6), np.zeros(6), np.zeros(6)),  # e = z parallel to the normal
                 lambda: hybrid.simulate(hybrid.paper_experiment(model_error=2.0, allow_unstable=True)),
                 lambda: hybrid.paper_experiment(model_error=2.0),  # refused: predicted unstable
                 lambda: hybrid.simulate(hybrid.paper_experiment(duration=2.0, singular_tol=0.9)),
                 lambda: hybrid.Controller(robot, SPHERE, velocity_reference=lambda t: np.nan)(
                     0.0, Q_UR5, np.zeros(6), np.zeros(6))):
        with pytest.raises(hybrid.HybridError) as info:
            call()
        cases.append(info.value)
    for exc in cases:
        assert len(first_line(exc)) <= 240, first_line(exc)  # a sentence, not a state
        assert "[" not in first_line(exc).split(":", 1)[-1] or "t = " in first_line(exc), first_line(exc)


# ------------------------------------------------------------- every Controller call: works or says why


class _Timeout(Exception):
    pass


# ------------------------------------------------------------------ what the constructors take


@pytest.mark.parametrize("frame", [np.array(["actual", "desired"]), np.array([1.0, 2.0]), np.array([]), ["actual"],
                                   None, 1, b"actual", "Actual"])
def test_a_frame_is_one_of_its_names(frame):
    """Anything but "actual" or "desired" is refused by name, in the record as by the keyword (an array once
    met the check's ``in`` and raised NumPy's ambiguous truth value)."""
    for make in (lambda: hybrid.Controller(hybrid.ur5(), SPHERE, frame=frame), lambda: hybrid.Tracking(frame=frame)):
        with pytest.raises(hybrid.HybridError, match=r"^frame = .*; give 'actual' or 'desired'$"):
            make()


class _Desired:
    """A desired point as an object that is called: a path need not be a function."""

    def __call__(self, t: float):
        return np.array([0.6, 0.0, 0.3]), np.zeros(3)


@pytest.mark.parametrize("path", [3, "circle", (0.5, 0.0, 0.35), np.array([0.5, 0.0, 0.35]), np.array([]), True])
def test_a_path_that_cannot_be_called_is_refused_when_given(path):
    for make in (lambda: hybrid.Controller(hybrid.ur5(), SPHERE, path=path), lambda: hybrid.Tracking(path=path)):
        with pytest.raises(hybrid.HybridError, match=r"^path = .*; give a function path\(t\)"):
            make()
    # what is called is taken, and read at the samples: a desired frame on it is served
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, frame="desired", path=_Desired(), timing_tolerance=None)
    assert np.isfinite(ctrl(0.0, Q_UR5, np.zeros(6), np.zeros(3))).all()


def test_arguments_by_position_beyond_the_signature_are_refused():
    with pytest.raises(hybrid.HybridError, match=r"^Controller takes 3 arguments by position \(robot, surface, "
                       r"scheme\), 4 were given \(the first extra: \(0, 2\)\); give the others by keyword"):
        hybrid.Controller(hybrid.ur5(), SPHERE, "task", (0, 2))
    fields = [f.name for f in dataclasses.fields(hybrid.Limits)]
    with pytest.raises(hybrid.HybridError, match=f"^Limits takes {len(fields)} arguments by position"):
        hybrid.Limits(*[None] * (len(fields) + 1))
    with pytest.raises(hybrid.HybridError, match="^Controller: surface not given; give robot, surface"):
        hybrid.Controller(hybrid.ur5())
    with pytest.raises(hybrid.HybridError, match="^Controller: scheme is given twice"):
        hybrid.Controller(hybrid.ur5(), SPHERE, "task", scheme="khatib")
    # a call that fits is the constructor's own: by position as far as the signature goes, the rest by keyword
    assert hybrid.Limits(0.002, None).sample_time == 0.002
    assert hybrid.Controller(hybrid.ur5(), SPHERE, "khatib", axes="position").scheme.name == "khatib"


@pytest.mark.parametrize("name", ["torque_limit", "torque_step_limit"])
@pytest.mark.parametrize("value", [10**400, -10**400, [10**400] * 6], ids=["huge", "-huge", "huge_per_joint"])
def test_a_limit_beyond_any_double_is_refused_by_name(name, value):
    with pytest.raises(hybrid.HybridError, match=f"^{name} = .*; give"):
        hybrid.Controller(hybrid.ur5(), SPHERE, **{name: value})


def test_a_singular_tolerance_changed_between_samples_is_the_one_a_sample_reads():
    """The step's binding holds the tolerance: a sample after a change reads the new one, as a controller
    built with it does (it once read the tolerance bound at the first sample)."""
    sample = (Q_UR5, np.zeros(6), np.array([0.0, 0.0, -10.0]))
    fresh = {tol: hybrid.Controller(hybrid.ur5(), SPHERE, singular_tol=tol, timing_tolerance=None)
             for tol in (1e-3, 0.99)}
    with pytest.raises(hybrid.SingularConfigurationError):
        fresh[0.99](0.0, *sample)
    fresh[1e-3](0.0, *sample)
    ctrl = hybrid.Controller(hybrid.ur5(), SPHERE, timing_tolerance=None)
    ctrl(0.0, *sample)
    ctrl.singular_tol = 0.99
    with pytest.raises(hybrid.SingularConfigurationError):
        ctrl(0.01, *sample)
    ctrl.singular_tol = 1e-3
    np.testing.assert_array_equal(ctrl(0.01, *sample), fresh[1e-3](0.01, *sample))


def _alarm(signum, frame):
    raise _Timeout


ARGUMENTS = st.fixed_dictionaries({}, optional={
    "scheme": st.sampled_from(["task", "khatib", "raibert_craig", "fisher_mujtaba", "pid", 3, None]),
    "axes": st.sampled_from([None, "all", "position", "planar", (0, 2), (0, 0), (7,), "xyz", 5, [0, 1, 2]]),
    "selection": st.sampled_from([None, ("n",), "n", ("t1", "n"), (9,), "q", 2, ()]),
    "gains": st.sampled_from([None, hybrid.Gains(), {"n": hybrid.Gains(KPf=1.0)}, {"zz": hybrid.Gains()}, 3.0]),
    "force_reference": st.sampled_from([None, 10.0, hybrid.Step(5, 10, 0.1), {"n": 3.0}, {"t1": 1.0}, "ten",
                                        np.nan, lambda t: 10.0 + t]),
    "velocity_reference": st.sampled_from([None, 0.1, {"t2": 0.05}, [0.1], lambda t: 0.1]),
    "sample_time": st.sampled_from([0.01, 0.0, -1.0, np.inf, "0.01", 1e-300]),
    "integral": st.sampled_from([True, False, 1, None]),
    "curvature": st.sampled_from([True, False, "yes"]),
    "frame": st.sampled_from(["actual", "desired", "world", np.array([1.0, 2.0])]),
    "path": st.sampled_from([None, lambda t: ((0.5, 0.0, 0.35), (0.1, 0.0, 0.0)), lambda t: (0.1,), 3,
                             np.array([0.5, 0.0, 0.35])]),
    "torque_limit": st.sampled_from(["urdf", None, 50.0, 10**400, "none"]),
    "frame_direction": st.sampled_from([(0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0, 0, 0), (np.nan, 0, 1), "z"]),
    "position_error": st.sampled_from([False, True, 0]),
    "integral_limit": st.sampled_from([None, 5.0, -1.0, np.nan, "big"]),
    "contact_loss": st.sampled_from([None, hybrid.ContactLoss(), 0.5]),
    "singular_tol": st.sampled_from([1e-3, 0.0, 0.99, 1.0, -1e-3, np.nan]),
    "posture": st.sampled_from([None, hybrid.Posture(Q_UR5), hybrid.Posture((0.0, 1.0)), "rest"]),
})


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                   HealthCheck.function_scoped_fixture])
@given(ARGUMENTS, st.sampled_from(["ur5", "paper"]),
       st.sampled_from([np.zeros(6), np.array([0.0, 0.0, 10.0]), np.array([np.nan] * 6), np.zeros(2)]))
def test_every_controller_call_works_or_raises_a_hybrid_error(kwargs, which, Fc):
    robot, surface, q = ((hybrid.ur5(), SPHERE, Q_UR5) if which == "ur5" else
                         (hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2), np.array([2.2, 1.9])))
    kwargs = dict(kwargs)
    scheme = kwargs.pop("scheme", "task")
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(60)  # no call may hang (a cold build of a new variant takes seconds)
    try:
        ctrl = hybrid.Controller(robot, surface, scheme, **kwargs)
        for k in range(3):
            tau = ctrl(k * ctrl.sample_time, q, np.zeros(len(q)), Fc)
            assert tau.shape == (len(q),) and np.isfinite(tau).all()
    except hybrid.HybridError as exc:
        assert first_line(exc).strip(), "an error says something on its first line"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


@pytest.mark.parametrize("port", ["q", "qdot", "Fc"])
def test_a_number_beyond_any_double_at_a_sample_is_refused_as_a_nan_is(paper_ctrl, port):
    """An integer beyond any double in a sample's input is no finite number: refused as a NaN there is (a
    NonFiniteError carrying the torque last written, counted as a faulted sample), never a foreign error."""
    ctrl, T = paper_ctrl, paper_ctrl.sample_time
    given = {"q": np.array([2.2, 1.9]), "qdot": np.zeros(2), "Fc": np.zeros(2)}
    tau = ctrl(0.0, *given.values())
    faults = []
    for k, bad in enumerate(([10**400, 0], [np.nan, 0.0]), start=1):
        with pytest.raises(hybrid.NonFiniteError) as err:
            ctrl(k * T, *{**given, port: bad}.values())
        assert first_line(err.value).strip()
        np.testing.assert_array_equal(err.value.torque, tau)
        faults.append(ctrl.fault_state[-3])
    assert faults == [1.0, 2.0]
