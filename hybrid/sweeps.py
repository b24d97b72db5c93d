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
import itertools
import json
import math
import os
import re
import struct
import sys
import threading
import time
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.errors import HybridError
from hybrid.experiments.experiment import PHYSICS
from hybrid.experiments.settings import RunSettings, setting_aliases, setting_path
from hybrid.simulation import closed_loop
from hybrid.simulation.metrics import metrics
from hybrid.simulation.runner import SimulationError, simulate
from hybrid.validate import check_nesting, check_size, count_text, product, shown

ENGINES = ("local", "dask")


# ------------------------------------------------------------------ distributions


def _numbers(owner, **values) -> None:
    for name, v in values.items():
        try:
            ok = not isinstance(v, bool) and isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(v)
        except OverflowError:  # an int beyond float range
            ok = False
        if not ok:
            raise HybridError(f"{owner}: {name} = {shown(v)} must be a finite number (within float range)")


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


#: memory a sweep keeps per run (its point, its row of metrics, its row of the table), estimated [bytes]
RUN_BYTES = 2048
#: and per swept parameter of each run [bytes]
PARAMETER_BYTES = 256


def check_runs(runs: int, n_parameters: int, what: str) -> None:
    """Refuse, before building them, more runs than the sweep's table can hold in memory."""
    check_size(f"{what} {count_text(runs)} runs, whose table needs",
               runs * (RUN_BYTES + PARAMETER_BYTES * n_parameters), "sweep fewer values or samples")


def check_mapping(parameters) -> None:
    """``parameters`` is a non-empty mapping whose keys are setting names (text)."""
    usage = "{setting name: a list of values or a distribution}, e.g. {'model_error': [0.0, 0.1]}"
    if not isinstance(parameters, Mapping):
        pairs = isinstance(parameters, (list, tuple)) and parameters and all(
            isinstance(p, (list, tuple)) and len(p) == 2 for p in parameters)
        got = "a list of pairs; make it a dict (dict(pairs))" if pairs else f"{type(parameters).__name__}"
        raise HybridError(f"parameters must be a mapping {usage}, got {got}")
    if not parameters:
        raise HybridError(f"parameters is empty: give at least one setting to sweep, {usage}")
    for name in parameters:
        if not isinstance(name, str) or not name:
            raise HybridError(f"parameter names are setting names (text), got {shown(name, 60)}")


def parameters_mapping(parameters) -> dict:
    """``parameters`` checked to be ``{setting name: values or distribution}`` (values: a list, tuple,
    range or 1-D array, taken as a list), before anything reads it."""
    check_mapping(parameters)
    check_nesting("sweep parameters", dict(parameters))  # before any message or JSON recurses into them
    checked = {}
    for name, values in parameters.items():
        if isinstance(values, np.ndarray) and values.ndim == 1:
            values = values.tolist()
        elif isinstance(values, range):
            values = list(values)
        if isinstance(values, (Uniform, LogUniform, Normal)):
            checked[name] = values
            continue
        if not isinstance(values, (list, tuple)):
            raise HybridError(f"parameter {name!r}: give a list of values or a distribution (hybrid.sweeps.Uniform, "
                              f"LogUniform, Normal), got {type(values).__name__} {shown(values, 60)}")
        if len(values) == 0:
            raise HybridError(f"parameter {name!r} has no values; give at least one")
        _check_values(name, values)
        checked[name] = list(values)
    return checked


def _whole(name: str, value, low: int) -> int:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or value < low:
        raise HybridError(f"{name} = {shown(value)}; give a whole number >= {low}")
    return int(value)


