"""The system C compiler: which one, its identity, the flags, and compiling an extension with it.

The compiler is ``$CC`` when set (and then only it), else ``cc``, else ``gcc``; its identity (the
first line of ``--version``) is remembered in the cache by the binary's path, time and size, so a
warm start runs no subprocess. The identity, the flags and the processor go into every cache key.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import logging
import os
import re
import shutil
import subprocess
import sysconfig
import tempfile
from functools import cache
from pathlib import Path

from hybrid.errors import NativeBuildError
from hybrid.native.cache import atomic_write, cache_dir, digest

log = logging.getLogger("hybrid")

#: flags for the extension; no -ffast-math: the status checks rely on isfinite(). On x86-64 the
#: code is tuned for this processor (FMA, AVX-512 where present): the cache key then carries the
#: processor's identity, so a shared cache never hands a build to a machine that cannot run it.
CFLAGS = ("-O3", "-fPIC", "-fno-math-errno", "-std=gnu99") + (
    ("-march=native",) if os.uname().machine in ("x86_64", "AMD64") else ())
#: GCC's instruction scheduling before register allocation, minding register pressure (off by default
#: on x86-64): the generated kernels are long straight-line code that the allocator otherwise takes in
#: the order written, and spills from; the closed loops run 6-9 % faster with it, the numbers the same
GCC_FLAGS = ("-fschedule-insns", "-fsched-pressure")


def is_gcc(ident: str) -> bool:
    """Whether the compiler whose ``--version`` line is ``ident`` is GCC (whose line reads ``NAME (PACKAGE)
    VERSION``; Clang's and others' do not)."""
    return re.match(r"\S+ \(.*\) \d", ident) is not None and "clang" not in ident.lower()


def flags(ident: str) -> tuple[str, ...]:
    """The flags a build passes to the compiler whose ``--version`` line is ``ident``: :data:`CFLAGS`, and
    :data:`GCC_FLAGS` for GCC (:func:`is_gcc`)."""
    return CFLAGS + (GCC_FLAGS if is_gcc(ident) else ())


@cache
def processor() -> str:
    """The processor's identity (model and instruction-set flags) for the cache key."""
    try:
        lines = Path("/proc/cpuinfo").read_text().splitlines()
    except OSError:
        return f"{os.uname().machine} {os.uname().version}"
    pick = [ln.split(":", 1)[1].strip() for ln in lines if ln.startswith(("model name", "flags", "Features"))]
    return hashlib.sha256(" | ".join(dict.fromkeys(pick)).encode()).hexdigest()[:16] + f" {os.uname().machine}"


def ready_for_threads() -> tuple[str, str]:
    """Read what every build reads once per process before threads build side by side: Python's build
    variables (``sysconfig`` fills them on first use, and two threads doing it at once can read them
    half-filled) and the compiler (returned, as :func:`compiler` gives it)."""
    sysconfig.get_config_vars()
    return compiler()


class CompilerUnusable(NativeBuildError):
    """The C compiler can build nothing here: ``$CC`` names no program, none is installed, it does not
    run, or it ran and wrote no library. Said once: every later build in the process raises it again
    at once, without trying (no run falls back to the Python runner, which needs the compiler too)."""


#: the first :class:`CompilerUnusable` of this process, by the value of ``$CC`` it met
_unusable: dict[str, str] = {}


def compiler() -> tuple[str, str]:
    """``(path, identity)`` of the C compiler: ``$CC`` when set (and then only it), else ``cc``,
    else ``gcc``. Probed once per process and value of ``$CC``; a compiler found unusable
    (:class:`CompilerUnusable`) is not tried again."""
    cc_env = os.environ.get("CC", "")
    if cc_env in _unusable:
        raise CompilerUnusable(_unusable[cc_env])
    try:
        return _compiler(cc_env)
    except CompilerUnusable as exc:
        _unusable.setdefault(cc_env, str(exc))
        raise


def unusable(message: str) -> CompilerUnusable:
    """A :class:`CompilerUnusable` saying ``message``, remembered: every later build raises it at once."""
    _unusable.setdefault(os.environ.get("CC", ""), message)
    return CompilerUnusable(message)


def _chosen_by(cc_env: str) -> str:
    return f"$CC={cc_env!r}" if cc_env.strip() else "cc or gcc on PATH ($CC unset)"


@cache
def _compiler(cc_env: str) -> tuple[str, str]:
    why = _chosen_by(cc_env)
    if cc_env.strip():
        path = shutil.which(cc_env.split()[0])
        if path is None:
            raise CompilerUnusable(f"$CC={cc_env!r} names no program on PATH; set CC to a C compiler's path, "
                                   "or unset it to use cc")
    else:
        path = shutil.which("cc") or shutil.which("gcc")
        if path is None:
            raise CompilerUnusable(
                "no C compiler found (tried cc and gcc; $CC is unset): install one, e.g. `apt-get install gcc` "
                "on Debian/Ubuntu or `xcode-select --install` on macOS, or set CC to its path")
    ident = _known_identity(path)
    if ident is None:
        try:
            ident = subprocess.run([path, "--version"], capture_output=True, text=True, check=True,
                                   timeout=60).stdout.splitlines()[0]
        except (OSError, subprocess.SubprocessError, IndexError) as exc:
            raise CompilerUnusable(f"the C compiler {path} (chosen by {why}) does not run ({exc}); "
                                   "reinstall it or set CC") from exc
        _remember_identity(path, ident)
    log.info("hybrid: C compiler %s (%s), chosen by %s", path, ident, why)
    return path, ident


