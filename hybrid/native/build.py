"""Compile the generated C once, cache it, load it: the thin native call path.

Each unit in ``generated/`` is compiled with the system C compiler into a CPython
extension (cffi, API mode) the first time it is used. The result is cached under
``$HYBRID_CACHE_DIR`` (default ``~/.cache/hybrid``) by a key that covers the C source,
the cffi declarations, the compiler's identity, the flags and the Python ABI. Builds
take a file lock and replace files atomically, so concurrent processes never see a
partial library; a cache entry whose checksum does not match is rebuilt, not loaded.
"""

from __future__ import annotations

import contextlib
import fcntl
import hashlib
import importlib.util
import json
import logging
import os
import re
import shutil
import subprocess
import sysconfig
import tempfile
import time
from collections.abc import Callable
from functools import cache
from pathlib import Path

import cffi

from hybrid import files
from hybrid.errors import NativeBuildError
from hybrid.native import checkout
from hybrid.spec.stamp import is_hand_edited

log = logging.getLogger("hybrid")
#: marks a log record of slow work (compiling, generating): a program showing progress can tell it
SLOW = {"slow": True}

#: flags for the extension; no -ffast-math: the status checks rely on isfinite(). On x86-64 the
#: code is tuned for this processor (FMA, AVX-512 where present): the cache key then carries the
#: processor's identity, so a shared cache never hands a build to a machine that cannot run it.
CFLAGS = ("-O3", "-fPIC", "-fno-math-errno", "-std=gnu99") + (
    ("-march=native",) if os.uname().machine in ("x86_64", "AMD64") else ())
#: GCC's instruction scheduling before register allocation, minding register pressure (off by default
#: on x86-64): the generated kernels are long straight-line code that the allocator otherwise takes in
#: the order written, and spills from; the closed loops run 6-9 % faster with it, the numbers the same
GCC_FLAGS = ("-fschedule-insns", "-fsched-pressure")


def flags(ident: str) -> tuple[str, ...]:
    """The flags a build passes to the compiler whose ``--version`` line is ``ident``: :data:`CFLAGS`, and
    :data:`GCC_FLAGS` for GCC (whose line reads ``NAME (PACKAGE) VERSION``; Clang's and others' do not)."""
    gcc = re.match(r"\S+ \(.*\) \d", ident) is not None and "clang" not in ident.lower()
    return CFLAGS + (GCC_FLAGS if gcc else ())


@cache
def processor() -> str:
    """The processor's identity (model and instruction-set flags) for the cache key."""
    try:
        lines = Path("/proc/cpuinfo").read_text().splitlines()
    except OSError:
        return f"{os.uname().machine} {os.uname().version}"
    pick = [ln.split(":", 1)[1].strip() for ln in lines if ln.startswith(("model name", "flags", "Features"))]
    return hashlib.sha256(" | ".join(dict.fromkeys(pick)).encode()).hexdigest()[:16] + f" {os.uname().machine}"


def source_dir() -> Path:
    """Where the generated C lives: ``generated/`` of the checkout this package runs from, else the
    installed copy (a folder named ``generated`` that merely sits beside an installed package is
    not the project's)."""
    package = Path(__file__).resolve().parent.parent
    top = checkout.root()
    for candidate in ([top / "generated"] if top else []) + [package / "_generated"]:
        if (candidate / "hybrid_sympy.c").is_file():
            return candidate
    raise NativeBuildError(
        "the generated C sources are missing (looked in generated/ next to the package); "
        "run `python -m hybrid regenerate` in a checkout of the project")


