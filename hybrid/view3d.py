"""A run in the browser: the arm doing the task as an interactive 3-D figure (plotly), with a play button
and a slider, one self-contained HTML file that opens offline.

The figure draws the pictures :mod:`hybrid.animation` draws, from the same data
(:func:`~hybrid.animation.arm_frames`: no kinematics of its own): the arm's links through the joint
origins, the elastic sensor, the surface, the sensor tip's path so far, the recorded contact force
``F_c`` as an arrow and the task frame's axes ``t1, t2, n`` at the arm tip, in base axes with equal
scales [m]. The paper's planar arm is drawn in its plane, ``z = 0``.

Plotly draws with WebGL in any browser and needs no server: the figure is written as one HTML file with
plotly.js inside, where a server-based viewer (meshcat, viser) needs a running process and a websocket.
Plotly is an optional extra (``pip install 'hybrid-decoupling[view]'``), loaded on first use.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.colors import to_hex

from hybrid import files
from hybrid.animation import (
    AXIS_COLORS,
    AXIS_LENGTH,
    ArmFrame,
    arm_frames,
    chosen_samples,
    default_force_scale,
    playback_fps,
    section_ends,
    surface_grid,
    touched_points,
)
from hybrid.errors import HybridError
from hybrid.plots import is_spatial
from hybrid.validate import checked_keywords, shown

#: the file types :func:`view` writes
SUFFIXES = (".html", ".htm")
#: at most about this many points of the sensor tip's path are drawn in one picture (a long run's path is
#: thinned: every picture holds its path so far, and the file holds every picture)
PATH_POINTS = 400
#: the names of the traces each picture changes, in the figure's order after the surface's
#: (short: the legend is a row above the scene, and wraps in a narrow page)
MOVING = ("sensor tip's path", "arm", "sensor", "F_c", "t1", "t2", "n")
#: the planar arm's task frame axes (its rows t, n), named as the figure names them
PLANAR_AXES = ("t", "n")


def _plotly():
    """plotly's graph objects, or a HybridError saying how to install them."""
    try:
        import plotly.graph_objects as go
    except ImportError:
        raise HybridError("the 3-D view needs plotly, an optional extra: pip install 'hybrid-decoupling[view]'"
                          ) from None
    return go


def _out_path(out) -> Path | None:
    """``out`` checked before anything is drawn: None, or an ``.html`` file name."""
    if out is None:
        return None
    path = files.output_path(out)
    if path.suffix.lower() not in SUFFIXES:
        raise HybridError(f"out = {shown(str(out), 60)}; give a file name ending in .html")
    return path


def _in_space(points: np.ndarray) -> np.ndarray:
    """``points`` with 3 columns: the planar arm's ``(x, y)`` at ``z = 0``."""
    points = np.asarray(points, float)
    return points if points.shape[-1] == 3 else np.concatenate([points, np.zeros((*points.shape[:-1], 1))], -1)


def _lines(grid: np.ndarray) -> np.ndarray:
    """The rows and columns of a ``(3, rows, cols)`` grid as one polyline, pieces apart by NaN (a gap)."""
    pieces = [*np.moveaxis(grid, 0, -1), *np.moveaxis(grid, 0, -1).transpose(1, 0, 2)]
    gap = np.full((1, 3), np.nan)
    return np.vstack([np.vstack([p, gap]) for p in pieces])


def _surface(go, result, path: np.ndarray):
    """The surface as plotly traces (drawn once), and the points they span (for the axes' ranges)."""
    exp = result.experiment
    grey = dict(color="#b0b0b0", width=1)
    if not is_spatial(result):  # the planar arm's circle or line, in z = 0
        section = exp.section
        if hasattr(section, "radius"):
            u = np.linspace(0, 2 * np.pi, 73)
            points = np.asarray(section.center) + section.radius * np.column_stack([np.cos(u), np.sin(u)])
        else:
            points = section_ends(section, path)
        points = _in_space(points)
        return [go.Scatter3d(x=points[:, 0], y=points[:, 1], z=points[:, 2], mode="lines", name="surface",
                             line=dict(color="#808080", width=3), hoverinfo="skip")], points
    surface = exp.surface
    vertices, faces = getattr(surface, "vertices", None), getattr(surface, "faces", None)
    if vertices is not None and faces is not None:  # a part's mesh, placed in base axes
        v, f = np.asarray(vertices), np.asarray(faces)
        return [go.Mesh3d(x=v[:, 0], y=v[:, 1], z=v[:, 2], i=f[:, 0], j=f[:, 1], k=f[:, 2], name="surface",
                          color="#c8c8c8", opacity=0.5, flatshading=True, hoverinfo="skip", showlegend=True)], v
    grid = surface_grid(surface, path)
    if grid is not None:
        lines = _lines(grid)
        return [go.Scatter3d(x=lines[:, 0], y=lines[:, 1], z=lines[:, 2], mode="lines", name="surface",
                             line=grey, hoverinfo="skip", connectgaps=False)], grid.reshape(3, -1).T
    # a point cloud by its points, any other surface by where the sensor tip touched it
    cloud = getattr(surface, "points", None)
    points, name = (np.asarray(cloud), "surface (its points)") if cloud is not None else (
        touched_points(result), "contact points")
    if len(points) > 20 * PATH_POINTS:
        points = points[:: math.ceil(len(points) / (20 * PATH_POINTS))]
    return [go.Scatter3d(x=points[:, 0], y=points[:, 1], z=points[:, 2], mode="markers", name=name,
                         marker=dict(size=1.5, color="#999999"), hoverinfo="skip")], points


