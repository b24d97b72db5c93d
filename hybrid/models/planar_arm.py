"""Parameters of the paper's planar arm, as a validated dataclass (SI units)."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import _finite, check_model_error, checked_keywords, field_values


@checked_keywords
@dataclass(frozen=True)
class Arm:
    """Planar two-link arm of revolute joints (conventions §3 and §5).

    Link ``i`` has length ``Li`` [m], mass ``mi`` [kg] with its centre of mass at ``di`` [m]
    along the link, inertia ``Ii`` [kg m^2] about that centre, joint viscosity ``Vi``
    [N m s/rad]. ``gravity`` [m/s^2] acts along ``-y`` (0 for a SCARA). The paper gives
    ``I1`` about the joint axis and no ``m1, d1``: that is ``m1 = d1 = 0`` here.

    Parameters
    ----------
    L1, L2 : float
        The links' lengths [m], > 0.
    m1, m2 : float
        The links' masses [kg], >= 0.
    d1, d2 : float
        The distance of each link's centre of mass from its joint, along the link [m].
    I1, I2 : float
        The links' inertias about their centres of mass [kg m^2], >= 0.
    V1, V2 : float
        The joints' viscosities [N m s/rad], >= 0.
    gravity : float
        The acceleration of gravity along ``-y`` [m/s^2] (default 0: a SCARA).

    Raises
    ------
    HybridError
        A value is not finite, a length not positive, a mass, inertia or viscosity negative, or the
        inertia matrix ``B(q)`` is not positive definite.

    Examples
    --------
    >>> import hybrid
    >>> arm = hybrid.Arm(L1=0.45, L2=0.32, m1=0.0, m2=3.5, d1=0.0,
    ...                  d2=0.15, I1=0.25, I2=0.16, V1=1.3, V2=0.2)
    >>> arm == hybrid.paper_arm()
    True
    >>> arm.reach()
    (0.13, 0.77)
    """

    L1: float
    L2: float
    m1: float
    m2: float
    d1: float
    d2: float
    I1: float
    I2: float
    V1: float
    V2: float
    gravity: float = 0.0

    def __post_init__(self):
        _finite("Arm", **field_values(self))
        for name in ("L1", "L2"):
            if getattr(self, name) <= 0:
                raise HybridError(f"Arm.{name} = {getattr(self, name)} m; link lengths must be positive")
        for name in ("m1", "m2", "I1", "I2", "V1", "V2"):
            if getattr(self, name) < 0:
                raise HybridError(f"Arm.{name} = {getattr(self, name)} is negative; "
                                  "masses, inertias and viscosities must be >= 0")
        # det B(q) is smallest at cos q2 = +-1: checking both elbows checks every pose
        for q2 in (0.0, math.pi):
            (a, b), (_, d) = self.inertia_matrix(q2)
            mid, half = 0.5 * (a + d), math.hypot(0.5 * (a - d), b)  # the 2 x 2 eigenvalues, in closed form
            eig = (mid - half, mid + half)
            if eig[0] <= 1e-12 * max(eig[1], 1e-300):
                raise HybridError(
                    f"Arm inertia matrix B(q) is not positive definite at q2 = {q2:g} rad "
                    f"(eigenvalues {eig[0]:.3g}, {eig[1]:.3g}); give the links positive inertia "
                    "(I1 > 0 or m1 d1 > 0, and I2 > 0 or m2 d2 > 0)")

    def inertia_matrix(self, q2: float) -> np.ndarray:
        """Joint-space inertia ``B(q)`` [kg m^2]; it depends on ``q2`` only.

        Parameters
        ----------
        q2 : float
            The second joint's position [rad].

        Returns
        -------
        numpy.ndarray
            ``B(q)``, 2 x 2.
        """
        return dynamics((0.0, q2), (0.0, 0.0), self.as_array())[0]

    def as_array(self) -> np.ndarray:
        """The ``arm[11]`` array of the generated C.

        Returns
        -------
        numpy.ndarray
            ``L1, L2, m1, m2, d1, d2, I1, I2, V1, V2, g``.
        """
        return np.array([getattr(self, f.name) for f in fields(self)], dtype=float)

    def with_model_error(self, inertial: float = 0.1, viscous_compensation: float = 0.5) -> Arm:
        """The controller's model of this arm.

        Parameters
        ----------
        inertial : float
            The relative error of the inertial parameters: masses and inertias ``(1 + inertial)``
            times the true ones.
        viscous_compensation : float
            The share of the joints' viscosity the model knows.

        Returns
        -------
        Arm
            The model's parameters.
        """
        k = check_model_error(inertial, viscous_compensation)
        return _modelled(self, k, float(viscous_compensation))

    def conditioning(self, q):
        """Distance of ``J(q)`` from singularity, ``2 |det J| / |J|_F^2`` in [0, 1] (about
        ``|sin q2|``).

        Parameters
        ----------
        q : numpy.ndarray
            Joint positions [rad], of shape (2,) or (2, N).

        Returns
        -------
        float or numpy.ndarray
            The measure, one per state.
        """
        L1, L2, c2 = self.L1, self.L2, np.cos(q[1])
        return 2.0 * L1 * L2 * np.abs(np.sin(q[1])) / (L1**2 + 2.0 * L2**2 + 2.0 * L1 * L2 * c2)

    def inverse_kinematics(self, position, elbow: int = 1) -> np.ndarray:
        """Joint positions putting the tip at ``position``, in closed form.

        Parameters
        ----------
        position : array_like
            The tip's position (x, y) [m].
        elbow : int
            +1 for ``q2 > 0``, -1 for ``q2 < 0``.

        Returns
        -------
        numpy.ndarray
            ``q`` [rad], 2 entries.

        Raises
        ------
        HybridError
            The point is out of reach.
        """
        r = np.asarray(position, float)
        L1, L2 = self.L1, self.L2
        c2 = (float(r @ r) - L1**2 - L2**2) / (2 * L1 * L2)
        if not -1.0 <= c2 <= 1.0:
            lo, hi = self.reach()
            raise HybridError(f"the point {np.round(r, 4).tolist()} m is out of the arm's reach "
                              f"({lo:.3f} m to {hi:.3f} m from the base); move the surface or start_point")
        q2 = elbow * math.acos(c2)
        return np.array([math.atan2(r[1], r[0]) - math.atan2(L2 * math.sin(q2), L1 + L2 * math.cos(q2)), q2])

    def reach(self) -> tuple[float, float]:
        """Smallest and largest distance of the tip from the base.

        Returns
        -------
        tuple of float
            ``(|L1 - L2|, L1 + L2)`` [m].
        """
        return abs(self.L1 - self.L2), self.L1 + self.L2


@lru_cache(maxsize=1024)  # every run of a sweep builds its controller's model; most share it
def _modelled(arm: Arm, k: float, viscous: float) -> Arm:
    return replace(arm, m1=arm.m1 * k, m2=arm.m2 * k, I1=arm.I1 * k, I2=arm.I2 * k, V1=arm.V1 * viscous,
                   V2=arm.V2 * viscous)


def check_arm(arm) -> None:
    """Refuse anything but an :class:`Arm` where the planar closed form is asked for."""
    if not isinstance(arm, Arm):
        raise HybridError(f"arm must be a hybrid.Arm (see hybrid.paper_arm()), got {type(arm).__name__}")


@checked_keywords
def paper_arm() -> Arm:
    """The two-link SCARA of the paper (conventions §5).

    Returns
    -------
    Arm
        ``L1 = 0.45``, ``L2 = 0.32`` m, ``m2 = 3.5`` kg, ``d2 = 0.15`` m, ``I1 = 0.25``, ``I2 = 0.16``
        kg m^2, ``V1 = 1.3``, ``V2 = 0.2`` N m s/rad, no gravity.

    Examples
    --------
    >>> import hybrid
    >>> arm = hybrid.paper_arm()
    >>> arm.L1, arm.L2, arm.m2
    (0.45, 0.32, 3.5)
    >>> arm.inertia_matrix(0.0).round(4).tolist()
    [[1.67, 0.475], [0.475, 0.2388]]
    """
    return Arm(L1=0.45, L2=0.32, m1=0.0, m2=3.5, d1=0.0, d2=0.15, I1=0.25, I2=0.16, V1=1.3, V2=0.2)


# ------------------------------------------------------------ the closed form in NumPy


def kinematics(q, qd, arm):
    """``r`` [m], ``J`` (2x2), ``J'(q, q') q'`` [m/s^2] of the two-link arm."""
    L1, L2 = arm[0], arm[1]
    c1, s1, c12, s12 = np.cos(q[0]), np.sin(q[0]), np.cos(q[0] + q[1]), np.sin(q[0] + q[1])
    r = np.array([L1 * c1 + L2 * c12, L1 * s1 + L2 * s12])
    J = np.array([[-L1 * s1 - L2 * s12, -L2 * s12], [L1 * c1 + L2 * c12, L2 * c12]])
    w1, w12 = qd[0], qd[0] + qd[1]
    Jdqd = -np.array([L1 * c1 * w1**2 + L2 * c12 * w12**2, L1 * s1 * w1**2 + L2 * s12 * w12**2])
    return r, J, Jdqd


def dynamics(q, qd, arm):
    """``B(q)`` [kg m^2] and ``n(q, q')`` [N m]: Coriolis/centrifugal, viscous, gravity (-y)."""
    L1, _, m1, m2, d1, d2, I1, I2, V1, V2, g = arm
    c2, s2 = np.cos(q[1]), np.sin(q[1])
    b22 = I2 + m2 * d2**2
    b12 = b22 + m2 * L1 * d2 * c2
    b11 = I1 + m1 * d1**2 + b22 + m2 * L1**2 + 2 * m2 * L1 * d2 * c2
    B = np.array([[b11, b12], [b12, b22]])
    h = m2 * L1 * d2 * s2
    c1, c12 = np.cos(q[0]), np.cos(q[0] + q[1])
    grav2 = g * m2 * d2 * c12
    grav1 = g * (m1 * d1 + m2 * L1) * c1 + grav2
    n = np.array([-h * (2 * qd[0] * qd[1] + qd[1] ** 2) + V1 * qd[0] + grav1,
                  h * qd[0] ** 2 + V2 * qd[1] + grav2])
    return B, n
