"""Parts (:class:`hybrid.MeshSurface`): the fit of a finely tessellated part, the controller's sample on a part
against the same on the shape's formula, and the 3-D run on a part in the compiled loop against the run on the
formula."""

from __future__ import annotations

import time

import numpy as np

from hybrid.bench.harness import WARM_UP, median_ns
from hybrid.bench.targets import PART_FIT, PART_RUN, PART_SAMPLE
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.parts import MeshSurface
from hybrid.geometry.surfaces import Sphere
from hybrid.simulation.runner import simulate

#: the shape the part is a mesh of (the tracing experiment's sphere)
CENTRE, RADIUS = np.array([0.5, 0.0, 0.2]), 0.15


def sphere_mesh(subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    """An icosphere's vertices and faces (20 * 4**subdivisions facets) on the sphere."""
    import trimesh

    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=RADIUS)
    return np.asarray(mesh.vertices) + CENTRE, np.asarray(mesh.faces)


def part_benchmarks(quick: bool, add) -> None:
    """The fit of the sphere tessellated in 81,920 facets (2.8 mm) at a spacing of 6 mm; the UR5 controller's
    sample on the 5.7 mm mesh (20,480 facets) against the sphere's; its 3 s run in the compiled loop against the
    sphere's."""
    vertices, faces = sphere_mesh(6)
    t0 = time.perf_counter()
    MeshSurface(vertices, faces, spacing=0.006)
    fit = time.perf_counter() - t0
    add(PART_FIT, fit, "s", ratio=f"{len(faces):,} facets, a grid of 6 mm, a band of 3 cm")
    part = MeshSurface(*sphere_mesh(5), spacing=0.006)
    sphere = Sphere(tuple(CENTRE), RADIUS)
    start = tuple(sphere.project(np.array([0.5, -0.05, 0.35])))
    runs = {name: tracing_experiment(surface=s, start_point=start, duration=3.0)
            for name, s in (("part", part), ("sphere", sphere))}
    samples = {name: _sample_us(exp, quick) for name, exp in runs.items()}
    add(PART_SAMPLE, samples["part"], "us",
        ratio=f"{samples['part'] / samples['sphere']:.1f}x the sample on the sphere ({samples['sphere']:.1f} us)")
    times = {}
    for name, exp in runs.items():
        for _ in range(WARM_UP):
            simulate(exp)
        times[name] = median_ns(lambda e=exp: simulate(e), 1, 3 if quick else 7) / 1e6
    add(PART_RUN, times["part"], "ms",
        ratio=f"{times['part'] / times['sphere']:.2f}x the run on the sphere ({times['sphere']:.0f} ms)",
        of_formula=times["part"] / times["sphere"])


def _sample_us(exp, quick: bool) -> float:
    """The median time [us] of ``exp``'s controller's sample at its start, time moving on."""
    ctrl, x0 = exp.build_controller(), exp.start_state()
    wrench = np.array([0.0, 0.0, 10.0])
    clock = iter(range(10 ** 9))
    return median_ns(lambda: ctrl(next(clock) * exp.sample_time, x0.q, x0.qdot, wrench), 200,
                     5 if quick else 15) / 1e3
