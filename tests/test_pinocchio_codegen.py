"""The benchmark against Pinocchio's code generation compares like with like: Pinocchio's generated C
(CppADCodeGen) and our generated dynamics give the same numbers on random states, for RNEA, forward
dynamics, CRBA and the terms, on the UR5 and the Panda; skipped where the C++ packages or a compiler
are missing. Correctness only: nothing here is timed."""

import numpy as np
import pytest
from conftest import PANDA, UR5, example_robot, pinocchio_model

import hybrid
from hybrid.bench import dynamics, pinocchio_codegen
from hybrid.native import units


# on a cold cache about 2 minutes of one core (the generator's C++ build; 4.5 minutes on a busy 2-core machine),
# seconds once it is cached
@pytest.mark.slow
@pytest.mark.parametrize("arm", [UR5, PANDA], ids=["ur5", "panda"])
def test_our_dynamics_give_the_numbers_of_pinocchios_generated_code(arm):
    urdf = example_robot(arm[0])
    why = pinocchio_codegen.missing()
    if why:
        pytest.skip(why)
    robot = hybrid.Robot.from_urdf(urdf, tip=arm[1])
    race = pinocchio_codegen.race(robot, urdf, arm[1])
    worst = dynamics.differences(race, dynamics.random_states(robot.n, 50, seed=7))
    assert set(worst) == {(f, side) for f in pinocchio_codegen.FUNCTIONS for side in ("ours", "constant")}
    assert max(worst.values()) <= 1e-12, worst


@pytest.mark.parametrize("arm", [UR5, PANDA], ids=["ur5", "panda"])
def test_the_inertia_unit_is_pinocchios_crba(arm, rng):
    """Our CRBA alone (the benchmark's side of CRBA) against Pinocchio's from Python: no C++ needed."""
    urdf = example_robot(arm[0])
    robot = hybrid.Robot.from_urdf(urdf, tip=arm[1])
    model = pinocchio_model(urdf, robot.joint_names)
    pin = pytest.importorskip("pinocchio")
    data, inertia = model.createData(), units.inertia_unit(robot.chain, robot.name).function("inertia")
    for q in rng.uniform(-np.pi, np.pi, (5, robot.n)):
        M = pin.crba(model, data, q)
        np.testing.assert_allclose(inertia(q, robot.as_array())["B"].reshape(robot.n, robot.n),
                                   np.triu(M) + np.triu(M, 1).T, rtol=1e-12, atol=1e-12)


class _Given:
    """A race whose outputs are given: what :func:`dynamics.differences` reads of one."""

    def __init__(self, n, outputs):
        self.n, self._outputs = n, outputs

    def evaluate(self, states):
        return self._outputs


def test_differences_compare_the_upper_triangle_and_each_part_on_its_own_scale():
    n = 2
    B = np.array([[2.0, 0.5], [0.5, 1.0]])
    terms = np.concatenate([np.full(3, 1e-3), np.ones(9 + 6 * n + 6 + n * n + n)])
    ones = np.ones((1, n))
    outputs = {"rnea": (ones, ones, ones), "aba": (ones, ones, ones),
               # our whole inertia against Pinocchio's upper triangle, row by row
               "crba": (B.reshape(1, -1), B.reshape(1, -1), np.array([[2.0, 0.5, 1.0]])),
               "terms": (terms[None, :], terms[None, :], terms[None, :])}
    assert max(dynamics.differences(_Given(n, outputs), None).values()) == 0.0
    # a lower triangle that is not the upper's is not compared: Pinocchio's CRBA gives the upper
    lower = B.copy()
    lower[1, 0] = 9.0
    crba = (lower.reshape(1, -1), B.reshape(1, -1), outputs["crba"][2])
    assert dynamics.differences(_Given(n, {**outputs, "crba": crba}), None)["crba", "ours"] == 0.0
    # the tip position's millimetres are compared with the position's scale, not the inertia's; each side alone
    shifted = terms.copy()
    shifted[0] += 1e-9
    got = dynamics.differences(_Given(n, {**outputs, "terms": (terms[None, :], shifted[None, :], terms[None, :])}),
                               None)
    assert got["terms", "constant"] == pytest.approx(1e-6) and got["terms", "ours"] == 0.0


def test_without_a_package_the_comparison_is_skipped_in_one_line(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(pinocchio_codegen, "prefix", lambda: tmp_path)  # an install prefix without the headers
    assert pinocchio_codegen.missing() == "no pinocchio/codegen/cppadcg-algo.hpp (package pin): pip install pin"
    rows = []
    dynamics.dynamics_benchmarks("ur5", UR5[0].rsplit("/", 1)[-1], UR5[1], 1, True, lambda *a, **k: rows.append(a))
    err = capsys.readouterr().err
    assert not rows and err.count("\n") == 1 and "skipped ur5 against Pinocchio's code generation: no " in err


def test_a_cxx_naming_no_program_is_said(monkeypatch):
    why = pinocchio_codegen.missing()
    if why:
        pytest.skip(why)
    monkeypatch.setenv("CXX", "no-such-compiler-here")
    assert pinocchio_codegen.missing().startswith("$CXX='no-such-compiler-here' names no program")
