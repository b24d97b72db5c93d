"""Parameter sweeps: many closed-loop runs, one row of metrics each, on this machine or a Dask cluster.

``sweep(base, {"model_error": [0, 0.1], "contact.friction": Uniform(0, 0.3)}, samples=100)`` runs
``simulate`` on every point and returns a :class:`pandas.DataFrame`: the run's index, the
parameters (columns named as given), every metric (the names of ``res.metrics``), ``status``
(``"ok"``, ``"failed"`` for a run that stopped, ``"invalid"`` for settings an experiment refuses)
and ``error`` (the first line of the cause). A failing run is a row, not an abort.

With ``out``, finished chunks are written as Parquet parts as they come (atomically) beside a
``sweep.json`` describing the sweep; running the same sweep into the same folder again resumes
where it stopped, and the table is the same as an uninterrupted sweep's. Runs are deterministic,
so the table does not depend on the engine, the number of workers or the chunking.
"""

from __future__ import annotations

import dataclasses
import importlib
import json
import math
import os
import sys
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.errors import HybridError
from hybrid.experiments.settings import RunSettings, setting_aliases
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import SimulationError, simulate

ENGINES = ("local", "dask")


# ------------------------------------------------------------------ distributions


def _numbers(owner, **values) -> None:
    for name, v in values.items():
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) or not math.isfinite(v):
            raise HybridError(f"{owner}: {name} = {v!r:.40} must be a finite number")


@dataclass(frozen=True)
class Uniform:
    """Values drawn uniformly in ``[low, high)``."""

    low: float
    high: float

    def __post_init__(self):
        _numbers("Uniform", low=self.low, high=self.high)
        if not self.low < self.high:
            raise HybridError(f"Uniform({self.low}, {self.high}) needs low < high")

    def sample(self, rng: np.random.Generator, n: int) -> list:
        return rng.uniform(self.low, self.high, n).tolist()


@dataclass(frozen=True)
class LogUniform:
    """Values whose logarithm is uniform in ``[log low, log high)`` (``0 < low < high``)."""

    low: float
    high: float

    def __post_init__(self):
        _numbers("LogUniform", low=self.low, high=self.high)
        if not 0 < self.low < self.high:
            raise HybridError(f"LogUniform({self.low}, {self.high}) needs 0 < low < high")

    def sample(self, rng: np.random.Generator, n: int) -> list:
        return np.exp(rng.uniform(math.log(self.low), math.log(self.high), n)).tolist()


@dataclass(frozen=True)
class Normal:
    """Values drawn from a normal distribution."""

    mean: float
    std: float

    def __post_init__(self):
        _numbers("Normal", mean=self.mean, std=self.std)
        if self.std <= 0:
            raise HybridError(f"Normal({self.mean}, {self.std}) needs std > 0")

    def sample(self, rng: np.random.Generator, n: int) -> list:
        return rng.normal(self.mean, self.std, n).tolist()


DISTRIBUTIONS = {"uniform": Uniform, "loguniform": LogUniform, "normal": Normal}


