"""Strict checks of user-given values, shared by every validated dataclass."""

from __future__ import annotations

import dataclasses
import difflib
import functools
import hashlib
import inspect
import keyword
import math
import os
import re
import reprlib
import unicodedata

import numpy as np

from hybrid.errors import HybridError


def _finite(owner: str, **values: float) -> None:
    """Each value a real number (not a bool), finite as a float."""
    for name, v in values.items():
        if not isinstance(v, (int, float, np.floating, np.integer)) or isinstance(v, bool):
            raise HybridError(f"{owner}.{name} must be a real number, got {shown(v, 60)}")
        try:
            ok = math.isfinite(float(v))
        except OverflowError:  # a Python int beyond float range
            ok = False
        if not ok:
            raise HybridError(f"{owner}.{name} is {str(v)[:30]}; give a finite value (within float range)")


def check_call(where: str, signature: inspect.Signature, args: tuple, kwargs: dict) -> None:
    """Refuse a call of ``where`` (``"Controller"``) whose arguments do not fit ``signature`` (``args`` with ``self``
    first, for a method): a keyword it has not, with the nearest one it has; too many arguments by position; one
    missing or given twice. Python's own refusal is a TypeError that names neither what to give nor the near miss."""
    try:
        signature.bind(*args, **kwargs)
        return
    except TypeError:
        pass
    params = [p for p in signature.parameters.values() if p.name != "self"]
    keywords = [p.name for p in params if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]
    positional = [p.name for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    given = args[1:] if "self" in signature.parameters else args
    unknown = [k for k in kwargs if k not in keywords]
    twice = [k for k in positional[:len(given)] if k in kwargs]
    required = [p.name for p in params if p.default is p.empty and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    missing = [k for k in required if k not in positional[:len(given)] and k not in kwargs]
    # its arguments as help() names them: a function of settings by name (``**overrides``) takes them by keyword
    named = keywords + [f"**{p.name}" for p in params if p.kind is p.VAR_KEYWORD]
    if unknown:
        near = nearest(unknown[0], keywords)
        hint = f"did you mean {near!r}?" if near else "give one of its keywords" if keywords else "it takes none"
        problem = f"{where} has no keyword {shown(unknown[0], 40)}; {hint} (help(hybrid.{where}))"
    elif len(given) > len(positional):
        takes, then = ((f"takes {len(positional)} argument{'s' * (len(positional) != 1)} by position "
                        f"({listed(positional, 6)})", "give the others by keyword") if positional else
                       ("takes its arguments by keyword only", "give them by keyword") if named else
                       ("takes no arguments", "give none"))
        problem = (f"{where} {takes}, {len(given)} {'was' if len(given) == 1 else 'were'} given (the first extra: "
                   f"{shown(given[len(positional)], 40)}); {then}")
    elif twice:
        problem = f"{where}: {twice[0]} is given twice, by position and as a keyword; give it once"
    else:
        problem = f"{where}: {', '.join(missing) or 'an argument'} not given; give {', '.join(required)}"
    raise HybridError(f"{problem}\n  its arguments: {', '.join(named) or 'none'}") from None


def nearest(word: str, names) -> str | None:
    """The one of ``names`` a user most likely meant by ``word`` (a keyword misspelt), or None: the same but
    for capitals; else the one a single typo away (a letter dropped, added, changed, or two swapped; of several,
    one with the same letters, then the most similar by :mod:`difflib`); else the most similar, if similar
    enough."""
    names = list(names)
    same = [n for n in names if n.lower() == word.lower()]
    if same:
        return same[0]
    typo = [n for n in names if _one_typo(word, n)]
    if typo:  # two letters swapped first (its letters all there), then the most similar
        return max(typo, key=lambda n: (sorted(n) == sorted(word), difflib.SequenceMatcher(None, word, n).ratio()))
    near = difflib.get_close_matches(word, names, n=1, cutoff=0.6)
    return near[0] if near else None


def _one_typo(a: str, b: str) -> bool:
    """Whether ``a`` and ``b`` differ by one typo: a letter dropped or added, one changed, or two neighbours
    swapped."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    i = 0
    while i < min(len(a), len(b)) and a[i] == b[i]:
        i += 1
    if len(a) == len(b):
        return a[i + 1:] == b[i + 1:] or (a[i:i + 2] == b[i:i + 2][::-1] and a[i + 2:] == b[i + 2:])
    longer, shorter = (a, b) if len(a) > len(b) else (b, a)
    return longer[i + 1:] == shorter[i:]


def checked_keywords(target=None, *, where: str | None = None):
    """A decorator of a class (after ``@dataclass``) or of a function that makes things: a call with a keyword it
    has not, too many arguments by position, one missing or given twice is refused by :func:`check_call` (a
    HybridError naming the nearest keyword) in place of Python's TypeError; its signature stays as it was, for
    ``help`` and ``inspect``. ``where``: its name in the message (default its own; ``"sweeps.Uniform"`` for one
    that is not ``hybrid.<name>``). The call is checked only when it fails: a call that fits costs nothing more.

    ``@checked_keywords`` or ``@checked_keywords(where=...)``; a class that takes no arguments (no ``__init__`` of
    its own) is given one that takes none, a subclass of a checked class is checked under its own name."""
    def decorate(made):
        name = where or made.__name__
        call = made.__init__ if isinstance(made, type) else made
        call = getattr(call, "_unchecked", call)  # a checked class's subclass: its own name, one check
        if call is object.__init__:  # object's takes anything: its refusal comes later, from object.__new__
            call = _no_arguments
        signature = inspect.signature(call)

        @functools.wraps(call)
        def checked(*args, **kwargs):
            try:
                return call(*args, **kwargs)
            except TypeError:  # Python binds the arguments before the body runs: nothing was done
                check_call(name, signature, args, kwargs)  # a HybridError when they do not fit the signature
                raise  # they fit: the TypeError is the body's own

        checked._unchecked = call
        if not isinstance(made, type):
            return checked
        made.__init__ = checked
        return made

    return decorate if target is None else decorate(target)


def _no_arguments(self) -> None:
    """The ``__init__`` of a class that takes no arguments (what :func:`checked_keywords` checks a call against)."""


def field_values(obj) -> dict:
    """A flat dataclass's fields by name (``dataclasses.asdict`` copies deeply: slow in a sweep)."""
    return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)}


