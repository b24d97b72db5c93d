"""The path follower's interface: a path on a surface as run-time data, and what it gives each sample.

A path task (:class:`hybrid.PathTask`) follows a curve on a surface at a speed and a normal force that
may change along it. Its path is a table (:data:`PATH_TABLE`, one row per node, nodes in increasing arc
length), so one compiled follower serves every path; the follower (``hybrid_path_follow`` in the
generated header ``hybrid_path.h``) reads the tip's position each sample and gives the task frame's
direction and the loops' references (:data:`PATH_OUTPUT`). The standalone C, the
:class:`hybrid.Controller` and the compiled closed loop call that one function.

Between nodes the path is the cubic Hermite curve through the nodes' points with their unit tangents
(an arc-length parametrisation: its error is about ``h^4 kappa^3 / 384`` for nodes ``h`` apart on a
curve of curvature ``kappa``); the normal, the geodesic curvature and the profiles are interpolated
linearly. Each sample:

1. the progress ``s`` moves to the path's point nearest the tip (Newton steps on ``(p - c(s)) . t(s)``
   from the last sample's ``s``: the measured motion along the path; at the first sample, from the node
   nearest the tip), within the path (an open path ends; a closed one wraps), and ``travelled`` (the arc
   length since the start) with it;
2. at ``c(s)``: the tangent ``t``, the surface's normal ``n`` and the cross-track direction
   ``e = n x t``, which, as the task frame's direction, makes ``t1 = e x n = t`` and ``t2 = n x t1 = e``;
3. the phase (:data:`PATH_PHASES`): before the first touch (the measured normal force below ``touch_force``)
   the tip approaches and does not move along the path; in contact it follows it; at the end (an open
   path's, a closed one's last lap) it is held there, pressing, unless there is a ``retreat_distance``: then
   the force is released over ``unload_time`` down to ``touch_force``, the normal axis turns
   velocity-controlled and the tip leaves along ``n`` at ``retreat_speed`` until it is that far from the
   surface, where it stops;
4. the tool's axis (the tip frame's z axis, from the tip's rotation ``R``) is turned towards ``-n`` turned
   by the lead angle about ``t2`` and then by the tilt angle about ``t1``: with ``w = z x z_d``, the angular
   velocity references ``orientation_gain * (w . t1)`` and ``orientation_gain * (w . t2)`` (for the
   rotational task axes about ``t1`` and ``t2``);
5. the speed along ``t1``: the table's speed bounded by the acceleration from ``speed_start`` since the
   start and, on an open path, by the deceleration to 0 at its end (a trapezoid in arc length), and its
   rate ``v dv/ds``; on ``t2``: ``-cross_track_gain * d`` for the cross-track error ``d = (p - c) . e``
   (at most ``cross_track_limit`` in magnitude),
   and the centripetal feedforward ``kappa_g v^2`` of the path's turn on the surface (the task frame's
   rate, computed for a fixed direction, does not carry it); on ``n``: the table's force.
"""

from __future__ import annotations

#: a node's numbers, one row of the path's table: its arc length [m], point [m], unit tangent and the
#: surface's unit normal there (towards the robot), the path's geodesic curvature (its turn on the surface,
#: positive towards ``n x t``) [1/m], the speed [m/s], the normal force [N] and the tool's tilt and lead angles [rad]
#: there (:data:`PATH_OUTPUT`'s ``spin_t1``, ``spin_t2``)
PATH_TABLE = ("s", "p_x", "p_y", "p_z", "t_x", "t_y", "t_z", "n_x", "n_y", "n_z", "kappa_g", "speed", "force",
              "tilt", "lead")
#: the follower's settings: the table's rows, 1 for a closed path, its length [m], the arc length where the
#: run starts [m], the arc length to travel [m] (an open path: to its end), the speed at the start [m/s], the
#: acceleration limit along the path [m/s^2], the cross-track gain [1/s] and the largest correction [m/s] (the
#: task's speed), the normal force [N] from which the
#: tip touches (-1e300: touching from the start), the sample period [s], the time [s] over which the force is
#: released at the end, the distance [m] the tip retreats from the surface then (0: it stays, pressing) and its
#: speed [m/s], the gain [1/s] of the tool axis's correction towards its tilt and lead
PATH_SETTINGS = ("rows", "closed", "length", "start", "distance", "speed_start", "acceleration",
                 "cross_track_gain", "cross_track_limit", "touch_force", "sample_time", "unload_time",
                 "retreat_distance", "retreat_speed", "orientation_gain")
#: the follower's state: the progress ``s`` [m] (the arc length of the path's point nearest the tip), the arc
#: length travelled [m], the table's row that holds ``s`` (a hint), 1 once started, the phase
#: (:data:`PATH_PHASES`) and the time in it [s]
PATH_STATE = ("s", "travelled", "row", "started", "phase", "phase_time")
#: the phases of a path task, by number: approaching the surface, following the path, releasing the force at
#: its end, retreating along the normal, clear of the surface (stopped)
PATH_PHASES = ("approach", "follow", "unload", "retreat", "clear")
#: what it gives each sample: the state after it, the path's point ``c(s)`` [m], its tangent, the surface's
#: normal, the cross-track direction ``e = n x t`` (the task frame's direction), the references of t1 (speed
#: [m/s] and its rate [m/s^2]), of t2 (the cross-track correction [m/s] and the turn's feedforward [m/s^2]),
#: of n (force [N]; in the retreat, speed [m/s]), the cross-track error ``d`` [m], the tip's distance from the
#: path in the surface's tangent plane [m], its height above the path's point along ``n`` [m], 1 once the
#: path is done (its end reached), 1 while the normal axis is velocity-controlled (the retreat), the angular
#: velocity references about t1 and t2 [rad/s] turning the tool's axis towards the one its tilt and lead give,
#: and the angle between the two [rad]
PATH_OUTPUT = (*PATH_STATE, "c_x", "c_y", "c_z", "t_x", "t_y", "t_z", "n_x", "n_y", "n_z", "e_x", "e_y", "e_z",
               "speed", "speed_rate", "lateral_speed", "lateral_rate", "normal_reference", "cross_track", "path_error",
               "height", "done", "retreat", "spin_t1", "spin_t2", "tool_angle_error")
#: the follower's statuses: 0 the outputs are written; otherwise nothing is (the state stays)
PATH_STATUSES = {"PATH_OK": 0, "PATH_INPUT_NONFINITE": 1, "PATH_TABLE_INVALID": 2}
#: how close [m] to the end of the distance to travel (an open path's end, a closed one's last lap) counts as done
PATH_DONE_TOL = 1e-4
#: Newton steps of the progress per sample (the tip moves far less than a node's spacing in one)
PATH_NEWTON_STEPS = 3


def path_axes(axes) -> tuple[tuple[int, int, int], tuple[int, int] | None]:
    """Where a path task's axes are among the task ``axes`` (their numbers, 0-5 for t1, t2, n and the
    rotations about them): ``(t1, t2, n)``, and the rotations about t1 and t2 (the tool's tilt and lead)
    where the task has both, else None.

    Examples
    --------
    >>> path_axes((0, 1, 2, 3, 4, 5))
    ((0, 1, 2), (3, 4))
    >>> path_axes((0, 1, 2))
    ((0, 1, 2), None)
    """
    axes = tuple(axes)
    return (axes.index(0), axes.index(1), axes.index(2)), \
        (axes.index(3), axes.index(4)) if 3 in axes and 4 in axes else None
