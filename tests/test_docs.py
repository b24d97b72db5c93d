"""The documentation's Python snippets run as written, page by page, its API reference lists
every public name, and its pages typeset their equations as math, not as code.

Each page's Python blocks (``.. code-block:: python`` in reST, fenced ```` ```python ```` in Markdown)
run in order, as one script, in a fresh interpreter and an empty folder (the snippets of a page build
on each other), twice in a row: a snippet does not depend on what an earlier run left behind. The build itself is
``python -m sphinx -W --keep-going -b html docs docs/_build/html`` (``.ci/run``).
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import hybrid

DOCS = Path(__file__).resolve().parent.parent / "docs"
FOLDERS = ("", "howto/", "studies/", "reference/")
PAGES = sorted(p for folder in FOLDERS for suffix in ("rst", "md") for p in DOCS.glob(f"{folder}*.{suffix}")
               if ".. code-block:: python" in p.read_text() or "```python" in p.read_text())
#: what runs a page's code: a script of its own, so that worker processes (Dask spawns them) that
#: import the main module do not run the page again
RUNNER = """import sys
if __name__ == "__main__":
    path = sys.argv[1]
    exec(compile(open(path).read(), path, "exec"), {"__name__": "__main__"})
"""


def python_blocks(page: Path) -> str:
    """The page's Python blocks, dedented and joined, line numbers kept apart by blank lines."""
    if page.suffix == ".md":
        return "\n".join(re.findall(r"^```python\n(.*?)^```", page.read_text(), flags=re.M | re.S))
    blocks = re.findall(r"^\.\. code-block:: python\n\n((?:(?:   .*)?\n)+)", page.read_text(), flags=re.M)
    return "\n".join("\n".join(line[3:] for line in block.splitlines()) for block in blocks)


def test_pages_have_snippets():
    assert {p.name for p in PAGES} >= {"urdf.rst", "surfaces.rst", "controller.rst", "sweeps.rst",
                                       "standalone_c.rst", "estimated_surface.rst", "library.md", "controller.md",
                                       "arms_and_law.md", "first_touch.md", "demo_sweep.md"}


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(DOCS)))
def test_page_snippets_run(page, tmp_path):
    code = tmp_path / f"{page.stem}_snippets.py"
    code.write_text(python_blocks(page))
    runner = tmp_path / "run_page.py"
    runner.write_text(RUNNER)
    work = tmp_path / "work"
    work.mkdir()
    for attempt in ("first", "second"):
        done = subprocess.run([sys.executable, str(runner), str(code)], cwd=work, capture_output=True, text=True,
                              timeout=600, env={**os.environ, "MPLBACKEND": "Agg"})
        assert done.returncode == 0, f"{page.name}'s snippets failed on the {attempt} run:\n{done.stderr[-3000:]}"


def test_api_reference_lists_every_public_name():
    listed = set(re.findall(r"^   (\w+)$", (DOCS / "api.rst").read_text(), flags=re.M))
    assert set(hybrid.__all__) - {"__version__"} <= listed


#: pages whose equations are typeset (MyST ``$...$`` and ``$$...$$``), not written as code
MATH_PAGES = ("conventions.md", "reference/arms_and_law.md", "reference/controller.md")
#: what marks an equation written as code: an assignment or relation of the law's symbols
EQUATION_SYMBOLS = ("R^T", "Bbar", "tau", "q'", "r'", "Sigma", "^-1", "^-T")


def equations_as_code(markdown: str) -> list[str]:
    """The inline code spans of a Markdown page, outside its fenced blocks, that are equations: an
    ``=`` among the law's symbols, and not Python (``tau = ctrl(t, q, qdot, Fc)`` is a call in the API)."""
    prose = re.sub(r"^```.*?^```", "", markdown, flags=re.M | re.S)
    spans = re.findall(r"(?<!`)`([^`\n]+(?:\n[^`\n]+)*)`(?!`)", prose)
    return [span for span in spans if "=" in span and any(symbol in span for symbol in EQUATION_SYMBOLS)
            and not is_python(span)]


def is_python(text: str) -> bool:
    """Whether the text parses as Python."""
    try:
        ast.parse(text)
    except SyntaxError:
        return False
    return True


def test_equations_as_code_found():
    # the check below finds what it looks for: equations in backticks, as the pages once wrote them
    page = ("law `tau = J^T F`, `B_o r'' + n_o = T^T F`, not `tau = ctrl(t, q, qdot, Fc)`, `KPv = 40` nor $\\tau$"
            "\n```python\nx = `tau = J^T F`\n```\n")
    assert equations_as_code(page) == ["tau = J^T F", "B_o r'' + n_o = T^T F"]


@pytest.mark.parametrize("name", MATH_PAGES)
def test_page_equations_are_math(name):
    page = (DOCS / name).read_text()
    equations = equations_as_code(page)
    assert not equations, f"{name} writes equations as code; typeset them as $...$: {equations}"
    # and the page parses to math nodes, its displays too
    docutils_ = pytest.importorskip("myst_parser.parsers.docutils_")
    from docutils import nodes
    from docutils.core import publish_doctree
    tree = publish_doctree(page, parser=docutils_.Parser(),
                           settings_overrides={"myst_enable_extensions": ["dollarmath"], "report_level": 5})
    inline, display = list(tree.findall(nodes.math)), list(tree.findall(nodes.math_block))
    assert inline and (display or "$$" not in page), f"{name}'s math did not parse as math"
    assert all("`" not in node.astext() for node in inline + display)
