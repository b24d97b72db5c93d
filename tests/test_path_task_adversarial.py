"""Path tasks (hybrid.PathTask) at settings away from the tuned ones: other surfaces and paths, speeds,
forces, friction, gains and node spacings, the Panda, the controller in a loop of one's own, and bad input.
"""

from __future__ import annotations

import dataclasses
import math
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import hybrid
from hybrid.control.path_task import PathFollower
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_SETTINGS

PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
LEVEL = hybrid.Plane((0.45, 0.0, 0.1), (0.0, 0.0, 1.0))
SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
CYLINDER = hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.6, 0.8), 0.1)
PILLAR = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)
OUT = {name: i for i, name in enumerate(PATH_OUTPUT)}


def raster(passes: int = 3, length: float = 0.08) -> hybrid.RasterPath:
    origin = PLANE.project(np.array([0.45, -0.05, 0.1]))
    return hybrid.RasterPath(PLANE, origin, (1.0, 0.0, 0.0), length, 0.01, passes)


def line(length: float = 0.2) -> hybrid.RasterPath:
    """A straight pass on the tilted plane."""
    return hybrid.RasterPath(PLANE, PLANE.project(np.array([0.3, -0.2, 0.1])), (0.0, 1.0, 0.0), length, 0.01, 1)


def distance(task: hybrid.PathTask, surface) -> float:
    return float(task.table(surface)[1][PATH_SETTINGS.index("distance")])


def run(task: hybrid.PathTask, surface, duration: float, **experiment):
    exp = hybrid.tracing_experiment(surface=surface, path_task=task, duration=duration, **experiment)
    return hybrid.simulate(exp)


def sensor_tip(res) -> np.ndarray:
    return res.outputs[:, [res.record["outputs"].index(c) for c in ("s_x", "s_y", "s_z")]]


# ---------------------------------------------------------------------------- other surfaces and paths

@pytest.mark.parametrize("case", ["cylinder along its axis", "implicit paraboloid", "level circle, 1.5 laps",
                                  "sphere's latitude circle, 1 lap", "closed waypoints, 2 laps"])
def test_other_surfaces_and_paths_are_followed(case):
    axis = np.array([0.0, 0.6, 0.8])
    side = np.array([0.6, 0.0, 0.0])
    paraboloid = hybrid.ImplicitSurface("z - 0.1 - 0.5*(x-0.45)**2 - 0.5*y**2", {})
    square = [(0.42, -0.03, 0.1), (0.48, -0.03, 0.1), (0.48, 0.03, 0.1), (0.42, 0.03, 0.1)]
    path, surface, duration, task, experiment = {
        "cylinder along its axis": (hybrid.WaypointPath(CYLINDER, [side - 0.05 * axis, side + 0.05 * axis]), CYLINDER,
                                    2.5, {}, {}),
        "implicit paraboloid": (hybrid.WaypointPath(paraboloid, [(0.4, -0.05, 0.10125), (0.45, 0.0, 0.1),
                                                                 (0.5, 0.05, 0.10125)]), paraboloid, 3.0, {}, {}),
        "level circle, 1.5 laps": (hybrid.CirclePath((0.45, 0.0, 0.1), 0.03), LEVEL, 5.0, dict(laps=1.5), {}),
        "sphere's latitude circle, 1 lap": (SPHERE.latitude_circle(60.0), SPHERE, 9.0, dict(laps=1.0), {}),
        "closed waypoints, 2 laps": (hybrid.WaypointPath(LEVEL, square, closed=True), LEVEL, 10.0, dict(laps=2.0), {}),
    }[case]
    task = hybrid.PathTask(path, **task)
    res = run(task, surface, duration, **experiment)
    m = res.metrics
    assert m["path_error_rms_m"] <= 1e-3 and m["path_error_max_m"] <= 2e-3
    assert m["path_force_rms_error_N"] <= 0.1
    assert m["path_travelled_m"] >= distance(task, surface) - 1e-3 and np.isfinite(m["path_time_s"])


@pytest.mark.parametrize("speed, acceleration, duration", [(0.01, 0.5, 22.0), (0.05, 0.5, 5.0), (0.3, 0.5, 2.5),
                                                           (0.5, 2.0, 1.5)])
