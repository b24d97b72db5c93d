"""Path tasks (hybrid.PathTask): the generated follower against NumPy written from its equations, runs of
the UR5 along paths on a plane, a sphere and a cylinder (and along a path of one's own) judged by the
distance from the path and the force, the controller's state rules, and the refusals."""

from __future__ import annotations

import json
import math
import shutil
import subprocess

import numpy as np
import pytest

import hybrid
from hybrid.control.path_task import PathFollower
from hybrid.geometry.paths import Path
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_PHASES, PATH_SETTINGS, PATH_TABLE

PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
CYLINDER = hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.6, 0.8), 0.1)
OUT = {name: i for i, name in enumerate(PATH_OUTPUT)}


def on_cylinder(points) -> np.ndarray:
    return np.array([CYLINDER.project(np.asarray(p, dtype=float)) for p in points])


def raster(passes: int = 3, length: float = 0.08):
    origin = PLANE.project(np.array([0.45, -0.05, 0.1]))
    return hybrid.RasterPath(PLANE, origin, (1.0, 0.0, 0.0), length, 0.01, passes)


def hermite(table: np.ndarray, s: float) -> tuple[np.ndarray, np.ndarray]:
    """The table's curve at ``s`` written from the spec: cubic Hermite through the nodes' points with their
    tangents (times the interval), and its unit tangent."""
    col = {name: i for i, name in enumerate(PATH_TABLE)}
    P, T = table[:, col["p_x"]:col["p_z"] + 1], table[:, col["t_x"]:col["t_z"] + 1]
    knots = table[:, col["s"]]
    i = min(max(int(np.searchsorted(knots, s, side="right")) - 1, 0), len(knots) - 2)
    h = knots[i + 1] - knots[i]
    u = (s - knots[i]) / h
    basis = np.array([2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2])
    slope = np.array([6 * u**2 - 6 * u, 3 * u**2 - 4 * u + 1, -6 * u**2 + 6 * u, 3 * u**2 - 2 * u])
    c = basis[0] * P[i] + basis[1] * h * T[i] + basis[2] * P[i + 1] + basis[3] * h * T[i + 1]
    d = (slope[0] * P[i] + slope[2] * P[i + 1]) / h + slope[1] * T[i] + slope[3] * T[i + 1]
    return c, d / np.linalg.norm(d)


SPIRAL_CENTER = SPHERE.project(np.array([0.55, 0.05, 0.34]))


@pytest.mark.parametrize("path", [raster(), hybrid.SpiralPath(SPHERE, SPIRAL_CENTER, 0.01, 2.0, start_radius=0.01),
                                  hybrid.WaypointPath(CYLINDER, on_cylinder(
                                      [[0.62, -0.05, 0.1], [0.6, 0.0, 0.13], [0.61, 0.05, 0.12]]))],
                         ids=["raster", "spiral", "waypoints"])
def test_the_follower_is_its_equations(path):
    surface = path.surface
    task = hybrid.PathTask(path, speed=0.1, force=10.0, acceleration=0.5)
    follower = PathFollower(task, surface)
    table, settings = follower.table, follower.settings
    rng = np.random.default_rng(3)
    # the nodes are the path's own points: the interpolant between them is within the cubic's error bound
    kappa = max(np.linalg.norm(path.curvature_at(s)) for s in np.linspace(0.0, path.length, 400))
    bound = max(task.spacing ** 4 * kappa ** 3 / 100, 1e-10)
    for s in rng.uniform(0.0, path.length, 40):
        c, t = hermite(table, s)
        assert np.linalg.norm(c - path.point_at(s)) < bound
        assert np.linalg.norm(t - path.tangent_at(s)) < max(task.spacing ** 3 * kappa ** 3 / 24, 1e-8)
    # one sample from a tip off the path: the progress is the nearest point, e = n x t, the references
    for s in rng.uniform(0.05 * path.length, 0.95 * path.length, 20):
        n, t = path.normal_at(s), path.tangent_at(s)
        side = np.cross(n, t)
        tip = path.point_at(s) + 0.0007 * side + 0.0004 * n
        follower.state[:] = [s + 0.002, 0.0, 0.0, 1.0, 1.0, 0.0]  # following, 2 mm ahead: Newton brings it back
        follower.state[1] = s + 0.002 - settings[PATH_SETTINGS.index("start")]
        out = follower.follow(tip, 10.0 * n)
        assert out[OUT["s"]] == pytest.approx(path.arc_of(tip), abs=100 * bound)
        c, tc = hermite(table, out[OUT["s"]])
        assert np.allclose(out[OUT["c_x"]:OUT["c_z"] + 1], c, atol=1e-12)
        assert np.allclose(out[OUT["t_x"]:OUT["t_z"] + 1], tc, atol=1e-12)  # the follower's cubic is this one
        e = out[OUT["e_x"]:OUT["e_z"] + 1]
        assert np.allclose(e, np.cross(out[OUT["n_x"]:OUT["n_z"] + 1], tc), atol=1e-12)
        d = (tip - c) @ e
        assert out[OUT["cross_track"]] == pytest.approx(d, abs=1e-12)
        assert out[OUT["lateral_speed"]] == pytest.approx(-task.cross_track_gain * d, abs=1e-12)
        assert out[OUT["cross_track"]] == pytest.approx(0.0007, abs=2e-5)
        kappa_g = path.curvature_at(out[OUT["s"]]) @ e
        v = out[OUT["speed"]]
        assert out[OUT["lateral_rate"]] == pytest.approx(kappa_g * v * v, rel=2e-2, abs=1e-6)
        assert v ** 2 * abs(kappa_g) <= task.acceleration * 1.02  # the turns' limit
        assert out[OUT["normal_reference"]] == pytest.approx(10.0, rel=1e-15)


