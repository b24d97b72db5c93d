"""A smooth signed distance fitted to oriented points: the representation of a part (a mesh, a point cloud).

The part's surface is the zero set of a tricubic B-spline ``phi`` (:class:`~hybrid.geometry.bspline.SplineGrid`),
continuous to the second derivative, so the task frame ``R(r)`` (from ``grad phi``) and its rate ``R'`` (from
the Hessian) are defined everywhere near the part, across the facets' edges. Its coefficients minimise, in
the least-squares sense (the smooth signed distance of Calakli and Taubin, 2011, with distance samples off
the part),

    sum_i phi(p_i)^2 + sum_i |h (grad phi(p_i) - n_i)|^2 + sum_j (phi(q_j) - d_j)^2
        + smoothing * sum_m |h^2 D^2 C_m|^2 + RIDGE * sum_m (C_m - d_m)^2

over the oriented points ``(p_i, n_i)`` sampled on the part and points ``q_j`` moved off it along their normals
by ``d_j`` (to the band, on both sides, each only as far as the medial axis): ``phi`` is 0 on the part, its
gradient the unit normal there, and the signed distance within the band (positive on the normals' side),
where the tool's tip, behind its compliant sensor, evaluates the frame and its rate; its second differences
``D^2 C`` (the Hessian's, on the coefficients ``C``) are small, which smooths the facets' corners and the
noise of a scan. The ridge pulls each coefficient weakly towards the signed distance along the nearest
point's normal: it fixes the coefficients no sample reaches and starts the solver there.

Only the coefficients the samples reach, and two cells beyond them, are unknowns: ``phi`` is defined within
``band`` of the part and not beyond (NaN coefficients), and the grid's size is checked before anything is
allocated. The normal equations, applied as ``A^T (A x)``, are solved by conjugate gradients preconditioned
on the grid and two grids each twice as coarse as the one before (:mod:`hybrid.geometry.fit_solver`).
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.bspline import SplineGrid, basis
from hybrid.geometry.fit_solver import LEVELS, coarse_shape, coarsened, conjugate_gradients, multilevel, refined
from hybrid.validate import check_size

#: the most coefficients a part's grid may have (its bounding box over the spacing): 2e7 doubles, 160 MB
MAX_COEFFICIENTS = 20_000_000
#: the weight of the coefficients' pull towards the nearest point's signed distance (see the module docstring)
RIDGE = 1e-6
#: the points moved off the part, one in so many, for its signed distance within the band
OFFSET_STRIDE = 4
#: how much nearer [cells] than its own point another may be to an offset that is still its own point's
OWN_MARGIN = 0.25
#: the conjugate gradients' relative residual (the fit's own error is far larger)
TOLERANCE = 1e-4
#: the conjugate gradients' iterations at most
MOST_ITERATIONS = 5000
#: the default weight of the second differences: on a sphere of 25 cells' radius tessellated in facets of a
#: cell, the frame's rate within 4 % of the sphere's (a grid finer than the facets resolves their ripple)
SMOOTHING = 0.2


#: the bytes the fit holds per term of its least squares (the term, its row and column, their copies in the
#: sparse matrix's assembly) and per coefficient of the grid (the masks and the solver's vectors)
BYTES_PER_TERM, BYTES_PER_COEFFICIENT = 64, 80


def _check_memory(points: int, offsets: int, coefficients: int) -> None:
    """Refuse a fit whose least squares would need more than half the machine's memory, before it is built."""
    terms = 64 * (4 * points + offsets) + 6 * 4 * coefficients
    need = BYTES_PER_TERM * terms + BYTES_PER_COEFFICIENT * coefficients
    check_size(f"the part's fit ({points:,} points, {offsets:,} off the part, a grid of {coefficients:,}) needs",
               need, "give a coarser spacing, a narrower band or fewer points")


def kd_tree(points: np.ndarray):
    """SciPy's k-d tree of ``points`` (the nearest points of a part's samples)."""
    try:
        from scipy.spatial import cKDTree
    except ImportError:
        raise HybridError("fitting a part's surface needs SciPy: pip install 'hybrid-decoupling[parts]'") from None
    return cKDTree(points, leafsize=32)  # (larger leaves than SciPy's 16: a third faster to query here)


