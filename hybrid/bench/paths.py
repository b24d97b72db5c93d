"""Path tasks (:class:`hybrid.PathTask`): the generated follower per call, the controller's sample with a
path task against one without, and a raster's run through ``simulate`` (the compiled closed loop, its
metrics from the follower replayed on the record)."""

from __future__ import annotations

import numpy as np

from hybrid.bench.harness import WARM_UP, median_ns
from hybrid.bench.targets import PATH_FOLLOW, PATH_RUN, PATH_SAMPLE
from hybrid.control.path_task import PathFollower, PathTask
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.patterns import RasterPath
from hybrid.geometry.surfaces import Plane
from hybrid.simulation.runner import simulate

#: the part and the raster the benchmarks follow (the tests' and the how-to's)
PLANE = Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))


def raster() -> RasterPath:
    """Three passes of 8 cm, 1 cm apart, on the tilted plane within the UR5's reach."""
    return RasterPath(PLANE, PLANE.project(np.array([0.45, -0.05, 0.1])), (1.0, 0.0, 0.0), 0.08, 0.01, 3)


def path_benchmarks(quick: bool, add) -> None:
    """The follower along the raster, one call from Python per point; the UR5 controller's sample at its
    start, with the path task and without (the same task, its references as numbers); the raster's run."""
    path = raster()
    task = PathTask(path, speed=0.1, force=10.0)
    follower = PathFollower(task, PLANE)
    points = path.points_at(np.linspace(0.0, path.length, 500))
    force = np.zeros(3)

    def follow_all():
        for p in points:
            follower.follow(p, force)
            follower.advance()
        follower.reset()
    per_call = median_ns(follow_all, 1, 3 if quick else 11) / len(points)
    add(PATH_FOLLOW, per_call / 1e3, "us", ratio=f"{len(follower.table)} nodes; the Python call around the C")
    exp = tracing_experiment(surface=PLANE, path_task=task, duration=4.0)
    plain = tracing_experiment(surface=PLANE, start_point=tuple(path.point_at(0.0)), force_reference=10.0,
                               speed_reference=0.1, frame_direction=exp.frame_direction)
    x0 = exp.start_state()
    wrench = np.array([0.0, 6.0, 8.0])
    samples = {name: _sample_us(e, x0, wrench, quick) for name, e in (("path", exp), ("plain", plain))}
    add(PATH_SAMPLE, samples["path"], "us",
        ratio=f"{samples['path'] / samples['plain']:.1f}x the sample without a path task ({samples['plain']:.1f} us)")
    for _ in range(WARM_UP):
        simulate(exp)
    run = median_ns(lambda: simulate(exp), 1, 3 if quick else 7) / 1e6
    python = median_ns(lambda: simulate(exp, compiled=False), 1, 3 if quick else 5) / 1e6
    add(PATH_RUN, run, "ms", ratio=f"{exp.n_samples} samples in the compiled loop; the Python runner {python:.0f} ms")


def _sample_us(exp, x0, wrench: np.ndarray, quick: bool) -> float:
    """The median time [us] of ``exp``'s controller's sample at the start state ``x0``, time moving on."""
    ctrl = exp.build_controller()
    clock = iter(range(10 ** 9))
    return median_ns(lambda: ctrl(next(clock) * exp.sample_time, x0.q, x0.qdot, wrench), 200,
                     3 if quick else 11) / 1e3
