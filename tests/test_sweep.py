"""Sweeps: rows equal one-by-one runs, failures are rows, resuming and the Dask engine change nothing."""

from __future__ import annotations

import dataclasses
import json
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import hybrid
from hybrid.sweeps import Uniform, apply, check_names, points, sweep

BASE = hybrid.paper_experiment(duration=0.6)
GRID = {"model_error": [0.0, 0.3], "contact.friction": [0.0, 0.2], "controller": ["task", "khatib"]}


def assert_same_metrics(row, metrics):
    for name, value in metrics.items():
        if isinstance(value, float) and math.isnan(value):
            assert math.isnan(row[name]), name
        else:
            assert row[name] == pytest.approx(value, rel=1e-6, abs=1e-12), name


def test_rows_equal_individual_runs():
    table = sweep(BASE, {"model_error": Uniform(0.0, 0.4), "gains.KPf": [1.5, 2.0], "F_d": [8.0, 12.0]},
                  samples=6, seed=3, workers=2)
    assert list(table["run"]) == list(range(6)) and (table["status"] == "ok").all()
    for _, row in table.iloc[[0, 3, 5]].iterrows():
        exp = hybrid.paper_experiment(duration=0.6, model_error=row["model_error"], KPf=row["gains.KPf"],
                                      F_d=row["F_d"])
        assert_same_metrics(row, hybrid.simulate(exp).metrics)


def test_a_sweep_is_its_runs_simulated_one_by_one_to_the_bit():
    """Runs prepared from others alike (the model error, the contact differ) and in lanes beside others."""
    grid = {"model_error": [0.0, 0.25, -0.0, 0.25], "contact.friction": [0.1, 0], "controller": ["task", "khatib"]}
    table = sweep(BASE, grid, workers=2, chunk_size=8)
    assert (table["status"] == "ok").all()
    for (_, row), point in zip(table.iterrows(), points(grid)):
        for name, value in hybrid.simulate(apply(BASE, point)).metrics.items():
            assert row[name] == value or (math.isnan(value) and math.isnan(row[name])), (point, name)


#: every setting a run can be prepared alike in (closed_loop.ROW_SETTINGS): repeated values, a whole number, -0.0,
#: refused values
ALIKE = {"model_error": [0.2, 0, -0.0, -1.5, 0.2], "viscous_compensation": [0.5, -0.0],
         "contact.stiffness": [1e5, 5e4, 1e12], "contact.damping": [50.0, 0.0], "contact.friction": [0.1, -0.0, -0.1],
         "contact.friction_smoothing": [1e-3, 2e-3], "sensor.mass": [0.025, 0.05, 0.0],
         "sensor.stiffness": [1000.0, 800], "sensor.damping": [7.0, 5.0]}


@pytest.mark.parametrize("names", [(name,) for name in ALIKE] + [tuple(ALIKE)], ids=[*ALIKE, "all"])
@pytest.mark.parametrize("base", [
    hybrid.paper_experiment(duration=0.02),
    hybrid.tracing_experiment(duration=0.02, start_gap=0.002, approach_speed=0.05),  # the sensor's mass sags it
], ids=["paper", "tracing"])
def test_runs_prepared_alike_are_the_runs_prepared_alone(base, names, monkeypatch):
    """Each run of a chunk that sweeps settings of ALIKE (each alone: the parts of the row it reaches; all at
    once) and settings that do not make runs alike (a scheme; a sensor's noise, whose runs the Python runner
    runs), is refused as it is alone, or its prepared row is the row it has alone, to the bit."""
    from hybrid.simulation import closed_loop
    from hybrid.sweeps import plan

    assert set(ALIKE) == set(closed_loop.ROW_SETTINGS)
    real, alike = closed_loop.prepare_alike, []
    monkeypatch.setattr(closed_loop, "prepare_alike", lambda *args: alike.append(args) or real(*args))
    grid = {**{name: ALIKE[name] for name in names}, "controller": ["task", "khatib"], "sensor.force_noise": [0.0, 0.5]}
    chunk = list(enumerate(points(grid, samples=300, seed=2) if len(names) > 1 else points(grid)))
    rows, compiled = plan._prepared(base, chunk)
    prepared = {index: p for index, _, _, p in compiled}
    for index, settings in chunk:
        try:
            alone = closed_loop.prepare(apply(base, settings))
        except hybrid.HybridError as exc:
            assert rows[index]["status"] == "invalid" and rows[index]["error"] == str(exc).splitlines()[0]
            continue
        if alone is None:
            assert rows[index]["status"] == "ok" and index not in prepared
            continue
        got = prepared[index]
        assert got.loop is alone.loop and got.settings == alone.settings and got.experiment == alone.experiment
        assert got.row.tobytes() == alone.row.tobytes(), settings
    assert len(alike) >= len(compiled) - 2  # all but the first run of each scheme, in the compiled loop