def test_the_speed_is_a_trapezoid_in_arc_length():
    path = raster(passes=1, length=0.2)  # one straight pass
    task = hybrid.PathTask(path, speed=0.1, acceleration=0.4, speed_start=0.02)
    follower = PathFollower(task, PLANE)
    L = path.length
    for s in np.linspace(0.0, L, 57):
        follower.state[:] = [s, s, 0.0, 1.0, 1.0, 0.0]
        out = follower.follow(path.point_at(s), np.zeros(3))
        expected = min(0.1, math.sqrt(0.02 ** 2 + 2 * 0.4 * s), math.sqrt(2 * 0.4 * max(L - s, 0.0)))
        assert out[OUT["speed"]] == pytest.approx(0.0 if L - s <= 1e-4 else expected, abs=1e-12)
        assert out[OUT["done"]] == float(L - s <= 1e-4)


def run(path, duration, **task):
    task = hybrid.PathTask(path, speed=task.pop("speed", 0.1), force=task.pop("force", 10.0), **task)
    exp = hybrid.tracing_experiment(surface=path.surface, path_task=task, duration=duration)
    return hybrid.simulate(exp)


# the UR5 at 10 N and 0.1 m/s with today's model error and friction (the experiment's defaults)
CASES = {
    "raster on a plane": (lambda: raster(), 4.0),
    "spiral on a sphere": (lambda: hybrid.SpiralPath(SPHERE, SPIRAL_CENTER, 0.01, 2.0, start_radius=0.01), 4.0),
    "waypoints on a cylinder": (lambda: hybrid.WaypointPath(CYLINDER, on_cylinder(
        [[0.62, -0.06, 0.1], [0.6, -0.02, 0.14], [0.61, 0.03, 0.12], [0.6, 0.07, 0.15]])), 3.0),
}


@pytest.mark.parametrize("case", list(CASES))
def test_the_ur5_follows_paths_on_surfaces(case):
    make, duration = CASES[case]
    path = make()
    res = run(path, duration)
    m = res.metrics
    assert m["path_error_rms_m"] <= 1e-3
    assert m["path_force_rms_error_N"] <= 0.02 * 10.0
    assert m["contact_losses"] == 0
    assert m["path_travelled_m"] >= path.length - 1e-3  # the whole path, to its end
    assert np.isfinite(m["path_time_s"])
    if isinstance(path, hybrid.WaypointPath):  # every waypoint passed within 2 mm
        tip = res.outputs[:, [res.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]]
        for w in path.points_at([path.arc_at_knot(i) for i in range(len(path.points))]):
            assert np.min(np.linalg.norm(tip - w, axis=1)) <= 2e-3