def test_speeds_from_1_cm_to_half_a_metre_per_second_on_a_straight_pass(speed, acceleration, duration):
    path = line()
    res = run(hybrid.PathTask(path, speed=speed, acceleration=acceleration), PLANE, duration)
    m = res.metrics
    assert m["path_error_max_m"] <= 1e-3
    assert m["path_travelled_m"] >= path.length - 1e-3
    assert m["path_speed_rms_error_m_per_s"] <= 0.1 * speed + 0.01


@pytest.mark.parametrize("force, friction", [(1.0, 0.2), (10.0, 0.0), (10.0, 0.5), (30.0, 0.2)])
def test_forces_and_frictions_the_raster_takes(force, friction):
    contact = dataclasses.replace(hybrid.tracing_experiment().contact, friction=friction)
    path = raster()
    res = run(hybrid.PathTask(path, force=force), PLANE, 5.0, contact=contact)
    m = res.metrics
    assert m["path_error_rms_m"] <= 1.5e-3 and m["path_travelled_m"] >= path.length - 1e-3
    assert m["path_force_rms_error_N"] <= 0.05 * force + 0.05 and m["contact_losses"] == 0


@pytest.mark.parametrize("force, friction", [(40.0, 0.2), (10.0, 0.8)])
def test_the_metrics_follow_a_sensor_tip_that_trails_beyond_a_turn(force, friction):
    contact = dataclasses.replace(hybrid.tracing_experiment().contact, friction=friction)
    path = raster()
    res = run(hybrid.PathTask(path, force=force), PLANE, 5.0, contact=contact)
    end = path.point_at(path.length)
    assert np.linalg.norm(sensor_tip(res)[-1] - end) <= 3e-3  # the arm did reach the raster's end
    assert res.metrics["path_travelled_m"] >= path.length - 3e-3
    assert res.metrics["path_error_max_m"] <= 5e-3


@pytest.mark.parametrize("surface", ["level plane", "sphere's top"])
def test_a_path_where_the_normal_is_base_z_runs_without_a_frame_direction(surface):
    if surface == "level plane":
        path = hybrid.RasterPath(LEVEL, (0.4, -0.05, 0.1), (1.0, 0.0, 0.0), 0.08, 0.01, 3)
    else:
        top = SPHERE.project(np.array([0.5, 0.0, 0.4]))
        path = hybrid.WaypointPath(SPHERE, [top, SPHERE.project(np.array([0.55, 0.03, 0.4]))])
    res = run(hybrid.PathTask(path, speed=0.05), path.surface, 0.5)
    assert res.metrics["path_error_max_m"] <= 1e-3


def test_a_level_plane_runs_to_the_end_and_a_frame_direction_of_ones_own_is_refused():
    path = hybrid.RasterPath(LEVEL, (0.4, -0.05, 0.1), (1.0, 0.0, 0.0), 0.08, 0.01, 3)
    res = run(hybrid.PathTask(path), LEVEL, 4.0)
    assert res.metrics["path_error_max_m"] <= 1e-3
    assert res.metrics["path_travelled_m"] >= path.length - 1e-3
    with pytest.raises(hybrid.HybridError, match="leave frame_direction out"):
        run(hybrid.PathTask(path), LEVEL, 0.1, frame_direction=(1.0, 0.0, 0.0))


@pytest.mark.parametrize("surface", [LEVEL, SPHERE], ids=["plane", "sphere top"])
def test_a_spiral_from_its_centre(surface):
    center = surface.project(np.array([0.5, 0.0, 0.4])) if surface is SPHERE else (0.45, 0.0, 0.1)
    table, _ = hybrid.PathTask(hybrid.SpiralPath(surface, center, 0.01, 2.0, start_radius=0.0)).table(surface)
    assert np.isfinite(table).all()


def test_a_spiral_from_its_centre_is_taken_at_a_finer_spacing():
    table, settings = hybrid.PathTask(hybrid.SpiralPath(LEVEL, (0.45, 0.0, 0.1), 0.01, 2.0), spacing=1e-4).table(LEVEL)
    assert np.isfinite(table).all() and settings[PATH_SETTINGS.index("rows")] == len(table)


def test_a_coarse_spacing_on_a_raster_is_refused_naming_the_spacing():
    with pytest.raises(hybrid.HybridError, match="smaller spacing"):
        hybrid.PathTask(raster(), spacing=0.01).table(PLANE)


def test_a_fine_spacing_follows_as_the_default():
    res = run(hybrid.PathTask(raster(), spacing=1e-4), PLANE, 4.0)
    assert res.metrics["path_error_rms_m"] <= 1e-3 and res.metrics["path_error_max_m"] <= 2e-3


