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

import ast
import keyword
import math
from dataclasses import dataclass

import numpy as np
import sympy as sp

from codegen import surfaces as cs

from .errors import HybridError
from .validate import _finite, _point, unit_vector


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
class Circle:
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
class Plane:
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

    def spec(self) -> cs.SurfaceSpec:
        self._spatial()
        return cs.builtin("plane")

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


class _Spatial:
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

    def spec(self) -> cs.SurfaceSpec:
        return cs.builtin("sphere")

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

    def spec(self) -> cs.SurfaceSpec:
        return cs.builtin("cylinder")

    def as_array(self) -> np.ndarray:
        return np.array([*self.point, *self.axis, self.radius])

    def normal_at(self, p) -> np.ndarray:
        d = np.asarray(p, float) - self.point
        radial = d - np.dot(d, self.axis) * np.asarray(self.axis)
        return _unit_normal(radial, f"the point {p} is on the cylinder's axis")


@dataclass(frozen=True)
class ImplicitSurface(_Spatial):
    """Any surface ``phi(x, y, z) = 0`` written in SymPy, ``phi > 0`` on the robot's side.

    ``parameters`` maps the names of ``phi``'s other symbols to their values (run-time inputs
    of the generated code: changing a value never regenerates). ``phi`` may be a SymPy
    expression or a string SymPy can parse, e.g. an ellipsoid
    ``ImplicitSurface("(x/a)**2 + (y/b)**2 + (z/c)**2 - 1", {"a": 0.3, "b": 0.2, "c": 0.1})``.
    """

    phi: object
    parameters: dict
    kind = "implicit"

    def __post_init__(self):
        if not isinstance(self.parameters, dict):
            raise HybridError(f"ImplicitSurface.parameters must be a {{name: value}} dict, got "
                              f"{type(self.parameters).__name__}")
        for name, value in self.parameters.items():
            if not isinstance(name, str) or not name.isidentifier() or keyword.iskeyword(name) \
                    or name in ("x", "y", "z"):
                raise HybridError(f"ImplicitSurface parameter name {name!r} must be an identifier other "
                                  "than x, y, z")
            _finite("ImplicitSurface", **{name: value})
        phi = self.phi
        if isinstance(phi, str):
            phi = parse_phi(phi, tuple(self.parameters))
        if not isinstance(phi, sp.Expr):
            raise HybridError(f"ImplicitSurface.phi must be a SymPy expression of x, y, z, got {type(phi).__name__}")
        # one symbol per name, real, whatever assumptions the user's symbols carried
        phi = phi.xreplace({s: sp.Symbol(str(s), real=True) for s in phi.free_symbols})
        names = {str(s) for s in phi.free_symbols}
        if not names & {"x", "y", "z"}:
            raise HybridError(f"ImplicitSurface.phi = {phi} does not depend on x, y or z")
        unknown = names - {"x", "y", "z"} - set(self.parameters)
        if unknown:
            raise HybridError(f"ImplicitSurface.phi uses {', '.join(sorted(unknown))}, which parameters "
                              "does not give; add their values to parameters")
        spec = cs.implicit(phi, tuple(self.parameters))
        try:  # fail here, not at code generation, on a function the backend cannot translate
            import casadi as ca

            cs.phi_sx(spec, ca.SX.sym("p", 3), ca.SX.sym("theta", max(len(self.parameters), 1)))
        except (NotImplementedError, TypeError, ValueError, RuntimeError) as exc:
            raise HybridError(f"ImplicitSurface.phi cannot be translated ({str(exc)[:80]}); write phi with +, -, "
                              "*, /, powers, sqrt, exp, log, trigonometric and hyperbolic functions, Abs, Min, "
                              "Max") from None
        object.__setattr__(self, "phi", phi)
        object.__setattr__(self, "_spec", spec)

    def __hash__(self):
        return hash((self.phi, tuple(self.parameters.items())))

    def spec(self) -> cs.SurfaceSpec:
        return self._spec

    def as_array(self) -> np.ndarray:
        return np.array([float(v) for v in self.parameters.values()])

    def normal_at(self, p) -> np.ndarray:
        x, y, z = sp.symbols("x y z", real=True)
        grad = [sp.diff(self.phi, s) for s in (x, y, z)]
        subs = {x: p[0], y: p[1], z: p[2], **{sp.Symbol(k, real=True): v for k, v in self.parameters.items()}}
        g = np.array([float(gi.subs(subs)) for gi in grad])
        return _unit_normal(g, f"grad phi vanishes at {p}")


#: what a surface written as text may use besides numbers, x, y, z and its parameters
PHI_FUNCTIONS = ("sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "log", "sqrt",
                 "Abs", "Min", "Max")
PHI_CONSTANTS = ("pi", "E")
MAX_PHI_CHARS = 2000
_PHI_NODES = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow,
              ast.USub, ast.UAdd, ast.Load, ast.Name, ast.Constant, ast.Call)


def parse_phi(text: str, parameters: tuple[str, ...]) -> sp.Expr:
    """``phi`` written as text, read without running it: only arithmetic, numbers, ``x, y, z``,
    the parameters, :data:`PHI_FUNCTIONS` and :data:`PHI_CONSTANTS` are accepted."""
    shown = f"{text[:60]!r}" + ("..." if len(text) > 60 else "")
    if len(text) > MAX_PHI_CHARS:
        raise HybridError(f"ImplicitSurface.phi is {len(text)} characters; write it in at most {MAX_PHI_CHARS}")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise HybridError(f"ImplicitSurface.phi {shown} is not an expression ({exc.msg}, "
                          f"column {exc.offset})") from None
    names = {*parameters, "x", "y", "z", *PHI_FUNCTIONS, *PHI_CONSTANTS}
    for node in ast.walk(tree):
        bad = None
        if not isinstance(node, _PHI_NODES):
            bad = f"{type(node).__name__.lower()} syntax"
        elif isinstance(node, ast.Name) and node.id not in names:
            bad = f"the name {node.id!r} (not x, y, z, a parameter, a known function or pi, E)"
        elif isinstance(node, ast.Constant) and (not isinstance(node.value, (int, float))
                                                 or isinstance(node.value, bool) or not abs(node.value) < 1e300):
            bad = f"the constant {node.value!r:.30}"
        elif isinstance(node, ast.Call) and (node.keywords or not isinstance(node.func, ast.Name)
                                             or node.func.id not in PHI_FUNCTIONS):
            bad = "a call that is not one of " + ", ".join(PHI_FUNCTIONS)
        elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow) and not _small_exponent(node.right):
            bad = "an exponent that is not a number of at most 64 in size or an expression of x, y, z"
        if bad:
            raise HybridError(f"ImplicitSurface.phi {shown} uses {bad}; write phi with +, -, *, /, **, numbers, "
                              "x, y, z, its parameters and " + ", ".join(PHI_FUNCTIONS))
    symbols = {n: sp.Symbol(n, real=True) for n in (*parameters, "x", "y", "z")}
    return sp.sympify(text, locals=symbols, evaluate=False)


def _small_exponent(node) -> bool:
    """An exponent is a number of size at most 64, or anything involving a name (not a tower of numbers)."""
    if any(isinstance(n, ast.Name) for n in ast.walk(node)):
        return True
    if isinstance(node, ast.UnaryOp):
        node = node.operand
    return isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and abs(node.value) <= 64


PlanarSurface = Circle | Plane
Surface = Circle | Plane | Sphere | Cylinder | ImplicitSurface