def points(parameters: Mapping, samples: int | None = None, seed: int = 0) -> list[dict]:
    """The sweep's points: the full grid of the value lists, or ``samples`` random draws (a list is
    then drawn from uniformly; ``seed`` makes the draws repeatable)."""
    if not isinstance(parameters, Mapping) or not parameters:
        raise HybridError("parameters must be a non-empty mapping {setting name: values or distribution}")
    names = list(parameters)
    for name, values in parameters.items():
        if not isinstance(name, str):
            raise HybridError(f"parameter names are setting names (text), got {name!r}")
        is_list = isinstance(values, Sequence) and not isinstance(values, str)
        if not (is_list or hasattr(values, "sample")):
            raise HybridError(f"parameter {name!r}: give a list of values or a distribution (hybrid.sweeps.Uniform, "
                              f"LogUniform, Normal), got {values!r:.60}")
        if is_list and len(values) == 0:
            raise HybridError(f"parameter {name!r} has no values")
        if is_list:
            _check_values(name, values)
    if samples is None:
        lists = [parameters[n] for n in names]
        if any(not isinstance(v, Sequence) or isinstance(v, str) for v in lists):
            raise HybridError("a distribution needs samples=N (the number of random draws)")
        grid = np.array(np.meshgrid(*[np.arange(len(v)) for v in lists], indexing="ij")).reshape(len(names), -1).T
        return [{n: _plain(lists[k][i]) for k, (n, i) in enumerate(zip(names, row))} for row in grid]
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 1:
        raise HybridError(f"samples = {samples!r}; give a whole number of runs >= 1")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise HybridError(f"seed = {seed!r}; give a whole number >= 0")
    rng = np.random.default_rng(seed)
    columns = {}
    for n in names:
        values = parameters[n]
        if hasattr(values, "sample"):
            columns[n] = values.sample(rng, int(samples))
        else:
            columns[n] = [values[i] for i in rng.integers(0, len(values), int(samples))]
    return [{n: _plain(columns[n][i]) for n in names} for i in range(int(samples))]


def _check_values(name: str, values) -> None:
    """A parameter's values: all numbers, all text or all booleans (one column of the table each)."""
    kinds = set()
    for v in values:
        if isinstance(v, (bool, np.bool_)):
            kinds.add("bool")
        elif isinstance(v, (int, float, np.integer, np.floating)):
            kinds.add("number")
        elif isinstance(v, str):
            kinds.add("text")
        else:
            raise HybridError(f"parameter {name!r}: {v!r:.50} is not a number, text or boolean; sweep a "
                              "setting's numbers by a dotted name, e.g. 'force_reference.after'")
    if len(kinds) > 1:
        raise HybridError(f"parameter {name!r} mixes {' and '.join(sorted(kinds))} values; give one kind")


def _plain(value):
    """A value as plain Python (numbers from NumPy become float/int; JSON- and Parquet-friendly)."""
    if isinstance(value, np.generic):
        return value.item()
    return value


# --------------------------------------------------------------------- settings


def check_names(base, names) -> None:
    """Refuse, before any run, a setting name the experiment does not have (naming the known ones), and
    two names of which one sets a part of the other (``contact`` and ``contact.friction``)."""
    if not isinstance(base, RunSettings):
        raise HybridError(f"base must be an experiment (hybrid.paper_experiment() or hybrid.tracing_experiment()), "
                          f"got {type(base).__name__}")
    paths = {name: setting_aliases().get(name, name) for name in names}
    for a, pa in paths.items():
        for b, pb in paths.items():
            if a != b and (pb == pa or pb.startswith(pa + ".")):
                raise HybridError(f"parameters {a!r} and {b!r} set the same setting; keep one of them")
    for name in names:
        path = setting_aliases().get(name, name).split(".")
        obj = base
        for part in path:
            if not dataclasses.is_dataclass(obj) or part not in {f.name for f in dataclasses.fields(obj)}:
                known = sorted({f.name for f in dataclasses.fields(base)} | set(setting_aliases()))
                raise HybridError(f"unknown setting {name!r} for a {type(base).__name__}; use a field name or a "
                                  f"dotted path (contact.friction, gains.KPf)\n  known: {', '.join(known)}")
            obj = getattr(obj, part)


def apply(base, settings: Mapping):
    """``base`` with ``settings`` (field names, gain names, ``F_d``/``v_d``, or dotted paths) applied;
    the experiment checks the result as it would any other."""
    aliases = setting_aliases()
    nested: dict = {}
    for name, value in settings.items():
        path = aliases.get(name, name).split(".")
        node = nested
        for part in path[:-1]:
            node = node.setdefault(part, {})
        node[path[-1]] = value

    def build(obj, changes: dict):
        kwargs = {k: build(getattr(obj, k), v) if isinstance(v, dict) else v for k, v in changes.items()}
        try:
            return dataclasses.replace(obj, **kwargs)
        except TypeError as exc:  # a wrong type reaching a dataclass's own checks
            raise HybridError(f"{type(obj).__name__}: {exc}") from None

    return build(base, nested)


