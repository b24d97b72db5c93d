"""Figures that reproduce the paper's Figures 5-8, and an overlay of both controllers."""

from __future__ import annotations

from pathlib import Path

import matplotlib

from . import files

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402

TITLES = {"khatib": "Khatib (1987) operational space", "task": "task-space decoupling"}
COLORS = {"khatib": "tab:red", "task": "tab:blue"}


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
    files.write_with(Path(path), lambda tmp: fig.savefig(tmp, dpi=150, format="png"), overwrite=True)
    plt.close(fig)
    return path


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
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for ctrl, res in results.items():
        _axes_speed(axes[0], res, TITLES[ctrl], COLORS[ctrl])
        _axes_force(axes[1], res, TITLES[ctrl], COLORS[ctrl])
    any_res = next(iter(results.values()))
    _reference(axes[0], any_res, "speed")
    _reference(axes[1], any_res, "force")
    axes[0].set_title("Khatib vs task-space decoupling (circle, friction, 10 % model error)", fontsize=9)
    axes[0].grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    files.append(_finish(fig, axes[1], out / "overlay_speed_force.png"))
    return files
