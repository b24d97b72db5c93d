"""Bad input to the general law and its surfaces: a HybridError that names the cause, never a NaN."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from conftest import UR5, example_robot

import hybrid

Q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2])


@pytest.fixture(scope="module")
def ur5():
    return hybrid.Robot.from_urdf(example_robot(UR5[0]), tip=UR5[1])


@pytest.fixture(scope="module")
def law(ur5):
    return hybrid.decoupling_law(ur5, hybrid.Sphere((0.4, 0.1, 0.3), 0.15), curvature=True)


def test_frame_direction_parallel_to_the_normal_is_a_frame_error(ur5, law):
    # a plane whose normal is base z: with e = z the task frame's t1 = e x n is undefined
    flat = hybrid.decoupling_law(ur5, hybrid.Plane((0, 0, 0.1), (0, 0, 1)))
    with pytest.raises(hybrid.TaskFrameError, match="its direction e is parallel to the surface normal"):
        flat(Q, np.zeros(6), np.zeros(6), np.zeros(6))
    with pytest.raises(hybrid.TaskFrameError):
        flat.task_frame((0.2, 0.3, 0.4), (0.0, 0.0, 0.0))
    sideways = hybrid.decoupling_law(ur5, hybrid.Plane((0, 0, 0.1), (0, 0, 1)), frame_direction=(1, 0, 0))
    assert np.isfinite(sideways(Q, np.zeros(6), np.zeros(6), np.zeros(6))).all()
    # batched: the failing state is named
    many = np.tile(Q, (3, 1))
    with pytest.raises(hybrid.TaskFrameError, match="state 0 of 3"):
        flat(many, np.zeros((3, 6)), np.zeros((3, 6)), np.zeros((3, 6)))


@pytest.mark.parametrize("eps", [0.0, 1e-5])
def test_wrist_singularity(law, eps):
    q = Q.copy()
    q[4] = eps  # UR5 wrist: joints 4 and 6 aligned
    with pytest.raises(hybrid.SingularConfigurationError, match="singular or nearly so.*wrist, elbow or shoulder"):
        law(q, np.zeros(6), np.zeros(6), np.zeros(6))
    with pytest.raises(hybrid.SingularConfigurationError):
        hybrid.operational_space(law.robot, q, np.zeros(6))


def test_euler_singularity_names_the_angle(ur5):
    """A tool frame turned so that at Q its x axis points down: beta = pi/2 exactly, J well conditioned."""
    import dataclasses

    current = hybrid.arm_terms(ur5, Q, np.zeros(6))["rotation"]
    target = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])  # Ry(pi/2)
    old_tip = np.array(ur5.chain.tip_rotation)
    tip = old_tip @ current.T @ target
    chain = dataclasses.replace(ur5.chain, tip_rotation=tuple(map(tuple, tip)))
    turned = dataclasses.replace(ur5, chain=chain)
    np.testing.assert_allclose(hybrid.arm_terms(turned, Q, np.zeros(6))["rotation"], target, atol=1e-12)
    with pytest.raises(hybrid.SingularConfigurationError, match="Euler angles are singular.*beta = \\+-pi/2"):
        hybrid.operational_space(turned, Q, np.zeros(6), coordinates="euler_zyx")
    assert np.isfinite(hybrid.operational_space(turned, Q, np.zeros(6)).B_o).all()  # the twist form is fine


@pytest.mark.parametrize("kwargs, match", [
    ({"axes": (0, 2, 2)}, "distinct"),
    ({"axes": (0, 7)}, "distinct task-axis indices 0-5"),
    ({"axes": "sideways"}, "name one of all, position, planar"),
    ({"axes": ()}, "distinct"),
    ({"axes": (True, 1)}, "distinct"),
    ({"frame_direction": (0, 0, 0)}, "nonzero direction"),
    ({"frame_direction": (0, 1)}, "nonzero direction"),
    ({"curvature": "yes"}, "curvature must be True or False"),
    ({"singular_tol": 2.0}, "singular_tol"),
    ({"backend": "casadi"}, "closed form"),
])
def test_bad_law_settings(ur5, kwargs, match):
    with pytest.raises(hybrid.HybridError, match=match):
        hybrid.decoupling_law(ur5, hybrid.Sphere((0.4, 0.1, 0.3), 0.15), **kwargs)


def test_planar_arm_needs_reduced_axes_and_planar_surfaces():
    robot = hybrid.Robot.planar(hybrid.paper_arm())
    # the paper's arm serves its planar task unless told otherwise; a 2-joint arm cannot serve all six
    assert hybrid.decoupling_law(robot, hybrid.Circle((0.5, 0), 0.2)).axes == (0, 2)
    with pytest.raises(hybrid.HybridError, match="2-joint arm cannot control all six task axes.*planar"):
        hybrid.decoupling_law(robot, hybrid.Circle((0.5, 0), 0.2), axes="all")
    with pytest.raises(hybrid.HybridError, match="3 task axes need at least 3 joints"):
        hybrid.decoupling_law(robot, hybrid.Circle((0.5, 0), 0.2), axes="position")
    with pytest.raises(hybrid.HybridError, match="planar arm needs a hybrid.Circle or hybrid.Plane in 2-D"):
        hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Sphere((0.5, 0, 0), 0.2))
    with pytest.raises(hybrid.HybridError, match="planar arm needs"):  # a horizontal plane: no line along z
        hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Plane((0.5, 0, 0), (0, 0, 1)))
    # a vertical plane is the paper's line (its cross-section): the closed form runs on it
    assert hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Plane((0.5, 0, 0), (1, 0, 0))).backend == "sympy"
    with pytest.raises(hybrid.HybridError, match="6-D operational space needs at least 6 joints"):
        hybrid.operational_space(robot, [0.1, 0.2], [0.0, 0.0])


def test_wrong_shapes_name_the_argument(law):
    z6 = np.zeros(6)
    with pytest.raises(hybrid.HybridError, match=r"q must have shape \(6,\), got \(5,\)"):
        law(np.zeros(5), z6, z6, z6)
    with pytest.raises(hybrid.HybridError, match=r"qdot must have shape"):
        law(Q, np.zeros(7), z6, z6)
    with pytest.raises(hybrid.HybridError, match=r"a must have shape \(6,\)"):
        law(Q, z6, np.zeros(3), z6)
    with pytest.raises(hybrid.HybridError, match=r"tau0 must have shape \(6,\)"):
        law.torque(Q, z6, z6, z6, tau0=np.zeros(2))
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input qdot"):
        law(Q, [np.nan] * 6, z6, z6)
    with pytest.raises(hybrid.HybridError, match="same number of rows"):
        law(np.tile(Q, (2, 1)), np.zeros((3, 6)), np.zeros((2, 6)), np.zeros((2, 6)))


@pytest.mark.parametrize("make, match", [
    (lambda: hybrid.Sphere((0, 0), 0.1), r"Sphere.center must be three numbers"),
    (lambda: hybrid.Sphere((0, 0, 0), -0.1), "positive radius"),
    (lambda: hybrid.Sphere((0, 0, np.nan), 0.1), "not finite"),
    (lambda: hybrid.Cylinder((0, 0, 0), (0, 0, 0), 0.1), "Cylinder.axis .* has zero length"),
    (lambda: hybrid.Cylinder((0, 0, 0), (0, 0, 1), "wide"), "Cylinder.radius must be a real number"),
    (lambda: hybrid.Plane((0, 0, 0), (0, 1)), r"Plane.normal must be three numbers"),
    (lambda: hybrid.Plane((0, 0, 0), (0, 0, 0)), "zero length"),
    (lambda: hybrid.ImplicitSurface("x**2 + y**2 - r**2", {}), "uses the name 'r'"),
    (lambda: hybrid.ImplicitSurface(sp.Symbol("x") ** 2 - sp.Symbol("r"), {}), "uses r, which parameters does not"),
    (lambda: hybrid.ImplicitSurface("__import__('os').getcwd() or x", {}), "uses .* syntax"),
    (lambda: hybrid.ImplicitSurface("x - factorial(10)", {}), "not one of the functions below"),
    (lambda: hybrid.ImplicitSurface("x - 2**2**40", {}), "exponent"),
    (lambda: hybrid.ImplicitSurface("x" + " + x" * 1000, {}), "characters; write it in at most"),
    (lambda: hybrid.ImplicitSurface("a + 1", {"a": 1.0}), "does not depend on x, y or z"),
    (lambda: hybrid.ImplicitSurface("x +* y", {}), "is not an expression"),
    (lambda: hybrid.ImplicitSurface("x - a", {"a": float("inf")}), "give a finite value"),
    (lambda: hybrid.ImplicitSurface("x - a", {"x": 1.0}), "identifier other than x, y, z"),
    (lambda: hybrid.ImplicitSurface("x - a", [("a", 1.0)]), "must be a {name: value} dict"),
    (lambda: hybrid.ImplicitSurface(sp.besselj(0, sp.Symbol("x")), {}), "write phi with"),
    (lambda: hybrid.ImplicitSurface(3, {}), "must be a SymPy expression"),
])
def test_bad_surfaces(make, match):
    with pytest.raises(hybrid.HybridError, match=match):
        make()


def test_implicit_surface_parameters_are_run_time(ur5):
    """Changing a parameter value reuses the compiled code; the user's own symbols work."""
    x, y, z, r = sp.symbols("x y z r")  # no assumptions, as a user writes them
    small = hybrid.ImplicitSurface((x - 0.4) ** 2 + y**2 + (z - 0.3) ** 2 - r**2, {"r": 0.1})
    large = hybrid.ImplicitSurface((x - 0.4) ** 2 + y**2 + (z - 0.3) ** 2 - r**2, {"r": 0.2})
    a, b = hybrid.decoupling_law(ur5, small), hybrid.decoupling_law(ur5, large)
    assert a._fn is b._fn
    sphere = hybrid.decoupling_law(ur5, hybrid.Sphere((0.4, 0.0, 0.3), 0.2))
    p, pd = np.array([0.5, 0.1, 0.4]), np.array([0.1, -0.2, 0.05])
    np.testing.assert_allclose(b.task_frame(p, pd)[0], sphere.task_frame(p, pd)[0], atol=1e-14)
    np.testing.assert_allclose(b.task_frame(p, pd)[1], sphere.task_frame(p, pd)[1], atol=1e-13)


