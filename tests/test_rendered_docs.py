"""The check of the rendered documentation (``docs/check_rendered.py``) in headless Chromium: a page
that renders passes, and a page with a code line wider than its box, a missing image and math left as
TeX fails, with each named.

The built documentation itself is checked by ``.ci/run`` after its build. These tests need Playwright
and Chromium (the ``docs`` extra and, on Debian, ``apt-get install chromium``): without them they are
skipped, saying what is missing.
"""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "docs" / "check_rendered.py"
FIXTURES = Path(__file__).resolve().parent / "data" / "rendered"


def _script():
    """``docs/check_rendered.py`` as a module (the docs folder is not a package)."""
    spec = importlib.util.spec_from_file_location("check_rendered", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def browser() -> str:
    """Chromium's path; the test is skipped where Playwright or Chromium is missing."""
    if importlib.util.find_spec("playwright") is None:
        pytest.skip("playwright is not installed: pip install -e '.[docs]'")
    found = _script().find_browser()
    if found is None:
        pytest.skip("no Chromium on the PATH: apt-get install chromium (Debian)")
    return found


def check(folder: Path, browser: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(SCRIPT), str(folder), "--browser", browser],
                          capture_output=True, text=True, timeout=300)


def test_a_page_that_renders_passes(browser, tmp_path):
    """The good page's math is typeset by the MathJax the docs ship (sphinx-mathjax-offline), from the
    page's own folder; its wide table and the wide Markdown table an example printed both pass."""
    mathjax = importlib.util.find_spec("sphinx-mathjax-offline")
    if mathjax is None:
        pytest.skip("sphinx-mathjax-offline is not installed: pip install -e '.[docs]'")
    shutil.copytree(Path(mathjax.submodule_search_locations[0]) / "static" / "mathjax",
                    tmp_path / "_static" / "mathjax")
    shutil.copy(FIXTURES / "good.html", tmp_path / "good.html")
    done = check(tmp_path, browser)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "1 pages checked at 1280 px, 0 failures" in done.stdout


def test_a_page_that_does_not_render_fails_naming_each_problem(browser, tmp_path):
    shutil.copy(FIXTURES / "bad.html", tmp_path / "bad.html")
    done = check(tmp_path, browser)
    assert done.returncode == 1, done.stdout + done.stderr
    failures = done.stdout.splitlines()[:-1]
    assert len(failures) == 3, done.stdout
    code, image, math = sorted(failures, key=lambda line: ("pre " not in line, "img " not in line))
    assert code.startswith('bad.html: pre "python3 -m venv .venv && .venv/bin/pip install -e . && ')
    assert "in #install: code block overflows: 1 line longer than its" in code
    assert image == 'bad.html: img "no_such_figure.png" in #figure: broken image: nothing loaded'
    assert math == 'bad.html: math "\\\\(\\\\dot y = a\\\\)" in #math: math not typeset: TeX shown as text'
    assert done.stdout.splitlines()[-1] == "check_rendered: 1 pages checked at 1280 px, 3 failures"


def test_a_folder_without_pages_is_refused(browser, tmp_path):
    done = check(tmp_path, browser)
    assert done.returncode == 2 and "no HTML pages in" in done.stderr
