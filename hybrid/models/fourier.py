"""A finite Fourier series per joint, in Swevers' form: the periodic excitation trajectories are made of it.

Joint ``i`` moves as ``q_i(t) = q0_i + sum_k a_ik / (w k) sin(w k t) - b_ik / (w k) cos(w k t)``,
``k = 1 .. K``, ``w = 2 pi / period`` (Swevers, Ganseman, Tukel, De Schutter and Van Brussel, "Optimal robot
excitation and identification", IEEE Trans. Robotics and Automation 13(5), 1997), so that
``q'_i = sum_k a_ik cos(w k t) + b_ik sin(w k t)``: the coefficients are the velocity's. Each of ``q``,
``q'``, ``q''`` is linear in the coefficients: at given times it is a matrix (the basis) times them, the
columns ``a_1 .. a_K`` then ``b_1 .. b_K``. Each is bounded for all times by its harmonics' amplitudes
``r_k = |(a_k, b_k)|`` (:func:`amplitude_bounds`), which also bound how far a value moves between two
samples of a grid (:func:`grid_bound`).
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import null_space


def fundamental(period: float) -> float:
    """``w = 2 pi / period`` [rad/s]."""
    return 2.0 * np.pi / period


def basis(period: float, harmonics: int, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(Pq, Pv, Pa)``, each ``(N, 2 K)``: ``q - q0 = Pq c``, ``q' = Pv c``, ``q'' = Pa c`` at the times ``t``
    (``(N,)``, taken modulo the period) for one joint's coefficients ``c = (a_1 .. a_K, b_1 .. b_K)``."""
    wk = fundamental(period) * np.arange(1, harmonics + 1, dtype=float)
    phase = np.mod(np.asarray(t, dtype=float), period)[:, None] * wk
    s, c = np.sin(phase), np.cos(phase)
    return np.hstack([s / wk, -c / wk]), np.hstack([c, s]), np.hstack([-wk * s, wk * c])


def rest_basis(period: float, harmonics: int) -> np.ndarray:
    """An orthonormal basis ``(2 K, 2 K - 3)`` of the coefficients of a motion that starts (and, periodic,
    ends) at ``q0`` at rest: ``q(0) = q0``, ``q'(0) = 0``, ``q''(0) = 0``, three linear conditions."""
    at_zero = np.vstack(basis(period, harmonics, np.zeros(1)))
    return null_space(at_zero)


def evaluate(period: float, center, a, b, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``q, q', q''`` ``(N, n)`` of the series with offsets ``center`` ``(n,)`` and coefficients ``a``, ``b``
    ``(n, K)`` at the times ``t`` ``(N,)``."""
    Pq, Pv, Pa = basis(period, a.shape[1], t)
    C = np.hstack([a, b]).T  # (2 K, n)
    return center + Pq @ C, Pv @ C, Pa @ C


def amplitude_bounds(period: float, a, b) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Per joint, bounds for all times on ``|q - q0|``, ``|q'|``, ``|q''|`` and ``|q'''|``:
    ``sum_k r_k (w k)^(d - 1)`` for the ``d``-th derivative, ``r_k`` the ``k``-th harmonic's amplitude."""
    wk = fundamental(period) * np.arange(1, a.shape[1] + 1, dtype=float)
    r = np.hypot(a, b)
    return tuple((r * wk ** (d - 1)).sum(axis=1) for d in range(4))


def grid_bound(on_grid: np.ndarray, slope: np.ndarray, spacing: float) -> np.ndarray:
    """A bound for all times on a periodic signal from its largest values on a grid of ``spacing``
    (``on_grid``: per column) and a bound on its rate (``slope``): every time is within half a spacing of
    a grid point, where the signal is at most ``slope * spacing / 2`` from its value there."""
    return on_grid + 0.5 * spacing * slope
