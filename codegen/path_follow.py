"""The path follower's C: one header (:data:`PATH_HEADER`) rendered from its template with the layouts of
:mod:`hybrid.spec.path_follow`, so the C's index macros and the runtime's arrays name the same numbers.

``generated/`` holds a copy, stamped, beside the units; the standalone controller of a path task ships it
with its own files, and the runtime compiles it for the :class:`hybrid.Controller`.
"""

from __future__ import annotations

from dataclasses import dataclass

from hybrid.spec import path_follow as spec

from .templates import render

#: the follower's header (C99, every function static inline)
PATH_HEADER = "hybrid_path.h"


@dataclass(frozen=True)
class _Group:
    name: str
    doc: str


def path_header() -> str:
    """The follower's header.

    Returns
    -------
    str
        The text of :data:`PATH_HEADER`, C99, its layouts' macros from :mod:`hybrid.spec.path_follow`.
    """
    layouts = [(_Group("TABLE", "a node's numbers: one row of the table"), spec.PATH_TABLE),
               (_Group("SETTINGS", "the follower's settings"), spec.PATH_SETTINGS),
               (_Group("STATE", "the follower's state (the first outputs are the state after a sample)"),
                spec.PATH_STATE),
               (_Group("OUT", "what a sample gives"), spec.PATH_OUTPUT)]
    return render("hybrid_path.h.j2", layouts=layouts, statuses=list(spec.PATH_STATUSES.items()),
                  phases=spec.PATH_PHASES,
                  done_tol=repr(spec.PATH_DONE_TOL), newton_steps=spec.PATH_NEWTON_STEPS)
