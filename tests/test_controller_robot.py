"""An experiment's ``controller_robot``: the robot the controller is told, apart from the plant's.

Told the true robot, the run is the exact model's (``model_error=0``, all the viscosity compensated);
told the model ``model_error`` makes, it is that run; told another, it differs. A robot of another
structure, or a scaling that would not apply, is refused; the setting is saved and read back.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import hybrid

EXACT = {"model_error": 0.0, "viscous_compensation": 1.0}


@pytest.fixture(scope="module")
def tracing():
    return hybrid.tracing_experiment(duration=0.1)


def _same_run(a: hybrid.Experiment, b: hybrid.Experiment) -> bool:
    ra, rb = hybrid.simulate(a), hybrid.simulate(b)
    return np.array_equal(ra.state, rb.state) and np.array_equal(ra.tau, rb.tau)


@pytest.mark.parametrize("factory", [hybrid.paper_experiment, hybrid.tracing_experiment])
def test_told_the_true_robot_runs_the_exact_model(factory):
    exp = factory(duration=0.1)
    told = dataclasses.replace(exp, controller_robot=exp.robot)
    assert told.controller_model() == exp.robot
    assert _same_run(told, dataclasses.replace(exp, **EXACT))
    assert not _same_run(told, exp)  # the default model error changes the run: the comparison can fail


def test_told_a_model_runs_it(tracing):
    """The model ``model_error`` makes, given as ``controller_robot``, is that run; a robot with one link
    changed is another run."""
    model = tracing.robot.with_model_error(0.2, 0.3)
    told = dataclasses.replace(tracing, controller_robot=model)
    assert _same_run(told, dataclasses.replace(tracing, model_error=0.2, viscous_compensation=0.3))
    joint = tracing.robot.joint_names[2]
    heavier = tracing.robot.with_link(joint, mass=tracing.robot.links[2].mass * 1.3)
    assert not _same_run(told, dataclasses.replace(tracing, controller_robot=heavier))


def test_another_structure_is_refused(tracing):
    with pytest.raises(hybrid.HybridError, match="another kinematic structure.*6 joints against 7"):
        dataclasses.replace(tracing, controller_robot=hybrid.panda())
    robot = tracing.robot
    j = robot.chain.joints[1]
    moved = dataclasses.replace(j, translation=(j.translation[0], j.translation[1] + 0.01, j.translation[2]))
    chain = dataclasses.replace(robot.chain, joints=(robot.chain.joints[0], moved, *robot.chain.joints[2:]))
    with pytest.raises(hybrid.HybridError, match=f"joint 2 \\({j.name}\\): origin translation"):
        dataclasses.replace(tracing, controller_robot=dataclasses.replace(robot, chain=chain))
    planar = hybrid.paper_experiment(duration=0.1)
    with pytest.raises(hybrid.HybridError, match="closed form"):
        dataclasses.replace(planar, controller_robot=hybrid.Robot(
            "planar_arm", planar.robot.chain, planar.robot.links, planar.robot.damping, planar.robot.gravity))
    with pytest.raises(hybrid.HybridError, match="must be a hybrid.Robot"):
        dataclasses.replace(tracing, controller_robot="ur5")


def test_a_scaling_that_would_not_apply_is_refused(tracing):
    told = dataclasses.replace(tracing, controller_robot=tracing.robot)
    for change in ({"model_error": 0.3}, {"viscous_compensation": 1.0}):
        with pytest.raises(hybrid.HybridError, match=f"{next(iter(change))} = .*give one or the other"):
            dataclasses.replace(told, **change)
        with pytest.raises(hybrid.HybridError, match="give one or the other"):
            told.with_physics(**change)  # a sweep's run that changes only its physics


def test_saved_and_read_back(tracing):
    model = tracing.robot.with_link(tracing.robot.joint_names[4], mass=2.0)
    told = dataclasses.replace(tracing, controller_robot=model)
    again = hybrid.Experiment.from_dict(told.to_dict())
    assert again.controller_robot == model and again == told
    assert "controller_robot" not in tracing.to_dict()  # saved as before when not given


def test_joint_friction_is_compensated_when_known():
    """A plant with Coulomb friction and offsets on its joints: the controller told them runs close to the
    frictionless run (the law cancels them at each sample's velocity; within the sample the plant's friction
    moves on), told the robot without them it runs several times further from it."""
    base = hybrid.tracing_experiment(duration=0.6)
    robot = dataclasses.replace(base.robot, coulomb=(3.0, 4.0, 2.0, 0.8, 0.6, 0.4),
                                offset=(0.5, -0.8, 0.4, 0.1, -0.1, 0.05), coulomb_speed=(0.2,) * 6)
    frictionless = hybrid.simulate(dataclasses.replace(base, **EXACT))
    told = hybrid.simulate(dataclasses.replace(base, robot=robot, controller_robot=robot))
    untold = hybrid.simulate(dataclasses.replace(base, robot=robot, controller_robot=base.robot))

    def apart(res, what):
        return float(np.sqrt(np.mean((getattr(res, what) - getattr(frictionless, what)) ** 2)))

    for what in ("force_normal", "velocity_tangential"):  # measured: 6.5x and 15x further
        assert apart(told, what) < 0.25 * apart(untold, what)
