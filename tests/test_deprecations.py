"""Old names keep working for one release, each with a DeprecationWarning that names the new one."""

from __future__ import annotations

import dataclasses
import importlib
import json
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import hybrid
from hybrid import oracle
from hybrid.experiments.settings import setting_path
from hybrid.sweeps import apply, check_names


def test_the_old_module_name_of_the_numpy_oracle_is_the_oracle_and_warns():
    sys.modules.pop("hybrid.reference", None)  # imported before: import it afresh
    with pytest.warns(DeprecationWarning, match="hybrid.oracle"):
        old = importlib.import_module("hybrid.reference")
    assert old is oracle
    assert old.simulate is oracle.simulate


# ------------------------------------------------------------------ reference -> frame_direction

SIDEWAYS = (1.0, 0.0, 0.0)


@pytest.fixture(scope="module")
def ur5():
    return hybrid.ur5()


@pytest.fixture(scope="module")
def plane():
    return hybrid.Plane((0.0, 0.0, 0.1), (0.0, 0.0, 1.0))  # its normal is base z: e = z leaves no frame


def test_the_frame_direction_sets_the_task_frame(ur5, plane):
    """``t1 = e x n``: on a horizontal plane, ``e`` = base x gives ``t1`` = base y."""
    law = hybrid.decoupling_law(ur5, plane, frame_direction=SIDEWAYS)
    R, _ = law.task_frame((0.4, 0.1, 0.1), (0.0, 0.0, 0.0))
    np.testing.assert_allclose(R[0], np.cross(SIDEWAYS, (0.0, 0.0, 1.0)), atol=1e-15)
    assert law.frame_direction == SIDEWAYS


def test_reference_is_the_old_keyword_of_frame_direction_and_warns(ur5, plane):
    new = hybrid.decoupling_law(ur5, plane, frame_direction=SIDEWAYS)
    with pytest.warns(DeprecationWarning, match="decoupling_law: 'reference' is renamed 'frame_direction'"):
        old = hybrid.decoupling_law(ur5, plane, reference=SIDEWAYS)
    assert old.frame_direction == new.frame_direction == SIDEWAYS
    with pytest.warns(DeprecationWarning, match="'reference' is renamed 'frame_direction'"):
        assert old.reference == SIDEWAYS
    p, v = np.array([0.4, 0.1, 0.1]), np.array([0.1, 0.0, 0.0])
    with pytest.warns(DeprecationWarning, match="task_frame: 'reference' is renamed 'frame_direction'"):
        got = hybrid.task_frame(plane, p, v, reference=SIDEWAYS)
    np.testing.assert_array_equal(got[0], hybrid.task_frame(plane, p, v, frame_direction=SIDEWAYS)[0])
    with pytest.warns(DeprecationWarning, match="DecouplingLaw: 'reference'"):
        assert hybrid.DecouplingLaw(ur5, plane, reference=SIDEWAYS).frame_direction == SIDEWAYS
    with pytest.warns(DeprecationWarning), pytest.raises(hybrid.HybridError, match="give frame_direction alone"):
        hybrid.decoupling_law(ur5, plane, reference=SIDEWAYS, frame_direction=SIDEWAYS)


def test_the_controller_takes_reference_as_frame_direction(ur5, plane):
    new = hybrid.Controller(ur5, plane, frame_direction=SIDEWAYS)
    with pytest.warns(DeprecationWarning, match="Controller: 'reference' is renamed 'frame_direction'"):
        old = hybrid.Controller(ur5, plane, reference=SIDEWAYS)
    assert old.frame_direction == new.frame_direction == SIDEWAYS
    np.testing.assert_array_equal(old.step_inputs()["e"], SIDEWAYS)
    with pytest.warns(DeprecationWarning, match="'reference' is renamed 'frame_direction'"):
        assert new.reference == SIDEWAYS