def test_a_path_with_a_cusp_is_refused():
    cusp = hybrid.WaypointPath(LEVEL, [(0.42, 0.0, 0.1), (0.45, 0.0, 0.1), (0.42, 0.0, 0.1)])
    with pytest.raises(hybrid.HybridError):
        hybrid.PathTask(cusp).table(LEVEL)


def test_very_short_paths_run_to_their_end():
    for end, speed in (((0.45005, 0.0, 0.1), 0.001), ((0.452, 0.0, 0.1), 0.02)):
        path = hybrid.WaypointPath(LEVEL, [(0.45, 0.0, 0.1), end])
        res = run(hybrid.PathTask(path, speed=speed), LEVEL, 1.0)
        assert res.metrics["path_error_max_m"] <= 2e-4 and np.isfinite(res.metrics["path_time_s"])


def test_a_path_out_of_reach_ends_in_a_hybrid_error():
    far = hybrid.WaypointPath(LEVEL, [(0.6, 0.0, 0.1), (1.5, 0.0, 0.1)])
    with pytest.raises(hybrid.HybridError):
        run(hybrid.PathTask(far, speed=0.2), LEVEL, 8.0)


# ---------------------------------------------------------------------------- gains

def test_cross_track_gain_zero_still_follows_within_3_mm():
    # the velocity loop's double integral on t2 alone holds the path (the correction halves the error)
    res = run(hybrid.PathTask(raster(), cross_track_gain=0.0), PLANE, 4.0)
    assert res.metrics["path_error_max_m"] <= 3e-3


def test_a_cross_track_gain_beyond_the_sample_rate_is_refused():
    with pytest.raises(hybrid.HybridError, match="cross_track_gain"):
        hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster(), cross_track_gain=200.0),
                                  sample_time=0.02, duration=1.0)
    with pytest.raises(hybrid.HybridError, match="cross_track_gain"):
        hybrid.Controller(hybrid.ur5(), PLANE, path_task=hybrid.PathTask(raster(), cross_track_gain=200.0),
                          sample_time=0.01)


# ---------------------------------------------------------------------------- the follower

@pytest.mark.parametrize("step", [0.002, 0.005, 0.01])
def test_the_progress_keeps_up_with_a_tip_moving_up_to_a_centimetre_a_sample(step):
    path = raster()
    follower = PathFollower(hybrid.PathTask(path), PLANE)
    for s in np.arange(0.0, path.length, step):
        out = follower.follow(path.point_at(s), np.zeros(3))
        follower.advance()
        assert abs(out[OUT["s"]] - s) <= 1e-4


def test_after_a_reset_mid_run_the_progress_finds_the_tip():
    path = raster()
    follower = PathFollower(hybrid.PathTask(path), PLANE)
    for s in (0.1, 0.15, 0.2, 0.25):
        follower.reset()
        out = follower.follow(path.point_at(s), np.zeros(3))
        assert out[OUT["path_error"]] <= 1e-4 and out[OUT["s"]] == pytest.approx(s, abs=1e-4)


def test_the_cross_track_correction_is_bounded():
    path = raster()
    task = hybrid.PathTask(path)
    follower = PathFollower(task, PLANE)
    n = np.asarray(PLANE.normal) / np.linalg.norm(PLANE.normal)
    out = follower.follow(path.point_at(0.0) + 0.05 * np.cross(n, path.tangent_at(0.0)), np.zeros(3))
    assert abs(out[OUT["lateral_speed"]]) <= task.speed


# ---------------------------------------------------------------------------- a loop of one's own

def test_nan_joints_in_a_hand_loop_end_in_the_safe_state_with_a_finite_torque():
    exp = hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster()), duration=0.5)
    ctrl = exp.build_controller()
    x0 = exp.initial_state()
    q, qd = x0[:6], x0[6:12]
    T = exp.sample_time
    ctrl(0.0, q, qd, np.zeros(3))
    before = ctrl._path_task.follower.state.copy()
    samples = ctrl.fault_reaction.fault_samples
    for k in range(1, samples):
        with pytest.raises(hybrid.HybridError) as refused:
            ctrl(k * T, np.full(6, np.nan), qd, np.zeros(3))
        assert np.isfinite(refused.value.torque).all()
    with pytest.raises(hybrid.SafeStopError) as stop:
        ctrl(samples * T, np.full(6, np.nan), qd, np.zeros(3))
    assert np.isfinite(stop.value.torque).all() and ctrl.stopped
    assert np.array_equal(ctrl._path_task.follower.state, before)  # the refused samples kept the progress
    ctrl.reset()
    assert np.isfinite(ctrl(1.0, q, qd, np.zeros(3))).all()


