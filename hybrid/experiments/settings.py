"""The experiment's checks, the settings it derives, and its factories' overrides by keyword."""

from __future__ import annotations

import math
from dataclasses import fields, replace
from functools import lru_cache

import numpy as np

from hybrid.control.loops import Gains
from hybrid.control.options import ContactLoss
from hybrid.control.references import Step
from hybrid.control.wrench_sensor import WrenchSensor
from hybrid.deprecation import RENAMED, renamed_settings
from hybrid.errors import HybridError
from hybrid.plants.contact import Contact, Sensor, fastest_mode
from hybrid.spec.axes import AXIS_NAMES
from hybrid.user_warnings import RedundancyWarning, warn
from hybrid.validate import _finite, check_singular_tol, check_size, nearest, shown

#: where the loops' task frame is taken: at the actual contact point or at the desired one
FRAMES = ("actual", "desired")
#: how far from the surface a start point may lie [m]
START_TOL = 1e-3
#: the measured normal force below which a force axis is out of contact, by default [N]
TOUCH_THRESHOLD = 0.5


class RunSettings:
    """What an :class:`~hybrid.Experiment` derives from its settings (its base: sample counts, gains in
    force, the controller's keywords, the plant's array)."""

    @property
    def steps_per_sample(self) -> int:
        """How many integration steps (RK4, ``integration_step`` each) a control sample spans."""
        return round(self.sample_time / self.integration_step)

    @property
    def n_samples(self) -> int:
        """How many control samples (``sample_time`` each) the run's ``duration`` spans."""
        return math.ceil(self.duration / self.sample_time - 1e-9)

    def check_memory(self, record: dict | None = None) -> None:
        """Refuse, before anything sized by the run's length is allocated (its record, the path check's
        arrays), a run whose record would not fit in memory (:func:`hybrid.validate.check_size`, with the
        numbers). :meth:`Experiment.checked_start` calls it, before every run: simulated, swept or
        generated.

        Parameters
        ----------
        record : dict, optional
            The plant's columns (``state``, ``nq``, ``outputs``: :func:`hybrid.plants.interface.plant_record`);
            without it, the least any plant keeps (the joints' and the sensor tip's state and the torque).

        Raises
        ------
        HybridError
            A record larger than the share of the machine's memory a run may take, with the numbers.
        """
        nq = self.robot.n
        columns = (len(record["state"]) + record["nq"] + len(record["outputs"]) if record is not None
                   else 2 * nq + 4 + nq)
        steps = self.steps_per_sample * self.n_samples + 1
        check_size(f"duration = {self.duration} s at integration_step = {self.integration_step} s is {steps:,} RK4 "
                   "steps, whose record needs", steps * 8 * (columns + 3),  # doubles kept per RK4 step
                   "shorten duration or lengthen integration_step")

    def effective_gains(self) -> Gains:
        """The gains in force.

        Returns
        -------
        Gains
            ``gains``, or without integral action (``integral=False``) a copy with ``KI2v = KIf = 0``.
        """
        return self.gains if self.integral else replace(self.gains, KI2v=0.0, KIf=0.0)

    def controller_settings(self) -> dict:
        """The :class:`~hybrid.Controller` keywords every experiment sets alike.

        Returns
        -------
        dict
            By keyword: the force loop on the normal, the speed reference on ``t1`` (or the path task),
            gains, sampling, options.
        """
        loss = ContactLoss(self.touch_threshold, self.approach_speed) if self.approach_speed > 0 else None
        task = getattr(self, "path_task", None)  # a path task gives the references
        return {"selection": ("n",), "gains": self.gains, "path_task": task,
                "force_reference": None if task else self.force_reference,
                "velocity_reference": None if task else self.speed_reference, "sample_time": self.sample_time,
                "integral": self.integral, "curvature": self.curvature, "frame": self.frame,
                "path": self.desired_point if self.frame == "desired" else None, "singular_tol": self.singular_tol,
                "contact_loss": loss, "wrench_sensor": self.controller_wrench_sensor or self.wrench_sensor,
                "fault_reaction": self.fault_reaction}

    def plant_array(self) -> np.ndarray:
        """The ``plant[7]`` array of the generated C.

        Returns
        -------
        numpy.ndarray
            The sensor's ``m_s, K_s, D_s``, then the contact's ``k_e, d_e, gamma, v_eps``.
        """
        s, c = self.sensor, self.contact
        return np.array([s.mass, s.stiffness, s.damping, c.stiffness, c.damping, c.friction,
                         c.friction_smoothing])


