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
    ("lower above upper", edited('lower="-2" upper="2"', 'lower="2" upper="-2"'),
     r"joint 'shoulder', <limit> at line \d+: lower=\"2\" is above upper=\"-2\""),
    ("prismatic lower above upper", edited('lower="-0.3" upper="0.3"', 'lower="0.31" upper="0.3"'),
     r"joint 'slide', <limit> at line \d+: lower=\"0.31\" is above upper"),
    ("negative effort", edited('effort="50"', 'effort="-50"'),
     r"joint 'shoulder', <limit> .*effort=\"-50\" is negative"),
    ("negative velocity", edited('effort="50" velocity="2"', 'effort="50" velocity="-0.1"'),
     r"joint 'shoulder', <limit> .*velocity=\"-0.1\" is negative"),
    ("negative tiny velocity", edited('velocity="1.0"', 'velocity="-1e-9"'), r"joint 'slide'.*velocity=\"-1e-09\""),
    ("negative zero-mass link", edited('<mass value="0.8"/>', '<mass value="-0.0001"/>'),
     r"link 'fore' \(line \d+\): mass -0.0001 kg is negative"),
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
    from hybrid.validate import MAX_PREFIX

    out = generate(path, "tool", tmp_path / "gen", name="x" * MAX_PREFIX)  # the longest name taken
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


def test_a_branch_of_thousands_of_links_is_merged(tmp_path):
    """Merging what hangs off the chain walks the tree without recursion: 5000 links in one branch."""
    n = 5000
    branch = "".join(f'<link name="b{i}"><inertial><mass value="0.001"/><inertia ixx="1e-7" ixy="0" ixz="0" '
                     f'iyy="1e-7" iyz="0" izz="1e-7"/></inertial></link><joint name="bj{i}" type="fixed">'
                     f'<parent link="{"upper" if i == 0 else f"b{i - 1}"}"/><child link="b{i}"/>'
                     '<origin xyz="0.0001 0 0"/></joint>' for i in range(n))
    plain = hybrid.Robot.from_urdf(write(tmp_path, SLIDER), tip="tool")
    robot = hybrid.Robot.from_urdf(write(tmp_path, edited("</robot>", branch + "</robot>")), tip="tool")
    assert robot.n == 3
    assert robot.links[1].mass == pytest.approx(plain.links[1].mass + n * 0.001)
    # a second deep branch off another link, through revolute joints held at 0
    revolute = branch.replace('type="fixed"', 'type="revolute"').replace(
        "</joint>", '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')
    revolute = revolute.replace('"upper"', '"fore"').replace('name="b', 'name="c').replace('link="b', 'link="c')
    both = hybrid.Robot.from_urdf(write(tmp_path, edited("</robot>", branch + revolute + "</robot>")), tip="tool")
    assert both.links[2].mass == pytest.approx(plain.links[2].mass + n * 0.001)


def long_arm(n: int) -> str:
    """A URDF of ``n`` revolute joints in series (links l0 .. l{n})."""
    parts = ['<robot name="long"><link name="l0"/>']
    for i in range(n):
        parts.append(f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
                     f'<origin xyz="0 0 0.1"/><axis xyz="{["0 0 1", "0 1 0"][i % 2]}"/>'
                     '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
                     f'<link name="l{i + 1}"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" '
                     'iyy="0.01" iyz="0" izz="0.01"/></inertial></link>')
    return "".join(parts) + "</robot>"


def test_long_chains_warn_then_are_refused(tmp_path):
    import warnings

    from hybrid.models.urdf import MAX_JOINTS, WARN_JOINTS

    path = write(tmp_path, long_arm(MAX_JOINTS + 50))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no warning below the threshold
        assert hybrid.Robot.from_urdf(path, tip=f"l{WARN_JOINTS}").n == WARN_JOINTS
    for n in (WARN_JOINTS + 1, MAX_JOINTS):
        with pytest.warns(hybrid.LargeModelWarning, match=rf"has {n} moving joints: .* takes about .*minute"):
            assert hybrid.Robot.from_urdf(path, tip=f"l{n}").n == n
    for n in (MAX_JOINTS + 1, MAX_JOINTS + 50):
        with pytest.raises(hybrid.URDFError, match=rf"has {n} moving joints; at most {MAX_JOINTS}") as info:
            hybrid.Robot.from_urdf(path, tip=f"l{n}")
        assert len(str(info.value).splitlines()) == 1
    # locking joints brings a long arm under the bound
    locked = {f"j{i}": 0.0 for i in range(60)}
    with pytest.warns(hybrid.LargeModelWarning):
        assert hybrid.Robot.from_urdf(path, tip=f"l{MAX_JOINTS + 50}", locked=locked).n == MAX_JOINTS - 10
    from hybrid.native.standalone import generate

    with pytest.raises(hybrid.URDFError, match="at most"):
        generate(path, f"l{MAX_JOINTS + 1}", tmp_path / "gen")
    assert not (tmp_path / "gen").exists()