def _thinned(path: np.ndarray, stride: int) -> np.ndarray:
    """Every ``stride``-th point of ``path`` from the start, and its last point."""
    kept = path[::stride]
    return kept if (len(path) - 1) % stride == 0 else np.vstack([kept, path[-1:]])


def _moving(go, frame: ArmFrame, stride: int, planar: bool, force_label: str) -> list:
    """The traces one picture changes (in the order of :data:`MOVING`), for ``frame``; the force arrow
    is named ``force_label``."""
    links, path, arrow = _in_space(frame.links), _in_space(_thinned(frame.path, stride)), _in_space(frame.force_arrow)
    tip, sensor_tip = links[-1], _in_space(frame.sensor_tip)
    axes = _in_space(frame.task_axes)

    def line(points, **style):
        points = np.asarray(points)
        return go.Scatter3d(x=points[:, 0], y=points[:, 1], z=points[:, 2], **style)

    traces = [
        line(path, mode="lines", name=MOVING[0], line=dict(color="#595959", width=3)),
        line(links, mode="lines+markers", name=MOVING[1], line=dict(color="#262626", width=8),
             marker=dict(size=4, color="white", line=dict(color="#262626", width=2))),
        line([tip, sensor_tip], mode="lines+markers", name=MOVING[2], line=dict(color=to_hex("tab:purple"), width=5),
             marker=dict(size=3, color=to_hex("tab:purple"))),
        line(arrow, mode="lines+markers", name=force_label, line=dict(color=to_hex("tab:orange"), width=7),
             marker=dict(size=[0.1, 6], symbol="diamond", color=to_hex("tab:orange"))),
    ]
    names, colours = (PLANAR_AXES, AXIS_COLORS[::2]) if planar else (MOVING[4:], AXIS_COLORS)
    for name, colour, row in zip(names, colours, axes):
        traces.append(line([tip, tip + AXIS_LENGTH * row], mode="lines", name=name,
                           line=dict(color=to_hex(colour), width=5)))
    return traces


def _clock(frame: ArmFrame) -> str:
    return f"t = {frame.t:.2f} s, |F_c| = {np.linalg.norm(frame.force):.1f} N"


def _scene(points: np.ndarray) -> dict:
    """Equal scales on the three axes, spanning ``points`` (as :mod:`hybrid.animation` draws)."""
    points = points[np.isfinite(points).all(axis=1)]
    mid = (points.max(axis=0) + points.min(axis=0)) / 2
    half = max((points.max(axis=0) - points.min(axis=0)).max() / 2 * 1.1, 1e-3)
    axes = {f"{a}axis": dict(range=[m - half, m + half], title=f"{a} [m]", autorange=False)
            for a, m in zip("xyz", mid)}
    return dict(**axes, aspectmode="cube", camera=dict(eye=dict(x=1.25, y=-1.25, z=0.8)))


def _controls(frames: list[ArmFrame], fps: float) -> tuple[list, list]:
    """The play and pause buttons, and the slider with a step per picture (labelled by its time [s])."""
    play = dict(frame=dict(duration=1000.0 / fps, redraw=True), fromcurrent=True, transition=dict(duration=0),
                mode="immediate")
    still = dict(frame=dict(duration=0, redraw=True), transition=dict(duration=0), mode="immediate")
    buttons = [dict(type="buttons", direction="left", x=0.0, y=0.0, xanchor="left", yanchor="top",
                    pad=dict(t=40, r=10), showactive=False,
                    buttons=[dict(label="Play", method="animate", args=[None, play]),
                             dict(label="Pause", method="animate", args=[[None], still])])]
    slider = dict(active=0, x=0.22, len=0.78, y=0.0, yanchor="top", pad=dict(t=30),
                  currentvalue=dict(prefix="t = ", suffix=" s"),
                  steps=[dict(label=f"{f.t:.2f}", method="animate", args=[[str(f.sample)], still]) for f in frames])
    return buttons, [slider]


