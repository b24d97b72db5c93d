"""Unrolled factorisations on CasADi SX matrices: every linear solve the generated C performs.

No symbolic inverse is formed: a solve is a factorisation (Cholesky ``A = L L^T`` of a
symmetric positive definite matrix, or a thin QR of a full-column-rank matrix by modified
Gram-Schmidt) followed by triangular substitutions. A zero or negative pivot gives NaN or
infinity, which the entry points report as ``HYBRID_NONFINITE`` (or a guard catches first).
"""

from __future__ import annotations

import casadi as ca


def _zero():
    return ca.SX(0)


def reciprocal(y) -> ca.SX:
    """``1/y`` that stays a reciprocal: CasADi rewrites ``x * (1/y)`` as ``x / y``, and a division
    costs several multiplications; ``copysign`` (exact: ``1/y`` has the sign of ``y``) stops that."""
    return ca.copysign(1 / y, y)


def cholesky(A) -> list[list]:
    """Lower-triangular ``L`` (a list of rows) with ``A = L L^T``."""
    n = A.shape[0]
    L = [[None] * n for _ in range(n)]
    for j in range(n):
        L[j][j] = ca.sqrt(A[j, j] - sum((L[j][k] ** 2 for k in range(j)), _zero()))
        inv = reciprocal(L[j][j])
        for i in range(j + 1, n):
            L[i][j] = (A[i, j] - sum((L[i][k] * L[j][k] for k in range(j)), _zero())) * inv
    return L


def forward_substitution(L, b) -> list:
    """``y = L^-1 b`` for lower-triangular ``L`` (list of rows) and a column ``b``."""
    n = len(L)
    y = [None] * n
    for i in range(n):
        y[i] = (b[i] - sum((L[i][k] * y[k] for k in range(i)), _zero())) * reciprocal(L[i][i])
    return y


def back_substitution_transposed(L, y) -> list:
    """``x = L^-T y`` for lower-triangular ``L``."""
    n = len(L)
    x = [None] * n
    for i in reversed(range(n)):
        x[i] = (y[i] - sum((L[k][i] * x[k] for k in range(i + 1, n)), _zero())) * reciprocal(L[i][i])
    return x


def back_substitution_upper(R, y) -> list:
    """``x = R^-1 y`` for upper-triangular ``R`` (list of rows)."""
    m = len(R)
    x = [None] * m
    for i in reversed(range(m)):
        x[i] = (y[i] - sum((R[i][k] * x[k] for k in range(i + 1, m)), _zero())) * reciprocal(R[i][i])
    return x


def cholesky_solve(A, b) -> ca.SX:
    """``x = A^-1 b`` for symmetric positive definite ``A``, by Cholesky and two substitutions."""
    L = cholesky(A)
    return ca.vertcat(*back_substitution_transposed(L, forward_substitution(L, b)))


def ldl(A) -> tuple[list[list], list]:
    """``A = L D L^T`` (square-root-free Cholesky) of a symmetric positive definite ``A``: the
    unit lower-triangular ``L`` (a list of rows, its unit diagonal implied) and the reciprocals
    of ``D``'s diagonal. ``W_ij = L_ij D_j = A_ij - sum_{k<j} L_ik W_jk``, ``D_j = W_jj``."""
    n = A.shape[0]
    L, W, inv = [[None] * n for _ in range(n)], [[None] * n for _ in range(n)], [None] * n
    for j in range(n):
        for i in range(j, n):
            W[i][j] = A[i, j] - sum((L[i][k] * W[j][k] for k in range(j)), _zero())
        inv[j] = reciprocal(W[j][j])
        for i in range(j + 1, n):
            L[i][j] = W[i][j] * inv[j]
    return L, inv


