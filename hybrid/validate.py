"""Strict checks of user-given values, shared by every validated dataclass."""

from __future__ import annotations

import dataclasses
import hashlib
import math
import os
import re

import numpy as np

from hybrid.errors import HybridError


def _finite(owner: str, **values: float) -> None:
    """Each value a real number (not a bool), finite as a float."""
    for name, v in values.items():
        if not isinstance(v, (int, float, np.floating, np.integer)) or isinstance(v, bool):
            raise HybridError(f"{owner}.{name} must be a real number, got {v!r:.60}")
        try:
            ok = math.isfinite(float(v))
        except OverflowError:  # a Python int beyond float range
            ok = False
        if not ok:
            raise HybridError(f"{owner}.{name} is {str(v)[:30]}; give a finite value (within float range)")


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
    if isinstance(p, (str, bytes)):
        raise HybridError(f"{owner}.{name} must be {what} in m, got {p!r}")
    try:
        arr = np.asarray(p, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise HybridError(f"{owner}.{name} must be {what} in m, got {p!r:.80}") from None
    if arr.ndim != 1 or arr.shape[0] not in dims:
        raise HybridError(f"{owner}.{name} must be {what} in m, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise HybridError(f"{owner}.{name} = {p!r} is not finite; give finite coordinates")
    # + 0.0 makes -0.0 a 0.0: one place, one run (the runner's caches key on equal values)
    return tuple(float(v) + 0.0 for v in arr)


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


#: the longest prefix of emitted symbols and file names (a longer name is cut and given a hash)
MAX_PREFIX = 48


def c_identifier(name: str) -> str:
    """``name`` made a C identifier (the prefix of every emitted symbol and file), at most
    :data:`MAX_PREFIX` characters."""
    ident = re.sub(r"\W", "_", name, flags=re.ASCII)
    ident = ident if re.match(r"[A-Za-z_]", ident) else f"robot_{ident}"
    if len(ident) > MAX_PREFIX:
        ident = f"{ident[:MAX_PREFIX - 13]}_{hashlib.sha256(name.encode()).hexdigest()[:12]}"
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
