"""What the :class:`hybrid.Controller` measures, and the measured values it is given, read and checked."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError, NonFiniteError
from hybrid.validate import checked_keywords, shown


@checked_keywords
@dataclass(frozen=True)
class Measurement:
    """What the controller measures, at the arm tip: position ``p`` [m] and twist ``v = (p', w)``
    [m/s, rad/s] in base axes; on all six task axes ``t1, t2, n`` (then rotations about them) the
    task velocity ``R v`` and the task wrench ``R F_c`` [N, N m]. With a sensor, the stages of its
    reading: ``reading`` (as given), ``compensated`` (less the bias and the tool's weight, sensor
    axes) and ``contact_wrench`` (``F_c``: base axes, at the tip, before the filter, which keeps a
    state: ``last["contact_wrench"]`` is the filtered one a sample used); without, all three are the
    wrench given.

    Parameters
    ----------
    p : numpy.ndarray
        The tip's position [m], base axes.
    v : numpy.ndarray
        Its twist ``(p', w)`` [m/s, rad/s], base axes.
    task_velocity : numpy.ndarray
        ``R v`` on the six task axes.
    task_wrench : numpy.ndarray
        ``R F_c`` on the six task axes [N, N m].
    reading : numpy.ndarray
        The sensor's reading as given.
    compensated : numpy.ndarray
        The reading less the bias and the tool's weight, sensor axes.
    contact_wrench : numpy.ndarray
        ``F_c``: base axes, at the tip, before the filter.

    Examples
    --------
    ``Controller.measure(q, qdot, Fc)`` gives one; its fields are:

    >>> import dataclasses
    >>> import hybrid
    >>> fields = dataclasses.fields(hybrid.Measurement)
    >>> [f.name for f in fields]  # doctest: +NORMALIZE_WHITESPACE
    ['p', 'v', 'task_velocity', 'task_wrench', 'reading',
     'compensated', 'contact_wrench']
    """

    p: np.ndarray
    v: np.ndarray
    task_velocity: np.ndarray
    task_wrench: np.ndarray
    reading: np.ndarray
    compensated: np.ndarray
    contact_wrench: np.ndarray


def wrench_of(Fc, force_size: int) -> np.ndarray:
    """A measured force without moments (``force_size`` entries: 2 in the planar arm's plane, 3 in
    space) or a wrench (6), base axes, as the 6-vector ``(f, m)``."""
    try:
        arr = np.asarray(Fc, dtype=float)
    except OverflowError:  # an integer beyond any double
        raise NonFiniteError(f"Fc = {shown(Fc, 60)} is not finite; give the measured force or wrench") from None
    except (TypeError, ValueError):
        arr = None
    if arr is None or arr.shape not in ((force_size,), (6,)):
        raise HybridError(f"Fc = {shown(Fc, 60)}; give the measured force on the robot ({force_size} numbers, base "
                          "axes) or the wrench (force, moment: 6 numbers)")
    return np.concatenate([arr, np.zeros(6 - arr.size)])


def padded_vector(name: str, v, size: int) -> np.ndarray:
    """``v`` as ``size`` finite numbers, padded to 3 (a planar point lies at z = 0)."""
    try:
        arr = np.asarray(v, dtype=float)
    except (TypeError, ValueError, OverflowError):
        arr = np.full(1, np.nan)
    if arr.shape != (size,) or not np.isfinite(arr).all():
        raise HybridError(f"the desired {name} {shown(v, 60)} must be {size} finite numbers [m, m/s or rad]")
    return np.concatenate([arr, np.zeros(3 - size)])
