"""The benchmarks' rows by name, and the targets some of them have, as a table.

A target is data: the row it is for, how the report says it, the bound on one of the row's fields
(in the row's own unit: ns, ms, s, ops), and what else it asks (a field at least some value; the
row against another row). A row that did not run has no target, and neither has one whose target
compares it with a row that did not run.
"""

from __future__ import annotations

import math
from typing import NamedTuple

# ------------------------------------------------------------------ the paper's arm

ONE_STATE = "F* from Python, one state (law(q, qdot, a, Fc))"
BATCHED = "F* from Python, batched, per state (N = 1e5, SIMD lanes, both cores)"
NUMPY_LAW = "F* in plain NumPy (hybrid.oracle)"


def in_c(backend: str) -> str:
    return f"F* in C, {backend} backend, per call"


def experiment_row(duration: float, how: str) -> str:
    """The name of the paper experiment's end-to-end row (``how``: compiled, NumPy)."""
    return f"paper experiment end to end ({duration:g} s simulated), {how}"


# ------------------------------------------------------------------ first use

IMPORT = "import hybrid in a fresh process, from bytecode, less the interpreter's start"
FIRST_SIMULATE = "first paper simulate (hybrid.simulate(hybrid.paper_experiment())), fresh process and cache"
COLD_PAPER = "python -m hybrid paper --out DIR, fresh process and cache (wall time)"
FIRST_SWEEP = "first sweep of 10,000 paper runs (both cores), fresh process and cache"

# ------------------------------------------------------------------ the URDF arms (each row's name after "ARM: ")

TERMS_IN_C = "r, rotation, J, J'q', B, n in C, per call (robot_terms)"
LAW_IN_C = "6-D F* on a sphere in C, per call (curvature on)"
LAW_ONE = "6-D F* from Python, one state (law(q, qdot, a, Fc))"
LAW_BATCHED = "6-D F* from Python, batched, per state (N = 1e5, both cores)"
LAW_BATCHED_ONE_CORE = "6-D F* from Python, batched, per state (N = 1e5, one core)"
STEP_IN_C = "controller step in C (measurement, six loops, law), per sample"
STEP_ONE = "controller step from Python, per sample (ctrl(t, q, qdot, Fc))"
GEN_COMPILE = "generate + compile, fresh cache and process"

# ------------------------------------------------------------------ against Pinocchio's code generation (after "ARM: ")

#: each function compared with Pinocchio's generated code (by its name there): what it computes, and our
#: entry point
DYNAMICS = {"rnea": ("RNEA", "inverse_dynamics"),
            "aba": ("forward dynamics", "forward_dynamics; Pinocchio's: ABA"),
            "crba": ("CRBA", "inertia, a unit of its own"),
            "terms": ("r, rotation, J, J'q', B, n", "robot_terms")}


def dynamics_row(function: str, side: str) -> str:
    """The name of a row comparing the ``function`` of :data:`DYNAMICS`, on one side: ``ours`` (the robot
    array at run time), ``constant`` (our constant model) or ``pinocchio``."""
    what, ours = DYNAMICS[function]
    if side == "pinocchio":
        return f"{what} by Pinocchio's code generation (CppADCodeGen), per call"
    if side == "constant":
        return f"{what} in C, constant model, beside Pinocchio's code generation, per call"
    return f"{what} in C beside Pinocchio's code generation, per call ({ours})"


# ------------------------------------------------------------------ against Pinocchio + Eigen by hand (after "ARM: ")

#: the functions compared with the same written by hand in C++ on Pinocchio + Eigen
EIGEN = {"law": "6-D F* on a sphere", "step": "controller step (measurement, six loops, law)"}
#: the hand-written forms, by side (hybrid.bench.eigen_race.FORMS)
EIGEN_FORMS = {"pinocchio": "crba, nonLinearEffects, LLT solves", "pinocchio_rnea": "rnea, LU solves"}


def eigen_row(function: str, side: str) -> str:
    """The name of a row comparing the ``function`` of :data:`EIGEN` with the same written on Pinocchio +
    Eigen, on one side: ``ours`` or a hand-written form of :data:`EIGEN_FORMS`."""
    what = EIGEN[function]
    if side == "ours":
        return f"{what} in C beside Pinocchio + Eigen, per call"
    return f"{what} by hand in C++ on Pinocchio + Eigen ({EIGEN_FORMS[side]}), per call"


# ------------------------------------------------------------------ runs and sweeps