class Arc(Path):
    """A path of one's own: a circular arc of radius 0.05 m on the plane, by arc length."""

    length, closed = 0.12, False

    def __init__(self):
        n = np.asarray(PLANE.normal)
        self.u = np.array([1.0, 0.0, 0.0])
        self.v = np.cross(n, self.u)
        self.c = np.asarray(PLANE.project(np.array([0.45, 0.0, 0.1])))

    def point_at(self, s):
        a = s / 0.05
        return self.c + 0.05 * (math.cos(a) * self.u + math.sin(a) * self.v)

    def points_at(self, s):
        return np.array([self.point_at(x) for x in np.atleast_1d(s)])

    def tangent_at(self, s):
        a = s / 0.05
        return -math.sin(a) * self.u + math.cos(a) * self.v

    def arc_of(self, p):
        d = np.asarray(p) - self.c
        return 0.05 * math.atan2(d @ self.v, d @ self.u)


def test_a_path_of_ones_own_is_followed():
    arc = Arc()
    task = hybrid.PathTask(arc, speed=0.08, force=10.0)
    exp = hybrid.tracing_experiment(surface=PLANE, path_task=task, duration=2.5)
    res = hybrid.simulate(exp)
    assert res.metrics["path_error_rms_m"] <= 1e-3
    tip = res.outputs[-1, [res.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]]
    assert np.linalg.norm(tip - arc.point_at(arc.length)) <= 2e-3  # it ended at the arc's end


def test_a_force_profile_along_the_path():
    path = raster(passes=1, length=0.2)
    force = lambda s: 8.0 + 4.0 * s / path.length  # noqa: E731 - 8 N rising to 12 N along the pass
    res = run(path, 3.0, force=force)
    assert res.metrics["path_force_rms_error_N"] <= 0.05 * 4.0  # within 5 % of the profile's range


def held_state(ctrl) -> list:
    """What a sample that is not served must leave as it was: the follower's state and last outputs, the step's
    parameters, the loops' integrals."""
    return [ctrl.path_references.follower.state.copy(), ctrl.path_references.follower.served.copy(),
            {k: v.copy() for k, v in ctrl.step_inputs().items()}, ctrl.state.copy()]


def assert_same(a, b):
    for x, y in zip(a, b):
        if isinstance(x, dict):
            assert all(np.array_equal(x[k], y[k]) for k in x)
        else:
            assert np.array_equal(x, y)


def test_a_refused_or_repeated_sample_changes_nothing():
    exp = whole_task(duration=4.6)
    ctrl = exp.build_controller()
    x0 = exp.initial_state()
    q, qd = x0[:6], x0[6:12]
    ctrl(0.0, q, qd, np.zeros(3))
    moved = q + 0.05  # the tip elsewhere: the follower would move on, and turn e
    before = held_state(ctrl)
    with pytest.raises(hybrid.SampleTimingError):
        ctrl(0.0, moved, qd, np.zeros(3))  # no time passed: nothing changes
    assert_same(before, held_state(ctrl))
    with pytest.raises(hybrid.HybridError):
        ctrl(0.01, moved, qd, np.array([np.nan, 0.0, 0.0]))  # refused
    assert_same(before, held_state(ctrl))
    # at the retreat's first sample, repeated: the normal axis stays force-controlled
    from test_standalone_controller import recorded_samples

    samples = recorded_samples(exp)
    ctrl.reset()
    n = ctrl.path_references.positions[2]
    switched = None
    for k, sample in enumerate(samples):
        before = held_state(ctrl)
        ctrl(*sample)
        if ctrl.step_inputs()["selection"][n] == 0.0:
            switched = k
            break
    assert switched is not None, "the run never retreated"
    k = switched
    replay = exp.build_controller()
    for t, q, qd, wrench in samples[:k]:
        replay(t, q, qd, wrench)
    assert_same(before, held_state(replay))
    _, q, qd, wrench = samples[k]
    with pytest.raises(hybrid.SampleTimingError):
        replay(samples[k - 1][0], q, qd, wrench)  # the retreat's sample, but at the last one's time
    assert_same(before, held_state(replay))
    ctrl.reset()
    assert not ctrl.path_references.follower.state.any()
    assert ctrl.step_inputs()["selection"][n] == 1.0


@pytest.mark.parametrize("bad, message", [
    (dict(speed=-0.1), "positive speed"),
    (dict(acceleration=0.0), "acceleration"),
    (dict(cross_track_gain=-1.0), "gain >= 0"),
    (dict(spacing=0.0), "node spacing"),
    (dict(speed_start=0.0), "start speed"),
    (dict(laps=2), "open path"),
    (dict(speed=1.0, acceleration=0.1), "not reached within the path"),
    (dict(speed=lambda s: 0.05 + 5.0 * s), "beyond the acceleration limit"),
])
def test_bad_tasks_are_refused(bad, message):
    with pytest.raises(hybrid.HybridError, match=message):
        hybrid.PathTask(raster(), **bad).table(PLANE)


