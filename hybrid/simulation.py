"""The runner: plant integrated by fixed-step RK4 between samples, controller under zero-order hold.

The loop over control samples is Python; everything inside a sample (the plant's RK4
steps, the controller's model terms) is compiled C, or the NumPy reference when
``Experiment.backend == "numpy"``. Runs are deterministic.
"""

from __future__ import annotations

import json
import math
import os
import zipfile
import zlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import files, reference
from .controllers import HybridController
from .errors import HybridError, NonFiniteError
from .experiment import Experiment
from .law import decoupling_law, planar_unit, status_error
from .loops import model_error_note
from .metrics import PLANT, PLANT_OUTPUTS, compute_metrics

OUT = {name: i for i, name in enumerate(PLANT_OUTPUTS)}


class SimulationError(HybridError):
    """The simulation cannot go on (singular pose, non-finite state); says when and where.

    ``time`` [s] is when it stopped; ``partial`` holds the run up to then (a
    :class:`SimulationResult` without metrics), to see how it got there.
    """

    def __init__(self, message: str, time: float | None = None, partial: SimulationResult | None = None):
        super().__init__(message)
        self.time, self.partial = time, partial


# ------------------------------------------------------------------ model terms


class NativeTerms:
    """The controller's model evaluated by the compiled C (single states, preallocated)."""

    def __init__(self, exp: Experiment):
        arm, surf = exp.controller_arm(), exp.surface
        curvature = exp.curvature and exp.frame == "actual"
        self._law = decoupling_law(arm, surf, curvature, backend=exp.backend, singular_tol=exp.singular_tol)
        unit = planar_unit(exp.backend)
        self._measure = unit.function(f"task_measurement_{surf.kind}")
        self._frame = unit.function(f"task_frame_{surf.kind}")
        self._arm, self._surface = arm.as_array(), surf.as_array()
        self._m_out = [np.empty(n) for _, n, _ in self._measure.outputs]
        self._f_out = [np.empty(n) for _, n, _ in self._frame.outputs]
        self._f_shapes = [shape for _, _, shape in self._frame.outputs]

    def measure(self, q, qdot, Fc):
        """``(r, r', R r', R F_c)``: what the controller measures."""
        status = self._measure.into(q, qdot, Fc, self._arm, self._surface, *self._m_out)
        if status:
            raise status_error(status, "task measurement", q=q, qdot=qdot, Fc=Fc)
        return tuple(o.copy() for o in self._m_out)

    def frame(self, r, rdot):
        """``(R, R')`` at ``r, r'``."""
        r, rdot = np.ascontiguousarray(r, float), np.ascontiguousarray(rdot, float)
        status = self._frame.into(r, rdot, self._surface, *self._f_out)
        if status:
            raise status_error(status, "task frame", r=r, rdot=rdot)
        return tuple(o.reshape(shape).copy() for o, shape in zip(self._f_out, self._f_shapes))

    def law(self, q, qdot, a, Fc):
        return self._law.torque(q, qdot, a, Fc)


class NumpyTerms:
    """The same terms from the plain NumPy reference (the benchmarks' and tests' baseline)."""

    def __init__(self, exp: Experiment):
        self.kind = exp.surface.kind
        self.arm, self.surface = exp.controller_arm().as_array(), exp.surface.as_array()
        self.curvature = exp.curvature and exp.frame == "actual"
        self.singular_tol = exp.singular_tol

    def measure(self, q, qdot, Fc):
        r, J, _ = reference.kinematics(q, qdot, self.arm)
        rd = J @ qdot
        R, _ = reference.frame(self.kind, r, rd, self.surface)
        return r, rd, R @ rd, R @ Fc

    def frame(self, r, rdot):
        return reference.frame(self.kind, np.asarray(r, float), np.asarray(rdot, float), self.surface)

    def law(self, q, qdot, a, Fc):
        # the same tests as the generated C, so both paths stop at the same sample
        inputs = {"q": q, "qdot": qdot, "a": a, "Fc": Fc}
        if not reference.conditioning(q, self.arm) >= self.singular_tol:
            raise status_error(1 if np.isfinite(q).all() else 2, "decoupling_law", **inputs)
        F, tau = reference.decoupling_law(self.kind, q, qdot, a, Fc, self.arm, self.surface, self.curvature)
        if not (np.isfinite(F).all() and np.isfinite(tau).all()):
            raise status_error(2, "decoupling_law", **inputs)
        return tau


