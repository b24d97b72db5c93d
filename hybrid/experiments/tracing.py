"""The 3-D experiment of NOTES section 10 as data: a URDF arm tracing a path on a surface.

The default is the UR5 (the URDF shipped by example-robot-data, kept in ``hybrid/data``) on a
sphere of radius 0.15 m, along the latitude circle 60 degrees from its top, with the references,
loops, sampling, integration and model error of the paper's experiment.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field, fields
from typing import ClassVar

import numpy as np

from hybrid.control.controller import Controller
from hybrid.control.loops import Gains
from hybrid.control.references import Step
from hybrid.control.schemes import scheme_of
from hybrid.errors import HybridError
from hybrid.experiments.settings import START_TOL, RunSettings, check_common_types, check_timing, with_overrides
from hybrid.geometry.surfaces import Sphere, Surface
from hybrid.geometry.task_axes import reference_direction
from hybrid.models.robot import Robot
from hybrid.models.shipped import UR5_URDF, ur5  # noqa: F401  (UR5_URDF: re-exported)
from hybrid.plants.compiled import SpatialPlant
from hybrid.plants.contact import Contact, Sensor
from hybrid.validate import SINGULAR_TOL, _finite

#: the sphere of the default experiment: in front of the UR5, within reach and away from its
#: singularities along the whole path (a choice, NOTES section 10)
SPHERE_CENTER, SPHERE_RADIUS = (0.5, 0.0, 0.2), 0.15


@dataclass(frozen=True)
class TracingExperiment(RunSettings):
    """One closed-loop run of a URDF arm on a 3-D surface (NOTES section 10).

    The sensor tip starts on the surface at ``start_point`` [m] (default: on the latitude circle
    ``latitude`` degrees from a sphere's top, on the side facing the robot), pressing with
    ``F_d(0)``, the tool's z axis along ``-n``. The task frame's reference direction is ``e``;
    the force loop runs on ``n``, the speed reference on ``t1`` (the latitude circle's direction
    on a sphere with ``e = z``), every other axis holds velocity 0. ``controller`` names a
    scheme (``"task"``, ``"khatib"``, ``"raibert_craig"``, ``"fisher_mujtaba"``).
    """

    controller: str = "task"
    integral: bool = True
    curvature: bool = False
    frame: str = "actual"
    model_error: float = 0.1
    viscous_compensation: float = 0.5
    robot: Robot = field(default_factory=ur5)
    surface: Surface = field(
        default_factory=lambda: Sphere(SPHERE_CENTER, SPHERE_RADIUS))
    latitude: float = 60.0
    start_point: tuple[float, float, float] | None = None
    reference: tuple[float, float, float] = (0.0, 0.0, 1.0)
    sensor: Sensor = field(default_factory=Sensor)
    contact: Contact = field(default_factory=Contact)
    gains: Gains = field(default_factory=Gains)
    force_reference: Step = field(default_factory=lambda: Step(10.0, 20.0, 0.5))
    speed_reference: Step = field(default_factory=lambda: Step(0.15, 0.3, 1.5))
    duration: float = 3.0
    step: float = 1e-4
    sample_time: float = 1e-2
    singular_tol: float = SINGULAR_TOL

    #: the generated plant of these runs
    plant_class: ClassVar[type] = SpatialPlant

    def __post_init__(self):
        check_common_types(self)
        scheme_of(self.controller)
        if not isinstance(self.robot, Robot):
            raise HybridError(f"robot must be a hybrid.Robot (e.g. hybrid.Robot.from_urdf), got "
                              f"{type(self.robot).__name__}")
        if not isinstance(self.surface, Surface) or self.surface.dim != 3:
            raise HybridError(f"surface = {self.surface!r:.60}; give a hybrid Sphere, Plane, Cylinder or "
                              "ImplicitSurface")
        _finite("tracing_experiment", latitude=self.latitude)
        if not 0 < self.latitude < 180:
            raise HybridError(f"latitude = {self.latitude} degrees from the top; give a value in (0, 180)")
        object.__setattr__(self, "reference", tuple(reference_direction(self.reference)))
        if self.start_point is None and not isinstance(self.surface, Sphere):
            raise HybridError(f"a {type(self.surface).__name__} has no latitude circle: give start_point, a "
                              "point on the surface [m]")
        if self.frame == "desired" and not isinstance(self.surface, Sphere):
            raise HybridError("frame='desired' follows the latitude circle of a Sphere; use frame='actual' here")
        if self.start_point is not None:
            try:
                point = tuple(float(v) for v in self.start_point)
            except (TypeError, ValueError):
                point = ()
            if len(point) != 3 or not all(map(math.isfinite, point)):
                raise HybridError(f"start_point = {self.start_point!r:.60}; give (x, y, z) [m]")
            object.__setattr__(self, "start_point", point)
        check_timing(self)

    def to_dict(self) -> dict:
        """The settings as JSON-ready data (the robot by name and joints; the surface by kind and values)."""
        from dataclasses import asdict

        d = {f.name: getattr(self, f.name) for f in fields(self) if f.name not in ("robot", "surface")}
        for name in ("sensor", "contact", "gains", "force_reference", "speed_reference"):
            d[name] = asdict(d[name])
        # the robot and surface by name and a digest of everything that defines them (for sweeps' resume)
        robot = repr((self.robot.chain, self.robot.links, self.robot.damping, self.robot.gravity)).encode()
        d["robot"] = {"name": self.robot.name, "joints": list(self.robot.joint_names),
                      "digest": hashlib.sha256(robot).hexdigest()[:16]}
        spatial = self.surface.lift()
        d["surface"] = {"kind": self.surface.kind, "parameters": self.surface.as_array().tolist(),
                        "phi": spatial.spec().key()}
        return {"kind": "tracing", **d}

    # ------------------------------------------------------------------ derived

    def build_controller(self) -> Controller:
        """Exactly the controller this run uses: its model of the arm (all six task axes of a 6-joint
        arm or more, else the position axes), loops, references, options."""
        robot = self.controller_robot()
        return Controller(robot, self.surface, self.controller, axes="all" if robot.n >= 6 else "position",
                          reference=self.reference, **self.controller_settings())

    def controller_robot(self) -> Robot:
        """The controller's (wrong) model of the arm."""
        return self.robot.with_model_error(self.model_error, self.viscous_compensation)

    def _circle(self) -> tuple[np.ndarray, float, float, float]:
        """The sphere's latitude circle: centre, radius, height above the sphere's centre, and the
        longitude of the start (facing the robot's base)."""
        sph = self.surface
        c = np.asarray(sph.center, float)
        polar = math.radians(self.latitude)
        return c, sph.radius * math.sin(polar), sph.radius * math.cos(polar), math.atan2(-c[1], -c[0])

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``p_d(t)`` on the latitude circle at the desired speed (counter-clockwise seen from +z,
        the direction of ``t1 = z x n``), and ``p_d'(t)``."""
        c, rho, h, psi0 = self._circle()
        psi = psi0 + self.speed_reference.integral(t) / rho
        radial = np.array([math.cos(psi), math.sin(psi), 0.0])
        tangent = np.array([-math.sin(psi), math.cos(psi), 0.0])
        return c + rho * radial + np.array([0.0, 0.0, h]), self.speed_reference(t) * tangent

    def plant(self) -> SpatialPlant:
        """The generated plant of this run (the true arm, sensor, contact on the surface)."""
        return self.plant_class(self)

    def mujoco_plant(self):
        raise HybridError("the MuJoCo plant runs the paper's experiment; the 3-D one runs on the generated plant")

    def initial_state(self) -> np.ndarray:
        """The run's start state ``x0 = (q, q', s, s')``: at rest, the sensor tip pressing at the start
        point (:meth:`~hybrid.experiments.settings.RunSettings.pressed_at`), the tool's z axis along
        ``-n`` (its x axis along ``t1``), the joints from inverse kinematics of the true arm."""
        return initial_tracing_state(self, self.plant())

    def check_path(self) -> None:
        """Nothing to refuse before the run: the start pose was checked by :meth:`initial_state`."""

    def start(self) -> np.ndarray:
        """The sensor tip's start point on the surface [m]."""
        if self.start_point is not None:
            return np.array(self.start_point)
        return self.desired_point(0.0)[0]


def initial_tracing_state(exp: TracingExperiment, plant) -> np.ndarray:
    """:meth:`TracingExperiment.initial_state`, with the plant that records the penetration."""
    p0 = exp.start()
    n = exp.robot.n
    probe = np.concatenate([np.zeros(2 * n), p0, np.zeros(3)])
    gap = float(plant.outputs(probe[None, :])[0][plant.record["outputs"].index("penetration")])
    if not abs(gap) <= START_TOL:
        raise HybridError(f"start_point {np.round(p0, 4).tolist()} m is {abs(gap) * 1000:.3g} mm off the surface; "
                          f"give a point on it (within {START_TOL * 1000:g} mm)")
    normal = exp.surface.lift().normal_at(p0)
    s, r = exp.pressed_at(p0, normal)
    x_tool = np.cross(exp.reference, normal)
    if np.linalg.norm(x_tool) < 1e-6:
        raise HybridError("the reference direction is parallel to the surface normal at the start point: the task "
                          "frame is undefined there; choose another reference or start_point")
    x_tool /= np.linalg.norm(x_tool)
    rotation = np.column_stack([x_tool, np.cross(-normal, x_tool), -normal])
    try:
        q = exp.robot.inverse_kinematics(r, rotation)
    except HybridError as exc:
        raise HybridError(f"the start pose cannot be reached: {exc}") from None
    if plant.conditioning(q) < max(exp.singular_tol, 1e-3):
        raise HybridError(f"the start point {np.round(p0, 4).tolist()} m puts the arm at or near a singularity "
                          f"(q = {np.round(q, 3).tolist()} rad); move the surface or start_point")
    return np.concatenate([q, np.zeros(n), s, np.zeros(3)])


def tracing_experiment(**overrides) -> TracingExperiment:
    """The 3-D experiment of NOTES section 10, with any setting overridden by keyword.

    Takes the keywords of :func:`hybrid.paper_experiment` that mean the same here (``controller``,
    ``integral``, ``curvature``, ``model_error``, ``viscous_compensation``, ``contact``, ``sensor``,
    the gains one by one or ``gains``, ``F_d``, ``v_d``, ``duration``, ``step``, ``sample_time``, ...)
    plus ``robot`` and ``surface``.
    """
    return with_overrides(TracingExperiment, "tracing_experiment", overrides)
