"""One closed-loop run as data: robot, surface, path, scheme, loops, sensor, contact, timing, model error.

An :class:`Experiment` is every setting of a run, validated when it is made. It builds what the
run needs from its own settings: the plant (:meth:`Experiment.plant`), the controller
(:meth:`Experiment.build_controller`) and the start state (:meth:`Experiment.initial_state`).
What differs between robots is a property of the robot: the paper's planar arm (a
:class:`~hybrid.Robot` with a ``closed_form``) runs on the committed closed-form plant, with
the planar task axes and closed-form inverse kinematics; any other arm on its generated
rigid-body plant, on all six task axes (or those it can serve). :func:`hybrid.paper_experiment`,
:func:`hybrid.tracing_experiment` and :func:`hybrid.panda_experiment` are factories of it.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, field, fields, replace
from functools import lru_cache

import numpy as np

from hybrid.control.controller import Controller, Posture, check_posture
from hybrid.control.loops import Gains
from hybrid.control.references import Step
from hybrid.control.schemes import SCHEMES, scheme_of
from hybrid.control.wrench_sensor import Tool, WrenchSensor
from hybrid.errors import HybridError
from hybrid.experiments.settings import (
    START_TOL,
    TOUCH_THRESHOLD,
    RunSettings,
    check_common_types,
    check_sensing,
    check_timing,
    free,
    pressed,
)
from hybrid.geometry.paths import CirclePath, LinePath, Path
from hybrid.geometry.surfaces import SURFACE_KINDS, Circle, Plane, Surface
from hybrid.geometry.task_axes import check_axes, reference_direction
from hybrid.models.planar_arm import Arm
from hybrid.models.robot import Robot, as_robot
from hybrid.models.urdf import JointLimits, LinkInertia
from hybrid.native.standalone import generate_experiment
from hybrid.plants.contact import Contact, Sensor
from hybrid.plants.planar import PlanarPlant
from hybrid.plants.rigid_body import RigidBodyPlant
from hybrid.spec.chain import Chain, Joint
from hybrid.validate import SINGULAR_TOL, _point

#: the committed units that can run the closed-form plant and law (the same equations, two printers)
BACKENDS = ("sympy", "casadi")

#: an experiment's physics: the controller's model error, the plant's sensor and contact. Of the
#: experiment's checks only ``check_common_types``, ``check_sensing`` and ``check_timing`` read them
#: (:meth:`Experiment.with_physics` runs those alone)
PHYSICS = frozenset({"model_error", "viscous_compensation", "sensor", "contact"})


@dataclass(frozen=True, kw_only=True)
class Experiment(RunSettings):
    """One closed-loop run: the true robot and surface, the controller's settings, the references,
    the sensor and contact, the integration and sampling.

    Parameters
    ----------
    robot : Robot
        The true arm. The controller's model is ``robot.with_model_error(model_error,
        viscous_compensation)``.
    surface : Surface
        What the sensor tip touches (2-D for the planar arm, 3-D otherwise).
    controller_surface : Surface, optional
        The surface the controller is told: the true ``surface`` (the default), a wrong one (a sphere of
        another radius, a plane for a curved part), or a :class:`~hybrid.EstimatedSurface` it estimates
        online. The plant always has the true one.
    path : CirclePath or LinePath, optional
        Where the desired point runs (for ``frame="desired"`` and the workspace check); default the
        surface's own path (:meth:`Surface.path`), when it has one.
    start_point : the sensor tip's start on the surface [m] (projected onto it when within
        1 mm); default the path's start.
    elbow : +1 (``q2 > 0``) or -1: the planar arm's start configuration.
    reference : the task frame's reference direction ``e`` (base axes).
    axes : the controller's task axes (see :func:`hybrid.decoupling_law`); default the robot's.
    posture : a :class:`~hybrid.Posture` task in the null space of a redundant arm's task (its rest
        posture is also where the start's inverse kinematics begins); off by default.
    controller : a scheme's name (``"task"``, ``"khatib"``, ``"raibert_craig"``, ``"fisher_mujtaba"``).
    sensor : the plant's elastic sensor and its signal (noise, bias, lag, delay: :class:`~hybrid.Sensor`).
    wrench_sensor : the true force/torque sensor and tool (a :class:`~hybrid.WrenchSensor`): the
        controller is then given its raw reading (sensor axes) for the plant's force, at the true
        arm's tip pose (conventions §14), and turns it back with ``controller_wrench_sensor``. None (the
        default): the controller is given the wrench on the robot itself.
    controller_wrench_sensor : the sensor and tool as the controller believes them (its mount, sign,
        tool, bias and its filter's ``cutoff``); default ``wrench_sensor`` itself. Needs ``wrench_sensor``.
    start_gap : [m] the run starts with the sensor tip this far from the surface along its normal at
        the start point, at rest and out of contact (conventions §4); 0 (the default): on the surface,
        pressing with ``F_d(0)``. Needs ``approach_speed``.
    approach_speed : [m/s] with it the controller has a :class:`~hybrid.ContactLoss` rule: a force axis
        whose measured force is below ``touch_threshold`` approaches the surface at this speed (before
        the first touch, and after a loss of contact); 0 (the default): no such rule.
    touch_threshold : [N] the force below which the force axis counts as out of contact (0.5 N).
    frame : ``"actual"`` (the loops in ``R(r)``) or ``"desired"`` (in ``R(r_d)``).
    backend : which committed unit runs the closed-form plant (``"sympy"`` or ``"casadi"``).
    singular_tol : the run stops when the Jacobian's conditioning at a sample falls below it.
    """

    robot: Robot | None = None
    surface: Surface | None = None
    controller_surface: Surface | None = None
    path: Path | None = None
    start_point: tuple[float, ...] | None = None
    elbow: int = 1
    reference: tuple[float, float, float] = (0.0, 0.0, 1.0)
    axes: str | tuple[int, ...] | None = None
    posture: Posture | None = None
    controller: str = "task"
    integral: bool = True
    curvature: bool = False
    frame: str = "actual"
    model_error: float = 0.1
    viscous_compensation: float = 0.5
    sensor: Sensor = field(default_factory=Sensor)
    contact: Contact = field(default_factory=Contact)
    wrench_sensor: WrenchSensor | None = None
    controller_wrench_sensor: WrenchSensor | None = None
    start_gap: float = 0.0
    approach_speed: float = 0.0
    touch_threshold: float = TOUCH_THRESHOLD
    gains: Gains = field(default_factory=Gains)
    force_reference: Step = field(default_factory=lambda: Step(10.0, 20.0, 0.4))
    speed_reference: Step = field(default_factory=lambda: Step(0.3, 0.6, 1.0))
    duration: float = 2.0
    step: float = 1e-4
    sample_time: float = 1e-2
    backend: str = "sympy"
    singular_tol: float = SINGULAR_TOL

    def __post_init__(self):
        # the checks that read PHYSICS are check_common_types, check_sensing and check_timing: keep it so
        # (with_physics runs them alone)
        check_common_types(self)
        if self.controller not in SCHEMES:
            raise HybridError(f"unknown controller {self.controller!r}; choose one of {', '.join(SCHEMES)}")
        if self.robot is None or self.surface is None:
            raise HybridError("an Experiment needs a robot and a surface; give both, or start from a factory: "
                              "hybrid.paper_experiment(), hybrid.tracing_experiment(), hybrid.panda_experiment()")
        object.__setattr__(self, "robot", as_robot(self.robot))
        if not isinstance(self.surface, Surface):
            raise HybridError(f"unknown surface {self.surface!r:.60}; give a hybrid Circle, Plane, Sphere, Cylinder "
                              "or ImplicitSurface")
        if self.controller_surface is not None:
            if not isinstance(self.controller_surface, Surface):
                raise HybridError(f"controller_surface = {self.controller_surface!r:.60}; give a hybrid surface (a "
                                  "wrong one, or hybrid.EstimatedSurface()) or None (the true surface)")
            if self.controller_surface.spec().estimated and self.frame == "desired":
                raise HybridError("frame='desired' puts the loops on the desired point of a surface the controller "
                                  "knows; with an EstimatedSurface give frame='actual'")
        if self.robot.closed_form is not None and self.surface.cross_section() is None:
            raise HybridError(f"the planar arm needs a planar surface (a hybrid.Circle or a 2-D hybrid.Plane: a "
                              f"cylinder or a plane along base z), got {self.surface!r:.60}")
        if self.posture is not None and not isinstance(self.posture, Posture):
            raise HybridError(f"posture = {self.posture!r:.60}; give a hybrid.Posture(q_rest, stiffness, damping) "
                              "or None")
        if self.path is not None and not isinstance(self.path, Path):
            raise HybridError(f"path = {self.path!r:.60}; give a hybrid.CirclePath or hybrid.LinePath, or None")
        if not isinstance(self.backend, str) or self.backend not in BACKENDS:
            raise HybridError(f"unknown backend {self.backend!r:.40}; choose one of {BACKENDS} (the NumPy reference "
                              "runs as hybrid.reference.simulate(experiment))")
        if isinstance(self.elbow, bool) or not isinstance(self.elbow, (int, np.integer)) or self.elbow not in (1, -1):
            raise HybridError(f"elbow = {self.elbow!r}; give +1 (q2 > 0) or -1 (q2 < 0)")
        object.__setattr__(self, "reference", tuple(reference_direction(self.reference)))
        if self.robot.closed_form is not None and self.reference != (0.0, 0.0, 1.0):
            raise HybridError(f"reference = {self.reference}: the planar arm's task frame has e = z (its plant "
                              "records in it); leave reference out")
        if self.robot.closed_form is None:
            for name, value, default in (("elbow", self.elbow, 1), ("backend", self.backend, "sympy")):
                if value != default:
                    raise HybridError(f"{name} = {value!r} is a setting of the planar arm's closed form; leave it "
                                      f"out for the robot {self.robot.name!r}")
        # what the controller will refuse, refused now (building it compiles its step)
        check_posture(self.robot, check_axes(self.robot, self.axes), scheme_of(self.controller), self.posture)
        if self.start_point is not None:
            object.__setattr__(self, "start_point", _point("Experiment", "start_point", self.start_point,
                                                           (self._geometry().dim,)))
        elif self.followed_path() is None:
            raise HybridError(f"a {type(self.surface).__name__} has no path of its own: give start_point, a point "
                              "on the surface [m], or a path")
        check_sensing(self)
        if self.frame == "desired" and self.followed_path() is None:
            raise HybridError("frame='desired' follows the experiment's path: give a path (hybrid.CirclePath or "
                              "hybrid.LinePath), or use frame='actual'")
        check_timing(self)

    def with_physics(self, **changes) -> Experiment:
        """This experiment with other settings of :data:`PHYSICS`: what ``dataclasses.replace(self,
        **changes)`` makes, or the refusal it raises, by the checks that read them alone (the others
        passed for this experiment and read none of them; a sweep's runs that differ in their physics
        only are checked at a fraction of the cost)."""
        unknown = set(changes) - PHYSICS
        if unknown:
            raise ValueError(f"with_physics changes {', '.join(sorted(unknown))}, which are not PHYSICS")
        if not self.physics_alone():
            return replace(self, **changes)
        exp = object.__new__(type(self))
        exp.__dict__.update(self.__dict__)
        exp.__dict__.update(changes)
        check_common_types(exp)  # in __post_init__'s order: the first refusal is the one it would raise
        check_sensing(exp)
        check_timing(exp)
        return exp

    @classmethod
    def physics_alone(cls) -> bool:
        """Whether :meth:`with_physics` checks this class's physics alone: its checks are the
        experiment's (a subclass's own checks may read the physics too; it is then made whole)."""
        return cls.__post_init__ is Experiment.__post_init__

    # ------------------------------------------------------------------ derived

    @property
    def arm(self) -> Arm | None:
        """The planar arm's parameters (its closed form), or None for any other robot."""
        return self.robot.closed_form

    @property
    def plant_class(self) -> type:
        """The generated plant of these runs: the closed form of the planar arm, else the rigid-body one."""
        return PlanarPlant if self.robot.closed_form is not None else RigidBodyPlant

    def plant(self):
        """The generated plant of this run (the true arm, sensor, contact on the surface)."""
        return self.plant_class(self)

    def controller_robot(self) -> Robot:
        """The controller's (wrong) model of the arm."""
        return self.robot.with_model_error(self.model_error, self.viscous_compensation)

    def build_controller(self) -> Controller:
        """Exactly the controller this run uses: its model of the arm, loops, references, options."""
        surface = self.surface if self.controller_surface is None else self.controller_surface
        return Controller(self.controller_robot(), surface, self.controller, axes=self.axes,
                          reference=self.reference, posture=self.posture, **self.controller_settings())

    @property
    def section(self):
        """The surface's cross-section the planar arm runs on (:meth:`Surface.cross_section`), or None."""
        return None if self.robot.closed_form is None else self.surface.cross_section()

    def _geometry(self):
        """Where the start, the path and the normals are taken: the planar arm's cross-section, else the
        surface itself."""
        section = self.section
        return self.surface if section is None else section

    def followed_path(self) -> Path | None:
        """The path the desired point follows: the one given, else the surface's through the start point
        given, else the surface's own (None where there is none)."""
        if self.path is not None:
            return self.path
        geometry = self._geometry()
        if self.start_point is not None:
            projected = geometry.project(self.start_point)
            return geometry.path_through(self.start_point if projected is None else projected)
        try:
            return geometry.path()
        except HybridError:
            return None

    def start(self) -> np.ndarray:
        """The sensor tip's start point on the surface [m]: ``start_point`` (projected onto the surface),
        else the path's start."""
        if self.start_point is None:
            return self.followed_path().point_at(self.followed_path().start)
        projected = self._geometry().project(self.start_point)
        return np.array(self.start_point) if projected is None else projected

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``r_d(t)`` [m] on the path, reached from the start at the desired speed, and ``r_d'(t)`` [m/s]."""
        path = self.followed_path()
        s = path.arc_of(self.start()) + self.speed_reference.integral(t)
        return path.point_at(s), self.speed_reference(t) * path.tangent_at(s)

    def initial_state(self) -> np.ndarray:
        """The run's start state ``x0 = (q, q', s, s')``: at rest, the sensor tip pressing at the start
        point with ``F_d(0)`` (:func:`~hybrid.experiments.settings.pressed`), or with ``start_gap`` the
        sensor tip that far from it along the normal, out of contact, the sensor at rest
        (:func:`~hybrid.experiments.settings.free`); the tool's z axis along ``-n`` when the task has
        rotational axes, the joints from inverse kinematics of the true arm. What a foreign loop starts
        from."""
        return _initial_state(self).copy()

    def check_path(self) -> None:
        """Refuse a run whose desired path leaves the arm's workspace (where the reach is known)."""
        reach, path = self.robot.reach(), self.followed_path()
        if reach is not None and path is not None:
            _check_path(reach, path, path.arc_of(self.start()), self.speed_reference, self.n_samples,
                        self.sample_time, self.duration)

    def generate(self, out, name: str | None = None, force: bool = False) -> list:
        """Write this run's closed loop as standalone C99 into the folder ``out``: the controller
        (``<name>_controller.c``, ``.h``, ``.json``; the struct ``<name>_controller``, as
        :meth:`hybrid.Controller.generate` writes it) and the plant (``<name>_plant.c``, ``.h``, ``.json``).
        Returns the paths written.

        ``<name>_plant_init(&p)`` gives a struct with this run's plant parameters (the true arm, the
        sensor, the contact, the surface), its timing (``h``, ``steps_per_sample``, ``sample_time``,
        ``duration``) and its start state (:meth:`initial_state`); ``<name>_plant_wrench`` reads the
        sensor (what the controller's step takes), ``<name>_plant_advance(&p, tau, n)`` takes ``n`` RK4
        steps with the torque held, ``<name>_plant_signals`` gives what the metrics read. A loop of
        samples around the two is this run (``hybrid.simulate``'s) to rounding error. ``name``: ASCII
        letters, digits and ``_``, a letter first (default the robot's name). C99, no allocation, no
        globals, no I/O, reentrant; the same bytes for the same experiment. Files in ``out`` with other
        content are refused unless ``force``. References the controller takes from its caller (a desired
        frame) are the caller's to write into the controller's struct each sample."""
        return generate_experiment(self, out, name, force)

    # ------------------------------------------------------------------- files

    def to_dict(self) -> dict:
        """The settings as JSON-ready data, from which :meth:`from_dict` builds the experiment again."""
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        for name in ("sensor", "contact", "gains", "force_reference", "speed_reference"):
            d[name] = asdict(d[name])
        d["robot"] = robot_to_dict(self.robot)
        d["surface"] = surface_to_dict(self.surface)
        d["controller_surface"] = None if self.controller_surface is None else surface_to_dict(self.controller_surface)
        d["path"] = None if self.path is None else {"kind": type(self.path).__name__, **asdict(self.path)}
        d["start_point"] = None if self.start_point is None else list(self.start_point)
        d["reference"] = list(self.reference)
        d["axes"] = list(self.axes) if isinstance(self.axes, tuple) else self.axes
        d["posture"] = None if self.posture is None else asdict(self.posture)
        for name in ("wrench_sensor", "controller_wrench_sensor"):
            d[name] = None if d[name] is None else asdict(d[name])
        return {"kind": "experiment", **d}

    @classmethod
    def from_dict(cls, d: dict) -> Experiment:
        """The experiment :meth:`to_dict` wrote; anything else is a HybridError."""
        try:
            return cls._from_dict(d)
        except (KeyError, TypeError, AttributeError, ValueError, IndexError) as exc:
            if isinstance(exc, HybridError):
                raise
            raise HybridError(f"not an experiment's settings ({type(exc).__name__}: {exc})") from None

    @classmethod
    def _from_dict(cls, d: dict) -> Experiment:
        d = dict(d)
        kind = d.pop("kind", None)
        if kind is None and "arm" in d:  # a paper run saved before experiments were one type
            d = _from_paper_settings(d)
        elif kind == "tracing":
            raise ValueError("a 3-D run saved before experiments were one type names its robot only by name: "
                             "its arrays load with numpy.load")
        elif kind != "experiment":
            raise ValueError("no 'kind': 'experiment' entry")
        parts = {"sensor": Sensor, "contact": Contact, "gains": Gains, "force_reference": Step,
                 "speed_reference": Step}
        for k, typ in parts.items():
            d[k] = typ(**d[k])
        d["robot"], d["surface"] = robot_from_dict(d["robot"]), surface_from_dict(d["surface"])
        if d.get("controller_surface") is not None:
            d["controller_surface"] = surface_from_dict(d["controller_surface"])
        if d["path"] is not None:
            path = dict(d["path"])
            d["path"] = {"CirclePath": CirclePath, "LinePath": LinePath}[path.pop("kind")](**path)
        if d["posture"] is not None:
            d["posture"] = Posture(**d["posture"])
        for name in ("wrench_sensor", "controller_wrench_sensor"):
            if d.get(name) is not None:
                d[name] = WrenchSensor(**{**d[name], "tool": Tool(**d[name]["tool"])})
        if isinstance(d["axes"], list):
            d["axes"] = tuple(d["axes"])
        return cls(**d)


