"""Surfaces the tool slides on, as validated dataclasses (SI units).

Every surface is 3-D: :class:`Plane`, :class:`Sphere`, :class:`Cylinder`, and
:class:`ImplicitSurface` for any ``phi(x, y, z) = 0`` a user writes down. Every surface gives
``phi > 0`` on the robot's side and the unit normal ``n = grad phi / |grad phi|`` towards the
robot; ``spec()`` is what the generator needs of it and ``as_array()`` its run-time parameters.
The paper's planar surfaces are constructors of 3-D ones: :func:`Circle` a cylinder about base z,
a :class:`Plane` given in 2 coordinates a vertical plane. Where the planar arm runs on such a
surface it uses the surface's :meth:`~Surface.cross_section` (a :class:`CircleSection` or
:class:`LineSection`), which the committed closed-form units take.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.paths import CirclePath, LinePath
from hybrid.spec.surface import FORMULAS, NORMAL_TOL, PARAMETERS, SurfaceSpec
from hybrid.validate import _finite, _point, checked_keywords, unit_vector

#: every surface class, by its kind (for files that name a surface by kind)
SURFACE_KINDS: dict[str, type] = {}


@lru_cache(maxsize=1024)
def _once(cls, *args):
    """``cls(*args)`` of an immutable geometric object, made once per arguments: a sweep's runs ask
    their surface for the same cross-section and path many times."""
    return cls(*args)


class Surface:
    """The base of every surface (3-D): ``kind``, ``as_array()`` (the generated code's run-time
    parameters), ``normal_at(p)``, ``phi_function()`` (``phi`` and its gradient in NumPy),
    ``project(p)`` (the nearest surface point, where it has a closed form, else None), ``path()``
    (where a run goes on it unless told) and ``cross_section()`` (where the paper's planar arm can run
    on it)."""

    kind: str
    dim = 3
    #: a built-in surface's run-time parameters, named in ``as_array`` order
    parameters_named: tuple[str, ...] = ()
    #: whether the generated code's parameters depend on the point where it is evaluated (a part's local
    #: expansion, :class:`~hybrid.geometry.parts.PartSurface`): then each call, each sample, gives them there
    #: (:meth:`parameters_at`)
    local = False

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

    def phi_function(self) -> Callable[[np.ndarray], tuple[float, np.ndarray]]:
        """``p -> (phi(p), grad phi(p))`` in NumPy, the parameters bound: what a plant that evaluates
        the contact itself needs (MuJoCo's). Here :meth:`formula` differentiated by SymPy; a surface
        with a closed-form gradient gives its own."""
        import sympy as sp  # only a surface without a gradient of its own needs SymPy

        if type(self).formula is Surface.formula:
            raise HybridError(f"a {type(self).__name__} gives no phi: define its formula(p, theta, sqrt) and "
                              "as_array() (as hybrid.Plane does), or write it as a hybrid.ImplicitSurface")
        xyz = sp.symbols("x y z", real=True)
        return numpy_phi(self.formula(xyz, [sp.Float(v) for v in self.as_array()], sp.sqrt), xyz)

    def parameters_at(self, p) -> np.ndarray:
        """The generated code's run-time parameters for the point ``p`` [m]: :meth:`as_array` (the same
        everywhere) but where the surface is :attr:`local`."""
        return self.as_array()

    def undefined_at(self, points) -> int | None:
        """The index of the first of ``points`` (3 coordinates each) where the surface gives no contact:
        ``phi`` or its gradient is not a finite number there (its formula undefined) or the gradient is 0
        (no normal); None where every point has one (or the surface gives no ``phi``)."""
        try:
            phi = self.phi_function()
        except HybridError:
            return None
        with np.errstate(all="ignore"):  # a closed form at its centre or axis divides by 0
            for i, p in enumerate(np.asarray(points, float).reshape(-1, 3)):
                value, grad = phi(p)
                if not (math.isfinite(value) and 0.0 < float(np.linalg.norm(grad)) <= sys.float_info.max):
                    return i
        return None

    def project(self, p) -> np.ndarray | None:
        return None

    def thinnest_wall(self, near=None, within: float = math.inf) -> float:
        """The thinnest wall [m] of the solid behind the surface within ``within`` of ``near``: inf for a
        surface given by a formula, whose ``phi`` measures from one face (a part's is measured,
        :meth:`~hybrid.geometry.parts.PartSurface.thinnest_wall`)."""
        return math.inf

    def cross_section(self) -> Section | None:
        """The cross-section by the base xy-plane where the paper's planar arm can run on it (a
        vertical cylinder's circle, a vertical plane's line), else None."""
        return None

    def path(self):
        raise HybridError(f"a {type(self).__name__} has no path of its own: give the experiment a path "
                          "(hybrid.CirclePath or hybrid.LinePath) or a start_point")

    def path_through(self, p):
        """The path a run starting at the surface point ``p`` follows unless told (along ``t1`` for
        ``e = z``); None where the surface has none."""
        return None


def numpy_phi(phi, xyz) -> Callable[[np.ndarray], tuple[float, np.ndarray]]:
    """``p -> (phi(p), grad phi(p))`` in NumPy of the SymPy expression ``phi`` of the symbols ``xyz``
    alone (its parameters' values substituted)."""
    import sympy as sp

    f = sp.lambdify(xyz, [phi, *(sp.diff(phi, v) for v in xyz)], modules="math")
    undefined = (math.nan, np.full(3, math.nan))

    def evaluate(p):
        try:
            value, *grad = f(*(float(v) for v in p))  # Python's floats: a domain error raises, as checked below
            return float(value), np.array(grad, float)
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            # the formula is undefined at p (the root or log of a negative number, a division by zero, a
            # complex power): NaN, as the generated C gives it, for the plant to stop on
            return undefined
    return evaluate


def _unit_normal(g: np.ndarray, where: str) -> np.ndarray:
    norm = float(np.linalg.norm(g))
    if not NORMAL_TOL < norm <= sys.float_info.max:
        raise HybridError(f"{where}, where the normal is undefined; give a point off it")
    return g / norm


def _positive(owner: str, name: str, value) -> None:
    _finite(owner, **{name: value})
    if value <= 0:
        raise HybridError(f"{owner}.{name} = {value} m; give a positive {name}")


# ----------------------------------------------------------------- planar cross-sections


class Section:
    """A surface's cross-section by the base xy-plane, where the paper's planar arm moves: its
    ``kind`` names the committed closed-form units (``"circle"``, ``"plane"``), ``as_array()`` their
    ``surface`` array, ``normal_at``, ``path()`` and ``project`` in 2 coordinates. Built by
    :meth:`Surface.cross_section`."""

    dim = 2


@dataclass(frozen=True)
class CircleSection(Section):
    """The circle of centre ``center`` [m] and radius ``radius`` [m]: a vertical cylinder's
    cross-section. Normal ``n = (r - c)/|r - c|`` (out of the disc, towards the robot), tangent
    ``t = (-n_y, n_x)`` (counter-clockwise), arc length ``radius * angle``."""

    center: tuple[float, float]
    radius: float
    kind = "circle"

    def as_array(self) -> np.ndarray:
        return np.array([*self.center, self.radius])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot at the circle's point nearest ``p``."""
        d = np.asarray(p, float)[:2] - self.center
        norm = np.hypot(*d)
        if norm == 0:
            raise HybridError(f"the point {p} is the circle's centre, where its normal is undefined")
        return d / norm

    def path(self) -> CirclePath:
        """The circle itself, counter-clockwise (the paper's path; arc length ``radius * angle``)."""
        return _once(CirclePath, self.center, self.radius)

    def path_through(self, p) -> CirclePath:
        return self.path()

    def project(self, p) -> np.ndarray:
        """The circle's point nearest ``p`` (radially)."""
        path = self.path()
        return path.point_at(path.arc_of(p))


@dataclass(frozen=True)
class LineSection(Section):
    """The line through ``point`` [m] with unit ``normal`` towards the robot: a vertical plane's
    cross-section. Tangent ``t = (-n_y, n_x)``, arc length ``(p - point) . t``."""

    point: tuple[float, float]
    normal: tuple[float, float]
    kind = "plane"

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.normal])

    def normal_at(self, p) -> np.ndarray:
        return np.array(self.normal)

    def path(self) -> LinePath:
        return _once(LinePath, self.point, (-self.normal[1], self.normal[0]))

    def path_through(self, p) -> LinePath:
        return self.path()

    def project(self, p) -> np.ndarray:
        """The line's point nearest ``p`` (along the normal)."""
        p = np.asarray(p, float)[:2]
        n = np.asarray(self.normal)
        return p - n * float((p - self.point) @ n)


