"""The plants: the true arm, sensor and surface. :mod:`hybrid.plants.interface` states what a plant
is; :mod:`hybrid.plants.registry` names those a run can take (``hybrid.simulate(exp, plant=name)``):
``"generated"`` (the experiment's own: :mod:`~hybrid.plants.planar` or :mod:`~hybrid.plants.rigid_body`)
and ``"mujoco"`` (:mod:`~hybrid.plants.mujoco`, an optional extra, loaded when a run asks for it). A
new plant is one implementation of the interface, named with
:func:`~hybrid.plants.registry.register_plant`.
"""
