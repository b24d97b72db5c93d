"""Gains tuned on the nonlinear closed loop across scenarios, a stability margin kept on each: :func:`tune`.

The search is CMA-ES (the ``cma`` package, the ``tune`` extra) over the logarithms of the tuned gains, each
scaled to its bounds, started at the experiment's own gains. Each generation is judged in two steps:

1. the margins of every candidate on every training scenario, on the sampled loops' model, batched
   (:class:`~hybrid.stability.margin_check.MarginCheck`): a candidate that loses a margin on one scenario
   is infeasible, not run, and ranked behind every feasible one by how far it is from keeping them;
2. the runs of the feasible candidates on every training scenario, as one batch of the compiled sweeps
   (:func:`hybrid.sweeps.engines.run_batch`: SIMD lanes on this machine's cores, or a Dask cluster); a
   candidate's objective is its runs' weighted metrics, their mean or worst over the scenarios. A run that
   does not finish makes its candidate infeasible too.

The experiment's own gains are judged alike (evaluation 0) and stay the answer unless a candidate beats
them. The answer's margins are then worked out exactly (:func:`hybrid.stability`) on every scenario: one
that the batched check passed and the exact one does not is set aside for the next best. One gain alone is
searched on a grid of ``budget`` values between its bounds (CMA-ES needs two or more).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from hybrid.control.loops import Gains
from hybrid.errors import HybridError
from hybrid.stability.experiment_loops import check_experiment
from hybrid.stability.margin_check import MarginCheck
from hybrid.stability.tuning_problem import (
    check_aggregate,
    gain_bounds,
    objective_weights,
    scenario_sets,
    tuned_gains,
)
from hybrid.stability.tuning_search import Runner, Search, Space
from hybrid.sweeps.engines import CONNECT_TIMEOUT, check_client
from hybrid.sweeps.space import apply
from hybrid.validate import checked_keywords, shown


@checked_keywords
@dataclass(frozen=True)
class Tuning:
    """What :func:`tune` found, and how the experiment's own gains compare.

    Parameters
    ----------
    gains, experiment_gains : Gains
        The tuned gains (the experiment's with the tuned ones replaced), and the experiment's own.
    tuned : tuple of str
        The names of the gains tuned.
    bounds : dict of str to (float, float)
        Each tuned gain's range.
    objective : dict of str to float
        The metrics minimised and their weights (a run's value: their weighted sum).
    aggregate : str
        ``"mean"`` or ``"worst"``: how a run's values make a candidate's objective over the scenarios.
    training, held_out : float
        The tuned gains' objective on the training and the held-out scenarios (NaN: none held out).
    training_before, held_out_before : float
        The experiment's own gains' (``inf`` where a run did not finish).
    scenarios, held_out_scenarios : tuple of dict
        The training and held-out scenarios (settings as a sweep names them).
    margins : pandas.DataFrame
        One row per scenario (``set``: ``"training"`` or ``"held_out"``, ``scenario``: its index there):
        its settings, then for the tuned gains and (``before_``) the experiment's, by :func:`hybrid.stability`:
        the smallest ``gain_margin_db``, ``phase_margin_deg`` and ``delay_margin_samples`` of the loops, the
        ``spectral_radius``, and ``kept`` (stable, both margins at least the minimum).
    runs : pandas.DataFrame
        The runs of the tuned gains on every scenario and of the experiment's on the held-out ones (the
        search made its runs on the training ones): ``set``, ``scenario``, ``gains`` (``"tuned"`` or
        ``"experiment"``), ``value`` (the run's objective), the settings, the metrics, ``status``, ``error``.
    history : pandas.DataFrame
        One row per candidate judged, in order (0: the experiment's gains): ``evaluation``, ``generation``
        (from 1; 0: the experiment's gains),
        the tuned gains, ``objective`` (NaN: not run, as it lost a margin; ``inf``: a run did not finish),
        ``margin_radius`` (the largest over the
        training scenarios; below 1: the margins kept), ``feasible``, ``note`` (why not).
    min_gain_margin_db, min_delay_margin_samples : float, int
        The margins kept on every training scenario.
    seed, budget, popsize : int
        The search's settings.
    simulated_runs : int
        The closed-loop runs made, the final ones included.
    seconds : float
        The tuning's wall time.
    stopped : str
        Why the search stopped (``"budget"``, or CMA-ES's criterion).

    Examples
    --------
    >>> import hybrid
    >>> exp = hybrid.paper_experiment(duration=0.6)
    >>> result = hybrid.tune(exp, "rms_force_error_N", [{}],
    ...                      gains=("KPf", "KDf"), budget=6,
    ...                      min_gain_margin_db=3.0, workers=1)
    >>> list(result.history.columns[:4]), result.evaluations
    (['evaluation', 'generation', 'KPf', 'KDf'], 6)
    >>> sorted(result.to_dict()["training"])
    ['experiment', 'tuned']
    """

    gains: Gains
    experiment_gains: Gains
    tuned: tuple[str, ...]
    bounds: dict
    objective: dict
    aggregate: str
    training: float
    held_out: float
    training_before: float
    held_out_before: float
    scenarios: tuple
    held_out_scenarios: tuple
    margins: object
    runs: object
    history: object
    min_gain_margin_db: float
    min_delay_margin_samples: int
    seed: int
    budget: int
    popsize: int
    simulated_runs: int
    seconds: float
    stopped: str

    @property
    def evaluations(self) -> int:
        """The candidates judged, the experiment's own gains not counted."""
        return len(self.history) - 1

    @property
    def improvement(self) -> float:
        """``1 - tuned / before`` on the held-out scenarios (on the training ones when none are held out):
        the share by which the objective fell; negative, it rose."""
        tuned, before = (self.held_out, self.held_out_before) if self.held_out_scenarios else \
            (self.training, self.training_before)
        return 1.0 - tuned / before if math.isfinite(before) and before != 0 else math.nan

    @property
    def margins_kept(self) -> bool:
        """Whether the tuned gains keep the margins on every training scenario (by :func:`hybrid.stability`)."""
        return bool(self.margins.loc[self.margins["set"] == "training", "kept"].all())

    def to_dict(self) -> dict:
        """The result as JSON-ready data.

        Returns
        -------
        dict
            The gains, the objectives, the margins kept, the scenarios and the search's settings (NaN and
            infinities as None); the tables (:attr:`history`, :attr:`margins`, :attr:`runs`) apart.
        """
        def number(v):
            return None if v is None or not math.isfinite(v) else float(v)

        held = self.margins[self.margins["set"] == "held_out"]
        return {"objective": self.objective, "aggregate": self.aggregate, "tuned": list(self.tuned),
                "gains": vars(self.gains), "experiment_gains": vars(self.experiment_gains),
                "bounds": {k: list(v) for k, v in self.bounds.items()},
                "training": {"tuned": number(self.training), "experiment": number(self.training_before)},
                "held_out": {"tuned": number(self.held_out), "experiment": number(self.held_out_before)},
                "improvement": number(self.improvement),
                "min_gain_margin_db": self.min_gain_margin_db,
                "min_delay_margin_samples": self.min_delay_margin_samples,
                "margins_kept": {"training": self.margins_kept,
                                 "held_out": bool(held["kept"].all()) if len(held) else None},
                "scenarios": list(self.scenarios), "held_out_scenarios": list(self.held_out_scenarios),
                "seed": self.seed, "budget": self.budget, "popsize": self.popsize, "evaluations": self.evaluations,
                "simulated_runs": self.simulated_runs, "seconds": round(self.seconds, 3), "stopped": self.stopped}

    def figure(self, title: str | None = None):
        """The objective over the evaluations, and the tuned gains against the experiment's on the
        held-out scenarios (the training ones when none are held out).

        Parameters
        ----------
        title : str, optional
            The figure's title (default: what was tuned).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from hybrid.stability.tuning_figure import tuning_figure

        return tuning_figure(self, title)

    def __str__(self) -> str:
        what = " + ".join(f"{w:g} {m}" if w != 1 else m for m, w in self.objective.items())
        lines = [f"tuned {', '.join(self.tuned)} for the {self.aggregate} {what} over {len(self.scenarios)} scenarios "
                 f"({self.evaluations} candidates, {self.simulated_runs:,} runs, {self.seconds:.1f} s; stopped: "
                 f"{self.stopped})",
                 "  " + ", ".join(f"{k} {getattr(self.experiment_gains, k):.4g} -> {getattr(self.gains, k):.4g}"
                                  for k in self.tuned),
                 f"  training: {self.training_before:.4g} -> {self.training:.4g}"]
        if self.held_out_scenarios:
            lines.append(f"  held out ({len(self.held_out_scenarios)} scenarios): {self.held_out_before:.4g} -> "
                         f"{self.held_out:.4g} ({100 * self.improvement:+.1f} % better)")
        lowest = self.margins.loc[self.margins["set"] == "training", "gain_margin_db"].min()
        lines.append(f"  gain margin >= {self.min_gain_margin_db:g} dB kept on every training scenario: "
                     f"{'yes' if self.margins_kept else 'NO'} (smallest {lowest:.3g} dB)")
        return "\n".join(lines)


@checked_keywords
def tune(exp, objective, scenarios=None, *, distributions=None, samples: int = 16, held_out=None,
         aggregate: str = "mean", budget: int = 200, seed: int = 0, gains=None, bounds=None,
         min_gain_margin_db: float = 6.0, min_delay_margin_samples: int = 0, popsize: int | None = None,
         client=None, workers: int | None = None, progress: bool = False,
         connect_timeout: float = CONNECT_TIMEOUT) -> Tuning:
    """Tune ``exp``'s gains on its nonlinear closed loop across scenarios, keeping a stability margin on each.

    Parameters
    ----------
    exp : Experiment
        What every run starts from (e.g. ``hybrid.paper_experiment()``); its gains are the start and the
        comparison.
    objective : str or mapping
        A metric of the runs to minimise (``"rms_force_error_N"``; :data:`hybrid.spec.metrics.METRICS`), or
        ``{metric: weight}``, their weighted sum (weights > 0, in the units that make the metrics comparable).
    scenarios : list of dict, optional
        Training scenarios, each settings of the experiment as a sweep names them
        (``{"contact.stiffness": 2e4, "model_error": 0.3}``; ``{}`` is the experiment as it is).
    distributions : mapping, optional
        ``{setting: distribution or list}`` (:class:`hybrid.sweeps.Uniform`, ``LogUniform``, ``Normal``):
        ``samples`` scenarios drawn from it with ``seed`` join the training ones.
    samples : int
        How many training scenarios to draw from ``distributions`` (16).
    held_out : int or list of dict, optional
        Scenarios the tuning does not see, for judging it: a list, or how many more to draw from
        ``distributions`` (default: as many as ``samples``; none without distributions).
    aggregate : str
        ``"mean"`` (default) or ``"worst"``: a candidate's objective over the scenarios.
    budget : int
        How many candidate gains to judge, each on every training scenario (the runs:
        ``budget x len(training)`` at most; candidates that lose the margin are not run).
    seed : int
        The draws' and the search's seed: the same seed, the same gains, bit for bit.
    gains : sequence of str, optional
        The gains to tune (:class:`~hybrid.Gains`' names); default every gain the experiment's loops use.
    bounds : mapping, optional
        ``{gain: (low, high)}``, ``0 < low < high``; default a tenth to ten times the experiment's own.
    min_gain_margin_db : float
        The gain margin every task axis's loop keeps on every training scenario [dB] (6; 0: stable only),
        as :func:`hybrid.stability` works it out.
    min_delay_margin_samples : int
        The samples by which every loop's force reading may be late, the loop stable still (0).
    popsize : int, optional
        The candidates of each generation (default CMA-ES's, ``4 + 3 ln d`` for ``d`` gains).
    client : optional
        A ``dask.distributed.Client``, or a scheduler's address: the runs go to that Dask cluster.
    workers : int, optional
        Processes for the runs on this machine (default every core).
    progress : bool
        Report each generation on standard error.
    connect_timeout : float
        How long [s] to wait for a Dask scheduler.

    Returns
    -------
    Tuning
        The tuned gains, the objective before and after (training and held out), the margins per
        scenario, the runs, the history.

    Raises
    ------
    HybridError
        An objective that is not a metric, no scenario, a budget below 1, an unknown gain, bounds that are
        not ``0 < low < high``, a scenario the experiment refuses; no candidate (the experiment's gains
        among them) keeping the margins on every scenario.

    Examples
    --------
    >>> import hybrid
    >>> exp = hybrid.paper_experiment(duration=0.6)
    >>> scenarios = [{"model_error": 0.0}, {"model_error": 0.3}]
    >>> result = hybrid.tune(exp, "rms_force_error_N", scenarios,
    ...                      gains=("KPf", "KDf"), budget=12,
    ...                      min_gain_margin_db=3.0, workers=1)
    >>> better = result.training < result.training_before
    >>> result.margins_kept, bool(better)
    (True, True)
    """
    t0 = time.perf_counter()
    check_experiment(exp, "tune")
    budget = _whole("budget", budget, 1)
    seed = _whole("seed", seed, 0)
    min_delay_margin_samples = _whole("min_delay_margin_samples", min_delay_margin_samples, 0)
    if popsize is not None:
        popsize = _whole("popsize", popsize, 2)
    if workers is not None:
        workers = _whole("workers", workers, 1)
    if isinstance(min_gain_margin_db, bool) or not isinstance(min_gain_margin_db, (int, float, np.integer,
                                                                                   np.floating)) \
            or not math.isfinite(min_gain_margin_db):
        raise HybridError(f"min_gain_margin_db = {shown(min_gain_margin_db, 40)}; give a gain margin in dB, e.g. 6.0")
    if not isinstance(progress, (bool, np.bool_)):
        raise HybridError(f"progress = {shown(progress)}; give True or False")
    weights = objective_weights(exp, objective)
    aggregate = check_aggregate(aggregate)
    names = tuned_gains(exp, gains)
    ranges = gain_bounds(exp, names, bounds)
    training, held = scenario_sets(exp, names, scenarios, distributions, samples, held_out, seed)
    check_client(client, "dask" if client is not None else "local")
    base = replace(exp, allow_unstable=True)  # the runs' loops are checked here: the experiment's own may not hold
    space = Space(names, ranges, exp.gains)
    checks = {"candidates": MarginCheck.of([apply(replace(base, gains=space.gains(space.start)), s) for s in training],
                                           float(min_gain_margin_db), min_delay_margin_samples),
              "experiment": MarginCheck.of([apply(base, s) for s in training], float(min_gain_margin_db),
                                           min_delay_margin_samples)}
    search = Search(base, space, training, weights, aggregate, checks, progress, budget)
    with Runner(client, workers, connect_timeout) as run:
        search.run = run
        popsize = search.optimise(budget, popsize, seed)
        best, exact = search.verified_best()
        result = search.final(best, exact, held)
    return Tuning(gains=space.gains(best), experiment_gains=exp.gains, tuned=names, bounds=ranges, objective=weights,
                  aggregate=aggregate, training=result["training"], held_out=result["held_out"],
                  training_before=search.before, held_out_before=result["held_out_before"],
                  scenarios=tuple(training), held_out_scenarios=tuple(held), margins=result["margins"],
                  runs=result["runs"], history=search.table(), min_gain_margin_db=float(min_gain_margin_db),
                  min_delay_margin_samples=min_delay_margin_samples, seed=seed, budget=budget, popsize=popsize,
                  simulated_runs=search.simulated, seconds=time.perf_counter() - t0, stopped=search.stopped)


def _whole(name: str, value, low: int) -> int:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or value < low:
        raise HybridError(f"{name} = {shown(value, 40)}; give a whole number >= {low}")
    return int(value)
