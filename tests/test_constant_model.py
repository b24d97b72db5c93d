"""A constant model (the robot's parameters compiled into its kernels) computes what the run-time-parameter
build computes with the same numbers; it is cached by the numbers exactly; its standalone C compiles strictly
and gives the same numbers; a robot array handed to it, or ``--constant-model`` without a URDF, is refused."""

from __future__ import annotations

import dataclasses
import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.cli.main import main
from hybrid.errors import HybridError
from hybrid.native import units
from hybrid.spec.chain import parameter_digest

ROOT = Path(__file__).resolve().parent.parent
CC = shutil.which("gcc") or shutil.which("cc")
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2"]
#: the largest difference from the run-time build, relative to the output's largest number
RTOL = 1e-12
#: where a kernel solves with the task Jacobian (its conditioning guarded), the same relative to its conditioning
#: ``c = 6 / (|J|_F |J^+|_F)``: rounding, which the two builds' orders of operations differ in, grows as ``1 / c``
RTOL_CONDITIONED = 5e-14


def with_friction(robot: hybrid.Robot, seed: int) -> hybrid.Robot:
    """``robot`` with its links perturbed, random viscous and Coulomb friction, offsets, smooth-sign speeds
    and a tilted gravity: no parameter left at 0 for the constant model to fold away."""
    rng = np.random.default_rng(seed)
    n = robot.n
    return dataclasses.replace(hybrid.perturbed_robot(robot, 0.3, seed=seed),
                               damping=tuple(rng.uniform(0.01, 0.5, n)), coulomb=tuple(rng.uniform(0.1, 2.0, n)),
                               offset=tuple(rng.normal(0, 0.3, n)), coulomb_speed=tuple(rng.uniform(0.02, 0.2, n)),
                               gravity=tuple(rng.normal(0, 1, 3) + (0.0, 0.0, -9.81)))


ROBOTS = {"ur5": hybrid.ur5, "panda": hybrid.panda,
          "perturbed ur5 with friction": lambda: with_friction(hybrid.ur5(), 4)}


