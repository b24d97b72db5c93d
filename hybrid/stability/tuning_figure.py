"""A tuning as a figure: the objective over the evaluations, and the tuned gains against the experiment's own
on the held-out scenarios."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure


def tuning_figure(result, title: str | None = None) -> Figure:
    """The figure of a :class:`~hybrid.stability.tuning.Tuning` (see :meth:`Tuning.figure`)."""
    fig = Figure(figsize=(11.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2, width_ratios=(1.1, 1.0))
    _history(left, result)
    _scenarios(right, result)
    what = " + ".join(f"{w:g} {m}" if w != 1 else m for m, w in result.objective.items())
    fig.suptitle(title or f"{', '.join(result.tuned)} tuned for the {result.aggregate} {what} "
                          f"(gain margin >= {result.min_gain_margin_db:g} dB on every scenario)")
    return fig


def _history(ax, result) -> None:
    h = result.history
    n = h["evaluation"].to_numpy()
    value = h["objective"].to_numpy(float)
    feasible = h["feasible"].to_numpy(bool)
    ax.plot(n[feasible], value[feasible], ".", color="tab:blue", ms=4, label="candidate (margins kept)")
    if (~feasible[1:]).any():
        shown = np.isfinite(value) & ~feasible
        ax.plot(n[shown], value[shown], "x", color="tab:red", ms=4, label="run, a margin lost")
        lost = ~np.isfinite(value) & ~feasible
        top = np.nanmax(np.where(np.isfinite(value), value, np.nan), initial=1.0) if np.isfinite(value).any() else 1.0
        ax.plot(n[lost], np.full(lost.sum(), top), "|", color="tab:red", ms=8, label="not run: a margin lost")
    best = np.fmin.accumulate(np.where(feasible, value, np.nan))
    ax.step(n, best, where="post", color="k", lw=1.5, label="best so far")
    before = result.training_before
    if math.isfinite(before):
        ax.axhline(before, color="tab:orange", ls="--", lw=1.2, label="the experiment's gains")
    ax.set_xlabel("evaluation (candidate gains judged)")
    ax.set_ylabel(f"objective, {result.aggregate} over {len(result.scenarios)} training scenarios")
    finite = value[np.isfinite(value)]
    if len(finite) and finite.min() > 0 and finite.max() / finite.min() > 20:
        ax.set_yscale("log")
    ax.legend(loc="center right", fontsize="small")
    ax.grid(True, alpha=0.3)


def _scenarios(ax, result) -> None:
    runs = result.runs
    where = "held_out" if result.held_out_scenarios else "training"
    part = runs[runs["set"] == where]
    tuned = part[part["gains"] == "tuned"].sort_values("scenario")["value"].to_numpy(float)
    before = part[part["gains"] == "experiment"].sort_values("scenario")["value"].to_numpy(float)
    if not len(before):  # no held-out scenarios: the experiment's training runs are the search's
        before = np.full(len(tuned), np.nan)
    order = np.argsort(np.nan_to_num(before, nan=np.inf))
    x = np.arange(len(tuned))
    ax.bar(x - 0.2, before[order], 0.4, color="tab:orange", label="the experiment's gains")
    ax.bar(x + 0.2, tuned[order], 0.4, color="tab:blue", label="tuned gains")
    ax.set_xticks(x, [str(i) for i in part["scenario"].drop_duplicates().sort_values().to_numpy()[order]],
                  fontsize="small")
    ax.set_xlabel(f"{'held-out' if where == 'held_out' else 'training'} scenario")
    (metric,) = result.objective if len(result.objective) == 1 else ("objective",)
    ax.set_ylabel(f"a run's {metric}")
    top = np.nanmax(np.where(np.isfinite(np.r_[tuned, before]), np.r_[tuned, before], np.nan), initial=0.0)
    if top > 0:
        ax.set_ylim(0.0, 1.3 * top)  # room for the legend above the bars
    summary = (f"{result.aggregate}: {result.held_out_before:.4g} -> {result.held_out:.4g}" if where == "held_out"
               else f"{result.aggregate}: {result.training_before:.4g} -> {result.training:.4g}")
    ax.set_title(summary, fontsize="medium")
    ax.legend(loc="upper left", fontsize="small")
    ax.grid(True, axis="y", alpha=0.3)
