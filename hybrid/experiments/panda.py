"""The Panda experiment: the shipped Panda tracing a circle around a vertical cylinder, its spare
joint held by a posture task.

The arm is :func:`hybrid.panda` (7 joints, tip ``panda_hand_tcp``) on all six task axes, one joint
to spare. The surface is a vertical pillar of radius 0.25 m, its axis 0.67 m in front of the base,
touched from outside at the point facing the robot, (0.42, 0, 0.78) m: the normal there points back
at the robot, so the hand points straight ahead (its z axis along +x), its x axis along the path's
tangent ``t1 = -y``. The path is the level circle around the pillar through that point
(:meth:`hybrid.Cylinder.circle_at`), run counter-clockwise seen from above.

The posture task (:class:`hybrid.Posture` with its default gains: 5 rad/s, critically damped) rests
at the Panda's usual ready pose ``(0, -pi/4, 0, -3 pi/4, 0, pi/2, pi/4)`` with the hand turned to
face the pillar: joint 6 a quarter turn further (to pi) pitches it from pointing down to pointing
ahead, joint 7 a quarter turn further (to 3 pi/4) rolls its x axis onto ``t1``; shoulder and elbow
stay as in the ready pose. Its tip is within 6 mm of where the arm tip starts (1 cm beyond the
sensor tip, the sensor spring carrying 10 N), so the start's inverse kinematics, which begins at
it, ends next to it: conditioning 0.27 (0.34 at the ready pose), every joint at least 0.54 rad
inside its limits (joint 7's upper one the nearest). The height follows from the level hand: in the
robot's plane of symmetry a hand pointing level ahead keeps joints 2, 4 and 6 half a radian inside
their ranges only from about 0.72 m up (lower, joint 6 must pitch it beyond 3.25 rad). Without the
posture task the spare joint motion falls under gravity (the law decouples the task only) and the
joints wind up by several turns within the run.

The loops, gains, sampling (10 ms), integration (RK4 at 0.1 ms) and model error are the paper's;
the references are the 3-D experiment's scaled to what the arm allows. The speed steps from
0.05 m/s to 0.1 m/s at 1.5 s: the hand turns with the normal, at up to 0.43 rad/s, and the 0.225 m
of the run take it 55 degrees around the pillar (the arm tip, whose speed the loops set, runs
1.5 cm inside it), over which the conditioning stays above 0.18, every joint 0.5 rad inside its
limits and below 30 % of its speed limit, and the arm's joints more than 0.1 m outside the pillar
(at twice the speed the wrist would sweep into it). The force steps from 10 N to 15 N at 0.5 s: the
paper's loops answer a force step at once, as an acceleration along the normal, and at this reach
one sample after a 10 N step would take joint 2 to 99 N m, beyond its 87 N m rating; after 5 N
every joint stays below 60 % of its rating throughout.
"""

from __future__ import annotations

from hybrid.control.options import Posture
from hybrid.control.references import Step
from hybrid.experiments.experiment import Experiment
from hybrid.experiments.settings import with_overrides
from hybrid.geometry.surfaces import Cylinder
from hybrid.models.shipped import panda
from hybrid.validate import checked_keywords

#: the pillar of the default experiment: its axis vertical, 0.67 m in front of the base (a choice)
CYLINDER_POINT, CYLINDER_RADIUS = (0.67, 0.0, 0.0), 0.25
#: where the sensor tip starts: on the pillar, on its side facing the robot, 0.78 m up [m]
START_POINT = (0.42, 0.0, 0.78)
#: the ready pose with the hand turned to point ahead (joints 6 and 7 a quarter turn further) [rad]
REST_POSTURE = (0.0, -0.785, 0.0, -2.356, 0.0, 3.142, 2.356)


@checked_keywords
def panda_experiment(**overrides) -> Experiment:
    """The Panda experiment, with any setting of :class:`Experiment` overridden by keyword.

    Takes the same keywords as :func:`hybrid.paper_experiment` (the gains one by one, ``F_d``,
    ``v_d``). On a vertical cylinder the path is, unless given, the circle around it through the
    start point (``start_point``, or the default one projected onto the cylinder); ``posture=None``
    turns the posture task off (warned: :class:`hybrid.RedundancyWarning`).

    Parameters
    ----------
    **overrides
        Any field of :class:`Experiment`; the gains one by one; ``F_d`` / ``v_d`` in place of the
        force / speed references.

    Returns
    -------
    Experiment
        The Panda pressing on a vertical pillar and sliding around it, overridden.

    Raises
    ------
    HybridError
        An unknown or refused setting.

    Examples
    --------
    >>> import hybrid
    >>> experiment = hybrid.panda_experiment(duration=1.0)
    >>> experiment.robot.name, experiment.duration
    ('panda', 1.0)
    """
    surface = overrides.get("surface", Cylinder(CYLINDER_POINT, (0.0, 0.0, 1.0), CYLINDER_RADIUS))
    defaults = {"robot": panda(), "surface": surface, "posture": Posture(REST_POSTURE),
                "force_reference": Step(10.0, 15.0, 0.5), "speed_reference": Step(0.05, 0.1, 1.5), "duration": 3.0}
    if isinstance(surface, Cylinder) and "start_point" not in overrides:
        # the default start, moved radially onto a cylinder of the caller's (the path runs through it)
        defaults["start_point"] = tuple(surface.project(START_POINT).tolist())
    if "path_task" in overrides:  # the task gives the references and the start
        for name in ("force_reference", "speed_reference", "start_point"):
            defaults.pop(name, None)
    return with_overrides(Experiment, "panda_experiment", overrides, defaults)
