"""The native build cache: the compiler it uses and why, and healing from any broken entry."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.native import cache, compiler, loader

ROOT = Path(__file__).resolve().parent.parent
LAW = ("import hybrid; law = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0), 0.2)); "
       "print(law([2.2, 1.9], [0.3, -0.4], [0.1, 1.0], [-8.0, 3.0]))")


def run(code: str, **env) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                          env={**os.environ, **env})


def test_cc_naming_a_missing_program_is_an_error_not_a_fallback(tmp_path):
    proc = run(LAW, CC="no-such-compiler", HYBRID_CACHE_DIR=str(tmp_path))
    assert proc.returncode != 0
    # a NativeBuildError: the compiler can build nothing
    assert "CompilerUnusable: $CC='no-such-compiler' names no program on PATH" in proc.stderr
    assert not list(tmp_path.rglob("*.so"))  # gcc was not used behind the user's back


def test_a_compiler_that_writes_nothing_is_reported(tmp_path):
    proc = run(LAW, CC=shutil.which("true"), HYBRID_CACHE_DIR=str(tmp_path))
    assert proc.returncode != 0 and "exited 0 but wrote no library" in proc.stderr
    assert "FileNotFoundError" not in proc.stderr
    good = run(LAW, HYBRID_CACHE_DIR=str(tmp_path))  # the next run with a real compiler is fine
    assert good.returncode == 0, good.stderr


def test_an_entry_that_matches_its_checksum_but_does_not_load_heals(tmp_path):
    first = run(LAW, HYBRID_CACHE_DIR=str(tmp_path))
    assert first.returncode == 0, first.stderr
    for so in tmp_path.rglob("*.so"):
        so.write_bytes(b"\x7fELF not really a library")
        manifest = so.parent / "manifest.json"
        data = json.loads(manifest.read_text())
        data["sha256"] = cache.digest(so.read_bytes())  # the checksum agrees: only loading can tell
        manifest.write_text(json.dumps(data))
    second = run(LAW, HYBRID_CACHE_DIR=str(tmp_path))
    assert second.returncode == 0, second.stderr
    assert second.stdout == first.stdout


def test_hand_edited_generated_code_is_used_with_a_warning(tmp_path, monkeypatch):
    src = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", src)
    c = src / "hybrid_sympy.c"
    c.write_text(c.read_text() + "\n/* my tuning */\n")
    monkeypatch.setattr(loader, "source_dir", lambda: src)
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    loader.load.cache_clear()
    try:
        with pytest.warns(loader.HandEditedWarning, match="hybrid_sympy.c in .* were edited by hand"):
            loader.load("sympy")
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            loader.load("casadi")  # untouched: no warning
    finally:
        loader.load.cache_clear()


def test_a_hand_edited_committed_loop_is_used_with_a_warning(tmp_path, monkeypatch):
    """A closed loop of ``generated/loops`` edited by hand is compiled as it is, with a warning saying so."""
    from hybrid.native import units
    from hybrid.simulation import closed_loop

    src = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", src)
    plant, variant = closed_loop.loop_of(hybrid.paper_experiment(controller="raibert_craig"))
    prefix, _ = units._loop_key(plant, dict(variant), 1)
    c = src / "loops" / f"{prefix}.c"
    c.write_text(c.read_text() + "\n/* my tuning */\n")
    monkeypatch.setattr(loader, "source_dir", lambda: src)  # where the units look for the committed loops
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    unit = units.loop_unit(plant, dict(variant), 1)
    assert unit.folder == src / "loops"
    with pytest.warns(loader.HandEditedWarning, match=f"{prefix}.c in .* were edited by hand"):
        assert unit.module.lib is not None  # compiled from the edited C


@pytest.mark.parametrize("damage", ["edited", "missing"])
def test_a_loop_compiles_with_the_generated_lanes_header_said_when_edited_or_missing(tmp_path, monkeypatch, damage):
    """The SIMD lanes' header a loop includes is the generated C's copy: edited by hand, it is used with a
    warning; missing, the build is refused with what to run."""
    from hybrid.native import generator, units
    from hybrid.simulation import closed_loop

    src = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", src)
    lanes = src / generator.LANES_HEADER
    if damage == "edited":
        lanes.write_text(lanes.read_text() + "\n/* my tuning */\n")
    else:
        lanes.unlink()
    plant, variant = closed_loop.loop_of(hybrid.paper_experiment(controller="raibert_craig"))
    monkeypatch.setattr(loader, "source_dir", lambda: src)
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    unit = units.loop_unit(plant, dict(variant), 1)
    if damage == "edited":
        with pytest.warns(loader.HandEditedWarning, match=f"{generator.LANES_HEADER} in .* were edited by hand"):
            assert unit.module.lib is not None  # compiled with the edited header
    else:
        with pytest.raises(hybrid.HybridError, match=f"{generator.LANES_HEADER} cannot be read .* regenerate"):
            _ = unit.module  # the module loads on first use


def test_a_committed_loop_with_a_file_missing_is_generated_instead(tmp_path, monkeypatch):
    from hybrid.native import units
    from hybrid.simulation import closed_loop

    src = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", src)
    plant, variant = closed_loop.loop_of(hybrid.paper_experiment(controller="raibert_craig"))
    prefix, _ = units._loop_key(plant, dict(variant), 1)
    (src / "loops" / f"{prefix}.c").unlink()
    monkeypatch.setattr(loader, "source_dir", lambda: src)  # where the units look for the committed loops
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    unit = units.loop_unit(plant, dict(variant), 1)
    assert unit.folder.parent == tmp_path / "cache" / "units"  # generated into the cache
    assert unit.module.lib is not None


def test_the_compiler_is_probed_once_per_process():
    compiler._compiler.cache_clear()
    compiler.compiler()
    compiler.compiler()
    assert compiler._compiler.cache_info().misses == 1
    assert isinstance(hybrid.NativeBuildError("x"), hybrid.HybridError)


def test_a_known_compiler_is_not_probed_again_and_a_changed_one_is(tmp_path, monkeypatch):
    """A warm start reads the compiler's identity from the cache (no subprocess); a compiler whose
    binary changed is asked again."""
    calls = tmp_path / "calls"
    fake = tmp_path / "fakecc"

    def install(version: str) -> None:
        fake.write_text(f"#!/bin/sh\necho x >> {calls}\necho 'fakecc {version}'\n")
        fake.chmod(0o755)

    install("1.0")
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("CC", str(fake))
    try:
        for _ in range(2):
            compiler._compiler.cache_clear()
            assert compiler.compiler() == (str(fake), "fakecc 1.0")
        assert calls.read_text().count("x") == 1
        install("2.0.1")  # another binary (size and time differ)
        compiler._compiler.cache_clear()
        assert compiler.compiler()[1] == "fakecc 2.0.1"
        assert calls.read_text().count("x") == 2
    finally:
        compiler._compiler.cache_clear()


def test_a_cache_folder_under_a_file_is_a_native_build_error(tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    proc = run(LAW, HYBRID_CACHE_DIR=str(afile / "cache"))
    assert proc.returncode != 0 and "NativeBuildError" in proc.stderr and "HYBRID_CACHE_DIR" in proc.stderr
    assert "NotADirectoryError" not in proc.stderr.splitlines()[-1]


def test_robot_names_become_ascii_c_identifiers(tmp_path):
    from hybrid.validate import c_identifier

    assert c_identifier("robôt arm") == "robot_arm"  # accents dropped, not each made a _
    text = (Path(__file__).parent / "data" / "slider_arm.urdf").read_text().replace('name="slider_arm"', 'name="robôt"')
    path = tmp_path / "r.urdf"
    path.write_text(text)
    robot = hybrid.Robot.from_urdf(path, tip="tool")
    assert hybrid.arm_terms(robot, [0.0, 0.1, 0.2], [0.0, 0.0, 0.0])["B"].shape == (3, 3)


@pytest.mark.parametrize("ident, gcc", [
    ("cc (Debian 12.2.0-14+deb12u1) 12.2.0", True), ("gcc (GCC) 13.2.1 20231011 (Red Hat 13.2.1-4)", True),
    ("x86_64-linux-gnu-gcc-12 (Debian 12.2.0-14) 12.2.0", True), ("gcc-13 (Homebrew GCC 13.2.0) 13.2.0", True),
    ("clang version 16.0.6", False), ("Debian clang version 14.0.6", False),
    ("Apple clang version 15.0.0 (clang-1500.1.0.2.5)", False), ("Ubuntu clang version 18.1.3 (1ubuntu1)", False),
    ("Intel(R) oneAPI DPC++/C++ Compiler 2023.0.0 (2023.0.0.20221201)", False),
])
def test_gccs_scheduling_flags_go_to_gcc_alone(ident, gcc):
    """GCC takes its pre-allocation scheduling flags; Clang and others (which may refuse them) do not."""
    got = compiler.flags(ident)
    assert got[:len(compiler.CFLAGS)] == compiler.CFLAGS
    assert (set(compiler.GCC_FLAGS) <= set(got)) is gcc and (len(got) > len(compiler.CFLAGS)) is gcc


def test_a_gcc_that_fails_on_its_scheduling_flags_builds_without_them(tmp_path):
    """A GCC that cannot take -fschedule-insns -fsched-pressure (some have failed on them) still builds,
    without them, with a warning; the numbers are those of the build with them."""
    real = shutil.which("gcc") or shutil.which("cc")
    wrapper = tmp_path / "oldgcc"
    wrapper.write_text(f"""#!/bin/sh
