"""Pictures of the arm doing the task: a run drawn sample by sample, as an animation or one still.

Each picture (:class:`ArmFrame`, the data one picture draws, as arrays) shows at one control sample

- the arm: a polyline from the base through every joint frame's origin to the arm tip ``r``
  (:func:`hybrid.models.chain_kinematics.joint_frames`, the chain the generated C is built from), and
  the elastic sensor from ``r`` to the sensor tip;
- the surface: a sphere, or a cylinder or plane around the path, as a wireframe; a part given as a mesh
  (:class:`hybrid.MeshSurface`) by its facets' edges around the path; the planar arm's circle or line;
  any other surface by the points where the sensor tip touched it;
- the sensor tip's path so far;
- the contact force ``F_c`` the run recorded (on the robot, base axes) as an arrow from the sensor tip;
- the task frame's axes ``t1, t2, n`` (the planar arm's ``t, n``) at the arm tip, the frame ``R(r)`` the
  record's task components are in (:func:`hybrid.task_frame`).

A 3-D run is drawn on 3-D axes with equal scales, the paper's planar arm on 2-D axes. Lengths are in
metres; the force arrow is ``force_scale`` metres per newton (the label says how many mm per N).
:func:`animate` (what :meth:`hybrid.SimulationResult.animate` calls) returns a matplotlib
``FuncAnimation`` and can write it as an animated GIF (Pillow's writer; an ``.mp4`` needs ffmpeg),
atomically; :func:`still` draws one picture.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from matplotlib import animation
from mpl_toolkits.mplot3d.art3d import Line3DCollection

from hybrid import files
from hybrid.errors import HybridError
from hybrid.geometry.frames import task_frame
from hybrid.geometry.parts import MeshSurface
from hybrid.geometry.surfaces import Cylinder, Plane, Sphere
from hybrid.models.chain_kinematics import joint_frames
from hybrid.plots import FONT, is_spatial
from hybrid.validate import shown

#: the file types :func:`animate` writes, and the matplotlib writer of each
WRITERS = {".gif": "pillow", ".mp4": "ffmpeg"}
#: how long the largest recorded contact force's arrow is drawn, unless told [m]
FORCE_ARROW = 0.1
#: the task frame's axes' length [m]
AXIS_LENGTH = 0.08
#: about how many pictures an animation has unless told (``every``)
PICTURES = 60
#: the task frame's axes' colours, in the order of its rows
AXIS_COLORS = ("tab:red", "tab:green", "tab:blue")
#: how far beyond the sensor tip's path a plane, a cylinder or a mesh part is drawn [m]
MARGIN = 0.05


@dataclass(frozen=True)
class ArmFrame:
    """What one picture draws, at the control sample ``sample`` (time ``t`` [s]); base axes, metres,
    3 columns (the planar arm's 2: x, y).

    ``links``: the base's origin, each joint frame's origin, the arm tip ``r``, ``(n + 2, d)``;
    ``sensor_tip`` ``(d,)``; ``path``: the sensor tip at every control sample so far, ``(k, d)``;
    ``force``: the recorded contact force ``F_c`` on the robot [N] ``(d,)``; ``force_arrow``: its
    arrow, tail at the sensor tip, ``(2, d)`` (head = tail + ``force_scale`` F_c); ``task_axes``: the
    rows of ``R(r)`` (``t1, t2, n``; the planar arm's ``t, n``), drawn from ``r``.
    """

    sample: int
    t: float
    links: np.ndarray
    sensor_tip: np.ndarray
    path: np.ndarray
    force: np.ndarray
    force_arrow: np.ndarray
    task_axes: np.ndarray


def _columns(result, names) -> np.ndarray:
    return np.column_stack([result.output(c) for c in names])


def _dimension(result) -> int:
    return 3 if is_spatial(result) else 2


def last_sample(result) -> int:
    """The last control sample whose state the record holds (the end of the run: ``n_samples``)."""
    return (len(result.t) - 1) // result.experiment.steps_per_sample


def chosen_samples(result, every: int | None = None) -> np.ndarray:
    """The control samples an animation of ``result`` draws: every ``every``-th from 0 (default: about
    :data:`PICTURES` of them), and the run's end."""
    last = last_sample(result)
    if every is None:
        every = max(1, round(last / PICTURES))
    elif isinstance(every, bool) or not isinstance(every, numbers.Integral) or every <= 0:
        raise HybridError(f"every = {shown(every, 40)}; give a whole number of control samples >= 1 between "
                          "pictures (e.g. every=10)")
    samples = np.arange(0, last + 1, int(every))
    return samples if samples[-1] == last else np.append(samples, last)


def default_force_scale(result) -> float:
    """Metres per newton that draw the run's largest recorded contact force :data:`FORCE_ARROW` long."""
    d = _dimension(result)
    largest = np.linalg.norm(_columns(result, ("Fc_x", "Fc_y", "Fc_z")[:d]), axis=1).max()
    return FORCE_ARROW / largest if np.isfinite(largest) and largest > 0 else FORCE_ARROW / 10.0


def arm_frames(result, samples, force_scale: float | None = None) -> list[ArmFrame]:
    """The pictures of ``result`` at the control ``samples`` (:class:`ArmFrame` each); ``force_scale``
    [m/N], default :func:`default_force_scale`."""
    exp = result.experiment
    samples = np.atleast_1d(np.asarray(samples))
    last = last_sample(result)
    if (samples.dtype.kind not in "iu" or samples.ndim != 1 or samples.size == 0 or samples.min() < 0
            or samples.max() > last):
        raise HybridError(f"samples = {shown(samples, 60)}; give control sample numbers from 0 to {last}")
    d = _dimension(result)
    scale = default_force_scale(result) if force_scale is None else _positive("force_scale", force_scale)
    rows = samples * exp.steps_per_sample
    origins, _, tip, _ = joint_frames(exp.robot.chain, result.q[rows])
    links = np.concatenate([origins, tip[:, None, :]], axis=1)[:, :, :d]
    sensor = _columns(result, ("s_x", "s_y", "s_z")[:d])
    force = _columns(result, ("Fc_x", "Fc_y", "Fc_z")[:d])[rows]
    r = links[:, -1]
    options = {"frame_direction": exp.frame_direction} if d == 3 else {}
    axes, _ = task_frame(exp.surface, r, np.zeros_like(r), **options)
    every_sample = sensor[::exp.steps_per_sample]
    return [ArmFrame(int(k), float(result.t[row]), links[i], sensor[row], every_sample[:k + 1], force[i],
                     np.array([sensor[row], sensor[row] + scale * force[i]]), axes[i])
            for i, (k, row) in enumerate(zip(samples, rows))]


def arm_frame(result, sample: int, force_scale: float | None = None) -> ArmFrame:
    """The picture of ``result`` at the control sample ``sample`` (negative: from the end)."""
    if isinstance(sample, bool) or not isinstance(sample, numbers.Integral):
        raise HybridError(f"sample = {shown(sample, 40)}; give a control sample number")
    last = last_sample(result)
    return arm_frames(result, [int(sample) + (last + 1 if sample < 0 else 0)], force_scale)[0]


def playback_fps(result, samples, fps: float | None = None) -> float:
    """Pictures per second that play the pictures at the control ``samples`` of ``result``: ``fps`` if
    given (a positive number), else real time, within 1 to 30."""
    if fps is None:
        step = (samples[1] - samples[0]) * result.experiment.sample_time if len(samples) > 1 else 1.0
        fps = min(30.0, max(1.0, 1.0 / step))
    return _positive("fps", fps)


def _positive(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not np.isfinite(value) or value <= 0:
        raise HybridError(f"{name} = {shown(value, 40)}; give a positive number")
    return float(value)


# ------------------------------------------------------------------ drawing


def _across(direction: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors that make a right-handed orthonormal basis with the unit ``direction``."""
    a = next(e for e in np.eye(3) if abs(e @ direction) < 0.9)
    a = a - (a @ direction) * direction
    a /= np.linalg.norm(a)
    return a, np.cross(direction, a)


def surface_grid(surface, path: np.ndarray) -> np.ndarray | None:
    """A grid of points on ``surface`` around the sensor tip's ``path``, ``(3, rows, cols)`` (drawn as a
    wireframe); None for a surface drawn by its contact points (:func:`touched_points`)."""
    if isinstance(surface, Sphere):
        u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 25), np.linspace(0, np.pi, 13))
        c, rho = np.asarray(surface.center), surface.radius
        return np.array([c[0] + rho * np.cos(u) * np.sin(v), c[1] + rho * np.sin(u) * np.sin(v),
                         c[2] + rho * np.cos(v)])
    if isinstance(surface, Cylinder):  # the stretch of it the path spans
        axis, point = np.asarray(surface.axis), np.asarray(surface.point)
        along = (path - point) @ axis
        a, b = _across(axis)
        h, u = np.meshgrid(np.linspace(along.min() - MARGIN, along.max() + MARGIN, 5), np.linspace(0, 2 * np.pi, 25))
        ring = surface.radius * (np.cos(u)[..., None] * a + np.sin(u)[..., None] * b)
        return np.moveaxis(point + h[..., None] * axis + ring, -1, 0)
    if isinstance(surface, Plane):  # a square patch around the path
        a, b = _across(np.asarray(surface.normal))
        on = np.array([surface.project(p) for p in path])
        mid = on.mean(axis=0)
        half = max(np.abs((on - mid) @ a).max(), np.abs((on - mid) @ b).max()) + 2 * MARGIN
        u, v = np.meshgrid(np.linspace(-half, half, 7), np.linspace(-half, half, 7))
        return np.moveaxis(mid + u[..., None] * a + v[..., None] * b, -1, 0)
    return None


def _facets_near(surface, path: np.ndarray) -> np.ndarray | None:
    """The facets of a mesh part with a corner within :data:`MARGIN` of the box around the sensor tip's
    ``path``, ``(facets, 3, 3)``; None for a surface that is not a mesh."""
    if not isinstance(surface, MeshSurface):
        return None
    corners = surface.vertices[surface.faces]
    near = np.all((corners >= path.min(axis=0) - MARGIN) & (corners <= path.max(axis=0) + MARGIN), axis=2)
    return corners[near.any(axis=1)]


def section_ends(section, path: np.ndarray) -> np.ndarray:
    """The planar arm's straight ``section`` (a line) from 0.1 m before the sensor tip's ``path`` to 0.1 m
    beyond it, ``(2, 2)``."""
    normal = np.asarray(section.normal)
    tangent = np.array([-normal[1], normal[0]])
    along = (path - section.point) @ tangent
    return np.asarray(section.point) + np.outer([along.min() - 0.1, along.max() + 0.1], tangent)


def touched_points(result) -> np.ndarray:
    """The sensor tip at the control samples of ``result`` where it touched the surface, ``(k, d)``: how a
    surface with no grid (:func:`surface_grid`) is drawn."""
    every = result.experiment.steps_per_sample
    path = _columns(result, ("s_x", "s_y", "s_z")[:_dimension(result)])[::every]
    return path[result.contact_force[::every] > 0]


class ArmPicture:
    """A figure that draws the pictures of one run; :meth:`draw` shows one :class:`ArmFrame`."""

    def __init__(self, result, frames: list[ArmFrame], force_scale: float, title: str | None = None):
        self.result, self.frames = result, frames
        exp = result.experiment
        self.d = _dimension(result)
        self.figure = plt.figure(figsize=(6.4, 5.6) if self.d == 3 else (6.0, 5.0), layout="constrained")
        ax = self.figure.add_subplot(projection="3d" if self.d == 3 else None)
        self.ax = ax
        path = _columns(result, ("s_x", "s_y", "s_z")[:self.d])[::exp.steps_per_sample]
        extent = [path, *(f.links for f in frames)]
        extent.append(self._draw_surface(exp, path))
        empty = np.zeros((0, self.d))
        self.path, = ax.plot(*empty.T, color="0.35", lw=1.0, label="sensor tip's path")
        self.arm, = ax.plot(*empty.T, color="0.15", lw=2.5, marker="o", ms=4, mfc="white", label="arm (joint origins)")
        self.sensor, = ax.plot(*empty.T, color="tab:purple", lw=1.5, marker="o", ms=3, label="sensor")
        self.force, = ax.plot(*empty.T, color="tab:orange", lw=2.5,
                              label=f"contact force $F_c$ ({1e3 * force_scale:.3g} mm/N)")
        self.force_head, = ax.plot(*empty.T, color="tab:orange", marker="o", ms=4, ls="none")
        names = ("$t_1$", "$t_2$", "$n$") if self.d == 3 else ("$t$", "$n$")
        colours = AXIS_COLORS if self.d == 3 else AXIS_COLORS[::2]
        self.axes = [ax.plot(*empty.T, color=c, lw=1.5, label=name)[0] for name, c in zip(names, colours)]
        self._limits(np.vstack([e.reshape(-1, self.d) for e in extent if e is not None]))
        ax.legend(fontsize=FONT - 2, loc="upper left", ncol=2, frameon=False)
        self.clock = ax.set_title("", fontsize=FONT)
        if title:
            self.figure.suptitle(title, fontsize=FONT + 1)

    def _draw_surface(self, exp, path: np.ndarray) -> np.ndarray | None:
        """The surface, drawn once; returns its drawn points (for the axes' limits)."""
        ax = self.ax
        if self.d == 2:
            section = exp.section
            if hasattr(section, "radius"):
                ax.add_patch(plt.Circle(section.center, section.radius, color="0.85", ec="0.5", lw=1.0))
                return np.asarray(section.center) + section.radius * np.array([[-1, -1], [1, 1]])
            ends = section_ends(section, path)
            ax.plot(*ends.T, color="0.5", lw=1.5)
            return ends
        grid = surface_grid(exp.surface, path)
        if grid is not None:
            ax.plot_wireframe(*grid, color="0.8", lw=0.5)
            return grid.reshape(3, -1).T
        facets = _facets_near(exp.surface, path)
        if facets is not None and len(facets):
            ax.add_collection3d(Line3DCollection(facets, colors="0.85", linewidths=0.3))
            return facets.reshape(-1, 3)
        touched = touched_points(self.result)
        ax.scatter(*touched.T, s=2, color="0.6", label="contact points")
        return touched

    def _limits(self, points: np.ndarray) -> None:
        """Equal scales on every axis, spanning ``points``."""
        mid = (points.max(axis=0) + points.min(axis=0)) / 2
        half = (points.max(axis=0) - points.min(axis=0)).max() / 2 * 1.1
        names = "xyz"[:self.d]
        self.ax.set(**{f"{a}lim": (m - half, m + half) for a, m in zip(names, mid)})
        for a in names:
            getattr(self.ax, f"set_{a}label")(f"{a} [m]", fontsize=FONT)
        if self.d == 3:
            self.ax.set_box_aspect((1, 1, 1))
        else:
            self.ax.set_aspect("equal")
            self.ax.grid(alpha=0.3)
        self.ax.tick_params(labelsize=FONT - 2)

    def _set(self, line, points: np.ndarray) -> None:
        if self.d == 3:
            line.set_data_3d(*points.T)
        else:
            line.set_data(*points.T)

    def draw(self, frame: ArmFrame) -> list:
        """Show ``frame``; returns the artists changed."""
        self._set(self.path, frame.path)
        self._set(self.arm, frame.links)
        self._set(self.sensor, np.array([frame.links[-1], frame.sensor_tip]))
        self._set(self.force, frame.force_arrow)
        self._set(self.force_head, frame.force_arrow[1:])
        for line, row in zip(self.axes, frame.task_axes):
            self._set(line, np.array([frame.links[-1], frame.links[-1] + AXIS_LENGTH * row]))
        self.clock.set_text(f"t = {frame.t:.2f} s, |F_c| = {np.linalg.norm(frame.force):.1f} N")
        return [self.path, self.arm, self.sensor, self.force, self.force_head, *self.axes, self.clock]


def still(result, sample: int = -1, *, force_scale: float | None = None, title: str | None = None):
    """One picture of ``result`` at the control sample ``sample`` (default: the end) as a matplotlib
    Figure; nothing is shown or written."""
    scale = default_force_scale(result) if force_scale is None else _positive("force_scale", force_scale)
    frame = arm_frame(result, sample, scale)
    picture = ArmPicture(result, [frame], scale, title)
    picture.draw(frame)
    return picture.figure


def _out_path(out) -> Path | None:
    """``out`` checked before anything is drawn: None, or a file name whose suffix a writer takes."""
    if out is None:
        return None
    path = files.output_path(out)
    writer = WRITERS.get(path.suffix.lower())
    if writer is None:
        raise HybridError(f"out = {shown(str(out), 60)}; give a file name ending in "
                          f"{' or '.join(WRITERS)} (an animated GIF needs nothing more; an MP4 needs ffmpeg)")
    if not animation.writers.is_available(writer):
        raise HybridError(f"out = {shown(str(out), 60)}: writing {path.suffix} needs matplotlib's {writer!r} "
                          "writer, which is not available (install ffmpeg); give a .gif file name")
    return path


def animate(result, every: int | None = None, out=None, *, fps: float | None = None, overwrite: bool = False,
            force_scale: float | None = None, title: str | None = None, dpi: int = 100):
    """The run ``result`` as a matplotlib ``FuncAnimation``: one picture (:class:`ArmFrame`) per
    ``every``-th control sample (:func:`chosen_samples`), at ``fps`` pictures per second (default: real
    time, within 1 to 30).

    With ``out`` (a ``.gif`` path; ``.mp4`` when ffmpeg is installed) the animation is also written
    there, atomically; an existing file is refused unless ``overwrite``. Returns the animation (its
    figure stays open: in a notebook, show it with ``IPython.display.HTML(anim.to_jshtml())``).
    """
    path = _out_path(out)
    samples = chosen_samples(result, every)
    scale = default_force_scale(result) if force_scale is None else _positive("force_scale", force_scale)
    fps = playback_fps(result, samples, fps)
    frames = arm_frames(result, samples, scale)
    picture = ArmPicture(result, frames, scale, title)
    picture.draw(frames[0])  # the figure shows the start until the animation runs
    anim = animation.FuncAnimation(picture.figure, picture.draw, frames=frames, init_func=lambda: [],
                                   interval=1000.0 / fps, blit=False, repeat=True)
    if path is not None:
        writer = animation.writers[WRITERS[path.suffix.lower()]]
        files.write_with(path, lambda tmp: anim.save(tmp, writer=writer(fps=fps), dpi=dpi), overwrite)
    return anim
