"""Path tasks in the compiled closed loop at settings nobody tuned: other surfaces and closed paths with laps, a
path of one's own, runs that end before contact or long past the path's end, runs that stop, dropouts in every
phase of the task (and long enough to enter the safe state), the law's guard refusing the samples where the
follower turns the frame or starts the retreat, the timing check off, the Panda's tilted tool, runs of very
different tables side by side as lanes, sweeps, and bad input.

Each run in C is held against the Python runner (the Controller calling the same generated follower each sample)
twice: whole runs within rounding, and sample by sample (the Controller, given the compiled run's states and the
readings the runner gives, gives the compiled torques), which holds where the plant amplifies rounding (an arm
held still against friction, in a safe state or at the path's end)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from test_path_loop import PILLAR, PLANE, SPHERE, raster, relative

import hybrid
from hybrid.control.controller import Controller
from hybrid.geometry.paths import Path
from hybrid.simulation import closed_loop, runner
from hybrid.simulation.path_metrics import path_series
from hybrid.simulation.sensing import plant_reader
from hybrid.spec.metrics import PATH_METRICS
from hybrid.spec.path_follow import PATH_PHASES

# the task on three axes leaves the UR5 three joints to spare (warned: no posture task)
pytestmark = [pytest.mark.filterwarnings("ignore::hybrid.JointLimitWarning"),
              pytest.mark.filterwarnings("ignore::hybrid.RedundancyWarning")]

#: a level plane, for circles (a CirclePath runs in a plane of constant z)
FLAT = hybrid.Plane((0.45, 0.0, 0.1), (0.0, 0.0, 1.0))
#: an ellipsoid about the sphere's centre, as a formula
ELLIPSOID = hybrid.ImplicitSurface("((x - 0.5)/a)**2 + (y/b)**2 + ((z - 0.2)/c)**2 - 1",
                                   {"a": 0.18, "b": 0.15, "c": 0.13})
RETREAT, CLEAR = PATH_PHASES.index("retreat"), PATH_PHASES.index("clear")


def short_raster(**kw) -> hybrid.RasterPath:
    """Two 3 cm passes on the plane: the whole task, to clear, within 2 s."""
    return raster(passes=2, length=0.03, **kw)


def toward_the_singularity(passes: int = 1) -> hybrid.RasterPath:
    """A raster on the plane towards the base, where the arm's conditioning falls (to 0.2 at 0.48 s)."""
    return hybrid.RasterPath(PLANE, PLANE.project(np.array([0.3, -0.05, 0.1])), (-1.0, 0.0, 0.0), 0.2, 0.01, passes)


def on_plane(along=None, duration: float = 2.0, **settings) -> hybrid.Experiment:
    """A path task ``along`` a path on the plane (default :func:`short_raster`); ``settings``: the PathTask's (by
    its field names) and the experiment's."""
    fields = {f.name for f in dataclasses.fields(hybrid.PathTask)} - {"path"}
    task = {k: settings.pop(k) for k in list(settings) if k in fields}
    task = hybrid.PathTask(short_raster() if along is None else along, **{"retreat_distance": 0.01, **task})
    return hybrid.tracing_experiment(surface=PLANE, path_task=task, duration=duration, **settings)


def with_dropout(exp, at: float, duration: float) -> hybrid.Experiment:
    return dataclasses.replace(exp, sensor=dataclasses.replace(exp.sensor, dropout_at=at, dropout_duration=duration))


def replay_mismatch(exp, compiled) -> float:
    """The largest difference, relative to the torque, between the compiled run's torque at each sample and the
    Controller's given that sample's compiled state and the reading the Python runner gives (a sample the
    controller refuses in a run that reacts to faults: the torque its error carries, as the runner applies it)."""
    ctrl, plant, m = exp.build_controller(), exp.plant(), exp.steps_per_sample
    read, nq, worst = plant_reader(exp, plant) or plant.sensor_wrench, plant.nq, 0.0
    for k in range(exp.n_samples):
        x = compiled.state[k * m]
        try:
            tau = ctrl(k * exp.sample_time, x[:nq], x[nq:2 * nq], read(x))
        except hybrid.HybridError as exc:
            if not exp.sensor.drops_out:
                raise
            tau = exc.torque
        worst = max(worst, float(np.abs(tau - compiled.tau[1 + k * m]).max() / max(1.0, np.abs(tau).max())))
    return worst


