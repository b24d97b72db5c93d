"""A surface a user writes down: ``phi(x, y, z) = 0`` as a SymPy expression or as text.

Text is parsed, not run: :func:`parse_phi` accepts only arithmetic, numbers, ``x, y, z``, the
surface's parameters and the functions of :data:`PHI_FUNCTIONS`. Loaded on first use of
:class:`ImplicitSurface` (it needs SymPy, and the generator to check that ``phi`` translates).
"""

from __future__ import annotations

import ast
import hashlib
import math
import operator
from dataclasses import dataclass

import casadi as ca
import numpy as np
import sympy as sp

from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Surface, _unit_normal, numpy_phi
from hybrid.native import generator
from hybrid.spec.surface import SurfaceSpec
from hybrid.validate import _finite, check_identifier, checked_keywords, shown


@checked_keywords
@dataclass(frozen=True)
class ImplicitSurface(Surface):
    """Any surface ``phi(x, y, z) = 0`` written in SymPy, ``phi > 0`` on the robot's side.

    Parameters
    ----------
    phi : sympy.Expr or str
        ``phi(x, y, z)``, a SymPy expression of the symbols ``x, y, z`` and the parameters, or text
        (read without running it: arithmetic, numbers, ``x, y, z``, the parameters and the functions
        of :data:`PHI_FUNCTIONS`).
    parameters : dict
        The values of ``phi``'s other symbols, by name (run-time inputs of the generated code:
        changing a value never regenerates).

    Raises
    ------
    HybridError
        ``phi`` not an expression of ``x, y, z``, a symbol without a value, a value not finite, text
        that is not such a formula, or a function the code generator cannot translate.

    Examples
    --------
    An ellipsoid of semi-axes 0.3, 0.2 and 0.1 m:

    >>> import hybrid
    >>> ellipsoid = hybrid.ImplicitSurface(
    ...     "(x/a)**2 + (y/b)**2 + (z/c)**2 - 1",
    ...     {"a": 0.3, "b": 0.2, "c": 0.1})
    >>> ellipsoid.normal_at([0.0, 0.0, 0.1]).tolist()
    [0.0, 0.0, 1.0]
    >>> ellipsoid.as_array().tolist()
    [0.3, 0.2, 0.1]
    """

    phi: object
    parameters: dict
    kind = "implicit"

    def __post_init__(self):
        if not isinstance(self.parameters, dict):
            raise HybridError(f"ImplicitSurface.parameters must be a {{name: value}} dict, got "
                              f"{type(self.parameters).__name__}")
        check_parameter_names(tuple(self.parameters))
        for name, value in self.parameters.items():
            _finite("ImplicitSurface", **{name: value})
        phi = self.phi
        if isinstance(phi, str):
            phi = parse_phi(phi, tuple(self.parameters))
        if not isinstance(phi, sp.Expr):
            raise HybridError(f"ImplicitSurface.phi must be a SymPy expression of x, y, z, got {type(phi).__name__}")
        bad = _non_finite(phi)
        if bad is not None:
            raise HybridError(f"ImplicitSurface.phi = {shown(phi, 60)} has the value {bad}; write phi with real, "
                              "finite values\n  (a division by zero, the log of 0, the root of a negative number or a "
                              "number beyond float range)")
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
            generator.api().phi_sx(spec, ca.SX.sym("p", 3), ca.SX.sym("theta", max(len(self.parameters), 1)))
        except (NotImplementedError, TypeError, ValueError, RuntimeError) as exc:
            raise HybridError(f"ImplicitSurface.phi cannot be translated ({str(exc)[:80]}); write phi with +, -, "
                              "*, /, powers, sqrt, exp, log, trigonometric and hyperbolic functions, Abs, Min, "
                              "Max") from None
        object.__setattr__(self, "phi", phi)
        object.__setattr__(self, "_spec", spec)

    def __hash__(self):
        return hash((self.phi, tuple(self.parameters.items())))

    def spec(self) -> SurfaceSpec:
        """What the code generator needs of this surface.

        Returns
        -------
        SurfaceSpec
            ``phi`` and its parameters' names, its kind named by a digest of ``phi``.
        """
        return self._spec

    def as_array(self) -> np.ndarray:
        """The generated code's run-time parameters of this surface.

        Returns
        -------
        numpy.ndarray
            The values of ``parameters``, in their order.
        """
        return np.array([float(v) for v in self.parameters.values()])

    def normal_at(self, p) -> np.ndarray:
        """Unit normal towards the robot, ``grad phi / |grad phi|``.

        Parameters
        ----------
        p : array_like
            A point (3 coordinates) [m].

        Returns
        -------
        numpy.ndarray
            The unit normal (3).

        Raises
        ------
        HybridError
            ``phi`` or its gradient is undefined at ``p``, or the gradient vanishes there.
        """
        x, y, z = sp.symbols("x y z", real=True)
        grad = [sp.diff(self.phi, s) for s in (x, y, z)]
        subs = {x: p[0], y: p[1], z: p[2], **{sp.Symbol(k, real=True): v for k, v in self.parameters.items()}}
        try:
            g = np.array([float(gi.subs(subs)) for gi in grad])
        except (TypeError, ValueError, OverflowError):  # complex or infinite: phi is undefined at p
            g = np.full(3, np.nan)
        if not np.isfinite(g).all():
            raise HybridError(f"ImplicitSurface.phi = {shown(self.phi, 60)} is undefined at {tuple(p)} (grad phi = "
                              f"{g.tolist()}): the surface has no normal there; give a point where phi and its "
                              "gradient are finite numbers")
        return _unit_normal(g, f"grad phi vanishes at {tuple(p)}")

    def phi_function(self):
        """``phi`` and its gradient in NumPy, ``phi``'s parameters bound.

        Returns
        -------
        callable
            ``p -> (phi(p), grad phi(p))``, ``p`` 3 coordinates; NaN where ``phi`` is undefined.
        """
        values = {sp.Symbol(k, real=True): float(v) for k, v in self.parameters.items()}
        return numpy_phi(self.phi.xreplace(values), sp.symbols("x y z", real=True))


