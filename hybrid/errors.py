"""The one error family the library raises on bad input."""


class HybridError(ValueError):
    """Bad input or an impossible request; the message says what was wrong and what to do."""


class SingularConfigurationError(HybridError):
    """The arm is at (or too near) a kinematic singularity: ``J(q)`` cannot be inverted."""


class NonFiniteError(HybridError):
    """A computation produced NaN or infinity."""


class NativeBuildError(HybridError):
    """The generated C could not be compiled or loaded."""


class URDFError(HybridError):
    """A URDF file that cannot describe a controllable serial arm; names the element and line."""


class TaskFrameError(HybridError):
    """The task frame is undefined: its reference direction is parallel to the surface normal."""


class LargeModelWarning(UserWarning):
    """A model so large that generating and compiling its code takes minutes (the message says how long)."""