# -------------------------------------------------------------------------- runs


def run_points(base, chunk: list[tuple[int, dict]]) -> list[dict]:
    """Run each ``(index, settings)`` of ``chunk`` on ``base``: one row each (the unit of work of
    every engine). Runs the compiled loop can take run there together, as SIMD lanes
    (:mod:`hybrid.closed_loop`); the others, and any run that stopped (for the cause in words),
    through :func:`hybrid.simulate`."""

    rows: dict[int, dict] = {}
    compiled = []
    for index, settings in chunk:
        try:
            exp = apply(base, settings)
            prepared = closed_loop.prepare(exp)
        except Exception as exc:  # noqa: BLE001 - refused before it started: the row says why
            rows[index] = _failure_row(index, settings, exc)
            continue
        if prepared is None:  # not for the compiled loop: the Python runner
            rows[index] = _simulated_row(index, settings, exp)
        else:
            compiled.append((index, settings, exp, prepared))
    for (index, settings, exp, _), outcome in zip(compiled, closed_loop.run([c[3] for c in compiled])):
        # a run that stopped: the Python runner says where and why
        rows[index] = ({"run": index, **settings, **outcome.metrics, "status": "ok", "error": ""}
                       if outcome.status == 0 else _simulated_row(index, settings, exp))
    return [rows[index] for index, _ in chunk]


def _simulated_row(index: int, settings: dict, exp) -> dict:
    """A run through the Python runner (``prepare`` has said it is not for the compiled loop, or the
    loop has seen it stop): its metrics, or why it did not finish."""

    try:
        res = simulate(exp, compiled=False)
    except Exception as exc:  # noqa: BLE001 - every run is a row, even one that meets a defect of ours
        return _failure_row(index, settings, exc)
    return {"run": index, **settings, **res.metrics, "status": "ok", "error": ""}


def _failure_row(index: int, settings: dict, exc: Exception) -> dict:
    """A run that did not finish: stopped while running (a result), refused before it started
    (invalid settings), or a defect of ours (error)."""

    status = ("failed" if isinstance(exc, SimulationError) else
              "invalid" if isinstance(exc, HybridError) else "error")
    cause = str(exc) if isinstance(exc, HybridError) else f"{type(exc).__name__}: {exc}"
    return {"run": index, **settings, "status": status, "error": cause.splitlines()[0]}


def _chunks(todo: list[tuple[int, dict]], size: int) -> list[list[tuple[int, dict]]]:
    return [todo[i:i + size] for i in range(0, len(todo), size)]


def _local(base, chunks, workers: int):
    """Chunks on a pool of processes, as they finish. Forked where the system can (the workers inherit
    the compiled code already loaded, and a user's script needs no ``__main__`` guard), else spawned
    (each worker loads the cached code once)."""
    if workers == 1:
        for chunk in chunks:
            yield run_points(base, chunk)
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    if method == "fork":
        if _PRELOAD[0] is not None:  # an interrupted sweep's: a fork must not copy a thread in an import
            _PRELOAD[0].join()
        _load_loops(base, chunks)
    with ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context(method)) as pool:
        futures = [pool.submit(run_points, base, chunk) for chunk in chunks]
        try:
            for f in as_completed(futures):
                yield f.result()
        except BaseException:
            for f in futures:
                f.cancel()
            raise


def _load_loops(base, chunks) -> None:
    """Load, before forking, the compiled loops of the base and of the first run: the workers inherit
    them instead of each loading them again (a fraction of a second each)."""

    for settings in ({}, chunks[0][0][1] if chunks and chunks[0] else {}):
        try:
            closed_loop.prepare(apply(base, settings))
        except Exception:  # noqa: BLE001 - a run's own problem is reported by its row, not here
            pass