@checked_keywords
def Circle(center, radius: float) -> Cylinder:  # noqa: N802  (a constructor, named as the shape it makes)
    """The paper's disc, touched from outside: the cylinder about base z through its centre.

    Parameters
    ----------
    center : array_like
        The disc's centre (x, y) [m].
    radius : float
        Its radius [m], > 0.

    Returns
    -------
    Cylinder
        The cylinder about base z through ``(x, y, 0)`` (its cross-section is the circle).

    Raises
    ------
    HybridError
        A centre not of two finite numbers, or a radius not positive.

    Examples
    --------
    >>> import hybrid
    >>> disc = hybrid.Circle(center=(0.5, 0.0), radius=0.2)
    >>> disc
    Cylinder(point=(0.5, 0.0, 0.0), axis=(0.0, 0.0, 1.0), radius=0.2)
    >>> disc.cross_section()
    CircleSection(center=(0.5, 0.0), radius=0.2)
    """
    c = _point("Circle", "center", center)
    _positive("Circle", "radius", radius)
    return Cylinder((*c, 0.0), (0.0, 0.0, 1.0), radius)


# --------------------------------------------------------------------------- planes


@checked_keywords
@dataclass(frozen=True)
class Plane(Surface):
    r"""A plane through ``point`` :math:`p_0` with unit ``normal`` :math:`n` towards the robot:
    :math:`\varphi(p) = n^T (p - p_0)`.

    Parameters
    ----------
    point : array_like
        A point of the plane [m]: 3 coordinates, or 2 for the paper's planar line (the vertical plane
        through ``(x, y, 0)``).
    normal : array_like
        The direction from the plane towards the robot (as many coordinates as ``point``; made unit).

    Raises
    ------
    HybridError
        Coordinates not finite or of the wrong number, or a normal of zero length.

    Examples
    --------
    >>> import hybrid
    >>> wall = hybrid.Plane(point=(0.3, 0.0), normal=(-1.0, 0.0))
    >>> wall
    Plane(point=(0.3, 0.0, 0.0), normal=(-1.0, 0.0, 0.0))
    >>> wall.project([0.5, 0.1, 0.2]).tolist()
    [0.3, 0.1, 0.2]
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
        # a planar line's normal is made unit in its plane, then lifted (z = 0, exactly)
        normal = unit_vector("Plane", "normal", normal)
        object.__setattr__(self, "point", (*point, 0.0)[:3])
        object.__setattr__(self, "normal", (*normal, 0.0)[:3])

    def as_array(self) -> np.ndarray:
        """The generated code's run-time parameters of this surface.

        Returns
        -------
        numpy.ndarray
            ``point`` (3), then ``normal`` (3).
        """
        return np.array([*self.point, *self.normal])

    parameters_named = PARAMETERS["plane"]
    formula = staticmethod(FORMULAS["plane"])

    def cross_section(self) -> LineSection | None:
        """The line where a vertical plane cuts the base xy-plane.

        Returns
        -------
        LineSection or None
            The line, or None for a plane that is not vertical.
        """
        if self.normal[2] != 0.0:
            return None
        return _once(LineSection, self.point[:2], self.normal[:2])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot (the same everywhere).

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The unit normal towards the robot (3).
        """
        return np.array(self.normal)

    def phi_function(self):
        """``phi`` and its gradient in NumPy: ``n^T (p - point)`` and the unit normal ``n``.

        Returns
        -------
        callable
            ``p -> (phi(p), grad phi(p))``, ``p`` a NumPy array of 3 coordinates.
        """
        theta = self.as_array()
        point, normal = theta[:3], theta[3:]
        unit = normal / math.sqrt(normal @ normal)
        return lambda p: (float(unit @ (p - point)), unit)

    def path_through(self, p) -> LinePath:
        """The line through ``p`` along ``t1 = z x n`` (base x on a horizontal plane).

        Parameters
        ----------
        p : array_like
            A point of the plane (3 coordinates) [m].

        Returns
        -------
        LinePath
            The line, its arc length 0 at ``p``.
        """
        n = np.asarray(self.normal)
        d = np.array([-n[1], n[0], 0.0])
        return LinePath(tuple(np.asarray(p, float)), tuple(d) if np.linalg.norm(d) > 1e-9 else (1.0, 0.0, 0.0))

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (along the normal).

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The surface point (3) [m].
        """
        p = np.asarray(p, float)
        n = np.asarray(self.normal)
        return p - n * float((p - self.point) @ n)


# ----------------------------------------------------------------- curved surfaces



@checked_keywords
@dataclass(frozen=True)
class Sphere(Surface):
    """A sphere touched from outside: ``phi = |p - c| - radius``.

    Parameters
    ----------
    center : array_like
        The centre ``c`` (3 coordinates) [m].
    radius : float
        The radius [m], > 0.

    Raises
    ------
    HybridError
        A centre not of three finite numbers, or a radius not positive.

    Examples
    --------
    >>> import hybrid
    >>> ball = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)
    >>> ball.normal_at([0.5, 0.0, 0.5]).tolist()
    [0.0, 0.0, 1.0]
    >>> ball.project([0.5, 0.0, 0.5]).tolist()
    [0.5, 0.0, 0.35]
    """

    center: tuple[float, float, float]
    radius: float
    kind = "sphere"

    def __post_init__(self):
        object.__setattr__(self, "center", _point("Sphere", "center", self.center, (3,)))
        _positive("Sphere", "radius", self.radius)

    parameters_named = PARAMETERS["sphere"]
    formula = staticmethod(FORMULAS["sphere"])

    def as_array(self) -> np.ndarray:
        """The generated code's run-time parameters of this surface.

        Returns
        -------
        numpy.ndarray
            ``center`` (3), then ``radius``.
        """
        return np.array([*self.center, self.radius])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot, along ``p - c``.

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The unit normal towards the robot (3).

        Raises
        ------
        HybridError
            ``p`` is the centre.
        """
        d = np.asarray(p, float) - self.center
        return _unit_normal(d, f"the point {p} is the sphere's centre")

    def phi_function(self):
        """``phi`` and its gradient in NumPy: ``|p - c| - radius`` and ``(p - c) / |p - c|``.

        Returns
        -------
        callable
            ``p -> (phi(p), grad phi(p))``, ``p`` a NumPy array of 3 coordinates.
        """
        theta = self.as_array()
        center, rho = theta[:3], theta[3]

        def sphere(p):
            d = p - center
            dist = math.sqrt(d @ d)
            return dist - rho, d / dist
        return sphere

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (radially).

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The surface point (3) [m].
        """
        return np.asarray(self.center) + self.radius * self.normal_at(p)

    def latitude_circle(self, latitude: float = 60.0) -> CirclePath:
        """A latitude circle, counter-clockwise seen from +z (along ``t1 = z x n``), starting on the
        side that faces the base's z axis.

        Parameters
        ----------
        latitude : float
            Its angle from the top (+z) [degrees], in (0, 180).

        Returns
        -------
        CirclePath
            The circle.

        Raises
        ------
        HybridError
            A latitude outside (0, 180).
        """
        _finite("Sphere.latitude_circle", latitude=latitude)
        if not 0 < latitude < 180:
            raise HybridError(f"latitude = {latitude} degrees from the top; give a value in (0, 180)")
        c, polar = np.asarray(self.center, float), math.radians(latitude)
        rho, h = self.radius * math.sin(polar), self.radius * math.cos(polar)
        return CirclePath((c[0], c[1], c[2] + h), rho, rho * math.atan2(-c[1], -c[0]))

    def path(self) -> CirclePath:
        """The default path on a sphere: its latitude circle 60 degrees from the top.

        Returns
        -------
        CirclePath
            The circle (see :meth:`latitude_circle`).
        """
        return self.latitude_circle()

    def path_through(self, p) -> CirclePath:
        """The latitude circle through the point ``p`` of the sphere (about the vertical through its centre).

        Parameters
        ----------
        p : array_like
            A point of the sphere (3 coordinates) [m].

        Returns
        -------
        CirclePath or None
            The circle, its arc length at ``p`` its start; None at a pole.
        """
        p, c = np.asarray(p, float), np.asarray(self.center, float)
        rho = math.hypot(p[0] - c[0], p[1] - c[1])
        if rho < 1e-9:
            return None  # a pole: no circle through it
        path = CirclePath((c[0], c[1], float(p[2])), rho)
        return CirclePath(path.center, rho, path.arc_of(p))


@checked_keywords
@dataclass(frozen=True)
class Cylinder(Surface):
    r"""An infinite cylinder touched from outside: :math:`\varphi(p) = \lVert (I - u u^T)(p - p_0) \rVert - \rho`,
    with :math:`p_0` a point of its axis, :math:`u` the axis's unit direction and :math:`\rho` the radius.

    Parameters
    ----------
    point : array_like
        A point of its axis (3 coordinates) [m].
    axis : array_like
        The axis' direction ``u`` (3 coordinates; made unit).
    radius : float
        The radius [m], > 0.

    Raises
    ------
    HybridError
        Coordinates not finite or of the wrong number, an axis of zero length, or a radius not positive.

    Examples
    --------
    >>> import hybrid
    >>> pillar = hybrid.Cylinder(point=(0.5, 0.0, 0.0),
    ...                          axis=(0.0, 0.0, 1.0), radius=0.2)
    >>> pillar.normal_at([0.3, 0.0, 0.1]).tolist()
    [-1.0, 0.0, 0.0]
    >>> pillar.circle_at([0.3, 0.0, 0.1])  # doctest: +ELLIPSIS
    CirclePath(center=(0.5, 0.0, 0.1), radius=0.2, start=0.628...)
    """

    point: tuple[float, float, float]
    axis: tuple[float, float, float]
    radius: float
    kind = "cylinder"

    def __post_init__(self):
        object.__setattr__(self, "point", _point("Cylinder", "point", self.point, (3,)))
        object.__setattr__(self, "axis", unit_vector("Cylinder", "axis", _point("Cylinder", "axis", self.axis, (3,))))
        _positive("Cylinder", "radius", self.radius)

    parameters_named = PARAMETERS["cylinder"]
    formula = staticmethod(FORMULAS["cylinder"])

    def as_array(self) -> np.ndarray:
        """The generated code's run-time parameters of this surface.

        Returns
        -------
        numpy.ndarray
            ``point`` (3), ``axis`` (3), then ``radius``.
        """
        return np.array([*self.point, *self.axis, self.radius])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot, radially from the axis.

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The unit normal towards the robot (3).

        Raises
        ------
        HybridError
            ``p`` is on the axis.
        """
        d = np.asarray(p, float) - self.point
        radial = d - np.dot(d, self.axis) * np.asarray(self.axis)
        return _unit_normal(radial, f"the point {p} is on the cylinder's axis")

    def phi_function(self):
        """``phi`` and its gradient in NumPy: the distance from the axis less the radius, and the
        radial unit vector.

        Returns
        -------
        callable
            ``p -> (phi(p), grad phi(p))``, ``p`` a NumPy array of 3 coordinates.
        """
        theta = self.as_array()
        point, axis, rho = theta[:3], theta[3:6], theta[6]
        uu = axis @ axis

        def cylinder(p):
            d = p - point
            radial = d - axis * ((axis @ d) / uu)
            dist = math.sqrt(radial @ radial)
            return dist - rho, radial / dist
        return cylinder

    def project(self, p) -> np.ndarray:
        """The surface point nearest ``p`` (radially from the axis).

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The surface point (3) [m].
        """
        d = np.asarray(p, float) - self.point
        u = np.asarray(self.axis)
        return np.asarray(self.point) + np.dot(d, u) * u + self.radius * self.normal_at(p)

    def circle_at(self, point) -> CirclePath:
        """The circle around a vertical cylinder (axis along base z) through ``point``,
        counter-clockwise seen from +z, starting at ``point``.

        Parameters
        ----------
        point : array_like
            A point of the cylinder (3 coordinates) [m].

        Returns
        -------
        CirclePath
            The circle, its arc length at ``point`` its start.

        Raises
        ------
        HybridError
            The cylinder's axis is not along base z.
        """
        if abs(abs(self.axis[2]) - 1.0) > 1e-12:
            raise HybridError(f"Cylinder.circle_at needs a cylinder about base z, its axis is {self.axis}; "
                              "give the experiment a path of your own")
        p = np.asarray(_point("Cylinder.circle_at", "point", point, (3,)))
        path = CirclePath((self.point[0], self.point[1], float(p[2])), self.radius)
        return CirclePath(path.center, self.radius, path.arc_of(p))

    def path(self) -> CirclePath:
        """A cylinder has no path of its own: see :meth:`circle_at`.

        Returns
        -------
        CirclePath
            Never: this raises.

        Raises
        ------
        HybridError
            Always.
        """
        raise HybridError("a cylinder has no path of its own: give the experiment a path, e.g. "
                          "cylinder.circle_at(point)")

    def path_through(self, p) -> CirclePath | None:
        """The circle around a vertical cylinder through ``p``.

        Parameters
        ----------
        p : array_like
            A point of the cylinder (3 coordinates) [m].

        Returns
        -------
        CirclePath or None
            The circle of :meth:`circle_at`, or None for a cylinder that is not vertical.
        """
        return self.circle_at(p) if self.cross_section() is not None else None

    def cross_section(self) -> CircleSection | None:
        """The circle where a vertical cylinder cuts the base xy-plane.

        Returns
        -------
        CircleSection or None
            The circle, or None for a cylinder that is not vertical.
        """
        if self.axis[0] != 0.0 or self.axis[1] != 0.0:
            return None
        return _once(CircleSection, self.point[:2], self.radius)

