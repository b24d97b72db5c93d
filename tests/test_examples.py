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


def test_there_are_examples():
    assert len(EXAMPLES) >= 4
    for path in EXAMPLES:
        head = path.read_text().split('"""')
        assert path.name.startswith("plot_"), f"{path.name}: the gallery runs examples/plot_*.py"
        assert len(head) > 2 and head[0] == "" and "\n===" in head[1], f"{path.name}: no title docstring"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(path, tmp_path):
    start = time.perf_counter()
    done = subprocess.run([sys.executable, str(path)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=BUDGET, env={**os.environ, "MPLBACKEND": "Agg"})
    seconds = time.perf_counter() - start
    assert done.returncode == 0, f"{path.name} failed:\n{done.stderr[-3000:]}"
    assert seconds < BUDGET
    assert not any(tmp_path.iterdir()), f"{path.name} left files: {sorted(p.name for p in tmp_path.iterdir())}"


STUDIES = sorted((Path(__file__).resolve().parent.parent / "examples" / "studies").glob("*.py"))


@pytest.mark.parametrize("path", STUDIES, ids=lambda p: p.name)
def test_study_runs_quick(path, tmp_path):
    """A study (a longer script with its own output folder) runs in its quick form and writes its tables."""
    done = subprocess.run([sys.executable, str(path), "--quick", "--out", str(tmp_path / "out")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=BUDGET, env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, f"{path.name} failed:\n{done.stderr[-3000:]}"
    written = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert any(name.endswith(".csv") for name in written) and any(name.endswith(".png") for name in written), written
