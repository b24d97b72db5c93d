"""The warnings the library gives about a run's settings and outcome (a run beyond the robot's joint
limits, a redundant arm without a posture task), told at the user's line (:mod:`hybrid.errors` holds
its errors; its bytes shape the generated code's fingerprint, these do not)."""

from __future__ import annotations

import sys
import warnings

#: the modules a warning's line is not in: the package's, and those that build its dataclasses
_INSIDE = (__name__.partition(".")[0], "dataclasses")


class JointLimitWarning(UserWarning):
    """A run that left the robot's joint position, velocity or effort limits (the URDF's): the message names
    the worst joint, its limit, how far beyond it and when first (``SimulationResult.limit_violations``
    holds the numbers).

    Examples
    --------
    Make it an error where a run must stay within the limits:

    >>> import warnings
    >>> import hybrid
    >>> exp = hybrid.paper_experiment(duration=0.05)
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("error", hybrid.JointLimitWarning)
    ...     result = hybrid.simulate(exp)
    >>> result.limit_violations
    {}
    """


class RedundancyWarning(UserWarning):
    """A redundant arm (more joints than task axes) without a posture task: the joint motion the task
    leaves free is nobody's to hold, and it falls under gravity and winds up (give a ``hybrid.Posture``).

    Examples
    --------
    >>> import warnings
    >>> import hybrid
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     experiment = hybrid.panda_experiment(posture=None)
    >>> [w.category.__name__ for w in caught]
    ['RedundancyWarning']
    """


def warn(message: str, category: type[Warning]) -> None:
    """Warn ``message`` at the user's line: the first caller outside the package and ``dataclasses`` (by
    the module's name: a dataclass's generated ``__init__`` has no file of its own, ``replace`` calls it)."""
    frame, level = sys._getframe(1), 2  # the caller of this function is warnings.warn's level 2
    while frame is not None and frame.f_globals.get("__name__", "").partition(".")[0] in _INSIDE:
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)
