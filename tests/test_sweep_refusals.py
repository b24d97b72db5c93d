"""Bad input to sweeps and batched calls: a HybridError first, in words, before any allocation,
connection wait or overwrite; never a foreign exception, a hang or a huge allocation."""

from __future__ import annotations

import os
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hybrid
from hybrid import sweeps
from hybrid.sweeps import LogUniform, Normal, Uniform, sweep

BASE = hybrid.paper_experiment(duration=0.02)
CLOSED = "tcp://127.0.0.1:1"  # loopback, a port nothing listens on: no traffic leaves the machine


def refused(call, words: str = "") -> str:
    """The first line of the HybridError ``call()`` raises (containing ``words``)."""
    with pytest.raises(hybrid.HybridError) as info:
        call()
    first = str(info.value).splitlines()[0]
    assert words in first, first
    return first


def views(N: int, size: int) -> np.ndarray:
    """N equal states as a broadcast view: no memory of their own, as a user's could be."""
    return np.broadcast_to(np.linspace(0.2, 0.4, size), (N, size))


# ------------------------------------------------------------------ sizes before allocation


@pytest.mark.parametrize("N", [10**8, 10**9, 10**12])
def test_a_batch_too_big_for_memory_is_refused_with_its_numbers(N):
    ur5 = hybrid.ur5()
    first = refused(lambda: hybrid.arm_terms(ur5, views(N, 6), views(N, 6)), f"{N:,} states of robot_terms")
    assert "GiB; this machine has" in first and "fewer states" in first
    law = hybrid.decoupling_law(ur5, hybrid.Plane((0.0, 0.0, 1.0), (0.0, 0.0, 0.2)))
    for call in (lambda: law(views(N, 6), views(N, 6), views(N, 6), views(N, 6)),
                 lambda: law.torque(views(N, 6), views(N, 6), views(N, 6), views(N, 6)),
                 lambda: law.evaluate(views(N, 6), views(N, 6), views(N, 6), views(N, 6), tau0=views(N, 6))):
        assert f"{N:,} states of " in refused(call, "GiB; this machine has")


def test_a_planar_batch_and_a_task_frame_batch_too_big_are_refused():
    law = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.0, 0.0), 0.25))
    refused(lambda: law(views(10**9, 2), views(10**9, 2), views(10**9, 2), views(10**9, 2)), "1,000,000,000 states")
    plane = hybrid.Plane((0.0, 0.0, 1.0), (0.0, 0.0, 0.2))
    refused(lambda: hybrid.task_frame(plane, views(10**10, 3), views(10**10, 3)), "states of r")


def test_the_limit_is_the_one_shared_setting(monkeypatch):
    """One helper sizes every request: lowering its fraction refuses a small batch and a small sweep."""
    import hybrid.validate as validate

    small = views(1000, 6)
    assert hybrid.arm_terms(hybrid.ur5(), small, small)["J"].shape == (1000, 6, 6)
    monkeypatch.setattr(validate, "MEMORY_FRACTION", 1e-9)
    refused(lambda: hybrid.arm_terms(hybrid.ur5(), small, small), "1,000 states")
    refused(lambda: sweeps.points({"model_error": [0.0] * 100}), "100 runs")


@pytest.mark.parametrize("parameters, samples, words", [
    ({"model_error": Uniform(0, 1)}, 10**12, "samples = 1,000,000,000,000 runs"),
    ({"model_error": [0.0, 0.1]}, 10**30, "samples = about 10^30 runs"),
    ({"model_error": Normal(0, 1)}, 10**300 * 10**300, "about 10^600 runs"),
    ({"model_error": [0.0] * 10**6, "contact.friction": [0.0] * 10**6}, None, "1000000 x 1000000 values"),
    ({f"gains.{g}": [1.0] * 100 for g in ("KPf", "KIf", "KPv", "KDf", "KIv")}, None, "100 x 100 x 100 x 100 x 100"),
])
def test_a_sweep_too_big_for_memory_is_refused_before_any_point(parameters, samples, words):
    t0 = time.perf_counter()
    first = refused(lambda: sweep(BASE, parameters, samples=samples), words)
    assert "GiB; this machine has" in first and time.perf_counter() - t0 < 10


