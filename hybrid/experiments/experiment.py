"""One closed-loop run as data: robot, surface, path, scheme, loops, sensor, contact, timing, model error.

An :class:`Experiment` is every setting of a run, validated when it is made. It builds what the
run needs from its own settings: the plant (:meth:`Experiment.plant`), the controller
(:meth:`Experiment.build_controller`) and the start state (:meth:`Experiment.initial_state`).
What differs between robots is a property of the robot: the paper's planar arm (a
:class:`~hybrid.Robot` with a ``closed_form``) runs on the committed closed-form plant, with
the planar task axes and closed-form inverse kinematics; any other arm on its generated
rigid-body plant, on all six task axes (or those it can serve). :func:`hybrid.paper_experiment`,
:func:`hybrid.tracing_experiment` and :func:`hybrid.panda_experiment` are factories of it. Where
its run starts and where its desired point goes are worked out in
:mod:`hybrid.experiments.path_and_start` (the start state in :mod:`hybrid.experiments.start`),
its settings as data in :mod:`hybrid.experiments.serialisation`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from hybrid.control.controller import Controller
from hybrid.control.fault import FaultReaction
from hybrid.control.loops import Gains
from hybrid.control.options import Posture, check_posture
from hybrid.control.path_task import PathTask
from hybrid.control.references import Step
from hybrid.control.schemes import SCHEMES, scheme_of
from hybrid.control.wrench_sensor import WrenchSensor
from hybrid.deprecation import RENAMED, RenamedKeywords, renamed_attribute
from hybrid.errors import HybridError
from hybrid.experiments.followed import TaskDirection, check_followed, task_references, told_surface
from hybrid.experiments.path_and_start import PathAndStart
from hybrid.experiments.serialisation import experiment_from_dict, experiment_to_dict
from hybrid.experiments.settings import (
    TOUCH_THRESHOLD,
    RunSettings,
    check_common_types,
    check_sensing,
    check_timing,
    warn_redundancy,
)
from hybrid.experiments.start import check_seed
from hybrid.experiments.walls import check_walls
from hybrid.geometry.paths import Path
from hybrid.geometry.surfaces import Surface
from hybrid.geometry.task_axes import check_axes, frame_direction_of
from hybrid.models.planar_arm import Arm
from hybrid.models.robot import Robot, as_robot, structure_difference
from hybrid.native.standalone import generate_experiment
from hybrid.plants.contact import Contact, Sensor
from hybrid.plants.registry import generated_plant_class
from hybrid.spec.interfaces import PRINTERS
from hybrid.stability.analysis import check_stable
from hybrid.validate import SINGULAR_TOL, _point, checked_keywords, shown

#: the committed units that can run the closed-form plant and law (the same equations, two printers)
BACKENDS = PRINTERS  # the closed form's units the plant and the law may take

#: an experiment's physics: the controller's model error, the plant's sensor and contact. Of the experiment's
#: checks only ``check_common_types``, ``check_sensing``, ``check_timing``, ``check_walls`` and ``check_stable``
#: read them
#: (:meth:`Experiment.with_physics` runs those alone)
PHYSICS = frozenset({"model_error", "viscous_compensation", "sensor", "contact"})


@checked_keywords
@dataclass(frozen=True, kw_only=True)
class Experiment(RunSettings, PathAndStart, metaclass=RenamedKeywords):
    """One closed-loop run: the true robot and surface, the controller's settings, the references,
    the sensor and contact, the integration and sampling.

    Every setting is checked when the experiment is made, and it is immutable: change one with
    ``dataclasses.replace``, which checks the copy. Only ``robot`` and ``surface`` are needed (and
    ``start_point`` or ``path`` on a surface without a path of its own); :func:`~hybrid.paper_experiment`,
    :func:`~hybrid.tracing_experiment` and :func:`~hybrid.panda_experiment` give whole ones. Below, the
    settings in groups: the arm and the controller's model of it; the surface, the path and the start;
    the controller; the references; the sensing, the contact and the approach from free space; the
    timing; the run's guards. Points and directions are in base axes.

    Parameters
    ----------
    robot : Robot
        The true arm (the plant's).
    controller_robot : Robot, optional
        The robot the controller is told, as it is (e.g. one identified from the arm's data): of the
        kinematic structure of ``robot`` (the same joints, origins, axes and tip frame; refused
        otherwise), its inertial parameters, joint friction and gravity its own. With it ``model_error``
        and ``viscous_compensation`` do not apply: a value other than their defaults is refused.
    model_error : float
        Without ``controller_robot``, the controller's model is the true robot with its masses and
        inertias ``1 + model_error`` times the true ones (default 0.1: 10 % heavy;
        :meth:`controller_model`).
    viscous_compensation : float
        The share of the joints' friction (viscosities, Coulomb frictions, offsets) the controller's
        model knows (default 0.5: half).
    surface : Surface
        What the sensor tip touches (2-D for the planar arm, 3-D otherwise): the plant's, always the
        true one.
    controller_surface : Surface, optional
        The surface the controller is told: the true ``surface`` (the default), a wrong one (a sphere of
        another radius, a plane for a curved part), or a :class:`~hybrid.EstimatedSurface` it estimates
        online.
    path : Path, optional
        Where the desired point ``r_d(t)`` runs (for ``frame="desired"`` and the workspace check); default
        the surface's own path (:meth:`Surface.path`), when it has one. The tip moves along the task axis
        ``t1``, in the plane through the start normal to ``frame_direction``: a path out of that plane, or
        against ``t1``, is not followed and refused (:func:`~hybrid.experiments.followed.check_followed`).
    path_task : PathTask, optional
        The tip follows this :class:`~hybrid.PathTask`'s path on the surface from its start, at its speed and
        force along the path (:mod:`hybrid.control.path_task`); ``force_reference`` is then its force at the
        start (the start presses with it) and ``speed_reference`` 0, set here: give neither. A 3-D arm with
        the task axes ``t1, t2, n``; the run's metrics add the path's (``path_error_rms_m``, ...).
    start_point : sequence of float, optional
        The sensor tip's start on the surface [m] (projected onto it when within 1 mm); default the
        path's start.
    elbow : int
        The planar arm's start configuration: +1 (``q2 > 0``, the default) or -1.
    q0 : sequence of float, optional
        Joint positions [rad or m], one per joint, where the start's inverse kinematics begins (default:
        the posture's rest, else the middle of the joint ranges): a seed near the start wanted picks its
        solution branch. A start outside the joint position limits is refused
        (:mod:`hybrid.experiments.start`). The planar arm's start is in closed form: ``elbow`` picks it.
    controller : str
        The scheme: ``"task"`` (the paper's task-space decoupling, the default), ``"khatib"``,
        ``"raibert_craig"`` or ``"fisher_mujtaba"``.
    axes : str or tuple of int, optional
        The controller's task axes (see :func:`hybrid.decoupling_law`); default the robot's.
    frame_direction : sequence of float, optional
        The task frame's direction ``e``: ``t1 = e x n / |e x n|``; default base z, with a path task the
        path's at its start (``n x t``), set here.
    frame : str
        Where the loops' task frame is taken: ``"actual"`` (the default: ``R(r)`` at the arm tip) or
        ``"desired"`` (``R(r_d)`` at the desired point on the path).
    posture : Posture, optional
        A :class:`~hybrid.Posture` task in the null space of a redundant arm's task (its rest posture is
        also where the start's inverse kinematics begins); off by default.
    integral : bool
        Whether the loops have integral action (default True); without it ``K_I2v = K_If = 0``
        (:meth:`effective_gains`).
    curvature : bool
        Whether the controller is given the task frame's rate ``R'(r, r')`` (the surface's curvature) in
        ``F*``; default False, as in the paper (``R' = 0``).
    gains : Gains
        The loops' gains ``K_Pv, K_Iv, K_I2v, K_Pf, K_Df, K_If`` (:class:`~hybrid.Gains`; default the
        paper's, conventions §4).
    force_reference : Step or float, optional
        The normal force ``F_d(t)`` [N] (positive: pressing): a :class:`~hybrid.Step` or a number (a
        constant); default 10 N, 20 N from 0.4 s.
    speed_reference : Step or float, optional
        The speed ``v_d(t)`` along ``t1`` [m/s]: a :class:`~hybrid.Step` or a number (a constant);
        default 0.3 m/s, 0.6 m/s from 1 s.
    sensor : Sensor
        The plant's elastic sensor and its signal (noise, bias, lag, delay: :class:`~hybrid.Sensor`;
        default the paper's, 1000 N/m, ideal).
    contact : Contact
        The surface's penalty contact and friction on the sensor tip (:class:`~hybrid.Contact`; default
        ``k_e`` = 1e5 N/m, ``d_e`` = 50 N s/m, ``gamma`` = 0.2).
    wrench_sensor : WrenchSensor, optional
        The true force/torque sensor and tool (a :class:`~hybrid.WrenchSensor`): the controller is then
        given its raw reading (sensor axes) for the plant's force, at the true arm's tip pose
        (conventions §14), and turns it back with ``controller_wrench_sensor``. None (the default): the
        controller is given the wrench on the robot itself.
    controller_wrench_sensor : WrenchSensor, optional
        The sensor and tool as the controller believes them (its mount, sign, tool, bias and its filter's
        ``cutoff``); default ``wrench_sensor`` itself. Needs ``wrench_sensor``.
    start_gap : float
        [m] the run starts with the sensor tip this far from the surface along its normal at the start
        point, at rest and out of contact (conventions §4); 0 (the default): on the surface, pressing
        with ``F_d(0)``. Needs ``approach_speed``.
    approach_speed : float
        [m/s] with it the controller has a :class:`~hybrid.ContactLoss` rule: a force axis whose measured
        force is below ``touch_threshold`` approaches the surface at this speed (before the first touch,
        and after a loss of contact); 0 (the default): no such rule.
    touch_threshold : float
        [N] the measured normal force below which the force axis counts as out of contact (default
        0.5 N).
    duration : float
        [s] the run's length (default 2 s), a whole number of samples (:attr:`n_samples`).
    integration_step : float
        [s] the plant's fixed RK4 step (default 0.1 ms); ``sample_time`` is a whole multiple of it
        (:attr:`steps_per_sample` integration steps a control sample).
    sample_time : float
        [s] the control sample period ``T`` (default 10 ms), the torque held over it.
    backend : str
        Which committed unit runs the closed-form plant: ``"sympy"`` (the default) or ``"casadi"``.
    singular_tol : float
        The run stops when the Jacobian's conditioning at a sample falls below it (default 1e-3).
    fault_reaction : FaultReaction
        The controller's :class:`~hybrid.FaultReaction` (its defaults): what a run with a sensor's
        dropout (``Sensor.dropout_duration``) measures; a sweep varies its numbers by name
        (``fault_reaction.stop_time``).
    allow_unstable : bool
        An experiment whose sampled loops are predicted unstable (:func:`hybrid.stability`) is refused,
        saying which loop and why (the default, False); True runs it anyway (a study that tests the
        prediction), and its result says it was predicted so (:attr:`~hybrid.SimulationResult.predicted_stable`).

    Raises
    ------
    HybridError
        A setting of the wrong kind or out of its range, or settings the run cannot meet together (a start
        off the surface or out of reach, a path the tip does not follow, loops predicted unstable, ...).

    Examples
    --------
    The UR5 on a sphere, 50 ms of the sphere's own path (its latitude circle 60 degrees from the top):

    >>> import hybrid
    >>> sphere = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> experiment = hybrid.Experiment(
    ...     robot=hybrid.ur5(), surface=sphere, force_reference=15.0,
    ...     speed_reference=0.1, duration=0.05)
    >>> # 10 ms samples of 100 RK4 steps
    >>> experiment.n_samples, experiment.steps_per_sample
    (5, 100)
    >>> # (q, q', s, s') of 6 joints and the sensor tip
    >>> experiment.initial_state().shape
    (18,)
    >>> result = hybrid.simulate(experiment)
    >>> round(float(result.force_normal[-1]))  # [N]
    15
    >>> import dataclasses
    >>> # a copy, checked again
    >>> faster = dataclasses.replace(experiment, sample_time=0.005)
    >>> faster.n_samples, faster.steps_per_sample
    (10, 50)
    """

    robot: Robot | None = None
    surface: Surface | None = None
    controller_surface: Surface | None = None
    controller_robot: Robot | None = None
    path: Path | None = None
    path_task: PathTask | None = None
    start_point: tuple[float, ...] | None = None
    elbow: int = 1
    frame_direction: tuple[float, float, float] | None = None
    axes: str | tuple[int, ...] | None = None
    posture: Posture | None = None
    q0: tuple[float, ...] | None = None
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
    force_reference: Step | None = None
    speed_reference: Step | None = None
    duration: float = 2.0
    integration_step: float = 1e-4
    sample_time: float = 1e-2
    backend: str = "sympy"
    singular_tol: float = SINGULAR_TOL
    fault_reaction: FaultReaction = field(default_factory=FaultReaction)
    allow_unstable: bool = False

    #: the old names of renamed settings (:mod:`hybrid.deprecation`): given, they warn and set the new ones
    _renamed = RENAMED
    #: deprecated: :attr:`frame_direction`
    reference = renamed_attribute("reference", "frame_direction")
    #: deprecated: :attr:`integration_step`
    step = renamed_attribute("step", "integration_step")

    def __post_init__(self):
        # the checks that read PHYSICS are check_common_types, check_sensing, check_timing, check_walls and
        # check_stable: keep it so (with_physics runs them alone). check_stable, which judges the whole, comes last
        task_references(self)
        check_common_types(self)
        if self.controller not in SCHEMES:
            raise HybridError(f"unknown controller {shown(self.controller)}; choose one of {', '.join(SCHEMES)}")
        if self.robot is None or self.surface is None:
            raise HybridError("an Experiment needs a robot and a surface; give both, or start from a factory: "
                              "hybrid.paper_experiment(), hybrid.tracing_experiment(), hybrid.panda_experiment()")
        object.__setattr__(self, "robot", as_robot(self.robot))
        if not isinstance(self.surface, Surface):
            raise HybridError(f"unknown surface {shown(self.surface, 60)}; give a hybrid Circle, Plane, Sphere, "
                              "Cylinder or ImplicitSurface")
        if self.surface.spec().estimated:
            raise HybridError("surface = EstimatedSurface(...): the plant needs the true surface; give it as surface "
                              "and the EstimatedSurface as controller_surface (the controller estimates the normal)")
        if self.controller_surface is not None:
            if not isinstance(self.controller_surface, Surface):
                raise HybridError(f"controller_surface = {shown(self.controller_surface, 60)}; give a hybrid surface "
                                  "(a wrong one, or hybrid.EstimatedSurface()) or None (the true surface)")
            if self.controller_surface.spec().estimated and self.frame == "desired":
                raise HybridError("frame='desired' puts the loops on the desired point of a surface the controller "
                                  "knows; with an EstimatedSurface give frame='actual'")
        if self.controller_robot is not None:
            object.__setattr__(self, "controller_robot", as_robot(self.controller_robot))
            difference = structure_difference(self.robot, self.controller_robot)
            if difference is not None:
                raise HybridError(f"controller_robot has another kinematic structure than robot ({difference}); "
                                  "give a model of the same arm (e.g. robot.with_link(...)), its parameters its own")
        self.robot.kind.check_surface(self.surface)
        if self.posture is not None and not isinstance(self.posture, Posture):
            raise HybridError(f"posture = {shown(self.posture, 60)}; give a hybrid.Posture(q_rest, stiffness, damping) "
                              "or None")
        if self.path is not None and not isinstance(self.path, Path):
            raise HybridError(f"path = {shown(self.path, 60)}; give a hybrid path (CirclePath, LinePath, or a "
                              "subclass of hybrid.geometry.paths.Path), or None")
        if not isinstance(self.backend, str) or self.backend not in BACKENDS:
            raise HybridError(f"unknown backend {shown(self.backend, 40)}; choose one of {BACKENDS} (the NumPy oracle "
                              "runs as hybrid.oracle.simulate(experiment))")
        if isinstance(self.elbow, bool) or not isinstance(self.elbow, (int, np.integer)) or self.elbow not in (1, -1):
            raise HybridError(f"elbow = {shown(self.elbow)}; give +1 (q2 > 0) or -1 (q2 < 0)")
        # (a direction worked out from the path task stays marked so: a copy with another task works it out again)
        kind = TaskDirection if isinstance(self.frame_direction, TaskDirection) else tuple
        object.__setattr__(self, "frame_direction", kind(frame_direction_of(self.frame_direction)))
        self.robot.kind.check_settings(self.robot, self.frame_direction, {"elbow": self.elbow, "backend": self.backend})
        # what the controller will refuse, refused now (building it compiles its step)
        axes = check_axes(self.robot, self.axes)
        check_posture(self.robot, axes, scheme_of(self.controller), self.posture)
        object.__setattr__(self, "q0", check_seed(self.robot, self.q0))
        warn_redundancy(self.robot, axes, self.posture)
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
        check_followed(self)
        if not isinstance(self.fault_reaction, FaultReaction):
            raise HybridError(f"fault_reaction = {shown(self.fault_reaction, 60)}; give a hybrid.FaultReaction(...)")
        self.fault_reaction.check_sampling(self.sample_time)
        if self.path_task is not None:
            self.path_task.check_sampling(self.sample_time)
        check_walls(self)
        check_stable(self)

    def with_physics(self, **changes) -> Experiment:
        """This experiment with other settings of :data:`PHYSICS`: what ``dataclasses.replace(self,
        **changes)`` makes, or the refusal it raises, by the checks that read them alone (the others
        passed for this experiment and read none of them; a sweep's runs that differ in their physics
        only are checked at a fraction of the cost).

        Parameters
        ----------
        **changes
            New values of ``model_error``, ``viscous_compensation``, ``sensor`` or ``contact``.

        Returns
        -------
        Experiment
            The changed copy.

        Raises
        ------
        ValueError
            A setting other than those; a refused value is a HybridError, as ``replace`` raises it.
        """
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
        check_walls(exp)
        check_stable(exp)
        return exp

    @classmethod
    def physics_alone(cls) -> bool:
        """Whether :meth:`with_physics` checks this class's physics alone: its checks are the
        experiment's (a subclass's own checks may read the physics too; it is then made whole).

        Returns
        -------
        bool
            True for :class:`Experiment`, False for a subclass with a ``__post_init__`` of its own.
        """
        return cls.__post_init__ is Experiment.__post_init__

    # ------------------------------------------------------------------ derived

    # what the robot's kind makes of the experiment, worked out once: an experiment is immutable, and the
    # settings with_physics changes (PHYSICS) reach none of these
    @cached_property
    def arm(self) -> Arm | None:
        """The planar arm's parameters (its closed form), or None for any other robot."""
        return self.robot.kind.arm

    @cached_property
    def plant_class(self) -> type:
        """The generated plant of these runs, the robot's kind's (the closed form of the planar arm, else the
        rigid-body one; :data:`hybrid.plants.registry.GENERATED_PLANTS`)."""
        return generated_plant_class(self.robot.kind.plant)

    def plant(self):
        """The generated plant of this run.

        Returns
        -------
        GeneratedPlant
            A :attr:`plant_class` with the true arm, the sensor and the contact on the true surface.
        """
        return self.plant_class(self)

    def controller_model(self) -> Robot:
        """The controller's model of the arm.

        Returns
        -------
        Robot
            ``controller_robot`` when given, else ``robot.with_model_error(model_error,
            viscous_compensation)``.
        """
        if self.controller_robot is not None:
            return self.controller_robot
        return self.robot.with_model_error(self.model_error, self.viscous_compensation)

    def told_surface(self) -> Surface:
        """The surface the controller is told.

        Returns
        -------
        Surface
            ``controller_surface`` when given, else the true ``surface``.
        """
        return told_surface(self)

    def build_controller(self) -> Controller:
        """Exactly the controller this run uses.

        Returns
        -------
        Controller
            A new :class:`~hybrid.Controller` of :meth:`controller_model` on :meth:`told_surface`, with the
            experiment's scheme, axes, loops, references and options, before its first sample.
        """
        return Controller(self.controller_model(), self.told_surface(), self.controller, axes=self.axes,
                          frame_direction=self.frame_direction, posture=self.posture, **self.controller_settings())

    def generate(self, out, name: str | None = None, force: bool = False) -> list:
        """Write this run's closed loop as standalone C99 into the folder ``out``: the controller
        (``<name>_controller.c``, ``.h``, ``.json``; the struct ``<name>_controller``, as
        :meth:`hybrid.Controller.generate` writes it) and the plant (``<name>_plant.c``, ``.h``, ``.json``).

        ``<name>_plant_init(&p)`` gives a struct with this run's plant parameters (the true arm, the
        sensor, the contact, the surface), its timing (``h``, the integration step; ``steps_per_sample``,
        ``sample_time``, ``duration``) and its start state (:meth:`initial_state`); ``<name>_plant_wrench`` reads the
        sensor (what the controller's step takes), ``<name>_plant_advance(&p, tau, n)`` takes ``n`` RK4
        steps with the torque held, ``<name>_plant_signals`` gives what the metrics read. A loop of
        samples around the two is this run (``hybrid.simulate``'s) to rounding error. C99, no allocation,
        no globals, no I/O, reentrant; the same bytes for the same experiment. References the controller
        takes from its caller (a desired frame) are the caller's to write into the controller's struct
        each sample. On a part, ``hybrid_part.h`` and the part's data file ``<name>_part.bin`` too: its
        numbers are run-time data (one build serves every part), which the caller reads and gives to
        ``<name>_controller_set_part`` and ``<name>_plant_set_part`` (a damaged file is refused); the plant
        expands the part about the sensor tip at each RK4 step, as the Python plant does.

        Parameters
        ----------
        out : str or pathlib.Path
            The folder written into (made when missing).
        name : str, optional
            The prefix of the files and C names: ASCII letters, digits and ``_``, a letter first
            (default the robot's name).
        force : bool
            Whether files in ``out`` with other content are replaced (default False: refused).

        Returns
        -------
        list of pathlib.Path
            The paths written.
        """
        return generate_experiment(self, out, name, force)

    # ------------------------------------------------------------------- files

    def to_dict(self) -> dict:
        """The settings as data.

        Returns
        -------
        dict
            JSON-ready data, from which :meth:`from_dict` builds the experiment again.
        """
        return experiment_to_dict(self)

    @classmethod
    def from_dict(cls, d: dict) -> Experiment:
        """The experiment :meth:`to_dict` wrote.

        Parameters
        ----------
        d : dict
            The data, as :meth:`to_dict` wrote it (read back from JSON, say).

        Returns
        -------
        Experiment
            The experiment, equal to the one written.

        Raises
        ------
        HybridError
            Data :meth:`to_dict` did not write.
        """
        return experiment_from_dict(cls, d)
