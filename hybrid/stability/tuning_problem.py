"""What a tuning is asked (:func:`hybrid.tune`), checked before any run: the objective, the scenarios it is
judged on (training and held out), the gains tuned and their bounds.

A scenario is settings of the experiment as a sweep names them (``contact.stiffness``, ``model_error``,
``sensor.force_noise``...): given one by one as dicts, or drawn from distributions
(:class:`hybrid.sweeps.Uniform`, :class:`~hybrid.sweeps.LogUniform`, :class:`~hybrid.sweeps.Normal`, or a
list drawn from uniformly) with the tuning's seed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import fields, replace

import numpy as np

from hybrid.control.loops import Gains
from hybrid.errors import HybridError
from hybrid.experiments.settings import setting_path
from hybrid.spec.metrics import PATH_METRICS
from hybrid.sweeps.space import apply, check_base, check_names, parameters_mapping, points
from hybrid.sweeps.store import metric_names
from hybrid.validate import shown

#: how a candidate's objective is taken over the scenarios: their mean, or the worst of them
AGGREGATES = ("mean", "worst")
#: the default bounds of a tuned gain: the experiment's own divided and multiplied by this
SPAN = 10.0
#: the gains of each loop, in :class:`~hybrid.Gains`' order
GAIN_NAMES = tuple(f.name for f in fields(Gains))
#: the integrals' gains, which act only with the experiment's ``integral``
INTEGRAL_GAINS = ("KI2v", "KIf")


def objective_weights(base, objective) -> dict[str, float]:
    """``objective`` (a metric's name, or ``{metric: weight}``) as weights by metric name, each a metric of
    ``base``'s runs and each weight a finite number > 0."""
    known = metrics_of(base)
    usage = f"give a metric's name or {{name: weight > 0}}; the metrics: {', '.join(known)}"
    if isinstance(objective, str):
        objective = {objective: 1.0}
    if not isinstance(objective, Mapping) or not objective:
        raise HybridError(f"objective = {shown(objective, 60)} is not a metric; {usage}")
    weights = {}
    for name, weight in objective.items():
        if not isinstance(name, str) or name not in known:
            raise HybridError(f"objective {shown(name, 60)} is not a metric of the runs; {usage}")
        if isinstance(weight, bool) or not isinstance(weight, (int, float, np.integer, np.floating)) \
                or not math.isfinite(weight) or weight <= 0:
            raise HybridError(f"objective weight of {name} = {shown(weight, 40)}; give a finite number > 0 (the "
                              "objective is minimised: a metric to raise has no place in it)")
        weights[name] = float(weight)
    return weights


def metrics_of(base) -> list[str]:
    """The metrics of ``base``'s runs: every run's, and a path task's (:data:`~hybrid.spec.metrics.PATH_METRICS`)."""
    names = metric_names(base)
    if getattr(base, "path_task", None) is not None:
        names += [m.name for m in PATH_METRICS]
    return names


def check_aggregate(aggregate) -> str:
    if not isinstance(aggregate, str) or aggregate not in AGGREGATES:
        raise HybridError(f"aggregate = {shown(aggregate, 40)}; give 'mean' (the scenarios' mean) or 'worst' (their "
                          "largest)")
    return aggregate


def tuned_gains(base, gains) -> tuple[str, ...]:
    """The names of the gains tuned: ``gains`` checked, or by default every gain the experiment's loops use
    (not 0, and the integrals' only with ``integral``)."""
    acting = [n for n in GAIN_NAMES if getattr(base.effective_gains(), n) != 0]
    if gains is None:
        if not acting:
            raise HybridError("the experiment's gains are all 0; name the gains to tune, gains=('KPf', 'KDf')")
        return tuple(acting)
    if isinstance(gains, str):
        gains = (gains,)
    if not isinstance(gains, (list, tuple)) or not gains:
        raise HybridError(f"gains = {shown(gains, 60)}; give the names of the gains to tune, e.g. ('KPf', 'KDf'), "
                          f"from {', '.join(GAIN_NAMES)}")
    for name in gains:
        if not isinstance(name, str) or name not in GAIN_NAMES:
            raise HybridError(f"gains: {shown(name, 40)} is not a gain; name them from {', '.join(GAIN_NAMES)}")
        if name in INTEGRAL_GAINS and not base.integral:
            raise HybridError(f"gains: {name} acts only with integral action, and the experiment has integral=False; "
                              "leave it out, or give the experiment integral=True")
    if len(set(gains)) != len(gains):
        raise HybridError(f"gains = {shown(gains, 60)} names a gain twice; name each once")
    return tuple(n for n in GAIN_NAMES if n in gains)  # Gains' order: the same tuning however they are listed


def gain_bounds(base, names: tuple[str, ...], bounds) -> dict[str, tuple[float, float]]:
    """Each tuned gain's ``(low, high)``: given, or the experiment's own over and times :data:`SPAN`."""
    if bounds is None:
        bounds = {}
    if not isinstance(bounds, Mapping):
        raise HybridError(f"bounds = {shown(bounds, 60)}; give {{gain: (low, high)}}, e.g. {{'KPf': (0.5, 8.0)}}")
    unknown = [k for k in bounds if k not in names]
    if unknown:
        raise HybridError(f"bounds names {shown(unknown[0], 40)}, which is not tuned; the gains tuned: "
                          f"{', '.join(names)}")
    out = {}
    for name in names:
        own = float(getattr(base.gains, name))
        given = bounds.get(name)
        if given is None:
            if own <= 0:
                raise HybridError(f"bounds: the experiment's {name} is 0, so it has no default range; give "
                                  f"bounds={{'{name}': (low, high)}} with 0 < low < high")
            out[name] = (own / SPAN, own * SPAN)
            continue
        try:
            low, high = (float(v) for v in given)
        except (TypeError, ValueError):
            low = high = math.nan
        if isinstance(given, (str, bytes)) or not (math.isfinite(low) and math.isfinite(high)) \
                or not 0 < low < high:
            raise HybridError(f"bounds of {name} = {shown(given, 40)}; give (low, high) with 0 < low < high (the "
                              "gains are searched on a log scale between them)")
        out[name] = (low, high)
    return out


def scenario_sets(base, names: tuple[str, ...], scenarios, distributions, samples, held_out,
                  seed: int) -> tuple[list[dict], list[dict]]:
    """The training and held-out scenarios: ``scenarios`` (dicts of settings) and ``samples`` draws of
    ``distributions``; held out, ``held_out`` dicts, or that many more draws (default as many as drawn
    for training; none without distributions). Each checked to make a valid experiment of ``base``."""
    check_base(base)
    if _count(held_out) and held_out < 0:
        raise HybridError(f"held_out = {held_out}; give a whole number of draws >= 0 or a list of scenarios")
    fixed = _listed("scenarios", scenarios)
    drawn_train: list[dict] = []
    drawn_held: list[dict] = []
    if distributions is not None:
        space = parameters_mapping(distributions)
        check_names(base, space)
        if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 0:
            raise HybridError(f"samples = {shown(samples, 40)}; give how many training scenarios to draw, a whole "
                              "number >= 0")
        extra = int(samples) if held_out is None else (int(held_out) if _count(held_out) else 0)
        # each set from its own stream of the seed: the training draws do not depend on how many are held out
        drawn_train = points(space, int(samples), seed) if samples else []
        drawn_held = points(space, extra, held_out_seed(seed)) if extra else []
    elif _count(held_out) and held_out:
        raise HybridError(f"held_out = {held_out} draws scenarios, and there are no distributions to draw from; "
                          "give distributions, or the held-out scenarios as dicts")
    training = fixed + drawn_train
    if not training:
        raise HybridError("no scenario to tune on: give scenarios (a list of dicts of settings, [{}] for the "
                          "experiment as it is) or distributions with samples >= 1")
    held = drawn_held if held_out is None or _count(held_out) else _listed("held_out", held_out)
    for what, group in (("scenario", training), ("held-out scenario", held)):
        for i, scenario in enumerate(group):
            _check_scenario(base, names, what, i, scenario)
    return training, held


def held_out_seed(seed: int) -> int:
    """The seed of the held-out draws: a stream of ``seed`` apart from the training draws'."""
    return int(np.random.SeedSequence([seed, 1]).generate_state(1, np.uint64)[0] >> 1)


def _count(held_out) -> bool:
    return isinstance(held_out, (int, np.integer)) and not isinstance(held_out, bool)


def _listed(what: str, given) -> list[dict]:
    if given is None:
        return []
    if isinstance(given, Mapping):
        raise HybridError(f"{what} is a mapping; give a list of scenarios, each a dict of settings, e.g. "
                          "[{'contact.stiffness': 2e4}, {'model_error': 0.3}] (distributions to draw from go to "
                          "distributions=)")
    if not isinstance(given, (list, tuple)) or not all(isinstance(s, Mapping) for s in given):
        raise HybridError(f"{what} = {shown(given, 60)}; give a list of scenarios, each a dict of settings, e.g. "
                          "[{'contact.stiffness': 2e4}]")
    return [dict(s) for s in given]


def _check_scenario(base, names: tuple[str, ...], what: str, i: int, scenario: dict) -> None:
    """One scenario: setting names the experiment has, none setting a tuned gain, making a valid experiment."""
    for name in scenario:
        if not isinstance(name, str):
            raise HybridError(f"{what} {i}: setting names are text, got {shown(name, 40)}")
        path = setting_path(name)
        if path == "gains" or path.removeprefix("gains.") in names and path.startswith("gains."):
            raise HybridError(f"{what} {i} sets {name}, a gain being tuned; leave it out of the scenarios (or out "
                              "of the gains tuned)")
    try:
        apply(replace(base, allow_unstable=True), scenario)
    except HybridError as exc:
        raise HybridError(f"{what} {i} ({shown(scenario, 80)}): {str(exc).splitlines()[0]}") from None
