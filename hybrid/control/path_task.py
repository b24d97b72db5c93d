"""A task along a path on a surface (:class:`PathTask`) and its follower (:class:`PathFollower`).

The task is the path, the speed and the normal force along it (numbers, or functions of the arc
length), the acceleration limit of the speed's trapezoid and the cross-track gain. Its follower holds
the path as a table (:data:`hybrid.spec.path_follow.PATH_TABLE`) and calls the generated follower
(``hybrid_path.h``, :mod:`hybrid.spec.path_follow`) once a sample: the :class:`~hybrid.Controller`
takes the task frame's direction and the loops' references from it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from hybrid.control.options import call_user
from hybrid.control.task_settings import gain_array
from hybrid.errors import HybridError, NonFiniteError
from hybrid.geometry.paths import CirclePath, Path
from hybrid.geometry.surface_points import project_points
from hybrid.geometry.surfaces import Surface
from hybrid.geometry.task_axes import frame_direction_of
from hybrid.native import loader
from hybrid.spec.controller_step import LOOP_GAINS, NO_LIMIT
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_SETTINGS, PATH_STATE, PATH_STATUSES, PATH_TABLE, path_axes
from hybrid.validate import _finite, checked_keywords, shown

#: how far [m] a path's node may be from the surface
ON_SURFACE_TOL = 1e-4
#: the step [m] of the central differences of a path's tangent where the path gives no curvature
CURVATURE_STEP = 1e-4
#: how far a path of one's own may be from an arc-length parametrisation between nodes (relative)
ARC_LENGTH_TOL = 1e-2
#: a touch force of minus this: touching from the start (the controller's "off", as its loss threshold's)
NO_TOUCH = 1e300
#: the tip's rotation a follower is given when none is (its spin references then turn base z)
_IDENTITY = np.eye(3).ravel()
#: what the settings left out are: the release's time [s], the retreat's speed [m/s], the tool's turn rate [1/s]
DEFAULTS = {"unload_time": 0.2, "retreat_speed": 0.02, "orientation_gain": 10.0}
#: the most nodes a path's table may have (8 bytes times 15 numbers each: about 120 MB)
MAX_ROWS = 1_000_000
#: the least cosine of the turn between neighbouring nodes' tangents (a cusp reverses the tangent)
MAX_TURN = 0.0
#: the largest tilt or lead angle [rad] (80 degrees: the tool well off the surface's plane)
MAX_ANGLE = math.radians(80.0)
#: the largest cross-track gain times the sample period: a correction sampled slower is not a first-order lag
MAX_GAIN_SAMPLES = 0.5


@checked_keywords
@dataclass(frozen=True)
class PathTask:
    """Follow ``path`` on its surface at ``speed`` [m/s] pressing with ``force`` [N] along the normal.

    Parameters
    ----------
    path : Path
        The path on the surface, 3-D: a :class:`~hybrid.WaypointPath`, :class:`~hybrid.RasterPath`,
        :class:`~hybrid.SpiralPath`, a :class:`~hybrid.CirclePath` in space, or one's own :class:`Path`
        parametrised by arc length with a ``length`` (and ``closed``, default False). The run starts at
        its ``start`` arc length and runs towards growing arc length.
    speed : float or callable
        The speed along the path [m/s]: a number, or ``speed(s)`` of the arc length ``s`` [m] (the
        acceleration along the path, ``v dv/ds``, at most ``acceleration``). The speed reference is
        it within the turns' limit (the centripetal acceleration ``v^2 |kappa_g|`` of the path's turn on
        the surface at most ``acceleration``: a raster's turnarounds are slower) and a trapezoid: from
        ``speed_start`` up at ``acceleration``, and on an open path down to 0 at its end.
    force : float or callable
        The normal force [N]: a number, or ``force(s)`` of the arc length.
    acceleration : float
        The acceleration limit along the path and across it in turns [m/s^2].
    speed_start : float, optional
        The speed reference at the start [m/s] (above 0: the progress follows the tip, which must move);
        default a tenth of the speed there.
    cross_track_gain : float
        [1/s] the cross-track error ``d`` is corrected by the velocity reference ``-gain d`` along ``t2``
        (a time constant of ``1 / gain``), at most the task's speed in magnitude; ``gain`` times the sample
        period at most 0.5.
    laps : float, optional
        A closed path's number of laps (None: it runs until the experiment ends); an open path runs to
        its end.
    retreat_distance : float
        [m] at the end, the force is released over ``unload_time`` and the tip retreats along the normal at
        ``retreat_speed`` [m/s] until it is this far from the surface, where it stops (the normal axis is
        velocity-controlled from the retreat on); 0 (the default): the tip stays at the end, pressing.
    unload_time : float, optional
        [s] the time over which the force is released before the retreat (default 0.2 s); only with a
        ``retreat_distance``.
    retreat_speed : float, optional
        [m/s] the speed of the retreat (default 0.02 m/s); only with a ``retreat_distance``.
    tilt, lead : float or callable
        [rad] the tool's angles from the normal, numbers or functions of the arc length: its axis (the tip
        frame's z) is ``-n`` turned by ``lead`` about ``t2`` (positive: its tip trails, the flange leads along
        ``t1``), then by ``tilt`` about ``t1``; each below 80 degrees. They need the rotational task axes
        about ``t1`` and ``t2`` (``axes="all"``), velocity-controlled.
    orientation_gain : float, optional
        [1/s] the tool's axis turns towards the tilted one at this rate (angular velocity references about
        ``t1`` and ``t2``; default 10 1/s), on a task with those rotational axes only; its product with the
        sample period at most 0.5.
    spacing : float
        The longest distance [m] between the table's nodes (the interpolation's error is about
        ``spacing^4 kappa^3 / 384``: 1e-10 m at 1 mm on a curve of 1 cm radius); at most a million nodes.
        A path whose tangent turns by more than 90 degrees between nodes (a cusp, or a turn the spacing
        does not resolve) is refused.

    Examples
    --------
    >>> import hybrid
    >>> plane = hybrid.Plane((0.4, 0.0, 0.2), (0.0, 0.0, 1.0))
    >>> raster = hybrid.RasterPath(plane, (0.4, -0.05, 0.2),
    ...                            (1.0, 0.0, 0.0), 0.1, 0.01, 3)
    >>> task = hybrid.PathTask(raster, speed=0.1, force=10.0)
    >>> table, settings = task.table(plane)
    >>> table.shape[1], bool(settings[1])
    (15, False)
    """

    path: Path
    speed: float | Callable[[float], float] = 0.1
    force: float | Callable[[float], float] = 10.0
    acceleration: float = 0.5
    speed_start: float | None = None
    cross_track_gain: float = 20.0
    laps: float | None = None
    spacing: float = 1e-3
    retreat_distance: float = 0.0
    unload_time: float | None = None
    retreat_speed: float | None = None
    tilt: float | Callable[[float], float] = 0.0
    lead: float | Callable[[float], float] = 0.0
    orientation_gain: float | None = None

    def __post_init__(self):
        if not isinstance(self.path, Path):
            raise HybridError(f"PathTask.path = {shown(self.path, 60)}; give a hybrid path (WaypointPath, RasterPath, "
                              "SpiralPath, CirclePath, or a subclass of hybrid.geometry.paths.Path)")
        for name in ("speed", "force", "tilt", "lead"):
            value = getattr(self, name)
            if not callable(value):
                _finite("PathTask", **{name: value})
        if self.orientation_gain is not None:
            _finite("PathTask", orientation_gain=self.orientation_gain)
            if self.orientation_gain < 0:
                raise HybridError(f"PathTask.orientation_gain = {self.orientation_gain} 1/s; give a gain >= 0")
        _finite("PathTask", acceleration=self.acceleration, cross_track_gain=self.cross_track_gain,
                spacing=self.spacing)
        if not self.acceleration > 0:
            raise HybridError(f"PathTask.acceleration = {self.acceleration} m/s^2; give a positive acceleration limit")
        if self.cross_track_gain < 0:
            raise HybridError(f"PathTask.cross_track_gain = {self.cross_track_gain} 1/s; give a gain >= 0")
        _finite("PathTask", retreat_distance=self.retreat_distance)
        if self.retreat_distance < 0:
            raise HybridError(f"PathTask.retreat_distance = {self.retreat_distance} m; give a distance >= 0 (0: no "
                              "retreat)")
        for name in ("unload_time", "retreat_speed"):
            if getattr(self, name) is not None:
                _finite("PathTask", **{name: getattr(self, name)})
                if not self.retreat_distance > 0:
                    raise HybridError(f"PathTask.{name} = {getattr(self, name)} acts at the retreat: give a "
                                      "retreat_distance too, or leave it out")
        if self.unload_time is not None and self.unload_time < 0:
            raise HybridError(f"PathTask.unload_time = {self.unload_time} s; give a time >= 0")
        if self.retreat_speed is not None and not self.retreat_speed > 0:
            raise HybridError(f"PathTask.retreat_speed = {self.retreat_speed} m/s; give a positive speed to retreat "
                              f"{self.retreat_distance} m")
        if not 0 < self.spacing <= 0.1:
            raise HybridError(f"PathTask.spacing = {self.spacing} m; give a node spacing in (0, 0.1] m (1 mm: "
                              "the default)")
        if self.speed_start is not None:
            _finite("PathTask", speed_start=self.speed_start)
            if not self.speed_start > 0:
                raise HybridError(f"PathTask.speed_start = {self.speed_start} m/s; give a positive start speed (the "
                                  "progress follows the tip, which must move)")
        if self.laps is not None:
            _finite("PathTask", laps=self.laps)
            if not self.laps > 0:
                raise HybridError(f"PathTask.laps = {self.laps}; give a positive number of laps, or None")

    # ------------------------------------------------------------------ the path as a table

    def extent(self) -> tuple[float, bool]:
        """The path's length and whether it is closed.

        Returns
        -------
        length : float
            [m] the path's arc length (a closed path's: one lap).
        closed : bool
            True for a closed path (it wraps around; ``laps`` says how often it is run).
        """
        path = self.path
        closed = bool(getattr(path, "closed", isinstance(path, CirclePath)))
        length = 2 * math.pi * path.radius if isinstance(path, CirclePath) else getattr(path, "length", None)
        if not isinstance(length, (int, float, np.floating)) or not (0 < length < math.inf):
            raise HybridError(f"PathTask.path = {type(path).__name__} has no finite length; give a path with an end "
                              "(a WaypointPath through two points for a straight one) or a closed one")
        if self.laps is not None and not closed:
            raise HybridError(f"PathTask.laps = {self.laps}: an open path runs to its end; leave laps out")
        return float(length), closed

    def _frames(self, surface, s: np.ndarray):
        """Points, tangents, normals and curvature vectors of the path at ``s``, checked to lie on ``surface``."""
        path, name = self.path, type(self.path).__name__
        if hasattr(path, "frames_at"):
            points, tangents, normals, kappa = path.frames_at(s)
        else:
            points = np.asarray(path.points_at(s), dtype=float)
            if points.ndim != 2 or points.shape[1] != 3:
                raise HybridError(f"PathTask.path = {name} gives points of shape {points.shape[1:]}; a path task is "
                                  "3-D: give a path of 3 coordinates")
            tangents = self._tangents(s)
            h = CURVATURE_STEP
            kappa = (self._tangents(s + h) - self._tangents(s - h)) / (2 * h)
            normals = None
        if not (np.isfinite(points).all() and np.isfinite(tangents).all() and np.isfinite(kappa).all()):
            raise NonFiniteError(f"PathTask.path = {name} gives points or tangents that are not finite; give a path "
                                 "defined along its whole length")
        on, surface_normals = project_points(surface, points, "PathTask.path")
        off = np.linalg.norm(on - points, axis=1)
        if off.max() > ON_SURFACE_TOL:
            i = int(np.argmax(off))
            raise HybridError(f"PathTask.path = {name} leaves the surface: at s = {s[i]:.4g} m its point "
                              f"{np.round(points[i], 5).tolist()} m is {off[i] * 1e3:.3g} mm off it; give a path on "
                              f"the surface (within {ON_SURFACE_TOL * 1e3:g} mm)")
        normals = surface_normals if normals is None else normals
        return points, tangents, normals, kappa

    def _tangents(self, s: np.ndarray) -> np.ndarray:
        t = np.array([np.asarray(self.path.tangent_at(float(x)), dtype=float) for x in s])
        return t / np.linalg.norm(t, axis=1)[:, None]

    def _nodes(self, length: float) -> np.ndarray:
        """The table's arc lengths: at most ``spacing`` apart, with a node at every joint of the path's pieces
        (where its curvature may jump, which no cubic between nodes would follow)."""
        if length / self.spacing > MAX_ROWS:
            raise HybridError(f"PathTask.spacing = {self.spacing} m asks {length / self.spacing:.3g} nodes for a "
                              f"{length:.4g} m path (at most {MAX_ROWS:.0e}); give a spacing of at least "
                              f"{length / MAX_ROWS:.3g} m")
        joints = np.asarray(getattr(self.path, "joints", (0.0, length)), dtype=float)
        breaks = np.unique(np.clip(np.concatenate([[0.0, length], joints]), 0.0, length))
        breaks = breaks[np.concatenate([[True], np.diff(breaks) > 1e-9 * length])]
        breaks[-1] = length
        parts = [np.linspace(a, b, int(math.ceil((b - a) / self.spacing)) + 1)[:-1]
                 for a, b in zip(breaks[:-1], breaks[1:])]
        return np.concatenate([*parts, [length]])

    def check_sampling(self, sample_time: float) -> None:
        """Refuse gains too fast for the sample period ``sample_time`` [s]: a correction sampled slower than
        :data:`MAX_GAIN_SAMPLES` times its time constant is no first-order lag.

        Parameters
        ----------
        sample_time : float
            The controller's sample period [s].
        """
        for name in ("cross_track_gain", "orientation_gain"):
            gain = DEFAULTS[name] if getattr(self, name) is None else getattr(self, name)
            if gain * sample_time > MAX_GAIN_SAMPLES:
                raise HybridError(f"PathTask.{name} = {gain} 1/s is too fast for the sample period {sample_time} "
                                  f"s (gain x period = {gain * sample_time:.3g}, at most {MAX_GAIN_SAMPLES}); give a "
                                  f"gain up to {MAX_GAIN_SAMPLES / sample_time:.4g} 1/s")

    def frame_direction(self, surface, given=None) -> tuple[float, float, float]:
        """The task frame's direction at the path's start, ``e = n x t``, which a controller starts from (its
        follower sets it each sample).

        Parameters
        ----------
        surface : Surface
            The surface the controller is told.
        given : array_like, optional
            A direction given besides the task (an experiment's or a controller's ``frame_direction``): refused
            unless it is this one.

        Returns
        -------
        tuple of float
            ``e`` (base axes, a unit vector).
        """
        length, closed = self.extent()
        start = float(np.mod(self.path.start, length)) if closed else float(self.path.start)
        _, tangents, normals, _ = self._frames(surface, np.array([start]))
        e = np.cross(normals[0], tangents[0])
        e /= np.linalg.norm(e)
        if given is not None and not np.allclose(frame_direction_of(given), e, rtol=0, atol=1e-9):
            raise HybridError(f"frame_direction = {shown(given, 60)}: with a path task the direction is the path's "
                              f"(n x t, {np.round(e, 6).tolist()} at its start); leave frame_direction out")
        return tuple(e.tolist())

    def angles_at(self, s: float) -> tuple[float, float]:
        """The tool's angles at an arc length.

        Parameters
        ----------
        s : float
            The arc length [m].

        Returns
        -------
        tuple of float
            ``(tilt, lead)`` there [rad], each checked to be a finite number.
        """
        at = np.array([float(s)])
        return float(self._profile("tilt", at)[0]), float(self._profile("lead", at)[0])

    def force_at(self, s: float) -> float:
        """The task's force at an arc length.

        Parameters
        ----------
        s : float
            The arc length [m].

        Returns
        -------
        float
            ``force`` there [N], checked to be a finite number.
        """
        return float(self._profile("force", np.array([float(s)]))[0])

    def _profile(self, name: str, s: np.ndarray) -> np.ndarray:
        value = getattr(self, name)
        if not callable(value):
            return np.full(len(s), float(value))
        got = []
        for x in s:
            y = call_user(value, float(x), f"PathTask.{name}")
            if isinstance(y, (bool, np.bool_)) or not isinstance(y, (int, float, np.integer, np.floating)):
                raise HybridError(f"PathTask.{name}({x:.4g}) gave {shown(y, 40)}; {name}(s) returns one number")
            got.append(float(y))
        arr = np.array(got)
        if not np.isfinite(arr).all():
            i = int(np.flatnonzero(~np.isfinite(arr))[0])
            raise HybridError(f"PathTask.{name}({s[i]:.4g}) = {arr[i]}; give a finite {name} along the whole path")
        return arr

    def table(self, surface, sample_time: float = 0.01,
              touch_force: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The follower's table (one row of :data:`~hybrid.spec.path_follow.PATH_TABLE` per node) and settings
        (:data:`~hybrid.spec.path_follow.PATH_SETTINGS`) on ``surface``.

        Parameters
        ----------
        surface : Surface
            The surface the controller is told (the path's normals are its own, or this surface's).
        sample_time : float
            [s] the controller's sample period (the release's clock).
        touch_force : float, optional
            [N] the normal force from which the tip touches (the controller's contact-loss threshold); None:
            touching from the start.

        Returns
        -------
        table : ndarray, shape (rows, 15)
            One node per row: arc length, point, tangent, normal, geodesic curvature, speed, force, tilt, lead.
        settings : ndarray, shape (15,)
            :data:`~hybrid.spec.path_follow.PATH_SETTINGS`, in that order.
        """
        if not isinstance(surface, Surface):
            raise HybridError(f"PathTask.table: surface = {shown(surface, 60)}; give the hybrid surface the path is on")
        _finite("PathTask.table", sample_time=sample_time)
        if not sample_time > 0:
            raise HybridError(f"PathTask.table: sample_time = {sample_time} s; give a positive sample period")
        self.check_sampling(sample_time)
        length, closed = self.extent()
        s = self._nodes(length)
        rows = len(s)
        points, tangents, normals, kappa = self._frames(surface, s)
        if closed:  # one point at both ends
            points[-1], tangents[-1], normals[-1], kappa[-1] = points[0], tangents[0], normals[0], kappa[0]
        turn = np.einsum("ij,ij->i", tangents[:-1], tangents[1:])
        if turn.min() < MAX_TURN:
            i = int(np.argmin(turn))
            raise HybridError(f"PathTask.path = {type(self.path).__name__} turns by "
                              f"{math.degrees(math.acos(max(-1.0, turn[i]))):.0f} degrees from s = {s[i]:.4g} m to "
                              f"{s[i + 1]:.4g} m: a cusp, or a turn the node spacing does not resolve; give a smooth "
                              "path (a turn of some radius), or a smaller spacing")
        # the chord of an arc turning by theta is ds (1 - theta^2 / 24): farther off, s is not the arc length
        chords = np.linalg.norm(np.diff(points, axis=0), axis=1)
        ds = np.diff(s)
        expected = ds * (1 - np.arccos(np.clip(turn, -1.0, 1.0)) ** 2 / 24)
        stretch = np.abs(chords / expected - 1)
        if stretch.max() > ARC_LENGTH_TOL:
            i = int(np.argmax(stretch))
            raise HybridError(f"PathTask.path = {type(self.path).__name__} is not parametrised by arc length: from s = "
                              f"{s[i]:.4g} m to {s[i + 1]:.4g} m its point moves {chords[i]:.4g} m; give point_at(s) "
                              "at arc length s")
        kappa_g = np.einsum("ij,ij->i", kappa, np.cross(normals, tangents))
        speed, force = self._profile("speed", s), self._profile("force", s)
        tilt, lead = self._profile("tilt", s), self._profile("lead", s)
        for name, angle in (("tilt", tilt), ("lead", lead)):
            if np.abs(angle).max() >= MAX_ANGLE:
                i = int(np.argmax(np.abs(angle)))
                raise HybridError(f"PathTask.{name} at s = {s[i]:.4g} m is {math.degrees(angle[i]):.1f} degrees; give "
                                  f"an angle from the normal below {math.degrees(MAX_ANGLE):.0f} degrees (in rad)")
        if not (speed > 0).all():
            i = int(np.flatnonzero(~(speed > 0))[0])
            raise HybridError(f"PathTask.speed at s = {s[i]:.4g} m is {speed[i]} m/s; give a positive speed")
        rate = speed[:-1] * np.diff(speed) / np.diff(s)
        if np.abs(rate).max() > self.acceleration * (1 + 1e-9):
            i = int(np.argmax(np.abs(rate)))
            raise HybridError(f"PathTask.speed changes at {abs(rate[i]):.3g} m/s^2 near s = {s[i]:.4g} m, beyond the "
                              f"acceleration limit {self.acceleration} m/s^2; raise acceleration or smooth the speed")
        peak = float(speed.max())  # as asked: the turns' limit below slows where it must
        speed = _turn_limited(speed, kappa_g, np.diff(s), self.acceleration)
        start = float(np.mod(self.path.start, length)) if closed else float(self.path.start)
        if not 0 <= start <= length:
            raise HybridError(f"PathTask.path.start = {start} m is beyond the path (0 to {length:.6g} m); give a start "
                              "on it")
        speed_start = 0.1 * float(np.interp(start, s, speed)) if self.speed_start is None else float(self.speed_start)
        distance = (NO_LIMIT if self.laps is None else self.laps * length) if closed else length - start
        need = (max(peak ** 2 - speed_start ** 2, 0.0) + peak ** 2) / (2 * self.acceleration)
        if not closed and need > distance:
            raise HybridError(f"PathTask: at {self.acceleration} m/s^2 the speed {peak} m/s is not reached within the "
                              f"path ({distance:.4g} m to travel, {need:.4g} m needed to speed up and stop); lower "
                              "the speed or raise the acceleration")
        table = np.column_stack([s, points, tangents, normals, kappa_g, speed, force, tilt, lead])
        settings = {"rows": rows, "closed": float(closed), "length": length, "start": start, "distance": distance,
                    "speed_start": speed_start, "acceleration": self.acceleration,
                    "cross_track_gain": self.cross_track_gain, "cross_track_limit": peak,
                    "touch_force": -NO_TOUCH if touch_force is None else float(touch_force),
                    "sample_time": float(sample_time), "retreat_distance": self.retreat_distance,
                    **{name: DEFAULTS[name] if getattr(self, name) is None else getattr(self, name)
                       for name in ("unload_time", "retreat_speed", "orientation_gain")}}
        assert table.shape[1] == len(PATH_TABLE)
        return np.ascontiguousarray(table), np.array([settings[k] for k in PATH_SETTINGS], dtype=float)


