"""The plants: the true arm, sensor and surface (:mod:`hybrid.plants.interface`); every implementation
is imported here, so that each registers itself for ``hybrid.simulate(exp, plant=name)``."""

from hybrid.plants import mujoco, planar, rigid_body  # noqa: F401  (each registers its plant)
