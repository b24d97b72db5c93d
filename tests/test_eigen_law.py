"""The benchmark against the law and step written by hand on Pinocchio + Eigen compares like with like:
the hand-written C++ (Pinocchio's algorithms, the sphere's frame in closed form, Eigen's solves) gives
the statuses and numbers of our generated law and controller step on random states, under the bench's
settings and under settings where every branch of the step acts, on the UR5 and the Panda, and takes
no heap memory in its calls; skipped where the C++ packages or a compiler are missing. Correctness
only: nothing here is timed."""

import numpy as np
import pytest
from conftest import PANDA, UR5, example_robot

import hybrid
from hybrid.bench import eigen_law, eigen_race
from hybrid.bench import pinocchio_codegen as pc
from hybrid.bench.robots import SPHERE


def _race(arm):
    urdf = example_robot(arm[0])
    why = eigen_race.missing()
    if why:
        pytest.skip(why)
    robot = hybrid.Robot.from_urdf(urdf, tip=arm[1])
    sphere = hybrid.Sphere(SPHERE[:3], SPHERE[3])
    return robot, sphere, eigen_race.race(robot, urdf, arm[1], sphere.spec())


# on a cold cache about 2 minutes of one core a robot (the C++ build; 5 minutes on a busy 2-core machine),
# seconds once it is cached
@pytest.mark.slow
@pytest.mark.parametrize("arm", [UR5, PANDA], ids=["ur5", "panda"])
def test_the_law_and_step_by_hand_on_pinocchio_give_our_numbers(arm):
    robot, sphere, race = _race(arm)
    assert race.sides == (("ours", "pinocchio", "pinocchio_rnea") if robot.n == 6 else ("ours", "pinocchio"))
    ctrl = eigen_law.controller(robot, sphere)
    for config, seed, acting in ((eigen_law.config_of(ctrl), 7, False), (eigen_law.acting(ctrl), 8, True)):
        states = eigen_law.random_states(robot.n, 60, seed)
        worst = eigen_law.differences(race, config, states,
                                      eigen_law.conditioning(robot, example_robot(arm[0]), arm[1], states))
        assert set(worst) == {(f, s) for f in eigen_race.FUNCTIONS for s in race.sides[1:]}
        assert max(worst.values()) <= eigen_law.AGREEMENT, worst
        status, out = race.evaluate(config, states)["step", "ours"]
        assert (status == 0).mean() > 0.8  # the comparison is of outputs, not of refusals
        if acting:  # the limits bind on some states and not on others, and contact is lost on some
            assert 0 < out["saturated"].mean() < 1
            force = out["f"][:, 2]
            assert (force < 2.0).any() and (force >= 2.0).any()


@pytest.mark.slow
@pytest.mark.parametrize("arm", [UR5, PANDA], ids=["ur5", "panda"])
def test_the_hand_written_calls_take_no_heap_memory_and_callgrind_counts_their_parts(arm):
    robot, sphere, race = _race(arm)
    config, state = eigen_law.config_of(eigen_law.controller(robot, sphere)), eigen_law.bench_state(robot.n)
    heap = race.allocations(config, state, calls=10)
    assert set(heap) == {(f, s) for f in eigen_race.FUNCTIONS for s in race.sides[1:]}
    assert not any(heap.values()), heap
    if not pc.can_count():
        pytest.skip("valgrind's callgrind is not installed")
    counted = eigen_race.race(robot, example_robot(arm[0]), arm[1], sphere.spec(), counted=True)
    law = counted.instructions(config, state, "law_pinocchio", calls=20)
    # the parts are inside the call and add up to most of it; the step runs the law's parts and its loops
    parts = sum(law[p] for p in eigen_race.PARTS if p in law)
    assert {"kinematics", "dynamics", "sphere_frame", "operational", "conditioning"} <= set(law)
    assert 0.8 * law["total"] < parts < law["total"]
    step = counted.instructions(config, state, "step_pinocchio", calls=20)
    assert step["loops"] > 0 and step["limits"] > 0 and step["total"] > law["total"] - law["operational"]


class _Given:
    """A race whose outputs are given: what :func:`eigen_law.differences` reads of one."""

    sides = ("ours", "pinocchio")

    def __init__(self, found):
        self.found = found

    def evaluate(self, config, states):
        return self.found


def test_differences_compare_each_output_on_its_scale_and_every_status():
    ours = {"F": np.array([[1.0, 2.0], [3.0, 4.0]]), "tau": np.array([[1e-3, 0.0], [1.0, 1.0]])}
    law = (np.array([0, 0]), ours)
    step = (np.array([0, 1]), {"tau": np.array([[1.0], [np.nan]])})
    found = {("law", "ours"): law, ("law", "pinocchio"): law, ("step", "ours"): step, ("step", "pinocchio"): step}
    assert eigen_law.differences(_Given(found), None, []) == {("law", "pinocchio"): 0.0, ("step", "pinocchio"): 0.0}
    # a millinewton off on an output of a millinewton is all of it, whatever the other outputs' sizes
    off = {"F": ours["F"], "tau": ours["tau"] + np.array([[1e-3, 0.0], [0.0, 0.0]])}
    got = eigen_law.differences(_Given({**found, ("law", "pinocchio"): (law[0], off)}), None, [])
    assert got["law", "pinocchio"] == pytest.approx(1.0)
    # each state's difference weighed by its scale (the conditioning: rounding grows as it falls)
    weighed = eigen_law.differences(_Given({**found, ("law", "pinocchio"): (law[0], off)}), None, [],
                                    np.array([0.25, 1.0]))
    assert weighed["law", "pinocchio"] == pytest.approx(0.25)
    # a status that differs is infinitely far; a state refused on both sides is compared on its status alone
    refused = (np.array([0, 0]), step[1])
    assert eigen_law.differences(_Given({**found, ("step", "pinocchio"): refused}), None, [])[
        "step", "pinocchio"] == np.inf


def test_without_a_package_the_comparison_is_skipped_in_one_line(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(eigen_race.pc, "prefix", lambda: tmp_path)  # an install prefix without the headers
    assert eigen_race.missing() == "no pinocchio/algorithm/crba.hpp (package pin): pip install pin"
    rows = []
    eigen_law.eigen_law_benchmarks("ur5", UR5[0].rsplit("/", 1)[-1], UR5[1], 1, True, lambda *a, **k: rows.append(a))
    err = capsys.readouterr().err
    assert not rows and err.count("\n") == 1 and "skipped ur5 against Pinocchio + Eigen: no " in err


def test_a_joint_the_program_cannot_build_is_refused_by_name(monkeypatch):
    pytest.importorskip("pinocchio")
    urdf = example_robot(UR5[0])
    robot = hybrid.Robot.from_urdf(urdf, tip=UR5[1])
    numbers = eigen_race.model_numbers(robot, urdf, UR5[1])
    # per joint 1 code + 1 parent + 12 placement + 3 axis + 1 mass + 3 lever + 9 inertia; the tip's 13;
    # gravity; four friction arrays
    assert len(numbers) == 30 * robot.n + 13 + 3 + 4 * robot.n
    assert numbers[:2] == [float(eigen_race.JOINTS.index("JointModelRZ")), 0.0]  # the UR5's shoulder pan
    monkeypatch.setattr(eigen_race, "JOINTS", ("JointModelRX",))
    with pytest.raises(hybrid.HybridError, match="joint 'shoulder_pan_joint' is a JointModelRZ"):
        eigen_race.model_numbers(robot, urdf, UR5[1])