#: what a surface written as text may call, with the least and most arguments of each (None: any)
PHI_FUNCTIONS = {"sin": (1, 1), "cos": (1, 1), "tan": (1, 1), "asin": (1, 1), "acos": (1, 1), "atan": (1, 1),
                 "sinh": (1, 1), "cosh": (1, 1), "tanh": (1, 1), "exp": (1, 1), "log": (1, 1), "sqrt": (1, 1),
                 "Abs": (1, 1), "Min": (2, None), "Max": (2, None)}
PHI_CONSTANTS = {"pi": sp.pi, "E": sp.E}
MAX_PHI_CHARS = 2000
#: the deepest nesting of operations in a formula (SymPy and the generator walk it recursively)
MAX_PHI_DEPTH = 100
_PHI_NODES = (ast.BinOp, ast.UnaryOp, ast.Name, ast.Constant, ast.Call)
_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.Pow: operator.pow}
_UNARY = {ast.USub: operator.neg, ast.UAdd: operator.pos}


def check_parameter_names(parameters: tuple) -> None:
    """Each parameter name an ASCII identifier that is none of ``x, y, z`` and does not hide one
    of the functions or constants a formula may use."""
    for name in parameters:
        check_identifier("ImplicitSurface parameter name", name)
        if name in ("x", "y", "z"):
            raise HybridError(f"ImplicitSurface parameter name {name!r} must be an identifier other than x, y, z")
        if name in PHI_FUNCTIONS or name in PHI_CONSTANTS:
            what = "function" if name in PHI_FUNCTIONS else "constant"
            raise HybridError(f"ImplicitSurface parameter name {name!r} hides the {what} {name} of phi's "
                              "formulas; rename the parameter")


def _arity(name: str) -> str:
    least, most = PHI_FUNCTIONS[name]
    if least == most:
        return f"{least} argument" + ("s" if least != 1 else "")
    return f"at least {least} arguments" if most is None else f"{least} to {most} arguments"


def parse_phi(text: str, parameters: tuple[str, ...]) -> sp.Expr:
    """``phi`` written as text, read without running it: only arithmetic, numbers, ``x, y, z``,
    the parameters, :data:`PHI_FUNCTIONS` (each with its number of arguments) and
    :data:`PHI_CONSTANTS` are accepted. The expression is built from the checked syntax tree
    itself (no SymPy parser, whose own names a parameter could hide)."""
    if not isinstance(text, str):
        raise HybridError(f"ImplicitSurface.phi as text must be a str, got {type(text).__name__}")
    check_parameter_names(tuple(parameters))
    shown_text = f"{text[:60]!r}" + ("..." if len(text) > 60 else "")
    if len(text) > MAX_PHI_CHARS:
        raise HybridError(f"ImplicitSurface.phi is {len(text)} characters; write it in at most {MAX_PHI_CHARS}")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise HybridError(f"ImplicitSurface.phi {shown_text} is not an expression ({exc.msg}, "
                          f"column {exc.offset})") from None
    except (RecursionError, MemoryError):  # the parser's own limit on nesting
        raise HybridError(f"ImplicitSurface.phi {shown_text} is nested too deeply; write it with at most "
                          f"{MAX_PHI_DEPTH} levels of operations") from None
    symbols = {n: sp.Symbol(n, real=True) for n in (*parameters, "x", "y", "z")}

    def refuse(bad: str):
        raise HybridError(f"ImplicitSurface.phi {shown_text} uses {bad}; write it with the operations below\n"
                          "  +, -, *, /, **, numbers, x, y, z, its parameters, pi, E and " + ", ".join(PHI_FUNCTIONS))

    # post-order over the tree with an explicit stack: a long formula cannot exhaust Python's recursion
    done: dict[int, sp.Expr] = {}
    stack = [(tree.body, 1, False)]
    while stack:
        node, depth, ready = stack.pop()
        if depth > MAX_PHI_DEPTH:
            raise HybridError(f"ImplicitSurface.phi {shown_text} is nested more than {MAX_PHI_DEPTH} levels deep; "
                              "write it more simply")
        kids = _operands(node, refuse)
        if not ready:
            stack.append((node, depth, True))
            # SymPy flattens a chain of sums (or of products) into one node: only other operations nest
            stack.extend((k, depth + (0 if _group(k) is not None and _group(k) == _group(node) else 1), False)
                         for k in kids)
            continue
        done[id(node)] = _build(node, [done.pop(id(k)) for k in kids], symbols, refuse)
    return done[id(tree.body)]


