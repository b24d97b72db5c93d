"""Reading and writing the files a user names: atomically, never over their files unasked, one clear line on failure.

A file a user names is read by :func:`read_user_text`: a regular file only (a FIFO, a device or a
folder is refused before it is opened, so nothing blocks), of a bounded size, decoded as UTF-8.

Every output goes to a temporary file in the target's folder and is renamed into place, so an
interrupted run leaves either the old file or the new one, never half of one. Every temporary file
(and folder) of the library is named by one scheme, :func:`temporary`'s, that says whose it is: a
write removes the temporaries in its folder that a process no longer running left (a killed run's).
A file-system failure (missing, read-only or non-folder parent, full disk) is a :class:`HybridError`
naming the path and what to do.
"""

from __future__ import annotations

import contextlib
import fnmatch
import hashlib
import os
import re
import secrets
import shutil
import socket
import stat
import time
from collections.abc import Callable, Iterator
from pathlib import Path

from hybrid.errors import HybridError
from hybrid.validate import shown

#: this machine, in a temporary's name (a short hash of its host name): the process ids in names are its own
_HOST = hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:6]
#: a temporary of the library's: ``.<target>.<host>-<pid>-<random>.tmp<target's suffix>`` (the suffix last:
#: writers such as NumPy's and Matplotlib's choose the format by it)
_TEMPORARY = re.compile(r"\.(?P<target>.+)\.(?P<host>[0-9a-f]{6})-(?P<pid>[0-9]{1,12})-[0-9a-f]{8}\.tmp(\.[^.]*)?")
#: a temporary this old is stale whoever made it (a process id of another machine, or reused) [s]
STALE_AFTER = 24 * 3600
#: the target of the probe :func:`writable_folder` writes
_PROBE = "hybrid-probe"


def _temporary_name(path: Path) -> Path:
    return path.parent / f".{path.name}.{_HOST}-{os.getpid()}-{secrets.token_hex(4)}.tmp{path.suffix}"


def temporary(path: Path) -> tuple[int, str]:
    """``(fd, name)`` of a new temporary file beside ``path`` (named ``.<name>.<host>-<pid>-<random>.tmp<suffix>``),
    with the permissions a plain ``open`` would give. The stale temporaries of the folder (a killed
    process's: :func:`remove_stale_temporaries`) are removed first."""
    remove_stale_temporaries(path.parent)
    while True:
        tmp = _temporary_name(path)
        try:
            return os.open(tmp, os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o666), str(tmp)
        except FileExistsError:  # the random part met another: draw again
            continue


@contextlib.contextmanager
def temporary_folder(parent: Path, what: str = "build") -> Iterator[Path]:
    """A new folder in ``parent``, named as :func:`temporary` names files (``what`` as its target), removed
    with what it holds when the block ends; a killed process's is removed as a stale temporary."""
    remove_stale_temporaries(parent)
    folder = _temporary_name(parent / what)
    folder.mkdir()
    try:
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _temporaries(folder: Path) -> Iterator[tuple[Path, re.Match]]:
    """The library's temporaries in ``folder``, each with its name parsed."""
    try:
        with os.scandir(folder) as entries:
            found = [(Path(e.path), m) for e in entries if e.name.startswith(".")
                     and (m := _TEMPORARY.fullmatch(e.name)) is not None]
    except OSError:  # no folder (yet), or not readable: nothing of ours to remove
        return iter(())
    return iter(found)


def _running(pid: int) -> bool:
    """Whether a process ``pid`` runs on this machine (one of another user counts)."""
    if pid <= 0 or os.name != "posix":
        return os.name != "posix"  # elsewhere no cheap check: a temporary is stale by its age alone
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (OSError, OverflowError):
        return True
    return True


def _stale(path: Path, name: re.Match) -> bool:
    """Whether the temporary ``path`` is a leftover: its process (of this machine) no longer runs, or it is
    older than :data:`STALE_AFTER`."""
    try:
        age = time.time() - path.lstat().st_mtime
    except OSError:
        return False
    return age > STALE_AFTER or (name["host"] == _HOST and not _running(int(name["pid"])))


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        path.unlink(missing_ok=True)


def remove_stale_temporaries(folder: Path) -> None:
    """Remove the temporaries in ``folder`` that a process no longer running (or long ago) left: what a
    killed write, build or sweep left. Another running process's are kept."""
    for path, name in _temporaries(folder):
        if _stale(path, name):
            with contextlib.suppress(OSError):
                _remove(path)


def leftovers(folder: Path, patterns) -> list[Path]:
    """The temporaries in ``folder`` (whoever made them) for targets whose names match one of ``patterns``
    (``fnmatch`` patterns: ``"results.parquet"``, ``"part-*.parquet"``), and the probes of
    :func:`writable_folder`: what a process that holds the folder's lock may remove, since no one else
    writes there."""
    return [path for path, name in _temporaries(folder) if path.is_file()
            and (name["target"] == _PROBE or any(fnmatch.fnmatchcase(name["target"], p) for p in patterns))]


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
        fd, probe = temporary(folder / _PROBE)  # removes a killed run's temporaries too
        os.close(fd)
        os.unlink(probe)
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