def test_late_and_backwards_samples_in_a_hand_loop():
    exp = hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster()), duration=0.5)
    ctrl = exp.build_controller()
    x0 = exp.initial_state()
    q, qd = x0[:6], x0[6:12]
    ctrl(0.0, q, qd, np.zeros(3))
    ctrl(0.01, q, qd, np.zeros(3))
    state = ctrl._path_task.follower.state.copy()
    with pytest.raises(hybrid.SampleTimingError):
        ctrl(0.005, q, qd, np.zeros(3))  # backwards: nothing advances
    assert np.array_equal(ctrl._path_task.follower.state, state)
    with pytest.raises(hybrid.SampleTimingError) as late:
        ctrl(0.05, q, qd, np.zeros(3))
    assert np.isfinite(late.value.torque).all()


# ---------------------------------------------------------------------------- the Panda

def test_the_panda_experiment_takes_a_path_task():
    circle = PILLAR.circle_at((0.42, 0.0, 0.78))
    hybrid.panda_experiment(path_task=hybrid.PathTask(circle, laps=0.1))


def test_the_panda_follows_a_path_on_its_pillar_on_all_six_axes():
    points = [PILLAR.project(np.array(p)) for p in [(0.42, 0.0, 0.78), (0.43, -0.05, 0.80), (0.45, -0.1, 0.76)]]
    path = hybrid.WaypointPath(PILLAR, points)
    task = hybrid.PathTask(path, speed=0.05)
    exp = hybrid.panda_experiment(path_task=task)
    res = hybrid.simulate(exp)
    m = res.metrics
    assert m["path_error_max_m"] <= 1e-3 and m["path_force_rms_error_N"] <= 0.1
    assert m["path_travelled_m"] >= path.length - 1e-3


# ---------------------------------------------------------------------------- bad input

def boom(s):
    raise ValueError("boom")


@pytest.mark.parametrize("name", ["speed", "force"])
@pytest.mark.parametrize("bad", [lambda s: float("nan"), lambda s: "abc", lambda s: None, boom],
                         ids=["nan", "string", "none", "raises"])
def test_a_profile_that_gives_no_number_is_refused_by_the_table(name, bad):
    with pytest.raises(hybrid.HybridError):
        hybrid.PathTask(raster(), **{name: bad}).table(PLANE)


@pytest.mark.parametrize("bad", [boom, lambda s: "abc", lambda s: None, lambda s: np.array([1.0, 2.0]),
                                 lambda s: "10"], ids=["raises", "string", "none", "array", "numeric string"])
def test_a_bad_force_function_is_refused_by_the_experiment(bad):
    with pytest.raises(hybrid.HybridError):
        hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster(), force=bad))


@pytest.mark.parametrize("surface", [None, "plane"])
def test_a_table_on_no_surface_is_refused(surface):
    with pytest.raises(hybrid.HybridError):
        hybrid.PathTask(raster()).table(surface)


def test_a_spacing_that_asks_a_billion_nodes_is_refused_before_allocating():
    code = textwrap.dedent("""
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (3 * 2**30, 3 * 2**30))
        import numpy as np, hybrid
        plane = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
        path = hybrid.RasterPath(plane, plane.project(np.array([0.3, -0.2, 0.1])), (0.0, 1.0, 0.0), 0.4, 0.01, 1)
        try:
            hybrid.PathTask(path, spacing=1e-9).table(plane)
        except hybrid.HybridError:
            print("refused")
        except MemoryError:
            print("memory")
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.stdout.strip() == "refused", done.stdout + done.stderr[-500:]


def test_degenerate_numbers_are_refused():
    for bad in (dict(speed="0.1"), dict(speed=math.inf), dict(acceleration="1"), dict(laps=True), dict(spacing=True),
                dict(spacing=0.2), dict(speed_start=-1.0)):
        with pytest.raises(hybrid.HybridError):
            hybrid.PathTask(raster(), **bad)
    with pytest.raises(hybrid.HybridError, match="leave laps out"):
        hybrid.PathTask(raster(), laps=2.0).table(PLANE)
