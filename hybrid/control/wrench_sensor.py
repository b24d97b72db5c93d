"""A force/torque sensor as the controller sees it: its mount, its sign, the tool beyond it, its bias, a filter.

The controller is given the wrench ``F_c`` on the robot at the tip frame's origin, in base axes. A real
sensor reports ``w = (f, m)`` in its own axes, about its own origin, mounted between the flange and a
tool whose weight it also measures, with a bias. :class:`WrenchSensor` describes it, and the controller
turns each raw reading into ``F_c`` (conventions §12):

1. ``w_t = s w - b - w_g``: the sign ``s`` (+1: the reading is the wrench the tool side exerts on the
   sensor; -1: the one the sensor exerts on the tool), the bias ``b`` and the tool's weight
   ``w_g = (m g_s, c x m g_s)`` with ``g_s = R_s^T g`` (gravity in sensor axes, ``c`` the tool's centre
   of mass in sensor axes), all in sensor axes about the sensor origin: what the environment exerts on
   the tool;
2. ``F = (R_s f_t, R_s m_t + (p_s - p) x R_s f_t)``: in base axes, about the tip origin ``p`` (the
   sensor frame is ``p_s = p + R r``, ``R_s = R R_m`` from the tip frame ``(p, R)`` and the mount
   ``(r, R_m)``);
3. the low-pass filter (Butterworth of order 1 or 2 at ``cutoff`` [Hz], by the bilinear transform with
   the cutoff prewarped, so its gain is exactly -3 dB there), per component, started at the first
   sample's value.

The functions here are the NumPy statement of these steps (the generated step's oracle) and their
inverse (the reading a sensor would give for a wrench, used by the simulated sensor).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.urdf import rigid_offset
from hybrid.validate import checked_keywords, shown


def _vector(owner: str, name: str, value, size: int) -> tuple[float, ...]:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        arr = np.full(1, np.nan)
    if arr.shape != (size,) or not np.isfinite(arr).all():
        raise HybridError(f"{owner} {name} = {shown(value, 60)}; give {size} finite numbers")
    return tuple(float(v) for v in arr)


@checked_keywords
@dataclass(frozen=True)
class Tool:
    """What hangs beyond the sensor (its weight is part of every reading).

    Parameters
    ----------
    mass : float
        Its mass [kg], >= 0.
    com : tuple of float
        Its centre of mass [m], sensor axes.

    Raises
    ------
    HybridError
        A negative or non-finite mass, or a centre of mass not of three finite numbers.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Tool(mass=0.5, com=(0.0, 0.0, 0.03))
    Tool(mass=0.5, com=(0.0, 0.0, 0.03))
    """

    mass: float = 0.0
    com: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self):
        mass = self.mass
        if isinstance(mass, bool) or not isinstance(mass, (int, float, np.integer, np.floating)) \
                or not np.isfinite(mass) or mass < 0:
            raise HybridError(f"Tool mass = {shown(mass, 40)}; give the tool's mass in kg, a number >= 0")
        object.__setattr__(self, "mass", float(mass))
        object.__setattr__(self, "com", _vector("Tool", "com", self.com, 3))


def _rotation(value) -> np.ndarray:
    try:
        R = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        R = np.full(1, np.nan)
    if R.shape != (3, 3) or not np.isfinite(R).all() or not np.allclose(R.T @ R, np.eye(3), atol=1e-9) \
            or np.linalg.det(R) < 0:
        raise HybridError(f"WrenchSensor rotation = {shown(value, 80)}; give a 3 x 3 rotation matrix (orthonormal, "
                          "det +1): the sensor axes in tip axes")
    return R


@checked_keywords
@dataclass(frozen=True)
class WrenchSensor:
    """A force/torque sensor mounted beyond the arm's tip (module docstring).

    Parameters
    ----------
    frame : str or None
        A frame of the robot's URDF rigidly attached to the tip's link (the sensor's own frame), or
        None with ``position`` and ``rotation``.
    position : tuple of float
        The sensor origin in tip axes [m] (default: at the tip).
    rotation : tuple
        The sensor axes in tip axes (3 x 3; default: the tip's).
    sign : int
        +1 (default): the reading is the wrench the tool side exerts on the sensor; -1: the one the
        sensor exerts on the tool.
    tool : Tool
        The tool beyond the sensor (its weight is subtracted at the current orientation).
    bias : tuple of float
        The reading with nothing on the sensor [N, N m], sensor axes.
    cutoff : float or None
        The low-pass filter's cutoff [Hz], below the Nyquist frequency ``1 / (2 T)``; None: no filter.
    order : int
        1 or 2 (Butterworth).

    Raises
    ------
    HybridError
        A value out of its range: not a rotation, a sign other than +-1, a cutoff not positive, an
        order other than 1 or 2.

    Examples
    --------
    A sensor 5 cm beyond the tip, carrying a 0.5 kg tool, filtered at 20 Hz:

    >>> import hybrid
    >>> tool = hybrid.Tool(0.5, (0.0, 0.0, 0.03))
    >>> sensor = hybrid.WrenchSensor(position=(0.0, 0.0, 0.05),
    ...                              tool=tool, cutoff=20.0)
    >>> sensor.mount()[0].tolist()
    [0.0, 0.0, 0.05]
    >>> # 20 Hz is below the Nyquist frequency of 10 ms samples
    >>> sensor.check_sampling(0.01)
    """

    frame: str | None = None
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rotation: tuple = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    sign: int = 1
    tool: Tool = field(default_factory=Tool)
    bias: tuple[float, ...] = (0.0,) * 6
    cutoff: float | None = None
    order: int = 1

    def __post_init__(self):
        if self.frame is not None and not isinstance(self.frame, str):
            raise HybridError(f"WrenchSensor frame = {shown(self.frame, 40)}; give a frame name of the URDF, or None")
        object.__setattr__(self, "position", _vector("WrenchSensor", "position", self.position, 3))
        object.__setattr__(self, "rotation", tuple(tuple(r) for r in _rotation(self.rotation)))
        if self.sign not in (1, -1) or isinstance(self.sign, bool):
            raise HybridError(f"WrenchSensor sign = {shown(self.sign)}; give +1 (the tool side's wrench on the sensor) "
                              "or -1 (the sensor's on the tool)")
        if not isinstance(self.tool, Tool):
            raise HybridError(f"WrenchSensor tool = {shown(self.tool, 60)}; give a hybrid.Tool(mass, com)")
        object.__setattr__(self, "bias", _vector("WrenchSensor", "bias", self.bias, 6))
        if self.cutoff is not None:
            c = self.cutoff
            if isinstance(c, bool) or not isinstance(c, (int, float, np.integer, np.floating)) \
                    or not np.isfinite(c) or c <= 0:
                raise HybridError(f"WrenchSensor cutoff = {shown(c, 40)}; give the filter's cutoff in Hz (> 0), "
                                  "or None")
            object.__setattr__(self, "cutoff", float(c))
        if self.order not in (1, 2) or isinstance(self.order, bool):
            raise HybridError(f"WrenchSensor order = {shown(self.order)}; give 1 or 2 (the Butterworth filter's order)")

    def check_sampling(self, sample_time: float) -> None:
        """Refuse a cutoff at or above the Nyquist frequency of ``sample_time``.

        Parameters
        ----------
        sample_time : float
            The controller's sample time [s].

        Raises
        ------
        HybridError
            The cutoff is at or above ``1 / (2 sample_time)``.
        """
        if self.cutoff is not None and self.cutoff >= 0.5 / sample_time:
            raise HybridError(f"WrenchSensor cutoff = {self.cutoff:g} Hz is at or above the Nyquist frequency "
                              f"{0.5 / sample_time:g} Hz of the sample time {sample_time:g} s; give a cutoff below it")

    def mount(self, robot=None) -> tuple[np.ndarray, np.ndarray]:
        """The sensor frame in tip axes.

        Parameters
        ----------
        robot : Robot or None
            The robot whose URDF names ``frame`` (needed only with a ``frame``).

        Returns
        -------
        r : numpy.ndarray
            The sensor origin [m], tip axes.
        R_m : numpy.ndarray
            The sensor axes in tip axes (3 x 3).

        Raises
        ------
        HybridError
            A ``frame`` with a robot not read from a URDF.
        """
        if self.frame is None:
            return np.array(self.position), np.array(self.rotation)
        source = getattr(robot, "source", None)
        if source is None:
            raise HybridError(f"WrenchSensor frame = {shown(self.frame)} names a URDF frame, but the robot "
                              f"{getattr(robot, 'name', robot)!r} was not read from a URDF; give position and "
                              "rotation instead")
        path, tip, locked = source
        r, R = _mounted(path, tip, self.frame, tuple(locked))
        return r.copy(), R.copy()

    def as_array(self, robot, sample_time: float) -> np.ndarray:
        """The generated step's ``sensor`` array.

        Parameters
        ----------
        robot : Robot or None
            The robot whose URDF names ``frame``.
        sample_time : float
            The controller's sample time [s] (the cutoff is checked against it).

        Returns
        -------
        numpy.ndarray
            The array, laid out as :data:`hybrid.spec.controller_step.SENSOR`.
        """
        self.check_sampling(sample_time)
        r, Rm = self.mount(robot)
        return np.concatenate([r, Rm.ravel(), [float(self.sign), self.tool.mass], self.tool.com, self.bias,
                               [0.0 if self.cutoff is None else self.cutoff, float(self.order)]])


@lru_cache(maxsize=64)
def _mounted(path: str, tip: str, frame: str, locked: tuple) -> tuple[np.ndarray, np.ndarray]:
    """:func:`rigid_offset`, read once per file, tip, frame and locked joints (a sensor's chain runs at
    every sample)."""
    return rigid_offset(path, tip, frame, dict(locked))


def tool_wrench(tool: Tool, R_s: np.ndarray, gravity) -> np.ndarray:
    """The tool's weight as a wrench in sensor axes about the sensor origin."""
    f = tool.mass * (R_s.T @ np.asarray(gravity, float))
    return np.concatenate([f, np.cross(tool.com, f)])


def contact_wrench(sensor: WrenchSensor, reading, p, R, gravity, robot=None) -> np.ndarray:
    """Steps 1-2 (module docstring): ``F_c`` at the tip ``(p, R)`` [m, base axes] from a raw ``reading``."""
    r, Rm = sensor.mount(robot)
    R_s = np.asarray(R) @ Rm
    w = sensor.sign * np.asarray(reading, float) - np.array(sensor.bias) - tool_wrench(sensor.tool, R_s, gravity)
    f = R_s @ w[:3]
    return np.concatenate([f, R_s @ w[3:] + np.cross(np.asarray(R) @ r, f)])


def reading_of(sensor: WrenchSensor, F, p, R, gravity, robot=None) -> np.ndarray:
    """The inverse of :func:`contact_wrench`: the raw reading for the wrench ``F`` on the robot at the tip."""
    r, Rm = sensor.mount(robot)
    R_s = np.asarray(R) @ Rm
    F = np.asarray(F, float)
    m_s = F[3:] - np.cross(np.asarray(R) @ r, F[:3])
    w = np.concatenate([R_s.T @ F[:3], R_s.T @ m_s]) + np.array(sensor.bias) + tool_wrench(sensor.tool, R_s, gravity)
    return sensor.sign * w


def filter_coefficients(cutoff: float | None, order: int, sample_time: float) -> np.ndarray:
    """``(b0, b1, b2, a1, a2)`` of the discrete Butterworth low-pass (bilinear, cutoff prewarped):
    ``y_k = b0 x_k + b1 x_k-1 + b2 x_k-2 - a1 y_k-1 - a2 y_k-2``; the identity without a cutoff."""
    if cutoff is None or cutoff <= 0:
        return np.array([1.0, 0.0, 0.0, 0.0, 0.0])
    K = np.tan(np.pi * cutoff * sample_time)
    if order == 1:
        n = 1 / (1 + K)
        return np.array([K * n, K * n, 0.0, (K - 1) * n, 0.0])
    n = 1 / (1 + np.sqrt(2) * K + K * K)
    return np.array([K * K * n, 2 * K * K * n, K * K * n, 2 * (K * K - 1) * n, (1 - np.sqrt(2) * K + K * K) * n])
