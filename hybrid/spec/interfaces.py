"""Each interface between generated C and Python, declared once.

A :class:`Port` is one array argument of a generated function: its name, its size in the
interface's dimensions (:class:`Dims`: joints ``nq``, task axes ``m``, the robot's and the
surface's parameter counts), its unit, its meaning, the names of its elements and its role. An
:class:`Interface` is a function's ports in argument order and the statuses it returns.

From these declarations the generator writes the C (the kernel's argument list, the standalone
struct's fields and index macros, the status macros and the manifest), and the runtime binds the C
(the :class:`~hybrid.Controller`'s packing, the closed loop's rows, the status names of its errors):
a port added here reaches every one of them, and a unit whose manifest disagrees with its
declaration is refused when it is bound (:meth:`Interface.check_manifest`).

The statuses (:data:`STATUSES`) and the metrics (:data:`METRICS`) are declared here too: one
number has one name in Python and in C. So are the checks of a parameter's values (:data:`CHECKS`): a
port's ``check`` says which values each of its elements may take, and the standalone C and the
:class:`~hybrid.Controller` refuse any other from that one statement.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from hybrid.errors import HybridError

#: the printers of the paper's closed-form units (``generated/hybrid_<printer>.*``): SymPy's C printer, or
#: CasADi's from the same SymPy derivation (a law's derivation is one of these or the rigid-body algorithms)
PRINTERS = ("sympy", "casadi")

# ------------------------------------------------------------------ the vocabulary


@dataclass(frozen=True)
class Dims:
    """The dimensions an interface's ports are sized in, and the names they index.

    ``joints``: the joints' names (``nq`` of them); ``axes``: the task axes' names (``m``);
    ``robot``: the names of the robot's run-time parameters; ``surface``: the surface's."""

    joints: tuple[str, ...]
    axes: tuple[str, ...]
    robot: tuple[str, ...] = ()
    surface: tuple[str, ...] = ()

    @classmethod
    def sized(cls, joints, axes, n_robot: int, n_surface: int) -> Dims:
        """Dimensions whose parameters are known by their count only (their elements unnamed)."""
        return cls(tuple(joints), tuple(axes), ("",) * n_robot, ("",) * n_surface)

    @property
    def sizes(self) -> dict[str, int]:
        return {"nq": len(self.joints), "m": len(self.axes), "robot": len(self.robot),
                "surface": len(self.surface)}


@dataclass(frozen=True)
class PerAxis:
    """Element names ``<item>_<axis>``: for each task axis, each of ``items`` (axis by axis)."""

    items: tuple[str, ...]

    def names(self, dims: Dims) -> tuple[str, ...]:
        return tuple(f"{k}_{ax}" for ax in dims.axes for k in self.items)


@dataclass(frozen=True)
class PerJoint:
    """Element names ``<item>_<joint>``: for each of ``items``, every joint (item by item), then ``tail``."""

    items: tuple[str, ...]
    tail: tuple[str, ...] = ()

    def names(self, dims: Dims) -> tuple[str, ...]:
        return (*(f"{k}_{j}" for k in self.items for j in dims.joints), *self.tail)


@dataclass(frozen=True)
class Named:
    """Element names taken from the dimensions: ``"joints"``, ``"axes"``, ``"robot"`` or ``"surface"``."""

    of: str

    def names(self, dims: Dims) -> tuple[str, ...]:
        return getattr(dims, self.of)


@dataclass(frozen=True)
class Check:
    """What values a parameter's element may take: ``meaning`` in words, ``c`` the C expression of ``x``
    (the element) and ``T`` (the sample time) that is true for a valid one, ``valid`` the same in Python
    (on a number or an array, ``T`` a number). Both are false for NaN: every test is a comparison that
    NaN fails."""

    name: str
    meaning: str
    c: str
    valid: object


#: the largest finite double: ``|x| <= DBL_MAX`` is false for infinities and NaN alike
_DBL_MAX = 1.7976931348623157e308


def _floor(x):
    """``floor(x)`` of a number or an array without NumPy (the generator imports none): NaN stays NaN."""
    return x - x % 1

#: every check of a parameter's values, by name
CHECKS = {c.name: c for c in (
    Check("finite", "a finite number", "isfinite(x)", lambda x, T: abs(x) <= _DBL_MAX),
    Check("nonnegative", "a finite number >= 0 (a limit or a tolerance: DBL_MAX is none)",
          "(isfinite(x) && x >= 0.0)", lambda x, T: (abs(x) <= _DBL_MAX) & (x >= 0)),
    Check("positive", "a finite number > 0", "(isfinite(x) && x > 0.0)", lambda x, T: (abs(x) <= _DBL_MAX) & (x > 0)),
    Check("switch", "0 or 1", "(x == 0.0 || x == 1.0)", lambda x, T: (x == 0) | (x == 1)),
    Check("fraction", "a number in [0, 1)", "(x >= 0.0 && x < 1.0)", lambda x, T: (x >= 0) & (x < 1)),
    Check("fraction_or_off", "a number in [0, 1), or -1: no check", "(x == -1.0 || (x >= 0.0 && x < 1.0))",
          lambda x, T: (x == -1) | ((x >= 0) & (x < 1))),
    Check("count", "a whole number >= 1 (at most 1e9)", "(x >= 1.0 && x <= 1e9 && x == floor(x))",
          lambda x, T: (x >= 1) & (x <= 1e9) & (x == _floor(x))),
    Check("sampled_time_constant", "a time constant of at least two sample times (2 sample_time) [s]: the "
          "sampled stop is unstable at one sample time or less", "(isfinite(x) && x >= 2.0 * T)",
          lambda x, T: (abs(x) <= _DBL_MAX) & (x >= 2 * T)),
    Check("below_nyquist", "a frequency >= 0 below the Nyquist frequency 0.5 / sample_time (0: off)",
          "(x >= 0.0 && x < 0.5 / T)", lambda x, T: (x >= 0) & (x < 0.5 / T)),
)}


#: the roles of a function's inputs: what gives each its numbers at a sample
ARGUMENT = "argument"    # the caller's measurement of this sample (t, q, q', the wrench)
STATE = "state"          # kept between samples: zero at a start, written back from the outputs
REFERENCE = "reference"  # computed by the caller at each sample (references given as code); zero when not
PARAMETER = "parameter"  # the configuration: fixed between samples unless the caller changes it
ROLES = (ARGUMENT, STATE, REFERENCE, PARAMETER)

_TERM = re.compile(r"^(?:(\d+)\*)?([a-z]+|\d+)$")


@dataclass(frozen=True)
class Port:
    """One array argument of a generated function.

    ``size`` is stated in the dimensions of :class:`Dims` (``"nq"``, ``"2*m"``, ``"nq+1"``, ``"13"``);
    ``names`` gives the elements' names (a tuple, or :class:`PerAxis`, :class:`PerJoint`,
    :class:`Named`); ``role`` says what fills an input (:data:`ROLES`; outputs have none);
    ``default`` is the value of every element (or one per element) of a parameter that its owner does not
    set, the value at which it changes nothing; None where no value is neutral (the owner must give it).
    ``check`` names the values a parameter's elements may take (:data:`CHECKS`): one name for every
    element, or a tuple of one per item of a :class:`PerJoint` or :class:`PerAxis` (repeated over the
    joints or axes) or one per element of a fixed ``names``."""

    name: str
    size: str
    unit: str
    doc: str
    role: str = ""
    names: tuple[str, ...] | PerAxis | PerJoint | Named | None = None
    default: float | tuple[float, ...] | None = None
    check: str | tuple[str, ...] = ""

    def __post_init__(self):
        for name in (self.check,) if isinstance(self.check, str) else self.check:
            if name and name not in CHECKS:
                raise ValueError(f"port {self.name}: check {name!r} is not one of {', '.join(CHECKS)}")

    def checks(self, dims: Dims) -> tuple[str, ...]:
        """The check of each element for ``dims`` (``""``: none)."""
        size = self.size_of(dims)
        if isinstance(self.check, str):
            return (self.check,) * size
        if isinstance(self.names, PerJoint):
            got = tuple(k for k in self.check for _ in dims.joints)
        elif isinstance(self.names, PerAxis):
            got = tuple(self.check) * len(dims.axes)
        else:
            got = tuple(self.check)
        if len(got) != size:
            raise ValueError(f"port {self.name}: {len(self.check)} checks do not fit its {size} elements")
        return got

    def size_of(self, dims: Dims) -> int:
        """The number of elements for ``dims``."""
        sizes, total = dims.sizes, 0
        for term in self.size.replace(" ", "").split("+"):
            match = _TERM.match(term)
            if match is None:
                raise ValueError(f"port {self.name}: size {self.size!r} is not a sum of [k*]dimension terms")
            k, what = int(match[1] or 1), match[2]
            total += k * (int(what) if what.isdigit() else sizes[what])
        return total

    def element_names(self, dims: Dims) -> tuple[str, ...] | None:
        """The elements' names for ``dims`` (None: they have none)."""
        if self.names is None or isinstance(self.names, tuple):
            return self.names
        return tuple(self.names.names(dims))