def _turn_limited(speed: np.ndarray, kappa_g: np.ndarray, ds: np.ndarray, a: float) -> np.ndarray:
    """The speed at the nodes within the turns' limit ``v^2 |kappa_g| <= a`` (the centripetal acceleration
    on the surface), then within the acceleration limit along the path (``v dv/ds <= a``: a forward and a
    backward pass over ``v^2``)."""
    with np.errstate(divide="ignore"):
        v2 = np.minimum(speed ** 2, a / np.abs(kappa_g))
    for i in range(1, len(v2)):
        v2[i] = min(v2[i], v2[i - 1] + 2 * a * ds[i - 1])
    for i in range(len(v2) - 2, -1, -1):
        v2[i] = min(v2[i], v2[i + 1] + 2 * a * ds[i])
    return np.sqrt(v2)


class PathFollower:
    """A :class:`PathTask` on a surface, followed sample by sample (the generated follower).

    ``follow(p, force)`` gives the outputs (:data:`~hybrid.spec.path_follow.PATH_OUTPUT`, by index) for the
    tip at ``p`` [m] under the contact force ``force`` [N, base axes] without changing the state; ``advance()``
    keeps the last sample's state; ``reset()`` starts the run again."""

    def __init__(self, task: PathTask, surface, sample_time: float = 0.01, touch_force: float | None = None):
        self.task = task
        self.table, self.settings = task.table(surface, sample_time, touch_force)
        module = loader.path_follower()
        self._ffi, self._lib = module.ffi, module.lib
        self._table_ptr = self._ffi.from_buffer("double[]", self.table)
        self._settings_ptr = self._ffi.from_buffer("double[]", self.settings)
        if not self._lib.hybrid_path_table_entry(self._table_ptr, self._settings_ptr):
            raise HybridError("PathTask: the path's table is not one the follower takes (not finite, or its arc "
                              "lengths do not grow); give a path defined along its whole length")
        self.state = np.zeros(len(PATH_STATE))
        self.out = np.zeros(len(PATH_OUTPUT))
        self.served = np.zeros(len(PATH_OUTPUT))  # the outputs of the last sample served
        self._p, self._R, self._force = np.zeros(3), _IDENTITY.copy(), np.zeros(3)
        self._ptrs = [self._ffi.from_buffer("double[]", a) for a in (self.state, self._p, self._R, self._force,
                                                                       self.out)]

    def follow(self, p, force, R=None) -> np.ndarray:
        """The outputs for the tip at ``p`` [m, base axes] under the contact force ``force`` [N, base axes: the
        wrench on the robot], the tip frame's rotation ``R`` (3 x 3 or 9 numbers row by row; default the
        identity: the spin references then turn base z) (the state stays until :meth:`advance`)."""
        self._p[:], self._force[:] = p, force
        self._R[:] = _IDENTITY if R is None else np.ravel(R)
        status = self._lib.hybrid_path_follow_entry(self._table_ptr, self._settings_ptr, *self._ptrs)
        if status != PATH_STATUSES["PATH_OK"]:
            name = next(k for k, v in PATH_STATUSES.items() if v == status)
            raise NonFiniteError(f"the path follower refused the sample ({name}): tip {self._p.tolist()} m, state "
                                 f"{self.state.tolist()}")
        return self.out

    def advance(self) -> None:
        """Keep the last sample's progress and outputs (a sample served as time passed)."""
        self.state[:] = self.out[:len(PATH_STATE)]
        self.served[:] = self.out

    def reset(self) -> None:
        """Back to the path's start: no progress, no outputs served."""
        self.state[:] = 0.0
        self.served[:] = 0.0