def pressed(point, normal, F0: float, k_e: float, K_s: float) -> tuple[np.ndarray, np.ndarray]:
    """The sensor tip ``s`` and the arm tip ``r`` at rest, the sensor tip on the surface at ``point``
    (unit ``normal``) pressing with the force ``F0`` [N]: it penetrates ``F0/k_e`` (the surface's
    stiffness ``k_e`` [N/m], in equilibrium) and the arm tip sits ``F0/K_s`` beyond it (the sensor
    spring's ``K_s`` [N/m], in equilibrium)."""
    s = np.asarray(point, float) - normal * max(F0, 0.0) / k_e
    return s, s - normal * F0 / K_s


def free(point, normal, gap: float, sag) -> tuple[np.ndarray, np.ndarray]:
    """The sensor tip ``s`` and the arm tip ``r`` at rest out of contact: the sensor tip ``gap`` [m] from
    the surface's ``point`` along its unit ``normal``, the arm tip ``sag`` [m] (the tip mass's weight
    on the sensor spring, ``m_s g / K_s``, where the plant gives it gravity) above it, so the spring
    carries just that weight and nothing moves."""
    s = np.asarray(point, float) + gap * np.asarray(normal, float)
    return s, s - np.asarray(sag, float)


def check_sensing(exp) -> None:
    """The sensor's signal, the force/torque sensors and the start from free space, checked alike for
    every experiment (conventions §4, §14)."""
    exp.sensor.check_sampling(exp.sample_time)
    for name in ("wrench_sensor", "controller_wrench_sensor"):
        value = getattr(exp, name)
        if value is not None and not isinstance(value, WrenchSensor):
            raise HybridError(f"{name} = {shown(value, 60)}; give a hybrid.WrenchSensor(...) or None")
    if exp.controller_wrench_sensor is not None and exp.wrench_sensor is None:
        raise HybridError("controller_wrench_sensor is what the controller believes of the true sensor: give "
                          "wrench_sensor too (the true one)")
    if exp.wrench_sensor is not None:
        if any(exp.sensor.bias):
            raise HybridError(f"Sensor bias = {exp.sensor.bias} with a wrench_sensor: the true sensor's bias is "
                              "wrench_sensor=hybrid.WrenchSensor(bias=...) (in its axes); leave Sensor bias at 0")
        for sensor in (exp.wrench_sensor, exp.controller_wrench_sensor):
            if sensor is not None:
                sensor.mount(exp.robot)  # a URDF frame that is not there is refused now
                sensor.check_sampling(exp.sample_time)
    for name in ("start_gap", "approach_speed", "touch_threshold"):
        value = getattr(exp, name)
        _finite(type(exp).__name__, **{name: value})
        object.__setattr__(exp, name, float(value))
    units = {"start_gap": "m", "approach_speed": "m/s"}
    for name, unit in units.items():
        if getattr(exp, name) < 0:
            raise HybridError(f"{name} = {getattr(exp, name):g} {unit}; give a {name.replace('_', ' ')} >= 0 "
                              f"(0: {'start on the surface, pressed' if name == 'start_gap' else 'no approach'})")
    if exp.touch_threshold <= 0:
        raise HybridError(f"touch_threshold = {exp.touch_threshold:g} N; give the force below which the force axis "
                          f"is out of contact, > 0 (default {TOUCH_THRESHOLD:g} N)")
    if exp.start_gap > 0 and exp.approach_speed == 0:
        raise HybridError(f"start_gap = {exp.start_gap:g} m needs an approach speed to reach the surface: give "
                          "approach_speed > 0 [m/s], e.g. approach_speed=0.05")


def check_common_types(exp) -> None:
    """The experiment's fields of the kind they must be (references given as numbers become constant
    :class:`Step` references)."""
    owner = type(exp).__name__
    for name in ("integral", "curvature"):
        if not isinstance(getattr(exp, name), bool):
            raise HybridError(f"{name} = {shown(getattr(exp, name))}; give True or False")
    for name in ("controller", "frame"):
        if not isinstance(getattr(exp, name), str):
            raise HybridError(f"{name} = {shown(getattr(exp, name))}; give its name as a string")
    for name, typ in (("sensor", Sensor), ("contact", Contact), ("gains", Gains)):
        if not isinstance(getattr(exp, name), typ):
            raise HybridError(f"{name} = {shown(getattr(exp, name), 60)}; give a hybrid.{typ.__name__}(...)")
    for name in ("force_reference", "speed_reference"):
        ref = getattr(exp, name)
        if isinstance(ref, (int, float, np.integer, np.floating)) and not isinstance(ref, bool):
            _finite(owner, **{name: ref})
            object.__setattr__(exp, name, Step(float(ref), float(ref), 0.0))  # a constant reference
        elif not isinstance(ref, Step):
            raise HybridError(f"{name} = {shown(ref, 60)}; give a hybrid.Step(before, after, at) or a number")
    _finite(owner, model_error=exp.model_error, viscous_compensation=exp.viscous_compensation)
    if exp.frame not in FRAMES:
        raise HybridError(f"unknown frame {shown(exp.frame)}; choose one of {FRAMES}")
    check_singular_tol(owner, exp.singular_tol)


