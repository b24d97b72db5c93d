"""The build cache: where it is, its entries' keys and checksums, atomic writes and build locks.

The cache lives under ``$HYBRID_CACHE_DIR`` (default ``~/.cache/hybrid``). An entry is named by a
hash of everything it is built from, so a change to any of it makes a new entry instead of
loading a stale one. Builds take a file lock and replace files atomically, so concurrent
processes never see a partial file. The cache records the checksum (SHA-256) of every file it
stores and verifies it at every read: a file that differs (truncated, damaged) is a cache miss,
built again, never copied to a user or loaded; a library whose parts reach past its end is not
loaded either.
"""

from __future__ import annotations

import contextlib
import fcntl
import hashlib
import json
import logging
import os
import struct
import sys
from collections.abc import Callable, Iterator
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


@contextlib.contextmanager
def locked(folder: Path) -> Iterator[None]:
    """Hold the build lock of ``folder`` (across processes) for the block."""
    with open(folder / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


def once(folder: Path, valid: Callable[[], bool], make: Callable[[], None]) -> None:
    """``make()`` unless ``valid()``, under a file lock in ``folder``: across processes one builds,
    the others wait and then find the result valid."""
    if valid():
        return
    with locked(folder):
        if not valid():
            make()


def digest(data: bytes) -> str:
    """The checksum the cache records of a file's bytes."""
    return hashlib.sha256(data).hexdigest()


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


def library_intact(library: Path, manifest: Path) -> bool:
    """Whether ``library`` may be loaded: its checksum is the one ``manifest`` records, and it holds
    every part its headers name (:func:`_whole_elf`)."""
    try:
        data = library.read_bytes()
        return json.loads(manifest.read_text())["sha256"] == digest(data) and _whole_elf(data)
    except (OSError, ValueError, KeyError, TypeError):
        return False


def _whole_elf(data: bytes) -> bool:
    """Whether an ELF file's program headers, the segments they map and its section headers all lie
    within ``data``. A library cut short maps pages past its end, and the first touch of one kills
    the process (SIGBUS) instead of failing to load: refused before it is loaded. A library is ELF
    everywhere but on macOS (Mach-O, left to the checksum)."""
    if data[:4] != b"\x7fELF":
        return sys.platform == "darwin" and len(data) > 0
    if len(data) < 64 or data[4] not in (1, 2) or data[5] not in (1, 2):
        return False
    wide, order = data[4] == 2, "<" if data[5] == 1 else ">"
    header = struct.unpack_from(order + ("QQIHHHHHH" if wide else "IIIHHHHHH"), data, 32 if wide else 28)
    phoff, shoff, _, _, phentsize, phnum, shentsize, shnum, _ = header
    if phoff + phnum * phentsize > len(data) or shoff + shnum * shentsize > len(data):
        return False
    for k in range(phnum):
        offset, filesz = (struct.unpack_from(order + "QQQQ", data, phoff + k * phentsize + 8)[::3] if wide
                          else struct.unpack_from(order + "IIII", data, phoff + k * phentsize + 4)[::3])
        if offset + filesz > len(data):
            return False
    return True


def write_checksum(manifest: Path, checksum: str, **facts) -> None:
    """Record a library's ``checksum`` (of the bytes written; and ``facts`` about its build) in
    ``manifest``, atomically."""
    atomic_write(manifest, json.dumps({"sha256": checksum, **facts}).encode())


# ------------------------------------------------------------------ generated units


def write_unit_files(target: Path, files: dict[str, str | bytes]) -> None:
    """Write a generated unit's files (texts, or a data file's bytes) into ``target``, each atomically."""
    target.mkdir(parents=True, exist_ok=True)
    for name, data in files.items():
        atomic_write(target / name, data if isinstance(data, bytes) else data.encode())


#: the record of a generated unit's folder: its files' names and checksums, written last
RECORD = "complete.json"


def stored_texts(folder: Path) -> dict[str, str] | None:
    """The files of the unit stored in ``folder`` by name, each read once and verified against the
    checksum recorded when it was stored; None when the record is missing or any file is missing or
    differs (a cache miss)."""
    try:
        recorded = json.loads((folder / RECORD).read_text())["sha256"]
        texts = {}
        for name, checksum in recorded.items():
            data = (folder / name).read_bytes()
            if digest(data) != checksum:
                return None
            texts[name] = data.decode()
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None
    return texts or None


def generated_unit(stem: str, key_material: dict,
                   generate: Callable[[], dict[str, str]]) -> tuple[Path, dict[str, str]]:
    """``(folder, files)``: the unit that ``generate()`` writes (its files by name, verified
    (:func:`stored_texts`)) and the folder holding it, generated once per key (cached).

    Generation runs under a file lock; the files are written atomically, their checksums last, and a
    folder whose files are missing or differ from their checksums is generated again.
    """
    key = digest(json.dumps(key_material, sort_keys=True).encode())[:20]
    folder = writable_cache() / "units" / f"{stem}_{key}"
    texts = stored_texts(folder)
    if texts is not None:
        return folder, texts
    folder.mkdir(parents=True, exist_ok=True)
    with locked(folder):
        texts = stored_texts(folder)  # another process may have made it meanwhile
        if texts is None:
            log.info("hybrid: generating the C of %s", stem, extra=SLOW)
            texts = generate()
            write_unit_files(folder, texts)
            # "files" as well: a runtime that reads only the names finds the entry whole too
            atomic_write(folder / RECORD, json.dumps({"files": sorted(texts), "sha256": {
                n: digest(t.encode()) for n, t in texts.items()}}).encode())
    return folder, texts
