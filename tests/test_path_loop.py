"""Path tasks in the compiled closed loop: a run there against the Python runner (the Controller calling the
generated follower each sample), runs of different paths side by side as SIMD lanes, a sweep of a path task,
and a sensor's dropout (a refused sample changes nothing of the follower's)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hybrid
from hybrid.simulation import closed_loop
from hybrid.spec.metrics import PATH_METRICS

PLANE = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
PILLAR = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)


def raster(passes: int = 3, length: float = 0.08, origin=(0.45, -0.05, 0.1)) -> hybrid.RasterPath:
    return hybrid.RasterPath(PLANE, PLANE.project(np.array(origin)), (1.0, 0.0, 0.0), length, 0.01, passes)


def on_plane(**task) -> hybrid.Experiment:
    """A whole task on the plane: approach, three passes, release and retreat."""
    task = {"speed": 0.1, "force": 10.0, "retreat_distance": 0.01, **task}
    return hybrid.tracing_experiment(surface=PLANE, path_task=hybrid.PathTask(raster(), **task), duration=3.5)


def tilted_panda() -> hybrid.Experiment:
    """The Panda on six axes with its posture, the tool tilted and led along waypoints on a pillar."""
    points = [PILLAR.project(np.array(p)) for p in [(0.42, 0.0, 0.78), (0.43, -0.05, 0.80), (0.45, -0.1, 0.76)]]
    task = hybrid.PathTask(hybrid.WaypointPath(PILLAR, points), speed=0.05, tilt=0.1, lead=-0.2)
    return hybrid.panda_experiment(path_task=task, duration=1.5)


CASES = {
    "raster on a plane, whole task": on_plane,
    "spiral on the sphere, friction": lambda: hybrid.tracing_experiment(
        surface=SPHERE, contact=hybrid.Contact(friction=0.4), duration=2.0,
        path_task=hybrid.PathTask(hybrid.SpiralPath(SPHERE, SPHERE.project(np.array([0.45, 0.0, 0.4])), 0.01, 2.0,
                                                    start_radius=0.01), speed=0.08, force=lambda s: 8.0 + 40.0 * s)),
    "the Panda, tilted tool": tilted_panda,
}


def relative(a: np.ndarray, b: np.ndarray) -> float:
    """The largest difference of two records, each column against its own scale."""
    return float(np.max(np.abs(a - b) / (np.abs(b).max(axis=0) + 1e-3)))


@pytest.mark.filterwarnings("ignore::hybrid.JointLimitWarning")
@pytest.mark.parametrize("case", list(CASES))
def test_a_path_run_in_c_equals_the_python_runner(case):
    """The compiled loop follows the path as the Controller does (the same generated follower, fed the same
    measured tip, changing the same parameters): the same run within rounding, and the same metrics."""
    exp = CASES[case]()
    prepared = closed_loop.prepare(exp)
    assert prepared is not None and prepared.loop.path_task
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    # sample by sample: the Controller, given the compiled run's states and readings, gives its torques (its own
    # integrals and follower carried along: about 2e-12 of the largest torque where the frame turns with the path,
    # the measured tip's rounding in two builds reaching e)
    ctrl, plant, m = exp.build_controller(), exp.plant(), exp.steps_per_sample
    nq = plant.nq
    for k in range(exp.n_samples):
        x = compiled.state[k * m]
        tau = ctrl(k * exp.sample_time, x[:nq], x[nq:2 * nq], plant.sensor_wrench(x))
        assert np.abs(tau - compiled.tau[1 + k * m]).max() <= 1e-11 * max(1.0, np.abs(tau).max()), k
    # whole runs: the rounding of two builds (the loop's contracts into fused multiply-adds) grows along them
    assert relative(compiled.state, python.state) < 1e-8
    for name, value in python.metrics.items():
        assert compiled.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name
    assert {m.name for m in PATH_METRICS} <= compiled.metrics.keys()
    assert compiled.metrics["path_travelled_m"] > 0.02  # it moved along the path


def test_different_paths_run_side_by_side_as_lanes():
    """Nine runs of one loop (more than a group of lanes): other paths (each its own table, of another length),
    speeds, forces, retreats and a friction; each run is bitwise the same beside other neighbours, and equals its
    run alone within rounding."""
    exps = [on_plane(speed=v, force=f) for v in (0.05, 0.1, 0.15) for f in (6.0, 12.0)]
    exps += [hybrid.tracing_experiment(surface=PLANE, duration=3.0, path_task=hybrid.PathTask(
        raster(passes=p, length=0.05, origin=(0.42, -0.02, 0.1)), speed=0.08, retreat_distance=0.0))
        for p in (2, 4)]
    exps.append(on_plane(speed=0.1, force=10.0).__class__.from_dict(
        {**on_plane().to_dict(), "contact": {**on_plane().to_dict()["contact"], "friction": 0.45}}))
    prepared = [closed_loop.prepare(e) for e in exps]
    assert len({id(p.loop) for p in prepared}) == 1
    together = closed_loop.run(prepared, record=True)
    reordered = closed_loop.run(prepared[::-1], record=True)[::-1]
    lengths = set()
    for i, p in enumerate(prepared):
        lengths.add(len(p.tables[0]))  # the path table: its only one
        assert together[i].status == 0
        np.testing.assert_array_equal(reordered[i].states, together[i].states)
        assert reordered[i].metrics == pytest.approx(together[i].metrics, rel=0, abs=0, nan_ok=True)
        alone = closed_loop.run([p], record=True)[0]
        assert relative(together[i].states, alone.states) < 1e-11
        for name, value in alone.metrics.items():
            assert together[i].metrics[name] == pytest.approx(value, rel=1e-9, abs=1e-12, nan_ok=True), name
    assert len(lengths) >= 3
    # the runs differ as their tasks do: a slower task travels less in the same time
    assert together[0].metrics["path_travelled_m"] < together[4].metrics["path_travelled_m"]


def test_a_sweep_of_a_path_task_gives_its_path_metrics():
    exp = on_plane()
    frame = hybrid.sweep(exp, {"contact.friction": [0.1, 0.4], "model_error": [0.0, 0.2]}, workers=1)
    assert (frame["status"] == "ok").all()
    for _, row in frame.iterrows():
        run = hybrid.simulate(hybrid.sweeps.apply(exp, {"contact.friction": row["contact.friction"],
                                                        "model_error": row["model_error"]}))
        for m in PATH_METRICS:
            assert row[m.name] == pytest.approx(run.metrics[m.name], rel=1e-9, abs=1e-12, nan_ok=True), m.name
    assert frame["path_error_rms_m"].max() <= 1e-3


def test_a_dropout_during_a_path_is_a_refused_sample_in_c_as_in_python():
    """The reading lost for 30 ms in the middle of a pass: the follower refuses those samples (its force is not a
    number) and the law holds its torque, alike in the compiled loop and the Controller; the task goes on."""
    base = on_plane()
    exp = base.__class__.from_dict({**base.to_dict(), "sensor": {**base.to_dict()["sensor"], "dropout_at": 1.5,
                                                                 "dropout_duration": 0.03}})
    assert closed_loop.prepare(exp) is not None
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    assert relative(compiled.state, python.state) < 1e-8
    for name, value in python.metrics.items():
        assert compiled.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name
    assert compiled.metrics["path_error_rms_m"] <= 1e-3
    assert not math.isnan(compiled.metrics["path_time_s"])


def test_refused_samples_along_a_path_run_alike_in_c_and_in_python():
    """On a spiral the follower turns ``e`` at every sample; where the law refuses a sample (the Jacobian's
    conditioning below ``singular_tol``: a threshold among the run's own lowest values), a run that reacts to
    faults holds its torque, its follower stays where it was and what it changed is undone (the next sample
    sets it afresh), alike in the compiled loop and the Controller."""
    spiral = hybrid.SpiralPath(SPHERE, SPHERE.project(np.array([0.45, 0.0, 0.4])), 0.01, 2.0, start_radius=0.01)
    task = hybrid.PathTask(spiral, speed=0.08)
    free = hybrid.tracing_experiment(surface=SPHERE, path_task=task, duration=1.0)
    plant, m, nq = free.plant(), free.steps_per_sample, free.robot.n
    run = hybrid.simulate(free)
    conditioning = np.array([float(plant.conditioning(run.state[k * m, :nq])) for k in range(free.n_samples)])
    assert conditioning[0] > np.percentile(conditioning, 5)  # the start is served
    tolerant = hybrid.tracing_experiment(surface=SPHERE, path_task=task, duration=1.0,
                                         singular_tol=float(np.percentile(conditioning, 5)),
                                         fault_reaction=hybrid.FaultReaction(fault_samples=10 ** 6))
    d = tolerant.to_dict()  # a dropout after the run's end: the run reacts to faults, and loses no reading
    exp = tolerant.__class__.from_dict({**d, "sensor": {**d["sensor"], "dropout_at": 50.0, "dropout_duration": 0.01}})
    compiled, python = hybrid.simulate(exp), hybrid.simulate(exp, compiled=False)
    torques = compiled.tau[1::m]
    held = np.all(torques[1:] == torques[:-1], axis=1)
    assert held.sum() >= 2  # refused samples, each holding the torque last written
    assert relative(compiled.state, python.state) < 1e-8
    for name, value in python.metrics.items():
        assert compiled.metrics[name] == pytest.approx(value, rel=1e-6, abs=1e-10, nan_ok=True), name
    assert not np.array_equal(compiled.state, run.state)  # the refusals changed the run
