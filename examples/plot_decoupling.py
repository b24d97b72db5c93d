"""
The decoupling: every task axis becomes an integrator, ``y' = a``
===================================================================

The law ``F* = F*(r, r', a)`` is built so that the task velocities ``y = R v`` (``v`` the tip's
twist, ``R`` the task frame at the contact point) obey ``y' = a``: each task axis an integrator,
decoupled from the others, whatever the orientation of the frame
(:ref:`conventions §2 <conventions-law>`, :ref:`§9 <conventions-spatial>`).

This example checks it on the exact model, from the public API alone: the law's torque goes into
the arm's own dynamics ``B(q) q'' + n(q, q') = tau + J^T F_c``, and the resulting task acceleration
``y' = R (J q'' + J' q') + R' v`` is compared with the commanded ``a``. It does so for the UR5 on a
sphere (six task axes), for the Panda on the pillar of its experiment (a vertical cylinder) with an
arbitrary null-space torque ``tau0`` (seven joints, six axes: ``tau0`` must not disturb the task),
and for the paper's planar arm on its disc.
"""

import matplotlib.pyplot as plt
import numpy as np

import hybrid

rng = np.random.default_rng(0)
N = 2000  # states, each law evaluated for all of them in one call


def task_acceleration(robot, law, q, qdot, Fc, tau):
    """``y' = R v' + R' v`` from the arm's dynamics under ``tau`` and
    the contact wrench ``Fc``."""
    terms = hybrid.arm_terms(robot, q, qdot)
    J, B, n = terms["J"], terms["B"], terms["n"]
    rhs = tau + np.einsum("nji,nj->ni", J, Fc) - n
    qdd = np.linalg.solve(B, rhs[..., None])[..., 0]
    v = np.einsum("nij,nj->ni", J, qdot)
    vdot = np.einsum("nij,nj->ni", J, qdd) + terms["Jdot_qdot"]
    # the frame's rows t1, t2, n at the tip (N x 3 x 3)
    RL, RLdot = law.task_frame(terms["r"], v[:, :3])
    Z = np.zeros_like(RL)
    R, Rdot = (np.block([[M, Z], [Z, M]]) for M in (RL, RLdot))
    return (np.einsum("nij,nj->ni", R, vdot)
            + np.einsum("nij,nj->ni", Rdot, v))


def relative_errors(robot, surface, q_nominal, tau0=False):
    # R' in the law: exact on a curved surface
    law = hybrid.decoupling_law(robot, surface, curvature=True)
    # near a pose of the arm pressing on the surface
    q = q_nominal + 0.1 * rng.standard_normal((N, robot.n))
    qdot = rng.standard_normal((N, robot.n))
    a = rng.standard_normal((N, 6))  # any task acceleration
    # any measured wrench (the law cancels it)
    Fc = 10 * rng.standard_normal((N, 6))
    t0 = 20 * rng.standard_normal((N, robot.n)) if tau0 else None
    tau = law.torque(q, qdot, a, Fc, tau0=t0)
    ydot = task_acceleration(robot, law, q, qdot, Fc, tau)
    error = np.linalg.norm(ydot - a, axis=1)
    return error / np.linalg.norm(a, axis=1)


# their surfaces and start poses
ur5_run = hybrid.tracing_experiment()
panda_run = hybrid.panda_experiment()
errors = {
    "UR5 on a sphere": relative_errors(
        hybrid.ur5(), ur5_run.surface, ur5_run.start_state().q),
    "Panda on a cylinder, any tau0": relative_errors(
        hybrid.panda(), panda_run.surface, panda_run.start_state().q,
        tau0=True),
}

# %%
# The paper's planar arm in closed form: two joints, the task axes ``(t1, n)`` of its plane.
arm = hybrid.paper_arm()
disc = hybrid.Circle(center=(0.5, 0.0), radius=0.2)
law = hybrid.decoupling_law(arm, disc, curvature=True)
planar = []
# the closed form's terms take one state at a time
for _ in range(200):
    q = np.array([2.2, 1.9]) + 0.2 * rng.standard_normal(2)
    qdot = rng.standard_normal(2)
    a, Fc = rng.standard_normal(2), 10 * rng.standard_normal(2)
    terms = hybrid.arm_terms(arm, q, qdot)
    tau = law.torque(q, qdot, a, Fc)
    qdd = np.linalg.solve(terms["B"],
                          tau + terms["J"].T @ Fc - terms["n"])
    rdot = terms["J"] @ qdot
    R, Rdot = law.task_frame(terms["r"], rdot)
    ydot = R @ (terms["J"] @ qdd + terms["Jdot_qdot"]) + Rdot @ rdot
    planar.append(np.linalg.norm(ydot - a) / np.linalg.norm(a))
errors["the paper's arm on its disc"] = np.array(planar)

# %%
# The relative error ``|y' - a| / |a|`` is rounding error: the law decouples the task axes exactly.
fig, ax = plt.subplots(figsize=(7, 3.6))
bins = np.linspace(-17, -9, 41)
for label, err in errors.items():
    ax.hist(np.log10(np.maximum(err, 1e-17)), bins=bins, alpha=0.6,
            label=label)
    print(f"{label:30s} largest |y' - a| / |a| = {err.max():.1e}")
ax.set_xlabel("log10 |y' - a| / |a|")
ax.set_ylabel("states")
ax.legend(fontsize=8)
ax.set_title("the task acceleration equals the commanded one, "
             "to rounding", fontsize=9)
fig.tight_layout()
