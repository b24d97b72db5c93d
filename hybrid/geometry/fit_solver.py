"""The normal equations of a part's fit solved: conjugate gradients preconditioned on the B-spline grid and on
two grids each twice as coarse as the one before.

The fit (:mod:`hybrid.geometry.part_fit`) minimises ``|A C - b|^2 + ridge |C - C_0|^2`` over the coefficients
``C`` of a tricubic B-spline: its normal matrix ``N = A^T A + ridge I`` is applied as ``A^T (A x)``. Formed, it
would hold up to 343 numbers a row, three times A's (390 MB on the bench's sphere at 6 mm), and forming it
takes longer than the whole solve: that rules out the preconditioners that need it (incomplete Cholesky,
algebraic multigrid). Its diagonal alone (Jacobi) leaves the smooth errors, which the second differences and
the ridge alone hold, to many iterations.

The preconditioner adds to the diagonal's correction the same correction on two coarser grids (an additive
multilevel preconditioner, Bramble, Pasciak and Xu 1990): a cubic B-spline on a grid of spacing ``2 h`` is
exactly a B-spline on the grid of spacing ``h`` (:func:`refined`, the subdivision ``[1, 4, 6, 4, 1] / 8``), so
the residual is taken to the coarse grid by the subdivision's transpose (:func:`coarsened`), divided there by
the diagonal of ``P^T N P`` and brought back, weighted by :data:`LEVEL_WEIGHT` per level. The preconditioner is
a fixed symmetric positive definite operator, so the iteration is plain preconditioned conjugate gradients,
stopped where the residual is :data:`~hybrid.geometry.part_fit.TOLERANCE` of the right-hand side's norm (as
SciPy's ``cg``): the solution is the one the diagonal alone converges to, within that tolerance, in a
third to a sixth of the iterations.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

#: the weight of each coarser grid's correction (a grid ``l`` levels coarse weighs ``LEVEL_WEIGHT ** l``) and
#: the coarser grids used: the fewest iterations measured over 0.2 to 0.7 and one to four grids (the bench's
#: sphere at 6 mm: 24 iterations against the diagonal's 82; the tests' torus, box and bowl about 35 against 170;
#: a noisy scan smoothed 20 times the default, 80 against 500). A third grid saves an iteration or two and
#: costs them back
LEVEL_WEIGHT = 0.4
LEVELS = 2


def coarse_shape(shape: tuple[int, ...]) -> tuple[int, ...]:
    """The coefficients' shape of the grid twice as coarse that :func:`refined` takes to ``shape``."""
    return tuple((n + 2) // 2 + 2 for n in shape)


def refined(coarse: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """The coefficients on a grid of ``shape`` (spacing ``h``, origin ``o``) of the B-spline whose coefficients
    on the grid twice as coarse (spacing ``2 h``, origin ``o - 2 h``) are ``coarse``: along each axis the fine
    coefficient ``2 i`` is ``(c[i+1] + c[i+2]) / 2`` and ``2 i + 1`` is ``(c[i+1] + 6 c[i+2] + c[i+3]) / 8``.

    Examples
    --------
    A linear function's coefficients are its values at the coefficients' places: refined, they stay so (the
    coarse ones at -4, -2, 0, ... fine cells from the fine grid's origin, the fine ones at -1, 0, 1, ...).

    >>> refined(np.arange(6.0), (7,)).tolist()
    [1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5]
    """
    out = coarse
    for axis, n in enumerate(shape):
        c = np.moveaxis(out, axis, 0)
        even, odd = (n + 1) // 2, n // 2
        fine = np.empty((n, *c.shape[1:]))
        fine[0::2] = 0.5 * (c[1:even + 1] + c[2:even + 2])
        fine[1::2] = 0.75 * c[2:odd + 2] + 0.125 * (c[1:odd + 1] + c[3:odd + 3])
        out = np.moveaxis(fine, 0, axis)
    return out


def coarsened(fine: np.ndarray) -> np.ndarray:
    """The transpose of :func:`refined`: a fine grid's residual taken to the grid twice as coarse."""
    out = fine
    for axis, n in enumerate(fine.shape):
        f = np.moveaxis(out, axis, 0)
        even, odd = (n + 1) // 2, n // 2
        c = np.zeros(((n + 2) // 2 + 2, *f.shape[1:]))
        c[1:even + 1] += 0.5 * f[0::2]
        c[2:even + 2] += 0.5 * f[0::2]
        c[2:odd + 2] += 0.75 * f[1::2]
        c[1:odd + 1] += 0.125 * f[1::2]
        c[3:odd + 3] += 0.125 * f[1::2]
        out = np.moveaxis(c, 0, axis)
    return out


def multilevel(unknown: np.ndarray, diagonal: np.ndarray,
               coarse_diagonals: list[np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """The preconditioner (module docstring): ``r -> r / diagonal + sum_l w^l P_l (P_l^T r / D_l)``, for the
    residual ``r`` of the ``unknown`` coefficients (a mask of the grid), ``diagonal`` the normal matrix's and
    ``coarse_diagonals`` those of ``P_l^T N P_l`` on the grids ``l = 1, 2, ...`` levels coarse (each of
    :func:`coarse_shape` of the one before; zero where no unknown is reached)."""
    # each coarse level's inverse diagonal with its weight w^l, taken once (the same products at every iteration)
    weighted = [LEVEL_WEIGHT ** level * np.divide(1.0, d, out=np.zeros_like(d), where=d > 0)
                for level, d in enumerate(coarse_diagonals, start=1)]
    shapes = [unknown.shape]
    for _ in coarse_diagonals:
        shapes.append(coarse_shape(shapes[-1]))

    def apply(r: np.ndarray) -> np.ndarray:
        full = np.zeros(unknown.shape)
        full[unknown] = r
        residuals = [full]
        for _ in weighted:
            residuals.append(coarsened(residuals[-1]))
        correction = np.zeros(shapes[-1])
        for level in range(len(weighted), 0, -1):  # from the coarsest: each level's correction, then refined
            correction = refined(correction + weighted[level - 1] * residuals[level], shapes[level - 1])
        return r / diagonal + correction[unknown]

    return apply


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    """``a . b`` on this thread: BLAS's threads, woken for each product between the matrix's products, cost
    tens of milliseconds a product on a loaded machine (a whole iteration's work)."""
    return float(np.einsum("i,i->", a, b))


def conjugate_gradients(apply: Callable[[np.ndarray], np.ndarray], right: np.ndarray, start: np.ndarray,
                        precondition: Callable[[np.ndarray], np.ndarray], tolerance: float,
                        most: int) -> tuple[np.ndarray, int, bool]:
    """Preconditioned conjugate gradients for ``apply(x) = right`` from ``start``, stopped where the residual's
    norm is ``tolerance`` of ``right``'s (SciPy's ``cg``'s test): the solution, the iterations taken and whether
    it converged within ``most``.

    Examples
    --------
    >>> matrix = np.array([[4.0, 1.0], [1.0, 3.0]])
    >>> x, iterations, converged = conjugate_gradients(lambda v: matrix @ v, np.array([1.0, 2.0]), np.zeros(2),
    ...                                                lambda r: r / np.diag(matrix), 1e-12, 10)
    >>> np.round(x, 6).tolist(), iterations, converged
    ([0.090909, 0.636364], 2, True)
    """
    x = start.copy()
    r = right - apply(x)
    goal = tolerance * np.sqrt(_dot(right, right))
    z = precondition(r)
    p = z.copy()
    rz = _dot(r, z)
    for k in range(most):
        if np.sqrt(_dot(r, r)) <= goal:
            return x, k, True
        q = apply(p)
        alpha = rz / _dot(p, q)
        x += alpha * p
        r -= alpha * q
        z = precondition(r)
        rz, previous = _dot(r, z), rz
        p *= rz / previous
        p += z
    return x, most, bool(np.sqrt(_dot(r, r)) <= goal)