def test_too_many_workers_are_refused():
    refused(lambda: sweep(BASE, {"model_error": [0.0]}, workers=10**6), "workers = 1,000,000 processes")
    refused(lambda: sweep(BASE, {"model_error": [0.0]}, workers=10**5000), "about 10^5000 processes")


def test_a_sweep_file_of_two_million_value_parameters_is_one_line(tmp_path):
    config = tmp_path / "s.toml"
    config.write_text('[parameters]\nmodel_error = {linspace = [0.0, 0.5, 1000000]}\n'
                      '"contact.friction" = {linspace = [0.0, 0.3, 1000000]}\n')
    done = subprocess.run([sys.executable, "-m", "hybrid", "sweep", str(config), "--out", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "1,000,000,000,000 runs" in done.stderr and not (tmp_path / "o" / "parts").exists()


# ------------------------------------------------------------------ Dask errors


@pytest.mark.parametrize("client, words", [
    (5, "client must be a dask.distributed.Client"),
    (object(), "client must be a dask.distributed.Client"),
    ("not an address", "is not one"),
    ("127.0.0.1:99999", "is not one"),
    ("", "is not one"),
    ("tcp://", "is not one"),
    ("gopher://127.0.0.1:8786", "is not one"),
    ("tcp://127.0.0.1", "is not one"),
])
def test_a_client_of_the_wrong_type_or_a_malformed_address_is_refused_at_once(client, words):
    pytest.importorskip("dask.distributed")
    t0 = time.perf_counter()
    refused(lambda: sweep(BASE, {"model_error": [0.0]}, engine="dask", client=client), words)
    assert time.perf_counter() - t0 < 3


@pytest.mark.parametrize("address", [CLOSED, "127.0.0.1:1"])
def test_an_unreachable_scheduler_is_refused_within_the_timeout(address):
    pytest.importorskip("dask.distributed")
    t0 = time.perf_counter()
    first = refused(lambda: sweep(BASE, {"model_error": [0.0]}, engine="dask", client=address, connect_timeout=1),
                    "could not reach the Dask scheduler")
    assert "within 1 s" in first and time.perf_counter() - t0 < 8


def test_a_closed_client_a_client_for_local_and_a_bad_timeout_are_refused():
    distributed = pytest.importorskip("dask.distributed")
    client = distributed.Client(processes=False, dashboard_address=None, n_workers=1, threads_per_worker=1)
    client.close()
    refused(lambda: sweep(BASE, {"model_error": [0.0]}, engine="dask", client=client), "the Dask client is closed")
    refused(lambda: sweep(BASE, {"model_error": [0.0]}, client=CLOSED), "client is for engine='dask'")
    for bad in (0, -1, float("nan"), float("inf"), "5", True):
        refused(lambda bad=bad: sweep(BASE, {"model_error": [0.0]}, engine="dask", client=CLOSED,
                                      connect_timeout=bad), "connect_timeout")


@pytest.mark.parametrize("extra, words", [
    (["--engine", "dask", "--scheduler", CLOSED, "--connect-timeout", "1"], "within 1 s"),
    (["--engine", "dask", "--scheduler", "nonsense"], "is not one"),
    (["--scheduler", CLOSED], "--scheduler is for --engine dask"),
    (["--engine", "dask", "--scheduler", CLOSED, "--connect-timeout", "nan"], "argument --connect-timeout"),
])
def test_cli_dask_failures_are_one_line(tmp_path, extra, words):
    pytest.importorskip("dask.distributed")
    config = tmp_path / "s.toml"
    config.write_text('[base]\nduration = 0.02\n[parameters]\nmodel_error = [0.0]\n')
    done = subprocess.run([sys.executable, "-m", "hybrid", "sweep", str(config), "--out", str(tmp_path / "o"), *extra],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and words in done.stderr, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr


# ------------------------------------------------------------------ the sweep folder


GRID = {"model_error": [0.0, 0.1, 0.2, 0.3]}


@pytest.mark.parametrize("name", ["results.parquet", "results.csv", "heatmap_rms_force_error_N.png",
                                  "parts/part-00000000-00000001.parquet"])
def test_files_without_the_sweeps_description_are_the_users(tmp_path, name):
    out = tmp_path / "s"
    (out / name).parent.mkdir(parents=True)
    (out / name).write_bytes(b"mine")
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "no sweep.json")
    assert (out / name).read_bytes() == b"mine" and not (out / "sweep.json").exists()
    table = sweep(BASE, GRID, out=out, workers=1, force=True)
    pd.testing.assert_frame_equal(pd.read_parquet(out / "results.parquet"), table)
    assert not (out / name).exists() or name == "results.parquet"


def test_a_foreign_sweep_json_is_not_taken_for_a_sweep(tmp_path):
    out = tmp_path / "s"
    out.mkdir()
    (out / "sweep.json").write_text('["my notes"]')
    (out / "results.csv").write_text("mine\n")
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "is not a sweep's")
    assert (out / "results.csv").read_text() == "mine\n"


def _written(tmp_path):
    out = tmp_path / "s"
    whole = sweep(BASE, GRID, out=out, workers=1, chunk_size=2)
    parts = sorted((out / "parts").glob("*.parquet"))
    assert len(parts) == 2
    return out, whole, parts


def _foreign_run(frame):
    frame.loc[0, "model_error"] = 0.7
    return frame


def _foreign_numbers(frame):
    frame["run"] = frame["run"] + 10
    return frame


def _foreign_column(frame):
    frame["notes"] = "mine"
    return frame


def _foreign_type(frame):
    frame["rms_force_error_N"] = "high"
    return frame


def _foreign_status(frame):
    frame["status"] = "great"
    return frame


def _missing_column(frame):
    return frame.drop(columns=["status"])


def _text_parameter(frame):
    frame["model_error"] = frame["model_error"].astype(str)
    return frame


@pytest.mark.parametrize("change, words", [
    (_foreign_run, "has model_error = 0.7"), (_foreign_numbers, "its runs are not"),
    (_foreign_column, "column notes"), (_foreign_type, "is not numbers"), (_foreign_status, "status"),
    (_missing_column, "no column status"), (_text_parameter, "model_error"),
])
def test_a_part_replaced_by_another_table_is_refused_then_redone_with_force(tmp_path, change, words):
    out, whole, parts = _written(tmp_path)
    change(pd.read_parquet(parts[1])).to_parquet(parts[1], index=False)
    (out / "results.parquet").unlink()
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "is not this sweep's")
    assert not (out / "results.parquet").exists()
    with pytest.raises(hybrid.HybridError, match=words):
        sweep(BASE, GRID, out=out, workers=1)
    pd.testing.assert_frame_equal(sweep(BASE, GRID, out=out, workers=1, force=True), whole)


