"""Figures of runs and sweeps: matplotlib Figures to show or save, and the files the commands write.

Figures (each returns a :class:`matplotlib.figure.Figure`; nothing is shown or saved):

- :func:`plot_result` (what :meth:`hybrid.SimulationResult.plot` draws): one run's tangential speed
  [m/s] and normal force [N] against their references over time [s]; for a 3-D run also the sensor
  tip's deviation from the desired path across it, along ``t2`` [mm], and its penetration into the
  surface [mm];
- :func:`plot_comparison`: the same speed and force for several runs on shared axes (one per scheme);
- :func:`plot_path`: 3-D runs' paths in space (equal axis scales, the desired path dashed) and their
  deviation from the desired path [mm] and penetration [mm] over time;
- :func:`plot_first_touch`: runs from free space: the measured normal force and the surface's force on
  the sensor tip against the time from the first touch;
- :func:`plot_path_force`: a 3-D run's sensor-tip trace on a light wireframe of its surface, coloured by
  the measured normal force [N];
- :func:`plot_normal_estimate`: an estimated surface's normal against the true one (or the angle
  between them [deg]) over time [s];
- :func:`plot_sweep`: a sweep's metric over two swept settings, a panel per value of up to two
  others, the panels on one colour scale; or the ratio of one row's values to another's
  (e.g. the task law's metric over Khatib's), on a logarithmic scale centred at 1.

Files (each writes every format asked for, atomically, and returns the paths): :func:`paper_figures`,
:func:`trace_figures`, :func:`sweep_heatmaps`, :func:`save`. PNG by default; PDF and SVG are vector
graphics. Axis labels carry names and units (:func:`label`).
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np

from hybrid import files
from hybrid.deprecation import RENAMED
from hybrid.errors import HybridError
from hybrid.geometry.surface_points import project_points
from hybrid.spec.metrics import METRICS

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colors, ticker  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

# ------------------------------------------------------------------ styles and labels

TITLES = {"khatib": "Khatib (1987) operational space", "task": "task-space decoupling",
          "raibert_craig": "Raibert & Craig (1981)", "fisher_mujtaba": "Raibert & Craig, Fisher & Mujtaba (1992)"}
#: each scheme's line: colour, and a line style and marker that tell it apart in grey print too; the
#: task law is drawn on top (highest zorder)
STYLES = {"task": dict(color="tab:blue", ls="-", marker="o", lw=1.6, zorder=4),
          "khatib": dict(color="tab:red", ls="--", marker="s", lw=1.4, zorder=3),
          "raibert_craig": dict(color="tab:green", ls="-.", marker="^", lw=1.2, zorder=2),
          "fisher_mujtaba": dict(color="tab:olive", ls=":", marker="v", lw=1.2, zorder=2)}
COLORS = {k: s["color"] for k, s in STYLES.items()}
#: the schemes' short names, where a long one does not fit
SHORT = {"task": "task law", "khatib": "Khatib", "raibert_craig": "Raibert & Craig",
         "fisher_mujtaba": "Fisher & Mujtaba"}
#: the references: a wide light-grey band behind the measured lines
REFERENCE = dict(color="0.55", lw=3.0, alpha=0.55, zorder=1, solid_capstyle="butt", label="reference")
#: the formats the file writers take
FORMATS = ("png", "pdf", "svg")
FONT = 9  # pt, at the figures' saved size

#: names and units of the metrics (hybrid.metrics, as hybrid.spec.metrics declares them) and of settings a sweep
#: often varies
LABELS = {
    **{m.name: m.axis_label for m in METRICS},
    "normal_angle_error_deg": "RMS normal estimate error [deg]",
    "max_normal_angle_error_deg": "largest normal estimate error [deg]",
    "model_error": "model error (inertia too high) [fraction]",
    "viscous_compensation": "viscous friction compensated [fraction]",
    "controller": "scheme",
    "contact.friction": "friction coefficient [-]",
    "contact.stiffness": "contact stiffness [N/m]",
    "contact.damping": "contact damping [N s/m]",
    "sensor.stiffness": "sensor stiffness [N/m]",
    "sensor.damping": "sensor damping [N s/m]",
    "sensor.mass": "sensor tip mass [kg]",
    "sensor.force_noise": "sensor force noise (standard deviation) [N]",
    "sensor.bandwidth_hz": "sensor bandwidth [Hz]",
    "sensor.delay_samples": "sensor delay [samples]",
    "start_gap": "start gap [m]",
    "approach_speed": "approach speed [m/s]",
    "speed_reference.before": "speed while the force steps [m/s]",
    "speed_reference.after": "speed after the speed step [m/s]",
    "speed_reference.at": "time of the speed step [s]",
    "force_reference.before": "force before the force step [N]",
    "force_reference.after": "force after the force step [N]",
    "force_reference.at": "time of the force step [s]",
    "v_d": "speed reference [m/s]",
    "F_d": "force reference [N]",
    "duration": "duration [s]",
    "sample_time": "sample time [s]",
    "integration_step": "integration step [s]",
}
#: the units metric names end with, and how a label writes them
SUFFIXES = (("_m_per_s", "m/s"), ("_percent", "%"), ("_Nm", "N m"), ("_deg", "deg"), ("_N", "N"), ("_s", "s"),
            ("_m", "m"))
GAIN_UNITS = {"KPv": "1/s", "KIv": "1/s^2", "KI2v": "1/s^3", "KPf": "1/kg", "KDf": "1/s", "KIf": "1/(kg s)"}


def label(name: str) -> str:
    """A metric's or a setting's name as an axis label with its unit: ``speed_drop_after_force_step_m_per_s``
    is ``"speed drop after the force step [m/s]"``; an unknown name is spelled out from its parts."""
    name = RENAMED.get(name, name)  # a sweep's parameter by a renamed setting's old name
    if name in LABELS:
        return LABELS[name]
    gain = name.removeprefix("gains.")
    if gain in GAIN_UNITS:
        return f"gain {gain} [{GAIN_UNITS[gain]}]"
    if name.startswith("peak_torque_joint"):
        return f"peak torque of joint {name.removeprefix('peak_torque_joint').removesuffix('_Nm')} [N m]"
    unit = ""
    for suffix, text in SUFFIXES:
        if name.endswith(suffix):
            name, unit = name[:-len(suffix)], f" [{text}]"
            break
    words = name.replace(".", " ").replace("_", " ").replace("rms", "RMS").replace("2pct", "2 %")
    return words + unit


def _scaled(text: str, values) -> tuple[str, float]:
    """``(label, factor)``: lengths and speeds below 1 in mm and mm/s (values times 1000)."""
    finite = np.abs(np.asarray(values, float))
    finite = finite[np.isfinite(finite)]
    if finite.size and finite.max() < 1.0:
        for si, small in (("[m/s]", "[mm/s]"), ("[m]", "[mm]")):
            if text.endswith(si):
                return text[:-len(si)] + small, 1e3
    return text, 1.0


def _value_text(value) -> str:
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        return f"{value:g}"
    return TITLES.get(str(value), str(value))


def _style(ax) -> None:
    ax.grid(alpha=0.3)
    ax.tick_params(labelsize=FONT - 1)


def _markevery(n: int, scheme: str | None, n_markers: int = 10):
    """About ``n_markers`` markers over ``n`` points, staggered between the schemes so they do not
    fall on one another."""
    every = max(1, n // n_markers)
    k = list(STYLES).index(scheme) if scheme in STYLES else 0
    return (every * k // len(STYLES), every)


def _line(ax, t, y, scheme: str | None, name: str, markers: bool = True):
    style = dict(STYLES.get(scheme, dict(color="tab:blue", ls="-", marker=None, lw=1.4, zorder=4)))
    if not markers:
        style.pop("marker")
    return ax.plot(t, y, label=name, markevery=_markevery(len(t), scheme), ms=4, mfc="white", **style)


def _finished(fig, axes, title: str | None):
    """``fig`` with its axes in the project's style, the first one's legend and the title."""
    for ax in axes:
        _style(ax)
    axes[0].legend(fontsize=FONT - 1, loc="lower right")
    if title:
        fig.suptitle(title, fontsize=FONT + 1)
    return fig


def _rows(res, every: int | None = None) -> slice:
    """Every k-th record row, enough for a smooth line (about 3,000 points)."""
    return slice(None, None, every or max(1, len(res.t) // 3000))


# ------------------------------------------------------------------ runs


def is_spatial(res) -> bool:
    """Whether ``res`` is a 3-D run (its record has a z coordinate)."""
    return "s_z" in res.record["outputs"]


def path_deviation(res, rows: slice = slice(None)) -> tuple[np.ndarray, np.ndarray]:
    """The sensor tip's deviation [m] from the desired path of a 3-D run, at the record's ``rows``:
    ``(across, normal)``, along ``t2 = n x t1`` (in the surface, across the path) and along the
    surface normal ``n`` at the nearest point of the path (positive towards the robot)."""
    exp = res.experiment
    path = exp.followed_path()
    tip = np.column_stack([res.output(c)[rows] for c in ("s_x", "s_y", "s_z")])
    arcs = np.array([path.arc_of(p) for p in tip])
    nearest = path.points_at(arcs)
    t1 = np.array([path.tangent_at(s) for s in arcs])
    n = np.array([exp.surface.normal_at(p) for p in nearest])
    t2 = np.cross(n, t1)
    d = tip - nearest
    return np.einsum("ij,ij->i", d, t2), np.einsum("ij,ij->i", d, n)


def plot_result(res, title: str | None = None, scheme: str | None = None):
    """One run: tangential speed [m/s] and normal force [N] against their references over time [s];
    for a 3-D run also the deviation from the desired path across it [mm] and the penetration [mm].
    Returns the Figure."""
    scheme = scheme or getattr(res.experiment, "controller", None)
    return plot_comparison({scheme: res}, title=title or f"{TITLES.get(scheme, scheme)}: one run",
                           path=is_spatial(res))


#: the pair a comparison draws the difference of, when both ran: the task law minus Khatib's scheme, whose curves
#: nearly coincide on the signals' own scale
DIFFERENCE = ("task", "khatib")


def conditions(exp) -> str:
    """The conditions of a run in a few words, for a figure's title: the surface, the contact's friction, the
    controller's model, the sample time."""
    model = ("the controller told its own robot" if exp.controller_robot is not None
             else f"model {100 * exp.model_error:+.0f} %" if exp.model_error else "exact model")
    return (f"{exp.surface.kind}, friction {exp.contact.friction:g}, {model}, "
            f"T = {1e3 * exp.sample_time:g} ms")


