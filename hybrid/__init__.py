"""Task-space decoupling hybrid force/velocity control of robot manipulators (De Luca & Manes).

The public API, by subpackage:

- robot models (:mod:`hybrid.models`): :class:`Robot`, the one robot model (any serial arm, e.g.
  from a URDF; the shipped :func:`ur5` and :func:`panda`, their files :data:`UR5_URDF` and
  :data:`PANDA_URDF`; the paper's planar arm as ``Robot.planar(paper_arm())``, with :class:`Arm` its
  parameters), and their terms (:func:`arm_terms`, :func:`operational_space`); the joint-torque
  regressor ``tau = Y pi`` (:func:`regressor`) on the parameters the dynamics are linear in
  (:func:`linear_parameters`, and back: :func:`with_linear_parameters`), its base parameters
  (:func:`base_parameters`, :class:`BaseParameters`) and the dynamics identified from a log of measured
  torques (:func:`identify_dynamics`, :class:`DynamicsIdentification`) along trajectories that excite them
  well (:func:`excitation_trajectory`, :class:`ExcitationTrajectory`); a robot's inertial parameters
  perturbed at random, each link still a rigid body (:func:`perturbed_robot`);
- geometry (:mod:`hybrid.geometry`): the surfaces :class:`Plane`, :class:`Circle`, :class:`Sphere`,
  :class:`Cylinder` and :class:`ImplicitSurface`, and parts as they come (:class:`MeshSurface`,
  :class:`PointCloudSurface`); paths on them (:class:`CirclePath`,
  :class:`LinePath`; on any surface :class:`WaypointPath`, :class:`RasterPath`,
  :class:`SpiralPath`); the task frame at points of any surface (:func:`task_frame`);
- control (:mod:`hybrid.control`): the compiled law (:class:`DecouplingLaw`, :func:`decoupling_law`),
  the :class:`Controller` component, its settings in three groups (:class:`Tracking`, :class:`Limits`,
  :class:`Sensing`), its options (:class:`Posture`, a null-space posture task;
  :class:`ContactLoss`) and its schemes (:data:`SCHEMES`); :class:`Gains`, :class:`Step`; a controller
  described in a TOML file (:func:`read_controller_config`); a force/torque sensor's bias and tool
  (:class:`WrenchSensor`, the :class:`Tool` beyond it) identified from readings at rest
  (:func:`identify_tool`, :class:`ToolIdentification`) and tared at run time (:func:`tare`);
- experiments and simulation: the one :class:`Experiment` type and its factories
  (:func:`paper_experiment`, :func:`tracing_experiment`, :func:`panda_experiment`), the plant's
  :class:`Sensor` and :class:`Contact`, :func:`simulate`, :class:`SimulationResult`, :func:`metrics`; a run
  as an interactive 3-D figure for the browser (:func:`view`, plotly: an optional extra);
  sweeps (:func:`sweep`); gains tuned across scenarios with a stability margin kept (:func:`tune`);
- :class:`HybridError`, the base of every error raised on bad input; :class:`LargeModelWarning`,
  warned for a chain whose code takes minutes to generate; :class:`JointLimitWarning`, for a run that
  left the robot's joint limits; :class:`RedundancyWarning`, for a redundant arm without a posture task;
  :class:`PartFitWarning`, for a part's surface that follows the part poorly.

Importing the package loads neither SymPy nor CasADi and reads no file: the code generator
runs only when a unit must be built, and :class:`ImplicitSurface` (a SymPy expression),
:func:`sweep` (pandas), :func:`read_controller_config` (a TOML parser),
:func:`excitation_trajectory` (SciPy's optimisers) and :func:`view` (plotly) load what they need on
first use.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from hybrid._version import __version__
from hybrid.control.controller import Controller
from hybrid.control.controller_settings import Limits, Sensing, Tracking
from hybrid.control.estimation import EstimatedSurface
from hybrid.control.fault import FaultReaction
from hybrid.control.identification import ToolIdentification, identify_tool, tare
from hybrid.control.law import DecouplingLaw, decoupling_law
from hybrid.control.loops import Gains
from hybrid.control.measurement import Measurement
from hybrid.control.options import ContactLoss, Posture, Reference
from hybrid.control.path_task import PathTask
from hybrid.control.references import Step
from hybrid.control.schemes import SCHEMES, Khatib, Scheme, TaskDecoupling
from hybrid.control.wrench_sensor import Tool, WrenchSensor
from hybrid.errors import (
    HybridError,
    LargeModelWarning,
    NativeBuildError,
    NonFiniteError,
    ParameterError,
    SafeStopError,
    SampleTimingError,
    SingularConfigurationError,
    TaskFrameError,
    URDFError,
)
from hybrid.experiments.experiment import Experiment
from hybrid.experiments.panda import panda_experiment
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.geometry.frames import task_frame
from hybrid.geometry.paths import CirclePath, LinePath
from hybrid.geometry.patterns import RasterPath, SpiralPath
from hybrid.geometry.surfaces import Circle, Cylinder, Plane, Sphere
from hybrid.geometry.waypoints import WaypointPath
from hybrid.models.base_parameters import BaseParameters, base_parameters
from hybrid.models.dynamics_identification import DynamicsIdentification, identify_dynamics
from hybrid.models.perturbation import perturbed_robot
from hybrid.models.planar_arm import Arm, paper_arm
from hybrid.models.regressor import linear_parameters, regressor, with_linear_parameters
from hybrid.models.robot import Robot
from hybrid.models.shipped import PANDA_URDF, UR5_URDF, panda, ur5
from hybrid.models.terms import OperationalSpace, arm_terms, operational_space
from hybrid.plants.contact import Contact, Sensor
from hybrid.simulation.metrics import metrics
from hybrid.simulation.results import SimulationResult
from hybrid.simulation.runner import SimulationError, simulate
from hybrid.stability.analysis import LoopStability, Stability, stability
from hybrid.user_warnings import JointLimitWarning, PartFitWarning, RedundancyWarning

if TYPE_CHECKING:  # type checkers see the lazy names' real signatures
    from hybrid.control.config import read_controller_config
    from hybrid.geometry.implicit import ImplicitSurface
    from hybrid.geometry.parts import MeshSurface, PointCloudSurface
    from hybrid.models.excitation import ExcitationTrajectory, excitation_trajectory
    from hybrid.stability.gains import GainSuggestion, suggest_gains
    from hybrid.stability.maps import StabilityMap, stability_map
    from hybrid.stability.tuning import Tuning, tune
    from hybrid.sweeps import sweep
    from hybrid.view3d import view

#: public names loaded on first use (what they need is heavy: SymPy, pandas, SciPy's optimisers, plotly; a TOML
#: parser and its schema)
_LAZY = {"ImplicitSurface": "hybrid.geometry.implicit", "MeshSurface": "hybrid.geometry.parts",
         "PointCloudSurface": "hybrid.geometry.parts", "sweep": "hybrid.sweeps",
         "read_controller_config": "hybrid.control.config", "stability_map": "hybrid.stability.maps",
         "StabilityMap": "hybrid.stability.maps", "suggest_gains": "hybrid.stability.gains",
         "GainSuggestion": "hybrid.stability.gains",
         "tune": "hybrid.stability.tuning", "Tuning": "hybrid.stability.tuning",
         "excitation_trajectory": "hybrid.models.excitation", "ExcitationTrajectory": "hybrid.models.excitation",
         "view": "hybrid.view3d"}


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'hybrid' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)


__all__ = [
    "Arm", "BaseParameters", "Circle", "CirclePath", "Contact", "ContactLoss", "Controller", "Cylinder",
    "DecouplingLaw", "DynamicsIdentification", "EstimatedSurface", "Experiment", "FaultReaction", "GainSuggestion",
    "Gains",
    "HybridError", "ImplicitSurface",
    "JointLimitWarning", "Khatib", "LargeModelWarning", "LinePath", "LoopStability", "Measurement", "MeshSurface",
    "NativeBuildError",
    "NonFiniteError", "OperationalSpace", "PANDA_URDF", "ParameterError", "PartFitWarning", "PathTask", "Plane",
    "PointCloudSurface", "Posture", "RasterPath",
    "RedundancyWarning", "Reference", "Robot", "SCHEMES", "SafeStopError", "SampleTimingError", "Scheme", "Sensor",
    "SimulationError", "SimulationResult", "SingularConfigurationError", "Sphere", "SpiralPath", "Stability",
    "StabilityMap", "Step",
    "TaskDecoupling",
    "TaskFrameError", "Tool", "ToolIdentification", "UR5_URDF", "URDFError", "WaypointPath", "WrenchSensor",
    "__version__", "arm_terms", "base_parameters", "decoupling_law", "identify_dynamics", "identify_tool",
    "linear_parameters", "metrics",
    "operational_space", "panda", "panda_experiment", "paper_arm", "paper_experiment", "perturbed_robot",
    "read_controller_config",
    "regressor", "simulate", "stability", "stability_map", "suggest_gains",
    "sweep", "tare", "task_frame", "tracing_experiment", "ur5", "with_linear_parameters",
    "Tuning", "tune",
    "ExcitationTrajectory", "excitation_trajectory",
    "Tracking", "Limits", "Sensing",
    "view",
]
