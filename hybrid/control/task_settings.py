"""The :class:`hybrid.Controller`'s settings per task axis and per joint, read and checked.

The task axes are given by index (``axes``: :data:`hybrid.spec.axes.AXIS_NAMES`' positions) and named by
their names (``"t1"``, ``"n"``, ...); ``selection`` holds 1 on a force-controlled axis, 0 on a velocity
one, per task axis.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import numpy as np

from hybrid.control.loops import Gains
from hybrid.control.options import Reference
from hybrid.errors import HybridError
from hybrid.spec.axes import AXIS_NAMES
from hybrid.spec.controller_step import LOOP_GAINS
from hybrid.validate import shown


def axis_index(axes: tuple[int, ...], what: str, key) -> int:
    """The position in ``axes`` of the axis named or numbered ``key`` (``what`` names the setting)."""
    index = AXIS_NAMES.index(key) if isinstance(key, str) and key in AXIS_NAMES else key
    if isinstance(index, (int, np.integer)) and not isinstance(index, bool) and index in axes:
        return axes.index(int(index))
    raise HybridError(f"{what}: {shown(key)} is not one of the task axes {', '.join(_names(axes))}; name one of "
                      "them (or give its index 0-5)")


def selection_of(axes: tuple[int, ...], selection) -> tuple[int, ...]:
    """The force-controlled axes (names or indices; None: the normal ``n`` if it is a task axis) as 0/1
    per task axis."""
    if selection is None:
        selection = ("n",) if 2 in axes else ()
    if isinstance(selection, (str, int)):
        selection = (selection,)
    try:
        chosen = {axis_index(axes, "selection", k) for k in selection}
    except HybridError:
        raise
    except (TypeError, ValueError):
        raise HybridError(f"selection = {shown(selection, 60)}; give the force-controlled axes by name, "
                          "e.g. ('n',)") from None
    return tuple(int(k in chosen) for k in range(len(axes)))


def gains_of(axes: tuple[int, ...], gains, integral: bool = True) -> tuple[Gains, ...]:
    """A :class:`Gains` per task axis from one for all, ``{axis: Gains}`` for some (the others the
    defaults) or None; without ``integral`` the integral actions ``KI2v, KIf`` are 0."""
    per_axis = [Gains()] * len(axes)
    if gains is None:
        pass
    elif isinstance(gains, Gains):
        per_axis = [gains] * len(axes)
    elif isinstance(gains, Mapping):
        for key, g in gains.items():
            if not isinstance(g, Gains):
                raise HybridError(f"gains[{shown(key, 40)}] is a {type(g).__name__}; give a hybrid.Gains(...)")
            per_axis[axis_index(axes, "gains", key)] = g
    else:
        raise HybridError(f"gains is a {type(gains).__name__}; give a hybrid.Gains(...) or {{axis name: Gains}}")
    if not integral:
        per_axis = [replace(g, KI2v=0.0, KIf=0.0) for g in per_axis]
    return tuple(per_axis)


def gain_array(gains: tuple[Gains, ...], selection: tuple[int, ...]) -> np.ndarray:
    """``(KP, KI, KI2, KD)`` per axis, as the generated step reads them (:data:`LOOP_GAINS`)."""
    rows = [{"KP": g.KPf, "KI": g.KIf, "KI2": 0.0, "KD": g.KDf} if s else
            {"KP": g.KPv, "KI": g.KIv, "KI2": g.KI2v, "KD": 0.0} for g, s in zip(gains, selection)]
    return np.array([[row[k] for k in LOOP_GAINS] for row in rows], float).ravel()


def joint_limit(robot, name: str, value) -> np.ndarray:
    """A per-joint limit > 0 of ``robot`` (``inf``: none) from None, ``"urdf"`` (``torque_limit`` only: the
    URDF's effort limits), one number or one per joint."""
    n = robot.n
    if value is None:
        return np.full(n, np.inf)
    if isinstance(value, str) and value == "urdf" and name == "torque_limit":
        limits = robot.limits
        if limits is None:
            return np.full(n, np.inf)
        # an effort of 0 (or none) in a URDF states no limit: an actuated joint with no torque is not one
        effort = np.array(limits.effort, float)
        return np.where(effort > 0, effort, np.inf)
    try:
        arr = np.broadcast_to(np.asarray(value, dtype=float), (n,)).copy()
    except (TypeError, ValueError, OverflowError):  # OverflowError: an integer beyond any double
        arr = np.full(n, np.nan)
    if isinstance(value, (str, bool)) or np.isnan(arr).any() or (arr <= 0).any():
        urdf = "'urdf' (the URDF's effort limits), " if name == "torque_limit" else ""
        raise HybridError(f"{name} = {shown(value, 60)}; give {urdf}None (no limit), one number > 0 [N m or N"
                          f"{' per sample' if name != 'torque_limit' else ''}] or {n} of them (one per joint)")
    return arr


def axis_references(axes: tuple[int, ...], selection: tuple[int, ...], force, velocity) -> list[Reference]:
    """A :class:`Reference` per task axis: ``force`` on the force axes and ``velocity`` on the others, each
    one value (the normal force, the speed along ``t1``) or ``{axis: value}``; None: 10 N on the normal
    when it is a force axis, and every other reference 0."""
    refs: list = [0.0] * len(axes)
    if force is None:
        force = {"n": 10.0} if 2 in axes and selection[axes.index(2)] else {}
    if velocity is None:
        velocity = {}
    for what, given, force_axes in (("force_reference", force, True), ("velocity_reference", velocity, False)):
        if isinstance(given, Mapping):
            items = {axis_index(axes, what, k): v for k, v in given.items()}
        else:
            main = 2 if force_axes else 0  # the normal force, the speed along t1
            items = {axes.index(main): given} if main in axes else {}
        for k, v in items.items():
            if bool(selection[k]) != force_axes:
                kind = "force" if force_axes else "velocity"
                chosen = ", ".join(n for n, s in zip(_names(axes), selection) if s) or "none"
                raise HybridError(f"{what} names axis {_names(axes)[k]}, which is not a {kind}-controlled axis "
                                  f"(selection: {chosen}); move it to the other reference")
            refs[k] = Reference.of(f"{what}[{_names(axes)[k]}]", v)
    return [Reference.of("reference", r) for r in refs]


def _names(axes: tuple[int, ...]) -> tuple[str, ...]:
    return tuple(AXIS_NAMES[i] for i in axes)
