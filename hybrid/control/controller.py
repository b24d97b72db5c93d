"""The hybrid controller as a component: ``tau = ctrl(t, q, qdot, Fc)`` in any loop.

One control sample is one native call (see :mod:`codegen.controller_step`): the task-frame
measurement, the loops of conventions §4 on every task axis, and the decoupling law. The
controller keeps the loops' integrals between calls. References that are numbers or steps
are evaluated in the compiled step at the sample time ``t``; others, given as code, in Python.
The step's numbers and buffers are held as :mod:`hybrid.control.controller_binding` makes them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from math import isfinite as _isfinite

import numpy as np

from hybrid.control.controller_binding import ADVANCED, StepBinding
from hybrid.control.controller_copies import CopiedRun
from hybrid.control.controller_settings import SETTINGS, GroupedSettings, check_settings, grouped
from hybrid.control.fault import FaultMonitor, FaultReaction, finite_time, sample_periods, time_passed, timing_status
from hybrid.control.loops import Gains
from hybrid.control.measurement import Measurement, wrench_of
from hybrid.control.options import ContactLoss, Posture, check_posture
from hybrid.control.path_task import PATH_CHANGES, PathReferences, PathTask
from hybrid.control.sample_references import SampleReferences
from hybrid.control.schemes import Scheme, scheme_of
from hybrid.control.step_checks import CheckedParameters
from hybrid.control.task_settings import axis_references, gains_of, joint_limit, selection_of
from hybrid.control.wrench_sensor import WrenchSensor
from hybrid.deprecation import renamed_attribute, renamed_keywords
from hybrid.errors import HybridError, ParameterError, SampleTimingError
from hybrid.geometry.task_axes import check_axes, frame_direction_of, spatial_surface
from hybrid.models.planar_arm import Arm
from hybrid.models.robot import Robot, as_robot
from hybrid.native.standalone import generate_controller
from hybrid.spec.axes import AXIS_NAMES
from hybrid.spec.controller_step import CONTROLLER_STEP, ESTIMATE
from hybrid.spec.interfaces import HELD_STATUSES
from hybrid.validate import shown

#: the compiled step's inputs a controller fixes, in the step's order (after the per-sample ones)
PARAMETERS = CONTROLLER_STEP.parameters


class Controller(SampleReferences, StepBinding, GroupedSettings, CheckedParameters, CopiedRun):
    r"""A sampled hybrid force/velocity controller of ``robot`` in contact with ``surface``.

    ``tau = ctrl(t, q, qdot, Fc)`` is one control sample: the task-frame measurement, the loops on every
    task axis and the decoupling law
    :math:`F^* = \bar B_o R^T \left[a - (\dot R T + R \dot T)\, \dot r\right] + T^{-T} n_o - F_c`
    (conventions §3-§4), in one compiled call. The settings come in three groups, each a record or its
    fields as flat keywords of the same names: :class:`~hybrid.Tracking` (gains and references),
    :class:`~hybrid.Limits` (timing and limits), :class:`~hybrid.Sensing` (sensor and estimate).

    Parameters
    ----------
    robot : Robot or Arm
        The controller's own model (possibly wrong). A planar :class:`~hybrid.Arm` is the chain of
        :meth:`Robot.planar` with the planar task axes ``(t1, n)``.
    surface : Plane, Circle, Sphere, Cylinder, ImplicitSurface, MeshSurface, PointCloudSurface or EstimatedSurface
        The surface the tip is in contact with, in base axes [m].
    scheme : str or Scheme
        ``"task"`` (De Luca & Manes, the default), ``"khatib"``, ``"raibert_craig"``,
        ``"fisher_mujtaba"`` or a :class:`~hybrid.Scheme`.
    axes : str or sequence of str, optional
        The task axes (see :func:`hybrid.decoupling_law`); default all six, ``"planar"`` for an Arm.
    selection : str or sequence, optional
        The force-controlled axes, by name (``"n"``) or index; default the normal ``n``.
    tracking : Tracking, optional
        The gains and references, as one record (or give its fields flat, below).
    limits : Limits, optional
        The timing and limits, as one record (or flat).
    sensing : Sensing, optional
        The sensor and the contact-loss rule, as one record (or flat).
    gains, force_reference, velocity_reference, posture, path_task
        What the loops track: the :class:`~hybrid.Tracking` fields of these names.
    integral, curvature, frame, path, frame_direction, position_error
        How they track it: the :class:`~hybrid.Tracking` fields of these names.
    sample_time, timing_tolerance, fault_reaction
        The sample clock and what faults lead to: the :class:`~hybrid.Limits` fields of these names.
    torque_limit, torque_step_limit, integral_limit, singular_tol
        The bounds: the :class:`~hybrid.Limits` fields of these names.
    wrench_sensor, contact_loss
        The :class:`~hybrid.Sensing` fields of these names.

    Raises
    ------
    HybridError
        A setting refused (naming it and what to give), or one given both flat and in its group.

    Notes
    -----
    Every number the compiled step reads is checked against its declaration, as the standalone C checks
    it (:mod:`hybrid.control.step_checks`); the arrays the step reads are then read-only. The settings a
    sample reads in Python (``sample_time``, ``timing_tolerance``, ``singular_tol``) may change between
    samples: a new ``sample_time`` is the period of everything from the next sample on (the timing check,
    the integrals, the filter, the estimate, a path task's progress), as for a controller built with it;
    one changed to an invalid value refuses the sample with a :class:`~hybrid.ParameterError`
    (``status`` ``PARAMETER_INVALID``, ``torque`` the torque last written), nothing changed. The
    bounds ``torque_limit``, ``torque_step_limit`` and ``integral_limit`` are fixed when it is built:
    assigning one is refused (build another controller).

    A controller copies (``copy.copy``, ``copy.deepcopy``) and pickles: the copy is built anew from the same
    arguments and takes over the run (the integrals, the last torque, the filter, the estimate, the sample
    clock, the fault reaction's and a path task's state, the settings as they are now), so on the same
    samples it gives the same torques, bit for bit, and each runs on alone (:meth:`reset` starts either
    afresh). ``copy.copy`` shares the robot, the surface and references given as code; a pickle needs
    them to pickle (functions defined at a module's top level, not lambdas).

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> ur5 = hybrid.ur5()
    >>> sphere = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> limits = hybrid.Limits(sample_time=0.002,
    ...                        torque_step_limit=2.0)
    >>> ctrl = hybrid.Controller(ur5, sphere, "task",
    ...                          force_reference=15.0,
    ...                          velocity_reference=0.1,
    ...                          limits=limits)
    >>> ctrl.axis_names
    ('t1', 't2', 'n', 'rot_t1', 'rot_t2', 'rot_n')
    >>> q = np.array([0.0, -1.2, 1.5, -1.9, -1.57, 0.0])
    >>> tau = ctrl(0.0, q, np.zeros(6), np.array([0.0, 0.0, -15.0]))
    >>> tau.shape, ctrl.last["saturated"]
    ((6,), False)
    """

    #: deprecated: :attr:`frame_direction`
    reference = renamed_attribute("reference", "frame_direction")

    @renamed_keywords(reference="frame_direction")
    @grouped
    def __init__(self, robot: Robot | Arm, surface, scheme: str | Scheme = "task", *, axes=None, selection=None,
                 gains: Gains | Mapping | None = None, force_reference=None, velocity_reference=None,
                 sample_time: float = 0.01, integral: bool = True, curvature: bool = False,
                 frame: str = "actual", path: Callable | None = None, frame_direction=None,
                 position_error: bool = False, integral_limit: float | None = None,
                 contact_loss: ContactLoss | None = None, singular_tol: float = 1e-3,
                 posture: Posture | None = None, torque_limit="urdf", torque_step_limit=None,
                 timing_tolerance: float | None = 0.25, wrench_sensor: WrenchSensor | None = None,
                 fault_reaction: FaultReaction | None = None, path_task: PathTask | None = None):
        robot = as_robot(robot)
        self._settings = {name: value for name, value in locals().items() if name in SETTINGS}
        check_settings(self._settings)
        if (frame == "desired" or position_error) and not callable(path):
            raise HybridError(f"{'position_error' if position_error else 'frame=desired'} needs path=f(t) returning "
                              "the desired point and its velocity (p_d [m], p_d' [m/s])")
        self.robot, self.scheme = robot, scheme_of(scheme)
        self.axes = check_axes(robot, axes)
        self.surface, self._spatial = surface, spatial_surface(surface)
        self._estimated = self._spatial.spec().estimated
        if self._estimated:
            if frame == "desired" or position_error:
                raise HybridError("an EstimatedSurface has no desired point to put a frame on: the controller does "
                                  "not know the surface; use frame='actual' and position_error=False with it")
            self._spatial.check_sampling(sample_time)
        if self._spatial.local and (frame == "desired" or position_error):
            raise HybridError("a part is expanded about the tip at each sample, not about a desired point: use "
                              "frame='actual' and position_error=False with it")
        # the sample time is also one of the step's numbers: set later, it is written there (step_checks)
        self._sample_time, self.integral, self.curvature, self.frame = float(sample_time), integral, curvature, frame
        self.frame_direction = tuple(frame_direction_of((0.0, 0.0, 1.0) if frame_direction is None
                                                        else frame_direction))
        self.singular_tol, self.path = float(singular_tol), path
        self.selection = selection_of(self.axes, selection)
        self.gains = gains_of(self.axes, gains, integral)
        if self.scheme.needs_force_gain and any(s and g.KPf <= 0 for g, s in zip(self.gains, self.selection)):
            raise HybridError(f"the {self.scheme.name} scheme commands m_d a = a / KPf on force axes: give KPf > 0")
        self.position_error, self.integral_limit, self.contact_loss = position_error, integral_limit, contact_loss
        self.posture = check_posture(self.robot, self.axes, self.scheme, posture)
        self.torque_limit = joint_limit(robot, "torque_limit", torque_limit)
        self.torque_step_limit = joint_limit(robot, "torque_step_limit", torque_step_limit)
        self.timing_tolerance = None if timing_tolerance is None else float(timing_tolerance)
        self.wrench_sensor = wrench_sensor
        self._fault_reaction = fault_reaction or FaultReaction()
        self._fault_reaction.check_sampling(self.sample_time)
        self._path_task = None if path_task is None else PathReferences(
            path_task, self._spatial, robot, self.axes, self.selection, self.gains, self.sample_time,
            None if contact_loss is None else contact_loss.threshold,
            force_reference is not None or velocity_reference is not None,
            frame != "actual" or position_error or path is not None)
        if path_task is not None:  # its references are the follower's, added to these; its direction the path's
            force_reference = {"n": 0.0}
            self.frame_direction = path_task.frame_direction(self._spatial, frame_direction)
        self._references = axis_references(self.axes, self.selection, force_reference, velocity_reference)
        # a posture has its own generated step (the law plus tau0), so the law without one stays the very code
        # it was, bit for bit; both are in the same unit, and the posture's numbers are run-time inputs of both
        self._step_name = self.scheme.step if self.posture is None else "controller_posture_step"
        self._hold_step()  # the compiled step's numbers, checked, and its per-sample buffers
        self._fault = FaultMonitor(self._dims)
        self._clock = None  # the last sample's time
        self._checked_settings = None  # the settings a sample reads, as last found valid
        self._sampled = False

    # ----------------------------------------------------------------- settings

    @classmethod
    def from_experiment(cls, exp) -> Controller:
        """Exactly the controller an experiment runs.

        Parameters
        ----------
        exp : Experiment
            The paper's experiment or a 3-D one (:func:`hybrid.tracing_experiment`).

        Returns
        -------
        Controller
            Its model of the arm, loops, references and options: the experiment builds it.
        """
        return exp.build_controller()

    def set_wrench_sensor(self, sensor: WrenchSensor) -> None:
        """Change the sensor's numbers between samples (a new tool, a new bias: :func:`hybrid.tare`).

        Parameters
        ----------
        sensor : WrenchSensor
            The new numbers. The controller must have been built with a sensor (its step reads a raw
            reading); its numbers are checked as at construction.
        """
        if self.wrench_sensor is None:
            raise HybridError("this controller takes the contact wrench itself, not a sensor's reading: build it "
                              "with wrench_sensor=hybrid.WrenchSensor(...) to give it one")
        if not isinstance(sensor, WrenchSensor):
            raise HybridError(f"sensor = {shown(sensor, 60)}; give a hybrid.WrenchSensor(...)")
        self._params = self._checked_parameters({**self.step_inputs(),
                                                 "sensor": sensor.as_array(self.robot, self._period)})
        self.wrench_sensor = sensor
        self._bind()

    @property
    def runs_in_c(self) -> bool:
        """True when every reference is a number, a :class:`Step` or a path task's, no desired path is given and
        the wrench is given as such (no sensor reading): then a whole run can be compiled C
        (:mod:`hybrid.simulation.closed_loop`)."""
        given_as_code = self._varying or self._rates or self.path is not None
        return not given_as_code and self.wrench_sensor is None and not self._estimated

    def step_inputs(self, at_start: bool = False) -> dict[str, np.ndarray]:
        """The compiled step's inputs this controller fixes.

        Parameters
        ----------
        at_start : bool
            As at the start of a run (before a path task turned ``e`` or retreated), not as now.

        Returns
        -------
        dict of str to ndarray
            The gains, the references' steps, the model, the surface, the options, by the manifest's names
            (read-only arrays).
        """
        return dict(zip(PARAMETERS, self._start_params if at_start else self._params))

    def step_variant(self) -> dict:
        """What the compiled step is made of (what selects its compiled unit).

        Returns
        -------
        dict
            The model's ``chain`` and ``name``, the surface's ``spec``, the task ``axes``, the compiled-in
            options and the ``step`` function (the scheme's, or the posture task's).
        """
        return {"chain": self.robot.chain, "name": self.robot.name, "spec": self._spatial.spec(), "axes": self.axes,
                "desired_frame": self.frame == "desired", "position_error": self.position_error,
                "wrench_sensor": self.wrench_sensor is not None, "step": self._step_name}

    def generate(self, out, name: str | None = None, force: bool = False) -> list:
        """Write this controller as standalone C99.

        Parameters
        ----------
        out : str or Path
            The folder: ``<name>.c``, ``<name>.h`` and the manifest ``<name>.json`` are written there.
        name : str, optional
            ASCII letters, digits and ``_``, a letter first; default ``<robot>_controller``.
        force : bool
            Overwrite files in ``out`` with other content (refused otherwise).

        Returns
        -------
        list of Path
            The paths written.

        Notes
        -----
        The C is this controller, sample for sample: ``<name>_controller_init(&c)`` gives a struct with
        this configuration (gains, references, model, surface, limits, options: fields that may change
        between samples), and ``<name>_controller_step(&c, t, q, qd, wrench, tau)`` runs one sample
        (``wrench``: six numbers, force and moment on the robot at the tip in base axes) and returns a
        status, where this class raises (see ``timing_tolerance``). References given as code are the
        caller's: it writes them into ``c.yd_extra``, ``c.yd_rate`` and ``c.target`` each sample; a path
        task's follower writes them itself (``hybrid_path.h``, written beside). On a part, the evaluator's
        header ``hybrid_part.h`` and the part's data file ``<name>_part.bin`` are written beside: the
        caller gives the file's numbers to ``<name>_controller_set_part`` before the first sample. C99,
        no allocation, no globals, no I/O, reentrant; the same bytes for the same controller.
        """
        return generate_controller(self, out, name, force)

    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(AXIS_NAMES[i] for i in self.axes)

    # ------------------------------------------------------------------ running

    def reset(self, torque=None) -> None:
        """A new run: the loops' integrals zero, no last sample (the next one is on time whenever it
        comes), the fault reaction's state cleared (it ends the safe state; no joint positions known yet).

        Parameters
        ----------
        torque : array_like, optional
            The torque the arm has now [N m or N, one per joint]: the first sample's torque is then
            rate-limited from it (``torque_step_limit``).
        """
        for name in ("integrals", "last_torque", *ADVANCED):
            self._held[self._at[name]][:] = 0.0
        self._fault.reset()
        if self._path_task is not None:  # the path's start, and the normal axis force-controlled again
            self._path_task.follower.reset()
            self._params = tuple(start if name in PATH_CHANGES else now
                                 for name, start, now in zip(PARAMETERS, self._start_params, self._params))
            self._bind()
        self._sampled = False
        self._clock = None
        if torque is not None:
            try:
                tau = np.asarray(torque, dtype=float)
            except (TypeError, ValueError, OverflowError):
                tau = np.full(1, np.nan)
            if tau.shape != (self.robot.n,) or not np.isfinite(tau).all():
                raise HybridError(f"reset(torque={shown(torque, 60)}); give the arm's present torque, {self.robot.n} "
                                  "finite numbers [N m or N], or None")
            self._last[:-1], self._last[-1] = tau, 1.0

    @property
    def state(self) -> np.ndarray:
        """The loops' integrals, one row per task axis: ``(int e, int int e)`` (a copy)."""
        return self._z.reshape(-1, 2).copy()

    @state.setter
    def state(self, value) -> None:
        try:
            arr = np.asarray(value, dtype=float)
        except (TypeError, ValueError, OverflowError):
            arr = np.full(1, np.nan)
        if arr.shape != (len(self.axes), 2) or not np.isfinite(arr).all():
            raise HybridError(f"state must be {len(self.axes)} x 2 finite numbers (int e, int int e per axis "
                              f"{', '.join(self.axis_names)}), got shape {arr.shape}")
        self._z[:] = arr.ravel()

    def __call__(self, t: float, q, qdot, Fc) -> np.ndarray:
        """One control sample: the torque for the sample at time ``t``; it advances the integrals.

        Parameters
        ----------
        t : float
            The sample's time [s].
        q, qdot : array_like
            The joint positions [rad or m] and velocities [rad/s or m/s].
        Fc : array_like
            The measured wrench on the robot: base axes, a force [N] of 2 or 3 entries, or force and
            moment [N, N m], 6; with a ``wrench_sensor``, its raw reading (six numbers, sensor axes).

        Returns
        -------
        ndarray
            ``tau`` [N m or N], one per joint.

        Raises
        ------
        HybridError
            A sample the law cannot serve raises and changes nothing but the fault reaction's count (the
            integrals, the last torque, the filter, the estimate, the sample clock stay): :class:`HybridError`
            for a bad input, :class:`SingularConfigurationError` or :class:`TaskFrameError` where the law
            fails; :class:`SampleTimingError` off the sample clock (see ``timing_tolerance``). Every error a
            sample raises carries ``torque``, what to apply. After the ``fault_reaction``'s
            ``fault_samples`` consecutive faulted samples (refused, late or early; one after a gap counts the
            sample periods the gap spans) every sample raises
            :class:`SafeStopError` until :meth:`reset`, its torque the safe state's
            (:mod:`hybrid.control.fault`).
        """
        # with the timing check off the law serves every sample as one sample period, whatever its time
        checked, clock = self.timing_tolerance is not None, self._clock  # (the clock before a late sample moves it)
        passed = not checked or time_passed(t, clock)
        if self._fault.stopped:
            raise self._safe_sample(t, q, qdot, passed, "the safe state holds until reset()")
        try:
            tau = self._serve(t, q, qdot, Fc)
        except HybridError as exc:
            timing = getattr(exc, "status", None)
            if timing in HELD_STATUSES:  # no time passed: no fault of its own
                raise
            if isinstance(exc, SampleTimingError):  # served, off time
                self._fault.served(q, on_time=False)
            if not hasattr(exc, "torque"):
                exc.torque = self._last[:-1] * self._last[-1]
            # a gap counts its periods where the timing is checked and the sample time trusted (no setting refused)
            trusted = checked and not isinstance(exc, ParameterError)
            periods = sample_periods(t, clock, self.sample_time) if trusted else 0.0
            if self._fault.faulted(passed, self.fault_reaction, self._last[:-1] * self._last[-1], q, periods):
                raise self._safe_sample(t, q, qdot, passed, str(exc).partition("\n")[0]) from exc
            raise
        self._fault.served(q, on_time=True)
        return tau

    @property
    def fault_reaction(self) -> FaultReaction:
        """The fault reaction's numbers (fixed: the step reads them)."""
        return self._fault_reaction

    @property
    def stopped(self) -> bool:
        """Whether the step is in its safe state (after the ``fault_reaction``'s consecutive faulted samples;
        until :meth:`reset`)."""
        return self._fault.stopped

    @property
    def fault_state(self) -> np.ndarray:
        """The fault reaction's state (:data:`hybrid.spec.controller_step.FAULT_STATE`, as the standalone
        C's ``fault_state``; a copy)."""
        return self._fault.state.copy()

    def _safe_sample(self, t, q, qdot, passed: bool, cause: str):
        """One sample of the safe state: the :class:`SafeStopError` carrying its torque."""
        if self._binding is None:
            self._native()
        error = self._fault.safe_sample(self._stop, q, qdot, self._last, dict(zip(PARAMETERS, self._params)),
                                        passed, cause)
        value = finite_time(t)
        if value is not None:  # the clock follows a forward t (_tick) that is a finite number
            self._tick(value)
        return error

    def _serve(self, t, q, qdot, Fc) -> np.ndarray:
        """One sample served by the law, or refused (:meth:`__call__`)."""
        if type(Fc) is not np.ndarray or Fc.shape != (6,):
            Fc = self._padded(Fc)
        if type(t) is not float and (isinstance(t, (str, bytes, bool, np.bool_))
                                     or not isinstance(t, (int, np.integer, np.floating))):
            raise HybridError(f"t = {shown(t, 40)}; give the sample time in seconds (a number)")
        try:
            self._t[0] = t
        except OverflowError:  # an integer beyond any double
            self._t[0] = np.inf
        if not _isfinite(self._t[0]):
            raise HybridError(f"t = {shown(t, 40)}; give a finite sample time")
        t = self._t[0]
        settings = (self.sample_time, self.timing_tolerance, self.singular_tol)
        if settings != self._checked_settings:  # checked again whenever one changed (a NaN never equals)
            refused = self._refused_setting()
            if refused is not None:  # nothing changes; the torque last written is the safe one
                raise ParameterError(*refused, self._last[:-1] * self._last[-1])
            self._checked_settings = settings
            self._bind()  # the step's binding holds singular_tol: bound again to the one now set
        clock, timing = self._clock, timing_status(t, self._clock, self.sample_time, self.timing_tolerance)
        if self._binding is None:
            self._native()
        # late or early: the law's torque, the integrals as they were (the filter and the estimate advance);
        # repeated or backwards: no time passed, so nothing advances (every output into scratch arrays)
        held = timing in HELD_STATUSES
        out = self._out if timing is None else self._out_held if held else self._out_off_time
        # what a part's surface and a path task change for this sample, undone unless it is served as time passes
        kept = (self._params, self._z.copy()) if self._spatial.local or self._path_task is not None else None
        try:
            # the tip, measured once for both (its position, rotation and wrench depend on neither's parameters)
            tip = self._measured(q, qdot, Fc) if kept is not None else None
            if self._spatial.local:
                self._localize(tip)
            if not self._short:
                self._python_references(t)
                if self.path is not None:
                    self._target[:] = self._desired(t)
                if self._path_task is not None:
                    self._follow(tip)
            done = self._into(self._binding, out, q, qdot, Fc, *self._held)
            if done is None:
                self._checked(q, qdot, Fc, out)
        except HybridError:
            self._restore(kept)
            raise
        if held:
            self._restore(kept)
        if not held:
            if self._path_task is not None:
                self._path_task.follower.advance()
            self._tick(t)
            self._last[:-1], self._last[-1] = out[0], 1.0
            self._sampled = True
        if timing is not None:
            raise SampleTimingError(timing, t, clock, self.sample_time, out[0].copy())
        return out[0].copy()

    def _tick(self, t: float) -> None:
        """The sample clock after a sample at ``t``: it follows every sample that moves forward."""
        if self._clock is None or t > self._clock:
            self._clock = t

    @property
    def last(self) -> dict[str, np.ndarray] | None:
        """The latest sample's ``tau`` (in the safe state, the safe state's), integrals after it, loop
        accelerations ``a``, task velocity ``y`` and task wrench ``f`` (loop frame), by name; None before the
        first sample."""
        if not self._sampled:
            return None
        out = {name: o for (name, _, _), o in zip(self._step.outputs, self._out)}
        # in the safe state the torque applied is the safe state's (as the standalone C's struct keeps it)
        tau = self._last[:-1] * self._last[-1] if self._fault.stopped else out["tau"]
        return {"tau": tau.copy(), "integrals": self._z.copy(), "a": out["a"].copy(), "y": out["y"].copy(),
                "f": out["f"].copy(), "saturated": bool(out["saturated"][0]),
                "contact_wrench": out["contact_wrench"].copy(), "normal": self.normal}

    @property
    def normal(self) -> np.ndarray | None:
        """An estimated surface's normal estimate now (base axes; its start before the first sample);
        None for a surface the controller is told."""
        if not self._estimated:
            return None
        started, n = ESTIMATE.index("started"), [ESTIMATE.index(k) for k in ("n_x", "n_y", "n_z")]
        return self._estimate[n].copy() if self._estimate[started] else np.array(self._spatial.start_normal)

    def measure(self, q, qdot, Fc) -> Measurement:
        """What the controller measures, without a sample.

        Parameters
        ----------
        q, qdot, Fc : array_like
            As for a sample (:meth:`__call__`).

        Returns
        -------
        Measurement
            The tip's position and velocity, the task velocity and wrench, the reading and what the
            controller makes of it (see :class:`Measurement`).
        """
        if self._binding is None:
            self._native()
        reading = wrench_of(Fc, self._force_size)
        p = self.step_inputs()
        out = self._measure(q, qdot, reading, p["surface"], p["e"], p["robot"], p["sensor"], self._estimate)
        return Measurement(out["p"], out["v"], out["task_velocity"], out["task_wrench"], reading, out["compensated"],
                           out["contact_wrench"])
