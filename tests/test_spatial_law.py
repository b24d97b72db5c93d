"""The general (6-D) decoupling law of conventions §9 against Pinocchio + NumPy, finite differences and physics."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import pinocchio_terms, well_conditioned_states

import hybrid
from hybrid import oracle
from hybrid.native import units

pin = pytest.importorskip("pinocchio")

SURFACES = {
    "plane": hybrid.Plane((0.3, 0.1, 0.2), (0.2, -0.3, 1.0)),
    "sphere": hybrid.Sphere((0.4, 0.1, 0.3), 0.15),
    "cylinder": hybrid.Cylinder((0.3, -0.2, 0.1), (0.2, 1.0, 0.4), 0.12),
    "ellipsoid": hybrid.ImplicitSurface("(x - x0)**2/a**2 + (y/b)**2 + (z - z0)**2/c**2 - 1",
                                        {"x0": 0.4, "z0": 0.3, "a": 0.25, "b": 0.2, "c": 0.15}),
    "torus": hybrid.ImplicitSurface("(sqrt(x**2 + y**2) - R)**2 + (z - h)**2 - r**2", {"R": 0.4, "r": 0.1, "h": 0.3}),
}


@pytest.mark.parametrize("surface", list(SURFACES), ids=list(SURFACES))
@pytest.mark.parametrize("key", ["ur5", "panda"])
def test_law_matches_numpy_oracle_on_pinocchio_terms(rng, robots, key, surface):
    robot, model, fid = robots[key]
    surf = SURFACES[surface]
    states = well_conditioned_states(rng, robot, model, fid, surf, 500)
    q = np.array([s[0] for s in states])
    qd = np.array([s[1] for s in states])
    a, Fc = rng.normal(0, 2, (len(q), 6)), rng.normal(0, 10, (len(q), 6))
    tau0 = rng.normal(0, 3, (len(q), robot.n))
    for curvature in (False, True):
        law = hybrid.decoupling_law(robot, surf, curvature=curvature)
        F, tau = law.evaluate(q, qd, a, Fc, tau0)
        for i, (_, qdi, (J, Jdqd, B, n, p)) in enumerate(states):
            R, Rd = oracle.spatial_frame(surf, p, J[:3] @ qdi, (0, 0, 1))
            F_ref, tau_ref = oracle.spatial_decoupling_law(J, Jdqd, B, n, R, Rd, qdi, a[i], Fc[i], tau0[i],
                                                        range(6), curvature)
            np.testing.assert_allclose(F[i], F_ref, rtol=1e-9, atol=1e-9 * np.abs(F_ref).max())
            np.testing.assert_allclose(tau[i], tau_ref, rtol=1e-9, atol=1e-9 * np.abs(tau_ref).max())


@pytest.mark.parametrize("key", ["ur5", "panda"])
def test_decoupling_identity_in_pinocchio_forward_dynamics(rng, robots, key):
    """Apply tau and the wrench F_c to Pinocchio's arm: R v' + R' v = a, whatever tau0."""
    robot, model, fid = robots[key]
    surf = SURFACES["sphere"]
    law = hybrid.decoupling_law(robot, surf, curvature=True)
    data = model.createData()
    damping = np.array(robot.damping)
    worst = 0.0
    for q, qd, (J, Jdqd, _, _, p) in well_conditioned_states(rng, robot, model, fid, surf, 100):
        a, Fc = rng.normal(0, 2, 6), rng.normal(0, 10, 6)
        tau0 = rng.normal(0, 5, robot.n) if key == "panda" else None
        tau = law.torque(q, qd, a, Fc, tau0)
        qdd = pin.aba(model, data, q, qd, tau + J.T @ Fc - damping * qd)
        v, vdot = J @ qd, J @ qdd + Jdqd
        R, Rd = oracle.spatial_frame(surf, p, v[:3], (0, 0, 1))
        Z = np.zeros((3, 3))
        R6, Rd6 = np.block([[R, Z], [Z, R]]), np.block([[Rd, Z], [Z, Rd]])
        y_dot = R6 @ vdot + Rd6 @ v
        worst = max(worst, np.abs(y_dot - a).max() / max(1.0, np.abs(a).max()))
    assert worst < 1e-8


