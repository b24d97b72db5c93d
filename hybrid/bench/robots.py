"""The URDF arms (UR5, Panda): their terms, the 6-D decoupling law on a sphere and the controller
step, in C, from Python (one state, batched) and by Pinocchio + NumPy; generation and compile times."""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from importlib.metadata import PackageNotFoundError
from pathlib import Path

import numpy as np

from hybrid import oracle
from hybrid.bench.harness import c_harness_ns, median_ns, on_one_core
from hybrid.bench.targets import (
    GEN_COMPILE,
    LAW_BATCHED,
    LAW_BATCHED_ONE_CORE,
    LAW_IN_C,
    LAW_ONE,
    STEP_IN_C,
    STEP_ONE,
    TERMS_IN_C,
)
from hybrid.control.controller import Controller
from hybrid.control.law import decoupling_law
from hybrid.control.references import Step
from hybrid.geometry.surfaces import Sphere
from hybrid.models.robot import Robot
from hybrid.models.terms import arm_terms
from hybrid.native import generator, units
from hybrid.spec.controller_step import CONTROLLER_STEP

#: the URDF arms of the robot benchmarks (files of the example-robot-data package) and their tips
ROBOTS = {"ur5": ("ur5_robot.urdf", "tool0"), "panda": ("panda.urdf", "panda_hand_tcp")}
SPHERE = (0.45, 0.1, 0.3, 0.15)


def shipped_urdf(name: str) -> Path | None:
    """The file ``name`` of the example-robot-data package; None where it is not installed."""
    try:
        from importlib.metadata import distribution

        dist = distribution("example-robot-data")
    except PackageNotFoundError:
        return None
    return next((Path(dist.locate_file(f)) for f in dist.files or () if str(f).endswith("/" + name)), None)


def comparable_urdf(name: str, urdf_name: str, against: str, missing) -> Path | None:
    """The shipped arm ``urdf_name``'s file for a comparison of ``name`` with ``against``; None, with one line
    on stderr saying why the comparison is skipped, where example-robot-data is not installed or
    ``missing()`` gives a reason (a package or a compiler it needs)."""
    urdf = shipped_urdf(urdf_name)
    why = "pip install example-robot-data" if urdf is None else missing()
    if why:
        print(f"  (skipped {name} against {against}: {why})", file=sys.stderr)
        return None
    return urdf


def _pinocchio_terms(pin, path: Path, robot, tip: str):
    """``terms(q, qd) -> (tip placement, J, J' q', B, n)`` by Pinocchio from Python, on its own
    reading of the URDF (joints off our chain held at 0, as Robot.from_urdf does)."""
    model = pin.buildModelFromUrdf(str(path))
    if model.nq != robot.n:
        extra = [model.getJointId(n) for n in model.names[1:] if n not in robot.joint_names]
        model = pin.buildReducedModel(model, extra, pin.neutral(model))
    data, fid, damping = model.createData(), model.getFrameId(tip), np.array(robot.damping)

    def terms(q, qd):
        pin.forwardKinematics(model, data, q, qd, np.zeros(robot.n))
        pin.updateFramePlacements(model, data)
        J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)
        acc = pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        return data.oMf[fid], J, acc, B, pin.nonLinearEffects(model, data, q, qd) + damping * qd

    return terms


