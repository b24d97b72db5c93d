"""
The controller in your own loop
===============================

``hybrid.Controller`` is the sampled controller as a component: ``tau = ctrl(t, q, qdot, Fc)``
runs one sample (measurement, loops, law) in one native call, and keeps the loops' integrals
between calls. Here the loop is written out by hand, with the experiment's generated plant
standing for a real UR5 and its force sensor: per sample, read the wrench, call the controller,
hold the torque while the plant advances.

The first loop is exactly what ``hybrid.simulate`` runs. The second uses a controller built by
hand, with a limit on the torque's change per sample, and misses a deadline on purpose.
"""

import matplotlib.pyplot as plt
import numpy as np

import hybrid

# the UR5 on the sphere, 1 s
exp = hybrid.tracing_experiment(duration=1.0)
n = exp.robot.n


def run(ctrl, miss=None):
    """The closed loop, one control sample at a time; ``miss``: a
    sample index whose call is skipped."""
    # the true arm, its elastic sensor, the contact with friction
    plant = exp.plant()
    # (q, q', s, s'): the arm at rest, pressing with F_d(0)
    x = exp.initial_state()
    # the RK4 steps of one sample
    states = np.empty((exp.steps_per_sample, len(x)))
    force, tau = [], np.zeros(n)
    ctrl.reset()
    for k in range(exp.n_samples):
        t = k * exp.sample_time
        # the wrench on the robot at the tip, base axes [N, N m]
        Fc = plant.sensor_wrench(x)
        if k != miss:
            try:
                tau = ctrl(t, x[:n], x[n:2 * n], Fc)
            # off the clock: apply the law's torque, integrals kept
            except hybrid.SampleTimingError as err:
                print(f"t = {t:.2f} s: {err.status}")
                tau = err.torque
        # a zero-order hold on tau
        plant.advance(x, tau, exp.steps_per_sample, states)
        # the task wrench's normal component, as the controller saw
        # it
        force.append(ctrl.last["f"][2])
    return np.array(force)


# %%
# The experiment's own controller: the loop gives ``simulate``'s run.
ctrl = exp.build_controller()
force = run(ctrl)
res = hybrid.simulate(exp)
sampled = res.force_normal[::exp.steps_per_sample][:exp.n_samples]
difference = np.abs(force - sampled).max()
print(f"largest difference from simulate: {difference:.1e} N")

# %%
# A controller built by hand: the controller's model of the arm, the surface, the scheme, the
# references, and the torque's change bounded to 2 N m per sample on every joint. The call of
# sample 50 is skipped (a missed deadline): the next sample comes late, is served with the law's
# torque, and leaves the integrals as they were.
mine = hybrid.Controller(
    exp.controller_model(), exp.surface, "task", selection=("n",),
    gains=exp.gains, force_reference=exp.force_reference,
    velocity_reference=exp.speed_reference,
    sample_time=exp.sample_time, torque_step_limit=2.0)
limited = run(mine, miss=50)

t = np.arange(exp.n_samples) * exp.sample_time
fig, ax = plt.subplots(figsize=(7, 3.6))
ax.plot(t, force, label="the experiment's controller")
ax.plot(t, limited, label="torque rate limit, sample 50 missed")
ax.plot(res.t, res.force_reference, "k--", lw=1.0, label="reference")
ax.set_xlabel("time [s]")
ax.set_ylabel("normal force [N]")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
