"""The built documentation as a reader sees it: every HTML page rendered in headless Chromium.

Run from the repository's root after the build::

    python docs/check_rendered.py docs/_build/html

Each page is loaded from a local HTTP server on 127.0.0.1, in a window 1280 px wide (a desktop), and
fails on:

- a code block (``pre``) wider than its box: a line the reader has to scroll to, or misses;
- a page that scrolls sideways as a whole, whatever makes it so. A table does not count while it scrolls
  within its own box (the theme's tables do, and so does a table an example prints, Markdown rows in its
  output): a table of many columns is wide by nature, where a code line can always be broken;
- a broken image: an ``img`` that has no pixels (``naturalWidth`` 0) once loaded;
- math that MathJax did not typeset: a ``.math`` element with no ``mjx-container``, with TeX left as text,
  or with a TeX error.

A code block not displayed (in a closed tab) has no width and is not checked. Each failure is printed
as page, element and what is wrong; the exit status is 1 if there is any, 2 if the check cannot run. The
browser is Chromium (``--browser``, else ``chromium`` on the ``PATH``), driven by Playwright. It reaches
nothing but the pages' own server: a page that needs the network (MathJax from a CDN) fails as it would
for a reader offline.
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import threading
from functools import partial
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

#: the width of a desktop's browser window, in CSS pixels
WIDTH = 1280
#: Chromium's switches: headless, and none of its own traffic (updates, sync, field trials), which
#: would otherwise try hosts that a machine without network cannot reach
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]
#: build folders that hold no pages of their own
NOT_PAGES = {"_static", "_sources", "_images", "_downloads", ".doctrees"}

#: what the browser runs on a loaded page: waits for the images and MathJax (at most ``timeout`` ms
#: each), then returns the failures as [element, what is wrong]
CHECK_PAGE = r"""
async (timeout) => {
  const settle = (promise) => Promise.race([promise, new Promise((r) => setTimeout(r, timeout))]);
  const images = [...document.images];
  images.forEach((img) => { img.loading = "eager"; });
  await settle(Promise.all(images.map((img) => img.complete ? null : new Promise((r) => {
    img.addEventListener("load", r); img.addEventListener("error", r); }))));
  if (document.querySelector(".math") && window.MathJax?.startup?.promise) {
    await settle(window.MathJax.startup.promise);
  }
  const where = (el) => { const s = el.closest("section[id]"); return s ? ` in #${s.id}` : ""; };
  const quote = (text) => JSON.stringify(text.trim().split("\n")[0].slice(0, 70));
  const failures = [];
  for (const pre of document.querySelectorAll("pre")) {
    if (pre.clientWidth === 0 || pre.scrollWidth <= pre.clientWidth + 1) continue;
    const probe = pre.appendChild(document.createElement("span"));
    probe.textContent = "x".repeat(100);
    const style = getComputedStyle(pre);
    const room = (pre.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight))
      / (probe.getBoundingClientRect().width / 100);
    probe.remove();
    const wide = pre.textContent.split("\n").filter((line) => line.length > room);
    // a table an example printed (Markdown rows) is wide by nature, as an HTML table is
    if (pre.closest(".sphx-glr-script-out") && wide.every((line) => line.startsWith("|"))) continue;
    const lines = `${wide.length} line${wide.length > 1 ? "s" : ""}`;
    failures.push([`pre ${quote(wide[0] || pre.textContent)}${where(pre)}`, `code block overflows: ${lines} `
      + `longer than its ${Math.floor(room)} characters (${pre.scrollWidth} px in ${pre.clientWidth})`]);
  }
  const page = document.documentElement;
  if (page.scrollWidth > page.clientWidth + 1) {
    const clipped = (el) => { for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
      if (getComputedStyle(a).overflowX !== "visible") return true; } return false; };
    const widest = [...document.body.querySelectorAll("*")].find(
      (el) => el.getBoundingClientRect().right > page.clientWidth + 1 && !clipped(el));
    failures.push([widest ? `${widest.tagName.toLowerCase()}${where(widest)}` : "page",
      `the page scrolls sideways: ${page.scrollWidth} px in a ${page.clientWidth} px window`]);
  }
  for (const img of images) {
    if (img.naturalWidth === 0) {
      failures.push([`img ${quote(img.getAttribute("src") || "")}${where(img)}`,
        "broken image: nothing loaded"]);
    }
  }
  for (const math of document.querySelectorAll(".math")) {
    const rest = math.cloneNode(true);
    rest.querySelectorAll("mjx-container, .eqno").forEach((c) => c.remove());  // .eqno: "(1)", its link
    const error = math.querySelector("mjx-merror");
    if (!math.querySelector("mjx-container")) {
      failures.push([`math ${quote(math.textContent)}${where(math)}`, "math not typeset: TeX shown as text"]);
    } else if (error) {
      failures.push([`math ${quote(error.getAttribute("data-mjx-error") || error.textContent)}${where(math)}`,
        "TeX error in the math"]);
    } else if (rest.textContent.trim()) {
      failures.push([`math ${quote(rest.textContent)}${where(math)}`, "TeX left as text beside the math"]);
    }
  }
  return failures;
}
"""


def find_browser(given: str | None = None) -> str | None:
    """The Chromium to run: ``given`` if it exists, else ``chromium`` on the ``PATH``, else None."""
    if given:
        return given if Path(given).is_file() else None
    return shutil.which("chromium") or shutil.which("chromium-browser")


def pages_of(root: Path) -> list[Path]:
    """The HTML pages of a build, relative to its folder, outside the folders of static files."""
    return sorted(p.relative_to(root) for p in root.rglob("*.html")
                  if not NOT_PAGES & set(p.relative_to(root).parts[:-1]))


class _QuietHandler(SimpleHTTPRequestHandler):
    """Serves the build's files without a log line per request."""

    def log_message(self, format, *args):  # noqa: A002 (the base class's name)
        pass


