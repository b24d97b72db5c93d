"""A run on a part whose wall is too thin for its sensor's deflection, refused before it runs.

The controller evaluates the task frame at the arm tip, which sits below the surface by the sensor's
deflection ``F / K_s`` and the contact's own penetration ``(F + m_s g) / k_e`` (conventions §5: the sensor
measures the spring's force, which the force loop holds at ``F``; the contact bears the tip mass's weight
too). Past the middle of the part's wall (half its thickness in, the medial surface) the fitted ``phi``'s
gradient turns over: the frame flips and the force loop pushes the wrong way; before it, the fitted normal
tilts as the far face's pull grows. Measured on plates of 1 to 40 mm (docs/howto/parts.rst), by the arm tip's
share of the way to the medial surface: to 0.2 every plate whose fit runs right at all ran as the analytic
plane (its RMS force error within 6 %, the steady force within 0.05 N); from 0.3 to 0.5 up to 20 % off (the
steady force still within 0.05 N); from 0.6 up to three times off, and from 0.8 to 1 the frame flipped (forces
newtons off, contact lost, the state NaN). A run whose arm tip would go past half the way
(:data:`~hybrid.geometry.part_walls.SOUND_SHARE`, a quarter of the thinnest wall it can reach) is refused,
with the fix.
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.part_walls import SOUND_SHARE

#: the gravity that loads the sensor's tip mass [m/s^2] (the 3-D plant's; a bound for the planar one)
GRAVITY = 9.81


def expected_depth(exp) -> tuple[float, float]:
    """The arm tip's depth below the surface while pressing [m], and the largest normal force it presses with
    [N]: ``F / K_s + (F + m_s g) / k_e`` (the weight where it adds most: pressing down)."""
    ref = exp.force_reference
    force = max(abs(ref.before), abs(ref.after))
    task = exp.path_task
    if task is not None and callable(task.force):
        s = np.linspace(0.0, float(task.path.length), 201)
        force = max(force, float(np.max(np.abs([task.force_at(float(x)) for x in s]))))
    sensor, contact = exp.sensor, exp.contact
    return force / sensor.stiffness + (force + sensor.mass * GRAVITY) / contact.stiffness, force


def reach_of(exp) -> float:
    """How far from its start [m] the sensor tip can slide along the part within the run: the fastest speed
    reference over the whole run; inf with a path task (its path may run anywhere on the part)."""
    if exp.path_task is not None:
        return math.inf
    ref = exp.speed_reference
    return max(abs(ref.before), abs(ref.after)) * exp.duration


def check_walls(exp) -> None:
    """Refuse a run whose arm tip would press deeper than :data:`SOUND_SHARE` of half the thinnest wall of the
    part it touches within its reach (module docstring), saying by how much and what to change."""
    surface = exp.told_surface()
    if math.isinf(surface.thinnest_wall()):
        return  # no far face anywhere (a formula's surface, an open sheet)
    depth, force = expected_depth(exp)
    wall = surface.thinnest_wall(exp.start(), reach_of(exp) + surface.band)
    sound = SOUND_SHARE * wall / 2
    if depth < sound:
        return
    sensor, contact = exp.sensor, exp.contact
    room = sound - sensor.mass * GRAVITY / contact.stiffness  # what the force's two deflections may take
    fixes = "a stiffer contact"
    if room > 0:
        fixes = f"a force below {_rounded(room / (1 / sensor.stiffness + 1 / contact.stiffness), math.floor):g} N"
        if room > force / contact.stiffness:
            stiffer = _rounded(force / (room - force / contact.stiffness), math.ceil)
            fixes = f"a sensor stiffness >= {stiffer:g} N/m, " + fixes
    raise HybridError(
        f"a part's wall of {wall * 1e3:.3g} mm where the run reaches: the arm tip, the frame's point, would press "
        f"{depth * 1e3:.3g} mm in, past {sound * 1e3:.3g} mm ({SOUND_SHARE:g} of the half wall); "
        f"give {fixes}, or model a sheet as an open surface\n"
        f"  the depth: {force:g} N over the sensor's {sensor.stiffness:g} N/m, and with the tip mass's weight over "
        f"the contact's {contact.stiffness:g} N/m; half the wall in, the fitted normal turns over and the force loop "
        "pushes the wrong way")


def _rounded(x: float, way) -> float:
    """``x`` (> 0) to three significant digits, rounded ``way`` (``math.floor`` or ``math.ceil``): a bound the
    number shown keeps."""
    unit = 10.0 ** (math.floor(math.log10(x)) - 2)
    return way(x / unit) * unit