def _initial_state(exp: Experiment) -> np.ndarray:
    geometry = exp._geometry()
    path = exp.followed_path() if exp.start_point is None else None
    given = np.asarray(exp.start_point) if path is None else path.point_at(path.start)  # a path's start too
    nearest = geometry.project(given)
    p0 = nearest if nearest is not None and path is None else given  # as exp.start() gives it
    if nearest is not None:
        gap = float(np.linalg.norm(given - nearest))
    else:  # without a closed-form projection the plant's own record says how far the point is
        plant = exp.plant()
        gap = abs(float(plant.outputs(_probe(exp, p0))[0][plant.record["outputs"].index("penetration")]))
    if not gap <= START_TOL:
        what = "start_point" if exp.start_point is not None else "the path's start"
        hint = f", e.g. {np.round(nearest, 4).tolist()}" if nearest is not None else ""
        raise HybridError(f"{what} {np.round(given, 4).tolist()} m is {gap * 1000:.1f} mm off the surface; give a "
                          f"point on it (within {START_TOL * 1000:g} mm){hint}")
    q0 = None if exp.posture is None else exp.posture.q_rest
    p0 = tuple(np.asarray(p0).tolist())
    if exp.start_gap > 0:
        # the sensor tip's weight hangs on its spring where the plant gives it gravity (the 3-D plant's)
        weight = np.zeros(3) if exp.robot.closed_form is not None else exp.sensor.mass * np.array(exp.robot.gravity)
        return _free_start(exp.robot, geometry, p0, exp.elbow, q0, exp.reference, exp.singular_tol, exp.start_gap,
                           tuple((weight[:len(p0)] / exp.sensor.stiffness).tolist()))
    return _pressed_start(exp.robot, geometry, p0, exp.elbow, q0, exp.reference,
                          exp.singular_tol, exp.force_reference(0.0), exp.contact.stiffness, exp.sensor.stiffness)


