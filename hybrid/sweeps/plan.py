"""A sweep's plan: its runs in chunks, and a chunk's runs prepared alike and run together.

:func:`run_points` is the unit of work of every engine (:mod:`hybrid.sweeps.engines`): the runs of a
chunk that the compiled loop can take run there together, as SIMD lanes; the others through the
Python runner. Every run is a row, a failing one too.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Mapping
from dataclasses import dataclass

from hybrid.errors import HybridError
from hybrid.experiments.experiment import PHYSICS
from hybrid.native.compiler import CompilerUnusable
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import SimulationError, simulate
from hybrid.spec.interfaces import STATUS_CODES
from hybrid.sweeps.space import _built, _made, _nested, _paths


def run_points(base, chunk: list[tuple[int, dict]]) -> list[dict]:
    """Run each ``(index, settings)`` of ``chunk`` on ``base``: one row each (the unit of work of
    every engine). Runs the compiled loop can take run there together, as SIMD lanes
    (:mod:`hybrid.closed_loop`); the others, and any run that stopped (for the cause in words),
    through :func:`hybrid.simulate`."""

    rows, compiled = _prepared(base, chunk)
    for (index, settings, exp, _), outcome in zip(compiled, closed_loop.run([c[3] for c in compiled])):
        # a run that stopped: the Python runner says where and why
        rows[index] = ({"run": index, **settings, **outcome.metrics, "status": "ok", "error": ""}
                       if outcome.status == STATUS_CODES["OK"] else _simulated_row(index, settings, exp))
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
    (invalid settings), or a defect of ours (error). A compiler that can build nothing is no run's
    result: it stops the sweep (its finished chunks are kept, to resume with a working one)."""
    if isinstance(exc, CompilerUnusable):
        raise exc
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
