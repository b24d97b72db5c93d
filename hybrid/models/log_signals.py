"""A robot's log made ready for identification: its times checked, the positions and torques low-pass
filtered alike, velocities and accelerations differentiated, the filter's edges dropped and the samples
thinned to the filtered signals' rate.

The choices, and why:

- **One zero-phase filter for every signal.** A Butterworth low-pass of order :data:`ORDER`, run forward
  and backward (:func:`scipy.signal.sosfiltfilt`: no phase lag, the magnitude's roll-off doubled), filters
  ``q`` and, the same filter, ``tau`` (and ``q'``, ``q''`` when the log has them). The torques and the
  motion that caused them keep one bandwidth and no delay between them; what the filter takes from the
  torque's fastest content it takes from the motion's too.
- **Derivatives by central differences of the filtered q**, on a stencil of ``2 m + 1`` samples
  (:data:`STENCIL` ``= m = 4``: exact for polynomials of degree 8). On a sinusoid of angular frequency
  ``w`` sampled every ``h`` its relative error is ``(w h)^8 / 630`` for ``q'`` (less for ``q''``):
  3e-9 at 3 Hz sampled at 100 Hz, far less at 1 kHz. Differences amplify noise at high frequencies,
  and the filter has removed it there. A Savitzky-Golay derivative was not taken: it is a low-pass of
  its own whose bandwidth is set by its window in samples, so ``q'`` would have another bandwidth
  than ``tau`` (or be filtered twice).
- **The default cutoff**, :data:`DEFAULT_CUTOFF_HZ` (at most a quarter of the sampling rate): well
  above a trajectory of a few hertz, whose torques (products and harmonics of the motion's
  frequencies) keep most of their content below it, and low enough that a log sampled at 100 Hz to
  10 kHz loses its measurement noise above it. On the UR5 along a multi-sine up to 3 Hz logged at 1
  kHz it recovers the base parameters to about 1e-5 of the largest (the filter's attenuation of the
  torques' content near the cutoff); give ``cutoff_hz`` about 5 to 10 times the excitation's highest
  frequency for another trajectory.
- **The filter's edges are dropped**: the forward-backward filter starts from a guess of the signal
  beyond the log (an odd reflection); the error it makes decays as the filter's slowest pole, and the
  samples within :data:`EDGE_DECAY` of it (``5.7 / cutoff`` seconds for order 4) at each end are not
  used, nor the ``m`` more the differences need.
- **Thinned to about twice the cutoff**: the filtered signals have no content above the cutoff, so
  every ``fs / (2 cutoff)``-th sample carries what the samples between do; the filtered noise of
  samples that far apart is nearly independent (correlation 0.1), which the least squares' standard
  deviations assume, where neighbouring samples' is nearly 1 (standard deviations too small by
  ``sqrt(fs / (2 cutoff))``). A log too short to give the fit its samples that far apart is refused:
  thinned closer, a 1 s log of the UR5 at 1 kHz left 23-32 of its 54 base parameters more than 3
  standard deviations off, some of them not named poorly excited (30 % off and more).
- **Uniform sampling is required**: times deviating from a uniform grid by more than :data:`JITTER` of
  a step (a missed sample, a clock's jump) are refused, with the fix (resample the log onto a uniform
  grid, or cut it at the gap); within it, the samples are taken as uniform at the mean step (a timing
  error of ``JITTER h`` is a position error of ``q' JITTER h``, 2e-5 rad at 1 rad/s and 1 kHz).
- **The Coulomb friction's smooth sign filtered too** (given the joints' ``coulomb_speed``): the filter
  takes from the measured torque the fast content of ``F_c tanh(q' / v_s)`` where a joint's speed
  crosses zero (about ``v_s / |q''|`` long: 25 ms at 0.05 rad/s and 2 rad/s^2, content up to the
  cutoff's 20 Hz), which ``tanh`` of the filtered ``q'`` keeps. Unmatched, an exact log of the UR5
  with Coulomb friction of 2 % of its efforts gave its frictions 2-16 % off and an inertia many times
  off; ``tanh(q' / v_s)`` filtered by the same filter (``sign``) matches the torques: every base
  parameter within 2e-4 of its size, as without friction.

``smooth=False`` takes the log as it is (no filter, no thinning): signals already filtered, or exact
ones (a simulation's); ``q'`` and ``q''`` not given are then differences of the raw ``q``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import listed, shown

#: the Butterworth filter's order (run forward and backward: order 8 in magnitude, no phase)
ORDER = 4
#: the default cutoff [Hz], for trajectories of a few hertz; capped at a quarter of the sampling rate
DEFAULT_CUTOFF_HZ = 20.0
#: the share of the sampling rate the default cutoff is capped at (half the Nyquist frequency)
DEFAULT_RATE_SHARE = 0.25
#: the samples dropped at each end: until the filter's slowest pole has decayed to this fraction
EDGE_DECAY = 1e-6
#: half the central differences' stencil (``2 m + 1`` samples, exact to degree ``2 m``)
STENCIL = 4
#: the largest deviation of the times from a uniform grid taken as uniform, as a share of the step
JITTER = 0.02
#: the slowest sampling rate taken [Hz]: an arm's dynamics need its accelerations, which a slower log does not
#: resolve (a log whose times are in milliseconds would seem sampled a thousand times too slowly)
LEAST_RATE = 10.0
#: the samples kept are about this many times the cutoff apart in rate (twice: the filtered signals'
#: Nyquist rate)
KEPT_RATE = 2.0


@dataclass(frozen=True)
class LogSignals:
    """The samples of a log that a fit uses: filtered, differentiated, edges dropped, thinned.

    Parameters
    ----------
    q, qd, qdd, tau : numpy.ndarray
        ``(M, n)`` each: joint positions, velocities, accelerations and torques of the samples kept.
    rows : numpy.ndarray
        ``(M,)``: each kept sample's row in the log.
    sample_time : float
        The log's step [s] (the mean of its intervals).
    cutoff_hz : float or None
        The filter's cutoff [Hz]; None for a log taken as it is.
    edge : int
        The samples dropped at each end (the filter's and the differences').
    step : int
        Every ``step``-th sample is kept.
    log_samples : int
        The log's samples.
    sign : numpy.ndarray or None
        ``(M, n)``: the Coulomb friction's smooth sign ``tanh(q' / v_s)`` filtered as the torques were;
        None where the log is taken as it is (or no ``coulomb_speed`` was given).
    """

    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
    tau: np.ndarray
    rows: np.ndarray
    sample_time: float
    cutoff_hz: float | None
    edge: int
    step: int
    log_samples: int
    sign: np.ndarray | None = None


def _real(name: str, value, what: str) -> np.ndarray:
    """``value`` as floats; complex numbers (whose imaginary part a cast drops), booleans and text refused."""
    try:
        kind = np.asarray(value).dtype.kind
        arr = np.asarray(value, dtype=float) if kind not in "cb" else None
    except (TypeError, ValueError):
        arr = None
    if arr is None:
        raise HybridError(f"{name} = {shown(value, 60)}; give {what}")
    return arr


def _joint_order(name: str, value, joints) -> None:
    """Refuse a table (a pandas DataFrame) whose columns name the joints (``joint`` or ``name[joint]``) in
    another order than the robot's: its columns are taken by position."""
    columns = getattr(value, "columns", None)
    if columns is None:
        return
    labels = [str(c).strip() for c in columns]
    for wanted in (list(joints), [f"{name}[{j}]" for j in joints]):
        if labels != wanted and sorted(labels) == sorted(wanted):
            raise HybridError(f"{name}'s columns {listed(labels)} are the robot's joints in another order; give them "
                              f"in the robot's (robot.joint_names: {listed(wanted)}), e.g. {name}[{wanted}]")


