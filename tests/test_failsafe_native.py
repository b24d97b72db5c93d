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
    """The project's own headers (the generator's templates') and those its templates include by <...>."""
    import re

    from hybrid.native import generator
    from hybrid.validate import c_name_problem

    templates = generator.include_dir()
    own = {p.stem for p in templates.glob("*.h")}
    included = {m for p in templates.iterdir() if p.is_file()
                for m in re.findall(r"#include <(\w+)\.h>", p.read_text())}
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
