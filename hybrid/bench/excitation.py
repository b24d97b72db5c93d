"""An excitation trajectory for the Panda's dynamic identification (:func:`hybrid.excitation_trajectory`): the
wall time of its optimisation, the condition number reached against its random start's."""

from __future__ import annotations

import time

from hybrid.bench.targets import EXCITATION, EXCITATION_QUICK
from hybrid.models.excitation import excitation_trajectory
from hybrid.models.shipped import panda


def excitation_benchmarks(quick: bool, add) -> None:
    """The Panda's trajectory with the defaults (5 harmonics of 0.1 Hz, 100 samples, 3 restarts; with
    ``quick``: 1 restart), its regressor unit built beforehand."""
    robot = panda()
    excitation_trajectory(robot, harmonics=2, samples=16, restarts=1, iterations=1)  # the units built, not timed
    t0 = time.perf_counter()
    trajectory = excitation_trajectory(robot, restarts=1 if quick else 3)
    seconds = time.perf_counter() - t0
    add(EXCITATION_QUICK if quick else EXCITATION, seconds, "s",
        ratio=f"condition number {trajectory.start_condition:.0f} (random start) -> {trajectory.condition:.1f}")
