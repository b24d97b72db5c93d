"""Triangle meshes of parts: checked, placed, and sampled as oriented points for the fit of a smooth surface.

A mesh is ``vertices`` (V x 3) [m] and ``faces`` (F x 3 vertex indices, counter-clockwise seen from the side
the facets' normals point to). :func:`checked_mesh` refuses what the fit cannot use: no facets, vertices that
are not numbers, indices out of range, facets of no area, an edge shared by more than two facets (not a
manifold), an edge two facets run in the same direction (their normals point to opposite sides), a part
out of the scale of a robot cell. :func:`oriented_samples` draws points on the facets in proportion to
their areas, each with the normal of its facet's corners blended (:func:`corner_normals`: a corner averages
the facets that meet there within :data:`CREASE_DEG` of its own, so a curved part's facets blend and a
machined edge stays sharp until the fit rounds it at the grid's scale).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import shown

#: facets meeting at a corner within this angle [deg] share their normal there (a smooth part's tessellation);
#: beyond it (a machined edge) each keeps its own
CREASE_DEG = 30.0
#: the (corner, facet) pairs :func:`corner_normals` weighs at once (about 100 bytes each)
PAIRS_AT_ONCE = 1 << 20
#: the Phong tessellation's shape factor (its authors': 3/4)
PHONG_SHAPE = 0.75
#: the largest and the smallest part [m] (its bounding box's diagonal) a robot cell holds
LARGEST_PART, SMALLEST_PART = 10.0, 1e-3
#: the largest mesh file read [bytes]
MAX_FILE_BYTES = 500_000_000
#: the mesh files read, by suffix (through trimesh)
MESH_SUFFIXES = (".stl", ".obj", ".ply", ".off", ".glb", ".gltf", ".dae")


def checked_mesh(vertices, faces, what: str = "the mesh") -> tuple[np.ndarray, np.ndarray]:
    """``vertices`` (V x 3 floats) and ``faces`` (F x 3 integers) checked (module docstring).

    Raises
    ------
    HybridError
        Naming the problem, the first facet or edge that has it, and the fix.

    Examples
    --------
    >>> v = [(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0)]
    >>> checked_mesh(v, [(0, 1, 2)])[1].tolist()
    [[0, 1, 2]]
    """
    try:
        if np.iscomplexobj(np.asarray(vertices)) or np.iscomplexobj(np.asarray(faces)):
            raise TypeError
        v = np.asarray(vertices, float)
        f = np.asarray(faces, float)
    except (TypeError, ValueError):
        raise HybridError(f"{what}: vertices and faces must be arrays of real numbers (V x 3 and F x 3)") from None
    if v.ndim != 2 or v.shape[1] != 3 or f.ndim != 2 or f.shape[1] != 3:
        raise HybridError(f"{what}: vertices {v.shape} and faces {f.shape}; give V x 3 coordinates [m] and F x 3 "
                          "vertex indices (triangles)")
    if len(f) == 0:
        raise HybridError(f"{what} has no facets; give a mesh with triangles")
    if not np.isfinite(v).all():
        bad = int(np.flatnonzero(~np.isfinite(v).all(axis=1))[0])
        raise HybridError(f"{what}: vertex {bad} is {v[bad].tolist()}; give finite coordinates")
    if not (np.isfinite(f).all() and np.array_equal(f, np.round(f))):
        raise HybridError(f"{what}: faces must hold vertex indices (whole numbers)")
    f = f.astype(np.int64)
    if f.min() < 0 or f.max() >= len(v):
        raise HybridError(f"{what}: a facet names vertex {int(f.max() if f.max() >= len(v) else f.min())}, of "
                          f"{len(v)} vertices; give indices from 0 to {len(v) - 1}")
    size = float(np.linalg.norm(np.ptp(v[f].reshape(-1, 3), axis=0)))
    if not SMALLEST_PART <= size <= LARGEST_PART:
        raise HybridError(f"{what} is {size:.3g} m across; a part in a robot cell is {SMALLEST_PART:g} to "
                          f"{LARGEST_PART:g} m: give scale (1e-3 for a mesh in millimetres)")
    area = face_areas(v, f)
    degenerate = np.flatnonzero(area <= (1e-9 * size) ** 2)
    if len(degenerate):
        raise HybridError(f"{what} has {len(degenerate)} facets of no area (the first: facet {int(degenerate[0])}, "
                          f"vertices {f[degenerate[0]].tolist()}); remove them (trimesh: "
                          "mesh.update_faces(mesh.nondegenerate_faces()); mesh.merge_vertices())")
    _check_edges(f, what)
    return v, f


def _check_edges(f: np.ndarray, what: str) -> None:
    """Refuse an edge of more than two facets, or one two facets run in the same direction."""
    directed = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    undirected = np.sort(directed, axis=1)
    vertices = int(f.max()) + 1  # each edge one number (its two vertices' indices): a sort of numbers, not of rows
    keys, counts = np.unique(undirected[:, 0] * vertices + undirected[:, 1], return_counts=True)
    if counts.max() > 2:
        edge = divmod(int(keys[np.argmax(counts)]), vertices)
        raise HybridError(f"{what} is not a manifold: the edge between vertices {list(edge)} belongs to "
                          f"{int(counts.max())} facets; give a surface each edge of which bounds one or two facets")
    keys, counts = np.unique(directed[:, 0] * vertices + directed[:, 1], return_counts=True)
    if counts.max() > 1:
        edge = divmod(int(keys[np.argmax(counts)]), vertices)
        raise HybridError(f"{what} is inconsistently oriented: two facets run the edge {list(edge)} the same way "
                          "(their normals point to opposite sides); orient its facets alike (trimesh: "
                          "trimesh.repair.fix_winding(mesh))")


def face_areas(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Each facet's area [m^2]."""
    return 0.5 * np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1)


