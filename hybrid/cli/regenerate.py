"""``python -m hybrid regenerate``: write ``generated/`` from the generator, or check that it is up to date.

``generated/`` holds the paper's arm in closed form (one unit per backend) and the closed loops that
:data:`LOOPS_FILE` names (``generated/loops/``, with the index that files each under its key). What each
loop is built from (an experiment under a scheme) is the runtime's to say; the generator is given plain
descriptions (:mod:`hybrid.native.units`, through :mod:`hybrid.native.generator`).
"""

from __future__ import annotations

import difflib
import os
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid.errors import HybridError
from hybrid.experiments.paper import paper_experiment
from hybrid.files import temporary
from hybrid.native import checkout, generator
from hybrid.native.units import BACKENDS, LOOPS, loop_files
from hybrid.simulation.closed_loop import loop_of
from hybrid.spec.stamp import is_hand_edited

UPDATE_HINT = "run `python -m hybrid regenerate` and commit generated/"
#: the closed loops committed in ``generated/loops``: an experiment by name, a scheme and lanes each
LOOPS_FILE = Path(__file__).resolve().parent.parent / "data" / "committed_loops.toml"
#: a committed loop's ``lanes`` for the build a sweep and a batch of runs take (as many lanes as the vector unit has)
BATCH = "batch"
#: the experiments a committed loop may be built from, by the name :data:`LOOPS_FILE` gives them
EXPERIMENTS = {"paper": paper_experiment}


def _hint(target: Path | None) -> str:
    return UPDATE_HINT if target is None else f"run `python -m hybrid regenerate --target {target}`"


def committed_loops(path: Path = LOOPS_FILE) -> list[tuple]:
    """The closed loops :data:`LOOPS_FILE` names, ``(plant, variant, lanes)`` each (as
    :func:`hybrid.native.units.loop_files` takes them)."""
    loops = []
    for entry in tomllib.loads(path.read_text())["loop"]:
        make, lanes = EXPERIMENTS.get(entry.get("experiment")), entry.get("lanes")
        if make is None or not (lanes == BATCH or isinstance(lanes, int) and not isinstance(lanes, bool)):
            raise HybridError(f"{path}: a [[loop]] needs experiment (one of {', '.join(EXPERIMENTS)}), scheme and "
                              f"lanes (an integer, or \"{BATCH}\"), got {entry}; correct the file")
        plant, variant = loop_of(make(controller=entry["scheme"]))
        loops.append((plant, dict(variant), None if lanes == BATCH else lanes))
    return loops


def expected_files(backends=BACKENDS) -> dict[str, str]:
    """Every generated file's name (a path under ``generated/``) and the text the generator produces now."""
    files: dict[str, str] = {}
    files.update(generator.api().shared_headers())
    for b in backends:
        files.update(generator.api().build_planar_unit(b).files)
    files.update({f"{LOOPS}/{name}": text for name, text in loop_files(committed_loops()).items()})
    return files


def _diff(name: str, old: str, new: str, limit: int = 40) -> str:
    lines = list(difflib.unified_diff(old.splitlines(), new.splitlines(), f"committed/{name}",
                                      f"generated-now/{name}", lineterm="", n=1))
    more = f"\n    ... ({len(lines) - limit} more diff lines)" if len(lines) > limit else ""
    return "\n".join("    " + ln for ln in lines[:limit]) + more


def check(target: Path | None = None) -> list[str]:
    """Problems with the committed files, or with those in ``target`` (empty when they are up to date).

    Reads nothing but the files it compares: a checkout whose ``generated/`` is empty (or gone)
    reports each file as missing.
    """
    hint = _hint(target)
    target = target or checkout.generated_dir()
    problems = []
    for name, text in expected_files().items():
        path = target / name
        if not path.is_file():
            problems.append(f"{name}: missing; {hint}")
        elif (old := path.read_text()) != text:
            why = "hand-edited" if is_hand_edited(old) else "stale"
            problems.append(f"{name}: {why}; {hint}\n{_diff(name, old, text)}")
    return problems


def write(target: Path | None = None, force: bool = False) -> list[str]:
    """Regenerate every file; refuse (unless ``force``) to overwrite a hand-edited one.

    Returns the names of the files that changed. Files are replaced atomically, with the
    permissions a plain ``open`` gives (the checkout's other users can read them).
    """
    target = target or checkout.generated_dir()
    files = expected_files()
    for name in files:
        (target / name).parent.mkdir(parents=True, exist_ok=True)
    edited = [n for n in files if (target / n).is_file() and is_hand_edited((target / n).read_text())]
    if edited and not force:
        raise FileExistsError(
            f"{', '.join(edited)} in {target} were edited by hand (their content no longer matches "
            "the hash in their first line); move your changes into codegen/, or pass --force to "
            "overwrite them")
    changed = []
    for name, text in files.items():
        path = target / name
        if path.is_file() and path.read_text() == text:
            continue
        fd, tmp = temporary(path)
        try:
            with os.fdopen(fd, "w") as f:
                f.write(text)
            os.replace(tmp, path)
        finally:
            Path(tmp).unlink(missing_ok=True)
        changed.append(name)
    return changed