def robot_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """Terms of a URDF arm: in C, from Python (one state, batched), by Pinocchio; generation time, code size."""

    path = shipped_urdf(urdf)
    if path is None:
        print(f"  (skipped {name}: pip install example-robot-data)", file=sys.stderr)
        return
    script = (f"import numpy as np, hybrid; r = hybrid.Robot.from_urdf({str(path)!r}, tip={tip!r}); "
              "hybrid.arm_terms(r, np.zeros(r.n), np.zeros(r.n))")
    with tempfile.TemporaryDirectory() as cache:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", script], check=True, env={**os.environ, "HYBRID_CACHE_DIR": cache})
        add(f"{name}: {GEN_COMPILE}", time.perf_counter() - t0, "s")
    robot = Robot.from_urdf(path, tip=tip)
    unit = robot.unit
    source = (unit.folder / f"{unit.manifest['unit']}.c").read_text()
    add(f"{name}: generated C size", len(source.encode()) / 1024, "KiB", ratio=f"{source.count(chr(10))} lines")
    rng = np.random.default_rng(1)
    q, qd = rng.uniform(-1, 1, robot.n), rng.normal(size=robot.n)
    entry = unit.entry("robot_terms")
    add(f"{name}: {TERMS_IN_C}", c_harness_ns(unit.folder, unit.manifest["unit"], entry,
                                              {"q": q, "qd": qd, "robot": robot.as_array()},
                                              50_000 if quick else 500_000, rep))
    ours = median_ns(lambda: arm_terms(robot, q, qd), 500 if quick else 5000, rep)
    add(f"{name}: the same from Python, one state (arm_terms)", ours)
    N = 10_000
    Q, QD = rng.uniform(-1, 1, (N, robot.n)), rng.normal(size=(N, robot.n))
    add(f"{name}: the same from Python, batched, per state (N = 1e4)", median_ns(
        lambda: arm_terms(robot, Q, QD), 1, rep) / N)
    try:
        import pinocchio as pin
    except ImportError:
        return
    pinocchio_terms = _pinocchio_terms(pin, path, robot, tip)
    theirs = median_ns(lambda: pinocchio_terms(q, qd), 500 if quick else 5000, rep)
    add(f"{name}: the same by Pinocchio from Python", theirs, ratio=f"{theirs / ours:.2f}x the time of arm_terms")


