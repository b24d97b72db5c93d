"""The runner: plant integrated by fixed-step RK4 between samples, controller under zero-order hold.

A run the compiled loop takes (:mod:`hybrid.simulation.closed_loop`: references that are
numbers or steps, the controller's frame at the contact point) runs there whole, as a sweep runs
it. The others run here: the loop over control samples in Python, everything inside a sample
(the plant's RK4 steps, one controller step) compiled C; a compiled run that stopped is run here
again, for the account of where and why. The NumPy oracle runs through the same runner
(:func:`hybrid.oracle.simulate`, for tests and benchmarks). Runs are deterministic.
"""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError, NonFiniteError
from hybrid.experiments.experiment import Experiment
from hybrid.plants.registry import plant_for
from hybrid.simulation import closed_loop
from hybrid.simulation.limits import warn_limit_violations
from hybrid.simulation.metrics import run_metrics
from hybrid.simulation.results import SimulationResult
from hybrid.simulation.sensing import plant_reader
from hybrid.spec.interfaces import STATUS_CODES
from hybrid.stability.analysis import predicted_note
from hybrid.validate import checked_keywords, shown


class SimulationError(HybridError):
    """The simulation cannot go on (singular pose, non-finite state); says when and where.

    Parameters
    ----------
    message : str
        What happened, when and where.
    time : float or None
        When the run stopped [s] (kept as ``time``).
    partial : SimulationResult or None
        The run up to then, without metrics, to see how it got there (kept as ``partial``).

    Examples
    --------
    >>> import hybrid
    >>> error = hybrid.SimulationError(
    ...     "the arm reached a singular pose at t = 0.5 s", time=0.5)
    >>> error.time, error.partial is None
    (0.5, True)
    >>> isinstance(error, hybrid.HybridError)
    True
    """

    def __init__(self, message: str, time: float | None = None, partial: SimulationResult | None = None):
        super().__init__(message)
        self.time, self.partial = time, partial


# -------------------------------------------------------------- initial state


# ---------------------------------------------------------------------- runner


@checked_keywords
def simulate(exp, plant: str = "generated", *, compiled: bool = True) -> SimulationResult:
    """Run the experiment ``exp``: its controller sampled every ``sample_time`` under zero-order hold,
    its plant advanced by RK4 every ``integration_step``.

    Parameters
    ----------
    exp : Experiment
        The experiment to run (e.g. :func:`hybrid.paper_experiment`).
    plant : str
        One of :data:`hybrid.plants.registry.PLANTS`: ``"generated"`` (default; the experiment's own:
        the paper's arm in closed form, else its rigid-body plant) or ``"mujoco"`` (MuJoCo reading the
        arm's URDF, :mod:`hybrid.plants.mujoco`).
    compiled : bool
        False: the Python runner runs it even where the compiled loop could (the reference that loop
        is tested against; equal within rounding).

    Returns
    -------
    SimulationResult
        The run's signals, sampled at every integration step, and its metrics.

    Raises
    ------
    HybridError
        ``exp`` is not an experiment, or ``plant`` is not a plant's name.
    SimulationError
        The run cannot go on (a singular pose, a non-finite state); it carries the run up to then.

    Warns
    -----
    JointLimitWarning
        The run left the robot's joint limits.

    Examples
    --------
    >>> import hybrid
    >>> exp = hybrid.paper_experiment(duration=0.05)
    >>> result = hybrid.simulate(exp)
    >>> float(result.t[-1])
    0.05
    >>> result.metrics["contact_losses"]
    0
    """
    if not isinstance(exp, Experiment):
        raise HybridError(f"simulate() takes an experiment (see hybrid.paper_experiment() and "
                          f"hybrid.tracing_experiment()), got {type(exp).__name__}")
    model = plant_for(exp, plant)
    x0 = exp.checked_start(model.record)  # the record's memory before anything sized by the run
    # the compiled loop runs the experiment's own generated plant
    result = _compiled_or_run(exp, model, x0, compiled and isinstance(model, exp.plant_class))
    warn_limit_violations(result)
    return result


def _compiled_or_run(exp, plant, x0: np.ndarray, compiled: bool = True) -> SimulationResult:
    """The whole run in compiled C when the loop takes it (as a sweep runs it), else, and for the
    account of a run that stopped there, the Python runner (the record's memory checked already), with
    the one controller built for it."""
    controller = exp.build_controller()
    prepared = closed_loop.prepare(exp, x0, lanes=1, ctrl=controller) if compiled else None
    if prepared is not None:
        done = closed_loop.run([prepared], record=True)[0]
        if done.status == STATUS_CODES["OK"]:
            return _result(exp, plant, done.states, done.taus, done.metrics, outputs=done.outputs)
    return run(exp, plant, controller, x0)