def samples(name: str, value, n: int, joints) -> np.ndarray:
    """``value`` as an ``(N, n)`` array of finite numbers; a bad sample is named by its row and joint."""
    _joint_order(name, value, joints)
    arr = _real(name, value, f"an (N, {n}) array of real numbers, one row per sample")
    if arr.ndim != 2 or arr.shape[1] != n:
        raise HybridError(f"{name} has shape {arr.shape}; give an (N, {n}) array, one row of {n} joint values per "
                          "sample")
    if not np.isfinite(arr).all():
        k, j = np.argwhere(~np.isfinite(arr))[0]
        raise HybridError(f"{name}[{k}, {j}] = {arr[k, j]} (sample {k}, joint {joints[j]}); give finite numbers "
                          "(drop the samples where the measurement failed, with their times)")
    return arr


def times(t) -> np.ndarray:
    """``t`` as ``(N,)`` finite, strictly increasing times, uniform within :data:`JITTER` of a step."""
    t = _real("t", t, "the samples' times [s], one real number per sample")
    if t.ndim != 1:
        raise HybridError(f"t has shape {t.shape}; give the samples' times [s] as one number per sample, (N,)")
    if not np.isfinite(t).all():
        k = int(np.argmax(~np.isfinite(t)))
        raise HybridError(f"t[{k}] = {t[k]}; give finite times (drop the samples whose time failed)")
    if len(t) < 2:
        raise HybridError(f"the log has {len(t)} sample(s); give a log of many samples (seconds of motion)")
    dt = np.diff(t)
    if (dt <= 0).any():
        k = int(np.argmax(dt <= 0)) + 1
        how = "repeats" if dt[k - 1] == 0 else "is before"
        raise HybridError(f"t[{k}] = {float(t[k])!r} {how} t[{k - 1}] = {float(t[k - 1])!r}; give strictly increasing "
                          "times (sort the log by time, drop repeated rows)")
    k = np.arange(len(t))
    since = t - t[0]  # (a clock's epoch would cost the fit its precision)
    slope, offset = np.polyfit(k, since, 1)
    off = np.abs(since - (offset + slope * k))
    if off.max() > JITTER * slope:
        worst = int(np.argmax(off))
        raise HybridError(f"the log's times are not uniform: t[{worst}] = {float(t[worst])!r} is "
                          f"{off[worst] / slope:.2g} of a step ({slope:.4g} s) off a uniform grid, more than "
                          f"{JITTER:g}; resample the log onto uniform times (numpy.interp per column) or cut it at the "
                          "gap")
    return t


