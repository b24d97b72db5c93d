"""Pinocchio's own code generation (CppADCodeGen) for a URDF arm, built beside our generated dynamics.

The generator is a C++ program (``c/pinocchio_codegen.cpp``) compiled against the headers the ``pin``
wheel and the ``cmeel-*`` packages install (Pinocchio, CppAD, CppADCodeGen, Eigen, the URDF model's
headers) and linked with Pinocchio's URDF parser; Pinocchio's algorithms are templates, so a library
built for ``double`` serves the CppAD scalar as well. It writes the C of Pinocchio's RNEA, ABA and CRBA
code generators and of the same terms as our ``robot_terms``; that C is compiled into a shared library
with the flags our units are compiled with (:func:`hybrid.native.compiler.flags`), and so is our side
(the robot unit's C, and the unit of our CRBA alone: :func:`hybrid.native.units.inertia_unit`), and a
C program (``c/pinocchio_race.c.j2``) loads the two libraries side by side: it prints both sides'
outputs on given states, or times them alternately.

Everything built is cached (:func:`hybrid.native.cache.entry`) under a key of all it is built from: the
generator's source, the packages' versions and the compilers' identities (the generator), and the
URDF, the chain, both sides' C, the flags and the processor (a robot's libraries and program).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, replace
from functools import cache
from importlib.metadata import PackageNotFoundError, distribution, version
from pathlib import Path

import numpy as np

from hybrid.bench.templates import FOLDER, render
from hybrid.errors import HybridError
from hybrid.native import compiler, generator, loader, units
from hybrid.native.cache import digest, entry, library_intact, once, write_checksum
from hybrid.validate import c_identifier

#: the generator's source
GENERATOR = FOLDER / "pinocchio_codegen.cpp"
#: the C program that runs both sides
RACE = "pinocchio_race.c.j2"
#: Pinocchio's generated functions (the generator's names), in the order the program runs them
FUNCTIONS = ("rnea", "aba", "crba", "terms")
#: the sides, in the order the program prints their outputs: ours with the robot array given at run
#: time, ours with it compiled in (a constant model), Pinocchio's
SIDES = ("ours", "constant", "pinocchio")
#: a header of each package the generator needs, under the install prefix's include/, and the package
HEADERS = (("pinocchio/codegen/cppadcg-algo.hpp", "pin"), ("cppad/cppad.hpp", "cmeel-cppad"),
           ("cppad/cg.hpp", "cmeel-cppadcodegen"), ("eigen3/Eigen/Core", "cmeel-eigen"),
           ("urdfdom_headers/urdf_model/model.h", "cmeel-urdfdom-headers"), ("boost/version.hpp", "cmeel-boost"))
#: the packages whose versions shape the generator
PACKAGES = ("libpinocchio", "cmeel-cppad", "cmeel-cppadcodegen", "cmeel-eigen", "cmeel-urdfdom-headers", "cmeel-boost")
#: Pinocchio's CMake targets whose compile definitions a program including its headers and calling its
#: URDF parser takes (read from the installed package: they are its build's)
TARGETS = ("pinocchio_headers", "pinocchio_parsers")


def prefix() -> Path | None:
    """The install prefix of the ``pin`` wheel's C++ side (``site-packages/cmeel.prefix``); None without it."""
    try:
        return Path(distribution("libpinocchio").locate_file("cmeel.prefix"))
    except PackageNotFoundError:
        return None


def cxx() -> str | None:
    """The C++ compiler: ``$CXX`` when set, else ``g++``, else ``c++``."""
    named = os.environ.get("CXX", "").split()
    return shutil.which(named[0]) if named else (shutil.which("g++") or shutil.which("c++"))