def run(exp, plant, controller, x0: np.ndarray) -> SimulationResult:
    """Run ``exp`` from the state ``x0`` (:meth:`~hybrid.Experiment.checked_start`, given ``plant``'s
    record: its memory is checked there) with ``plant`` (see :mod:`hybrid.plants`) and
    ``tau = controller(t, q, qdot, Fc)`` under zero-order hold. Where the sensor drops out
    (``Sensor.dropout_duration``), the torque each faulted sample's error carries is applied (as a real
    arm's loop does: the controller's fault reaction), elsewhere an error ends the run."""
    x = np.array(x0, dtype=float)
    m, n_samples = exp.steps_per_sample, exp.n_samples
    total = m * n_samples
    nq = plant.nq
    states = np.empty((total + 1, len(x)))
    taus = np.full((total + 1, nq), np.nan)  # NaN marks "no torque computed" in a partial run
    states[0] = x
    # what the controller is given: the plant's sensor force, or the sensor's signal (conventions §14)
    read = plant_reader(exp, plant) or plant.sensor_wrench
    # an estimated surface's normal, at each sample (after it)
    estimates = getattr(controller, "normal", None) is not None  # any callable controller runs here
    normals = np.full((n_samples, 3), np.nan) if estimates else None
    for k in range(n_samples):
        t = k * exp.sample_time
        q, qdot = x[0:nq].copy(), x[nq:2 * nq].copy()
        # the sensor's reading: its spring and damper between arm tip and sensor tip
        Fc = read(x)
        try:
            tau = np.ascontiguousarray(_applied(controller, t, q, qdot, Fc, exp.sensor.drops_out),
                                       dtype=float)
            if not np.isfinite(tau).all():
                raise NonFiniteError(f"the controller's torque is {tau.tolist()} N m")
        except HybridError as exc:
            first, _, rest = str(exc).partition("\n")
            # a frame or a result undefined: where the surface's formula is, that is why
            tips = {"the arm tip r": _arm_tip(plant, x), "the sensor tip s": _sensor_tip(x, nq)}
            where = _undefined_surface(exp, {k: v for k, v in tips.items() if v is not None})
            first = f"{where}\n  {first}" if where else first
            raise SimulationError(
                f"at t = {t:.4f} s: {first}\n  q = {np.round(q, 5).tolist()} rad, qdot = "
                f"{np.round(qdot, 4).tolist()} rad/s" + (f"\n{rest}" if rest else ""),
                t, _result(exp, plant, states[:1 + k * m], taus[:1 + k * m], False)) from exc
        if normals is not None:
            normals[k] = controller.normal
        if k == 0:
            taus[0] = tau  # the first sample's torque acts from t = 0
        rows = slice(1 + k * m, 1 + (k + 1) * m)
        done = plant.advance(x, tau, m, states[rows])
        taus[rows] = tau
        if done < m:
            last = 1 + k * m + done
            raise _divergence(_result(exp, plant, states[:last], taus[:last], False), plant, t, q, qdot, tau, x)
    return _result(exp, plant, states, taus, True, normals)


def _applied(controller, t: float, q, qdot, Fc, faults: bool):
    """The controller's torque at a sample; where ``faults`` are injected, a faulted sample's too (the torque
    its error carries, as a real arm's loop applies it)."""
    try:
        return controller(t, q, qdot, Fc)
    except HybridError as exc:
        if not faults or getattr(exc, "torque", None) is None:
            raise
        return exc.torque


def _divergence(partial: SimulationResult, plant, t: float, q, qdot, tau, x) -> SimulationError:
    """The error for a plant state gone non-finite in the sample from ``t`` (state ``q, qdot`` then,
    torque ``tau``, last finite state ``x``): when, where, and the likely cause."""
    exp = partial.experiment
    t_fail = partial.t[-1] + exp.integration_step
    cond = plant.conditioning(q)
    causes = [c.lstrip("; ") for c in (_left_the_surface(exp, x, len(q)), predicted_note(exp),
                                       _closest_singularity(partial, plant)) if c]
    causes = causes or ["reduce integration_step or check gains and parameters"]
    return SimulationError(
        f"the plant state became NaN or infinite at t = {t_fail:.5f} s: {causes[0]}\n"
        + "".join(f"  also: {c}\n" for c in causes[1:]) +
        f"  in the control sample from t = {t:.4f} s: q = {np.round(q, 5).tolist()} rad, qdot = "
        f"{np.round(qdot, 4).tolist()} rad/s, {plant.conditioning_name} = {cond:.3g}, "
        f"tau = {np.round(tau, 3).tolist()} N m\n"
        f"  last finite state: q = {np.array2string(x[:len(q)], precision=4)} rad, qdot = "
        f"{np.array2string(x[len(q):2 * len(q)], precision=4)} rad/s",
        t_fail, partial)


