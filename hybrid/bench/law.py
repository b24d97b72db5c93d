"""The paper's arm: its law F* in C (both backends), from Python (one state, batched) and by the
alternatives (plain NumPy, SymPy's lambdify, a CasADi Function, Pinocchio + NumPy); the paper's
experiment end to end, compiled and in NumPy; and regenerating the committed C."""

from __future__ import annotations

import subprocess
import sys
import time
from functools import cached_property
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from hybrid import oracle
from hybrid.bench.harness import c_harness_ns, median_ns
from hybrid.bench.targets import BATCHED, NUMPY_LAW, ONE_STATE, experiment_row, in_c
from hybrid.control.law import decoupling_law
from hybrid.experiments.paper import paper_experiment
from hybrid.geometry.surfaces import Circle
from hybrid.models.planar_arm import paper_arm
from hybrid.native import generator, loader
from hybrid.native.units import planar_unit
from hybrid.simulation.runner import simulate


class PaperLaw:
    """The groups of the paper's arm, each a method adding its rows through ``add``; the arm, its law and
    one state are built by the first group that needs them."""

    def __init__(self, quick: bool, rep: int, add):
        self.quick, self.rep, self.add = quick, rep, add

    @cached_property
    def planar(self) -> SimpleNamespace:
        """The paper's arm, its law and one state."""
        arm, circle = paper_arm(), Circle((0.5, 0.0), 0.2)
        q, qd, a, Fc = (np.array(v) for v in ([2.2, 1.9], [0.3, -0.4], [0.1, 1.0], [-8.0, 3.0]))
        return SimpleNamespace(arm=arm, law=decoupling_law(arm, circle, curvature=True), q=q, qd=qd, a=a, Fc=Fc,
                               p=arm.as_array(), s=circle.cross_section().as_array())

    @cached_property
    def kernel(self):
        """The planar law's generated kernel (SymPy)."""
        return {kk.name: kk for kk in generator.api().planar_kernels(2)}["decoupling_law_circle"]

    def law_in_c(self, b: str) -> None:
        P = self.planar
        values = {"q": P.q, "qd": P.qd, "a": P.a, "Fc": P.Fc, "arm": P.p, "surface": P.s, "opts": [1.0]}
        entry = planar_unit(b).entry("decoupling_law_circle")
        self.add(in_c(b), c_harness_ns(loader.source_dir(), f"hybrid_{b}", entry, values,
                                       200_000 if self.quick else 2_000_000, self.rep))

    def one_state(self) -> None:
        P = self.planar
        self.add(ONE_STATE, median_ns(lambda: P.law(P.q, P.qd, P.a, P.Fc), 20000, self.rep))

    def batched(self) -> None:
        law, N = self.planar.law, 100_000
        rng = np.random.default_rng(0)
        Q = np.column_stack([rng.uniform(-3, 3, N), rng.uniform(0.3, 2.8, N)])
        QD, A, FC = rng.normal(size=(N, 2)), rng.normal(size=(N, 2)), rng.normal(size=(N, 2))
        self.add(BATCHED, median_ns(lambda: law(Q, QD, A, FC), 1, self.rep) / N)

    def numpy_law(self) -> None:
        P = self.planar
        self.add(NUMPY_LAW, median_ns(
            lambda: oracle.decoupling_law("circle", P.q, P.qd, P.a, P.Fc, P.p, P.s, True), 2000, self.rep))

    def lambdified(self) -> None:
        import sympy as sp

        P, kern = self.planar, self.kernel
        fn = sp.lambdify([a.expr for a in kern.inputs], kern.outputs[0].expr, modules="numpy", cse=True)
        col = [v.reshape(-1, 1) for v in (P.q, P.qd, P.a, P.Fc, P.p, P.s, np.array([1.0]))]
        self.add("F* by SymPy lambdify (NumPy, CSE)", median_ns(lambda: fn(*col), 2000, self.rep))

    def casadi_call(self) -> None:
        P = self.planar
        cf = generator.api().kernel_function(self.kernel)
        self.add("F* by a CasADi Function call",
                 median_ns(lambda: cf(P.q, P.qd, P.a, P.Fc, P.p, P.s, 1.0), 2000, self.rep))

    def pinocchio(self) -> None:
        P = self.planar
        pin_ns = _pinocchio_ns(P.arm, P.q, P.qd, P.a, P.Fc, P.s, self.rep)
        if pin_ns is not None:
            self.add("F* by Pinocchio (crba, nle) + NumPy", pin_ns)

    def experiment(self, how: str) -> None:
        """The paper's experiment end to end (``how``: compiled, NumPy), 2 s simulated (0.2 s quick)."""
        dur = 0.2 if self.quick else 2.0
        exp = paper_experiment(duration=dur)
        if how == "compiled":
            self.add(experiment_row(dur, how), median_ns(lambda: simulate(exp), 1, 3 if self.quick else 9) / 1e6,
                     "ms")
        else:
            self.add(experiment_row(dur, how),
                     median_ns(lambda: oracle.simulate(exp), 1, 1 if self.quick else 3) / 1e6, "ms")

    def regenerate(self) -> None:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", "from hybrid.cli.regenerate import expected_files; expected_files()"],
                       check=True, cwd=Path(__file__).resolve().parents[2])
        self.add("regenerate from scratch (both backends, fresh process)", (time.perf_counter() - t0) * 1e3, "ms")


def _pinocchio_ns(arm, q, qd, a, Fc, s, rep):
    try:
        import pinocchio as pin
    except ImportError:
        return None
    model = pin.Model()
    parent = 0
    for i, (L, m, d, inertia) in enumerate([(0.0, arm.m1, arm.d1, arm.I1), (arm.L1, arm.m2, arm.d2, arm.I2)]):
        parent = model.addJoint(parent, pin.JointModelRZ(), pin.SE3(np.eye(3), np.array([L, 0, 0])), f"j{i}")
        model.appendBodyToJoint(parent, pin.Inertia(m, np.array([d, 0, 0]), np.diag([inertia] * 3)),
                                pin.SE3.Identity())
    frame = model.addFrame(pin.Frame("tip", parent, 0, pin.SE3(np.eye(3), np.array([arm.L2, 0, 0])),
                                     pin.FrameType.OP_FRAME))
    data = model.createData()
    V = np.array([arm.V1, arm.V2])

    def law():
        B = pin.crba(model, data, q)
        B = np.triu(B) + np.triu(B, 1).T
        n = pin.nonLinearEffects(model, data, q, qd) + V * qd
        pin.forwardKinematics(model, data, q, qd, np.zeros(2))
        J = pin.computeFrameJacobian(model, data, q, frame, pin.LOCAL_WORLD_ALIGNED)[:2]
        pin.updateFramePlacements(model, data)
        r = data.oMf[frame].translation[:2]
        Jdqd = pin.getFrameClassicalAcceleration(model, data, frame, pin.LOCAL_WORLD_ALIGNED).linear[:2]
        rd = J @ qd
        R, Rd = oracle.frame("circle", r, rd, s)
        Jinv = np.linalg.inv(J)
        Bo = Jinv.T @ B @ Jinv
        return Bo @ R.T @ (a - Rd @ rd) + Jinv.T @ n - Bo @ Jdqd - Fc

    return median_ns(law, 2000, rep)
