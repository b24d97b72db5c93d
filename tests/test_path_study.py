"""The path study's figure (hybrid.plots.plot_path_force): the trace it draws is the run's sensor tip, its
colours the run's recorded normal force there, its wireframe on the surface; checked on a short raster."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

import hybrid
from hybrid.plots import plot_path_force

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)


@pytest.fixture(scope="module")
def res():
    raster = hybrid.RasterPath(SPHERE, SPHERE.project(np.array([0.485, -0.005, 0.35])), (1.0, 0.0, 0.0), 0.03,
                               0.01, 2)
    task = hybrid.PathTask(raster, speed=0.1, force=10.0)
    return hybrid.simulate(hybrid.tracing_experiment(surface=SPHERE, path_task=task, duration=1.5,
                                                     contact=hybrid.Contact(friction=0.35)))


def test_the_colours_are_the_recorded_force_at_the_plotted_points(res):
    ax = plot_path_force(res, every=7)
    trace = ax.collections[-1]
    segments = np.array(trace._segments3d)  # the 3-D segments (get_segments gives the 2-D projection)
    values = np.asarray(trace.get_array())
    tip = np.column_stack([res.output(c) for c in ("s_x", "s_y", "s_z")])
    # each segment starts at a recorded sensor-tip position and ends at the next plotted one
    rows = [int(np.argmin(np.linalg.norm(tip - a, axis=1))) for a in segments[:, 0]]
    assert np.allclose(tip[rows], segments[:, 0], atol=1e-12)
    assert np.allclose(segments[1:, 0], segments[:-1, 1])
    assert rows[0] == 0 and len(tip) - 1 - rows[-1] <= 2 * 7  # the whole run, start to end
    # the colour value is the force recorded there, and the drawn colour is the colour map's of it
    assert np.array_equal(values, res.force_normal[rows])
    assert np.ptp(values) > 0.05  # a force that varies: the colours are not one colour by chance
    trace.update_scalarmappable()
    expected = matplotlib.colormaps["viridis"]((values - values.min()) / (values.max() - values.min()))
    assert np.allclose(trace.get_edgecolor(), expected, atol=1e-6)


def test_the_colour_range_and_the_wireframe(res):
    ax = plot_path_force(res, vmin=9.0, vmax=11.0, colorbar=False)
    trace, wire = ax.collections[-1], ax.collections[0]
    assert (trace.norm.vmin, trace.norm.vmax) == (9.0, 11.0)
    points = np.concatenate([np.asarray(seg) for seg in wire._segments3d])
    assert np.allclose(np.linalg.norm(points - SPHERE.center, axis=1), SPHERE.radius, atol=1e-9)  # on the sphere
    tip = np.column_stack([res.output(c) for c in ("s_x", "s_y", "s_z")])
    assert (points.min(0) <= tip.min(0) + 1e-3).all() and (points.max(0) >= tip.max(0) - 1e-3).all()  # about it


def test_a_planar_run_is_refused():
    planar = hybrid.simulate(hybrid.paper_experiment(duration=0.05))
    with pytest.raises(hybrid.HybridError, match="planar"):
        plot_path_force(planar)