def test_an_experiment_takes_reference_as_frame_direction():
    new = hybrid.tracing_experiment(frame_direction=SIDEWAYS)
    assert new.frame_direction == SIDEWAYS
    with pytest.warns(DeprecationWarning, match="tracing_experiment: 'reference' is renamed 'frame_direction'"):
        assert hybrid.tracing_experiment(reference=SIDEWAYS) == new
    with pytest.warns(DeprecationWarning, match="Experiment: 'reference' is renamed 'frame_direction'"):
        assert hybrid.Experiment(robot=new.robot, surface=new.surface, reference=SIDEWAYS) == \
            hybrid.Experiment(robot=new.robot, surface=new.surface, frame_direction=SIDEWAYS)
    with pytest.warns(DeprecationWarning, match="Experiment: 'reference'"):  # replace passes every field beside
        assert dataclasses.replace(hybrid.tracing_experiment(), reference=SIDEWAYS) == new
    with pytest.warns(DeprecationWarning, match="'reference' is renamed 'frame_direction'"):
        assert new.reference == SIDEWAYS
    assert "reference" not in new.to_dict() and new.to_dict()["frame_direction"] == list(SIDEWAYS)


def test_a_sweep_names_frame_direction_by_its_old_name_too():
    assert setting_path("reference") == "frame_direction"
    check_names(hybrid.tracing_experiment(), ["reference"])
    assert apply(hybrid.tracing_experiment(), {"reference": SIDEWAYS}).frame_direction == SIDEWAYS


def test_a_controller_file_with_reference_reads_as_frame_direction(tmp_path, ur5):
    example = Path(hybrid.__file__).resolve().parent / "data" / "controller_ur5_sphere.toml"
    text = example.read_text()
    assert text.count("frame_direction = [0.0, 0.0, 1.0]") == 1
    old = tmp_path / "old.toml"
    old.write_text(text.replace("frame_direction = [0.0, 0.0, 1.0]", "reference = [1.0, 0.0, 0.0]"))
    new = tmp_path / "new.toml"
    new.write_text(text.replace("frame_direction = [0.0, 0.0, 1.0]", "frame_direction = [1.0, 0.0, 0.0]"))
    line = next(n for n, s in enumerate(old.read_text().splitlines(), 1) if s.startswith("reference"))
    warned = f"old.toml:{line}: \\[task\\]: 'reference' is renamed 'frame_direction'"
    with pytest.warns(DeprecationWarning, match=warned):
        got = hybrid.read_controller_config(old, ur5)
    assert got.frame_direction == hybrid.read_controller_config(new, ur5).frame_direction == SIDEWAYS
    both = tmp_path / "both.toml"
    both.write_text(text.replace("frame_direction = [0.0, 0.0, 1.0]", "frame_direction = [1.0, 0.0, 0.0]\n"
                                 "reference = [1.0, 0.0, 0.0]"))
    with pytest.raises(hybrid.HybridError, match="task.reference: and frame_direction are both given"):
        hybrid.read_controller_config(both, ur5)


# ------------------------------------------------------------------ step -> integration_step


def test_the_integration_step_is_the_plants_rk4_step():
    exp = hybrid.paper_experiment(integration_step=5e-5, duration=0.02)
    assert exp.steps_per_sample == 200  # 10 ms samples of 0.05 ms integration steps
    res = hybrid.simulate(exp)
    np.testing.assert_allclose(np.diff(res.t), 5e-5, rtol=1e-9)


def test_step_is_the_old_name_of_integration_step_and_warns():
    new = hybrid.paper_experiment(integration_step=5e-5)
    with pytest.warns(DeprecationWarning, match="paper_experiment: 'step' is renamed 'integration_step'"):
        assert hybrid.paper_experiment(step=5e-5) == new
    with pytest.warns(DeprecationWarning, match="Experiment: 'step' is renamed 'integration_step'"):
        assert dataclasses.replace(hybrid.paper_experiment(), step=5e-5) == new
    with pytest.warns(DeprecationWarning, match="'step' is renamed 'integration_step'"):
        assert new.step == 5e-5
    with pytest.warns(DeprecationWarning), pytest.raises(hybrid.HybridError, match="integration_step = 0.001 s is too "
                                                                                     "large for the contact"):
        hybrid.paper_experiment(step=1e-3)
    assert "step" not in new.to_dict() and new.to_dict()["integration_step"] == 5e-5


