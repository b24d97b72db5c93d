"""Fail-safe generation and native builds: the names of generated files, the build cache's checksums, the
temporaries a killed run leaves, a compiler that writes nothing, and the memory a run's record needs."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

import hybrid
from hybrid.errors import HybridError

DATA = Path(__file__).parent / "data"
CC = shutil.which("gcc") or shutil.which("cc")
#: the headers of the C standard library (C11) and common POSIX ones: a generated ``<name>.h`` beside a
#: user's sources, built with -I., would hide each from every file that includes it
C_HEADERS = ("assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp signal stdalign "
             "stdarg stdatomic stdbool stddef stdint stdio stdlib stdnoreturn string tgmath threads time uchar "
             "wchar wctype unistd fcntl pthread dlfcn").split()


def urdf_named(tmp_path: Path, robot: str) -> Path:
    """The slider arm of tests/data as a URDF whose robot is named ``robot``."""
    path = tmp_path / "arm.urdf"
    text = (DATA / "slider_arm.urdf").read_text()
    path.write_text(text.replace('<robot name="slider_arm">', f'<robot name="{robot}">'), encoding="utf-8")
    return path


def generate(tmp_path: Path, robot: str = "slider_arm", name: str | None = None) -> list[Path]:
    from hybrid.native.standalone import generate

    return generate(urdf_named(tmp_path, robot), "tool", tmp_path / "out", name)


# ------------------------------------------------------------------ names


@pytest.mark.parametrize("name", [*C_HEADERS, "Math", "STDIO", "hybrid_lanes", "for", "int", "null", "a__b", "arm_",
                                  "x" * 49, "bras_à_ressort", "_x", "1st"])
def test_a_name_that_cannot_be_used_as_given_is_refused_and_nothing_written(tmp_path, name):
    with pytest.raises(HybridError) as info:
        generate(tmp_path, name=name)
    message = str(info.value)
    assert len(message.splitlines()) == 1 and "cannot name C symbols and files" in message and "e.g." in message
    assert not (tmp_path / "out").exists()


def test_a_system_header_name_is_what_the_check_refuses_and_would_hide_the_header(tmp_path):
    """The reason of the refusal, shown by a build: a ``math.h`` beside the sources, compiled with -I.,
    takes the place of the system's."""
    if CC is None:
        pytest.skip("no C compiler")
    (tmp_path / "math.h").write_text("#error the generated math.h, not the system's\n")
    (tmp_path / "main.c").write_text("#include <math.h>\nint main(void) { return (int)sqrt(4.0) - 2; }\n")
    proc = subprocess.run([CC, "-I.", "main.c", "-o", "main", "-lm"], cwd=tmp_path, capture_output=True, text=True)
    assert proc.returncode != 0 and "the generated math.h" in proc.stderr


def test_the_headers_the_generated_units_include_are_reserved():
    """The project's own header that the units include from the generated C's folder (the SIMD lanes') and
    those it and the generator's templates include by <...>."""
    import re

    from hybrid.native import generator, loader
    from hybrid.validate import c_name_problem

    lanes = loader.source_dir() / generator.LANES_HEADER
    own = {lanes.stem}
    texts = [lanes, *(p for p in (generator.sources()["codegen"] / "templates").iterdir() if p.is_file())]
    included = {m for p in texts for m in re.findall(r"#include <(\w+)\.h>", p.read_text())}
    assert own and "math" in included
    for stem in sorted(own | included):
        assert c_name_problem(stem) is not None, stem


def test_the_longest_name_is_used_exactly_as_given(tmp_path):
    name = "a" * 47 + "z"
    written = generate(tmp_path, name=name)
    assert sorted(p.name for p in written) == [f"{name}.c", f"{name}.h", f"{name}.json"]


@pytest.mark.parametrize("robot", ["math", "time", "for", "null", "arm__2", "arm_", "Roboter_ß", "Roboter_ä",
                                   "ロボット", "αβ", "_", "x" * 300, "y" * 48 + "ß"])
