"""The 6-D decoupling law F* and the controller step written by hand in C++ on Pinocchio + Eigen
(``c/eigen_law.hpp``), built into one program (``c/eigen_race.cpp.j2``) beside our generated law,
controller step and robot terms, for a URDF arm on a sphere.

The hand-written side uses Pinocchio's headers alone (its algorithms are templates): Pinocchio's
compiled libraries are built for any x86-64, and a program built for this processor (AVX-512 where
present) aligns Eigen's fixed-size matrices differently, so it may not share their model. The arm's
model is read from the URDF here, by Pinocchio's Python bindings (the joints off the chain held at 0,
as :meth:`hybrid.Robot.from_urdf` does), and given to the program as numbers (:func:`model_numbers`),
which builds it joint by joint. Both sides are compiled with the flags our units are compiled with
(:func:`hybrid.native.compiler.flags`; C++17 and ``NDEBUG`` on the C++ side: Eigen's assertions off, as
in any release build), ours by the C compiler, the hand-written side by the C++ compiler, and linked
into one program.

Everything built is cached (:func:`hybrid.native.cache.entry`) under a key of all it is built from: the
hand-written source and the program's, our units' C, the packages' versions, the compilers' identities,
the flags and the processor.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hybrid.bench import pinocchio_codegen as pc
from hybrid.bench.templates import FOLDER, render
from hybrid.errors import HybridError
from hybrid.native import compiler, generator, loader, units
from hybrid.native.cache import digest, entry, library_intact, once, write_checksum
from hybrid.spec.controller_step import CONTROLLER_STEP
from hybrid.spec.interfaces import Dims
from hybrid.validate import c_identifier

#: the hand-written law and step
HAND = FOLDER / "eigen_law.hpp"
#: the program that runs both sides
RACE = "eigen_race.cpp.j2"
#: a header of each package the hand-written side includes, under the install prefix's include/
HEADERS = (("pinocchio/algorithm/crba.hpp", "pin"), ("eigen3/Eigen/Core", "cmeel-eigen"),
           ("boost/version.hpp", "cmeel-boost"))
#: the packages whose versions shape the hand-written side
PACKAGES = ("libpinocchio", "cmeel-eigen", "cmeel-boost")
#: the joints the program builds, by their code (its ``joint_model``): Pinocchio's models' short names
JOINTS = ("JointModelRX", "JointModelRY", "JointModelRZ", "JointModelRevoluteUnaligned", "JointModelPX",
          "JointModelPY", "JointModelPZ", "JointModelPrismaticUnaligned")
#: the hand-written law's forms (eigen_law.hpp's ``Form``) by side: the operational-space form for any arm,
#: and for a square arm (six joints) the inverse-dynamics form, as our law takes there
FORMS = {"pinocchio": "OPERATIONAL", "pinocchio_rnea": "INVERSE_DYNAMICS"}
#: the functions raced
FUNCTIONS = ("law", "step")
#: the fixed inputs, in the order the program reads them: the law's ``opts`` and the singular tolerance,
#: then the step's parameters (their sizes from its interface)
CONFIG = ("robot", "surface", "e", "opts", "singular_tol", "steps", "gains", "selection", "options", "posture",
          "limits", "sensor", "fault")
#: the inputs of a state, in the order the program reads them: the law's acceleration and null-space torque,
#: and the step's per-sample inputs but its filter's, estimate's and desired point's (zero: none of them)
STATE = ("q", "qd", "a", "Fc", "tau0", "integrals", "last_torque", "t", "yd_extra", "yd_rate")
#: the outputs of each function, in the order the program prints them (after a status)
OUTPUTS = {"law": ("F", "tau"), "step": tuple(p.name for p in CONTROLLER_STEP.outputs)}
#: the heap wrapped at link time, to count its allocations
WRAPPED = ("malloc", "calloc", "realloc", "posix_memalign")


def missing() -> str | None:
    """Why the hand-written side cannot be built here (one line), or None when it can."""
    return pc.missing(HEADERS, ())


def sizes(n: int, n_robot: int, n_surface: int) -> dict[str, int]:
    """Every input's and output's size for an ``n``-joint arm with six task axes."""
    dims = Dims.sized([f"j{i}" for i in range(n)], ["axis"] * 6, n_robot, n_surface)
    out = {p.name: p.size_of(dims) for p in (*CONTROLLER_STEP.inputs, *CONTROLLER_STEP.outputs)}
    return {**out, "a": 6, "tau0": n, "opts": 1, "singular_tol": 1, "F": 6}


def pinocchio_model(robot, urdf: Path, tip: str):
    """Pinocchio's model of ``robot``'s chain in ``urdf`` (its joints off the chain held at 0, as
    :meth:`hybrid.Robot.from_urdf` holds them), read by Pinocchio's Python bindings, and the frame
    ``tip``'s index."""
    import pinocchio as pin

    model = pin.buildModelFromUrdf(str(urdf))
    extra = [model.getJointId(name) for name in model.names[1:] if name not in robot.joint_names]
    if extra:
        model = pin.buildReducedModel(model, extra, pin.neutral(model))
    if not model.existFrame(tip) or model.nq != robot.n or model.nv != robot.n:
        raise HybridError(f"{urdf}: Pinocchio's model of the chain to {tip!r} is not {robot.n} one-degree-of-freedom "
                          "joints with that frame; the comparison with Pinocchio + Eigen needs one")
    return model, model.getFrameId(tip)


