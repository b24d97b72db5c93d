"""The runner: plant integrated by fixed-step RK4 between samples, controller under zero-order hold.

A run the compiled loop takes (:mod:`hybrid.closed_loop`: references that are numbers or
steps, the controller's frame at the contact point) runs there whole, as a sweep runs it. The
others run here: the loop over control samples in Python, everything inside a sample (the
plant's RK4 steps, one controller step) compiled C; a compiled run that stopped is run here
again, for the account of where and why. ``Experiment.backend == "numpy"`` runs the plain
NumPy reference instead (:mod:`hybrid.reference`, for tests and benchmarks). Runs are
deterministic.
"""

from __future__ import annotations

import math
import os
from functools import lru_cache

import numpy as np

from . import closed_loop
from .controller import Controller
from .errors import HybridError, NonFiniteError
from .experiment import Experiment, pressed
from .loops import model_error_note
from .performance import run_metrics
from .plants import PLANT, NativePlant, SpatialPlant
from .results import SimulationResult


class SimulationError(HybridError):
    """The simulation cannot go on (singular pose, non-finite state); says when and where.

    ``time`` [s] is when it stopped; ``partial`` holds the run up to then (a
    :class:`SimulationResult` without metrics), to see how it got there.
    """

    def __init__(self, message: str, time: float | None = None, partial: SimulationResult | None = None):
        super().__init__(message)
        self.time, self.partial = time, partial


# -------------------------------------------------------------- initial state


#: how far from the surface a start point may lie [m] (it is projected onto it)
START_TOL = 1e-3
#: the most memory a run's record may take, as a fraction of the machine's
MEMORY_FRACTION = 0.5


def check_memory(exp, record: dict = PLANT) -> None:
    """Refuse, before any work, a run whose record would not fit in memory (with the numbers)."""
    steps = exp.steps_per_sample * exp.n_samples + 1
    per_step = 8 * (len(record["state"]) + record["nq"] + len(record["outputs"]) + 3)  # doubles kept per RK4 step
    need = steps * per_step
    try:
        total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        return
    if need > MEMORY_FRACTION * total:
        raise HybridError(f"duration = {exp.duration} s at step = {exp.step} s is {steps:,} RK4 steps, whose record "
                          f"needs {need / 2**30:.1f} GiB; this machine has {total / 2**30:.1f} GiB: shorten "
                          "duration or lengthen step")


def initial_state(exp: Experiment) -> np.ndarray:
    """At rest, pressing at ``start_point`` (:meth:`~hybrid.experiment.RunSettings.pressed_at`); joints
    from inverse kinematics, elbow as asked."""
    return _initial_state(exp.arm, exp.surface, exp.start_point, exp.elbow, exp.singular_tol,
                          exp.force_reference(0.0), exp.contact.stiffness, exp.sensor.stiffness).copy()


# the runs of a sweep mostly start alike: what they share is worked out once (from its arguments only)
@lru_cache(maxsize=1024)
def _initial_state(arm, surf, start_point, elbow, singular_tol, F0, k_e, K_s) -> np.ndarray:
    s_surf = surf.at(surf.arc_coordinate(start_point))
    gap = float(np.linalg.norm(np.asarray(start_point) - s_surf))
    if gap > START_TOL:
        raise HybridError(f"start_point {list(start_point)} m is {gap * 1000:.1f} mm off the surface; give a "
                          f"point on it (within {START_TOL * 1000:g} mm), e.g. {np.round(s_surf, 4).tolist()}")
    s, r = pressed(s_surf, surf.normal_at(s_surf), F0, k_e, K_s)
    q = _inverse_kinematics(arm, elbow, singular_tol, r)
    return np.concatenate([q, [0.0, 0.0], s, [0.0, 0.0]])


def _inverse_kinematics(arm, elbow: int, singular_tol: float, r: np.ndarray) -> np.ndarray:
    L1, L2 = arm.L1, arm.L2
    dist2 = float(r @ r)
    c2 = (dist2 - L1**2 - L2**2) / (2 * L1 * L2)
    lo, hi = arm.reach()
    if not -1.0 <= c2 <= 1.0:
        raise HybridError(f"the start point {np.round(r, 4).tolist()} m is out of the arm's reach "
                          f"({lo:.3f} m to {hi:.3f} m from the base); move the surface or start_point")
    q2 = elbow * math.acos(c2)
    q1 = math.atan2(r[1], r[0]) - math.atan2(L2 * math.sin(q2), L1 + L2 * math.cos(q2))
    q = np.array([q1, q2])
    cond = arm.conditioning(q)
    if cond < max(singular_tol, 1e-3):
        raise HybridError(f"the start point {np.round(r, 4).tolist()} m puts the arm at or near a singularity "
                          f"(q2 = {q2:.4f} rad, 2|det J|/|J|_F^2 = {cond:.2e}); move it inside the workspace")
    return q


