"""Our generated dynamics against Pinocchio's own code generation (CppADCodeGen) for a URDF arm: RNEA,
forward dynamics (ours: CRBA, RNEA and an ``L D L^T`` solve; Pinocchio's: ABA), CRBA and the terms.
Ours twice: with the robot array given at run time (the robot unit), and with it compiled in (the
constant model), as Pinocchio's code has it.

The sides are built and run by :mod:`hybrid.bench.pinocchio_codegen`: first they must give the same
numbers on random states (to :data:`AGREEMENT`, relative), then each is timed in C, in one program, the
sides one after the other, and its instructions per call are counted (callgrind, where valgrind is
installed; an x86-64-v3 build of the same C, as valgrind runs no AVX-512)."""

from __future__ import annotations

import statistics

import numpy as np

from hybrid.bench import pinocchio_codegen
from hybrid.bench.harness import paired_ratio
from hybrid.bench.robots import comparable_urdf
from hybrid.bench.targets import dynamics_row
from hybrid.errors import HybridError
from hybrid.models.robot import Robot

#: the largest difference between the sides, relative to the largest of the output's (or the terms' part's)
#: numbers, that counts as the same
AGREEMENT = 1e-13


def blocks(function: str, n: int) -> tuple[int, ...]:
    """The sizes of the parts of ``function``'s output compared apart (each against its own scale): the
    terms' tip position, rotation, Jacobian, ``J' q'``, inertia and ``n``; the others' output whole."""
    if function == "terms":
        return (3, 9, 6 * n, 6, n * n, n)
    return {"rnea": (n,), "aba": (n,), "crba": (n * (n + 1) // 2,)}[function]


def differences(race: pinocchio_codegen.Race, states: np.ndarray) -> dict[tuple[str, str], float]:
    """The largest relative difference between each of our sides' outputs and Pinocchio's on ``states``
    (rows ``(q, v, w)``), by function and side (``ours``, ``constant``): each part's largest difference
    over its largest number of Pinocchio's, the worst over the parts and states (our inertia compared on
    its upper triangle, Pinocchio's CRBA's output)."""
    upper = np.triu_indices(race.n)
    worst = {}
    for function, (*ours, theirs) in race.evaluate(states).items():
        for side, mine in zip(pinocchio_codegen.SIDES, ours):
            if function == "crba":
                mine = mine.reshape(-1, race.n, race.n)[:, upper[0], upper[1]]
            at, worst[function, side] = 0, 0.0
            for size in blocks(function, race.n):
                a, b = mine[:, at:at + size], theirs[:, at:at + size]
                scale = np.maximum(np.abs(b).max(axis=1), np.finfo(float).tiny)
                worst[function, side] = max(worst[function, side], float((np.abs(a - b).max(axis=1) / scale).max()))
                at += size
    return worst


def random_states(n: int, count: int, seed: int = 0) -> np.ndarray:
    """``count`` states ``(q, v, w)`` of an ``n``-joint arm: angles anywhere, speeds, accelerations and
    torques of usual sizes."""
    rng = np.random.default_rng(seed)
    return np.hstack([rng.uniform(-np.pi, np.pi, (count, n)), rng.normal(0, 1, (count, n)),
                      rng.normal(0, 5, (count, n))])


def dynamics_benchmarks(name: str, urdf_name: str, tip: str, rep: int, quick: bool, add) -> None:
    """Each function of the shipped arm ``urdf_name`` on every side: the same numbers (or a HybridError),
    then the median time of a call of each side, the ratios, and the instructions a call."""
    urdf = comparable_urdf(name, urdf_name, "Pinocchio's code generation", pinocchio_codegen.missing)
    if urdf is None:
        return
    robot = Robot.from_urdf(urdf, tip=tip)
    race = pinocchio_codegen.race(robot, urdf, tip)
    worst = differences(race, random_states(robot.n, 20 if quick else 200))
    if max(worst.values()) > AGREEMENT:
        raise HybridError(f"{name}: our dynamics and Pinocchio's generated code differ by more than {AGREEMENT:g} "
                          "(relative): " + ", ".join(f"{f} ({side}) {d:.1e}" for (f, side), d in worst.items()))
    # short rounds, many: the ratios are the medians of the rounds' (harness.paired_ratio)
    times = race.time(20_000 if quick else 40_000, rep if quick else 5 * rep)
    counted = pinocchio_codegen.race(robot, urdf, tip, counted=True).instructions() if (
        pinocchio_codegen.can_count()) else {}
    for function in pinocchio_codegen.FUNCTIONS:
        median = {side: statistics.median(times[function, side]) for side in pinocchio_codegen.SIDES}
        count = {side: counted.get((function, side)) for side in pinocchio_codegen.SIDES}
        for side in ("ours", "constant"):
            ins = "" if count[side] is None else f"; {count[side]:,.0f} instructions a call"
            add(f"{name}: {dynamics_row(function, side)}", median[side], agreement=worst[function, side],
                instructions=count[side], ratio=f"the same as Pinocchio's to {worst[function, side]:.0e}{ins}")
        theirs = median["pinocchio"]
        of_ours, of_constant = (paired_ratio(times[function, "pinocchio"], times[function, side])
                                for side in ("ours", "constant"))
        ins = "" if None in count.values() else (f"; {count['pinocchio']:,.0f} instructions a call "
                                                 f"({count['pinocchio'] / count['ours']:.2f}x ours, "
                                                 f"{count['pinocchio'] / count['constant']:.2f}x the constant model's)")
        add(f"{name}: {dynamics_row(function, 'pinocchio')}", theirs, of_ours=of_ours,
            of_constant=of_constant, instructions=count["pinocchio"],
            ratio=f"{of_ours:.2f}x the time of ours, {of_constant:.2f}x the constant model's{ins}")