@dataclass(frozen=True)
class Status:
    """A status a generated function returns: its name (``HYBRID_<name>`` in a unit's C, ``<PREFIX>_<name>``
    in a standalone one) and its number, the same everywhere."""

    name: str
    code: int
    meaning: str


#: every status of the generated code, numbered once: the kernels' (their guards and outputs), then the
#: standalone step's checks of its call
STATUSES = (
    Status("OK", 0, "a sample on time; tau is the law's, the integrals advanced"),
    Status("SINGULAR", 1, "the task Jacobian's conditioning is below singular_tol; tau is the torque last written"),
    Status("NONFINITE", 2, "the law's output is not finite; tau is the torque last written"),
    Status("FRAME_UNDEFINED", 3, "the task frame's reference direction is parallel to the normal, or the surface "
                                 "has no normal (grad phi 0 or not finite); tau is the torque last written"),
    Status("EULER_SINGULAR", 4, "cos(beta) of the tip's ZYX Euler angles is near 0; tau is the torque last written"),
    Status("INPUT_NONFINITE", 5, "t, q, qd or wrench is not finite; tau is the torque last written, nothing "
                                 "changed"),
    Status("SAMPLE_LATE", 6, "t advanced by more than (1 + timing_tolerance) sample_time; tau is the law's, the "
                             "integrals kept"),
    Status("SAMPLE_EARLY", 7, "t advanced by less than (1 - timing_tolerance) sample_time; tau is the law's, the "
                              "integrals kept"),
    Status("SAMPLE_REPEATED", 8, "t equals the last sample's: no time passed; tau is the law's at this sample "
                                 "within the limits, nothing changed"),
    Status("SAMPLE_BACKWARDS", 9, "t is before the last sample's; tau is the law's at this sample within the "
                                  "limits, nothing changed"),
    Status("PARAMETER_INVALID", 10, "a run-time parameter is not a value its check allows (a NaN, a negative "
                                    "limit or tolerance, a filter cutoff at or above Nyquist) or the sample "
                                    "clock is not finite; tau is the torque last written, nothing changed"),
    Status("SAFE_STOP", 11, "the step is in its safe state after fault_samples consecutive faulted samples, until "
                            "a reset: tau stops the arm and holds it (its model's inverse dynamics, time "
                            "constant stop_time) and releases the torque it had over unload_time"),
)
STATUS_CODES = {s.name: s.code for s in STATUSES}
STATUS_NAMES = {s.code: s.name for s in STATUSES}
#: the statuses a generated kernel returns (``HYBRID_<name>``): its guards' and a non-finite output's
KERNEL_STATUSES = ("OK", "SINGULAR", "NONFINITE", "FRAME_UNDEFINED", "EULER_SINGULAR")
#: the sample-timing statuses, by the interval since the last sample
TIMING_STATUSES = ("SAMPLE_LATE", "SAMPLE_EARLY", "SAMPLE_REPEATED", "SAMPLE_BACKWARDS")
#: the timing statuses of a sample at which no time passed (or it went back): nothing of the step changes
HELD_STATUSES = ("SAMPLE_REPEATED", "SAMPLE_BACKWARDS")