def plot_comparison(results: dict, title: str | None = None, path: bool = False):
    """Runs on shared axes, ``{scheme name: SimulationResult}``: speed [m/s] and force [N] against the
    (first run's) references over time [s]; where the task law and Khatib's scheme both ran, their
    difference (task law minus Khatib) under each; with ``path`` (3-D runs) also the deviation across the
    desired path [mm] and the penetration [mm]. Returns the Figure."""
    pair = all(name in results for name in DIFFERENCE) and len(results[DIFFERENCE[0]].t) == len(
        results[DIFFERENCE[1]].t)
    panels = (4 if path else 2) + (2 if pair else 0)
    fig, axes = plt.subplots(panels, 1, figsize=(7.0, 2.3 * panels + 0.6), sharex=True, layout="constrained")
    if pair:  # the difference under its signal: speed, its difference, force, its difference, then the rest
        signal_axes = [axes[0], axes[2], *axes[4:]]
        _differences(axes[1], axes[3], *(results[name] for name in DIFFERENCE))
        axes = signal_axes
    first = next(iter(results.values()))
    rows = _rows(first)
    axes[0].plot(first.t[rows], first.speed_reference[rows], **REFERENCE)
    axes[1].plot(first.t[rows], first.force_reference[rows], **REFERENCE)
    for scheme, res in results.items():
        rows = _rows(res)
        name = TITLES.get(scheme, scheme)
        _line(axes[0], res.t[rows], res.velocity_tangential[rows], scheme, name)
        _line(axes[1], res.t[rows], res.force_normal[rows], scheme, name)
        if path:
            across, _ = path_deviation(res, rows)
            _line(axes[2], res.t[rows], 1e3 * across, scheme, name)
            _line(axes[3], res.t[rows], 1e3 * res.penetration[rows], scheme, name)
    axes[0].set_ylabel("tangential speed [m/s]", fontsize=FONT)
    axes[1].set_ylabel("normal force [N]", fontsize=FONT)
    if path:
        axes[2].set_ylabel("deviation across\nthe desired path [mm]", fontsize=FONT)
        axes[3].set_ylabel("penetration [mm]", fontsize=FONT)
    fig.axes[-1].set_xlabel("time [s]", fontsize=FONT)
    return _finished(fig, fig.axes, title)