ONE_RUN = "paper run through hybrid.simulate (2 s simulated)"
SWEEP_1000 = "1,000 paper runs by hybrid.sweep (both cores)"
SWEEP_10000 = "10,000 paper runs by hybrid.sweep (both cores)"
LOOP_RUN = "paper run in the compiled closed loop, as SIMD lanes, one core, per run"
TRACE_ONE = "3-D run (UR5 on the sphere, 3 s simulated) through hybrid.simulate"
TRACE_RUN = "3-D run (UR5 on the sphere, 3 s simulated) in the compiled loop, as SIMD lanes, one core, per run"
SWEEP_3D = "1,000 3-D runs (UR5 on the sphere) by hybrid.sweep (both cores)"
LOOP_OPS = "3-D closed loop (UR5 on the sphere), generated operations per RK4 step"
TUNE = "tuning of the paper's force gains by hybrid.tune, about 10^4 runs of 2 s simulated (both cores)"
TUNE_QUICK = "tuning of the paper's force gains by hybrid.tune, about 10^3 runs of 2 s simulated (both cores)"
PATH_FOLLOW = "path follower (generated C), one call from Python, per call"
PATH_SAMPLE = "UR5 controller sample with a path task (follower, measurement, step) from Python, per sample"
PATH_RUN = "UR5 along a 3-pass raster (4 s simulated) through hybrid.simulate"
PART_FIT = "fit of a part of 102,400 facets (a torus's mesh, a grid of 6 mm)"
PART_FRAME = "task frame, its rate and the normal on a part in C (the expansion about the point, the frame), per call"
PART_SAMPLE = "UR5 controller sample on a part (its expansion about the tip, measurement, step) from Python, per sample"
PART_RUN = "3-D run on a part (UR5 on the sphere's mesh, 3 s simulated) through hybrid.simulate"
STABILITY_MAP = "stability map of 10^4 points (paper's experiment: sensor stiffness x sample time)"
STABILITY_REPORT = "hybrid.stability of the paper's experiment, with its margins"
EXCITATION = "excitation trajectory of the Panda by hybrid.excitation_trajectory (5 harmonics, 3 restarts)"
EXCITATION_QUICK = "excitation trajectory of the Panda by hybrid.excitation_trajectory (5 harmonics, 1 restart)"
IDENTIFY = "dynamics identified from a log of 10^5 samples (Panda, 1 kHz): filtered, fitted, made consistent"
REGRESSOR = "the Panda's joint-torque regressor Y(q, q', q'') in C, batched, per state"


#: LOOP_OPS before the body-frame algorithms: 4 x 2,593 (the plant's right-hand side) + 3,488 / 100 (the
#: controller step, once a sample of 100 steps) = 10,406.9. A reference count, like a baseline: the target
#: is a share of it
LOOP_OPS_REFERENCE = 10_407


def peak_row(kind: str) -> str:
    """The name of the row of the machine's peak for one kind of vector operation (hybrid.bench.peak's)."""
    return f"machine peak at the lanes' vector width (accumulators in registers): {kind}, per operation per lane"


def census_row(loop: str) -> str:
    """The name of the row of a closed loop's census (``loop``: paper, 3-D)."""
    return f"{loop} closed loop in lanes, vector operations per RK4 step by kind (the generator's census)"


def bound_row(loop: str) -> str:
    """The name of the row of a run in lanes against its floating-point bound (``loop``: paper, 3-D)."""
    return f"{loop} run in lanes, one core, over its floating-point bound (each kind at its measured peak)"

# ------------------------------------------------------------------ the standalone controller (after "ARM: ")

STANDALONE_STEP = "standalone controller step in C (NAME_controller_step), per call"
STANDALONE_P999 = "standalone controller step in C, p99.9 of the calls"
STANDALONE_SIZE = "standalone controller, .text of the compiled object"
STANDALONE_COMPILE = "standalone controller, compile time of the generated C"


# ------------------------------------------------------------------ constant models (after "ARM: ")

#: the kernels timed with the parameters given at run time and compiled in, and how a row names each
CONSTANT_KERNELS = {"inverse_dynamics": "inverse dynamics (RNEA)",
                    "forward_dynamics": "forward dynamics (CRBA, RNEA, L D L^T)",
                    "robot_terms": "r, rotation, J, J'q', B, n (robot_terms)"}


def constant_row(kernel: str, constant: bool) -> str:
    """The name of the row of ``kernel`` (a key of :data:`CONSTANT_KERNELS`) in C, its parameters compiled in
    (a constant model) or given at run time."""
    how = "parameters compiled in (constant model)" if constant else "run-time parameters"
    return f"{CONSTANT_KERNELS[kernel]} in C, per call, {how}"