# ------------------------------------------------------------------------ plant


class NativePlant:
    """Arm + sensor + surface, integrated by the compiled RK4 (the ``integrator`` of ``plant_rhs``)."""

    def __init__(self, exp: Experiment):
        unit = planar_unit(exp.backend)
        kind = exp.surface.kind
        self._rhs = unit.function(f"plant_rhs_{kind}")
        self._outputs = unit.function(f"plant_outputs_{kind}")
        self._arm, self._plant, self._surface = exp.arm.as_array(), exp.plant_array(), exp.surface.as_array()
        self._done = unit.module.ffi.new("int *")
        self.h = exp.step

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place, writing each step's state to ``trajectory``; steps done."""
        self._rhs.integrate(x, tau, self._arm, self._plant, self._surface, h=self.h, nsteps=nsteps,
                            trajectory=trajectory, done=self._done)
        return self._done[0]

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The output record (``PLANT_OUTPUTS``) of each state, in one native call."""
        states = np.ascontiguousarray(states)
        out = np.empty((len(states), len(PLANT_OUTPUTS)))
        # a partial run's last states may be non-finite: their records are kept as they come
        self._outputs.batch_into(states, self._arm, self._plant, self._surface, out,
                                 status=np.empty(len(states), dtype=np.intc))
        return out


class NumpyPlant:
    """The same plant stepped by the NumPy reference."""

    def __init__(self, exp: Experiment):
        self.kind, self.h = exp.surface.kind, exp.step
        self.arm, self.plant, self.surface = exp.arm.as_array(), exp.plant_array(), exp.surface.as_array()

    def advance(self, x, tau, nsteps, trajectory):
        for k in range(nsteps):
            nxt = reference.plant_advance(self.kind, x, tau, self.arm, self.plant, self.surface, self.h, 1)
            if not np.isfinite(nxt).all():
                return k  # like the C: x keeps the last finite state
            x[:] = trajectory[k] = nxt
        return nsteps

    def outputs(self, states):
        return np.array([reference.plant_outputs(self.kind, x, self.arm, self.plant, self.surface)
                         for x in states])


# -------------------------------------------------------------- initial state


#: how far from the surface a start point may lie [m] (it is projected onto it)
START_TOL = 1e-3
#: the most memory a run's record may take, as a fraction of the machine's
MEMORY_FRACTION = 0.5


def check_memory(exp: Experiment) -> None:
    """Refuse, before any work, a run whose record would not fit in memory (with the numbers)."""
    steps = exp.steps_per_sample * exp.n_samples + 1
    per_step = 8 * (len(PLANT["state"]) + PLANT["nq"] + len(PLANT_OUTPUTS) + 3)  # doubles kept per RK4 step
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
    """At rest, sensor tip on the surface at ``start_point``, pressing with ``F_d(0)``.

    The sensor tip penetrates ``F/k_e`` (surface in equilibrium), the arm tip sits ``F/K_s``
    beyond it (sensor spring in equilibrium); joints from inverse kinematics, elbow as asked.
    """
    surf, F0 = exp.surface, exp.force_reference(0.0)
    s_surf = surf.at(surf.arc_coordinate(exp.start_point))
    gap = float(np.linalg.norm(np.asarray(exp.start_point) - s_surf))
    if gap > START_TOL:
        raise HybridError(f"start_point {list(exp.start_point)} m is {gap * 1000:.1f} mm off the surface; give a "
                          f"point on it (within {START_TOL * 1000:g} mm), e.g. {np.round(s_surf, 4).tolist()}")
    n = surf.normal_at(s_surf)
    s = s_surf - n * max(F0, 0.0) / exp.contact.stiffness
    r = s - n * F0 / exp.sensor.stiffness
    q = inverse_kinematics(exp, r)
    return np.concatenate([q, [0.0, 0.0], s, [0.0, 0.0]])


def inverse_kinematics(exp: Experiment, r: np.ndarray) -> np.ndarray:
    L1, L2 = exp.arm.L1, exp.arm.L2
    dist2 = float(r @ r)
    c2 = (dist2 - L1**2 - L2**2) / (2 * L1 * L2)
    lo, hi = exp.arm.reach()
    if not -1.0 <= c2 <= 1.0:
        raise HybridError(f"the start point {np.round(r, 4).tolist()} m is out of the arm's reach "
                          f"({lo:.3f} m to {hi:.3f} m from the base); move the surface or start_point")
    q2 = exp.elbow * math.acos(c2)
    q1 = math.atan2(r[1], r[0]) - math.atan2(L2 * math.sin(q2), L1 + L2 * math.cos(q2))
    q = np.array([q1, q2])
    cond = reference.conditioning(q, exp.arm.as_array())
    if cond < max(exp.singular_tol, 1e-3):
        raise HybridError(f"the start point {np.round(r, 4).tolist()} m puts the arm at or near a singularity "
                          f"(q2 = {q2:.4f} rad, 2|det J|/|J|_F^2 = {cond:.2e}); move it inside the workspace")
    return q


def check_path(exp: Experiment, controller: HybridController) -> None:
    """Refuse a run whose desired path leaves the arm's workspace."""
    lo, hi = exp.arm.reach()
    for t in np.arange(exp.n_samples + 1) * exp.sample_time:
        p, _ = controller.desired_point(min(t, exp.duration))
        d = math.hypot(*p)
        if not lo + 1e-3 < d < hi - 1e-3:
            raise HybridError(f"the desired path leaves the arm's workspace at t = {t:.3f} s "
                              f"(point {np.round(p, 4).tolist()} m, {d:.3f} m from the base, reach "
                              f"{lo:.3f}-{hi:.3f} m); shorten duration, lower the speed or move the surface")


