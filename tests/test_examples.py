"""The gallery's scripts (``examples/*.py``) run as written, each within a time budget.

The documentation's build runs them too (sphinx-gallery, ``docs/conf.py``); here each runs alone,
in a fresh interpreter and an empty folder, as a reader would run it.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

EXAMPLES = sorted((Path(__file__).resolve().parent.parent / "examples").glob("*.py"))
#: seconds one example may take, its units compiled on a cold cache included (a few seconds warm)
BUDGET = 120.0
#: seconds after which a script that hangs is stopped: well past the budget, so that the budget is the
#: measured time's to enforce (a script between the two fails on its time, with the time it took)
STOP = 5 * BUDGET


def run_within_budget(args: list[str], cwd: Path, name: str) -> subprocess.CompletedProcess:
    """Run ``python args`` in ``cwd``; fail unless it ends within :data:`BUDGET`."""
    start = time.perf_counter()
    try:
        done = subprocess.run([sys.executable, *args], cwd=cwd, capture_output=True, text=True, timeout=STOP,
                              env={**os.environ, "MPLBACKEND": "Agg"})
    except subprocess.TimeoutExpired:
        pytest.fail(f"{name} still ran after {STOP:g} s (its budget is {BUDGET:g} s): stopped")
    seconds = time.perf_counter() - start
    assert done.returncode == 0, f"{name} failed:\n{done.stderr[-3000:]}"
    assert seconds < BUDGET, f"{name} took {seconds:.1f} s, past its budget of {BUDGET:g} s"
    return done


def test_there_are_examples():
    assert len(EXAMPLES) >= 4
    for path in EXAMPLES:
        head = path.read_text().split('"""')
        assert path.name.startswith("plot_"), f"{path.name}: the gallery runs examples/plot_*.py"
        assert len(head) > 2 and head[0] == "" and "\n===" in head[1], f"{path.name}: no title docstring"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(path, tmp_path):
    run_within_budget([str(path)], tmp_path, path.name)
    assert not any(tmp_path.iterdir()), f"{path.name} left files: {sorted(p.name for p in tmp_path.iterdir())}"


STUDIES = sorted((Path(__file__).resolve().parent.parent / "examples" / "studies").glob("*.py"))


@pytest.mark.parametrize("path", STUDIES, ids=lambda p: p.name)
def test_study_runs_quick(path, tmp_path):
    """A study (a longer script with its own output folder) runs in its quick form and writes its tables."""
    run_within_budget([str(path), "--quick", "--out", str(tmp_path / "out")], tmp_path, path.name)
    written = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert any(name.endswith(".csv") for name in written) and any(name.endswith(".png") for name in written), written