def default_cutoff(sample_rate: float) -> float:
    """The cutoff [Hz] taken when none is given: :data:`DEFAULT_CUTOFF_HZ`, at most
    :data:`DEFAULT_RATE_SHARE` of the sampling rate."""
    return min(DEFAULT_CUTOFF_HZ, DEFAULT_RATE_SHARE * sample_rate)


def derivative(x: np.ndarray, h: float, order: int, rows=None) -> np.ndarray:
    """The ``order``-th derivative of the uniformly sampled ``x`` (along axis 0, step ``h``) by central
    differences on ``2 m + 1`` samples (:data:`STENCIL` ``= m``); the ``m`` samples at each end, which
    the stencil does not cover, are NaN. With ``rows`` (each within ``[m, len(x) - m)``): at those rows
    alone, so a long log thinned to a few of its samples is not differentiated whole."""
    m = STENCIL
    offsets = np.arange(-m, m + 1, dtype=float)
    # the weights w with sum_k w_k k^j = order! [j == order], j = 0..2m: exact for polynomials of degree 2m
    rhs = np.zeros(2 * m + 1)
    rhs[order] = math.factorial(order)
    w = np.linalg.solve(np.vander(offsets, increasing=True).T, rhs) / h**order
    if rows is not None:
        rows = np.asarray(rows)
        return sum(wk * x[rows + k - m] for k, wk in enumerate(w))
    out = np.full_like(x, np.nan)
    out[m:len(x) - m] = sum(wk * x[k:len(x) - 2 * m + k] for k, wk in enumerate(w))
    return out


