"""Figures that reproduce the paper's Figures 5-8, an overlay of both controllers, sweeps' heatmaps and an
estimated surface's normal against the true one."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

from hybrid import files
from hybrid.errors import HybridError

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402

TITLES = {"khatib": "Khatib (1987) operational space", "task": "task-space decoupling",
          "raibert_craig": "Raibert & Craig (1981)", "fisher_mujtaba": "Raibert & Craig, Fisher & Mujtaba (1992)"}
COLORS = {"khatib": "tab:red", "task": "tab:blue", "raibert_craig": "tab:green", "fisher_mujtaba": "tab:olive"}


def _axes_speed(ax, res, label=None, color=None):
    ax.plot(res.t, res.velocity_tangential, color=color or "tab:blue", lw=1.2, label=label or "measured")
    ax.set_ylabel("tangential speed [m/s]")


def _axes_force(ax, res, label=None, color=None):
    ax.plot(res.t, res.force_normal, color=color or "tab:blue", lw=1.2, label=label or "measured")
    ax.set_ylabel("normal force [N]")


def _reference(ax, res, which):
    y = res.speed_reference if which == "speed" else res.force_reference
    ax.plot(res.t, y, "k--", lw=1.0, label="reference")


def _finish(fig, ax, path: Path) -> Path:
    ax.set_xlabel("time [s]")
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    return _save(fig, path)


def _save(fig, path: Path, dpi: int = 150) -> Path:
    """Write ``fig`` as PNG atomically and close it."""
    files.write_with(Path(path), lambda tmp: fig.savefig(tmp, dpi=dpi, format="png"), overwrite=True)
    plt.close(fig)
    return Path(path)


def _overlay(results: dict, title: str, path: Path) -> Path:
    """Speed and force of every scheme on shared axes, with the references."""
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for ctrl, res in results.items():
        _axes_speed(axes[0], res, TITLES.get(ctrl, ctrl), COLORS.get(ctrl))
        _axes_force(axes[1], res, TITLES.get(ctrl, ctrl), COLORS.get(ctrl))
    any_res = next(iter(results.values()))
    _reference(axes[0], any_res, "speed")
    _reference(axes[1], any_res, "force")
    axes[0].set_title(title, fontsize=9)
    axes[0].grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    return _finish(fig, axes[1], path)


def trace_figures(results: dict, out: Path) -> list[Path]:
    """The 3-D experiment: speed and force of every scheme, and the arm tip's path on the sphere."""
    import numpy as np

    written = [_overlay(results, "3-D experiment: speed along t1 and normal force (UR5 on a sphere)",
                        out / "trace_speed_force.png")]
    fig = plt.figure(figsize=(6, 5))
    ax = fig.add_subplot(projection="3d")
    exp = next(iter(results.values())).experiment
    surf = exp.surface
    if hasattr(surf, "radius") and hasattr(surf, "center"):
        u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 36), np.linspace(0, np.pi / 2, 10))
        c = np.asarray(surf.center)
        ax.plot_wireframe(c[0] + surf.radius * np.cos(u) * np.sin(v), c[1] + surf.radius * np.sin(u) * np.sin(v),
                          c[2] + surf.radius * np.cos(v), color="0.8", lw=0.5)
    for ctrl, res in results.items():
        r = res.outputs[:, [res.record["outputs"].index(k) for k in ("s_x", "s_y", "s_z")]]
        ax.plot(*r.T, color=COLORS.get(ctrl), lw=1.2, label=TITLES.get(ctrl, ctrl))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title("the sensor tip's path on the surface", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return [*written, _save(fig, out / "trace_path_3d.png")]


def paper_figures(results: dict, out: Path) -> list[Path]:
    """Figures 5-8 (speed and force of each controller) and the overlay; returns the files."""
    numbers = {("khatib", "speed"): 5, ("khatib", "force"): 6, ("task", "speed"): 7, ("task", "force"): 8}
    files = []
    for (ctrl, which), num in numbers.items():
        if ctrl not in results:
            continue
        res = results[ctrl]
        fig, ax = plt.subplots(figsize=(6, 3.4))
        (_axes_speed if which == "speed" else _axes_force)(ax, res, color=COLORS[ctrl])
        _reference(ax, res, which)
        ax.set_title(f"Figure {num}: {'tangential velocity' if which == 'speed' else 'normal force'}, "
                     f"{TITLES[ctrl]}", fontsize=9)
        files.append(_finish(fig, ax, out / f"figure{num}_{ctrl}_{which}.png"))
    files.append(_overlay(results, "the schemes compared (circle, friction, 10 % model error)",
                          out / "overlay_speed_force.png"))
    return files


def _label(value) -> str:
    return f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)


def sweep_heatmaps(table, figures: dict | None, out: Path) -> list[Path]:
    """One figure per metric of ``figures["metrics"]``: the metric over ``x`` by ``y``, a panel per
    value of ``rows`` and ``cols`` (averaged over any other swept setting); NaN cells are blank."""
    import numpy as np

    if not figures or not (table["status"] == "ok").any():
        return []
    x, y = figures["x"], figures["y"]
    rows, cols = figures.get("rows"), figures.get("cols")
    written = []
    ok = table[table["status"] == "ok"]
    row_values = sorted(table[rows].unique()) if rows else [None]
    col_values = sorted(table[cols].unique()) if cols else [None]
    for metric in figures.get("metrics", []):
        fig, axes = plt.subplots(len(row_values), len(col_values), squeeze=False,
                                 figsize=(3.4 * len(col_values) + 1.2, 2.4 * len(row_values) + 0.6))
        grid = ok.pivot_table(index=[c for c in (rows, cols) if c] + [y], columns=x, values=metric, aggfunc="mean")
        values = grid.values[np.isfinite(grid.values)]
        if values.size == 0:  # a metric no run reports (e.g. after a step no reference makes)
            plt.close(fig)
            continue
        lo, hi = values.min(), values.max()
        for i, rv in enumerate(row_values):
            for j, cv in enumerate(col_values):
                ax = axes[i][j]
                key = tuple(v for v in (rv, cv) if v is not None)
                title = ", ".join(f"{n} = {_label(v)}" for n, v in zip([c for c in (rows, cols) if c], key))
                try:
                    panel = grid.loc[key] if key else grid
                except KeyError:  # no run of this panel finished: left empty
                    ax.set_title(f"{title} (no ok runs)", fontsize=6)
                    ax.axis("off")
                    continue
                image = ax.imshow(panel.values, origin="lower", aspect="auto", vmin=lo, vmax=hi, cmap="viridis")
                for axis, values in ((ax.xaxis, panel.columns), (ax.yaxis, panel.index)):
                    shown = range(0, len(values), max(1, math.ceil(len(values) / 6)))  # six labels at most
                    axis.set_ticks(list(shown), [_label(values[k]) for k in shown], fontsize=6)
                ax.set_title(title, fontsize=6)
                if i == len(row_values) - 1:
                    ax.set_xlabel(x, fontsize=7)
                if j == 0:
                    ax.set_ylabel(y, fontsize=7)
        fig.colorbar(image, ax=axes, shrink=0.8, label=metric)
        fig.suptitle(metric, fontsize=9)
        written.append(_save(fig, out / f"heatmap_{metric}.png", dpi=120))
    return written


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
