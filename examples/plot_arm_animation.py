"""
The UR5 on the sphere, animated
===============================

The arm doing the task: ``res.animate()`` draws a run sample by sample, with matplotlib's 3-D axes
(:mod:`hybrid.animation`). Each picture shows the links as a polyline through the joint frames'
origins (the base, the six joints of the UR5, the arm tip), the elastic sensor, the sphere, the
sensor tip's path so far, the contact force the run recorded (an arrow, in mm per N) and the task
frame's axes ``t1, t2, n`` at the tip.

A short run (1 s: the force reference steps from 10 N to 20 N at 0.5 s), a picture every 10
control samples (0.1 s), written as an animated GIF; then one still, at 0.8 s.
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import hybrid
from hybrid.animation import arm_frame, still

res = hybrid.simulate(hybrid.tracing_experiment(duration=1.0))

with tempfile.TemporaryDirectory() as folder:
    out = Path(folder) / "ur5_sphere.gif"
    # an animated GIF, written atomically (Pillow)
    anim = res.animate(every=10, out=out)
    pictures = len(list(anim.new_frame_seq()))
    print(f"{pictures} pictures, {out.stat().st_size / 1e3:.0f} kB")
plt.close("all")  # the animation's figure: written, no longer needed

# %%
# One picture is data too (:func:`hybrid.animation.arm_frame`): the points the links are drawn
# through [m] and the recorded contact force [N], base axes.
frame = arm_frame(res, 80)
print("joint origins [m]:\n", frame.links.round(3))
print("F_c [N]:", frame.force.round(2))
print("rows t1, t2, n of R(r):\n", frame.task_axes.round(3))

fig = still(res, 80, title="the UR5 on the sphere at 0.8 s, "
                           "after the force step to 20 N")
