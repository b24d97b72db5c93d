"""The one error family the library raises on bad input."""


class HybridError(ValueError):
    """Bad input or an impossible request; the message says what was wrong and what to do."""


class SingularConfigurationError(HybridError):
    """The arm is at (or too near) a kinematic singularity: ``J(q)`` cannot be inverted."""


class NonFiniteError(HybridError):
    """A computation produced NaN or infinity."""


class NativeBuildError(HybridError):
    """The generated C could not be compiled or loaded."""


class URDFError(HybridError):
    """A URDF file that cannot describe a controllable serial arm; names the element and line."""


class TaskFrameError(HybridError):
    """The task frame is undefined: its reference direction is parallel to the surface normal, or the
    surface has no normal there (its gradient vanishes, or its formula is undefined)."""


class SampleTimingError(HybridError):
    """A control sample off the sample clock: ``t`` did not advance by one sample time (within the
    controller's ``timing_tolerance``). ``status`` names the fault (``SAMPLE_LATE``, ``SAMPLE_EARLY``,
    ``SAMPLE_REPEATED``, ``SAMPLE_BACKWARDS``); ``torque`` [N m or N] is what to apply: the law's at
    this sample, within the limits, with the loops' integrals left as they were."""

    def __init__(self, status: str, t: float, last: float, sample_time: float, torque):
        self.status, self.t, self.torque = status, float(t), torque
        t, last = float(t), float(last)
        what = {"SAMPLE_LATE": "late", "SAMPLE_EARLY": "early", "SAMPLE_REPEATED": "repeated",
                "SAMPLE_BACKWARDS": "backwards"}[status]
        super().__init__(
            f"sample at t = {t!r} s is {what}: {t - last:.6g} s after the last (t = {last!r} s), the sample time "
            f"is {sample_time:g} s\n  call the controller once every sample time; apply this error's torque "
            "(the integrals were left as they were), or give timing_tolerance=None to skip the check")


class ParameterError(HybridError):
    """A run-time parameter of the control step that its declared check refuses (a NaN, a negative limit
    or tolerance, a filter cutoff at or above Nyquist): the sample is refused and nothing changes.
    ``status`` is ``PARAMETER_INVALID`` (the standalone C's status); ``torque`` [N m or N] is what to
    apply: the torque last written (within the last valid limits), 0 before any."""

    status = "PARAMETER_INVALID"

    def __init__(self, name: str, value, valid: str, torque):
        self.name, self.value, self.torque = name, value, torque
        super().__init__(f"{name} = {value!r}; give {valid} (the sample was refused: apply this error's torque, "
                         "the torque last written)")


class SafeStopError(HybridError):
    """The control step is in its safe state (``status`` ``SAFE_STOP``, the standalone C's status) after
    its fault reaction's ``fault_samples`` consecutive faulted samples, until ``reset()``: ``torque``
    [N m or N] is what to apply (it holds the arm and releases the torque it had at the fault)."""

    status = "SAFE_STOP"

    def __init__(self, torque, faults: int, cause: str):
        self.torque, self.faults = torque, faults
        super().__init__(f"the controller is in its safe state after {faults} consecutive faulted samples (the "
                         f"last: {cause}); apply this error's torque (it holds the arm and releases the contact) "
                         "and call reset() to resume")


class LargeModelWarning(UserWarning):
    """A model so large that generating and compiling its code takes minutes (the message says how long)."""
