"""Reading and writing the files a user names: atomically, never over their files unasked, one clear line on failure.

A file a user names is read by :func:`read_user_text`: a regular file only (a FIFO, a device or a
folder is refused before it is opened, so nothing blocks), of a bounded size, decoded as UTF-8.

Every output goes to a temporary file in the target's folder and is renamed into place, so an
interrupted run leaves either the old file or the new one, never half of one. A file-system
failure (missing, read-only or non-folder parent, full disk) is a :class:`HybridError` naming
the path and what to do.
"""

from __future__ import annotations

import contextlib
import fnmatch
import os
import stat
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

from hybrid.errors import HybridError
from hybrid.validate import shown


def _read_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


_UMASK = _read_umask()  # read once, at import: os.umask is process-wide


def temporary(path: Path) -> tuple[int, str]:
    """``(fd, name)`` of a new temporary file beside ``path``, with the permissions a plain
    ``open`` would give (``mkstemp``'s 0600 would hide the result from other users)."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=path.suffix)
    os.fchmod(fd, 0o666 & ~_UMASK)
    return fd, tmp


def leftovers(folder: Path, patterns) -> list[Path]:
    """The temporary files :func:`temporary` made in ``folder`` for targets whose names match one of
    ``patterns`` (``fnmatch`` patterns: ``"results.parquet"``, ``"part-*.parquet"``) and that nothing
    renamed or removed: what a killed process left. The folder-probe files too."""
    found = []
    for path in Path(folder).glob(".*"):
        name = path.name[1:]
        if fnmatch.fnmatchcase(path.name, ".hybrid-probe-????????"):
            found.append(path)
            continue
        for pattern in patterns:
            suffix = Path(pattern).suffix
            stem = name[:len(name) - len(suffix)] if suffix and name.endswith(suffix) else None
            target, _, random = (stem or "").rpartition(".")
            # mkstemp's random part: 8 characters of [a-z0-9_]
            if target and len(random) == 8 and fnmatch.fnmatchcase(target, pattern) \
                    and all(c.isdigit() or "a" <= c <= "z" or c == "_" for c in random):
                found.append(path)
                break
    return [p for p in found if p.is_file()]


def _why(exc: OSError) -> str:
    return exc.strerror or exc.__class__.__name__


def output_path(path) -> Path:
    """``path`` as a file name to write, or a HybridError saying why it cannot be one."""
    if not isinstance(path, (str, os.PathLike)) or not str(path).strip() or "\0" in str(path):
        raise HybridError(f"the output path {shown(path, 60)} is not a file name; give one")
    path = Path(path)
    if len(path.name.encode()) > 200:
        raise HybridError(f"the file name {path.name[:40]}... is {len(path.name)} characters; give a shorter one")
    return path


def writable_folder(folder: Path, what: str = "output folder") -> Path:
    """``folder``, created if missing, checked to be a writable folder before any long work."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise HybridError(f"the {what} {folder} is a file; give a folder (nothing was written)")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=folder, prefix=".hybrid-probe-"):
            pass
    except OSError as exc:
        raise HybridError(f"the {what} {folder} is not writable ({_why(exc)}); choose another folder") from None
    return folder


@contextlib.contextmanager
def atomic_path(path: Path, overwrite: bool = False) -> Iterator[Path]:
    """A temporary path beside ``path`` to write to; renamed onto ``path`` when the block ends
    without error (removed otherwise). Refuses an existing ``path`` unless ``overwrite``."""
    path = output_path(path)
    if path.is_dir():
        raise HybridError(f"{path} is a folder; give a file name")
    if path.exists() and not overwrite:
        raise HybridError(f"{path} exists; choose another name or pass overwrite=True (--force) to replace it")
    writable_folder(path.parent, "folder")
    try:
        fd, tmp = temporary(path)
        os.close(fd)
    except OSError as exc:
        raise HybridError(f"cannot write beside {path} ({_why(exc)}); choose another folder") from None
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    except OSError as exc:
        raise HybridError(f"writing {path} failed ({_why(exc)}); nothing was changed there") from None
    finally:
        Path(tmp).unlink(missing_ok=True)


def write_text(path: Path, text: str, overwrite: bool = False) -> Path:
    with atomic_path(path, overwrite) as tmp:
        tmp.write_text(text)
    return Path(path)


def write_with(path: Path, writer: Callable[[Path], None], overwrite: bool = False) -> Path:
    """``writer(tmp)`` writes the content; it lands at ``path`` whole or not at all."""
    with atomic_path(path, overwrite) as tmp:
        writer(tmp)
    return Path(path)


MAX_USER_TEXT_BYTES = 16 * 2**20  # a controller, sweep or robot description is far smaller


def regular_file(path, what: str, error: type[HybridError] = HybridError) -> Path:
    """``path`` as a :class:`~pathlib.Path` to an existing regular file, or ``error`` saying why not.

    Looked at with ``os.stat`` before anything opens it: a FIFO or a device would block or
    never end, a folder cannot be read as text.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise error(f"the {what} must be a path, got {type(path).__name__}; give a path")
    name = os.fspath(path)
    if not isinstance(name, str) or "\0" in name or not name.strip():
        raise error(f"the {what} path {shown(name, 60)} is not a file name; give a path")
    try:
        mode = os.stat(name).st_mode
    except OSError as exc:
        raise error(f"cannot read the {what} {name:.200} ({_why(exc)}); check the path") from None
    if not stat.S_ISREG(mode):
        kind = "a folder" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode) else "not a regular file"
        raise error(f"the {what} {name:.200} is {kind}; give a regular file")
    return Path(name)


def read_user_bytes(path, what: str, limit_bytes: int = MAX_USER_TEXT_BYTES,
                    error: type[HybridError] = HybridError) -> bytes:
    """The content of the regular file ``path`` (a ``what``: "controller file"), at most
    ``limit_bytes`` long; anything else is ``error`` naming the file and what to do."""
    path = regular_file(path, what, error)
    try:
        # O_NONBLOCK: should the name turn into a FIFO after the check, opening it does not wait
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise error(f"cannot read the {what} {path} ({_why(exc)}); check the path") from None
    with os.fdopen(fd, "rb") as f:
        info = os.fstat(f.fileno())
        if not stat.S_ISREG(info.st_mode):
            raise error(f"the {what} {path} is not a regular file; give a regular file")
        if info.st_size > limit_bytes:
            raise error(f"the {what} {path} is {info.st_size} bytes, more than the {limit_bytes} read; "
                        "give a smaller file")
        try:
            data = f.read(limit_bytes + 1)
        except OSError as exc:
            raise error(f"cannot read the {what} {path} ({_why(exc)}); check the file") from None
    if len(data) > limit_bytes:  # grew since fstat
        raise error(f"the {what} {path} is more than {limit_bytes} bytes; give a smaller file")
    return data


def read_user_text(path, what: str, limit_bytes: int = MAX_USER_TEXT_BYTES,
                   error: type[HybridError] = HybridError) -> str:
    """The UTF-8 text of the regular file ``path`` (see :func:`read_user_bytes`); bytes that are
    not UTF-8 are ``error`` naming the file and the byte offset."""
    data = read_user_bytes(path, what, limit_bytes, error)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise error(f"the {what} {os.fspath(path)} is not UTF-8 text (byte {exc.start}, line {line}); "
                    "save it as UTF-8") from None