def test_every_derived_prefix_passes_the_one_check_and_casadi(robot):
    casadi = pytest.importorskip("casadi")
    from hybrid.validate import c_identifier, c_name_problem

    prefix = c_identifier(robot)
    assert c_name_problem(prefix) is None, prefix
    # CasADi's own rule for a generated unit's name (independent of ours)
    for name in (prefix, f"{prefix}_controller", f"{prefix}_plant"):
        assert casadi.Function.check_name(name), name
    assert c_identifier(robot) == prefix  # deterministic


@pytest.mark.parametrize("robot", ["Roboter_ß", "Roboter_ä", "ロボット", "math"])
def test_a_robot_name_that_is_no_c_name_gives_ascii_files_that_compile(tmp_path, robot):
    written = generate(tmp_path, robot)
    stems = {p.stem for p in written}
    assert len(stems) == 1 and all(p.name.isascii() and p.read_bytes().isascii() for p in written)
    (stem,) = stems
    assert stem.lower() not in C_HEADERS and not (tmp_path / "out" / f"{robot}.h").exists()
    if CC is not None:
        proc = subprocess.run([CC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-c", f"{stem}.c", "-o",
                               str(tmp_path / "x.o")], cwd=tmp_path / "out", capture_output=True, text=True)
        assert proc.returncode == 0, proc.stderr[:2000]
    shutil.rmtree(tmp_path / "out")
    assert {p.name for p in generate(tmp_path, robot)} == {p.name for p in written}  # the same name again


def test_a_user_name_is_refused_alike_by_the_controller_and_the_experiment(tmp_path):
    ctrl = hybrid.read_controller_config(Path(hybrid.__file__).parent / "data" / "controller_ur5_sphere.toml",
                                         hybrid.ur5())
    for generate_c in (ctrl.generate, hybrid.tracing_experiment().generate):
        for name, why in (("Roboter_ä", "non-ASCII"), ("stdlib", "hide the header"), ("z" * 49, "at most 48")):
            with pytest.raises(HybridError, match=why):
                generate_c(tmp_path / "out", name)
    assert not (tmp_path / "out").exists()


# ------------------------------------------------------------------ the cache's checksums

#: a run that loads the UR5's compiled unit (and its one-state entry point) and prints numbers of it
TERMS = ("import hybrid, numpy as np; t = hybrid.arm_terms(hybrid.ur5(), np.linspace(0.1, 0.6, 6), np.full(6, 0.2)); "
         "print(t['B'].tolist(), t['r'].tolist())")


def run_python(code: str, cache: Path, **env) -> subprocess.CompletedProcess:
    """``code`` run by a fresh interpreter with the cache in ``cache``: a crash cannot take pytest with it."""
    import os
    import sys

    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600,
                          env={**os.environ, "HYBRID_CACHE_DIR": str(cache), **env})


