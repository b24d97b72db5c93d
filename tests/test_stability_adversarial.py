"""The stability tools at the settings a demanding user reaches for, each judged against something
independent: the nonlinear simulation, the model's own definitions, SciPy, the experiment's own check.

Other arms, tasks and schemes (the UR5, the redundant Panda, a subset of the axes, Khatib's scheme), the
edges of the settings (tiny and huge sample times, long delays, a lag near the Nyquist frequency), bad
input to the map and the suggested gains (a clear :class:`hybrid.HybridError`, never another exception),
and what the check costs an experiment.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.stability.experiment_loops import loop_numbers
from hybrid.stability.model import closed_loop

sys.path.insert(0, str(Path(__file__).parent))
from test_stability_boundary import force_error, grows, plane_experiment  # noqa: E402

#: the UR5 pressing on a wall in front of it at rest, gravity on, no friction (the model's assumptions)
UR5_WALL = dict(surface=hybrid.Plane((0.5, 0.0, 0.2), (-1.0, 0.0, 0.0)), start_point=(0.5, 0.1, 0.2),
                contact=hybrid.Contact(friction=0.0), speed_reference=hybrid.Step(0.0, 0.0, 0.0))
#: the controller's model exact
EXACT = dict(model_error=0.0, viscous_compensation=1.0)


def model_force_step(exp, at: float) -> np.ndarray:
    """The model's normal force at each sample for a unit step of ``F_d`` at ``at`` [s]."""
    st, p = loop_numbers(exp)
    m = closed_loop(st, p)
    force_axis = list(st.force).index(True)
    normal = list(st.sensed).index(force_axis)
    X, r = np.zeros(m["A"].shape[0]), np.zeros(st.n)
    out = []
    for k in range(exp.n_samples):
        r[force_axis] = 1.0 if k * exp.sample_time >= at - 1e-12 else 0.0
        out.append((m["force"] @ np.concatenate([X, r]))[normal])
        X = m["A"] @ X + m["B"] @ r
    return np.array(out)


def simulated_force_step(factory, step: float, at: float = 0.05, **settings) -> tuple[np.ndarray, np.ndarray]:
    """The simulated normal force's response to a step of ``step`` [N] at ``at``, per newton, at each sample
    (the run without the step subtracted: the start is at rest to its own tolerance only), and the model's."""
    exp = factory(force_reference=hybrid.Step(10.0, 10.0 + step, at), **settings)
    still = factory(force_reference=hybrid.Step(10.0, 10.0, at), **settings)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", hybrid.RedundancyWarning)
        runs = [hybrid.simulate(e) for e in (exp, still)]
    rows = np.searchsorted(runs[0].t, np.arange(exp.n_samples) * exp.sample_time - 1e-12)
    simulated = (runs[0].force_normal[rows] - runs[1].force_normal[rows]) / step
    return simulated, model_force_step(exp, at)


# ------------------------------------------------------------------------------------------ Khatib's scheme

def test_khatibs_loops_are_modelled_as_they_run():
    # Khatib's law feeds the desired force forward where the task law cancels the measured one: on the UR5
    # the model's step response is the simulation's to 1e-5 of its size (the task law's model: 3 % off)
    simulated, model = simulated_force_step(hybrid.tracing_experiment, 1e-2, controller="khatib", duration=0.3,
                                            integration_step=1e-5, **UR5_WALL, **EXACT)
    scale = np.abs(model).max()
    assert scale > 0.5
    np.testing.assert_allclose(model, simulated, rtol=0, atol=1e-5 * scale)


def test_khatibs_scheme_turns_unstable_where_the_task_law_holds():
    # the paper's arm on a 1.12e4 N/m sensor, 10 ms: the task law's loops hold, Khatib's grow, as predicted
    sensor = hybrid.Sensor(stiffness=11220.0)
    task, khatib = (plane_experiment(sensor=sensor, controller=c) for c in ("task", "khatib"))
    assert hybrid.stability(task, margins=False).stable and not grows(force_error(task))
    assert not hybrid.stability(khatib, margins=False).stable and grows(force_error(khatib))
    with pytest.raises(hybrid.HybridError, match="force loop on n is unstable"):
        hybrid.paper_experiment(sensor=sensor, controller="khatib")
    hybrid.paper_experiment(sensor=sensor)
