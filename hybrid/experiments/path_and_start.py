"""Where an :class:`~hybrid.Experiment`'s run starts and where its desired point goes.

:class:`PathAndStart` is the experiment's part that works these out from its settings: the surface's cross-section
the planar arm runs on (the geometry the start, the path and the normals are taken on), the sensor tip's start
point, the path the desired point follows and the desired point on it at a time, the run's start state (worked out
in :mod:`hybrid.experiments.start`), and the checks every run makes before it starts (its record fits in memory,
its path stays in the arm's workspace).
"""

from __future__ import annotations

from functools import cached_property, lru_cache

import numpy as np

from hybrid.errors import HybridError
from hybrid.experiments.followed import check_reach
from hybrid.experiments.start import StartState, start_state
from hybrid.geometry.paths import Path


class PathAndStart:
    """An experiment's start and desired path (module docstring): it reads the experiment's ``robot``, ``surface``,
    ``path``, ``path_task``, ``start_point``, ``speed_reference`` and timing."""

    # worked out once: an experiment is immutable, and the settings with_physics changes (PHYSICS) reach none of it
    @cached_property
    def section(self):
        """The surface's cross-section the planar arm runs on (:meth:`Surface.cross_section`), or None."""
        return self.robot.kind.section(self.surface)

    def _geometry(self):
        """Where the start, the path and the normals are taken: the planar arm's cross-section, else the
        surface itself."""
        section = self.section
        return self.surface if section is None else section

    def followed_path(self) -> Path | None:
        """The path the desired point follows.

        Returns
        -------
        Path or None
            ``path`` when given, else the path task's, else the surface's through ``start_point``, else
            the surface's own; None where there is none.
        """
        if self.path is not None:
            return self.path
        if self.path_task is not None:
            return self.path_task.path
        geometry = self._geometry()
        if self.start_point is not None:
            projected = geometry.project(self.start_point)
            return geometry.path_through(self.start_point if projected is None else projected)
        try:
            return geometry.path()
        except HybridError:
            return None

    def start(self) -> np.ndarray:
        """The sensor tip's start point on the surface.

        Returns
        -------
        numpy.ndarray
            ``start_point`` projected onto the surface (the planar arm's cross-section), else the
            followed path's point at its ``start`` [m], base axes (2 coordinates for the planar arm).
        """
        if self.start_point is None:
            return self.followed_path().point_at(self.followed_path().start)
        projected = self._geometry().project(self.start_point)
        return np.array(self.start_point) if projected is None else projected

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """The desired point on the path, reached from the start at the desired speed.

        Parameters
        ----------
        t : float
            The time [s].

        Returns
        -------
        r_d, r_d_dot : numpy.ndarray
            ``r_d(t)`` [m], at the arc length ``arc_of(start) + int_0^t v_d``, and its velocity
            ``r_d'(t) = v_d(t)`` times the path's unit tangent [m/s], base axes.
        """
        path = self.followed_path()
        s = path.arc_of(self.start()) + self.speed_reference.integral(t)
        return path.point_at(s), self.speed_reference(t) * path.tangent_at(s)

    def initial_state(self) -> np.ndarray:
        """The run's start state: at rest, the sensor tip pressing at the start point with ``F_d(0)``
        (:func:`~hybrid.experiments.settings.pressed`), or with ``start_gap`` the sensor tip that far from
        it along the normal, out of contact, the sensor at rest (:func:`~hybrid.experiments.settings.free`);
        the tool's z axis along ``-n`` when the task has rotational axes, the joints from inverse
        kinematics of the true arm. What a foreign loop starts from.

        Returns
        -------
        numpy.ndarray
            ``x0 = (q, q', s, s')``: joint positions [rad or m] and velocities, the sensor tip [m] and its
            velocity [m/s] (base axes); a copy.
        """
        return start_state(self).copy()

    def start_state(self) -> StartState:
        """:meth:`initial_state` by its parts.

        Returns
        -------
        StartState
            ``q``, ``qdot``, ``sensor_tip``, ``sensor_velocity`` (and ``array``, the whole).
        """
        return StartState.of(start_state(self), self.robot.n)

    def checked_start(self, record: dict | None = None) -> np.ndarray:
        """:meth:`initial_state`, after the checks every run of this experiment makes before anything
        sized by its length is allocated: its record fits in memory (:meth:`check_memory`), and its path
        stays in the workspace (:meth:`check_path`). What ``simulate``, a sweep and ``generate`` start from.

        Parameters
        ----------
        record : dict, optional
            The plant's record, where the run keeps one (its columns size the memory check).

        Returns
        -------
        numpy.ndarray
            ``x0 = (q, q', s, s')``, as :meth:`initial_state`.
        """
        self.check_memory(record)
        x0 = self.initial_state()
        self.check_path()
        return x0

    def check_path(self) -> None:
        """Refuse a run whose desired path leaves the arm's workspace (where the reach is known; a path task's
        path, everywhere: :func:`~hybrid.experiments.followed.check_reach`)."""
        if self.path_task is not None:
            check_reach(self, self.initial_state()[:self.robot.n])
            return
        reach, path = self.robot.reach(), self.followed_path()
        if reach is not None and path is not None:
            _check_path(reach, path, path.arc_of(self.start()), self.speed_reference, self.n_samples,
                        self.sample_time, self.duration)


@lru_cache(maxsize=1024)
def _check_path(reach, path, s0, speed_reference, n_samples, sample_time, duration) -> None:
    lo, hi = reach
    t = np.minimum(np.arange(n_samples + 1) * sample_time, duration)
    points = path.points_at(s0 + speed_reference.integral(t))
    d = np.hypot(points[:, 0], points[:, 1])
    outside = np.flatnonzero(~((lo + 1e-3 < d) & (d < hi - 1e-3)))
    if len(outside):
        i = outside[0]
        raise HybridError(f"the desired path leaves the arm's workspace at t = {t[i]:.3f} s "
                          f"(point {np.round(points[i], 4).tolist()} m, {d[i]:.3f} m from the base, reach "
                          f"{lo:.3f}-{hi:.3f} m); shorten duration, lower the speed or move the surface")
