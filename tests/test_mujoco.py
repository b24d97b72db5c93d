"""MuJoCo as the plant of every experiment: the generated plant's physics, integrated by an independent
rigid-body engine from its own reading of the robot's URDF, agrees with the generated plant."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hybrid
from hybrid.models.chain_terms import robot_terms
from hybrid.plants import mujoco as mujoco_plant

mujoco = pytest.importorskip("mujoco")

#: the agreement asked of the two plants, RMS over the run: normal force [N], tangential speed [m/s]
FORCE_TOL, SPEED_TOL = 1e-3, 1e-4
#: what the same physics reaches (the same RMS): rounding, about 1e-13 N in the 3-D runs, amplified in
#: the paper's by the sticking friction to about 1e-10 N (as much as a one-ulp change of the start
#: state moves them); a friction or contact formula off by 0.1 % exceeds the 3-D bounds
ROUNDING = {"planar": (1e-7, 1e-8), "spatial": (1e-9, 1e-10)}


def rms(x):
    return float(np.sqrt(np.mean(np.square(x))))


def assert_close(force, speed, kind):
    """Both differences within the bounds asked and within rounding of the same physics."""
    assert force < min(FORCE_TOL, ROUNDING[kind][0])
    assert speed < min(SPEED_TOL, ROUNDING[kind][1])


def assert_agrees(exp, kind="spatial"):
    ours, theirs = hybrid.simulate(exp), hybrid.simulate(exp, plant="mujoco")
    assert len(theirs.t) == len(ours.t)
    assert_close(rms(ours.force_normal - theirs.force_normal),
                 rms(ours.velocity_tangential - theirs.velocity_tangential), kind)
    # the same result object: the metrics of both runs are the same quantities, and equal
    assert set(theirs.metrics) == set(ours.metrics)
    assert theirs.metrics["rms_force_error_N"] == pytest.approx(ours.metrics["rms_force_error_N"], rel=1e-6)
    return ours


PAPER = {"task": dict(), "khatib": dict(controller="khatib", duration=1.0),
         "no-integral": dict(integral=False, duration=1.0),
         "plane": dict(surface=hybrid.Plane((0.3, 0.0), (-1.0, 0.0)), start_point=(0.3, 0.1), duration=1.0),
         "gravity": dict(arm=hybrid.Arm(**{**vars(hybrid.paper_arm()), "gravity": 9.81}), duration=1.0)}


@pytest.mark.parametrize("settings", PAPER.values(), ids=PAPER.keys())
def test_paper_experiment_agrees(settings):
    assert_agrees(hybrid.paper_experiment(**settings), "planar")


def test_ur5_experiment_agrees():
    res = assert_agrees(hybrid.tracing_experiment(duration=0.6))  # past the force step at 0.5 s
    assert res.force_normal[-1] > 15


def test_panda_experiment_agrees():
    """The whole default run, its posture task on and both references stepping within it."""
    exp = hybrid.panda_experiment()
    res = assert_agrees(exp)
    assert res.force_normal[-1] == pytest.approx(exp.force_reference.after, abs=0.1)
    assert res.velocity_tangential[-1] == pytest.approx(exp.speed_reference.after, abs=1e-3)


def surfaces(exp):
    """A plane, a cylinder and an implicit ellipsoid through the UR5 experiment's start point."""
    p0 = exp.start()
    c = np.array(exp.surface.center)
    d = p0 - c
    a = 0.2  # the ellipsoid's horizontal semi-axis; the vertical one puts p0 on it
    b = abs(d[2]) / np.sqrt(1 - (d[0] ** 2 + d[1] ** 2) / a**2)
    return {"plane": hybrid.Plane(tuple(p0), tuple(exp.surface.normal_at(p0))),
            "cylinder": hybrid.Cylinder(tuple(c), (0.0, 0.0, 1.0), float(np.hypot(d[0], d[1]))),
            "implicit": hybrid.ImplicitSurface("((x - cx)/a)**2 + ((y - cy)/a)**2 + ((z - cz)/b)**2 - 1",
                                               {"cx": c[0], "cy": c[1], "cz": c[2], "a": a, "b": b})}