#: where along the integration step from the last finite state the sensor tip is looked at (fractions of
#: the step, as its RK4 stages reach, and a little beyond)
_STAGES = np.linspace(0.0, 1.5, 13)


def _left_the_surface(exp, x: np.ndarray, nq: int) -> str:
    """Where the sensor tip left the domain of the surface's formula in the integration step from the
    last finite state ``x`` (a clause), or ''."""
    s, sd = _sensor_tip(x, nq), x[2 * nq + 3:2 * nq + 6]
    if s is None:
        return ""
    along = s + np.outer(_STAGES * exp.integration_step, sd)
    i = exp.surface.undefined_at(along)
    return "" if i is None else _undefined_surface(exp, {"the sensor tip s": along[i]})


def _undefined_surface(exp, points: dict) -> str:
    """'phi ... is undefined at <the first of ``points`` (by name) where it is>', or ''."""
    names = list(points)
    i = exp.surface.undefined_at([points[n] for n in names]) if names else None
    if i is None:
        return ""
    off_band = getattr(exp.surface, "off_band", None)
    if off_band is not None:  # a part: defined within its fitted band
        return f"at {names[i]}, {off_band(points[names[i]])}"
    formula = getattr(exp.surface, "phi", None)
    what = f"the surface's phi = {shown(formula, 60)}" if formula is not None else f"the {exp.surface.kind}'s phi"
    return (f"{what} is undefined (or has no normal) at {names[i]} = {np.round(points[names[i]], 5).tolist()} m; "
            "keep the path where phi is defined, or write phi so that it is")


def _sensor_tip(x: np.ndarray, nq: int) -> np.ndarray | None:
    """The sensor tip ``s`` of a 3-D plant's state ``x = (q, q', s, s')`` (None for another plant)."""
    return x[2 * nq:2 * nq + 3] if len(x) == 2 * nq + 6 else None


def _arm_tip(plant, x: np.ndarray) -> np.ndarray | None:
    """The arm tip ``r`` of the plant's output record at ``x`` (None where the record has none in 3-D)."""
    names = plant.record["outputs"]
    if not all(c in names for c in ("r_x", "r_y", "r_z")):
        return None
    row = plant._record_row(x)
    return np.array([row[names.index(c)] for c in ("r_x", "r_y", "r_z")])


def _check_signals(res: SimulationResult, plant) -> None:
    """Stop a run whose record of what the metrics read (normal force, tangential speed, penetration,
    contact force) is not a finite number at a row, as the compiled loop stops it: where and why (the
    task frame or the contact undefined where a tip went), never metrics over NaN."""
    signals = np.column_stack([res.force_normal, res.velocity_tangential, res.penetration, res.contact_force])
    bad = np.flatnonzero(~np.isfinite(signals).all(axis=1))
    if len(bad) == 0:
        return
    i, exp = int(bad[0]), res.experiment
    x = res.state[i]
    tips = {"the arm tip r": _arm_tip(plant, x), "the sensor tip s": _sensor_tip(x, plant.nq)}
    why = _undefined_surface(exp, {k: v for k, v in tips.items() if v is not None})
    raise SimulationError(
        f"the run's force, speed or penetration became NaN or infinite at t = {res.t[i]:.5f} s: "
        + (why or "the task frame at the arm tip is undefined there (its direction e parallel to the normal)"),
        float(res.t[i]), _result(exp, plant, res.state[:max(i, 1)], res.tau[:max(i, 1)], False))


def _closest_singularity(res: SimulationResult, plant, near: float = 0.1) -> str:
    """Where a failed run passed closest to a singularity, when that was close (a clause of the message)."""
    rows = range(0, len(res.t), 5)
    cond = plant.conditioning(res.q[rows.start::rows.step])
    i = int(np.argmin(cond))
    if cond[i] >= near:
        return ""
    return (f"; the arm passed near a singularity ({plant.conditioning_name} = {cond[i]:.2g} at "
            f"t = {res.t[rows[i]]:.4f} s): raise singular_tol to stop there, or keep the path away from full extension")


def _result(exp, plant, states: np.ndarray, taus: np.ndarray, metrics: bool | dict,
            normals: np.ndarray | None = None, outputs: np.ndarray | None = None) -> SimulationResult:
    """The result of a run; ``metrics``: computed from the series (True), none (False), or as given;
    ``normals``: an estimated surface's normal at each sample; ``outputs``: the output record of each
    state, when the compiled loop gave it (else the plant computes it)."""
    t = np.arange(len(states)) * exp.integration_step
    outputs = plant.outputs(states) if outputs is None else outputs
    res = SimulationResult(exp, t, states, taus, outputs, exp.force_reference.sampled(t),
                           exp.speed_reference.sampled(t), record=plant.record, normal_estimate=normals)
    if metrics is True:
        _check_signals(res, plant)
        res.metrics = run_metrics(res)
    elif metrics:
        res.metrics = dict(metrics)
    return res
