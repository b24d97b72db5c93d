"""The paper's experiment: its two-link planar arm sliding on a disc, every setting as the paper's.

The arm of :func:`hybrid.paper_arm`, the disc of centre (0.5, 0) m and radius 0.2 m touched from
outside at (0.3, 0) m, the paper's loops and gains, a 10 ms zero-order hold, RK4 at 0.1 ms, the
controller's model 10 % heavy with half the joint viscosity compensated; the force reference
steps from 10 N to 20 N at 0.4 s, the speed from 0.3 m/s to 0.6 m/s at 1 s; 2 s in all.
"""

from __future__ import annotations

from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments.experiment import Experiment
from hybrid.experiments.settings import with_overrides
from hybrid.geometry.surfaces import Circle
from hybrid.models.planar_arm import Arm, paper_arm
from hybrid.models.robot import Robot
from hybrid.validate import checked_keywords, shown


@checked_keywords
def paper_experiment(**overrides) -> Experiment:
    """The paper's experiment, with any setting of :class:`Experiment` overridden by keyword.

    Parameters
    ----------
    **overrides
        Any field of :class:`Experiment`; the gains one by one (``KPv=50``); ``F_d`` / ``v_d`` in
        place of the force / speed references; ``arm`` (a :class:`hybrid.Arm`), the planar arm's
        parameters.

    Returns
    -------
    Experiment
        The paper's experiment (module docstring), overridden.

    Raises
    ------
    HybridError
        An unknown or refused setting, or both ``arm`` and ``robot``.

    Examples
    --------
    >>> import hybrid
    >>> experiment = hybrid.paper_experiment(duration=0.5, KPf=3.0)
    >>> experiment.duration, experiment.gains.KPf
    (0.5, 3.0)
    """
    arm = overrides.pop("arm", None)
    if arm is not None:
        if not isinstance(arm, Arm):
            raise HybridError(f"arm = {shown(arm, 60)}; give a hybrid.Arm (see hybrid.paper_arm())")
        if "robot" in overrides:
            raise HybridError("give arm (the planar arm's parameters) or robot, not both")
        overrides["robot"] = Robot.planar(arm)
    defaults = {"robot": Robot.planar(paper_arm()), "surface": Circle(center=(0.5, 0.0), radius=0.2),
                "start_point": (0.3, 0.0), "force_reference": Step(10.0, 20.0, 0.4),
                "speed_reference": Step(0.3, 0.6, 1.0), "duration": 2.0}
    return with_overrides(Experiment, "paper_experiment", overrides, defaults)