@pytest.mark.parametrize("as_input", [list, np.array], ids=["lists", "arrays"])
def test_nan_state_is_non_finite_not_singular(ur5, law, as_input):
    """A NaN joint angle makes every measure NaN: it is named as non-finite input, not as a singular pose."""
    z6 = np.zeros(6)
    q = Q.copy()
    q[2] = np.nan
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input q") as info:
        law(as_input(q), as_input(z6), as_input(z6), as_input(z6))
    assert not isinstance(info.value, hybrid.SingularConfigurationError)
    with pytest.raises(hybrid.NonFiniteError, match="non-finite input q"):
        hybrid.operational_space(ur5, q, z6)
    planar = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0), 0.2))
    for bad in ([np.nan, 1.0], [0.3, np.inf]):
        with pytest.raises(hybrid.NonFiniteError, match="non-finite input q"):
            planar(as_input(bad), as_input([0.0, 0.0]), as_input([0.0, 0.0]), as_input([0.0, 0.0]))


def test_a_one_state_row_among_batched_inputs_is_refused(ur5, law):
    """A per-state input given as one row, whose length happens to equal N, is not read as N rows."""
    Q6 = np.tile(Q, (6, 1))
    with pytest.raises(hybrid.HybridError, match=r"qdot must have shape \(N, 6\)"):
        hybrid.arm_terms(ur5, Q6, Q6[0])
    with pytest.raises(hybrid.HybridError, match=r"a must have shape \(N, 6\)"):
        law(Q6, np.zeros((6, 6)), np.zeros(6), np.zeros((6, 6)))