def same_metrics(a: dict, b: dict, rel: float) -> None:
    assert a.keys() == b.keys()
    for name, value in b.items():
        assert a[name] == pytest.approx(value, rel=rel, abs=1e-10, nan_ok=True), name


def compiled_and_python(exp, states: float | None = 1e-8):
    """Both runs of ``exp``, checked alike: the states within ``states`` (None: not compared whole; the plant
    amplifies rounding there), the metrics within 1e-6, every sample's torque within 1e-11."""
    assert closed_loop.prepare(exp) is not None
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    if states is not None:
        assert relative(compiled.state, python.state) < states
    same_metrics(compiled.metrics, python.metrics, 1e-6)
    assert replay_mismatch(exp, compiled) <= 1e-11
    return compiled, python


def phases(run) -> np.ndarray:
    """The phase the run's path task is in at each control sample."""
    return path_series(run)["phase"]


def conditioning(exp, run) -> np.ndarray:
    """The controller's model's conditioning at each control sample of ``run`` (what the law's guard reads)."""
    return exp.controller_model().conditioning(run.q[::exp.steps_per_sample][:exp.n_samples])


class PlaneCircle(Path):
    """A circle on a tilted plane, parametrised by arc length: a closed path of one's own (no frames, no
    curvature given: the task takes them from its points and tangents)."""

    closed = True

    def __init__(self, plane, center, radius: float, start: float = 0.0):
        n = np.asarray(plane.normal_at(center), float)
        self.u = np.cross(n, (1.0, 0.0, 0.0)) / np.linalg.norm(np.cross(n, (1.0, 0.0, 0.0)))
        self.v = np.cross(n, self.u)
        self.c, self.r, self.start, self.length = np.asarray(center, float), radius, start, 2 * math.pi * radius

    def point_at(self, s):
        return self.c + self.r * (math.cos(s / self.r) * self.u + math.sin(s / self.r) * self.v)

    def points_at(self, s):
        return np.array([self.point_at(float(x)) for x in np.asarray(s, float)])

    def tangent_at(self, s):
        return -math.sin(s / self.r) * self.u + math.cos(s / self.r) * self.v

    def arc_of(self, p):
        d = np.asarray(p, float) - self.c
        return self.r * math.atan2(d @ self.v, d @ self.u)


class Straight(Path):
    """A straight path of one's own from a point of the plane along ``direction`` (off the plane where it leaves
    it), ``pace`` m per metre of arc length (1: parametrised by arc length)."""

    length = 0.05

    def __init__(self, direction=(1.0, 0.0, 0.0), pace: float = 1.0):
        self.c = PLANE.project(np.array([0.45, -0.02, 0.1]))
        self.d, self.pace = np.asarray(direction, float) / np.linalg.norm(direction), pace

    def point_at(self, s):
        return self.c + self.d * self.pace * s

    def points_at(self, s):
        return np.array([self.point_at(float(x)) for x in np.asarray(s, float)])

    def tangent_at(self, s):
        return self.d

    def arc_of(self, p):
        return float((np.asarray(p, float) - self.c) @ self.d)


def _closed_waypoints_on_the_sphere():
    points = [SPHERE.project(np.array(p)) for p in [(0.45, -0.04, 0.4), (0.52, -0.03, 0.4), (0.53, 0.04, 0.4),
                                                    (0.46, 0.04, 0.4)]]
    path = hybrid.WaypointPath(SPHERE, points, closed=True)
    return hybrid.tracing_experiment(surface=SPHERE, duration=4.0, path_task=hybrid.PathTask(
        path, speed=0.08, laps=1.1, force=lambda s: 6.0 + 30.0 * s)), path.length * 1.1


