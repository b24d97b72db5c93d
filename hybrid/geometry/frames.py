"""The task frame ``R(r)`` and its rate ``R'(r, r')`` at points of any surface, from the generated C.

The rows of ``R_L`` are ``t1 = e x n / |e x n|``, ``t2 = n x t1`` and the normal ``n`` (towards the
robot) for the frame's direction ``e``; ``R_L'`` is its derivative along the point's velocity,
which carries the surface's curvature. A planar surface's frame is the paper's 2 x 2 one, rows
tangent ``t = (-n_y, n_x)`` and normal (the rows ``t1, n`` and columns ``x, y`` of its lift's with
``e = z``).
"""

from __future__ import annotations

import numpy as np

from hybrid.deprecation import renamed_keywords
from hybrid.errors import HybridError, NonFiniteError, TaskFrameError
from hybrid.geometry.surfaces import Surface
from hybrid.geometry.task_axes import frame_direction_of
from hybrid.native import units
from hybrid.native.binding import as_array, is_batch
from hybrid.validate import checked_keywords, shown


@renamed_keywords(reference="frame_direction")
@checked_keywords
def task_frame(surface: Surface, r, rdot, *, frame_direction=(0.0, 0.0, 1.0),
               backend: str = "sympy") -> tuple[np.ndarray, np.ndarray]:
    """``R(r)`` and ``R'(r, r')`` on ``surface`` at the point ``r`` moving at ``r'``.

    Points of 3 coordinates give the 3-D frame, ``(3, 3)`` for one point and ``(N, 3, 3)`` for N
    (shape ``(N, 3)``) in one native call, generated for the surface.
    Points of 2 coordinates (in the base xy-plane, on a surface with a
    :meth:`~hybrid.geometry.surfaces.Surface.cross_section`: a cylinder about z, a vertical plane)
    give the paper's 2 x 2 frame: one point from the committed closed-form unit of ``backend``, N
    points from the 3-D frame's rows ``t1, n`` and columns ``x, y``.

    Parameters
    ----------
    surface : Surface
        Any surface of the library (:class:`~hybrid.Plane`, :class:`~hybrid.Sphere`, ...).
    r : array_like
        The point [m]: 3 coordinates or 2, or N rows of them.
    rdot : array_like
        Its velocity [m/s], of the shape of ``r``.
    frame_direction : array_like
        The task frame's direction ``e``, base axes (3-D frames only).
    backend : str
        The planar frame's committed unit: ``"sympy"`` (default) or ``"casadi"``.

    Returns
    -------
    R : numpy.ndarray
        The task frame, rows ``t1, t2, n`` (2-D: ``t, n``), base axes.
    Rdot : numpy.ndarray
        Its rate.

    Raises
    ------
    TaskFrameError
        ``e`` is parallel to the normal at ``r``, or the surface has no normal there.
    NonFiniteError
        ``r`` or ``rdot`` is not finite.
    HybridError
        Not a surface, shapes that differ, or 2 coordinates on a surface with no planar cross-section.

    Examples
    --------
    On the paper's disc, at its point nearest the base, the normal row points back to the robot:

    >>> import hybrid
    >>> disc = hybrid.Circle((0.5, 0.0), 0.2)
    >>> R, Rdot = hybrid.task_frame(disc, [0.3, 0.0], [0.0, -0.1])
    >>> R.shape, R[1].tolist()
    ((2, 2), [-1.0, 0.0])
    >>> sphere = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
    >>> R, Rdot = hybrid.task_frame(sphere, [[0.35, 0.0, 0.2]] * 4,
    ...                             [[0.0, 0.1, 0.0]] * 4)
    >>> R.shape
    (4, 3, 3)
    """
    if not isinstance(surface, Surface):
        raise HybridError(f"surface must be a hybrid surface (Circle, Plane, Sphere, Cylinder, ImplicitSurface), "
                          f"got {shown(surface, 60)}")
    d = 2 if np.shape(r)[-1:] == (2,) else 3
    r, rdot = as_array("r", r, d, batched=None), as_array("rdot", rdot, d, batched=None)
    if r.shape != rdot.shape:
        raise HybridError(f"r and rdot must have the same shape, got {r.shape} and {rdot.shape}")
    if not (np.isfinite(r).all() and np.isfinite(rdot).all()):  # a plane's frame would not show it
        raise NonFiniteError(f"task_frame: non-finite input r = {r}, rdot = {rdot}")
    if d == 2:
        section = surface.cross_section()
        if section is None:
            raise HybridError(f"points of 2 coordinates lie in the base xy-plane, but {shown(surface, 60)} has no "
                              "planar cross-section there; give 3 coordinates")
        if not np.array_equal(frame_direction_of(frame_direction), (0.0, 0.0, 1.0)):
            raise HybridError("a planar frame has e = z (tangent t = (-n_y, n_x)); leave frame_direction out")
        if not is_batch(r):
            out = units.planar_unit(backend).function(f"task_frame_{section.kind}")(r, rdot, section.as_array())
            return out["R"], out["Rd"]
        r, rdot = (np.column_stack([x, np.zeros(len(x))]) for x in (r, rdot))
    frame = units.frame_unit(surface.spec()).function("task_frame")
    e = frame_direction_of(frame_direction)
    if surface.local:  # a part: its expansion about each point
        points, rates = np.reshape(r, (-1, 3)), np.reshape(rdot, (-1, 3))
        theta = [surface.parameters_at(p) for p in points]
        beyond = [i for i, t in enumerate(theta) if not np.isfinite(t).all()]
        if beyond:
            raise TaskFrameError(surface.off_band(points[beyond[0]]))
        rows = [frame(p, v, t, e) for p, v, t in zip(points, rates, theta)]
        R, Rd = (np.stack([o[k] for o in rows]) for k in ("R", "Rd"))
        if not is_batch(r):
            R, Rd = R[0], Rd[0]
    else:
        out = (frame.batch if is_batch(r) else frame)(r, rdot, surface.as_array(), e)
        R, Rd = out["R"], out["Rd"]
    if d == 2:  # rows t1, n and columns x, y of the 3-D frame
        R, Rd = R[:, ::2, :2], Rd[:, ::2, :2]
    return R, Rd
