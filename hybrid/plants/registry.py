"""The plants a run can take, by name (``hybrid.simulate(exp, plant=name)``): ``"generated"`` (the
experiment's own: :mod:`~hybrid.plants.planar` or :mod:`~hybrid.plants.rigid_body`), ``"mujoco"``
(:mod:`~hybrid.plants.mujoco`, an optional extra, loaded when a run asks for it) and ``"mujoco_contact"``
(MuJoCo's own collision and contact against a part's mesh, :mod:`~hybrid.plants.mujoco_contact`). A new plant is one
implementation of :class:`hybrid.plants.interface.Plant`, named with :func:`register_plant`.
"""

from __future__ import annotations

from collections.abc import Callable

from hybrid.errors import HybridError
from hybrid.plants.interface import GeneratedPlant
from hybrid.plants.planar import PlanarPlant
from hybrid.plants.rigid_body import RigidBodyPlant
from hybrid.validate import shown

#: the plants a run can take, by name: each builds the plant of an experiment
PLANTS: dict[str, Callable] = {}
#: the generated plants, by the name a robot's kind gives (:attr:`hybrid.models.kinds.SerialChain.plant`): a
#: new generated plant is a :class:`~hybrid.plants.interface.GeneratedPlant` named here
GENERATED_PLANTS: dict[str, type[GeneratedPlant]] = {"planar": PlanarPlant, "rigid_body": RigidBodyPlant}


def generated_plant_class(name: str) -> type[GeneratedPlant]:
    """The generated plant named ``name``."""
    if name not in GENERATED_PLANTS:
        raise HybridError(f"no generated plant is named {name!r}; the generated plants are "
                          f"{', '.join(GENERATED_PLANTS)} (hybrid.plants.registry.GENERATED_PLANTS)")
    return GENERATED_PLANTS[name]


def register_plant(name: str):
    """Decorator: make the plant factory ``f(experiment) -> plant`` selectable as ``plant=name``."""
    def register(factory):
        PLANTS[name] = factory
        return factory
    return register


@register_plant("generated")
def generated_plant(exp):
    """The experiment's generated plant (:meth:`hybrid.Experiment.plant`: the closed form of the
    paper's arm, else the rigid-body plant)."""
    return exp.plant()


@register_plant("mujoco")
def mujoco_plant(exp):
    """MuJoCo as the experiment's plant (:func:`hybrid.plants.mujoco.mujoco_plant`)."""
    from hybrid.plants import mujoco  # an optional extra: its module loads when a run asks for it

    return mujoco.mujoco_plant(exp)


@register_plant("mujoco_contact")
def mujoco_contact_plant(exp):
    """MuJoCo as the plant with its own collision and contact against the experiment's part
    (:class:`hybrid.plants.mujoco_contact.MujocoContactPlant`)."""
    from hybrid.plants import mujoco_contact  # an optional extra: its module loads when a run asks for it

    return mujoco_contact.MujocoContactPlant(exp, exp.robot, sensor_gravity=exp.robot.kind.sensor_weighs)


def plant_for(exp, name: str):
    """The plant ``name`` of the experiment ``exp``."""
    if not isinstance(name, str) or name not in PLANTS:
        raise HybridError(f"plant = {shown(name, 40)}; give one of {', '.join(repr(n) for n in PLANTS)}")
    return PLANTS[name](exp)
