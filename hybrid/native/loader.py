"""Load the generated C as CPython extensions (cffi, API mode): the thin native call path.

Each unit in ``generated/`` is compiled with the system C compiler (:mod:`hybrid.native.compiler`)
the first time it is used, and the result is cached (:mod:`hybrid.native.cache`) by a key that
covers the C source, the cffi declarations, the compiler's identity, the flags and the Python ABI.
Beside the cffi module of a unit, :func:`load_fastcall` builds its one-state entry point
(``hybrid/native/fastcall.c``).
"""

from __future__ import annotations

import importlib.util
import json
import logging
import sysconfig
import time
from collections.abc import Callable
from functools import cache
from pathlib import Path

import cffi

from hybrid import files
from hybrid.errors import NativeBuildError
from hybrid.native import checkout, generator
from hybrid.native.cache import SLOW, entry, library_intact, once, write_checksum
from hybrid.native.compiler import compile_extension, compiler, flags, processor
from hybrid.spec.stamp import is_hand_edited
from hybrid.validate import shown

log = logging.getLogger("hybrid")


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


def cdef_of(header: str) -> str:
    """The declarations between the header's cdef markers, for cffi."""
    try:
        return header.split("/* cdef-begin */", 1)[1].split("/* cdef-end */", 1)[0]
    except IndexError:
        raise NativeBuildError("generated header lacks its cdef markers; run `python -m hybrid regenerate`") from None


