"""The one error family the library raises on bad input."""


class HybridError(ValueError):
    """Bad input or an impossible request; the message says what was wrong and what to do.

    The base of every error the library raises on bad input (a :class:`ValueError`): catch it to
    catch them all.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Sphere(center=(0.0, 0.0, 0.0),
    ...               radius=-0.1)  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
        ...
    hybrid.errors.HybridError: Sphere.radius = -0.1 m;
    give a positive radius
    >>> issubclass(hybrid.URDFError, hybrid.HybridError)
    True
    """


class SingularConfigurationError(HybridError):
    """The arm is at (or too near) a kinematic singularity: ``J(q)`` cannot be inverted.

    Examples
    --------
    The planar arm stretched out (``q2 = 0``) has no operational space:

    >>> import hybrid
    >>> hybrid.operational_space(hybrid.paper_arm(), [0.0, 0.0],
    ...                          [0.0, 0.0])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    hybrid.errors.SingularConfigurationError: ...
    """


class NonFiniteError(HybridError):
    """A computation produced NaN or infinity, or was given it.

    Examples
    --------
    >>> import hybrid
    >>> disc = hybrid.Circle((0.5, 0.0), 0.2)
    >>> hybrid.task_frame(disc, [0.3, float("nan")],
    ...                   [0.0, 0.1])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    hybrid.errors.NonFiniteError: task_frame: non-finite input ...
    """


class NativeBuildError(HybridError):
    """The generated C could not be compiled or loaded (no C compiler, an unwritable cache folder).

    Examples
    --------
    >>> import hybrid
    >>> issubclass(hybrid.NativeBuildError, hybrid.HybridError)
    True
    """


class URDFError(HybridError):
    """A URDF file that cannot describe a controllable serial arm; names the element and line.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Robot.from_urdf(
    ...     hybrid.UR5_URDF, tip="no_such_link")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    hybrid.errors.URDFError: ...no_such_link...
    """


class TaskFrameError(HybridError):
    """The task frame is undefined: its reference direction is parallel to the surface normal, or the
    surface has no normal there (its gradient vanishes, or its formula is undefined).

    Examples
    --------
    On a horizontal plane the default frame direction ``e = z`` is the normal itself:

    >>> import hybrid
    >>> floor = hybrid.Plane(point=(0, 0, 0), normal=(0, 0, 1))
    >>> hybrid.task_frame(floor, [0.3, 0.0, 0.0],
    ...                   [0.1, 0.0, 0.0])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    hybrid.errors.TaskFrameError: task_frame: the task frame is ...
    """


class SampleTimingError(HybridError):
    """A control sample off the sample clock: ``t`` did not advance by one sample time (within the
    controller's ``timing_tolerance``).

    Parameters
    ----------
    status : str
        The fault: ``"SAMPLE_LATE"``, ``"SAMPLE_EARLY"``, ``"SAMPLE_REPEATED"`` or
        ``"SAMPLE_BACKWARDS"`` (kept as ``status``).
    t : float
        The sample's time [s] (kept as ``t``).
    last : float
        The time of the last sample served [s].
    sample_time : float
        The controller's sample time [s].
    torque : numpy.ndarray
        What to apply [N m or N]: the law's torque at this sample, within the limits, with the
        loops' integrals left as they were (kept as ``torque``).

    Examples
    --------
    >>> import hybrid
    >>> error = hybrid.SampleTimingError(
    ...     "SAMPLE_LATE", t=0.03, last=0.01, sample_time=0.01,
    ...     torque=[0.0, 0.0])
    >>> error.status, error.t
    ('SAMPLE_LATE', 0.03)
    >>> first = str(error).splitlines()[0]
    >>> print(first)  # doctest: +NORMALIZE_WHITESPACE
    sample at t = 0.03 s is late: 0.02 s after the last (t = 0.01 s),
    the sample time is 0.01 s
    """

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
    ``status`` is ``PARAMETER_INVALID`` (the standalone C's status).

    Parameters
    ----------
    name : str
        The parameter refused (kept as ``name``).
    value : object
        Its value (kept as ``value``).
    valid : str
        What would be valid, in words (the message's advice).
    torque : numpy.ndarray
        What to apply [N m or N]: the torque last written (within the last valid limits), 0 before
        any (kept as ``torque``).

    Examples
    --------
    >>> import hybrid
    >>> error = hybrid.ParameterError("torque_limit", -1.0,
    ...                               "a limit >= 0", torque=[0, 0])
    >>> error.status, error.name
    ('PARAMETER_INVALID', 'torque_limit')
    >>> print(error)  # doctest: +ELLIPSIS, +NORMALIZE_WHITESPACE
    torque_limit = -1.0; give a limit >= 0 (the sample was refused:
    ...)
    """

    status = "PARAMETER_INVALID"

    def __init__(self, name: str, value, valid: str, torque):
        self.name, self.value, self.torque = name, value, torque
        super().__init__(f"{name} = {value!r}; give {valid} (the sample was refused: apply this error's torque, "
                         "the torque last written)")


class SafeStopError(HybridError):
    """The control step is in its safe state (``status`` ``SAFE_STOP``, the standalone C's status) after
    its fault reaction's ``fault_samples`` consecutive faulted samples, until ``reset()``.

    Parameters
    ----------
    torque : numpy.ndarray
        What to apply [N m or N]: it holds the arm and releases the torque it had at the fault (kept
        as ``torque``).
    faults : int
        The consecutive faulted samples that entered the safe state (kept as ``faults``).
    cause : str
        The last fault, in words.

    Examples
    --------
    >>> import hybrid
    >>> error = hybrid.SafeStopError([0.0, 0.0], faults=5,
    ...                              cause="a NaN force reading")
    >>> error.status, error.faults
    ('SAFE_STOP', 5)
    >>> print(error)  # doctest: +ELLIPSIS, +NORMALIZE_WHITESPACE
    the controller is in its safe state after 5 consecutive faulted
    samples (the last: a NaN force reading); ...
    """

    status = "SAFE_STOP"

    def __init__(self, torque, faults: int, cause: str):
        self.torque, self.faults = torque, faults
        super().__init__(f"the controller is in its safe state after {faults} consecutive faulted samples (the "
                         f"last: {cause}); apply this error's torque (it holds the arm and releases the contact) "
                         "and call reset() to resume")


class LargeModelWarning(UserWarning):
    """A model so large that generating and compiling its code takes minutes (the message says how long).

    Examples
    --------
    Silence it where a long build is expected:

    >>> import warnings
    >>> import hybrid
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", hybrid.LargeModelWarning)
    ...     robot = hybrid.ur5()
    >>> robot.n
    6
    """
