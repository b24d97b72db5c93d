"""A part's data file: what the standalone C of a run on a part reads at run time (``generated/hybrid_part.h``'s
``hybrid_part_data``), so that one build serves every part.

The layout is :mod:`hybrid.spec.part`'s: IEEE-754 binary64 numbers, little-endian, the header
(:data:`~hybrid.spec.part.PART_DATA_HEADER`: the tag, the layout's version, the grid's count of numbers, the
coefficients' count, the CRC-32 of what follows), the grid's numbers, the coefficients (z fastest; NaN beyond
the fitted band). The same part gives the same bytes.
"""

from __future__ import annotations

import zlib

import numpy as np

from hybrid.spec.part import PART_DATA_HEADER, PART_DATA_TAG, PART_DATA_VERSION, PART_GRID


def data_file(grid: np.ndarray, coefficients: np.ndarray) -> bytes:
    """The data file's bytes of a part whose grid's numbers are ``grid`` and coefficients ``coefficients`` (as
    :meth:`~hybrid.geometry.parts.PartSurface.data` gives them)."""
    body = np.concatenate([np.asarray(grid, "<f8").ravel(), np.asarray(coefficients, "<f8").ravel()])
    if len(body) - len(PART_GRID) != int(np.prod(np.asarray(grid[-3:], float) + 3)):
        raise ValueError("the coefficients are not the grid's")
    head = {"tag": PART_DATA_TAG, "version": PART_DATA_VERSION, "grid_size": len(PART_GRID),
            "coefficients": len(body) - len(PART_GRID), "crc32": zlib.crc32(body.tobytes())}
    return np.array([head[k] for k in PART_DATA_HEADER], "<f8").tobytes() + body.tobytes()
