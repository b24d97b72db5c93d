"""
The Panda on its pillar: the spare joint and the posture task
=============================================================

The Panda has seven joints for the task's six axes (:func:`hybrid.panda_experiment`: it presses on a
vertical pillar and slides around it, force along ``n``, speed along ``t1``, the other four axes held).
The law decouples the task; the one joint motion the task leaves free, the *self-motion* ``z``
(``J z = 0``: the joints move, the hand's pose does not), is the posture task's
(:class:`hybrid.Posture`): a PD towards a rest posture ``q_rest``, projected into the task's null space
(:doc:`../howto/urdf`).

Here the start is moved 0.4 rad along the self-motion, away from the rest posture, and the arm runs
for 1.5 s three times: with the posture and the experiment's own controller model (10 % heavy), with
the posture and an exact model, and without a posture. The hand's task is the same in all three; what
the spare joint does is not.
"""

import textwrap
import warnings

import matplotlib.pyplot as plt
import numpy as np

import hybrid
from hybrid.animation import arm_frame, still

# the speed steps at 1.5 s: the run ends before it
exp = hybrid.panda_experiment(duration=1.5)
q_rest = np.array(exp.posture.q_rest)
q_start = exp.start_state().q
terms = hybrid.arm_terms(exp.robot, q_start, np.zeros(exp.robot.n))
# the self-motion at the start: J's null space (7 joints, 6 rows)
z0 = np.linalg.svd(terms["J"])[2][-1]
# its sign is arbitrary: joint 7 turning away from its upper limit
z0 *= -np.sign(z0[6])

# %%
# The start's inverse kinematics begins at ``q0``: from a seed 0.4 rad along the self-motion it ends
# there, the hand where it was. ``posture=None`` is warned (:class:`hybrid.RedundancyWarning`), and
# the run without a posture leaves the joint limits (:class:`hybrid.JointLimitWarning`): both are
# expected here, and printed.
seed = tuple(q_start + 0.4 * z0)
settings = {"with the posture, model 10 % heavy": {},
            "with the posture, exact model": {"model_error": 0.0},
            "without a posture": {"posture": None}}
runs = {}
for label, setting in settings.items():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        experiment = hybrid.panda_experiment(duration=1.5, q0=seed,
                                             **setting)
        runs[label] = hybrid.simulate(experiment)
    for w in caught:
        print(f"{label}: {w.category.__name__}:")
        first_line = str(w.message).splitlines()[0]
        print(textwrap.indent(textwrap.fill(first_line, 64), "  "))
for v in runs["without a posture"].limit_violations.values():
    print(f"  {v.kind}: {v.joint} reached {v.value:.2f} {v.unit} "
          f"(limit {v.limit:g}) at {v.first_time:.2f} s")


def self_motion(res):
    """Per control sample, the component of ``q - q_rest`` along the
    self-motion ``z`` in the inertia metric,
    ``z^T B (q - q_rest) / z^T B z`` [rad]: what the posture task
    drives to 0 (the rest of ``q - q_rest`` is the task's to set)."""
    q = res.q[::exp.steps_per_sample]
    # the true arm's J and B at every sample
    arm = hybrid.arm_terms(exp.robot, q, np.zeros_like(q))
    z = np.linalg.svd(arm["J"])[2][:, -1]
    z[0] *= np.sign(z[0] @ z0)
    # the SVD's sign, per sample, made continuous along the run
    for k in range(1, len(z)):
        z[k] *= np.sign(z[k] @ z[k - 1])
    Bz = np.einsum("nij,nj->ni", arm["B"], z)
    along = np.einsum("ni,ni->n", Bz, q - q_rest)
    return along / np.einsum("ni,ni->n", Bz, z)


# %%
# The arm at the end of the run with the posture (the model 10 % heavy), and dashed the arm at the
# end of the run without one (:func:`hybrid.animation.arm_frame`: the points the picture draws the
# links through): the hand on the pillar in both, the elbow swung aside and the wrist wound up
# without a posture.
title = "the Panda at 1.5 s: with the posture, and without"
fig = still(runs["with the posture, model 10 % heavy"], title=title)
ax = fig.axes[0]
loose = arm_frame(runs["without a posture"], -1).links
ax.plot(*loose.T, color="tab:brown", lw=1.5, ls="--", marker="o",
        ms=3, label="arm without a posture")
ax.legend(fontsize=7, loc="upper left", ncol=2, frameon=False)
ax.view_init(elev=35, azim=-125)

# %%
# The self-motion's coordinate and the normal force. With an exact model the posture's PD (5 rad/s,
# critically damped) takes the offset back to a few milliradians; with the model 10 % heavy the
# model's error pushes along the self-motion too and the PD, which has no integral, settles off the
# rest posture. Without a posture nothing holds the self-motion: it falls under gravity and winds
# up. The force, on the task's axes, is alike in all three.
fig, (ax_z, ax_f) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
t = np.arange(exp.n_samples + 1) * exp.sample_time
for label, res in runs.items():
    ax_z.plot(t, self_motion(res), lw=1.2, label=label)
    ax_f.plot(res.t, res.force_normal, lw=1.0, label=label)
ax_f.plot(res.t, res.force_reference, "k--", lw=1.0,
          label="reference")
ax_z.set_ylabel("self-motion's coordinate\nof q - q_rest [rad]")
ax_f.set_ylabel("normal force [N]")
ax_f.set_xlabel("time [s]")
for ax in (ax_z, ax_f):
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()

print(f"{'':34s} {'self-motion [rad] at':24s}RMS force")
print(f"{'':34s} {'0 s':8s}{'0.5 s':8s}{'1.5 s':8s}error [N]")
half = round(0.5 / exp.sample_time)  # the sample at 0.5 s
for label, res in runs.items():
    along = self_motion(res)
    error = res.metrics["rms_force_error_N"]
    print(f"{label:34s} {along[0]:+.3f}  {along[half]:+.3f}  "
          f"{along[-1]:+.3f}  {error:.3f}")