@pytest.mark.parametrize("bad", [[[0.0] * 6, [0.0] * 5], "abc", [[1j] * 6]])
def test_ragged_or_foreign_input_is_a_hybrid_error(ur5, law, bad):
    with pytest.raises(hybrid.HybridError):
        hybrid.arm_terms(ur5, bad, np.zeros(6))
    with pytest.raises(hybrid.HybridError):
        law(bad, np.zeros(6), np.zeros(6), np.zeros(6))
    planar = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0), 0.2))
    with pytest.raises(hybrid.HybridError):
        planar([[0.3, 1.0], [1.0]], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0])


def test_axes_keep_the_given_order(rng, ur5):
    """a[k] acts along axes[k]: the same task with the axes listed in another order gives the same F*."""
    sphere = hybrid.Sphere((0.45, 0.1, 0.3), 0.15)
    one = hybrid.decoupling_law(ur5, sphere, axes=(0, 1, 2))
    other = hybrid.decoupling_law(ur5, sphere, axes=(2, 0, 1))
    assert other.axes == (2, 0, 1)
    qd, a, Fc = rng.normal(size=6), rng.normal(size=3), rng.normal(size=6)
    np.testing.assert_allclose(other(Q, qd, a[[2, 0, 1]], Fc), one(Q, qd, a, Fc), rtol=1e-12, atol=1e-12)