def _circle_laps_on_a_level_plane():
    circle = hybrid.CirclePath((0.45, 0.0, 0.1), 0.03, start=0.25)  # beyond one lap: its start is modulo the lap
    return hybrid.tracing_experiment(surface=FLAT, duration=3.0, start_gap=0.003, approach_speed=0.04,
                                     path_task=hybrid.PathTask(circle, speed=0.1, laps=1.2,
                                                               retreat_distance=0.005)), 1.2 * 2 * math.pi * 0.03


def _own_closed_path():
    own = PlaneCircle(PLANE, PLANE.project(np.array([0.45, 0.0, 0.1])), 0.025, start=0.01)
    return hybrid.tracing_experiment(surface=PLANE, duration=3.0, path_task=hybrid.PathTask(
        own, speed=0.08, laps=1.3, retreat_distance=0.004, speed_start=0.02)), 1.3 * own.length


def _spiral_on_an_ellipsoid():
    a = 0.35  # a point on the ellipsoid's upper side, facing the robot
    center = np.array([0.5 - 0.18 * math.sin(a), 0.0, 0.2 + 0.13 * math.cos(a)])
    spiral = hybrid.SpiralPath(ELLIPSOID, center, 0.008, 1.5, start_radius=0.01)
    return hybrid.tracing_experiment(surface=ELLIPSOID, duration=2.5, path_task=hybrid.PathTask(
        spiral, speed=0.06, retreat_distance=0.004)), spiral.length


def _position_axes_only():
    return on_plane(axes="position", duration=1.8, retreat_distance=0.005), short_raster().length


SURFACES = {
    "closed waypoints on the sphere, laps, force(s)": _closed_waypoints_on_the_sphere,
    "circle on a level plane, laps, approach, retreat": _circle_laps_on_a_level_plane,
    "a closed path of one's own, laps, retreat": _own_closed_path,
    "spiral on an implicit ellipsoid, retreat": _spiral_on_an_ellipsoid,
    "the task on three axes (no tool spins)": _position_axes_only,
}


@pytest.mark.parametrize("case", list(SURFACES))
def test_other_surfaces_paths_and_axes_run_in_c_as_in_python(case):
    exp, distance = SURFACES[case]()
    compiled, _ = compiled_and_python(exp)
    # the task ran to its end: the laps asked, or the open path
    assert compiled.metrics["path_time_s"] < exp.duration
    assert compiled.metrics["path_travelled_m"] > 0.9 * distance
    assert compiled.metrics["path_error_rms_m"] < 1e-3


@pytest.mark.parametrize("duration, gap", [(0.01, 0.0), (0.05, 0.0), (0.05, 0.005), (0.3, 0.005), (6.0, 0.0)])
def test_runs_that_end_before_contact_mid_path_or_long_past_the_end(duration, gap):
    """One sample; a run that ends in the approach (the path's errors are NaN alike) or mid-path; a run that
    retreats, clears and stays clear for seconds."""
    exp = on_plane(duration=duration, **({"start_gap": gap, "approach_speed": 0.05} if gap else {}))
    compiled, _ = compiled_and_python(exp)
    if gap and duration < 0.1:  # still approaching: nothing followed yet
        assert math.isnan(compiled.metrics["path_error_rms_m"])
    if duration > 5:
        assert phases(compiled)[-1] == CLEAR
        assert compiled.metrics["path_time_s"] < 2.0


def test_a_run_that_stops_is_run_again_by_the_python_runner_for_its_error():
    """The law's guard stops the run where the arm's conditioning falls below singular_tol (chosen from a run
    that goes there): the compiled loop stops at that sample with NaN metrics, path metrics too, and simulate
    raises what the Python runner raises, at the same time."""
    exp = on_plane(toward_the_singularity(), duration=1.0, retreat_distance=0.0, singular_tol=0.05)
    free = hybrid.simulate(exp)
    cond = conditioning(exp, free)
    k = int(np.argmin(cond))
    assert cond[0] > cond[k] + 1e-3
    stopping = dataclasses.replace(exp, singular_tol=float(cond[0] + cond[k]) / 2)
    outcome = closed_loop.run([closed_loop.prepare(stopping, lanes=1)])[0]
    expected = int(np.flatnonzero(cond < stopping.singular_tol)[0])
    assert outcome.status != 0 and outcome.failed_sample == expected
    assert all(math.isnan(outcome.metrics[m.name]) for m in PATH_METRICS)
    errors = []
    for compiled in (True, False):
        with pytest.raises(hybrid.SimulationError) as info:
            hybrid.simulate(stopping, compiled=compiled)
        errors.append(info.value)
    assert errors[0].time == errors[1].time == pytest.approx(expected * exp.sample_time)
    assert str(errors[0]).splitlines()[0] == str(errors[1]).splitlines()[0]
    assert "singular" in str(errors[0])


