"""The warnings the library gives about a run's settings and outcome (a run beyond the robot's joint
limits, a redundant arm without a posture task, a part's surface fitted poorly), told at the user's line
(:mod:`hybrid.errors` holds its errors; its bytes shape the generated code's fingerprint, these do not)."""

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


class PartFitWarning(UserWarning):
    """A part's smooth surface (:class:`hybrid.MeshSurface`, :class:`hybrid.PointCloudSurface`) that follows the
    part poorly: the typical point of the part (the median) farther from it than a quarter of the grid's cell, or
    the typical normal more than 4 degrees off (:data:`hybrid.geometry.parts.POOR_DISTANCE_CELLS`,
    :data:`~hybrid.geometry.parts.POOR_ANGLE_DEG`). The message names the measured error and the fix (a finer
    spacing, less smoothing, a cloud's normals); the part's ``fit`` holds the numbers.

    Examples
    --------
    Make it an error where a part must be fitted well (here a box smoothed 500 times the default: its faces
    bulge and its normals turn):

    >>> import warnings
    >>> import hybrid, numpy as np
    >>> corners = [(x, y, z) for x in (-1, 1) for y in (-1, 1)
    ...            for z in (-1, 1)]
    >>> v = 0.05 * np.array(corners)
    >>> f = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5],
    ...      [0, 5, 1], [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4],
    ...      [1, 5, 7], [1, 7, 3]]
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("error", hybrid.PartFitWarning)
    ...     try:
    ...         hybrid.MeshSurface(v, f, spacing=0.01, band=0.03,
    ...                            smoothing=100.0)
    ...     except hybrid.PartFitWarning as poor:
    ...         print(str(poor).split(":")[0])
    MeshSurface follows the part poorly
    """


def warn(message: str, category: type[Warning]) -> None:
    """Warn ``message`` at the user's line: the first caller outside the package and ``dataclasses`` (by
    the module's name: a dataclass's generated ``__init__`` has no file of its own, ``replace`` calls it)."""
    frame, level = sys._getframe(1), 2  # the caller of this function is warnings.warn's level 2
    while frame is not None and frame.f_globals.get("__name__", "").partition(".")[0] in _INSIDE:
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)
