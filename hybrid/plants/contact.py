"""The plant's elastic force sensor (and the signal it gives) and its penalty contact with friction, as
validated parameters."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import _finite, checked_keywords, field_values, shown


@checked_keywords
@dataclass(frozen=True)
class Sensor:
    """The plant's elastic force sensor at the arm tip: a tip mass on an isotropic spring-damper
    (conventions §5, §10), and the signal it gives the controller (conventions §14).

    With every signal option off (the defaults) the controller gets the spring-damper's force itself,
    bit for bit.

    Parameters
    ----------
    mass, stiffness, damping : float
        The tip mass ``m_s`` [kg], the spring ``K_s`` [N/m] and damper ``D_s`` [N s/m] between it and
        the arm tip; the sensor measures the spring-damper's force.
    force_noise, moment_noise : float
        The standard deviations [N] and [N m] of white Gaussian noise added to each force and each
        moment component of every reading (one draw per control sample); 0: none.
    bias : tuple of float
        A constant offset of the reading ``(f_x, f_y, f_z, m_x, m_y, m_z)`` [N, N m], base axes (with an
        experiment's ``wrench_sensor`` the true sensor's bias is that sensor's own, in its axes, and
        this stays 0).
    bandwidth_hz : float or None
        The corner frequency [Hz] of a first-order lag on the reading, discretised at the sample time
        (below its Nyquist frequency); None: no lag.
    delay_samples : int
        The reading reaches the controller this many control samples late (a whole number >= 0).
    seed : int
        The noise's seed: the same seed, the same noise, run after run.
    dropout_at, dropout_duration : float
        [s] the reading the controller gets is NaN from ``dropout_at`` for ``dropout_duration`` (a
        dropped sensor, a cut cable), samples the controller refuses: its fault reaction acts
        (:mod:`hybrid.control.fault`), and the run applies the torque each faulted sample's error
        carries, as a real arm's loop does. ``dropout_duration`` 0 (the default): none.

    Raises
    ------
    HybridError
        A value out of its range (a mass or stiffness not positive, a negative noise, a delay not a
        whole number).

    Examples
    --------
    >>> import hybrid
    >>> noisy = hybrid.Sensor(force_noise=0.2, delay_samples=1)
    >>> noisy.ideal, hybrid.Sensor().ideal
    (False, True)
    >>> experiment = hybrid.paper_experiment(sensor=noisy)
    """

    mass: float = 0.025       # m_s [kg]
    stiffness: float = 1000.0  # K_s [N/m]
    damping: float = 7.0      # D_s [N s/m]
    force_noise: float = 0.0                  # standard deviation [N]
    moment_noise: float = 0.0                 # standard deviation [N m]
    bias: tuple[float, ...] = (0.0,) * 6      # [N, N m]
    bandwidth_hz: float | None = None         # first-order lag [Hz]
    delay_samples: int = 0                    # whole control samples
    seed: int = 0
    dropout_at: float = 0.0
    dropout_duration: float = 0.0

    def __post_init__(self):
        _finite("Sensor", mass=self.mass, stiffness=self.stiffness, damping=self.damping)
        if self.mass <= 0 or self.stiffness <= 0 or self.damping < 0:
            raise HybridError(f"Sensor needs mass > 0, stiffness > 0, damping >= 0; got mass = {self.mass}, "
                              f"stiffness = {self.stiffness}, damping = {self.damping}")
        for name, unit, example in (("force_noise", "N", 0.2), ("moment_noise", "N m", 0.01)):
            v = getattr(self, name)
            _finite("Sensor", **{name: v})
            if v < 0:
                raise HybridError(f"Sensor {name} = {shown(v)}; give a standard deviation >= 0 [{unit}] (0: no noise), "
                                  f"e.g. {name}={example}")
            object.__setattr__(self, name, float(v))
        object.__setattr__(self, "bias", _numbers("bias", self.bias, 6, "(f_x, f_y, f_z, m_x, m_y, m_z) [N, N m]"))
        if self.bandwidth_hz is not None:
            b = self.bandwidth_hz
            if not _real(b) or not math.isfinite(b) or b <= 0:
                raise HybridError(f"Sensor bandwidth_hz = {shown(b, 40)}; give the lag's corner frequency in Hz (> 0), "
                                  "or None for no lag")
            object.__setattr__(self, "bandwidth_hz", float(b))
        d = self.delay_samples
        if not _real(d) or not math.isfinite(d) or d != int(d) or d < 0:
            raise HybridError(f"Sensor delay_samples = {shown(d, 40)}; give a whole number of control samples >= 0 "
                              "(e.g. delay_samples=2: 20 ms at a 10 ms sample time)")
        object.__setattr__(self, "delay_samples", int(d))
        s = self.seed
        if not _real(s) or not math.isfinite(s) or s != int(s) or s < 0:
            raise HybridError(f"Sensor seed = {shown(s, 40)}; give a whole number >= 0")
        object.__setattr__(self, "seed", int(s))
        for name in ("dropout_at", "dropout_duration"):
            v = getattr(self, name)
            if not _real(v) or not math.isfinite(v) or v < 0:
                raise HybridError(f"Sensor {name} = {shown(v, 40)}; give a time >= 0 [s]")
            object.__setattr__(self, name, float(v))

    @property
    def clean(self) -> bool:
        """True when the reading, where it is not lost (a dropout), is the spring-damper's force itself:
        no noise, bias, lag or delay."""
        return (self.force_noise == 0 and self.moment_noise == 0 and not any(self.bias) and self.bandwidth_hz is None
                and self.delay_samples == 0)

    @property
    def ideal(self) -> bool:
        """True when the reading is the spring-damper's force itself: no noise, bias, lag, delay or dropout."""
        return self.clean and not self.drops_out

    def dropped(self, t: float) -> bool:
        """Whether the reading at ``t`` is lost (``dropout_at``, ``dropout_duration``).

        Parameters
        ----------
        t : float
            The time [s].

        Returns
        -------
        bool
            True within the dropout.
        """
        return self.dropout_at <= t < self.dropout_at + self.dropout_duration

    @property
    def drops_out(self) -> bool:
        """Whether the reading is lost some time in a run."""
        return self.dropout_duration > 0

    def check_sampling(self, sample_time: float) -> None:
        """Refuse a lag whose corner frequency is at or above the Nyquist frequency of ``sample_time``.

        Parameters
        ----------
        sample_time : float
            The controller's sample time [s].

        Raises
        ------
        HybridError
            ``bandwidth_hz`` is at or above ``1 / (2 sample_time)``.
        """
        if self.bandwidth_hz is not None and self.bandwidth_hz >= 0.5 / sample_time:
            raise HybridError(f"Sensor bandwidth_hz = {self.bandwidth_hz:g} Hz is at or above the Nyquist frequency "
                              f"{0.5 / sample_time:g} Hz of the sample time {sample_time:g} s; give a bandwidth "
                              "below it, or None for no lag")


