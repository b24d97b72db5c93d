"""
A surface the controller is not told
====================================

The controller of the 3-D experiment is usually told the sphere it slides on. With
``controller_surface=hybrid.EstimatedSurface(...)`` it is not: the compiled step estimates the
unit normal at each sample from the contact force (friction removed along the sliding direction)
and from the tip's velocity (tangent to the surface), and builds the task frame from that estimate
(:ref:`conventions §13 <conventions-estimated-surface>`). The plant still has the true sphere.

Here the estimate starts 8 degrees off the true normal; it is compared with a controller told the
sphere, and with one told a flat plane through the start point, whose task frame stays the start's
while the true normal turns as the tool moves on: it presses too hard, then loses the surface
within a second.
"""

import warnings

import matplotlib.pyplot as plt
import numpy as np

import hybrid

# the speed held at 0.15 m/s along t1
told = hybrid.tracing_experiment(v_d=0.15)
start = told.start_state().sensor_tip  # the sensor tip's start [m]
n_true = told.surface.normal_at(start)

# %%
# The estimate's start: the true normal turned by 8 degrees. ``compliance`` is the tool's (here the
# sensor spring's) [m/N]: the deflection under a changing force would otherwise look like a slope.
# Told a plane, the controller presses too hard, then loses the surface: the arm leaves its joint
# limits (a :class:`hybrid.JointLimitWarning`, said here in one line), or the run stops altogether.
e = np.cross(n_true, (0.0, 0.0, 1.0))
e /= np.linalg.norm(e)
n0 = np.cos(np.radians(8)) * n_true + np.sin(np.radians(8)) * e
estimated = hybrid.EstimatedSurface(
    initial_normal=tuple(n0), compliance=1 / told.sensor.stiffness)
flat = hybrid.Plane(point=tuple(start), normal=tuple(n_true))

runs = {"told the sphere": hybrid.simulate(told),
        "estimated": hybrid.simulate(hybrid.tracing_experiment(
            v_d=0.15, controller_surface=estimated))}
with warnings.catch_warnings():
    warnings.simplefilter("ignore", hybrid.JointLimitWarning)
    try:
        plane_run = hybrid.tracing_experiment(
            v_d=0.15, controller_surface=flat, duration=1.0)
        runs["told a plane"] = hybrid.simulate(plane_run)
    except hybrid.SimulationError as err:
        print("told a plane:", str(err).splitlines()[0])
        runs["told a plane"] = err.partial
for v in runs["told a plane"].limit_violations.values():
    print(f"told a plane: {v.joint} at {v.value:.2f} {v.unit}, "
          f"limit {v.limit:g}, first at {v.first_time:.2f} s")

# %%
# The estimate's angle to the true normal at the sensor tip, sample by sample, and the normal force.
est = runs["estimated"]
fig, (ax_n, ax_f) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
ax_n.plot(est.sample_t, est.normal_angle_error_deg,
          color="tab:purple")
ax_n.set_ylabel("normal estimate's error [deg]")
ax_n.set_yscale("log")
for label, res in runs.items():
    ax_f.plot(res.t, res.force_normal, lw=1.0, label=label)
ax_f.plot(est.t, est.force_reference, "k--", lw=1.0,
          label="reference")
ax_f.set_ylabel("normal force [N]")
ax_f.set_xlabel("time [s]")
ax_f.set_ylim(0, 30)
for ax in (ax_n, ax_f):
    ax.grid(alpha=0.3)
ax_f.legend(fontsize=8)
fig.tight_layout()

for label in ("told the sphere", "estimated"):
    rms = runs[label].metrics["rms_force_error_N"]
    print(f"{label:16s} RMS force error {rms:.3f} N")
angle = est.metrics["normal_angle_error_deg"]
largest = est.metrics["max_normal_angle_error_deg"]
print(f"estimate after 0.5 s: RMS {angle:.2f} deg, "
      f"largest {largest:.2f} deg")