# --------------------------------------------------------------------- results


@dataclass
class SimulationResult:
    """Time series of one run (one row per integration step, ``t`` from 0) and its metrics.

    Units: ``t`` [s], ``q`` [rad], ``qdot`` [rad/s], ``tau`` [N m] (held per sample), forces [N],
    speeds [m/s], lengths [m]. Task quantities are in the frame ``R(r)`` at the arm tip.
    """

    experiment: Experiment
    t: np.ndarray
    state: np.ndarray
    tau: np.ndarray
    outputs: np.ndarray
    force_reference: np.ndarray
    speed_reference: np.ndarray
    metrics: dict = field(default_factory=dict)

    UNITS = {"t": "s", "state": ", ".join(PLANT["state_units"]), "tau": "N m",
             "force_reference": "N", "speed_reference": "m/s", "outputs": ", ".join(PLANT["output_units"])}

    @property
    def q(self):
        return self.state[:, 0:PLANT["nq"]]

    @property
    def qdot(self):
        return self.state[:, PLANT["nq"]:2 * PLANT["nq"]]

    def output(self, name: str) -> np.ndarray:
        """A column of the plant output record by name (``codegen.model.PLANT_OUTPUTS``)."""
        return self.outputs[:, OUT[name]]

    @property
    def force_normal(self):
        """Normal force measured by the sensor, ``(R(r) F_c)_n`` [N]."""
        return self.output("Fc_n")

    @property
    def force_tangential(self):
        return self.output("Fc_t")

    @property
    def velocity_tangential(self):
        """Tangential speed of the arm tip, ``(R(r) r')_t`` [m/s]."""
        return self.output("v_t")

    @property
    def velocity_normal(self):
        return self.output("v_n")

    @property
    def penetration(self):
        return self.output("penetration")

    @property
    def contact_force(self):
        return self.output("N")

    def save(self, path: str | Path, overwrite: bool = False) -> Path:
        """Write an ``.npz`` with every array, the units and the experiment's settings; returns the
        path written (``.npz`` is added when missing). Atomic; refuses an existing file unless
        ``overwrite``."""
        path = files.output_path(path)
        if path.suffix != ".npz":
            path = path.with_name(path.name + ".npz")

        def write(tmp: Path) -> None:
            with open(tmp, "wb") as f:  # a file object: NumPy adds no suffix to it
                np.savez_compressed(
                    f, t=self.t, state=self.state, tau=self.tau, outputs=self.outputs,
                    force_reference=self.force_reference, speed_reference=self.speed_reference,
                    output_names=np.array(PLANT_OUTPUTS), units=json.dumps(self.UNITS),
                    experiment=json.dumps(self.experiment.to_dict()), metrics=json.dumps(self.metrics))

        return files.write_with(path, write, overwrite)

    @classmethod
    def load(cls, path: str | Path) -> SimulationResult:
        """A result written by :meth:`save`; a missing, truncated or foreign file is a HybridError."""
        try:
            with np.load(path, allow_pickle=False) as z:
                arrays = {k: z[k] for k in ("t", "state", "tau", "outputs", "force_reference", "speed_reference")}
                experiment = Experiment.from_dict(json.loads(str(z["experiment"])))
                metrics = json.loads(str(z["metrics"]))
            n = len(arrays["t"])
            shapes = {"t": (n,), "state": (n, len(PLANT["state"])), "tau": (n, PLANT["nq"]),
                      "outputs": (n, len(PLANT_OUTPUTS)), "force_reference": (n,), "speed_reference": (n,)}
            wrong = [k for k, shape in shapes.items() if arrays[k].shape != shape]
            if wrong or n == 0 or not np.isfinite(arrays["t"]).all() or not isinstance(metrics, dict):
                raise ValueError(f"arrays {', '.join(wrong) or 't'} do not have the shapes of a run")
            return cls(experiment, arrays["t"], arrays["state"], arrays["tau"], arrays["outputs"],
                       arrays["force_reference"], arrays["speed_reference"], metrics)
        except (OSError, KeyError, ValueError, EOFError, zipfile.BadZipFile, zlib.error, TypeError,
                AttributeError) as exc:
            why = getattr(exc, "strerror", None) or f"{type(exc).__name__}: {exc}"
            raise HybridError(f"{path} is not a readable saved hybrid result ({why:.120}); "
                              "save it again with SimulationResult.save") from None

    def save_csv(self, path: str | Path, overwrite: bool = False) -> Path:
        """Write the time series as CSV, units in the header (atomic; refuses an existing file
        unless ``overwrite``)."""
        path = files.output_path(path)
        cols = {"t_s": self.t, "q1_rad": self.q[:, 0], "q2_rad": self.q[:, 1],
                "tau1_Nm": self.tau[:, 0], "tau2_Nm": self.tau[:, 1],
                "force_reference_N": self.force_reference, "speed_reference_m_per_s": self.speed_reference}
        units = dict(zip(PLANT_OUTPUTS, self.UNITS["outputs"].split(", ")))
        cols.update({f"{n}_{units[n].replace('/', '_per_').replace(' ', '')}": self.output(n)
                     for n in PLANT_OUTPUTS})
        return files.write_with(path, lambda tmp: np.savetxt(
            tmp, np.column_stack(list(cols.values())), delimiter=",", header=",".join(cols), comments="",
            fmt="%.10g"), overwrite)


