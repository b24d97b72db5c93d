"""Parameters of the arm and the surfaces, as validated dataclasses (SI units)."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields, replace

import numpy as np

from .errors import HybridError


def _finite(owner: str, **values: float) -> None:
    for name, v in values.items():
        if not isinstance(v, (int, float, np.floating, np.integer)) or isinstance(v, bool):
            raise HybridError(f"{owner}.{name} must be a real number, got {v!r}")
        if not math.isfinite(v):
            raise HybridError(f"{owner}.{name} is {v}; give a finite value")


def _point(owner: str, name: str, p) -> tuple[float, float]:
    try:
        arr = np.asarray(p, dtype=float)
    except (TypeError, ValueError):
        raise HybridError(f"{owner}.{name} must be two numbers (x, y) in m, got {p!r}") from None
    if arr.shape != (2,):
        raise HybridError(f"{owner}.{name} must be two numbers (x, y) in m, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise HybridError(f"{owner}.{name} = {p!r} is not finite; give finite coordinates")
    return float(arr[0]), float(arr[1])


@dataclass(frozen=True)
class Arm:
    """Planar two-link arm of revolute joints (NOTES section 3 and 5).

    Link ``i`` has length ``Li`` [m], mass ``mi`` [kg] with its centre of mass at ``di`` [m]
    along the link, inertia ``Ii`` [kg m^2] about that centre, joint viscosity ``Vi``
    [N m s/rad]. ``gravity`` [m/s^2] acts along ``-y`` (0 for a SCARA). The paper gives
    ``I1`` about the joint axis and no ``m1, d1``: that is ``m1 = d1 = 0`` here.
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
        _finite("Arm", **asdict(self))
        for name in ("L1", "L2"):
            if getattr(self, name) <= 0:
                raise HybridError(f"Arm.{name} = {getattr(self, name)} m; link lengths must be positive")
        for name in ("m1", "m2", "I1", "I2", "V1", "V2"):
            if getattr(self, name) < 0:
                raise HybridError(f"Arm.{name} = {getattr(self, name)} is negative; "
                                  "masses, inertias and viscosities must be >= 0")
        # det B(q) is smallest at cos q2 = +-1: checking both elbows checks every pose
        for q2 in (0.0, math.pi):
            eig = np.linalg.eigvalsh(self.inertia_matrix(q2))
            if eig[0] <= 1e-12 * max(eig[1], 1e-300):
                raise HybridError(
                    f"Arm inertia matrix B(q) is not positive definite at q2 = {q2:g} rad "
                    f"(eigenvalues {eig[0]:.3g}, {eig[1]:.3g}); give the links positive inertia "
                    "(I1 > 0 or m1 d1 > 0, and I2 > 0 or m2 d2 > 0)")

    def inertia_matrix(self, q2: float) -> np.ndarray:
        """Joint-space inertia ``B(q)`` [kg m^2]; it depends on ``q2`` only."""
        c = math.cos(q2)
        b22 = self.I2 + self.m2 * self.d2**2
        b12 = b22 + self.m2 * self.L1 * self.d2 * c
        b11 = self.I1 + self.m1 * self.d1**2 + b22 + self.m2 * self.L1**2 + 2 * self.m2 * self.L1 * self.d2 * c
        return np.array([[b11, b12], [b12, b22]])

    def as_array(self) -> np.ndarray:
        """The ``arm[11]`` array of the generated C: ``L1, L2, m1, m2, d1, d2, I1, I2, V1, V2, g``."""
        return np.array([getattr(self, f.name) for f in fields(self)], dtype=float)

    def with_model_error(self, inertial: float = 0.1, viscous_compensation: float = 0.5) -> Arm:
        """The controller's model of this arm: inertial parameters ``(1 + inertial)`` times
        the true ones, joint viscosity ``viscous_compensation`` times the true one."""
        _finite("model error", inertial=inertial, viscous_compensation=viscous_compensation)
        if inertial <= -1:
            raise HybridError(f"model_error = {inertial} makes masses non-positive; give a value > -1")
        if viscous_compensation < 0:
            raise HybridError(f"viscous_compensation = {viscous_compensation}; give a fraction >= 0")
        k = 1.0 + inertial
        return replace(self, m1=self.m1 * k, m2=self.m2 * k, I1=self.I1 * k, I2=self.I2 * k,
                       V1=self.V1 * viscous_compensation, V2=self.V2 * viscous_compensation)

    def reach(self) -> tuple[float, float]:
        """Smallest and largest distance of the tip from the base [m]."""
        return abs(self.L1 - self.L2), self.L1 + self.L2


def paper_arm() -> Arm:
    """The two-link SCARA of the paper (NOTES section 5)."""
    return Arm(L1=0.45, L2=0.32, m1=0.0, m2=3.5, d1=0.0, d2=0.15, I1=0.25, I2=0.16, V1=1.3, V2=0.2)


@dataclass(frozen=True)
class Circle:
    """A disc of centre ``center`` [m] and radius ``radius`` [m], touched from outside.

    Task frame: normal ``n = (r - c)/|r - c|`` (out of the disc, towards the robot),
    tangent ``t = (-n_y, n_x)`` (counter-clockwise). Arc coordinate ``s = radius * angle``.
    """

    center: tuple[float, float]
    radius: float
    kind = "circle"

    def __post_init__(self):
        object.__setattr__(self, "center", _point("Circle", "center", self.center))
        _finite("Circle", radius=self.radius)
        if self.radius <= 0:
            raise HybridError(f"Circle.radius = {self.radius} m; a circle needs a positive radius")

    def as_array(self) -> np.ndarray:
        return np.array([*self.center, self.radius])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot at the surface point nearest ``p``."""
        d = np.asarray(p, float) - self.center
        norm = np.hypot(*d)
        if norm == 0:
            raise HybridError(f"the point {p} is the circle's centre, where its normal is undefined")
        return d / norm

    def arc_coordinate(self, p) -> float:
        d = np.asarray(p, float) - self.center
        return self.radius * math.atan2(d[1], d[0])

    def at(self, s: float) -> np.ndarray:
        """The surface point at arc coordinate ``s`` [m]."""
        ang = s / self.radius
        return np.array(self.center) + self.radius * np.array([math.cos(ang), math.sin(ang)])


@dataclass(frozen=True)
class Plane:
    """A straight surface through ``point`` [m] with ``normal`` pointing towards the robot.

    Tangent ``t = (-n_y, n_x)``; arc coordinate ``s = (p - point) . t``.
    """

    point: tuple[float, float]
    normal: tuple[float, float]
    kind = "plane"

    def __post_init__(self):
        object.__setattr__(self, "point", _point("Plane", "point", self.point))
        n = _point("Plane", "normal", self.normal)
        norm = math.hypot(*n)
        if norm < 1e-12:
            raise HybridError(f"Plane.normal = {self.normal} has zero length; give the direction "
                              "from the surface towards the robot, e.g. (-1, 0)")
        object.__setattr__(self, "normal", (n[0] / norm, n[1] / norm))

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.normal])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot (the same everywhere)."""
        return np.array(self.normal)

    def _tangent(self) -> np.ndarray:
        return np.array([-self.normal[1], self.normal[0]])

    def arc_coordinate(self, p) -> float:
        return float((np.asarray(p, float) - self.point) @ self._tangent())

    def at(self, s: float) -> np.ndarray:
        """The surface point at arc coordinate ``s`` [m]."""
        return np.array(self.point) + s * self._tangent()


Surface = Circle | Plane
