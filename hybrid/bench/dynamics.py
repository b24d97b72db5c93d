"""Our generated dynamics against Pinocchio's own code generation (CppADCodeGen) for a URDF arm: RNEA,
forward dynamics (ours: CRBA, RNEA and an ``L D L^T`` solve; Pinocchio's: ABA), CRBA and the terms.

Both sides are built and run by :mod:`hybrid.bench.pinocchio_codegen`: first they must give the same
numbers on random states (to :data:`AGREEMENT`, relative), then each is timed in C, in one program, the
sides alternating, and its instructions per call are counted (callgrind, where valgrind is installed)."""

from __future__ import annotations

import statistics
import sys

import numpy as np

from hybrid.bench import pinocchio_codegen
from hybrid.bench.robots import shipped_urdf
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


def differences(race: pinocchio_codegen.Race, states: np.ndarray) -> dict[str, float]:
    """The largest relative difference between our outputs and Pinocchio's on ``states`` (rows ``(q, v,
    w)``), by function: each part's largest difference over its largest number of Pinocchio's, the worst
    over the parts and states (our inertia compared on its upper triangle, Pinocchio's CRBA's output)."""
    upper = np.triu_indices(race.n)
    worst = {}
    for function, (ours, theirs) in race.evaluate(states).items():
        if function == "crba":
            ours = ours.reshape(-1, race.n, race.n)[:, upper[0], upper[1]]
        at, worst[function] = 0, 0.0
        for size in blocks(function, race.n):
            a, b = ours[:, at:at + size], theirs[:, at:at + size]
            scale = np.maximum(np.abs(b).max(axis=1), np.finfo(float).tiny)
            worst[function] = max(worst[function], float((np.abs(a - b).max(axis=1) / scale).max()))
            at += size
    return worst


def random_states(n: int, count: int, seed: int = 0) -> np.ndarray:
    """``count`` states ``(q, v, w)`` of an ``n``-joint arm: angles anywhere, speeds, accelerations and
    torques of usual sizes."""
    rng = np.random.default_rng(seed)
    return np.hstack([rng.uniform(-np.pi, np.pi, (count, n)), rng.normal(0, 1, (count, n)),
                      rng.normal(0, 5, (count, n))])


def dynamics_benchmarks(name: str, urdf_name: str, tip: str, rep: int, quick: bool, add) -> None:
    """Each function of the shipped arm ``urdf_name`` on both sides: the same numbers (or a HybridError),
    then the median time of a call of each side, the ratio, and the instructions a call."""
    urdf = shipped_urdf(urdf_name)
    why = "pip install example-robot-data" if urdf is None else pinocchio_codegen.missing()
    if why:
        print(f"  (skipped {name} against Pinocchio's code generation: {why})", file=sys.stderr)
        return
    robot = Robot.from_urdf(urdf, tip=tip)
    race = pinocchio_codegen.race(robot, urdf, tip)
    worst = differences(race, random_states(robot.n, 20 if quick else 200))
    if max(worst.values()) > AGREEMENT:
        raise HybridError(f"{name}: our dynamics and Pinocchio's generated code differ by more than {AGREEMENT:g} "
                          f"(relative): {', '.join(f'{f} {d:.1e}' for f, d in worst.items())}")
    times = race.time(20_000 if quick else 200_000, rep)
    counted = pinocchio_codegen.race(robot, urdf, tip, counted=True).instructions() if (
        pinocchio_codegen.can_count()) else {}
    for function in pinocchio_codegen.FUNCTIONS:
        ours, theirs = (statistics.median(times[function, side]) for side in ("ours", "pinocchio"))
        ours_ins, theirs_ins = counted.get((function, "ours")), counted.get((function, "pinocchio"))
        ins = "" if ours_ins is None else f"; {ours_ins:,.0f} instructions a call"
        add(f"{name}: {dynamics_row(function, pinocchio=False)}", ours, agreement=worst[function],
            instructions=ours_ins, ratio=f"the same as Pinocchio's to {worst[function]:.0e}{ins}")
        ins = "" if theirs_ins is None or ours_ins is None else (f"; {theirs_ins:,.0f} instructions a call "
                                             f"({theirs_ins / ours_ins:.2f}x ours)")
        add(f"{name}: {dynamics_row(function, pinocchio=True)}", theirs, of_ours=theirs / ours,
            instructions=theirs_ins, ratio=f"{theirs / ours:.2f}x the time of ours{ins}")
