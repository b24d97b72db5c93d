"""Surfaces the tool slides on, as validated dataclasses (SI units).

Planar (the paper's arm, NOTES section 3): :class:`Circle` and a 2-D :class:`Plane`.
Spatial (NOTES section 9): a 3-D :class:`Plane`, :class:`Sphere`, :class:`Cylinder`, and
:class:`ImplicitSurface` for any ``phi(x, y, z) = 0`` a user writes in SymPy. Every surface
gives ``phi > 0`` on the robot's side and the unit normal ``n = grad phi / |grad phi|`` towards
the robot. A spatial surface's ``spec()`` is its expression for code generation and
``as_array()`` its run-time parameters; a planar one ``lift()`` s to the spatial surface it
is the cross-section of (so the general law can run the paper's case).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import _finite, _point, unit_vector

#: the parameters of the built-in surfaces, in the order of the generated C's ``surface`` array
SURFACE_PARAMETERS = {"plane": ("p_x", "p_y", "p_z", "n_x", "n_y", "n_z"), "sphere": ("c_x", "c_y", "c_z", "rho"),
                      "cylinder": ("p_x", "p_y", "p_z", "u_x", "u_y", "u_z", "rho")}


@dataclass(frozen=True)
class SurfaceSpec:
    """What the code generator needs of a surface: ``kind`` (it names the generated code), the
    names of its run-time parameters, and ``phi`` (a SymPy expression of ``x, y, z`` and those
    parameters), None for a built-in kind, whose ``phi`` the generator writes out itself."""

    kind: str
    parameters: tuple[str, ...]
    phi: object = None
    #: ``phi`` as canonical text (SymPy's ``srepr``), which identifies it
    phi_text: str = "built-in"

    def key(self) -> str:
        """A stable text identifying the surface's expression (for cache keys)."""
        return f"{self.kind}:{','.join(self.parameters)}:{self.phi_text}"


class Surface:
    """The base of every surface: ``kind``, ``dim`` (2 for the planar arm's, 3 in space),
    ``as_array()`` (the generated code's run-time parameters), ``normal_at(p)`` and ``lift()`` (the
    3-D surface; a planar one is the cross-section of its lift at ``z = 0``)."""

    kind: str
    dim: int


def _unit_normal(g: np.ndarray, where: str) -> np.ndarray:
    norm = float(np.linalg.norm(g))
    if not norm > 1e-12:
        raise HybridError(f"{where}, where the normal is undefined; give a point off it")
    return g / norm


def _positive(owner: str, name: str, value) -> None:
    _finite(owner, **{name: value})
    if value <= 0:
        raise HybridError(f"{owner}.{name} = {value} m; give a positive {name}")


# --------------------------------------------------------------------------- planar


