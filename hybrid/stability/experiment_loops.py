"""An experiment's sampled loops as the numbers of :mod:`hybrid.stability.model`, at its start.

The arm's terms are taken where the run starts (the contact at rest), from the robot's kind
(:meth:`~hybrid.models.kinds.SerialChain.rest_terms`: no controller is built for it): the task Jacobian
``J_t`` (the frame Jacobian's rows in the task frame at the start point, the controller's axes), the true
arm's ``B`` and viscosities ``V_q``, the controller's model's. So ``G = J_t B^-1 J_t^T``, ``M = G
Lambda_hat`` with ``Lambda_hat = (J_t B_hat^-1 J_t^T)^-1``, ``V = J_t B^-1 V_q J_t^+`` (and ``V_hat`` of
the model's ``V_q``), ``K = J_t B^-1 d(J^T F_0 - g)/dq J_t^+``.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.schemes import scheme_of
from hybrid.control.wrench_sensor import filter_coefficients
from hybrid.errors import HybridError
from hybrid.experiments.settings import RunSettings
from hybrid.geometry.task_axes import check_axes, frame_rows
from hybrid.plants.contact import lag_pole
from hybrid.stability.model import Structure

#: task-axis indices below this are linear (t1, t2, n), the rest rotations
LINEAR_AXES = 3
#: the task axis a force loop acts on (the experiments' selection: the normal)
FORCE_AXIS = 2

#: the model's numbers that are matrices over the task axes
MATRICES = ("mobility", "gain", "viscosity", "compensated_viscosity", "held_stiffness")

#: the longest delay of the reading the model takes [samples]: each sample of it adds a state per sensed axis,
#: and the eigenvalues' cost grows as its cube (a second at 100 samples on the 3-D arms; margins, tens)
MOST_DELAY_SAMPLES = 100


def check_delay(delay: int) -> None:
    """Refuse a reading's delay longer than the model takes (:data:`MOST_DELAY_SAMPLES`)."""
    if delay > MOST_DELAY_SAMPLES:
        raise HybridError(f"Sensor delay_samples = {delay} is beyond the {MOST_DELAY_SAMPLES} samples the sampled "
                          "loops' model takes (hybrid.stability, and the experiment's check: give a shorter delay, "
                          "or allow_unstable=True to run it unchecked)")


def check_experiment(exp, what: str) -> None:
    """Refuse an ``exp`` that is not an experiment, in words, before any of its settings is read (the
    experiment's base, :class:`~hybrid.experiments.settings.RunSettings`: its own module imports this one)."""
    if not isinstance(exp, RunSettings):
        raise HybridError(f"{what}() takes an experiment (e.g. hybrid.paper_experiment()), got "
                          f"{type(exp).__name__}; make one with a factory or hybrid.Experiment(...)")


def arm_terms_at_start(exp) -> dict[str, np.ndarray]:
    """The task-axis matrices (:data:`MATRICES`) of ``exp`` at its start, with the controller's ``axes``
    (indices 0-5) and which of them are ``force`` axes.

    Raises
    ------
    HybridError
        The start cannot be worked out (the message says why).
    """
    x0 = exp.initial_state()
    n = exp.robot.n
    R = frame_rows(exp._geometry().normal_at(tuple(np.asarray(exp.start()).tolist())), exp.frame_direction)
    axes = check_axes(exp.robot, exp.axes)
    # the controller's model by what makes it (controller_model() builds a robot: most of a cache hit's cost)
    model = (exp.controller_robot,) if exp.controller_robot is not None else (exp.model_error, exp.viscous_compensation)
    key = (exp.robot, model, tuple(x0[:n].tolist()), tuple(x0[2 * n:].tolist()), exp.sensor.stiffness,
           tuple(R.ravel().tolist()), axes)
    found = _TERMS.get(key)
    if found is None:
        found = _TERMS[key] = _worked_out(exp.robot, exp.controller_model(), x0, R, axes, exp.sensor.stiffness)
        if len(_TERMS) > 1024:
            _TERMS.pop(next(iter(_TERMS)))
    return found


