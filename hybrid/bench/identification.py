"""The dynamics identified from a log: 10^5 samples of the Panda (100 s at 1 kHz along a multi-sine), filtered,
differentiated, fitted and made physically consistent; and the Panda's regressor in C, per state."""

from __future__ import annotations

import time

import numpy as np

from hybrid.bench.harness import median_ns
from hybrid.bench.targets import IDENTIFY, REGRESSOR
from hybrid.models.dynamics_identification import identify_dynamics
from hybrid.models.regressor import linear_parameters, regressor
from hybrid.models.shipped import panda

#: the log: its samples and rate [Hz]; the multi-sine's frequencies [Hz]
SAMPLES, RATE, FREQUENCIES = 100_000, 1000.0, 0.3 * np.arange(1, 11)


def panda_log(samples: int = SAMPLES, seed: int = 0):
    """``(robot, t, q, tau)``: the Panda along ten sines per joint (0.3-3 Hz, random phases) about the middle of
    its joint ranges, over a third of each range; the torques of its model 20 % heavier."""
    robot = panda()
    rng = np.random.default_rng(seed)
    t = np.arange(samples) / RATE
    w = 2 * np.pi * FREQUENCIES
    lower, upper = robot.limits.lower, robot.limits.upper
    a = rng.uniform(0.5, 1.0, (robot.n, len(w))) / w  # about equal speeds per sine
    a *= ((upper - lower) / 6 / a.sum(axis=1))[:, None]
    phase = t[:, None, None] * w + rng.uniform(0, 2 * np.pi, (robot.n, len(w)))
    q = (lower + upper) / 2 + (a * np.sin(phase)).sum(-1)
    qd, qdd = (a * w * np.cos(phase)).sum(-1), (-a * w**2 * np.sin(phase)).sum(-1)
    Y, _ = regressor(robot, q, qd, qdd)
    return robot, t, q, Y @ linear_parameters(robot.with_model_error(inertial=0.2))


def identification_benchmarks(quick: bool, add) -> None:
    """The wall time of :func:`hybrid.identify_dynamics` on the log of :func:`panda_log` (the program's first
    solve, cvxpy's import, made beforehand)."""
    robot, t, q, tau = panda_log()
    identify_dynamics(robot, t[:5000], q[:5000], tau[:5000])  # cvxpy, SciPy's filters, the native regressor
    states = 10_000
    qd, qdd = np.gradient(q[:states], axis=0) * RATE, np.zeros((states, robot.n))
    per_state = median_ns(lambda: regressor(robot, q[:states], qd, qdd), 1, 3 if quick else 9) / states
    add(REGRESSOR, per_state, "ns", ratio=f"{states:,} states a call, {robot.n} x {13 * robot.n} each")
    times = []
    for _ in range(1 if quick else 3):
        t0 = time.perf_counter()
        found = identify_dynamics(robot, t, q, tau)
        times.append(time.perf_counter() - t0)
    add(IDENTIFY, float(np.median(times)), "s",
        ratio=f"{found.samples:,} samples fitted, {len(found.names)} base parameters, condition {found.condition:.3g}")
