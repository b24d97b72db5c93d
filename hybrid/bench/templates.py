"""The benchmarks' C programs (``hybrid/bench/c/``) and the environment that renders them.

The hand-written C that times generated code (a loop around one generated function, the standalone
controller's step driver) lives in template files, as C with Jinja placeholders; Python builds only their
context: names, sizes and values. Blocks' tags take their line with them (``trim_blocks``,
``lstrip_blocks``), so a template reads as the C it renders; an undefined name is an error, never an empty
string.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import jinja2

#: the folder of the templates
FOLDER = Path(__file__).resolve().parent / "c"


@cache
def environment() -> jinja2.Environment:
    return jinja2.Environment(loader=jinja2.FileSystemLoader(FOLDER), undefined=jinja2.StrictUndefined,
                              trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True, autoescape=False)


def render(name: str, **context) -> str:
    """The template ``name`` rendered with ``context``."""
    return environment().get_template(name).render(**context)