def states(n: int, count: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    return {"q": rng.uniform(-np.pi, np.pi, (count, n)), "qd": rng.normal(0, 1, (count, n)),
            "qdd": rng.normal(0, 2, (count, n)), "tau": rng.normal(0, 10, (count, n))}


def assert_same(ours: dict, theirs: dict, where: str, rtol: float = RTOL) -> None:
    assert set(ours) == set(theirs)
    for name, b in theirs.items():
        a = ours[name]
        scale = np.abs(b).max()
        assert np.abs(a - b).max() <= rtol * scale, f"{where}: {name} differs by {np.abs(a - b).max() / scale:.1e}"


def conditioning(J: np.ndarray) -> float:
    """``6 / (|J|_F |J^+|_F)`` from NumPy's singular values."""
    s = np.linalg.svd(J, compute_uv=False)
    return float(6 / np.sqrt((s ** 2).sum() * (s ** -2.0).sum()))


@pytest.mark.parametrize("which", ROBOTS)
def test_each_constant_kernel_is_the_run_time_kernel_with_the_same_numbers(which):
    robot = ROBOTS[which]()
    fixed, given, params = robot.constant_unit, robot.unit, robot.as_array()
    names = [f["name"] for f in given.manifest["functions"]]
    assert [f["name"] for f in fixed.manifest["functions"]] == [*names, "constant_parameters"]
    x = states(robot.n, 50, seed=len(which))
    for name in names:
        f, g = fixed.function(name), given.function(name)
        assert [n for n, _ in g.inputs] == [*(n for n, _ in f.inputs), "robot"]
        args = [x[n] for n, _ in f.inputs]
        if f.per_state:  # all the states in one call
            assert_same(f.batch(*args), g.batch(*args, params), f"{which} {name}")
        else:
            tol = {"singular_tol": 0.0} if f.takes_singular_tol else {}
            for i in range(10):
                one = [a[i] for a in args]
                rtol = RTOL
                if f.takes_singular_tol:
                    J = given.function("robot_terms")(x["q"][i], x["qd"][i], params)["J"].reshape(6, robot.n)
                    rtol = max(RTOL, RTOL_CONDITIONED / conditioning(J))
                assert_same(f(*one, **tol), g(*one, params, **tol), f"{which} {name}, state {i}", rtol)
    np.testing.assert_array_equal(fixed.function("constant_parameters")()["robot"], params)
    model = fixed.manifest["model"]
    assert model["constant"] and model["robot"] == params.tolist()
    assert model["robot_sha256"] == parameter_digest(params) and "model" not in given.manifest


def test_the_constant_model_folds_what_the_numbers_make_trivial():
    """The UR5's centres of mass on their axes, zero products of inertia and no Coulomb friction: fewer
    operations than the run-time build (the numbers of the project's bench)."""
    api = pytest.importorskip("hybrid.codegen.api")
    ur5 = hybrid.ur5()
    kernels = {k.name: k for k in api.robot_kernels(ur5.chain)}
    folded = {k.name: k for k in api.constant_kernels(tuple(kernels.values()), ur5.as_array())[0]}
    for name in ("inverse_dynamics", "forward_dynamics", "robot_terms"):
        fixed, given = (api.kernel_function(k[name]).n_instructions() for k in (folded, kernels))
        assert fixed < 0.75 * given, name
        assert "robot" not in api.kernel_function(folded[name]).name_in()


def test_the_cache_key_tells_numbers_one_ulp_apart():
    ur5 = hybrid.ur5()
    params = ur5.as_array()
    key = units.constant_key(ur5.chain, params)
    keys = {json.dumps(key)}
    for i in range(len(params)):
        for toward in (-np.inf, np.inf):
            moved = params.copy()
            moved[i] = np.nextafter(moved[i], toward)
            keys.add(json.dumps(units.constant_key(ur5.chain, moved)))
    assert len(keys) == 1 + 2 * len(params)
    zero = int(np.flatnonzero(params == 0.0)[0])
    signed = params.copy()
    signed[zero] = -0.0
    assert units.constant_key(ur5.chain, signed) != key
    assert units.constant_key(ur5.chain, params.copy()) == key  # the same numbers: the same model


def test_a_robot_one_ulp_apart_is_another_constant_model():
    ur5 = hybrid.ur5()
    g = ur5.gravity
    moved = dataclasses.replace(ur5, gravity=(g[0], g[1], float(np.nextafter(g[2], 0.0))))
    assert moved.as_array()[-1] != ur5.as_array()[-1]
    assert ur5.constant_unit is hybrid.ur5().constant_unit  # cached in the process
    assert moved.constant_unit is not ur5.constant_unit
    assert moved.constant_unit.manifest["model"]["robot"][-1] == moved.gravity[2]
    assert moved.constant_unit.manifest["model"]["robot_sha256"] != ur5.constant_unit.manifest["model"]["robot_sha256"]


def test_a_robot_array_given_to_a_constant_kernel_is_refused():
    ur5 = hybrid.ur5()
    f = ur5.constant_unit.function("inverse_dynamics")
    q = np.zeros(6)
    with pytest.raises(HybridError, match="compiled in: call it with q, qd, qdd alone"):
        f(q, q, q, ur5.as_array())
    with pytest.raises(HybridError, match="compiled in"):
        f.batch(np.zeros((3, 6)), np.zeros((3, 6)), np.zeros((3, 6)), ur5.as_array())
    with pytest.raises(HybridError, match="compiled in: call it with no arrays"):
        ur5.constant_unit.function("constant_parameters")(ur5.as_array())
    with pytest.raises(HybridError, match="takes 4 arrays"):  # the run-time build's refusal is unchanged
        ur5.unit.function("inverse_dynamics")(q, q, q)


@pytest.mark.parametrize("extra", [[], ["--experiment", "tracing"],
                                   ["--urdf", "hybrid/data/ur5_robot.urdf", "--tip", "tool0", "--controller",
                                    "hybrid/data/controller_ur5_sphere.toml"]])
def test_constant_model_without_a_urdf_alone_is_refused(extra, tmp_path, capsys):
    assert main(["generate", "--constant-model", "--out", str(tmp_path / "out"), *extra]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: --constant-model") and "--urdf" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "out").exists()


MAIN_C = r"""
#include <stdio.h>
#include "panda.h"
int main(void) {
    const double q[PANDA_NQ] = {%(q)s}, qd[PANDA_NQ] = {%(qd)s}, qdd[PANDA_NQ] = {%(qdd)s};
    double tau[PANDA_NQ], robot[PANDA_ROBOT_SIZE];
    int i;
    if (panda_inverse_dynamics(q, qd, qdd, tau) != HYBRID_OK || panda_constant_parameters(robot) != HYBRID_OK)
        return 1;
    for (i = 0; i < PANDA_NQ; ++i) printf("%%.17g\n", tau[i]);
    return 0;
}
"""


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_the_command_writes_a_constant_model_that_compiles_strictly(tmp_path):
    out = tmp_path / "panda"
    proc = subprocess.run([sys.executable, "-m", "hybrid", "generate", "--urdf", "hybrid/data/panda.urdf", "--tip",
                           "panda_hand_tcp", "--constant-model", "--out", str(out), "--name", "panda"],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    manifest = json.loads((out / "panda.json").read_text())
    panda = hybrid.Robot.from_urdf(ROOT / "hybrid" / "data" / "panda.urdf", tip="panda_hand_tcp")
    assert manifest["model"]["robot"] == panda.as_array().tolist()
    for f in manifest["functions"]:
        assert "robot" not in [a["name"] for a in f["inputs"]], f["name"]
    x = {k: v[0] for k, v in states(7, 1, seed=9).items()}
    (tmp_path / "main.c").write_text(MAIN_C % {k: ", ".join(repr(float(v)) for v in x[k]) for k in ("q", "qd", "qdd")})
    exe = tmp_path / "main"
    build = subprocess.run([CC, *STRICT, str(tmp_path / "main.c"), str(out / "panda.c"), f"-I{out}", "-o", str(exe),
                            "-lm"], capture_output=True, text=True)
    assert build.returncode == 0 and not build.stderr, build.stderr
    tau = np.array([float(v) for v in subprocess.run([str(exe)], capture_output=True, text=True,
                                                     check=True).stdout.split()])
    given = panda.unit.function("inverse_dynamics")(x["q"], x["qd"], x["qdd"], panda.as_array())["tau"]
    assert np.abs(tau - given).max() <= RTOL * np.abs(given).max()
