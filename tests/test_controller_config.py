"""A controller described in a TOML file (:mod:`hybrid.control.config`), and ``generate --controller``.

Most controllers here share the shipped example's compiled unit (the UR5 on a sphere, all six axes):
only their run-time inputs differ. Three others are built: the posture task's (three axes), the
desired frame's, and none for the other surfaces (their files are read, not built).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import hybrid
from hybrid.cli.main import main
from hybrid.control.config import PathMotion, Source, key_lines, load_controller_config

EXAMPLE = Path(hybrid.__file__).resolve().parent / "data" / "controller_ur5_sphere.toml"
TEXT = EXAMPLE.read_text()


@pytest.fixture(scope="module")
def ur5():
    return hybrid.ur5()


@pytest.fixture(scope="module")
def example(ur5):
    return hybrid.read_controller_config(EXAMPLE, ur5)


def edited(*changes: tuple[str, str]) -> str:
    """The example with each ``old`` text replaced by ``new`` (each ``old`` must be in it once)."""
    text = TEXT
    for old, new in changes:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return text


def written(tmp_path, text: str) -> Path:
    path = tmp_path / "controller.toml"
    path.write_text(text)
    return path


def line_of(text: str, start: str) -> int:
    """The number of the first line that starts with ``start`` (comments are not)."""
    return next(n for n, s in enumerate(text.splitlines(), 1) if s.lstrip().startswith(start))


def inputs(ctrl) -> dict:
    return {k: v.copy() for k, v in ctrl.step_inputs().items()}


def changed(a, b) -> set[str]:
    """The names of the step inputs in which two controllers differ."""
    x, y = inputs(a), inputs(b)
    assert x.keys() == y.keys()
    return {k for k in x if x[k].shape != y[k].shape or not np.array_equal(x[k], y[k])}


# ------------------------------------------------------------------ the example


def test_the_example_is_the_controller_built_by_hand(example, ur5):
    by_hand = hybrid.Controller(
        ur5, hybrid.Sphere((0.5, 0.0, 0.2), 0.15), "task", axes="all", selection=("n",),
        gains=hybrid.Gains(KPv=40.0, KIv=200.0, KI2v=1000.0, KPf=2.0, KDf=90.0, KIf=25.0),
        force_reference=hybrid.Step(10.0, 20.0, 0.5), velocity_reference=hybrid.Step(0.15, 0.3, 1.5),
        sample_time=0.01, integral=True, curvature=False, frame="actual", frame_direction=(0.0, 0.0, 1.0),
        position_error=False, integral_limit=None, contact_loss=None, singular_tol=1e-3, posture=None,
        torque_limit="urdf", torque_step_limit=None, timing_tolerance=0.25)
    assert changed(example, by_hand) == set()
    assert example.step_variant() == by_hand.step_variant()
    for name in ("scheme", "axes", "selection", "gains", "sample_time", "integral", "curvature", "frame",
                 "frame_direction", "position_error", "integral_limit", "contact_loss", "singular_tol", "posture",
                 "timing_tolerance", "path"):
        assert getattr(example, name) == getattr(by_hand, name), name
    np.testing.assert_array_equal(example.torque_limit, ur5.limits.effort)  # "urdf": the file's limits
    assert np.isinf(example.torque_step_limit).all()
    # the tracing experiment's controller, on the arm as the URDF describes it (no model error)
    exp = hybrid.tracing_experiment()
    assert changed(example, hybrid.Controller(exp.robot, exp.surface, exp.controller, axes=exp.axes,
                                              **{**exp.controller_settings(), "path": None})) == set()


def test_the_example_controls_the_arm(example):
    exp = hybrid.tracing_experiment()
    x0 = exp.initial_state()
    example.reset()
    tau = example(0.0, x0[:6], x0[6:12], [0.0, 0.0, -10.0])
    assert tau.shape == (6,) and np.isfinite(tau).all() and np.abs(tau).max() > 1.0


def test_an_empty_file_but_its_surface_takes_the_controllers_defaults(tmp_path, ur5, example):
    path = written(tmp_path, '[surface]\nkind = "sphere"\ncenter = [0.5, 0.0, 0.2]\nradius = 0.15\n')
    ctrl = hybrid.read_controller_config(path, ur5)
    default = hybrid.Controller(ur5, hybrid.Sphere((0.5, 0.0, 0.2), 0.15))
    assert changed(ctrl, default) == set()
    assert changed(ctrl, example) == {"steps"}  # the example's references are steps; the default 10 N


# ------------------------------------------------------------------ each key, its input

VELOCITY = "velocity = { before = 0.15, after = 0.3, at = 1.5 }"
#: (an id, the example's texts and what replaces each, the step inputs that change)
CHANGES = [
    ("scheme", [('scheme = "task"', 'scheme = "khatib"')], {"options"}),
    ("sample_time", [("sample_time = 0.01 ", "sample_time = 0.005 ")], {"options"}),
    ("integral", [("integral = true", "integral = false")], {"gains"}),
    ("curvature", [("curvature = false", "curvature = true")], {"options"}),
    ("surface.center", [("center = [0.5, 0.0, 0.2]", "center = [0.5, 0.1, 0.2]")], {"surface"}),
    ("surface.radius", [("radius = 0.15 ", "radius = 0.2 ")], {"surface"}),
    ("task.selection", [('selection = ["n"]', 'selection = ["n", "rot_n"]')], {"selection", "gains"}),
    ("task.frame_direction", [("frame_direction = [0.0, 0.0, 1.0]", "frame_direction = [1.0, 0.0, 0.0]")], {"e"}),
    ("gains.KPv", [("KPv = 40.0", "KPv = 30.0")], {"gains"}),
    ("gains.KIv", [("KIv = 200.0", "KIv = 100.0")], {"gains"}),
    ("gains.KI2v", [("KI2v = 1000.0", "KI2v = 500.0")], {"gains"}),
    ("gains.KPf", [("KPf = 2.0", "KPf = 3.0")], {"gains"}),
    ("gains.KDf", [("KDf = 90.0", "KDf = 80.0")], {"gains"}),
    ("gains.KIf", [("KIf = 25.0", "KIf = 20.0")], {"gains"}),
    ("gains.n", [("# [gains.n]", "[gains.n]"), ("# KPf = 3.0", "KPf = 3.0")], {"gains"}),
    ("references.force", [("force = { before = 10.0, after = 20.0, at = 0.5 }", "force = 12.0")], {"steps"}),
    ("references.velocity", [(VELOCITY, VELOCITY.replace("1.5", "1.0"))], {"steps"}),
    ("references.velocity.AXIS", [(VELOCITY, "# velocity"), ("# [references.velocity]", "[references.velocity]"),
                                  ("# t1 = 0.15", "t1 = 0.15"), ("# rot_n = 0.0", "rot_n = 0.05")], {"steps"}),
    ("limits.torque", [('torque = "urdf"', "torque = 100.0")], {"limits"}),
    ("limits.torque_step", [('torque_step = "none"', "torque_step = [5.0, 5.0, 5.0, 2.0, 2.0, 2.0]")], {"limits"}),
    ("limits.integral", [('integral = "none"', "integral = 3.0")], {"options"}),
    ("contact_loss", [("# [contact_loss]", "[contact_loss]")], {"options"}),
]


CHANGES_BY_ID = [(c[0], c[1]) for c in CHANGES]


@pytest.mark.parametrize(("changes", "inputs_changed"), [c[1:] for c in CHANGES], ids=[c[0] for c in CHANGES])
def test_each_key_changes_its_step_input(tmp_path, ur5, example, changes, inputs_changed):
    ctrl = hybrid.read_controller_config(written(tmp_path, edited(*changes)), ur5)
    assert changed(ctrl, example) == inputs_changed


def test_each_key_changes_its_setting(tmp_path, ur5, example):
    """The keys and values the inputs above do not show: what they set, and how the step reads it."""
    def read(*changes):
        return hybrid.read_controller_config(written(tmp_path, edited(*changes)), ur5)

    steps = read(*dict(CHANGES_BY_ID)["references.velocity.AXIS"]).step_inputs()["steps"]
    np.testing.assert_array_equal(steps.reshape(6, 3)[[0, 2, 5]], [[0.15, 0.15, 0], [10, 20, 0.5], [0.05, 0.05, 0]])
    assert read(("singular_tol = 0.001", "singular_tol = 0.01")).singular_tol == 0.01
    assert read(("timing_tolerance = 0.25", "timing_tolerance = 0.1")).timing_tolerance == 0.1
    assert read(("timing_tolerance = 0.25", 'timing_tolerance = "none"')).timing_tolerance is None
    assert read(('torque = "urdf"', 'torque = "none"')).step_inputs()["limits"][:6].min() >= 1e300
    loss = read(("# [contact_loss]", "[contact_loss]"), ("# threshold = 0.5", "threshold = 1.5"))
    assert loss.contact_loss == hybrid.ContactLoss(1.5, 0.02)
    gains = read(*dict(CHANGES_BY_ID)["gains.n"]).gains
    assert gains[2] == hybrid.Gains(KPf=3.0) and gains[:2] + gains[3:] == (hybrid.Gains(),) * 5
    fisher = read(('scheme = "task"', 'scheme = "fisher_mujtaba"'))
    assert fisher.scheme.name == "fisher_mujtaba" and fisher.step_variant()["step"] == "raibert_craig_step"


def test_axes_and_posture(tmp_path, ur5, example):
    text = edited(('axes = "all"', 'axes = ["t1", "t2", "n"]'), ("# [posture]", "[posture]"),
                  ("# q_rest", "q_rest"), ("# stiffness = 25.0", "stiffness = 16.0"),
                  ("# damping = 10.0", "damping = [8.0, 8.0, 8.0, 4.0, 4.0, 4.0]"))
    ctrl = hybrid.read_controller_config(written(tmp_path, text), ur5)
    assert ctrl.axes == (0, 1, 2) and ctrl.step_variant()["step"] == "controller_posture_step"
    assert ctrl.posture == hybrid.Posture((0.0, -1.57, 1.57, -1.57, -1.57, 0.0), 16.0, (8.0,) * 3 + (4.0,) * 3)
    np.testing.assert_array_equal(ctrl.step_inputs()["posture"], ctrl.posture.as_array())
    named = hybrid.read_controller_config(written(tmp_path, edited(('axes = "all"', 'axes = "position"'))), ur5)
    assert named.axes == (0, 1, 2) and named.posture is None


def test_a_path_for_the_desired_frame_and_the_position_error(tmp_path, ur5):
    text = edited(('frame = "actual"', 'frame = "desired"'), ("position_error = false", "position_error = true"),
                  ("# [path]", "[path]"), ('# kind = "circle"', 'kind = "circle"'),
                  ("# center = [0.5, 0.0, 0.275]", "center = [0.5, 0.0, 0.275]"),
                  ("# radius = 0.1299", "radius = 0.1299"), ("# start = 0.0", "start = 0.02"))
    ctrl = hybrid.read_controller_config(written(tmp_path, text), ur5)
    assert ctrl.step_variant()["desired_frame"] and ctrl.step_variant()["position_error"]
    circle = hybrid.CirclePath((0.5, 0.0, 0.275), 0.1299, 0.02)
    assert ctrl.path == PathMotion(circle, hybrid.Step(0.15, 0.3, 1.5))
    # the desired point runs as an experiment's does along the same path, at the speed along t1
    exp = hybrid.tracing_experiment(path=circle, frame="desired")
    for t in (0.0, 0.7, 1.5, 2.9):
        for got, want in zip(ctrl.path(t), exp.desired_point(t)):
            np.testing.assert_allclose(got, want, atol=1e-12)
    line = load_controller_config(written(tmp_path, edited(
        ("position_error = false", "position_error = true"), ("# [path]", "[path]"),
        ('# kind = "circle"', 'kind = "line"'), ("# center = [0.5, 0.0, 0.275]", "point = [0.5, 0.0, 0.35]"),
        ("# radius = 0.1299", "direction = [0.0, 2.0, 0.0]"), ("force = { before", "force = 5.0 #"),
        ("velocity = { before", "velocity = 0.1 #"))))
    motion = line.keywords["path"]
    assert motion == PathMotion(hybrid.LinePath((0.5, 0.0, 0.35), (0.0, 1.0, 0.0)), hybrid.Step(0.1, 0.1, 0.0))
    np.testing.assert_allclose(motion(2.0)[0], [0.5, 0.2, 0.35])


SURFACES = [
    ('kind = "plane"\npoint = [0.5, 0.0, 0.1]\nnormal = [0.0, 0.0, 2.0]', hybrid.Plane((0.5, 0.0, 0.1), (0, 0, 1))),
    ('kind = "cylinder"\npoint = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\nradius = 0.1',
     hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.0, 1.0), 0.1)),
    ('kind = "circle"\ncenter = [0.5, 0.0]\nradius = 0.1', hybrid.Circle((0.5, 0.0), 0.1)),
]


@pytest.mark.parametrize(("table", "surface"), SURFACES, ids=["plane", "cylinder", "circle"])
def test_each_surface_kind(tmp_path, table, surface):
    text = edited(('kind = "sphere"', table.split("\n")[0]), ("center = [0.5, 0.0, 0.2]  # m, base axes", ""),
                  ("radius = 0.15 ", "\n".join(table.split("\n")[1:]) + "\n# "))
    assert load_controller_config(written(tmp_path, text)).surface == surface


def test_an_implicit_surface(tmp_path):
    path = written(tmp_path, '[surface]\nkind = "implicit"\nphi = "(x/a)**2 + (y/a)**2 + (z/b)**2 - 1"\n'
                             "parameters = { a = 0.3, b = 0.2 }\n")
    surface = load_controller_config(path).surface
    assert surface == hybrid.ImplicitSurface("(x/a)**2 + (y/a)**2 + (z/b)**2 - 1", {"a": 0.3, "b": 0.2})


# ------------------------------------------------------------------ refusals

#: (the example's text, what replaces it, the text on the line named, the key the error names, a part of its fix)
REFUSALS = [
    # unknown keys, with the nearest known one
    ("radius = 0.15 ", "radus = 0.15 ", "radus =", "surface.radus: unknown key", "did you mean 'radius'?"),
    ("sample_time = 0.01 ", "sampletime = 0.01 ", "sampletime =", "sampletime: unknown key",
     "did you mean 'sample_time'?"),
    ("KPv = 40.0", "kpv = 40.0", "kpv =", "gains.kpv: unknown key", "did you mean 'KPv'?"),
    ("[limits]", "[limit]", "[limit]", "limit: unknown key", "did you mean 'limits'?"),
    ("at = 0.5 }", "time = 0.5 }", "force =", "references.force.time: unknown key", "takes before, after, at"),
    ("# [contact_loss]", "[contact_loss]\nthreshhold = 1.0\n#", "threshhold", "contact_loss.threshhold: unknown key",
     "did you mean 'threshold'?"),
    # wrong types
    ("sample_time = 0.01 ", 'sample_time = "fast" ', "sample_time =", 'sample_time = "fast"', "give a number"),
    ("integral = true", "integral = 1", "integral = 1", "integral = 1", "give true or false"),
    ('selection = ["n"]', "selection = 2", "selection =", "task.selection = 2", "give the force-controlled axes"),
    ("center = [0.5, 0.0, 0.2]", 'center = "front"', "center =", 'surface.center = "front"', "a list of numbers"),
    ("KPf = 2.0", "KPf = -2.0", "KPf =", "gains.KPf = -2", "give a number >= 0"),
    ('torque = "urdf"', 'torque = "effort"', "torque =", 'limits.torque = "effort"',
     'give "urdf", "none" or a number'),
    ("force = { before = 10.0, after = 20.0, at = 0.5 }", "force = { before = 10.0, after = 20.0 }", "force =",
     "references.force: a step needs before, after and at", "add at"),
    ('axes = "all"', 'axes = ["t1", "nn"]', "axes =", 'task.axes = "nn"', 'did you mean "n"?'),
    # a surface that does not exist, or lacks a parameter
    ('kind = "sphere"', 'kind = "cone"', "kind =", 'surface.kind = "cone"', 'give one of "plane", "sphere"'),
    ('kind = "sphere"', 'kind = "sphre"', "kind =", 'surface.kind = "sphre"', 'did you mean "sphere"?'),
    ("radius = 0.15 ", "# ", "[surface]", "surface: a sphere needs radius", "add them to [surface]"),
    ("radius = 0.15 ", "radius = -0.15 ", "radius =", "surface.radius: Sphere.radius = -0.15 m",
     "give a positive radius"),
    # the Controller's refusals, with the key and its line
    ("sample_time = 0.01 ", "sample_time = -0.01 ", "sample_time =", "sample_time: sample_time = -0.01 s",
     "positive sample period"),
    ('torque = "urdf"', "torque = 0", "torque =", "limits.torque: torque_limit = 0.0", "one number > 0"),
    ('torque = "urdf"', "torque = [50.0, 50.0]", "torque =", "limits.torque: torque_limit = (50.0, 50.0)",
     "6 of them"),
    ("timing_tolerance = 0.25", "timing_tolerance = 1.5", "timing_tolerance =",
     "limits.timing_tolerance: timing_tolerance = 1.5", "between 0 and 1"),
    ("frame_direction = [0.0, 0.0, 1.0]", "frame_direction = [0.0, 0.0, 0.0]", "frame_direction =",
     "task.frame_direction: frame_direction = (0.0, 0.0, 0.0)", "give a nonzero direction"),
    ("force = { before = 10.0, after = 20.0, at = 0.5 }", "force = { t1 = 5.0 }", "force =",
     "references.force.t1: force_reference names axis t1", "move it to the other reference"),
    ('selection = ["n"]', 'selection = ["t1", "n"]', "velocity =",
     "references.velocity: velocity_reference names axis t1", "not a velocity-controlled axis"),
    ("# [posture]", "[posture]\nq_rest = [0.0, -1.57, 1.57, -1.57, -1.57, 0.0]\n#", "[posture]",
     "posture: a posture task acts in the task's null space", "axes='position'"),
]


@pytest.mark.parametrize(("old", "new", "at", "key", "fix"), REFUSALS, ids=[r[3].split(":")[0] for r in REFUSALS])
def test_a_refusal_names_the_key_its_line_and_the_fix(tmp_path, ur5, old, new, at, key, fix):
    text = edited((old, new))
    path = written(tmp_path, text)
    with pytest.raises(hybrid.HybridError) as info:
        hybrid.read_controller_config(path, ur5)
    first = str(info.value).splitlines()[0]
    assert first.startswith(f"{path}:{line_of(text, at)}: {key}"), first
    assert fix in first, first


def test_a_refusal_of_a_value_with_no_line(tmp_path, ur5):
    path = written(tmp_path, "sample_time = 0.01\n")
    with pytest.raises(hybrid.HybridError, match=r"controller.toml: surface: missing; add a \[surface\] table"):
        hybrid.read_controller_config(path, ur5)


def test_a_toml_syntax_error_gives_its_line(tmp_path, ur5):
    text = edited(("KPv = 40.0", "KPv = = 40.0"))
    path = written(tmp_path, text)
    with pytest.raises(hybrid.HybridError) as info:
        hybrid.read_controller_config(path, ur5)
    assert str(info.value).startswith(f"{path}:{line_of(text, 'KPv = =')}: not valid TOML: ")


def test_frame_and_path_go_together(tmp_path, ur5):
    text = edited(('frame = "actual"', 'frame = "desired"'))
    with pytest.raises(hybrid.HybridError, match=r":16: frame: needs the desired point's path: add a \[path\]"):
        hybrid.read_controller_config(written(tmp_path, text), ur5)
    text = edited(("# [path]", "[path]"), ('# kind = "circle"', 'kind = "circle"'))
    with pytest.raises(hybrid.HybridError, match=rf":{line_of(text, '[path]')}: path: a path is used only by"):
        hybrid.read_controller_config(written(tmp_path, text), ur5)


def test_an_unreadable_file(tmp_path, ur5):
    with pytest.raises(hybrid.HybridError, match="cannot read the controller file"):
        hybrid.read_controller_config(tmp_path / "missing.toml", ur5)


def test_key_lines_find_tables_keys_and_skip_values():
    text = "\n".join([
        'scheme = "task"  # [not.a.table]',       # 1
        "[surface]",                               # 2
        'kind = "implicit"',                       # 3
        'phi = """',                               # 4
        "x = 1",                                   # 5: inside a string
        '"""',                                     # 6
        "parameters = { a = 0.3, 'b' = 1 }",       # 7
        "[posture]",                               # 8
        "q_rest = [",                              # 9
        "  [1.0],",                                # 10: inside a list
        "  2.0 ]",                                 # 11
        'damping.x = 3',                           # 12
        '[ "gains" . n ]',                         # 13
        "KPf = 1",                                 # 14
    ])
    assert key_lines(text) == {
        ("scheme",): 1, ("surface",): 2, ("surface", "kind"): 3, ("surface", "phi"): 4,
        ("surface", "parameters"): 7, ("surface", "parameters", "a"): 7, ("surface", "parameters", "b"): 7,
        ("posture",): 8, ("posture", "q_rest"): 9, ("posture", "damping", "x"): 12, ("gains", "n"): 13,
        ("gains", "n", "KPf"): 14}
    where = Source(Path("c.toml"), key_lines(text))
    assert where.line(("posture", "damping", "x", "y")) == 12 and where.line(("gains", "n", "KDf")) == 13
    assert where.line(("task", "axes")) is None
    error = where.error(("gains", "n", "KDf"), "= -1: give a number >= 0")
    assert str(error) == "c.toml:13: gains.n.KDf = -1: give a number >= 0"
    assert str(where.error(("task",), "no line")) == "c.toml: task: no line"