def check_path(exp: Experiment) -> None:
    """Refuse a run whose desired path leaves the arm's workspace."""
    _check_path(exp.arm.reach(), exp.surface, exp.start_point, exp.speed_reference, exp.n_samples,
                exp.sample_time, exp.duration)


@lru_cache(maxsize=1024)
def _check_path(reach, surf, start_point, speed_reference, n_samples, sample_time, duration) -> None:
    lo, hi = reach
    t = np.minimum(np.arange(n_samples + 1) * sample_time, duration)
    points = surf.points_at(surf.arc_coordinate(start_point) + speed_reference.integral(t))
    d = np.hypot(points[:, 0], points[:, 1])
    outside = np.flatnonzero(~((lo + 1e-3 < d) & (d < hi - 1e-3)))
    if len(outside):
        i = outside[0]
        raise HybridError(f"the desired path leaves the arm's workspace at t = {t[i]:.3f} s "
                          f"(point {np.round(points[i], 4).tolist()} m, {d[i]:.3f} m from the base, reach "
                          f"{lo:.3f}-{hi:.3f} m); shorten duration, lower the speed or move the surface")


# ---------------------------------------------------------------------- runner


def simulate(exp, plant: str = "generated", *, compiled: bool = True) -> SimulationResult:
    """Run ``exp`` (the paper's :class:`Experiment` or a :class:`~hybrid.tracing.TracingExperiment`):
    controller sampled every ``sample_time``, plant RK4 every ``step``. ``plant="mujoco"`` runs the
    paper's experiment with MuJoCo as the plant (:mod:`hybrid.mujoco_plant`). With ``compiled=False``
    the Python runner runs it even where the compiled loop could (the reference that loop is tested
    against; equal within rounding)."""
    if plant not in ("generated", "mujoco"):
        raise HybridError(f"plant = {plant!r}; give 'generated' (the compiled plant) or 'mujoco'")
    from .tracing import TracingExperiment, initial_tracing_state

    if isinstance(exp, TracingExperiment):
        if plant == "mujoco":
            raise HybridError("the MuJoCo plant runs the paper's experiment; the 3-D one runs on the generated plant")
        spatial = SpatialPlant(exp)
        check_memory(exp, spatial.record)
        return _compiled_or_run(exp, spatial, initial_tracing_state(exp, spatial), compiled)
    if not isinstance(exp, Experiment):
        raise HybridError(f"simulate() takes an experiment (see hybrid.paper_experiment() and "
                          f"hybrid.tracing_experiment()), got {type(exp).__name__}")
    check_memory(exp)  # before the path check, whose arrays grow with the run too
    x0 = initial_state(exp)
    check_path(exp)
    if plant == "mujoco":
        from .mujoco_plant import MujocoPlant

        return run(exp, MujocoPlant(exp), Controller.from_experiment(exp), x0)
    if exp.backend == "numpy":
        from . import reference  # the reference path only: the compiled runtime does not need it

        return run(exp, reference.NumpyPlant(exp), reference.NumpyController(exp), x0)
    return _compiled_or_run(exp, NativePlant(exp), x0, compiled)


def _compiled_or_run(exp, plant, x0: np.ndarray, compiled: bool = True) -> SimulationResult:
    """The whole run in compiled C when the loop takes it (as a sweep runs it), else, and for the
    account of a run that stopped there, the Python runner (the record's memory checked already)."""
    prepared = closed_loop.prepare(exp, x0) if compiled else None
    if prepared is not None:
        done = closed_loop.run([prepared], record=True)[0]
        if done.status == 0:
            return _result(exp, plant, done.states, done.taus, done.metrics)
    return run(exp, plant, Controller.from_experiment(exp), x0)