def test_null_space_torque_does_not_disturb_the_task(rng, robots):
    robot, model, fid = robots["panda"]
    law = hybrid.decoupling_law(robot, SURFACES["plane"])
    q, qd, (J, *_) = well_conditioned_states(rng, robot, model, fid, SURFACES["plane"], 1)[0]
    a, Fc, tau0 = rng.normal(size=6), rng.normal(size=6), rng.normal(0, 5, robot.n)
    t0, t1 = law.torque(q, qd, a, Fc), law.torque(q, qd, a, Fc, tau0)
    B = pinocchio_terms(model, fid, q, qd, 0 * qd)[2]
    assert np.linalg.norm(t1 - t0) > 1.0                              # tau0 does act ...
    np.testing.assert_allclose(J @ np.linalg.solve(B, t1 - t0), 0, atol=1e-10)   # ... but not on the task
    np.testing.assert_array_equal(law(q, qd, a, Fc), law.evaluate(q, qd, a, Fc, tau0)[0])


@pytest.mark.parametrize("surface", list(SURFACES), ids=list(SURFACES))
def test_task_frame_derivative_by_finite_differences(rng, robots, surface):
    robot = robots["ur5"][0]
    surf = SURFACES[surface]
    law = hybrid.decoupling_law(robot, surf)
    h = 1e-6
    for _ in range(30):
        p, pd = rng.uniform(-0.6, 0.6, 3), rng.normal(0, 0.5, 3)
        R, Rd = law.task_frame(p, pd)
        fd = (law.task_frame(p + h * pd, pd)[0] - law.task_frame(p - h * pd, pd)[0]) / (2 * h)
        np.testing.assert_allclose(Rd, fd, atol=1e-6 * max(1.0, np.abs(Rd).max()))
        np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
        assert np.linalg.det(R) == pytest.approx(1.0)
        np.testing.assert_allclose(R[2], surf.normal_at(p), atol=1e-12)   # third row: the normal
        np.testing.assert_allclose(R[0], np.cross((0, 0, 1), R[2]) / np.linalg.norm(np.cross((0, 0, 1), R[2])),
                                   atol=1e-12)


def test_planar_arm_through_the_general_pipeline_equals_the_planar_law(rng):
    """The two derivations of one law: the closed form (SymPy, from the kinetic energy) and the
    recursive rigid-body algorithms (CasADi, from the chain)."""
    arm = hybrid.paper_arm()
    robot = hybrid.Robot.planar(arm)
    for surf in (hybrid.Circle((0.5, 0.0), 0.2), hybrid.Plane((0.4, 0.0), (-1.0, 0.3))):
        for curvature in (False, True):
            planar = hybrid.decoupling_law(robot, surf, curvature=curvature)
            assert planar.backend == "sympy" and planar.wrench_size == 2  # the closed form where it applies
            general = hybrid.decoupling_law(robot, surf, curvature=curvature, backend="rigid_body")
            assert general.wrench_size == 6
            q = np.column_stack([rng.uniform(-np.pi, np.pi, 500), rng.uniform(0.3, np.pi - 0.3, 500)])
            qd, a, Fc2 = rng.normal(0, 1, (500, 2)), rng.normal(0, 2, (500, 2)), rng.normal(0, 10, (500, 2))
            Fc = np.column_stack([Fc2, np.zeros((500, 4))])
            F1, tau1 = planar.evaluate(q, qd, a, Fc2)
            F2, tau2 = general.evaluate(q, qd, a, Fc)
            np.testing.assert_allclose(F2[:, :2], F1, rtol=1e-12, atol=1e-12 * np.abs(F1).max())
            np.testing.assert_allclose(tau2, tau1, rtol=1e-12, atol=1e-12 * np.abs(tau1).max())
            assert np.abs(F2[:, 2:]).max() == 0.0


def test_position_only_task(rng, robots):
    """Three linear task axes on the UR5: the linear rows of y' = a hold, tau0 acts in the null space."""
    robot, model, fid = robots["ur5"]
    law = hybrid.decoupling_law(robot, SURFACES["sphere"], curvature=True, axes="position")
    assert law.m == 3
    data = model.createData()
    for q, qd, (J, Jdqd, _, _, p) in well_conditioned_states(rng, robot, model, fid, SURFACES["sphere"], 20):
        a, Fc, tau0 = rng.normal(size=3), rng.normal(0, 5, 6), rng.normal(0, 2, 6)
        tau = law.torque(q, qd, a, Fc, tau0)
        qdd = pin.aba(model, data, q, qd, tau + J.T @ Fc - np.array(robot.damping) * qd)
        v, vdot = J @ qd, J @ qdd + Jdqd
        R, Rd = oracle.spatial_frame(SURFACES["sphere"], p, v[:3], (0, 0, 1))
        np.testing.assert_allclose(R @ vdot[:3] + Rd @ v[:3], a, atol=1e-8)


