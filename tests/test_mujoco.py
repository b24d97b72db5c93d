"""The paper's experiment in MuJoCo, an independent physics engine, under the same controller."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid

pytest.importorskip("mujoco")


def rms(x):
    return float(np.sqrt(np.mean(np.square(x))))


@pytest.mark.parametrize("settings", [dict(), dict(controller="khatib"), dict(integral=False, duration=1.0),
                                      dict(surface=hybrid.Plane((0.3, 0.0), (-1.0, 0.0)), start_point=(0.3, 0.1),
                                           duration=1.0)],
                         ids=["task", "khatib", "no-integral", "plane"])
def test_mujoco_plant_agrees_with_the_generated_plant(settings):
    exp = hybrid.paper_experiment(**settings)
    ours, theirs = hybrid.simulate(exp), hybrid.simulate(exp, plant="mujoco")
    assert rms(ours.force_normal - theirs.force_normal) < 0.02  # N
    assert rms(ours.velocity_tangential - theirs.velocity_tangential) < 1e-3  # m/s
    # the same result object: the metrics of both runs are the same quantities
    assert set(theirs.metrics) == set(ours.metrics)
    assert theirs.metrics["rms_force_error_N"] == pytest.approx(ours.metrics["rms_force_error_N"], rel=0.05)


def test_mujoco_refuses_what_it_does_not_model():
    with pytest.raises(hybrid.HybridError, match="generated plant"):
        hybrid.simulate(hybrid.tracing_experiment(duration=0.1), plant="mujoco")
    with pytest.raises(hybrid.HybridError, match="gravity"):
        hybrid.simulate(hybrid.paper_experiment(arm=hybrid.Arm(**{**vars(hybrid.paper_arm()), "gravity": 9.81}),
                                                duration=0.1), plant="mujoco")
    with pytest.raises(hybrid.HybridError, match="plant ="):
        hybrid.simulate(hybrid.paper_experiment(duration=0.1), plant="bullet")