@pytest.fixture(scope="module")
def whole_task():
    """The task on the plane to clear (2.5 s) and the first sample of each of its phases."""
    exp = on_plane(duration=2.5)
    ph = phases(hybrid.simulate(exp))
    return exp, {name: int(np.flatnonzero(ph == i)[0]) for i, name in enumerate(PATH_PHASES) if (ph == i).any()}


@pytest.mark.parametrize("phase, after, samples", [("follow", 50, 3), ("unload", 0, 3), ("retreat", -1, 3),
                                                   ("retreat", 0, 3), ("clear", 0, 3), ("follow", 50, 12)])
def test_a_dropout_in_each_phase_runs_in_c_as_in_python(whole_task, phase, after, samples):
    """The reading lost for ``samples`` samples from ``after`` samples after the first of a phase (-1: from the
    sample before it; 12 samples: more than the fault reaction's 5, into the safe state mid-path)."""
    exp, first = whole_task
    lost = with_dropout(exp, (first[phase] + after) * exp.sample_time, samples * exp.sample_time)
    compiled, _ = compiled_and_python(lost)
    clean = hybrid.simulate(exp)
    assert relative(compiled.state, clean.state) > 1e-6  # the dropout changed the run
    if samples >= 12:  # the safe state: the arm held where it was, the path left unfinished
        assert compiled.metrics["path_travelled_m"] < 0.75 * clean.metrics["path_travelled_m"]
        assert math.isnan(compiled.metrics["path_time_s"])


@pytest.mark.parametrize("at", [0.0, 0.05])
def test_a_dropout_from_the_start_or_in_the_approach_runs_in_c_as_in_python(at):
    """Lost from the first sample (no torque served yet) into the safe state, and in the approach from a gap.
    Held still against friction in the safe state the plant amplifies rounding: the samples' torques agree."""
    exp = with_dropout(on_plane(duration=1.0, start_gap=0.005 if at else 0.0, approach_speed=0.05 if at else 0.0),
                       at, 0.06)
    compiled_and_python(exp, states=None if at == 0 else 1e-8)


@pytest.fixture(scope="module")
def near_singular():
    """A curved path running towards lower conditioning (its retreat starting at once), its run and the
    conditioning at each sample."""
    points = [PLANE.project(np.array(p)) for p in [(0.33, -0.05, 0.1), (0.30, -0.035, 0.1), (0.27, -0.05, 0.1),
                                                   (0.24, -0.035, 0.1)]]
    task = hybrid.PathTask(hybrid.WaypointPath(PLANE, points), speed=0.08, retreat_distance=0.01, unload_time=0.0)
    return _reacting_run(task)


@pytest.fixture(scope="module")
def turning_near_singular():
    """A raster whose turn comes where the conditioning is lowest, its run and the conditioning at each sample."""
    path = hybrid.RasterPath(PLANE, PLANE.project(np.array([0.3, -0.05, 0.1])), (-1.0, 0.0, 0.0), 0.04, 0.01, 2)
    return _reacting_run(hybrid.PathTask(path, retreat_distance=0.005))


def _reacting_run(task):
    # a dropout after the task: the run reacts to faults, so a refused sample does not stop it
    exp = with_dropout(hybrid.tracing_experiment(surface=PLANE, path_task=task, duration=2.0, singular_tol=0.02),
                       1.9, 0.01)
    run = hybrid.simulate(exp)
    return exp, run, conditioning(exp, run)


