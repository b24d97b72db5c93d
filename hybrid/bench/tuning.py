"""A tuning (:func:`hybrid.tune`) of the paper's force gains: about 10^4 closed-loop runs of 2 s simulated, the
margins' checks and the final exact margins included, on every core."""

from __future__ import annotations

import time

from hybrid.bench.targets import TUNE, TUNE_QUICK
from hybrid.experiments.paper import paper_experiment
from hybrid.stability.tuning import tune
from hybrid.sweeps.space import LogUniform, Uniform

#: the scenarios drawn: the model error, the surface's stiffness and friction
DISTRIBUTIONS = {"model_error": Uniform(0.0, 0.3), "contact.stiffness": LogUniform(2e4, 2e5),
                 "contact.friction": Uniform(0.05, 0.3)}
#: training and held-out scenarios drawn
SCENARIOS = 20
#: the candidates judged: with seed 0, 10,600 runs (the candidates that lose the 6 dB margin are not run)
BUDGET, QUICK_BUDGET = 700, 60


def tuning_benchmarks(quick: bool, add) -> None:
    """The paper's force gains (``KPf``, ``KDf``, ``KIf``) tuned for the mean RMS force error over 20 scenarios
    (20 more held out), a 6 dB gain margin kept on each: the wall time of the whole tuning, the compiled loops
    built beforehand (with ``quick``: 60 candidates, about a tenth of the runs)."""
    exp = paper_experiment()
    settings = {"distributions": DISTRIBUTIONS, "gains": ("KPf", "KDf", "KIf"), "seed": 0}
    tune(exp, "rms_force_error_N", samples=2, held_out=1, budget=3, min_gain_margin_db=0.0, **settings)  # loops built
    budget = QUICK_BUDGET if quick else BUDGET
    t0 = time.perf_counter()
    result = tune(exp, "rms_force_error_N", samples=SCENARIOS, held_out=SCENARIOS, budget=budget, **settings)
    seconds = time.perf_counter() - t0
    add(TUNE_QUICK if quick else TUNE, seconds, "s", runs=result.simulated_runs,
        ratio=f"{result.simulated_runs:,} runs, {seconds / result.simulated_runs * 1e3:.2f} ms a run; held-out RMS "
              f"force error {result.held_out_before:.3f} -> {result.held_out:.3f} N, gain margin >= 6 dB kept")