def test_grid_is_the_product_and_names_are_kept():
    grid = points(GRID)
    assert len(grid) == 8 and len({json.dumps(p, sort_keys=True) for p in grid}) == 8
    table = sweep(BASE, GRID, workers=1)
    assert list(table.columns[:4]) == ["run", "model_error", "contact.friction", "controller"]
    assert {"force_overshoot_N", "rms_speed_error_m_per_s", "status", "error"} <= set(table.columns)
    assert apply(BASE, {"contact.friction": 0.3, "KIf": 5.0}).contact.friction == 0.3


def test_a_failing_run_is_a_row_with_its_cause():
    # predicted unstable, a run is refused (an invalid row saying so); allowed, it diverges (a failed one)
    refused = sweep(BASE, {"model_error": [5.0]}, workers=1)
    assert (refused["status"] == "invalid").all() and refused["error"].str.contains("unstable").all()
    table = sweep(dataclasses.replace(BASE, allow_unstable=True), {"model_error": [0.0, 5.0, 0.1],
                                                                  "gains.KPv": [40.0, -1.0]}, workers=2)
    assert len(table) == 6
    bad_gain = table[table["gains.KPv"] < 0]
    assert (bad_gain["status"] == "invalid").all() and bad_gain["error"].str.contains("negative").all()
    diverged = table[(table["model_error"] == 5.0) & (table["gains.KPv"] > 0)]
    assert (diverged["status"] == "failed").all() and diverged["error"].str.contains("t = ").all()
    assert ((table["model_error"] < 1) & (table["gains.KPv"] > 0)).sum() == (table["status"] == "ok").sum()


def test_resume_after_an_interruption_gives_the_same_table(tmp_path):
    whole = sweep(BASE, GRID, workers=2)
    out = tmp_path / "sweep"
    sweep(BASE, GRID, out=out, workers=2, chunk_size=2)
    parts = sorted((out / "parts").glob("*.parquet"))
    for part in parts[1::2]:  # as if stopped with half of the chunks written
        part.unlink()
    (out / "results.parquet").unlink()
    resumed = sweep(BASE, GRID, out=out, workers=2, chunk_size=3, csv=True)
    pd.testing.assert_frame_equal(resumed, whole)
    pd.testing.assert_frame_equal(pd.read_parquet(out / "results.parquet"), whole)
    assert (out / "results.csv").read_text().splitlines()[0].startswith("run,model_error,contact.friction")
    with pytest.raises(hybrid.HybridError, match="different sweep"):
        sweep(BASE, {"model_error": [0.0]}, out=out)


def test_an_interrupted_cli_sweep_resumes(tmp_path):
    """Stop the command while it runs (SIGINT, as Ctrl-C), run it again: the table is the uninterrupted one."""
    config = tmp_path / "s.toml"
    config.write_text('experiment = "paper"\n[base]\nduration = 0.6\n[parameters]\n'
                      'model_error = [0.0, 0.1, 0.2, 0.3]\n"contact.friction" = [0.0, 0.1, 0.2, 0.3]\n')
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "hybrid", "sweep", str(config), "--out", str(out), "--workers", "1"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while time.time() < deadline and not list((out / "parts").glob("*.parquet")):
        time.sleep(0.05)
    proc.send_signal(2)
    proc.communicate(timeout=60)
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    again = pd.read_parquet(out / "results.parquet")
    whole = sweep(BASE, {"model_error": [0.0, 0.1, 0.2, 0.3], "contact.friction": [0.0, 0.1, 0.2, 0.3]}, workers=2)
    pd.testing.assert_frame_equal(again, whole)
    assert "16 runs" in done.stdout


