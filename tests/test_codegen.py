"""Generated code: up to date, byte-for-byte repeatable, strict-C clean, protected from hand edits."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hybrid.codegen import emit

import hybrid
from hybrid.cli import regenerate
from hybrid.simulation.closed_loop import loop_of
from hybrid.spec import stamp

ROOT = Path(__file__).resolve().parent.parent


def test_committed_generated_code_is_up_to_date():
    problems = regenerate.check()
    assert not problems, "\n".join(problems)


def test_regeneration_is_repeatable_across_processes(tmp_path):
    """Two processes with different hash seeds write the same bytes."""
    outs = []
    for seed in ("1", "12345"):
        target = tmp_path / seed
        env = {**os.environ, "PYTHONHASHSEED": seed}
        subprocess.run([sys.executable, "-m", "hybrid", "regenerate", "--target", str(target)],
                       check=True, cwd=ROOT, env=env, capture_output=True)
        files = sorted(p for p in target.rglob("*") if p.is_file())
        outs.append({p.relative_to(target).as_posix(): p.read_bytes() for p in files})
    assert outs[0] == outs[1]
    assert all(b"/work" not in text and b"/home" not in text for text in outs[0].values())


@pytest.mark.parametrize("backend", emit.BACKENDS)
def test_generated_c_compiles_strictly(tmp_path, backend):
    cc = shutil.which("gcc") or shutil.which("cc")
    src = ROOT / "generated" / f"hybrid_{backend}.c"
    proc = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                           f"-I{src.parent}", "-c", str(src), "-o", str(tmp_path / "x.o")],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr


def test_check_reports_stale_files_with_a_diff(tmp_path):
    target = tmp_path / "gen"
    regenerate.write(target)
    path = target / "hybrid_sympy.h"
    path.write_text(stamp.stamp(path.read_text().split("\n", 1)[1].replace("B_o", "Bo_old")))
    problems = regenerate.check(target)
    assert len(problems) == 1 and "hybrid_sympy.h: stale" in problems[0]
    assert "python -m hybrid regenerate" in problems[0] and "-" in problems[0]
    proc = subprocess.run([sys.executable, "-m", "hybrid", "regenerate", "--check", "--target", str(target)],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 1 and "hybrid_sympy.h" in proc.stderr


def test_regenerate_refuses_to_overwrite_hand_edits(tmp_path):
    target = tmp_path / "gen"
    regenerate.write(target)
    path = target / "hybrid_casadi.c"
    edited = path.read_text() + "\n/* my tuning */\n"
    path.write_text(edited)
    assert stamp.is_hand_edited(edited)
    with pytest.raises(FileExistsError, match="edited by hand.*--force"):
        regenerate.write(target)
    assert path.read_text() == edited  # nothing lost
    proc = subprocess.run([sys.executable, "-m", "hybrid", "regenerate", "--target", str(target)],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 2 and "--force" in proc.stderr and path.read_text() == edited
    assert regenerate.write(target, force=True) == ["hybrid_casadi.c"]
    assert not stamp.is_hand_edited(path.read_text())


def test_the_committed_loops_cover_every_scheme_of_the_paper():
    """A scheme added to the registry has its paper loop committed (``hybrid/data/committed_loops.toml``
    names it), so ``hybrid paper`` and ``simulate`` of the paper's experiment never generate at first use."""
    committed = {(plant, tuple(sorted(variant.items()))) for plant, variant, _ in regenerate.committed_loops()}
    for scheme in hybrid.SCHEMES:
        assert loop_of(hybrid.paper_experiment(controller=scheme)) in committed, scheme
