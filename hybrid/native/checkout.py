"""Whether this ``hybrid`` runs from a checkout of the project's repository, and where its parts are.

A checkout is the folder above the ``hybrid`` package when it holds the project's
``pyproject.toml`` (by its project name, not just any such file) and ``codegen/``, the generator's
source. An installed package has neither beside it: a wheel ships no ``pyproject.toml``. The
``generated/`` folder itself is not required: ``regenerate`` must be able to rebuild it from nothing.

Nothing here runs at import; each answer reads ``pyproject.toml`` afresh (it is small).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid.errors import HybridError

#: ``[project] name`` in the repository's ``pyproject.toml``
PROJECT = "hybrid-decoupling"


def _top() -> Path:
    """The folder above the ``hybrid`` package."""
    return Path(__file__).resolve().parents[2]


def _not_a_checkout(top: Path) -> str | None:
    """Why ``top`` is not a checkout of the project's repository (None when it is one)."""
    pyproject = top / "pyproject.toml"
    try:
        data = tomllib.loads(pyproject.read_bytes().decode())
    except FileNotFoundError:
        return "no pyproject.toml beside it"
    except OSError as exc:
        return f"{pyproject} cannot be read: {exc.strerror or exc}"
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        return f"{pyproject} is not valid TOML: {str(exc).splitlines()[0]}"
    project = data.get("project")
    name = project.get("name") if isinstance(project, dict) else None
    if name != PROJECT:
        return f"{pyproject} is another project's ({name!r}, not {PROJECT!r})"
    if not (top / "codegen" / "__init__.py").is_file():
        return f"no codegen/ in {top}"
    return None


def root() -> Path | None:
    """The checkout this ``hybrid`` package runs from, or None when it runs installed."""
    top = _top()
    return None if _not_a_checkout(top) else top


def _generator_elsewhere(top: Path) -> str | None:
    """Why the generator that would run is not this checkout's ``codegen/`` (None when it is).

    The generated text depends on the generator and on what it shares with the runtime
    (:mod:`hybrid.spec`), so both must come from one tree; and ``hybrid.codegen`` maps to ``codegen/``
    only through an install's path mapping, which may point at another checkout. ``find_spec``
    locates it without running it (no SymPy).
    """
    spec = importlib.util.find_spec("hybrid.codegen")
    if spec is None or spec.origin is None:
        return "hybrid.codegen cannot be imported: install the checkout with `pip install -e .`"
    found = Path(spec.origin).resolve().parent
    if found != (top / "codegen").resolve():
        return f"its generator hybrid.codegen is imported from {found}, not from {top / 'codegen'}"
    return None


def generated_dir() -> Path:
    """The checkout's ``generated/``, which ``python -m hybrid regenerate`` rewrites.

    Raises
    ------
    HybridError
        When ``hybrid`` runs installed (writing into the install would leave a stray folder that no
        one reads) or when the generator comes from another tree than the runtime.
    """
    top = _top()
    problem = _not_a_checkout(top) or _generator_elsewhere(top)
    if problem:
        raise HybridError(
            f"regenerate needs a checkout of the project's repository, and hybrid in {top / 'hybrid'} does not run "
            f"from one ({problem}); run it in a clone installed with `pip install -e .`, or give --target DIR to "
            "write (or --check) a folder of your own; nothing was written")
    return top / "generated"