def test_the_guard_refusing_samples_at_a_turn_leaves_the_follower_as_it_was(turning_near_singular):
    """singular_tol just above the conditioning's lowest values: the law's guard refuses a few samples at the
    raster's turn (where the follower turns the frame's direction each sample), the next ones are served again
    and the task goes on to its end, in C as in the Controller (whose follower stays at a refused sample)."""
    exp, run, cond = turning_near_singular
    lowest = np.sort(cond)
    refusing = dataclasses.replace(exp, singular_tol=float(lowest[1] + lowest[2]) / 2)
    compiled, _ = compiled_and_python(refusing)
    refused = np.flatnonzero(conditioning(refusing, compiled) < refusing.singular_tol)
    assert 1 <= len(refused) < exp.fault_reaction.fault_samples and np.all(np.diff(refused) == 1)
    series = path_series(compiled)
    e = np.column_stack([series[f"e_{c}"] for c in "xyz"])
    assert np.linalg.norm(e[refused] - e[refused - 1], axis=1).min() > 1e-3  # the frame turns there
    assert compiled.metrics["path_time_s"] < exp.duration
    assert relative(compiled.state, run.state) > 1e-6


@pytest.mark.parametrize("where", ["mid-path", "at the retreat"])
def test_the_guard_refusing_a_sample_the_follower_changed_runs_in_c_as_in_python(near_singular, where):
    """singular_tol between the conditioning at a sample and the lowest before it: the law's guard refuses that
    sample (and the next, into the safe state) after the follower turned the frame's direction (mid-path) or
    turned the normal axis velocity-controlled (the retreat's first sample): what it changed is undone."""
    exp, run, cond = near_singular
    k = len(cond) // 4 if where == "mid-path" else int(np.flatnonzero(phases(run) == RETREAT)[0])
    assert cond[k] < cond[:k].min()
    refusing = dataclasses.replace(exp, singular_tol=float(cond[k] + cond[:k].min()) / 2)
    compiled, _ = compiled_and_python(refusing, states=1e-7)
    m = exp.steps_per_sample
    assert relative(compiled.state[:k * m + 1], run.state[:k * m + 1]) < 1e-12  # the same run up to there
    assert relative(compiled.state, run.state) > 1e-6


def _with_timing(exp, timing_tolerance):
    return Controller(exp.controller_model(), exp.told_surface(), exp.controller, axes=exp.axes,
                      frame_direction=exp.frame_direction, posture=exp.posture, **exp.controller_settings(),
                      timing_tolerance=timing_tolerance)


def test_the_timing_check_off_runs_in_c_as_in_python():
    """timing_tolerance None: the sample after a dropout is on time (its integrals advance), alike in C and in the
    Controller; with the check on it is late, and the runs differ."""
    exp = with_dropout(on_plane(duration=1.5), 0.5, 0.03)
    plant = exp.plant()
    outcomes = {}
    for tolerance in (None, 0.25):
        outcome = closed_loop.run([closed_loop.prepare(exp, lanes=1, ctrl=_with_timing(exp, tolerance))],
                                  record=True)[0]
        python = runner.run(exp, plant, _with_timing(exp, tolerance), exp.checked_start(plant.record))
        assert relative(outcome.states, python.state) < 1e-8
        same_metrics(outcome.metrics, python.metrics, 1e-6)
        outcomes[tolerance] = outcome
    assert relative(outcomes[None].states, outcomes[0.25].states) > 1e-4


def test_the_panda_with_a_tool_tilted_along_the_path_retreats_as_in_python():
    """The Panda on six axes with its posture: tilt a function of arc length, a lead, its own release time and
    retreat speed, and a dropout mid-path."""
    points = [PILLAR.project(np.array(p)) for p in [(0.42, 0.0, 0.78), (0.43, -0.05, 0.80), (0.45, -0.1, 0.76)]]
    task = hybrid.PathTask(hybrid.WaypointPath(PILLAR, points), speed=0.05, tilt=lambda s: 0.1 + 0.5 * s, lead=-0.2,
                           retreat_distance=0.005, unload_time=0.1, retreat_speed=0.03)
    exp = with_dropout(hybrid.panda_experiment(path_task=task, duration=3.0), 1.0, 0.02)
    compiled, _ = compiled_and_python(exp)
    assert phases(compiled)[-1] == CLEAR
    assert compiled.metrics["path_error_rms_m"] < 1e-3