def model_numbers(robot, urdf: Path, tip: str) -> list[float]:
    """The arm's Pinocchio model (:func:`pinocchio_model`) as the program reads it: per joint its code
    (:data:`JOINTS`), parent, placement (rotation row by row, translation), axis, mass, centre of mass and
    inertia (row by row); the tip frame's parent joint and placement; gravity; the joints' friction
    (``damping``, ``coulomb``, ``offset``, ``coulomb_speed``)."""
    model, frame_id = pinocchio_model(robot, urdf, tip)
    numbers: list[float] = []

    def placement(M):
        numbers.extend([*np.asarray(M.rotation).ravel(), *np.asarray(M.translation)])

    for j in range(1, model.njoints):
        joint = model.joints[j]
        if joint.shortname() not in JOINTS:
            raise HybridError(f"{urdf}: joint {model.names[j]!r} is a {joint.shortname()}; the comparison with "
                              f"Pinocchio + Eigen builds {', '.join(JOINTS)} only")
        numbers += [JOINTS.index(joint.shortname()), model.parents[j]]
        placement(model.jointPlacements[j])
        numbers += list(getattr(joint.extract(), "axis", np.zeros(3)))
        inertia = model.inertias[j]
        numbers += [inertia.mass, *inertia.lever, *np.asarray(inertia.inertia).ravel()]
    frame = model.frames[frame_id]
    numbers.append(frame.parentJoint)
    placement(frame.placement)
    numbers += [*robot.gravity, *robot.damping, *robot.coulomb, *robot.offset, *robot.coulomb_speed]
    return [float(x) for x in numbers]


def _text(values) -> str:
    return " ".join(f"{float(x):.17g}" for x in np.ravel(values))


@dataclass(frozen=True)
class EigenRace:
    """A robot's program (:func:`race`): its joints, sides (``ours`` first), model numbers and sizes."""

    program: Path
    n: int
    sides: tuple[str, ...]
    model: tuple[float, ...]
    size: dict

    def _input(self, config: dict, tail: str) -> str:
        """The program's standard input: the model, the fixed inputs ``config``, then ``tail``."""
        return _text(self.model) + "\n" + "\n".join(_text(config[k]) for k in CONFIG) + "\n" + tail

    def _run(self, config: dict, tail: str, *args: str) -> str:
        return subprocess.run([str(self.program), *args], input=self._input(config, tail), capture_output=True,
                              text=True, check=True).stdout

    def _state(self, state: dict) -> str:
        return "\n".join(_text(state[k]) for k in STATE) + "\n"

    def evaluate(self, config: dict, states: list[dict]) -> dict[tuple[str, str], tuple[np.ndarray, dict]]:
        """Each function's status and outputs on every side for ``states`` (dicts of :data:`STATE`), with the
        fixed inputs ``config`` (a dict of :data:`CONFIG`): ``(statuses, {output: rows})`` by
        ``(function, side)``."""
        text = f"{len(states)}\n" + "".join(self._state(s) for s in states)
        values = np.array(self._run(config, text, "check").split(), float)
        widths = {f: 1 + sum(self.size[o] for o in OUTPUTS[f]) for f in FUNCTIONS}
        per_state = values.reshape(len(states), len(self.sides) * sum(widths.values()))
        found, at = {}, 0
        for function in FUNCTIONS:
            for side in self.sides:
                block, at = per_state[:, at:at + widths[function]], at + widths[function]
                outputs, k = {}, 1
                for name in OUTPUTS[function]:
                    outputs[name], k = block[:, k:k + self.size[name]], k + self.size[name]
                found[function, side] = (block[:, 0].astype(int), outputs)
        return found

    def time(self, config: dict, state: dict, calls: int, repeat: int) -> dict[tuple[str, str], list[float]]:
        """Per-call times [ns] of each function and side, ``repeat`` runs of ``calls`` calls each, the sides
        one after the other (which goes first rotates)."""
        times: dict[tuple[str, str], list[float]] = {}
        for line in self._run(config, self._state(state), "time", str(calls), str(repeat)).splitlines():
            function, side, ns = line.split()
            times.setdefault((function, side), []).append(float(ns))
        return times

    def allocations(self, config: dict, state: dict, calls: int = 100) -> dict[tuple[str, str], int]:
        """The heap allocations of ``calls`` calls of each hand-written function and side."""
        out = self._run(config, self._state(state), "alloc", str(calls))
        return {(f, side): int(k) for f, side, k in (line.split() for line in out.splitlines())}

    def instructions(self, config: dict, state: dict, name: str, calls: int = 1000) -> dict[str, float]:
        """Instructions per call of the program's function ``name`` alone (``law_ours``, ``step_pinocchio``,
        ``terms_ours``, ...) by callgrind: ``"total"``, the hand-written parts (``hand::kinematics``, ...;
        their callees included), and ``"libm"`` (the maths library's own instructions: sine, cosine,
        tanh ...). Empty where valgrind is not installed (:func:`hybrid.bench.pinocchio_codegen.can_count`)
        or cannot run the program."""
        if not pc.can_count():
            return {}
        with tempfile.TemporaryDirectory() as tmp:
            profile = Path(tmp) / "callgrind.out"
            counted = subprocess.run([shutil.which("valgrind"), "--tool=callgrind", f"--callgrind-out-file={profile}",
                                      str(self.program), "count", name, str(calls)],
                                     input=self._input(config, self._state(state)),
                                     capture_output=True, text=True)
            if counted.returncode != 0:
                return {}
            annotate = [shutil.which("callgrind_annotate"), "--threshold=100", str(profile)]
            report_inclusive = subprocess.run([*annotate[:1], "--inclusive=yes", *annotate[1:]],
                                              capture_output=True, text=True, check=True).stdout
            exclusive = subprocess.run(annotate, capture_output=True, text=True, check=True).stdout
        counts = {"total": inclusive(report_inclusive, "timed") / calls,
                  "libm": sum(count for count, _, where in _rows(exclusive) if "libm" in where) / calls}
        for count, function, _ in _rows(report_inclusive):
            part = re.search(r"\bhand::(\w+)", function)
            if part and part[1] in PARTS:
                counts[part[1]] = counts.get(part[1], 0.0) + count / calls
        return counts