# ---------------------------------------------------------------------- runner


def simulate(exp: Experiment) -> SimulationResult:
    """Run ``exp``: controller sampled every ``sample_time``, plant RK4 every ``step``."""
    if not isinstance(exp, Experiment):
        raise HybridError(f"simulate() takes an Experiment (see hybrid.paper_experiment()), "
                          f"got {type(exp).__name__}")
    numpy_path = exp.backend == "numpy"
    terms = NumpyTerms(exp) if numpy_path else NativeTerms(exp)
    plant = NumpyPlant(exp) if numpy_path else NativePlant(exp)
    controller = HybridController(exp, terms)
    check_memory(exp)
    x = initial_state(exp)
    check_path(exp, controller)

    m, n_samples = exp.steps_per_sample, exp.n_samples
    total = m * n_samples
    nq = PLANT["nq"]
    states = np.empty((total + 1, len(PLANT["state"])))
    taus = np.full((total + 1, nq), np.nan)  # NaN marks "no torque computed" in a partial run
    states[0] = x
    for k in range(n_samples):
        t = k * exp.sample_time
        q, qdot = x[0:nq].copy(), x[nq:2 * nq].copy()
        # the sensor's reading: its spring and damper between arm tip and sensor tip
        out = plant.outputs(x[None, :])[0]
        Fc = np.array([out[OUT["Fc_x"]], out[OUT["Fc_y"]]])
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
            raise _divergence(_result(exp, plant, states[:last], taus[:last], False), t, q, qdot, tau, x)
    return _result(exp, plant, states, taus, True)