def _edge(sos: np.ndarray) -> int:
    """The samples at each end the forward-backward filter ``sos`` has not settled in: its slowest pole's
    decay to :data:`EDGE_DECAY`."""
    from scipy import signal

    radius = float(np.abs(signal.sos2zpk(sos)[1]).max())
    return int(math.ceil(math.log(EDGE_DECAY) / math.log(radius)))


def log_signals(robot_joints, t, q, tau, *, qd=None, qdd=None, cutoff_hz=None, smooth: bool = True,
                least: int = 1, coulomb_speed=None) -> LogSignals:
    """The log's samples ready for a fit: checked, filtered, differentiated, edges dropped, thinned (see
    the module's description).

    Parameters
    ----------
    robot_joints : sequence of str
        The joints' names (the columns of ``q``, ``tau``), to name a bad sample.
    t : array_like
        ``(N,)`` times [s], uniform.
    q, tau : array_like
        ``(N, n)`` joint positions and torques.
    qd, qdd : array_like or None
        ``(N, n)`` measured velocities and accelerations, or None: differences of the filtered ``q``
        (``qdd`` of ``qd`` when only ``qd`` is given).
    cutoff_hz : float or None
        The filter's cutoff [Hz]; None: :func:`default_cutoff`.
    smooth : bool
        False: no filter and no thinning (a log already filtered, or exact).
    least : int
        The samples the fit must keep at the least, after the edges and the thinning (the fit passes its
        base parameters' count: a margin over the ``p / n`` samples its ``p`` unknowns need).
    coulomb_speed : sequence of float or None
        The joints' smooth-sign speeds ``v_s`` [rad/s or m/s]: the Coulomb friction's sign
        ``tanh(q' / v_s)`` is filtered as the torques are (``sign``); None: not.

    Returns
    -------
    LogSignals
        The samples kept.

    Raises
    ------
    HybridError
        Arrays of the wrong shape or lengths, a sample not finite, times not increasing or not uniform, a
        cutoff not below the Nyquist frequency, or a log too short for the filter's edges and ``least``.
    """
    joints = tuple(robot_joints)
    n = len(joints)
    t = times(t)
    given = {"q": q, "tau": tau, "qd": qd, "qdd": qdd}
    arrays = {name: samples(name, v, n, joints) for name, v in given.items() if v is not None}
    lengths = {name: len(a) for name, a in arrays.items()}
    if set(lengths.values()) != {len(t)}:
        raise HybridError(f"t, {', '.join(lengths)} have {len(t)}, {', '.join(map(str, lengths.values()))} samples; "
                          "give one row of each per time, all the same length")
    N, h = len(t), float((t[-1] - t[0]) / (len(t) - 1))
    rate = 1.0 / h
    if rate < LEAST_RATE:
        raise HybridError(f"the log is sampled at {rate:.3g} Hz (a step of {h:.3g} s), too slowly for an arm's "
                          f"dynamics; give the times in seconds (a log in milliseconds: t / 1000), sampled at "
                          f"{LEAST_RATE:g} Hz or more")
    if not isinstance(smooth, (bool, np.bool_)):
        raise HybridError(f"smooth = {shown(smooth)}; give True (filter the log) or False (take it as it is)")
    if not smooth and cutoff_hz is not None:
        raise HybridError(f"cutoff_hz = {cutoff_hz!r} with smooth=False; give one of them (a cutoff filters the log)")
    fc = None
    if smooth:
        fc = default_cutoff(rate) if cutoff_hz is None else _cutoff(cutoff_hz, rate)
    m = STENCIL if (qd is None or qdd is None) else 0
    if fc is None:
        edge, sos = m, None
    else:
        from scipy import signal

        with warnings.catch_warnings():  # a cutoff far below the rate: the design's own warning, refused below
            warnings.simplefilter("ignore", signal.BadCoefficients)
            sos = signal.butter(ORDER, fc, fs=rate, output="sos")
        edge = _edge(sos) + m
    # thinned to about twice the cutoff: samples closer than that carry correlated noise, and a log too short to
    # give the fit its samples that far apart gave standard deviations several times too small
    step = 1 if fc is None else max(1, int(rate / (KEPT_RATE * fc)))
    if N < 2 * edge + least * step:
        because = f"filtering at {fc:g} Hz drops {edge}" if fc is not None else f"the differences drop {edge}"
        apart = "" if step == 1 else f" {step} apart (twice the cutoff)"
        # the filter settles fastest at a quarter of the sampling rate, slower toward 0 and toward Nyquist
        nearer = "" if fc is None else f", or a {'higher' if fc < DEFAULT_RATE_SHARE * rate else 'lower'} cutoff_hz"
        raise HybridError(f"the log has {N} samples; {because} at each end and the fit needs {least} more{apart}: give "
                          f"at least {2 * edge + least * step} samples (a longer log){nearer}")
    if sos is not None:
        from scipy import signal

        arrays = {name: _filtered(signal, sos, a) for name, a in arrays.items()}
    rows = np.arange(edge, N - edge, step)
    picked = {name: np.ascontiguousarray(a[rows]) for name, a in arrays.items()}
    # differentiated at the rows kept alone (the edge covers the stencil): memory of the samples kept, not the log's
    # the Coulomb friction's sign filtered needs q' at every sample: the rows' are then taken from it
    speed = _speed(arrays, h) if sos is not None and coulomb_speed is not None else None
    if "qd" not in picked:
        picked["qd"] = derivative(arrays["q"], h, 1, rows) if speed is None else speed[rows]
    if "qdd" not in picked:
        picked["qdd"] = derivative(arrays["qd"], h, 1, rows) if qd is not None else derivative(arrays["q"], h, 2, rows)
    sign = None if speed is None else _filtered(signal, sos, np.tanh(speed / np.asarray(coulomb_speed, float)))[rows]
    return LogSignals(**picked, rows=rows, sample_time=h, cutoff_hz=fc, edge=edge, step=step,
                      log_samples=N, sign=sign)