def points(parameters: Mapping, samples: int | None = None, seed: int = 0) -> list[dict]:
    """The sweep's points: the full grid of the value lists, or ``samples`` random draws (a list is
    then drawn from uniformly; ``seed`` makes the draws repeatable). How many is checked against the
    machine's memory before any is made."""
    parameters = parameters_mapping(parameters)
    names = list(parameters)
    seed = _whole("seed", seed, 0)
    if samples is None:
        lists = [parameters[n] for n in names]
        if any(not isinstance(v, list) for v in lists):
            raise HybridError("a distribution needs samples=N (the number of random draws)")
        sizes = [len(v) for v in lists]
        check_runs(product(sizes), len(names), f"the grid of {' x '.join(map(str, sizes))} values is")
        # the last parameter varies fastest
        return [dict(zip(names, values)) for values in itertools.product(*[[_plain(v) for v in vs] for vs in lists])]
    samples = _whole("samples", samples, 1)
    check_runs(samples, len(names), "samples =")
    rng = np.random.default_rng(seed)
    columns = {}
    for n in names:
        values = parameters[n]
        if isinstance(values, list):
            columns[n] = [values[i] for i in rng.integers(0, len(values), samples)]
        else:
            columns[n] = values.sample(rng, samples)
    return [{n: _plain(columns[n][i]) for n in names} for i in range(samples)]


def _check_values(name: str, values) -> None:
    """A parameter's values: all numbers, all text or all booleans (one column of the table each)."""
    kinds = set()
    for v in values:
        if isinstance(v, (bool, np.bool_)):
            kinds.add("bool")
        elif isinstance(v, (int, float, np.integer, np.floating)):
            if isinstance(v, int) and not -2**63 <= v < 2**63:  # no column of the table holds it
                raise HybridError(f"parameter {name!r}: {shown(v)} is beyond a table's whole numbers "
                                  "(64 bits); give it as a float")
            kinds.add("number")
        elif isinstance(v, str):
            kinds.add("text")
        else:
            raise HybridError(f"parameter {name!r}: {shown(v, 50)} is not a number, text or boolean; sweep a "
                              "setting's numbers by a dotted name, e.g. 'force_reference.after'")
    if len(kinds) > 1:
        raise HybridError(f"parameter {name!r} mixes {' and '.join(sorted(kinds))} values; give one kind")


def _plain(value):
    """A value as plain Python (numbers from NumPy become float/int; JSON- and Parquet-friendly)."""
    if isinstance(value, np.generic):
        return value.item()
    return value


# --------------------------------------------------------------------- settings


def check_base(base) -> None:
    """Refuse a base that is not an experiment, saying what to give."""
    if isinstance(base, RunSettings):
        return
    usage = "base must be an experiment, e.g. hybrid.paper_experiment() or hybrid.tracing_experiment()"
    if isinstance(base, Mapping):
        raise HybridError(f"{usage}, got a mapping; the experiment comes first: sweep(base, parameters)")
    if callable(base) and not isinstance(base, type):
        raise HybridError(f"{usage}, got the function {getattr(base, '__name__', '?')}; call it: "
                          f"{getattr(base, '__name__', 'paper_experiment')}()")
    got = f"the class {base.__name__}; make one" if isinstance(base, type) else type(base).__name__
    raise HybridError(f"{usage}, got {got}")


def check_names(base, names) -> None:
    """Refuse, before any run, a setting name the experiment does not have (naming the known ones), and
    two names of which one sets a part of the other (``contact`` and ``contact.friction``)."""
    check_base(base)
    names = list(names)
    for name in names:
        if not isinstance(name, str):
            raise HybridError(f"parameter names are setting names (text), got {type(name).__name__} {shown(name, 60)}")
    paths = {name: setting_path(name) for name in names}
    for a, pa in paths.items():
        for b, pb in paths.items():
            if a != b and (pb == pa or pb.startswith(pa + ".")):
                raise HybridError(f"parameters {a!r} and {b!r} set the same setting; keep one of them")
    for name in names:
        path = setting_path(name).split(".")
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
    return _built(base, _nested(_paths(base, settings), settings))


def _paths(base, settings) -> dict[str, list[str]]:
    """The dotted path of each setting of ``settings``, split, after checking them and ``base``."""
    check_base(base)
    if not isinstance(settings, Mapping):
        raise HybridError(f"settings must be a mapping {{setting name: value}}, e.g. {{'model_error': 0.1}}, got "
                          f"{type(settings).__name__}")
    check_names(base, settings)
    return {name: setting_path(name).split(".") for name in settings}


