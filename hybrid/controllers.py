"""Controllers sampled by the runner: the paper's task-space law and Khatib's 1987 scheme.

Both see only what a real controller sees: joint angles and rates, the sensor's force
``F_c``, the references, and their own model of the arm (``Experiment.controller_arm``).
Both run the same task-frame loops (NOTES section 4); they differ in the contact-force
term of ``F*`` (NOTES section 7): the task law cancels the *measured* ``F_c``, Khatib's
scheme feeds forward the *desired* normal force ``R^T Sigma F_d``.
"""

from __future__ import annotations

import numpy as np

from .experiment import Experiment


class TaskLoops:
    """PI^2 velocity loop on the tangent axis and impedance + integral force loop on the normal.

    Integrals advance once per sample period ``T`` (forward in time, current error included).
    """

    def __init__(self, exp: Experiment):
        g = exp.effective_gains()
        self.g, self.T = g, exp.sample_time
        self.v_ref, self.f_ref = exp.speed_reference, exp.force_reference
        self.int_v = self.int2_v = self.int_f = 0.0

    def __call__(self, t: float, v: np.ndarray, f: np.ndarray) -> tuple[float, float]:
        """Task acceleration ``a = (a_t, a_n)`` from task velocity ``v`` and task force ``f``."""
        g, T = self.g, self.T
        e_v = self.v_ref(t) - v[0]
        self.int_v += T * e_v
        self.int2_v += T * self.int_v
        e_f = self.f_ref(t) - f[1]
        self.int_f += T * e_f
        a_t = g.KPv * e_v + g.KIv * self.int_v + g.KI2v * self.int2_v  # v_d' = 0 between steps
        a_n = -g.KPf * e_f - g.KDf * v[1] - g.KIf * self.int_f
        return a_t, a_n


class HybridController:
    """The sampled controller of an experiment: ``tau = controller(t, q, qdot, Fc)``.

    ``terms`` evaluates the controller's model (compiled C or the NumPy reference):
    ``measure(q, qdot, Fc) -> (r, r', R r', R F_c)`` and ``law(q, qdot, a, Fc) -> tau``.
    """

    def __init__(self, exp: Experiment, terms):
        self.exp, self.terms, self.loops = exp, terms, TaskLoops(exp)
        self.khatib = exp.controller == "khatib"
        self.desired_frame = exp.frame == "desired"
        self.s0 = exp.surface.arc_coordinate(exp.start_point)

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``r_d(t)`` on the surface at the desired speed, and ``r_d'(t)``."""
        surf, vref = self.exp.surface, self.exp.speed_reference
        s = self.s0 + vref.integral(t)
        rd_point = surf.at(s)
        n = surf.normal_at(rd_point)
        return rd_point, vref(t) * np.array([-n[1], n[0]])

    def __call__(self, t: float, q: np.ndarray, qdot: np.ndarray, Fc: np.ndarray) -> np.ndarray:
        r, rdot, v, f = self.terms.measure(q, qdot, Fc)
        if self.desired_frame:
            # loops in the frame R(r_d); the law, which works in R(r), gets a rotated back:
            # R(r)^T a' = R_d^T (a - R_d' r')  with  a' = R(r) R_d^T (a - R_d' r')
            rd_point, rd_vel = self.desired_point(t)
            R_d, Rdot_d = self.terms.frame(rd_point, rd_vel)
            v, f = R_d @ rdot, R_d @ Fc
            a = np.array(self.loops(t, v, f))
            if self.exp.curvature:
                a = a - Rdot_d @ rdot
            R, _ = self.terms.frame(r, rdot)
            a = R @ (R_d.T @ a)
        else:
            R = None
            a = np.array(self.loops(t, v, f))
        if self.khatib:
            if R is None:
                R, _ = self.terms.frame(r, rdot)
            Fc = R[1] * self.exp.force_reference(t)  # R^T Sigma F_d: the desired normal force
        return self.terms.law(q, qdot, a, Fc)