def _differences(ax_speed, ax_force, a, b) -> None:
    """The task law's speed and force minus Khatib's, at the same times (their runs share the time grid)."""
    rows = _rows(a)
    for ax, what, unit in ((ax_speed, "velocity_tangential", "m/s"), (ax_force, "force_normal", "N")):
        ax.plot(a.t[rows], (getattr(a, what) - getattr(b, what))[rows], color="0.25", lw=1.0)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_ylabel(f"{SHORT[DIFFERENCE[0]]} - {SHORT[DIFFERENCE[1]]}\n[{unit}]", fontsize=FONT)


def plot_path(results: dict, title: str | None = None):
    """3-D runs' paths, ``{scheme name: SimulationResult}``: the sensor tip in space with equal axis
    scales [m] (the desired path dashed, the surface faint), and its deviation from the desired path
    across it [mm] and its penetration [mm] over time [s]. Returns the Figure."""
    fig = plt.figure(figsize=(11.0, 5.0), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.0, 1.15))
    ax3 = fig.add_subplot(grid[:, 0], projection="3d")
    across_ax = fig.add_subplot(grid[0, 1])
    pen_ax = fig.add_subplot(grid[1, 1], sharex=across_ax)
    first = next(iter(results.values()))
    exp = first.experiment
    surface, path = exp.surface, exp.followed_path()
    tips = []
    for scheme, res in results.items():
        rows = _rows(res)
        name = TITLES.get(scheme, scheme)
        tip = np.column_stack([res.output(c)[rows] for c in ("s_x", "s_y", "s_z")])
        tips.append(tip)
        style = {k: v for k, v in STYLES.get(scheme, {}).items() if k != "zorder"}
        ax3.plot(*tip.T, label=name, markevery=_markevery(len(tip), scheme), ms=3, mfc="white", **style)
        across, _ = path_deviation(res, rows)
        _line(across_ax, res.t[rows], 1e3 * across, scheme, name)
        _line(pen_ax, res.t[rows], 1e3 * res.penetration[rows], scheme, name)
    desired = path.points_at(np.linspace(0.0, 2 * np.pi * getattr(path, "radius", 0.0), 200)) \
        if hasattr(path, "radius") else np.array([path.point_at(s) for s in (-0.1, 0.1)])
    ax3.plot(*desired.T, color="k", ls=":", lw=1.0, label="desired path")
    if hasattr(surface, "radius") and hasattr(surface, "center") and len(surface.center) == 3:
        c = np.asarray(surface.center)
        u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 37), np.linspace(0, np.pi / 2, 7))
        ax3.plot_wireframe(c[0] + surface.radius * np.cos(u) * np.sin(v), c[1] + surface.radius * np.sin(u) * np.sin(v),
                           c[2] + surface.radius * np.cos(v), color="0.85", lw=0.4)
    _equal_scales(ax3, np.vstack([*tips, desired]))
    ax3.legend(fontsize=FONT - 1, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=2, frameon=False)
    ax3.set_title("the sensor tip's path (equal scales)", fontsize=FONT)
    across_ax.set_ylabel("deviation across\nthe desired path [mm]", fontsize=FONT)
    pen_ax.set_ylabel("penetration [mm]", fontsize=FONT)
    pen_ax.set_xlabel("time [s]", fontsize=FONT)
    for ax in (across_ax, pen_ax):
        _style(ax)
    across_ax.tick_params(labelbottom=False)
    if title:
        fig.suptitle(title, fontsize=FONT + 1)
    return fig


