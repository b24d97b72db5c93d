"""The stable region of an experiment's sampled loops across its settings: :func:`stability_map`.

Every point of the grid is the experiment with those settings, judged as its own check judges it (the
whole closed loop's spectral radius, :func:`hybrid.stability`). Points that share what moves the start
or shapes the model (the stiffnesses, the delay, which gains are 0) share one start and one
structure; across the rest the model's numbers are arrays, and the grid is one batched evaluation.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from hybrid.control.loops import Gains
from hybrid.control.wrench_sensor import filter_coefficients
from hybrid.errors import HybridError
from hybrid.experiments.settings import setting_path
from hybrid.plants.contact import fastest_mode, lag_pole
from hybrid.stability.analysis import loop_radius
from hybrid.stability.experiment_loops import check_delay, check_experiment, loop_numbers
from hybrid.sweeps.space import apply
from hybrid.validate import check_size, checked_keywords, shown

#: the settings whose value moves the start or the model's structure: their points are grouped
GROUPED = ("contact.stiffness", "sensor.stiffness", "sensor.delay_samples")
#: the settings that enter the model's numbers only, and which number each sets
NUMBERS = {"sample_time": "sample_time", "contact.damping": "contact_damping", "sensor.damping": "sensor_damping",
           "sensor.mass": "sensor_mass", "sensor.bandwidth_hz": "lag", "model_error": "gain",
           "wrench_sensor.cutoff": "filter", **{f"gains.{name}": name for name in Gains.__dataclass_fields__}}
#: the most points a map takes
MOST_POINTS = 10**6
#: the points evaluated in one batch (bounds the memory of a large map)
BATCH = 4096


@checked_keywords
@dataclass(frozen=True)
class StabilityMap:
    """The spectral radius of an experiment's sampled loops over a grid of its settings.

    Parameters
    ----------
    table : pandas.DataFrame
        One row per point: the settings (as named), ``spectral_radius`` (NaN where the setting is not
        a valid loop, e.g. a lag above the Nyquist frequency) and ``stable``.
    settings : tuple of str
        The settings varied, in the order given.

    Examples
    --------
    >>> import hybrid
    >>> m = hybrid.stability_map(hybrid.paper_experiment(),
    ...                          {"sensor.delay_samples": [0, 2, 8]})
    >>> m.settings, m.stable_share
    (('sensor.delay_samples',), 0.6666666666666666)
    """

    table: object
    settings: tuple[str, ...]

    @property
    def stable_share(self) -> float:
        """The share of the grid's points that are stable."""
        return float(self.table["stable"].mean())

    def figure(self, title: str | None = None):
        """The map as a figure.

        Parameters
        ----------
        title : str, optional
            Its title (default: what it shows).

        Returns
        -------
        matplotlib.figure.Figure
            The spectral radius over the first two settings with the boundary (radius 1) drawn, one
            panel per value of a third (six at most); over one setting, a curve.
        """
        from hybrid.stability.figures import stability_map_figure

        return stability_map_figure(self, title)