def _binary_key(path: str) -> str | None:
    """The compiler binary's real path, modification time and size: a new or reinstalled compiler
    has another key."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return f"{os.path.realpath(path)}|{st.st_mtime_ns}|{st.st_size}"


def _identities() -> Path:
    return cache_dir() / "compilers.json"


def _known_identity(path: str) -> str | None:
    """The identity ``--version`` gave for this very binary before (a warm start runs no subprocess)."""
    key = _binary_key(path)
    try:
        known = json.loads(_identities().read_text())
    except (OSError, ValueError):
        return None
    ident = known.get(key) if isinstance(known, dict) else None
    return ident if isinstance(ident, str) and ident else None


def _remember_identity(path: str, ident: str) -> None:
    """Add the identity to the cache's table, atomically; a cache that cannot be written is no error."""
    key = _binary_key(path)
    if key is None:
        return
    try:
        known = json.loads(_identities().read_text())
        known = known if isinstance(known, dict) else {}
    except (OSError, ValueError):
        known = {}
    known[key] = ident
    try:
        _identities().parent.mkdir(parents=True, exist_ok=True)
        atomic_write(_identities(), json.dumps(known, indent=1, sort_keys=True).encode())
    except OSError:
        pass


def compile_extension(c_file: Path, target: Path, cc: str, ident: str, includes: list[str],
                      parts: tuple[Path, ...] = ()) -> str:
    """Compile ``c_file`` into the extension ``target`` (written atomically) with the compiler ``cc``
    whose identity is ``ident``; with ``parts``, the unit's parts: ``c_file`` (the binding, which then
    declares what it calls) is compiled with ``-DHL_PART=0`` and part ``n`` with ``-DHL_PART=n``, all at
    once (one compiler each), then linked. Returns the checksum of the bytes the compiler wrote (the
    cache records it: a copy that came out otherwise is never loaded)."""
    so = c_file.with_name(target.name)
    paths = [str(c_file.parent), *sorted({sysconfig.get_paths()["include"], sysconfig.get_paths()["platinclude"]}),
             *includes]

    def attempt(chosen: tuple[str, ...]) -> tuple[list[str], int, str]:
        head = [cc, *chosen, *(f"-I{p}" for p in paths)]
        if not parts:
            return _run([*head, "-shared", str(c_file), "-o", str(so), "-lm"])
        sources = (c_file, *parts)
        objects = [c_file.with_name(f"part{n}.o") for n in range(len(sources))]
        failed = _run_together([[*head, "-c", f"-DHL_PART={n}", str(src), "-o", str(obj)]
                                for n, (src, obj) in enumerate(zip(sources, objects))])
        return failed or _run([cc, *chosen, "-shared", *map(str, objects), "-o", str(so), "-lm"])

    cmd, code, stderr = attempt(flags(ident))
    if code != 0 and flags(ident) != CFLAGS:
        # a GCC that fails on its scheduling flags (some have, spilling): they change no number, so
        # the build without them is the same build
        log.warning("hybrid: %s failed on %s with %s; compiling without them", cc, c_file.name, " ".join(GCC_FLAGS))
        cmd, code, stderr = attempt(CFLAGS)
    if code != 0:
        hint = ("install the Python headers (apt-get install python3-dev)" if "Python.h" in stderr
                else "the compiler's messages follow")
        raise NativeBuildError(f"compiling {c_file.name} with {cc} failed: {hint}\n"
                               f"$ {' '.join(cmd)}\n{stderr[-4000:]}")
    if not so.is_file() or so.stat().st_size == 0:
        # no build can succeed with it: said once, not tried again (CompilerUnusable)
        cc_env = os.environ.get("CC", "")
        raise unusable(f"the compiler {cc} (chosen by {_chosen_by(cc_env)}) exited 0 but wrote no library for "
                       f"{c_file.name}; set CC to a working C compiler (e.g. CC=gcc)"
                       + (", or unset it to use cc" if cc_env.strip() else ""))
    data = so.read_bytes()
    atomic_write(target, data)
    return digest(data)


def _run(cmd: list[str]) -> tuple[list[str], int, str]:
    """``(cmd, exit status, stderr)`` of running ``cmd``."""
    proc = subprocess.run(cmd, capture_output=True, text=True)
    return cmd, proc.returncode, proc.stderr


def _run_together(cmds: list[list[str]]) -> tuple[list[str], int, str] | None:
    """Run ``cmds`` at once; the first that failed (as :func:`_run` says), or None. Their messages go
    to files (a pipe left unread would stall a compiler); an interrupted wait ends them all."""
    with contextlib.ExitStack() as stack:
        logs = [stack.enter_context(tempfile.TemporaryFile("w+")) for _ in cmds]
        procs = []
        try:
            for cmd, messages in zip(cmds, logs):
                procs.append(subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=messages))
            codes = [p.wait() for p in procs]
        finally:
            for p in procs:
                if p.poll() is None:
                    p.kill()
                    p.wait()
        for cmd, code, messages in zip(cmds, codes, logs):
            if code != 0:
                messages.seek(0)
                return cmd, code, messages.read()
    return None
