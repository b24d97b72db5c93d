"""
A small sweep: friction and speed against the orthogonal disturbance
====================================================================

``hybrid.sweep`` runs an experiment at every point of a grid (or of random draws) and returns one
row of metrics per run, as a pandas DataFrame. Here: the paper's experiment, the task-space
decoupling law against Khatib's scheme, over the contact's friction and the speed at which the
force steps. The metric is the largest drop of the tangential speed after the force step, the
sensitivity of the velocity loop to a disturbance on the force axis.

The task law cancels the *measured* contact force, friction included, so its drop hardly depends on
the friction; it grows with the speed instead. Khatib's scheme feeds forward only the *desired*
normal force, and its drop grows with the friction: at low speed it is the larger one everywhere,
while at 0.5 m/s with little friction it is the smaller. ``python -m hybrid sweep --demo`` runs the
same study on a finer grid, with model error too.
"""

import matplotlib.pyplot as plt
import numpy as np

import hybrid
from hybrid.plots import plot_sweep

# the force steps at 0.4 s: one second is enough
base = hybrid.paper_experiment(duration=1.0)
parameters = {
    "controller": ["task", "khatib"],
    # a dotted name reaches into a setting
    "contact.friction": np.linspace(0.0, 0.5, 11).tolist(),
    # the speed while the force steps [m/s]
    "speed_reference.before": [0.1, 0.3, 0.5],
}
# 66 runs, on a pool of processes (every core)
table = hybrid.sweep(base, parameters)
DROP = "speed_drop_after_force_step_m_per_s"
shown = table[["controller", "contact.friction",
               "speed_reference.before", DROP, "status"]]
print(shown.head().to_string(
    header=["scheme", "friction", "speed", "drop [m/s]", "status"]))
print(table["status"].value_counts().to_dict())

# %%
# The speed drop against friction, a line per scheme and speed.
fig, ax = plt.subplots(figsize=(7, 4))
styles = {"task": "-", "khatib": "--"}
colors = {0.1: "tab:blue", 0.3: "tab:orange", 0.5: "tab:green"}
for (scheme, speed), rows in table.groupby(
        ["controller", "speed_reference.before"]):
    rows = rows.sort_values("contact.friction")
    ax.plot(rows["contact.friction"], 1000 * rows[DROP],
            styles[scheme], marker="o", ms=3, color=colors[speed],
            label=f"{scheme}, {speed} m/s")
ax.set_xlabel("friction coefficient")
ax.set_ylabel("speed drop after the force step [mm/s]")
ax.grid(alpha=0.3)
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()

# %%
# The same table as heatmaps (:func:`hybrid.plots.plot_sweep`, what ``python -m hybrid sweep`` draws):
# the speed drop over friction and speed, a row of panels per scheme. The panels share one colour
# scale and one colour bar, so that a colour is the same drop in both: Khatib's grows with the
# friction, the task law's hardly does.
fig = plot_sweep(table, "contact.friction", "speed_reference.before",
                 DROP, rows="controller")

# %%
# Their ratio, the task law's drop over Khatib's, on a logarithmic scale centred at 1: blue where the
# task law's is the smaller, a black line where the two are equal.
fig = plot_sweep(table, "contact.friction", "speed_reference.before",
                 DROP, rows="controller", ratio=("task", "khatib"))
