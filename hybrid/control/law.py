r"""The decoupling law :math:`F^*(r, \dot r, a)` of any arm on any surface, evaluated by generated C.

:math:`F^* = \Lambda \left(R^T (a - \dot R v) - \dot J \dot q\right) + \bar J^T n - F_c`, with
:math:`\Lambda = (J B^{-1} J^T)^{-1}` and :math:`\bar J^T = \Lambda J B^{-1}`, makes the task axes'
accelerations :math:`\dot y = R \dot v + \dot R v` equal the commanded :math:`a`; the joint torques are
:math:`\tau = J^T F^* + (I - J^T \bar J^T)\, \tau_0`, a redundant arm's :math:`\tau_0` acting in the task's
null space only. One :class:`DecouplingLaw` serves every
arm, from one of two derivations of the same equations:

- ``backend="rigid_body"``: the recursive rigid-body algorithms (CasADi), generated for the
  robot's kinematic structure, the surface and the task axes: ``F*`` is the wrench
  ``(f, m)`` [N, N m] in base axes, ``F_c`` the measured wrench at the tip;
- ``backend="sympy"`` or ``"casadi"``: the paper's planar arm in closed form (its committed
  units, printed by SymPy or by CasADi from one SymPy derivation), for a robot with a
  ``closed_form`` on a planar surface with the planar task axes ``(t1, n)``: ``F*`` and ``F_c`` are
  the force in the arm's plane [N].

By default the closed form runs where it applies, the rigid-body derivation everywhere else.
Parameters (inertias, the surface's) are run-time inputs: another arm of the same structure, or
another surface of the same kind, needs no recompilation.
"""

from __future__ import annotations

from functools import partial

import numpy as np

from hybrid.deprecation import renamed_attribute, renamed_keywords
from hybrid.errors import HybridError, NonFiniteError
from hybrid.geometry.frames import task_frame
from hybrid.geometry.surfaces import Surface
from hybrid.geometry.task_axes import check_axes, frame_direction_of, spatial_surface
from hybrid.models.planar_arm import Arm
from hybrid.models.robot import Robot, as_robot
from hybrid.native import units
from hybrid.native.binding import is_batch
from hybrid.spec.interfaces import PRINTERS
from hybrid.validate import SINGULAR_TOL, check_singular_tol, check_size, checked_keywords, shown

#: the derivations a law can run: the rigid-body algorithms, or the planar arm's committed closed form
BACKENDS = ("rigid_body", *PRINTERS)


