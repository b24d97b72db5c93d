"""A constant model against the run-time-parameter build: the UR5's and the Panda's inverse dynamics (RNEA),
forward dynamics and terms in C, each timed in C on the same state, and their generated operations."""

from __future__ import annotations

import numpy as np

from hybrid.bench.harness import c_harness_ns
from hybrid.bench.targets import CONSTANT_KERNELS, constant_row
from hybrid.models.shipped import panda, ur5
from hybrid.native import generator

#: the arms of the constant-model rows
ARMS = {"ur5": ur5, "panda": panda}


def constant_model_benchmarks(name: str, rep: int, quick: bool, add) -> None:
    """Each of :data:`~hybrid.bench.targets.CONSTANT_KERNELS` of the arm ``name`` in C: with the ``robot``
    array given at run time (:attr:`hybrid.Robot.unit`), then with it compiled in
    (:attr:`hybrid.Robot.constant_unit`), the ratio of the times and the operation counts."""
    api = generator.api()
    robot = ARMS[name]()
    rng = np.random.default_rng(3)
    values = {"q": rng.uniform(-1, 1, robot.n), "qd": rng.normal(size=robot.n), "qdd": rng.normal(size=robot.n),
              "tau": rng.normal(0, 5, robot.n), "robot": robot.as_array()}
    kernels = {k.name: k for k in api.robot_kernels(robot.chain)}
    folded = {k.name: k for k in api.constant_kernels(tuple(kernels.values()), robot.as_array())[0]}
    calls = 50_000 if quick else 500_000
    for kernel in CONSTANT_KERNELS:
        times, ops = [], []
        for unit, k in ((robot.unit, kernels[kernel]), (robot.constant_unit, folded[kernel])):
            times.append(c_harness_ns(unit.folder, unit.manifest["unit"], unit.entry(kernel), values, calls, rep))
            ops.append(api.kernel_function(k).n_instructions())
        add(f"{name}: {constant_row(kernel, False)}", times[0], ratio=f"{ops[0]} generated operations")
        add(f"{name}: {constant_row(kernel, True)}", times[1], speedup=times[0] / times[1],
            ratio=f"{times[0] / times[1]:.2f}x faster than run-time parameters; {ops[1]} generated operations")