def test_bad_paths_and_experiments_are_refused():
    with pytest.raises(hybrid.HybridError, match="leaves the surface"):
        hybrid.PathTask(raster()).table(SPHERE)
    with pytest.raises(hybrid.HybridError, match="give a hybrid path"):
        hybrid.PathTask([(0, 0, 0), (1, 0, 0)])

    class Stretched(Arc):
        def point_at(self, s):
            return super().point_at(2 * s)

    with pytest.raises(hybrid.HybridError, match="not parametrised by arc length"):
        hybrid.PathTask(Stretched()).table(PLANE)
    task = hybrid.PathTask(raster())
    with pytest.raises(hybrid.HybridError, match="leave force_reference"):
        hybrid.tracing_experiment(surface=PLANE, path_task=task, force_reference=20.0)
    with pytest.raises(hybrid.HybridError, match="leave path and start_point out"):
        hybrid.tracing_experiment(surface=PLANE, path_task=task, path=raster())
    with pytest.raises(hybrid.HybridError, match="t1 and t2 velocity-controlled"):
        hybrid.Controller(hybrid.ur5(), PLANE, axes=(0, 2), path_task=task)
    with pytest.raises(hybrid.HybridError, match="for an arm in space"):
        hybrid.Controller(hybrid.paper_arm(), hybrid.Circle((1.0, 1.0), 0.5), path_task=task)


@pytest.mark.parametrize("path", [raster(), hybrid.SpiralPath(SPHERE, SPIRAL_CENTER, 0.01, 2.0, start_radius=0.01),
                                  hybrid.WaypointPath(CYLINDER, on_cylinder([[0.62, -0.05, 0.1], [0.6, 0.0, 0.13],
                                                                             [0.61, 0.05, 0.12]]), closed=True)],
                         ids=["raster", "spiral", "waypoints"])
def test_a_path_task_is_saved_and_loaded(tmp_path, path):
    task = hybrid.PathTask(path, speed=0.08, force=12.0, retreat_distance=0.01, laps=1.0 if path.closed else None)
    exp = hybrid.tracing_experiment(surface=path.surface, path_task=task, duration=0.3)
    back = hybrid.Experiment.from_dict(json.loads(json.dumps(exp.to_dict())))
    assert back.path_task.path.arguments() == path.arguments()
    assert np.array_equal(back.path_task.table(path.surface)[0], task.table(path.surface)[0])  # the same path
    res = hybrid.simulate(exp)
    res.save(tmp_path / "run.npz")
    loaded = hybrid.SimulationResult.load(tmp_path / "run.npz")
    assert loaded.metrics["path_error_rms_m"] == res.metrics["path_error_rms_m"]
    with pytest.raises(hybrid.HybridError, match="not written to a file"):
        hybrid.tracing_experiment(surface=PLANE, duration=0.1,
                                  path_task=hybrid.PathTask(raster(), force=lambda s: 10.0)).to_dict()
    with pytest.raises(hybrid.HybridError, match="of one's own is not written"):
        hybrid.tracing_experiment(surface=PLANE, duration=0.1, path_task=hybrid.PathTask(Arc())).to_dict()


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
def test_the_follower_header_compiles_on_its_own_warning_free(tmp_path):
    from hybrid.native import loader

    header = (loader.source_dir() / loader.PATH_HEADER).read_text()
    (tmp_path / loader.PATH_HEADER).write_text(header)
    for defines in ([], ["-DHYBRID_PATH_ENTRY_POINTS"]):
        (tmp_path / "use.c").write_text(f'#include "{loader.PATH_HEADER}"\n')
        done = subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow",
                               "-Werror", *defines, "-c", "use.c", "-o", "use.o"], cwd=tmp_path, capture_output=True,
                              text=True)
        assert done.returncode == 0 and not done.stderr, done.stderr