def test_a_sweep_over_step_sweeps_the_integration_step(tmp_path):
    from hybrid.plots import label

    base, values = hybrid.paper_experiment(duration=0.05), [1e-4, 5e-5]
    new = hybrid.sweep(base, {"integration_step": values}, workers=1)
    with pytest.warns(DeprecationWarning, match="sweep: 'step' is renamed 'integration_step'"):
        old = hybrid.sweep(base, {"step": values}, out=tmp_path / "s", workers=1)
    pd.testing.assert_frame_equal(old.rename(columns={"step": "integration_step"}), new)
    assert label("step") == label("integration_step") == "integration step [s]"
    # the folder resumes under the new name: its parts are the same runs
    parts = {p.name: p.stat().st_mtime_ns for p in (tmp_path / "s" / "parts").iterdir()}
    again = hybrid.sweep(base, {"integration_step": values}, out=tmp_path / "s", workers=1)
    pd.testing.assert_frame_equal(again, new)
    assert {p.name: p.stat().st_mtime_ns for p in (tmp_path / "s" / "parts").iterdir()} == parts

# ------------------------------------------------------------------ files written before the renames

#: the keys a saved experiment had before the renames, by their new names (written out: not read from the
#: library's own table, which the test checks)
OLD_KEYS = {"frame_direction": "reference", "integration_step": "step"}


def _as_saved_before(d: dict) -> dict:
    """An experiment's dict as the library wrote it before the renames: the old keys, in their place."""
    return {OLD_KEYS.get(k, k): v for k, v in d.items()}


@pytest.mark.parametrize("make", [hybrid.paper_experiment, lambda: hybrid.tracing_experiment(
    frame_direction=SIDEWAYS)], ids=["paper", "tracing"])
def test_an_experiment_saved_before_the_renames_reads_back_equal(make, recwarn):
    exp = make()
    saved = json.loads(json.dumps(_as_saved_before(exp.to_dict())))
    assert set(OLD_KEYS.values()) <= set(saved) and not set(OLD_KEYS) & set(saved)
    assert hybrid.Experiment.from_dict(saved) == exp
    assert not [w for w in recwarn if issubclass(w.category, DeprecationWarning)]  # a file is not the reader's
    assert set(OLD_KEYS) <= set(exp.to_dict()) and not set(OLD_KEYS.values()) & set(exp.to_dict())


def test_a_sweep_folder_written_before_the_renames_resumes(tmp_path):
    base, grid = hybrid.paper_experiment(duration=0.05), {"model_error": [0.0, 0.1]}
    out = tmp_path / "sweep"
    first = hybrid.sweep(base, grid, out=out, workers=1)
    spec = out / "sweep.json"
    written = json.loads(spec.read_text())
    before = {**written, "base": _as_saved_before(written["base"])}
    spec.write_text(json.dumps(before, indent=2, sort_keys=True) + "\n")
    parts = {p.name: p.stat().st_mtime_ns for p in (out / "parts").iterdir()}
    again = hybrid.sweep(base, grid, out=out, workers=1)  # the same sweep: resumed, not refused
    pd.testing.assert_frame_equal(again, first)
    assert {p.name: p.stat().st_mtime_ns for p in (out / "parts").iterdir()} == parts  # nothing run again
    assert json.loads(spec.read_text()) == written  # now by the new names


def test_the_command_line_tells_an_old_setting_name_and_takes_it(tmp_path, capsys):
    from hybrid.cli.main import main

    assert main(["generate", "--experiment", "paper", "--set", "frame_direction=[0, 0, 1]", "--out",
                 str(tmp_path / "new")]) == 0
    assert "warning" not in capsys.readouterr().err
    assert main(["generate", "--experiment", "paper", "--set", "reference=[0, 0, 1]", "--out",
                 str(tmp_path / "old")]) == 0
    assert "warning: paper_experiment: 'reference' is renamed 'frame_direction'" in capsys.readouterr().err
    new, old = (sorted((tmp_path / d).iterdir()) for d in ("new", "old"))
    assert [p.name for p in old] == [p.name for p in new] and all(a.read_bytes() == b.read_bytes()
                                                                  for a, b in zip(old, new))