def test_runs_of_very_different_tables_side_by_side_as_lanes():
    """Nine runs in one loop: tables of 4 to 13573 nodes, a run that stops at a singularity, one that enters the
    safe state, one that approaches, friction and a force profile, a dropout in the release, a closed path's
    laps. Each is bitwise the same beside other neighbours (a run of another loop in the same call among them), the
    same within rounding alone and without a record."""
    ends = [PLANE.project(np.array(p)) for p in [(0.45, -0.02, 0.1), (0.47, -0.02, 0.1)]]
    ring = [PLANE.project(np.array(p)) for p in [(0.44, -0.03, 0.1), (0.48, -0.03, 0.1), (0.47, 0.01, 0.1)]]
    base = {"singular_tol": 0.2}
    exps = {
        "to clear": on_plane(**base),
        "stops": on_plane(toward_the_singularity(passes=2), retreat_distance=0.0, **base),
        "fine table": on_plane(raster(), spacing=2e-5, **base),
        "tiny table": on_plane(hybrid.WaypointPath(PLANE, ends), speed=0.02, spacing=0.01, retreat_distance=0.0,
                               **base),
        "safe state": with_dropout(on_plane(**base), 0.4, 0.1),
        "approach": on_plane(start_gap=0.005, approach_speed=0.05, **base),
        "friction, force(s)": on_plane(force=lambda s: 5.0 + 100.0 * s, contact=hybrid.Contact(friction=0.4), **base),
        "dropout in the release": with_dropout(on_plane(**base), 1.15, 0.03),
        "closed, laps": on_plane(hybrid.WaypointPath(PLANE, ring, closed=True), laps=1.5, retreat_distance=0.0,
                                 **base),
    }
    prepared = [closed_loop.prepare(e) for e in exps.values()]
    assert len({id(p.loop) for p in prepared}) == 1 and len({p.settings for p in prepared}) == 1
    sizes = [len(p.tables[0]) for p in prepared]  # the path tables
    assert min(sizes) < 10 and max(sizes) > 10_000
    other = closed_loop.prepare(hybrid.tracing_experiment(duration=2.0))
    together = closed_loop.run([other, *prepared], record=True)[1:]
    reordered = closed_loop.run(prepared[::-1], record=True)[::-1]
    unrecorded = closed_loop.run(prepared)
    for name, p, got, back, bare in zip(exps, prepared, together, reordered, unrecorded):
        assert (back.status, back.failed_sample) == (got.status, got.failed_sample), name
        assert np.array_equal(back.states, got.states, equal_nan=True), name
        assert back.metrics == pytest.approx(got.metrics, rel=0, abs=0, nan_ok=True), name
        same_metrics(bare.metrics, got.metrics, 1e-12)  # without a record: its path metrics within rounding
        alone = closed_loop.run([p], record=True)[0]  # its own build: the same within rounding
        assert (alone.status, alone.failed_sample) == (got.status, got.failed_sample), name
        assert np.array_equal(np.isnan(alone.states), np.isnan(got.states)), name
        assert relative(np.nan_to_num(got.states), np.nan_to_num(alone.states)) < 1e-11, name
        same_metrics(got.metrics, alone.metrics, 1e-9)
    outcome = dict(zip(exps, together))
    assert outcome["stops"].status != 0 and math.isnan(outcome["stops"].metrics["path_error_rms_m"])
    assert all(o.status == 0 for name, o in outcome.items() if name != "stops")
    assert outcome["safe state"].metrics["path_travelled_m"] < outcome["to clear"].metrics["path_travelled_m"] / 2
    # each against the Python runner: its metrics
    for name, exp in exps.items():
        if name != "stops":
            same_metrics(outcome[name].metrics, hybrid.simulate(exp, compiled=False).metrics, 1e-6)


