"""The paper's experiment as data: every setting of NOTES section 5, validated."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from functools import lru_cache
from typing import ClassVar

import numpy as np

from hybrid.control.controller import Controller
from hybrid.control.loops import Gains
from hybrid.control.references import Step
from hybrid.control.schemes import SCHEMES
from hybrid.errors import HybridError
from hybrid.experiments.settings import (
    START_TOL,
    RunSettings,
    check_common_types,
    check_timing,
    pressed,
    with_overrides,
)
from hybrid.geometry.surfaces import Circle, Plane
from hybrid.models.planar_arm import Arm, paper_arm
from hybrid.plants.compiled import NativePlant
from hybrid.plants.contact import Contact, Sensor
from hybrid.plants.mujoco import MujocoPlant
from hybrid.validate import SINGULAR_TOL, _point

#: the committed units that can run the paper's plant and law (the same equations, two derivations)
BACKENDS = ("sympy", "casadi")


@dataclass(frozen=True)
class Experiment(RunSettings):
    """One closed-loop run: plant, controller, references, integration settings.

    ``arm`` is the true arm; the controller's model is ``arm.with_model_error(model_error,
    viscous_compensation)``. ``frame``: task frame at the actual contact point ``R(r)`` or
    at the desired one ``R(r_d)`` (the paper's Figure 3). ``backend``: which committed unit
    runs the plant and the law in the Python runner (a run in the compiled loop,
    :mod:`hybrid.closed_loop`, does not depend on it), or ``"numpy"`` for the plain NumPy
    reference path.
    ``singular_tol``: the run stops when ``2 |det J| / |J|_F^2`` (about ``|sin q2|``) at a
    control sample falls below it.
    """

    controller: str = "task"
    integral: bool = True
    curvature: bool = False
    frame: str = "actual"
    model_error: float = 0.1
    viscous_compensation: float = 0.5
    arm: Arm = field(default_factory=paper_arm)
    surface: Circle | Plane = field(default_factory=lambda: Circle(center=(0.5, 0.0), radius=0.2))
    start_point: tuple[float, float] = (0.3, 0.0)
    elbow: int = 1
    sensor: Sensor = field(default_factory=Sensor)
    contact: Contact = field(default_factory=Contact)
    gains: Gains = field(default_factory=Gains)
    force_reference: Step = field(default_factory=lambda: Step(10.0, 20.0, 0.4))
    speed_reference: Step = field(default_factory=lambda: Step(0.3, 0.6, 1.0))
    duration: float = 2.0
    step: float = 1e-4
    sample_time: float = 1e-2
    backend: str = "sympy"
    singular_tol: float = SINGULAR_TOL

    #: the generated plant of these runs
    plant_class: ClassVar[type] = NativePlant

    def __post_init__(self):
        self._check_types()
        if self.controller not in SCHEMES:
            raise HybridError(f"unknown controller {self.controller!r}; choose one of {tuple(SCHEMES)}")
        if self.backend not in BACKENDS:
            raise HybridError(f"unknown backend {self.backend!r}; choose one of {BACKENDS}")
        if not isinstance(self.arm, Arm):
            raise HybridError(f"arm must be a hybrid.Arm, got {type(self.arm).__name__}")
        if not isinstance(self.surface, (Circle, Plane)) or self.surface.dim != 2:
            raise HybridError(f"unknown surface {self.surface!r:.60} for the paper's experiment; give a "
                              "hybrid.Circle or a 2-D hybrid.Plane")
        if self.elbow not in (1, -1):
            raise HybridError(f"elbow = {self.elbow}; give +1 (q2 > 0) or -1 (q2 < 0)")
        check_timing(self)

    def _check_types(self) -> None:
        """Every field of the kind it must be: a bool is a bool, a reference a Step or a number."""
        check_common_types(self)
        if not isinstance(self.backend, str):
            raise HybridError(f"backend = {self.backend!r}; give its name as a string")
        if isinstance(self.elbow, bool) or not isinstance(self.elbow, (int, np.integer)):
            raise HybridError(f"elbow = {self.elbow!r}; give +1 (q2 > 0) or -1 (q2 < 0)")
        object.__setattr__(self, "start_point", _point("Experiment", "start_point", self.start_point))

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``r_d(t)`` [m] on the surface, reached from ``start_point`` at the desired speed, and
        ``r_d'(t)`` [m/s] (along the tangent ``t = (-n_y, n_x)``)."""
        surf, vref = self.surface, self.speed_reference
        p = surf.at(surf.arc_coordinate(self.start_point) + vref.integral(t))
        n = surf.normal_at(p)
        return p, vref(t) * np.array([-n[1], n[0]])

    def initial_state(self) -> np.ndarray:
        """The run's start state ``x0 = (q, q', s, s')``: at rest, the sensor tip pressing at
        ``start_point`` with ``F_d(0)`` (:meth:`~hybrid.experiments.settings.RunSettings.pressed_at`),
        the joints from the arm's inverse kinematics, elbow as asked. What a foreign loop starts from."""
        return _initial_state(self.arm, self.surface, self.start_point, self.elbow, self.singular_tol,
                              self.force_reference(0.0), self.contact.stiffness, self.sensor.stiffness).copy()

    def check_path(self) -> None:
        """Refuse a run whose desired path leaves the arm's workspace."""
        _check_path(self.arm.reach(), self.surface, self.start_point, self.speed_reference, self.n_samples,
                    self.sample_time, self.duration)

    def plant(self) -> NativePlant:
        """The generated plant of this run (the committed unit of ``backend``)."""
        return self.plant_class(self)

    def mujoco_plant(self):
        """MuJoCo as this run's plant (:mod:`hybrid.plants.mujoco`; needs the ``mujoco`` extra): the arm
        as :meth:`hybrid.Robot.planar`, the sensor tip without gravity, as in the planar plant."""
        from hybrid.models.robot import Robot

        return MujocoPlant(self, Robot.planar(self.arm), sensor_gravity=False)

    def build_controller(self) -> Controller:
        """Exactly the controller this run uses: its model of the arm, its loops, references, options."""
        return Controller(self.controller_arm(), self.surface, self.controller, **self.controller_settings())

    def controller_arm(self) -> Arm:
        """The controller's (wrong) model of the arm."""
        return self.arm.with_model_error(self.model_error, self.viscous_compensation)

    def to_dict(self) -> dict:
        d = asdict(self)
        d["surface"] = {"kind": self.surface.kind, **asdict(self.surface)}
        return d

    @classmethod
    def from_dict(cls, d: dict) -> Experiment:
        """The experiment :meth:`to_dict` wrote; anything else is a HybridError."""
        try:
            return cls._from_dict(d)
        except (KeyError, TypeError, AttributeError, ValueError) as exc:
            if isinstance(exc, HybridError):
                raise
            raise HybridError(f"not an experiment's settings ({type(exc).__name__}: {exc})") from None

    @classmethod
    def _from_dict(cls, d: dict) -> Experiment:
        d = dict(d)
        surf = dict(d.pop("surface"))
        kind = surf.pop("kind")
        surface = Circle(**surf) if kind == "circle" else Plane(**surf)
        parts = {"arm": Arm, "sensor": Sensor, "contact": Contact, "gains": Gains,
                 "force_reference": Step, "speed_reference": Step}
        for k, typ in parts.items():
            d[k] = typ(**d[k])
        d["start_point"] = tuple(d["start_point"])
        return cls(surface=surface, **d)



def paper_experiment(**overrides) -> Experiment:
    """The paper's experiment (NOTES section 5), with any setting overridden by keyword.

    Besides every field of :class:`Experiment`, the gains can be given one by one
    (``KPv=50``) and ``F_d`` / ``v_d`` replace the force / speed references.
    """
    return with_overrides(Experiment, "paper_experiment", overrides)


# the runs of a sweep mostly start alike: what they share is worked out once (from its arguments only)
@lru_cache(maxsize=1024)
def _initial_state(arm, surf, start_point, elbow, singular_tol, F0, k_e, K_s) -> np.ndarray:
    s_surf = surf.at(surf.arc_coordinate(start_point))
    gap = float(np.linalg.norm(np.asarray(start_point) - s_surf))
    if gap > START_TOL:
        raise HybridError(f"start_point {list(start_point)} m is {gap * 1000:.1f} mm off the surface; give a "
                          f"point on it (within {START_TOL * 1000:g} mm), e.g. {np.round(s_surf, 4).tolist()}")
    s, r = pressed(s_surf, surf.normal_at(s_surf), F0, k_e, K_s)
    q = arm.inverse_kinematics(r, elbow)
    cond = arm.conditioning(q)
    if cond < max(singular_tol, 1e-3):
        raise HybridError(f"the start point {np.round(r, 4).tolist()} m puts the arm at or near a singularity "
                          f"(q2 = {q[1]:.4f} rad, 2|det J|/|J|_F^2 = {cond:.2e}); move it inside the workspace")
    return np.concatenate([q, [0.0, 0.0], s, [0.0, 0.0]])


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
