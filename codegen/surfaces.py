"""Surfaces ``phi(p) = 0`` and the task frame ``R_L(p)`` on them, with its exact ``R_L'(p, p')``.

Conventions of docs/conventions.md §9: ``phi > 0`` on the robot's side, unit
normal ``n = grad phi / |grad phi|`` from the surface to the robot; task-frame rows
``t1 = e x n / |e x n|``, ``t2 = n x t1``, ``n`` for a reference direction ``e``. ``R_L'`` is
the directional derivative of ``R_L`` along ``p'``: it carries the surface's curvature.

A surface is described by a :class:`hybrid.spec.surface.SurfaceSpec`: a kind, its
parameter names (run-time inputs of the generated C) and ``phi`` as a SymPy expression of
``x, y, z`` and those parameters (the built-in plane's, sphere's and cylinder's from their formulas there).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import casadi as ca
import sympy as sp

from hybrid.spec.surface import NORMAL_TOL, SurfaceSpec

from .casadi_backend import to_sx
from .factor import reciprocal
from .rigid_body import cross

X, Y, Z = sp.symbols("x y z", real=True)
#: below this ``|e x n|`` (the sine of the angle between ``e`` and ``n``) the task frame is undefined
FRAME_TOL = 1e-6


def phi_of(spec: SurfaceSpec) -> sp.Expr:
    """``phi`` of ``spec`` as a SymPy expression (a built-in surface's from its class's formula)."""
    if spec.phi is not None:
        return spec.phi
    return _built_in(spec.formula, spec.parameters)


@cache
def _built_in(formula, parameters: tuple[str, ...]) -> sp.Expr:
    return formula((X, Y, Z), sp.symbols(parameters, real=True), sp.sqrt)


def phi_sx(spec: SurfaceSpec, p, theta) -> ca.SX:
    """``phi`` as CasADi SX of the point ``p`` (3) and the parameter column ``theta``."""
    symbols = {X: p[0], Y: p[1], Z: p[2]}
    symbols.update({sp.Symbol(n, real=True): theta[i] for i, n in enumerate(spec.parameters)})
    phi = phi_of(spec)
    # the user's symbols may lack real=True: map them by name too
    by_name = {str(k): v for k, v in symbols.items()}
    for s in phi.free_symbols:
        if s not in symbols:
            symbols[s] = by_name[str(s)]
    return to_sx(phi, symbols, {})


@dataclass
class TaskFrame:
    """``R_L`` (3x3, rows t1, t2, n), its derivative ``R_L'``, and the frame's guard ``sine``: ``|e x n|``,
    0 where the surface has no normal (:func:`normal_defined`)."""

    R: ca.SX
    Rd: ca.SX
    sine: ca.SX
    normal: ca.SX


def task_frame(spec: SurfaceSpec, p, pd, theta, e) -> TaskFrame:
    """The task frame at ``p`` on ``spec`` for the reference direction ``e`` and its time
    derivative along ``p'`` (exact: a forward-mode directional derivative).

    ``p`` may be an expression (the arm's tip): the frame is derived on symbols, then applied.
    """
    args = [ca.SX.sym(name, size) for name, size in (("p", 3), ("pd", 3), ("theta", theta.shape[0]), ("e", 3))]
    f = ca.Function("task_frame", args, list(_frame_on_symbols(spec, *args)))
    return TaskFrame(*f(p, pd, theta, e))


def _frame_on_symbols(spec: SurfaceSpec, p, pd, theta, e):
    phi = phi_sx(spec, p, theta)
    grad = ca.gradient(phi, p)
    size = ca.norm_2(grad)
    n = grad * reciprocal(size)
    e_unit = e * reciprocal(ca.norm_2(e))
    c = cross(e_unit, n)
    sine = ca.norm_2(c)
    t1 = c * reciprocal(sine)
    t2 = cross(n, t1)
    R = ca.vertcat(t1.T, t2.T, n.T)
    Rd = ca.reshape(ca.jtimes(ca.reshape(R, 9, 1), p, pd), 3, 3)
    # the guard: 0 where a finite point has no normal; a non-finite point's spread is NaN or infinite, never
    # below the tolerance (the kernel's non-finite check names the input, not the frame)
    spread = ca.fabs(p[0]) + ca.fabs(p[1]) + ca.fabs(p[2])
    guard = ca.if_else(normal_defined(size), sine, ca.if_else(spread <= _DBL_MAX, 0, spread))
    return R, Rd, guard, n


def normal_defined(size) -> ca.SX:
    """1 where ``|grad phi| = size`` gives a normal: above :data:`NORMAL_TOL` and finite (a comparison with
    NaN is false: a formula undefined at the point, its gradient NaN or infinite, gives none), else 0."""
    return ca.logic_and(size > NORMAL_TOL, size <= _DBL_MAX)


#: the largest double: ``x <= _DBL_MAX`` is false for an infinity and for NaN
_DBL_MAX = 1.7976931348623157e308