def alone_is_bitwise(law, batch: tuple[np.ndarray, ...], rows: tuple[int, ...] | None = None) -> bool:
    """Whether ``law`` gives each of ``rows`` of the per-state arrays ``batch`` alone (a batch of one)
    the same bits as inside the whole batch (default rows: the first, second, middle (where two cores
    split it) and last)."""
    N = len(batch[0])
    whole = law(*batch)
    for i in sorted(set(rows if rows is not None else (0, 1, N // 2, N - 1))):
        alone = law(*(x[i:i + 1] for x in batch))
        if alone.shape[0] != 1 or alone[0].tobytes() != whole[i].tobytes():
            return False
    return True


def _arm_on_sphere(urdf: str, tip: str) -> tuple[Path, Robot, Sphere] | None:
    """The shipped arm ``urdf``'s file, its chain to ``tip`` and the benchmarks' sphere; None where the arm
    is not installed."""
    path = shipped_urdf(urdf)
    return None if path is None else (path, Robot.from_urdf(path, tip=tip), Sphere(SPHERE[:3], SPHERE[3]))


def spatial_law_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """The general law of conventions §9 for a URDF arm on a sphere: in C, from Python, batched,
    against Pinocchio + NumPy; the generated operation count."""
    kernel_function = generator.api().kernel_function
    law_kernels = generator.api().law_kernels
    arm = _arm_on_sphere(urdf, tip)
    if arm is None:
        return
    path, robot, sphere = arm
    law = decoupling_law(robot, sphere, curvature=True)
    unit = units.law_unit(robot.chain, robot.name, sphere.spec(), law.axes)
    rng = np.random.default_rng(2)
    q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5][:robot.n])
    qd, a, Fc = rng.normal(0, 0.5, robot.n), rng.normal(size=6), rng.normal(0, 5, 6)
    ops = kernel_function(law_kernels(robot.chain, sphere.spec(), law.axes)[1]).n_instructions()
    values = {"q": q, "qd": qd, "a": a, "Fc": Fc, "tau0": np.zeros(robot.n), "robot": robot.as_array(),
              "surface": sphere.as_array(), "e": [0.0, 0.0, 1.0], "opts": [1.0]}
    in_c = c_harness_ns(unit.folder, unit.manifest["unit"], unit.entry("decoupling_law"), values,
                        50_000 if quick else 500_000, rep)
    add(f"{name}: {LAW_IN_C}", in_c, ratio=f"{ops} generated operations")
    ours = median_ns(lambda: law(q, qd, a, Fc), 2000 if quick else 20000, rep)
    N = 10_000 if quick else 100_000
    Q, QD = np.tile(q, (N, 1)) + rng.normal(0, 0.05, (N, robot.n)), rng.normal(0, 0.5, (N, robot.n))
    A, FC = rng.normal(size=(N, 6)), rng.normal(0, 5, (N, 6))
    batched = median_ns(lambda: law(Q, QD, A, FC), 1, rep) / N
    one_core = on_one_core(lambda: median_ns(lambda: law(Q, QD, A, FC), 1, rep) / N)
    bitwise = alone_is_bitwise(law, (Q, QD, A, FC))

    def batched_rows():
        add(f"{name}: {LAW_BATCHED}", batched, bitwise=bitwise,
            ratio=f"bitwise: {'yes' if bitwise else 'no'} (a state alone in a batch of one, against the same state "
                  "inside this batch)")
        if one_core is not None:
            add(f"{name}: {LAW_BATCHED_ONE_CORE}", one_core,
                ratio=f"{one_core / in_c:.2f}x a call in C, {one_core / batched:.2f}x the time on both cores")

    try:
        import pinocchio as pin
    except ImportError:
        add(f"{name}: {LAW_ONE}", ours)
        batched_rows()
        return
    pinocchio_terms = _pinocchio_terms(pin, path, robot, tip)

    def pinocchio_law():
        placement, J, Jdqd, B, n = pinocchio_terms(q, qd)
        R, Rd = oracle.spatial_frame(sphere, placement.translation, J[:3] @ qd, (0.0, 0.0, 1.0))
        return oracle.spatial_decoupling_law(J, Jdqd, B, n, R, Rd, qd, a, Fc, np.zeros(robot.n), range(6), True)

    theirs = median_ns(pinocchio_law, 300 if quick else 3000, rep)
    add(f"{name}: {LAW_ONE}", ours, speedup=theirs / ours, ratio=f"{theirs / ours:.0f}x faster than Pinocchio + NumPy")
    batched_rows()
    add(f"{name}: 6-D F* by Pinocchio (crba, nle, frame terms) + NumPy", theirs)


def controller_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """One sample of :class:`hybrid.Controller` (task scheme, six axes, step references) on a sphere:
    in C, and from Python."""
    kernel_function = generator.api().kernel_function
    controller_kernels = generator.api().controller_kernels
    arm = _arm_on_sphere(urdf, tip)
    if arm is None:
        return
    _, robot, sphere = arm
    # the same sample again and again: no sample clock to keep
    ctrl = Controller(robot, sphere, force_reference=Step(10.0, 20.0, 0.5), velocity_reference=Step(0.15, 0.3, 1.5),
                      timing_tolerance=None)
    q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5][:robot.n])
    qd, Fc = np.full(robot.n, 0.1), np.array([1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    ctrl._native()  # a controller builds its step at its first sample: built here, not timed
    step = ctrl._step  # the function the controller binds
    # every per-sample input zero but the sample's own (sizes as the step declares them)
    sizes = dict(step.inputs)
    values = {**{n: np.zeros(sizes[n]) for n in CONTROLLER_STEP.per_sample}, "q": q, "qd": qd, "Fc": Fc, "t": [0.3],
              **ctrl.step_inputs()}
    ops = kernel_function(controller_kernels(robot.chain, sphere.spec(), ctrl.axes)[0]).n_instructions()
    add(f"{name}: {STEP_IN_C}", c_harness_ns(step.unit.folder, step.unit.manifest["unit"], step.entry, values,
                                             50_000 if quick else 500_000, rep), ratio=f"{ops} generated operations")
    add(f"{name}: {STEP_ONE}", median_ns(lambda: ctrl(0.3, q, qd, Fc), 2000 if quick else 20000, rep))


def spatial_benchmarks(name: str, urdf: str, tip: str, rep: int, quick: bool, add) -> None:
    """The 6-D law (:func:`spatial_law_benchmarks`) and the controller step (:func:`controller_benchmarks`)."""
    spatial_law_benchmarks(name, urdf, tip, rep, quick, add)
    controller_benchmarks(name, urdf, tip, rep, quick, add)
