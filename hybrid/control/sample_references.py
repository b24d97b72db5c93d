"""What a :class:`~hybrid.Controller` computes in Python before each sample's compiled step: the references
given as code (``f(t)`` and its ``rate``), a desired path's point (``path(t)``), and a path task's direction and
references (:mod:`hybrid.control.path_task`), with the checks of the joint state they read.

:class:`SampleReferences` is the controller's part that does it; it reads the controller's references
(``_varying``, ``_rates``), its step's per-sample inputs (``_extra``, ``_rate``, ``_target``, ``_z``), its
parameters (``_params``, rebound by ``_bind``), its measurement (``_measure``, ``_estimate``) and settings.
"""

from __future__ import annotations

import numpy as np

from hybrid.control.measurement import padded_vector
from hybrid.control.options import call_user
from hybrid.control.path_task import PathReferences
from hybrid.errors import HybridError, NonFiniteError, TaskFrameError
from hybrid.spec.controller_step import CONTROLLER_STEP
from hybrid.validate import shown

#: the step's parameters, in its order
PARAMETERS = CONTROLLER_STEP.parameters


class SampleReferences:
    """The references a controller computes in Python at each sample (module docstring)."""

    def _python_references(self, t: float) -> None:
        """The references given as code, at ``t``: into the step's ``yd_extra`` and ``yd_rate``."""
        for target, calls, what in ((self._extra, self._varying, "reference"), (self._rate, self._rates, "rate")):
            for i, f in calls:
                name = f"the {self.axis_names[i]} {what}"
                value = call_user(f, t, name)
                if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
                    raise HybridError(f"{name} gave {shown(value, 40)} at t = {t} s; a reference f(t) returns one "
                                      "number (and its rate(t) one number)")
                target[i] = value

    def _measured(self, q, qdot, Fc) -> dict[str, np.ndarray]:
        """The controller's measurement at ``q, qdot`` under the wrench ``Fc`` (its parameters as they stand)."""
        self._check_joint_state(q, qdot)
        p = self.step_inputs()
        return self._measure(q, qdot, Fc, p["surface"], p["e"], p["robot"], p["sensor"], self._estimate)

    def _localize(self, tip: dict[str, np.ndarray]) -> None:
        """A part's surface about the measured ``tip`` (:meth:`_measured`): the step's ``surface`` parameters, its
        second-order expansion there (:meth:`~hybrid.geometry.parts.PartSurface.parameters_at`), so the frame
        and its rate are the part's own at the tip."""
        p = tip["p"].ravel()
        theta = self._spatial.parameters_at(p)
        if not np.isfinite(theta).all():
            raise TaskFrameError(self._spatial.off_band(p))
        theta.flags.writeable = False
        self._params = tuple(theta if name == "surface" else a for name, a in zip(PARAMETERS, self._params))
        self._bind()

    def _follow(self, tip: dict[str, np.ndarray]) -> None:
        """The path task's references for the measured ``tip`` (:meth:`_measured`: its position, rotation and
        wrench); the step's binding follows the parameters it changes (``e``, and at the retreat the normal
        axis's selection and gains, its integrals zero): :meth:`_restore` undoes them, for a sample that is not
        served."""
        changed = self._path_task.write(tip["p"].ravel(), tip["R"].ravel(), tip["contact_wrench"].ravel()[:3],
                                        self.step_inputs(), self._extra, self._rate)
        if not changed:
            return
        # the follower's unit e, and a selection and gains of 0/1 and >= 0: their checks hold
        self._params = tuple(changed.get(name, a) for name, a in zip(PARAMETERS, self._params))
        if "selection" in changed:  # the normal axis turns velocity-controlled: its loop starts afresh
            n = self._path_task.positions[2]
            self._z[2 * n:2 * n + 2] = 0.0
        self._bind()

    def _restore(self, kept: tuple | None) -> None:
        """The step's parameters and integrals as ``kept`` before a sample that is not served (None: nothing
        was kept)."""
        if kept is None:
            return
        params, integrals = kept
        self._z[:] = integrals
        if self._params is not params:
            self._params = params
            self._bind()

    @property
    def path_references(self) -> PathReferences | None:
        """The path task's follower (``.follower``: its table, settings and state) and where ``t1``, ``t2`` and
        ``n`` are among the task axes (``.positions``); None without a path task."""
        return self._path_task

    @property
    def path_task(self) -> dict[str, float] | None:
        """The path task's last sample (the follower's outputs by name: progress ``s``, the path's point, the
        cross-track error, the references), None without a path task."""
        return None if self._path_task is None else self._path_task.last

    def _desired(self, t: float) -> np.ndarray:
        got = call_user(self.path, t, "the path")
        if not isinstance(got, tuple) or len(got) not in (2, 3):
            raise HybridError(f"path({t}) returned {shown(got, 60)}; return (p_d, p_d') or (p_d, p_d', phi_d)")
        d = self._force_size  # a point of the planar arm's plane, or of space
        phi = padded_vector("path angles", got[2], 3) if len(got) == 3 else np.zeros(3)
        return np.concatenate([padded_vector("path point", got[0], d), padded_vector("path velocity", got[1], d), phi])

    def _check_joint_state(self, q, qdot) -> None:
        """Refuse joint positions or velocities that are not one finite number per joint."""
        for name, v in (("q", q), ("qdot", qdot)):
            try:
                arr = np.asarray(v, dtype=float)
            except OverflowError:  # an integer beyond any double
                raise NonFiniteError(f"{name} = {shown(v, 60)} is not finite; give finite joint positions and "
                                     "velocities [rad, rad/s or m, m/s]") from None
            except (TypeError, ValueError):
                arr = None
            if arr is None or arr.shape != (self.robot.n,):
                raise HybridError(f"{name} = {shown(v, 60)}; give {self.robot.n} numbers (one per joint)")
            if not np.isfinite(arr).all():
                raise NonFiniteError(f"{name} = {arr.tolist()} is not finite; give finite joint positions and "
                                     "velocities [rad, rad/s or m, m/s]")
