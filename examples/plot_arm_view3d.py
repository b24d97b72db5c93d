"""
The UR5 on the sphere, in the browser
=====================================

The arm doing the task as an interactive 3-D figure: ``res.view()`` (:func:`hybrid.view`) draws the
pictures ``res.animate()`` draws, from the same data, with plotly. Turn and zoom the figure with the
mouse, play it with its button or move through it with the slider: the links through the joint origins
(the base, the six joints of the UR5, the arm tip), the elastic sensor, the sphere, the sensor tip's
path so far, the contact force the run recorded (an arrow) and the task frame's axes ``t1, t2, n``.

Plotly needs no server: written with ``out``, the figure is one HTML file with plotly.js inside, which
opens offline in any browser (``pip install 'hybrid-decoupling[view]'``).

A short run (1 s: the force reference steps from 10 N to 20 N at 0.5 s), a picture every 4 control
samples (0.04 s).
"""

import tempfile
from pathlib import Path

import hybrid

res = hybrid.simulate(hybrid.tracing_experiment(duration=1.0))

with tempfile.TemporaryDirectory() as folder:
    out = Path(folder) / "ur5_sphere.html"
    # one file, written atomically
    fig = res.view(every=4, out=out, title="the UR5 on the sphere")
    size_mb = out.stat().st_size / 1e6
    print(f"{len(fig.frames)} pictures, "
          f"{size_mb:.1f} MB with plotly.js inside")

# %%
# Each picture is a frame of the figure, named by its control sample; its traces are the ones that
# move (the path so far, the arm, the sensor, the force arrow, the task frame's axes).
print([frame.name for frame in fig.frames[:4]], "...")
print(*[trace.name for trace in fig.frames[0].data], sep=", ")

# %%
# The figure (``fig.show()`` opens it in a browser; a notebook shows it as the cell's result):
fig
