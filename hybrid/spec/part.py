"""The layouts of a part's fitted surface as the generated C takes it (``generated/hybrid_part.h``).

A part (:class:`hybrid.MeshSurface`, :class:`hybrid.PointCloudSurface`) is a tricubic B-spline ``phi`` on a
uniform grid (:mod:`hybrid.geometry.bspline`): the grid's numbers :data:`PART_GRID` (its first cell's corner
[m], its spacing [m] and its cells along x, y and z) and its ``(cells_x + 3) (cells_y + 3) (cells_z + 3)``
coefficients [m], z fastest, NaN where ``phi`` is not defined (beyond the fitted band). The evaluator gives
the surface's second-order expansion about a point, the parameters of the ``quadric`` surface
(:data:`hybrid.spec.surface.PARAMETERS`): what the task frame, its rate and the plant's contact read there.
"""

from __future__ import annotations

#: the grid's numbers, in order
PART_GRID = ("origin_x", "origin_y", "origin_z", "spacing", "cells_x", "cells_y", "cells_z")
#: the evaluator's statuses: 0 the expansion is written; otherwise nothing is
PART_STATUSES = {"PART_OK": 0, "PART_INPUT_NONFINITE": 1, "PART_OFF_BAND": 2}