def lag_pole(bandwidth_hz, sample_time):
    """The pole ``a = exp(-2 pi f_b T)`` of the sensor's first-order lag discretised at the sample time
    (conventions §14); 0 (no lag) for a ``bandwidth_hz`` of None. Arrays give arrays."""
    if bandwidth_hz is None:
        return 0.0
    return np.exp(-2 * np.pi * np.asarray(bandwidth_hz, float) * np.asarray(sample_time, float))


def fastest_mode(sensor: Sensor, contact: Contact, sensor_stiffness: float | None = None,
                 contact_stiffness: float | None = None) -> float:
    """The plant's fastest mode [rad/s]: the sensor's tip mass on the contact's and the sensor's springs
    (their stiffnesses, or the ones given), or on their dampers, whichever is faster. RK4 resolves it at
    an integration step of at most its inverse."""
    k = (contact.stiffness if contact_stiffness is None else contact_stiffness) \
        + (sensor.stiffness if sensor_stiffness is None else sensor_stiffness)
    return max(math.sqrt(k / sensor.mass), (contact.damping + sensor.damping) / sensor.mass)


def _real(v) -> bool:
    return isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool)


def _numbers(name: str, value, size: int, what: str) -> tuple[float, ...]:
    """``value`` as ``size`` finite numbers (a list read from a file is a tuple again)."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        arr = np.full(1, np.nan)
    flags = isinstance(value, (list, tuple)) and any(isinstance(v, (bool, np.bool_)) for v in value)
    if arr.shape != (size,) or not np.isfinite(arr).all() or flags:
        raise HybridError(f"Sensor {name} = {shown(value, 60)}; give {size} finite numbers: {what}")
    return tuple(float(v) + 0.0 for v in arr)


@checked_keywords
@dataclass(frozen=True)
class Contact:
    """Rigid surface as a unilateral penalty ``N = max(0, k_e delta + d_e delta')``, Coulomb friction.

    Parameters
    ----------
    stiffness : float
        ``k_e`` [N/m], > 0.
    damping : float
        ``d_e`` [N s/m], >= 0.
    friction : float
        The Coulomb coefficient ``gamma``, >= 0.
    friction_smoothing : float
        ``v_eps`` of ``tanh(v_t / v_eps)`` [m/s], > 0.

    Raises
    ------
    HybridError
        A value out of its range, or not finite.

    Examples
    --------
    >>> import hybrid
    >>> slippery = hybrid.Contact(friction=0.05)
    >>> slippery.stiffness, slippery.friction
    (100000.0, 0.05)
    >>> experiment = hybrid.paper_experiment(contact=slippery)
    """

    stiffness: float = 1e5        # k_e [N/m]
    damping: float = 50.0         # d_e [N s/m]
    friction: float = 0.2         # gamma
    friction_smoothing: float = 1e-3  # v_eps of tanh(v_t / v_eps) [m/s]

    def __post_init__(self):
        _finite("Contact", **field_values(self))
        if self.stiffness <= 0 or self.damping < 0 or self.friction < 0 or self.friction_smoothing <= 0:
            raise HybridError("Contact needs stiffness > 0, damping >= 0, friction >= 0, "
                              f"friction_smoothing > 0; got {self}")
