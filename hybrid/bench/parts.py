"""Parts (:class:`hybrid.MeshSurface`): the fit of a finely tessellated part, the task frame and its rate on a part
in C against the same on the shape's formula (and their instructions a call, by callgrind where valgrind is
installed), the controller's sample on a part against the same on the formula, and the 3-D run on a part in the
compiled loop against the run on the formula."""

from __future__ import annotations

import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from hybrid.bench import pinocchio_codegen as pc
from hybrid.bench.eigen_race import compile_object, inclusive
from hybrid.bench.harness import WARM_UP, c_program_ns, harness_source, median_ns
from hybrid.bench.targets import PART_FIT, PART_FRAME, PART_RUN, PART_SAMPLE
from hybrid.bench.templates import render
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.parts import MeshSurface
from hybrid.geometry.surfaces import Sphere
from hybrid.native import compiler, loader, units
from hybrid.simulation.runner import simulate

#: the shape the part is a mesh of (the tracing experiment's sphere)
CENTRE, RADIUS = np.array([0.5, 0.0, 0.2]), 0.15


def sphere_mesh(subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    """An icosphere's vertices and faces (20 * 4**subdivisions facets) on the sphere."""
    import trimesh

    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=RADIUS)
    return np.asarray(mesh.vertices) + CENTRE, np.asarray(mesh.faces)


def torus_mesh() -> tuple[np.ndarray, np.ndarray]:
    """A torus of radii 15 and 5 cm about the sphere's centre in 102,400 facets (2.9 by 2.0 mm): the part of
    more than 100,000 facets whose fit the bench times."""
    import trimesh

    mesh = trimesh.creation.torus(major_radius=RADIUS, minor_radius=0.05, major_sections=320, minor_sections=160)
    return np.asarray(mesh.vertices) + CENTRE, np.asarray(mesh.faces)


