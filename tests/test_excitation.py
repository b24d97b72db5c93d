"""Excitation trajectories (``hybrid.excitation_trajectory``): the limits hold between the samples too, the
series' derivatives are its derivatives and it repeats, the optimisation conditions the base regressor
and its data identify the arm; the CSV and the C header give back what ``sample`` gives; bad input is
refused with its limit named.

Kept small (few harmonics and samples, one restart): the optimisation's size, not its quality, is what the
tests need.
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pandas as pd
import pytest

import hybrid
from hybrid.models.excitation import DEFAULT_ACCELERATION
from hybrid.models.excitation_design import Design, Limits

PLANAR = hybrid.Robot.planar(hybrid.paper_arm())
#: a small optimisation
SMALL = {"harmonics": 3, "samples": 30, "restarts": 1, "iterations": 40}
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]


@pytest.fixture(scope="module")
def ur5_trajectory():
    return hybrid.excitation_trajectory(hybrid.ur5(), harmonics=4, samples=40, restarts=2, iterations=60)


@pytest.fixture(scope="module")
def planar_trajectory():
    return hybrid.excitation_trajectory(PLANAR, period=4.0, **SMALL, limits={"velocity": 2.0, "acceleration": 5.0})


def _between(trajectory, samples: int) -> np.ndarray:
    """Times off the trajectory's own grids: ten times as many as its samples, offset by a third of a step,
    and random ones."""
    T = trajectory.period
    grid = (np.arange(10 * samples) + 1 / 3) * T / (10 * samples)
    return np.concatenate([grid, np.random.default_rng(7).uniform(0, T, 500)])


def _assert_within(trajectory, lower, upper, velocity, acceleration, samples):
    q, qd, qdd = trajectory.sample(_between(trajectory, samples))
    assert (q >= lower).all() and (q <= upper).all(), (q.min(axis=0) - lower, upper - q.max(axis=0))
    assert (np.abs(qd) <= velocity).all(), velocity - np.abs(qd).max(axis=0)
    assert (np.abs(qdd) <= acceleration).all(), acceleration - np.abs(qdd).max(axis=0)
    return q


# ------------------------------------------------------------------------------------------------ limits


@pytest.mark.parametrize("make", [hybrid.ur5, hybrid.panda], ids=["ur5", "panda"])
def test_the_urdf_limits_times_the_safety_factor_hold_between_the_samples(make):
    robot = make()
    trajectory = hybrid.excitation_trajectory(robot, **SMALL, safety=0.8)
    lim = robot.limits
    middle, half = (lim.lower + lim.upper) / 2, 0.8 * (lim.upper - lim.lower) / 2
    q = _assert_within(trajectory, middle - half, middle + half, 0.8 * lim.velocity, DEFAULT_ACCELERATION,
                       SMALL["samples"])
    assert np.ptp(q, axis=0).min() > 0.05  # every joint moves


@pytest.mark.parametrize("seed", range(4))
def test_random_limits_and_boxes_hold_between_the_samples(seed):
    rng = np.random.default_rng(seed)
    robot = hybrid.ur5() if seed == 0 else PLANAR
    n = robot.n
    start = rng.uniform(-1.0, 1.0, n)
    limits = {"lower": start - rng.uniform(0.05, 1.5, n), "upper": start + rng.uniform(0.05, 1.5, n),
              "velocity": rng.uniform(0.1, 2.0, n), "acceleration": rng.uniform(0.5, 8.0, n)}
    tip = hybrid.arm_terms(robot, start, np.zeros(n))["r"]
    box = np.column_stack([tip - rng.uniform(0.05, 0.4, 3), tip + rng.uniform(0.05, 0.4, 3)])
    if seed == 3:
        box[2] = (-np.inf, np.inf)  # a side without bound
    trajectory = hybrid.excitation_trajectory(robot, period=5.0, start=start, limits=limits, box=box, seed=seed,
                                              **SMALL)
    q = _assert_within(trajectory, limits["lower"], limits["upper"], limits["velocity"], limits["acceleration"],
                       SMALL["samples"])
    r = hybrid.arm_terms(robot, q, np.zeros_like(q))["r"]
    assert (r >= box[:, 0]).all() and (r <= box[:, 1]).all()
    assert np.allclose(trajectory.sample(0.0)[0][0], start)  # made at rest: it starts where asked


def test_a_box_that_binds_is_kept_between_the_samples():
    robot = hybrid.ur5()
    tip = hybrid.arm_terms(robot, np.zeros(6), np.zeros(6))["r"]
    box = np.array([[-np.inf, np.inf], [-np.inf, np.inf], [tip[2] - 0.1, tip[2] + 0.1]])  # a slot 20 cm high
    times = np.linspace(0.0, 10.0, 5001)
    heights = {}
    for name, given in (("free", None), ("boxed", box)):
        q = hybrid.excitation_trajectory(robot, box=given, **SMALL).sample(times)[0]
        heights[name] = hybrid.arm_terms(robot, q, np.zeros_like(q))["r"][:, 2]
    assert np.ptp(heights["free"]) > 0.5  # without the box the tool leaves it
    z = heights["boxed"]
    assert (z >= box[2, 0]).all() and (z <= box[2, 1]).all()
    assert min(z.min() - box[2, 0], box[2, 1] - z.max()) < 0.01  # it uses the box


# --------------------------------------------------------------------------------------------- the series


def test_the_derivatives_are_those_of_the_positions_across_the_period_too(planar_trajectory):
    traj, h = planar_trajectory, 1e-5
    T = traj.period
    t = np.concatenate([np.linspace(0.0, T, 17), [T - 2e-5, 3 * T + 1e-5, -0.7 * T]])  # across the wrap
    q, qd, qdd = traj.sample(t)
    (q_hi, qd_hi, _), (q_lo, qd_lo, _) = traj.sample(t + h), traj.sample(t - h)
    assert np.allclose((q_hi - q_lo) / (2 * h), qd, rtol=1e-7, atol=1e-7)
    assert np.allclose((qd_hi - qd_lo) / (2 * h), qdd, rtol=1e-7, atol=1e-7)


def test_it_repeats_every_period_and_starts_at_rest(planar_trajectory):
    traj = planar_trajectory
    t = np.random.default_rng(1).uniform(0, traj.period, 50)
    for k in (1, 2, -3):
        for now, later in zip(traj.sample(t), traj.sample(t + k * traj.period)):
            assert np.allclose(now, later, rtol=0, atol=1e-12)
    q, qd, qdd = traj.sample([0.0, traj.period - 1e-9])
    assert np.allclose(q[0], traj.center) and np.allclose(qd, 0.0, atol=1e-8) and np.allclose(qdd, 0.0, atol=1e-7)


def test_without_rest_it_oscillates_about_the_start():
    traj = hybrid.excitation_trajectory(PLANAR, period=4.0, harmonics=1, samples=16, restarts=1, rest=False,
                                        limits={"velocity": 2.0, "acceleration": 5.0})
    q, qd, _ = traj.sample(np.linspace(0, 4.0, 400, endpoint=False))
    assert np.allclose(q.mean(axis=0), traj.center) and np.abs(qd[0]).max() > 1e-3


# ------------------------------------------------------------------------------------------- conditioning


def _condition(robot, q, qd, qdd) -> float:
    Y, _ = hybrid.regressor(robot, q, qd, qdd)
    W = hybrid.base_parameters(robot).regressor(Y).reshape(-1, len(hybrid.base_parameters(robot).independent))
    return float(np.linalg.cond(W))


def _filling_the_limits(trajectory, a, b, times) -> hybrid.ExcitationTrajectory:
    """The series of coefficients ``a``, ``b`` about the trajectory's centre, each joint scaled until its
    tightest limit is met at ``times``: a motion as large as the optimised one may be, not optimised."""
    lim, c = trajectory.limits, trajectory.center
    unit = hybrid.ExcitationTrajectory(trajectory.robot, trajectory.period, c, a, b, trajectory.samples)
    q, qd, qdd = unit.sample(times)
    scale = np.min([(lim["upper"] - c) / (q.max(axis=0) - c), (c - lim["lower"]) / (c - q.min(axis=0)),
                    lim["velocity"] / np.abs(qd).max(axis=0), lim["acceleration"] / np.abs(qdd).max(axis=0)], axis=0)
    return hybrid.ExcitationTrajectory(trajectory.robot, trajectory.period, c, a * scale[:, None], b * scale[:, None],
                                       trajectory.samples)


def test_the_optimised_condition_number_is_far_below_the_start_and_unoptimised_motion(ur5_trajectory):
    traj, robot = ur5_trajectory, hybrid.ur5()
    dense = (np.arange(10 * traj.samples) + 0.5) * traj.period / (10 * traj.samples)
    assert traj.condition == pytest.approx(_condition(robot, *traj.sample(dense)), rel=1e-9)
    assert traj.condition < traj.start_condition / 5
    rng = np.random.default_rng(3)
    plain = [_filling_the_limits(traj, rng.standard_normal(traj.a.shape), rng.standard_normal(traj.b.shape),
                                 dense).condition for _ in range(8)]
    assert traj.condition < np.median(plain) / 3, plain


def test_the_searchs_gradients_are_those_of_its_objective_and_constraints():
    robot, n = hybrid.panda(), 7
    box = np.array([[-2.0, 2.0], [-2.0, 2.0], [0.2, 1.0]])
    limits = Limits(np.full(n, -3.0), np.full(n, 3.0), np.full(n, 2.0), np.full(n, 2.0), box)
    design = Design(robot, hybrid.base_parameters(robot), 10.0, 3, np.array([0, 0, 0, -1.5, 0, 1.5, 0]), limits,
                    30, True)
    x, h = np.random.default_rng(1).normal(size=n * design.m) * 0.3, 1e-6

    def central(f):
        return np.array([(f(x + h * e) - f(x - h * e)) / (2 * h) for e in np.eye(len(x))]).T

    assert np.allclose(design.gradient(x), central(design.objective), rtol=0, atol=1e-3)
    for constraint in design.constraints():
        assert np.allclose(constraint["jac"](x), central(constraint["fun"]), rtol=0, atol=1e-6)


def test_its_data_identify_the_ur5s_base_parameters(ur5_trajectory):
    robot = hybrid.ur5()
    t = np.arange(200) * ur5_trajectory.period / 200
    q, qd, qdd = ur5_trajectory.sample(t)
    Y, _ = hybrid.regressor(robot, q, qd, qdd)
    found = hybrid.identify_dynamics(robot, t, q, Y @ hybrid.linear_parameters(robot), qd=qd, qdd=qdd, smooth=False,
                                     consistent=False)
    assert np.allclose(found.estimate, found.nominal, rtol=1e-7, atol=1e-9)
    assert found.condition == pytest.approx(_condition(robot, q, qd, qdd), rel=1e-9)


def test_the_same_seed_gives_the_same_trajectory_and_another_another():
    kw = {"period": 4.0, "harmonics": 3, "samples": 16, "restarts": 2, "iterations": 20}
    one, again, other = (hybrid.excitation_trajectory(PLANAR, seed=s, **kw) for s in (5, 5, 6))
    assert np.array_equal(one.a, again.a) and np.array_equal(one.b, again.b)
    assert not np.allclose(one.a, other.a)


# ------------------------------------------------------------------------------------------------- files


def test_the_csv_gives_back_the_samples(planar_trajectory, tmp_path):
    traj, path = planar_trajectory, tmp_path / "excitation.csv"
    assert traj.to_csv(path, rate=50.0, periods=2) == path
    table = pd.read_csv(path)
    names = PLANAR.joint_names
    assert list(table.columns) == ["t", *(f"{k}[{j}]" for k in ("q", "qd", "qdd") for j in names)]
    assert len(table) == 2 * 4.0 * 50 and np.allclose(np.diff(table["t"]), 1 / 50)
    q, qd, qdd = traj.sample(table["t"].to_numpy())
    for kind, values in (("q", q), ("qd", qd), ("qdd", qdd)):
        assert np.array_equal(table[[f"{kind}[{j}]" for j in names]].to_numpy(), values)
    with pytest.raises(hybrid.HybridError, match="exists"):
        traj.to_csv(path)
    traj.to_csv(path, rate=10.0, overwrite=True)
    assert len(pd.read_csv(path)) == 40 and sorted(p.name for p in tmp_path.iterdir()) == ["excitation.csv"]


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
def test_the_c_header_compiles_alone_and_gives_the_samples(ur5_trajectory, tmp_path):
    traj = ur5_trajectory
    traj.to_c(tmp_path / "ur5_excitation.h", prefix="ur5_excitation")
    with pytest.raises(hybrid.HybridError, match="exists"):
        traj.to_c(tmp_path / "ur5_excitation.h", prefix="ur5_excitation")
    alone = subprocess.run(["gcc", *STRICT, "-x", "c", "-c", "ur5_excitation.h", "-o", "alone.o"], cwd=tmp_path,
                           capture_output=True, text=True)
    assert alone.returncode == 0, alone.stderr
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include <stdlib.h>\n#include "ur5_excitation.h"\n#include "ur5_excitation.h"\n'
        "int main(int argc, char **argv) {\n"
        "    double q[UR5_EXCITATION_JOINTS], qd[UR5_EXCITATION_JOINTS], qdd[UR5_EXCITATION_JOINTS];\n"
        "    int i, j;\n"
        "    for (i = 1; i < argc; ++i) {\n"
        "        ur5_excitation_sample(atof(argv[i]), q, qd, qdd);\n"
        "        for (j = 0; j < UR5_EXCITATION_JOINTS; ++j) printf(\"%.17g %.17g %.17g \", q[j], qd[j], qdd[j]);\n"
        "        printf(\"\\n\");\n"
        "    }\n"
        "    return 0;\n"
        "}\n")
    built = subprocess.run(["gcc", *STRICT, "main.c", "-o", "main", "-lm"], cwd=tmp_path, capture_output=True,
                           text=True)
    assert built.returncode == 0, built.stderr
    t = np.array([0.0, 0.37, 1.9, 5.5, 9.99, 23.4, -3.3])
    ran = subprocess.run(["./main", *(repr(float(x)) for x in t)], cwd=tmp_path, capture_output=True, text=True,
                         check=True)
    got = np.array([[float(v) for v in line.split()] for line in ran.stdout.splitlines()]).reshape(len(t), 6, 3)
    for k, expected in enumerate(traj.sample(t)):
        assert np.allclose(got[:, :, k], expected, rtol=1e-12, atol=1e-12)


# ------------------------------------------------------------------------------------------------ refusals


REFUSED = [
    ({"period": 0.0}, "period = 0.0"), ({"period": float("nan")}, "period = nan"), ({"period": "10"}, "period"),
    ({"harmonics": 0}, "harmonics = 0"), ({"harmonics": 1}, "harmonics = 1"), ({"harmonics": 500}, "harmonics = 500"),
    ({"harmonics": 2.5}, "harmonics = 2.5"), ({"samples": 5}, "samples = 5"), ({"restarts": 0}, "restarts = 0"),
    ({"seed": -1}, "seed = -1"), ({"safety": 1.5}, "safety = 1.5"), ({"rest": "yes"}, "rest = 'yes'"),
    ({"limits": {"velocity": [1.0, 2.0, 3.0]}}, "limits\\['velocity'\\]"),
    ({"limits": {"lower": [np.nan, -1.0]}}, "NaN"), ({"limits": {"speed": 1.0}}, "key 'speed'"),
    ({"limits": [1.0, 2.0]}, "limits = "),
    ({"limits": {"lower": [-1.0, 0.5], "upper": [1.0, 0.5]}}, "joint 'joint2': the position range .* no width"),
    ({"limits": {"velocity": [1.0, 0.0]}}, "joint 'joint2': the velocity limit 0"),
    ({"limits": {"acceleration": np.inf}}, "joint 'joint1': the acceleration limit inf"),
    ({"limits": {"lower": [0.1, -1.0]}}, "joint 'joint1': the start 0 is not inside"),
    ({"start": [0.0, 0.0, 0.0]}, "start = "),
    ({"box": [[0.0, 1.0], [-1.0, 1.0]]}, "box = "),
    ({"box": [[0.8, 0.7], [-1.0, 1.0], [-1.0, 1.0]]}, "the box's x range .* is empty"),
    ({"box": [[0.0, 0.5], [-1.0, 1.0], [-1.0, 1.0]]}, "does not hold the tool's start x = 0.77"),
    ({"box": [[0.76, 0.78], [-1e-7, 1e-7], [-1.0, 1.0]]}, "the tool cannot move in the box"),
    ({"box": [[0.7699, 0.7701], [-1e-4, 1e-4], [-1.0, 1.0]]}, "does not excite the base parameters .*joint2"),
    ({"limits": {"velocity": [1.0, 1e-12]}}, "does not excite the base parameters .*joint2"),
]


def test_a_poorly_conditioned_trajectory_is_warned_of_naming_the_parameters():
    # joint 2 kept well below its Coulomb friction's smooth-sign speed (0.05 rad/s): its viscous and Coulomb
    # columns nearly proportional
    with pytest.warns(UserWarning, match="condition number is .*barely excites the base parameters .*joint2") as w:
        hybrid.excitation_trajectory(PLANAR, period=4.0, harmonics=2, samples=12, restarts=1, iterations=10,
                                     limits={"velocity": [2.0, 3e-3], "acceleration": 5.0})
    assert w[0].filename == __file__  # told at the caller's line
    # far below it they are proportional to rounding: refused, naming the parameter
    with pytest.raises(hybrid.HybridError, match=r"does not excite the base parameters damping\[joint2\]"):
        hybrid.excitation_trajectory(PLANAR, period=4.0, harmonics=2, samples=12, restarts=1, iterations=10,
                                     limits={"velocity": [2.0, 1e-4], "acceleration": 5.0})


@pytest.mark.parametrize(("kwargs", "message"), REFUSED, ids=[str(m)[:40] for _, m in REFUSED])
def test_bad_input_is_refused_naming_it(kwargs, message):
    kw = {"period": 4.0, "harmonics": 2, "samples": 12, "restarts": 1, "iterations": 10,
          "limits": {"velocity": 2.0, "acceleration": 5.0}} | kwargs
    with pytest.raises(hybrid.HybridError, match=message) as caught:
        hybrid.excitation_trajectory(PLANAR, **kw)
    assert len(str(caught.value).splitlines()[0]) <= 240


def test_bad_files_and_hand_made_trajectories_are_refused(planar_trajectory, tmp_path):
    for call, message in ((lambda: planar_trajectory.to_csv(tmp_path / "a.csv", rate=0.0), "rate = 0.0"),
                          (lambda: planar_trajectory.to_csv(tmp_path / "a.csv", periods=0), "periods = 0"),
                          (lambda: planar_trajectory.to_c(tmp_path / "a.h", prefix="2 bad"), "prefix '2 bad'"),
                          (lambda: planar_trajectory.sample([0.0, np.nan]), "t = "),
                          (lambda: hybrid.ExcitationTrajectory(PLANAR, 1.0, [0.0, 0.0], np.ones((2, 2)),
                                                               np.ones((2, 3))), "a has shape"),
                          (lambda: hybrid.ExcitationTrajectory(PLANAR, -1.0, [0.0, 0.0], np.ones((2, 2)),
                                                               np.ones((2, 2))), "period = -1.0"),
                          (lambda: hybrid.excitation_trajectory("ur5"), "robot must be")):
        with pytest.raises(hybrid.HybridError, match=message):
            call()
    assert not list(tmp_path.iterdir())


def test_many_unexcited_parameters_are_named_in_a_short_first_line():
    """Limits that leave the UR5 hardly any motion excite few of its base parameters: the first line names some
    and counts the rest, the next names them all."""
    with pytest.raises(hybrid.HybridError, match=r"does not excite the base parameters .* and \d+ more; give") as e:
        hybrid.excitation_trajectory(hybrid.ur5(), period=4.0, harmonics=2, samples=12, restarts=1, iterations=0,
                                     safety=1e-9)
    first, *rest = str(e.value).splitlines()
    assert len(first) <= 240 and len(rest) == 1 and "damping[wrist_3_joint]" in rest[0]
