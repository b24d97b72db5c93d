"""Where a user's input leaves the domain the library can serve, a HybridError that says so, never a NaN
or a foreign exception: a surface without a normal at a point (its gradient vanishes, or its formula is
undefined there)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import UR5, example_robot

import hybrid

Q = np.array([0.3, -1.0, 1.2, -0.4, 1.1, 0.2])

#: surfaces through the point (a, b, c) that have no normal there
NO_NORMAL = {
    "gradient vanishes": "(z - c)**2",
    "cone apex": "sqrt((x - a)**2 + (y - b)**2) + z - c",
    "formula undefined": "z - c + 0.01*sqrt(c - 0.001 - z)",
}


@pytest.fixture(scope="module")
def ur5():
    return hybrid.Robot.from_urdf(example_robot(UR5[0]), tip=UR5[1])


def _through(text: str, point) -> hybrid.ImplicitSurface:
    return hybrid.ImplicitSurface(text, dict(zip("abc", (float(v) for v in point))))


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_a_point_without_a_normal_has_no_task_frame(kind):
    p = np.array([0.45, 0.1, 0.3])
    surface = _through(NO_NORMAL[kind], p)
    # independently (SymPy's gradient in NumPy): there is no normal at p
    _, grad = surface.phi_function()(p)
    assert not (np.isfinite(grad).all() and np.linalg.norm(grad) > 1e-12)
    e = (1.0, 0.0, 0.0)
    with pytest.raises(hybrid.TaskFrameError, match="no normal there"):
        hybrid.task_frame(surface, p, (0.1, 0.0, 0.0), frame_direction=e)
    # 2 mm aside and below, on the side where the formula is defined, the frame is the one of the normal there
    near = p + [0.002, 0.0, -0.002]
    R, _ = hybrid.task_frame(surface, near, (0.1, 0.0, 0.0), frame_direction=e)
    np.testing.assert_allclose(R[2], surface.normal_at(near), atol=1e-12)
    with pytest.raises(hybrid.TaskFrameError, match="state 1 of 2"):
        hybrid.task_frame(surface, np.array([near, p]), np.zeros((2, 3)), frame_direction=e)
    with pytest.raises(hybrid.HybridError, match="grad phi vanishes|is undefined at"):
        surface.normal_at(p)


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_an_experiment_does_not_start_where_the_surface_has_no_normal(kind):
    p = (0.45, 0.1, 0.3)
    exp = hybrid.tracing_experiment(surface=_through(NO_NORMAL[kind], p), start_point=p)
    with pytest.raises(hybrid.HybridError, match="grad phi vanishes|is undefined at") as info:
        exp.initial_state()
    assert "nan" not in str(info.value).splitlines()[0].split("grad phi")[0]


@pytest.mark.parametrize("kind", NO_NORMAL)
def test_the_compiled_step_names_a_missing_normal_at_the_tip(ur5, kind):
    """The controller's compiled step at a pose whose tip is where the surface has no normal: its
    FRAME_UNDEFINED status (a TaskFrameError), nothing changed."""
    tip = hybrid.arm_terms(ur5, Q, np.zeros(6))["r"]
    ctrl = hybrid.Controller(ur5, _through(NO_NORMAL[kind], tip), frame_direction=(1.0, 0.0, 0.0))
    with pytest.raises(hybrid.TaskFrameError, match="no normal there"):
        ctrl(0.0, Q, np.zeros(6), np.zeros(6))
    assert ctrl.last is None
    ctrl(0.0, Q + 0.01, np.zeros(6), np.zeros(6))  # a pose 10 mrad away is served