def test_a_part_that_is_not_parquet_or_misnamed_is_refused(tmp_path):
    out, whole, parts = _written(tmp_path)
    parts[1].write_text("not a table")
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "does not read as Parquet")
    parts[1].unlink()
    pd.read_parquet(parts[0]).to_parquet(out / "parts" / "mine.parquet")
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "its name is not")
    pd.testing.assert_frame_equal(sweep(BASE, GRID, out=out, workers=1, force=True), whole)


def test_a_truncated_part_is_refused_then_redone_with_force(tmp_path):
    """A part cut short (what a write in place would leave when killed) is named, never read as rows."""
    out, whole, parts = _written(tmp_path)
    data = parts[1].read_bytes()
    parts[1].write_bytes(data[:len(data) // 2])
    (out / "results.parquet").unlink()
    refused(lambda: sweep(BASE, GRID, out=out, workers=1), "does not read as Parquet")
    assert not (out / "results.parquet").exists()
    pd.testing.assert_frame_equal(sweep(BASE, GRID, out=out, workers=1, force=True), whole)


def test_a_part_whose_write_is_cut_short_is_not_there(tmp_path, monkeypatch):
    """A part is written beside its name and renamed whole: a write stopped halfway (here by an
    interrupt after half its bytes) leaves the parts before it and nothing of its own; the next sweep
    resumes and gives the whole table."""
    out = tmp_path / "s"
    whole = sweep(BASE, GRID, out=tmp_path / "fresh", workers=1, chunk_size=2)
    real, written = pd.DataFrame.to_parquet, []

    def halfway(frame, path, *args, **kwargs):
        written.append(path)
        if len(written) == 2:  # the second part: half its bytes, then stopped
            real(frame, path, *args, **kwargs)
            data = open(path, "rb").read()
            open(path, "wb").write(data[:len(data) // 2])
            raise KeyboardInterrupt
        return real(frame, path, *args, **kwargs)

    monkeypatch.setattr(pd.DataFrame, "to_parquet", halfway)
    with pytest.raises(KeyboardInterrupt):
        sweep(BASE, GRID, out=out, workers=1, chunk_size=2)
    monkeypatch.undo()
    left = sorted(p.name for p in (out / "parts").iterdir())
    assert left == ["part-00000000-00000001.parquet"]
    assert len(pd.read_parquet(out / "parts" / left[0])) == 2
    pd.testing.assert_frame_equal(sweep(BASE, GRID, out=out, workers=1, chunk_size=2), whole)


def test_what_an_interrupted_write_left_is_removed(tmp_path):
    out, whole, _ = _written(tmp_path)
    # temporaries of any process (named as hybrid.files.temporary names them): the sweep's lock says none runs
    left = [out / ".results.parquet.abc123-4242-0a1b2c3d.tmp.parquet", out / ".results.csv.abc123-1-ffffffff.tmp.csv",
            out / ".sweep.json.0f0f0f-77-a1b2c3d4.tmp.json",
            out / "parts" / ".part-00000002-00000003.parquet.abc123-5-01234567.tmp.parquet",
            out / ".hybrid-probe.abc123-9-abcd1234.tmp"]
    kept = [out / ".notes", out / ".results.parquet.backup", out / "parts" / ".keep.abc123-5-01234567.tmp.parquet"]
    for path in left + kept:
        path.write_text("half")
    pd.testing.assert_frame_equal(sweep(BASE, GRID, out=out, workers=1), whole)
    assert not any(p.exists() for p in left) and all(p.read_text() == "half" for p in kept)


def test_a_killed_sweep_leaves_nothing_the_next_one_keeps(tmp_path):
    """SIGKILL (no clean-up can run) while parts are written; the next sweep resumes clean."""
    out = tmp_path / "s"
    grid = {"model_error": [0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35]}
    code = (f"import hybrid; hybrid.sweep(hybrid.paper_experiment(duration=0.6), {grid!r}, out={str(out)!r}, "
            "workers=1, chunk_size=1)")
    proc = subprocess.Popen([sys.executable, "-c", code], env=os.environ)
    deadline = time.time() + 120
    while time.time() < deadline and not list((out / "parts").glob("*.parquet")):
        time.sleep(0.02)
    proc.kill()
    proc.wait(timeout=60)
    # as a kill mid-write leaves it
    (out / "parts" / ".part-00000007-00000007.parquet.abc123-4242-abcdefab.tmp.parquet").write_text("half")
    table = sweep(hybrid.paper_experiment(duration=0.6), grid, out=out, workers=1)
    assert list(table["run"]) == list(range(8)) and not [p for p in out.rglob(".*") if p.name != ".lock"]


# ------------------------------------------------------------------ wrong types


@pytest.mark.parametrize("base, parameters, words", [
    (BASE, [("model_error", [0, 0.1])], "got a list of pairs"),
    (BASE, (("model_error", [0, 0.1]),), "got a list of pairs"),
    (BASE, [["model_error", [0, 0.1]], ["KPf", [1.0]]], "got a list of pairs"),
    (BASE, "model_error", "parameters must be a mapping"),
    (BASE, None, "parameters must be a mapping"),
    (BASE, {}, "parameters is empty"),
    (BASE, {("model_error",): [0.0]}, "setting names (text)"),
    (BASE, {"model_error": {0.0, 0.1}}, "give a list of values"),
    (BASE, {"model_error": 0.1}, "give a list of values"),
    (BASE, {"model_error": np.zeros((2, 2))}, "give a list of values"),
    (BASE, {"model_error": [[0.0, 0.1]]}, "not a number, text or boolean"),
    (BASE, {"model_error": [10**30]}, "64 bits"),
    ({"model_error": [0.0]}, BASE, "the experiment comes first"),
    (hybrid.paper_experiment, {"model_error": [0.0]}, "call it"),
    (hybrid.Experiment, {"model_error": [0.0]}, "the class Experiment"),
    ([("duration", 0.02)], {"model_error": [0.0]}, "base must be an experiment"),
    (None, {"model_error": [0.0]}, "base must be an experiment"),
])
def test_arguments_of_the_wrong_type_are_refused_in_words(base, parameters, words):
    refused(lambda: sweep(base, parameters), words)


def test_run_settings_of_the_wrong_type_are_refused_in_words():
    refused(lambda: sweeps.apply(BASE, [("model_error", 0.1)]), "settings must be a mapping")
    refused(lambda: sweeps.apply(BASE, {("model_error",): 0.1}), "setting names (text)")
    refused(lambda: sweeps.check_names(BASE, [("model_error", [0.1])]), "setting names (text)")
    refused(lambda: sweeps.points([("model_error", [0.1])]), "list of pairs")
    assert sweeps.apply(BASE, {"model_error": 0.1}).model_error == 0.1


def test_arrays_and_ranges_are_lists_of_values():
    table = sweep(BASE, {"model_error": np.array([0.0, 0.1]), "gains.KPf": range(1, 3)}, workers=1)
    assert len(table) == 4 and (table["status"] == "ok").all()


# ------------------------------------------------------------------ every argument: works or HybridError


NUMBERS = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**20, 10**20),
                    st.sampled_from([0.0, 0.1, -0.5, 2.0, 10**400]))
VALUES = st.one_of(
    st.lists(st.sampled_from([0.0, 0.05, 0.2]), min_size=1, max_size=3),
    st.lists(NUMBERS, min_size=0, max_size=3),
    st.lists(st.one_of(NUMBERS, st.text(max_size=3), st.booleans(), st.none()), max_size=3),
    st.builds(Uniform, st.floats(-1, 1), st.floats(1.5, 3)),
    st.builds(LogUniform, st.floats(0.01, 0.1), st.floats(0.2, 1)),
    st.builds(Normal, st.floats(-1, 1), st.floats(0.01, 1)),
    st.one_of(NUMBERS, st.text(max_size=5), st.none(), st.just(np.zeros((2, 2))), st.just({1, 2}), st.just({})),
)
NAMES = st.sampled_from(["model_error", "contact.friction", "gains.KPf", "F_d", "controller", "bogus", "", "contact"])
PARAMETERS = st.one_of(
    st.dictionaries(NAMES, VALUES, min_size=1, max_size=3),
    st.lists(st.tuples(NAMES, VALUES), max_size=2),
    st.dictionaries(st.one_of(st.integers(), st.none()), VALUES, max_size=2),
    st.one_of(st.none(), st.text(max_size=5), st.integers()),
)
SAMPLES = st.one_of(st.none(), st.integers(-2, 3), st.sampled_from([10**12, 10**100, 2.5, "3", True, float("nan")]))
SEEDS = st.one_of(st.integers(-2, 10**30), st.sampled_from([1.5, "s", None, True]))
ENGINES = st.sampled_from(["local", "dask", "Local", "", None, 3])
CLIENTS = st.sampled_from([None, 5, "nonsense", "127.0.0.1:99999", object()])
OUTS = st.sampled_from([None, "folder", "file", "", 3, "file/below"])


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(parameters=PARAMETERS, samples=SAMPLES, seed=SEEDS, engine=ENGINES, client=CLIENTS, out=OUTS)
def test_every_sweep_call_works_or_raises_a_hybrid_error(tmp_path_factory, parameters, samples, seed, engine, client,
                                                         out):
    folder = tmp_path_factory.mktemp("out")
    (folder / "file").write_text("")
    where = out if not isinstance(out, str) or not out else str(folder / out)
    if engine == "dask" and client is None:
        client = "nonsense"  # a local cluster takes seconds to start: its path is tested above
    t0 = time.perf_counter()
    try:
        table = sweep(BASE, parameters, samples=samples, seed=seed, engine=engine, client=client, out=where,
                      workers=1)
    except hybrid.HybridError as exc:
        assert str(exc).strip() and len(str(exc).splitlines()[0]) < 400
    else:
        assert isinstance(table, pd.DataFrame) and set(table["status"]) <= set(sweeps.STATUSES)
    assert time.perf_counter() - t0 < 20
