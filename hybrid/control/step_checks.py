"""The compiled step's numbers held by a controller, checked against their declarations.

Each number the step reads has a declared check (:data:`hybrid.spec.interfaces.CHECKS`, on the ports of
:data:`hybrid.spec.controller_step.CONTROLLER_STEP`); the standalone C checks the same at each sample. A
controller checks its numbers when they are set, and the settings a sample reads in Python (the sample time,
the timing and singular tolerances) at the sample, since they may change between samples.

The sample time is also one of the step's numbers (``options``' ``sample_time``, the standalone C's
``sample_time`` field): the integrals, the sensor's filter, the estimate and the safe state's release advance
by it, and a path task's follower by the same. A sample time set between samples is written there at once, so the
next sample advances everything by the new period, as in the standalone C.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.path_task import MAX_GAIN_SAMPLES, PATH_SAMPLE_TIME
from hybrid.errors import HybridError
from hybrid.spec.controller_step import CONTROLLER_STEP, OPTIONS, SETTING_CHECKS
from hybrid.spec.interfaces import CHECKS, Dims
from hybrid.validate import shown

#: the step's parameters, in its order
_PARAMETERS = CONTROLLER_STEP.parameters
#: where the sample time is among the step's options
_SAMPLE_TIME = OPTIONS.index("sample_time")


def _number(value) -> float | None:
    """``value`` as a float when it is a real number within the range of one (not a bool, a string, None ...)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        return None
    try:
        return float(value)
    except OverflowError:  # an integer beyond any double
        return None


def _retimed(params: tuple, T: float) -> tuple:
    """``params`` (the step's, in its order) with the sample time ``T`` among the options (a new read-only array:
    the step's numbers change only by replacement)."""
    out = []
    for name, a in zip(_PARAMETERS, params):
        if name == "options" and a[_SAMPLE_TIME] != T:
            a = a.copy()
            a[_SAMPLE_TIME] = T
            a.flags.writeable = False
        out.append(a)
    return tuple(out)


#: the bounds the step's numbers hold from the controller's construction: assigned later, they would be ignored
FIXED_BOUNDS = ("torque_limit", "torque_step_limit", "integral_limit")


def _fixed_bound(name: str) -> property:
    """The controller's attribute ``name``, one of :data:`FIXED_BOUNDS`: set once by the constructor (an array
    read-only), then refused, since the compiled step keeps the bound it was built with (a bound that reads one
    value and applies another is no bound)."""

    def get(self):
        return self.__dict__[name]

    def refuse(self, value) -> None:
        if name in self.__dict__:
            raise HybridError(f"Controller {name} is fixed when the controller is built (its step holds the bound); "
                              f"build another controller with {name}=...")
        if isinstance(value, np.ndarray):
            value = value.copy()
            value.flags.writeable = False
        self.__dict__[name] = value

    return property(get, refuse, doc=f"The ``{name}`` the controller was built with (fixed: its step holds it).")