def check_pages(root: Path, browser: str, width: int = WIDTH, timeout_ms: int = 20000) -> tuple[int, list[str]]:
    """Render every page of the build ``root`` and collect what is wrong.

    Parameters
    ----------
    root : Path
        The HTML build's folder (``docs/_build/html``).
    browser : str
        Path of the Chromium executable.
    width : int
        The window's width in CSS pixels.
    timeout_ms : int
        How long to wait for a page, its images and its math, in milliseconds.

    Returns
    -------
    tuple of (int, list of str)
        The number of pages checked, and one line per failure: ``page: element: what is wrong``.
    """
    from playwright.sync_api import sync_playwright

    server = ThreadingHTTPServer(("127.0.0.1", 0), partial(_QuietHandler, directory=str(root)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/"
    pages, failures = pages_of(root), []
    try:
        # a profile of its own, made for this run and removed after it
        with tempfile.TemporaryDirectory(prefix="check-rendered-") as profile, sync_playwright() as pw:
            context = pw.chromium.launch_persistent_context(
                profile, executable_path=browser, headless=True, args=CHROMIUM_ARGS,
                viewport={"width": width, "height": 900})
            # anything but the build's own files is refused, as it would fail offline
            context.route(lambda url: not url.startswith(base), lambda route: route.abort())
            tab = context.new_page()
            for page in pages:
                tab.goto(base + page.as_posix(), wait_until="load", timeout=timeout_ms)
                failures += [f"{page.as_posix()}: {element}: {problem}"
                             for element, problem in tab.evaluate(CHECK_PAGE, timeout_ms)]
            context.close()
    finally:
        server.shutdown()
        server.server_close()
    return len(pages), failures


def main(argv: list[str] | None = None) -> int:
    """Check the pages of a build; print each failure; 0 if none, 1 if any, 2 if it cannot run."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("html", nargs="?", type=Path, default=Path("docs/_build/html"),
                        help="the HTML build's folder (default: docs/_build/html)")
    parser.add_argument("--browser", help="the Chromium executable (default: chromium on the PATH)")
    parser.add_argument("--width", type=int, default=WIDTH, help=f"the window's width in px (default: {WIDTH})")
    args = parser.parse_args(argv)
    browser = find_browser(args.browser)
    if browser is None:
        print("check_rendered: no Chromium found: install it (apt-get install chromium) or pass --browser PATH",
              file=sys.stderr)
        return 2
    try:
        import playwright  # noqa: F401
    except ImportError:
        print("check_rendered: playwright is not installed: pip install -e '.[docs]'", file=sys.stderr)
        return 2
    if not pages_of(args.html):
        print(f"check_rendered: no HTML pages in {args.html}: build the docs first", file=sys.stderr)
        return 2
    count, failures = check_pages(args.html, browser, args.width)
    for failure in failures:
        print(failure)
    print(f"check_rendered: {count} pages checked at {args.width} px, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