def unit_vector(owner: str, name: str, v) -> tuple[float, ...]:
    """``v / |v|`` without overflow for huge components; a zero or non-finite ``v`` is an error."""
    arr = np.asarray(v, dtype=float)
    scale = float(np.max(np.abs(arr))) if arr.size else 0.0
    if not np.isfinite(arr).all() or not scale > 0:
        raise HybridError(f"{owner}.{name} = {tuple(v)} has zero length or is not finite; give a direction")
    arr = arr / scale
    return tuple(float(x) + 0.0 for x in arr / np.linalg.norm(arr))


def _point(owner: str, name: str, p, dims: tuple[int, ...] = (2,)) -> tuple[float, ...]:
    """``p`` as a tuple of finite coordinates, of one of the lengths ``dims``."""
    what = " or ".join({2: "two numbers (x, y)", 3: "three numbers (x, y, z)"}[d] for d in dims)
    if p is None:
        raise HybridError(f"{owner}.{name} must be {what} in m, got None (it is missing): give the point")
    if isinstance(p, (str, bytes)):
        raise HybridError(f"{owner}.{name} must be {what} in m, got {shown(p)}")
    try:
        arr = np.asarray(p, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise HybridError(f"{owner}.{name} must be {what} in m, got {shown(p, 80)}") from None
    if arr.ndim != 1 or arr.shape[0] not in dims:
        got = (f"{arr.shape[0]} coordinates" if arr.ndim == 1 else "a single number" if arr.ndim == 0
               else f"an array of shape {arr.shape}")
        raise HybridError(f"{owner}.{name} must be {what} in m, got {got}: {shown(p, 60)}")
    if not np.isfinite(arr).all():
        raise HybridError(f"{owner}.{name} = {shown(p)} is not finite; give finite coordinates")
    # + 0.0 makes -0.0 a 0.0: one place, one run (the runner's caches key on equal values)
    return tuple(float(v) + 0.0 for v in arr)


def finite_array(name: str, v, shape) -> np.ndarray:
    """``v`` as finite numbers of ``shape``, else a HybridError naming ``name``."""
    try:
        arr = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        arr = np.array([])
    if arr.shape != shape or not np.isfinite(arr).all():
        raise HybridError(f"{name} must be finite numbers of shape {shape}, got {shown(v, 80)}")
    return arr


def check_model_error(inertial, viscous_compensation) -> float:
    """The factor ``1 + inertial`` of a controller's model, after checking both settings."""
    _finite("model error", inertial=inertial, viscous_compensation=viscous_compensation)
    if inertial <= -1:
        raise HybridError(f"model_error = {inertial} makes masses non-positive; give a value > -1")
    if viscous_compensation < 0:
        raise HybridError(f"viscous_compensation = {viscous_compensation}; give a fraction >= 0")
    return 1.0 + inertial


def inertia_problem(I: np.ndarray) -> str | None:  # noqa: E741
    """Why the 3x3 ``I`` [kg m^2] cannot be a rigid body's inertia about its centre of mass (not
    positive semi-definite, or breaking the triangle inequality), or None when it can."""
    eig = np.linalg.eigvalsh(0.5 * (I + I.T))
    tol = 1e-9 * max(float(np.trace(I)), 1e-300)
    if eig[0] < -tol:
        return f"is not positive semi-definite (eigenvalues {_moments(eig)} kg m^2)"
    if eig[0] + eig[1] < eig[2] - tol:
        return (f"has principal moments {_moments(eig)} kg m^2, which break the triangle inequality (the two "
                "smaller must add up to at least the largest): no rigid body has them")
    return None


def _moments(eig) -> str:
    return ", ".join(f"{e:.4g}" for e in eig)


#: the longest prefix of emitted symbols and file names: a user's longer name is refused, a derived one is
#: cut and given a hash
MAX_PREFIX = 48
#: an ASCII C name that reserves nothing: a letter first (C keeps ``_X`` and ``__`` names for itself)
_C_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
#: an ASCII identifier (a symbol in a formula; it only reaches C inside comments)
_ASCII_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
#: the headers a generated unit's name must not take: ``<name>.h`` beside the user's sources (built with
#: ``-I.``, as the C interface's page shows) would hide the system's header of that name from every file
#: that includes it. The C standard library's, common POSIX and compiler ones, and the project's own
SYSTEM_HEADERS = frozenset((
    "assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp signal stdalign stdarg "
    "stdatomic stdbool stdckdint stdbit stddef stdint stdio stdlib stdnoreturn string tgmath threads time uchar "
    "wchar wctype "
    "aio cpio dirent dlfcn fcntl fmtmsg fnmatch ftw glob grp iconv langinfo libgen monetary mqueue ndbm netdb "
    "nl_types poll pthread pwd regex sched search semaphore spawn strings syslog tar termios trace ulimit unistd "
    "utime utmpx wordexp alloca malloc memory features endian byteswap "
    "immintrin smmintrin emmintrin xmmintrin arm_neon omp Python "
    "hybrid_lanes").lower().split())
#: C's keywords (C23's included) and the names CasADi's code generator keeps: the generated symbols start
#: with the name, and CasADi refuses these as a unit's
RESERVED_WORDS = frozenset((
    "auto break case char const continue default do double else enum extern float for goto if inline int long "
    "register restrict return short signed sizeof static struct switch typedef union unsigned void volatile "
    "while bool true false nullptr alignas alignof constexpr static_assert thread_local typeof typeof_unqual "
    "null jac hess").split())


def shown(value, limit: int = 60) -> str:
    """``repr(value)`` cut to about ``limit`` characters, safe for any value: nested containers are
    shown a few levels deep, so a deeply nested or huge value cannot overflow or fill memory."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**15:
        return ("-" if value < 0 else "") + count_text(abs(value))  # a number too long to print, by its size
    r = reprlib.Repr()
    r.maxlevel, r.maxstring, r.maxother = 3, limit, limit
    r.maxlist = r.maxtuple = r.maxdict = r.maxset = r.maxfrozenset = r.maxdeque = r.maxarray = 6
    try:
        text = r.repr(value)
    except Exception:  # a user's object whose __repr__ fails: name its type instead
        text = f"<{type(value).__name__}>"
    text = " ".join(text.split())  # one line (an array's repr spans several): a message's first line says it all
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _shown_names(names, most: int, width: int) -> int:
    """How many of ``names`` :func:`listed` names: at most ``most``, in about ``width`` characters, at least one."""
    count, length = 0, 0
    for name in names[:most]:
        length += len(str(name)) + 2
        if count and length > width:
            break
        count += 1
    return count


def listed(names, most: int = 4, width: int = 80) -> str:
    """``names`` joined by commas, at most ``most`` of them in about ``width`` characters, and how many more: a
    list that keeps a message's first line short however many and however long they are."""
    names = [str(name) for name in names]
    count = _shown_names(names, most, width)
    return ", ".join(names[:count]) + (f" and {len(names) - count} more" if len(names) > count else "")


def listed_in_full(names, most: int = 4, width: int = 80) -> str:
    """A message's further line naming every one of ``names`` when :func:`listed` (with the same ``most`` and
    ``width``) named only some (empty otherwise)."""
    names = [str(name) for name in names]
    return f"\n  all {len(names)}: {', '.join(names)}" if _shown_names(names, most, width) < len(names) else ""


def whole_number(name: str, value, least: int, most: int) -> int:
    """``value`` as a whole number in ``[least, most]`` (not a bool), else a HybridError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not least <= value <= most:
        raise HybridError(f"{name} = {shown(value, 40)}; give a whole number from {least} to {most}")
    return int(value)


#: the deepest nesting of tables and lists read from a user's file
MAX_NESTING = 16


def check_nesting(what: str, value, max_depth: int = MAX_NESTING) -> None:
    """Refuse ``value`` (dicts and lists inside each other) nested more than ``max_depth`` deep.

    Walked with an explicit stack, so checking cannot itself overflow; every later step (messages,
    JSON, comparisons) may then recurse freely.
    """
    stack = [(value, 0, ())]
    while stack:
        item, depth, keys = stack.pop()
        if depth > max_depth:
            at = ".".join(str(k)[:30] for k in keys[:4]) + ("..." if len(keys) > 4 else "")
            raise HybridError(f"{what}: {at or 'the value'} is nested more than {max_depth} tables or lists deep; "
                              "write it flatter")
        if isinstance(item, dict):
            stack.extend((v, depth + 1, (*keys, k) if len(keys) <= 4 else keys) for k, v in item.items())
        elif isinstance(item, (list, tuple)):
            stack.extend((v, depth + 1, keys) for v in item)


def c_name_problem(name) -> str | None:
    """Why ``name`` cannot be used as it is for C symbols and file names, or None when it can: the one
    check of every name a generated unit's files and symbols take (a user's, and one derived by
    :func:`c_identifier`)."""
    if not isinstance(name, str):
        return f"it is a {type(name).__name__}, not text"
    bad = next((c for c in name if not c.isascii()), None)
    if bad is not None:
        return f"it has the non-ASCII character {bad!r} (U+{ord(bad):04X})"
    if not name:
        return "it is empty"
    if len(name) > MAX_PREFIX:
        return f"it has {len(name)} characters (at most {MAX_PREFIX})"
    if not _C_NAME.fullmatch(name):
        bad = next((c for c in name if not (c.isalnum() or c == "_")), None)
        return f"it has the character {bad!r}" if bad is not None else "it does not start with a letter"
    if "__" in name or name.endswith("_"):
        # the symbols are ``<name>_...``: a final _ doubles too
        return "it has two _ in a row or ends with _ (C and CasADi keep names with __ for themselves)"
    if name.lower() in SYSTEM_HEADERS:
        return f"{name}.h would hide the header <{name.lower()}.h> from the sources built beside it (cc -I. ...)"
    if name in RESERVED_WORDS:
        return "it is a C keyword or a name CasADi's code generator keeps"
    return None


def check_c_name(what: str, name) -> str:
    """``name`` if it can prefix C symbols and file names as it is (:func:`c_name_problem`); otherwise a
    HybridError that suggests a name that can. A user's name is used as given or refused, never changed."""
    problem = c_name_problem(name)
    if problem:
        hint = f", e.g. {c_identifier(name)!r}" if isinstance(name, str) else ""
        raise HybridError(f"{what} {shown(name, 60)} cannot name C symbols and files: {problem}; give another "
                          f"(ASCII letters, digits and single _, a letter first, at most {MAX_PREFIX}){hint}")
    return name