def test_the_standalone_c_carries_the_path_task(tmp_path):
    from test_standalone_controller import CController, recorded_samples

    exp = hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster()), duration=1.5)
    py = exp.build_controller()
    py.generate(tmp_path, "ur5_path")
    assert (tmp_path / "hybrid_path.h").is_file()
    c = CController(tmp_path, "ur5_path")
    worst = 0.0
    for t, q, qd, wrench in recorded_samples(exp):
        tau_py = py(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0, c.name(status)
        worst = max(worst, float(np.max(np.abs(tau_c - tau_py)) / max(1.0, np.max(np.abs(tau_py)))))
        path_c = np.frombuffer(c.ffi.buffer(c.c.path), float)
        np.testing.assert_allclose(path_c, py.path_references.follower.served, rtol=1e-12, atol=1e-12)
    assert worst < 1e-12
    assert py.path_task["travelled"] > 0.1  # it went along the path
    # one build serves every path: the struct pointed at another path's table follows that one
    other = PathFollower(hybrid.PathTask(raster(passes=2, length=0.05), speed=0.05), PLANE)
    c.c.path_table = c.ffi.from_buffer("double[]", other.table)
    for i, x in enumerate(other.settings):
        c.c.path_settings[i] = x
    c.lib.ur5_path_controller_reset(c.c)
    t, q, qd, wrench = recorded_samples(exp, 1)[0]
    assert c.step(t, q, qd, wrench)[0] == 0
    assert c.c.path_settings[PATH_SETTINGS.index("length")] == pytest.approx(other.task.path.length)
    assert c.c.path[OUT["speed"]] == pytest.approx(0.005)  # the other task's start speed, a tenth of 0.05


def whole_task(duration: float = 4.6):
    """From 5 mm above the path's start to 2 cm above its end: approach, touch, path, release, retreat."""
    task = hybrid.PathTask(raster(passes=2, length=0.06), speed=0.1, force=10.0, retreat_distance=0.02)
    return hybrid.tracing_experiment(surface=PLANE, path_task=task, duration=duration, start_gap=0.005,
                                     approach_speed=0.05)


def test_a_whole_task_from_free_space_to_the_retreat():
    exp = whole_task()
    res = hybrid.simulate(exp)
    m = res.metrics
    from hybrid.simulation.path_metrics import path_series

    series = path_series(res)
    phases = series["phase"]
    assert phases[0] == 0 and phases[-1] == PATH_PHASES.index("clear")  # from the approach to clear of the part
    assert np.all(np.diff(phases) >= 0)  # each phase once, in order
    assert 0 < m["first_touch_time_s"] < 0.5
    assert m["path_error_rms_m"] <= 1e-3 and m["path_contact_losses"] == 0
    assert m["path_force_rms_error_N"] <= 0.02 * 10.0
    assert m["path_end_peak_force_N"] <= 10.0 * 1.02  # the release and retreat: no force spike
    tip = res.outputs[-1, [res.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]]
    height = (tip - np.asarray(PLANE.point)) @ np.asarray(PLANE.normal) / np.linalg.norm(PLANE.normal)
    assert height == pytest.approx(0.02, abs=2e-3)  # it stopped 2 cm above the part


def test_the_whole_task_in_standalone_c_equals_the_controller(tmp_path):
    from test_standalone_controller import CController, recorded_samples

    exp = whole_task()
    py = exp.build_controller()
    py.generate(tmp_path, "ur5_task")
    c = CController(tmp_path, "ur5_task")
    seen = set()
    for t, q, qd, wrench in recorded_samples(exp):
        tau_py = py(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0, c.name(status)
        assert np.max(np.abs(tau_c - tau_py)) <= 1e-12 * max(1.0, np.max(np.abs(tau_py)))
        seen.add(py.path_task["phase"])
        assert np.frombuffer(c.ffi.buffer(c.c.selection), float).tolist() == py.step_inputs()["selection"].tolist()
    assert seen == set(range(len(PATH_PHASES)))
    py.reset()
    c.lib.ur5_task_controller_reset(c.c)
    assert np.frombuffer(c.ffi.buffer(c.c.gains), float).tolist() == py.step_inputs()["gains"].tolist()
    assert py.step_inputs()["selection"].tolist() == py.step_inputs(at_start=True)["selection"].tolist()


def rotated(v, k, angle):
    """``v`` turned by ``angle`` about the unit axis ``k`` (Rodrigues), in NumPy."""
    return v * math.cos(angle) + np.cross(k, v) * math.sin(angle) + k * (k @ v) * (1 - math.cos(angle))


# the Panda's wrist (joint 5) passes its speed limit briefly at the start of a tilted tool with its posture: the
# start's, whatever the task's gains (it does with orientation_gain=0 too); the test judges the tool's axis
@pytest.mark.filterwarnings("ignore::hybrid.JointLimitWarning")
@pytest.mark.parametrize("tilt, lead", [(0.1, 0.2), (-0.1, 0.15), (0.1, -0.2), (0.0, 0.0)])
def test_the_tool_holds_its_tilt_and_lead_along_the_path(tilt, lead):
    pillar = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)
    points = [pillar.project(np.array(p)) for p in [(0.42, 0.0, 0.78), (0.43, -0.05, 0.80), (0.45, -0.1, 0.76)]]
    path = hybrid.WaypointPath(pillar, points)
    exp = hybrid.panda_experiment(path_task=hybrid.PathTask(path, speed=0.05, tilt=tilt, lead=lead), duration=3.0)
    res = hybrid.simulate(exp)
    assert res.metrics["path_error_rms_m"] <= 1e-3
    nq = exp.robot.n
    q = res.state[-1, :nq]
    tool = hybrid.arm_terms(exp.robot, q, np.zeros(nq))["rotation"][:, 2]
    from hybrid.simulation.path_metrics import path_series

    end = {k: v[-1] for k, v in path_series(res).items()}
    t, n = (np.array([end[f"{a}_{x}"] for x in "xyz"]) for a in ("t", "n"))
    wanted = rotated(rotated(-n, np.cross(n, t), lead), t, tilt)  # -n turned by the lead about t2, the tilt about t1
    assert math.degrees(math.acos(min(1.0, tool @ wanted))) <= 1.0
    assert math.degrees(math.acos(min(1.0, -tool @ n))) == pytest.approx(
        math.degrees(math.acos(math.cos(tilt) * math.cos(lead))), abs=1.0)


def test_a_tilt_needs_the_rotational_axes():
    with pytest.raises(hybrid.HybridError, match="axes='all'"):
        hybrid.Controller(hybrid.ur5(), PLANE, axes="position", path_task=hybrid.PathTask(raster(), tilt=0.1))
    with pytest.raises(hybrid.HybridError, match="below 80 degrees"):
        hybrid.PathTask(raster(), lead=1.5).table(PLANE)


@pytest.mark.filterwarnings("ignore::hybrid.JointLimitWarning")
def test_a_tilted_tool_in_standalone_c_equals_the_controller(tmp_path):
    from test_standalone_controller import CController, recorded_samples

    pillar = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)
    points = [pillar.project(np.array(p)) for p in [(0.42, 0.0, 0.78), (0.43, -0.05, 0.80)]]
    task = hybrid.PathTask(hybrid.WaypointPath(pillar, points), speed=0.05, tilt=0.1, lead=-0.2)
    exp = hybrid.panda_experiment(path_task=task, duration=0.5)
    py = exp.build_controller()
    py.generate(tmp_path, "panda_task")
    c = CController(tmp_path, "panda_task")
    for t, q, qd, wrench in recorded_samples(exp):
        tau_py = py(t, q, qd, wrench)
        status, tau_c = c.step(t, q, qd, wrench)
        assert status == 0, c.name(status)
        # the measurement compiled twice (the runtime's build for this processor contracts into fused
        # multiply-adds, the strict one does not): the tip rotation's rounding reaches the law through the spin
        # references, amplified by the Panda's wrist (2e-12 of the torque measured on this run)
        assert np.max(np.abs(tau_c - tau_py)) <= 1e-11 * max(1.0, np.max(np.abs(tau_py)))
    spins = [OUT["spin_t1"], OUT["spin_t2"]]
    # the spins alike: the joints' sines and cosines differ by an ulp between the two builds (1.6e-12 rad measured)
    assert np.allclose(np.frombuffer(c.ffi.buffer(c.c.path), float)[spins], py.path_references.follower.served[spins],
                       rtol=1e-11, atol=1e-11)


def test_a_path_out_of_the_arms_reach_is_refused_before_the_run():
    far = hybrid.WaypointPath(PLANE, [PLANE.project(np.array(p)) for p in [(0.45, 0.0, 0.1), (1.4, 0.0, 0.1)]])
    exp = hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(far, speed=0.2), duration=8.0)
    with pytest.raises(hybrid.HybridError, match="leaves the arm's reach near s = "):
        hybrid.simulate(exp)