# ------------------------------------------------------------------ the command line


@pytest.fixture
def recorded(monkeypatch):
    """``Controller.generate`` replaced by a recorder: what the command asked of it."""
    calls = []

    def generate(self, out, name=None, force=False):
        calls.append({"ctrl": self, "out": out, "name": name, "force": force})
        return [Path(out) / f"{name}.c", Path(out) / f"{name}.h"]

    monkeypatch.setattr(hybrid.Controller, "generate", generate, raising=False)
    return calls


def test_generate_with_a_controller_file(tmp_path, recorded, example, capsys, monkeypatch):
    monkeypatch.setattr("hybrid.cli.main.generate", lambda *a, **k: pytest.fail("the arm-only generator ran"))
    out = tmp_path / "c"
    args = ["generate", "--urdf", str(hybrid.UR5_URDF), "--tip", "tool0", "--controller", str(EXAMPLE),
            "--out", str(out), "--name", "ur5_sphere"]
    assert main(args + ["--force"]) == 0
    (call,) = recorded
    assert (Path(call["out"]), call["name"], call["force"]) == (out, "ur5_sphere", True)
    assert changed(call["ctrl"], example) == set() and call["ctrl"].step_variant() == example.step_variant()
    assert capsys.readouterr().out.strip() == f"wrote {out / 'ur5_sphere.c'}, {out / 'ur5_sphere.h'}"
    assert main(args) == 0 and recorded[1]["force"] is False


