"""The decoupling law ``F*(r, r', a)`` of the paper's planar arm, evaluated by the compiled C; and
:func:`decoupling_law`, which builds the law of any arm."""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from hybrid.control.spatial_law import spatial_law
from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Circle, Plane
from hybrid.models.planar_arm import Arm, check_arm
from hybrid.models.robot import Robot
from hybrid.native import binding
from hybrid.native.binding import as_states
from hybrid.native.units import PLANAR_SINGULAR, planar_unit
from hybrid.validate import SINGULAR_TOL, check_singular_tol


def status_error(status: int, where: str, **inputs) -> HybridError:
    """The exception for a planar unit's status code, naming the inputs that caused it."""
    return binding.status_error(status, where, PLANAR_SINGULAR, **inputs)


def check_surface(surface) -> str:
    """The kind of a planar surface (the paper's arm moves in a plane)."""
    if not isinstance(surface, (Circle, Plane)) or surface.dim != 2:
        raise HybridError(f"the planar arm needs a hybrid.Circle or hybrid.Plane in 2-D, got {surface!r:.100}; "
                          "for a 3-D surface use a hybrid.Robot")
    return surface.kind


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
        if backend != "sympy":
            raise HybridError("backend selects the planar units; a Robot's law is always generated by CasADi")
        return spatial_law(arm, surface, curvature, reference=reference, axes=axes, singular_tol=singular_tol)
    return DecouplingLaw(arm, surface, curvature, backend, singular_tol)