def _equal_scales(ax3, points: np.ndarray) -> None:
    """The 3-D axes ``ax3`` about ``points`` (N x 3) [m] with equal scales (a cube of equal spans), labelled."""
    mid, half = (points.max(0) + points.min(0)) / 2, (points.max(0) - points.min(0)).max() / 2 * 1.05
    ax3.set(xlim=(mid[0] - half, mid[0] + half), ylim=(mid[1] - half, mid[1] + half),
            zlim=(mid[2] - half, mid[2] + half))
    ax3.set_box_aspect((1, 1, 1))
    for axis in "xyz":
        getattr(ax3, f"set_{axis}label")(f"{axis} [m]", fontsize=FONT)
    ax3.tick_params(labelsize=FONT - 2)


def plot_path_force(res, ax=None, *, every: int | None = None, cmap: str = "viridis", vmin: float | None = None,
                    vmax: float | None = None, colorbar: bool = True):
    """A 3-D run's sensor-tip trace on its surface, coloured by the measured normal force.

    Parameters
    ----------
    res : SimulationResult
        A run of an arm in space (e.g. along a :class:`~hybrid.PathTask`).
    ax : mpl_toolkits.mplot3d.axes3d.Axes3D, optional
        The 3-D axes to draw on; a new figure's when None.
    every : int, optional
        Draw every ``every``-th record row (default: about 3,000 points).
    cmap, vmin, vmax
        The colour map and the force range [N] it spans (default the plotted forces' range).
    colorbar : bool
        Add a colour bar of the force.

    Returns
    -------
    Axes3D
        The axes: the trace is its last collection, one segment per plotted point to the next, its
        ``get_array()`` the measured normal force ``res.force_normal`` [N] at each segment's first
        point; the surface, a light wireframe about the trace, beneath it; equal scales.
    """
    if not is_spatial(res):
        raise HybridError("plot_path_force draws a run in space; this run is planar (plot it with plot_result)")
    if ax is None:
        ax = plt.figure(figsize=(6.0, 5.0), layout="constrained").add_subplot(projection="3d")
    rows = _rows(res, every)
    tip = np.column_stack([res.output(c)[rows] for c in ("s_x", "s_y", "s_z")])
    force = res.force_normal[rows]
    # the wireframe: a grid in the tangent plane at the trace's middle, 20 % wider, moved onto the surface
    surface, mid = res.experiment.surface, (tip.max(0) + tip.min(0)) / 2
    (centre,), (n,) = project_points(surface, mid[None, :], "plot_path_force")
    u = np.cross(n, (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0))
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    a, b = (tip - centre) @ u, (tip - centre) @ v
    half = 0.6 * max(np.ptp(a), np.ptp(b), 1e-3)
    A, B = np.meshgrid(np.linspace(-half, half, 15), np.linspace(-half, half, 15))
    grid = centre + A.reshape(-1, 1) * u + B.reshape(-1, 1) * v
    on, _ = project_points(surface, grid, "plot_path_force")
    ax.plot_wireframe(*(on[:, i].reshape(A.shape) for i in range(3)), color="0.8", lw=0.4)
    trace = Line3DCollection(np.stack([tip[:-1], tip[1:]], axis=1), cmap=cmap, lw=1.6,
                             norm=colors.Normalize(force.min() if vmin is None else vmin,
                                                   force.max() if vmax is None else vmax))
    trace.set_array(force[:-1])
    ax.add_collection(trace)
    _equal_scales(ax, np.vstack([tip, on]))
    if colorbar:
        ax.figure.colorbar(trace, ax=ax, shrink=0.7, label="measured normal force [N]")
    return ax


