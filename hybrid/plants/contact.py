"""The plant's elastic force sensor and its penalty contact with friction, as validated parameters."""

from __future__ import annotations

from dataclasses import dataclass

from hybrid.errors import HybridError
from hybrid.validate import _finite, field_values


@dataclass(frozen=True)
class Sensor:
    """2-D elastic force sensor at the arm tip: tip mass on an isotropic spring-damper."""

    mass: float = 0.025       # m_s [kg]
    stiffness: float = 1000.0  # K_s [N/m]
    damping: float = 7.0      # D_s [N s/m]

    def __post_init__(self):
        _finite("Sensor", **field_values(self))
        if self.mass <= 0 or self.stiffness <= 0 or self.damping < 0:
            raise HybridError(f"Sensor needs mass > 0, stiffness > 0, damping >= 0; got {self}")


@dataclass(frozen=True)
class Contact:
    """Rigid surface as a unilateral penalty ``N = max(0, k_e delta + d_e delta')``, Coulomb friction."""

    stiffness: float = 1e5        # k_e [N/m]
    damping: float = 50.0         # d_e [N s/m]
    friction: float = 0.2         # gamma
    friction_smoothing: float = 1e-3  # v_eps of tanh(v_t / v_eps) [m/s]

    def __post_init__(self):
        _finite("Contact", **field_values(self))
        if self.stiffness <= 0 or self.damping < 0 or self.friction < 0 or self.friction_smoothing <= 0:
            raise HybridError("Contact needs stiffness > 0, damping >= 0, friction >= 0, "
                              f"friction_smoothing > 0; got {self}")
