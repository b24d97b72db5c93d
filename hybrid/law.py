"""The decoupling law ``F*(r, r', a)`` and the arm's terms, evaluated by the compiled C."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache, partial

import numpy as np

from . import binding, native
from .binding import Unit
from .errors import HybridError, NonFiniteError
from .parameters import Arm, Circle, Plane, _finite
from .robot import Robot

#: default lower bound on ``2 |det J| / |J|_F^2`` (``~ |sin q2|``) before a pose counts as singular
SINGULAR_TOL = 1e-3
#: what a singular planar pose means, added to SingularConfigurationError messages
PLANAR_SINGULAR = " (elbow q2 near 0 or pi)"


def planar_unit(backend: str) -> Unit:
    """The committed planar unit of ``backend``, bound from its manifest."""
    if not isinstance(backend, str) or backend not in ("sympy", "casadi"):
        raise HybridError(f"backend must be 'sympy' or 'casadi', got {backend!r:.40}")
    return _planar_unit(backend)


@cache
def _planar_unit(backend: str) -> Unit:
    return Unit(native.load(backend), native.manifest(backend), PLANAR_SINGULAR, {"qd": "qdot", "rd": "rdot"},
                folder=native.source_dir())


def status_error(status: int, where: str, **inputs) -> HybridError:
    """The exception for a planar unit's status code, naming the inputs that caused it."""
    return binding.status_error(status, where, PLANAR_SINGULAR, **inputs)


def check_surface(surface) -> str:
    """The kind of a planar surface (the paper's arm moves in a plane)."""
    if not isinstance(surface, (Circle, Plane)) or surface.dim != 2:
        raise HybridError(f"the planar arm needs a hybrid.Circle or hybrid.Plane in 2-D, got {surface!r:.100}; "
                          "for a 3-D surface use a hybrid.Robot")
    return surface.kind


def check_arm(arm) -> None:
    if not isinstance(arm, Arm):
        raise HybridError(f"arm must be a hybrid.Arm (see hybrid.paper_arm()), got {type(arm).__name__}")


def check_singular_tol(owner: str, value) -> None:
    """``value`` as a singular-pose tolerance: a real number in [0, 1)."""
    _finite(owner, singular_tol=value)
    if not 0 <= value < 1:
        raise HybridError(f"singular_tol = {value}; give a value in [0, 1) (default {SINGULAR_TOL})")


