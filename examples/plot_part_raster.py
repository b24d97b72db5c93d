"""
A raster across a part given as a mesh
======================================

A part comes as a mesh (a CAD export: STL, OBJ, PLY). :class:`hybrid.MeshSurface` fits it with a smooth
signed distance and reports how far the fit is from the mesh; a :class:`hybrid.RasterPath` is drawn
across it and followed with a :class:`hybrid.PathTask` (:doc:`../howto/parts`, :doc:`../howto/paths`):
the UR5 presses with 10 N and moves at up to 0.1 m/s along three passes with round turns between them,
then releases the force and leaves along the normal.

The part here is a curved panel (240 mm by 200 mm, bent to radii of 250 mm and 400 mm), written to an
STL file in millimetres as a CAD tool would, and read back from it. It needs trimesh
(``pip install 'hybrid-decoupling[parts]'``).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import trimesh

import hybrid
from hybrid.animation import still
from hybrid.plots import plot_path_force

# %%
# The panel's mesh: a grid of 5 mm in x and y, two facets per cell, its normals up (the tool's
# side), in millimetres; written as STL, read back with the part's place in the robot's base axes
# (0.5 m ahead, 0.25 m up) and its unit (``scale``: metres per millimetre).
x, y = np.meshgrid(np.linspace(-120.0, 120.0, 49),
                   np.linspace(-100.0, 100.0, 41), indexing="ij")
z = -x ** 2 / (2 * 250.0) - y ** 2 / (2 * 400.0)
vertices = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
# each cell's corner of least x and y
corner = np.arange(x.size).reshape(x.shape)[:-1, :-1].ravel()
step = x.shape[1]  # the next vertex in x
faces = np.vstack(
    [np.column_stack([corner, corner + step, corner + step + 1]),
     np.column_stack([corner, corner + step + 1, corner + 1])])

place = np.eye(4)
place[:3, 3] = (0.5, 0.0, 0.25)
with tempfile.TemporaryDirectory() as folder:
    stl = Path(folder) / "panel.stl"
    trimesh.Trimesh(vertices, faces).export(stl)
    part = hybrid.MeshSurface.from_file(stl, transform=place,
                                        scale=1e-3, spacing=0.008)
fit = part.fit
print(f"{len(part.faces)} facets; the fit, "
      f"at a spacing of {1000 * fit.spacing_m:.0f} mm:")
print(f"  distance from the mesh: "
      f"{1000 * fit.distance_rms_m:.3f} mm RMS, "
      f"{1000 * fit.distance_max_m:.3f} mm at most")
print(f"  normal's angle: {fit.normal_angle_rms_deg:.2f} deg RMS, "
      f"{fit.normal_angle_max_deg:.2f} deg at most")

# %%
# The raster: three passes of 0.12 m along base x, 25 mm apart, drawn in the tangent plane at its
# first point and moved onto the part; the task follows it at 0.1 m/s (slower in the turns, where
# the acceleration limit bounds ``v^2 kappa``) with 10 N, and at its end retreats 1 cm.
# a point of the part, above which the raster starts
origin = part.project([0.44, -0.025, 0.26])
raster = hybrid.RasterPath(part, origin, (1.0, 0.0, 0.0),
                           pass_length=0.12, spacing=0.025, passes=3)
task = hybrid.PathTask(raster, speed=0.1, force=10.0,
                       retreat_distance=0.01)
res = hybrid.simulate(hybrid.tracing_experiment(
    surface=part, path_task=task, duration=6.0))
print(f"raster: {raster.length:.3f} m")
for name in ("path_travelled_m", "path_time_s", "path_error_rms_m",
             "path_error_max_m", "path_force_rms_error_N",
             "path_contact_losses", "path_end_peak_force_N"):
    print(f"  {name:24s} {res.metrics[name]:.4g}")

# %%
# The arm on the part half-way through the raster: the facets around the path, the sensor tip's
# path so far, the contact force and the task frame.
fig = still(res, 250, title="the UR5 on the mesh part at 2.5 s, "
                            "on the raster's second pass")
fig.axes[0].view_init(elev=35, azim=-70)

# %%
# The force along the path: the sensor tip's trace on the part coloured by the measured normal
# force, and the force against the arc length along the raster (at each control sample from the
# start to the path's end, the arc length of the raster's point nearest the sensor tip, among points
# 1 mm apart), its passes shaded. After a dip as the tip sets off (its first centimetre), the
# force stays within a few hundredths of a newton of its 10 N, along the passes and through
# the turns; after the path's end it is released (the trace's last, dark stretch: the tip leaving).
end = np.searchsorted(res.t, res.metrics["path_time_s"])
samples = slice(0, end, res.experiment.steps_per_sample)
tip = np.column_stack([res.output(c) for c in ("s_x", "s_y", "s_z")])
tip = tip[samples]
s = np.arange(0.0, raster.length, 1e-3)
gaps = tip[:, None, :] - raster.points_at(s)[None]
nearest = np.argmin(np.linalg.norm(gaps, axis=2), axis=1)
arc, force = s[nearest], res.force_normal[samples]

fig = plt.figure(figsize=(11, 4.5), layout="constrained")
ax3 = fig.add_subplot(1, 2, 1, projection="3d")
# the start's dip and the release are off this scale
plot_path_force(res, ax3, vmin=9.98, vmax=10.02)
ax3.set_title("the sensor tip's trace, coloured by the normal force",
              fontsize=9)
ax = fig.add_subplot(1, 2, 2)
for k, (s0, s1) in enumerate(raster.pass_arcs):
    ax.axvspan(s0, s1, color="0.92",
               label="a pass" if k == 0 else None)
ax.plot(arc, force, lw=1.2, label="measured")
ax.axhline(10.0, color="k", ls="--", lw=1.0,
           label="the task's force")
ax.set_xlabel("arc length along the raster [m]")
ax.set_ylabel("normal force [N]")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
after = arc > 0.02  # past the start's dip
print(f"normal force along the raster after its first 2 cm: "
      f"{force[after].min():.3f} to {force[after].max():.3f} N")