def _group(node) -> str | None:
    """``"sum"`` or ``"product"`` for a node SymPy merges with a parent of the same group."""
    if isinstance(node, ast.BinOp):
        return {ast.Add: "sum", ast.Sub: "sum", ast.Mult: "product", ast.Div: "product"}.get(type(node.op))
    return None


def _operands(node, refuse) -> list:
    """The operands of one node of a formula, after checking the node itself."""
    if not isinstance(node, _PHI_NODES):
        refuse(f"{type(node).__name__.lower()} syntax")
    if isinstance(node, ast.BinOp):
        if type(node.op) not in _BINARY:
            refuse(f"the operator {type(node.op).__name__}")
        if isinstance(node.op, ast.Pow) and not _small_exponent(node.right):
            refuse("an exponent that is not a number of at most 64 in size or an expression of x, y, z")
        return [node.left, node.right]
    if isinstance(node, ast.UnaryOp):
        if type(node.op) not in _UNARY:
            refuse(f"the operator {type(node.op).__name__}")
        return [node.operand]
    if isinstance(node, ast.Call):
        if node.keywords or not isinstance(node.func, ast.Name) or node.func.id not in PHI_FUNCTIONS:
            called = node.func.id if isinstance(node.func, ast.Name) else "an expression"
            refuse(f"a call of {called!r}, not one of the functions below" if not node.keywords
                   else "a call with keyword arguments")
        name, n = node.func.id, len(node.args)
        least, most = PHI_FUNCTIONS[name]
        if n < least or (most is not None and n > most):
            refuse(f"{name} with {n} argument{'s' if n != 1 else ''} ({name} takes {_arity(name)})")
        return list(node.args)
    return []


def _build(node, args: list, symbols: dict, refuse) -> sp.Expr:
    """The SymPy expression of one checked node from those of its operands."""
    if isinstance(node, ast.BinOp):
        return _BINARY[type(node.op)](*args)
    if isinstance(node, ast.UnaryOp):
        return _UNARY[type(node.op)](args[0])
    if isinstance(node, ast.Call):
        return getattr(sp, node.func.id)(*args)
    if isinstance(node, ast.Name):
        if node.id in symbols:
            return symbols[node.id]
        if node.id in PHI_CONSTANTS:
            return PHI_CONSTANTS[node.id]
        if node.id in PHI_FUNCTIONS:
            refuse(f"the function {node.id} without calling it")
        refuse(f"the name {node.id!r} (not x, y, z, a parameter, a known function or pi, E)")
    value = node.value
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not abs(value) < 1e300:
        refuse(f"the constant {shown(value, 30)}")
    return sp.Integer(value) if isinstance(value, int) else sp.Float(value)


def _non_finite(phi: sp.Expr) -> str | None:
    """A value of ``phi`` that C cannot hold as a finite double (zoo, nan, oo, I, 1e400), or None."""
    for bad in (sp.zoo, sp.nan, sp.oo, -sp.oo, sp.I):
        if phi.has(bad):
            return str(bad)
    for number in phi.atoms(sp.Number):
        try:
            ok = math.isfinite(float(number))
        except (OverflowError, TypeError, ValueError):
            ok = False
        if not ok:
            return str(number.evalf(6))[:30]
    for term in phi.atoms(sp.Function, sp.Pow):  # a constant part such as acos(2) or (-8)**(1/3)
        if not term.free_symbols:
            value = complex(term.evalf())
            if not (math.isfinite(value.real) and value.imag == 0):
                return f"{term} = {value:.6g}"
    return None


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


