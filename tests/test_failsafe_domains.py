"""Where a user's input leaves the domain the library can serve, a HybridError that says so, never a NaN
or a foreign exception: a surface without a normal at a point (its gradient vanishes, or its formula is
undefined there)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import UR5, example_robot

import hybrid

Q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2])

#: surfaces through the point (a, b, c) that have no normal there
NO_NORMAL = {
    "gradient vanishes": "(z - c)**2",
    "cone apex": "sqrt((x - a)**2 + (y - b)**2) + z - c",
    "formula undefined": "z - c + 0.01*sqrt(c - 0.001 - z)",
}


@pytest.fixture(scope="module")
def ur5():
    return hybrid.Robot.from_urdf(example_robot(UR5[0]), tip=UR5[1])


def _through(text: str, point) -> hybrid.ImplicitSurface:
    return hybrid.ImplicitSurface(text, dict(zip("abc", (float(v) for v in point))))


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_a_point_without_a_normal_has_no_task_frame(kind):
    p = np.array([0.45, 0.1, 0.3])
    surface = _through(NO_NORMAL[kind], p)
    # independently (SymPy's gradient in NumPy): there is no normal at p
    _, grad = surface.phi_function()(p)
    assert not (np.isfinite(grad).all() and np.linalg.norm(grad) > 1e-12)
    e = (1.0, 0.0, 0.0)
    with pytest.raises(hybrid.TaskFrameError, match="no normal there"):
        hybrid.task_frame(surface, p, (0.1, 0.0, 0.0), frame_direction=e)
    # 2 mm aside and below, on the side where the formula is defined, the frame is the one of the normal there
    near = p + [0.002, 0.0, -0.002]
    R, _ = hybrid.task_frame(surface, near, (0.1, 0.0, 0.0), frame_direction=e)
    np.testing.assert_allclose(R[2], surface.normal_at(near), atol=1e-12)
    with pytest.raises(hybrid.TaskFrameError, match="state 1 of 2"):
        hybrid.task_frame(surface, np.array([near, p]), np.zeros((2, 3)), frame_direction=e)
    with pytest.raises(hybrid.HybridError, match="grad phi vanishes|is undefined at"):
        surface.normal_at(p)


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_an_experiment_does_not_start_where_the_surface_has_no_normal(kind):
    p = (0.45, 0.1, 0.3)
    exp = hybrid.tracing_experiment(surface=_through(NO_NORMAL[kind], p), start_point=p)
    with pytest.raises(hybrid.HybridError, match="grad phi vanishes|is undefined at") as info:
        exp.initial_state()
    assert "nan" not in str(info.value).splitlines()[0].split("grad phi")[0]


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_the_compiled_step_names_a_missing_normal_at_the_tip(ur5, kind):
    """The controller's compiled step at a pose whose tip is where the surface has no normal: its
    FRAME_UNDEFINED status (a TaskFrameError), nothing changed."""
    tip = hybrid.arm_terms(ur5, Q, np.zeros(6))["r"]
    ctrl = hybrid.Controller(ur5, _through(NO_NORMAL[kind], tip), frame_direction=(1.0, 0.0, 0.0))
    with pytest.raises(hybrid.TaskFrameError, match="no normal there"):
        ctrl(0.0, Q, np.zeros(6), np.zeros(6))
    assert ctrl.last is None
    ctrl(0.0, Q + 0.01, np.zeros(6), np.zeros(6))  # a pose 10 mrad away is served



# ---------------------------------------------------------------- a run leaving the domain of phi

#: tilted planes a run along t1 (base +x) leaves at x = 0.5: phi itself undefined there (its gradient
#: finite beyond: the controller's frame does not see it), and phi with its gradient undefined
LEAVING = {"log": "z - 0.2 - 0.1*y + 1e-9*log(0.5 - x)", "root": "z - 0.2 - 0.1*y + 1e-3*sqrt(0.5 - x)**3"}


def _leaving(kind: str, duration: float = 0.5):
    surface = hybrid.ImplicitSurface(LEAVING[kind], {})
    z0 = -surface.phi_function()(np.array([0.45, 0.0, 0.0]))[0]  # phi = z + g(x, y): on it at z = -g
    return hybrid.tracing_experiment(surface=surface, start_point=(0.45, 0.0, z0), duration=duration)


def _plant(name: str) -> str:
    if name == "mujoco":
        pytest.importorskip("mujoco")
    return name


@pytest.mark.parametrize("plant, compiled", [("generated", True), ("generated", False), ("mujoco", False)],
                         ids=["compiled loop", "python runner", "mujoco"])
def test_a_run_leaving_the_domain_of_phi_stops_where_the_sensor_tip_leaves_it(plant, compiled):
    exp = _leaving("log")
    with pytest.raises(hybrid.SimulationError, match="is undefined .* at the sensor tip s") as info:
        hybrid.simulate(exp, plant=_plant(plant), compiled=compiled)
    err, h, n = info.value, exp.integration_step, exp.robot.n
    # the last state kept has the sensor tip short of x = 0.5, reaching it within its integration step
    s, sd = err.partial.state[-1][2 * n:2 * n + 3], err.partial.state[-1][2 * n + 3:]
    assert s[0] < 0.5 <= s[0] + 1.5 * h * sd[0]
    assert err.time == pytest.approx(err.partial.t[-1] + h)
    assert f"t = {err.time:.5f} s" in str(err).splitlines()[0]
    assert np.isfinite(err.partial.outputs).all()  # no row of NaN penetration before it


def test_the_compiled_loop_stops_a_run_leaving_phi_as_non_finite_its_metrics_nan():
    from hybrid.simulation import closed_loop
    from hybrid.spec.interfaces import STATUS_NAMES

    exp = _leaving("log")
    done = closed_loop.run([closed_loop.prepare(exp, lanes=1)], record=True)[0]
    assert STATUS_NAMES[done.status] == "NONFINITE"
    assert all(np.isnan(v) for v in done.metrics.values())
    # every row whose state is finite has a finite penetration (the plant stops where phi is undefined)
    record = exp.plant().record["outputs"]
    finite = np.isfinite(done.states).all(axis=1)
    assert 0 < finite.sum() < len(finite)
    assert np.isfinite(done.outputs[finite][:, record.index("penetration")]).all()


@pytest.mark.parametrize("plant", ["generated", "mujoco"])
def test_a_run_whose_arm_tip_leaves_the_domain_of_phi_stops_at_that_sample(plant):
    exp = _leaving("root")
    with pytest.raises(hybrid.SimulationError, match="is undefined .* at the arm tip r") as info:
        hybrid.simulate(exp, plant=_plant(plant))
    err = info.value
    assert err.time == pytest.approx(err.partial.t[-1])  # a control sample: the controller's frame refused it
    assert "the task frame is undefined" in str(err)
    r = err.partial.outputs[-1][[exp.plant().record["outputs"].index(c) for c in ("r_x", "r_y", "r_z")]]
    assert r[0] >= 0.5 and np.isnan(exp.surface.phi_function()(r)[1]).any()


# ---------------------------------------------------------------- values nested thousands deep


def _nested(depth: int, leaf=1.0, key="n") -> dict:
    """``{key: {key: ... leaf}}``, ``depth`` mappings deep (built without recursion)."""
    value = leaf
    for _ in range(depth):
        value = {key: value}
    return value


DEEP = _nested(5000)
DEEP_LIST = [1.0]
for _ in range(5000):
    DEEP_LIST = [DEEP_LIST]


SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)


def _refused_in_a_short_line(make, accepted: bool = False) -> None:
    """``make()`` raises a HybridError whose first line is short (or, ``accepted``, raises nothing)."""
    try:
        make()
    except hybrid.HybridError as exc:
        first = str(exc).splitlines()[0]
        assert len(first) < 300, first
    else:
        assert accepted, "no error"


@pytest.mark.parametrize("make", [
    lambda: hybrid.Controller(hybrid.ur5(), SPHERE, gains=DEEP),
    lambda: hybrid.Controller(hybrid.ur5(), SPHERE, gains={"n": DEEP}),
    lambda: hybrid.tracing_experiment(gains=DEEP),
    lambda: hybrid.paper_experiment(gains=DEEP),
    lambda: hybrid.paper_experiment(KPv=DEEP),
    lambda: hybrid.task_frame(SPHERE, (0.5, 0.0, 0.4), (0.0, 0.0, 0.0), frame_direction=DEEP),
], ids=["gains", "gains per axis", "tracing gains", "paper gains", "one gain", "frame_direction"])
def test_gains_nested_thousands_deep_are_refused_in_a_short_line(make):
    _refused_in_a_short_line(make)


def _keywords(make) -> list[str]:
    import inspect

    return [n for n, p in inspect.signature(make).parameters.items()
            if p.kind is p.KEYWORD_ONLY or (p.default is not p.empty and n != "self")]


@pytest.mark.parametrize("deep", [DEEP, DEEP_LIST], ids=["mapping", "list"])
def test_every_setting_nested_thousands_deep_is_refused_in_a_short_line(deep):
    """Every setting of an experiment, a Controller and the settings' classes, given a mapping or a
    list nested 5000 deep: a HybridError, its first line short, never a RecursionError (a Controller
    reads a mapping's keys as the axes ``selection`` names, and calls ``path`` only at a sample)."""
    import dataclasses

    for name in [f.name for f in dataclasses.fields(hybrid.Experiment)]:
        _refused_in_a_short_line(lambda name=name: hybrid.tracing_experiment(**{name: deep}))
    for name in _keywords(hybrid.Controller.__init__):
        _refused_in_a_short_line(lambda name=name: hybrid.Controller(hybrid.ur5(), SPHERE, **{name: deep}),
                                 accepted=name in ("selection", "path"))
    _refused_in_a_short_line(lambda: hybrid.Controller(hybrid.ur5(), deep))
    for cls in (hybrid.Sensor, hybrid.Contact, hybrid.Gains, hybrid.Posture, hybrid.ContactLoss,
                hybrid.WrenchSensor, hybrid.EstimatedSurface, hybrid.Step):
        for f in dataclasses.fields(cls):
            # the class's own fields given, the one under test nested: a missing one is not the point
            values = {g.name: deep if g.name == f.name else _a_valid(cls, g) for g in dataclasses.fields(cls)}
            _refused_in_a_short_line(lambda cls=cls, values=values: cls(**values))


def _a_valid(cls, field):
    """A valid value of ``cls``'s ``field``: its default, or the example the class takes."""
    import dataclasses

    if field.default is not dataclasses.MISSING:
        return field.default
    if field.default_factory is not dataclasses.MISSING:
        return field.default_factory()
    return {("Posture", "q_rest"): (0.0,) * 6, ("Step", "before"): 1.0, ("Step", "after"): 2.0,
            ("Step", "at"): 0.5, ("ContactLoss", "threshold"): 1.0}[(cls.__name__, field.name)]


def test_messages_show_values_through_the_bounded_repr():
    """``{value!r:.60}`` builds the whole repr before cutting it (recursing as deep as the value is nested,
    as long as it is long): every message shows a value through ``hybrid.validate.shown``."""
    import ast
    from pathlib import Path

    root = Path(hybrid.__file__).parent
    found = []
    for path in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FormattedValue) and node.conversion == ord("r") and node.format_spec:
                found.append(f"{path.relative_to(root.parent)}:{node.lineno}")
    assert not found, found