def part_benchmarks(quick: bool, add) -> None:
    """The fit of a torus tessellated in 102,400 facets at a spacing of 6 mm; the task frame on the
    5.7 mm mesh (20,480 facets) in C against the sphere's; the UR5 controller's sample on the mesh against the
    sphere's; its 3 s run in the compiled loop against the sphere's."""
    vertices, faces = torus_mesh()
    t0 = time.perf_counter()
    MeshSurface(vertices, faces, spacing=0.006)
    fit = time.perf_counter() - t0
    add(PART_FIT, fit, "s", ratio=f"{len(faces):,} facets, a grid of 6 mm, a band of 3 cm")
    part = MeshSurface(*sphere_mesh(5), spacing=0.006)
    sphere = Sphere(tuple(CENTRE), RADIUS)
    start = tuple(sphere.project(np.array([0.5, -0.05, 0.35])))
    frames = frame_ns(part, sphere, np.array(start), quick)
    counted = "" if "part_instructions" not in frames else (
        f"; instructions a call {frames['part_instructions']:,.0f} (the frame {frames['quadric_instructions']:,.0f}, "
        f"the expansion and the loop {frames['part_instructions'] - frames['quadric_instructions']:,.0f}) against "
        f"{frames['sphere_instructions']:,.0f}")
    add(PART_FRAME, frames["part"], "ns", of_formula=frames["part"] / frames["sphere"],
        instructions=frames.get("part_instructions"), sphere_instructions=frames.get("sphere_instructions"),
        frame_instructions=frames.get("quadric_instructions"),
        ratio=f"{frames['part'] / frames['sphere']:.2f}x the frame on the sphere in C ({frames['sphere']:.0f} ns; "
              f"{frames['low']:.2f}-{frames['high']:.2f}x in {frames['rounds']} rounds taking turns)" + counted)
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
    expansion about ``p`` by ``hybrid_part.h``, then the quadric's frame) and on the ``sphere``'s formula;
    each the median of rounds taking turns (``rounds``; ``low``, ``high``: the rounds' least and greatest
    ratio of the part's to the sphere's); and their instructions a call by callgrind where valgrind is
    installed (``part_instructions``, ``sphere_instructions``; ``quadric_instructions``: the part's frame
    alone, the rest its expansion and the loop)."""
    pd, e = np.array([0.05, 0.02, 0.0]), np.array([0.0, 0.0, 1.0])
    calls, repeat = (20_000, 5) if quick else (200_000, 5)
    unit = units.frame_unit(sphere.spec())
    formula = harness_source(unit.manifest["unit"], unit.entry("task_frame"),
                             {"p": p, "pd": pd, "surface": sphere.as_array(), "e": e})
    sides = {"sphere": (formula, unit, ())}
    unit = units.frame_unit(part.spec())
    quadric = unit.entry("task_frame")["symbol"]
    source = render("part_frame.c.j2", prefix=unit.manifest["unit"], symbol=quadric,
                    p=[repr(float(x)) for x in p], pd=[repr(float(x)) for x in pd], e=[repr(float(x)) for x in e])
    data = np.concatenate(part.data())
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "part.bin"
        path.write_bytes(np.int64(len(data)).tobytes() + data.astype(float).tobytes())
        sides["part"] = (source, unit, (str(path),))
        # the sides in turn, a few rounds (a shared machine's speed drifts within seconds): each side's median
        rounds = {name: [] for name in sides}
        for _ in range(1 if quick else 5):
            for name, (text, u, args) in sides.items():
                rounds[name].append(c_program_ns(text, u.folder, u.manifest["unit"], calls, repeat, *args,
                                                 include=(loader.source_dir(),)))
        times = {name: float(np.median(r)) for name, r in rounds.items()}
        each = np.array(rounds["part"]) / np.array(rounds["sphere"])
        times["rounds"], times["low"], times["high"] = len(each), float(each.min()), float(each.max())
        for name, (text, u, args) in sides.items():
            counts = instructions(text, u.folder / f"{u.manifest['unit']}.c", (u.folder, loader.source_dir()),
                                  args, ("main", quadric))
            if counts:
                times[f"{name}_instructions"] = counts["main"]
                if name == "part":
                    times["quadric_instructions"] = counts[quadric]
    return times


def instructions(source: str, unit_c: Path, include: tuple[Path, ...], args: tuple[str, ...],
                 functions: tuple[str, ...], calls: int = 20_000) -> dict[str, float]:
    """Instructions a call of the timing program ``source`` (with the unit's C ``unit_c``; its loop of ``calls``
    calls once, then ``args``) by callgrind: each of ``functions`` with its callees (``main``: the loop whole).
    Built for x86-64-v3 (valgrind runs no AVX-512; vectors of four either way); empty where valgrind is not
    installed or cannot run the program."""
    if not pc.can_count():
        return {}
    cc, ident = compiler.compiler()
    flags = [pc.COUNTED if f == pc.NATIVE else f for f in compiler.flags(ident) if f != "-fPIC"]
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "bench.c").write_text(source)
        command = [cc, *flags, *(f"-I{d}" for d in (*include, loader.source_dir()))]
        objects = [folder / "bench.o", folder / "unit.o"]
        for c_file, obj in zip((folder / "bench.c", unit_c), objects):
            compile_object(command, c_file, obj, True, "compiling a timing program to count its instructions")
        pc.run_tool([cc, *map(str, objects), "-o", str(folder / "bench"), "-lm"], "linking a timing program")
        profile = folder / "callgrind.out"
        counted = subprocess.run([shutil.which("valgrind"), "--tool=callgrind", f"--callgrind-out-file={profile}",
                                  str(folder / "bench"), str(calls), "1", *args], capture_output=True)
        if counted.returncode != 0:
            return {}
        report = subprocess.run([shutil.which("callgrind_annotate"), "--inclusive=yes", "--threshold=100",
                                 str(profile)], capture_output=True, text=True, check=True).stdout
    return {f: inclusive(report, f) / calls for f in functions}


def _sample_us(exp, quick: bool) -> float:
    """The median time [us] of ``exp``'s controller's sample at its start, time moving on."""
    ctrl, x0 = exp.build_controller(), exp.start_state()
    wrench = np.array([0.0, 0.0, 10.0])
    clock = iter(range(10 ** 9))
    return median_ns(lambda: ctrl(next(clock) * exp.sample_time, x0.q, x0.qdot, wrench), 200,
                     5 if quick else 15) / 1e3