def plot_normal_estimate(result, ax=None, *, angle: bool = False, label: str | None = None, color=None):
    """An estimated surface's normal (:class:`~hybrid.EstimatedSurface`) against the true one over time.

    ``result``: a :class:`~hybrid.SimulationResult` of a controller that estimated the surface. On ``ax``
    (a new figure's when None) the three components of the estimate (solid) and of the true surface's
    normal at the sensor tip (dashed), base axes, one per control sample; with ``angle``, the angle
    between them [deg] instead, drawn with ``label`` and ``color``. Returns the axes; a result without an
    estimate is a HybridError.
    """
    if result.normal_estimate is None:
        raise HybridError("this run's controller was told its surface: there is no normal estimate to plot; "
                          "run it with controller_surface=hybrid.EstimatedSurface(...)")
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 3.4))
    t = result.sample_t
    if angle:
        ax.plot(t, result.normal_angle_error_deg, color=color, lw=1.2, label=label or "estimate")
        ax.set_ylabel("normal angle error [deg]")
    else:
        true = result.true_normal
        for i, (name, c) in enumerate(zip("xyz", ("tab:blue", "tab:orange", "tab:green"))):
            ax.plot(t, result.normal_estimate[:, i], color=c, lw=1.2, label=f"$n_{name}$ estimated")
            ax.plot(t, true[:, i], color=c, lw=1.0, ls="--", label=f"$n_{name}$ true")
        ax.set_ylabel("normal (base axes)")
    ax.set_xlabel("time [s]")
    ax.grid(alpha=0.3)
    return ax


# ------------------------------------------------------------------ sweeps


