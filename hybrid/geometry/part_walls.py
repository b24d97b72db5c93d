"""How thick a part's walls are: at each point of the part, the distance along its inward normal to the part's far
face (a plate's thickness; a sheet, an open surface, has none).

The arm tip, behind its compliant sensor, sits below the part's surface by the sensor's deflection, and the
frame is evaluated there. Past the medial surface (half a wall's thickness in) the nearest face is the far one:
the fitted ``phi``'s gradient turns over and the frame with it. :func:`walls` measures each point's wall from
the points themselves: moving inwards along the point's normal, the first depth where one of the nearest points
faces the other way (its normal more than :data:`FACING_DEG` from the point's), lies below the point (within 45
degrees of its inward normal: not a neighbour whose normal a scan's noise turned over) and its tangent plane
lies nearer than the point's own; the wall is then the depth at which the point's inward normal meets that
tangent plane (a flat plate's thickness exactly, however sparse its points: they need not lie opposite each
other; on a wall thinner than the points' spacing, the points with one of the far face's points within 45
degrees below them find it: 40 % of them on a plate of 1 mm sampled every 4 mm). The depths
tried double, from a twentieth of a millimetre to the depth asked, so a point is read a dozen times in a k-d
tree.

A convex edge's adjacent face (its normal at right angles) is not a wall's far face: beyond a convex edge the
frame turns, it does not flip (the band's limit there is the fit's own).
"""

from __future__ import annotations

import math

import numpy as np

#: how deep into the half wall (to the medial surface) the arm tip may go: this share of half the thinnest wall
#: it can reach (measured on plates: docs/howto/parts.rst; :mod:`hybrid.experiments.walls` refuses a run past it)
SOUND_SHARE = 0.5
#: a point whose normal is more than this [deg] from the point's is on the wall's far face
FACING_DEG = 120.0
#: the nearest points read at each depth (a thin wall's far points lie beside the point's own neighbours)
NEAREST = 8
#: the shallowest depth tried [m] (the thinnest wall measured is about twice it)
SHALLOWEST = 5e-5
#: the depths tried double (a wall's far face is found at a depth between half the wall and the wall)
GROWTH = 2.0


def walls(points: np.ndarray, normals: np.ndarray, tree, reach: float, stride: int = 1,
          gap: float = 0.0) -> np.ndarray:
    """The wall [m] at every ``stride``-th point (module docstring): the distance along its inward normal to the
    far face's tangent plane, inf where no far face lies within ``reach`` [m] (an open sheet, a part thicker than
    twice ``reach``).

    Parameters
    ----------
    points, normals : numpy.ndarray
        N x 3 points on the part [m] and their unit normals (outwards: towards the tool's side).
    tree : scipy.spatial.cKDTree
        The k-d tree of ``points``.
    reach : float
        The deepest depth tried [m].
    stride : int
        The walls of ``points[::stride]`` are measured (against all the points).
    gap : float
        How far apart [m] the points may lie on a face (the far face's nearest point may lie this far aside):
        only points within ``1.5 depth + 2 gap`` of the depth reached are read (deep inside a thick part the
        nearest points are far, and a k-d tree finds them slowly).

    Returns
    -------
    numpy.ndarray
        The walls of ``points[::stride]`` [m], inf where none was found.

    Examples
    --------
    A plate of 2 mm (its two faces' points, 3 mm apart and not opposite each other):

    >>> from scipy.spatial import cKDTree
    >>> g = np.stack(np.meshgrid(np.arange(20.0), np.arange(20.0)), -1)
    >>> g = 3e-3 * g.reshape(-1, 2)
    >>> top = np.column_stack([g, np.full(len(g), 2e-3)])
    >>> bottom = np.column_stack([g + 1e-3, np.zeros(len(g))])
    >>> p = np.vstack([top, bottom])
    >>> n = np.repeat([[0.0, 0, 1], [0, 0, -1]], len(g), axis=0)
    >>> w = walls(p, n, cKDTree(p), reach=0.03)
    >>> round(float(np.median(w)) * 1e3, 6)
    2.0
    """
    everyone = tree.data  # (the tree holds ``points``: their normals are ``normals``)
    queried = np.arange(0, len(points), stride)
    facing = math.cos(math.radians(FACING_DEG))
    wall = np.full(len(queried), np.inf)
    open_ = np.arange(len(queried))
    depth = SHALLOWEST
    k = min(NEAREST, len(everyone))
    while depth <= reach and len(open_):
        mine = queried[open_]
        at = points[mine] - depth * normals[mine]
        _, near = tree.query(at, k=k, distance_upper_bound=1.5 * depth + 2 * gap)
        near = near.reshape(len(open_), k)
        there = near < len(everyone)  # (the tree gives the count for none within the bound)
        near = np.where(there, near, 0)
        q, nq = everyone[near], normals[near]  # (M, k, 3)
        n = normals[mine]
        faces = there & (np.einsum("mki,mi->mk", nq, n) < facing)
        plane = np.abs(np.einsum("mki,mki->mk", nq, at[:, None, :] - q))
        # below the point, within 45 degrees of its inward normal: a neighbour on the point's own face whose
        # normal a scan's noise turned over lies beside it, not below
        below = np.einsum("mki,mi->mk", points[mine][:, None, :] - q, n)
        aside = np.linalg.norm(points[mine][:, None, :] - q - below[..., None] * n[:, None, :], axis=2)
        crossed = faces & (plane < depth) & (below > 0) & (aside <= below)
        found = crossed.any(axis=1)
        if found.any():
            rows = np.flatnonzero(found)
            pick = np.where(crossed[rows], plane[rows], np.inf).argmin(axis=1)
            qq, nn = q[rows, pick], nq[rows, pick]
            p, m = points[mine[rows]], n[rows]
            # p - t m on the plane through qq normal to nn: t = nn.(p - qq) / nn.m
            wall[open_[rows]] = np.einsum("ij,ij->i", nn, p - qq) / np.einsum("ij,ij->i", nn, m)
            open_ = open_[~found]
        depth *= GROWTH
    return wall