# ------------------------------------------------------------------ the targets


class Target(NamedTuple):
    """A row's target, met when the row's ``field`` is at most ``at_most``; with ``at_least``, ``(field,
    bound)``, when that field is also at least the bound (a row without it has 0); with ``against``,
    ``(other row, factor)``, when the other row's median is also at least ``factor`` times this row's."""

    row: str
    text: str  # as the report says it
    at_most: float
    field: str = "median"
    at_least: tuple[str, float] | None = None
    against: tuple[str, float] | None = None

    def met(self, by: dict[str, dict]) -> bool:
        """Whether the row of ``by`` (the rows by name) meets the target."""
        row = by[self.row]
        ok = row[self.field] <= self.at_most
        if ok and self.at_least is not None:
            field, bound = self.at_least
            ok = row.get(field, 0) >= bound
        if ok and self.against is not None:
            other, factor = self.against
            ok = by[other]["median"] / row["median"] >= factor
        return bool(ok)


#: every target; the experiment's is for the full run (2 s simulated): a quick run has no such row
TARGETS = (
    Target(in_c("sympy"), "<= 60 ns", 60),
    Target(in_c("casadi"), "<= 60 ns", 60),
    Target(ONE_STATE, "<= 1 us, >= 70x NumPy", 1000, against=(NUMPY_LAW, 70)),
    Target(BATCHED, "<= 10 ns", 10),
    Target(experiment_row(2.0, "compiled"), "<= 25 ms, >= 100x NumPy", 25,
           against=(experiment_row(2.0, "NumPy"), 100)),
    Target(IMPORT, "<= 2.5x import numpy", 2.5, field="ratio_value"),
    Target(FIRST_SIMULATE, "<= 1.5 s", 1.5),
    Target(COLD_PAPER, "<= 8 s", 8),
    Target(FIRST_SWEEP, "<= 2x the same sweep warm", 2, field="of_warm"),
    Target(f"panda: {TERMS_IN_C}", "<= 1 us", 1000),
    Target(f"panda: {GEN_COMPILE}", "<= 30 s", 30),
    Target(f"ur5: {LAW_IN_C}", "<= 0.6 us", 600),
    Target(f"panda: {LAW_IN_C}", "<= 1.5 us", 1500),
    Target(f"ur5: {LAW_ONE}", "<= 1.5 us, >= 20x Pinocchio + NumPy", 1500, at_least=("speedup", 20)),
    Target(f"ur5: {LAW_BATCHED}", "<= 0.5 us", 500),
    Target(f"ur5: {LAW_BATCHED_ONE_CORE}", "<= 120 ns", 120),
    Target(f"ur5: {STEP_ONE}", "<= 2 us", 2000),
    Target(f"ur5: {STANDALONE_STEP}", "<= 0.6 us", 600),
    Target(f"ur5: {STANDALONE_P999}", "<= 2x the median", 2, field="of_median"),
    *(Target(f"{arm}: {eigen_row(function, 'ours')}", f">= {k}x faster than Pinocchio + Eigen by hand", math.inf,
             at_least=("speedup", k)) for arm in ("ur5", "panda") for function, k in (("law", 5), ("step", 4))),
    Target(ONE_RUN, "<= 2.3 ms", 2.3),
    Target(SWEEP_1000, "<= 1 s", 1),
    Target(SWEEP_10000, "<= 2.8 s", 2.8),
    Target(TRACE_ONE, "<= 25 ms", 25),
    Target(SWEEP_3D, "<= 3 s", 3),
    Target(TUNE, "<= 60 s", 60),
    Target(LOOP_OPS, f"<= 2/3 of {LOOP_OPS_REFERENCE:,}", 2 / 3 * LOOP_OPS_REFERENCE),
    Target(PART_FIT, "<= 10 s", 10),
    Target(PART_FRAME, "<= 2x the frame on the sphere", 2, field="of_formula"),
    Target(PART_RUN, "<= 2x the run on the sphere", 2, field="of_formula"),
    Target(STABILITY_MAP, "<= 1 s", 1),
    Target(IDENTIFY, "<= 10 s", 10),
    Target(REGRESSOR, "<= 2 us", 2000),
)


def mark_targets(results: list[dict]) -> None:
    """Give each row that has a target (:data:`TARGETS`) the target and whether it is ``met``."""
    by = {r["name"]: r for r in results}
    for target in TARGETS:
        if target.row in by and (target.against is None or target.against[0] in by):
            by[target.row].update(target=target.text, met=target.met(by))
