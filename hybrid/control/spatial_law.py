"""The decoupling law for any serial arm on any surface (NOTES section 9), evaluated by generated C.

``law = decoupling_law(robot, surface)`` builds it; ``law(q, qdot, a, Fc)`` gives ``F*`` (a
wrench in base axes), ``law.torque(q, qdot, a, Fc, tau0)`` the joint torques. The task axes
are rows of ``R = diag(R_L, R_L)``: ``t1, t2, n`` (linear), then rotations about them.
See :mod:`codegen.task_law` for the equations.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from hybrid.errors import HybridError, NonFiniteError
from hybrid.geometry.task_axes import check_axes, reference_direction, spatial_surface
from hybrid.models.robot import Robot
from hybrid.native import units
from hybrid.native.binding import is_batch
from hybrid.validate import check_singular_tol


@dataclass(frozen=True)
class SpatialDecouplingLaw:
    """Compiled decoupling law of ``robot`` on ``surface`` for the task ``axes``.

    ``law(q, qdot, a, Fc)`` gives ``F*`` (6: force [N], moment [N m], base axes);
    ``law.torque(q, qdot, a, Fc, tau0=None)`` gives ``tau`` (n) [N m or N]. ``q``, ``qdot``,
    ``tau0`` have n entries, ``a`` one task acceleration per axis (m/s^2 or rad/s^2, task
    frame), ``Fc`` (6) the measured wrench on the robot at the tip, base axes; or N rows of
    each for N states in one native call. ``tau0`` acts in the task's null space only.
    """

    robot: Robot
    surface: object
    curvature: bool = False
    reference: tuple[float, float, float] = (0.0, 0.0, 1.0)
    axes: tuple[int, ...] | str | None = None
    singular_tol: float = 1e-3

    def __post_init__(self):
        if not isinstance(self.robot, Robot):
            raise HybridError(f"robot must be a hybrid.Robot, got {type(self.robot).__name__}")
        if not isinstance(self.curvature, bool):
            raise HybridError(f"curvature must be True or False, got {self.curvature!r}")
        check_singular_tol("decoupling_law", self.singular_tol)
        init = partial(object.__setattr__, self)
        init("axes", check_axes(self.robot, self.axes))
        init("reference", tuple(reference_direction(self.reference)))
        spatial = spatial_surface(self.surface)
        unit = units.law_unit(self.robot.chain, self.robot.name, spatial.spec(), self.axes)
        init("_law", unit.function("decoupling_law"))
        init("_frame", unit.function("task_frame"))
        init("_params", (self.robot.as_array(), spatial.as_array(), np.array(self.reference),
                         np.array([1.0 if self.curvature else 0.0])))
        init("_zeros", np.zeros(self.robot.n))
        init("_spatial", spatial)
        # one state from NumPy arrays skips cffi's per-array conversion (see hybrid/fastcall.c)
        fast, handle = self._law.fast_bind(5, *self._params, singular_tol=self.singular_tol)
        init("_fast", fast)
        init("_binding", handle)

    def __reduce__(self):
        # the compiled handles do not pickle: a copy is built again from the settings
        return (type(self), (self.robot, self.surface, self.curvature, self.reference, self.axes,
                             self.singular_tol))

    @property
    def m(self) -> int:
        """Number of task axes."""
        return len(self.axes)

    def evaluate(self, q, qdot, a, Fc, tau0=None) -> tuple[np.ndarray, np.ndarray]:
        """``(F*, tau)`` for one state or N states."""
        _finite_tau0(tau0)
        out = self._fast(self._binding, -1, q, qdot, a, Fc, self._zeros if tau0 is None else tau0)
        return self._checked(q, qdot, a, Fc, tau0) if out is None else out

    def _checked(self, q, qdot, a, Fc, tau0) -> tuple[np.ndarray, np.ndarray]:
        """The general path: any array-like input, N states, and the errors that name the cause."""
        batched = is_batch(q)
        if tau0 is None:
            tau0 = np.zeros((len(q), self.robot.n)) if batched else self._zeros
        call = self._law.batch if batched else self._law
        out = call(q, qdot, a, Fc, tau0, *self._params, singular_tol=self.singular_tol)
        return out["F"], out["tau"]

    def __call__(self, q, qdot, a, Fc) -> np.ndarray:
        """``F*`` [N, N m] in base axes."""
        out = self._fast(self._binding, 0, q, qdot, a, Fc, self._zeros)
        return self._checked(q, qdot, a, Fc, None)[0] if out is None else out

    def torque(self, q, qdot, a, Fc, tau0=None) -> np.ndarray:
        """``tau = J^T F* + (I - J^T Jbar^T) tau0`` [N m or N]."""
        _finite_tau0(tau0)
        out = self._fast(self._binding, 1, q, qdot, a, Fc, self._zeros if tau0 is None else tau0)
        return self._checked(q, qdot, a, Fc, tau0)[1] if out is None else out

    def task_frame(self, p, pdot) -> tuple[np.ndarray, np.ndarray]:
        """``R_L`` (rows ``t1, t2, n``) at the point ``p`` [m] and ``R_L'`` [1/s] for its velocity ``pdot``."""
        out = self._frame(p, pdot, self._params[1], self._params[2])
        return out["R"], out["Rd"]


def _finite_tau0(tau0) -> None:
    """A square task ignores ``tau0`` (no null space): a non-finite one must still be refused."""
    if tau0 is None:
        return
    try:
        finite = bool(np.isfinite(np.asarray(tau0, dtype=float)).all())
    except (TypeError, ValueError):
        return  # the shape and type checks name it
    if not finite:
        raise NonFiniteError(f"tau0 = {np.array2string(np.asarray(tau0, float), precision=4):.100} is not finite")


def spatial_law(robot: Robot, surface, curvature: bool = False, *, reference=(0.0, 0.0, 1.0), axes=None,
                singular_tol: float = 1e-3) -> SpatialDecouplingLaw:
    """The general decoupling law of NOTES section 9, compiled for ``robot`` on ``surface``."""
    return SpatialDecouplingLaw(robot, surface, curvature, reference, axes, singular_tol)
