"""The compiled decoupling law and arm terms against independent oracles (the NumPy oracle, Pinocchio)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import random_arm, random_states, random_surface

import hybrid
from hybrid import oracle
from hybrid.spec.interfaces import PRINTERS

KINDS = ("plane", "circle")
BACKENDS = PRINTERS


def rel_err(x, y):
    return np.linalg.norm(x - y, axis=-1) / np.maximum(np.linalg.norm(y, axis=-1), 1e-12)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("curvature", [False, True])
@pytest.mark.parametrize("elbow", [1, -1])
def test_law_matches_numpy_oracle(rng, backend, kind, curvature, elbow):
    worst = 0.0
    for _ in range(20):  # 20 random arms and surfaces x 100 states
        arm, surface = random_arm(rng), random_surface(rng, kind)
        st = random_states(rng, 100, elbow)
        law = hybrid.decoupling_law(arm, surface, curvature=curvature, backend=backend)
        F, tau = law.evaluate(st["q"], st["qdot"], st["a"], st["Fc"])
        for i in range(100):
            Fr, taur = oracle.decoupling_law(kind, st["q"][i], st["qdot"][i], st["a"][i], st["Fc"][i],
                                          arm.as_array(), surface.cross_section().as_array(), curvature)
            worst = max(worst, rel_err(F[i], Fr), rel_err(tau[i], taur))
        # the single-state path gives the batch's numbers (the batch runs as SIMD lanes: within rounding)
        np.testing.assert_allclose(law(st["q"][0], st["qdot"][0], st["a"][0], st["Fc"][0]), F[0], rtol=1e-12,
                                   atol=1e-12 * np.abs(F[0]).max())
    assert worst < 1e-9, worst


@pytest.mark.parametrize("backend", BACKENDS)
def test_single_state_gives_the_same_numbers_for_any_array_layout(rng, backend):
    """The one-state entry point reads NumPy memory directly; every other layout takes the general path."""
    for kind in KINDS:
        arm, surface = random_arm(rng), random_surface(rng, kind)
        law = hybrid.decoupling_law(arm, surface, curvature=True, backend=backend)
        st = random_states(rng, 1)
        # values exact in float32, so every layout below holds the same numbers
        base = [st[k][0].astype(np.float32).astype(float) for k in ("q", "qdot", "a", "Fc")]
        Fr, taur = oracle.decoupling_law(kind, *base, arm.as_array(), surface.cross_section().as_array(), True)
        F, tau = law(*base), law.torque(*base)
        assert rel_err(F, Fr) < 1e-9 and rel_err(tau, taur) < 1e-9
        both = law.evaluate(*base)
        np.testing.assert_array_equal(both[0], F)
        np.testing.assert_array_equal(both[1], tau)
        layouts = {
            "list": lambda x: x.tolist(),
            "tuple": lambda x: tuple(x),
            "strided": lambda x: np.stack([x, -x], axis=1)[:, 0],
            "big-endian": lambda x: x.astype(">f8"),
            "float32": lambda x: x.astype(np.float32),
            "read-only": lambda x: np.frombuffer(x.tobytes()),
            "column": lambda x: x.reshape(2, 1)[:, 0],
        }
        for name, layout in layouts.items():
            args = [layout(x) for x in base]
            np.testing.assert_array_equal(law(*args), F, err_msg=name)
            np.testing.assert_array_equal(law.torque(*args), tau, err_msg=name)
        # the result is a fresh array each call, never a view of shared memory
        first = law(*base)
        first[:] = 0.0
        np.testing.assert_array_equal(law(*base), F)


def test_backends_agree_on_every_kernel(rng):
    for kind in KINDS:
        arm, surface = random_arm(rng), random_surface(rng, kind)
        st = random_states(rng, 500)
        laws = [hybrid.decoupling_law(arm, surface, curvature=True, backend=b) for b in BACKENDS]
        (F1, t1), (F2, t2) = (law.evaluate(st["q"], st["qdot"], st["a"], st["Fc"]) for law in laws)
        assert rel_err(F1, F2).max() < 1e-12 and rel_err(t1, t2).max() < 1e-12
        for i in range(20):
            terms = [hybrid.arm_terms(arm, st["q"][i], st["qdot"][i], backend=b) for b in BACKENDS]
            for key in terms[0]:
                np.testing.assert_allclose(terms[0][key], terms[1][key], rtol=1e-12, atol=1e-13)
            frames = [hybrid.task_frame(surface, st["a"][i], st["Fc"][i], backend=b) for b in BACKENDS]
            np.testing.assert_allclose(frames[0], frames[1], rtol=1e-12, atol=1e-13)


def test_arm_terms_match_closed_forms(rng):
    for _ in range(50):
        arm = random_arm(rng)
        st = random_states(rng, 1, elbow=rng.choice([-1, 1]))
        q, qd = st["q"][0], st["qdot"][0]
        t = hybrid.arm_terms(arm, q, qd)
        r, J, Jdqd = oracle.kinematics(q, qd, arm.as_array())
        B, n = oracle.dynamics(q, qd, arm.as_array())
        for got, want in ((t["r"], r), (t["J"], J), (t["Jdot_qdot"], Jdqd), (t["B"], B), (t["n"], n)):
            np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(t["B"], arm.inertia_matrix(q[1]), rtol=1e-12)
        Bo, no = hybrid.operational_space(arm, q, qd)
        Bo_ref, no_ref = oracle.operational_space(q, qd, arm.as_array())
        np.testing.assert_allclose(Bo, Bo_ref, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(no, no_ref, rtol=1e-10, atol=1e-10)


def test_jdot_qdot_by_finite_differences(rng):
    h = 1e-6
    for _ in range(50):
        arm = random_arm(rng)
        st = random_states(rng, 1)
        q, qd = st["q"][0], st["qdot"][0]
        J_plus = hybrid.arm_terms(arm, q + h * qd, qd)["J"]
        J_minus = hybrid.arm_terms(arm, q - h * qd, qd)["J"]
        fd = (J_plus - J_minus) / (2 * h) @ qd
        np.testing.assert_allclose(hybrid.arm_terms(arm, q, qd)["Jdot_qdot"], fd, rtol=1e-6, atol=1e-7)


@pytest.mark.parametrize("kind", KINDS)
def test_task_frame_derivative_by_finite_differences(rng, kind):
    h = 1e-6
    for _ in range(50):
        surface = random_surface(rng, kind)
        r = rng.uniform(-1, 1, 2)
        rd = rng.normal(size=2)
        R, Rd = hybrid.task_frame(surface, r, rd)
        fd = (hybrid.task_frame(surface, r + h * rd, rd)[0] - hybrid.task_frame(surface, r - h * rd, rd)[0]) / (2 * h)
        np.testing.assert_allclose(Rd, fd, rtol=1e-5, atol=1e-6)
        np.testing.assert_allclose(R @ R.T, np.eye(2), atol=1e-14)  # a rotation...
        assert np.linalg.det(R) == pytest.approx(-1.0) or np.linalg.det(R) == pytest.approx(1.0)
        section = surface.cross_section()  # the paper's planar surfaces are cylinders and planes along z
        np.testing.assert_allclose(R[1], section.normal_at(r) if kind == "circle" else section.normal,
                                   atol=1e-14)  # ...whose second row is the outward normal


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("curvature", [False, True])
def test_decoupling_identity(rng, kind, curvature):
    """Applying tau to the exact model gives R r'' + R' r' = a (R r'' = a with R' dropped)."""
    for _ in range(200):
        arm, surface = random_arm(rng), random_surface(rng, kind)
        st = {k: v[0] for k, v in random_states(rng, 1, elbow=rng.choice([-1, 1])).items()}
        tau = hybrid.decoupling_law(arm, surface, curvature).torque(st["q"], st["qdot"], st["a"], st["Fc"])
        B, n = oracle.dynamics(st["q"], st["qdot"], arm.as_array())
        r, J, Jdqd = oracle.kinematics(st["q"], st["qdot"], arm.as_array())
        qdd = np.linalg.solve(B, tau + J.T @ st["Fc"] - n)   # the robot in contact
        rdd, rd = J @ qdd + Jdqd, J @ st["qdot"]
        R, Rd = oracle.frame(kind, r, rd, surface.cross_section().as_array())
        ydot = R @ rdd + (Rd @ rd if curvature else 0.0)
        np.testing.assert_allclose(ydot, st["a"], rtol=1e-9, atol=1e-9 * (1 + np.abs(st["a"]).max()))


def test_parameters_are_runtime_inputs():
    """Another arm or surface is another array, not another build."""
    from dataclasses import replace

    from hybrid.native import loader as native

    arm = hybrid.paper_arm()
    before = native.load.cache_info().currsize
    law1 = hybrid.decoupling_law(arm, hybrid.Circle((0.5, 0.0), 0.2))
    law2 = hybrid.decoupling_law(replace(arm, m2=3.85), hybrid.Circle((0.4, 0.1), 0.3))
    assert native.load.cache_info().currsize <= max(before, 1)
    args = ([0.3, 1.2], [0.2, -0.1], [0.1, 0.2], [1.0, 2.0])
    assert not np.allclose(law1(*args), law2(*args))


def test_batched_law_writes_into_the_callers_arrays(rng):
    law = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2), curvature=True)
    s = random_states(rng, 2000)
    F, tau = np.full((2000, 2), np.nan), np.full((2000, 2), np.nan)
    got = law.evaluate(s["q"], s["qdot"], s["a"], s["Fc"], out=(F, tau))
    assert got[0] is F and got[1] is tau
    want = law.evaluate(s["q"], s["qdot"], s["a"], s["Fc"])
    np.testing.assert_array_equal(F, want[0])
    np.testing.assert_array_equal(tau, want[1])
    assert law.torque(s["q"], s["qdot"], s["a"], s["Fc"], out=tau) is tau
    for bad in (np.empty((2000, 3)), np.empty((2, 2000)).T, np.empty((2000, 2), dtype=np.float32), [[0.0, 0.0]]):
        with pytest.raises(hybrid.HybridError, match="out"):
            law(s["q"], s["qdot"], s["a"], s["Fc"], out=bad)
    with pytest.raises(hybrid.HybridError, match="N states"):
        law(s["q"][0], s["qdot"][0], s["a"][0], s["Fc"][0], out=np.empty((1, 2)))


