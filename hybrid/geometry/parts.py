"""Parts as they come: a surface from a triangle mesh (:class:`MeshSurface`) or a point cloud
(:class:`PointCloudSurface`), smooth to the second derivative.

The part's ``phi`` is the smooth signed distance fitted to oriented points on it
(:mod:`hybrid.geometry.part_fit`): positive on the side its normals point to (a closed mesh's outside), the
distance from the part near it, its gradient the unit normal and its Hessian the curvature the law's ``R'``
needs. Everything is in the base axes: a part is placed by ``transform`` (its frame in the base, 4 x 4) and
``scale`` (1e-3 for a file in millimetres). :attr:`PartSurface.fit` says how well the smooth surface
follows the part.

The generated code takes a part as the surface's second-order expansion about a point
(:func:`hybrid.spec.surface.quadric_phi`): :meth:`PartSurface.parameters_at` gives it about the point of
contact, exact there (``phi``, its gradient and its Hessian are the fitted surface's).
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.errors import HybridError
from hybrid.geometry.clouds import check_spread, estimated_normals, sparsest
from hybrid.geometry.meshes import (
    LARGEST_PART,
    SMALLEST_PART,
    checked_mesh,
    face_areas,
    face_normals,
    oriented_samples,
    read_mesh,
)
from hybrid.geometry.part_data import data_file
from hybrid.geometry.part_fit import OFFSET_STRIDE, SMOOTHING, fit_signed_distance, kd_tree
from hybrid.geometry.part_walls import SOUND_SHARE, walls
from hybrid.geometry.placement import placed
from hybrid.geometry.surfaces import Surface, _unit_normal
from hybrid.native import loader
from hybrid.spec.part import PART_STATUSES
from hybrid.spec.surface import FORMULAS, PARAMETERS, SurfaceSpec
from hybrid.user_warnings import PartFitWarning, warn
from hybrid.validate import _finite, _point, checked_keywords, shown

#: the samples drawn per cell of the grid on the part's surface (area / spacing^2 of them, each)
SAMPLES_PER_CELL = 2.0
#: the fewest and the most samples drawn on a part
FEWEST_SAMPLES, MOST_SAMPLES = 2_000, 400_000
#: the shortest spacing and band [m] a fit takes
SHORTEST = 1e-4
#: a fit that follows the part poorly (warned, :class:`~hybrid.PartFitWarning`): the median point of the part
#: farther from the smooth surface than this share of a cell, or the median normal more than this angle [deg] off.
#: The tests' good fits keep within 0.1 of a cell and 2.4 degrees (the Panda's link at 5 mm, a noisy scan's
#: estimated normals); a machined edge's or a cloud's rim's few points lie in the largest error, not the median
POOR_DISTANCE_CELLS, POOR_ANGLE_DEG = 0.25, 4.0
#: the most points of the part whose walls are measured (:mod:`hybrid.geometry.part_walls`), and how deep [bands]:
#: a wall found that deep is up to twice as thick, and the arm tip (within the band) is refused no deeper than
#: SOUND_SHARE of half a wall (a wall of 2 / SOUND_SHARE bands at most: twice as deep, for the far face's tilt)
WALL_POINTS, WALL_BANDS = 50_000, 2.0 / SOUND_SHARE
#: the Newton steps :meth:`PartSurface.project` takes at most
PROJECTION_STEPS = 20
#: how far from the part [m] its surface is defined by default (at least three cells): the arm tip reaches into
#: the part as far as the sensor deflects (2 cm at 20 N on the default sensor of 1000 N/m)
DEFAULT_BAND = 0.03
#: a smaller part's default band: this share of its size (its bounding box's diagonal), where that is less than
#: :data:`DEFAULT_BAND` (a part under 12 cm across): a band wider than the part would be most of its grid
BAND_SHARE = 0.25


@dataclass(frozen=True)
class PartFit:
    """How well a part's smooth surface follows the part.

    Attributes
    ----------
    spacing_m, band_m : float
        The fit's grid spacing, and how far from the part ``phi`` is defined [m].
    samples : int
        The oriented points it was fitted to.
    distance_rms_m, distance_max_m : float
        The smooth surface's distance from the part's own points (a mesh's vertices and facets' centroids, a
        cloud's points) [m]: ``|phi| / |grad phi|`` there.
    normal_angle_rms_deg, normal_angle_max_deg : float
        The angle between the smooth surface's normal and the part's own (a mesh's facets' at their centroids,
        away from its edges; a cloud's given or estimated normals) [deg].
    distance_median_m, normal_angle_median_deg : float
        The typical point's distance [m] and normal's angle [deg] (their medians): a fit whose median distance
        exceeds :data:`POOR_DISTANCE_CELLS` of a cell, or whose median angle exceeds :data:`POOR_ANGLE_DEG`, is
        warned of (:class:`~hybrid.PartFitWarning`).
    thinnest_wall_m : float
        The part's thinnest wall [m]: at its points, the distance along the inward normal to its far face (a
        plate's thickness; :mod:`hybrid.geometry.part_walls`), the least; inf where no point has a far face
        within four bands (an open sheet, a part thicker than eight bands). A run whose arm tip would press past a
        quarter of the wall it reaches is refused (:mod:`hybrid.experiments.walls`).
    """

    spacing_m: float
    band_m: float
    samples: int
    distance_rms_m: float
    distance_max_m: float
    normal_angle_rms_deg: float
    normal_angle_max_deg: float
    distance_median_m: float = math.nan
    normal_angle_median_deg: float = math.nan
    thinnest_wall_m: float = math.inf

    def poor(self) -> str | None:
        """What makes the fit poor (:data:`POOR_DISTANCE_CELLS`, :data:`POOR_ANGLE_DEG`) and its fix, or None."""
        if self.distance_median_m > POOR_DISTANCE_CELLS * self.spacing_m:
            return (f"the part's points lie {self.distance_median_m * 1e3:.3g} mm from it (the median; at most "
                    f"{POOR_DISTANCE_CELLS:g} of a cell, {POOR_DISTANCE_CELLS * self.spacing_m * 1e3:.3g} mm): give "
                    "less smoothing, a finer spacing for features of a few cells, a mesh whose facets are finer where "
                    "it curves (flat facets lie inside a sphere through their corners), or a cloud of one layer (its "
                    "scans registered onto each other)")
        if self.normal_angle_median_deg > POOR_ANGLE_DEG:
            return (f"its normal is {self.normal_angle_median_deg:.3g} degrees from the part's (the median; at most "
                    f"{POOR_ANGLE_DEG:g}): give a finer spacing (a tenth of the smallest radius of curvature) or less "
                    "smoothing; a cloud's estimated normals need points spread over its surface, neither on a line "
                    "nor doubled (or give its normals)")
        return None


class PartSurface(Surface):
    """A surface fitted to a part (module docstring); built by :class:`MeshSurface` or :class:`PointCloudSurface`.

    Attributes
    ----------
    grid : SplineGrid
        The fitted ``phi`` (:class:`~hybrid.geometry.bspline.SplineGrid`), NaN beyond the band.
    fit : PartFit
        How well it follows the part.
    """

    local = True
    parameters_named = PARAMETERS["quadric"]
    formula = staticmethod(FORMULAS["quadric"])

    def _settings(self, points: np.ndarray, spacing, band, smoothing, what: str) -> None:
        """The fit's spacing, band and smoothing, checked (the defaults' where None)."""
        extent = float(np.linalg.norm(np.ptp(points, axis=0)))
        spacing = _length(what, "spacing", extent / 50 if spacing is None else spacing)
        band = _length(what, "band", max(3 * spacing, min(DEFAULT_BAND, BAND_SHARE * extent)) if band is None
                       else band)
        _finite(what, smoothing=smoothing)
        if smoothing < 0:
            raise HybridError(f"{what}.smoothing = {smoothing}; give a weight >= 0")
        self.spacing, self.band, self.smoothing = spacing, band, float(smoothing)

    def _fitted(self, points: np.ndarray, normals: np.ndarray, what: str) -> None:
        """The fit to ``points`` and ``normals`` (its settings :meth:`_settings`'), and the evaluator's data."""
        tree = kd_tree(points)  # (the fit's and the walls')
        self.grid = fit_signed_distance(points, normals, self.spacing, self.band, self.smoothing, tree)
        # the walls of one point in OFFSET_STRIDE (at most WALL_POINTS of them, evenly), against all the points
        stride = max(OFFSET_STRIDE, -(-len(points) // WALL_POINTS))
        reach = min(float(np.linalg.norm(np.ptp(points, axis=0))) / 2, WALL_BANDS * self.band)
        self._walls = walls(points, normals, tree, reach, stride, self.spacing)
        self._wall_points = points[::stride].copy()
        self._what = what
        self._anchor = points[0].copy()
        self._grid_numbers, self._coefficients = self.grid.as_arrays()
        for a in (self._grid_numbers, self._coefficients):
            a.flags.writeable = False
        self._digest = None
        self._bound = None  # the generated evaluator and its pointers at the grid, made at the first expansion

    def __getstate__(self) -> dict:
        """What a copy (a sweep's process, pickled) needs: all but the evaluator's handles, made again there."""
        return {**self.__dict__, "_bound": None}

    @property
    def _evaluator(self) -> tuple:
        """``(lib, ffi, grid, coefficients)``: the generated evaluator and its pointers at this part's data."""
        if self._bound is None:
            module = loader.part_evaluator()
            self._bound = (module.lib, module.ffi, module.ffi.from_buffer("double[]", self._grid_numbers),
                           module.ffi.from_buffer("double[]", self._coefficients))
        return self._bound

    def _report(self, points: np.ndarray, at: np.ndarray, normals: np.ndarray, samples: int) -> None:
        """:attr:`fit`: the distance at the part's own ``points``, the normal's angle at ``at`` against the part's
        ``normals`` there."""
        phi, grad, _ = self.grid.evaluate(points)
        distance = np.abs(phi) / np.linalg.norm(grad, axis=1)
        _, grad, _ = self.grid.evaluate(at)
        cos = np.einsum("ij,ij->i", grad, normals) / np.linalg.norm(grad, axis=1)
        angle = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
        self.fit = PartFit(self.spacing, self.band, samples, float(np.sqrt(np.mean(distance ** 2))),
                           float(distance.max()), float(np.sqrt(np.mean(angle ** 2))), float(angle.max()),
                           float(np.median(distance)), float(np.median(angle)), float(self._walls.min()))
        poor = self.fit.poor()
        if poor is not None:
            warn(f"{self._what} follows the part poorly: {poor} (the numbers: its .fit)", PartFitWarning)

    # ----------------------------------------------------------------- the surface's interface

    def phi_function(self):
        """``p -> (phi(p), grad phi(p))`` of the fitted surface (NaN beyond its band)."""
        def evaluate(p):
            phi, grad, _ = self.grid.evaluate(np.asarray(p, float).reshape(1, 3))
            return float(phi[0]), grad[0]
        return evaluate

    def phi_and_gradient(self, points) -> tuple[np.ndarray, np.ndarray]:
        """``phi`` (N) and its gradient (N x 3) at ``points`` (N x 3) [m]; NaN beyond the band."""
        phi, grad, _ = self.grid.evaluate(points)
        return phi, grad

    def evaluate(self, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``phi`` (N), its gradient (N x 3) and its Hessian (N x 3 x 3) [1/m] at ``points`` (N x 3) [m]; NaN
        beyond the band."""
        try:
            a = np.atleast_2d(np.asarray(points, float))
        except (TypeError, ValueError):
            a = None
        if a is None or a.ndim != 2 or a.shape[1] != 3:
            raise HybridError(f"{self._what}: points = {shown(points, 40)}; give N x 3 coordinates [m]")
        return self.grid.evaluate(a)

    def normal_at(self, p) -> np.ndarray:
        """The unit normal towards the robot at ``p`` [m] (3 coordinates, within the band).

        Raises
        ------
        HybridError
            ``p`` beyond the band (no normal there).
        """
        p = np.array(_point(self._what, "point", p, (3,)))
        _, grad = self.phi_function()(p)
        if not np.isfinite(grad).all():
            raise HybridError(self.off_band(p))
        return _unit_normal(grad, f"{self._what} at {p.tolist()}")

    def parameters_at(self, p) -> np.ndarray:
        """The generated code's parameters at the point ``p`` [m]: the fitted surface's second-order expansion
        about it (:func:`~hybrid.spec.surface.quadric_phi`: ``p``, ``phi``, the gradient, the Hessian's upper
        triangle), computed by the generated evaluator (``generated/hybrid_part.h``, as the compiled loop and
        the standalone C compute it); NaN beyond the band."""
        lib, ffi, grid, coefficients = self._evaluator
        point = np.array(_point(self._what, "point", p, (3,)))
        out = np.empty(len(PARAMETERS["quadric"]))
        status = lib.hybrid_part_expansion_entry(grid, coefficients,
                                                 ffi.from_buffer("double[]", point), ffi.from_buffer("double[]", out))
        if status != PART_STATUSES["PART_OK"]:
            out[:] = np.nan
        return out

    def as_array(self) -> np.ndarray:
        """The parameters about the part's first point (each call and sample gives its own: :meth:`parameters_at`)."""
        return self.parameters_at(self._anchor)

    def data(self) -> tuple[np.ndarray, np.ndarray]:
        """The generated C's run-time data of the part: the grid's numbers (:data:`~hybrid.spec.part.PART_GRID`)
        and its coefficients (z fastest; NaN beyond the band)."""
        return self._grid_numbers, self._coefficients

    def save_data(self, path, overwrite: bool = False) -> Path:
        """Write the part's data file: what the standalone C reads at run time (``<name>_set_part``), so one
        build serves every part (:mod:`hybrid.geometry.part_data`; ``Experiment.generate`` writes it beside the C).

        Parameters
        ----------
        path : str or pathlib.Path
            The file (``<name>_part.bin`` by convention), written atomically.
        overwrite : bool
            Whether an existing file is replaced (default False: refused).

        Returns
        -------
        pathlib.Path
            The path written.
        """
        data = data_file(*self.data())
        return files.write_with(Path(path), lambda tmp: tmp.write_bytes(data), overwrite)

    def thinnest_wall(self, near=None, within: float = math.inf) -> float:
        """The part's thinnest wall [m] within ``within`` of ``near`` (:attr:`PartFit.thinnest_wall_m` of the
        points there; inf where none has a far face: an open sheet).

        Parameters
        ----------
        near : array_like, optional
            A point [m] (3 coordinates); default: the whole part.
        within : float
            How far from ``near`` [m] the part's points count (default: all of them).

        Returns
        -------
        float
            The least wall [m] of the points within reach, or inf.

        Examples
        --------
        A plate of 2 cm (its top face at z = 0.01 m):

        >>> import hybrid, trimesh
        >>> box = trimesh.creation.box(extents=(0.1, 0.1, 0.02))
        >>> plate = hybrid.MeshSurface(box.vertices, box.faces,
        ...                            spacing=0.004)
        >>> round(plate.thinnest_wall((0.0, 0.0, 0.01), 0.02) * 1e3, 3)
        20.0
        """
        if near is None:
            return self.fit.thinnest_wall_m
        point = np.array(_point(self._what, "near", near, (3,)))
        if isinstance(within, bool) or not isinstance(within, (int, float, np.integer, np.floating)) or not within >= 0:
            raise HybridError(f"{self._what}.thinnest_wall: within = {shown(within, 30)}; give a distance >= 0 [m]")
        close = np.linalg.norm(self._wall_points - point, axis=1) <= within
        return float(self._walls[close].min()) if close.any() else math.inf

    def project(self, p) -> np.ndarray | None:
        """The point of the part nearest ``p`` [m] (Newton steps along the normal; ``p`` within the band), or
        None beyond it."""
        x = np.asarray(p, float).reshape(3).copy()
        for _ in range(PROJECTION_STEPS):
            phi, grad = self.phi_function()(x)
            if not (math.isfinite(phi) and np.isfinite(grad).all()):
                return None
            step = phi * grad / float(grad @ grad)
            x -= step
            if float(np.linalg.norm(step)) <= 1e-13:
                break
        return x

    def off_band(self, p) -> str:
        """What to say of the point ``p`` beyond the fitted band (no surface there)."""
        return (f"{self._what}: the point {np.round(np.asarray(p, float), 5).tolist()} m is beyond the fitted band "
                f"({self.band:g} m from the part); give a point nearer the part, or a wider band")

    def arguments(self) -> dict:
        """What the part is made from, in base axes and metres (a saved experiment's surface: read, it is fitted
        again to the same surface)."""
        return dict(self._arguments)

    def spec(self) -> SurfaceSpec:
        """The generated code's surface: the second-order expansion about a point (``quadric``), its parameters
        given at each point (:meth:`parameters_at`)."""
        return SurfaceSpec("quadric", self.parameters_named, formula=self.formula)

    def digest(self) -> str:
        """What identifies the fitted surface (its grid's numbers; worked out once: the grid never changes)."""
        if self._digest is None:
            h = hashlib.sha256()
            h.update(self._grid_numbers.tobytes())
            h.update(self._coefficients.tobytes())
            self._digest = h.hexdigest()
        return self._digest

    def __eq__(self, other) -> bool:
        return type(other) is type(self) and other.digest() == self.digest()

    def __hash__(self) -> int:
        return hash(self.digest())


@checked_keywords
class MeshSurface(PartSurface):
    """A part given as a triangle mesh, its surface smooth to the second derivative.

    Parameters
    ----------
    vertices : array_like
        V x 3 vertex coordinates (in the mesh's units: ``scale`` makes them metres).
    faces : array_like
        F x 3 vertex indices, counter-clockwise seen from the side the normals point to (a closed mesh's
        outside): the tool's side, where ``phi > 0``, unless ``flip``.
    transform : array_like, optional
        The part's frame in the base axes (4 x 4 homogeneous; a rotation and a translation [m]); default the
        identity. In single precision (float32, or a file's 7 digits) its rotation is orthonormal only to about
        1e-7: it is taken within 100 times its numbers' precision (at least 1e-6) and re-orthonormalised (the
        nearest rotation); a scale or a shear is refused.
    scale : float
        Metres per mesh unit (1e-3 for millimetres), applied before ``transform``.
    flip : bool
        True: the tool works on the other side (against the facets' normals: the inside of a bowl).
    spacing : float, optional
        The fit's grid spacing [m]: finer than the smallest radius of curvature to keep (a tenth of it keeps
        it within about 1 %); default a fiftieth of the part's size (its bounding box's diagonal).
    band : float, optional
        How far from the part [m] ``phi`` is defined, on both sides (the tool's approach starts within it, and
        the arm tip behind a compliant sensor reaches into the part as far as the sensor deflects): default
        :data:`DEFAULT_BAND` (3 cm), or a quarter of the part's size (its bounding box's diagonal) where that is
        less (:data:`BAND_SHARE`: a part under 12 cm across), and at least three cells.
    smoothing : float
        The weight of the fit's second differences (:data:`~hybrid.geometry.part_fit.SMOOTHING`).

    Raises
    ------
    HybridError
        A mesh that is empty, not a manifold, inconsistently oriented, with facets of no area or vertices
        that are not numbers, out of a robot cell's scale; a transform that is not a rigid motion.

    Warns
    -----
    PartFitWarning
        A fit that follows the part poorly (:meth:`PartFit.poor`: the median distance beyond a quarter of a
        cell, or the median normal beyond 4 degrees), with the measured error and the fix.

    Examples
    --------
    A cube of 0.1 m (8 vertices, 12 facets), its top at z = 0.05 m:

    >>> import hybrid, numpy as np
    >>> v = 0.05 * np.array([[x, y, z] for x in (-1, 1)
    ...                      for y in (-1, 1) for z in (-1, 1)])
    >>> f = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5],
    ...      [0, 5, 1], [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4],
    ...      [1, 5, 7], [1, 7, 3]]
    >>> cube = hybrid.MeshSurface(v, f, spacing=0.005, band=0.02)
    >>> round(float(cube.normal_at([0.0, 0.0, 0.052])[2]), 4)
    1.0

    Its edges and corners are rounded at the grid's scale (the fit is smooth): the corners lie a few millimetres
    off the fitted surface, and the report says so.

    >>> bool(0.001 < cube.fit.distance_max_m < 0.01)
    True
    """

    kind = "mesh"

    def __init__(self, vertices, faces, transform=None, scale: float = 1.0, flip: bool = False,
                 spacing: float | None = None, band: float | None = None, smoothing: float = SMOOTHING):
        what = "MeshSurface"
        if not isinstance(flip, (bool, np.bool_)):
            raise HybridError(f"{what}.flip = {shown(flip, 30)}; give True or False")
        _finite(what, scale=scale)
        if scale <= 0:
            raise HybridError(f"{what}.scale = {scale}; give the metres per mesh unit (> 0; 1e-3 for millimetres)")
        try:
            if np.iscomplexobj(np.asarray(vertices)):
                raise TypeError
            raw = np.asarray(vertices, float) * scale
        except (TypeError, ValueError):
            raise HybridError(f"{what}: vertices must be V x 3 real numbers") from None
        v, f = checked_mesh(placed(raw, transform, what), faces, what)
        self.flip = bool(flip)
        if flip:
            f = f[:, ::-1].copy()
        self.vertices, self.faces = v, f
        self._settings(v, spacing, band, smoothing, what)
        count = int(np.clip(SAMPLES_PER_CELL * _area(v, f) / self.spacing ** 2, FEWEST_SAMPLES, MOST_SAMPLES))
        points, normals = oriented_samples(v, f, count)
        self._fitted(points, normals, what)
        self._arguments = {"vertices": v.tolist(), "faces": f.tolist(), "spacing": self.spacing, "band": self.band,
                           "smoothing": self.smoothing}
        # the report: the distance at the vertices and the facets' centroids, the angle at the centroids
        centroids = v[f].mean(axis=1)
        self._report(np.vstack([v, centroids]), centroids, face_normals(v, f), count)

    @classmethod
    def from_file(cls, path, transform=None, scale: float = 1.0, flip: bool = False, spacing: float | None = None,
                  band: float | None = None, smoothing: float = SMOOTHING) -> MeshSurface:
        """A part from a mesh file (STL, OBJ, PLY, ...; read by trimesh).

        Parameters
        ----------
        path : str or pathlib.Path
            The mesh file (at most :data:`~hybrid.geometry.meshes.MAX_FILE_BYTES`, checked before it is read).
        transform, scale, flip, spacing, band, smoothing
            As :class:`MeshSurface` takes them.

        Returns
        -------
        MeshSurface
            The part's fitted surface.

        Raises
        ------
        HybridError
            A file that is missing, too large, not a mesh, or a mesh :class:`MeshSurface` refuses.
        """
        vertices, faces = read_mesh(path)
        return cls(vertices, faces, transform, scale, flip, spacing, band, smoothing)


@checked_keywords
class PointCloudSurface(PartSurface):
    """A part given as points on its surface (a scan), its surface smooth to the second derivative.

    Parameters
    ----------
    points : array_like
        N x 3 points on the part [m, base axes].
    normals : array_like, optional
        N x 3 normals there, pointing to the tool's side; without them each point's normal is the direction
        of least spread of its ``neighbours`` nearest points, turned towards ``viewpoint``.
    viewpoint : array_like, optional
        A point on the tool's side (the scanner's position) [m]: needed without ``normals``.
    neighbours : int
        The points that give an estimated normal (at least 6).
    spacing, band, smoothing
        As :class:`MeshSurface` takes them.

    Raises
    ------
    HybridError
        Too few points, points or normals that are not numbers, normals of zero length, no viewpoint without
        normals, points on a line (within a tenth of a cell of it), a cloud too sparse for its spacing.

    Warns
    -----
    PartFitWarning
        A fit that follows the cloud poorly (as :class:`MeshSurface`'s; also a cloud of two layers, whose
        estimated normals scatter).

    Examples
    --------
    The upper half of a sphere of 0.1 m, scanned from above (the normals estimated, turned to the scanner):

    >>> import hybrid, numpy as np
    >>> n = np.random.default_rng(0).normal(size=(8000, 3))
    >>> n = n[n[:, 2] > 0.3]
    >>> n /= np.linalg.norm(n, axis=1, keepdims=True)
    >>> scan = hybrid.PointCloudSurface(0.1 * n, viewpoint=(0, 0, 1),
    ...                                 spacing=0.008, band=0.02)
    >>> round(float(scan.normal_at([0.0, 0.0, 0.101])[2]), 3)
    1.0
    """

    kind = "point_cloud"

    def __init__(self, points, normals=None, viewpoint=None, neighbours: int = 12, spacing: float | None = None,
                 band: float | None = None, smoothing: float = SMOOTHING):
        what = "PointCloudSurface"
        p = _array(what, "points", points)
        if len(p) < 100:
            raise HybridError(f"{what}: {len(p)} points; give at least 100 points on the part")
        if normals is None:
            if viewpoint is None:
                raise HybridError(f"{what}: without normals, give viewpoint= (a point on the tool's side, the "
                                  "scanner's position) to orient the estimated ones")
            if isinstance(neighbours, bool) or not isinstance(neighbours, (int, np.integer)) or neighbours < 6:
                raise HybridError(f"{what}.neighbours = {shown(neighbours, 30)}; give a whole number >= 6")
            eye = np.array(_point(what, "viewpoint", viewpoint, (3,)))
            n = estimated_normals(p, int(neighbours), eye, what)
            given = {"viewpoint": eye.tolist(), "neighbours": int(neighbours)}
        else:
            n = _array(what, "normals", normals)
            if n.shape != p.shape:
                raise HybridError(f"{what}: {len(n)} normals for {len(p)} points; give one per point")
            length = np.linalg.norm(n, axis=1)
            if (length <= 1e-12).any():
                raise HybridError(f"{what}: normal {int(np.argmax(length <= 1e-12))} has no length; give unit "
                                  "normals towards the tool's side")
            given = {"normals": np.asarray(normals, float).tolist()}  # as given: read, it is normalised alike
            n = n / length[:, None]
        extent = float(np.linalg.norm(np.ptp(p, axis=0)))
        if not SMALLEST_PART <= extent <= LARGEST_PART:
            raise HybridError(f"{what} is {extent:.3g} m across; a part in a robot cell is {SMALLEST_PART:g} to "
                              f"{LARGEST_PART:g} m: give its points in metres")
        self._settings(p, spacing, band, smoothing, what)
        check_spread(p, self.spacing, what)
        gaps = sparsest(p)  # before the fit: a cloud too sparse for its cells is refused at once
        if gaps > 2 * self.spacing:
            raise HybridError(f"{what}: points {gaps:.3g} m apart where the fit's cells are {self.spacing:.3g} m; "
                              f"give spacing >= {gaps / 2:.2g} m, or a denser cloud")
        # a dense scan: one point in so many, evenly, is fitted (the report reads them all)
        every = max(1, -(-len(p) // MOST_SAMPLES))
        self._fitted(p[::every], n[::every], what)
        self.points, self.normals = p, n
        self._arguments = {"points": p.tolist(), **given, "spacing": self.spacing, "band": self.band,
                           "smoothing": self.smoothing}
        self._report(p, p, n, min(len(p), MOST_SAMPLES))


def _length(what: str, name: str, value) -> float:
    _finite(what, **{name: value})
    if not value >= SHORTEST:
        raise HybridError(f"{what}.{name} = {value} m; give a length of at least {SHORTEST:g} m")
    return float(value)


def _area(v: np.ndarray, f: np.ndarray) -> float:
    return float(face_areas(v, f).sum())


def _array(what: str, name: str, value) -> np.ndarray:
    try:
        a = np.asarray(value, float)
    except (TypeError, ValueError):
        a = None
    if a is None or a.ndim != 2 or a.shape[1] != 3:
        raise HybridError(f"{what}.{name}: give N x 3 numbers")
    if not np.isfinite(a).all():
        raise HybridError(f"{what}.{name}: row {int(np.flatnonzero(~np.isfinite(a).all(axis=1))[0])} is not finite; "
                          "give finite numbers")
    return a