[ "$1" = --version ] && {{ echo 'gcc (Old GCC) 5.4.0'; exit 0; }}
for a in "$@"; do
    [ "$a" = -fsched-pressure ] && {{ echo 'internal compiler error: unable to find a register' >&2; exit 1; }}
done
exec {real} "$@"
""")
    wrapper.chmod(0o755)
    law = LAW.replace("import hybrid; ", "import hybrid, logging; logging.basicConfig(); ")
    old = run(law, CC=str(wrapper), HYBRID_CACHE_DIR=str(tmp_path / "old"))
    assert old.returncode == 0, old.stderr
    assert "failed on" in old.stderr and "compiling without them" in old.stderr
    new = run(LAW, HYBRID_CACHE_DIR=str(tmp_path / "new"))
    assert new.returncode == 0, new.stderr
    assert old.stdout == new.stdout


def test_this_compiler_takes_the_flags_it_is_given(tmp_path):
    """The flags chosen for the compiler found here compile a unit with it (and GCC's are among them
    when it is GCC)."""
    cc, ident = compiler.compiler()
    src = tmp_path / "t.c"
    src.write_text("double f(double x) { return x * x + 1.0; }\n")
    proc = subprocess.run([cc, *compiler.flags(ident), "-shared", str(src), "-o", str(tmp_path / "t.so")],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    version = subprocess.run([cc, "-dM", "-E", "-"], input="", capture_output=True, text=True).stdout
    is_gcc = "__GNUC__" in version and "__clang__" not in version
    assert (set(compiler.GCC_FLAGS) <= set(compiler.flags(ident))) is is_gcc


def _paper_loop(tmp_path: Path, parts: int | None):
    """The committed loop of the paper's run alone, compiled from a copy whose manifest says ``parts``
    (None: says nothing), and the prefix of its unit."""
    index = json.loads((ROOT / "generated" / "loops" / "index.json").read_text())["loops"]
    prefix = next(p for p in index if "controller" in p)
    src = tmp_path / f"src{parts}"
    src.mkdir()
    for ext in ("c", "h", "json"):
        shutil.copy(ROOT / "generated" / "loops" / f"{prefix}.{ext}", src)
    data = json.loads((src / f"{prefix}.json").read_text())
    data.pop("parts", None)
    if parts is not None:
        data["parts"] = parts
    (src / f"{prefix}.json").write_text(json.dumps(data))
    return loader.load_generated(src, prefix), prefix


def test_a_loop_compiled_in_parts_computes_what_it_computes_whole(tmp_path, monkeypatch):
    """The closed loop's unit is compiled in the parts its manifest names, at once, and linked: the same
    run gives the same bits, states and metrics, as the unit compiled whole."""
    from hybrid.simulation import closed_loop

    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    manifest = json.loads(next((ROOT / "generated" / "loops").glob("*controller*.json")).read_text())
    assert manifest["parts"] == 2
    together = []
    real = compiler._run_together
    monkeypatch.setattr(compiler, "_run_together", lambda cmds: together.append(cmds) or real(cmds))
    runs = {}
    exp = hybrid.paper_experiment(duration=0.3)
    row = closed_loop.prepare(exp, lanes=1).row
    for parts in (2, None):
        module, prefix = _paper_loop(tmp_path, parts)
        ffi, lib = module.ffi, module.lib
        steps = exp.n_samples * exp.steps_per_sample + 1
        metrics, states = np.empty(18), np.empty((steps, 8))
        status, failed = np.empty(1, np.intc), np.empty(1, np.intc)
        getattr(lib, f"{prefix}_closed_loop")(1, ffi.from_buffer("double[]", row), ffi.NULL, exp.n_samples,
                                              exp.steps_per_sample, exp.integration_step, exp.sample_time,
                                              exp.singular_tol, ffi.from_buffer("double[]", metrics),
                                              ffi.from_buffer("int[]", status), ffi.from_buffer("int[]", failed),
                                              ffi.from_buffer("double[]", states), ffi.NULL, ffi.NULL, ffi.NULL)
        assert status[0] == 0
        runs[parts] = metrics, states
    # the binding and both parts, each by its own compiler, once (the whole unit is one command)
    compiled = [[c[c.index("-c") + 1] for c in cmds] for cmds in together]
    assert compiled == [["-DHL_PART=0", "-DHL_PART=1", "-DHL_PART=2"]]
    assert np.array_equal(runs[2][0], runs[None][0], equal_nan=True)
    assert np.array_equal(runs[2][1], runs[None][1])
    assert np.isfinite(runs[2][1]).all()


@pytest.mark.parametrize("parts", [0, 9, "2", True, 1.5])
def test_a_manifest_naming_impossible_parts_is_a_native_build_error(tmp_path, monkeypatch, parts):
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    with pytest.raises(hybrid.NativeBuildError, match="parts; regenerate the unit"):
        _paper_loop(tmp_path, parts)
    assert not list(tmp_path.rglob("*.so"))


def test_a_part_that_fails_to_compile_is_reported_with_its_messages(tmp_path, monkeypatch):
    """A compiler failing on one part: the error names that part's command and shows its messages, and
    no library is cached (the next build with a working compiler succeeds)."""
    real = shutil.which("gcc") or shutil.which("cc")
    wrapper = tmp_path / "badgcc"
    wrapper.write_text(f"""#!/bin/sh
for a in "$@"; do
    [ "$a" = -DHL_PART=2 ] && {{ echo 'part two: internal compiler error' >&2; exit 1; }}
done
exec {real} "$@"
""")
    wrapper.chmod(0o755)
    monkeypatch.setenv("HYBRID_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("CC", str(wrapper))
    with pytest.raises(hybrid.NativeBuildError) as err:
        _paper_loop(tmp_path, 2)
    assert "-DHL_PART=2" in str(err.value) and "part two: internal compiler error" in str(err.value)
    assert not list((tmp_path / "cache").rglob("*.so"))
