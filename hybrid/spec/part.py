"""The layouts of a part's fitted surface as the generated C takes it (``generated/hybrid_part.h``).

A part (:class:`hybrid.MeshSurface`, :class:`hybrid.PointCloudSurface`) is a tricubic B-spline ``phi`` on a
uniform grid (:mod:`hybrid.geometry.bspline`): the grid's numbers :data:`PART_GRID` (its first cell's corner
[m], its spacing [m] and its cells along x, y and z) and its ``(cells_x + 3) (cells_y + 3) (cells_z + 3)``
coefficients [m], z fastest, NaN where ``phi`` is not defined (beyond the fitted band). The evaluator gives
the surface's second-order expansion about a point, the parameters of the ``quadric`` surface
(:data:`hybrid.spec.surface.PARAMETERS`): what the task frame, its rate and the plant's contact read there.

The part's data file (``<name>_part.bin``, :meth:`hybrid.MeshSurface.save_data`) holds them for the standalone
C: IEEE-754 binary64 numbers, little-endian, the :data:`PART_DATA_HEADER` numbers, then the grid's, then the
coefficients. The header's tag :data:`PART_DATA_TAG` (the four letters ``HYPT`` read as a number) tells the file
apart from another and from one read in the other byte order; its CRC-32 (zlib's) is that of the grid's and the
coefficients' bytes as the file holds them, so that a file cut short, padded or damaged is refused whole.
"""

from __future__ import annotations

#: the grid's numbers, in order
PART_GRID = ("origin_x", "origin_y", "origin_z", "spacing", "cells_x", "cells_y", "cells_z")
#: the evaluator's statuses: 0 the expansion is written (or the data file's numbers taken); otherwise nothing is
PART_STATUSES = {"PART_OK": 0, "PART_INPUT_NONFINITE": 1, "PART_OFF_BAND": 2, "PART_DATA_INVALID": 3}
#: the data file's header, in order: its tag, its layout's version, the grid's count of numbers, the
#: coefficients' count, the CRC-32 of the numbers after the header
PART_DATA_HEADER = ("tag", "version", "grid_size", "coefficients", "crc32")
#: the data file's tag: ``HYPT`` (0x48595054) as a number
PART_DATA_TAG = 0x48595054
#: the data file's layout
PART_DATA_VERSION = 1
#: the most cells a grid has along an axis (the evaluator's bound: no index it implies runs past an array)
MOST_CELLS = 2 ** 20