def test_generate_with_a_controller_file_refused(tmp_path, recorded, capsys):
    # a locked joint leaves five: the example's six task axes are too many, and the error says where
    args = ["generate", "--urdf", str(hybrid.UR5_URDF), "--tip", "tool0", "--controller", str(EXAMPLE),
            "--out", str(tmp_path), "--lock", "wrist_3_joint=0.5"]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"error: {EXAMPLE}:{line_of(TEXT, 'axes = ')}: task.axes: a 5-joint arm cannot control")
    bad = written(tmp_path, edited(("radius = 0.15 ", "radius = 0 ")))
    assert main(args[:6] + [str(bad), "--out", str(tmp_path)]) == 2
    assert f"{bad}:{line_of(TEXT, 'radius = ')}: surface.radius" in capsys.readouterr().err
    assert recorded == []


def test_generate_without_a_controller_file_is_unchanged(tmp_path, recorded, monkeypatch, capsys):
    calls = []
    monkeypatch.setattr("hybrid.cli.main.generate", lambda *a, **k: calls.append((a, k)) or [tmp_path / "x.c"])
    assert main(["generate", "--urdf", "arm.urdf", "--tip", "tool0", "--out", str(tmp_path), "--lock", "j1=0.5"]) == 0
    assert calls == [(("arm.urdf", "tool0", str(tmp_path), None, {"j1": 0.5}),
                      {"force": False, "constant_model": False})]
    assert recorded == []
    assert "--controller CONFIG.toml" in main_help(capsys)


def main_help(capsys) -> str:
    with pytest.raises(SystemExit):
        main(["generate", "--help"])
    return capsys.readouterr().out
