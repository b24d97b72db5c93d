"""Reference signals the loops follow: a number is constant, a :class:`Step` jumps once."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.validate import _finite, checked_keywords


@checked_keywords
@dataclass(frozen=True)
class Step:
    """A reference that jumps from ``before`` to ``after`` at time ``at``.

    Parameters
    ----------
    before : float
        The value before ``at`` (its unit the reference's: N, m/s, ...).
    after : float
        The value from ``at`` on.
    at : float
        The time of the jump [s].

    Raises
    ------
    HybridError
        A value that is not finite.

    Examples
    --------
    >>> import hybrid
    >>> force = hybrid.Step(before=10.0, after=20.0, at=0.4)
    >>> force(0.0), force(0.4)
    (10.0, 20.0)
    >>> force.integral(1.0)
    16.0
    """

    before: float
    after: float
    at: float

    def __post_init__(self):
        _finite("Step", before=self.before, after=self.after, at=self.at)

    def __call__(self, t: float) -> float:
        """The reference at ``t``.

        Parameters
        ----------
        t : float
            The time [s].

        Returns
        -------
        float
            ``before`` if ``t < at``, else ``after``.
        """
        return self.before if t < self.at else self.after

    def sampled(self, t: np.ndarray) -> np.ndarray:
        """The reference at each time of ``t`` (one array operation).

        Parameters
        ----------
        t : numpy.ndarray
            Times [s].

        Returns
        -------
        numpy.ndarray
            The reference at each, of the shape of ``t``.
        """
        return np.where(np.asarray(t) < self.at, np.float64(self.before), np.float64(self.after))

    def integral(self, t):
        """``int_0^t`` of the reference (arc length for a speed).

        Parameters
        ----------
        t : float or numpy.ndarray
            A time [s] or an array of them.

        Returns
        -------
        float or numpy.ndarray
            The integral [the reference's unit times s], of the shape of ``t``.
        """
        if isinstance(t, np.ndarray):
            return self.before * np.minimum(t, self.at) + self.after * np.maximum(0.0, t - self.at)
        return self.before * min(t, self.at) + self.after * max(0.0, t - self.at)
