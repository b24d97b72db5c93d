"""A function of space as a uniform tricubic B-spline: ``phi``, its gradient and its Hessian anywhere on its grid.

The grid has its first cell's corner at ``origin`` [m], cubic cells of side ``spacing`` [m] and
``coefficients`` of shape ``(nx + 3, ny + 3, nz + 3)`` for ``nx x ny x nz`` cells: in the cell ``(i, j, k)``,
at the fractions ``(t, u, w)`` of its sides,

    phi = sum_{a,b,c = 0..3} C[i + a, j + b, k + c] B_a(t) B_b(u) B_c(w)

with the uniform cubic B-spline's pieces ``B_0 = (1 - t)^3 / 6``, ``B_1 = (3 t^3 - 6 t^2 + 4) / 6``,
``B_2 = (-3 t^3 + 3 t^2 + 3 t + 1) / 6``, ``B_3 = t^3 / 6``: continuous to the second derivative everywhere.
A coefficient that is not a number (NaN) marks where the function is not defined: a point whose 64
coefficients are not all numbers has none (off the fitted band of a part, :mod:`hybrid.geometry.part_fit`).
The generated C evaluates the same sums (``generated/hybrid_part.h``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def basis(t: np.ndarray, order: int = 0) -> np.ndarray:
    """The four pieces of the uniform cubic B-spline at the fractions ``t`` (any shape), or their ``order``-th
    derivative by ``t`` (1 or 2): shape ``t.shape + (4,)``.

    Examples
    --------
    >>> basis(np.array(0.5)).sum()  # a partition of unity
    np.float64(1.0)
    """
    t = np.asarray(t, float)
    s = 1.0 - t
    if order == 0:
        pieces = (s ** 3 / 6, (3 * t ** 3 - 6 * t ** 2 + 4) / 6, (-3 * t ** 3 + 3 * t ** 2 + 3 * t + 1) / 6, t ** 3 / 6)
    elif order == 1:
        pieces = (-s ** 2 / 2, (3 * t ** 2 - 4 * t) / 2, (-3 * t ** 2 + 2 * t + 1) / 2, t ** 2 / 2)
    elif order == 2:
        pieces = (s, 3 * t - 2, 1 - 3 * t, t)
    else:
        raise ValueError(f"order {order}: the pieces, their first or their second derivative (0, 1, 2)")
    return np.stack(pieces, axis=-1)


@dataclass(frozen=True, eq=False)
class SplineGrid:
    """A tricubic B-spline on a uniform grid (module docstring).

    Parameters
    ----------
    origin : numpy.ndarray
        The first cell's corner (3) [m].
    spacing : float
        The cells' side [m].
    coefficients : numpy.ndarray
        ``(nx + 3, ny + 3, nz + 3)`` coefficients [m]; NaN where the function is not defined.

    Examples
    --------
    Coefficients that are a linear function of their place give that linear function:

    >>> g = np.indices((5, 5, 5)).astype(float)
    >>> grid = SplineGrid(np.zeros(3), 0.1, 0.1 * (g[0] - 1.0))  # phi = x
    >>> float(grid.evaluate([[0.123, 0.1, 0.1]])[0][0])
    0.123
    """

    origin: np.ndarray
    spacing: float
    coefficients: np.ndarray

    @property
    def cells(self) -> tuple[int, int, int]:
        """The grid's cells along x, y and z."""
        return tuple(int(n) - 3 for n in self.coefficients.shape)

    def cell_of(self, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each point's cell ``(i, j, k)`` (N x 3 integers), its fractions in it (N x 3) and whether it lies on
        the grid (N booleans)."""
        u = (np.asarray(points, float).reshape(-1, 3) - self.origin) / self.spacing
        with np.errstate(invalid="ignore"):
            cell = np.floor(u)
            inside = np.all((cell >= 0) & (cell < np.array(self.cells)), axis=1)
        cell = np.where(inside[:, None], cell, 0).astype(np.int64)
        return cell, np.where(inside[:, None], u - cell, 0.0), inside

    def evaluate(self, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``phi`` (N), its gradient (N x 3) [1] and its Hessian (N x 3 x 3) [1/m] at ``points`` (N x 3) [m];
        NaN at a point off the grid or where a coefficient it reads is not defined."""
        cell, frac, inside = self.cell_of(points)
        h = self.spacing
        b = [basis(frac, order) for order in (0, 1, 2)]  # each N x 3 x 4
        # the 4 x 4 x 4 coefficients of each point's cell
        offsets = np.arange(4)
        c = self.coefficients[(cell[:, 0, None, None, None] + offsets[:, None, None]),
                              (cell[:, 1, None, None, None] + offsets[None, :, None]),
                              (cell[:, 2, None, None, None] + offsets[None, None, :])]

        # the sums taken an axis at a time (z, then y, then x): each derivative's from the partial sums it shares
        along_z = [np.einsum("nabc,nc->nab", c, b[o][:, 2]) for o in range(3)]
        along_yz = {(oy, oz): np.einsum("nab,nb->na", along_z[oz], b[oy][:, 1])
                    for oy, oz in ((0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2))}

        def along(ox: int, oy: int, oz: int) -> np.ndarray:
            return np.einsum("na,na->n", along_yz[oy, oz], b[ox][:, 0])

        phi = along(0, 0, 0)
        grad = np.stack([along(1, 0, 0), along(0, 1, 0), along(0, 0, 1)], axis=1) / h
        hess = np.empty((len(phi), 3, 3))
        for i in range(3):
            for j in range(i, 3):
                order = [0, 0, 0]
                order[i] += 1
                order[j] += 1
                hess[:, i, j] = hess[:, j, i] = along(*order) / h ** 2
        phi[~inside], grad[~inside], hess[~inside] = np.nan, np.nan, np.nan
        return phi, grad, hess

    def as_arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """The generated C's run-time data: the header ``(origin (3), spacing, nx, ny, nz)`` (cells) and the
        coefficients, z fastest (C order)."""
        header = np.array([*self.origin, self.spacing, *self.cells], float)
        return header, np.ascontiguousarray(self.coefficients, float).ravel()
