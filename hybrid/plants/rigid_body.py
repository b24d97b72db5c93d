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
        # a part's surface: its expansion about the sensor tip, written into the held array at each step
        self._part = exp.surface if exp.surface.local else None
        self._theta = given["surface"]
        self._tip = slice(self.record["state"].index("s_x"), self.record["state"].index("s_z") + 1)

    def _about_tip(self, x: np.ndarray) -> None:
        """A part's surface about the sensor tip of the state ``x`` (NaN beyond its band: the state that
        follows is not finite, and the run says where the tip left the part)."""
        self._theta[:] = self._part.parameters_at(x[self._tip])

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """As :meth:`GeneratedPlant.advance`; on a part, one RK4 step at a time, each with the part's surface
        about the sensor tip at its start (it moves ``h |s'|``, a few micrometres, within the step: the
        expansion's error there is of the order of its cube)."""
        if self._part is None:
            return super().advance(x, tau, nsteps, trajectory)
        for i in range(nsteps):
            self._about_tip(x)
            if super().advance(x, tau, 1, trajectory[i:i + 1]) < 1:
                return i
        return nsteps

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """As :meth:`GeneratedPlant.outputs`; on a part, each state's record with the surface about its own
        sensor tip."""
        if self._part is None:
            return super().outputs(states)
        return np.array([self._record_row(x) for x in np.ascontiguousarray(states)]).reshape(
            len(states), len(self.record["outputs"]))

    def _record_row(self, x: np.ndarray) -> np.ndarray:
        if self._part is None:
            return super()._record_row(x)
        # the one-state entry point holds the parameters it was bound with: the batch reads them as they are
        self._about_tip(x)
        return super().outputs(x[None, :])[0]

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