def _nested(paths: Mapping[str, list[str]], settings: Mapping) -> dict:
    """``settings`` as nested changes ``{field: value or {field: ...}}`` along their ``paths``."""
    nested: dict = {}
    for name, value in settings.items():
        path = paths[name]
        node = nested
        for part in path[:-1]:
            node = node.setdefault(part, {})
        node[path[-1]] = value
    return nested


def _built(obj, changes: dict):
    """``obj`` with the nested ``changes``, each dataclass checking itself as it is made."""
    return _made(obj, _parts(obj, changes), dataclasses.replace)


def _parts(obj, changes: dict) -> dict:
    """The fields of ``obj`` that the nested ``changes`` change, made (:func:`_built`)."""
    return {k: _built(getattr(obj, k), v) if isinstance(v, dict) else v for k, v in changes.items()}


def _made(obj, fields: dict, make):
    """``make(obj, **fields)``: ``obj`` with other ``fields``, checked as it is made."""
    try:
        return make(obj, **fields)
    except TypeError as exc:  # a wrong type reaching a dataclass's own checks
        raise HybridError(f"{type(obj).__name__}: {exc}") from None


# -------------------------------------------------------------------------- runs


def run_points(base, chunk: list[tuple[int, dict]]) -> list[dict]:
    """Run each ``(index, settings)`` of ``chunk`` on ``base``: one row each (the unit of work of
    every engine). Runs the compiled loop can take run there together, as SIMD lanes
    (:mod:`hybrid.closed_loop`); the others, and any run that stopped (for the cause in words),
    through :func:`hybrid.simulate`."""

    rows, compiled = _prepared(base, chunk)
    for (index, settings, exp, _), outcome in zip(compiled, closed_loop.run([c[3] for c in compiled])):
        # a run that stopped: the Python runner says where and why
        rows[index] = ({"run": index, **settings, **outcome.metrics, "status": "ok", "error": ""}
                       if outcome.status == 0 else _simulated_row(index, settings, exp))
    return [rows[index] for index, _ in chunk]


def _prepared(base, chunk: list[tuple[int, dict]]) -> tuple[dict[int, dict], list[tuple]]:
    """Each run of ``chunk`` applied to ``base`` (checked as :func:`apply` checks it) and prepared: the
    rows of those refused or for the Python runner, by index, and ``(index, settings, exp, prepared)``
    of those for the compiled loop. A run whose settings differ from an earlier one's only in those of
    :data:`~hybrid.simulation.closed_loop.ROW_SETTINGS` (the experiment's physics) is checked and
    prepared from it (:meth:`~hybrid.Experiment.with_physics`,
    :func:`~hybrid.simulation.closed_loop.prepare_alike`): the same experiment and row, or the same
    refusal, at a fraction of the cost."""

    rows: dict[int, dict] = {}
    compiled: list[tuple] = []
    kinds: dict = {}  # by the names of a run's settings: their paths and what tells runs alike
    templates: dict = {}  # by the settings that are not row settings: the first run prepared whole
    made: dict = {}  # the physics and the parts of rows made, by what they are made of (runs share them)
    for index, settings in chunk:
        try:
            kind = _kind(base, settings, kinds)
            changes, key = _nested(kind.paths, settings), kind.key(settings)
            template = templates.get(key)
            if template is None:
                exp = _built(base, changes)
                prepared = closed_loop.prepare(exp)
            else:  # the template's experiment with this run's physics
                # in the settings' order, as apply makes them: of two refused, the first is the run's refusal
                physics = _physics(base, {k: v for k, v in changes.items() if k in kind.physics}, made)
                exp = _made(template.experiment, physics, type(template.experiment).with_physics)
                prepared = closed_loop.prepare_alike(template, exp, kind.parts, made)
        except Exception as exc:  # noqa: BLE001 - refused before it started: the row says why
            rows[index] = _failure_row(index, settings, exc)
            continue
        if prepared is None:  # not for the compiled loop: the Python runner
            rows[index] = _simulated_row(index, settings, exp)
            continue
        if template is None and key is not None:
            templates[key] = prepared
        compiled.append((index, settings, exp, prepared))
    return rows, compiled