@checked_keywords
class DecouplingLaw:
    """The compiled decoupling law of ``robot`` on ``surface`` for the task ``axes``.

    ``law(q, qdot, a, Fc)`` gives ``F*``, ``law.torque(q, qdot, a, Fc, tau0=None)`` the joint
    torques [N m or N], ``law.evaluate(...)`` both. ``q`` [rad or m] and ``qdot`` have one entry per
    joint, ``a`` one task acceleration per axis [m/s^2 or rad/s^2, task frame], ``Fc`` the measured
    contact wrench on the robot (``wrench_size`` entries, base axes); or N rows of each for N states
    in one native call (``out=`` then takes the caller's arrays). Its settings are read-only: the
    compiled entry point is bound to them. :func:`decoupling_law` builds one.

    Parameters
    ----------
    robot : Robot or Arm
        The arm (the paper's planar arm's parameters stand for that arm).
    surface : Surface
        The surface the tool slides on.
    curvature : bool
        Include ``R' v`` (the paper runs without it).
    frame_direction : array_like
        The task frame's direction ``e`` (base axes).
    axes : str or sequence of int or None
        The task axes (see :func:`decoupling_law`); None: the robot's default.
    backend : str or None
        ``"rigid_body"``, or the planar closed form's ``"sympy"`` / ``"casadi"``; None: the closed
        form where it applies.
    singular_tol : float
        The smallest distance from singularity accepted.

    Raises
    ------
    HybridError
        A setting refused: an unknown backend, a closed form where it does not apply, task axes the
        arm cannot control.
    NativeBuildError
        The generated C could not be compiled.

    Examples
    --------
    >>> import hybrid
    >>> disc = hybrid.Circle((0.5, 0.0), 0.2)
    >>> law = hybrid.DecouplingLaw(hybrid.paper_arm(), disc)
    >>> law.backend, law.axes, law.wrench_size
    ('sympy', (0, 2), 2)
    >>> q, qdot, a, Fc = [0.3, 1.2], [0.0, 0.0], [0.0, 1.0], [0, 0]
    >>> force, torque = law.evaluate(q, qdot, a, Fc)
    >>> force.shape, torque.shape
    ((2,), (2,))
    """

    __slots__ = ("robot", "surface", "curvature", "frame_direction", "axes", "backend", "singular_tol", "_fn",
                 "_params", "_tail", "_fast", "_binding", "_force")

    @renamed_keywords(reference="frame_direction")
    def __init__(self, robot: Robot | Arm, surface: Surface, curvature: bool = False,
                 frame_direction=(0.0, 0.0, 1.0), axes=None, backend: str | None = None,
                 singular_tol: float = SINGULAR_TOL):
        init = partial(object.__setattr__, self)
        if isinstance(robot, Arm):  # the paper's parameters stand for its arm, in closed form
            if not (isinstance(surface, Surface) and surface.cross_section() is not None):
                raise HybridError(f"the planar arm needs a hybrid.Circle or hybrid.Plane in 2-D, got "
                                  f"{shown(surface, 100)}; for another surface use a hybrid.Robot")
        robot = as_robot(robot)
        if not isinstance(curvature, bool):
            raise HybridError(f"curvature must be True or False, got {shown(curvature)}")
        check_singular_tol("decoupling_law", singular_tol)
        init("robot", robot)
        init("surface", surface)
        init("curvature", curvature)
        init("singular_tol", float(singular_tol))
        init("frame_direction", tuple(frame_direction_of(frame_direction)))
        init("axes", check_axes(robot, axes))
        section = robot.kind.closed_form_section(surface, self.axes, self.frame_direction)
        closed = section is not None
        backend = backend if backend is not None else ("sympy" if closed else "rigid_body")
        if backend not in BACKENDS:
            raise HybridError(f"backend must be one of {', '.join(BACKENDS)}, got {shown(backend, 40)}")
        if backend != "rigid_body" and not closed:
            raise HybridError(f"backend {backend!r} is the paper's planar arm in closed form: it needs "
                              "hybrid.Robot.planar(arm) (or a hybrid.Arm) on a hybrid.Circle or a 2-D hybrid.Plane, "
                              "planar task axes and frame_direction (0, 0, 1); use backend='rigid_body'")
        init("backend", backend)
        if backend == "rigid_body":
            spatial = spatial_surface(surface)
            fn = units.law_unit(robot.chain, robot.name, spatial.spec(), self.axes).function("decoupling_law")
            params = (robot.as_array(), spatial.as_array(), np.array(self.frame_direction))
            tail = (np.zeros(robot.n),)  # tau0
        else:
            fn = units.planar_unit(backend).function(f"decoupling_law_{section.kind}")
            params, tail = (robot.kind.arm.as_array(), section.as_array()), ()
        init("_fn", fn)
        init("_params", (*params, np.array([1.0 if curvature else 0.0])))
        init("_tail", tail)
        # one state from NumPy arrays skips cffi's per-array conversion (see hybrid/native/fastcall.c)
        fast, handle = fn.fast_bind(4 + len(tail), *self._params, singular_tol=self.singular_tol)
        init("_fast", fast)
        init("_binding", handle)
        # F* alone, a call of the four states' arrays: tau0 (which F* does not read) fixed with the parameters
        init("_force", partial(fast, fn.fast_bind(4, *tail, *self._params, singular_tol=self.singular_tol)[1], 0))

    def __setattr__(self, name, value):
        raise AttributeError(f"a DecouplingLaw's settings are read-only; build another law to change {name}")

    def __repr__(self) -> str:
        return (f"DecouplingLaw(robot={self.robot.name!r}, surface={self.surface!r}, curvature={self.curvature}, "
                f"frame_direction={self.frame_direction}, axes={self.axes}, backend={self.backend!r}, "
                f"singular_tol={self.singular_tol})")

    def __reduce__(self):
        # the compiled handles do not pickle: a copy is built again from the settings
        return (type(self), (self.robot, self.surface, self.curvature, self.frame_direction, self.axes, self.backend,
                             self.singular_tol))

    #: deprecated: :attr:`frame_direction`
    reference = renamed_attribute("reference", "frame_direction")

    @property
    def arm(self) -> Arm | None:
        """The planar arm's parameters (its closed form), or None."""
        return self.robot.kind.arm

    @property
    def m(self) -> int:
        """Number of task axes."""
        return len(self.axes)

    @property
    def wrench_size(self) -> int:
        """Entries of ``F_c`` and ``F*``: 6 (force and moment, base axes), or 2 for the closed form (the
        force in the arm's plane)."""
        return 6 if self.backend == "rigid_body" else 2

    def evaluate(self, q, qdot, a, Fc, tau0=None, out: tuple | None = None) -> tuple[np.ndarray, np.ndarray]:
        """``(F*, tau)`` for one state or N states.

        Parameters
        ----------
        q : array_like
            Joint positions [rad or m], one per joint (or N rows).
        qdot : array_like
            Joint velocities [rad/s or m/s].
        a : array_like
            The commanded task accelerations, one per axis [m/s^2 or rad/s^2, task frame].
        Fc : array_like
            The measured contact wrench on the robot (``wrench_size`` entries, base axes).
        tau0 : array_like or None
            A redundant arm's null-space torque (one per joint); None: 0.
        out : tuple of numpy.ndarray or None
            For N states, ``(F, tau)``: the caller's arrays to write (either may be None).

        Returns
        -------
        F : numpy.ndarray
            ``F*`` in base axes.
        tau : numpy.ndarray
            The joint torques [N m or N].
        """
        if out is not None:
            if not isinstance(out, (tuple, list)) or len(out) != 2:
                raise HybridError("out must be (F, tau): two arrays of shape (N, size), either may be None")
            return self._checked(q, qdot, a, Fc, tau0, dict(zip(("F", "tau"), out)))
        got = self._fast(self._binding, -1, q, qdot, a, Fc, *self._held(tau0))
        return self._checked(q, qdot, a, Fc, tau0) if got is None else got

    def __call__(self, q, qdot, a, Fc, out: np.ndarray | None = None) -> np.ndarray:
        """``F*`` in base axes.

        Parameters
        ----------
        q : array_like
            Joint positions [rad or m], one per joint (or N rows).
        qdot : array_like
            Joint velocities [rad/s or m/s].
        a : array_like
            The commanded task accelerations, one per axis [m/s^2 or rad/s^2, task frame].
        Fc : array_like
            The measured contact wrench on the robot (``wrench_size`` entries, base axes).
        out : numpy.ndarray or None
            For N states, the caller's array to write.

        Returns
        -------
        numpy.ndarray
            ``F*`` (``wrench_size`` entries, or N rows of them).
        """
        if out is None:
            got = self._force(q, qdot, a, Fc)
            if got is not None:
                return got
            return self._checked(q, qdot, a, Fc, None)[0]
        return self._checked(q, qdot, a, Fc, None, {"F": out})[0]

    def torque(self, q, qdot, a, Fc, tau0=None, out: np.ndarray | None = None) -> np.ndarray:
        """The joint torques ``tau = J^T F* + (I - J^T Jbar^T) tau0``.

        Parameters
        ----------
        q : array_like
            Joint positions [rad or m], one per joint (or N rows).
        qdot : array_like
            Joint velocities [rad/s or m/s].
        a : array_like
            The commanded task accelerations, one per axis [m/s^2 or rad/s^2, task frame].
        Fc : array_like
            The measured contact wrench on the robot (``wrench_size`` entries, base axes).
        tau0 : array_like or None
            A redundant arm's null-space torque (one per joint); None: 0.
        out : numpy.ndarray or None
            For N states, the caller's array to write.

        Returns
        -------
        numpy.ndarray
            ``tau`` [N m or N], one per joint (or N rows).
        """
        if out is not None:
            return self._checked(q, qdot, a, Fc, tau0, {"tau": out})[1]
        got = self._fast(self._binding, 1, q, qdot, a, Fc, *self._held(tau0))
        return self._checked(q, qdot, a, Fc, tau0)[1] if got is None else got

    def task_frame(self, p, pdot) -> tuple[np.ndarray, np.ndarray]:
        """The task frame at a point of the law's surface (see :func:`hybrid.task_frame`).

        Parameters
        ----------
        p : array_like
            The point [m].
        pdot : array_like
            Its velocity [m/s].

        Returns
        -------
        R : numpy.ndarray
            The task frame.
        Rdot : numpy.ndarray
            Its rate.
        """
        return task_frame(self.surface, p, pdot, frame_direction=self.frame_direction)

    def _held(self, tau0) -> tuple:
        """The inputs after ``Fc``: the null-space torque where the law takes one."""
        if tau0 is None:
            return self._tail
        if not self._tail:
            raise HybridError("tau0: the planar closed form has no null space (2 joints, 2 task axes); leave it out")
        _finite_tau0(tau0)
        return (tau0,)

    def _checked(self, q, qdot, a, Fc, tau0, out: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The general path: any array-like input, N states, caller-supplied outputs, and the errors
        that name the cause."""
        held = self._held(tau0)
        batched = is_batch(q)
        if held and batched and tau0 is None:
            # a view: the batch checks its size before copying it
            held = (np.broadcast_to(np.zeros(self.robot.n), (len(np.asarray(q)), self.robot.n)),)
        out = {k: v for k, v in (out or {}).items() if v is not None}
        if not batched:
            if out:
                raise HybridError("out= is for N states (arrays of shape (N, size)); one state returns new arrays")
            got = self._fn(q, qdot, a, Fc, *held, *self._params, singular_tol=self.singular_tol)
        else:  # the manifest's sizes and the rows of every state input are checked there
            got = self._fn.batch(q, qdot, a, Fc, *held, *self._params, singular_tol=self.singular_tol, out=out)
        return got["F"], got["tau"]


def _finite_tau0(tau0) -> None:
    """A square task ignores ``tau0`` (no null space): a non-finite one must still be refused."""
    if isinstance(tau0, np.ndarray) and tau0.ndim == 2:  # the check's own arrays are sized by the states
        check_size(f"{len(tau0):,} states of tau0 (shape {tau0.shape}) need", 9 * tau0.size,
                   "pass fewer states at a time (in chunks)")
    try:
        finite = bool(np.isfinite(np.asarray(tau0, dtype=float)).all())
    except (TypeError, ValueError):
        return  # the shape and type checks name it
    if not finite:
        raise NonFiniteError(f"tau0 = {np.array2string(np.asarray(tau0, float), precision=4):.100} is not finite")


@checked_keywords
@renamed_keywords(reference="frame_direction")
def decoupling_law(robot: Robot | Arm, surface: Surface, curvature: bool = False, *, backend: str | None = None,
                   singular_tol: float = SINGULAR_TOL, frame_direction=(0.0, 0.0, 1.0), axes=None) -> DecouplingLaw:
    """The decoupling law of ``robot`` on ``surface``, compiled (see :class:`DecouplingLaw`).

    Parameters
    ----------
    robot : Robot or Arm
        The arm (the paper's planar arm's parameters stand for that arm).
    surface : Surface
        The surface the tool slides on.
    curvature : bool
        Include ``R' v`` (the paper runs without it).
    backend : str or None
        The derivation: ``"rigid_body"``, or the planar closed form's ``"sympy"`` / ``"casadi"``;
        None (default): the closed form where it applies.
    singular_tol : float
        The smallest distance from singularity accepted.
    frame_direction : array_like
        The task frame's direction ``e`` (base axes).
    axes : str or sequence of int or None
        The task axes: ``"all"`` (the default for a 6-joint arm or more), ``"position"``,
        ``"planar"`` (the paper's ``(t1, n)``, the default of its arm) or indices 0-5 of ``t1, t2, n``
        and the rotations about them.

    Returns
    -------
    DecouplingLaw
        The compiled law.

    Raises
    ------
    HybridError
        A setting refused (see :class:`DecouplingLaw`).

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> disc = hybrid.Circle((0.5, 0.0), 0.2)
    >>> law = hybrid.decoupling_law(hybrid.paper_arm(), disc)
    >>> q = np.tile([0.3, 1.2], (4, 1))  # four states in one call
    >>> zeros = np.zeros((4, 2))
    >>> law.torque(q, zeros, zeros, zeros).shape
    (4, 2)
    """
    return DecouplingLaw(robot, surface, curvature, frame_direction, axes, backend, singular_tol)