def grid_for(points: np.ndarray, spacing: float, band: float) -> tuple[np.ndarray, tuple[int, int, int]]:
    """The origin and the cells of the grid that holds ``points`` with ``band`` [m] and two cells around them,
    refused where its coefficients would exceed :data:`MAX_COEFFICIENTS`."""
    pad = band + 2 * spacing
    lo, hi = points.min(axis=0) - pad, points.max(axis=0) + pad
    cells = np.ceil((hi - lo) / spacing).astype(int)
    total = float(np.prod(cells + 3.0))
    if total > MAX_COEFFICIENTS:
        extent = hi - lo
        wider = spacing * (total / MAX_COEFFICIENTS) ** (1 / 3)
        raise HybridError(f"a part of {extent[0]:.3g} x {extent[1]:.3g} x {extent[2]:.3g} m at a spacing of "
                          f"{spacing:g} m needs {total:.3g} coefficients (at most {MAX_COEFFICIENTS:.0e}); give "
                          f"spacing >= {wider:.2g} m, or check the part's units (scale=1e-3 for millimetres)")
    return lo, tuple(int(c) for c in cells)


def _stencils(grid_origin, spacing, cells, points, gradient: bool = True) -> tuple[np.ndarray, list[np.ndarray]]:
    """Each point's 64 coefficients (flat indices, N x 64) and the weights of ``phi`` and (``gradient``) of its
    gradient's three components there (each N x 64; the gradient's in 1/m)."""
    shape = np.array(cells) + 3
    u = (points - grid_origin) / spacing
    cell = np.clip(np.floor(u), 0, np.array(cells) - 1).astype(np.int64)
    t = u - cell
    b0, b1 = basis(t, 0), basis(t, 1) / spacing  # N x 3 x 4
    a = np.arange(4)
    index = ((cell[:, 0, None, None, None] + a[:, None, None]) * shape[1]
             + (cell[:, 1, None, None, None] + a[None, :, None])) * shape[2] + (cell[:, 2, None, None, None] + a)

    def product(bx, by, bz):
        return (bx[:, :, None, None] * by[:, None, :, None] * bz[:, None, None, :]).reshape(len(points), 64)

    weights = [product(b0[:, 0], b0[:, 1], b0[:, 2])]
    if gradient:
        weights += [product(b1[:, 0], b0[:, 1], b0[:, 2]), product(b0[:, 0], b1[:, 1], b0[:, 2]),
                    product(b0[:, 0], b0[:, 1], b1[:, 2])]
    return index.reshape(len(points), 64), weights


