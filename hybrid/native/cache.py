"""The build cache: where it is, its entries' keys and checksums, atomic writes and build locks.

The cache lives under ``$HYBRID_CACHE_DIR`` (default ``~/.cache/hybrid``). An entry is named by a
hash of everything it is built from, so a change to any of it makes a new entry instead of
loading a stale one. Builds take a file lock and replace files atomically, so concurrent
processes never see a partial file; a compiled library whose checksum does not match is
rebuilt, not loaded.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import logging
import os
from collections.abc import Callable
from pathlib import Path

from hybrid import files
from hybrid.errors import NativeBuildError

log = logging.getLogger("hybrid")
#: marks a log record of slow work (compiling, generating): a program showing progress can tell it
SLOW = {"slow": True}


def cache_dir() -> Path:
    root = os.environ.get("HYBRID_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "hybrid")
    return Path(root)


def writable_cache() -> Path:
    """:func:`cache_dir`, created; a folder that cannot be created or written is a NativeBuildError."""
    root = cache_dir()
    try:
        root.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise NativeBuildError(f"the cache folder {root} cannot be created ({exc.strerror}); "
                               "set HYBRID_CACHE_DIR to a writable folder") from None
    if not os.access(root, os.W_OK):
        raise NativeBuildError(f"the cache folder {root} is not writable; set HYBRID_CACHE_DIR to a writable folder")
    return root


def atomic_write(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename: never half-written."""
    fd, tmp = files.temporary(path)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def once(folder: Path, valid: Callable[[], bool], make: Callable[[], None]) -> None:
    """``make()`` unless ``valid()``, under a file lock in ``folder``: across processes one builds,
    the others wait and then find the result valid."""
    if valid():
        return
    with open(folder / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not valid():
            make()


# ------------------------------------------------------------------ compiled libraries


def entry(stem: str, material: str) -> tuple[str, Path]:
    """``(name, folder)`` of the cache entry for a library built from ``material`` (the text of its
    key): the name is ``stem`` and a hash of it, the folder is created."""
    name = f"{stem}_{hashlib.sha256(material.encode()).hexdigest()[:20]}"
    folder = writable_cache() / name
    try:
        folder.mkdir(exist_ok=True)
    except OSError as exc:
        raise NativeBuildError(f"the cache entry {folder} cannot be created ({exc.strerror}); "
                               "set HYBRID_CACHE_DIR to a writable folder") from None
    return name, folder


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def checksum_matches(library: Path, manifest: Path) -> bool:
    """Whether ``library`` is there and its checksum is the one ``manifest`` records."""
    try:
        return library.is_file() and json.loads(manifest.read_text())["sha256"] == _sha256(library)
    except (OSError, ValueError, KeyError):
        return False


def write_checksum(manifest: Path, library: Path, **facts) -> None:
    """Record ``library``'s checksum (and ``facts`` about its build) in ``manifest``, atomically."""
    atomic_write(manifest, json.dumps({"sha256": _sha256(library), **facts}).encode())


# ------------------------------------------------------------------ generated units


def write_unit_files(target: Path, files: dict[str, str]) -> None:
    """Write a generated unit's files into ``target``, each atomically."""
    target.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        atomic_write(target / name, text.encode())


def generated_unit(stem: str, key_material: dict, generate: Callable[[], dict[str, str]]) -> Path:
    """The folder holding the unit that ``generate()`` writes, generated once per key (cached).

    Generation runs under a file lock; the files are written atomically, and a folder whose
    files are missing is generated again.
    """
    digest = hashlib.sha256(json.dumps(key_material, sort_keys=True).encode()).hexdigest()[:20]
    folder = writable_cache() / "units" / f"{stem}_{digest}"
    done = folder / "complete.json"

    def valid() -> bool:
        try:
            names = json.loads(done.read_text())["files"]
            return all((folder / n).is_file() for n in names)
        except (OSError, ValueError, KeyError, TypeError):
            return False

    def make() -> None:
        log.info("hybrid: generating the C of %s", stem, extra=SLOW)
        files = generate()
        write_unit_files(folder, files)
        atomic_write(done, json.dumps({"files": sorted(files)}).encode())

    if not valid():
        folder.mkdir(parents=True, exist_ok=True)
        once(folder, valid, make)
    return folder
