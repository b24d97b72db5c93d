"""A sweep's folder: its description, its parts written as they come and read back, its table.

With ``out``, finished chunks are written as Parquet parts (atomically) beside a ``sweep.json``
describing the sweep; a folder holding this same sweep resumes from its parts, each checked to be
this sweep's. A lock keeps a second sweep out of the folder while one writes.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.deprecation import RENAMED, renamed_keys
from hybrid.errors import HybridError
from hybrid.simulation.metrics import metrics
from hybrid.sweeps.space import _plain
from hybrid.validate import shown


def _describe(base, parameters: Mapping, samples, seed) -> dict:
    def values(v):
        if hasattr(v, "sample"):
            return {type(v).__name__: dataclasses.asdict(v) if dataclasses.is_dataclass(v) else repr(v)}
        return [_plain(x) for x in v]

    to_dict = getattr(base, "to_dict", None)
    # the parameters in their order: it numbers the runs
    return {"sweep": 2, "base": to_dict() if to_dict else repr(base),
            "parameters": [[k, values(v)] for k, v in parameters.items()], "samples": samples, "seed": seed}


#: what a sweep writes into its folder besides ``parts/`` (``heatmap_*``: the command's figures)
OUTPUTS = ("sweep.json", "results.parquet", "results.csv", "heatmap_*.png", "heatmap_*.pdf", "heatmap_*.svg")
PART = "part-*.parquet"
STATUSES = ("ok", "failed", "invalid", "error")


def _prepare(out: Path, description: dict, force: bool):
    """Create ``out``, lock it, remove what an interrupted write left there, and check that it holds this
    same sweep or nothing of ours: files of our names without this sweep's ``sweep.json`` are another's
    (the user's, or another sweep's) and are refused, or cleared with ``force``. Returns the lock."""
    files.writable_folder(out, "sweep folder")
    lock = _lock(out)  # before anything is removed: a running sweep's temporaries are its own
    try:
        for left in files.leftovers(out, OUTPUTS) + files.leftovers(out / "parts", (PART,)):
            left.unlink(missing_ok=True)
        spec = out / "sweep.json"
        text = _text(description)
        stored = _read_text(spec) if spec.is_file() else None
        same = stored is not None and (stored == text or _renamed(stored) == _renamed(text))
        if same and stored != text:  # written before settings were renamed: the same sweep, now by its new names
            files.write_text(spec, text, overwrite=True)
        if not same:
            theirs = sorted({p for pattern in OUTPUTS for p in out.glob(pattern)}
                            | {p for p in (out / "parts").glob("*.parquet") if not p.name.startswith(".")})
            if theirs and not force:
                why = (("its sweep.json differs" if _is_description(spec) else "its sweep.json is not a sweep's")
                       if spec.exists() else f"it has {_listing(out, theirs)} but no sweep.json")
                raise HybridError(f"{out} holds a different sweep ({why}); choose another folder, or pass force=True "
                                  "(--force) to start this one there afresh (replacing them)")
            for path in theirs:
                if path.is_file() and path != spec:
                    path.unlink()
            files.write_text(spec, text, overwrite=True)
        (out / "parts").mkdir(exist_ok=True)
    except BaseException:
        lock.close()
        raise
    return lock


def _text(description: dict) -> str:
    """A sweep's ``sweep.json``."""
    return json.dumps(description, indent=2, sort_keys=True, default=str) + "\n"


def _renamed(stored: str) -> str | None:
    """The ``sweep.json`` text ``stored`` with renamed settings by their new names (its base experiment's,
    :func:`hybrid.deprecation.renamed_keys`, and its parameters'), or None where it is not a sweep's."""
    try:
        description = json.loads(stored)
    except ValueError:
        return None
    if not isinstance(description, dict) or not isinstance(description.get("base"), dict) \
            or not isinstance(description.get("parameters"), list):
        return None
    parameters = [[_new_name(p[0]), *p[1:]] if isinstance(p, list) and p else p for p in description["parameters"]]
    return _text({**description, "base": renamed_keys(description["base"]), "parameters": parameters})


def _new_name(name):
    """A parameter's name, a renamed setting's old name as its new one."""
    return RENAMED.get(name, name) if isinstance(name, str) else name


def _read_text(path: Path) -> str | None:
    try:
        return path.read_text()
    except (OSError, UnicodeDecodeError):
        return None


def _is_description(spec: Path) -> bool:
    """Whether ``spec`` reads as a sweep's description (written by a sweep, maybe another one)."""
    try:
        return isinstance(json.loads(_read_text(spec) or ""), dict) and "sweep" in json.loads(spec.read_text())
    except (ValueError, OSError):
        return False


def _listing(out: Path, paths: list[Path]) -> str:
    shown = ", ".join(str(p.relative_to(out)) for p in paths[:3])
    return shown + (f" and {len(paths) - 3} more" if len(paths) > 3 else "")


def _lock(out: Path):
    """An exclusive lock on ``out`` for the sweep's lifetime: a second sweep into it is refused."""
    import fcntl

    try:
        handle = open(out / ".lock", "w")
    except OSError as exc:
        raise HybridError(f"cannot lock the sweep folder {out} ({exc.strerror}); choose another folder") from None
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        handle.close()
        raise HybridError(f"another sweep is writing into {out}; wait for it or choose another folder") from None
    return handle


