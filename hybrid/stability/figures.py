"""A stability map as a figure: the spectral radius over one, two or three settings, the boundary drawn."""

from __future__ import annotations

import numpy as np
from matplotlib.colors import TwoSlopeNorm
from matplotlib.figure import Figure

#: the most panels a map's third setting gets (its values spread over them)
MOST_PANELS = 6
#: the radius the colours stop at (larger: as unstable as it)
TOP = 2.0


def stability_map_figure(smap, title: str | None = None) -> Figure:
    """The figure of a :class:`~hybrid.stability.maps.StabilityMap` (see :meth:`StabilityMap.figure`)."""
    table, names = smap.table, smap.settings
    if len(names) == 1:
        return _curve(table, names[0], title)
    third = names[2] if len(names) > 2 else None
    levels = [None] if third is None else _spread(np.unique(table[third]))
    fig = Figure(figsize=(4.2 * len(levels) + 1.2, 4.0), layout="constrained")
    axes = fig.subplots(1, len(levels), squeeze=False)[0]
    mesh = None
    radius = table["spectral_radius"].to_numpy()
    low = float(np.clip(np.min(radius[~np.isnan(radius)], initial=1.0), 0.0, 0.99))
    norm = TwoSlopeNorm(1.0, low, TOP)  # stable greens from the map's smallest radius, unstable reds
    for ax, level in zip(axes, levels):
        part = table if level is None else table[table[third] == level]
        x, y = np.unique(part[names[0]]), np.unique(part[names[1]])
        grid = part.pivot_table(index=names[1], columns=names[0], values="spectral_radius", aggfunc="first")
        R = grid.reindex(index=y, columns=x).to_numpy()
        shown = np.clip(np.nan_to_num(R, nan=TOP), 0.0, TOP)
        mesh = ax.pcolormesh(x, y, shown, shading="nearest", cmap="RdYlGn_r", norm=norm)
        judged = R[~np.isnan(R)]  # NaN: no such loop (a lag past the Nyquist frequency)
        if len(x) > 1 and len(y) > 1 and judged.size and judged.min() < 1.0 < judged.max():
            ax.contour(x, y, np.nan_to_num(R, nan=TOP), levels=[1.0], colors="k", linewidths=1.5)
        for axis, values in (("x", x), ("y", y)):
            if _logarithmic(values):
                getattr(ax, f"set_{axis}scale")("log")
        ax.set_xlabel(_label(names[0]))
        ax.set_ylabel(_label(names[1]))
        if level is not None:
            ax.set_title(f"{third} = {level:g}")
    fig.colorbar(mesh, ax=list(axes), label="spectral radius (stable below 1; black: the boundary)")
    fig.suptitle(title or "stable region of the sampled loops")
    return fig


def save_map(smap, stem, formats=("png",)) -> list:
    """Draw ``smap`` and write it as ``stem.<format>`` for each of ``formats``, atomically; the paths."""
    from hybrid.plots import save

    return save(stability_map_figure(smap), stem, formats)


def _curve(table, name: str, title: str | None) -> Figure:
    fig = Figure(figsize=(6.0, 3.6), layout="constrained")
    ax = fig.subplots()
    x, r = table[name].to_numpy(), table["spectral_radius"].to_numpy()
    order = np.argsort(x)
    ax.plot(x[order], r[order], "k.-")
    ax.axhline(1.0, color="r", lw=1.0)
    ax.fill_between(x[order], 1.0, max(TOP, np.nanmax(r, initial=1.0)), color="r", alpha=0.08, label="unstable")
    if _logarithmic(x):
        ax.set_xscale("log")
    ax.set_ylim(0.0, min(TOP, max(1.1, np.nanmax(r, initial=1.0) * 1.05)))
    ax.set_xlabel(_label(name))
    ax.set_ylabel("spectral radius")
    ax.legend(loc="best")
    ax.set_title(title or "stability of the sampled loops")
    return fig


#: the unit of each setting a map varies, by the end of its name
UNITS = {"stiffness": "N/m", "damping": "N s/m", "mass": "kg", "sample_time": "s", "delay_samples": "samples",
         "bandwidth_hz": "Hz", "cutoff": "Hz", "KPv": "1/s", "KIv": "1/s^2", "KI2v": "1/s^3", "KPf": "1/kg",
         "KDf": "1/s", "KIf": "1/(kg s)"}


def _label(name: str) -> str:
    unit = UNITS.get(name.rsplit(".", 1)[-1])
    return f"{name} [{unit}]" if unit else name


def _logarithmic(values) -> bool:
    """Positive values spanning more than a decade are drawn on a log axis."""
    values = np.asarray(values, float)
    return bool(len(values) > 2 and values.min() > 0 and values.max() / values.min() > 10)


def _spread(levels: np.ndarray) -> list:
    """At most :data:`MOST_PANELS` of ``levels``, spread evenly (the first and the last among them)."""
    if len(levels) <= MOST_PANELS:
        return list(levels)
    return list(levels[np.unique(np.linspace(0, len(levels) - 1, MOST_PANELS).round().astype(int))])