def _speed(arrays: dict, h: float) -> np.ndarray:
    """The filtered log's ``q'`` at every sample: measured, or central differences of ``q`` (the ``m`` samples
    at each end, which the stencil does not cover, take their neighbour's: the filter's error from them has
    decayed at the rows kept, the edge's)."""
    if "qd" in arrays:
        return arrays["qd"]
    qd = derivative(arrays["q"], h, 1)
    m = STENCIL
    qd[:m], qd[len(qd) - m:] = qd[m], qd[len(qd) - m - 1]
    return qd


def _filtered(signal, sos: np.ndarray, x: np.ndarray) -> np.ndarray:
    """``x`` filtered forward and backward by ``sos`` along axis 0, a column at a time: the filter's
    padded copies and passes are a column's, not the log's."""
    out = np.empty_like(x)
    for j in range(x.shape[1]):
        out[:, j] = signal.sosfiltfilt(sos, x[:, j])
    return out


def _cutoff(value, rate: float) -> float:
    """``cutoff_hz`` checked: a number in (0, Nyquist)."""
    try:
        fc = float(value)
    except (TypeError, ValueError):
        fc = float("nan")
    if isinstance(value, bool) or not math.isfinite(fc) or fc <= 0:
        raise HybridError(f"cutoff_hz = {shown(value)}; give the filter's cutoff in Hz, a positive number (a few "
                          "times the excitation's highest frequency), or None for the default")
    if fc >= rate / 2:
        raise HybridError(f"cutoff_hz = {fc:g} Hz is not below the log's Nyquist frequency {rate / 2:g} Hz (sampled at "
                          f"{rate:g} Hz); give a cutoff below it, a few times the excitation's highest frequency")
    return fc
