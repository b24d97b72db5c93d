"""A sweep's space: its parameters' values and distributions, its points, and the settings they name.

A parameter is a setting of the experiment (a field, a gain, ``F_d``/``v_d`` or a dotted path) and a
list of values or a distribution; the points are the full grid of the lists, or random draws.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.experiments.settings import RunSettings, setting_aliases, setting_path
from hybrid.validate import check_nesting, check_size, checked_keywords, count_text, product, shown

# ------------------------------------------------------------------ distributions


def _numbers(owner, **values) -> None:
    for name, v in values.items():
        try:
            ok = not isinstance(v, bool) and isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(v)
        except OverflowError:  # an int beyond float range
            ok = False
        if not ok:
            raise HybridError(f"{owner}: {name} = {shown(v)} must be a finite number (within float range)")


@checked_keywords(where="sweeps.Uniform")
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


@checked_keywords(where="sweeps.LogUniform")
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


@checked_keywords(where="sweeps.Normal")
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
                raise HybridError(f"parameters {shown(a)} and {shown(b)} set the same setting; keep one of them")
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