def _probe(exp: Experiment, p: np.ndarray) -> np.ndarray:
    """A plant state at rest with the sensor tip at ``p`` (one row)."""
    return np.concatenate([np.zeros(2 * exp.robot.n), p, np.zeros(len(p))])[None, :]


# the runs of a sweep mostly start alike: what they share is worked out once (from the values it reads)
@lru_cache(maxsize=1024)
def _pressed_start(robot, surface, p0, elbow, q0, reference, singular_tol, F0, k_e, K_s) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = pressed(p0, normal, F0, k_e, K_s)
    return _at_rest(robot, normal, p0, s, r, elbow, q0, reference, singular_tol)


@lru_cache(maxsize=1024)
def _free_start(robot, surface, p0, elbow, q0, reference, singular_tol, gap, sag) -> np.ndarray:
    normal = surface.normal_at(p0)
    s, r = free(p0, normal, gap, np.array(sag))
    return _at_rest(robot, normal, p0, s, r, elbow, q0, reference, singular_tol, gap)


def _at_rest(robot, normal, p0, s, r, elbow, q0, reference, singular_tol, gap: float = 0.0) -> np.ndarray:
    """The state at rest with the sensor tip at ``s`` and the arm tip at ``r`` (the start point ``p0`` on
    the surface, its ``normal``), the joints from the true arm's inverse kinematics."""
    # the tool's orientation is set where the task controls it (the planar arm's follows from r)
    rotation = None if robot.closed_form is not None else _tool_rotation(np.asarray(reference), normal)
    where = (f"start_gap = {gap:g} m puts the arm tip at {np.round(r, 4).tolist()} m" if gap > 0 else
             f"the start point {np.round(p0, 4).tolist()} m")
    fix = ("give a smaller start_gap, or move the surface or start_point" if gap > 0 else
           "move the surface or start_point")
    try:
        q = robot.inverse_kinematics(np.append(r, 0.0) if len(r) == 2 else r, rotation, q0=q0, elbow=elbow)
    except HybridError as exc:
        if gap > 0:
            first, _, rest = str(exc).partition("\n")
            raise HybridError(f"{where}, which the arm cannot reach; {fix}\n  {first}"
                              + (f"\n{rest}" if rest else "")) from None
        raise HybridError(f"the start pose cannot be reached: {exc}") from None
    cond = float(robot.conditioning(q))
    if cond < max(singular_tol, 1e-3):
        raise HybridError(f"{where} puts the arm at or near a singularity (q = {np.round(q, 4).tolist()} rad, "
                          f"{robot.conditioning_name} = {cond:.2e}); {fix}")
    return np.concatenate([q, np.zeros(robot.n), s, np.zeros(len(s))])