@pytest.mark.parametrize("kind", ["plane", "cylinder", "implicit"])
def test_every_surface_gives_the_same_contact(kind):
    """From the start state with the tip sliding at 5 cm/s and the torque holding the arm against
    gravity and the sensor's preload, both plants integrate 0.1 s alike (in contact throughout)."""
    base = hybrid.tracing_experiment()
    exp = hybrid.tracing_experiment(surface=surfaces(base)[kind], start_point=tuple(base.start()))
    generated, mj = exp.plant(), mujoco_plant.mujoco_plant(exp)
    x0 = exp.initial_state()
    n = exp.robot.n
    terms = robot_terms(exp.robot, x0[:n], np.zeros(n))
    slide = np.cross(exp.surface.normal_at(x0[2 * n:2 * n + 3]), [0.0, 0.0, 1.0])
    x0[n:2 * n] = np.linalg.pinv(terms["J"]) @ np.concatenate([0.05 * slide / np.linalg.norm(slide), np.zeros(3)])
    tau = terms["n"] - terms["J"][:3].T @ generated.sensor_wrench(x0)[:3]
    steps = 1000
    runs = []
    for plant in (generated, mj):
        x, trajectory = x0.copy(), np.empty((steps, len(x0)))
        assert plant.advance(x, tau, steps, trajectory) == steps
        runs.append(generated.outputs(trajectory))
    columns = generated.record["outputs"]
    N, v = columns.index("N"), columns.index("sensor_v_slide")
    assert runs[0][:, N].min() > 1.0
    assert runs[0][:, v].max() > 0.01
    assert_close(rms(runs[0][:, N] - runs[1][:, N]), rms(runs[0][:, v] - runs[1][:, v]), "spatial")


ODD_URDF = """<robot name="odd">
  <link name="base"/>
  <joint name="a" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.1" rpy="0.3 -0.2 0.5"/><axis xyz="0 0 2"/><limit lower="-2" upper="2" effort="1" velocity="1"/>
  </joint>
  <link name="l1"/>
  <joint name="b" type="prismatic"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.2 0 0" rpy="1.2 0.1 -0.4"/><axis xyz="1 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
    <dynamics damping="0.4" friction="0.3"/></joint>
  <link name="l2"><inertial><origin xyz="0.1 0.02 0"/><mass value="0"/>
    <inertia ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="c" type="continuous"><parent link="l2"/><child link="l3"/>
    <origin xyz="0 0.3 0" rpy="0 1.5707963 0"/><axis xyz="0 1 0"/></joint>
  <link name="l3"><inertial><origin xyz="0.1 0.02 0.05" rpy="0.2 0.3 0.1"/><mass value="1.5"/>
    <inertia ixx="0.02" iyy="0.03" izz="0.04" ixy="0.001" ixz="0.002" iyz="-0.001"/></inertial>
    <collision><geometry><mesh filename="package://nowhere/l3.stl"/></geometry></collision></link>
  <joint name="off" type="revolute"><parent link="l3"/><child link="l4"/>
    <origin xyz="0.1 0 0.1"/><axis xyz="1 0 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="l4"><inertial><origin xyz="0.1 0.05 0.02"/><mass value="0.7"/>
    <inertia ixx="0.01" iyy="0.02" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="to_tip" type="fixed"><parent link="l3"/><child link="tip"/>
    <origin xyz="0.2 0.1 0" rpy="0 0 0.3"/></joint>
  <link name="tip"/>
</robot>
"""


def arm_robots(tmp_path):
    """Robots MuJoCo reads from their URDF files, and robots it is given written from their parameters."""
    odd = tmp_path / "odd.urdf"
    odd.write_text(ODD_URDF)
    ur5 = hybrid.tracing_experiment().robot
    return {"ur5": (ur5, True), "panda": (hybrid.panda_experiment().robot, True),
            # a revolute and a prismatic joint, a massless link, an unreadable mesh, a joint locked at 0.7 rad
            "odd": (hybrid.Robot.from_urdf(odd, tip="tip", locked={"off": 0.7}), True),
            "planar": (hybrid.Robot.planar(hybrid.paper_arm()), False),
            "ur5-heavier": (ur5.with_link("wrist_1_joint", mass=2.0, damping=0.3), False)}