def _dask(base, chunks, client, workers: int):
    """Chunks as Dask tasks (retried when a worker dies), as they finish."""
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise HybridError("engine='dask' needs dask.distributed: pip install 'dask[distributed]'") from None
    own = client is None
    if own:
        client = Client(LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                     dashboard_address=None))
    elif isinstance(client, str):
        own, client = True, Client(client)
    try:
        base_future = client.scatter(base, broadcast=True)
        futures = client.map(run_points, [base_future] * len(chunks), chunks, pure=False, retries=3)
        for f in as_completed(futures):
            yield f.result()
    finally:
        if own:
            cluster = client.cluster
            client.close()
            if cluster is not None:
                cluster.close()


# ------------------------------------------------------------------------- files


def _describe(base, parameters: Mapping, samples, seed) -> dict:
    def values(v):
        if hasattr(v, "sample"):
            return {type(v).__name__: dataclasses.asdict(v) if dataclasses.is_dataclass(v) else repr(v)}
        return [_plain(x) for x in v]

    to_dict = getattr(base, "to_dict", None)
    # the parameters in their order: it numbers the runs
    return {"sweep": 2, "base": to_dict() if to_dict else repr(base),
            "parameters": [[k, values(v)] for k, v in parameters.items()], "samples": samples, "seed": seed}


def _prepare(out: Path, description: dict, force: bool) -> None:
    """Create ``out`` or check that it holds this same sweep (parts of another are refused, or cleared
    with ``force``)."""
    files.writable_folder(out, "sweep folder")
    spec = out / "sweep.json"
    text = json.dumps(description, indent=2, sort_keys=True, default=str) + "\n"
    parts = list((out / "parts").glob("*.parquet"))
    same = spec.exists() and spec.read_text() == text
    if not same and (spec.exists() or parts):
        if not force:
            why = "its sweep.json differs" if spec.exists() else "it has results but no sweep.json"
            raise HybridError(f"{out} holds a different sweep ({why}); choose another folder, or pass force=True "
                              "(--force) to start this one there afresh")
        for part in parts:
            part.unlink()
    if not same:
        files.write_text(spec, text, overwrite=True)
    (out / "parts").mkdir(exist_ok=True)


def _lock(out: Path):
    """An exclusive lock on ``out`` for the sweep's lifetime: a second sweep into it is refused."""
    import fcntl

    handle = open(out / ".lock", "w")
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        handle.close()
        raise HybridError(f"another sweep is writing into {out}; wait for it or choose another folder") from None
    return handle


def _read_parts(out: Path) -> list[dict]:
    """The rows of the parts already written, each run once."""
    import pandas as pd

    rows: dict[int, dict] = {}
    for part in sorted((out / "parts").glob("part-*.parquet")):
        try:
            frame = pd.read_parquet(part)
        except Exception:  # noqa: BLE001 - a part that does not read is redone (written atomically, it should not)
            part.unlink()
            continue
        for row in frame.to_dict("records"):
            rows.setdefault(int(row["run"]), row)
    return list(rows.values())


def _write_part(out: Path, rows: list[dict]) -> None:
    import pandas as pd

    first, last = rows[0]["run"], rows[-1]["run"]
    frame = pd.DataFrame(rows)
    files.write_with(out / "parts" / f"part-{first:08d}-{last:08d}.parquet",
                     lambda tmp: frame.to_parquet(tmp, index=False), overwrite=True)


def _table(rows: list[dict], names: list[str]):
    import pandas as pd

    frame = pd.DataFrame(rows)
    if frame.empty:
        return frame
    frame = frame.sort_values("run").reset_index(drop=True)
    metrics = [c for c in frame.columns if c not in ("run", *names, "status", "error")]
    return frame[["run", *names, *metrics, "status", "error"]]


# ------------------------------------------------------------------------- sweep