def _tool_rotation(e: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """The tool's start orientation: its z axis along ``-n``, its x axis along ``t1 = e x n``."""
    x_tool = np.cross(e, normal)
    if np.linalg.norm(x_tool) < 1e-6:
        raise HybridError("the reference direction is parallel to the surface normal at the start point: the task "
                          "frame is undefined there; choose another reference or start_point")
    x_tool /= np.linalg.norm(x_tool)
    return np.column_stack([x_tool, np.cross(-normal, x_tool), -normal])


@lru_cache(maxsize=1024)
def _check_path(reach, path, s0, speed_reference, n_samples, sample_time, duration) -> None:
    lo, hi = reach
    t = np.minimum(np.arange(n_samples + 1) * sample_time, duration)
    points = path.points_at(s0 + speed_reference.integral(t))
    d = np.hypot(points[:, 0], points[:, 1])
    outside = np.flatnonzero(~((lo + 1e-3 < d) & (d < hi - 1e-3)))
    if len(outside):
        i = outside[0]
        raise HybridError(f"the desired path leaves the arm's workspace at t = {t[i]:.3f} s "
                          f"(point {np.round(points[i], 4).tolist()} m, {d[i]:.3f} m from the base, reach "
                          f"{lo:.3f}-{hi:.3f} m); shorten duration, lower the speed or move the surface")


def _from_paper_settings(d: dict) -> dict:
    """The settings of a paper run in the form saved before experiments were one type: the planar arm's
    parameters as ``arm``, the surface as a 2-D circle or line."""
    surface = dict(d.pop("surface"))
    kind = surface.pop("kind")
    lifted = Circle(**surface) if kind == "circle" else Plane(**surface)
    d["robot"], d["surface"] = {"closed_form": d.pop("arm")}, surface_to_dict(lifted)
    d["backend"] = "sympy" if d.get("backend") == "numpy" else d.get("backend", "sympy")
    d.update(path=None, reference=[0.0, 0.0, 1.0], axes=None, posture=None)
    return d


# ------------------------------------------------------------- robots and surfaces as data


def robot_to_dict(robot: Robot) -> dict:
    """Everything that defines ``robot`` as JSON-ready data (and a digest of it, for sweeps' resume)."""
    if robot.closed_form is not None:
        d = {"closed_form": asdict(robot.closed_form)}
    else:
        limits = None if robot.limits is None else {k: np.asarray(v).tolist() for k, v in vars(robot.limits).items()}
        d = {"name": robot.name, "chain": asdict(robot.chain), "links": [asdict(lk) for lk in robot.links],
             "damping": list(robot.damping), "gravity": list(robot.gravity), "limits": limits}
    d["digest"] = hashlib.sha256(json.dumps(d, sort_keys=True).encode()).hexdigest()[:16]
    return d


def robot_from_dict(d: dict) -> Robot:
    if "closed_form" in d:
        return Robot.planar(Arm(**d["closed_form"]))
    c = d["chain"]

    def rows(m):
        return tuple(tuple(float(v) for v in row) for row in m)

    joints = tuple(Joint(j["name"], j["kind"], rows(j["rotation"]), tuple(j["translation"]), tuple(j["axis"]))
                   for j in c["joints"])
    chain = Chain(joints, rows(c["tip_rotation"]), tuple(c["tip_translation"]))
    links = tuple(LinkInertia(lk["mass"], tuple(lk["com"]), rows(lk["inertia"])) for lk in d["links"])
    limits = None if d["limits"] is None else JointLimits(**{k: np.array(v, float) for k, v in d["limits"].items()})
    return Robot(d["name"], chain, links, tuple(d["damping"]), tuple(d["gravity"]), limits)


def surface_to_dict(surface: Surface) -> dict:
    if surface.kind.startswith("implicit"):
        return {"kind": "implicit", "phi": str(surface.phi), "parameters": dict(surface.parameters)}
    return {"kind": surface.kind, **{k: list(v) if isinstance(v, tuple) else v for k, v in asdict(surface).items()}}


def surface_from_dict(d: dict) -> Surface:
    d = dict(d)
    kind = d.pop("kind")
    if kind == "implicit":
        from hybrid.geometry.implicit import ImplicitSurface  # SymPy: loaded only for a user's surface

        return ImplicitSurface(d["phi"], d["parameters"])
    return SURFACE_KINDS[kind](**d)