@pytest.mark.parametrize("name, problem", [
    ("robôt", "non-ASCII character 'ô'"), ("ロボット", "non-ASCII"), ("arm\u200b", "U+200B"),
    ("1arm", "does not start with a letter"), ("_arm", "does not start with a letter"), ("", "it is empty"),
    ("my-arm", "the character '-'"), ("my arm", "the character ' '"), ("../arm", "the character '.'"),
    ("arm;", "the character ';'"), ("a" * 1001, "1001 characters"), (3, "not text"),
])
def test_a_bad_name_for_the_generated_c_is_refused(tmp_path, name, problem):
    from hybrid.native.standalone import generate

    with pytest.raises(hybrid.HybridError, match=f"--name .* cannot name C symbols and files: .*{re.escape(problem)}") \
            as info:
        generate(write(tmp_path, SLIDER), "tool", tmp_path / "gen", name=name)
    assert len(str(info.value).splitlines()) == 1 and len(str(info.value)) < 300
    assert not (tmp_path / "gen").exists()


def test_the_cli_refuses_a_non_ascii_name(tmp_path, capsys):
    from hybrid.cli.main import main

    assert main(["generate", "--urdf", str(write(tmp_path, SLIDER)), "--tip", "tool", "--out",
                 str(tmp_path / "gen"), "--name", "bras_à_ressort"]) == 2
    err = capsys.readouterr().err
    assert "cannot name C symbols" in err and "e.g. 'bras_a_ressort'" in err and len(err.splitlines()) == 1


@pytest.mark.parametrize("name", ["robôt", "ロボット", "ボ", "Ro bot✓", "1st arm", "_x", "", "ﬁne", "x" * 300,
                                  "a\udc80b", "αβ", "γδ"])
def test_derived_prefixes_are_ascii_c_names(name):
    from hybrid.validate import MAX_PREFIX, c_identifier, c_name_problem

    ident = c_identifier(name)
    assert ident.isascii() and c_name_problem(ident) is None and len(ident) <= MAX_PREFIX
    assert re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", ident)
    assert c_identifier("αβ") != c_identifier("γδ")  # names that lose every letter stay apart
    assert c_identifier("robôt") == "robot"


def test_non_ascii_robot_and_joint_names_give_ascii_c(tmp_path):
    """A URDF's own names may be anything: the files are ASCII, compile strictly, the manifest keeps the names."""
    import json
    import shutil
    import subprocess

    text = SLIDER.replace('name="slider_arm"', 'name="robôt✓"').replace('name="elbow"', 'name="ellbögen"') \
        .replace('name="shoulder"', 'name="肩 *??/&#10;/ #error boom"')
    path = write(tmp_path, text)
    out = generate_default(path, tmp_path / "gen")
    assert sorted(p.name for p in out)[0].startswith("robot_") and all(p.name.isascii() for p in out)
    for p in out:
        assert p.read_bytes().isascii(), p.name
    manifest = json.loads(next(p for p in out if p.suffix == ".json").read_text())
    assert [j["name"] for j in manifest["robot"]["joints"]] == ["slide", "肩 *??/\n/ #error boom", "ellbögen"]
    c = next(p for p in out if p.suffix == ".c")
    cc = shutil.which("gcc") or shutil.which("cc")
    proc = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-c", str(c), "-o",
                           str(tmp_path / "x.o")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[:2000]


def generate_default(path, out):
    from hybrid.native.standalone import generate

    return generate(path, "tool", out)