class CheckedParameters:
    """The checks of a controller's step numbers (its ``_params``, sized by its ``_dims``), and its sample time."""

    _dims: Dims
    _params: tuple[np.ndarray, ...]
    _start_params: tuple[np.ndarray, ...]
    _sample_time: object
    _estimated: bool
    _spatial: object
    _path_task: object
    _checked_settings: tuple | None
    timing_tolerance: float | None
    singular_tol: float
    torque_limit = _fixed_bound("torque_limit")
    torque_step_limit = _fixed_bound("torque_step_limit")
    integral_limit = _fixed_bound("integral_limit")

    @property
    def sample_time(self) -> float:
        """The sample period ``T`` [s] the controller runs at. It may change between samples: from the next
        sample on, the timing check, the loops' integrals, the sensor's filter, the estimate, the safe state's
        release and a path task's progress all take the new one (as a controller built with it would), and so does
        the C that :meth:`generate` writes. One that is not valid refuses the next sample
        (:class:`~hybrid.ParameterError`), nothing changed."""
        return self._sample_time

    @sample_time.setter
    def sample_time(self, value) -> None:
        T = _number(value)
        self._sample_time = value if T is None else T
        if T is None or not CHECKS["positive"].valid(T, T):
            return  # refused at the next sample (_refused_setting); the step keeps the last valid one meanwhile
        # the period is a setting, not part of a run: a reset keeps it, so the start's numbers take it too
        self._params, self._start_params = _retimed(self._params, T), _retimed(self._start_params, T)
        if self._path_task is not None:
            self._path_task.follower.settings[PATH_SAMPLE_TIME] = T
        self._checked_settings = None  # the next sample checks the settings again and binds the step to the new T

    @property
    def _period(self) -> float:
        """The sample time the step's numbers hold: the last valid one set."""
        return float(self._params[_PARAMETERS.index("options")][_SAMPLE_TIME])

    def _checked_parameters(self, values: dict) -> tuple:
        """The step's parameters packed from ``values``, each refused unless its declared check allows it
        (:data:`hybrid.spec.interfaces.CHECKS`: the standalone C checks the same at each sample), then
        read-only: they change only through this check (the checks that read the sample time read the one
        packed among the options)."""
        params = CONTROLLER_STEP.pack(values, self._dims)
        T = float(params[_PARAMETERS.index("options")][_SAMPLE_TIME])
        refused = CONTROLLER_STEP.refused(params, self._dims, T)
        if refused:
            port, element, value, valid = refused[0]
            raise HybridError(f"the step's {port} {element} = {shown(value)}; give {valid}"
                              + (f" ({len(refused) - 1} more refused)" if len(refused) > 1 else ""))
        for p in params:
            p.flags.writeable = False
        return params

    def _refused_setting(self) -> tuple[str, object, str] | None:
        """The first of the settings a sample reads here (the sample time, the timing and singular
        tolerances) that its declared check refuses, as ``(name, value, what is valid)``, or a step's
        number whose check reads the sample time and refuses it at this one (a filter cutoff at or above
        Nyquist, a fault reaction's stop_time under two sample times), as the standalone C refuses its
        struct's, or a sample time an estimated surface or a path task cannot be sampled at. (The sample
        clock is the controller's own, only ever a finite ``t`` it served.)"""
        T = _number(self.sample_time)
        if T is None or not CHECKS["positive"].valid(T, T):
            return "sample_time", self.sample_time, CHECKS["positive"].meaning
        refused = CONTROLLER_STEP.refused(self._params, self._dims, T)
        if refused:
            port, element, value, valid = refused[0]
            return f"the step's {port} {element} at sample_time = {T:g} s", value, valid
        sampled = self._sampling_refused(T)
        if sampled is not None:
            return "sample_time", T, sampled
        tolerance = self.timing_tolerance
        # None turns the check off (the C's -1); a -1 given is a tolerance out of range here, refused
        given = _number(tolerance) if tolerance is not None else None
        settings = {"timing_tolerance": -1.0 if tolerance is None else None if given == -1.0 else given,
                    "singular_tol": _number(self.singular_tol)}
        for name, check in SETTING_CHECKS.items():
            if settings[name] is None or not CHECKS[check].valid(settings[name], T):
                return name, getattr(self, name), CHECKS[check].meaning
        return None

    def _sampling_refused(self, T: float) -> str | None:
        """What the sample time must be where an estimated surface or a path task refuses ``T`` (their
        ``check_sampling``, as at construction), or None."""
        owners = []
        if self._estimated:
            owners.append((self._spatial, "the EstimatedSurface's force_time_constant allows (at least one period)"))
        if self._path_task is not None:
            owners.append((self._path_task.follower.task,
                           f"the PathTask's gains allow (gain x period at most {MAX_GAIN_SAMPLES})"))
        for owner, allowed in owners:
            try:
                owner.check_sampling(T)
            except HybridError:
                return f"a period {allowed}"
        return None