def _divergence(partial: SimulationResult, t: float, q, qdot, tau, x) -> SimulationError:
    """The error for a plant state gone non-finite in the sample from ``t`` (state ``q, qdot`` then,
    torque ``tau``, last finite state ``x``): when, where, and the likely cause."""
    exp = partial.experiment
    t_fail = partial.t[-1] + exp.step
    cond = reference.conditioning(q, exp.arm.as_array())
    causes = [c.lstrip("; ") for c in (model_error_note(exp), _closest_singularity(partial)) if c]
    causes = causes or ["reduce step or check gains and parameters"]
    return SimulationError(
        f"the plant state became NaN or infinite at t = {t_fail:.5f} s: {causes[0]}\n"
        + "".join(f"  also: {c}\n" for c in causes[1:]) +
        f"  in the control sample from t = {t:.4f} s: q = {np.round(q, 5).tolist()} rad, qdot = "
        f"{np.round(qdot, 4).tolist()} rad/s, 2|det J|/|J|_F^2 = {cond:.3g}, tau = {np.round(tau, 3).tolist()} N m\n"
        f"  last finite state: q = {np.array2string(x[:len(q)], precision=4)} rad, qdot = "
        f"{np.array2string(x[len(q):2 * len(q)], precision=4)} rad/s",
        t_fail, partial)


def _closest_singularity(res: SimulationResult, near: float = 0.1) -> str:
    """Where a failed run passed closest to a singularity, when that was close (a clause of the message)."""
    arm, rows = res.experiment.arm.as_array(), range(0, len(res.t), 5)
    cond = np.array([reference.conditioning(res.q[i], arm) for i in rows])
    i = int(np.argmin(cond))
    if cond[i] >= near:
        return ""
    return (f"; the arm passed near a singularity (2|det J|/|J|_F^2 = {cond[i]:.2g} at t = {res.t[rows[i]]:.4f} s): "
            "raise singular_tol to stop there, or keep the path away from full extension")


def _result(exp: Experiment, plant, states: np.ndarray, taus: np.ndarray, metrics: bool) -> SimulationResult:
    t = np.arange(len(states)) * exp.step
    res = SimulationResult(exp, t, states, taus, plant.outputs(states),
                           np.array([exp.force_reference(ti) for ti in t]),
                           np.array([exp.speed_reference(ti) for ti in t]))
    if metrics:
        res.metrics = compute_metrics(res)
    return res
