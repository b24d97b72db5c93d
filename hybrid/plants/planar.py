"""The paper's plant in closed form: its planar arm, the 2-D elastic sensor and the surface, from the
committed units (``generated/``) of one SymPy derivation."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from hybrid.native import units
from hybrid.native.loader import manifest
from hybrid.plants.interface import GeneratedPlant, LoopPlant, plant_record


@cache
def planar_record() -> dict:
    """The paper's plant's record (its columns are ``codegen.model.PLANT_OUTPUTS``), read from the
    committed manifest when first asked for."""
    functions = {f["name"]: f for f in manifest("sympy")["functions"]}
    return plant_record(functions["plant_rhs_circle"], functions["plant_outputs_circle"])


@dataclass(frozen=True)
class PlanarLoopPlant(LoopPlant):
    """The paper's closed-form plant on a planar surface of ``kind``."""

    kind: str

    @property
    def name(self) -> str:
        return self.kind

    @property
    def what(self) -> str:
        return f"the paper's closed loop on a {self.kind}"

    def key(self) -> list:
        return ["planar", self.kind]

    def kernels(self, generator) -> tuple:
        kernels = {k.name: k for k in generator.planar_kernels(2)}
        return kernels[f"plant_rhs_{self.kind}"], kernels[f"plant_outputs_{self.kind}"], ("Fc_x", "Fc_y")


class PlanarPlant(GeneratedPlant):
    """The paper's plant in closed form: its arm, the 2-D elastic sensor, the surface's cross-section."""

    def __init__(self, exp):
        unit = units.planar_unit(exp.backend)
        kind = exp.section.kind
        held = tuple(self.inputs(exp).values())
        super().__init__(unit, f"plant_rhs_{kind}", f"plant_outputs_{kind}", held, held, exp.integration_step,
                         ("Fc_x", "Fc_y"))
        self._arm = exp.arm

    @staticmethod
    def loop_plant(exp) -> LoopPlant:
        """What the compiled closed loop's plant is built from (:func:`hybrid.native.units.loop_unit`)."""
        return PlanarLoopPlant(exp.section.kind)

    @staticmethod
    def inputs(exp) -> dict[str, np.ndarray]:
        """The plant's parameter arrays (after ``x, tau``) by the manifest's names."""
        return {"arm": exp.arm.as_array(), "plant": exp.plant_array(), "surface": exp.section.as_array()}

    conditioning_name = "2|det J|/|J|_F^2"

    def conditioning(self, q) -> np.ndarray:
        """``2 |det J| / |J|_F^2`` at ``q`` (one state, or one per row)."""
        return self._arm.conditioning(np.asarray(q, float).T)
