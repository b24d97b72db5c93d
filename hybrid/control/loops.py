"""The task-frame loops' gains (conventions §4).

Whether the loops they make are stable as sampled, with the sensor, the contact and the arm, is
:mod:`hybrid.stability`'s question.
"""

from __future__ import annotations

from dataclasses import dataclass

from hybrid.errors import HybridError
from hybrid.validate import _finite, checked_keywords, field_values


@checked_keywords
@dataclass(frozen=True)
class Gains:
    """Loop gains of conventions §4 (task frame, per axis).

    Velocity: ``a_t = v_d' + KPv e_v + KIv int e_v + KI2v int int e_v``.
    Force: ``a_n = -KPf e_F - KDf v_n - KIf int e_F`` with ``e_F = F_d - F_c,n``.

    Parameters
    ----------
    KPv, KIv, KI2v : float
        The velocity loop's gains [1/s, 1/s^2, 1/s^3], >= 0.
    KPf : float
        The force loop's proportional gain ``1/m_d`` [1/kg], >= 0.
    KDf : float
        Its damping ``d_v/m_d`` [1/s], >= 0.
    KIf : float
        Its integral gain [1/(kg s)], >= 0.

    Raises
    ------
    HybridError
        A gain that is negative or not finite.

    Examples
    --------
    >>> import hybrid
    >>> hybrid.Gains(KPf=3.0)  # doctest: +NORMALIZE_WHITESPACE
    Gains(KPv=40.0, KIv=200.0, KI2v=1000.0, KPf=3.0, KDf=90.0,
          KIf=25.0)
    """

    KPv: float = 40.0     # 1/s
    KIv: float = 200.0    # 1/s^2
    KI2v: float = 1000.0  # 1/s^3
    KPf: float = 2.0      # 1/kg = 1/m_d
    KDf: float = 90.0     # 1/s = d_v/m_d
    KIf: float = 25.0     # 1/(kg s)

    def __post_init__(self):
        _finite("Gains", **field_values(self))
        for k, v in field_values(self).items():
            if v < 0:
                raise HybridError(f"gain {k} = {v} is negative; loop gains must be >= 0")