def test_operational_space_twist_and_euler(rng, robots):
    robot, model, fid = robots["ur5"]
    for q, qd, (J, Jdqd, B, n, _) in well_conditioned_states(rng, robot, model, fid, SURFACES["plane"], 20):
        tw = hybrid.operational_space(robot, q, qd)
        Lam = np.linalg.inv(J @ np.linalg.solve(B, J.T))
        np.testing.assert_allclose(tw.B_o, Lam, rtol=1e-9, atol=1e-9 * np.abs(Lam).max())
        mu = Lam @ J @ np.linalg.solve(B, n) - Lam @ Jdqd
        np.testing.assert_allclose(tw.n_o, mu, rtol=1e-9, atol=1e-9 * np.abs(mu).max())
        eu = hybrid.operational_space(robot, q, qd, coordinates="euler_zyx")
        Tinv = np.linalg.inv(eu.T)
        np.testing.assert_allclose(Tinv.T @ eu.B_o @ Tinv, Lam, rtol=1e-9, atol=1e-9 * np.abs(Lam).max())  # Bbar_o
        # the angles reproduce the tip rotation, and w = T_A phi'
        alpha, beta, gamma = eu.r[3:]
        rot = hybrid.arm_terms(robot, q, qd)["rotation"]
        Rz = np.array([[np.cos(alpha), -np.sin(alpha), 0], [np.sin(alpha), np.cos(alpha), 0], [0, 0, 1]])
        Ry = np.array([[np.cos(beta), 0, np.sin(beta)], [0, 1, 0], [-np.sin(beta), 0, np.cos(beta)]])
        Rx = np.array([[1, 0, 0], [0, np.cos(gamma), -np.sin(gamma)], [0, np.sin(gamma), np.cos(gamma)]])
        np.testing.assert_allclose(Rz @ Ry @ Rx, rot, atol=1e-12)
        np.testing.assert_allclose(eu.T @ eu.rdot, J @ qd, atol=1e-12)
        # T_A by finite differences of the rotation: w^ = R' R^T along phi'
        h = 1e-6
        qp, qm = q + h * qd, q - h * qd
        Rp, Rm = (hybrid.arm_terms(robot, x, qd)["rotation"] for x in (qp, qm))
        W = (Rp - Rm) / (2 * h) @ rot.T
        np.testing.assert_allclose([W[2, 1], W[0, 2], W[1, 0]], eu.T[3:, 3:] @ eu.rdot[3:], atol=1e-7)
        # T' by finite differences of T along the motion
        Tp = hybrid.operational_space(robot, qp, qd, coordinates="euler_zyx").T
        Tm = hybrid.operational_space(robot, qm, qd, coordinates="euler_zyx").T
        np.testing.assert_allclose(eu.Tdot, (Tp - Tm) / (2 * h), atol=1e-6)
        # B_o r'' + n_o = T^T F for the same motion as Lambda v' + mu = F
        F = rng.normal(size=6)
        vdot = np.linalg.solve(Lam, F - mu)
        rdd = np.linalg.solve(eu.T, vdot - eu.Tdot @ eu.rdot)
        np.testing.assert_allclose(eu.B_o @ rdd + eu.n_o, eu.T.T @ F, atol=1e-9 * max(1, np.abs(F).max()))


def test_every_output_element_is_written(rng, robots):
    """Outputs pre-filled with NaN come back finite: no element is left to the caller's garbage."""
    robot, model, fid = robots["ur5"]
    law = hybrid.decoupling_law(robot, SURFACES["torus"], curvature=True)
    q, qd, _ = well_conditioned_states(rng, robot, model, fid, SURFACES["torus"], 1)[0]
    values = {"q": q, "qd": qd, "qdd": rng.normal(size=6), "tau": rng.normal(size=6), "tau0": rng.normal(size=6),
              "a": rng.normal(size=6), "Fc": rng.normal(size=6), "robot": robot.as_array(),
              "surface": SURFACES["torus"].as_array(), "e": np.array([0.0, 0.0, 1.0]), "opts": np.ones(1),
              "p": np.array([0.5, 0.1, 0.35]), "pd": rng.normal(size=3)}
    functions = [robot.unit.function(f["name"]) for f in robot.unit.manifest["functions"]]
    functions += [law._fn, units.frame_unit(SURFACES["torus"].spec()).function("task_frame")]
    for fn in functions:
        ins = [np.ascontiguousarray(values[name], dtype=float) for name, _ in fn.inputs]
        outs = [np.full(size, np.nan) for _, size, _ in fn.outputs]
        assert fn.into(*ins, *outs, singular_tol=1e-6) == 0, fn.name
        assert all(np.isfinite(o).all() for o in outs), fn.name