@pytest.mark.parametrize("key", ["ur5", "panda", "odd", "planar", "ur5-heavier"])
def test_mujoco_reads_the_robots_dynamics(key, tmp_path, rng):
    """MuJoCo's own reading of a URDF gives the generated B(q) and n(q, q') (Coriolis, gravity,
    viscosity; less the Coulomb friction the plant adds) at random states: an independent check of the URDF
    reading and of the rigid-body terms."""
    robot, from_file = arm_robots(tmp_path)[key]
    spec, source = mujoco_plant.arm_spec(robot)
    assert (source is not None) == from_file
    model = spec.compile()
    data = mujoco.MjData(model)
    assert model.nv == robot.n
    M = np.zeros((model.nv, model.nv))
    # MuJoCo's passive-force callback is one for the whole process: the model's own passive forces only here
    callback = mujoco.get_mjcb_passive()
    mujoco.set_mjcb_passive(None)
    try:
        states = []
        for _ in range(4):
            data.qpos[:] = rng.uniform(-np.pi, np.pi, robot.n)
            data.qvel[:] = rng.normal(0, 1, robot.n)
            mujoco.mj_forward(model, data)
            M_k = np.zeros_like(M)
            mujoco.mj_fullM(model, data, M_k)
            states.append((data.qpos.copy(), data.qvel.copy(), M_k, data.qfrc_bias - data.qfrc_passive))
    finally:
        mujoco.set_mjcb_passive(callback)
    for qpos, qvel, M, bias in states:
        terms = robot_terms(robot, qpos, qvel)
        scale = np.abs(terms["B"]).max()
        np.testing.assert_allclose(M, terms["B"], rtol=0, atol=1e-11 * scale)
        # the joints' Coulomb friction and offsets are the plant's passive forces, not the model's (the odd arm's
        # prismatic joint has a <dynamics friction>): MuJoCo's model has the rest of n
        smooth_sign = np.tanh(qvel / np.asarray(robot.coulomb_speed))
        n = terms["n"] - np.asarray(robot.coulomb) * smooth_sign - np.asarray(robot.offset)
        np.testing.assert_allclose(bias, n, rtol=0,
                                   atol=1e-10 * max(1.0, np.abs(n).max()))


def test_a_model_mujoco_reads_otherwise_is_refused(monkeypatch):
    read = mujoco_plant.arm_spec

    def heavier(robot):
        spec, source = read(robot)
        spec.body("wrist_1_link").mass *= 1.01
        return spec, source

    monkeypatch.setattr(mujoco_plant, "arm_spec", heavier)
    with pytest.raises(hybrid.HybridError, match="^MuJoCo's model of 'ur5' differs from the robot's at q = .*mass "
                                                 "matrix by .*ur5_robot.urdf: check its inertial"):
        hybrid.simulate(hybrid.tracing_experiment(duration=0.1), plant="mujoco")


def test_a_diverging_run_stops_where_the_generated_one_does():
    exp = hybrid.paper_experiment(model_error=2.0, allow_unstable=True)  # the force loop unstable
    stops = []
    for plant in ("generated", "mujoco"):
        with pytest.raises(hybrid.SimulationError, match="NaN or infinite") as info:
            hybrid.simulate(exp, plant=plant)
        stops.append(info.value.time)
    # in the same control sample: the last one's growth is so steep that rounding moves the step it overflows at
    assert stops[0] // exp.sample_time == stops[1] // exp.sample_time


def test_mujoco_refuses_what_it_cannot_run(monkeypatch):
    with pytest.raises(hybrid.HybridError, match="plant ="):
        hybrid.simulate(hybrid.paper_experiment(duration=0.1), plant="bullet")
    with monkeypatch.context() as patched:  # an older MuJoCo, which reads the Panda otherwise
        patched.setattr(mujoco, "__version__", "3.12.0")
        with pytest.raises(hybrid.HybridError, match=r"^the MuJoCo plant needs MuJoCo 3\.14 or later, found 3\.12\.0: "
                                                     r"pip install -U"):
            hybrid.simulate(hybrid.paper_experiment(duration=0.1), plant="mujoco")
    monkeypatch.setitem(sys.modules, "mujoco", None)  # as if not installed
    for exp in (hybrid.paper_experiment(duration=0.1), hybrid.tracing_experiment(duration=0.1)):
        with pytest.raises(hybrid.HybridError, match=r"^the MuJoCo plant needs MuJoCo: pip install "
                                                     r"'hybrid-decoupling\[mujoco\]'"):
            hybrid.simulate(exp, plant="mujoco")