def check_identifier(what: str, name, max_len: int = 64) -> str:
    """``name`` if it is an ASCII identifier of at most ``max_len`` characters (a symbol of a
    formula, shown in generated comments and manifests); otherwise a HybridError."""
    if not isinstance(name, str) or len(name) > max_len or not _ASCII_IDENTIFIER.fullmatch(name) \
            or keyword.iskeyword(name):
        raise HybridError(f"{what} {shown(name, 60)} must be an ASCII identifier (letters, digits, _; not "
                          f"a Python keyword) of at most {max_len} characters")
    return name


def c_identifier(name: str) -> str:
    """``name`` made a name :func:`c_name_problem` accepts (the prefix of every emitted symbol and file,
    derived from a robot's name): ASCII, a letter first, no ``__`` nor a final ``_`` (CasADi refuses them),
    no system header's name nor a keyword (``math`` gives ``math_robot``), at most :data:`MAX_PREFIX`
    characters. Accents are dropped (``robôt`` gives ``robot``); a name that had other non-ASCII
    characters, or was too long, gets a hash of it, so two such names stay apart. The same name always
    gives the same prefix."""
    if not isinstance(name, str):
        raise HybridError(f"a robot's name must be text, got {type(name).__name__}")
    letters = "".join(c for c in unicodedata.normalize("NFKD", name) if not unicodedata.combining(c))
    ident = re.sub(r"[^A-Za-z0-9_]", "_", letters.encode("ascii", "ignore").decode("ascii"))
    ident = re.sub(r"__+", "_", ident).rstrip("_")
    if not re.match(r"[A-Za-z]", ident):
        ident = "robot" + (f"_{ident.lstrip('_')}" if ident else "")
    if ident.lower() in SYSTEM_HEADERS or ident in RESERVED_WORDS:
        ident = f"{ident}_robot"
    if not letters.isascii() or len(ident) > MAX_PREFIX:
        digest = hashlib.sha256(name.encode("utf-8", "surrogatepass")).hexdigest()
        ident = f"{ident[:MAX_PREFIX - 13].rstrip('_')}_{digest[:12]}"
    return ident


