"""The decoupling law ``F*(r, r', a)`` and the arm's terms, evaluated by the compiled C."""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from . import native
from .errors import HybridError, NonFiniteError, SingularConfigurationError
from .parameters import Arm, Circle, Plane, _finite
from .robot import Robot

#: default lower bound on ``2 |det J| / |J|_F^2`` (``~ |sin q2|``) before a pose counts as singular
SINGULAR_TOL = 1e-3
_STATUS = {1: "singular", 2: "non-finite"}


def check_surface(surface) -> str:
    if not isinstance(surface, (Circle, Plane)):
        raise HybridError(f"surface must be a hybrid.Circle or hybrid.Plane, got {type(surface).__name__}")
    return surface.kind


def check_arm(arm) -> None:
    if not isinstance(arm, Arm):
        raise HybridError(f"arm must be a hybrid.Arm (see hybrid.paper_arm()), got {type(arm).__name__}")


def check_singular_tol(owner: str, value) -> None:
    """``value`` as a singular-pose tolerance: a real number in [0, 1)."""
    _finite(owner, singular_tol=value)
    if not 0 <= value < 1:
        raise HybridError(f"singular_tol = {value}; give a value in [0, 1) (default {SINGULAR_TOL})")


def as_states(name: str, x) -> np.ndarray:
    """``x`` as a C-contiguous float64 array of shape ``(2,)`` or ``(N, 2)``."""
    if np.iscomplexobj(x):
        raise HybridError(f"{name} must be real, got complex values")
    try:
        arr = np.ascontiguousarray(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise HybridError(f"{name} must be numbers of shape (2,) or (N, 2), got {x!r:.80}") from None
    if arr.ndim not in (1, 2) or arr.shape[-1] != 2 or (arr.ndim == 2 and arr.shape[0] == 0):
        raise HybridError(f"{name} must have shape (2,) or (N, 2) with N >= 1, got {arr.shape}")
    return arr


def status_error(status: int, where: str, **inputs) -> HybridError:
    """The exception for a native status code, naming the inputs that caused it."""
    shown = ", ".join(f"{k}={np.array2string(np.asarray(v), precision=6)}" for k, v in inputs.items())
    if status == 1:
        return SingularConfigurationError(
            f"{where}: the Jacobian is singular or nearly so at {shown} (elbow q2 near 0 or pi); "
            "keep the arm away from full extension/folding, or lower singular_tol")
    bad = [k for k, v in inputs.items() if not np.isfinite(np.asarray(v, float)).all()]
    hint = f"non-finite input {', '.join(bad)}" if bad else "the inputs are finite but extreme"
    return NonFiniteError(f"{where}: result is NaN or infinite ({hint}) at {shown}")


@dataclass(frozen=True)
class DecouplingLaw:
    """Compiled task-space decoupling law for one arm model and one surface.

    ``law(q, qdot, a, Fc)`` gives ``F*`` [N] (base frame), ``law.torque(...)`` gives
    ``tau = J^T F*`` [N m]. ``q`` [rad], ``qdot`` [rad/s], ``a`` the task-frame acceleration
    (tangent, normal) [m/s^2], ``Fc`` the measured contact force on the robot (base frame)
    [N]; each of shape ``(2,)``, or ``(N, 2)`` for N states in one native call.
    """

    arm: Arm
    surface: Circle | Plane
    curvature: bool = False
    backend: str = "sympy"
    singular_tol: float = SINGULAR_TOL

    def __post_init__(self):
        check_arm(self.arm)
        kind = check_surface(self.surface)
        if self.backend not in ("sympy", "casadi"):
            raise HybridError(f"backend must be 'sympy' or 'casadi', got {self.backend!r}")
        check_singular_tol("decoupling_law", self.singular_tol)
        # frozen: the compiled buffers below must keep matching the fields
        init = partial(object.__setattr__, self)
        mod = native.load(self.backend)
        init("_ffi", mod.ffi)
        name = f"hybrid_{self.backend}_decoupling_law_{kind}"
        init("_single", getattr(mod.lib, name))
        init("_batch", getattr(mod.lib, name + "_batch"))
        arm, surface, opts = self.arm.as_array(), self.surface.as_array(), np.array([1.0 if self.curvature else 0.0])
        # parameters live in C buffers for the law's lifetime: a call passes pointers only
        init("_arm", mod.ffi.new("double[]", arm.tolist()))
        init("_surface", mod.ffi.new("double[]", surface.tolist()))
        init("_opts", mod.ffi.new("double[]", opts.tolist()))
        # one state from NumPy arrays skips cffi's per-array conversion (see hybrid/fastcall.c)
        fast = native.load_fastcall(self.backend)
        init("_fast", fast.call)
        init("_binding", fast.bind(kind, arm, surface, opts, float(self.singular_tol)))

    def evaluate(self, q, qdot, a, Fc) -> tuple[np.ndarray, np.ndarray]:
        """``(F*, tau)`` for one state (shape ``(2,)``) or N states (shape ``(N, 2)``)."""
        out = self._fast(self._binding, 2, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc) if out is None else out

    def _checked(self, q, qdot, a, Fc) -> tuple[np.ndarray, np.ndarray]:
        """The general path: any array-like input, N states, and the errors that name the cause."""
        ins = [as_states(n, v) for n, v in (("q", q), ("qdot", qdot), ("a", a), ("Fc", Fc))]
        shape = ins[0].shape
        if any(x.shape != shape for x in ins):
            raise HybridError("q, qdot, a and Fc must have the same shape, got "
                              + ", ".join(str(x.shape) for x in ins))
        F, tau = np.empty(shape), np.empty(shape)
        fb = self._ffi.from_buffer
        ptrs = [fb("double[]", x) for x in ins]
        if len(shape) == 1:
            status = self._single(*ptrs, self._arm, self._surface, self._opts, self.singular_tol,
                                  fb("double[]", F), fb("double[]", tau))
            if status:
                raise status_error(status, "decoupling_law", q=ins[0], qdot=ins[1], a=ins[2], Fc=ins[3])
            return F, tau
        status = np.empty(shape[0], dtype=np.intc)
        failed = self._batch(shape[0], *ptrs, self._arm, self._surface, self._opts, self.singular_tol,
                             fb("double[]", F), fb("double[]", tau), fb("int[]", status))
        if failed:
            i = int(np.flatnonzero(status)[0])
            raise status_error(int(status[i]), f"decoupling_law, state {i} of {shape[0]} "
                               f"({failed} failed)", q=ins[0][i], qdot=ins[1][i], a=ins[2][i], Fc=ins[3][i])
        return F, tau

    def __call__(self, q, qdot, a, Fc) -> np.ndarray:
        """Cartesian ``F*`` [N] in the base frame."""
        out = self._fast(self._binding, 0, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc)[0] if out is None else out

    def torque(self, q, qdot, a, Fc) -> np.ndarray:
        """Joint torques ``tau = J^T F*`` [N m]."""
        out = self._fast(self._binding, 1, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc)[1] if out is None else out


def decoupling_law(arm: Arm, surface: Circle | Plane, curvature: bool = False, *,
                   backend: str = "sympy", singular_tol: float = SINGULAR_TOL) -> DecouplingLaw:
    """The paper's decoupling law (NOTES section 2) for ``arm`` on ``surface``, compiled.

    ``curvature=True`` includes the term ``R'(r, r') r'`` (the paper runs without it).
    Parameters are run-time inputs: another arm or surface needs no recompilation.
    """
    return DecouplingLaw(arm, surface, bool(curvature), backend, singular_tol)


def _call(backend: str, name: str, inputs: dict, outputs: dict, singular_tol: float | None = None):
    mod = native.load(backend)
    fb = mod.ffi.from_buffer
    ins = {k: np.ascontiguousarray(v, dtype=float) for k, v in inputs.items()}
    outs = {k: np.empty(n) for k, n in outputs.items()}
    extra = [] if singular_tol is None else [singular_tol]
    status = getattr(mod.lib, f"hybrid_{backend}_{name}")(
        *(fb("double[]", v) for v in ins.values()), *extra, *(fb("double[]", v) for v in outs.values()))
    if status:
        raise status_error(status, name, **ins)
    return tuple(outs.values())


def arm_terms(arm: Arm | Robot, q, qdot, *, backend: str = "sympy") -> dict[str, np.ndarray]:
    """Kinematic and dynamic terms of ``arm`` at one state, from the generated C.

    For the planar :class:`Arm`: ``r`` [m], ``J`` (2x2), ``Jdot_qdot`` [m/s^2], ``B`` (2x2)
    [kg m^2], ``n`` [N m]. For a :class:`Robot` with ``n`` joints (``q``, ``qdot`` of shape
    ``(n,)``, or ``(N, n)`` for N states in one native call, every output then gaining a
    leading N axis): ``r`` (3) [m] and ``rotation`` (3x3) of the tip frame in base axes, the
    frame Jacobian ``J`` (6 x n, linear rows first, base axes), ``Jdot_qdot`` (6, the classical
    acceleration at ``q'' = 0``), ``B`` (n x n), ``n`` (n): Coriolis/centrifugal, gravity, viscosity.
    """
    if isinstance(arm, Robot):
        return robot_terms(arm, q, qdot)
    check_arm(arm)
    q, qdot, p = _one_state("q", q), _one_state("qdot", qdot), arm.as_array()
    r, J, Jdqd = _call(backend, "arm_kinematics", {"q": q, "qd": qdot, "arm": p}, {"r": 2, "J": 4, "Jdqd": 2})
    B, n = _call(backend, "arm_dynamics", {"q": q, "qd": qdot, "arm": p}, {"B": 4, "n": 2})
    return {"r": r, "J": J.reshape(2, 2), "Jdot_qdot": Jdqd, "B": B.reshape(2, 2), "n": n}


def operational_space(arm: Arm, q, qdot, *, backend: str = "sympy",
                      singular_tol: float = SINGULAR_TOL) -> tuple[np.ndarray, np.ndarray]:
    """``B_o(r)`` [kg] (2x2) and ``n_o(r, r')`` [N] of Khatib's operational-space model."""
    check_arm(arm)
    Bo, no = _call(backend, "operational_space",
                   {"q": _one_state("q", q), "qd": _one_state("qdot", qdot), "arm": arm.as_array()},
                   {"Bo": 4, "no": 2}, singular_tol)
    return Bo.reshape(2, 2), no


def task_frame(surface: Circle | Plane, r, rdot, *, backend: str = "sympy") -> tuple[np.ndarray, np.ndarray]:
    """Task-frame rotation ``R(r)`` (rows: tangent, normal) and its derivative ``R'(r, r')``."""
    kind = check_surface(surface)
    R, Rd = _call(backend, f"task_frame_{kind}",
                  {"r": _one_state("r", r), "rd": _one_state("rdot", rdot), "surface": surface.as_array()},
                  {"R": 4, "Rd": 4})
    return R.reshape(2, 2), Rd.reshape(2, 2)


def _one_state(name: str, x) -> np.ndarray:
    """``x`` as one state of shape ``(2,)``; N states are refused, not silently cut to the first."""
    arr = as_states(name, x)
    if arr.ndim != 1:
        raise HybridError(f"{name} must have shape (2,): this function takes one state, got {arr.shape}; "
                          "call it once per state")
    return arr


_ROBOT_KEYS = {"p": "r", "rotation": "rotation", "J": "J", "Jdqd": "Jdot_qdot", "B": "B", "n": "n"}


def robot_terms(robot: Robot, q, qdot) -> dict[str, np.ndarray]:
    """:func:`arm_terms` of a :class:`Robot`: one state, or N states in one native call."""
    terms = robot.unit.function("robot_terms")
    q_arr = np.asarray(q) if not isinstance(q, np.ndarray) else q
    call = terms.batch if getattr(q_arr, "ndim", 1) == 2 else terms
    out = call(q, qdot, robot.as_array())
    return {_ROBOT_KEYS[k]: v for k, v in out.items()}