@dataclass(frozen=True)
class _Kind:
    """What runs of the same setting names share: each name's path, the names that are not row settings
    (:data:`~hybrid.simulation.closed_loop.ROW_SETTINGS`), the parts of the row and the fields of the
    experiment's physics those reach."""

    paths: dict
    others: tuple[str, ...]
    parts: frozenset
    physics: frozenset

    def key(self, settings: Mapping) -> tuple | None:
        """What two runs alike share: the names, and the others' values (:func:`_exact`); None for a
        value of another kind (a run prepared whole)."""
        values = [_exact(settings[name]) for name in self.others]
        return None if None in values else (tuple(self.paths), *values)


def _kind(base, settings, kinds: dict) -> _Kind:
    """The :class:`_Kind` of runs with the names of ``settings``, made once (it checks them: a refusal is
    raised for each run)."""
    names = tuple(settings) if isinstance(settings, dict) else None
    if names in kinds:
        return kinds[names]
    paths = _paths(base, settings)
    # an experiment whose physics its checks check alone: made from an earlier run's as apply makes it
    alike = getattr(type(base), "physics_alone", lambda: False)()
    reach = {name: closed_loop.ROW_SETTINGS.get(".".join(path)) if alike and path[0] in PHYSICS else None
             for name, path in paths.items()}
    kind = _Kind(paths, tuple(n for n, parts in reach.items() if parts is None),
                 frozenset(p for parts in reach.values() if parts for p in parts),
                 frozenset(paths[n][0] for n, parts in reach.items() if parts))
    if names is not None:
        kinds[names] = kind
    return kind


def _physics(base, changes: dict, made: dict) -> dict:
    """The fields of an experiment's physics that the nested ``changes`` change, made from ``base``'s as
    :func:`apply` makes them; each kept in ``made`` by its changes (a grid's runs share a few)."""
    fields = {}
    for name, change in changes.items():
        key = ("physics", name, _exact(change)) if isinstance(change, dict) else None
        if key is None:  # the field's value itself (the model error, the viscous compensation)
            fields[name] = change
        elif key[-1] is None:  # a value of no key: made for this run alone
            fields[name] = _built(getattr(base, name), change)
        else:
            if key not in made:
                made[key] = _built(getattr(base, name), change)
            fields[name] = made[key]
    return fields


def _exact(value) -> tuple | None:
    """A parameter's value, or nested changes, as a key that tells apart what a run could tell apart
    (types and bits: ``0`` is not ``0.0`` nor ``-0.0`` here); None for a value of another kind."""
    if type(value) is dict:
        items = tuple((k, _exact(v)) for k, v in value.items())
        return None if any(v is None for _, v in items) else items
    if type(value) in (bool, int, str):
        return type(value), value
    if type(value) is float:
        return float, struct.pack("<d", value)
    return None


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


#: a chunk's runs: pairs of whole groups of SIMD lanes (8 runs fill AVX-512's, and twice or four times
#: narrower ones; the runs of two schemes alternating fill theirs), 16 pairs at the most
LANES, MOST_PAIRS = 8, 16


def _chunks(todo: list[tuple[int, dict]], workers: int, size: int | None = None) -> list[list[tuple[int, dict]]]:
    """``todo`` in chunks of ``size`` runs, or by default of about a quarter of each worker's share of
    the runs left: large while many are left (few hand-overs), small at the end, so that the workers
    finish together."""
    chunks, start = [], 0
    while start < len(todo):
        pairs = math.ceil((len(todo) - start) / (4 * workers * 2 * LANES))
        end = start + (size or 2 * LANES * min(MOST_PAIRS, pairs))
        chunks.append(todo[start:end])
        start = end
    return chunks


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


#: how long [s] a sweep waits by default to reach a Dask scheduler (``connect_timeout``)
CONNECT_TIMEOUT = 5.0
#: the schemes of a scheduler's address a sweep connects to
SCHEMES = ("tcp", "tls", "ws", "wss")