def test_dask_engine_gives_the_same_table_and_survives_a_killed_worker():
    distributed = pytest.importorskip("dask.distributed")
    local = sweep(BASE, GRID, workers=2)
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    try:
        pd.testing.assert_frame_equal(sweep(BASE, GRID, engine="dask", client=client), local)
        # kill one worker's process while the sweep runs: its chunks are computed again elsewhere
        killed = []

        pids = client.run(os.getpid)

        def kill_one():
            time.sleep(1.0)
            worker, pid = next(iter(pids.items()))
            os.kill(pid, signal.SIGKILL)
            killed.append(worker)

        big = {**GRID, "gains.KDf": [80.0, 90.0, 100.0]}
        thread = threading.Thread(target=kill_one)
        thread.start()
        table = sweep(BASE, big, engine="dask", client=client, chunk_size=1)
        thread.join()
        assert killed and len(table) == 24 and list(table["run"]) == list(range(24))
        pd.testing.assert_frame_equal(table, sweep(BASE, big, workers=2))
    finally:
        client.close()
        cluster.close()


def test_cli_sweep_writes_table_and_heatmaps(tmp_path):
    config = tmp_path / "s.toml"
    config.write_text('experiment = "paper"\n[base]\nduration = 0.6\nF_d = {before = 10.0, after = 15.0, at = 0.3}\n'
                      '[parameters]\nmodel_error = [0.0, 0.2]\n"contact.friction" = {uniform = [0.0, 0.3]}\n'
                      'controller = ["task", "khatib"]\n[sweep]\nsamples = 6\nseed = 2\n'
                      '[figures]\nx = "model_error"\ny = "contact.friction"\nrows = "controller"\n'
                      'metrics = ["rms_force_error_N"]\n')
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "hybrid", "sweep", str(config), "--out", str(out), "--csv"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    table = pd.read_csv(out / "results.csv")
    assert len(table) == 6 and (out / "heatmap_rms_force_error_N.png").stat().st_size > 1000
    assert "6/6 runs" in done.stderr  # the progress bar


