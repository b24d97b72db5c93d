"""Our generated 6-D decoupling law F* and controller step against the same written by hand in C++ on
Pinocchio + Eigen (:mod:`hybrid.bench.eigen_race`, ``c/eigen_law.hpp``), for a URDF arm on the
benchmarks' sphere, six task axes.

First both sides must give the same statuses and outputs on random states (to :data:`AGREEMENT`,
relative) under two settings of the step (the bench's, and one where Khatib's scheme, the torque
limits, the anti-windup and the loss of contact act), and the hand-written side must take no memory
from the heap; then each is timed in one program (the sides one after the other, medians), and its
instructions per call counted by part (callgrind, where valgrind is installed; an x86-64-v3 build of
the same code, as valgrind runs no AVX-512): on the hand-written side the robot's terms (kinematics;
dynamics), the task frame, the law's algebra, the conditioning guard, the loops and the limits; on ours
the robot's terms and the task frame timed alone (our law and step are one generated function each),
and on both the maths library's share (sine, cosine, tanh).
"""

from __future__ import annotations

import math
import statistics

import numpy as np

from hybrid.bench import eigen_race
from hybrid.bench import pinocchio_codegen as pc
from hybrid.bench.harness import paired_ratio
from hybrid.bench.robots import SPHERE, comparable_urdf
from hybrid.bench.targets import EIGEN_FORMS, eigen_row
from hybrid.control.controller import Controller
from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Sphere
from hybrid.models.robot import Robot
from hybrid.spec.controller_step import OPTIONS

#: the largest difference between the sides' outputs, relative to the largest number of ours in the output and
#: times the state's conditioning of the task Jacobian (:func:`conditioning`), that counts as the same: both
#: sides' rounding grows as the conditioning falls (a state accepted just above the singular tolerance,
#: 1e-3, has numbers a thousand times less certain than one where J is well conditioned)
AGREEMENT = 2e-13
#: the bench's joint positions (the first n)
Q = (0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5)


def controller(robot: Robot, sphere: Sphere) -> Controller:
    """The bench's controller: the task scheme on six axes, force and speed references with steps."""
    return Controller(robot, sphere, force_reference=Step(10.0, 20.0, 0.5), velocity_reference=Step(0.15, 0.3, 1.5),
                      timing_tolerance=None)


def config_of(ctrl: Controller, **options: float) -> dict:
    """The race's fixed inputs (:data:`hybrid.bench.eigen_race.CONFIG`) from ``ctrl``'s step: its parameters,
    the law's curvature on and its singular tolerance, and the step's ``options`` changed by name."""
    config = {**ctrl.step_inputs(), "opts": [1.0], "singular_tol": [ctrl.singular_tol]}
    step_options = np.array(config["options"], float)
    for name, value in options.items():
        step_options[OPTIONS.index(name)] = value
    return {**config, "options": step_options}


def bench_state(n: int) -> dict:
    """The state the bench times: the law's benchmark's joints, speeds, task acceleration and wrench,
    the step's integrals and last torque zero at 0.3 s."""
    rng = np.random.default_rng(2)
    return {"q": np.array(Q[:n]), "qd": rng.normal(0, 0.5, n), "a": rng.normal(size=6), "Fc": rng.normal(0, 5, 6),
            "tau0": np.zeros(n), "integrals": np.zeros(12), "last_torque": np.zeros(n + 1), "t": [0.3],
            "yd_extra": np.zeros(6), "yd_rate": np.zeros(6)}


def random_states(n: int, count: int, seed: int = 0) -> list[dict]:
    """``count`` states of an ``n``-joint arm: angles anywhere, speeds, accelerations, wrenches, null-space
    torques, integrals and last torques (half of them written) of usual sizes, times across the steps."""
    rng = np.random.default_rng(seed)
    return [{"q": rng.uniform(-np.pi, np.pi, n), "qd": rng.normal(0, 1, n), "a": rng.normal(size=6),
             "Fc": rng.normal(0, 5, 6), "tau0": rng.normal(0, 2, n), "integrals": rng.normal(0, 0.05, 12),
             "last_torque": [*rng.normal(0, 20, n), rng.integers(0, 2)], "t": [rng.uniform(0, 3)],
             "yd_extra": rng.normal(0, 0.1, 6), "yd_rate": rng.normal(0, 0.1, 6)} for _ in range(count)]


def acting(ctrl: Controller) -> dict:
    """Fixed inputs under which every branch of the step acts on random states: Khatib's scheme, the
    curvature term off, torque limits and rates of 600 N m (which bind on a part of :func:`random_states`),
    an anti-windup limit and a loss of contact below 2 N approached at 5 cm/s."""
    config = config_of(ctrl, curvature=0.0, khatib=1.0, integral_limit=0.5, loss_threshold=2.0,
                       approach_speed=0.05)
    n = len(ctrl.robot.joint_names)
    return {**config, "limits": np.full(2 * n, 600.0)}


def conditioning(robot: Robot, urdf, tip: str, states: list[dict]) -> np.ndarray:
    """Each state's conditioning of the task Jacobian, ``6 / (|J|_F |J^+|_F)`` (the laws' guard), from
    Pinocchio's Python bindings and NumPy."""
    import pinocchio as pin

    model, frame = eigen_race.pinocchio_model(robot, urdf, tip)
    data, out = model.createData(), []
    for s in states:
        J = pin.computeFrameJacobian(model, data, np.asarray(s["q"], float), frame, pin.LOCAL_WORLD_ALIGNED)
        out.append(6.0 / (np.linalg.norm(J) * np.linalg.norm(np.linalg.pinv(J))))
    return np.array(out)


