"""`python -m hybrid generate`: deterministic standalone C99 for a URDF arm, compiled and run as the reference
page of the C interface (docs/reference/c_interface.md) shows."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import PANDA, UR5, example_robot

import hybrid

ROOT = Path(__file__).resolve().parent.parent
C_PAGE = (ROOT / "docs" / "reference" / "c_interface.md").read_text()
ARMS_PAGE = (ROOT / "docs" / "reference" / "arms_and_law.md").read_text()
CC = shutil.which("gcc") or shutil.which("cc")
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2"]


def generate(out: Path, spec, name: str, *extra: str, env=None) -> subprocess.CompletedProcess:
    path, tip = spec
    return subprocess.run([sys.executable, "-m", "hybrid", "generate", "--urdf", str(example_robot(path)),
                           "--tip", tip, "--out", str(out), "--name", name, *extra],
                          cwd=ROOT, capture_output=True, text=True, env=env)


def test_generate_is_deterministic_and_compiles_strictly(tmp_path):
    outs = []
    for seed in ("1", "4242"):
        proc = generate(tmp_path / seed, PANDA, "panda", env={**os.environ, "PYTHONHASHSEED": seed})
        assert proc.returncode == 0, proc.stderr
        outs.append({p.name: p.read_bytes() for p in sorted((tmp_path / seed).iterdir())})
    assert outs[0] == outs[1] and set(outs[0]) == {"panda.c", "panda.h", "panda.json"}
    assert not any(b"/tmp" in t or b"/work" in t for t in outs[0].values())  # no paths in the output
    c = tmp_path / "1" / "panda.c"
    proc = subprocess.run([CC, *STRICT, "-c", str(c), "-o", str(tmp_path / "panda.o")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    manifest = json.loads((tmp_path / "1" / "panda.json").read_text())
    terms = next(f for f in manifest["functions"] if f["name"] == "robot_terms")
    assert [a["name"] for a in terms["inputs"]] == ["q", "qd", "robot"]
    assert {a["name"]: a["shape"] for a in terms["outputs"]}["J"] == [6, 7]


def test_the_c_example_agrees_with_python(tmp_path):
    proc = generate(tmp_path / "ur5", UR5, "ur5")
    assert proc.returncode == 0, proc.stderr
    block = re.search(r"```c\n(.*?)```", C_PAGE, flags=re.S)
    assert block, "the C interface lost its C example"
    (tmp_path / "main.c").write_text(block.group(1))
    exe = tmp_path / "main"
    build = subprocess.run([CC, *STRICT, str(tmp_path / "main.c"), str(tmp_path / "ur5" / "ur5.c"),
                            f"-I{tmp_path / 'ur5'}", "-o", str(exe), "-lm"], capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.split("\n")
    p = np.array([float(v) for v in out[0].split()[1:]])
    n = np.array([float(line.split()[1]) for line in out[1:] if line])
    declared = {name: re.search(rf"\b{name}\[UR5_NQ\] = \{{(.*?)\}}", block.group(1))[1] for name in ("q", "qd")}
    q, qd = (np.array([float(v) for v in declared[name].split(",")]) for name in ("q", "qd"))
    ur5 = hybrid.Robot.from_urdf(example_robot(UR5[0]), tip="tool0")
    terms = hybrid.arm_terms(ur5, q, qd)
    np.testing.assert_allclose(p, terms["r"], rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(n, terms["n"], rtol=1e-12, atol=1e-12)


def test_the_robot_example_runs():
    blocks = re.findall(r"```python\n(.*?)```", ARMS_PAGE, flags=re.S)
    block = next(b for b in blocks if "Robot.from_urdf" in b)
    ns: dict = {}
    exec(compile(block, "arms_and_law.md", "exec"), ns)
    for key, value in ns["terms"].items():
        np.testing.assert_array_equal(ns["many"][key], np.tile(value, (100,) + (1,) * value.ndim))
    assert ns["panda"].n == 7 and ns["heavier"].links[6].mass == 1.5


def test_generate_refuses_to_overwrite_and_reports_bad_usage(tmp_path):
    out = tmp_path / "gen"
    assert generate(out, UR5, "ur5").returncode == 0
    assert generate(out, UR5, "ur5").returncode == 0  # same bytes: nothing to refuse
    mine = out / "ur5.c"
    mine.write_text("/* my edits */\n")
    proc = generate(out, UR5, "ur5")
    # the refusal is one line (beside a step told because it ran long, as on a loaded machine)
    told = [line for line in proc.stderr.splitlines() if not line.endswith(" ...")]
    assert proc.returncode == 2 and "--force" in proc.stderr and len(told) == 1
    assert mine.read_text() == "/* my edits */\n"  # nothing lost
    assert generate(out, UR5, "ur5", "--force").returncode == 0 and "my edits" not in mine.read_text()
    afile = tmp_path / "afile"
    afile.write_text("x")
    proc = generate(afile, UR5, "ur5")
    assert proc.returncode == 2 and "is a file" in proc.stderr
    proc = generate(tmp_path / "x", ("ur_description/urdf/ur5_robot.urdf", "hand"), "ur5")
    assert proc.returncode == 2 and proc.stderr.startswith("error: ") and "no link named 'hand'" in proc.stderr
    proc = generate(tmp_path / "y", UR5, "ur5", "--lock", "elbow_joint=abc")
    assert proc.returncode == 2 and "JOINT=POSITION" in proc.stderr


@pytest.mark.parametrize("name, ident", [("ur5", "ur5"), ("my-arm 2", "my_arm_2"), ("7dof", "robot_7dof")])
def test_prefix_is_a_c_identifier(name, ident):
    from hybrid.validate import c_identifier

    assert c_identifier(name) == ident


def test_the_controller_c_example_is_the_python_controller(tmp_path):
    """The C interface's controller example, generated from the shipped TOML by the command it gives, built
    strictly and run: its torque is the Python controller's of the same file, gains changed alike."""
    config = ROOT / "hybrid" / "data" / "controller_ur5_sphere.toml"
    proc = generate(tmp_path / "ur5s", UR5, "ur5s", "--controller", str(config))
    assert proc.returncode == 0, proc.stderr
    block = re.findall(r"```c\n(.*?)```", C_PAGE, flags=re.S)[1]
    assert "ur5s_controller_step" in block, "the C interface lost its controller C example"
    (tmp_path / "step.c").write_text(block)
    exe = tmp_path / "step"
    build = subprocess.run([CC, *STRICT, str(tmp_path / "step.c"), str(tmp_path / "ur5s" / "ur5s.c"),
                            f"-I{tmp_path / 'ur5s'}", "-o", str(exe), "-lm"], capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.split("\n")
    tau_c = np.array([float(line.split()[1]) for line in out if line.startswith("tau")])
    assert not [line for line in out if line.startswith("sample")]  # every sample OK
    changed = tmp_path / "changed.toml"
    changed.write_text(config.read_text() + "\n[gains.n]\nKPf = 3.0\n")
    ctrl = hybrid.read_controller_config(changed, hybrid.Robot.from_urdf(example_robot(UR5[0]), tip="tool0"))
    q = np.array([0.0, 0.63, -2.25, -1.0, -1.57, 0.0])
    for k in range(3):
        tau = ctrl(k * ctrl.sample_time, q, np.zeros(6), np.array([0.0, 0.0, 10.0, 0.0, 0.0, 0.0]))
    np.testing.assert_allclose(tau_c, tau, rtol=1e-12, atol=1e-12 * np.abs(tau).max())
