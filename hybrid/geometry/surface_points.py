"""Many points onto a surface at once: ``phi`` and its gradient vectorised over points, and the
projection of points onto ``phi = 0`` by Newton's method along the gradient.

A path drawn on a surface is made of thousands of such points (its samples and its arc-length
table); the surfaces' own ``project`` and ``normal_at`` take one point at a time. SymPy is loaded on
the first use (the surface's formula is turned into NumPy once per surface).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from hybrid.errors import HybridError

#: Newton's steps stop when every point's ``|phi|`` [m, for a distance-like phi] is below this
PHI_TOL = 1e-14
#: the most Newton steps a projection takes
MAX_STEPS = 50


@lru_cache(maxsize=64)
def _vectorised(surface):
    """``P -> (phi(P), grad phi(P))`` for the points ``P`` (N x 3), NaN where ``phi`` is undefined: the
    surface's own where it evaluates many points itself (a part's fitted grid), else its formula's."""
    own = getattr(surface, "phi_and_gradient", None)
    if own is not None:
        return own
    import sympy as sp

    xyz = sp.symbols("x y z", real=True)
    if surface.kind == "implicit":  # a user's ImplicitSurface: its own phi, the parameters bound
        values = {sp.Symbol(k, real=True): float(v) for k, v in surface.parameters.items()}
        phi = surface.phi.xreplace(values)
    else:
        phi = surface.formula(xyz, [sp.Float(v) for v in surface.as_array()], sp.sqrt)
    f = sp.lambdify(xyz, [phi, *(sp.diff(phi, v) for v in xyz)], modules="numpy")

    def evaluate(P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        with np.errstate(all="ignore"):  # an undefined formula gives NaN, checked by the caller
            value, *grad = f(P[:, 0], P[:, 1], P[:, 2])
        value = np.array(np.broadcast_to(np.asarray(value, dtype=float), (len(P),)))
        grad = np.column_stack([np.broadcast_to(np.asarray(g, dtype=float), (len(P),)) for g in grad])
        return value, grad
    return evaluate


def phi_and_normal(surface, P) -> tuple[np.ndarray, np.ndarray]:
    """``phi`` at the points ``P`` (N x 3) and the unit normals ``grad phi / |grad phi|`` there (NaN where
    either is undefined or the gradient vanishes)."""
    P = np.asarray(P, dtype=float).reshape(-1, 3)
    value, grad = _vectorised(surface)(P)
    norm = np.linalg.norm(grad, axis=1)
    with np.errstate(all="ignore"):
        normal = grad / norm[:, None]
    bad = ~(np.isfinite(value) & np.isfinite(norm) & (norm > 0))
    value[bad] = np.nan
    normal[bad] = np.nan
    return value, normal


def project_points(surface, P, owner: str) -> tuple[np.ndarray, np.ndarray]:
    """The points ``P`` (N x 3) moved onto ``phi = 0`` along the gradient (Newton's method; on a plane,
    sphere or cylinder, whose ``phi`` is the signed distance, the nearest surface point) and the unit
    normals there. A point where ``phi`` is undefined or has no gradient, or where Newton's method does
    not converge, is a HybridError naming ``owner`` and the point."""
    Q = np.array(P, dtype=float).reshape(-1, 3)
    for _ in range(MAX_STEPS):
        value, grad = _vectorised(surface)(Q)
        g2 = np.einsum("ij,ij->i", grad, grad)
        bad = ~(np.isfinite(value) & np.isfinite(g2) & (g2 > 0))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise HybridError(f"{owner} leaves the surface's domain near {np.round(P[i], 6).tolist()} m: phi or its "
                              "gradient is undefined there (the projection onto the surface fails); keep the path "
                              "where phi is defined")
        if np.max(np.abs(value) / np.sqrt(g2)) <= PHI_TOL:
            return Q, grad / np.sqrt(g2)[:, None]
        Q = Q - (value / g2)[:, None] * grad
    i = int(np.argmax(np.abs(value)))
    raise HybridError(f"{owner}: the point {np.round(P[i], 6).tolist()} m does not project onto the surface "
                      f"(phi = {value[i]:.3g} after {MAX_STEPS} Newton steps); keep the path nearer the surface")