def sweep(base, parameters: Mapping, *, samples: int | None = None, seed: int = 0, engine: str = "local",
          client=None, out=None, workers: int | None = None, chunk_size: int | None = None, csv: bool = False,
          force: bool = False, progress: bool = False):
    """Run ``base`` (an experiment) at every point of ``parameters``; one row of metrics per run.

    Parameters
    ----------
    base : :class:`hybrid.Experiment` or :class:`hybrid.TracingExperiment`.
    parameters : ``{setting name: values}``: a list (a full grid over the lists) or a distribution
        (:class:`Uniform`, :class:`LogUniform`, :class:`Normal`, drawn ``samples`` times). Names are
        the experiment's fields, the gains (``KPf``), ``F_d``/``v_d``, or dotted paths
        (``"contact.friction"``, ``"gains.KPf"``, ``"force_reference.after"``).
    samples, seed : random draws instead of the grid, repeatable by ``seed``.
    engine : ``"local"`` (processes on this machine; ``workers``, default every core) or ``"dask"``
        (``client``: a ``dask.distributed.Client`` or a scheduler address; default a ``LocalCluster``).
    out : a folder for incremental results and resuming (see the module docstring); with ``csv`` also
        ``results.csv``. ``force`` starts a different sweep afresh in a folder that holds one.
    """
    if engine not in ENGINES:
        raise HybridError(f"engine = {engine!r}; choose one of {', '.join(ENGINES)}")
    for name, value in (("workers", workers), ("chunk_size", chunk_size)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1):
            raise HybridError(f"{name} = {value!r}; give a whole number >= 1 (or None for the default)")
    check_names(base, parameters)
    todo_all = list(enumerate(points(parameters, samples, seed)))
    names = list(parameters)
    done_rows: list[dict] = []
    lock = None
    if out is not None:
        out = files.output_path(out)
        _prepare(out, _describe(base, parameters, samples, seed), force)
        lock = _lock(out)
        done_rows = _read_parts(out)
        done = {int(r["run"]) for r in done_rows}
        todo = [(i, p) for i, p in todo_all if i not in done]
    else:
        todo = todo_all
    try:
        return _run(base, todo, todo_all, names, done_rows, engine, client, out, workers, chunk_size, csv, progress)
    finally:
        if lock is not None:
            lock.close()


def _run(base, todo, todo_all, names, done_rows, engine, client, out, workers, chunk_size, csv, progress):
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    workers = max(1, min(workers or cores, len(todo) or 1))
    # whole groups of lanes (8 runs fill AVX-512's, and twice or four times narrower ones)
    size = chunk_size or 8 * max(1, min(8, math.ceil(len(todo) / (32 * workers))))
    chunks = _chunks(todo, size)
    results = _local(base, chunks, workers) if engine == "local" else _dask(base, chunks, client, workers)
    rows, t0, failed = list(done_rows), time.perf_counter(), 0
    for k, chunk_rows in enumerate(results):
        if k == 0 and "pandas" not in sys.modules:
            # the table's library loads (a third of a second) while the other chunks run; not before:
            # the local workers are forked by then, and a fork must not copy a thread in an import
            _PRELOAD[0] = threading.Thread(target=_preload_pandas, daemon=True)
            _PRELOAD[0].start()
        rows.extend(chunk_rows)
        failed += sum(r["status"] != "ok" for r in chunk_rows)
        if out is not None:
            _write_part(out, chunk_rows)
        if progress:
            _progress(len(rows), len(todo_all), failed, time.perf_counter() - t0)
    if progress:
        print(file=sys.stderr)
    table = _table(rows, names)
    if out is not None:
        files.write_with(out / "results.parquet", lambda tmp: table.to_parquet(tmp, index=False), overwrite=True)
        if csv:
            files.write_with(out / "results.csv", lambda tmp: table.to_csv(tmp, index=False), overwrite=True)
    return table


#: the thread loading pandas during a sweep, if any (a later sweep waits for it before it forks)
_PRELOAD: list = [None]


def _preload_pandas() -> None:
    try:
        importlib.import_module("pandas")
    except ImportError:  # said where the table needs it, in the sweep's own thread
        pass


def _progress(done: int, total: int, failed: int, seconds: float) -> None:
    width = 30
    filled = int(width * done / max(total, 1))
    print(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} runs, {failed} not ok, {seconds:.1f} s",
          end="", file=sys.stderr, flush=True)
