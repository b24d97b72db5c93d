"""Task-space decoupling hybrid force/velocity control of robot manipulators (De Luca & Manes).

The public API: parameters (:class:`Arm`, :func:`paper_arm`, :class:`Circle`, :class:`Plane`),
the compiled law (:func:`decoupling_law`) and the arm's terms, and :class:`HybridError`,
the base of every error raised on bad input.
"""

from .errors import HybridError, NativeBuildError, NonFiniteError, SingularConfigurationError
from .law import DecouplingLaw, arm_terms, decoupling_law, operational_space, task_frame
from .parameters import Arm, Circle, Plane, paper_arm

__all__ = [
    "Arm", "Circle", "DecouplingLaw", "HybridError", "NativeBuildError", "NonFiniteError", "Plane",
    "SingularConfigurationError", "arm_terms", "decoupling_law", "operational_space", "paper_arm",
    "task_frame",
]
