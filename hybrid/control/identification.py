"""A force/torque sensor's bias and tool from readings at rest in free space, and a tare at run time.

At rest and out of contact the sensor measures its bias and the tool's weight only (the model of
:mod:`hybrid.control.wrench_sensor`, step 1 with no contact):

    s w_i = b + (m g_i, c x m g_i),    g_i = R_s(q_i)^T g,    R_s = R_tip(q_i) R_m

``s`` the sensor's sign, ``b`` the bias (6), ``m`` the tool's mass and ``c`` its centre of mass in
sensor axes. With ``W = m |g|`` and ``h = W c`` it is linear in ``x = (b_f, b_m, W, h)`` (10 numbers,
all in N or N m) with a dimensionless regressor in ``u_i = g_i / |g|``:

    force rows   [I  0  u_i  0        ] x = s f_i
    moment rows  [0  I  0    -[u_i]_x ] x = s m_i

solved by least squares (:func:`numpy.linalg.lstsq`). The force rows fix ``b_f`` and ``W`` once two
gravity directions differ; the moment rows fix ``b_m`` and ``h`` once three differ (three points of a
sphere are never on one line). Poses that differ by a turn about the vertical hold gravity still in
sensor axes: they count as one orientation. Turning about one horizontal axis is enough; turning
about an axis near the vertical leaves the gravity directions in a small cone and the regressor
ill-conditioned (refused above :data:`MAX_CONDITION`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from hybrid.control.wrench_sensor import Tool, WrenchSensor, tool_wrench
from hybrid.errors import HybridError
from hybrid.models.robot import Robot
from hybrid.models.terms import arm_terms
from hybrid.validate import checked_keywords, shown

#: the largest condition number of the regressor (gravity scaled to unit length) accepted: about the
#: inverse of the spread of the gravity directions in radians (1 for directions all over the sphere)
MAX_CONDITION = 100.0
#: two gravity directions in sensor axes closer than this [rad] are one orientation
SAME_DIRECTION = 1e-6


@checked_keywords
@dataclass(frozen=True)
class ToolIdentification:
    """What :func:`identify_tool` found.

    Parameters
    ----------
    bias : tuple of float
        The sensor's bias [N, N m] (6, sensor axes, in the sign convention of ``s w``).
    tool : Tool
        The tool (mass [kg], centre of mass [m] in sensor axes).
    residual_force_N, residual_moment_Nm : float
        The RMS over the poses of the norm of the force and moment left unexplained by the fit (the
        readings' noise, or a model that does not fit).
    condition : float
        The condition number of the regressor (gravity scaled to unit length).

    Examples
    --------
    See :func:`identify_tool`, which makes one; :meth:`sensor` gives the sensor with what it found:

    >>> import hybrid
    >>> bias = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> found = hybrid.ToolIdentification(bias, hybrid.Tool(0.5), 0.0,
    ...                                   0.0, 1.0)
    >>> found.sensor(hybrid.WrenchSensor()).tool.mass
    0.5
    """

    bias: tuple[float, ...]
    tool: Tool
    residual_force_N: float
    residual_moment_Nm: float
    condition: float

    def sensor(self, sensor: WrenchSensor) -> WrenchSensor:
        """``sensor`` with the identified bias and tool.

        Parameters
        ----------
        sensor : WrenchSensor
            The sensor identified (its mount, sign and filter are kept).

        Returns
        -------
        WrenchSensor
            The sensor with this bias and tool.
        """
        _check_sensor(sensor)
        return dataclasses.replace(sensor, bias=self.bias, tool=self.tool)


def _check_sensor(sensor) -> None:
    if not isinstance(sensor, WrenchSensor):
        raise HybridError(f"sensor = {shown(sensor, 60)}; give a hybrid.WrenchSensor")


def _check_robot(robot, weighed: bool = True) -> np.ndarray:
    """``robot.gravity`` of a :class:`Robot` (not zero if the tool is ``weighed``)."""
    if not isinstance(robot, Robot):
        raise HybridError(f"robot = {shown(robot, 60)}; give a hybrid.Robot (e.g. hybrid.ur5())")
    g = np.array(robot.gravity)
    if not weighed:
        return g
    if not np.linalg.norm(g) > 0:
        raise HybridError(f"robot.gravity = {robot.gravity}; the tool is weighed against gravity: give the "
                          "robot its gravity vector (e.g. (0, 0, -9.81) m/s^2)")
    return g


def _array(name: str, value, shape: tuple, what: str) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise HybridError(f"{name} = {shown(value, 60)}; give {what}") from None
    if arr.shape != shape:
        raise HybridError(f"{name} has shape {arr.shape}; give {what}, shape {shape}")
    if not np.isfinite(arr).all():
        bad = np.argwhere(~np.isfinite(arr))[0]
        raise HybridError(f"{name}[{', '.join(map(str, bad))}] = {arr[tuple(bad)]}; give finite numbers")
    return arr


def _sensor_rotations(robot: Robot, sensor: WrenchSensor, q: np.ndarray) -> np.ndarray:
    """``R_s(q)`` for each row of ``q`` (N x 3 x 3)."""
    _, Rm = sensor.mount(robot)
    R_tip = np.asarray(arm_terms(robot, q, np.zeros_like(q))["rotation"]).reshape(len(q), 3, 3)
    return R_tip @ Rm


def _skew(u: np.ndarray) -> np.ndarray:
    """``[u]_x`` for each row of ``u`` (N x 3 x 3)."""
    S = np.zeros((len(u), 3, 3))
    S[:, 0, 1], S[:, 0, 2], S[:, 1, 2] = -u[:, 2], u[:, 1], -u[:, 0]
    return S - S.transpose(0, 2, 1)


def _distinct(u: np.ndarray) -> int:
    """How many of the unit vectors ``u`` differ (by more than :data:`SAME_DIRECTION`)."""
    kept: list[np.ndarray] = []
    for v in u:
        if all(np.linalg.norm(v - k) > SAME_DIRECTION for k in kept):
            kept.append(v)
            if len(kept) == 3:
                break
    return len(kept)


@checked_keywords
def identify_tool(robot: Robot, sensor: WrenchSensor, q, readings, *,
                  max_condition: float = MAX_CONDITION) -> ToolIdentification:
    """The bias and the tool of ``sensor`` from ``readings`` at rest in free space (module docstring).

    A mass that comes out below zero by more than three of its standard errors is refused (a reading of the
    wrong sign, or of a sensor in contact); within them the sensor carries no tool: the bias alone is
    fitted (the readings' mean) and the tool is ``Tool()``.

    Parameters
    ----------
    robot : Robot
        The arm carrying the sensor (its tip rotation and gravity are used).
    sensor : WrenchSensor
        The sensor: its mount and sign are used; its bias and tool are what is identified.
    q : array_like
        Joint positions of the N poses (N x n), N >= 3, the sensor held at 3 orientations to gravity
        or more.
    readings : array_like
        The raw readings at those poses (N x 6: force [N], then moment [N m], sensor axes, in the
        sensor's own sign convention).
    max_condition : float
        The largest condition number of the regressor accepted.

    Returns
    -------
    ToolIdentification
        The bias, the tool, the fit's residuals and its condition number.

    Raises
    ------
    HybridError
        Fewer than 3 poses or orientations to gravity, poses that do not excite the tool's centre of
        mass (above ``max_condition``), arrays of the wrong shape or not finite, a robot without
        gravity, or a mass below zero.

    Examples
    --------
    Readings of a 0.5 kg tool, its centre of mass 3 cm out, on a sensor of 1 N bias, at four wrist
    poses of the UR5:

    >>> import numpy as np
    >>> import hybrid
    >>> robot, sensor = hybrid.ur5(), hybrid.WrenchSensor()
    >>> q = np.array([[0.0, -1.57, 1.57, 0.0, 0.0, 0.0],
    ...               [0.0, -1.57, 1.57, 0.8, 0.0, 0.0],
    ...               [0.0, -1.57, 1.57, 0.0, 0.8, 0.0],
    ...               [0.0, -1.57, 1.57, 0.8, 0.8, 0.8]])
    >>> R = hybrid.arm_terms(robot, q, np.zeros_like(q))["rotation"]
    >>> # in sensor (tip) axes
    >>> weight = 0.5 * np.einsum("nji,j->ni", R, robot.gravity)
    >>> moment = np.cross([0.0, 0.0, 0.03], weight)
    >>> readings = np.hstack([weight, moment]) + [1.0, 0, 0, 0, 0, 0]
    >>> found = hybrid.identify_tool(robot, sensor, q, readings)
    >>> (round(found.tool.mass, 6), round(found.tool.com[2], 6),
    ...  round(found.bias[0], 6))
    (0.5, 0.03, 1.0)
    """
    _check_sensor(sensor)
    g = _check_robot(robot)
    try:
        N = len(q)
    except TypeError:
        N = -1
    if N < 3:
        raise HybridError(f"q holds {max(N, 0)} poses; give at least 3 (N x {robot.n} joint positions, the "
                          "sensor at rest at 3 orientations to gravity or more)")
    q = _array("q", q, (N, robot.n), f"{N} poses of {robot.n} joint positions")
    w = sensor.sign * _array("readings", readings, (N, 6), f"one reading per pose (force, then moment) for "
                                                           f"the {N} poses of q")
    if isinstance(max_condition, bool) or not (isinstance(max_condition, (int, float)) and max_condition >= 1):
        raise HybridError(f"max_condition = {shown(max_condition, 40)}; give a number >= 1")
    gn = float(np.linalg.norm(g))
    u = np.einsum("nji,j->ni", _sensor_rotations(robot, sensor, q), g) / gn  # R_s^T g / |g|
    k = _distinct(u)
    if k < 3:
        raise HybridError(f"q: the {N} poses hold the sensor at {k} orientation{'s' * (k > 1)} to gravity; give "
                          "at least 3 (turning about the vertical does not change gravity in sensor axes: "
                          "tilt the sensor)")
    A = np.zeros((N, 6, 10))
    A[:, :3, :3] = A[:, 3:, 3:6] = np.eye(3)
    A[:, :3, 6] = u
    A[:, 3:, 7:] = -_skew(u)
    A = A.reshape(6 * N, 10)
    condition = float(np.linalg.cond(A))
    if not condition <= max_condition:
        raise HybridError(f"q: the poses do not excite the tool's centre of mass (the regressor's condition number "
                          f"is {condition:.3g}, above max_condition = {max_condition:g}); spread the sensor's "
                          "orientations to gravity: tilt it by tens of degrees between poses")
    y = w.reshape(6 * N)
    x = np.linalg.lstsq(A, y, rcond=None)[0]
    W, h = x[6], x[7:]
    if W < 0:
        Af = A.reshape(N, 6, 10)[:, :3, [0, 1, 2, 6]].reshape(3 * N, 4)  # the force rows: b_f and W
        rf = Af @ x[[0, 1, 2, 6]] - w[:, :3].reshape(3 * N)
        s2 = rf @ rf / max(3 * N - 4, 1)
        se = float(np.sqrt(s2 * np.linalg.inv(Af.T @ Af)[3, 3]))
        if -W > 3 * se + 1e-9 * (1 + np.abs(w[:, :3]).max()):
            raise HybridError(f"readings: the tool's mass comes out {W / gn:.3g} kg, below zero; the readings or "
                              f"the sensor's sign ({sensor.sign:+d}) are likely wrong (the sign is +1 when the "
                              "reading is the wrench the tool exerts on the sensor)")
        x = np.concatenate([w.mean(axis=0), np.zeros(4)])  # no tool to within the noise: the bias alone
        W, h = 0.0, np.zeros(3)
    r = (A @ x - y).reshape(N, 6)
    tool = Tool(W / gn, tuple(h / W) if W > 0 else (0.0, 0.0, 0.0))
    return ToolIdentification(tuple(map(float, x[:6])), tool,
                              float(np.sqrt(np.mean(np.sum(r[:, :3] ** 2, axis=1)))),
                              float(np.sqrt(np.mean(np.sum(r[:, 3:] ** 2, axis=1)))), condition)


@checked_keywords
def tare(sensor: WrenchSensor, robot: Robot, q, reading) -> WrenchSensor:
    """``sensor`` with the bias that makes its compensated wrench zero at the joint positions ``q`` for
    the raw ``reading`` (the arm at rest, nothing in contact); the tool as it is.

    Parameters
    ----------
    sensor : WrenchSensor
        The sensor (its mount, sign and tool are used).
    robot : Robot
        The arm carrying it.
    q : array_like
        The joint positions of the pose (n).
    reading : array_like
        The raw reading at that pose (6: force [N], then moment [N m], sensor axes).

    Returns
    -------
    WrenchSensor
        The sensor with the new bias.

    Raises
    ------
    HybridError
        Arrays of the wrong shape or not finite, or not a sensor or a robot.

    Examples
    --------
    >>> import hybrid
    >>> reading = [1.0, 0.0, -2.0, 0.0, 0.0, 0.1]
    >>> tared = hybrid.tare(hybrid.WrenchSensor(), hybrid.ur5(),
    ...                     [0.0] * 6, reading)
    >>> tared.bias
    (1.0, 0.0, -2.0, 0.0, 0.0, 0.1)
    """
    _check_sensor(sensor)
    g = _check_robot(robot, weighed=False)
    q = _array("q", q, (robot.n,), f"the {robot.n} joint positions of the pose")
    reading = _array("reading", reading, (6,), "the raw reading at that pose: force, then moment")
    R_s = _sensor_rotations(robot, sensor, q[None])[0]
    bias = sensor.sign * reading - tool_wrench(sensor.tool, R_s, g)
    return dataclasses.replace(sensor, bias=tuple(map(float, bias)))
