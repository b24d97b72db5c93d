"""An experiment's sampled loops as the numbers of :mod:`hybrid.stability.model`, at its start.

The arm's terms are taken where the run starts (the contact at rest): the task Jacobian ``J_t`` from the
controller's own measurement (the task velocities per unit joint velocity, in its task frame and axes),
the true arm's ``B`` and viscosities ``V_q``, the controller's model's. So ``G = J_t B^-1 J_t^T``,
``M = G Lambda_hat`` with ``Lambda_hat = (J_t B_hat^-1 J_t^T)^-1``, ``V = J_t B^-1 V_q J_t^+`` (and
``V_hat`` of the model's ``V_q``), ``K = J_t B^-1 d(J^T F_0 - g)/dq J_t^+``.
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.control.wrench_sensor import filter_coefficients
from hybrid.errors import HybridError
from hybrid.models.terms import arm_terms
from hybrid.stability.model import Structure

#: task-axis indices below this are linear (t1, t2, n), the rest rotations
LINEAR_AXES = 3

#: the model's numbers that are matrices over the task axes
MATRICES = ("mobility", "gain", "viscosity", "compensated_viscosity", "held_stiffness")


def arm_terms_at_start(exp) -> dict[str, np.ndarray]:
    """The task-axis matrices (:data:`MATRICES`) of ``exp`` at its start, with the
    controller's ``axes`` (indices 0-5) and ``selection`` (1: a force axis).

    Raises
    ------
    HybridError
        The start cannot be worked out (the message says why).
    """
    x0 = exp.initial_state()
    n = exp.robot.n
    model = exp.controller_model()
    controller = exp.build_controller()
    tip = arm_terms_of(exp.robot, x0[:n])
    d = len(tip)  # the sensor's spring force on the robot at the start, base axes
    wrench = exp.sensor.stiffness * (x0[2 * n:2 * n + d] - tip)
    key = (exp.robot, model, tuple(x0[:n].tolist()), tuple(wrench.tolist()))
    return _terms(key, controller)


def arm_terms_of(robot, q) -> np.ndarray:
    """The arm tip's position [m] at ``q`` (2 coordinates for the planar arm, else 3)."""
    return np.asarray(arm_terms(robot, q, np.zeros_like(q))["r"], float)


def _terms(key, controller) -> dict:
    cached = _TERMS.get(key)
    if cached is None:
        robot, model, q, wrench = key
        cached = _TERMS[key] = _worked_out(robot, model, np.array(q), np.array(wrench), controller)
        if len(_TERMS) > 1024:
            _TERMS.pop(next(iter(_TERMS)))
    return cached


_TERMS: dict = {}


def _worked_out(robot, model, q: np.ndarray, wrench: np.ndarray, controller) -> dict:
    n = robot.n
    axes = tuple(controller.axes)
    # J_t: the controller's task velocities (its frame, its axes) per unit joint velocity
    Jt = np.stack([controller.measure(q, e, np.zeros(6)).task_velocity[list(axes)] for e in np.eye(n)], axis=1)
    B = arm_terms(robot, q, np.zeros(n))["B"]
    B_hat = arm_terms(model, q, np.zeros(n))["B"]
    G = Jt @ np.linalg.solve(B, Jt.T)
    Lambda_hat = np.linalg.inv(Jt @ np.linalg.solve(B_hat, Jt.T))
    pinv = np.linalg.pinv(Jt)
    viscosity = {name: Jt @ np.linalg.solve(B, np.diag(np.asarray(arm.damping, float)) @ pinv)
                 for name, arm in (("viscosity", robot), ("compensated_viscosity", model))}
    K = Jt @ np.linalg.solve(B, _held_stiffness(robot, q, wrench) @ pinv)
    force = tuple(bool(s) for s in controller.selection)
    return {"mobility": G, "gain": G @ Lambda_hat, **viscosity, "held_stiffness": K, "axes": axes, "force": force}


def _held_stiffness(robot, q: np.ndarray, wrench: np.ndarray, step: float = 1e-6) -> np.ndarray:
    """``d(J^T F_0 - g)/dq`` [N m/rad] at ``q`` (central differences): what the arm feels between samples
    as its configuration leaves the sample's, whose ``J^T F_0`` and gravity the held torque carries."""
    n = robot.n
    Q = q + step * np.concatenate([np.eye(n), -np.eye(n)])
    terms = arm_terms(robot, Q, np.zeros_like(Q))
    J, g = np.asarray(terms["J"]), np.asarray(terms["n"])
    W = np.zeros(J.shape[1])
    W[:len(wrench)] = wrench
    held = np.einsum("kij,i->kj", J, W) - g
    return ((held[:n] - held[n:]) / (2 * step)).T


def axis_names(axes) -> tuple[str, ...]:
    """The task axes' names for indices 0-5."""
    names = ("t1", "t2", "n", "rot_t1", "rot_t2", "rot_n")
    return tuple(names[i] for i in axes)


def loop_numbers(exp, terms: dict | None = None) -> tuple[Structure, dict]:
    """The coupled model's :class:`~hybrid.stability.model.Structure` and numbers for ``exp``."""
    terms = arm_terms_at_start(exp) if terms is None else terms
    g = exp.effective_gains()
    sensor, contact, T = exp.sensor, exp.contact, exp.sample_time
    told = exp.controller_wrench_sensor or exp.wrench_sensor
    cutoff = None if told is None else told.cutoff
    integrals = tuple((int(g.KIf != 0) if f else int(g.KIv != 0 or g.KI2v != 0) + int(g.KI2v != 0))
                      for f in terms["force"])
    st = Structure(force=terms["force"], linear=tuple(i < LINEAR_AXES for i in terms["axes"]),
                   delay=sensor.delay_samples, lag=sensor.bandwidth_hz is not None, filtered=cutoff is not None,
                   integrals=integrals)
    p = {"sample_time": T, **{k: terms[k] for k in MATRICES},
         "sensor_mass": sensor.mass, "sensor_stiffness": sensor.stiffness, "sensor_damping": sensor.damping,
         "contact_stiffness": contact.stiffness, "contact_damping": contact.damping,
         "lag": 0.0 if sensor.bandwidth_hz is None else math.exp(-2 * math.pi * sensor.bandwidth_hz * T),
         "filter": filter_coefficients(cutoff, 1 if told is None else told.order, T),
         **{k: float(v) for k, v in vars(g).items()}}
    if not any(st.force):
        raise HybridError("the experiment has no force axis; the sampled loops' model needs the contact's")
    return st, p