def as_states(name: str, x, size: int = 2) -> np.ndarray:
    """``x`` as a C-contiguous float64 array of shape ``(size,)`` or ``(N, size)``."""
    return binding.as_array(name, x, size, batched=None)


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
        check_singular_tol("decoupling_law", self.singular_tol)
        # frozen: the compiled buffers below must keep matching the fields
        init = partial(object.__setattr__, self)
        fn = planar_unit(self.backend).function(f"decoupling_law_{kind}")
        init("_fn", fn)
        init("_params", (self.arm.as_array(), self.surface.as_array(), np.array([1.0 if self.curvature else 0.0])))
        # one state from NumPy arrays skips cffi's per-array conversion (see hybrid/fastcall.c)
        fast, handle = fn.fast_bind(4, *self._params, singular_tol=self.singular_tol)
        init("_fast", fast)
        init("_binding", handle)

    def __reduce__(self):
        # the compiled handles do not pickle: a copy is built again from the settings
        return (type(self), (self.arm, self.surface, self.curvature, self.backend, self.singular_tol))

    def evaluate(self, q, qdot, a, Fc, out: tuple | None = None) -> tuple[np.ndarray, np.ndarray]:
        """``(F*, tau)`` for one state (shape ``(2,)``) or N states (shape ``(N, 2)``); for N states
        ``out = (F, tau)`` are the caller's arrays to write (either may be None)."""
        if out is not None:
            if not isinstance(out, (tuple, list)) or len(out) != 2:
                raise HybridError("out must be (F, tau): two arrays of shape (N, 2), either may be None")
            return self._checked(q, qdot, a, Fc, dict(zip(("F", "tau"), out)))
        got = self._fast(self._binding, -1, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc) if got is None else got

    def _checked(self, q, qdot, a, Fc, out: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The general path: any array-like input, N states, caller-supplied outputs, and the errors
        that name the cause."""
        size = self._fn.size("q")
        ins = [as_states(n, v, size) for n, v in (("q", q), ("qdot", qdot), ("a", a), ("Fc", Fc))]
        shape = ins[0].shape
        if any(x.shape != shape for x in ins):
            raise HybridError("q, qdot, a and Fc must have the same shape, got "
                              + ", ".join(str(x.shape) for x in ins))
        out = {k: v for k, v in (out or {}).items() if v is not None}
        if len(shape) == 1:
            if out:
                raise HybridError("out= is for N states (arrays of shape (N, 2)); one state returns new arrays")
            got = self._fn(*ins, *self._params, singular_tol=self.singular_tol)
        else:
            got = self._fn.batch(*ins, *self._params, singular_tol=self.singular_tol, out=out)
        return got["F"], got["tau"]

    def __call__(self, q, qdot, a, Fc, out: np.ndarray | None = None) -> np.ndarray:
        """Cartesian ``F*`` [N] in the base frame (for N states, into ``out`` when given)."""
        if out is not None:
            return self._checked(q, qdot, a, Fc, {"F": out})[0]
        got = self._fast(self._binding, 0, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc)[0] if got is None else got

    def torque(self, q, qdot, a, Fc, out: np.ndarray | None = None) -> np.ndarray:
        """Joint torques ``tau = J^T F*`` [N m] (for N states, into ``out`` when given)."""
        if out is not None:
            return self._checked(q, qdot, a, Fc, {"tau": out})[1]
        got = self._fast(self._binding, 1, q, qdot, a, Fc)
        return self._checked(q, qdot, a, Fc)[1] if got is None else got


def decoupling_law(arm: Arm | Robot, surface, curvature: bool = False, *, backend: str = "sympy",
                   singular_tol: float = SINGULAR_TOL, reference=(0.0, 0.0, 1.0), axes=None):
    """The decoupling law for ``arm`` on ``surface``, compiled.

    For the paper's planar :class:`Arm` on a :class:`Circle` or 2-D :class:`Plane`: NOTES
    section 2, a :class:`DecouplingLaw`. For a :class:`Robot` on any surface (a planar one is
    lifted to 3-D): NOTES section 9, a :class:`~hybrid.spatial_law.SpatialDecouplingLaw` with
    task frame reference direction ``reference`` (base axes) and task ``axes`` (``"all"``, the
    default for 6 or more joints, ``"position"``, ``"planar"``, or indices 0-5 of ``t1, t2, n``
    and the rotations about them). ``curvature=True`` includes ``R' v`` (the paper runs
    without it). Parameters are run-time inputs: another arm or surface of the same kind
    needs no recompilation.
    """
    if not isinstance(curvature, bool):
        raise HybridError(f"curvature must be True or False, got {curvature!r}")
    if isinstance(arm, Robot):
        from .spatial_law import spatial_law

        if backend != "sympy":
            raise HybridError("backend selects the planar units; a Robot's law is always generated by CasADi")
        return spatial_law(arm, surface, curvature, reference=reference, axes=axes, singular_tol=singular_tol)
    return DecouplingLaw(arm, surface, curvature, backend, singular_tol)


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
    unit = planar_unit(backend)
    q, qdot, p = _one_state("q", q), _one_state("qdot", qdot), arm.as_array()
    kin = unit.function("arm_kinematics")(q, qdot, p)
    dyn = unit.function("arm_dynamics")(q, qdot, p)
    return {"r": kin["r"], "J": kin["J"], "Jdot_qdot": kin["Jdqd"], "B": dyn["B"], "n": dyn["n"]}


def operational_space(arm: Arm | Robot, q, qdot, *, backend: str = "sympy", singular_tol: float = SINGULAR_TOL,
                      coordinates: str = "twist"):
    """Khatib's operational-space model.

    Planar :class:`Arm`: ``(B_o, n_o)``, ``B_o(r)`` [kg] (2x2) and ``n_o(r, r')`` [N].
    :class:`Robot` (6 or more joints): an :class:`OperationalSpace`. With
    ``coordinates="twist"`` (default), ``B_o = Lambda = (J B^-1 J^T)^-1`` and ``n_o = Jbar^T n -
    Lambda J' q'`` for the twist ``v = (p', w)``, base axes: ``Lambda v' + n_o = F + F_c``. With
    ``coordinates="euler_zyx"``, the paper's ``r = (p, phi)`` with ZYX Euler angles:
    ``B_o(r) = T^T Lambda T``, ``n_o(r, r') = T^T (Lambda T' r' + n_o,twist)``, ``T = diag(I, T_A)``
    and ``T'``, so that ``B_o r'' + n_o = T^T (F + F_c)``.
    """
    if isinstance(arm, Robot):
        return robot_operational_space(arm, q, qdot, singular_tol, coordinates)
    check_arm(arm)
    check_singular_tol("operational_space", singular_tol)
    out = planar_unit(backend).function("operational_space")(
        _one_state("q", q), _one_state("qdot", qdot), arm.as_array(), singular_tol=singular_tol)
    return out["Bo"], out["no"]


def task_frame(surface: Circle | Plane, r, rdot, *, backend: str = "sympy") -> tuple[np.ndarray, np.ndarray]:
    """Task-frame rotation ``R(r)`` (rows: tangent, normal) and its derivative ``R'(r, r')``."""
    kind = check_surface(surface)
    r, rdot = _one_state("r", r), _one_state("rdot", rdot)
    if not (np.isfinite(r).all() and np.isfinite(rdot).all()):  # a plane's frame would not show it
        raise NonFiniteError(f"task_frame: non-finite input r = {r}, rdot = {rdot}")
    out = planar_unit(backend).function(f"task_frame_{kind}")(r, rdot, surface.as_array())
    return out["R"], out["Rd"]


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
    fast, handle, names = robot.fast_terms
    out = fast(handle, -1, q, qdot)
    if out is not None:
        return {_ROBOT_KEYS[n]: v for n, v in zip(names, out)}
    terms = robot.unit.function("robot_terms")
    call = terms.batch if binding.is_batch(q) else terms
    out = call(q, qdot, robot.as_array())
    return {_ROBOT_KEYS[k]: v for k, v in out.items()}


@dataclass(frozen=True)
class OperationalSpace:
    """A robot's operational-space model at one state (see :func:`operational_space`).

    ``B_o`` (6x6) and ``n_o`` (6); in Euler coordinates also ``r = (p, alpha, beta, gamma)``,
    ``rdot``, ``T`` and ``Tdot`` (6x6, ``v = T r'``).
    """

    coordinates: str
    B_o: np.ndarray
    n_o: np.ndarray
    r: np.ndarray | None = None
    rdot: np.ndarray | None = None
    T: np.ndarray | None = None
    Tdot: np.ndarray | None = None


def robot_operational_space(robot: Robot, q, qdot, singular_tol: float, coordinates: str) -> OperationalSpace:
    check_singular_tol("operational_space", singular_tol)
    if coordinates not in ("twist", "euler_zyx"):
        raise HybridError(f"coordinates = {coordinates!r}; give 'twist' or 'euler_zyx'")
    if robot.n < 6:
        raise HybridError(f"the 6-D operational space needs at least 6 joints; this arm has {robot.n}")
    unit = robot.unit
    if coordinates == "twist":
        out = unit.function("operational_space")(q, qdot, robot.as_array(), singular_tol=singular_tol)
        return OperationalSpace("twist", out["Lambda"], out["no"])
    out = unit.function("operational_space_euler")(q, qdot, robot.as_array(), singular_tol=singular_tol)
    return OperationalSpace("euler_zyx", out["Bo"], out["no"], out["r"], out["rd"], out["T"], out["Td"])