def run(exp, plant, controller, x0: np.ndarray) -> SimulationResult:
    """Run ``exp`` from the state ``x0`` with ``plant`` (see :mod:`hybrid.plants`) and
    ``tau = controller(t, q, qdot, Fc)`` under zero-order hold."""
    check_memory(exp, plant.record)
    x = np.array(x0, dtype=float)
    m, n_samples = exp.steps_per_sample, exp.n_samples
    total = m * n_samples
    nq = plant.nq
    states = np.empty((total + 1, len(x)))
    taus = np.full((total + 1, nq), np.nan)  # NaN marks "no torque computed" in a partial run
    states[0] = x
    for k in range(n_samples):
        t = k * exp.sample_time
        q, qdot = x[0:nq].copy(), x[nq:2 * nq].copy()
        # the sensor's reading: its spring and damper between arm tip and sensor tip
        Fc = plant.sensor_wrench(x)
        try:
            tau = np.ascontiguousarray(controller(t, q, qdot, Fc), dtype=float)
            if not np.isfinite(tau).all():
                raise NonFiniteError(f"the controller's torque is {tau.tolist()} N m")
        except HybridError as exc:
            raise SimulationError(
                f"at t = {t:.4f} s (q = {np.round(q, 5).tolist()} rad, qdot = {np.round(qdot, 4).tolist()} "
                f"rad/s): {exc}", t, _result(exp, plant, states[:1 + k * m], taus[:1 + k * m], False)) from exc
        if k == 0:
            taus[0] = tau  # the first sample's torque acts from t = 0
        rows = slice(1 + k * m, 1 + (k + 1) * m)
        done = plant.advance(x, tau, m, states[rows])
        taus[rows] = tau
        if done < m:
            last = 1 + k * m + done
            raise _divergence(_result(exp, plant, states[:last], taus[:last], False), plant, t, q, qdot, tau, x)
    return _result(exp, plant, states, taus, True)


def _divergence(partial: SimulationResult, plant, t: float, q, qdot, tau, x) -> SimulationError:
    """The error for a plant state gone non-finite in the sample from ``t`` (state ``q, qdot`` then,
    torque ``tau``, last finite state ``x``): when, where, and the likely cause."""
    exp = partial.experiment
    t_fail = partial.t[-1] + exp.step
    cond = plant.conditioning(q)
    causes = [c.lstrip("; ") for c in (model_error_note(exp), _closest_singularity(partial, plant)) if c]
    causes = causes or ["reduce step or check gains and parameters"]
    return SimulationError(
        f"the plant state became NaN or infinite at t = {t_fail:.5f} s: {causes[0]}\n"
        + "".join(f"  also: {c}\n" for c in causes[1:]) +
        f"  in the control sample from t = {t:.4f} s: q = {np.round(q, 5).tolist()} rad, qdot = "
        f"{np.round(qdot, 4).tolist()} rad/s, {plant.conditioning_name} = {cond:.3g}, "
        f"tau = {np.round(tau, 3).tolist()} N m\n"
        f"  last finite state: q = {np.array2string(x[:len(q)], precision=4)} rad, qdot = "
        f"{np.array2string(x[len(q):2 * len(q)], precision=4)} rad/s",
        t_fail, partial)


def _closest_singularity(res: SimulationResult, plant, near: float = 0.1) -> str:
    """Where a failed run passed closest to a singularity, when that was close (a clause of the message)."""
    rows = range(0, len(res.t), 5)
    cond = plant.conditioning(res.q[rows.start::rows.step])
    i = int(np.argmin(cond))
    if cond[i] >= near:
        return ""
    return (f"; the arm passed near a singularity ({plant.conditioning_name} = {cond[i]:.2g} at "
            f"t = {res.t[rows[i]]:.4f} s): raise singular_tol to stop there, or keep the path away from full extension")


def _result(exp, plant, states: np.ndarray, taus: np.ndarray, metrics: bool | dict) -> SimulationResult:
    """The result of a run; ``metrics``: computed from the series (True), none (False), or as given."""
    t = np.arange(len(states)) * exp.step
    res = SimulationResult(exp, t, states, taus, plant.outputs(states), exp.force_reference.sampled(t),
                           exp.speed_reference.sampled(t), record=plant.record)
    if metrics is True:
        res.metrics = run_metrics(res)
    elif metrics:
        res.metrics = dict(metrics)
    return res
