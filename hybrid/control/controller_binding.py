"""A :class:`~hybrid.Controller`'s compiled step: its numbers, its per-sample buffers, its build and binding.

The controller gives the step (:data:`hybrid.spec.controller_step.CONTROLLER_STEP`) two kinds of input. Its
numbers (gains, references' steps, model, surface, options, posture, limits, sensor, fault reaction) are fixed
between samples: made here from the controller's settings, checked (:mod:`hybrid.control.step_checks`) and bound
to the compiled call once it is built. Its per-sample inputs (the joint state and wrench a call gives, the states
the step keeps, the sample time, the references computed in Python) live in buffers made here once, which the
call reads and writes in place. The compiled unit is built at the first sample (a run of the compiled closed loop
never needs it); an input the fast call refuses is run again on the general path (:meth:`StepBinding._checked`),
which names the cause.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.measurement import wrench_of
from hybrid.control.options import ContactLoss
from hybrid.control.task_settings import gain_array
from hybrid.errors import HybridError
from hybrid.native import units
from hybrid.spec.controller_step import CONTROLLER_STEP, NO_LIMIT, OPTIONS, SENSOR, STATE_NEXT
from hybrid.spec.interfaces import REFERENCE, Dims

#: "no limit" for the options that are off (the generated step takes finite numbers only)
OFF = 1e300
#: the step's per-sample inputs a call gives (its q, qdot and Fc); the others the controller holds
_CALLED = ("q", "qd", "Fc")
#: the states a sample the law served advances whether or not it was on time (the integrals only on time;
#: the last torque is the torque written), and the outputs they advance to
ADVANCED = {k: v for k, v in STATE_NEXT.items() if k not in ("integrals", "last_torque")}


class StepBinding:
    """The compiled step a controller holds (module docstring): it reads the controller's settings (``robot``,
    ``scheme``, ``axes``, ``gains``, ``selection``, the limits and options, ``_references``, ``_spatial``), and its
    step's checks (``_checked_parameters``, ``_check_joint_state``)."""

    #: the step's per-sample inputs computed here when references are given as code (else bound to zeros)
    _reference_inputs = CONTROLLER_STEP.named(REFERENCE)

    def _hold_step(self) -> None:
        """The step's numbers, checked, and its per-sample buffers, from the settings just set."""
        robot = self.robot
        loss = self.contact_loss or ContactLoss(-OFF, 0.0)
        option = {"curvature": float(self.curvature), "sample_time": self.sample_time,
                  "khatib": float(self.scheme.feeds_desired_force),
                  "integral_limit": OFF if self.integral_limit is None else float(self.integral_limit),
                  "loss_threshold": loss.threshold, "approach_speed": loss.approach_speed,
                  "pseudoinverse": float(self.scheme.pseudoinverse)}
        options = np.array([option[name] for name in OPTIONS])
        steps = np.array([ref.step or (0.0, 0.0, 0.0) for ref in self._references], float).ravel()
        # every step takes the posture's numbers (zeros when off: the step without a posture ignores them)
        posture_array = np.zeros(3 * robot.n) if self.posture is None else self.posture.as_array()
        # no limit is the largest double: bounding a finite torque by it changes nothing, bit for bit
        limits = np.minimum(np.concatenate([self.torque_limit, self.torque_step_limit]), NO_LIMIT)
        sensor = (np.zeros(len(SENSOR)) if self.wrench_sensor is None
                  else self.wrench_sensor.as_array(robot, self.sample_time))
        robot_array, surface_array = robot.as_array(), self._spatial.as_array()
        self._dims = Dims.sized(robot.joint_names, self.axis_names, len(robot_array), len(surface_array))
        self._params = self._checked_parameters({
            "steps": steps, "gains": gain_array(self.gains, self.selection), "selection": self.selection,
            "robot": robot_array, "surface": surface_array, "e": self.frame_direction, "options": options,
            "posture": posture_array, "limits": limits, "sensor": sensor, "fault": self._fault_reaction.as_array()})
        self._start_params = self._params  # what a path task changes as it runs is restored from these at a reset
        # the step's other per-sample inputs, in its order: the states it keeps (the loops' integrals, the torque
        # last given to the arm and 1 once there is one, the sensor filter's, an estimated surface's), the sample
        # time, the references computed here; the integrals, filter and estimate trade buffers with the outputs
        sizes = CONTROLLER_STEP.sizes(self._dims)
        per_sample = CONTROLLER_STEP.per_sample
        if per_sample[:len(_CALLED)] != _CALLED or per_sample[-len(self._reference_inputs):] != \
                self._reference_inputs:
            raise RuntimeError(f"the step's per-sample inputs {per_sample} do not start {_CALLED} and end with the "
                               "references: hybrid/spec/controller_step.py and the Controller disagree")
        held = per_sample[len(_CALLED):]
        self._held = [np.zeros(sizes[n]) for n in held]
        self._at = {n: i for i, n in enumerate(held)}
        self._t, self._last = self._held[self._at["t"]], self._held[self._at["last_torque"]]
        self._z, self._estimate = self._held[self._at["integrals"]], self._held[self._at["estimate"]]
        self._extra, self._rate, self._target = (self._held[self._at[n]] for n in ("yd_extra", "yd_rate", "target"))
        self._fc = np.zeros(sizes["Fc"])
        # a force without moments: the planar arm's in its plane (2), any other arm's in space (3); a sensor's
        # reading is always six numbers
        self._force_size = 6 if self.wrench_sensor else robot.kind.force_size
        self._fc_head = self._fc[:self._force_size]
        self._varying = [(i, ref.value) for i, ref in enumerate(self._references) if ref.value is not None]
        self._rates = [(i, ref.rate) for i, ref in enumerate(self._references) if ref.rate is not None]
        # with references all steps and no path, the per-sample inputs end at t: the rest is bound
        self._short = not (self._varying or self._rates or self.path or self._path_task)
        # what a call passes after q, qdot, Fc: the references are bound instead where they stay zero
        refs = len(self._reference_inputs) if self._short else 0
        self._bound_refs = self._held[len(self._held) - refs:]
        del self._held[len(self._held) - refs:]
        # the compiled step is built at the first sample (a run of the compiled closed loop never needs it)
        self._binding = None

    def _native(self) -> None:
        """The compiled step and measurement, bound to this controller's numbers (built once, cached)."""
        unit = units.controller_unit(self.robot.chain, self.robot.name, self._spatial.spec(), self.axes,
                                     self.frame == "desired", self.position_error, self.wrench_sensor is not None)
        self._step, self._measure = unit.function(self._step_name), unit.function("task_measurement")
        self._stop = unit.function("safe_stop")
        CONTROLLER_STEP.check_manifest(self._step.entry, self._dims)
        self._into = self._step.unit.fast().call_into
        # outputs written in place, in the declaration's order; a state's next value is written into the state
        # itself (the call reads every input before it writes an output), the integrals' only on a sample on
        # time (else into a scratch array: they stay as they were)
        into = {STATE_NEXT[s]: self._held[self._at[s]] for s in ADVANCED}
        self._out_off_time = [into.get(name) if name in into else np.empty(size)
                              for name, size, _ in self._step.outputs]
        self._out_held = [np.empty(size) for _, size, _ in self._step.outputs]
        integrals = STATE_NEXT["integrals"]
        self._out = [self._held[self._at["integrals"]] if name == integrals else o
                     for (name, _, _), o in zip(self._step.outputs, self._out_off_time)]
        self._bind()

    def _bind(self) -> None:
        """Bind the step's fixed inputs (all but the per-sample ones) to this controller's numbers (once the
        step is built)."""
        if not hasattr(self, "_step"):
            return
        n_state = len(CONTROLLER_STEP.per_sample) - len(self._bound_refs)
        _, self._binding = self._step.fast_bind(n_state, *self._bound_refs, *self._params,
                                                singular_tol=self.singular_tol)

    def _padded(self, Fc) -> np.ndarray:
        """``Fc`` as the step's 6-vector (into a buffer for a force without moments)."""
        if type(Fc) is np.ndarray and Fc.dtype == np.float64 and Fc.shape == (self._force_size,):
            self._fc_head[...] = Fc  # the other entries stay 0
            return self._fc
        return wrench_of(Fc, self._force_size)

    def _checked(self, q, qdot, Fc, out: list) -> None:
        """The general path: any array-like input, and the error that names the cause. A sample refused
        here changes nothing (the outputs are written only when the step succeeds), the clock neither,
        as in the generated C."""
        t = self._t[0]
        self._check_joint_state(q, qdot)
        if np.isfinite(Fc).all() and not all(np.isfinite(v).all() for v in (self._extra, self._rate, self._target)):
            raise HybridError(f"the references at t = {t} s are not finite; give references that return finite "
                              f"numbers\n  values {self._extra}, rates {self._rate}, desired point {self._target}")
        got = self._step(q, qdot, Fc, *self._held, *self._bound_refs, *self._params, singular_tol=self.singular_tol)
        for (name, _, _), o in zip(self._step.outputs, out):
            o[:] = got[name].ravel()

