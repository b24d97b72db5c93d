"""The control step's fault reaction: a safe state after consecutive faulted samples, until a reset.

A real arm's controller must not serve a fault for ever: holding the last torque through a long sensor
dropout lifts the tool off and brings it back with an impact. :class:`FaultReaction` holds the numbers
of the reaction (:data:`hybrid.spec.controller_step.FAULT`): after ``fault_samples`` consecutive faulted
samples (refused: a bad input or parameter, the law failing; or served off time: late, early) the step
enters its safe state and stays there until ``reset``. The safe state (``codegen.safe_stop``, the same
compiled kernel in C and Python) stops the arm and holds it where it was at the entry, by its model's
inverse dynamics for a critically damped hold of time constant ``stop_time`` (gravity, the velocity
terms and the joints' friction compensated), and releases the difference between the torque the arm
had and the hold's linearly over ``unload_time``, within the torque limits: a controlled stop with the
drives on (IEC 60204-1's stop category 2, as an industrial arm's protective stop), neither a fall
(power off) nor a rebound of the tool onto the part; the pressing the law added decays at a bounded
rate, and the contact force the tool's compliance stores at the held position stays.

A sample at which no time passed (repeated, or before the last) is no fault of its own: it counts
nothing (with the timing check off, time passes at every sample: the law serves each as one sample
period). A faulted sample counts one more, or the sample periods since the last sample served (to the
nearest whole) where those are more (:func:`counted`): a gap counts the samples it missed, as a dropout's
refused samples would have, so a clock jumped far ahead (a glitch, or a loop stalled longer than the fault
window) enters the safe state at once rather than leaving every later sample behind its clock, none of
them counted. A sample the law serves on time ends a count.

:class:`FaultMonitor` is that bookkeeping for :class:`hybrid.Controller` (the standalone C's step does
the same in its struct's ``fault_state``, element for element).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import isfinite

import numpy as np

from hybrid.errors import HybridError, SafeStopError
from hybrid.spec.controller_step import FAULT, FAULT_CHECKS, FAULT_DEFAULTS, FAULT_STATE, OPTIONS
from hybrid.spec.interfaces import CHECKS, Dims
from hybrid.validate import checked_keywords, shown


@checked_keywords
@dataclass(frozen=True)
class FaultReaction:
    """The fault reaction's numbers (module docstring).

    Parameters
    ----------
    fault_samples : int
        Consecutive faulted samples that enter the safe state (a whole number >= 1); a faulted sample
        after a gap counts the sample periods the gap spans.
    stop_time : float
        [s] > 0, the joints' velocities decay as ``q'' = -q' / stop_time`` in the safe state; a
        controller refuses one shorter than two of its sample times (:meth:`check_sampling`).
    unload_time : float
        [s] >= 0, the torque the arm had at the fault is released over it (0: at once).

    Raises
    ------
    HybridError
        A value out of its range, or not a number.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.FaultReaction(fault_samples=3).as_array().tolist()
    [3.0, 0.05, 0.2]
    """

    fault_samples: int = int(FAULT_DEFAULTS[0])
    stop_time: float = FAULT_DEFAULTS[1]
    unload_time: float = FAULT_DEFAULTS[2]

    def __post_init__(self):
        checks = dict(zip(FAULT, ("count", "positive", "nonnegative")))
        for name in FAULT:
            value = getattr(self, name)
            number = not isinstance(value, (bool, np.bool_)) and isinstance(value, (int, float, np.integer,
                                                                                     np.floating))
            if not number or not CHECKS[checks[name]].valid(float(value), 1.0):
                raise HybridError(f"FaultReaction {name} = {shown(value, 40)}; give {CHECKS[checks[name]].meaning}")
            object.__setattr__(self, name, int(value) if name == "fault_samples" else float(value))

    def check_sampling(self, sample_time: float) -> None:
        """Refuse a ``stop_time`` shorter than two sample times ``sample_time`` [s]: the hold is a PD law
        served once a sample (the torque held between samples), whose discrete poles leave the unit circle at
        ``stop_time <= sample_time`` (the arm is thrown, not stopped); at two sample times they are inside,
        at 0.7.

        Parameters
        ----------
        sample_time : float
            The controller's sample time [s].

        Raises
        ------
        HybridError
            ``stop_time`` is shorter than two sample times.
        """
        if not CHECKS[FAULT_CHECKS[FAULT.index("stop_time")]].valid(self.stop_time, sample_time):
            raise HybridError(f"FaultReaction stop_time = {self.stop_time:g} s is shorter than two sample times "
                              f"({2 * sample_time:g} s at the sample time {sample_time:g} s): the sampled stop "
                              "would be unstable; give at least two sample times")

    def as_array(self) -> np.ndarray:
        """The numbers as the step reads them.

        Returns
        -------
        numpy.ndarray
            ``fault_samples``, ``stop_time``, ``unload_time`` (:data:`~hybrid.spec.controller_step.FAULT`).
        """
        return np.array([float(getattr(self, name)) for name in FAULT])


class FaultMonitor:
    """The fault reaction's state for a controller of ``dims``' joints: ``state`` is
    :data:`~hybrid.spec.controller_step.FAULT_STATE` (the torque to release, the last finite joint
    positions, NaN before any, the positions held, the consecutive faulted samples, 1 in the safe state,
    the samples since its entry)."""

    def __init__(self, dims: Dims):
        names = FAULT_STATE.names(dims)
        self.n = len(dims.joints)
        self.state = np.zeros(len(names))
        self._faults, self._stopped, self._samples = (names.index(k) for k in FAULT_STATE.tail)
        self.reset()

    def reset(self) -> None:
        """No fault, no safe state, and no finite joint positions yet (``q_hold`` NaN: none to stop at)."""
        self.state[:] = 0.0
        self.state[self.n:2 * self.n] = np.nan

    @property
    def stopped(self) -> bool:
        return bool(self.state[self._stopped])

    @property
    def faults(self) -> int:
        return int(self.state[self._faults])

    def served(self, q, on_time: bool) -> None:
        """A sample the law served: its ``q`` kept; on time, the count ends."""
        self._hold(q)
        if on_time:
            self.state[self._faults] = 0.0

    def faulted(self, passed: bool, reaction: FaultReaction, torque: np.ndarray, q, periods: float) -> bool:
        """A faulted sample at ``q``, ``periods`` sample periods after the last served (counted when time
        ``passed``, :func:`counted`); True when it enters the safe state: the arm then stops and holds where
        it is, and the torque it has (``torque``) is released from here."""
        if passed:
            self.state[self._faults] = counted(self.state[self._faults], periods, reaction.fault_samples)
        if self.state[self._faults] < reaction.fault_samples:
            return False
        n = self.n
        q_now = _finite_vector(q, n)
        self.state[2 * n:3 * n] = self.state[n:2 * n] if q_now is None else q_now
        self.state[:n] = torque
        self.state[self._stopped], self.state[self._samples] = 1.0, 0.0
        return True

    def safe_sample(self, stop, q, qdot, last: np.ndarray, parameters: dict, passed: bool, cause: str):
        """One sample of the safe state: the error carrying its torque (the ``safe_stop`` kernel ``stop``
        at ``q``, or the last finite positions, and ``qdot``, or 0, from the ``parameters`` by name); when
        time ``passed``, the last torque ``last`` (the step's state) becomes it and the release advances.
        At a sample where no time passed nothing changes (as the law's own): else repeated samples would
        walk the torque by the rate bound each, with no time passing."""
        state = self.state if passed else self.state.copy()
        q_now = _finite_vector(q, self.n)
        qd_now = _finite_vector(qdot, self.n) if q_now is not None else None
        qs = state[self.n:2 * self.n] if q_now is None else q_now
        qds = np.zeros(self.n) if qd_now is None else qd_now
        q_stop = state[2 * self.n:3 * self.n]
        if q_now is not None and not np.isfinite(q_stop).all():
            # entered before any finite joint positions: the arm stops at the first finite ones (until then the
            # kernel gives no torque, and the torque last written stays)
            q_stop[:] = q_now
        T = parameters["options"][OPTIONS.index("sample_time")]
        try:
            got = stop(qs, qds, last, state, parameters["robot"], parameters["fault"], parameters["limits"],
                       np.array([T]))
            tau = np.asarray(got["tau"], float).ravel().copy()
            state[:self.n] = np.asarray(got["tau_offset_next"], float).ravel()
            finite = True
        except HybridError:  # the model gives no torque: the torque last written, and the release waits
            tau, finite = last[:-1] * last[-1], False
        if passed:
            last[:-1], last[-1] = tau, 1.0
            self.state[self._samples] += float(finite)
            self._hold(q)
        return SafeStopError(tau.copy(), self.faults, cause)

    def _hold(self, q) -> None:
        got = _finite_vector(q, self.n)
        if got is not None:
            self.state[self.n:2 * self.n] = got


def counted(count: float, periods: float, limit: float) -> float:
    """The fault count after a faulted sample ``periods`` sample periods after the last served: ``count + 1``,
    or the sample instants the gap spans where more (``periods`` to the nearest whole: a gap of whole
    periods counts them whatever its rounding; a NaN counts none), at most ``limit`` (the standalone C's
    ``counted``, the same numbers)."""
    n, spanned = count + 1.0, float(np.floor(periods + 0.5))
    if spanned > n:
        n = spanned
    return min(n, float(limit))


def sample_periods(t, clock: float | None, T: float) -> float:
    """The sample periods ``T`` from the last sample served at ``clock`` to ``t`` (0 without a clock, a
    finite ``t`` or a valid ``T``; the caller gives 0 with the timing check off)."""
    t, T = finite_time(t), finite_time(T)
    if clock is None or t is None or T is None or T <= 0:
        return 0.0
    return (t - float(clock)) / T  # Python floats: a difference past the largest double is inf, not a warning


def finite_time(t) -> float | None:
    """``t`` as a finite number of seconds, or None (not a number, or not finite)."""
    if isinstance(t, (bool, np.bool_)) or not isinstance(t, (int, float, np.integer, np.floating)):
        return None
    try:
        t = float(t)
    except OverflowError:
        return None
    return t if isfinite(t) else None


def timing_status(t: float, clock: float | None, T: float, tolerance: float | None) -> str | None:
    """The timing status of a sample at ``t`` after the last at ``clock`` (None: on time, or no check,
    or no last sample) for the sample period ``T`` within the fraction ``tolerance``."""
    if clock is None or tolerance is None:
        return None
    dt = t - clock
    if dt < 0:
        return "SAMPLE_BACKWARDS"
    if dt == 0:
        return "SAMPLE_REPEATED"
    if dt < T * (1 - tolerance):
        return "SAMPLE_EARLY"
    return "SAMPLE_LATE" if dt > T * (1 + tolerance) else None


def time_passed(t, clock: float | None) -> bool:
    """Whether time passed at a sample at ``t`` since the last served at ``clock``: not at a ``t`` at or
    before it (one that is not a finite number cannot tell)."""
    t = finite_time(t)
    return clock is None or t is None or t > clock


def _finite_vector(v, n: int) -> np.ndarray | None:
    try:
        arr = np.asarray(v, dtype=float)
    except (TypeError, ValueError, OverflowError):
        return None
    return arr.copy() if arr.shape == (n,) and np.isfinite(arr).all() else None