def check_client(client, engine: str) -> None:
    """``client`` as the documented type, before anything connects: None, a scheduler's address
    (text), or a ``dask.distributed.Client``; and only for ``engine="dask"``."""
    if client is None:
        return
    if engine != "dask":
        raise HybridError(f"client is for engine='dask'; leave it out for engine={engine!r}, or pass engine='dask'")
    if isinstance(client, str):
        _check_address(client)
        return
    try:
        from dask.distributed import Client
    except ImportError:
        raise HybridError("engine='dask' needs dask.distributed: pip install 'dask[distributed]'") from None
    if not isinstance(client, Client):
        raise HybridError(f"client must be a dask.distributed.Client or a scheduler's address such as "
                          f"'tcp://127.0.0.1:8786', got {type(client).__name__}")
    if client.status != "running":
        raise HybridError(f"the Dask client is {client.status}; give a connected one, or its scheduler's address")


def _check_address(address: str) -> None:
    """A scheduler's address ``[scheme://]host:port``: refused here, in words, rather than by Dask."""
    usage = f"give [scheme://]host:port with scheme {', '.join(SCHEMES)}, e.g. 'tcp://127.0.0.1:8786'"
    scheme, sep, rest = address.strip().rpartition("://")
    host, _, port = rest.rpartition(":")
    if (sep and scheme not in SCHEMES) or not host or not port.isdigit() or not 0 < int(port) < 65536 \
            or any(c.isspace() for c in rest):
        raise HybridError(f"the Dask scheduler address {address!r:.80} is not one; {usage}")


def _connect(client, workers: int, timeout: float):
    """``(client, own)``: the given client, a new one to the address given, or one of a new local
    cluster; every failure a HybridError saying how long it waited."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise HybridError("engine='dask' needs dask.distributed: pip install 'dask[distributed]'") from None
    if client is not None and not isinstance(client, str):
        return client, False
    try:
        if client is None:
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
            try:
                return Client(cluster, timeout=timeout), True
            except BaseException:
                cluster.close()
                raise
        return Client(client, timeout=timeout), True
    except HybridError:
        raise
    except Exception as exc:  # noqa: BLE001 - Dask raises OSError, ValueError, TimeoutError and its own
        where = "a local Dask cluster" if client is None else f"the Dask scheduler at {client}"
        raise HybridError(f"could not reach {where} within {timeout:g} s (connect_timeout); check that it runs "
                          f"and the address, or raise connect_timeout\n  {type(exc).__name__}: {exc}") from None


def _dask(base, chunks, client, workers: int, timeout: float = CONNECT_TIMEOUT):
    """Chunks as Dask tasks (retried when a worker dies), as they finish."""
    from dask.distributed import as_completed

    client, own = _connect(client, workers, timeout)
    try:
        try:
            base_future = client.scatter(base, broadcast=True, timeout=timeout)
            futures = client.map(run_points, [base_future] * len(chunks), chunks, pure=False, retries=3)
        except Exception as exc:  # noqa: BLE001 - a lost or refusing scheduler, in Dask's words below
            raise HybridError(f"the Dask scheduler did not take the sweep within {timeout:g} s (connect_timeout); "
                              f"check the cluster\n  {type(exc).__name__}: {exc}") from None
        for f in as_completed(futures):
            try:
                rows = f.result()
            except Exception as exc:  # noqa: BLE001 - run_points makes every run a row: this is the cluster's
                raise HybridError(f"a Dask task of the sweep failed ({type(exc).__name__}); finished chunks are "
                                  f"kept with out=, run it again to resume\n  {exc}") from None
            yield rows
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


#: what a sweep writes into its folder besides ``parts/`` (``heatmap_*``: the command's figures)
OUTPUTS = ("sweep.json", "results.parquet", "results.csv", "heatmap_*.png", "heatmap_*.pdf", "heatmap_*.svg")
PART = "part-*.parquet"
STATUSES = ("ok", "failed", "invalid", "error")


def _prepare(out: Path, description: dict, force: bool):
    """Create ``out``, lock it, remove what an interrupted write left there, and check that it holds this
    same sweep or nothing of ours: files of our names without this sweep's ``sweep.json`` are another's
    (the user's, or another sweep's) and are refused, or cleared with ``force``. Returns the lock."""
    files.writable_folder(out, "sweep folder")
    lock = _lock(out)  # before anything is removed: a running sweep's temporaries are its own
    try:
        for left in files.leftovers(out, OUTPUTS) + files.leftovers(out / "parts", (PART,)):
            left.unlink(missing_ok=True)
        spec = out / "sweep.json"
        text = json.dumps(description, indent=2, sort_keys=True, default=str) + "\n"
        same = spec.is_file() and _read_text(spec) == text
        if not same:
            theirs = sorted({p for pattern in OUTPUTS for p in out.glob(pattern)}
                            | {p for p in (out / "parts").glob("*.parquet") if not p.name.startswith(".")})
            if theirs and not force:
                why = (("its sweep.json differs" if _is_description(spec) else "its sweep.json is not a sweep's")
                       if spec.exists() else f"it has {_listing(out, theirs)} but no sweep.json")
                raise HybridError(f"{out} holds a different sweep ({why}); choose another folder, or pass force=True "
                                  "(--force) to start this one there afresh (replacing them)")
            for path in theirs:
                if path.is_file() and path != spec:
                    path.unlink()
            files.write_text(spec, text, overwrite=True)
        (out / "parts").mkdir(exist_ok=True)
    except BaseException:
        lock.close()
        raise
    return lock


def _read_text(path: Path) -> str | None:
    try:
        return path.read_text()
    except (OSError, UnicodeDecodeError):
        return None


def _is_description(spec: Path) -> bool:
    """Whether ``spec`` reads as a sweep's description (written by a sweep, maybe another one)."""
    try:
        return isinstance(json.loads(_read_text(spec) or ""), dict) and "sweep" in json.loads(spec.read_text())
    except (ValueError, OSError):
        return False