def test_the_plant_module_imports_mujoco_only_when_used():
    code = "import sys, hybrid, hybrid.plants.mujoco; print('mujoco' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


# ------------------------------------------------------------------ the surface, through its methods


class CountedSphere(hybrid.Sphere):
    """A sphere of a class the plant never heard of, that counts the plant's reads of its ``phi``."""

    def phi_function(self):
        sphere = super().phi_function()

        def counted(p):
            self.reads.append(1)
            return sphere(p)
        return counted

    @property
    def reads(self) -> list:
        return self.__dict__.setdefault("_reads", [])


def test_the_plant_reads_the_surface_through_its_methods():
    """A surface's own ``phi_function`` is all the plant knows of it: a subclass's is called, and gives
    what its base gives, to the bit."""
    runs = []
    for surface_class in (hybrid.Sphere, CountedSphere):
        base = hybrid.tracing_experiment()
        exp = hybrid.tracing_experiment(surface=surface_class(base.surface.center, base.surface.radius))
        plant, x = mujoco_plant.mujoco_plant(exp), exp.initial_state()
        trajectory = np.empty((50, len(x)))
        tau = robot_terms(exp.robot, x[:exp.robot.n], np.zeros(exp.robot.n))["n"]
        assert plant.advance(x, tau, 50, trajectory) == 50
        runs.append(trajectory)
    assert len(exp.surface.reads) == 4 * 50  # once per RK4 stage
    np.testing.assert_array_equal(runs[0], runs[1])


def numeric_formula(surface):
    """``phi`` at a point from the surface's ``formula`` alone, in floats."""
    theta = surface.as_array()
    return lambda p: float(surface.formula(p, theta, np.sqrt))


@pytest.mark.parametrize("key", ["plane", "cylinder", "sphere", "implicit", "user"])
def test_phi_function_is_the_formula_and_its_gradient(key, rng):
    """What the plant reads of every surface, a user's too, against its ``formula`` (or ``phi``) at random
    points, the gradient against central differences."""
    base = hybrid.tracing_experiment()
    shapes = {**surfaces(base), "sphere": base.surface, "user": CountedSphere((0.1, -0.2, 0.3), 0.25)}
    surface = shapes[key]
    if key == "implicit":
        import sympy as sp

        values = {sp.Symbol(k, real=True): v for k, v in surface.parameters.items()}
        phi = sp.lambdify(sp.symbols("x y z", real=True), surface.phi.xreplace(values))
        formula = lambda p: float(phi(*p))  # noqa: E731
    else:
        formula = numeric_formula(surface)
    read, h = surface.phi_function(), 1e-6
    for p in rng.uniform(-0.6, 0.6, (20, 3)):
        value, grad = read(p)
        assert value == pytest.approx(formula(p), rel=1e-12, abs=1e-14)
        differences = [(formula(p + h * e) - formula(p - h * e)) / (2 * h) for e in np.eye(3)]
        np.testing.assert_allclose(grad, differences, rtol=1e-6, atol=1e-7)


def test_a_surface_without_phi_is_refused():
    """A subclass that gives no formula (nor a ``phi_function`` of its own) cannot be read: it says what to add."""

    class Bare(hybrid.geometry.surfaces.Surface):
        def as_array(self):
            return np.zeros(0)

    with pytest.raises(hybrid.HybridError, match=r"^a Bare gives no phi: define its formula\(p, theta, sqrt\)"):
        Bare().phi_function()


def test_joint_friction_agrees():
    """A UR5 with Coulomb friction and offsets on its joints (MuJoCo's passive forces and the generated ABA
    under the same friction formula) and the controller told it: the two plants agree."""
    import dataclasses

    robot = dataclasses.replace(hybrid.ur5(), coulomb=(2.0, 2.5, 1.5, 0.5, 0.4, 0.3),
                                offset=(0.3, -0.5, 0.2, 0.05, -0.05, 0.02), coulomb_speed=(0.2,) * 6)
    exp = hybrid.tracing_experiment(duration=0.3, robot=robot, controller_robot=robot)
    assert_agrees(exp)