def missing(headers: tuple[tuple[str, str], ...] = HEADERS,
            libraries: tuple[str, ...] = ("libpinocchio_parsers.so",)) -> str | None:
    """Why a program on Pinocchio's C++ side cannot be built here (one line), or None when it can: the
    ``headers`` (each with its package) under the install prefix's include/, the ``libraries`` under its
    lib/, a C++ compiler and our C compiler. By default, what Pinocchio's code generation needs."""
    root = prefix()
    if root is None:
        return "Pinocchio is not installed: pip install pin"
    for header, package in headers:
        if not (root / "include" / header).is_file():
            return f"no {header} (package {package}): pip install {package}"
    for library in libraries:
        if not (root / "lib" / library).is_file():
            return f"no Pinocchio library {library} under {root / 'lib'}"
    if cxx() is None:
        named = os.environ.get("CXX", "")
        return (f"$CXX={named!r} names no program: set CXX to a C++ compiler, or unset it" if named.strip() else
                "no C++ compiler (tried g++ and c++; $CXX is unset): install one, e.g. apt-get install g++")
    try:
        compiler.compiler()
    except HybridError as exc:
        return str(exc).splitlines()[0]
    return None


def definitions(root: Path, targets: tuple[str, ...] = TARGETS) -> list[str]:
    """The compile definitions of Pinocchio's ``targets``, from the installed package's CMake export."""
    text = (root / "lib" / "cmake" / "pinocchio" / "pinocchioTargets.cmake").read_text()
    found: list[str] = []
    for target in targets:
        block = re.search(rf"set_target_properties\(pinocchio::{target} .*?\n\)", text, re.S)
        line = re.search(r'INTERFACE_COMPILE_DEFINITIONS "([^"]*)"', block.group(0)) if block else None
        found += [d for d in (line.group(1).split(";") if line else ()) if d and not d.startswith("$<")]
    return list(dict.fromkeys(found))


def identity(cc: str) -> str:
    return subprocess.run([cc, "--version"], capture_output=True, text=True, check=True).stdout.splitlines()[0]


def run_tool(cmd: list[str], what: str) -> None:
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise HybridError(f"{what} failed\n$ {' '.join(cmd)}\n{proc.stderr[-4000:]}")


@cache
def generator_program() -> Path:
    """The generator, compiled (cached by its source, the packages' versions and the C++ compiler)."""
    root, cpp = prefix(), cxx()
    inc = root / "include"
    # no -march: Eigen's alignment of the model the URDF parser fills must be the library's (generic
    # x86-64); -O0 compiles fastest, and the program runs for well under a second
    flags = ["-std=c++17", "-O0", "-DNDEBUG", "-w", *(f"-D{d}" for d in definitions(root)),
             f"-I{inc}", f"-I{inc / 'eigen3'}", f"-I{inc / 'urdfdom'}", f"-I{inc / 'urdfdom_headers'}"]
    libs = [f"-L{root / 'lib'}", "-lpinocchio_parsers", "-lpinocchio_default", f"-Wl,-rpath,{root / 'lib'}"]
    material = json.dumps({"source": digest(GENERATOR.read_bytes()), "cxx": [cpp, identity(cpp)], "flags": flags,
                           "libs": libs, "versions": {p: package_version(p) for p in PACKAGES}}, sort_keys=True)
    _, folder = entry("pinocchio_codegen", material)
    program, record = folder / "pinocchio_codegen", folder / "pinocchio_codegen.json"

    def make():
        # minutes: Pinocchio's algorithms on CppAD's scalar are templates compiled here
        run_tool([cpp, *flags, str(GENERATOR), "-o", str(program), *libs], "compiling Pinocchio's code generator")
        write_checksum(record, digest(program.read_bytes()))

    once(folder, lambda: library_intact(program, record), make)
    return program


def package_version(package: str) -> str | None:
    try:
        return version(package)
    except PackageNotFoundError:
        return None


# ------------------------------------------------------------------ both sides, one program


