"""One pipeline for every arm: one experiment type, its start state, its files, the task frame anywhere."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

import hybrid
import hybrid.geometry.surfaces
from hybrid import oracle


def _sphere_cylinder_plane_implicit():
    return [hybrid.Sphere((0.5, 0.0, 0.2), 0.15), hybrid.Cylinder((0.4, 0.1, 0.0), (0.2, 0.3, 1.0), 0.12),
            hybrid.Plane((0.4, 0.0, 0.1), (0.1, -0.2, 1.0)),
            hybrid.ImplicitSurface("(x/a)**2 + (y/b)**2 + ((z - 0.3)/c)**2 - 1", {"a": 0.3, "b": 0.2, "c": 0.15})]


@pytest.mark.parametrize("surface", _sphere_cylinder_plane_implicit(), ids=lambda s: s.kind[:8])
def test_task_frame_at_points_of_any_surface_matches_the_hand_derivation(rng, surface):
    # points near the surface (the frame is defined off it too), velocities at random
    p = rng.uniform([0.2, -0.3, 0.0], [0.8, 0.3, 0.5], (20, 3))
    pd = rng.normal(0.0, 0.3, (20, 3))
    e = np.array([0.1, 0.2, 1.0])
    R, Rd = hybrid.task_frame(surface, p, pd, frame_direction=e)
    assert R.shape == Rd.shape == (20, 3, 3)
    for i in range(20):
        R_ref, Rd_ref = oracle.spatial_frame(surface, p[i], pd[i], e)
        np.testing.assert_allclose(R[i], R_ref, atol=1e-12)
        np.testing.assert_allclose(Rd[i], Rd_ref, atol=1e-10)
        one = hybrid.task_frame(surface, p[i], pd[i], frame_direction=e)  # one point: the same numbers
        np.testing.assert_allclose(one[0], R[i], atol=1e-15)


@pytest.mark.parametrize("surface", [hybrid.Circle((0.5, 0.0), 0.2), hybrid.Plane((0.3, 0.0), (-1.0, 0.4))],
                         ids=["circle", "plane"])
def test_planar_task_frame_for_n_points_equals_the_closed_form_one_by_one(rng, surface):
    r, rd = rng.uniform(0.0, 0.6, (30, 2)), rng.normal(0.0, 0.5, (30, 2))
    R, Rd = hybrid.task_frame(surface, r, rd)
    for i in range(30):
        R1, Rd1 = hybrid.task_frame(surface, r[i], rd[i])  # the committed SymPy closed form
        np.testing.assert_allclose(R[i], R1, atol=1e-14)
        np.testing.assert_allclose(Rd[i], Rd1, atol=1e-12)


def test_task_frame_refuses_what_it_cannot_mean():
    with pytest.raises(hybrid.HybridError, match="no planar cross-section"):
        hybrid.task_frame(hybrid.Sphere((0, 0, 0), 1.0), [1.0, 0.0], [0.0, 0.0])
    with pytest.raises(hybrid.HybridError, match="shape"):
        hybrid.task_frame(hybrid.Sphere((0, 0, 0), 1.0), [1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 0.0])
    with pytest.raises(hybrid.HybridError, match="hybrid surface"):
        hybrid.task_frame("sphere", [1.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    with pytest.raises(hybrid.TaskFrameError):  # e parallel to n
        hybrid.task_frame(hybrid.Sphere((0, 0, 0), 1.0), [0.0, 0.0, 1.0], [0.0, 0.0, 0.0])


@pytest.mark.parametrize("make", [hybrid.paper_experiment, hybrid.tracing_experiment], ids=["paper", "3-D"])
def test_the_start_state_is_at_rest_pressing_with_the_force_reference(make):
    """What a foreign loop starts from: joints and rates at rest, the sensor spring carrying F_d(0)
    along the normal, the sensor tip F_d(0)/k_e into the surface."""
    exp = make()
    x0 = exp.initial_state()
    n, d = exp.robot.n, len(exp.start())
    q, qd, s, sd = x0[:n], x0[n:2 * n], x0[2 * n:2 * n + d], x0[2 * n + d:]
    assert not qd.any() and not sd.any()
    tip = hybrid.arm_terms(exp.robot, q, qd)["r"][:d]
    F0 = exp.force_reference(0.0)
    normal = exp.surface.normal_at(np.append(s, 0.0) if d == 2 else s)[:d]
    # the sensor spring's force on the robot, K_s (s - r): F_d(0) along the normal (to the inverse
    # kinematics' tolerance of 1e-10 m times K_s)
    np.testing.assert_allclose(exp.sensor.stiffness * (s - tip), F0 * normal, atol=exp.sensor.stiffness * 1e-9)
    penetration = exp.plant().outputs(x0[None, :])[0][exp.plant().record["outputs"].index("penetration")]
    assert penetration == pytest.approx(F0 / exp.contact.stiffness, rel=1e-6)


def test_every_experiment_saves_and_loads(tmp_path):
    exp = hybrid.tracing_experiment(duration=0.05, controller="khatib", KPv=35.0, F_d=hybrid.Step(8.0, 12.0, 0.02))
    res = hybrid.simulate(exp)
    back = hybrid.SimulationResult.load(res.save(tmp_path / "trace"))
    assert back.experiment == exp  # the robot rebuilt from its data, the surface and the path as they were
    for name in ("t", "state", "tau", "outputs", "force_reference", "speed_reference"):
        np.testing.assert_array_equal(getattr(back, name), getattr(res, name))
    assert back.record == res.record
    np.testing.assert_array_equal(list(back.metrics.values()), list(res.metrics.values()))  # NaN where no step
    assert list(back.metrics) == list(res.metrics)
    again = hybrid.simulate(back.experiment)  # the loaded settings run the same run
    np.testing.assert_array_equal(again.state, res.state)


def test_settings_round_trip_through_their_data():
    implicit = hybrid.ImplicitSurface("z - 0.1 - h*sin(k*x)", {"h": 0.01, "k": 20.0})
    for exp in (hybrid.paper_experiment(elbow=-1, start_point=(0.3, 0.0), frame="desired"),
                hybrid.paper_experiment(surface=hybrid.Plane((0.3, 0.0), (-1.0, 0.0)), start_point=(0.3, 0.1)),
                hybrid.tracing_experiment(latitude=45.0, axes="position"),
                hybrid.tracing_experiment(surface=implicit, start_point=(0.45, 0.0, 0.1 + 0.01 * np.sin(9.0)))):
        assert hybrid.Experiment.from_dict(exp.to_dict()) == exp


def test_one_experiment_type_refuses_mixed_dimensions():
    with pytest.raises(hybrid.HybridError, match="planar arm needs a planar surface"):
        hybrid.paper_experiment(surface=hybrid.Sphere((0.5, 0, 0), 0.2))
    with pytest.raises(hybrid.HybridError, match="three numbers"):  # a 3-D arm starts at a 3-D point
        hybrid.tracing_experiment(surface=hybrid.Circle((0.5, 0.0), 0.2), start_point=(0.3, 0.0))
    with pytest.raises(hybrid.HybridError, match="no latitude circle"):
        hybrid.tracing_experiment(surface=hybrid.Plane((0.4, 0, 0.1), (0, 0, 1)), latitude=30.0)
    # a path task runs its own path: a latitude (the followed path's circle) has nothing to set there
    sphere = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
    spiral = hybrid.SpiralPath(sphere, sphere.project(np.array([0.45, 0.0, 0.4])), 0.01, 1.0)
    with pytest.raises(hybrid.HybridError, match="latitude = 45.0: a path_task runs its own path"):
        hybrid.tracing_experiment(latitude=45.0, path_task=hybrid.PathTask(spiral))


# ------------------------------------------------------- what a new surface, scheme or plant takes


@dataclass(frozen=True)
class Paraboloid(hybrid.geometry.surfaces.Surface):
    """A surface written here, as a user or a new built-in would: one class, its formula and
    parameters. ``z = z0 + k |(x, y) - (x0, y0)|^2``, touched from above."""

    x0: float
    y0: float
    z0: float
    k: float
    kind = "test_paraboloid"
    parameters_named = ("x0", "y0", "z0", "k")

    @staticmethod
    def formula(p, theta, sqrt):
        return (p[2] - theta[2] - theta[3] * ((p[0] - theta[0]) ** 2 + (p[1] - theta[1]) ** 2))

    def as_array(self) -> np.ndarray:
        return np.array([self.x0, self.y0, self.z0, self.k])

    def normal_at(self, p) -> np.ndarray:
        g = np.array([-2 * self.k * (p[0] - self.x0), -2 * self.k * (p[1] - self.y0), 1.0])
        return g / np.linalg.norm(g)


def test_a_new_surface_is_one_class(tmp_path):
    """Frames, the law, the 3-D experiment, its files and MuJoCo take it with no other change."""
    surface = Paraboloid(0.45, 0.0, 0.1, 2.0)
    p, pd = np.array([0.5, 0.05, 0.1 + 2.0 * 0.0025 * 2]), np.array([0.1, -0.05, 0.02])
    R, Rd = hybrid.task_frame(surface, p, pd)
    R_ref, Rd_ref = oracle.spatial_frame(surface, p, pd, (0.0, 0.0, 1.0))
    np.testing.assert_allclose(R, R_ref, atol=1e-12)
    np.testing.assert_allclose(Rd, Rd_ref, atol=1e-10)
    np.testing.assert_allclose(R[2], surface.normal_at(p), atol=1e-12)  # the formula and the class agree
    start = (0.4, 0.0, 0.1 + 2.0 * 0.05**2)
    exp = hybrid.tracing_experiment(surface=surface, start_point=start, duration=0.05)
    res = hybrid.simulate(exp)
    assert np.isfinite(res.state).all() and res.force_normal[-1] == pytest.approx(10.0, abs=1.0)
    back = hybrid.SimulationResult.load(res.save(tmp_path / "paraboloid"))
    assert back.experiment == exp
    pytest.importorskip("mujoco")
    theirs = hybrid.simulate(exp, plant="mujoco")
    assert np.sqrt(np.mean((theirs.force_normal - res.force_normal) ** 2)) < 1e-9


def test_a_new_scheme_is_one_class():
    """A registered scheme runs wherever a scheme's name is taken: here the task law with Khatib's
    feedforward, which is Khatib's scheme by another name (its torques are Khatib's)."""
    from hybrid.control import schemes

    @schemes.register
    class Feedforward(schemes.TaskDecoupling):
        name = "test_feedforward"
        feeds_desired_force = True

    try:
        ours = hybrid.simulate(hybrid.paper_experiment(controller="test_feedforward", duration=0.3))
        khatib = hybrid.simulate(hybrid.paper_experiment(controller="khatib", duration=0.3))
        np.testing.assert_array_equal(ours.tau, khatib.tau)
    finally:
        del schemes.SCHEMES["test_feedforward"]


def test_a_new_plant_is_one_implementation():
    """A plant that implements the interface and registers a name runs every experiment: here the
    generated plant behind a plant of one's own (the Python runner's numbers, to the bit)."""
    from hybrid.plants import interface, registry

    class Wrapped(interface.Plant):
        def __init__(self, exp):
            self.inner = exp.plant()
            self.record, self.nq, self.force_columns = self.inner.record, self.inner.nq, self.inner.force_columns
            self.conditioning, self.conditioning_name = self.inner.conditioning, self.inner.conditioning_name

        def advance(self, x, tau, nsteps, trajectory):
            return self.inner.advance(x, tau, nsteps, trajectory)

        def outputs(self, states):
            return self.inner.outputs(states)

    registry.register_plant("test_wrapped")(Wrapped)
    try:
        exp = hybrid.tracing_experiment(duration=0.05)
        ours = hybrid.simulate(exp, plant="test_wrapped")
        np.testing.assert_array_equal(ours.state, hybrid.simulate(exp, compiled=False).state)
    finally:
        del registry.PLANTS["test_wrapped"]


def test_paper_settings_saved_before_experiments_were_one_type_still_load():
    """The former form of a paper run's settings: the arm's parameters as ``arm``, a 2-D surface."""
    from dataclasses import asdict

    exp = hybrid.paper_experiment(controller="khatib", elbow=-1, start_point=(0.3, 0.0))
    old = {"controller": "khatib", "integral": True, "curvature": False, "frame": "actual", "model_error": 0.1,
           "viscous_compensation": 0.5, "arm": asdict(hybrid.paper_arm()),
           "surface": {"kind": "circle", "center": [0.5, 0.0], "radius": 0.2}, "start_point": [0.3, 0.0],
           "elbow": -1, "backend": "sympy", "singular_tol": 1e-3, "duration": 2.0, "step": 1e-4, "sample_time": 1e-2,
           **{k: asdict(getattr(exp, k)) for k in ("sensor", "contact", "gains", "force_reference",
                                                   "speed_reference")}}
    assert hybrid.Experiment.from_dict(old) == exp
    old["surface"] = {"kind": "plane", "point": [0.3, 0.0], "normal": [-1.0, 0.0]}
    assert hybrid.Experiment.from_dict(old).surface == hybrid.Plane((0.3, 0.0, 0.0), (-1.0, 0.0, 0.0))


def test_the_planar_arms_parameters_sweep_by_their_names():
    """``arm.m2`` is the planar robot's closed form's ``m2``: the run is the one of an arm built so."""
    from dataclasses import replace

    base = hybrid.paper_experiment(duration=0.2)
    table = hybrid.sweep(base, {"arm.m2": [4.5]})
    alone = hybrid.simulate(hybrid.paper_experiment(duration=0.2, arm=replace(hybrid.paper_arm(), m2=4.5)))
    assert table["rms_force_error_N"][0] == alone.metrics["rms_force_error_N"]
    assert table["rms_force_error_N"][0] != hybrid.simulate(base).metrics["rms_force_error_N"]
    with pytest.raises(hybrid.HybridError, match="closed form's parameters"):
        hybrid.Robot.planar(hybrid.paper_arm()).with_link("joint2", mass=10.0)
