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
from hybrid.geometry.paths import CirclePath, LinePath
from hybrid.validate import _finite, _point, unit_vector


@dataclass(frozen=True)
class SurfaceSpec:
    """What the code generator needs of a surface: ``kind`` (it names the generated code), the
    names of its run-time parameters, and ``phi``: a SymPy expression of ``x, y, z`` and those
    parameters (a user's surface), or a built-in surface's ``formula(p, theta, sqrt)`` of the point
    ``p`` (3) and the parameters ``theta`` (in ``as_array`` order), written once with the class."""

    kind: str
    parameters: tuple[str, ...]
    phi: object = None
    #: ``phi`` as canonical text (SymPy's ``srepr``), which identifies it
    phi_text: str = "built-in"
    formula: object = None

    def key(self) -> str:
        """A stable text identifying the surface's expression (for cache keys)."""
        return f"{self.kind}:{','.join(self.parameters)}:{self.phi_text}"


#: every surface class, by its kind (for files that name a surface by kind)
SURFACE_KINDS: dict[str, type] = {}


class Surface:
    """The base of every surface: ``kind``, ``dim`` (2 for the planar arm's, 3 in space),
    ``as_array()`` (the generated code's run-time parameters), ``normal_at(p)``, ``lift()`` (the
    3-D surface; a planar one is the cross-section of its lift at ``z = 0``), ``project(p)`` (the
    nearest surface point, where it has a closed form, else None) and ``path()`` (where a run
    goes on it unless told)."""

    kind: str
    dim: int
    #: a built-in surface's run-time parameters, named in ``as_array`` order
    parameters_named: tuple[str, ...] = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if isinstance(cls.__dict__.get("kind"), str):
            SURFACE_KINDS[cls.kind] = cls

    @staticmethod
    def formula(p, theta, sqrt):
        """``phi(p)`` from the point ``p`` (3 coordinates) and the parameters ``theta``, with ``sqrt``
        the square root of the numbers used (SymPy's for the generator)."""
        raise NotImplementedError

    def spec(self) -> SurfaceSpec:
        """What the code generator needs of this surface (see :class:`SurfaceSpec`)."""
        return SurfaceSpec(self.kind, self.parameters_named, formula=self.formula)

    def project(self, p) -> np.ndarray | None:
        return None

    def path(self):
        raise HybridError(f"a {type(self).__name__} has no path of its own: give the experiment a path "
                          "(hybrid.CirclePath or hybrid.LinePath) or a start_point")


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

    def path(self) -> CirclePath:
        """The circle itself, counter-clockwise (the paper's path; arc length ``radius * angle``)."""
        return CirclePath(self.center, self.radius)

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (radially)."""
        return self.path().point_at(self.path().arc_of(p))


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

    parameters_named = ("p_x", "p_y", "p_z", "n_x", "n_y", "n_z")

    @staticmethod
    def formula(p, theta, sqrt):
        n = theta[3:6]
        return sum(n[i] * (p[i] - theta[i]) for i in range(3)) / sqrt(sum(v * v for v in n))

    def spec(self) -> SurfaceSpec:
        self._spatial()
        return super().spec()

    def lift(self) -> Plane:
        return self if self.dim == 3 else Plane((*self.point, 0.0), (*self.normal, 0.0))

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot (the same everywhere)."""
        return np.array(self.normal)

    def _spatial(self) -> None:
        if self.dim != 3:
            raise HybridError("this Plane is planar (2 coordinates); give 3-D point and normal, or use .lift()")

    def path(self) -> LinePath:
        """A planar line's own path: along the tangent ``t = (-n_y, n_x)``, arc length 0 at ``point``."""
        if self.dim != 2:
            raise HybridError("a plane in space has no path of its own: give the experiment a path (a "
                              "hybrid.LinePath or hybrid.CirclePath on the plane) or a start_point")
        return LinePath(self.point, (-self.normal[1], self.normal[0]))

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (along the normal)."""
        p = np.asarray(p, float)
        n = np.asarray(self.normal)
        return p - n * float((p - self.point) @ n)


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

    parameters_named = ("c_x", "c_y", "c_z", "rho")

    @staticmethod
    def formula(p, theta, sqrt):
        return sqrt(sum((p[i] - theta[i]) ** 2 for i in range(3))) - theta[3]

    def as_array(self) -> np.ndarray:
        return np.array([*self.center, self.radius])

    def normal_at(self, p) -> np.ndarray:
        d = np.asarray(p, float) - self.center
        return _unit_normal(d, f"the point {p} is the sphere's centre")

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (radially)."""
        return np.asarray(self.center) + self.radius * self.normal_at(p)

    def latitude_circle(self, latitude: float = 60.0) -> CirclePath:
        """The circle ``latitude`` degrees from the top (+z), counter-clockwise seen from +z (along
        ``t1 = z x n``), starting on the side that faces the base's z axis."""
        _finite("Sphere.latitude_circle", latitude=latitude)
        if not 0 < latitude < 180:
            raise HybridError(f"latitude = {latitude} degrees from the top; give a value in (0, 180)")
        c, polar = np.asarray(self.center, float), math.radians(latitude)
        rho, h = self.radius * math.sin(polar), self.radius * math.cos(polar)
        return CirclePath((c[0], c[1], c[2] + h), rho, rho * math.atan2(-c[1], -c[0]))

    def path(self) -> CirclePath:
        """The default path on a sphere: its latitude circle 60 degrees from the top."""
        return self.latitude_circle()


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

    parameters_named = ("p_x", "p_y", "p_z", "u_x", "u_y", "u_z", "rho")

    @staticmethod
    def formula(p, theta, sqrt):
        u = theta[3:6]
        d = [p[i] - theta[i] for i in range(3)]
        along = sum(u[i] * d[i] for i in range(3)) / sum(v * v for v in u)
        return sqrt(sum((d[i] - u[i] * along) ** 2 for i in range(3))) - theta[6]

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.axis, self.radius])

    def normal_at(self, p) -> np.ndarray:
        d = np.asarray(p, float) - self.point
        radial = d - np.dot(d, self.axis) * np.asarray(self.axis)
        return _unit_normal(radial, f"the point {p} is on the cylinder's axis")

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (radially from the axis)."""
        d = np.asarray(p, float) - self.point
        u = np.asarray(self.axis)
        return np.asarray(self.point) + np.dot(d, u) * u + self.radius * self.normal_at(p)

    def circle_at(self, point) -> CirclePath:
        """The circle around a vertical cylinder (axis along base z) through ``point``,
        counter-clockwise seen from +z, starting at ``point``."""
        if abs(abs(self.axis[2]) - 1.0) > 1e-12:
            raise HybridError(f"Cylinder.circle_at needs a cylinder about base z, its axis is {self.axis}; "
                              "give the experiment a path of your own")
        p = np.asarray(_point("Cylinder.circle_at", "point", point, (3,)))
        path = CirclePath((self.point[0], self.point[1], float(p[2])), self.radius)
        return CirclePath(path.center, self.radius, path.arc_of(p))

    def path(self) -> CirclePath:
        raise HybridError("a cylinder has no path of its own: give the experiment a path, e.g. "
                          "cylinder.circle_at(point)")


PlanarSurface = Circle | Plane
