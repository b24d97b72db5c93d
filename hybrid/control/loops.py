"""The task-frame loops' gains, and their stability as sampled by the controller (linear, decoupled).

With ``y' = a`` the closed loop per task axis is linear. Each loop is discretised
exactly as it runs: zero-order hold on ``a`` over the sample period ``T``, integrals
advanced once per sample. A loop is accepted when every eigenvalue lies inside the unit
circle; otherwise the error names the loop and says why.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import _finite, field_values


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
    >>> hybrid.Gains(KPf=3.0)
    Gains(KPv=40.0, KIv=200.0, KI2v=1000.0, KPf=3.0, KDf=90.0, KIf=25.0)
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


def velocity_loop_matrix(KP: float, KI: float, KI2: float, T: float) -> np.ndarray:
    """State ``(v, int e, int int e)`` from one sample to the next, ``v_d = 0``."""
    # at sample k: I1 += T e, I2 += T I1, a = KP e + KI I1 + KI2 I2, v += T a, with e = -v
    upd = np.array([[1.0, 0, 0], [-T, 1, 0], [-T * T, T, 1]])        # integrals after the update
    a_row = np.array([-KP, KI, KI2]) @ upd
    return upd + np.outer([T, 0, 0], a_row)


def force_loop_matrix(KP: float, KD: float, KI: float, k: float, T: float) -> np.ndarray:
    """State ``(beta, beta', int e_F)`` with ``F_c,n = -k beta`` (``beta`` along the normal)."""
    # e_F = F_d - F_c,n = k beta (F_d = 0); I += T e_F; a = -KP e_F - KD beta' - KI I
    upd = np.array([[1.0, 0, 0], [0, 1, 0], [T * k, 0, 1]])
    a_row = np.array([-KP * k, -KD, -KI]) @ upd
    hold = np.array([T * T / 2, T, 0.0])
    step = np.array([[1.0, T, 0], [0, 1, 0], [0, 0, 1]])
    return step @ upd + np.outer(hold, a_row)


def loop_radii(g, T: float, k: float) -> dict[str, tuple[float, str]]:
    """Spectral radius of each loop with gains ``g``, sample time ``T`` [s], contact stiffness ``k``
    [N/m], and the rule a stable loop satisfies."""
    return dict(_loop_radii(g, float(T), float(k)))


@lru_cache(maxsize=4096)  # every run of a sweep checks its loops; most share gains and timing
def _loop_radii(g, T: float, k: float) -> tuple:
    # an integrator whose gain is 0 feeds nothing back: its eigenvalue 1 is left out
    used_v = 1 + (g.KIv != 0 or g.KI2v != 0) + (g.KI2v != 0)
    used_f = 2 + (g.KIf != 0)
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is a radius of inf, below
        loops = {
            "velocity (tangent) loop": (velocity_loop_matrix(g.KPv, g.KIv, g.KI2v, T)[:used_v, :used_v],
                                        "needs KPv*KIv > KI2v and KPv*T well below 2"),
            "force (normal) loop": (force_loop_matrix(g.KPf, g.KDf, g.KIf, k, T)[:used_f, :used_f],
                                    "needs KDf*KPf > KIf, and KDf*T and sqrt(KPf*k)*T well below 2"),
        }
    return tuple((name, (_spectral_radius(M), rule)) for name, (M, rule) in loops.items())


def _spectral_radius(M: np.ndarray) -> float:
    """The largest eigenvalue modulus of ``M``; ``inf`` when ``M`` is not finite.

    An entry of ``M`` overflows only when a gain times the sample time (or the contact stiffness)
    passes the largest float; the loop's radius grows with those products (``KPf*k*T**2/2``,
    ``KPv*T``, ...), so such a loop is unstable by far, and ``inf`` says so in the same verdict.
    """
    if not np.isfinite(M).all():
        return float("inf")
    try:
        radius = float(max(abs(np.linalg.eigvals(M))))
    except np.linalg.LinAlgError:  # no convergence: only for entries near overflow, as above
        return float("inf")
    return radius if np.isfinite(radius) else float("inf")


def contact_stiffness(exp) -> float:
    """Sensor and surface springs in series [N/m]."""
    return 1.0 / (1.0 / exp.sensor.stiffness + 1.0 / exp.contact.stiffness)


def check_loops(exp) -> None:
    """Raise :class:`HybridError` when a loop of ``exp`` is unstable at its sample time."""
    g, T, k = exp.effective_gains(), exp.sample_time, contact_stiffness(exp)
    for name, (radius, rule) in loop_radii(g, T, k).items():
        if radius >= 1.0:
            why = (f"spectral radius {radius:.3g} >= 1" if np.isfinite(radius) else
                   f"a gain times sample_time or contact stiffness overflows: {_largest(g)}")
            raise HybridError(
                f"the {name} is unstable at sample_time {T} s ({why}); it {rule}\n"
                f"  gains {g}, contact stiffness {k:.0f} N/m")


def _largest(g) -> str:
    name, value = max(field_values(g).items(), key=lambda item: item[1])
    return f"{name} = {value:.3g}"


def model_error_note(exp) -> str:
    """Why a run with stable nominal loops may still diverge: the model error, or ``""``.

    The controller's inertia is ``(1 + model_error)`` times the arm's, so the arm's task
    acceleration is about ``(1 + model_error) a``: every loop gain is scaled by that factor.
    """
    if getattr(exp, "controller_robot", None) is not None:  # a model of its own: no model_error scales it
        return ""
    scale = 1.0 + exp.model_error
    g = exp.effective_gains()
    scaled = replace(g, **{name: value * scale for name, value in asdict(g).items()})
    unstable = [f"the {name} (spectral radius {radius:.2f})"
                for name, (radius, _) in loop_radii(scaled, exp.sample_time, contact_stiffness(exp)).items()
                if radius >= 1.0]
    if not unstable:
        return ""
    return (f"; model_error = {exp.model_error} scales every loop gain by {scale:.3g}, which makes "
            f"{' and '.join(unstable)} unstable: lower the gains or the model error")