def _listing(out: Path, paths: list[Path]) -> str:
    shown = ", ".join(str(p.relative_to(out)) for p in paths[:3])
    return shown + (f" and {len(paths) - 3} more" if len(paths) > 3 else "")


def _lock(out: Path):
    """An exclusive lock on ``out`` for the sweep's lifetime: a second sweep into it is refused."""
    import fcntl

    try:
        handle = open(out / ".lock", "w")
    except OSError as exc:
        raise HybridError(f"cannot lock the sweep folder {out} ({exc.strerror}); choose another folder") from None
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        handle.close()
        raise HybridError(f"another sweep is writing into {out}; wait for it or choose another folder") from None
    return handle


def metric_names(base) -> list[str]:
    """The names of the metrics a run of ``base`` reports (by the metrics' own definition)."""
    t = np.linspace(0.0, 1.0, 3)
    nq = base.robot.n if hasattr(base, "robot") else 2
    return list(metrics(t, t, t, t, t, penetration=t, contact_force=t, tau=np.zeros((3, nq))))


def _read_parts(out: Path, base, todo_all: list[tuple[int, dict]], force: bool) -> list[dict]:
    """The rows of the parts already written, each run once, each part checked to be this sweep's:
    its name, columns and their types, and its runs' numbers and parameters. Another's is refused,
    or with ``force`` removed (its runs are run again)."""
    import pandas as pd

    known = set(metric_names(base))
    rows: dict[int, dict] = {}
    for part in sorted(p for p in (out / "parts").glob("*.parquet") if not p.name.startswith(".")):
        try:
            frame = pd.read_parquet(part)
        except Exception as exc:  # noqa: BLE001 - pyarrow's errors are many; a part written by us reads
            problem = f"it does not read as Parquet ({type(exc).__name__})"
        else:
            problem = _part_problem(part.name, frame, todo_all, known)
        if problem is not None:
            if not force:
                raise HybridError(f"{part} is not this sweep's: {problem}; remove it, or pass force=True (--force) "
                                  "to run its runs again")
            part.unlink()
            continue
        for row in frame.to_dict("records"):
            rows.setdefault(int(row["run"]), row)
    return list(rows.values())