def plot_sweep(table, x: str, y: str, metric: str, rows: str | None = None, cols: str | None = None,
               ratio: tuple | None = None):
    """A sweep's ``metric`` (a column of :func:`hybrid.sweep`'s table) over the swept settings ``x`` by
    ``y``, averaged over any other swept setting, a panel per value of ``rows`` and ``cols``; runs
    that are not ``ok`` and NaN cells are left blank. The panels share one colour scale, from the
    smallest to the largest cell of any panel, and one colour bar, in the metric's unit (lengths and
    speeds below 1 in mm and mm/s): a colour is the same value in every panel. With
    ``ratio = (a, b)`` (two values of ``rows``): one row of panels, the metric at ``rows = a`` over
    the metric at ``rows = b``, on one logarithmic scale centred at 1 for every panel (blue: ``a``'s
    smaller; a black line where the two are equal). Returns the Figure, or None when no run reports
    the metric."""
    ok = table[table["status"] == "ok"]
    if ratio is not None:
        if rows is None:
            raise ValueError("ratio divides one value of rows by another: give rows")
        ok = ok[ok[rows].isin(ratio)]
    index = [c for c in (rows, cols) if c] + [y]
    grid = ok.pivot_table(index=index, columns=x, values=metric, aggfunc="mean") if len(ok) else None
    if grid is None or not np.isfinite(grid.values).any():
        return None
    col_values = sorted(table[cols].unique()) if cols else [None]
    row_values = [None] if ratio is not None else (sorted(table[rows].unique(), key=_order) if rows else [None])
    text, factor = _scaled(label(metric), grid.values)
    panels = {}
    for rv in row_values:
        for cv in col_values:
            try:
                panels[rv, cv] = _panel(grid, rows, cols, rv, cv, ratio)
            except KeyError:  # no run of this panel finished: left empty
                pass
    norm = _ratio_norm(panels.values()) if ratio is not None else _shared_norm(panels.values(), factor)
    fig, axes = plt.subplots(len(row_values), len(col_values), squeeze=False, layout="constrained",
                             figsize=(3.3 * len(col_values) + 1.6, 2.8 * len(row_values) + 0.9))
    image = None
    for i, rv in enumerate(row_values):
        for j, cv in enumerate(col_values):
            ax = axes[i][j]
            if (rv, cv) not in panels:
                ax.text(0.5, 0.5, "no ok runs", ha="center", va="center", transform=ax.transAxes, fontsize=FONT)
                ax.set_axis_off()
                continue
            image = _heatmap(ax, panels[rv, cv], factor if ratio is None else 1.0, norm,
                             "viridis" if ratio is None else "RdBu_r")
            if i == 0 and cols:
                ax.set_title(_setting_text(cols, cv), fontsize=FONT)
            if i == len(row_values) - 1:
                ax.set_xlabel(label(x), fontsize=FONT)
            if j == 0:
                scheme = f"{_value_text(rv)}\n" if rows and ratio is None else ""
                ax.set_ylabel(scheme + label(y), fontsize=FONT)
    bar = fig.colorbar(image, ax=axes, shrink=0.9, pad=0.01)  # one scale for every panel
    if ratio is not None:
        a, b = (SHORT.get(str(v), _value_text(v)) for v in ratio)
        bar.set_label(f"{a} / {b}", fontsize=FONT)
        _ratio_ticks(bar, norm)
        what = f"{_short(text)}: {a} / {b}\n(below 1, blue: the {a}'s is smaller; black line: equal)"
    else:
        bar.set_label(text, fontsize=FONT)
        bar.ax.tick_params(labelsize=FONT - 1)
        what = f"{text}" + (f", a row per {label(rows)}" if rows else "")
    fig.suptitle(what, fontsize=FONT + 1)
    return fig


#: schemes in the order the figures show them: the task law first
SCHEME_ORDER = ("task", "khatib", "raibert_craig", "fisher_mujtaba")


def _order(value):
    """Schemes in :data:`SCHEME_ORDER`, anything else as it sorts."""
    return (0, SCHEME_ORDER.index(value), "") if value in SCHEME_ORDER else (1, 0, str(value))


def _short(text: str) -> str:
    """A label without its unit."""
    return text.rsplit(" [", 1)[0]


