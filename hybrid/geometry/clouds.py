"""A point cloud's own geometry, before its surface is fitted: its spread (a cloud on a line has no surface),
its gaps (the largest distance to a nearest neighbour) and each point's normal estimated from its neighbours."""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.part_fit import kd_tree

#: a cloud whose points lie closer to one line than this share of a cell (RMS) is refused
LINE_CELLS = 0.1


def check_spread(p: np.ndarray, spacing: float, what: str) -> None:
    """Refuse points ``p`` (N x 3) on a line: closer to their best line than :data:`LINE_CELLS` of a cell
    ``spacing`` [m] (RMS): a line has no surface to fit, nor normals to estimate."""
    across = float(np.linalg.svd(p - p.mean(axis=0), compute_uv=False)[1]) / math.sqrt(len(p))
    if across < LINE_CELLS * spacing:
        raise HybridError(f"{what}: the points lie on a line ({across * 1e3:.2g} mm RMS across it, under "
                          f"{LINE_CELLS:g} of a cell); give points spread over the part's surface, not one line")


def estimated_normals(p: np.ndarray, k: int, viewpoint: np.ndarray, what: str) -> np.ndarray:
    """Each point's normal: the direction of least spread of its ``k`` nearest points, towards ``viewpoint``."""
    if k < 6:
        raise HybridError(f"{what}.neighbours = {k}; give at least 6")
    _, near = kd_tree(p).query(p, k=min(k, len(p)))
    local = p[near] - p[near].mean(axis=1, keepdims=True)
    _, vectors = np.linalg.eigh(np.einsum("nki,nkj->nij", local, local))
    n = vectors[:, :, 0]
    return n * np.where(np.einsum("ij,ij->i", n, viewpoint - p) < 0, -1.0, 1.0)[:, None]


def sparsest(p: np.ndarray) -> float:
    """The largest distance from a point to its nearest neighbour [m] (the cloud's gaps)."""
    d, _ = kd_tree(p).query(p, k=2)
    return float(d[:, 1].max())
