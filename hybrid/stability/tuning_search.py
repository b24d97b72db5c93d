"""The search of :func:`hybrid.tune`: the tuned gains as points of a unit cube, the generations judged (the
margins batched, then the runs of the feasible candidates as one batch), CMA-ES's steps, the best verified
by :func:`hybrid.stability`, and the final runs and margins on every scenario."""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, replace

import numpy as np

from hybrid.control.loops import Gains
from hybrid.errors import HybridError
from hybrid.native.binding import workers as cores
from hybrid.stability.analysis import stability
from hybrid.sweeps.engines import dask_client, run_batch
from hybrid.sweeps.space import apply

#: CMA-ES's initial step, in the gains' log range scaled to [0, 1] (0.2: about a factor 2.5 in a gain
#: of the default bounds, a hundredfold range)
SIGMA0 = 0.2
#: the candidates of each generation of a one-gain grid, by default
GRID_BATCH = 8


class Runner:
    """The batches' runner for the tuning's life: this machine's processes, or one Dask client."""

    def __init__(self, client, workers, timeout):
        self.client, self.workers, self.timeout, self._dask = client, workers, timeout, None

    def __enter__(self):
        if self.client is None:
            return lambda todo, base: run_batch(base, todo, workers=self.workers)
        self._dask = dask_client(self.client, self.workers or cores(), self.timeout)
        connected = self._dask.__enter__()
        return lambda todo, base: run_batch(base, todo, client=connected, timeout=self.timeout)

    def __exit__(self, *exc):
        if self._dask is not None:
            return self._dask.__exit__(*exc)
        return False


@dataclass(frozen=True)
class Space:
    """The tuned gains as points of ``[0, 1]^d``: each gain's logarithm scaled to its bounds."""

    names: tuple[str, ...]
    ranges: dict
    own: Gains

    @property
    def start(self) -> np.ndarray:
        """The experiment's own gains (each clipped into its bounds)."""
        own = [math.log(max(getattr(self.own, n), 1e-300)) for n in self.names]
        return np.clip((np.array(own) - self._low) / self._width, 0.0, 1.0)

    @property
    def _low(self) -> np.ndarray:
        return np.log([self.ranges[n][0] for n in self.names])

    @property
    def _width(self) -> np.ndarray:
        return np.log([self.ranges[n][1] for n in self.names]) - self._low

    def values(self, points: np.ndarray) -> dict[str, np.ndarray]:
        """The gains of ``points`` (``n x d``) by name."""
        g = np.exp(self._low + np.clip(points, 0.0, 1.0) * self._width)
        return {n: g[:, j] for j, n in enumerate(self.names)}

    def gains(self, point) -> Gains:
        """The experiment's gains with those of ``point`` (a point, or the experiment's own for None)."""
        if point is None:
            return self.own
        return replace(self.own, **{n: float(v[0]) for n, v in self.values(np.atleast_2d(point)).items()})