def _setting_text(name: str, value) -> str:
    """``"speed while the force steps = 0.1 m/s"``: a setting's name, value and unit."""
    text = label(name)
    unit = text.rsplit(" [", 1)[1].rstrip("]") if " [" in text else ""
    unit = "" if unit in ("-", "fraction", "count") else f" {unit}"
    return f"{_short(text)} = {_value_text(value)}{unit}"


def _panel(grid, rows, cols, rv, cv, ratio):
    """One panel's table (``y`` by ``x``) of the pivoted ``grid``; with ``ratio``, the quotient of two rows'."""
    def pick(row):
        key = tuple(v for v, on in ((row, rows), (cv, cols)) if on)
        return grid.loc[key] if key else grid

    if ratio is None:
        return pick(rv)
    return pick(ratio[0]) / pick(ratio[1])


def _shared_norm(panels, factor: float):
    """One linear scale for every panel (their values times ``factor``), from the smallest cell to the largest."""
    values = np.concatenate([np.ravel(p.values) for p in panels]) * factor if panels else np.array([])
    finite = values[np.isfinite(values)]
    return colors.Normalize(finite.min(), finite.max()) if finite.size else colors.Normalize()


def _ratio_norm(panels):
    """One logarithmic scale centred at 1 for every ratio panel, as wide as the farthest ratio."""
    values = np.concatenate([np.ravel(p.values) for p in panels]) if panels else np.array([])
    positive = values[np.isfinite(values) & (values > 0)]
    span = max(np.abs(np.log(positive)).max(), math.log(1.05)) if positive.size else 1.0
    return colors.LogNorm(math.exp(-span), math.exp(span))


def _ratio_ticks(bar, norm) -> None:
    ticks = [v for v in (0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20) if norm.vmin <= v <= norm.vmax]
    if len(ticks) < 3:  # a narrow range: finer steps
        fine = (0.7, 0.8, 0.9, 1, 1.1, 1.2, 1.4) if norm.vmax > 1.25 else (0.8, 0.9, 0.95, 1, 1.05, 1.1, 1.2)
        ticks = [v for v in fine if norm.vmin <= v <= norm.vmax]
    bar.set_ticks(ticks, labels=[f"{v:g}" for v in ticks])
    bar.ax.yaxis.set_minor_formatter(ticker.NullFormatter())
    bar.ax.tick_params(labelsize=FONT - 1)


def _heatmap(ax, panel, factor: float, norm, cmap):
    """``panel`` (``y`` by ``x``) as cells, its settings' values on the ticks; returns the image."""
    values = panel.values * factor
    if isinstance(norm, colors.LogNorm):
        values = np.where(values > 0, values, np.nan)
    image = ax.imshow(values, origin="lower", aspect="auto", norm=norm, cmap=cmap, interpolation="nearest")
    if isinstance(norm, colors.LogNorm) and np.nanmin(values) < 1 < np.nanmax(values):
        ax.contour(values, levels=[1.0], colors="k", linewidths=0.9)
    for axis, labels in ((ax.xaxis, panel.columns), (ax.yaxis, panel.index)):
        shown = range(0, len(labels), max(1, math.ceil(len(labels) / 6)))  # six labels at most
        axis.set_ticks(list(shown), [_value_text(labels[k]) for k in shown])
    ax.tick_params(labelsize=FONT - 1)
    return image


def plot_first_touch(results: dict, title: str | None = None):
    """Runs from free space, ``{label: SimulationResult}``: the measured normal force [N] and the
    surface's normal force on the sensor tip [N] against the time from each run's first touch [s]
    (conventions §8), the first run's force reference behind them; a run that never touches is left
    out. Returns the Figure."""
    fig, axes = plt.subplots(2, 1, figsize=(7.0, 5.2), sharex=True, layout="constrained")
    first = True
    for name, res in results.items():
        touched = np.flatnonzero(res.contact_force > 0)
        if len(touched) == 0:
            continue
        t = res.t - res.t[touched[0]]
        if first:
            axes[0].plot(t, res.force_reference, **REFERENCE)
            first = False
        axes[0].plot(t, res.force_normal, lw=1.2, label=name)
        axes[1].plot(t, res.contact_force, lw=0.8, label=name)
    axes[0].set_ylabel("measured normal force [N]", fontsize=FONT)
    axes[1].set_ylabel("surface's normal force\non the sensor tip [N]", fontsize=FONT)
    axes[1].set_xlabel("time from the first touch [s]", fontsize=FONT)
    axes[1].set_xlim(-0.02, 0.3)
    return _finished(fig, axes, title)


