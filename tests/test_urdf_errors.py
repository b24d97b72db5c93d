"""Bad URDF files and bad robot input: a URDFError / HybridError naming the element and line, never a crash."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import hybrid

SLIDER = (Path(__file__).parent / "data" / "slider_arm.urdf").read_text()


def write(tmp_path, text: str) -> Path:
    path = tmp_path / "arm.urdf"
    path.write_text(text)
    return path


def line_of(text: str, needle: str) -> int:
    return text[:text.index(needle)].count("\n") + 1


def edited(old: str, new: str) -> str:
    assert old in SLIDER
    return SLIDER.replace(old, new, 1)


CASES = [
    ("malformed", SLIDER.replace("</robot>", "</robt>"), r"not well-formed XML at line \d+"),
    ("not a robot", "<?xml version='1.0'?><model name='x'/>", r"root element is <model>"),
    ("floating on chain", edited('name="shoulder" type="revolute"', 'name="shoulder" type="floating"'),
     r"joint 'shoulder' \(line \d+\): a floating joint lies on the chain"),
    ("planar on chain", edited('name="shoulder" type="revolute"', 'name="shoulder" type="planar"'),
     r"joint 'shoulder' \(line \d+\): a planar joint lies on the chain"),
    ("mimic on chain", edited('<dynamics damping="0.2"/>', '<dynamics damping="0.2"/><mimic joint="shoulder"/>'),
     r"joint 'elbow' \(line \d+\): a mimic joint lies on the chain"),
    ("closed chain", edited("</robot>", '<joint name="loop" type="fixed"><parent link="camera"/>'
                                        '<child link="fore"/></joint></robot>'),
     r"joint 'loop' \(line \d+\): link 'fore' is already the child of joint 'elbow'.*closed"),
    ("inertia not PSD", edited('ixx="0.004" ixy="0.0002"', 'ixx="-0.004" ixy="0.0002"'),
     r"link 'upper' \(line \d+\): the inertia tensor is not positive semi-definite"),
    ("triangle inequality", edited('ixx="0.002" ixy="0" ixz="0.0001" iyy="0.006" iyz="0" izz="0.007"',
                                   'ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.007"'),
     r"link 'fore' \(line \d+\): the inertia tensor has principal moments .* triangle inequality"),
    ("negative mass", edited('<mass value="1.5"/>', '<mass value="-1.5"/>'),
     r"link 'upper' \(line \d+\): mass -1.5 kg is negative"),
    ("bad number", edited('xyz="0.3 0 0"', 'xyz="0.3 zero 0"'),
     r"joint 'elbow', <origin> at line \d+: xyz=\"0.3 zero 0\" must be 3 finite numbers"),
    ("zero axis", edited('<axis xyz="0 0.6 0.8"/>', '<axis xyz="0 0 0"/>'),
     r"joint 'elbow' \(line \d+\): the joint axis is zero"),
    ("unknown type", edited('name="elbow" type="continuous"', 'name="elbow" type="ball"'),
     r"joint 'elbow' \(line \d+\): unknown type 'ball'"),
    ("undefined link", edited('<child link="fore"/>', '<child link="forearm"/>'),
     r"joint 'elbow' \(line \d+\): its child link 'forearm' is not defined"),
    ("two roots", edited("</robot>", '<link name="stray"/></robot>'), r"expected one root link, found 2"),
]


@pytest.mark.parametrize("text, pattern", [pytest.param(t, p, id=i) for i, t, p in CASES])
def test_bad_urdf_names_the_element(tmp_path, text, pattern):
    with pytest.raises(hybrid.URDFError, match=pattern) as info:
        hybrid.Robot.from_urdf(write(tmp_path, text), tip="tool")
    assert len(str(info.value).splitlines()) == 1 and len(str(info.value)) < 300


def test_line_numbers_point_at_the_element(tmp_path):
    text = edited('name="shoulder" type="revolute"', 'name="shoulder" type="floating"')
    with pytest.raises(hybrid.URDFError) as info:
        hybrid.Robot.from_urdf(write(tmp_path, text), tip="tool")
    line = int(re.search(r"line (\d+)", str(info.value)).group(1))
    assert line == line_of(text, '<joint name="shoulder"')


def test_zero_mass_chain(tmp_path):
    text = re.sub(r'<mass value="[0-9.]+"/>', '<mass value="0"/>', SLIDER)
    text = re.sub(r'<inertia [^>]*/>', '<inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/>', text)
    with pytest.raises(hybrid.URDFError, match="zero mass"):
        hybrid.Robot.from_urdf(write(tmp_path, text), tip="tool")


def test_missing_file_tip_and_locked_names(tmp_path):
    with pytest.raises(hybrid.URDFError, match="cannot read the URDF file .*nothing.urdf"):
        hybrid.Robot.from_urdf(tmp_path / "nothing.urdf", tip="tool")
    path = write(tmp_path, SLIDER)
    with pytest.raises(hybrid.URDFError, match="no link named 'hand' for the tip; links are: .*tool"):
        hybrid.Robot.from_urdf(path, tip="hand")
    with pytest.raises(hybrid.URDFError, match="locked names joint 'wrist'"):
        hybrid.Robot.from_urdf(path, tip="tool", locked={"wrist": 0.0})
    with pytest.raises(hybrid.URDFError, match=r"locked\['gripper'\] = nan"):
        hybrid.Robot.from_urdf(path, tip="tool", locked={"gripper": float("nan")})
    with pytest.raises(hybrid.URDFError, match="no moving joint between the root 'world' and the tip 'base'"):
        hybrid.Robot.from_urdf(path, tip="base")
    with pytest.raises(hybrid.HybridError, match="tip must be a link name"):
        hybrid.Robot.from_urdf(path, tip=3)
    with pytest.raises(hybrid.HybridError, match="gravity"):
        hybrid.Robot.from_urdf(path, tip="tool", gravity=(0, -9.81))


def test_locking_a_chain_joint_and_off_chain_floating_joint(tmp_path):
    """Locking a joint on the chain removes it; a floating joint off the chain is simply held."""
    text = edited("</robot>", '<joint name="float" type="floating"><parent link="upper"/><child link="tag"/>'
                              '<origin xyz="0.1 0 0"/></joint><link name="tag"><inertial><mass value="0.05"/>'
                              '<inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/>'
                              '</inertial></link></robot>')
    path = write(tmp_path, text)
    robot = hybrid.Robot.from_urdf(path, tip="tool", locked={"shoulder": 0.3})
    assert robot.joint_names == ("slide", "elbow")
    assert hybrid.Robot.from_urdf(path, tip="tool").n == 3


def test_wrong_state_sizes_are_errors(tmp_path):
    robot = hybrid.Robot.from_urdf(write(tmp_path, SLIDER), tip="tool")
    with pytest.raises(hybrid.HybridError, match=r"q must have shape \(3,\), got \(2,\)"):
        hybrid.arm_terms(robot, np.zeros(2), np.zeros(3))
    with pytest.raises(hybrid.HybridError, match=r"qdot must have shape \(N, 3\) with N >= 1, got \(4, 2\)"):
        hybrid.arm_terms(robot, np.zeros((4, 3)), np.zeros((4, 2)))
    with pytest.raises(hybrid.HybridError, match="same number of rows"):
        hybrid.arm_terms(robot, np.zeros((4, 3)), np.zeros((5, 3)))
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input q"):
        hybrid.arm_terms(robot, [np.nan, 0, 0], np.zeros(3))
    with pytest.raises(hybrid.HybridError, match="must be real"):
        hybrid.arm_terms(robot, np.zeros(3) * 1j, np.zeros(3))


def test_model_changes_are_validated(tmp_path):
    robot = hybrid.Robot.from_urdf(write(tmp_path, SLIDER), tip="tool")
    with pytest.raises(hybrid.HybridError, match="no joint named 'wrist'"):
        robot.with_link("wrist", mass=1.0)
    with pytest.raises(hybrid.HybridError, match="mass of the link moved by 'elbow' is -1"):
        robot.with_link("elbow", mass=-1.0)
    with pytest.raises(hybrid.HybridError,
                       match="inertia of the link moved by 'elbow' has principal moments .* no rigid body"):
        robot.with_link("elbow", inertia=np.diag([1.0, 1.0, 3.0]))
    with pytest.raises(hybrid.HybridError, match=r"com of elbow must be finite numbers of shape \(3,\)"):
        robot.with_link("elbow", com=(0.0, 1.0))
    with pytest.raises(hybrid.HybridError, match="model_error = -1"):
        robot.with_model_error(-1.0)
    with pytest.raises(hybrid.HybridError, match="damping of joint 'elbow' is -1"):
        robot.with_link("elbow", damping=-1.0)



def test_a_loop_above_the_tip_is_an_error_not_a_hang(tmp_path):
    text = SLIDER.replace("</robot>", '<link name="ca"/><link name="cb"/>'
                          '<joint name="j1" type="revolute"><parent link="ca"/><child link="cb"/><axis xyz="0 0 1"/>'
                          '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
                          '<joint name="j2" type="revolute"><parent link="cb"/><child link="ca"/><axis xyz="0 0 1"/>'
                          '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>')
    with pytest.raises(hybrid.URDFError, match="form a closed loop"):
        hybrid.Robot.from_urdf(write(tmp_path, text), tip="ca")


@pytest.mark.parametrize("path", [None, 123, b"/tmp/x.urdf", "bad\x00path", "/dev/zero"])
def test_paths_that_are_not_urdf_files(path):
    with pytest.raises(hybrid.URDFError):
        hybrid.Robot.from_urdf(path, tip="tool")


def test_names_cannot_break_the_generated_c(tmp_path):
    """A joint name that would end a C comment, and a huge axis, still give C that compiles."""
    import shutil
    import subprocess

    text = SLIDER.replace('name="elbow"', 'name="el*/ #error boom /*bow"').replace(
        '<axis xyz="0 0.6 0.8"/>', '<axis xyz="0 6e200 8e200"/>')
    path = write(tmp_path, text)
    robot = hybrid.Robot.from_urdf(path, tip="tool")
    assert np.allclose(robot.chain.joints[2].axis, (0.0, 0.6, 0.8))
    from hybrid.native.standalone import generate

    out = generate(path, "tool", tmp_path / "gen", name="x" * 300)
    assert all(len(p.name) < 80 for p in out)
    c = next(p for p in out if p.suffix == ".c")
    cc = shutil.which("gcc") or shutil.which("cc")
    proc = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-c", str(c), "-o",
                           str(tmp_path / "x.o")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[:2000]


def test_a_massless_last_link_is_refused(tmp_path):
    robot = hybrid.Robot.from_urdf(write(tmp_path, SLIDER), tip="tool")
    with pytest.raises(hybrid.HybridError, match="last joint 'elbow' has no mass and no inertia"):
        robot.with_link("elbow", mass=0.0, inertia=np.zeros((3, 3)))
