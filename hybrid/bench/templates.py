"""The benchmarks' C programs (``hybrid/bench/c/``) and the environment that renders them.

The hand-written C that times generated code (a loop around one generated function, the standalone
controller's step driver) lives in template files, as C with Jinja placeholders; Python builds only their
context: names, sizes and values. They render as the generator's do (:mod:`hybrid.codegen.templates`).
"""

from __future__ import annotations

from pathlib import Path

import jinja2

from hybrid.native import generator

#: the folder of the templates
FOLDER = Path(__file__).resolve().parent / "c"


def environment() -> jinja2.Environment:
    """The generator's environment for C templates (one set of conventions), on this folder."""
    return generator.api().template_environment(FOLDER)


def render(name: str, **context) -> str:
    """The template ``name`` rendered with ``context``."""
    return environment().get_template(name).render(**context)
