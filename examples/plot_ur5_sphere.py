"""
A UR5 tracing a circle on a sphere
==================================

The 3-D analogue of the paper's experiment (:ref:`conventions §10 <conventions-3d-experiment>`):
the UR5 (its URDF is shipped with the package) presses on a sphere of radius 0.15 m and slides
along the latitude circle 60 degrees from the top. The normal force reference steps from 10 N
to 20 N at 0.5 s, the speed along ``t1`` from 0.15 m/s to 0.3 m/s at 1.5 s; the other five task
axes (the second tangent and the three rotations) hold zero velocity.

Three schemes on the same arm: the task-space decoupling law, Khatib's and Raibert & Craig's
(which has no dynamic decoupling).
"""

import matplotlib.pyplot as plt
import numpy as np

import hybrid

schemes = {"task": "task-space decoupling",
           "khatib": "Khatib (1987)",
           "raibert_craig": "Raibert & Craig (1981)"}
results = {s: hybrid.simulate(hybrid.tracing_experiment(
    controller=s)) for s in schemes}

# %%
# The sensor tip's path on the sphere. The plant's output record names its columns
# (``res.record["outputs"]``): ``s_x, s_y, s_z`` are the sensor tip's position [m].
exp = results["task"].experiment
sphere = exp.surface
fig = plt.figure(figsize=(6, 5))
ax = fig.add_subplot(projection="3d")
u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 36),
                   np.linspace(0, np.pi / 2, 10))
c, radius = np.asarray(sphere.center), sphere.radius
ax.plot_wireframe(c[0] + radius * np.cos(u) * np.sin(v),
                  c[1] + radius * np.sin(u) * np.sin(v),
                  c[2] + radius * np.cos(v), color="0.8", lw=0.5)
for s, label in schemes.items():
    res = results[s]
    columns = [res.record["outputs"].index(k)
               for k in ("s_x", "s_y", "s_z")]
    tip = res.outputs[:, columns]
    ax.plot(*tip.T, lw=1.2, label=label)
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_zlabel("z [m]")
ax.set_title("the sensor tip's path on the sphere", fontsize=9)
ax.legend(fontsize=7)
fig.tight_layout()

# %%
# Speed along ``t1`` and the normal force, against the references.
fig, (ax_v, ax_f) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
for s, label in schemes.items():
    res = results[s]
    ax_v.plot(res.t, res.velocity_tangential, lw=1.2, label=label)
    ax_f.plot(res.t, res.force_normal, lw=1.2, label=label)
for ax, reference in ((ax_v, res.speed_reference),
                      (ax_f, res.force_reference)):
    ax.plot(res.t, reference, "k--", lw=1.0, label="reference")
ax_v.set_ylabel("speed along t1 [m/s]")
ax_f.set_ylabel("normal force [N]")
ax_f.set_xlabel("time [s]")
for a in (ax_v, ax_f):
    a.grid(alpha=0.3)
    a.legend(fontsize=8)
fig.tight_layout()

print(f"{'':14s} {'RMS force error':>15s} {'speed drop':>12s}")
for s in schemes:
    m = results[s].metrics
    drop = 1000 * m["speed_drop_after_force_step_m_per_s"]
    rms = m["rms_force_error_N"]
    print(f"{s:14s} {rms:13.3f} N {drop:7.2f} mm/s")