# ------------------------------------------------------------------ files


def save(fig, stem: Path, formats=("png",), dpi: int = 150) -> list[Path]:
    """Write ``fig`` as ``stem.<format>`` for each of ``formats`` (png, pdf, svg), each atomically,
    and close it; returns the paths."""
    bad = [f for f in formats if f not in FORMATS]
    if bad or not formats:
        raise ValueError(f"formats = {formats!r}; give one or more of {', '.join(FORMATS)}")
    written = []
    for fmt in formats:
        path = Path(stem).with_name(f"{Path(stem).name}.{fmt}")
        files.write_with(path, lambda tmp, fmt=fmt: fig.savefig(tmp, dpi=dpi, format=fmt), overwrite=True)
        written.append(path)
    plt.close(fig)
    return written


def paper_figures(results: dict, out: Path, formats=("png",)) -> list[Path]:
    """Figures 5-8 (speed and force of Khatib's scheme and of the task law, each against its
    reference) and the overlay of every scheme; returns the files."""
    numbers = {("khatib", "speed"): 5, ("khatib", "force"): 6, ("task", "speed"): 7, ("task", "force"): 8}
    written = []
    for (scheme, which), num in numbers.items():
        if scheme not in results:
            continue
        res = results[scheme]
        fig, ax = plt.subplots(figsize=(6.0, 3.2), layout="constrained")
        rows = _rows(res)
        ref, y = ((res.speed_reference, res.velocity_tangential) if which == "speed"
                  else (res.force_reference, res.force_normal))
        ax.plot(res.t[rows], ref[rows], **REFERENCE)
        _line(ax, res.t[rows], y[rows], scheme, "measured", markers=False)
        ax.set_ylabel("tangential speed [m/s]" if which == "speed" else "normal force [N]", fontsize=FONT)
        ax.set_xlabel("time [s]", fontsize=FONT)
        ax.set_title(f"Figure {num}: {'tangential velocity' if which == 'speed' else 'normal force'}, "
                     f"{TITLES[scheme]}\n{conditions(res.experiment)}", fontsize=FONT)
        _style(ax)
        ax.legend(fontsize=FONT - 1, loc="lower right")
        written += save(fig, out / f"figure{num}_{scheme}_{which}", formats)
    first = next(iter(results.values()))
    fig = plot_comparison(results, f"the schemes compared ({conditions(first.experiment)})")
    return written + save(fig, out / "overlay_speed_force", formats)


def trace_figures(results: dict, out: Path, formats=("png",)) -> list[Path]:
    """The 3-D experiment: speed and force of every scheme, and the paths (in space, and as deviation
    from the desired path, with the penetration); returns the files."""
    first = next(iter(results.values()))
    fig = plot_comparison(results, f"3-D experiment (UR5 on a sphere; {conditions(first.experiment)}): speed along t1 "
                          "and normal force")
    written = save(fig, out / "trace_speed_force", formats)
    fig = plot_path(results, "3-D experiment: the sensor tip's path on the sphere")
    return written + save(fig, out / "trace_path_3d", formats)


def sweep_heatmaps(table, figures: dict | None, out: Path, formats=("png",)) -> list[Path]:
    """The heatmaps a sweep file's ``[figures]`` table asks for: for each of its ``metrics``,
    :func:`plot_sweep` over ``x`` by ``y`` with a panel per value of ``rows`` and ``cols``
    (``heatmap_METRIC``), and with ``ratio = [a, b]`` the ratio maps too (``heatmap_METRIC_a_over_b``).
    Returns the files."""
    if not figures or not (table["status"] == "ok").any():
        return []
    x, y, rows, cols, ratio = (figures.get(k) for k in ("x", "y", "rows", "cols", "ratio"))
    written = []
    for metric in figures.get("metrics", []):
        fig = plot_sweep(table, x, y, metric, rows, cols)
        if fig is None:  # a metric no run reports (e.g. after a step no reference makes)
            continue
        written += save(fig, out / f"heatmap_{metric}", formats, dpi=120)
        if ratio:
            fig = plot_sweep(table, x, y, metric, rows, cols, ratio=tuple(ratio))
            if fig is not None:
                written += save(fig, out / f"heatmap_{metric}_{ratio[0]}_over_{ratio[1]}", formats, dpi=120)
    return written