@pytest.mark.parametrize("grid", [
    {"contact.friction": [0.0, 0.4], "model_error": [0.0, 0.3], "sensor.stiffness": [800.0, 1500.0]},
    {"path_task.speed": [0.05, 0.12], "sample_time": [0.005, 0.01]},
    {"touch_threshold": [0.3, 3.0], "approach_speed": [0.03, 0.08]},
    {"singular_tol": [0.2, 0.05], "duration": [0.6, 1.0]},
])
def test_a_sweep_of_a_path_task_gives_each_row_the_path_metrics_simulate_gives(grid):
    """Rows made from the template's row (contact, sensor, model) or prepared whole (the task's speed, the sample
    time, the touch, the guard, the run's length), some stopping: each row's path metrics are simulate's (NaN
    where the run stopped, which simulate raises)."""
    start = {"start_gap": 0.005, "approach_speed": 0.05} if "approach_speed" in grid else {}
    along = toward_the_singularity() if "singular_tol" in grid else None
    exp = on_plane(along, duration=1.5, retreat_distance=0.0 if along else 0.01, **start)
    frame = hybrid.sweep(exp, grid, workers=1)
    assert len(frame) == math.prod(len(v) for v in grid.values())
    failed = 0
    for _, row in frame.iterrows():
        settings = {k: row[k] for k in grid}
        run_exp = hybrid.sweeps.apply(exp, settings)
        if row["status"] != "ok":
            failed += 1
            with pytest.raises(hybrid.SimulationError):
                hybrid.simulate(run_exp)
            assert all(math.isnan(row[m.name]) for m in PATH_METRICS)
            continue
        run = hybrid.simulate(run_exp)
        for m in PATH_METRICS:
            assert row[m.name] == pytest.approx(run.metrics[m.name], rel=1e-9, abs=1e-12, nan_ok=True), (settings, m)
    assert failed == (2 if "singular_tol" in grid else 0)


def test_a_sweep_in_two_workers_gives_the_rows_of_one():
    exp = on_plane(duration=1.5)
    grid = {"contact.friction": [0.0, 0.2, 0.4], "model_error": [0.0, 0.3]}
    one, two = (hybrid.sweep(exp, grid, workers=w) for w in (1, 2))
    names = [m.name for m in PATH_METRICS]
    assert one[names].equals(two[names])


