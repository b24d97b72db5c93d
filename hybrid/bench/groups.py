"""Every benchmark group in the order they run, each a progress label and a function adding its rows;
``--only`` picks those whose label contains a text."""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from hybrid.bench.bound import bound_benchmarks
from hybrid.bench.constant_model import ARMS as CONSTANT_ARMS
from hybrid.bench.constant_model import constant_model_benchmarks
from hybrid.bench.dynamics import dynamics_benchmarks
from hybrid.bench.eigen_law import eigen_law_benchmarks
from hybrid.bench.excitation import excitation_benchmarks
from hybrid.bench.first_use import cold_benchmarks, import_benchmarks
from hybrid.bench.identification import identification_benchmarks
from hybrid.bench.law import PaperLaw
from hybrid.bench.parts import part_benchmarks
from hybrid.bench.paths import path_benchmarks
from hybrid.bench.robots import ROBOTS, robot_benchmarks, spatial_benchmarks
from hybrid.bench.runs import loop_operation_benchmarks, sweep_benchmarks, trace_benchmarks
from hybrid.bench.stability import stability_benchmarks
from hybrid.bench.standalone import standalone_benchmarks
from hybrid.bench.tuning import tuning_benchmarks
from hybrid.errors import HybridError


def select_groups(groups: list, only: str | None) -> list:
    """The ``(label, run)`` groups whose label contains ``only`` (any case); all of them for None."""
    if only is None:
        return list(groups)
    if not only.strip():
        raise HybridError("--only needs part of a benchmark group's label, e.g. --only sweep")
    chosen = [g for g in groups if only.casefold() in g[0].casefold()]
    if not chosen:
        raise HybridError(f"--only {only!r}: no benchmark group's label contains it; the groups: "
                          + "; ".join(label for label, _ in groups))
    return chosen


def benchmark_groups(quick: bool, rep: int, add) -> list[tuple[str, Callable[[], None]]]:
    """Every benchmark as ``(progress label, run)`` groups in the order they run; ``run()`` adds the
    group's rows through ``add``."""
    law = PaperLaw(quick, rep, add)
    groups = [("import hybrid against import numpy, fresh processes",
               partial(import_benchmarks, 5 if quick else 21, add)),
              ("first use: the paper's simulate, paper command and first sweep, fresh process and cache",
               partial(cold_benchmarks, quick, add)),
              *((f"F* in C ({b} backend)", partial(law.law_in_c, b)) for b in ("sympy", "casadi")),
              ("F* from Python, single state", law.one_state),
              ("F* from Python, batched", law.batched),
              ("F* in plain NumPy", law.numpy_law),
              ("F* by SymPy lambdify", law.lambdified),
              ("F* by a CasADi Function call", law.casadi_call),
              ("F* by Pinocchio + NumPy", law.pinocchio),
              ("paper experiment, compiled", partial(law.experiment, "compiled")),
              ("paper experiment, NumPy plant and controller", partial(law.experiment, "NumPy")),
              ("regenerate from scratch", law.regenerate)]
    groups += [(f"{name}: generation, compilation, terms in C, from Python and by Pinocchio",
                partial(robot_benchmarks, name, path, tip, rep, quick, add)) for name, (path, tip) in ROBOTS.items()]
    groups += [(f"{name}: RNEA, forward dynamics, CRBA and the terms in C against Pinocchio's code generation "
                "(CppADCodeGen; its generator's first build takes minutes)",
                partial(dynamics_benchmarks, name, path, tip, rep, quick, add)) for name, (path, tip) in ROBOTS.items()]
    groups += [(f"{name}: the 6-D law and the controller step in C against the same written by hand on Pinocchio + "
                "Eigen (C++; its first build takes minutes)",
                partial(eigen_law_benchmarks, name, path, tip, rep, quick, add))
               for name, (path, tip) in ROBOTS.items()]
    groups += [(f"{name}: inverse and forward dynamics and terms in C, a constant model against run-time parameters",
                partial(constant_model_benchmarks, name, rep, quick, add)) for name in CONSTANT_ARMS]
    groups += [(f"{name}: the 6-D decoupling law in C, from Python, batched (both cores, one core), "
                "by Pinocchio + NumPy; the controller step",
                partial(spatial_benchmarks, name, path, tip, rep, quick, add)) for name, (path, tip) in ROBOTS.items()]
    groups += [("paper runs: one through simulate, in the compiled loop, sweeps on every core",
                partial(sweep_benchmarks, quick, add)),
               ("3-D runs (UR5 on the sphere): one through simulate, in the compiled loop, a sweep on every core",
                partial(trace_benchmarks, quick, add)),
               ("the 3-D closed loop's generated operations per RK4 step", partial(loop_operation_benchmarks, add)),
               ("the lanes at the floating-point bound: the machine's peak per kind of vector operation, the loops' "
                "census of them, a paper and a 3-D run in lanes against their bound",
                partial(bound_benchmarks, quick, add)),
               ("the standalone controller (generated C): each step call timed, code size, compile time",
                partial(standalone_benchmarks, quick, add)),
               ("path tasks: the follower per call, the controller's sample with one, a raster's run",
                partial(path_benchmarks, quick, add)),
               ("parts: a fine mesh's fit, the controller's sample and the 3-D run on a part against the formula's",
                partial(part_benchmarks, quick, add)),
               ("stability: a map of 10^4 points of the paper's loops, one report with its margins",
                partial(stability_benchmarks, quick, add)),
               ("tuning: the paper's force gains by hybrid.tune over 20 scenarios, a 6 dB margin kept",
                partial(tuning_benchmarks, quick, add)),
               ("excitation: the Panda's identification trajectory by hybrid.excitation_trajectory",
                partial(excitation_benchmarks, quick, add)),
               ("identification: the Panda's dynamics from a log of 10^5 samples",
                partial(identification_benchmarks, quick, add))]
    return groups