class Search:
    """The search's state: the candidates judged (the history), the best, the runs made."""

    def __init__(self, base, space: Space, training, weights, aggregate, checks, progress, budget):
        self.base, self.space, self.training, self.weights = base, space, training, weights
        self.aggregate, self.checks, self.progress, self.budget = aggregate, checks, progress, budget
        self.history: list[dict] = []
        self.points: list = []  # each history row's point (None: the experiment's own gains)
        self.simulated, self.generation, self.stopped, self.before = 0, 0, "budget", math.inf
        self.run = None
        self._t0 = time.perf_counter()

    # ------------------------------------------------------------------ one generation

    def judge(self, points: list) -> np.ndarray:
        """Judge ``points`` (None: the experiment's own gains) on every training scenario: the history's
        rows, and CMA-ES's values (the objective; infeasible ones behind every feasible one)."""
        own = [p is None for p in points]
        radius = np.empty((len(points), len(self.training)))
        given = [i for i, o in enumerate(own) if not o]
        if given:
            radius[given] = self.checks["candidates"].radius(self.space.values(np.array([points[i] for i in given])))
        if any(own):
            radius[own] = self.checks["experiment"].radius({n: np.array([getattr(self.space.own, n)])
                                                           for n in self.space.names})
        kept = (radius < 1.0).all(axis=1)
        ran = kept | np.array(own)  # the experiment's own gains run whatever their margins: the comparison
        todo, at = [], len(self.history) * len(self.training)
        for i in np.flatnonzero(ran):
            settings = vars(self.space.gains(points[i]))
            todo += [(at + i * len(self.training) + s, {**scenario, **{n: settings[n] for n in self.space.names}})
                     for s, scenario in enumerate(self.training)]
        rows = iter(self.run(todo, self.base)) if todo else iter(())
        self.simulated += len(todo)
        values, violation, notes = np.full(len(points), np.nan), np.zeros(len(points)), [""] * len(points)
        for i in range(len(points)):
            lost = radius[i] >= 1.0
            if lost.any():
                violation[i] = lost.sum() + np.minimum(radius[i][lost] - 1.0, 1e3).sum()
                notes[i] = f"margin lost on {lost.sum()} of {len(self.training)} scenarios"
            if not ran[i]:
                continue
            own_rows = [next(rows) for _ in self.training]
            run_values = [self.value(row) for row in own_rows]
            failed = sum(not math.isfinite(v) for v in run_values)
            if failed:
                values[i] = math.inf
                violation[i] += failed
                stopped = sum(row.get("status") != "ok" for row in own_rows)
                why = f"{stopped} runs did not finish" if stopped else f"{failed} runs' objective is not a number"
                notes[i] = "; ".join(filter(None, (notes[i], why)))
            else:
                values[i] = max(run_values) if self.aggregate == "worst" else float(np.mean(run_values))
        feasible = kept & np.isfinite(values)
        for i, point in enumerate(points):
            gains = self.space.gains(point)
            self.history.append({"evaluation": len(self.history), "generation": 0 if point is None else self.generation,
                                 **{n: getattr(gains, n) for n in self.space.names}, "objective": values[i],
                                 "margin_radius": float(radius[i].max()), "feasible": bool(feasible[i]),
                                 "note": notes[i]})
            self.points.append(point)
        ceiling = max((r["objective"] for r in self.history if r["feasible"]), default=0.0)
        return np.where(feasible, values, abs(ceiling) + 1.0 + violation)

    def value(self, row: dict) -> float:
        """A run's objective: its weighted metrics (NaN for a run that did not finish)."""
        if row.get("status") != "ok":
            return math.nan
        total = sum(w * float(row.get(m, math.nan)) for m, w in self.weights.items())
        return total if math.isfinite(total) else math.nan

    # ------------------------------------------------------------------ the search

    def optimise(self, budget: int, popsize: int | None, seed: int) -> int:
        """Judge the experiment's gains, then ``budget`` candidates; the generations' size."""
        d = len(self.space.names)
        if d == 1:
            size = popsize or GRID_BATCH
            grid = list(np.linspace(0.0, 1.0, budget)[:, None])
            first = True
            for at in range(0, budget, size):
                self._generation(([None] if first else []) + grid[at:at + size])
                first = False
            return size
        try:
            import cma
        except ImportError:
            raise HybridError("tuning two gains or more needs CMA-ES: pip install 'hybrid-decoupling[tune]' (the cma "
                              "package)") from None
        size = popsize or 4 + int(3 * math.log(d))
        options = {"bounds": [0.0, 1.0], "popsize": size, "seed": math.nan,
                   "randn": np.random.RandomState(seed).randn,  # its own draws, apart from numpy's global ones
                   "verbose": -9, "verb_disp": 0, "verb_log": 0, "tolx": 1e-6}
        es = cma.CMAEvolutionStrategy(list(self.space.start), SIGMA0, options)
        judged, first = 0, True
        while judged < budget:
            stop = es.stop()
            if stop:
                self.stopped = ", ".join(sorted(stop))
                break
            asked = es.ask()
            taken = asked[:budget - judged]
            values = self._generation(([None] if first else []) + list(taken))
            values = values[1:] if first else values
            first = False
            judged += len(taken)
            if len(taken) == len(asked):
                es.tell(asked, list(values))
        return size

    def _generation(self, points: list) -> np.ndarray:
        self.generation += 1
        values = self.judge(points)
        self.before = self.history[0]["objective"]  # the experiment's own gains, judged first
        if self.progress:
            self._report()
        return values

    def _report(self) -> None:
        done = len(self.history) - 1
        best = min((r["objective"] for r in self.history if r["feasible"]), default=math.nan)
        width = 30
        filled = int(width * done / max(self.budget, 1))
        print(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{self.budget} candidates, {self.simulated:,} runs, "
              f"best {best:.4g} (the experiment's {self.before:.4g}), {time.perf_counter() - self._t0:.1f} s",
              end="", file=sys.stderr, flush=True)

    # ------------------------------------------------------------------ the answer

    def verified_best(self) -> tuple:
        """The best feasible candidate whose margins :func:`hybrid.stability` confirms on every training
        scenario, with those exact reports; the others it finds lost are marked in the history."""
        if self.progress:
            print(f"\nthe best gains' margins by hybrid.stability on {len(self.training)} training scenarios, then the "
                  "final runs and margins ...", file=sys.stderr, flush=True)
        while True:
            feasible = [r for r in self.history if r["feasible"]]
            if not feasible:
                closest = min(r["margin_radius"] for r in self.history)
                raise HybridError(
                    f"no gains judged keep a {self.checks['candidates'].min_gain_margin_db:g} dB gain margin (and "
                    f"{self.checks['candidates'].min_delay_margin_samples} samples of delay margin) with finished runs "
                    f"on every scenario (the closest: margin radius {closest:.3g}, kept below 1); lower "
                    "min_gain_margin_db, widen the bounds or raise the budget")
            row = min(feasible, key=lambda r: (r["objective"], r["evaluation"]))
            point = self.points[row["evaluation"]]
            exact = [self.report(point, s) for s in self.training]
            if all(self.kept(x) for x in exact):
                return point, exact
            row["feasible"], row["note"] = False, "margin lost by the exact margins"

    def report(self, point, scenario):
        """:func:`hybrid.stability` of the gains of ``point`` on ``scenario``."""
        return stability(apply(replace(self.base, gains=self.space.gains(point)), scenario))

    def kept(self, report) -> bool:
        check = self.checks["candidates"]
        return report.stable and all(x.gain_margin_db >= check.min_gain_margin_db - 1e-9
                                     and x.delay_margin_samples >= check.min_delay_margin_samples
                                     for x in report.loops)

    def final(self, best, exact: list, held: list) -> dict:
        """The tuned gains' runs on every scenario and the experiment's on the held-out ones (one batch),
        the objectives, and the margins of both on every scenario."""
        import pandas as pd

        tuned, own = self.space.gains(best), self.space.own
        sets = [("training", s, scenario) for s, scenario in enumerate(self.training)] + \
               [("held_out", s, scenario) for s, scenario in enumerate(held)]
        jobs = [(which, gains, where, s, scenario) for which, gains in (("tuned", tuned), ("experiment", own))
                for where, s, scenario in sets if which == "tuned" or where == "held_out"]
        todo = [(k, {**scenario, **{n: getattr(gains, n) for n in self.space.names}})
                for k, (_, gains, _, _, scenario) in enumerate(jobs)]
        rows = self.run(todo, self.base)
        self.simulated += len(todo)
        runs = pd.DataFrame([{"set": where, "scenario": s, "gains": which, "value": self.value(row),
                              **{k: v for k, v in row.items() if k != "run"}}
                             for (which, _, where, s, _), row in zip(jobs, rows)])

        def objective(which, where):
            part = runs[(runs["gains"] == which) & (runs["set"] == where)]["value"].to_numpy()
            if not len(part):
                return math.nan
            if not np.isfinite(part).all():
                return math.inf
            return float(part.max() if self.aggregate == "worst" else part.mean())

        reports = {("tuned", "training", s): x for s, x in enumerate(exact)}
        margins = []
        for where, s, scenario in sets:
            row = {"set": where, "scenario": s, **scenario}
            for which, point in (("tuned", best), ("experiment", None)):
                x = reports.get((which, where, s)) or self.report(point, scenario)
                prefix = "" if which == "tuned" else "before_"
                row |= {f"{prefix}{k}": v for k, v in self.numbers(x).items()}
            margins.append(row)
        return {"training": objective("tuned", "training"), "held_out": objective("tuned", "held_out"),
                "held_out_before": objective("experiment", "held_out"), "runs": runs,
                "margins": pd.DataFrame(margins)}

    def numbers(self, report) -> dict:
        """A :class:`~hybrid.Stability`'s numbers in the margins' table: the loops' smallest margins."""
        loops = report.loops
        return {"gain_margin_db": min(x.gain_margin_db for x in loops),
                "phase_margin_deg": min(x.phase_margin_deg for x in loops),
                "delay_margin_samples": min(x.delay_margin_samples for x in loops),
                "spectral_radius": report.spectral_radius, "kept": self.kept(report)}

    def table(self):
        import pandas as pd

        return pd.DataFrame(self.history)