_TERMS: dict = {}


def _worked_out(robot, model, x0: np.ndarray, R: np.ndarray, axes: tuple, K_s: float) -> dict:
    n = robot.n
    q = x0[:n]
    here = robot.kind.rest_terms(robot, q)
    tip = here["r"][0]
    wrench = K_s * (x0[2 * n:2 * n + len(tip)] - tip)  # the sensor's spring on the robot at the start, base axes
    rotate = np.kron(np.eye(2), R)                     # twists into the task frame, linear then angular
    Jt = (rotate @ here["J"][0])[list(axes)]
    B = here["B"][0]
    B_hat = model.kind.rest_terms(model, q)["B"][0]
    G = Jt @ np.linalg.solve(B, Jt.T)
    Lambda_hat = np.linalg.inv(Jt @ np.linalg.solve(B_hat, Jt.T))
    pinv = np.linalg.pinv(Jt)
    viscosity = {name: Jt @ np.linalg.solve(B, np.diag(arm.rest_viscosity) @ pinv)
                 for name, arm in (("viscosity", robot), ("compensated_viscosity", model))}
    K = Jt @ np.linalg.solve(B, _held_stiffness(robot, q, wrench) @ pinv)
    force = tuple(axis == FORCE_AXIS for axis in axes)
    return {"mobility": G, "gain": G @ Lambda_hat, **viscosity, "held_stiffness": K, "axes": axes, "force": force}


def _held_stiffness(robot, q: np.ndarray, wrench: np.ndarray, step: float = 1e-6) -> np.ndarray:
    """``d(J^T F_0 - g)/dq`` [N m/rad] at ``q`` (central differences): what the arm feels between samples
    as its configuration leaves the sample's, whose ``J^T F_0`` and gravity the held torque carries."""
    n = robot.n
    Q = q + step * np.concatenate([np.eye(n), -np.eye(n)])
    terms = robot.kind.rest_terms(robot, Q)
    W = np.zeros(6)
    W[:len(wrench)] = wrench
    held = np.einsum("kij,i->kj", terms["J"], W) - terms["g"]
    return ((held[:n] - held[n:]) / (2 * step)).T


def axis_names(axes) -> tuple[str, ...]:
    """The task axes' names for indices 0-5."""
    names = ("t1", "t2", "n", "rot_t1", "rot_t2", "rot_n")
    return tuple(names[i] for i in axes)


def loop_numbers(exp, terms: dict | None = None) -> tuple[Structure, dict]:
    """The coupled model's :class:`~hybrid.stability.model.Structure` and numbers for ``exp``."""
    check_delay(exp.sensor.delay_samples)
    terms = arm_terms_at_start(exp) if terms is None else terms
    g = exp.effective_gains()
    sensor, contact, T = exp.sensor, exp.contact, exp.sample_time
    told = exp.controller_wrench_sensor or exp.wrench_sensor
    cutoff = None if told is None else told.cutoff
    integrals = tuple((int(g.KIf != 0) if f else int(g.KIv != 0 or g.KI2v != 0) + int(g.KI2v != 0))
                      for f in terms["force"])
    st = Structure(force=terms["force"], linear=tuple(i < LINEAR_AXES for i in terms["axes"]),
                   delay=sensor.delay_samples, lag=sensor.bandwidth_hz is not None, filtered=cutoff is not None,
                   integrals=integrals, feeds_desired_force=scheme_of(exp.controller).feeds_desired_force)
    p = {"sample_time": T, **{k: terms[k] for k in MATRICES},
         "sensor_mass": sensor.mass, "sensor_stiffness": sensor.stiffness, "sensor_damping": sensor.damping,
         "contact_stiffness": contact.stiffness, "contact_damping": contact.damping,
         "lag": float(lag_pole(sensor.bandwidth_hz, T)),
         "filter": filter_coefficients(cutoff, 1 if told is None else told.order, T),
         **{k: float(v) for k, v in vars(g).items()}}
    if not any(st.force):
        raise HybridError("the experiment has no force axis; the sampled loops' model needs the contact's")
    return st, p