#: the hand-written parts (eigen_law.hpp's functions that are never inlined)
PARTS = ("kinematics", "dynamics", "sphere_frame", "operational", "inverse_dynamics", "conditioning", "loops",
         "limits")


def _rows(report: str):
    """``(instructions, function, object)`` of each function's line of a callgrind_annotate report."""
    for line in report.splitlines():
        found = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+[^:\s]*:(.*?)(?: \[([^\]]*)\])?$", line)
        if found:
            yield int(found[1].replace(",", "")), found[2], found[3] or ""


def inclusive(report: str, function: str) -> float:
    """The instructions of ``function`` (a name, or a C++ function's name before its arguments) and its
    callees."""
    return sum(count for count, name, _ in _rows(report) if re.match(rf"(\w+ )?{function}\b", name))


# ------------------------------------------------------------------ the program


def cxx_flags(c_flags: tuple[str, ...] | list[str]) -> list[str]:
    """The C++ side's flags from our C flags: C++17 for C99, a program (no ``-fPIC``), ``NDEBUG`` (Eigen's
    assertions off, as any release build has them), Pinocchio's headers' definitions and include folders."""
    root = pc.prefix()
    inc = root / "include"
    flags = [("-std=gnu++17" if f.startswith("-std=") else f) for f in c_flags if f != "-fPIC"]
    return [*flags, "-DNDEBUG", "-w", *(f"-D{d}" for d in pc.definitions(root, ("pinocchio_headers",))),
            f"-I{inc}", f"-I{inc / 'eigen3'}", f"-I{FOLDER}"]


