"""Gains that place the sampled loops' poles: :func:`suggest_gains`.

The command of a loop is linear in its gains, ``a = sum_j g_j c_j X``, and it closes the loop through the
plant's way in ``Gamma``: ``A(g) = A_o + Gamma c(g)``. A pole ``z`` of the closed loop is then a root of
``1 = c(g) (z I - A_o)^-1 Gamma``, an equation linear in the gains. Three poles (a pair of natural
frequency ``omega_n`` and damping ``zeta``, and the integral's real pole at ``ratio * omega_n``, all
taken from ``s`` to ``z = exp(s T)``) give three real equations for the loop's three gains, solved
exactly on the full sampled model: the sensor's mass and compliance, the arm, the hold, the reading's
lag, delay and filter.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from numbers import Real

import numpy as np

from hybrid.errors import HybridError
from hybrid.stability.analysis import Stability, _poles, axis_alone, stability
from hybrid.stability.experiment_loops import check_experiment, loop_numbers
from hybrid.stability.model import closed_loop
from hybrid.validate import checked_keywords, shown

#: each loop's gains, in the order of its equations: proportional (or damping), then the integrals
LOOP_GAINS = {"force": ("KPf", "KDf", "KIf"), "velocity": ("KPv", "KIv", "KI2v")}


@checked_keywords
@dataclass(frozen=True)
class GainSuggestion:
    """Gains that place a loop's poles, and what they give.

    Parameters
    ----------
    gains : Gains
        The experiment's gains with the placed loops' replaced.
    poles : dict of str to numpy.ndarray
        Per loop placed (``"force"``, ``"velocity"``), the requested poles (``z``-plane).
    stability : Stability
        The experiment's loops with these gains (:func:`hybrid.stability`).

    Examples
    --------
    >>> import hybrid
    >>> s = hybrid.suggest_gains(hybrid.paper_experiment(),
    ...                          bandwidth_hz=3.0, damping=1.0,
    ...                          integral_ratio=0.0)
    >>> s.gains.KIf, len(s.poles["force"])
    (0.0, 2)
    """

    gains: object
    poles: dict
    stability: Stability


@checked_keywords
def suggest_gains(exp, bandwidth_hz, damping: float = 0.7, integral_ratio: float = 0.25) -> GainSuggestion:
    """Gains whose sampled loops have the requested poles, on the experiment's own model.

    Parameters
    ----------
    exp : Experiment
        The experiment (its sensor, contact, sample time, delay, filter, arm).
    bandwidth_hz : float or mapping
        The natural frequency ``f_n`` [Hz] of the force loop's dominant pole pair, or a mapping
        ``{"force": f_n, "velocity": f_n}`` placing either or both loops (the velocity loop's pair on
        its first velocity axis).
    damping : float
        The pair's damping ratio ``zeta`` (> 0).
    integral_ratio : float
        The integral's real pole at ``integral_ratio * 2 pi f_n`` [rad/s] (> 0); 0: the force loop
        without its integral (``KIf = 0``), the velocity loop without its double integral (``KI2v = 0``).

    Returns
    -------
    GainSuggestion
        The gains, the poles requested, the loops' stability with them.

    Raises
    ------
    HybridError
        A request that cannot be met at this sample time: a bandwidth at or above the Nyquist
        frequency, gains that come out negative, or other poles as slow as the placed ones (the
        message says about the largest bandwidth met); a bad value.

    Examples
    --------
    >>> import hybrid
    >>> s = hybrid.suggest_gains(hybrid.paper_experiment(),
    ...                          bandwidth_hz=5.0, damping=0.8)
    >>> round(s.gains.KPf, 3), s.stability.stable
    (0.937, True)
    """
    check_experiment(exp, "suggest_gains")
    wanted = _wanted(bandwidth_hz)
    if not _number(damping) or damping <= 0:
        raise HybridError(f"damping = {shown(damping, 40)}; give the pole pair's damping ratio, a number > 0")
    if not _number(integral_ratio) or integral_ratio < 0:
        raise HybridError(f"integral_ratio = {shown(integral_ratio, 40)}; give the integral pole over the pair's "
                          "natural frequency, a number >= 0 (0: no integral action)")
    damping, integral_ratio = float(damping), float(integral_ratio)
    if integral_ratio > 0 and not exp.integral:
        raise HybridError("the experiment runs without integral action (integral=False); give integral_ratio=0, or "
                          "the experiment integral=True")
    T = exp.sample_time
    values = dict(vars(exp.gains))
    requested = {}
    for loop, f_n in wanted.items():
        if f_n >= 0.5 / T:
            raise HybridError(f"bandwidth_hz = {f_n:g} Hz for the {loop} loop is at or above the Nyquist frequency "
                              f"{0.5 / T:g} Hz of sample_time {T:g} s; give a lower bandwidth or a shorter sample_time")
        poles = _requested(f_n, damping, integral_ratio, T)
        try:
            values.update(_placed(exp, loop, poles, integral_ratio))
        except _NotMet as why:
            best = _largest_met(exp, loop, f_n, damping, integral_ratio)
            met = (f"the largest met is about {best:.3g} Hz): lower bandwidth_hz" if best else
                   f"none is met from {_lowest(f_n):.3g} Hz up to it): give another bandwidth_hz or damping")
            raise HybridError(f"a {loop} loop of {f_n:g} Hz and damping {damping:g} cannot be met at sample_time "
                              f"{T:g} s with this sensor and arm ({met}, or shorten sample_time\n  {why}") from None
        requested[loop] = poles
    gains = type(exp.gains)(**values)
    placed = replace(exp, gains=gains, allow_unstable=True)
    return GainSuggestion(gains, requested, stability(placed))


def _number(v) -> bool:
    """Whether ``v`` is a finite real number (NumPy's too; not a bool)."""
    return isinstance(v, Real) and not isinstance(v, (bool, np.bool_)) and math.isfinite(v)


def _wanted(bandwidth_hz) -> dict[str, float]:
    given = dict(bandwidth_hz) if isinstance(bandwidth_hz, Mapping) else {"force": bandwidth_hz}
    if not given or set(given) - set(LOOP_GAINS):
        raise HybridError(f"bandwidth_hz = {shown(bandwidth_hz, 60)}; give the force loop's in Hz, or a mapping "
                          "{'force': ..., 'velocity': ...}")
    for loop, f in given.items():
        if not _number(f) or f <= 0:
            raise HybridError(f"bandwidth_hz for the {loop} loop = {shown(f, 40)}; give a frequency in Hz, > 0")
    return {loop: float(f) for loop, f in given.items()}


def _requested(f_n: float, zeta: float, ratio: float, T: float) -> np.ndarray:
    """The poles ``z = exp(s T)`` of the pair (``f_n`` [Hz], ``zeta``) and the integral's real pole."""
    w = 2 * math.pi * f_n
    root = np.sqrt(complex(zeta * zeta - 1.0))
    s = [w * (-zeta + root), w * (-zeta - root)] + ([-ratio * w] if ratio > 0 else [])
    return np.exp(np.array(s, complex) * T)


class _NotMet(Exception):
    """Placed gains that do not meet the request (the reason)."""


def _largest_met(exp, loop: str, f_n: float, zeta: float, ratio: float) -> float | None:
    """About the largest natural frequency [Hz] below ``f_n`` whose poles can be placed (a log grid from
    :func:`_lowest`, then bisection past its last one met: low frequencies fail too, where the arm's own damping
    exceeds the pair's); None when none is met."""
    def met(f: float) -> bool:
        try:
            _placed(exp, loop, _requested(f, zeta, ratio, exp.sample_time), ratio)
            return True
        except (_NotMet, np.linalg.LinAlgError):
            return False

    grid = np.geomspace(_lowest(f_n), f_n, 60)[:-1]
    found = [f for f in grid if met(f)]
    if not found:
        return None
    lo = found[-1]
    hi = grid[list(grid).index(lo) + 1] if lo != grid[-1] else f_n
    for _ in range(20):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if met(mid) else (lo, mid)
    return lo


def _lowest(f_n: float) -> float:
    """Where :func:`_largest_met` starts looking [Hz]: 0.01 Hz, or a decade below a lower request."""
    return min(0.01, f_n / 10)


def _placed(exp, loop: str, poles: np.ndarray, ratio: float) -> dict[str, float]:
    """The loop's gains that make ``poles`` poles of its axis's sampled loop (alone)."""
    names = LOOP_GAINS[loop][:len(poles)]
    st, p = loop_numbers(replace(exp, allow_unstable=True))
    axis = next((i for i, f in enumerate(st.force) if f == (loop == "force")), None)
    if axis is None:
        raise HybridError(f"bandwidth_hz places the {loop} loop, and the experiment has no {loop} axis (axes = "
                          f"{exp.axes!r}); place the {'velocity' if loop == 'force' else 'force'} loop alone")
    sub, q = axis_alone(st, p, axis)
    sub = replace(sub, integrals=(len(names) - (loop == "force") - 1,))  # the integrators the placed gains use
    # the command's row for each gain alone, and the open loop (neither depends on the gains)
    rows = {}
    for name in names:
        m = closed_loop(sub, {**q, **{k: float(k == name) for k in LOOP_GAINS[loop]}})
        rows[name] = m["command"][0, :m["A_open"].shape[-1]]
    A_o, B = m["A_open"], m["B_open"][:, 0]
    N = A_o.shape[0]
    equations, rhs = [], []
    for z, times in _distinct(poles):  # one of each conjugate pair: its real and imaginary parts
        R = np.linalg.inv(z * np.eye(N) - A_o)
        x = R @ B
        for k in range(times):  # a repeated pole: the equation's derivatives in z vanish too
            coeff = np.array([rows[name] @ x for name in names])
            equations.append(coeff.real)
            rhs.append(1.0 if k == 0 else 0.0)
            if z.imag > 0:
                equations.append(coeff.imag)
                rhs.append(0.0)
            x = R @ x
    try:
        g = np.linalg.solve(np.array(equations), np.array(rhs))
    except np.linalg.LinAlgError:  # a requested pole the gains cannot reach (a pole of the open loop)
        raise _NotMet("the gains cannot move the loop's poles there (a pole of the loop without feedback)") from None
    gains = {name: float(v) for name, v in zip(names, g)}
    gains.update({k: 0.0 for k in LOOP_GAINS[loop][len(names):]})
    _check_met(gains, poles, sub, q)
    return gains


def _distinct(poles: np.ndarray) -> list[tuple[complex, int]]:
    """The poles in the upper half plane (one of each conjugate pair), each with its multiplicity
    (poles within 1e-9 of each other count as one, repeated)."""
    out: list[list] = []
    for z in poles[np.imag(poles) >= 0]:
        for entry in out:
            if abs(entry[0] - z) <= 1e-9:
                entry[1] += 1
                break
        else:
            out.append([complex(z), 1])
    return [(z, k) for z, k in out]


def _check_met(gains: dict, poles: np.ndarray, sub, q: dict) -> None:
    """Raise :class:`_NotMet` for gains that come out negative, or leave another pole as slow as the placed
    ones."""
    with np.errstate(all="ignore"):
        found = _poles(closed_loop(sub, {**q, **gains})["A"])
    placed = max(abs(poles))
    slower = [z for z in found if min(abs(z - poles)) > 1e-4 * max(1.0, placed) and abs(z) >= placed]
    negative = [k for k, v in gains.items() if v < 0]
    if negative or slower:
        why = (f"it needs {', '.join(f'{k} = {gains[k]:.3g}' for k in negative)} < 0" if negative else
               f"another pole of the loop, of modulus {max(abs(z) for z in slower):.3g}, is as slow as the placed "
               f"ones ({placed:.3g})")
        raise _NotMet(why)