def metric_names(base) -> list[str]:
    """The names of the metrics a run of ``base`` reports (by the metrics' own definition)."""
    t = np.linspace(0.0, 1.0, 3)
    nq = base.robot.n if hasattr(base, "robot") else 2
    return list(metrics(t, t, t, t, t, penetration=t, contact_force=t, tau=np.zeros((3, nq))))


def _read_parts(out: Path, base, todo_all: list[tuple[int, dict]], force: bool) -> list[dict]:
    """The rows of the parts already written, each run once, each part checked to be this sweep's:
    its name, columns and their types, and its runs' numbers and parameters. Another's is refused,
    or with ``force`` removed (its runs are run again)."""
    import pandas as pd

    known = set(metric_names(base))
    rows: dict[int, dict] = {}
    for part in sorted(p for p in (out / "parts").glob("*.parquet") if not p.name.startswith(".")):
        try:
            frame = pd.read_parquet(part)
        except Exception as exc:  # noqa: BLE001 - pyarrow's errors are many; a part written by us reads
            problem = f"it does not read as Parquet ({type(exc).__name__}: cut short, or not a part)"
        else:
            names = list(todo_all[0][1]) if todo_all else []
            # a part written with a renamed setting's other name (before the rename, or after it)
            frame = frame.rename(columns={c: n for c in frame.columns for n in names
                                          if c != n and _new_name(c) == _new_name(n)})
            problem = _part_problem(part.name, frame, todo_all, known)
        if problem is not None:
            if not force:
                raise HybridError(f"{part} is not this sweep's: {problem}; remove it, or pass force=True (--force) "
                                  "to run its runs again")
            part.unlink()
            continue
        for row in frame.to_dict("records"):
            rows.setdefault(int(row["run"]), row)
    return list(rows.values())


def _part_problem(name: str, frame, todo_all: list[tuple[int, dict]], metrics: set[str]) -> str | None:
    """Why the table ``frame`` of the part file ``name`` is not one this sweep wrote, or None."""
    from pandas.api import types

    match = re.fullmatch(r"part-(\d{8,})-(\d{8,})\.parquet", name)
    if match is None:
        return "its name is not part-FIRST-LAST.parquet"
    names = list(todo_all[0][1]) if todo_all else []
    missing = [c for c in ("run", *names, "status", "error") if c not in frame.columns]
    if missing:
        return f"it has no column {', '.join(map(str, missing))}"
    foreign = [c for c in frame.columns if c not in ("run", *names, "status", "error") and c not in metrics]
    if foreign:
        return f"it has column {', '.join(map(str, foreign[:3]))}, which is not a parameter or metric of this sweep"
    if frame.empty or not types.is_integer_dtype(frame["run"]) or frame["run"].duplicated().any():
        return "its run column is not the run numbers of a chunk"
    runs = frame["run"].tolist()
    first, last = int(match.group(1)), int(match.group(2))
    if runs[0] != first or runs[-1] != last or runs != sorted(runs) or last >= len(todo_all):
        return f"its runs are not {first} to {last} of this sweep's {len(todo_all)}"
    if not frame["status"].isin(STATUSES).all() or not frame["error"].map(lambda e: isinstance(e, str)).all():
        return "its status and error columns are not a sweep's"
    bad = [c for c in frame.columns if c in metrics and not (types.is_numeric_dtype(frame[c])
                                                            and not types.is_bool_dtype(frame[c]))]
    if bad:
        return f"its column {bad[0]} is not numbers"
    for row in frame[["run", *names]].to_dict("records"):
        point = todo_all[row["run"]][1]
        for n in names:
            if not _same(row[n], point[n]):
                return f"its run {row['run']} has {n} = {shown(row[n], 30)}, this sweep's has {shown(point[n], 30)}"
    return None


def _same(got, want) -> bool:
    """A parameter's value read back equals the sweep's: same kind, same value (NaN equal to NaN)."""
    if isinstance(want, bool):
        return isinstance(got, (bool, np.bool_)) and bool(got) == want
    if isinstance(want, str):
        return isinstance(got, str) and got == want
    if isinstance(got, (bool, np.bool_, str)) or not isinstance(got, (int, float, np.integer, np.floating)):
        return False
    return got == want or (math.isnan(got) and math.isnan(want))


def _write_part(out: Path, rows: list[dict]) -> None:
    import pandas as pd

    first, last = rows[0]["run"], rows[-1]["run"]
    frame = pd.DataFrame(rows)
    files.write_with(out / "parts" / f"part-{first:08d}-{last:08d}.parquet",
                     lambda tmp: frame.to_parquet(tmp, index=False), overwrite=True)


def _table(rows: list[dict], names: list[str]):
    import pandas as pd

    frame = pd.DataFrame(rows)
    if frame.empty:
        return frame
    frame = frame.sort_values("run").reset_index(drop=True)
    metrics = [c for c in frame.columns if c not in ("run", *names, "status", "error")]
    return frame[["run", *names, *metrics, "status", "error"]]