def check_model_source(exp) -> None:
    """One source of the controller's model of the arm: ``controller_robot`` as it is, or the true robot
    scaled by ``model_error`` and ``viscous_compensation``; both given is refused (the scaling would have
    no effect)."""
    if getattr(exp, "controller_robot", None) is None:
        return
    defaults = {f.name: f.default for f in fields(exp)}
    changed = [f"{name} = {getattr(exp, name)}" for name in ("model_error", "viscous_compensation")
               if getattr(exp, name) != defaults[name]]
    if changed:
        raise HybridError(f"{' and '.join(changed)} scale the true robot into the controller's model, but "
                          "controller_robot is that model as it is; give one or the other (leave model_error "
                          f"= {defaults['model_error']} and viscous_compensation = "
                          f"{defaults['viscous_compensation']}, their defaults, with a controller_robot)")


def check_timing(exp) -> None:
    """The run's timing and physics settings, checked alike for every experiment: duration, integration
    step and sample time (whole multiples, fast enough for the contact), model error, stable loops."""
    owner = type(exp).__name__
    h = exp.integration_step
    _finite(owner, duration=exp.duration, integration_step=h, sample_time=exp.sample_time)
    if exp.duration <= 0:
        raise HybridError(f"duration = {exp.duration} s; give a positive duration")
    if h <= 0 or exp.sample_time <= 0:
        raise HybridError(f"integration_step = {h} s and sample_time = {exp.sample_time} s must be positive")
    ratio = exp.sample_time / h
    if not math.isfinite(ratio) or ratio > 1e9:
        raise HybridError(f"integration_step = {h} s is too small for sample_time = {exp.sample_time} s "
                          "(over 1e9 steps a sample); give an integration_step of at least sample_time / 1e9")
    if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
        raise HybridError(f"sample_time = {exp.sample_time} s is not a whole multiple of integration_step = "
                          f"{h} s; choose integration_step = sample_time / k for a whole k")
    # fastest plant mode: sensor mass on the contact (and sensor) spring-dampers
    rate = fastest_mode(exp.sensor, exp.contact)
    if h * rate > 1.0:
        raise HybridError(
            f"integration_step = {h} s is too large for the contact: its fastest mode is {rate:.3g} rad/s "
            f"and RK4 needs integration_step * rate <= 1 for accuracy; use integration_step <= {1.0 / rate:.2e} s")
    check_friction_mode(exp)
    if exp.model_error <= -1 or exp.viscous_compensation < 0:
        raise HybridError(f"model_error = {exp.model_error} must be > -1 and viscous_compensation = "
                          f"{exp.viscous_compensation} >= 0")
    check_model_source(exp)
    if abs(exp.duration / exp.sample_time - round(exp.duration / exp.sample_time)) > 1e-9 * exp.n_samples:
        k = max(1, round(exp.duration / exp.sample_time))
        raise HybridError(f"duration = {exp.duration} s is not a whole number of samples of "
                          f"{exp.sample_time} s; give duration = {k * exp.sample_time:g} s")
    if not isinstance(exp.allow_unstable, bool):
        raise HybridError(f"allow_unstable = {shown(exp.allow_unstable, 40)}; give True (run loops predicted unstable) "
                          "or False")