@dataclass(frozen=True)
class Race:
    """A robot's sides built: the program that runs them, the joints, and our functions' symbols by
    side (``ours``, ``constant``) and Pinocchio's function's name."""

    program: Path
    n: int
    ours: dict[str, dict[str, str]]

    def outputs(self) -> dict[str, tuple[int, ...]]:
        """Each function's output sizes by side (:data:`SIDES`; Pinocchio's CRBA gives the upper triangle)."""
        n, terms = self.n, 3 + 9 + 7 * self.n + 6 + self.n * self.n
        return {"rnea": (n, n, n), "aba": (n, n, n), "crba": (n * n, n * n, n * (n + 1) // 2),
                "terms": (terms, terms, terms)}

    def evaluate(self, states: np.ndarray) -> dict[str, tuple[np.ndarray, ...]]:
        """Every side's outputs on ``states`` (rows ``(q, v, w)``: ``w`` is ``q''`` for RNEA, ``tau`` for
        forward dynamics), by function: one array per side of :data:`SIDES`, a row per state."""
        text = f"{len(states)}\n" + "\n".join(" ".join(f"{x:.17g}" for x in row) for row in states) + "\n"
        out = subprocess.run([str(self.program), "check"], input=text, capture_output=True, text=True, check=True)
        sizes = self.outputs()
        values = np.array(out.stdout.split(), float).reshape(len(states), sum(map(sum, sizes.values())))
        found, at = {}, 0
        for name, widths in sizes.items():
            found[name] = tuple(values[:, at + sum(widths[:k]):at + sum(widths[:k + 1])] for k in range(len(widths)))
            at += sum(widths)
        return found

    def time(self, calls: int, repeat: int) -> dict[tuple[str, str], list[float]]:
        """Per-call times [ns] of each function and side (:data:`SIDES`), ``repeat`` runs of ``calls`` calls
        each, the sides one after the other (which goes first rotates)."""
        out = subprocess.run([str(self.program), "time", str(calls), str(repeat)], capture_output=True, text=True,
                             check=True)
        times: dict[tuple[str, str], list[float]] = {}
        for line in out.stdout.splitlines():
            name, side, ns = line.split()
            times.setdefault((name, side), []).append(float(ns))
        return times

    def instructions(self, calls: int = 1000) -> dict[tuple[str, str], float]:
        """Instructions per call of each function and side, by callgrind (its callees, libm's sine and
        cosine, included); empty where valgrind is not installed (:func:`can_count`) or cannot run the
        program."""
        if not can_count():
            return {}
        with tempfile.TemporaryDirectory() as tmp:
            profile = Path(tmp) / "callgrind.out"
            counted = subprocess.run([shutil.which("valgrind"), "--tool=callgrind", f"--callgrind-out-file={profile}",
                                      str(self.program), "time", str(calls), "1"], capture_output=True)
            if counted.returncode != 0:
                return {}
            text = subprocess.run([shutil.which("callgrind_annotate"), "--inclusive=yes", "--threshold=100",
                                   str(profile)], capture_output=True, text=True, check=True).stdout
        counts = {}
        for line in text.splitlines():
            found = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+(\S+)", line)
            if found:
                counts[found.group(2).rsplit(":", 1)[-1]] = int(found.group(1).replace(",", ""))
        symbols = {**self.ours, "pinocchio": {f: f"{f}_forward_zero" for f in FUNCTIONS}}
        return {(f, side): counts[symbols[side][f]] / calls for f in FUNCTIONS for side in SIDES
                if symbols[side][f] in counts}


def can_count() -> bool:
    """Whether callgrind (valgrind's, and its report) is installed to count instructions."""
    return shutil.which("valgrind") is not None and shutil.which("callgrind_annotate") is not None


#: the processor flag that valgrind cannot run (AVX-512), and what the build for counting takes instead
NATIVE, COUNTED = "-march=native", "-march=x86-64-v3"


def race(robot, urdf: Path, tip: str, counted: bool = False) -> Race:
    """The program that runs our sides (:data:`SIDES`) and Pinocchio's generated side of ``robot`` (read
    from ``urdf`` to ``tip``), built (cached). Ours run with the joints' friction zero (Pinocchio's has
    none): given at run time, or compiled in, where the constant model folds it away. With
    ``counted``, the build whose instructions callgrind can count: for AVX2 rather than this processor
    (valgrind runs no AVX-512), else the same."""
    values = [float(x) for x in _frictionless(robot).as_array()]
    built = (robot.unit, units.inertia_unit(robot.chain, robot.name),
             units.constant_robot_unit(robot.chain, robot.name, values),
             units.constant_inertia_unit(robot.chain, robot.name, values))
    prefixes = [u.manifest["unit"] for u in built]
    source = render(RACE, unit=prefixes[0], inertia=prefixes[1], constant=prefixes[2], constant_inertia=prefixes[3],
                    n=robot.n, robot=values)
    cc, ident = compiler.compiler()
    flags = [COUNTED if counted and f == NATIVE else f for f in compiler.flags(ident)]
    ours = [u.folder / f"{p}.c" for u, p in zip(built, prefixes)]
    chain = list(robot.joint_names)
    gen = generator_program()
    material = json.dumps({
        "generator": digest(gen.read_bytes()), "urdf": digest(Path(urdf).read_bytes()), "tip": tip, "joints": chain,
        "ours": [digest(p.read_bytes()) for p in ours], "headers": digest(loader.source_dir().joinpath(
            generator.LANES_HEADER).read_bytes()), "race": digest(source.encode()), "cc": [cc, ident], "flags": flags,
        "processor": compiler.processor()}, sort_keys=True)
    _, folder = entry(f"pinocchio_race_{c_identifier(robot.name)}", material)
    program, record = folder / "race", folder / "race.json"
    libraries = [folder / "libhybrid_side.so", folder / "libpinocchio_side.so"]

    def make():
        sources = folder / "pinocchio"
        sources.mkdir(exist_ok=True)
        run_tool([str(gen), str(urdf), str(sources), tip, *chain], "Pinocchio's code generation")
        theirs = [sources / f"{f}_forward_zero.c" for f in FUNCTIONS]
        run_tool([cc, *flags, f"-I{loader.source_dir()}", "-shared", *map(str, ours), "-o", str(libraries[0]),
              "-lm"], "compiling our generated C")
        run_tool([cc, *flags, "-shared", *map(str, theirs), "-o", str(libraries[1]), "-lm"],
             "compiling Pinocchio's generated C")
        (folder / "race.c").write_text(source)
        run_tool([cc, *(f for f in flags if f != "-fPIC"), *(f"-I{u.folder}" for u in built), str(folder / "race.c"),
              "-o", str(program), f"-L{folder}", "-l:libhybrid_side.so",
              "-l:libpinocchio_side.so", f"-Wl,-rpath,{folder}", "-lm"], "compiling the race program")
        for p in libraries:  # each as the cache records a library: checked whole before the program loads it
            write_checksum(record_of(p), digest(p.read_bytes()))
        write_checksum(record, digest(program.read_bytes()))

    once(folder, lambda: library_intact(program, record)
         and all(library_intact(p, record_of(p)) for p in libraries), make)
    symbols = {side: {"rnea": f"{unit}_inverse_dynamics", "aba": f"{unit}_forward_dynamics",
                      "crba": f"{inertia}_inertia", "terms": f"{unit}_robot_terms"}
               for side, unit, inertia in (("ours", *prefixes[:2]), ("constant", *prefixes[2:]))}
    return Race(program, robot.n, symbols)


def record_of(library: Path) -> Path:
    """The file recording ``library``'s checksum (:func:`hybrid.native.cache.write_checksum`)."""
    return library.with_name(f"{library.name}.json")


def _frictionless(robot):
    """``robot`` with its joints' viscous and Coulomb friction and offsets zero."""
    zero = (0.0,) * robot.n
    return replace(robot, damping=zero, coulomb=zero, offset=zero)