def race(robot, urdf: Path, tip: str, spec, counted: bool = False) -> EigenRace:
    """The program that runs our generated law, step and terms of ``robot`` (read from ``urdf`` to ``tip``)
    on the surface ``spec`` (a sphere's), six task axes, beside the hand-written ones (:data:`FORMS`: both
    forms for a six-joint arm, the operational-space one for others), built (cached; the C++ side takes
    minutes). With ``counted``, the build whose instructions callgrind can count: for AVX2 rather than
    this processor (valgrind runs no AVX-512), else the same."""
    if spec.kind != "sphere":
        raise HybridError(f"the hand-written law's task frame is a sphere's, not a {spec.kind}'s")
    axes = tuple(range(6))
    built = (units.law_unit(robot.chain, robot.name, spec, axes),
             units.controller_unit(robot.chain, robot.name, spec, axes), robot.unit)
    prefixes = [u.manifest["unit"] for u in built]
    sides = ("ours", "pinocchio", "pinocchio_rnea") if robot.n == 6 else ("ours", "pinocchio")
    size = sizes(robot.n, len(robot.as_array()), len(spec.parameters))
    source = render(RACE, law=prefixes[0], step=prefixes[1], terms=prefixes[2], n=robot.n,
                    config=[(k, size[k]) for k in CONFIG], state=[(k, size[k]) for k in STATE],
                    sides=[{"name": s, "form": FORMS.get(s)} for s in sides])
    cc, ident = compiler.compiler()
    c_flags = [pc.COUNTED if counted and f == pc.NATIVE else f for f in compiler.flags(ident) if f != "-fPIC"]
    includes = [f"-I{loader.source_dir()}", *(f"-I{u.folder}" for u in built)]
    hand = _hand_object(source, [u.folder / f"{p}.h" for u, p in zip(built, prefixes)], includes, counted)
    ours = [u.folder / f"{p}.c" for u, p in zip(built, prefixes)]
    material = json.dumps({
        "hand": digest(hand.read_bytes()), "ours": [digest(p.read_bytes()) for p in ours],
        "lanes": digest(loader.source_dir().joinpath(generator.LANES_HEADER).read_bytes()), "cc": [cc, ident],
        "flags": c_flags, "processor": compiler.processor(), "vex3": counted and _MOVQ.pattern}, sort_keys=True)
    _, folder = entry(f"eigen_race_{c_identifier(robot.name)}", material)
    program, record = folder / "race", folder / "race.json"

    def make():
        objects = []
        for c_file in ours:
            objects.append(folder / f"{c_file.stem}.o")
            compile_object([cc, *c_flags, *includes], c_file, objects[-1], counted, "compiling our generated C")
        pc.run_tool([pc.cxx(), str(hand), *map(str, objects), "-o", str(program),
                     "-Wl," + ",".join(f"--wrap={f}" for f in WRAPPED), "-lm"], "linking the Pinocchio + Eigen race")
        write_checksum(record, digest(program.read_bytes()))

    once(folder, lambda: library_intact(program, record), make)
    return EigenRace(program, robot.n, sides, tuple(model_numbers(robot, urdf, tip)), size)


def _hand_object(source: str, headers: list[Path], includes: list[str], counted: bool) -> Path:
    """The program's C++ side (``source``, the hand-written law and step in it) compiled, cached apart from our
    C: keyed by the sources, our headers' declarations (not their first line, which fingerprints the C they
    declare), the C++ compiler, its flags and the packages' versions; a change of our generated code alone
    does not rebuild it."""
    cpp = pc.cxx()
    flags = cxx_flags([pc.COUNTED if counted and f == pc.NATIVE else f for f in compiler.flags(pc.identity(cpp))])
    flags += ["-DHAND_COUNTED"] if counted else []  # the parts apart, to be counted apart
    declared = [digest(h.read_bytes().split(b"\n", 1)[1]) for h in headers]
    material = json.dumps({
        "hand": digest(HAND.read_bytes()), "race": digest(source.encode()), "headers": declared,
        "cxx": [cpp, pc.identity(cpp)], "flags": flags, "versions": {p: pc.package_version(p) for p in PACKAGES},
        "processor": compiler.processor(), "vex3": counted and _MOVQ.pattern}, sort_keys=True)
    _, folder = entry("eigen_hand", material)
    obj, record = folder / "race.o", folder / "race.o.json"

    def make():
        (folder / "race.cpp").write_text(source)
        # minutes: Pinocchio's algorithms are templates compiled here
        compile_object([cpp, *flags, *includes], folder / "race.cpp", obj, counted,
                       "compiling the law written on Pinocchio + Eigen")
        write_checksum(record, digest(obj.read_bytes()))

    once(folder, lambda: library_intact(obj, record), make)
    return obj


#: a move between vector registers of one quadword (``vmovq %xmmA, %xmmB``) in the compiler's assembly
_MOVQ = re.compile(r"^(\s*)(vmovq\s+%xmm\d+,\s*%xmm\d+\s*)$", re.M)


def compile_object(command: list[str], source: Path, obj: Path, counted: bool, what: str) -> None:
    """``source`` compiled to the object ``obj`` by ``command`` (the compiler and its flags). For ``counted``
    through its assembly, each register-to-register ``vmovq`` given the three-byte VEX prefix: the
    assembler otherwise encodes it by its store form where the source is xmm8-15, which valgrind 3.19
    cannot decode (the program dies of SIGILL under callgrind); the instruction is the same."""
    if not counted:
        pc.run_tool([*command, "-c", str(source), "-o", str(obj)], what)
        return
    assembly = obj.with_suffix(".s")
    pc.run_tool([*command, "-S", str(source), "-o", str(assembly)], what)
    assembly.write_text(_MOVQ.sub(r"\1{vex3} \2", assembly.read_text()))
    pc.run_tool([command[0], "-c", str(assembly), "-o", str(obj)], f"{what} (assembling)")