def _part_problem(name: str, frame, todo_all: list[tuple[int, dict]], metrics: set[str]) -> str | None:
    """Why the table ``frame`` of the part file ``name`` is not one this sweep wrote, or None."""
    from pandas.api import types

    match = re.fullmatch(r"part-(\d{8,})-(\d{8,})\.parquet", name)
    if match is None:
        return "its name is not part-FIRST-LAST.parquet"
    names = list(todo_all[0][1]) if todo_all else []
    missing = [c for c in ("run", *names, "status", "error") if c not in frame.columns]
    if missing:
        return f"it has no column {', '.join(map(str, missing))}"
    foreign = [c for c in frame.columns if c not in ("run", *names, "status", "error") and c not in metrics]
    if foreign:
        return f"it has column {', '.join(map(str, foreign[:3]))}, which is not a parameter or metric of this sweep"
    if frame.empty or not types.is_integer_dtype(frame["run"]) or frame["run"].duplicated().any():
        return "its run column is not the run numbers of a chunk"
    runs = frame["run"].tolist()
    first, last = int(match.group(1)), int(match.group(2))
    if runs[0] != first or runs[-1] != last or runs != sorted(runs) or last >= len(todo_all):
        return f"its runs are not {first} to {last} of this sweep's {len(todo_all)}"
    if not frame["status"].isin(STATUSES).all() or not frame["error"].map(lambda e: isinstance(e, str)).all():
        return "its status and error columns are not a sweep's"
    bad = [c for c in frame.columns if c in metrics and not (types.is_numeric_dtype(frame[c])
                                                            and not types.is_bool_dtype(frame[c]))]
    if bad:
        return f"its column {bad[0]} is not numbers"
    for row in frame[["run", *names]].to_dict("records"):
        point = todo_all[row["run"]][1]
        for n in names:
            if not _same(row[n], point[n]):
                return f"its run {row['run']} has {n} = {shown(row[n], 30)}, this sweep's has {shown(point[n], 30)}"
    return None


def _same(got, want) -> bool:
    """A parameter's value read back equals the sweep's: same kind, same value (NaN equal to NaN)."""
    if isinstance(want, bool):
        return isinstance(got, (bool, np.bool_)) and bool(got) == want
    if isinstance(want, str):
        return isinstance(got, str) and got == want
    if isinstance(got, (bool, np.bool_, str)) or not isinstance(got, (int, float, np.integer, np.floating)):
        return False
    return got == want or (math.isnan(got) and math.isnan(want))


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
          force: bool = False, progress: bool = False, connect_timeout: float = CONNECT_TIMEOUT):
    """Run ``base`` (an experiment) at every point of ``parameters``; one row of metrics per run.

    Parameters
    ----------
    base : :class:`hybrid.Experiment`
        What every run starts from, e.g. ``hybrid.paper_experiment()``.
    parameters : ``{setting name: values}`` (a mapping): a list (a full grid over the lists) or a
        distribution (:class:`Uniform`, :class:`LogUniform`, :class:`Normal`, drawn ``samples`` times).
        Names are the experiment's fields, the gains (``KPf``), ``F_d``/``v_d``, or dotted paths
        (``"contact.friction"``, ``"gains.KPf"``, ``"force_reference.after"``).
    samples, seed : random draws instead of the grid, repeatable by ``seed``.
    engine : ``"local"`` (processes on this machine; ``workers``, default every core) or ``"dask"``
        (``client``: a ``dask.distributed.Client`` or a scheduler address; default a ``LocalCluster``).
    out : a folder for incremental results and resuming (see the module docstring); with ``csv`` also
        ``results.csv``. ``force`` starts a different sweep afresh in a folder that holds one, or
        files of its names without its ``sweep.json``, and runs again the parts that are not its own.
    connect_timeout : how long [s] to wait for a Dask scheduler (default :data:`CONNECT_TIMEOUT`).

    The number of runs is checked against the machine's memory before any is made.
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