@pytest.mark.parametrize("text, words", [
    ('[parameters]\nbogus = [1]\n', "unknown setting 'bogus'"),
    ('[parameters]\nmodel_error = {uniform = [0, 1]}\n', "needs samples"),
    ('[parameters]\nmodel_error = 3\n', "list of values"),
    ('stuff = 1\n[parameters]\nmodel_error = [0]\n', "unknown key"),
    ('[parameters\n', "not valid TOML"),
    ('experiment = "moon"\n[parameters]\nmodel_error = [0]\n', "give one of 'paper', 'tracing', 'panda'"),
    ('[parameters]\nmodel_error = {uniform = 0.3}\n', "takes two numbers"),
    ('base = 3\n[parameters]\nmodel_error = [0]\n', "must be a table"),
    ('[parameters]\nmodel_error = [0]\n[figures]\nx = "model_error"\ny = "speed"\n', "not a swept parameter"),
    ('[parameters]\nmodel_error = [0]\n"contact.friction" = [0]\n[figures]\nx = "model_error"\n'
     'y = "contact.friction"\nmetrics = ["fun"]\n', "metric names"),
])
def test_bad_sweep_files_are_one_line(tmp_path, text, words):
    config = tmp_path / "s.toml"
    config.write_text(text)
    done = subprocess.run([sys.executable, "-m", "hybrid", "sweep", str(config), "--out", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and words in done.stderr and len(done.stderr.strip().splitlines()) == 1


def test_a_3d_sweep_runs():
    table = sweep(hybrid.tracing_experiment(duration=0.3), {"controller": ["task", "khatib"]}, workers=1)
    assert (table["status"] == "ok").all() and np.isfinite(table["rms_force_error_N"]).all()


def test_the_demo_config_reads():
    from hybrid.cli import sweep as sweep_cli

    config = sweep_cli.read_config(sweep_cli.DEMO)
    base = sweep_cli._base(config["experiment"], config["base"])
    check_names(base, config["parameters"])
    values = {k: sweep_cli._value(k, v) for k, v in config["parameters"].items()}
    assert len(points(values)) == 10140  # docs/studies/demo_sweep.md reads this many runs
    assert values["model_error"][:3] == [0.0, 0.02, 0.04] and values["model_error"][-1] == 0.5


def test_linspace_values_and_refusals():
    from hybrid.cli import sweep as sweep_cli

    got = sweep_cli._value("x", {"linspace": [0.1, 0.7, 7]})
    np.testing.assert_allclose(got, np.linspace(0.1, 0.7, 7), rtol=1e-12)
    assert got[2] == 0.3 and sweep_cli._value("x", {"linspace": [2, 5, 1]}) == [2.0]
    assert sweep_cli._value("x", {"linspace": [-0.1, 0.2, 4]})[1] == 0.0  # not 1.4e-17
    close = sweep_cli._value("x", {"linspace": [1.0, 1.0 + 1e-12, 5]})  # the rounding follows the span
    assert len(set(close)) == 5 and close[-1] == 1.0 + 1e-12
    for bad in ([0.0, 1.0], [0.0, 1.0, 2.5], [0.0, float("nan"), 3], [0.0, 1.0, 0], "0:1", [0.0, 1.0, True],
                [0, 10**400, 3], ["0", "1", 3]):
        with pytest.raises(hybrid.HybridError, match="linspace takes"):
            sweep_cli._value("x", {"linspace": bad})
    with pytest.raises(hybrid.HybridError, match="to itself"):
        sweep_cli._value("x", {"linspace": [1.0, 1.0, 3]})
    with pytest.raises(hybrid.HybridError, match="linspace = "):  # a table with more: the message names it
        sweep_cli._value("x", {"linspace": [0.0, 1.0, 3], "uniform": [0.0, 1.0]})


def test_the_demo_study_pages_sweep_example_runs():
    import re

    page = Path(__file__).resolve().parent.parent / "docs" / "studies" / "demo_sweep.md"
    block = next(b for b in re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S) if "hybrid.sweep(" in b)
    ns: dict = {}
    exec(compile(block, str(page), "exec"), ns)
    table = ns["table"]
    assert len(table) == 40 and (table["status"] == "ok").all()
    row = table.iloc[7]
    exp = hybrid.paper_experiment(duration=1.0, model_error=row["model_error"], controller=row["controller"],
                                  contact=hybrid.Contact(friction=row["contact.friction"]))
    assert_same_metrics(row, hybrid.simulate(exp).metrics)


def test_resume_refuses_what_is_not_the_same_sweep(tmp_path):
    out = tmp_path / "s"
    grid = {"model_error": [0.0, 0.1], "controller": ["task", "khatib"]}
    sweep(BASE, grid, out=out, workers=1)
    with pytest.raises(hybrid.HybridError, match="different sweep"):  # the order numbers the runs
        sweep(BASE, dict(reversed(list(grid.items()))), out=out, workers=1)
    (out / "sweep.json").unlink()
    with pytest.raises(hybrid.HybridError, match="no sweep.json"):
        sweep(BASE, {"model_error": [0.5, 0.6], "controller": ["task", "khatib"]}, out=out, workers=1)
    fresh = sweep(BASE, {"model_error": [0.5, 0.6], "controller": ["task", "khatib"]}, out=out, workers=1, force=True)
    assert sorted(fresh["model_error"].unique()) == [0.5, 0.6]
    heavier = hybrid.tracing_experiment(duration=0.02, robot=hybrid.ur5().with_model_error(0.5, 1.0))
    assert hybrid.tracing_experiment(duration=0.02).to_dict()["robot"] != heavier.to_dict()["robot"]


def test_a_second_sweep_into_the_same_folder_is_refused(tmp_path):
    from hybrid.sweeps.store import _lock

    out = tmp_path / "s"
    out.mkdir()
    held = _lock(out)
    try:
        with pytest.raises(hybrid.HybridError, match="another sweep"):
            sweep(BASE, {"model_error": [0.0]}, out=out)
    finally:
        held.close()
    assert len(sweep(BASE, {"model_error": [0.0]}, out=out)) == 1


@pytest.mark.parametrize("kwargs, words", [
    (dict(parameters={"contact": [hybrid.Contact()], "contact.friction": [0.1]}), "same setting"),
    (dict(parameters={"KPf": [1.0], "gains.KPf": [2.0]}), "same setting"),
    (dict(parameters={"force_reference": [hybrid.Step(1, 2, 0.1)]}), "not a number, text or boolean"),
    (dict(parameters={"model_error": [0.0, "bad"]}), "mixes"),
    (dict(parameters={"model_error": [0.0]}, chunk_size=-1), "chunk_size"),
    (dict(parameters={"model_error": [0.0]}, workers="2"), "workers"),
    (dict(parameters={"model_error": Uniform(0, 1)}, samples=3, seed=-1), "seed"),
])
def test_bad_sweep_arguments_are_named(kwargs, words):
    parameters = kwargs.pop("parameters")
    with pytest.raises(hybrid.HybridError, match=words):
        sweep(BASE, parameters, **kwargs)


def test_bad_distributions_and_bases_are_named(tmp_path):
    from hybrid.sweeps import LogUniform, Normal

    for make in (lambda: Normal(0, -1), lambda: Uniform("a", 1), lambda: Uniform(float("nan"), 1),
                 lambda: LogUniform(0, 1), lambda: sweep("paper", {"model_error": [0.0]}),
                 lambda: sweep(BASE, {"model_error": [0.0]}, out=tmp_path / "file" / "below")):
        if make is not None:
            (tmp_path / "file").write_text("")
        with pytest.raises(hybrid.HybridError):
            make()


def test_a_run_that_breaks_unexpectedly_is_a_row(monkeypatch):
    import hybrid.simulation.closed_loop as closed_loop

    def broken(real, at: int):
        def prepare(*args, **kwargs):
            if args[at].model_error > 0.2:
                raise ZeroDivisionError("a defect")
            return real(*args, **kwargs)
        return prepare

    # a run prepared whole (the first that starts), and one prepared from it (its model error differs only)
    monkeypatch.setattr(closed_loop, "prepare", broken(closed_loop.prepare, 0))
    monkeypatch.setattr(closed_loop, "prepare_alike", broken(closed_loop.prepare_alike, 1))
    table = sweep(BASE, {"model_error": [0.3, 0.0, 0.3]}, workers=1)
    assert list(table["status"]) == ["error", "ok", "error"] and "ZeroDivisionError" in table["error"][2]


DEEP = 2000


@pytest.mark.parametrize("text, words", [
    ('[parameters]\nmodel_error = ' + "{a = " * DEEP + "1" + "}" * DEEP + "\n", "nested too deeply to read"),
    ('[parameters]\nmodel_error = ' + "[" * DEEP + "0" + "]" * DEEP + "\n", "nested too deeply to read"),
    ('[parameters]\nmodel_error.' + ".".join(["a"] * DEEP) + " = 1\n", "parameters.model_error.a.a... is nested"),
    ('[parameters]\nmodel_error = [{' + "a." * DEEP + "b = 1}]\n", "is nested more than 16"),
    ('[parameters]\nmodel_error = [0]\n[sweep]\nseed.' + ".".join(["a"] * DEEP) + " = 1\n", "sweep.seed.a.a..."),
    ('[parameters]\nmodel_error = [0]\n[base]\ncontact.' + ".".join(["a"] * 40) + " = 1\n", "base.contact"),
    ('experiment = {name = "paper"}\n[parameters]\nmodel_error = [0]\n', "experiment = {'name': 'paper'}; give"),
    ('[parameters]\nmodel_error = [0]\n[figures]\nx = {a = 1}\ny = "model_error"\n', "x = {'a': 1} is not a swept"),
    ('[parameters]\nmodel_error = [0]\n[figures]\nx = "model_error"\ny = "model_error"\nmetrics = [{a = 1}]\n',
     "metric names"),
])
def test_deep_or_mistyped_sweep_files_are_one_line(tmp_path, capsys, text, words):
    """Tables nested thousands deep, or a table where a name belongs: an error, never a RecursionError."""
    from hybrid.cli.main import main

    config = tmp_path / "s.toml"
    config.write_text(text)
    assert main(["sweep", str(config), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1 and len(err) < 600, err[:700]
