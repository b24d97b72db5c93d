"""The one experiment type (:mod:`hybrid.experiments.experiment`) and its factories, one module each.

:data:`FACTORIES` names every factory (``"paper"``, ``"tracing"``, ``"panda"``): a sweep file's
``experiment = NAME`` picks one. A new experiment is one factory function, added here.
"""

from hybrid.experiments.panda import panda_experiment
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment

#: every experiment factory, by the name a sweep file gives it
FACTORIES = {"paper": paper_experiment, "tracing": tracing_experiment, "panda": panda_experiment}