def test_surface_expressions_with_constants_and_symbolic_powers(ur5):
    tilted = hybrid.ImplicitSurface("z - 0.3 - x*sin(pi/8)", {})
    plane = hybrid.Plane((0.0, 0.0, 0.3), (-np.sin(np.pi / 8), 0.0, 1.0))
    p, pd = np.array([0.5, 0.1, 0.4]), np.array([0.1, 0.0, 0.0])
    R1 = hybrid.decoupling_law(ur5, tilted).task_frame(p, pd)[0]
    R2 = hybrid.decoupling_law(ur5, plane).task_frame(p, pd)[0]
    np.testing.assert_allclose(R1, R2, atol=1e-14)
    hybrid.ImplicitSurface("x**k + y**2 + z**2 - 1", {"k": 2.0})  # a symbolic exponent translates
    with pytest.raises(hybrid.HybridError, match="normal is undefined"):
        hybrid.Sphere((0, 0, 0), 1.0).normal_at((0, 0, 0))


def test_robots_compare_and_hash(ur5):
    again = hybrid.Robot.from_urdf(example_robot(UR5[0]), tip=UR5[1])
    assert again == ur5 and hash(again) == hash(ur5)
    assert ur5.with_model_error(0.1) != ur5


def test_batched_calls_work_after_fork(ur5):
    """The thread pool behind batched calls is rebuilt in a forked child (it would otherwise hang)."""
    import multiprocessing

    many = np.tile(Q, (4096, 1))
    hybrid.arm_terms(ur5, many, np.zeros_like(many))  # the parent's pool exists now
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(1) as pool:
        result = pool.apply_async(_batched_rows, (ur5,))
        assert result.get(timeout=60) == 4096


def _batched_rows(robot) -> int:
    many = np.tile(Q, (4096, 1))
    return len(hybrid.arm_terms(robot, many, np.zeros_like(many))["B"])


def test_robots_and_laws_pickle(ur5, law):
    import pickle

    robot = pickle.loads(pickle.dumps(ur5))
    assert robot == ur5
    np.testing.assert_array_equal(hybrid.arm_terms(robot, Q, np.zeros(6))["B"],
                                  hybrid.arm_terms(ur5, Q, np.zeros(6))["B"])
    copy = pickle.loads(pickle.dumps(law))
    z = np.zeros(6)
    np.testing.assert_array_equal(copy(Q, z, z, z), law(Q, z, z, z))
    planar = hybrid.decoupling_law(hybrid.paper_arm(), hybrid.Circle((0.5, 0), 0.2))
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(planar))([2.2, 1.9], [0, 0], [0, 0], [0, 0]),
                                  planar([2.2, 1.9], [0, 0], [0, 0], [0, 0]))



@pytest.mark.parametrize("make, match", [
    (lambda: hybrid.Circle((0, 0), 10**400), "within float range"),
    (lambda: hybrid.Circle((0, 10**400), 1), "must be two numbers"),
    (lambda: hybrid.ImplicitSurface("x - a", {"a": 10**400}), "within float range"),
    (lambda: hybrid.paper_experiment(model_error=10**400), "within float range"),
    (lambda: hybrid.paper_experiment(integration_step=5e-324), "too small for sample_time"),
    (lambda: hybrid.paper_experiment(gains="x", KPv=1), "give a hybrid.Gains"),
    (lambda: hybrid.paper_experiment(surface=hybrid.Plane((0, 0, 0), (0, 0, 1))), "2-D hybrid.Plane"),
    (lambda: hybrid.operational_space(hybrid.paper_arm(), [0.1, 1.0], [0, 0], singular_tol="a"), "real number"),
    (lambda: hybrid.operational_space(hybrid.paper_arm(), [0.0, 1e-9], [0, 0], singular_tol=float("nan")),
     "singular_tol is nan"),
    (lambda: hybrid.arm_terms(hybrid.paper_arm(), [0.1, 1.0], [0, 0], backend=["sympy"]), "backend must be"),
])
def test_overflow_and_unchecked_settings(make, match):
    with pytest.raises(hybrid.HybridError, match=match):
        make()


def test_huge_directions_are_normalised_not_zeroed(ur5):
    assert hybrid.Plane((0, 0), (1e200, 1e200)).normal == pytest.approx((2**-0.5, 2**-0.5, 0.0))
    assert hybrid.Cylinder((0, 0, 0), (1e200, 0, 0), 1.0).axis == (1.0, 0.0, 0.0)
    law = hybrid.decoupling_law(ur5, hybrid.Sphere((0.45, 0.1, 0.3), 0.15), frame_direction=(0, 0, 1e200))
    assert law.frame_direction == (0.0, 0.0, 1.0)
    for axes in [(float("inf"),), (0.5, 1.7, 2.2), ("0", "1", "2"), {0: 1, 1: 1, 2: 1}]:
        with pytest.raises(hybrid.HybridError, match="axes"):
            hybrid.decoupling_law(ur5, hybrid.Sphere((0.45, 0.1, 0.3), 0.15), axes=axes)