#: default lower bound on ``2 |det J| / |J|_F^2`` (``~ |sin q2|``) before a pose counts as singular
SINGULAR_TOL = 1e-3


def check_singular_tol(owner: str, value) -> None:
    """``value`` as a singular-pose tolerance: a real number in [0, 1)."""
    _finite(owner, singular_tol=value)
    if not 0 <= value < 1:
        raise HybridError(f"singular_tol = {value}; give a value in [0, 1) (default {SINGULAR_TOL})")


# --------------------------------------------------------------------- sizes

#: the most memory one request sized by a user's numbers (N states, a sweep's runs, a run's record)
#: may take, as a fraction of the machine's
MEMORY_FRACTION = 0.5
#: what to assume when the system does not say how much memory it has [bytes]
ASSUMED_MEMORY = 8 * 2**30


def machine_memory() -> int:
    """The machine's physical memory [bytes] (:data:`ASSUMED_MEMORY` where the system does not say)."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):
        return ASSUMED_MEMORY


def count_text(n: int) -> str:
    """A whole number as text: in full, or its power of ten when astronomical (a float would
    overflow, and Python refuses to print integers of thousands of digits)."""
    return f"{n:,}" if n < 10**15 else f"about 10^{int(math.log10(n))}"


def _gib(nbytes: int) -> str:
    gib = nbytes // 2**30
    return count_text(gib) + " GiB" if gib >= 10**6 else f"{nbytes / 2**30:.1f} GiB"


def check_size(what: str, nbytes: int, fix: str, fraction: float | None = None) -> None:
    """Refuse, before anything is allocated, a request that would take ``nbytes`` bytes, more than
    ``fraction`` (default :data:`MEMORY_FRACTION`) of the machine's memory.

    Parameters
    ----------
    what : the request with its numbers, ending in its verb, e.g. ``"1,000,000,000 states of
        robot_terms need"``.
    nbytes : the estimate (a Python int: exact however large the product).
    fix : what to do instead, e.g. ``"pass fewer states at a time"``.
    """
    total = machine_memory()
    limit = (MEMORY_FRACTION if fraction is None else fraction) * total
    if int(nbytes) > limit:
        raise HybridError(f"{what} {_gib(int(nbytes))}; this machine has {_gib(total)}: {fix}\n"
                          f"  (a request may take at most {100 * limit / total:.0f}% of the memory)")


def product(counts) -> int:
    """The product of whole numbers as a Python int: exact, never overflowing as NumPy's would."""
    return math.prod(int(c) for c in counts)