@dataclass(frozen=True)
class Circle(Surface):
    """A disc of centre ``center`` [m] and radius ``radius`` [m], touched from outside.

    Task frame: normal ``n = (r - c)/|r - c|`` (out of the disc, towards the robot),
    tangent ``t = (-n_y, n_x)`` (counter-clockwise). Arc coordinate ``s = radius * angle``.
    """

    center: tuple[float, float]
    radius: float
    kind = "circle"
    dim = 2

    def __post_init__(self):
        object.__setattr__(self, "center", _point("Circle", "center", self.center))
        _positive("Circle", "radius", self.radius)

    def as_array(self) -> np.ndarray:
        return np.array([*self.center, self.radius])

    def lift(self) -> Cylinder:
        """The cylinder about base z of which this circle is the cross-section."""
        return Cylinder((*self.center, 0.0), (0.0, 0.0, 1.0), self.radius)

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot at the surface point nearest ``p``."""
        d = np.asarray(p, float) - self.center
        norm = np.hypot(*d)
        if norm == 0:
            raise HybridError(f"the point {p} is the circle's centre, where its normal is undefined")
        return d / norm

    def arc_coordinate(self, p) -> float:
        d = np.asarray(_point("Circle.arc_coordinate", "p", p)) - self.center
        return self.radius * math.atan2(d[1], d[0])

    def at(self, s: float) -> np.ndarray:
        """The surface point at arc coordinate ``s`` [m]."""
        _finite("Circle.at", s=s)
        ang = s / self.radius
        return np.array(self.center) + self.radius * np.array([math.cos(ang), math.sin(ang)])

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """The surface points at the arc coordinates ``s`` [m] (one row each)."""
        ang = np.asarray(s, float) / self.radius
        return np.array(self.center) + self.radius * np.column_stack([np.cos(ang), np.sin(ang)])


@dataclass(frozen=True)
class Plane(Surface):
    """A plane through ``point`` [m] with unit ``normal`` pointing towards the robot.

    Two coordinates make the paper's planar line (tangent ``t = (-n_y, n_x)``, arc coordinate
    ``s = (p - point) . t``); three make a plane in space (``phi = n . (p - point)``).
    """

    point: tuple[float, ...]
    normal: tuple[float, ...]
    kind = "plane"

    def __post_init__(self):
        point = _point("Plane", "point", self.point, (2, 3))
        normal = _point("Plane", "normal", self.normal, (len(point),))
        if math.hypot(*normal) < 1e-12:
            example = "(-1, 0)" if len(point) == 2 else "(0, 0, 1)"
            raise HybridError(f"Plane.normal = {self.normal} has zero length; give the direction "
                              f"from the surface towards the robot, e.g. {example}")
        object.__setattr__(self, "point", point)
        object.__setattr__(self, "normal", unit_vector("Plane", "normal", normal))

    @property
    def dim(self) -> int:
        return len(self.point)

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.normal])

    def spec(self) -> SurfaceSpec:
        self._spatial()
        return SurfaceSpec("plane", SURFACE_PARAMETERS["plane"])

    def lift(self) -> Plane:
        return self if self.dim == 3 else Plane((*self.point, 0.0), (*self.normal, 0.0))

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot (the same everywhere)."""
        return np.array(self.normal)

    def _spatial(self) -> None:
        if self.dim != 3:
            raise HybridError("this Plane is planar (2 coordinates); give 3-D point and normal, or use .lift()")

    def _planar(self) -> None:
        if self.dim != 2:
            raise HybridError("arc coordinates are defined for a planar Plane (2 coordinates)")

    def _tangent(self) -> np.ndarray:
        self._planar()
        return np.array([-self.normal[1], self.normal[0]])

    def arc_coordinate(self, p) -> float:
        return float((np.asarray(_point("Plane.arc_coordinate", "p", p)) - self.point) @ self._tangent())

    def at(self, s: float) -> np.ndarray:
        """The surface point at arc coordinate ``s`` [m]."""
        _finite("Plane.at", s=s)
        return np.array(self.point) + s * self._tangent()

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """The surface points at the arc coordinates ``s`` [m] (one row each)."""
        return np.array(self.point) + np.outer(np.asarray(s, float), self._tangent())


# -------------------------------------------------------------------------- spatial


class _Spatial(Surface):
    dim = 3

    def lift(self):
        return self


@dataclass(frozen=True)
class Sphere(_Spatial):
    """A sphere of centre ``center`` [m] and radius ``radius`` [m], touched from outside:
    ``phi = |p - c| - radius``."""

    center: tuple[float, float, float]
    radius: float
    kind = "sphere"

    def __post_init__(self):
        object.__setattr__(self, "center", _point("Sphere", "center", self.center, (3,)))
        _positive("Sphere", "radius", self.radius)

    def spec(self) -> SurfaceSpec:
        return SurfaceSpec("sphere", SURFACE_PARAMETERS["sphere"])

    def as_array(self) -> np.ndarray:
        return np.array([*self.center, self.radius])

    def normal_at(self, p) -> np.ndarray:
        d = np.asarray(p, float) - self.center
        return _unit_normal(d, f"the point {p} is the sphere's centre")


@dataclass(frozen=True)
class Cylinder(_Spatial):
    """An infinite cylinder of radius ``radius`` [m] about the line through ``point`` [m]
    along ``axis``, touched from outside: ``phi = |(I - u u^T)(p - point)| - radius``."""

    point: tuple[float, float, float]
    axis: tuple[float, float, float]
    radius: float
    kind = "cylinder"

    def __post_init__(self):
        object.__setattr__(self, "point", _point("Cylinder", "point", self.point, (3,)))
        object.__setattr__(self, "axis", unit_vector("Cylinder", "axis", _point("Cylinder", "axis", self.axis, (3,))))
        _positive("Cylinder", "radius", self.radius)

    def spec(self) -> SurfaceSpec:
        return SurfaceSpec("cylinder", SURFACE_PARAMETERS["cylinder"])

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.axis, self.radius])

    def normal_at(self, p) -> np.ndarray:
        d = np.asarray(p, float) - self.point
        radial = d - np.dot(d, self.axis) * np.asarray(self.axis)
        return _unit_normal(radial, f"the point {p} is on the cylinder's axis")


PlanarSurface = Circle | Plane