def test_a_batchs_own_arrays_are_apart(rng):
    """The outputs a batch allocates (one block between them) are each its own C-contiguous, writable
    array: writing one changes no other, and a partly given ``out`` leaves the rest as computed."""
    law = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0.0), 0.2), curvature=True)
    s = random_states(rng, 3000)
    F, tau = law.evaluate(s["q"], s["qdot"], s["a"], s["Fc"])
    want_F, want_tau = F.copy(), tau.copy()
    for a in (F, tau):
        assert a.flags.c_contiguous and a.flags.writeable and a.shape == (3000, 2)
    F[:] = np.nan
    np.testing.assert_array_equal(tau, want_tau)
    tau[:] = np.inf
    assert np.isnan(F).all()
    mine = np.empty((3000, 2))
    F2, tau2 = law.evaluate(s["q"], s["qdot"], s["a"], s["Fc"], out=(mine, None))
    assert F2 is mine
    np.testing.assert_array_equal(F2, want_F)
    np.testing.assert_array_equal(tau2, want_tau)


@pytest.mark.parametrize("backend", BACKENDS)
def test_batched_lanes_do_not_depend_on_position_or_split(rng, backend):
    """A batch runs as SIMD lanes (a partly filled last group, a split over the cores): every state
    gets the same numbers wherever it sits, and a singular state among them is the one reported."""
    arm, surface = random_arm(rng), random_surface(rng, "circle")
    law = hybrid.decoupling_law(arm, surface, curvature=True, backend=backend)
    st = random_states(rng, 3001)
    args = [st[k] for k in ("q", "qdot", "a", "Fc")]
    F, tau = law.evaluate(*args)  # over 512 states: split over the cores
    for lo, hi in ((0, 1), (5, 12), (2990, 3001), (1, 3001), (7, 8)):
        part = law.evaluate(*(a[lo:hi] for a in args))
        np.testing.assert_array_equal(part[0], F[lo:hi])
        np.testing.assert_array_equal(part[1], tau[lo:hi])
    q = st["q"][:20].copy()
    q[13, 1] = 0.0  # full extension
    with pytest.raises(hybrid.SingularConfigurationError, match="state 13"):
        law.evaluate(q, *(a[:20] for a in args[1:]))