@dataclass(frozen=True)
class Interface:
    """A generated function's boundary: its inputs and outputs in argument order."""

    name: str
    inputs: tuple[Port, ...]
    outputs: tuple[Port, ...]
    doc: str

    def __post_init__(self):
        for p in self.inputs:
            if p.role not in ROLES:
                raise ValueError(f"{self.name}: input {p.name} has role {p.role!r}, not one of {ROLES}")
        names = [p.name for p in (*self.inputs, *self.outputs)]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.name}: a port name is used twice in {names}")

    def port(self, name: str) -> Port:
        for p in (*self.inputs, *self.outputs):
            if p.name == name:
                return p
        raise KeyError(f"{self.name} has no port {name!r}")

    def named(self, role: str) -> tuple[str, ...]:
        """The names of the inputs of ``role``, in argument order."""
        return tuple(p.name for p in self.inputs if p.role == role)

    @property
    def per_sample(self) -> tuple[str, ...]:
        """The inputs that change at every sample (all but the parameters), in argument order; they come first."""
        return tuple(p.name for p in self.inputs if p.role != PARAMETER)

    @property
    def parameters(self) -> tuple[str, ...]:
        return self.named(PARAMETER)

    def sizes(self, dims: Dims) -> dict[str, int]:
        """Every port's size for ``dims``, by name."""
        return {p.name: p.size_of(dims) for p in (*self.inputs, *self.outputs)}

    def pack(self, values: dict, dims: Dims) -> tuple:
        """The parameters in argument order from ``values`` (arrays by port name): a parameter not in
        ``values`` takes its ``default``; a value of the wrong size, a parameter without a default left out,
        or a name that is no parameter, is refused (the caller and the declaration disagree)."""
        import numpy as np  # only the runtime packs

        unknown = set(values) - set(self.parameters)
        if unknown:
            raise HybridError(f"{self.name} has no parameter {', '.join(sorted(unknown))}; its parameters are "
                              f"{', '.join(self.parameters)}")
        out = []
        for p in self.inputs:
            if p.role != PARAMETER:
                continue
            size = p.size_of(dims)
            given = values.get(p.name)
            if given is None and p.default is None:
                raise HybridError(f"{self.name}'s {p.name} has no neutral value: give it ({p.doc})")
            arr = np.broadcast_to(np.asarray(p.default, float), (size,)) if given is None else \
                np.asarray(given, float).ravel()
            if arr.size != size:
                raise HybridError(f"{self.name}'s {p.name} takes {size} numbers, got {arr.size}")
            out.append(arr)
        return tuple(out)

    def refused(self, params: tuple, dims: Dims, sample_time: float) -> list[tuple[str, str, float, str]]:
        """The elements of ``params`` (the parameters in argument order, as :meth:`pack` gives them) that
        their ports' checks refuse, as ``(port, element, value, what is valid)``; ``sample_time`` [s] is
        the ``T`` of the checks that read it."""
        bad = []
        for p, values in zip((p for p in self.inputs if p.role == PARAMETER), params):
            names = p.element_names(dims) or tuple(str(i) for i in range(p.size_of(dims)))
            for name, value, check in zip(names, values, p.checks(dims)):
                if check and not CHECKS[check].valid(float(value), sample_time):
                    bad.append((p.name, name or str(len(bad)), float(value), CHECKS[check].meaning))
        return bad

    def check_manifest(self, entry: dict, dims: Dims) -> None:
        """Refuse a unit's manifest entry whose arguments are not this declaration's (names, order,
        sizes), naming the first difference: a unit built from other code is never called with
        arrays packed for this one."""
        for what, ports, got in (("input", self.inputs, entry["inputs"]), ("output", self.outputs,
                                                                           entry["outputs"])):
            want = [(p.name, p.size_of(dims)) for p in ports]
            have = [(a["name"], a["size"]) for a in got]
            if want == have:
                continue
            diff = next((f"{what} {i + 1} is declared {w[0]}[{w[1]}] and compiled {h[0]}[{h[1]}]"
                         for i, (w, h) in enumerate(zip(want, have)) if w != h), None)
            if diff is None:  # one is the other and more
                extra = want[len(have):] or have[len(want):]
                side = "declared, not compiled" if len(want) > len(have) else "compiled, not declared"
                diff = f"{what}s {', '.join(n for n, _ in extra)} {side}"
            raise HybridError(f"the compiled {entry['name']} does not match its declaration: {diff}; a unit "
                              "generated by other code is in the way: delete the cache folder (HYBRID_CACHE_DIR, "
                              "default ~/.cache/hybrid), or in a checkout run python -m hybrid regenerate")
