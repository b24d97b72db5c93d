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

The sweep's parts, one module each: :mod:`~hybrid.sweeps.space` (the parameters, their points and
the settings they name), :mod:`~hybrid.sweeps.plan` (chunks, and a chunk's runs prepared and run),
:mod:`~hybrid.sweeps.engines` (this machine, Dask) and :mod:`~hybrid.sweeps.store` (the folder).
"""

from __future__ import annotations

import os
import sys
import threading
import time
from collections.abc import Mapping

import numpy as np

from hybrid import files
from hybrid.deprecation import warn_old_names
from hybrid.errors import HybridError
from hybrid.sweeps import engines
from hybrid.sweeps.engines import CONNECT_TIMEOUT, ENGINES, SCHEMES, _dask, _local, _preload_pandas, check_client
from hybrid.sweeps.plan import LANES, MOST_PAIRS, _chunks, run_points
from hybrid.sweeps.space import (
    DISTRIBUTIONS,
    PARAMETER_BYTES,
    RUN_BYTES,
    LogUniform,
    Normal,
    Uniform,
    _whole,
    apply,
    check_base,
    check_mapping,
    check_names,
    check_runs,
    parameters_mapping,
    points,
)
from hybrid.sweeps.store import (
    OUTPUTS,
    PART,
    STATUSES,
    _describe,
    _prepare,
    _read_parts,
    _table,
    _write_part,
    metric_names,
)
from hybrid.validate import check_size, checked_keywords, count_text, shown

__all__ = ["CONNECT_TIMEOUT", "DISTRIBUTIONS", "ENGINES", "LANES", "MOST_PAIRS", "OUTPUTS", "PARAMETER_BYTES", "PART",
           "RUN_BYTES", "SCHEMES", "STATUSES", "WORKER_BYTES", "LogUniform", "Normal", "Uniform", "apply",
           "check_base", "check_client", "check_mapping", "check_names", "check_runs", "metric_names",
           "parameters_mapping", "points", "run_points", "sweep"]


@checked_keywords
def sweep(base, parameters: Mapping, *, samples: int | None = None, seed: int = 0, engine: str = "local",
          client=None, out=None, workers: int | None = None, chunk_size: int | None = None, csv: bool = False,
          force: bool = False, progress: bool = False, connect_timeout: float = CONNECT_TIMEOUT):
    """Run ``base`` (an experiment) at every point of ``parameters``; one row of metrics per run.

    The number of runs is checked against the machine's memory before any is made.

    Parameters
    ----------
    base : Experiment
        What every run starts from, e.g. ``hybrid.paper_experiment()``.
    parameters : Mapping
        ``{setting name: values}``: a list (a full grid over the lists) or a distribution
        (:class:`Uniform`, :class:`LogUniform`, :class:`Normal`, drawn ``samples`` times). Names are
        the experiment's fields, the gains (``KPf``), ``F_d``/``v_d``, or dotted paths
        (``"contact.friction"``, ``"gains.KPf"``, ``"force_reference.after"``).
    samples : int or None
        Random draws instead of the grid.
    seed : int
        The draws' seed: the same seed, the same draws.
    engine : str
        ``"local"`` (processes on this machine) or ``"dask"``.
    client : object
        For ``"dask"``, a ``dask.distributed.Client`` or a scheduler address; default a
        ``LocalCluster``.
    out : str or pathlib.Path or None
        A folder for incremental results and resuming (see the module docstring).
    workers : int or None
        For ``"local"``, the processes (default every core).
    chunk_size : int or None
        Runs per task (default: about a quarter of each worker's share of the runs left).
    csv : bool
        With ``out``, also write ``results.csv``.
    force : bool
        Start a different sweep afresh in a folder that holds one, or files of its names without its
        ``sweep.json``, and run again the parts that are not its own.
    progress : bool
        Report the progress on standard error.
    connect_timeout : float
        How long [s] to wait for a Dask scheduler (default :data:`CONNECT_TIMEOUT`).

    Returns
    -------
    pandas.DataFrame
        One row per run: ``run``, the parameters, every metric, ``status`` and ``error``.

    Raises
    ------
    HybridError
        A setting or parameter refused, an unknown engine, or more runs than the memory holds.

    Examples
    --------
    >>> import hybrid
    >>> exp = hybrid.paper_experiment(duration=0.05)
    >>> rows = hybrid.sweep(exp, {"KPf": [1.0, 2.0]}, workers=1)
    >>> rows["KPf"].tolist(), rows["status"].tolist()
    ([1.0, 2.0], ['ok', 'ok'])
    """
    if not isinstance(engine, str) or engine not in ENGINES:
        raise HybridError(f"engine = {shown(engine)}; choose one of {', '.join(ENGINES)}")
    for name, value in (("workers", workers), ("chunk_size", chunk_size)):
        if value is not None:
            _whole(name, value, 1)
    for name, value in (("csv", csv), ("force", force), ("progress", progress)):
        if not isinstance(value, (bool, np.bool_)):
            raise HybridError(f"{name} = {shown(value)}; give True or False")
    if isinstance(connect_timeout, (bool, np.bool_)) or not isinstance(connect_timeout, (int, float, np.integer,
                                                                                         np.floating)) \
            or not 0 < connect_timeout <= 3600:
        raise HybridError(f"connect_timeout = {shown(connect_timeout)}; give a number of seconds in (0, 3600]")
    check_base(base)
    check_mapping(parameters)
    check_names(base, parameters)
    warn_old_names(parameters, "sweep")
    parameters = parameters_mapping(parameters)
    check_client(client, engine)
    if workers is not None:
        check_size(f"workers = {count_text(workers)} processes of about {WORKER_BYTES // 2**20} MiB each need",
                   int(workers) * WORKER_BYTES, "give fewer workers (the default is one per core)")
    todo_all = list(enumerate(points(parameters, samples, seed)))
    names = list(parameters)
    done_rows: list[dict] = []
    lock = None
    if out is not None:
        out = files.output_path(out)
        lock = _prepare(out, _describe(base, parameters, samples, seed), bool(force))
    try:
        if out is not None:
            done_rows = _read_parts(out, base, todo_all, bool(force))
            done = {int(r["run"]) for r in done_rows}
            todo = [(i, p) for i, p in todo_all if i not in done]
        else:
            todo = todo_all
        return _run(base, todo, todo_all, names, done_rows, engine, client, out, workers, chunk_size, bool(csv),
                    bool(progress), float(connect_timeout))
    finally:
        if lock is not None:
            lock.close()


#: the memory of one worker process, estimated (the library, NumPy and the compiled loops) [bytes]
WORKER_BYTES = 150 * 2**20


def _run(base, todo, todo_all, names, done_rows, engine, client, out, workers, chunk_size, csv, progress,
         timeout=CONNECT_TIMEOUT):
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    workers = max(1, min(workers or cores, len(todo) or 1))
    chunks = _chunks(todo, workers, chunk_size)
    results = _local(base, chunks, workers) if engine == "local" else _dask(base, chunks, client, workers, timeout)
    rows, t0, failed = list(done_rows), time.perf_counter(), 0
    for k, chunk_rows in enumerate(results):
        if k == 0 and "pandas" not in sys.modules:
            # the table's library loads (a third of a second) while the other chunks run; not before:
            # the local workers are forked by then, and a fork must not copy a thread in an import
            engines._PRELOAD[0] = threading.Thread(target=_preload_pandas, daemon=True)
            engines._PRELOAD[0].start()
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


def _progress(done: int, total: int, failed: int, seconds: float) -> None:
    width = 30
    filled = int(width * done / max(total, 1))
    print(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} runs, {failed} not ok, {seconds:.1f} s",
          end="", file=sys.stderr, flush=True)