def test_non_finite_tau0_is_refused_even_where_it_has_no_effect(law):
    z6 = np.zeros(6)
    with pytest.raises(hybrid.NonFiniteError, match="tau0"):
        law.torque(Q, z6, z6, z6, tau0=np.full(6, np.nan))


@pytest.mark.parametrize("text, parameters, match", [
    # a call with the wrong number of arguments, checked from the one table of functions
    ("sin(x, y)", {}, r"sin with 2 arguments \(sin takes 1 argument\)"),
    ("x - atan(x, y)", {}, r"atan with 2 arguments"),
    ("sqrt() + x", {}, r"sqrt with 0 arguments"),
    ("Min() + x", {}, r"Min with 0 arguments \(Min takes at least 2"),
    ("Max(x) - 1", {}, r"Max with 1 argument "),
    ("exp(x, y, z)", {}, r"exp with 3 arguments"),
    ("Abs(x, 1)", {}, r"Abs with 2 arguments"),
    ("log(x, 2)", {}, r"log with 2 arguments"),
    # a function used as a value, a constant or parameter called
    ("sin + x", {}, "the function sin without calling it"),
    ("x * cos", {}, "the function cos without calling it"),
    ("x - pi(1)", {}, "not one of the functions below"),
    ("x - a(1)", {"a": 1.0}, "not one of the functions below"),
    # parameter names that hide a function or a constant
    ("x - sin", {"sin": 1.0}, "parameter name 'sin' hides the function sin"),
    ("x - pi", {"pi": 3}, "parameter name 'pi' hides the constant pi"),
    ("x - E", {"E": 2}, "parameter name 'E' hides the constant E"),
    ("x - Max", {"Max": 2.0}, "hides the function Max"),
    # values C cannot hold
    ("x - 1/0", {}, "has the value zoo"),
    ("x - log(0)", {}, "has the value zoo"),
    ("x - sqrt(-1)", {}, "has the value I"),
    ("x - acos(2)", {}, "has the value acos"),
    ("x - 1e200*1e200", {}, r"has the value -1\.0+e\+400"),
    # nesting deeper than SymPy and the generator can walk
    ("x" + "**(x" * 150 + ")" * 150, {}, "nested more than 100 levels"),
    ("-" * 1000 + "x", {}, "nested more than 100 levels"),
    ("sqrt(" * 150 + "x" + ")" * 150, {}, "nested"),
])
def test_phi_text_arity_shadowing_and_values(text, parameters, match):
    with pytest.raises(hybrid.HybridError, match=match) as info:
        hybrid.ImplicitSurface(text, parameters)
    assert len(str(info.value).splitlines()[0]) < 200  # the allowed functions follow on the next line


def test_phi_text_builds_the_same_expression_as_sympy():
    """Names SymPy's own parser uses (Integer, Symbol, Float) are ordinary parameters; text and SymPy agree."""
    x, y, z = sp.symbols("x y z", real=True)
    odd = hybrid.ImplicitSurface("x - Integer*Symbol + Float", {"Integer": 2.0, "Symbol": 3.0, "Float": 0.5})
    assert {str(s) for s in odd.phi.free_symbols} == {"x", "Integer", "Symbol", "Float"}
    a = sp.Symbol("a", real=True)
    text = hybrid.ImplicitSurface("(x/a)**2 + y**2 + Min(z, 2*z, -z) - sin(pi/8)*E", {"a": 0.3})
    assert sp.simplify(text.phi - ((x / a) ** 2 + y**2 + sp.Min(z, 2 * z, -z) - sp.sin(sp.pi / 8) * sp.E)) == 0
    long = hybrid.ImplicitSurface("+".join(["x"] * 600), {})  # a long flat sum is not deep
    assert long.phi == 600 * x


@pytest.mark.parametrize("name", ["θ", "rä", "a" * 65, "", "1a", "a-b", "lambda", 3, "x"])
def test_parameter_names_are_ascii_identifiers(name):
    with pytest.raises(hybrid.HybridError, match="ImplicitSurface parameter name"):
        hybrid.ImplicitSurface("x - 1", {name: 1.0})
