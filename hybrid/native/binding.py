"""Generated C functions bound from their manifest: the one place that reads the interface.

The generator writes beside every unit a manifest (``<prefix>.json``) naming each
function's symbol, its inputs and outputs with sizes, shapes and units, and its properties
(``guards``, ``batched``, ``integrator``). :class:`Function` calls a function from that
description alone: it checks and converts the inputs, allocates the outputs, and turns a
status code into a :class:`~hybrid.errors.HybridError` naming the inputs.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path

import numpy as np

from hybrid.errors import HybridError, NonFiniteError, SingularConfigurationError, TaskFrameError
from hybrid.native.loader import load_fastcall
from hybrid.spec.interfaces import STATUS_NAMES
from hybrid.validate import check_size, shown


def status_error(status: int, where: str, singular_hint: str = "", **inputs) -> HybridError:
    """The exception for a native status code: what happened and the fix on the first line, the
    inputs that caused it (the states, not the parameter arrays) on the next."""
    shown = "\n  at " + ", ".join(f"{k}={np.array2string(np.asarray(v), precision=6)}" for k, v in inputs.items()
                                  if np.size(v) <= 12)
    name = STATUS_NAMES.get(status)
    if name == "SINGULAR":
        return SingularConfigurationError(
            f"{where}: the Jacobian is singular or nearly so{singular_hint}; keep the arm away from the singular "
            f"pose, or lower singular_tol{shown}")
    if name == "FRAME_UNDEFINED":
        return TaskFrameError(
            f"{where}: the task frame is undefined: its direction e is parallel to the surface normal there, or the "
            "surface has no normal there (grad phi vanishes or phi is undefined); choose another frame_direction "
            f"or point{shown}")
    if name == "EULER_SINGULAR":
        return SingularConfigurationError(
            f"{where}: the ZYX Euler angles are singular (beta = +-pi/2, cos beta = 0); use coordinates='twist' "
            f"there, or keep the tool away from that orientation{shown}")
    bad = [k for k, v in inputs.items() if not np.isfinite(np.asarray(v, float)).all()]
    # finite inputs and no finite result: an exactly singular pose leaves the conditioning itself undefined
    hint = (f"non-finite input {', '.join(bad)}" if bad else
            f"the inputs are finite: the arm may be exactly at a singular pose{singular_hint}, or the numbers extreme")
    return NonFiniteError(f"{where}: result is NaN or infinite ({hint}){shown}")


def as_array(name: str, x, size: int, batched: bool | None = False) -> np.ndarray:
    """``x`` as a C-contiguous float64 array of shape ``(size,)``, or ``(N, size)`` when batched
    (``batched=None``: whichever ``x`` is)."""
    if type(x) is np.ndarray and x.dtype == np.float64 and x.flags.c_contiguous and batched is not True \
            and x.shape == (size,):
        return x  # already what C wants: no copy, no checks to repeat
    if batched is not False and isinstance(x, np.ndarray) and x.ndim == 2:
        # a broadcast view of N states takes no memory; its contiguous copy does
        check_size(f"{len(x):,} states of {name} (shape {x.shape}) need", 8 * x.size,
                   "pass fewer states at a time (in chunks)")
    try:
        arr = np.asarray(x)
        if np.iscomplexobj(arr):
            raise HybridError(f"{name} must be real, got complex values")
        arr = np.ascontiguousarray(arr, dtype=np.float64)
    except (TypeError, ValueError) as exc:  # ragged, text, objects
        if isinstance(exc, HybridError):
            raise
        arr = None
    if batched is None:
        batched = arr is not None and arr.ndim == 2
    want = f"(N, {size}) with N >= 1" if batched else f"({size},)"
    if arr is None:
        raise HybridError(f"{name} must be numbers of shape {want}, got {shown(x, 80)}")
    if arr.ndim != (2 if batched else 1) or arr.shape[-1] != size or arr.shape[0] == 0:
        raise HybridError(f"{name} must have shape {want}, got {arr.shape}")
    return arr


def as_states(name: str, x, size: int = 2) -> np.ndarray:
    """``x`` as a C-contiguous float64 array of shape ``(size,)`` or ``(N, size)``."""
    return as_array(name, x, size, batched=None)


def one_state(name: str, x) -> np.ndarray:
    """``x`` as one state of shape ``(2,)``; N states are refused, not silently cut to the first."""
    arr = as_states(name, x)
    if arr.ndim != 1:
        raise HybridError(f"{name} must have shape (2,): this function takes one state, got {arr.shape}; "
                          "call it once per state")
    return arr


def is_batch(x) -> bool:
    """Whether ``x`` holds N states (two dimensions); ragged or foreign input counts as one state,
    whose check then says what is wrong."""
    try:
        return np.ndim(x) == 2
    except (TypeError, ValueError):
        return False


#: fewer states than this run on the calling thread (a thread hand-off costs some microseconds)
PARALLEL_MIN_STATES = 512
_POOL: tuple | None = None  # (process id, executor): a forked child builds its own
_POOL_LOCK = threading.Lock()


def workers() -> int:
    """The cores this process may run on."""
    return _workers()


def _workers() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def one_block(rows: int, widths) -> list[np.ndarray]:
    """``rows x width`` float64 arrays, one for each of ``widths``, views of one allocation: the C
    library's allocator keeps it for the next call of the same size, where arrays apart, freed together,
    can exceed the size it keeps and go back to the system, to be faulted in page by page again (a
    tenth to a third of a batch's time). One array kept keeps the block."""
    block = np.empty(rows * sum(widths))
    ends = np.cumsum([0, *(rows * w for w in widths)]).tolist()
    return [block[a:b].reshape(rows, w) for a, b, w in zip(ends[:-1], ends[1:], widths)]


def parallel_chunks(run, N: int) -> list[int]:
    """``run(lo, hi)`` over ``[0, N)`` in one contiguous chunk per core (the native call releases
    the GIL, so the chunks run at once); results in chunk order. States are independent, so the
    outputs do not depend on the split."""
    global _POOL
    workers = min(_workers(), N // PARALLEL_MIN_STATES)
    if workers <= 1:
        return [run(0, N)]
    with _POOL_LOCK:
        if _POOL is None or _POOL[0] != os.getpid():  # a pool inherited through fork has no threads
            from concurrent.futures import ThreadPoolExecutor

            _POOL = (os.getpid(), ThreadPoolExecutor(max_workers=_workers(), thread_name_prefix="hybrid-batch"))
        pool = _POOL[1]
    bounds = np.linspace(0, N, workers + 1).astype(int)
    return list(pool.map(run, bounds[:-1], bounds[1:]))


class Function:
    """One generated function, called as its manifest describes it.

    ``f(*inputs)`` evaluates one state and returns ``{output name: array}`` shaped as the
    manifest says; ``f.batch(*inputs)`` evaluates N states (the ``per_state`` inputs of shape
    ``(N, size)``) in one native call.
    """

    def __init__(self, module, entry: dict, singular_hint: str = "", labels: dict | None = None, unit=None):
        self.entry, self.unit = entry, unit
        self.name = entry["name"]
        self.inputs = [(a["name"], a["size"]) for a in entry["inputs"]]
        self.outputs = [(a["name"], a["size"], tuple(a["shape"])) for a in entry["outputs"]]
        self.takes_singular_tol = entry["singular_tol"]
        self._ffi = module.ffi
        self._lib = module.lib
        self._fn = getattr(module.lib, entry["symbol"])
        batched, integrator = entry["batched"], entry["integrator"]
        self.per_state = tuple(batched["per_state"]) if batched else ()
        self._batch = getattr(module.lib, batched["symbol"]) if batched else None
        self._integrator = getattr(module.lib, integrator["symbol"]) if integrator else None
        self._hint = singular_hint
        self._labels = labels or {}
        # a constant model's kernels have the robot's parameters compiled in: a robot array is refused
        self._constant = bool(unit is not None and (unit.manifest.get("model") or {}).get("constant"))
        sizes = [size for _, size, _ in self.outputs]
        self._offsets = [sum(sizes[:i]) for i in range(len(sizes))]
        self._total = sum(sizes)

    def fast_bind(self, n_state: int, *params, singular_tol: float | None = None):
        """``(call, binding)`` of the one-state entry point with the inputs after the first
        ``n_state`` fixed to ``params``: ``call(binding, which, *states)`` returns output ``which``
        (-1: all, as a tuple), or None off the fast path (then call this function for the error)."""
        fast = self.unit.fast()
        tol = float(singular_tol) if self.takes_singular_tol else 0.0
        # the function's address in this unit's cffi module: the entry point calls it there
        address = int(self._ffi.cast("uintptr_t", self._ffi.addressof(self._lib, self.entry["symbol"])))
        return fast.call, fast.bind(self.entry["symbol"], address, n_state,
                                    tuple(np.asarray(p, float) for p in params), tol)

    def size(self, name: str) -> int:
        """Number of elements of the input or output ``name``."""
        sizes = {n: s for n, s in self.inputs} | {n: s for n, s, _ in self.outputs}
        return sizes[name]

    def pointers(self, *arrays):
        """cffi pointers to C-contiguous float64 arrays (the caller vouches for sizes and layout)."""
        fb = self._ffi.from_buffer
        return [fb("double[]", a) for a in arrays]

    def into(self, *arrays, singular_tol: float | None = None) -> int:
        """The raw call for hot loops: inputs then outputs as C-contiguous float64 arrays of the
        manifest's sizes (not checked), outputs written in place; returns the status code."""
        ptrs = self.pointers(*arrays)
        k = len(self.inputs)
        return self._fn(*ptrs[:k], *self._extra(singular_tol), *ptrs[k:])

    def batch_into(self, *arrays, status: np.ndarray, singular_tol: float | None = None) -> int:
        """The raw batched call: like :meth:`into` with ``len(status)`` states (per-state arrays of
        shape ``(N, size)``); ``status`` (``intc``) receives each state's code. Returns how many failed."""
        ptrs = self.pointers(*arrays)
        k = len(self.inputs)
        return self._batch(len(status), *ptrs[:k], *self._extra(singular_tol), *ptrs[k:],
                           self._ffi.from_buffer("int[]", status))

    def integrate(self, x: np.ndarray, *held, h: float, nsteps: int, trajectory: np.ndarray | None,
                  done) -> int:
        """``nsteps`` RK4 steps of ``h`` [s] on ``x`` (in place) with ``held`` inputs constant;
        ``done`` is a cffi ``int *`` receiving the steps completed. Returns the status code."""
        ptrs = self.pointers(x, *held)
        traj = self._ffi.NULL if trajectory is None else self._ffi.from_buffer("double[]", trajectory)
        return self._integrator(*ptrs, h, nsteps, traj, done)

    def _extra(self, singular_tol):
        if not self.takes_singular_tol:
            return []
        if singular_tol is None:
            raise HybridError(f"{self.name} needs a singular_tol")
        return [float(singular_tol)]

    def __call__(self, *args, singular_tol: float | None = None) -> dict[str, np.ndarray]:
        ins = self._inputs(args, batched=False)
        # one buffer for all outputs, handed out as views: one allocation, one conversion
        buf = np.empty(self._total)
        base = self._ffi.from_buffer("double[]", buf)
        fb = self._ffi.from_buffer
        status = self._fn(*(fb("double[]", v) for v in ins.values()), *self._extra(singular_tol),
                          *(base + o for o in self._offsets))
        if status:
            raise status_error(status, self.name, self._hint, **self._labelled(ins))
        return {n: buf[o:o + size].reshape(shape) for (n, size, shape), o in zip(self.outputs, self._offsets)}

    def _labelled(self, ins: dict) -> dict:
        return {self._labels.get(n, n): v for n, v in ins.items()}

    def batch(self, *args, singular_tol: float | None = None, out: dict | None = None) -> dict[str, np.ndarray]:
        """N states in one native call; ``out`` maps output names to the caller's arrays to write
        (float64, C-contiguous, writable, ``(N, *shape)``), the others are allocated."""
        if self._batch is None:
            raise HybridError(f"{self.name} has no batched entry point")
        self.check_batch(args)
        ins = self._inputs(args, batched=True)
        lengths = {len(ins[n]) for n in self.per_state}
        if len(lengths) != 1:
            raise HybridError(f"{', '.join(self.per_state)} must have the same number of rows, got "
                              + ", ".join(str(ins[n].shape) for n in self.per_state))
        N = lengths.pop()
        if out is not None and not isinstance(out, dict):
            raise HybridError(f"out must map output names to arrays, got {type(out).__name__}")
        given = out or {}
        unknown = set(given) - {n for n, _, _ in self.outputs}
        if unknown:  # before the outputs' block is allocated
            raise HybridError(f"out names {', '.join(sorted(unknown))}; {self.name} writes "
                              f"{', '.join(n for n, _, _ in self.outputs)}")
        fresh = [(n, size) for n, size, _ in self.outputs if given.get(n) is None]
        made = dict(zip((n for n, _ in fresh), one_block(N, [size for _, size in fresh])))
        outs = {n: made[n] if n in made else self._out_buffer(n, N, size, shape, given[n])
                for n, size, shape in self.outputs}
        status = np.empty(N, dtype=np.intc)

        def run(lo: int, hi: int) -> int:
            rows = [v[lo:hi] if n in self.per_state else v for n, v in ins.items()]
            return self.batch_into(*rows, *(v[lo:hi] for v in outs.values()), status=status[lo:hi],
                                   singular_tol=singular_tol)

        failed = sum(parallel_chunks(run, N))
        if failed:
            i = int(np.flatnonzero(status)[0])
            raise status_error(int(status[i]), f"{self.name}, state {i} of {N} ({failed} failed)", self._hint,
                               **self._labelled({n: (v[i] if n in self.per_state else v) for n, v in ins.items()}))
        return {n: outs[n].reshape((N, *shape)) if n in made else given[n] for n, _, shape in self.outputs}

    def check_batch(self, args) -> None:
        """Refuse, before converting or allocating anything, a batch whose inputs' copies and outputs
        would not fit in memory (with the numbers)."""
        rows = []
        for (name, _), x in zip(self.inputs, args):
            if name in self.per_state:
                try:
                    shape = x.shape if isinstance(x, np.ndarray) else np.shape(x)
                except (TypeError, ValueError):  # ragged: the shape check names it
                    continue
                if len(shape) == 2:
                    rows.append(int(shape[0]))
        if not rows:
            return
        N = max(rows)
        per_state = sum(size for name, size in self.inputs if name in self.per_state) + self._total
        check_size(f"{N:,} states of {self.name} ({per_state} numbers each, inputs and outputs) need",
                   N * (8 * per_state + np.dtype(np.intc).itemsize), "pass fewer states at a time (in chunks)")

    def _out_buffer(self, name: str, N: int, size: int, shape: tuple, given) -> np.ndarray:
        """The caller's array for output ``name``, checked, as the ``(N, size)`` array the batch writes."""
        ok = (isinstance(given, np.ndarray) and given.dtype == np.float64 and given.flags.c_contiguous
              and given.flags.writeable and given.shape in ((N, *shape), (N, size)))
        if not ok:
            got = f"{type(given).__name__} {getattr(given, 'dtype', '')} {getattr(given, 'shape', '')}"
            raise HybridError(f"out[{name!r}] must be a writable C-contiguous float64 array of shape {(N, *shape)}, "
                              f"got {got.strip()}")
        return given.reshape(N, size)

    def _inputs(self, args, batched: bool) -> dict[str, np.ndarray]:
        if len(args) != len(self.inputs):
            if self._constant and len(args) == len(self.inputs) + 1:
                raise HybridError(f"{self.name} of a constant model has the robot's parameters compiled in: call it "
                                  f"with {', '.join(n for n, _ in self.inputs) or 'no arrays'} alone, without a "
                                  "robot array (robot.unit's functions take one)")
            raise HybridError(f"{self.name} takes {len(self.inputs)} arrays "
                              f"({', '.join(n for n, _ in self.inputs)}), got {len(args)}")
        return {n: as_array(self._labels.get(n, n), v, size, batched and n in self.per_state)
                for (n, size), v in zip(self.inputs, args)}


class Unit:
    """A compiled unit and its manifest: ``unit.function(name)`` binds one function.

    ``module`` is the compiled module, or a function that compiles and loads it, called when a
    function is first bound (what a manifest says is known before any compiling);
    ``labels`` renames arguments in messages (the manifest's ``qd`` is the API's ``qdot``);
    ``folder`` is where the unit's C lives, when known.
    """

    def __init__(self, module, manifest: dict, singular_hint: str = "", labels: dict | None = None,
                 folder=None):
        self._module, self.manifest, self.folder = module, manifest, folder
        self._load_lock = threading.Lock()
        self._fast = None
        self._entries = {f["name"]: f for f in manifest["functions"]}
        self._hint, self._labels = singular_hint, labels
        self._bound: dict[str, Function] = {}

    @property
    def module(self):
        """The compiled module (``.ffi``, ``.lib``), compiled and loaded on first use."""
        with self._load_lock:
            if callable(self._module):
                self._module = self._module()
            return self._module

    def function(self, name: str) -> Function:
        if name not in self._bound:
            entry = self.manifest_entry(name)
            self._bound[name] = Function(self.module, entry, self._hint, self._labels, self)
        return self._bound[name]

    def fast(self):
        """The unit's one-state CPython entry point (``hybrid/native/fastcall.c``), compiled on first use."""
        if self._fast is None:
            self._fast = load_fastcall(Path(self.folder), self.manifest["unit"], self.manifest)
        return self._fast

    def manifest_entry(self, name: str) -> dict:
        """The manifest's entry of the function ``name`` (nothing compiled)."""
        if name not in self._entries:
            raise HybridError(f"the unit {self.manifest['unit']} has no function {name!r}; "
                              f"it has {', '.join(self._entries)}")
        return self._entries[name]

    def entry(self, name: str) -> dict:
        return self.function(name).entry