def _second_differences(unknown: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """The second differences of the coefficients (three along the axes, three mixed), as ``(indices, weights)``
    of their terms (each K x terms, flat indices), for the unknown coefficients whose stencil is all unknowns
    (worked out over the unknowns alone, not the whole grid)."""
    shape = np.array(unknown.shape)
    centre = np.flatnonzero(unknown)
    at = np.stack(np.unravel_index(centre, unknown.shape), axis=1)
    strides = np.array([shape[1] * shape[2], shape[2], 1])
    inside = np.all((at >= 1) & (at <= shape - 2), axis=1)  # a stencil reaches one coefficient each way
    centre, at = centre[inside], at[inside]
    axes = [np.eye(3, dtype=np.int64)[i] for i in range(3)]
    stencils = [([-e, 0 * e, e], [1.0, -2.0, 1.0]) for e in axes]
    root2 = math.sqrt(2.0)  # a mixed second derivative appears twice in the Hessian's norm
    for i in range(3):
        for j in range(i + 1, 3):
            ei, ej = axes[i], axes[j]
            stencils.append(([ei + ej, ei - ej, -ei + ej, -ei - ej], [root2 / 4, -root2 / 4, -root2 / 4, root2 / 4]))
    flat_unknown = unknown.ravel()
    rows = []
    for offsets, weights in stencils:
        terms = np.stack([centre + int(o @ strides) for o in offsets], axis=1)
        index = terms[np.all(flat_unknown[terms], axis=1)]
        rows.append((index, np.broadcast_to(np.array(weights), index.shape)))
    return rows


def _offset_samples(points: np.ndarray, normals: np.ndarray, spacing: float, band: float,
                    tree) -> tuple[np.ndarray, np.ndarray]:
    """Points off the part and their signed distances: every :data:`OFFSET_STRIDE`-th point moved along its
    normal by a cell and each further cell to the band, on both sides (the tool's tip, behind its compliant
    sensor, reaches into the part as far as the sensor deflects), each as far from the part as from its own
    point. An offset nearer another point of the part (past a concave fold, across a thin wall: the medial
    axis) is left out."""
    steps = spacing * np.arange(1, int(math.floor(band / spacing)) + 1)
    base, along = points[::OFFSET_STRIDE], normals[::OFFSET_STRIDE]
    at, value = [], []
    for delta in np.ravel(np.column_stack([steps, -steps])):
        moved = base + delta * along
        distance, _ = tree.query(moved)
        own = distance >= abs(delta) - OWN_MARGIN * spacing  # (a scan's noise is a fraction of a cell)
        at.append(moved[own])
        value.append(np.full(int(own.sum()), delta))
    return (np.concatenate(at), np.concatenate(value)) if at else (np.empty((0, 3)), np.empty(0))


def fit_signed_distance(points, normals, spacing: float, band: float, smoothing: float = SMOOTHING,
                        tree=None) -> SplineGrid:
    """The smooth signed distance of the oriented points (module docstring).

    Parameters
    ----------
    points, normals : numpy.ndarray
        N x 3 points on the part [m] and their unit normals (towards the side where ``phi > 0``).
    spacing : float
        The grid's cells [m]: a few times finer than the smallest radius of curvature to keep.
    band : float
        How far from the points [m] ``phi`` is defined.
    smoothing : float
        The weight of the second differences (:data:`SMOOTHING`).
    tree : scipy.spatial.cKDTree, optional
        :func:`kd_tree` of ``points``, where the caller has it already (default: built here).

    Returns
    -------
    SplineGrid
        ``phi``, NaN beyond the band.

    Examples
    --------
    A sphere of radius 0.1 m from 2,000 points on it:

    >>> rng = np.random.default_rng(0)
    >>> n = rng.normal(size=(2000, 3)); n /= np.linalg.norm(n, axis=1, keepdims=True)
    >>> grid = fit_signed_distance(0.1 * n, n, spacing=0.01, band=0.03)
    >>> phi, grad, _ = grid.evaluate([[0.0, 0.0, 0.105]])
    >>> round(float(phi[0]), 3), round(float(grad[0, 2]), 2)
    (0.005, 1.0)
    """
    if tree is None:
        tree = kd_tree(np.asarray(points, float))  # (refused with the reason where SciPy is missing)
    from scipy import ndimage, sparse

    points, normals = np.asarray(points, float), np.asarray(normals, float)
    origin, cells = grid_for(points, spacing, band)
    shape = tuple(c + 3 for c in cells)
    off, distance = _offset_samples(points, normals, spacing, band, tree)
    _check_memory(len(points), len(off), int(np.prod(np.array(cells, float) + 3)))
    index, (w, wx, wy, wz) = _stencils(origin, spacing, cells, points)
    off_index, (off_w,) = _stencils(origin, spacing, cells, off, gradient=False)
    # the unknowns: the samples' coefficients and a cell's beyond them (a point within the band reads them all)
    touched = np.zeros(shape, bool)
    touched.flat[index.ravel()] = True
    touched.flat[off_index.ravel()] = True
    unknown = ndimage.binary_dilation(touched, np.ones((3, 3, 3), bool), iterations=2)
    column = np.full(unknown.size, -1, np.int64)
    column[unknown.ravel()] = np.arange(int(unknown.sum()))
    m = int(unknown.sum())
    # rows: phi = 0 and h grad phi = h n at the points, phi = the distance off them; the second differences.
    # Each block's rows are as long as each other, so the matrix is laid out row by row as it is (CSR).
    data, cols = [w, spacing * wx, spacing * wy, spacing * wz, off_w], [index] * 4 + [off_index]
    rhs = [np.zeros(len(points)), spacing * normals[:, 0], spacing * normals[:, 1], spacing * normals[:, 2], distance]
    for terms, weights in _second_differences(unknown):
        data.append(math.sqrt(smoothing) * weights)
        cols.append(terms)
        rhs.append(np.zeros(len(terms)))
    starts = np.concatenate([[0], np.cumsum(np.concatenate([np.full(len(c), c.shape[1]) for c in cols]))])
    A = sparse.csr_matrix((np.concatenate([d.ravel() for d in data]),
                           column[np.concatenate([c.ravel() for c in cols])], starts),
                          shape=(len(starts) - 1, m))
    b = np.concatenate(rhs)
    # the ridge's target: the signed distance along the nearest point's normal, at each unknown's centre
    centres = origin + (np.argwhere(unknown) - 1.0) * spacing
    _, nearest = tree.query(centres)
    target = np.einsum("ij,ij->i", centres - points[nearest], normals[nearest])
    # the normal equations applied as A^T (A x): A holds a third of the numbers A^T A would (A^T, a view)
    At = A.T

    def normal_matrix(x):
        return At @ (A @ x) + RIDGE * x

    diagonal = np.bincount(A.indices, weights=A.data ** 2, minlength=m) + RIDGE
    precondition = multilevel(unknown, diagonal, _coarse_diagonals(origin, spacing, unknown, points, off, smoothing))
    solution, iterations, converged = conjugate_gradients(normal_matrix, At @ b + RIDGE * target, target, precondition,
                                                          TOLERANCE, MOST_ITERATIONS)
    if not converged or not np.isfinite(solution).all():
        raise HybridError(f"the part's fit did not converge in {iterations} iterations; give a coarser spacing or "
                          "more smoothing")
    coefficients = np.full(shape, np.nan)
    coefficients[unknown] = solution
    return SplineGrid(origin, float(spacing), coefficients)


def _coarse_diagonals(origin, spacing, unknown, points, off, smoothing) -> list[np.ndarray]:
    """The diagonals of the normal matrix on the :data:`~hybrid.geometry.fit_solver.LEVELS` grids each twice as
    coarse as the one before (``P^T N P``, :mod:`hybrid.geometry.fit_solver`): the samples' rows exactly (a
    coarse B-spline is one on the fine grid, so its rows are the coarse grid's stencils), the second
    differences and the ridge as they are away from the unknowns' border; zero where no unknown is reached."""
    diagonals, shape, reach = [], unknown.shape, unknown.astype(float)
    for level in range(1, LEVELS + 1):
        shape, reach = coarse_shape(shape), coarsened(reach)
        h = spacing * 2 ** level
        cells = tuple(n - 3 for n in shape)
        at = origin - (2 ** (level + 1) - 2) * spacing  # each coarser grid's origin two of its finer cells back
        index, (w, wx, wy, wz) = _stencils(at, h, cells, points)
        off_index, (off_w,) = _stencils(at, h, cells, off, gradient=False)
        size = int(np.prod(shape))
        d = np.bincount(index.ravel(), weights=(w ** 2 + spacing ** 2 * (wx ** 2 + wy ** 2 + wz ** 2)).ravel(),
                        minlength=size)
        d += np.bincount(off_index.ravel(), weights=(off_w ** 2).ravel(), minlength=size)
        d = d.reshape(shape) + _regular_diagonal(level, smoothing)
        diagonals.append(np.where(reach > 0, d, 0.0))
    return diagonals


def _regular_diagonal(level: int, smoothing: float) -> float:
    """What the second differences and the ridge add to the diagonal of a grid ``level`` times coarser, for a
    coefficient all of whose fine coefficients are unknowns: one coarse B-spline refined to the fine grid, its
    terms squared."""
    shapes = [(8 * 2 ** level,) * 3]
    for _ in range(level):
        shapes.append(coarse_shape(shapes[-1]))
    fine = np.zeros(shapes[-1])
    fine[tuple(n // 2 for n in shapes[-1])] = 1.0
    for finer in reversed(shapes[:-1]):
        fine = refined(fine, finer)
    total = RIDGE * float((fine ** 2).sum())
    for terms, weights in _second_differences(np.ones(fine.shape, bool)):
        total += smoothing * float(((fine.ravel()[terms] * weights).sum(axis=1) ** 2).sum())
    return total