def differences(race: eigen_race.EigenRace, config: dict, states: list[dict],
                scale: np.ndarray | None = None) -> dict[tuple[str, str], float]:
    """The largest difference between each hand-written side's outputs and ours on ``states``, relative to
    the largest number of ours in each output (each output on its own scale) and times the state's
    ``scale`` (default 1; :func:`conditioning` for :data:`AGREEMENT`), the worst over the outputs and the
    states, by function and side; where a status differs, infinity. States where our status is not OK are
    compared on their status alone."""
    found = race.evaluate(config, states)
    worst = {}
    for function in eigen_race.FUNCTIONS:
        status, ours = found[function, "ours"]
        ok = status == 0
        weight = np.ones(len(status)) if scale is None else np.asarray(scale, float)
        for side in race.sides[1:]:
            theirs_status, theirs = found[function, side]
            if (theirs_status != status).any():
                worst[function, side] = math.inf
                continue
            worst[function, side] = 0.0
            for name, mine in ours.items():
                a, b = mine[ok], theirs[name][ok]
                if a.size:
                    size = np.maximum(np.abs(a).max(axis=1), np.finfo(float).tiny)
                    d = np.abs(a - b).max(axis=1) / size * weight[ok]
                    worst[function, side] = max(worst[function, side], float(d.max()))
    return worst


def _parts_text(parts: dict[str, float]) -> str:
    """A side's instructions a call by part, as a row says them."""
    named = {"kinematics": "kinematics", "dynamics": "crba + nle", "sphere_frame": "frame",
             "operational": "law's algebra", "inverse_dynamics": "rnea + LU", "conditioning": "guard", "loops": "loops",
             "limits": "limits", "libm": "libm"}
    return ", ".join(f"{label} {parts[key]:,.0f}" for key, label in named.items() if parts.get(key))


def eigen_law_benchmarks(name: str, urdf_name: str, tip: str, rep: int, quick: bool, add) -> None:
    """The 6-D law and the controller step of the shipped arm ``urdf_name`` on the bench's sphere, ours and
    by hand on Pinocchio + Eigen: the same numbers and no heap memory (or a HybridError), then the median
    time of a call of each side, the ratios, and the instructions a call by part."""
    urdf = comparable_urdf(name, urdf_name, "Pinocchio + Eigen", eigen_race.missing)
    if urdf is None:
        return
    robot = Robot.from_urdf(urdf, tip=tip)
    sphere = Sphere(SPHERE[:3], SPHERE[3])
    race = eigen_race.race(robot, urdf, tip, sphere.spec())
    ctrl = controller(robot, sphere)
    config, state = config_of(ctrl), bench_state(robot.n)
    worst: dict[tuple[str, str], float] = {}
    for settings, seed in ((config, 1), (acting(ctrl), 2)):
        states = random_states(robot.n, 20 if quick else 200, seed)
        for key, d in differences(race, settings, states, conditioning(robot, urdf, tip, states)).items():
            worst[key] = max(worst.get(key, 0.0), d)
    if max(worst.values()) > AGREEMENT:
        raise HybridError(f"{name}: our law and step and those written on Pinocchio + Eigen differ by more "
                          f"than {AGREEMENT:g} (relative, times the conditioning): " + ", ".join(
                              f"{f} ({s}) {d:.1e}" for (f, s), d in worst.items()))
    heap = race.allocations(config, state)
    if any(heap.values()):
        raise HybridError(f"{name}: the law written on Pinocchio + Eigen takes heap memory in its calls: {heap}")
    # short rounds, many: the ratio is the median of the rounds' (harness.paired_ratio)
    times = race.time(config, state, 20_000 if quick else 40_000, rep if quick else 5 * rep)
    counted = eigen_race.race(robot, urdf, tip, sphere.spec(), counted=True) if pc.can_count() else None

    def count(function: str) -> dict[str, float]:
        return counted.instructions(config, state, function) if counted else {}

    ours_parts = {part: count(f"{part}_ours").get("total") for part in ("terms", "frame")}
    for function in eigen_race.FUNCTIONS:
        median = {side: statistics.median(times[function, side]) for side in race.sides}
        counts = {side: count(f"{function}_{side}") for side in race.sides}
        best = min(race.sides[1:], key=median.get)
        speedup = paired_ratio(times[function, best], times[function, "ours"])
        ours = counts["ours"].get("total")
        ins = "" if ours is None else (
            f"; {ours:,.0f} instructions a call (libm {counts['ours']['libm']:,.0f}; alone: the robot's terms "
            f"{ours_parts['terms']:,.0f}, the task frame {ours_parts['frame']:,.0f})")
        add(f"{name}: {eigen_row(function, 'ours')}", median["ours"], speedup=speedup, instructions=ours,
            agreement=max(worst[function, s] for s in race.sides[1:]),
            ratio=f"Pinocchio + Eigen's time / ours: {speedup:.2f}x ({EIGEN_FORMS[best]}); the same to "
                  f"{max(worst[function, s] for s in race.sides[1:]):.0e} (relative, times the conditioning){ins}")
        for side in race.sides[1:]:
            theirs = counts[side].get("total")
            ins = "" if theirs is None or ours is None else (
                f"; {theirs:,.0f} instructions a call ({theirs / ours:.2f}x ours): {_parts_text(counts[side])}")
            of_ours = paired_ratio(times[function, side], times[function, "ours"])
            add(f"{name}: {eigen_row(function, side)}", median[side], of_ours=of_ours,
                instructions=theirs, parts=counts[side] or None, heap=heap[function, side],
                ratio=f"{of_ours:.2f}x the time of ours, no heap memory{ins}")