_OUT = {name: i for i, name in enumerate(PATH_OUTPUT)}
#: the step's parameters a path task changes as it runs
PATH_CHANGES = ("e", "selection", "gains")
#: where the follower's settings hold the sample period (the controller's, written there each sample)
PATH_SAMPLE_TIME = PATH_SETTINGS.index("sample_time")
_E = slice(_OUT["e_x"], _OUT["e_z"] + 1)


def _fixed(a: np.ndarray) -> np.ndarray:
    """``a`` read-only, as the step's parameters are (they change only by replacement)."""
    a.flags.writeable = False
    return a


class PathReferences:
    """A :class:`PathTask` in a :class:`~hybrid.Controller`: each sample, the follower's task frame direction
    ``e`` and its references of ``t1`` (speed), ``t2`` (cross-track correction and the turn's feedforward)
    and ``n`` (force; in the retreat, speed, the normal axis then velocity-controlled), written into the
    step's inputs.

    ``follower`` holds the table, settings and state; ``positions`` where ``t1``, ``t2`` and ``n`` are among the
    task axes; ``retreat_gains`` the
    normal axis's loop gains in the retreat (its velocity gains)."""

    def __init__(self, task: PathTask, surface, robot, axes: tuple[int, ...], selection: tuple[int, ...], gains,
                 sample_time: float, touch_force: float | None, references_given: bool, loop_frame_given: bool):
        if not isinstance(task, PathTask):
            raise HybridError(f"path_task = {shown(task, 60)}; give a hybrid.PathTask(path, speed=..., force=...) or "
                              "None")
        if robot.kind.force_size != 3:
            raise HybridError("path_task: the planar arm's tip runs along its surface's cross-section; a path task is "
                              "for an arm in space")
        if not all(i in axes for i in (0, 1, 2)) or selection[axes.index(2)] != 1 or \
                selection[axes.index(0)] or selection[axes.index(1)]:
            raise HybridError("path_task needs the task axes t1 and t2 velocity-controlled and n force-controlled "
                              "(axes 'position' or 'all', the default selection)")
        if surface.spec().estimated:
            raise HybridError("path_task: the path is drawn on a surface the controller knows; give that surface "
                              "instead of an EstimatedSurface")
        if references_given:
            raise HybridError("path_task gives the speed along t1, the cross-track correction on t2 and the force on "
                              "n: leave force_reference and velocity_reference out (give them in the PathTask)")
        if loop_frame_given:
            raise HybridError("path_task puts the loops in the frame at the tip, along the path: leave frame, "
                              "position_error and path at their defaults")
        self.follower = PathFollower(task, surface, sample_time, touch_force)
        # the rotations about t1 and t2, where the task has them: the tool's tilt and lead
        self.positions, self.spins = path_axes(axes)
        self._t1, self._t2, self._n = self.positions
        tilted = np.any(self.follower.table[:, [PATH_TABLE.index("tilt"), PATH_TABLE.index("lead")]] != 0)
        if task.orientation_gain is not None and self.spins is None:
            raise HybridError(f"path_task.orientation_gain = {task.orientation_gain} turns the tool about t1 and t2, "
                              "which are not task axes here; give axes='all' (or leave it out)")
        if tilted and self.spins is None:
            raise HybridError("path_task: a tilt or lead angle turns the tool about t1 and t2, which are not task "
                              "axes here; give axes='all' (or leave tilt and lead 0)")
        if self.spins is not None and any(selection[k] for k in self.spins):
            raise HybridError("path_task: the rotations about t1 and t2 turn the tool to its tilt and lead: keep "
                              "them velocity-controlled (leave them out of selection)")
        retreat = tuple(0 if k == self._n else s for k, s in enumerate(selection))
        k = len(LOOP_GAINS) * self._n
        self.retreat_gains = gain_array(gains, retreat)[k:k + len(LOOP_GAINS)]

    def write(self, p, R, force, params: dict, extra: np.ndarray, rate: np.ndarray) -> dict[str, np.ndarray]:
        """The references for the tip at ``p`` [m] with the rotation ``R`` (9 numbers, row by row) under the
        contact force ``force`` [N, base axes] into ``extra`` and ``rate``; the step's parameters that change
        (of ``params``, by name: ``e`` as the path turns, ``selection`` and ``gains`` at the retreat, where the
        caller starts the normal axis's loop afresh), as new read-only arrays."""
        out = self.follower.follow(p, force, R)
        extra[self._t1], rate[self._t1] = out[_OUT["speed"]], out[_OUT["speed_rate"]]
        extra[self._t2], rate[self._t2] = out[_OUT["lateral_speed"]], out[_OUT["lateral_rate"]]
        extra[self._n] = out[_OUT["normal_reference"]]
        if self.spins is not None:
            extra[self.spins[0]], extra[self.spins[1]] = out[_OUT["spin_t1"]], out[_OUT["spin_t2"]]
        changed = {}
        if not np.array_equal(params["e"], out[_E]):
            changed["e"] = _fixed(out[_E].copy())
        if out[_OUT["retreat"]] == 1.0 and params["selection"][self._n] != 0.0:
            selection, gains = params["selection"].copy(), params["gains"].copy()
            selection[self._n] = 0.0
            k = len(LOOP_GAINS) * self._n
            gains[k:k + len(LOOP_GAINS)] = self.retreat_gains
            changed.update(selection=_fixed(selection), gains=_fixed(gains))
        return changed

    @property
    def last(self) -> dict[str, float]:
        """The follower's outputs at the last sample served, by name (:data:`~hybrid.spec.path_follow.PATH_OUTPUT`;
        as the standalone C's ``path``)."""
        return dict(zip(PATH_OUTPUT, self.follower.served.tolist()))
