"""Parts (:class:`hybrid.MeshSurface`): the fit of a finely tessellated part, the task frame and its rate on a part
in C against the same on the shape's formula, the controller's sample on a part against the same on the formula,
and the 3-D run on a part in the compiled loop against the run on the formula."""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np

from hybrid.bench.harness import WARM_UP, c_harness_ns, c_program_ns, median_ns
from hybrid.bench.targets import PART_FIT, PART_FRAME, PART_RUN, PART_SAMPLE
from hybrid.bench.templates import render
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.parts import MeshSurface
from hybrid.geometry.surfaces import Sphere
from hybrid.native import loader, units
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
    frames = frame_ns(part, sphere, np.array(start), quick)
    add(PART_FRAME, frames["part"], "ns", of_formula=frames["part"] / frames["sphere"],
        ratio=f"{frames['part'] / frames['sphere']:.2f}x the frame on the sphere in C ({frames['sphere']:.0f} ns)")
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


def frame_ns(part: MeshSurface, sphere: Sphere, p: np.ndarray, quick: bool) -> dict[str, float]:
    """The task frame ``R_L``, its rate and the normal at ``p`` in C, per call [ns]: on ``part`` (its phi's
    expansion about ``p`` by ``hybrid_part.h``, then the quadric's frame) and on the ``sphere``'s formula."""
    pd, e = np.array([0.05, 0.02, 0.0]), np.array([0.0, 0.0, 1.0])
    calls, repeat = (20_000, 5) if quick else (200_000, 11)
    unit = units.frame_unit(sphere.spec())
    entry = unit.entry("task_frame")
    formula = c_harness_ns(unit.folder, unit.manifest["unit"], entry,
                           {"p": p, "pd": pd, "surface": sphere.as_array(), "e": e}, calls, repeat)
    unit = units.frame_unit(part.spec())
    source = render("part_frame.c.j2", prefix=unit.manifest["unit"], symbol=unit.entry("task_frame")["symbol"],
                    p=[repr(float(x)) for x in p], pd=[repr(float(x)) for x in pd], e=[repr(float(x)) for x in e])
    data = np.concatenate(part.data())
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "part.bin"
        path.write_bytes(np.int64(len(data)).tobytes() + data.astype(float).tobytes())
        on_part = c_program_ns(source, unit.folder, unit.manifest["unit"], calls, repeat, str(path),
                               include=(loader.source_dir(),))
    return {"part": on_part, "sphere": formula}


def _sample_us(exp, quick: bool) -> float:
    """The median time [us] of ``exp``'s controller's sample at its start, time moving on."""
    ctrl, x0 = exp.build_controller(), exp.start_state()
    wrench = np.array([0.0, 0.0, 10.0])
    clock = iter(range(10 ** 9))
    return median_ns(lambda: ctrl(next(clock) * exp.sample_time, x0.q, x0.qdot, wrench), 200,
                     5 if quick else 15) / 1e3
