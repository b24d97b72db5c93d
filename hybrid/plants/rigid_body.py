"""The generated rigid-body plant of any serial arm: the arm from its chain, a 3-D elastic sensor and
penalty contact with friction on any surface, generated for the arm's structure and the surface."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.native import units
from hybrid.plants.interface import GeneratedPlant, LoopPlant


@dataclass(frozen=True)
class RigidBodyLoopPlant(LoopPlant):
    """The generated rigid-body plant of the arm ``chain`` (named ``robot``) on the surface ``spec``."""

    chain: object
    robot: str
    spec: object

    @property
    def name(self) -> str:
        return f"{self.robot}_{self.spec.kind}"

    @property
    def what(self) -> str:
        return f"the 3-D experiment's closed loop: {self.robot} on a {self.spec.kind}"

    def key(self) -> list:
        return ["spatial", units.chain_key(self.chain), self.spec.key()]

    def kernels(self, generator) -> tuple:
        kernels = {k.name: k for k in generator.plant_kernels(self.chain, self.spec)}
        return kernels["plant_rhs"], kernels["plant_outputs"], ("Fc_x", "Fc_y", "Fc_z")


class RigidBodyPlant(GeneratedPlant):
    """The 3-D experiment's plant: a URDF arm, 3-D sensor, contact on any surface."""

    def __init__(self, exp):
        unit = units.plant_unit(exp.robot.chain, exp.robot.name, exp.surface.spec())
        given = self.inputs(exp)
        super().__init__(unit, "plant_rhs", "plant_outputs", tuple(given[k] for k in ("robot", "plant", "surface")),
                         tuple(given.values()), exp.integration_step, ("Fc_x", "Fc_y", "Fc_z"))
        self._robot = exp.robot

    @staticmethod
    def loop_plant(exp) -> LoopPlant:
        """What the compiled closed loop's plant is built from (:func:`hybrid.native.units.loop_unit`)."""
        return RigidBodyLoopPlant(exp.robot.chain, exp.robot.name, exp.surface.spec())

    @staticmethod
    def inputs(exp) -> dict[str, np.ndarray]:
        """The plant's parameter arrays (after ``x, tau``; the output record's also ``e``) by the
        manifest's names."""
        return {"robot": exp.robot.as_array(), "plant": exp.plant_array(), "surface": exp.surface.as_array(),
                "e": np.asarray(exp.frame_direction, float)}

    conditioning_name = "m/(|J|_F |J^+|_F)"

    def conditioning(self, q) -> np.ndarray:
        """The arm's conditioning at ``q`` (one state, or one per row): see :meth:`Robot.conditioning`."""
        return self._robot.conditioning(q)
