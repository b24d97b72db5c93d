"""Sphinx configuration of the documentation.

Build from the repository's root (with the ``docs`` extra installed)::

    python -m sphinx -W --keep-going -b html docs docs/_build/html

The gallery runs every ``examples/plot_*.py``; ``-D plot_gallery=0`` builds the pages without
running them. ``HYBRID_DOCS_GALLERY`` (a regular expression) limits which examples run.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

from sphinx.pycode import ModuleAnalyzer
from sphinx.util import logging

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "docs"))  # the gallery's plotly scraper

import gallery_plotly  # noqa: E402

import hybrid  # noqa: E402

project = "hybrid"
author = "The hybrid-decoupling developers"
copyright = "the hybrid-decoupling developers"  # noqa: A001 (Sphinx's name)
release = hybrid.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax from the build's _static/, not a CDN: math typeset offline too
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}  # Markdown: the conventions, the changelog
root_doc = "index"
exclude_patterns = ["_build", "auto_examples/*.ipynb", "auto_examples/*.py", "auto_examples/*.zip"]
templates_path = ["_templates"]

# ------------------------------------------------------------------------- API reference
autosummary_generate = True
autodoc_default_options = {"members": True, "show-inheritance": True}  # inherited members: only where the page asks
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # the docstrings say what each argument takes
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
#: the classes whose page also shows what they take from a base the reference does not list: an
#: experiment's sample counts and gains in force, a path on a surface's points, normals and curvature
autosummary_context = {"showing_inherited": ("Experiment", "WaypointPath", "RasterPath", "SpiralPath")}

# ------------------------------------------------------------------------------ MyST
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

# --------------------------------------------------------------------------- gallery
sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": os.environ.get("HYBRID_DOCS_GALLERY", r"/plot_"),
    "ignore_pattern": r"__init__\.py|/studies/",  # the studies take command-line arguments and run for minutes
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    # plotly's figures with plotly.js from the documentation's own _static folder: the pages work offline
    "image_scrapers": ("matplotlib", "gallery_plotly.scraper"),
    "ignore_repr_types": gallery_plotly.IGNORE_REPR,
    "reset_modules": ("matplotlib",),
    "abort_on_example_error": True,
    "show_memory": False,
}

# ----------------------------------------------------------------------------- HTML
html_theme = "pydata_sphinx_theme"
html_title = f"hybrid {release}"
html_static_path: list[str] = []
html_theme_options = {
    "show_toc_level": 2,
    "navigation_with_keys": False,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_context = {"default_mode": "light"}


def _check_api_listed(app, config) -> None:
    """Every public name (``hybrid.__all__``) is listed in the API reference."""
    listed = set(re.findall(r"^\s{3}(\w+)\s*$", (Path(app.srcdir) / "api.rst").read_text(), flags=re.M))
    missing = sorted(set(hybrid.__all__) - listed - {"__version__"})
    if missing:
        logging.getLogger(__name__).warning("docs/api.rst does not list the public names %s", ", ".join(missing))


def _defined_data_comment(app, what, name, obj, options, lines) -> None:
    """A constant documented under a module that imports it (``hybrid.UR5_URDF``) has its definition's
    ``#:`` comment, not its type's docstring (a ``Path``'s, a ``tuple``'s)."""
    if what != "data":
        return
    where, _, attr = name.rpartition(".")
    if ("", attr) in ModuleAnalyzer.for_module(where).find_attr_docs():
        return  # documented where it is listed
    for modname, module in sorted(sys.modules.items()):
        if modname.startswith("hybrid.") and vars(module).get(attr) is obj:
            comment = ModuleAnalyzer.for_module(modname).find_attr_docs().get(("", attr))
            if comment:
                lines[:] = list(comment)
                return


def _gallery_headers_in_rest(app, config) -> None:
    """Gallery sections are folders with a reST header: the C examples' folders (a README.md each,
    linked from the how-to on standalone C) are not sections of the Python gallery."""
    config.sphinx_gallery_conf["source_suffix"] = {".rst": "restructuredtext"}


def setup(app):
    app.connect("config-inited", _check_api_listed)
    app.connect("build-finished", gallery_plotly.write_plotlyjs)
    app.connect("autodoc-process-docstring", _defined_data_comment)
    # after sphinx-gallery fills its configuration (priority 10), before it reads the examples
    app.connect("config-inited", _gallery_headers_in_rest, priority=11)