def cut(path: Path) -> None:
    """``path`` truncated to half its length, in place (what a full disk or a killed copy leaves)."""
    data = path.read_bytes()
    path.write_bytes(data[:len(data) // 2])


def test_a_damaged_cached_c_file_is_generated_again_not_copied(tmp_path, monkeypatch):
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    ctrl = hybrid.read_controller_config(Path(hybrid.__file__).parent / "data" / "controller_ur5_sphere.toml",
                                         hybrid.ur5())
    first = {p.name: p.read_bytes() for p in ctrl.generate(tmp_path / "first", "ur5s")}
    (cached,) = (tmp_path / "cache" / "units").glob("ur5s_*")
    for k, name in enumerate(sorted(first)):
        cut(cached / name)
        again = {p.name: p.read_bytes() for p in ctrl.generate(tmp_path / f"again{k}", "ur5s")}
        assert again == first, name
        assert (cached / name).read_bytes() == first[name]  # the entry itself is whole again


@pytest.mark.parametrize("forged", [False, True], ids=["checksum-differs", "checksum-forged"])
def test_a_damaged_cached_library_is_rebuilt_not_loaded(tmp_path, forged):
    """A library cut short is rebuilt, even when its manifest was rewritten to match it (the library is
    then refused for parts past its end): the run gives the same numbers, and nothing crashes."""
    import hashlib
    import json

    from hybrid.native.cache import library_intact

    cache = tmp_path / "cache"
    first = run_python(TERMS, cache)
    assert first.returncode == 0, first.stderr
    libraries = sorted(cache.glob("_*/*.so"))
    assert len(libraries) >= 2  # the unit and its one-state entry point
    for library in libraries:
        cut(library)
        if forged:
            manifest = library.parent / "manifest.json"
            record = json.loads(manifest.read_text())
            record["sha256"] = hashlib.sha256(library.read_bytes()).hexdigest()
            manifest.write_text(json.dumps(record))
        again = run_python(TERMS, cache)
        assert again.returncode == 0, f"{library.name}: exit {again.returncode}\n{again.stderr[-2000:]}"
        assert again.stdout == first.stdout
        assert library_intact(library, library.parent / "manifest.json")  # rebuilt in place


def test_a_damaged_cached_unit_file_is_generated_again(tmp_path):
    cache = tmp_path / "cache"
    first = run_python(TERMS, cache)
    assert first.returncode == 0, first.stderr
    (unit,) = (cache / "units").glob("hybrid_ur5_*")
    whole = {p.name: p.read_bytes() for p in unit.glob("hybrid_ur5.*")}
    assert len(whole) == 3
    for name in sorted(whole):
        cut(unit / name)
        again = run_python(TERMS, cache)
        assert again.returncode == 0 and again.stdout == first.stdout, again.stderr[-2000:]
        assert (unit / name).read_bytes() == whole[name]


def test_only_a_whole_elf_library_passes(tmp_path):
    from hybrid.native.cache import _whole_elf

    if CC is None or not hasattr(__import__("os"), "uname") or __import__("sys").platform == "darwin":
        pytest.skip("needs an ELF system and a C compiler")
    (tmp_path / "x.c").write_text("double twice(double x) { return 2 * x; }\n")
    subprocess.run([CC, "-shared", "-fPIC", "x.c", "-o", "x.so"], cwd=tmp_path, check=True)
    data = (tmp_path / "x.so").read_bytes()
    assert _whole_elf(data)
    for n in (0, 3, 40, 64, len(data) // 3, len(data) // 2, len(data) - 1):
        assert not _whole_elf(data[:n]), n


# ------------------------------------------------------------------ temporaries a killed run leaves

#: a process that starts writing the file argv[1] (or, with argv[2], building in its folder) and dies
#: before it can clean up: what SIGKILL leaves
DIES_WRITING = """
import os, sys
from pathlib import Path
from hybrid import files
target = Path(sys.argv[1])
if len(sys.argv) > 2:
    building = files.temporary_folder(target.parent)
    print(building.__enter__())
else:
    fd, name = files.temporary(target)
    os.write(fd, b"half a file")
    print(name)
sys.stdout.flush()
os._exit(9)
"""


def killed_write(target: Path, folder: bool = False) -> Path:
    """The temporary a process left that died writing ``target`` (or building beside it)."""
    import sys

    proc = subprocess.run([sys.executable, "-c", DIES_WRITING, str(target), *(["folder"] if folder else [])],
                          capture_output=True, text=True)
    assert proc.returncode == 9, proc.stderr
    left = Path(proc.stdout.strip())
    assert left.exists() and left.parent == target.parent and left.name.startswith(".")
    return left


def test_a_killed_runs_temporaries_are_removed_by_the_next_write(tmp_path, monkeypatch):
    """Output, the cache's files and its build folders: the next run removes what a killed one left,
    and keeps a running process's."""
    from hybrid import files

    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    ctrl = hybrid.read_controller_config(Path(hybrid.__file__).parent / "data" / "controller_ur5_sphere.toml",
                                         hybrid.ur5())
    first = {p.name: p.read_bytes() for p in ctrl.generate(tmp_path / "first", "ur5s")}
    out = tmp_path / "out"
    out.mkdir()
    (cached,) = (tmp_path / "cache" / "units").glob("ur5s_*")
    left = [killed_write(out / "ur5s.c"), killed_write(out / "ur5s.json"), killed_write(cached / "ur5s.h"),
            killed_write(cached / "x", folder=True)]
    fd, running = files.temporary(out / "ur5s.h")  # this process's, still writing
    try:
        (cached / "ur5s.c").write_text("cut")  # the entry is made again: its folder is written
        written = ctrl.generate(out, "ur5s", force=True)
        assert {p.name: p.read_bytes() for p in written} == first
        assert [p for p in left if p.exists()] == []
        assert Path(running).exists()
    finally:
        import os

        os.close(fd)
        Path(running).unlink()
    assert sorted(p.name for p in out.iterdir()) == sorted(first)


def test_an_old_temporary_of_another_machine_is_removed_and_others_files_are_kept(tmp_path):
    import os

    from hybrid import files

    theirs = tmp_path / ".r.txt.abcdef-1-0123abcd.tmp.txt"  # not this machine's: judged by its age
    fresh = tmp_path / ".q.txt.abcdef-1-0123abcd.tmp.txt"
    mine = [tmp_path / ".r.txt.backup", tmp_path / ".notes", tmp_path / "r.txt.abcdef-1-0123abcd.tmp.txt"]
    for path in (theirs, fresh, *mine):
        path.write_text("x")
    old = os.stat(theirs).st_mtime - files.STALE_AFTER - 60
    os.utime(theirs, (old, old))
    files.write_text(tmp_path / "r.txt", "whole")
    assert not theirs.exists() and fresh.exists() and all(p.exists() for p in mine)
    assert (tmp_path / "r.txt").read_text() == "whole"


# ------------------------------------------------------------------ a compiler that writes nothing

#: a "compiler" that runs, says who it is, logs every call and writes nothing
SILENT_CC = """#!/bin/sh
echo "$@" >> "$(dirname "$0")/calls.log"
[ "$1" = "--version" ] && echo "silentcc 1.0"
exit 0
"""


def silent_compiler(tmp_path: Path) -> Path:
    cc = tmp_path / "bin" / "silentcc"
    cc.parent.mkdir()
    cc.write_text(SILENT_CC)
    cc.chmod(0o755)
    return cc


def test_a_compiler_that_writes_nothing_is_one_error_and_tried_once(tmp_path):
    cc = silent_compiler(tmp_path)
    code = ("import hybrid\n"
            "for scheme in ('task', 'khatib', 'raibert_craig'):\n"
            "    try:\n"
            "        hybrid.simulate(hybrid.paper_experiment(controller=scheme, duration=0.1))\n"
            "    except hybrid.NativeBuildError as exc:\n"
            "        print(type(exc).__name__, str(exc).splitlines()[0])\n")
    proc = run_python(code, tmp_path / "cache", CC=str(cc))
    assert proc.returncode == 0, proc.stderr
    errors = proc.stdout.splitlines()
    assert len(errors) == 3 and len(set(errors)) == 1, errors  # the same error each time
    assert errors[0].startswith("CompilerUnusable ") and f"$CC={str(cc)!r}" in errors[0] and "set CC to" in errors[0]
    assert "warning" not in proc.stderr.lower(), proc.stderr
    builds = [line for line in (cc.parent / "calls.log").read_text().splitlines() if "-shared" in line]
    assert len(builds) == 1, builds  # the first failure stopped every later attempt


def test_the_command_line_says_a_silent_compiler_in_one_line(tmp_path):
    import os
    import sys

    cc = silent_compiler(tmp_path)
    proc = subprocess.run([sys.executable, "-m", "hybrid", "paper", "--out", str(tmp_path / "paper")],
                          capture_output=True, text=True, timeout=600,
                          env={**os.environ, "CC": str(cc), "HYBRID_CACHE_DIR": str(tmp_path / "cache")})
    assert proc.returncode == 2
    lines = [line for line in proc.stderr.splitlines() if not line.startswith("running ")]
    assert len(lines) == 1 and lines[0].startswith("error: ") and "wrote no library" in lines[0], proc.stderr
    assert "$CC=" in lines[0]


def test_a_sweep_stops_at_a_silent_compiler_and_resumes_with_a_working_one(tmp_path):
    """No run is stored as refused for want of a compiler: the sweep stops, and resumed with a working
    compiler it runs them all."""
    code = ("import hybrid; t = hybrid.sweep(hybrid.paper_experiment(duration=0.1), {'model_error': [0.0, 0.1]}, "
            f"out={str(tmp_path / 'sweep')!r}, workers=1); print(sorted(t['status']))")
    stopped = run_python(code, tmp_path / "cache", CC=str(silent_compiler(tmp_path)))
    assert stopped.returncode != 0 and "CompilerUnusable" in stopped.stderr.splitlines()[-1], stopped.stderr
    resumed = run_python(code, tmp_path / "cache", CC=CC or "cc")
    assert resumed.returncode == 0, resumed.stderr
    assert resumed.stdout.strip() == "['ok', 'ok']"


# ------------------------------------------------------------------ a run's memory

#: every way to run an experiment far too long for memory, in a process that may not allocate more than
#: 3 GiB: each must be refused by the one memory check (a HybridError), quickly, not a MemoryError or a kill
TOO_LONG = """
import resource, sys, time
import hybrid, hybrid.oracle
from hybrid.simulation import closed_loop
out = sys.argv[1]
runs = {
    "simulate": lambda exp: hybrid.simulate(exp),
    "python runner": lambda exp: hybrid.simulate(exp, compiled=False),
    "oracle": lambda exp: hybrid.oracle.simulate(exp),
    "generate": lambda exp: exp.generate(out),
    "sweep's run": lambda exp: closed_loop.prepare(exp),
    "sweep": lambda exp: hybrid.sweep(exp, {"model_error": [0.0]}, workers=1).iloc[0]["error"],
}
experiments = {"paper": hybrid.paper_experiment(duration=1e9), "tracing": hybrid.tracing_experiment(duration=1e9)}
resource.setrlimit(resource.RLIMIT_AS, (3 * 2**30, resource.getrlimit(resource.RLIMIT_AS)[1]))
for kind, exp in experiments.items():
    for what, run in runs.items():
        if kind == "tracing" and what == "oracle":
            continue  # the NumPy oracle runs the paper's arm only
        t0 = time.perf_counter()
        try:
            said = f"returned {run(exp)!r:.200}"
        except hybrid.HybridError as exc:
            said = f"HybridError {str(exc).splitlines()[0]}"
        except MemoryError as exc:
            said = f"MemoryError {exc}"
        print(f"{kind} {what}: {time.perf_counter() - t0:.1f} s: {said}", flush=True)
"""


def test_a_run_too_long_for_memory_is_refused_by_every_way_to_run_it(tmp_path):
    import sys

    proc = subprocess.run([sys.executable, "-c", TOO_LONG, str(tmp_path / "out")], capture_output=True, text=True,
                          timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    lines = proc.stdout.splitlines()
    assert len(lines) == 11, proc.stdout
    for line in lines:
        took = float(line.split(": ")[1].split(" s")[0])
        assert "whose record needs" in line and "shorten duration" in line and took < 60, line
        assert "MemoryError" not in line and ("HybridError" in line or "sweep:" in line), line
    assert not (tmp_path / "out").exists()