@checked_keywords
def stability_map(exp, over: Mapping) -> StabilityMap:
    """The stable region of ``exp``'s sampled loops over a grid of settings.

    Parameters
    ----------
    exp : Experiment
        The experiment whose other settings hold.
    over : mapping of str to sequence of float
        Each setting (a name a sweep takes: ``sample_time``, ``contact.stiffness``, ``sensor.stiffness``,
        ``sensor.damping``, ``sensor.mass``, ``sensor.delay_samples``, ``sensor.bandwidth_hz``,
        ``contact.damping``, ``model_error``, ``wrench_sensor.cutoff``, a gain ``KPf``...) and its
        values; the grid is their Cartesian product.

    Returns
    -------
    StabilityMap
        The table and its figure.

    Raises
    ------
    HybridError
        An empty or unknown setting, a value out of its range (naming it), a grid over
        :data:`MOST_POINTS` points.

    Examples
    --------
    >>> import hybrid
    >>> m = hybrid.stability_map(hybrid.paper_experiment(), {
    ...     "sensor.stiffness": [1e3, 1e4, 1e5],
    ...     "sample_time": [0.001, 0.01]})
    >>> m.table["stable"].tolist()
    [True, True, True, True, True, False]
    """
    check_experiment(exp, "stability_map")
    if not isinstance(over, Mapping) or not over:
        raise HybridError(f"over = {shown(over, 60)}; give settings and their values, e.g. "
                          "{'sensor.stiffness': [1e3, 1e4, 1e5], 'sample_time': [0.001, 0.01]}")
    names = tuple(over)
    paths = {name: _path(exp, name) for name in names}
    for path in set(paths.values()):
        same = [name for name in names if paths[name] == path]
        if len(same) > 1:
            raise HybridError(f"{' and '.join(map(repr, same))} name the same setting ({path}); give it once")
    values = {name: _values(exp, name, paths[name], over[name]) for name in names}
    size = math.prod(len(v) for v in values.values())
    if size > MOST_POINTS:
        raise HybridError(f"the map has {size:,} points, over {MOST_POINTS:,}; give fewer values")
    check_size("the map's table needs", size * 8 * (len(names) + 2), "give fewer values")
    grid = {name: g.ravel() for name, g in zip(names, np.meshgrid(*values.values(), indexing="ij"))}
    radius = np.full(size, np.nan)
    groups: dict[tuple, list[int]] = {}
    for i in range(size):
        groups.setdefault(_group_key(paths, {n: grid[n][i] for n in names}), []).append(i)
    for members in groups.values():
        where = np.array(members)
        base = _group_base(exp, paths, {n: grid[n][where[0]] for n in names})
        st, p = loop_numbers(base)
        for chunk in np.array_split(where, max(1, math.ceil(len(where) / BATCH))):
            radius[chunk] = _radii(st, p, base, paths, {n: grid[n][chunk] for n in names})
    import pandas as pd

    whole = {name: grid[name].astype(int) if paths[name] == "sensor.delay_samples" else grid[name] for name in names}
    table = pd.DataFrame({**whole, "spectral_radius": radius, "stable": radius < 1.0})
    return StabilityMap(table, names)


def _path(exp, name) -> str:
    if not isinstance(name, str):
        raise HybridError(f"setting {shown(name, 40)}; name it as a sweep does (e.g. 'sensor.stiffness')")
    path = setting_path(name)
    if path not in GROUPED and path not in NUMBERS:
        known = ", ".join(sorted({p.removeprefix("gains.") for p in (*GROUPED, *NUMBERS)}))
        raise HybridError(f"stability_map cannot vary {name!r}: it does not enter the sampled loops' model; vary one "
                          f"of {known}")
    if path == "model_error" and exp.controller_robot is not None:
        raise HybridError("stability_map over model_error: the experiment has a controller_robot, to which "
                          "model_error does not apply; vary the gains instead")
    if path in ("gains.KI2v", "gains.KIf") and not exp.integral:
        raise HybridError(f"stability_map over {name}: the experiment runs without integral action (integral=False), "
                          "where it has no effect; give the experiment integral=True")
    if path == "wrench_sensor.cutoff" and (exp.controller_wrench_sensor or exp.wrench_sensor) is None:
        raise HybridError("stability_map over wrench_sensor.cutoff: the experiment has no wrench_sensor, whose "
                          "filter it is; give the experiment wrench_sensor=hybrid.WrenchSensor()")
    return path


def _values(exp, name: str, path: str, values) -> np.ndarray:
    """``values`` as a 1-D array of finite numbers, each a valid value of the setting (checked as the
    experiment's parts check it)."""
    arr = _numbers(values)
    if arr is None or arr.ndim != 1 or not len(arr) or not np.isfinite(arr).all():
        raise HybridError(f"the values of {name!r} = {shown(values, 60)}; give a non-empty list of finite numbers")
    for v in np.unique(arr):
        _check_value(exp, name, path, float(v))
    return arr


def _numbers(values) -> np.ndarray | None:
    """``values`` as floats when it is a sequence of real numbers (not text, not True/False), else None."""
    if isinstance(values, (str, bytes, Mapping)) or not hasattr(values, "__len__"):
        return None
    try:
        arr = np.asarray(values)
    except (TypeError, ValueError):  # ragged
        return None
    if arr.dtype.kind not in "iuf":
        return None
    if not isinstance(values, np.ndarray) and any(isinstance(v, (bool, np.bool_)) for v in values):
        return None  # a bool among numbers (NumPy made them numbers)
    return arr.astype(float)