BAD = {
    "a planar arm": lambda: hybrid.paper_experiment(path_task=hybrid.PathTask(short_raster())),
    "a force reference besides": lambda: on_plane(force_reference=hybrid.Step(5.0, 8.0, 0.3)),
    "a frame direction besides": lambda: on_plane(frame_direction=(0.0, 0.0, 1.0)),
    "a path besides": lambda: on_plane(path=short_raster()),
    "laps on an open path": lambda: on_plane(laps=2.0),
    "a cross-track gain too fast": lambda: on_plane(cross_track_gain=80.0),
    "a tilt without the tool's axes": lambda: on_plane(axes="position", tilt=0.2),
    "a tilt of 86 degrees": lambda: on_plane(tilt=1.5),
    "a speed not a number": lambda: on_plane(speed=lambda s: float("nan")),
    "a negative speed": lambda: on_plane(speed=-0.1),
    "too fast for its path": lambda: on_plane(raster(passes=1, length=0.01), speed=0.5),
    "a path of one's own not by arc length": lambda: on_plane(Straight(pace=2.0)),
    "a path of one's own off the surface": lambda: on_plane(Straight(direction=(0.0, 1.0, 0.0))),
    "the desired frame": lambda: on_plane(frame="desired"),
    "a negative retreat": lambda: hybrid.PathTask(short_raster(), retreat_distance=-0.01),
    "an unload time without a retreat": lambda: hybrid.PathTask(short_raster(), unload_time=0.1),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_input_is_refused_with_a_hybrid_error(case):
    """Refused where the experiment is made, or where its run is: compiled or not, with a HybridError; a sweep
    marks the row invalid."""
    try:
        exp = BAD[case]()
    except hybrid.HybridError as exc:
        assert str(exc).strip()
        return
    exp = dataclasses.replace(exp, duration=0.05)
    for compiled in (True, False):
        with pytest.raises(hybrid.HybridError):
            hybrid.simulate(exp, compiled=compiled)
    with pytest.raises(hybrid.HybridError):
        closed_loop.prepare(exp)
    assert hybrid.sweep(exp, {"model_error": [0.1]}, workers=1)["status"].tolist() == ["invalid"]


def test_a_path_task_with_a_noisy_sensor_runs_in_python_with_its_path_metrics():
    exp = on_plane(duration=1.0, sensor=hybrid.Sensor(force_noise=0.2))
    assert closed_loop.prepare(exp) is None
    run = hybrid.simulate(exp)
    assert {m.name for m in PATH_METRICS} <= run.metrics.keys()
    assert run.metrics["path_travelled_m"] > 0.05


# ------------------------------------------------------------------------- copies, metrics and messages


def test_a_copy_with_another_path_task_works_out_its_references_again():
    """The force and direction an experiment worked out from its path task are its task's: a copy with another
    task (another force, another direction) works them out again, and a sweep over the task's force runs."""
    exp = on_plane(force=10.0)
    stronger = dataclasses.replace(exp, path_task=dataclasses.replace(exp.path_task, force=14.0))
    assert stronger.force_reference == hybrid.Step(14.0, 14.0, 0.0)
    across = hybrid.RasterPath(PLANE, PLANE.project(np.array([0.42, -0.02, 0.1])), (0.0, 0.6, -0.8), 0.03, 0.01, 2)
    turned = dataclasses.replace(exp, path_task=hybrid.PathTask(across, retreat_distance=0.01))
    assert not np.allclose(turned.frame_direction, exp.frame_direction)
    assert hybrid.Experiment.from_dict(stronger.to_dict()).force_reference == stronger.force_reference
    frame = hybrid.sweep(on_plane(duration=0.6), {"path_task.force": [8.0, 12.0]}, workers=1)
    assert (frame["status"] == "ok").all()
    # a reference given with the task, other than the task's, is still refused
    with pytest.raises(hybrid.HybridError, match="leave force_reference"):
        dataclasses.replace(exp, force_reference=hybrid.Step(12.0, 12.0, 0.0))


def test_the_travelled_length_of_a_completed_path_is_its_length():
    """The follower's progress falls back as the tip retreats past the path's end: what was travelled is the
    most it reached."""
    res = hybrid.simulate(on_plane(axes="position", retreat_distance=0.005, duration=1.8))
    m = res.metrics
    assert math.isfinite(m["path_time_s"])
    length = res.experiment.path_task.path.length
    assert m["path_travelled_m"] >= length - 1e-3


def test_the_replayed_phases_are_the_controllers_through_a_dropout():
    """A dropout in the release: the controller's follower holds through the lost samples, and so does the
    follower the metrics replay (its retreat starts at the controller's sample)."""
    exp = on_plane(duration=2.5)
    first = int(np.flatnonzero(phases(hybrid.simulate(exp)) == PATH_PHASES.index("unload"))[0])
    lost = with_dropout(exp, (first + 2) * exp.sample_time, 3 * exp.sample_time)
    res = hybrid.simulate(lost)
    ctrl, plant, m = lost.build_controller(), lost.plant(), lost.steps_per_sample
    read = plant_reader(lost, plant) or plant.sensor_wrench
    held = []
    for k in range(lost.n_samples):
        x = res.state[k * m]
        try:
            ctrl(k * lost.sample_time, x[:plant.nq], x[plant.nq:2 * plant.nq], read(x))
        except hybrid.HybridError:
            pass
        held.append(ctrl.path_task["phase"])
    np.testing.assert_array_equal(phases(res), held)


def test_a_path_task_on_the_planar_arm_is_refused_for_what_it_is():
    with pytest.raises(hybrid.HybridError, match="planar arm"):
        hybrid.paper_experiment(path_task=hybrid.PathTask(short_raster()))