def face_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Each facet's unit normal (counter-clockwise corners: the right-hand rule)."""
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def corner_normals(v: np.ndarray, f: np.ndarray, crease_deg: float = CREASE_DEG) -> np.ndarray:
    """The normal at each facet's corners (F x 3 x 3): the area-weighted mean of the normals of the facets at
    that vertex within ``crease_deg`` of the facet's own."""
    normals, areas = face_normals(v, f), face_areas(v, f)
    corner_vertex = f.ravel()  # corner 3 i + k is facet i's k-th
    # the facets at each vertex, listed vertex by vertex: those at vertex u are at_vertex[starts[u]:][:counts[u]]
    at_vertex = np.argsort(corner_vertex, kind="stable") // 3
    counts = np.bincount(corner_vertex, minlength=len(v))
    starts = np.cumsum(counts) - counts
    # each corner weighs each facet at its vertex: the counts squared summed, pairs (not the corners times the
    # most facets at a vertex, which a fan of hundreds of facets makes gigabytes), a bounded number at once
    pairs = counts[corner_vertex]
    ends = np.cumsum(pairs)
    threshold = math.cos(math.radians(crease_deg))
    blended = np.empty((len(corner_vertex), 3))
    first = 0
    while first < len(corner_vertex):
        last = max(first + 1, int(np.searchsorted(ends, ends[first] - pairs[first] + PAIRS_AT_ONCE, "right")))
        each = pairs[first:last]
        corner = np.repeat(np.arange(last - first), each)
        slot = np.arange(len(corner)) - np.repeat(np.cumsum(each) - each, each)
        facet = at_vertex[starts[corner_vertex[first:last]][corner] + slot]
        near = np.einsum("ck,ck->c", normals[facet], normals[(first + corner) // 3]) >= threshold
        weight = np.where(near, areas[facet], 0.0)
        for k in range(3):
            blended[first:last, k] = np.bincount(corner, weight * normals[facet, k], last - first)
        first = last
    blended /= np.linalg.norm(blended, axis=1, keepdims=True)
    return blended.reshape(len(f), 3, 3)


def oriented_samples(v: np.ndarray, f: np.ndarray, count: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """``count`` points on the part, in proportion to its facets' areas (the same points for the same mesh), and
    their normals: the corners' normals (:func:`corner_normals`) blended linearly, of unit length. A point lies
    on the facet's Phong tessellation (Boubekeur and Alexa, 2008; shape :data:`PHONG_SHAPE`): the quadratic patch
    through its corners that meets their normals, nearer a curved part than the flat facet (its sagitta falls
    from ``a^2 / 8 R`` to a small fraction of it for facets of side ``a`` on a radius ``R``); flat where the
    corners keep the facet's own normal (a machined face)."""
    areas = face_areas(v, f)
    rng = np.random.default_rng(seed)
    # each facet its share of the points, rounded down, the rest drawn by area: stratified over the part
    share = areas / areas.sum() * count
    per_face = np.floor(share).astype(np.int64)
    rest = count - int(per_face.sum())
    if rest > 0:
        per_face += np.bincount(rng.choice(len(f), size=rest, p=(share - per_face) / (share - per_face).sum()),
                                minlength=len(f))
    face = np.repeat(np.arange(len(f)), per_face)
    r1, r2 = rng.random(len(face)), rng.random(len(face))
    s = np.sqrt(r1)
    bary = np.stack([1 - s, s * (1 - r2), s * r2], axis=1)
    corners, corner_n = v[f[face]], corner_normals(v, f)[face]  # n x 3 corners x 3
    flat = np.einsum("nk,nkj->nj", bary, corners)
    # Phong tessellation: the flat point projected onto each corner's tangent plane, blended alike
    along = np.einsum("nkj,nkj->nk", flat[:, None, :] - corners, corner_n)
    projected = np.einsum("nk,nkj->nj", bary, flat[:, None, :] - along[:, :, None] * corner_n)
    points = (1 - PHONG_SHAPE) * flat + PHONG_SHAPE * projected
    normals = np.einsum("nk,nkj->nj", bary, corner_n)
    return points, normals / np.linalg.norm(normals, axis=1, keepdims=True)


def read_mesh(path) -> tuple[np.ndarray, np.ndarray]:
    """The vertices and faces of a mesh file (STL, OBJ, PLY and the others of :data:`MESH_SUFFIXES`, read by
    trimesh), its size checked before it is read."""
    if not isinstance(path, (str, os.PathLike)):
        raise HybridError(f"path = {shown(path, 60)}; give a mesh file's path")
    path = Path(path)
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise HybridError(f"{shown(str(path), 80)} is not a mesh file this reads; give one of "
                          f"{', '.join(MESH_SUFFIXES)}")
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise HybridError(f"the mesh file {shown(str(path), 80)} cannot be read ({exc.strerror}); give an existing "
                          "file") from None
    if size > MAX_FILE_BYTES:
        raise HybridError(f"the mesh file {path.name} is {size / 1e6:.0f} MB (at most {MAX_FILE_BYTES / 1e6:.0f} MB "
                          "are read); simplify it (a part's surface needs facets of a few millimetres)")
    try:
        import trimesh
    except ImportError:
        raise HybridError("reading a mesh file needs trimesh: pip install 'hybrid-decoupling[parts]'") from None
    try:
        mesh = trimesh.load(path, force="mesh", process=True)
    except ImportError as exc:  # a format whose reader trimesh takes from another package (COLLADA: pycollada)
        raise HybridError(f"reading {path.name} needs a package trimesh did not find ({str(exc).splitlines()[0]}); "
                          "install it, or give the part as an STL, OBJ or PLY file") from None
    except Exception as exc:  # noqa: BLE001 - any reader's failure is the file's problem
        raise HybridError(f"{path.name} is not a mesh trimesh can read ({type(exc).__name__}: "
                          f"{str(exc).splitlines()[0] if str(exc) else ''}); give an STL, OBJ or PLY file") from None
    if not hasattr(mesh, "faces") or len(mesh.faces) == 0:
        raise HybridError(f"{path.name} holds no triangles; give a mesh of the part's surface")
    return np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64)
