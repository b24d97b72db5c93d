"""The README's tour runs as written, twice; the library example of docs/reference/library.md runs as
written and gives the numbers the NumPy oracle gives."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

import hybrid
from hybrid import oracle

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
LIBRARY = ROOT / "docs" / "reference" / "library.md"


def test_readme_tour_runs_twice(tmp_path, monkeypatch):
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)
    assert len(blocks) == 1, "the README has one Python block: its tour"
    monkeypatch.chdir(tmp_path)
    for _ in range(2):
        ns: dict = {}
        exec(compile(blocks[0], "README.md", "exec"), ns)
    assert np.isfinite(ns["tau"]).all() and ns["res"].metrics["contact_losses"] == 0
    assert {"ur5s.c", "ur5s.h", "ur5s.json"} <= {p.name for p in (tmp_path / "ur5s").iterdir()}


def test_library_example(tmp_path, monkeypatch, capsys):
    blocks = re.findall(r"```python\n(.*?)```", LIBRARY.read_text(), flags=re.S)
    assert blocks, "the library reference lost its Python example"
    monkeypatch.chdir(tmp_path)
    ns: dict = {}
    exec(compile(blocks[0], str(LIBRARY), "exec"), ns)
    arm, circle = ns["arm"], ns["circle"]
    F_ref, tau_ref = oracle.decoupling_law("circle", ns["q"], ns["qdot"], ns["a"], ns["Fc"], arm.as_array(),
                                        circle.cross_section().as_array(), True)
    np.testing.assert_allclose(ns["F"], F_ref, rtol=1e-10)
    np.testing.assert_allclose(ns["tau"], tau_ref, rtol=1e-10)
    # the batch runs as SIMD lanes: the one-state numbers within rounding
    np.testing.assert_allclose(ns["F_many"], np.tile(ns["F"], (1000, 1)), rtol=1e-13, atol=1e-13)
    saved = hybrid.SimulationResult.load(tmp_path / "task.npz")
    np.testing.assert_array_equal(saved.state, ns["res"].state)
    assert abs(ns["res"].metrics["steady_state_force_error_N"]) < 0.05
    assert "NaN or infinite at t = " in capsys.readouterr().out  # the diverging run was stopped and told


def _quick_start(text: str) -> list[str]:
    """The quick start's commands: those that make the virtual environment, each with the lines it
    continues on (a trailing backslash) joined, its spaces as one."""
    commands = re.sub(r"\\\n", " ", text).splitlines()
    return [" ".join(line.split()) for line in commands if line.strip().startswith("python3 -m venv .venv")]


def test_getting_started_gives_the_readme_quick_start():
    """The documentation's two commands are the README's, character for character (a second run of the
    paper's command needs its --force), their line breaks aside."""
    readme = _quick_start(README.read_text())
    assert len(readme) == 2
    assert _quick_start((ROOT / "docs" / "getting_started.rst").read_text()) == readme
