"""Task-space decoupling hybrid force/velocity control of robot manipulators (De Luca & Manes).

Public API: robots (:class:`Arm`, :func:`paper_arm`, :class:`Robot`, :func:`ur5`) and surfaces
(:class:`Circle`, :class:`Plane`, :class:`Sphere`, :class:`Cylinder`, :class:`ImplicitSurface`);
the compiled law (:func:`decoupling_law`) and terms; the controller component
(:class:`Controller`, the schemes in :data:`SCHEMES`); the experiments (:func:`paper_experiment`,
:func:`tracing_experiment`, :func:`simulate`, :func:`metrics`); sweeps (:func:`sweep`); and
:class:`HybridError`, the base of every error raised on bad input.
"""

from .controller import ContactLoss, Controller, Measurement, Reference
from .errors import HybridError, NativeBuildError, NonFiniteError, SingularConfigurationError, TaskFrameError, URDFError
from .experiment import Contact, Experiment, Gains, Sensor, Step, paper_experiment
from .law import DecouplingLaw, OperationalSpace, arm_terms, decoupling_law, operational_space, task_frame
from .parameters import Arm, Circle, Plane, paper_arm
from .performance import metrics
from .results import SimulationResult
from .robot import Robot
from .schemes import SCHEMES, Khatib, Scheme, TaskDecoupling
from .simulation import SimulationError, simulate
from .spatial_law import SpatialDecouplingLaw
from .surfaces import Cylinder, ImplicitSurface, Sphere
from .sweeps import sweep
from .tracing import TracingExperiment, tracing_experiment, ur5

__all__ = [
    "Arm", "Circle", "Contact", "ContactLoss", "Controller", "Cylinder", "DecouplingLaw", "Experiment", "Gains",
    "HybridError", "ImplicitSurface", "Khatib", "Measurement", "NativeBuildError", "NonFiniteError",
    "OperationalSpace", "Plane", "Reference", "Robot", "SCHEMES", "Scheme", "Sensor", "SimulationError",
    "SimulationResult", "SingularConfigurationError", "SpatialDecouplingLaw", "Sphere", "Step", "TaskDecoupling",
    "TaskFrameError", "TracingExperiment", "URDFError", "arm_terms", "decoupling_law", "metrics", "operational_space",
    "paper_arm", "paper_experiment", "simulate", "sweep", "task_frame", "tracing_experiment", "ur5",
]