def _check_value(exp, name: str, path: str, v: float) -> None:
    head, _, tail = path.partition(".")
    if path == "sample_time" and not v > 0:
        raise HybridError(f"{name} = {v:g}; a sampled loop needs a sample time > 0 [s]")
    if path == "model_error" and not v > -1:
        raise HybridError(f"{name} = {v:g}; give a model error > -1")
    if tail:
        part = exp.controller_wrench_sensor or exp.wrench_sensor if head == "wrench_sensor" else getattr(exp, head)
        value = int(v) if tail == "delay_samples" and v == int(v) else v
        try:
            replace(part, **{tail: value})
            if path == "sensor.delay_samples":
                check_delay(value)
        except HybridError as exc:
            raise HybridError(f"{name} = {v:g} in the map: {str(exc).splitlines()[0]}") from None


def _group_key(paths: dict, point: dict) -> tuple:
    """What the point shares with the others of its group: the grouped settings' values, and whether
    each gain varied is 0 (an integrator the loop drops)."""
    return tuple(float(point[name]) if path in GROUPED else point[name] == 0.0
                 for name, path in paths.items() if path in GROUPED or path.startswith("gains."))


def _group_base(exp, paths: dict, point: dict):
    """The experiment of a group's first point in what the group shares (its start, its structure),
    checked as any experiment is; unstable loops allowed (the map judges them), and an integration step
    fine enough for its contact (the loops do not depend on it)."""
    changes = {name: (int(point[name]) if path == "sensor.delay_samples" else float(point[name]))
               for name, path in paths.items() if path in GROUPED or path.startswith("gains.")}
    given = {paths[k]: v for k, v in changes.items()}
    rate = fastest_mode(exp.sensor, exp.contact, given.get("sensor.stiffness"), given.get("contact.stiffness"))
    steps = max(exp.steps_per_sample, math.ceil(exp.sample_time * rate))
    try:
        return apply(replace(exp, allow_unstable=True, integration_step=exp.sample_time / steps), changes)
    except HybridError as exc:
        point = ", ".join(f"{name} = {value:g}" for name, value in changes.items())
        raise HybridError(f"the map's point {point} is no experiment: {str(exc).splitlines()[0]}") from None


def _radii(st, p: dict, base, paths: dict, grid: dict) -> np.ndarray:
    """The spectral radius at each point of one group (its numbers batched)."""
    size = len(next(iter(grid.values())))
    q = {k: np.broadcast_to(np.asarray(v, float), (size,) + np.shape(v)).copy() for k, v in p.items()}
    told = base.controller_wrench_sensor or base.wrench_sensor
    T = q["sample_time"]
    bandwidth = np.full(size, np.nan if base.sensor.bandwidth_hz is None else base.sensor.bandwidth_hz)
    cutoff = np.full(size, np.nan if told is None or told.cutoff is None else told.cutoff)
    scale = np.ones(size)
    for name, path in paths.items():
        v = np.asarray(grid[name], float)
        target = NUMBERS.get(path)
        if target is None:
            continue
        if path == "sample_time":
            T = q["sample_time"] = v
        elif path == "sensor.bandwidth_hz":
            bandwidth = v
        elif path == "wrench_sensor.cutoff":
            cutoff = v
        elif path == "model_error":
            scale = (1.0 + v) / (1.0 + base.model_error)
        else:
            q[target] = v
    q["gain"] = q["gain"] * scale[:, None, None]
    valid = np.ones(size, bool)
    if st.lag or np.isfinite(bandwidth).any():
        q["lag"] = lag_pole(np.nan_to_num(bandwidth), T)
        valid &= ~(bandwidth >= 0.5 / T)
    if st.filtered or np.isfinite(cutoff).any():
        order = 1 if told is None else told.order
        pairs = {(c, t): filter_coefficients(c, order, t) for c, t in set(zip(cutoff.tolist(), T.tolist()))}
        q["filter"] = np.array([pairs[(c, t)] for c, t in zip(cutoff.tolist(), T.tolist())])
        valid &= ~(cutoff >= 0.5 / T)
    st = replace(st, lag=st.lag or bool(np.isfinite(bandwidth).any()),
                 filtered=st.filtered or bool(np.isfinite(cutoff).any()))
    radius = np.asarray(loop_radius(st, q), float).reshape(size)
    radius[~valid] = np.nan
    return radius

