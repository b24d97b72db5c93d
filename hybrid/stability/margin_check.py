"""Whether many candidate gains keep a stability margin on a set of settings, in a few batched evaluations.

A loop keeps a gain margin of ``m`` dB when it stays stable with its gain raised or lowered by any factor up
to ``k_m = 10^(m/20)``; :func:`hybrid.stability` finds the factors at which it stops (its
:func:`~hybrid.stability.analysis.gain_margin`, stepping by 1.25 then narrowing, each way). Here the same
loops, each task axis alone, are judged at the steps that search takes below ``k_m`` and at ``k_m`` itself
(and at their inverses), and with
their reading late by each whole sample up to the delay margin asked; the whole closed loop at the gains
themselves. The largest spectral radius of all those is the *margin radius*: below 1, the margins hold.
Every candidate on every setting of one model structure is one batch (:mod:`hybrid.stability.model`'s
arrays take leading batch axes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from hybrid.errors import HybridError
from hybrid.stability.analysis import MOST_DELAY, MOST_GAIN, axis_alone, loop_radius
from hybrid.stability.experiment_loops import loop_numbers
from hybrid.stability.model import Structure

#: the gain factor's step of :func:`~hybrid.stability.analysis.gain_margin`'s search
STEP = 1.25


@dataclass(frozen=True)
class MarginCheck:
    """The loops of a set of settings (one experiment each), ready to judge candidate gains on them.

    Parameters
    ----------
    groups : tuple
        ``(structure, numbers, members)``: the settings that share a model structure, their numbers
        stacked on a leading axis, and their places in the set.
    size : int
        How many settings.
    min_gain_margin_db : float
        The gain margin every loop keeps [dB].
    min_delay_margin_samples : int
        The samples by which every loop's reading may be late, stable still.
    """

    groups: tuple
    size: int
    min_gain_margin_db: float
    min_delay_margin_samples: int

    @classmethod
    def of(cls, experiments, min_gain_margin_db: float, min_delay_margin_samples: int) -> MarginCheck:
        """The check of ``experiments`` (their loops taken at their starts, :func:`hybrid.stability`'s
        model); the gains judged later replace theirs. Each experiment's gains must make the same loops
        as the candidates' (an integral's gain 0 or not)."""
        if not 0 <= min_gain_margin_db <= 20 * math.log10(MOST_GAIN):
            raise HybridError(f"min_gain_margin_db = {min_gain_margin_db:g}; give a gain margin in [0, "
                              f"{20 * math.log10(MOST_GAIN):g}] dB")
        if not 0 <= min_delay_margin_samples <= MOST_DELAY:
            raise HybridError(f"min_delay_margin_samples = {min_delay_margin_samples}; give a whole number of samples "
                              f"in [0, {MOST_DELAY}]")
        by: dict[Structure, list] = {}
        for i, exp in enumerate(experiments):
            st, p = loop_numbers(exp)
            by.setdefault(st, []).append((i, p))
        groups = []
        for st, entries in by.items():
            keys = entries[0][1].keys()
            stacked = {k: np.stack([np.asarray(p[k], float) for _, p in entries]) for k in keys}
            groups.append((st, stacked, np.array([i for i, _ in entries])))
        return cls(tuple(groups), len(experiments), float(min_gain_margin_db), int(min_delay_margin_samples))

    @property
    def factors(self) -> np.ndarray:
        """The gain factors each loop is judged at: 1, the search's steps below ``k_m``, ``k_m``, and the
        inverse of each (the margin holds both ways: a loop with integrals needs a gain high enough too)."""
        top = 10 ** (self.min_gain_margin_db / 20)
        steps = [1.0]
        while steps[-1] * STEP < top * (1 - 1e-12):
            steps.append(steps[-1] * STEP)
        up = np.array(steps + ([top] if top > 1.0 else []))
        return np.concatenate([up, 1.0 / up[1:]])

    def radius(self, gains: dict[str, np.ndarray]) -> np.ndarray:
        """The margin radius (module docstring) of each candidate on each setting.

        Parameters
        ----------
        gains : dict of str to numpy.ndarray
            The candidates' gains by name (:class:`~hybrid.Gains`' fields), each of length ``n``; the
            others are each setting's own.

        Returns
        -------
        numpy.ndarray
            ``n x size``: below 1 where the candidate keeps the margins on the setting (``inf`` where a
            loop overflows).
        """
        n = len(next(iter(gains.values())))
        out = np.empty((n, self.size))
        for st, p, members in self.groups:
            out[:, members] = self._group(st, p, gains, n).T
        return out

    def _group(self, st: Structure, p: dict, gains: dict, n: int) -> np.ndarray:
        """``len(members) x n`` margin radii of one structure's settings."""
        m = len(next(iter(p.values())))
        q = {k: np.broadcast_to(v[:, None], (m, n) + v.shape[1:]).copy() for k, v in p.items()}
        for name, values in gains.items():
            q[name] = np.broadcast_to(np.asarray(values, float)[None, :], (m, n)).copy()
        worst = loop_radius(st, q)
        for i in range(st.n):
            sub, qi = axis_alone(st, q, i)
            for k in self.factors:
                worst = np.maximum(worst, loop_radius(sub, dict(qi, gain=qi["gain"] * k)))
            for extra in range(1, self.min_delay_margin_samples + 1):
                worst = np.maximum(worst, loop_radius(replace(sub, delay=sub.delay + extra), qi))
        return worst

