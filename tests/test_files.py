"""Results on disk: real paths, no silent overwrite, whole files or none, clear errors for broken ones."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid import files

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def result():
    return hybrid.simulate(hybrid.paper_experiment(duration=0.05))


def test_save_returns_the_path_it_wrote(tmp_path, result):
    path = result.save(tmp_path / "run")
    assert path == tmp_path / "run.npz" and path.is_file()
    loaded = hybrid.SimulationResult.load(path)
    np.testing.assert_array_equal(loaded.state, result.state)
    assert result.save(tmp_path / "run.v2").name == "run.v2.npz"


def test_save_never_overwrites_unasked(tmp_path, result):
    path = tmp_path / "r.npz"
    path.write_bytes(b"precious")
    with pytest.raises(hybrid.HybridError, match="r.npz exists; choose another name or pass overwrite=True"):
        result.save(path)
    assert path.read_bytes() == b"precious"
    with pytest.raises(hybrid.HybridError, match="exists"):
        result.save_csv(tmp_path / "r.npz")
    result.save(path, overwrite=True)
    assert hybrid.SimulationResult.load(path).t[-1] == result.t[-1]


@pytest.mark.parametrize("damage", ["truncate", "garbage", "missing", "empty", "foreign npz"])
def test_broken_result_files_are_hybrid_errors(tmp_path, result, damage):
    path = result.save(tmp_path / "r.npz")
    if damage == "truncate":
        path.write_bytes(path.read_bytes()[:300])
    elif damage == "garbage":
        path.write_bytes(b"PK\x03\x04" + bytes(range(256)) * 4)
    elif damage == "missing":
        path.unlink()
    elif damage == "empty":
        path.write_bytes(b"")
    else:
        np.savez(path, x=np.zeros(3))
    with pytest.raises(hybrid.HybridError, match="is not a readable saved hybrid result") as info:
        hybrid.SimulationResult.load(path)
    assert len(str(info.value).splitlines()) == 1


def test_a_failed_write_leaves_nothing_behind(tmp_path):
    target = tmp_path / "out.npz"

    def half_then_fail(tmp: Path) -> None:
        tmp.write_bytes(b"half a file")
        raise OSError(28, "No space left on device")

    with pytest.raises(hybrid.HybridError, match="writing .*out.npz failed \\(No space left on device\\)"):
        files.write_with(target, half_then_fail)
    assert list(tmp_path.iterdir()) == []  # neither the target nor a temporary file


def test_output_under_a_file_is_one_clear_line(tmp_path, result):
    afile = tmp_path / "afile"
    afile.write_text("x")
    with pytest.raises(hybrid.HybridError, match="is a file; give a folder"):
        result.save(afile / "r.npz")
    proc = subprocess.run([sys.executable, "-m", "hybrid", "paper", "--out", str(afile / "sub")], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert afile.read_text() == "x"


def test_written_files_have_ordinary_permissions(tmp_path, result):
    import os

    mask = os.umask(0o022)
    try:
        path = result.save(tmp_path / "r.npz")
        text = files.write_text(tmp_path / "t.txt", "x")
    finally:
        os.umask(mask)
    assert path.stat().st_mode & 0o777 == 0o644 and text.stat().st_mode & 0o777 == 0o644



@pytest.mark.parametrize("name", [None, 123, "", "bad\x00name", "a" * 300])
def test_bad_output_names(tmp_path, result, name):
    target = name if not isinstance(name, str) or not name or "\0" in name else tmp_path / name
    with pytest.raises(hybrid.HybridError):
        result.save(target)
    with pytest.raises(hybrid.HybridError):
        result.save_csv(target)


@pytest.mark.parametrize("forge", [{"state": np.zeros(3)}, {"outputs": np.zeros((3, 2))}, {"t": np.full(3, np.nan)}])
def test_forged_result_files_are_refused_at_load(tmp_path, result, forge):
    path = result.save(tmp_path / "r.npz")
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    arrays.update(forge)
    np.savez(path, **arrays)
    with pytest.raises(hybrid.HybridError, match="not a readable saved hybrid result"):
        hybrid.SimulationResult.load(path)


def test_regenerate_into_a_bad_target_is_one_line(tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    for args in (["--target", str(afile / "sub")], ["--target", str(afile)], ["--check", "--target", str(afile)]):
        proc = subprocess.run([sys.executable, "-m", "hybrid", "regenerate", *args], cwd=ROOT, capture_output=True,
                              text=True)
        assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
