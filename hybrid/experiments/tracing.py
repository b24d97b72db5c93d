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

#: the sphere of the default experiment: in front of the UR5, within reach and away from its
#: singularities along the whole path (a choice)
SPHERE_CENTER, SPHERE_RADIUS = (0.5, 0.0, 0.2), 0.15


def tracing_experiment(**overrides) -> Experiment:
    """The 3-D experiment, with any setting of :class:`Experiment` overridden by keyword.

    Takes the same keywords as :func:`hybrid.paper_experiment` (the gains one by one, ``F_d``,
    ``v_d``) and ``latitude`` [deg]: the path is the sphere's latitude circle that many degrees
    from its top (default 60).
    """
    latitude = overrides.pop("latitude", None)
    surface = overrides.get("surface", Sphere(SPHERE_CENTER, SPHERE_RADIUS))
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
