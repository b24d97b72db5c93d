"""A surface a user writes down: ``phi(x, y, z) = 0`` as a SymPy expression or as text.

Text is parsed, not run: :func:`parse_phi` accepts only arithmetic, numbers, ``x, y, z``, the
surface's parameters and the functions of :data:`PHI_FUNCTIONS`. Loaded on first use of
:class:`ImplicitSurface` (it needs SymPy, and the generator to check that ``phi`` translates).
"""

from __future__ import annotations

import ast
import hashlib
import keyword
from dataclasses import dataclass

import casadi as ca
import numpy as np
import sympy as sp

from hybrid.codegen import surfaces as cs
from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Surface, SurfaceSpec, _unit_normal
from hybrid.validate import _finite


@dataclass(frozen=True)
class ImplicitSurface(Surface):
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
        spec = implicit_spec(phi, tuple(self.parameters))
        try:  # fail here, not at code generation, on a function the backend cannot translate
            cs.phi_sx(spec, ca.SX.sym("p", 3), ca.SX.sym("theta", max(len(self.parameters), 1)))
        except (NotImplementedError, TypeError, ValueError, RuntimeError) as exc:
            raise HybridError(f"ImplicitSurface.phi cannot be translated ({str(exc)[:80]}); write phi with +, -, "
                              "*, /, powers, sqrt, exp, log, trigonometric and hyperbolic functions, Abs, Min, "
                              "Max") from None
        object.__setattr__(self, "phi", phi)
        object.__setattr__(self, "_spec", spec)

    def __hash__(self):
        return hash((self.phi, tuple(self.parameters.items())))

    def spec(self) -> SurfaceSpec:
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


def implicit_spec(phi: sp.Expr, parameters: tuple[str, ...]) -> SurfaceSpec:
    """The spec of a user's surface, its kind named by a digest of ``phi`` (one generated unit each)."""
    text = sp.srepr(phi)
    key = SurfaceSpec("implicit", tuple(parameters), phi, text).key()
    return SurfaceSpec(f"implicit_{hashlib.sha256(key.encode()).hexdigest()[:12]}", tuple(parameters), phi, text)