@checked_keywords
def view(result, every: int | None = None, *, force_scale: float | None = None, fps: float | None = None,
         title: str | None = None, out=None, overwrite: bool = False):
    """The run ``result`` as an interactive 3-D figure for the browser (plotly), a picture per chosen
    control sample with a play button and a slider.

    Each picture draws an :class:`~hybrid.animation.ArmFrame` (:func:`~hybrid.animation.arm_frames`, the
    data :func:`hybrid.animation.animate` draws): the arm's links as a polyline with a marker at every
    joint origin, the elastic sensor, the sensor tip's path so far, the recorded contact force ``F_c``
    as an arrow from the sensor tip and the task frame's axes ``t1, t2, n`` at the arm tip; the surface
    (a sphere, a cylinder or plane around the path, a part's mesh or points; any other by the points
    where the sensor tip touched it) is drawn once. Equal scales on every axis [m]. Plotly draws with
    WebGL in the browser and needs no server: written with ``out``, the figure is one HTML file with
    plotly.js inside, which opens offline.

    Parameters
    ----------
    result : SimulationResult
        The run (:func:`hybrid.simulate`); the paper's planar arm is drawn in its plane, ``z = 0``.
    every : int, optional
        Control samples between pictures (:func:`hybrid.animation.chosen_samples`): by default about 60
        pictures; the run's end is always the last.
    force_scale : float, optional
        The force arrow's length per newton [m/N]; by default the run's largest recorded contact force
        is drawn 0.1 m long.
    fps : float, optional
        Pictures per second when played; by default real time, within 1 to 30.
    title : str, optional
        A title above the figure (each picture's time and force follow it).
    out : str or path-like, optional
        An ``.html`` file to write the figure to, with plotly.js inside (about 5 MB and more), atomically.
    overwrite : bool
        Replace an existing ``out``; without it an existing file is refused.

    Returns
    -------
    plotly.graph_objects.Figure
        The figure, a frame per picture (named by its control sample); show it with ``fig.show()``
        (a browser or a notebook) or write it with ``fig.write_html``.

    Raises
    ------
    HybridError
        plotly not installed (``pip install 'hybrid-decoupling[view]'``), ``result`` not a run's
        result, ``every``, ``force_scale`` or ``fps`` not positive, ``out`` not an ``.html`` file name
        or an existing file without ``overwrite``, or the file not written (nothing changed there).

    Examples
    --------
    >>> import hybrid
    >>> # the UR5 on the sphere
    >>> res = hybrid.simulate(hybrid.tracing_experiment(duration=0.1))
    >>> fig = hybrid.view(res, every=5)
    >>> [frame.name for frame in fig.frames]  # control samples
    ['0', '5', '10']
    >>> [trace.name for trace in fig.data]
    ['surface', "sensor tip's path", 'arm', 'sensor',
     'F_c (... mm/N)', 't1', 't2', 'n']
    >>> # base, 6 joint origins, arm tip
    >>> fig.frames[-1].data[1].x.shape
    (8,)
    """
    go = _plotly()
    if getattr(result, "experiment", None) is None or not hasattr(result, "q"):
        raise HybridError(f"result = {shown(result, 40)}; give a run's result (hybrid.simulate(...))")
    if title is not None and not isinstance(title, str):
        raise HybridError(f"title = {shown(title, 40)}; give text")
    path = _out_path(out)
    samples = chosen_samples(result, every)
    fps = playback_fps(result, samples, fps)
    scale = default_force_scale(result) if force_scale is None else force_scale
    frames = arm_frames(result, samples, scale)  # checks force_scale
    scale = float(scale)
    force_label = f"{MOVING[3]} ({1e3 * scale:.3g} mm/N)"
    planar = not is_spatial(result)

    every_sample = frames[-1].path
    stride = max(1, math.ceil(len(every_sample) / PATH_POINTS))
    surface, spanned = _surface(go, result, every_sample)
    moving = [_moving(go, f, stride, planar, force_label) for f in frames]
    start = len(surface)
    indices = list(range(start, start + len(moving[0])))
    heading = f"{title}<br>" if title else ""
    figure = go.Figure(
        data=[*surface, *moving[0]],
        frames=[go.Frame(data=traces, traces=indices, name=str(f.sample),
                         layout=dict(title=dict(text=heading + _clock(f))))
                for f, traces in zip(frames, moving)])
    extent = np.vstack([_in_space(every_sample), spanned, *(_in_space(f.links) for f in frames),
                        *(_in_space(f.force_arrow) for f in frames)])
    buttons, sliders = _controls(frames, fps)
    figure.update_layout(title=dict(text=heading + _clock(frames[0]), x=0.02), scene=_scene(extent),
                         updatemenus=buttons, sliders=sliders, template="plotly_white", height=680,
                         margin=dict(l=0, r=0, t=130 if title else 100, b=100), uirevision="view",
                         legend=dict(orientation="h", x=0.0, y=1.0, yanchor="bottom", bgcolor="rgba(0,0,0,0)"))
    if path is not None:
        # a fixed id (not a random one): the same run writes the same file
        files.write_with(path, lambda tmp: figure.write_html(tmp, include_plotlyjs=True, full_html=True,
                                                             auto_play=False, div_id="hybrid-view"), overwrite)
    return figure