def check_friction_mode(exp) -> None:
    """Refuse an integration step too long for the joints' friction: about rest the Coulomb friction's smooth
    sign is a viscosity ``F_c / v_s``, the joints' viscosity ``F_v + F_c / v_s`` in all
    (:attr:`hybrid.Robot.rest_viscosity`), whose fastest mode at the start is the largest eigenvalue of
    ``B^-1 V``. A URDF's viscosities are far slower than the contact; a sharp smooth sign, or a viscosity
    given in the wrong units, is not."""
    robot, h = exp.robot, exp.integration_step
    if not np.any(robot.rest_viscosity):
        return
    try:
        q = exp.initial_state()[:robot.n]
    except HybridError:
        return  # no start to take it at: the run refuses it, saying why
    rate = friction_rate(robot, tuple(q.tolist()))
    if h * rate > 1.0:
        what, fix = (("Coulomb friction: about rest it is a viscosity F_v + F_c / v_s whose", "a larger Robot "
                      "coulomb_speed") if any(robot.coulomb) else
                     ("viscosity: its", "check the Robot's damping (in N m s/rad or N s/m)"))
        raise HybridError(f"integration_step = {h} s is too large for the joints' {what} fastest mode is {rate:.3g} "
                          f"rad/s; use integration_step <= {1.0 / rate:.2e} s or {fix}")


@lru_cache(maxsize=1024)
def friction_rate(robot, q: tuple) -> float:
    """The joints' friction's fastest mode about rest at ``q`` [rad/s], the largest eigenvalue of ``B^-1 V``
    (once per robot and start: a sweep's runs that differ in other settings share it)."""
    B = robot.kind.rest_terms(robot, np.array(q))["B"][0]
    return float(np.max(np.linalg.eigvals(np.linalg.solve(B, np.diag(robot.rest_viscosity))).real))


#: short names of the references
REFERENCE_ALIASES = {"F_d": "force_reference", "v_d": "speed_reference"}


#: short prefixes of settings' paths: the planar arm's parameters (``arm.m2``) are its robot's closed form
PREFIX_ALIASES = {"arm.": "robot.closed_form."}


def setting_path(name: str) -> str:
    """The dotted path a setting name stands for (:func:`setting_aliases`, :data:`PREFIX_ALIASES`; a renamed
    setting's old name, :data:`hybrid.deprecation.RENAMED`, stands for its new one)."""
    head, dot, rest = name.partition(".")
    path = setting_aliases().get(name, RENAMED.get(head, head) + dot + rest)
    for short, long in PREFIX_ALIASES.items():
        if path.startswith(short):
            return long + path[len(short):]
    return path


def setting_aliases() -> dict[str, str]:
    """Short names of settings and the paths they stand for: ``F_d`` / ``v_d`` for the references,
    each gain by its own name (``KPf`` for ``gains.KPf``)."""
    return {**REFERENCE_ALIASES, **{f.name: f"gains.{f.name}" for f in fields(Gains)}}


def warn_redundancy(robot, axes: tuple[int, ...], posture) -> None:
    """Warn of a redundant task (more joints than task ``axes``) without a ``posture``: nothing holds the
    joint motion it leaves free (:class:`hybrid.RedundancyWarning`)."""
    if posture is None and robot.n > len(axes):
        warn(f"the arm {robot.name!r} has {robot.n} joints for {len(axes)} task axes "
             f"({', '.join(AXIS_NAMES[i] for i in axes)}) and no posture task: the joint motion the task leaves "
             "free falls under gravity and winds up (joint rates, torques, contact lost); give "
             "posture=hybrid.Posture(q_rest), a rest posture within the joint limits", RedundancyWarning)


def with_overrides(cls, maker: str, overrides: dict, defaults: dict | None = None):
    """``cls(**defaults, **overrides)`` where the gains may also be given one by one (``KPv=50``) and
    ``F_d`` / ``v_d`` name the force / speed references; an unknown name lists the known ones. A renamed
    setting's old name sets the new one, with a warning."""
    overrides = renamed_settings(overrides, maker, stacklevel=5)
    names = {f.name for f in fields(cls)}
    gain_names = {f.name for f in fields(Gains)}
    aliases = REFERENCE_ALIASES
    gains = {k: overrides.pop(k) for k in list(overrides) if k in gain_names}
    for alias, name in aliases.items():
        if alias in overrides:
            overrides[name] = overrides.pop(alias)
    unknown = sorted(set(overrides) - names)
    if unknown:
        known = sorted(names | gain_names | set(aliases))
        near = nearest(unknown[0], known)
        hint = f"did you mean {near!r}? (the known ones below)" if near else "see the known ones below"
        raise HybridError(f"unknown setting(s) {', '.join(unknown)} for {maker}; {hint}\n  known: {', '.join(known)}")
    if gains:
        base = overrides.get("gains", Gains())
        if not isinstance(base, Gains):
            raise HybridError(f"gains = {shown(base, 60)}; give a hybrid.Gains(...) to combine with {', '.join(gains)}")
        overrides["gains"] = replace(base, **gains)
    return cls(**{**(defaults or {}), **overrides})