def ldl_solve(A, b) -> ca.SX:
    """``x = A^-1 b`` for symmetric positive definite ``A`` by :func:`ldl` and two unit-triangular
    substitutions (no square roots; a diagonal entry's reciprocal once)."""
    L, inv = ldl(A)
    n = len(L)
    y = [None] * n
    for i in range(n):
        y[i] = b[i] - sum((L[i][k] * y[k] for k in range(i)), _zero())
    x = [None] * n
    for i in reversed(range(n)):
        x[i] = y[i] * inv[i] - sum((L[k][i] * x[k] for k in range(i + 1, n)), _zero())
    return ca.vertcat(*x)


def factor_solve(L, b) -> ca.SX:
    """``(L L^T)^-1 b`` with ``L`` already computed."""
    return ca.vertcat(*back_substitution_transposed(L, forward_substitution(L, b)))


def lower_columns_solve(L, M) -> ca.SX:
    """``L^-1 M`` column by column (``M`` a matrix)."""
    return ca.horzcat(*(ca.vertcat(*forward_substitution(L, M[:, j])) for j in range(M.shape[1])))


def thin_qr(A) -> tuple[list, list[list]]:
    """``A = Q R`` for an ``n x m`` matrix of full column rank (``n >= m``), modified Gram-Schmidt:
    ``Q`` as a list of m orthonormal columns, ``R`` upper triangular (list of rows)."""
    m = A.shape[1]
    Q, R = [], [[_zero()] * m for _ in range(m)]
    for j in range(m):
        v = A[:, j]
        for i in range(j):
            R[i][j] = ca.dot(Q[i], v)
            v = v - R[i][j] * Q[i]
        R[j][j] = ca.norm_2(v)
        Q.append(v * reciprocal(R[j][j]))
    return Q, R


def upper_inverse_frobenius2(R) -> ca.SX:
    """``|R^-1|_F^2`` for upper-triangular ``R`` (list of rows): column ``j`` of ``R^-1`` solves the
    leading ``(j+1) x (j+1)`` block against the unit vector ``e_j``."""
    total = _zero()
    for col in range(len(R)):
        block = [row[:col + 1] for row in R[:col + 1]]
        x = back_substitution_upper(block, [_zero()] * col + [ca.SX(1.0)])
        total = total + sum((xi * xi for xi in x), _zero())
    return total


def gram_conditioning(A) -> ca.SX:
    """:func:`frobenius_conditioning` of ``A`` where no QR of ``A^T`` is formed for a solve: from the
    Cholesky factor ``L`` of ``G = A A^T``, as ``|A|_F^2 = trace(G)`` and ``|A^+|_F^2 = trace(G^-1) =
    |L^-1|_F^2``, at a third of the QR's operations. Forming ``G`` squares ``A``'s conditioning, so the
    measure's relative rounding is about ``1e-16 / c^2`` at a conditioning ``c`` (``1e-10`` at
    ``c = 1e-3``), where the QR's is ``1e-16 / c``; a pivot that rounding makes zero or negative (a rank
    loss) gives 0, not the square root's NaN, and a NaN in ``A`` stays NaN."""
    G = A @ A.T
    L = cholesky(G)
    m = len(L)
    pivot = [G[j, j] - sum((L[j][k] ** 2 for k in range(j)), _zero()) for j in range(m)]
    rank_lost = pivot[0] <= 0
    for p in pivot[1:]:
        rank_lost = ca.logic_or(rank_lost, p <= 0)
    R = [[L[j][i] if j >= i else _zero() for j in range(m)] for i in range(m)]
    return ca.if_else(rank_lost, 0, m / ca.sqrt(ca.trace(G) * upper_inverse_frobenius2(R)))


def frobenius_conditioning(A, R) -> ca.SX:
    """``m / (|A|_F |A^+|_F)`` in (0, 1] for the ``m x n`` matrix ``A`` (``m <= n``), from the R of
    the thin QR of ``A^T``: 1 when all singular values are equal, 0 at a rank loss, about
    ``sigma_min / sigma_max`` near one; for ``m = 2`` it equals ``2 |det A| / |A|_F^2``."""
    m = len(R)
    return m / ca.sqrt(ca.sumsqr(A) * upper_inverse_frobenius2(R))
