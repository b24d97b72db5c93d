"""A part's fitted surface in C: one header (:data:`PART_HEADER`) rendered from its template with the layouts of
:mod:`hybrid.spec.part`, so the C's index macros and the runtime's arrays name the same numbers: the evaluator,
and the reader of a part's data file (:func:`hybrid.geometry.part_data.data_file`'s numbers).

``generated/`` holds a copy, stamped, beside the units; the compiled loops and the standalone C of a run on a
part include it, and the runtime compiles it for the :class:`hybrid.Controller` and the plant.
"""

from __future__ import annotations

from hybrid.spec import part as spec
from hybrid.spec.surface import PARAMETERS

from .templates import render

#: the evaluator's header (C99, every function static inline)
PART_HEADER = "hybrid_part.h"


def part_header() -> str:
    """The evaluator's header.

    Returns
    -------
    str
        The text of :data:`PART_HEADER`, C99, its layouts' macros from :mod:`hybrid.spec.part`.
    """
    return render("hybrid_part.h.j2", grid=spec.PART_GRID, out=PARAMETERS["quadric"],
                  statuses=list(spec.PART_STATUSES.items()), header=spec.PART_DATA_HEADER, tag=spec.PART_DATA_TAG,
                  version=spec.PART_DATA_VERSION, most_cells=spec.MOST_CELLS, crc_table=_crc_nibbles())


def _crc_nibbles() -> list[str]:
    """The CRC-32's (zlib's: reflected, polynomial 0xEDB88320) table of the sixteen nibbles, as C constants."""
    table = []
    for n in range(16):
        crc = n
        for _ in range(4):
            crc = (crc >> 1) ^ (0xEDB88320 if crc & 1 else 0)
        table.append(f"0x{crc:08X}UL")
    return table
