"""The C templates (``codegen/templates/``) and the one environment that renders them.

The hand-written C the generator emits around the kernels (a unit's entry points and header, the closed
loop's driver, the RK4 step every integrator takes, the standalone units) lives in template files, as C
with Jinja placeholders; Python builds only their context (the printers of :mod:`codegen.sympy_backend`,
:mod:`codegen.casadi_backend` and :mod:`codegen.lanes` give the kernels' bodies).
Blocks' tags take their line with them (``trim_blocks``, ``lstrip_blocks``), so a template reads as the C it
renders; an undefined name is an error, never an empty string.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import jinja2

#: the folder of the templates
FOLDER = Path(__file__).resolve().parent / "templates"


@cache
def environment_for(folder: Path) -> jinja2.Environment:
    """The project's one way of rendering C templates, for the templates in ``folder`` (the generator's, or
    another C program's of the project: the benchmarks' drivers)."""
    return jinja2.Environment(loader=jinja2.FileSystemLoader(folder), undefined=jinja2.StrictUndefined,
                              trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True, autoescape=False)


def environment() -> jinja2.Environment:
    """The environment of the generator's templates."""
    return environment_for(FOLDER)


def render(name: str, **context) -> str:
    """The template ``name`` rendered with ``context``."""
    return environment().get_template(name).render(**context)


def macro(template: str, name: str):
    """The macro ``name`` of ``template``, callable from Python."""
    return getattr(environment().get_template(template).module, name)
