"""The gallery's interactive figures (plotly), in pages that work offline.

A code block of an example that ends with a plotly figure (its last line the figure, as a notebook
shows it) has the figure embedded in the page, interactive. The pages load plotly.js from the
documentation's own ``_static/plotly.min.js``, written once beside the pages when the build ends, never
from the network (plotly's own scraper loads it from a CDN).
"""

from __future__ import annotations

import ast
import os
import textwrap
from pathlib import Path

import plotly.io
import plotly.offline
from plotly.basedatatypes import BaseFigure

#: where the pages find plotly.js, under the built documentation
PLOTLY_JS = Path("_static") / "plotly.min.js"
#: sphinx-gallery's own repr of a plotly figure is left out: :func:`scraper` embeds it
IGNORE_REPR = r"plotly\."


def _shown_figure(block, block_vars) -> BaseFigure | None:
    """The plotly figure the code ``block`` ends with, or None (sphinx-gallery keeps a block's last
    expression as ``___``, which a block without one leaves as an earlier block set it)."""
    figure = block_vars.get("example_globals", {}).get("___")
    if not isinstance(figure, BaseFigure):
        return None
    try:
        body = ast.parse(block[1]).body
    except SyntaxError:
        return None
    return figure if body and isinstance(body[-1], ast.Expr) else None


def scraper(block, block_vars, gallery_conf) -> str:
    """sphinx-gallery's image scraper for plotly: the reST that embeds the block's figure, or ``""``."""
    figure = _shown_figure(block, block_vars)
    if figure is None:
        return ""
    page = Path(block_vars["target_file"])  # the example's page, in the documentation's sources
    script = Path(os.path.relpath(Path(gallery_conf["src_dir"]) / PLOTLY_JS, page.parent)).as_posix()
    div = f"plotly-{page.stem}-{block[2]}"
    html = plotly.io.to_html(figure, include_plotlyjs=script, full_html=False, auto_play=False,
                             default_width="100%", div_id=div, config={"responsive": True})
    # drawn while the page still lays out, the figure takes a width its column then loses: fit it once loaded
    resize = f'<script>window.addEventListener("load", () => Plotly.Plots.resize("{div}"));</script>'
    return "\n.. raw:: html\n\n" + textwrap.indent(html + "\n" + resize, "    ") + "\n"


def write_plotlyjs(app, exception) -> None:
    """Write plotly.js beside the built pages (``build-finished``)."""
    if exception is None and app.builder.format == "html":
        path = Path(app.outdir) / PLOTLY_JS
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(plotly.offline.get_plotlyjs(), encoding="utf-8")
