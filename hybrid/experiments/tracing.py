"""The 3-D experiment: a URDF arm tracing a circle on a surface, with the paper's loops and timing.

The default is the UR5 (the URDF shipped by example-robot-data, kept in ``hybrid/data``) on a
sphere of radius 0.15 m in front of it, along the latitude circle 60 degrees from the top, with
the loops, sampling, integration and model error of the paper's experiment; the force reference
steps from 10 N to 20 N at 0.5 s, the speed along ``t1`` from 0.15 m/s to 0.3 m/s at 1.5 s; 3 s.
"""

from __future__ import annotations

from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments.experiment import Experiment
from hybrid.experiments.settings import with_overrides
from hybrid.geometry.surfaces import Sphere
from hybrid.models.shipped import ur5
from hybrid.validate import checked_keywords

#: the sphere of the default experiment: in front of the UR5, within reach and away from its
#: singularities along the whole path (a choice)
SPHERE_CENTER, SPHERE_RADIUS = (0.5, 0.0, 0.2), 0.15


@checked_keywords
def tracing_experiment(**overrides) -> Experiment:
    """The 3-D experiment, with any setting of :class:`Experiment` overridden by keyword.

    The UR5 on a sphere of radius 0.15 m centred at (0.5, 0, 0.2) m in front of it, its sensor tip
    sliding along the latitude circle 60 degrees from the top, along the task axis ``t1`` (``e`` =
    base z), with the loops, sampling, integration and model error of the paper's experiment; the
    force reference ``F_d`` steps from 10 N to 20 N at 0.5 s, the speed ``v_d`` along ``t1`` from
    0.15 m/s to 0.3 m/s at 1.5 s; 3 s in all (conventions §10).

    Parameters
    ----------
    **overrides
        Any field of :class:`Experiment`; the gains one by one (``KPv=50``); ``F_d`` / ``v_d`` in
        place of the force / speed references (a number: a constant); and ``latitude`` [deg]: the path
        is then the sphere's latitude circle that many degrees from its top (default 60, the sphere's
        own path). With a ``path_task`` the task gives the references.

    Returns
    -------
    Experiment
        The 3-D experiment (above), overridden.

    Raises
    ------
    HybridError
        An unknown or refused setting, or a ``latitude`` on a surface that is not a sphere or with a
        ``path_task``.

    Examples
    --------
    >>> import hybrid
    >>> experiment = hybrid.tracing_experiment(
    ...     latitude=45.0, F_d=15.0, duration=0.5)
    >>> experiment.robot.name, experiment.force_reference
    ('ur5', Step(before=15.0, after=15.0, at=0.0))
    >>> # 0.15 m * sin(45 degrees)
    >>> round(experiment.followed_path().radius, 4)
    0.1061
    """
    latitude = overrides.pop("latitude", None)
    surface = overrides.get("surface", Sphere(SPHERE_CENTER, SPHERE_RADIUS))
    if latitude is not None and overrides.get("path_task") is not None:
        raise HybridError(f"latitude = {latitude}: a path_task runs its own path; leave latitude out")
    if latitude is not None:  # else the path follows the surface (a sphere's: 60 degrees from the top)
        if not isinstance(surface, Sphere):
            raise HybridError(f"latitude = {latitude}: a {type(surface).__name__} has no latitude circle; give a "
                              "path or a start_point")
        overrides.setdefault("path", surface.latitude_circle(latitude))
    defaults = {"robot": ur5(), "surface": surface, "force_reference": Step(10.0, 20.0, 0.5),
                "speed_reference": Step(0.15, 0.3, 1.5), "duration": 3.0}
    if "path_task" in overrides:  # the task gives the references
        del defaults["force_reference"], defaults["speed_reference"]
    return with_overrides(Experiment, "tracing_experiment", overrides, defaults)