def cache_dir() -> Path:
    root = os.environ.get("HYBRID_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "hybrid")
    return Path(root)


def ready_for_threads() -> tuple[str, str]:
    """Read what every build reads once per process before threads build side by side: Python's build
    variables (``sysconfig`` fills them on first use, and two threads doing it at once can read them
    half-filled) and the compiler (returned, as :func:`compiler` gives it)."""
    sysconfig.get_config_vars()
    return compiler()


def compiler() -> tuple[str, str]:
    """``(path, identity)`` of the C compiler: ``$CC`` when set (and then only it), else ``cc``,
    else ``gcc``. Probed once per process and value of ``$CC``."""
    return _compiler(os.environ.get("CC", ""))


@cache
def _compiler(cc_env: str) -> tuple[str, str]:
    if cc_env.strip():
        name, why = cc_env.split()[0], f"$CC={cc_env!r}"
        path = shutil.which(name)
        if path is None:
            raise NativeBuildError(f"$CC={cc_env!r} names no program on PATH; set CC to a C compiler's path, "
                                   "or unset it to use cc")
    else:
        path, why = shutil.which("cc") or shutil.which("gcc"), "cc or gcc on PATH ($CC unset)"
        if path is None:
            raise NativeBuildError(
                "no C compiler found (tried cc and gcc; $CC is unset): install one, e.g. `apt-get install gcc` "
                "on Debian/Ubuntu or `xcode-select --install` on macOS, or set CC to its path")
    ident = _known_identity(path)
    if ident is None:
        try:
            ident = subprocess.run([path, "--version"], capture_output=True, text=True, check=True,
                                   timeout=60).stdout.splitlines()[0]
        except (OSError, subprocess.SubprocessError, IndexError) as exc:
            raise NativeBuildError(f"the C compiler {path} (chosen by {why}) does not run ({exc}); "
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
        tmp = _identities().with_name(f".compilers.{os.getpid()}.tmp")
        tmp.write_text(json.dumps(known, indent=1, sort_keys=True))
        os.replace(tmp, _identities())
    except OSError:
        pass


def cdef_of(header: str) -> str:
    """The declarations between the header's cdef markers, for cffi."""
    try:
        return header.split("/* cdef-begin */", 1)[1].split("/* cdef-end */", 1)[0]
    except IndexError:
        raise NativeBuildError("generated header lacks its cdef markers; run `python -m hybrid regenerate`") from None


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _atomic_write(path: Path, data: bytes) -> None:
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


def _compile(c_file: Path, target: Path, cc: str, ident: str, includes: list[str],
             parts: tuple[Path, ...] = ()) -> None:
    """Compile ``c_file`` into the extension ``target`` (written atomically) with the compiler ``cc``
    whose identity is ``ident``; with ``parts``, the unit's parts: ``c_file`` (the binding, which then
    declares what it calls) is compiled with ``-DHL_PART=0`` and part ``n`` with ``-DHL_PART=n``, all at
    once (one compiler each), then linked."""
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
        raise NativeBuildError(f"the compiler {cc} exited 0 but wrote no library for {c_file.name}; "
                               "set CC to a working C compiler")
    _atomic_write(target, so.read_bytes())


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


def _cached_module(stem: str, key_material: dict, write_source: Callable[[str, Path], None],
                   includes: list[str], parts: tuple[str, ...] = ()):
    """Build (once per key) and import the extension whose C ``write_source(name, path)`` writes
    (with ``parts``, the files beside it holding the unit's further parts: :func:`_compile`).

    The name carries a hash of ``key_material`` plus the compiler, flags and ABI, so a change
    to any of them builds a new entry instead of loading a stale one.
    """
    cc, ident = compiler()
    material = json.dumps({**key_material, "cc": [cc, ident], "flags": flags(ident), "cpu": processor(),
                           "abi": sysconfig.get_config_var("EXT_SUFFIX")}, sort_keys=True)
    name = f"{stem}_{hashlib.sha256(material.encode()).hexdigest()[:20]}"
    entry = _writable_cache() / name
    try:
        entry.mkdir(exist_ok=True)
    except OSError as exc:
        raise NativeBuildError(f"the cache entry {entry} cannot be created ({exc.strerror}); "
                               "set HYBRID_CACHE_DIR to a writable folder") from None
    so = entry / f"{name}{sysconfig.get_config_var('EXT_SUFFIX')}"
    manifest = entry / "manifest.json"

    def valid() -> bool:
        try:
            return so.is_file() and json.loads(manifest.read_text())["sha256"] == _sha256(so)
        except (OSError, ValueError, KeyError):
            return False

    def make() -> None:
        log.info("hybrid: compiling %s with %s", name, cc, extra=SLOW)
        t0 = time.perf_counter()
        with tempfile.TemporaryDirectory(dir=entry) as tmp:
            c_file = Path(tmp) / f"{name}.c"
            write_source(name, c_file)
            _compile(c_file, so, cc, ident, includes, tuple(Path(tmp) / part for part in parts))
        log.info("hybrid: compiled %s in %.1f s", name, time.perf_counter() - t0)
        _atomic_write(manifest, json.dumps({"sha256": _sha256(so), "compiler": ident, "flags": flags(ident)}).encode())

    def build() -> None:
        _once(entry, valid, make)

    build()
    try:
        return _import(name, so)
    except (ImportError, OSError) as exc:
        # a library that matches its checksum but does not load (a foreign or damaged build): heal it
        log.warning("hybrid: %s does not load (%s); rebuilding it", so, exc)
        manifest.unlink(missing_ok=True)
        build()
        try:
            return _import(name, so)
        except (ImportError, OSError) as again:
            raise NativeBuildError(f"{so.name} does not load even after a rebuild ({again}); delete {entry} "
                                   "or set HYBRID_CACHE_DIR to a fresh folder") from None


def _import(name: str, so: Path):
    spec = importlib.util.spec_from_file_location(name, so)
    if spec is None or spec.loader is None:
        raise ImportError(f"no loader for {so}")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _check_backend(backend: str) -> None:
    if backend not in ("sympy", "casadi"):
        raise NativeBuildError(f"no generated unit for backend {backend!r}; known backends are 'sympy' and 'casadi'")


def _unit(backend: str) -> tuple[Path, str, str]:
    """``(source dir, C source, header)`` of the generated unit for ``backend``."""
    _check_backend(backend)
    src_dir = source_dir()
    return src_dir, *_read_unit(src_dir, f"hybrid_{backend}")


def _read_unit(src_dir: Path, prefix: str) -> tuple[str, str]:
    try:
        return (src_dir / f"{prefix}.c").read_text(), (src_dir / f"{prefix}.h").read_text()
    except OSError as exc:
        raise NativeBuildError(f"the generated unit {prefix} in {src_dir} cannot be read ({exc.strerror}); "
                               "run `python -m hybrid regenerate` in a checkout of the project") from None


def _compile_unit(src_dir: Path, prefix: str):
    """The unit ``<prefix>.c`` of ``src_dir`` compiled as a cffi module (``.ffi``, ``.lib``)."""
    c_source, header = _read_unit(src_dir, prefix)
    cdef = cdef_of(header)

    def write_source(name: str, path: Path) -> None:
        _copy_unit(path.parent, prefix, c_source, header)
        ffi = cffi.FFI()
        ffi.cdef(cdef)
        # quiet (cffi would announce the file on stdout; redirecting stdout is not safe beside other threads)
        ffi.set_source(name, f'#include "{prefix}.c"', compiler_verbose=0)
        ffi.emit_c_code(str(path))

    # a unit whose manifest says it has parts: its own file once for each
    n = _manifest_parts(src_dir, prefix)
    parts = (f"{prefix}.c",) * n if n > 1 else ()
    return _cached_module(f"_{prefix}", {"c": c_source, "h": header, "cffi": cffi.__version__,
                                         **({"parts": n} if parts else {})}, write_source, [], parts)


def _manifest_parts(src_dir: Path, prefix: str) -> int:
    """How many parts the unit's manifest says it is compiled in (``parts``; 1 where it says none)."""
    try:
        parts = read_manifest(src_dir, prefix).get("parts", 1)
    except (NativeBuildError, AttributeError):
        return 1  # a unit read without its manifest is compiled whole, as any unit can be
    if not isinstance(parts, int) or isinstance(parts, bool) or not 1 <= parts <= 8:
        raise NativeBuildError(f"the manifest {prefix}.json in {src_dir} says the unit has {parts!r:.40} parts; "
                               "regenerate the unit")
    return parts


def _copy_unit(folder: Path, prefix: str, c_source: str, header: str) -> None:
    """The unit's text, as read (and hashed into the cache key), beside the build's own source:
    a ``regenerate`` running meanwhile cannot slip other code under the same key."""
    (folder / f"{prefix}.c").write_text(c_source)
    (folder / f"{prefix}.h").write_text(header)


def read_manifest(src_dir: Path, prefix: str) -> dict:
    """The interface description written by the generator beside ``<prefix>.c``."""
    try:
        return json.loads((src_dir / f"{prefix}.json").read_text())
    except (OSError, ValueError) as exc:
        raise NativeBuildError(f"the manifest {prefix}.json in {src_dir} is missing or unreadable ({exc}); "
                               "regenerate the unit") from None


@cache
def load(backend: str = "sympy"):
    """The compiled unit ``hybrid_<backend>`` as a cffi module (``.ffi``, ``.lib``).

    A unit edited by hand (its body no longer matches the hash in its first line) is used as it
    is, with a :class:`HandEditedWarning` saying so.
    """
    src_dir, c_source, header = _unit(backend)
    warn_if_hand_edited(src_dir, {f"hybrid_{backend}.c": c_source, f"hybrid_{backend}.h": header})
    return _compile_unit(src_dir, f"hybrid_{backend}")


def warn_if_hand_edited(src_dir: Path, texts: dict[str, str]) -> None:
    """A :class:`HandEditedWarning` naming the committed files of ``texts`` (name: text) edited by hand."""
    import warnings

    edited = [n for n, text in texts.items() if is_hand_edited(text)]
    if edited:
        warnings.warn(f"{', '.join(edited)} in {src_dir} were edited by hand; using them as they are "
                      "(`python -m hybrid regenerate --force` restores the generated code)",
                      HandEditedWarning, stacklevel=4)


class HandEditedWarning(UserWarning):
    """Generated code that was edited by hand is being compiled."""


@cache
def manifest(backend: str = "sympy") -> dict:
    """The manifest of the committed unit ``hybrid_<backend>``."""
    _check_backend(backend)
    return read_manifest(source_dir(), f"hybrid_{backend}")


def load_generated(src_dir: Path, prefix: str):
    """Compile (cached) and load the unit ``<prefix>`` written into ``src_dir`` (a cffi module)."""
    return _compile_unit(src_dir, prefix)


def write_unit_files(target: Path, files: dict[str, str]) -> None:
    """Write a generated unit's files into ``target``, each atomically."""
    target.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        _atomic_write(target / name, text.encode())


def generated_unit(stem: str, key_material: dict, generate: Callable[[], dict[str, str]]) -> Path:
    """The folder holding the unit that ``generate()`` writes, generated once per key (cached).

    Generation runs under a file lock; the files are written atomically, and a folder whose
    files are missing is generated again.
    """
    digest = hashlib.sha256(json.dumps(key_material, sort_keys=True).encode()).hexdigest()[:20]
    folder = _writable_cache() / "units" / f"{stem}_{digest}"
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
        _atomic_write(done, json.dumps({"files": sorted(files)}).encode())

    if not valid():
        folder.mkdir(parents=True, exist_ok=True)
        _once(folder, valid, make)
    return folder


def _once(folder: Path, valid: Callable[[], bool], make: Callable[[], None]) -> None:
    """``make()`` unless ``valid()``, under a file lock in ``folder``: across processes one builds,
    the others wait and then find the result valid."""
    if valid():
        return
    with open(folder / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not valid():
            make()


def _writable_cache() -> Path:
    root = cache_dir()
    try:
        root.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise NativeBuildError(f"the cache folder {root} cannot be created ({exc.strerror}); "
                               "set HYBRID_CACHE_DIR to a writable folder") from None
    if not os.access(root, os.W_OK):
        raise NativeBuildError(f"the cache folder {root} is not writable; set HYBRID_CACHE_DIR to a writable folder")
    return root


#: the most arguments a function may have for the one-state entry point (hybrid/fastcall.c)
FAST_MAX_ARGS = 24


def fastcall_prelude(manifest: dict) -> str:
    """What ``hybrid/fastcall.c`` expects before it, written from the unit's manifest: an adapter
    per function (its arguments in order) and the table of sizes and shapes."""
    adapters, table, max_out = [], [], 1
    for k, f in enumerate(manifest["functions"]):
        n_in, n_out = len(f["inputs"]), len(f["outputs"])
        if n_in > FAST_MAX_ARGS or n_out > FAST_MAX_ARGS:
            continue
        args = ([f"in[{i}]" for i in range(n_in)] + (["tol"] if f["singular_tol"] else [])
                + [f"out[{i}]" for i in range(n_out)])
        types = (["const double *"] * n_in + (["double"] if f["singular_tol"] else []) + ["double *"] * n_out)
        adapters.append(f"static int adapt_{k}(hybrid_fn fn, const double *const *in, double tol, double *const *out) "
                        f"{{\n    typedef int (*prototype)({', '.join(types) or 'void'});\n"
                        f"    (void)in; (void)tol; (void)out;\n    return ((prototype)fn)({', '.join(args)});\n}}\n")
        sizes = ", ".join(str(a["size"]) for a in f["inputs"]) or "0"
        shapes = ", ".join(f"{{{a['shape'][0]}, {a['shape'][1] if len(a['shape']) == 2 else 0}}}"
                           for a in f["outputs"])
        table.append(f'{{"{f["symbol"]}", adapt_{k}, {n_in}, {n_out}, {{{sizes}}}, {{{shapes}}}}}')
        max_out = max(max_out, sum(a["size"] for a in f["outputs"]))
    return ("".join(adapters) + f"#define HYBRID_FAST_FUNCTIONS {', '.join(table)}\n"
            f"#define HYBRID_FAST_MAX_OUT {max_out}\n#define HYBRID_FAST_MAX_ARGS {FAST_MAX_ARGS}\n")


def load_fastcall(src_dir: Path, prefix: str, manifest: dict):
    """The one-state CPython entry point (``hybrid/fastcall.c``) of the unit ``<prefix>`` in ``src_dir``.

    ``bind(symbol, n_state, params, singular_tol)`` fixes a function's parameters; ``call(binding,
    which, *states)`` evaluates it, returning None off the fast path (see the C file).
    """
    import numpy

    shim = (Path(__file__).with_name("fastcall.c")).read_text()
    # the adapters need the typedef of the shim: it comes first, then the prelude, then the rest
    head, rest = shim.split("typedef int (*adapter)", 1)
    prelude = fastcall_prelude(manifest)

    def write_source(name: str, path: Path) -> None:
        path.write_text(f"{head}{prelude}#define HYBRID_MODULE {name}\ntypedef int (*adapter){rest}")

    return _cached_module(f"_{prefix}_fastcall", {"shim": shim, "prelude": prelude, "numpy": numpy.__version__},
                          write_source, [numpy.get_include()])