def test_the_six_d_example_runs():
    import re
    from pathlib import Path

    page = Path(__file__).resolve().parent.parent / "docs" / "reference" / "arms_and_law.md"
    blocks = re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)
    block = next(b for b in blocks if "hybrid.decoupling_law(ur5" in b)
    ns: dict = {}
    exec(compile(block, str(page), "exec"), ns)
    terms = hybrid.arm_terms(ns["ur5"], ns["q"], ns["qdot"])
    np.testing.assert_allclose(ns["tau"], terms["J"].T @ ns["F"], rtol=1e-10, atol=1e-10)
    assert ns["position_only"].m == 3 and ns["paper"].m == 2
    np.testing.assert_allclose(ns["R"] @ ns["R"].T, np.eye(3), atol=1e-12)
    np.testing.assert_allclose(ns["euler"].B_o, ns["euler"].T.T @ ns["ops"].B_o @ ns["euler"].T, rtol=1e-10)


@pytest.mark.parametrize("key", ["ur5", "panda"])
def test_batched_lanes_do_not_depend_on_position_or_split(rng, robots, key):
    """A 6-D batch runs as SIMD lanes (a partly filled last group, a split over the cores): every state
    gets bitwise the same numbers wherever it sits, within rounding of its one-state call; a failing
    state among them is the one reported."""
    robot, model, fid = robots[key]
    law = hybrid.decoupling_law(robot, SURFACES["sphere"], curvature=True)
    N = 1501
    # around a pose well away from the wrist, elbow and shoulder singularities of both arms
    q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2, 0.5][:robot.n]) + rng.normal(0, 0.1, (N, robot.n))
    args = [q, rng.normal(0, 0.5, (N, robot.n)), rng.normal(size=(N, 6)), rng.normal(0, 5, (N, 6)),
            rng.normal(0, 2, (N, robot.n))]
    F, tau = law.evaluate(*args)
    for lo, hi in ((0, 1), (5, 12), (N - 11, N), (1, N), (7, 8)):
        part = law.evaluate(*(a[lo:hi] for a in args))
        np.testing.assert_array_equal(part[0], F[lo:hi])
        np.testing.assert_array_equal(part[1], tau[lo:hi])
    for i in (0, 9, N - 1):
        one = law.evaluate(*(a[i] for a in args))
        np.testing.assert_allclose(one[0], F[i], rtol=1e-11, atol=1e-11 * np.abs(F[i]).max())
        np.testing.assert_allclose(one[1], tau[i], rtol=1e-11, atol=1e-11 * np.abs(tau[i]).max())
    singular = [a[:20].copy() for a in args]
    singular[0][13] = 0.0  # every joint at zero: a singular pose (the Panda's gives NaN before its measure)
    with pytest.raises((hybrid.SingularConfigurationError, hybrid.NonFiniteError), match="state 13 of 20"):
        law.evaluate(*singular)


@pytest.mark.parametrize("key", ["ur5", "panda"])
def test_the_conditioning_guard_trips_where_the_singular_values_say(rng, robots, key):
    """The guard's measure ``6 / (|J|_F |J^+|_F)`` against NumPy's singular values, on states from well
    conditioned to near a rank loss: a tolerance just above the measure refuses the state, one just
    below accepts it; at an exact rank loss the law is refused as singular, not as non-finite."""
    robot, model, fid = robots[key]
    surf = SURFACES["sphere"]
    stretched = np.zeros(robot.n)  # every joint at 0: both arms' elbows straight, a rank loss
    checked = []
    while len(checked) < 40:
        q = rng.uniform(robot.limits.lower, robot.limits.upper) * rng.choice([1.0, 1e-2, 1e-4])
        J, _, _, _, p = pinocchio_terms(model, fid, q, np.zeros(robot.n), np.zeros(robot.n))
        s = np.linalg.svd(J, compute_uv=False)
        measure = 6 / (np.sqrt((s ** 2).sum()) * np.sqrt((s ** -2.0).sum()))
        if measure < 1e-5 or not np.isfinite(oracle.spatial_frame(surf, p, np.zeros(3), (0, 0, 1))[0]).all():
            continue
        checked.append(measure)
        args = (q, np.zeros(robot.n), np.zeros(6), np.zeros(6))
        hybrid.DecouplingLaw(robot, surf, singular_tol=measure * (1 - 1e-6)).evaluate(*args)
        with pytest.raises(hybrid.SingularConfigurationError):
            hybrid.DecouplingLaw(robot, surf, singular_tol=measure * (1 + 1e-6)).evaluate(*args)
    assert min(checked) < 1e-3 < max(checked)  # the sample spans the default tolerance
    with pytest.raises(hybrid.SingularConfigurationError):
        hybrid.DecouplingLaw(robot, surf).evaluate(stretched, np.zeros(robot.n), np.zeros(6), np.zeros(6))
