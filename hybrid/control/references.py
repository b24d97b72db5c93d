"""Reference signals the loops follow: a number is constant, a :class:`Step` jumps once."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.validate import _finite


@dataclass(frozen=True)
class Step:
    """A reference that jumps from ``before`` to ``after`` at time ``at`` [s]."""

    before: float
    after: float
    at: float

    def __post_init__(self):
        _finite("Step", before=self.before, after=self.after, at=self.at)

    def __call__(self, t: float) -> float:
        return self.before if t < self.at else self.after

    def sampled(self, t: np.ndarray) -> np.ndarray:
        """The reference at each time of ``t`` [s] (one array operation)."""
        return np.where(np.asarray(t) < self.at, np.float64(self.before), np.float64(self.after))

    def integral(self, t):
        """``int_0^t`` of the reference (arc length for a speed) [unit s]; ``t`` a time or an array."""
        if isinstance(t, np.ndarray):
            return self.before * np.minimum(t, self.at) + self.after * np.maximum(0.0, t - self.at)
        return self.before * min(t, self.at) + self.after * max(0.0, t - self.at)