def _cached_module(stem: str, key_material: dict, write_source: Callable[[str, Path], None],
                   includes: list[str], parts: tuple[str, ...] = ()):
    """Build (once per key) and import the extension whose C ``write_source(name, path)`` writes
    (with ``parts``, the files beside it holding the unit's further parts:
    :func:`~hybrid.native.compiler.compile_extension`).

    The name carries a hash of ``key_material`` plus the compiler, flags and ABI, so a change
    to any of them builds a new entry instead of loading a stale one.
    """
    cc, ident = compiler()
    material = json.dumps({**key_material, "cc": [cc, ident], "flags": flags(ident), "cpu": processor(),
                           "abi": sysconfig.get_config_var("EXT_SUFFIX")}, sort_keys=True)
    name, folder = entry(stem, material)
    so = folder / f"{name}{sysconfig.get_config_var('EXT_SUFFIX')}"
    manifest = folder / "manifest.json"

    def valid() -> bool:  # verified at every load: a damaged library is rebuilt, never loaded
        return library_intact(so, manifest)

    def make() -> None:
        log.info("hybrid: compiling %s with %s", name, cc, extra=SLOW)
        t0 = time.perf_counter()
        with files.temporary_folder(folder) as tmp:
            c_file = Path(tmp) / f"{name}.c"
            write_source(name, c_file)
            checksum = compile_extension(c_file, so, cc, ident, includes, tuple(Path(tmp) / part for part in parts))
        log.info("hybrid: compiled %s in %.1f s", name, time.perf_counter() - t0)
        write_checksum(manifest, checksum, compiler=ident, flags=flags(ident))

    def build() -> None:
        once(folder, valid, make)

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
            raise NativeBuildError(f"{so.name} does not load even after a rebuild ({again}); delete {folder} "
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


def _compile_unit(src_dir: Path, prefix: str, texts: dict[str, str] | None = None):
    """The unit ``<prefix>.c`` of ``src_dir`` compiled as a cffi module (``.ffi``, ``.lib``); with
    ``texts``, its files as read already (by name: a cached unit's, verified against their checksums)."""
    c_source, header = (texts[f"{prefix}.c"], texts[f"{prefix}.h"]) if texts else _read_unit(src_dir, prefix)
    cdef = cdef_of(header)

    def write_source(name: str, path: Path) -> None:
        _copy_unit(path.parent, prefix, c_source, header)
        ffi = cffi.FFI()
        ffi.cdef(cdef)
        # quiet (cffi would announce the file on stdout; redirecting stdout is not safe beside other threads)
        ffi.set_source(name, f'#include "{prefix}.c"', compiler_verbose=0)
        ffi.emit_c_code(str(path))

    # a unit whose manifest says it has parts: its own file once for each
    n = _manifest_parts(src_dir, prefix, texts)
    parts = (f"{prefix}.c",) * n if n > 1 else ()
    # the header of the SIMD lanes, where the unit includes it: its text is part of the key
    lanes = generator.LANES_INCLUDE in c_source
    includes = [str(source_dir())] if lanes else []
    shared = {"lanes": _lanes_header()} if lanes else {}
    return _cached_module(f"_{prefix}", {"c": c_source, "h": header, "cffi": cffi.__version__, **shared,
                                         **({"parts": n} if parts else {})}, write_source, includes, parts)


def _lanes_header() -> str:
    """The text of the SIMD lanes' header a unit includes: the generated C's copy (where the generator writes
    it), which the unit is compiled with; said when edited by hand."""
    folder = source_dir()
    try:
        text = (folder / generator.LANES_HEADER).read_text()
    except OSError as exc:
        raise NativeBuildError(f"the SIMD lanes' header {folder / generator.LANES_HEADER} cannot be read "
                               f"({exc.strerror}); run `python -m hybrid regenerate` in a checkout of the project"
                               ) from None
    warn_if_hand_edited(folder, {generator.LANES_HEADER: text})
    return text


def _manifest_parts(src_dir: Path, prefix: str, texts: dict[str, str] | None = None) -> int:
    """How many parts the unit's manifest says it is compiled in (``parts``; 1 where it says none)."""
    try:
        parts = read_manifest(src_dir, prefix, texts).get("parts", 1)
    except (NativeBuildError, AttributeError):
        return 1  # a unit read without its manifest is compiled whole, as any unit can be
    if not isinstance(parts, int) or isinstance(parts, bool) or not 1 <= parts <= 8:
        raise NativeBuildError(f"the manifest {prefix}.json in {src_dir} says the unit has {shown(parts, 40)} parts; "
                               "regenerate the unit")
    return parts


def _copy_unit(folder: Path, prefix: str, c_source: str, header: str) -> None:
    """The unit's text, as read (and hashed into the cache key), beside the build's own source:
    a ``regenerate`` running meanwhile cannot slip other code under the same key."""
    (folder / f"{prefix}.c").write_text(c_source)
    (folder / f"{prefix}.h").write_text(header)


def read_manifest(src_dir: Path, prefix: str, texts: dict[str, str] | None = None) -> dict:
    """The interface description written by the generator beside ``<prefix>.c`` (in ``texts``, the
    unit's files read already, where given)."""
    try:
        return json.loads(texts[f"{prefix}.json"] if texts else (src_dir / f"{prefix}.json").read_text())
    except (OSError, ValueError, KeyError) as exc:
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


def load_generated(src_dir: Path, prefix: str, texts: dict[str, str] | None = None):
    """Compile (cached) and load the unit ``<prefix>`` written into ``src_dir`` (a cffi module); with
    ``texts``, its files as read already (by name)."""
    return _compile_unit(src_dir, prefix, texts)


# ------------------------------------------------------------------ the one-state entry point

#: the most arguments a function may have for the one-state entry point (hybrid/native/fastcall.c)
FAST_MAX_ARGS = 24


def fastcall_prelude(manifest: dict) -> str:
    """What ``hybrid/native/fastcall.c`` expects before it, written from the unit's manifest: an adapter
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
    """The one-state CPython entry point (``hybrid/native/fastcall.c``) of the unit ``<prefix>`` in ``src_dir``.

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


# ------------------------------------------------------------------ the shared headers' entry points

#: the committed header of the path follower (``codegen/path_follow.py``)
PATH_HEADER = "hybrid_path.h"
#: the committed header of a part's surface (``codegen/part_grid.py``)
PART_HEADER = "hybrid_part.h"


def _header_module(header_name: str, macro: str, what: str):
    """The committed header ``header_name`` compiled as a cffi module (``.ffi``, ``.lib``) with its entry points
    (``macro`` defined), cached by the header's text; ``what`` names it in an error."""
    folder = source_dir()
    try:
        header = (folder / header_name).read_text()
    except OSError as exc:
        raise NativeBuildError(f"{what}'s header {folder / header_name} cannot be read ({exc.strerror}); "
                               "run `python -m hybrid regenerate` in a checkout of the project") from None
    warn_if_hand_edited(folder, {header_name: header})
    source = f'#define {macro} 1\n#include "{header_name}"\n'

    def write_source(name: str, path: Path) -> None:
        (path.parent / header_name).write_text(header)
        ffi = cffi.FFI()
        ffi.cdef(cdef_of(header))
        ffi.set_source(name, source, compiler_verbose=0)
        ffi.emit_c_code(str(path))

    return _cached_module(f"_{header_name.removesuffix('.h')}", {"h": header, "c": source, "cffi": cffi.__version__},
                          write_source, [])


@cache
def path_follower():
    """The path follower of ``generated/hybrid_path.h`` compiled as a cffi module (``.ffi``, ``.lib``: its
    entry points ``hybrid_path_follow_entry`` and ``hybrid_path_table_entry``), cached by the header's text."""
    return _header_module(PATH_HEADER, "HYBRID_PATH_ENTRY_POINTS", "the path follower")


@cache
def part_evaluator():
    """A part's surface evaluator of ``generated/hybrid_part.h`` compiled as a cffi module (``.ffi``, ``.lib``:
    its entry point ``hybrid_part_expansion_entry``), cached by the header's text."""
    return _header_module(PART_HEADER, "HYBRID_PART_ENTRY_POINTS", "a part's surface evaluator")
