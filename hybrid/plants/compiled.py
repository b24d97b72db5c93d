"""Plants: the true arm, sensor and surface, advanced by fixed-step RK4 between control samples.

A plant has ``advance(x, tau, nsteps, trajectory) -> steps done`` (in place, stopping before a
non-finite state) and ``outputs(states)`` (the ``PLANT_OUTPUTS`` record of each state).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from hybrid.native import units
from hybrid.native.build import manifest


def plant_record(rhs: dict, outputs: dict) -> dict:
    """Names and units of a plant's state and output record, from its manifest entries."""
    x, tau, y = rhs["inputs"][0], rhs["inputs"][1], outputs["outputs"][0]
    return {"outputs": tuple(y["names"]), "output_units": tuple(y["unit"]), "state": tuple(x["names"]),
            "state_units": tuple(x["unit"]), "nq": tau["size"]}


@cache
def planar_record() -> dict:
    """The paper's plant's record (its columns are ``codegen.model.PLANT_OUTPUTS``), read from the
    committed manifest when first asked for."""
    functions = {f["name"]: f for f in manifest("sympy")["functions"]}
    return plant_record(functions["plant_rhs_circle"], functions["plant_outputs_circle"])


class LoopPlant:
    """What the compiled closed loop needs of a generated plant: ``name`` (part of its unit's name),
    ``key()`` (what the generated code depends on, for the cache), ``kernels(generator)`` (its state
    derivative, its output record and the record's sensor-force columns, from the generator's
    modules), ``what`` (a line for the unit's header). Equal plants compare equal: they share a build."""


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
        kernels = {k.name: k for k in generator("model").kernels(2)}
        return kernels[f"plant_rhs_{self.kind}"], kernels[f"plant_outputs_{self.kind}"], ("Fc_x", "Fc_y")


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
        kernels = {k.name: k for k in generator("spatial_plant").plant_kernels(self.chain, self.spec)}
        return kernels["plant_rhs"], kernels["plant_outputs"], ("Fc_x", "Fc_y", "Fc_z")


class Plant:
    """What the runner needs of a plant besides ``advance`` and ``outputs``: the sensor's reading."""

    #: the output-record columns of the sensor's force on the robot (base axes)
    force_columns: tuple[str, ...] = ("Fc_x", "Fc_y")

    def sensor_wrench(self, x: np.ndarray) -> np.ndarray:
        """The sensor's reading at the state ``x`` (what the controller is given at a sample), as the
        wrench ``(f, m)`` on the robot, base axes."""
        columns = self.__dict__.get("_force")
        if columns is None:
            columns = self._force = [self.record["outputs"].index(c) for c in self.force_columns]
        Fc = np.zeros(6)
        Fc[:len(columns)] = self._record_row(x)[columns]
        return Fc

    def _record_row(self, x: np.ndarray) -> np.ndarray:
        """The output record of the one state ``x``."""
        return self.outputs(x[None, :])[0]


class CompiledPlant(Plant):
    """A plant whose state derivative ``plant_rhs`` (with its RK4 entry point) and output record
    ``plant_outputs`` are generated C; ``held`` are the inputs after ``(x, tau)``, ``shown`` those
    after ``x`` of the outputs."""

    def __init__(self, rhs, outputs, held: tuple, shown: tuple, step: float, force_columns: tuple[str, ...]):
        self._rhs, self._outputs, self._held, self._shown = rhs, outputs, held, shown
        self.record = plant_record(rhs.entry, outputs.entry)
        self.nq, self.h, self.force_columns = self.record["nq"], step, force_columns
        self._done = rhs.unit.module.ffi.new("int *")
        # one state through the one-state entry point (a sample's reading in about a microsecond)
        self._fast, self._binding = outputs.fast_bind(1, *shown)

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place, writing each step's state to ``trajectory``; steps done."""
        self._rhs.integrate(x, tau, *self._held, h=self.h, nsteps=nsteps, trajectory=trajectory, done=self._done)
        return self._done[0]

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The output record of each state, in one native call."""
        states = np.ascontiguousarray(states)
        out = np.empty((len(states), len(self.record["outputs"])))
        # a partial run's last states may be non-finite: their records are kept as they come
        self._outputs.batch_into(states, *self._shown, out, status=np.empty(len(states), dtype=np.intc))
        return out

    def _record_row(self, x: np.ndarray) -> np.ndarray:
        row = self._fast(self._binding, 0, x)
        # off the fast path (a non-finite state): the record as the batch gives it
        return self.outputs(x[None, :])[0] if row is None else row


class NativePlant(CompiledPlant):
    """The paper's plant: arm + 2-D sensor + surface (NOTES section 5)."""

    def __init__(self, exp):
        unit = units.planar_unit(exp.backend)
        kind = exp.surface.kind
        held = tuple(self.inputs(exp).values())
        super().__init__(unit.function(f"plant_rhs_{kind}"), unit.function(f"plant_outputs_{kind}"),
                         held, held, exp.step, ("Fc_x", "Fc_y"))
        self._arm = exp.arm

    @staticmethod
    def loop_plant(exp) -> LoopPlant:
        """What the compiled closed loop's plant is built from (:func:`hybrid.native.units.loop_unit`)."""
        return PlanarLoopPlant(exp.surface.kind)

    @staticmethod
    def inputs(exp) -> dict[str, np.ndarray]:
        """The plant's parameter arrays (after ``x, tau``) by the manifest's names."""
        return {"arm": exp.arm.as_array(), "plant": exp.plant_array(), "surface": exp.surface.as_array()}

    conditioning_name = "2|det J|/|J|_F^2"

    def conditioning(self, q) -> np.ndarray:
        """``2 |det J| / |J|_F^2`` at ``q`` (one state, or one per row)."""
        return self._arm.conditioning(np.asarray(q, float).T)


class SpatialPlant(CompiledPlant):
    """The 3-D experiment's plant: a URDF arm, 3-D sensor, contact on any surface (NOTES section 10)."""

    def __init__(self, exp):
        unit = units.plant_unit(exp.robot.chain, exp.robot.name, exp.surface.lift().spec())
        given = self.inputs(exp)
        super().__init__(unit.function("plant_rhs"), unit.function("plant_outputs"),
                         tuple(given[k] for k in ("robot", "plant", "surface")), tuple(given.values()), exp.step,
                         ("Fc_x", "Fc_y", "Fc_z"))
        self._robot = exp.robot

    @staticmethod
    def loop_plant(exp) -> LoopPlant:
        """What the compiled closed loop's plant is built from (:func:`hybrid.native.units.loop_unit`)."""
        return RigidBodyLoopPlant(exp.robot.chain, exp.robot.name, exp.surface.lift().spec())

    @staticmethod
    def inputs(exp) -> dict[str, np.ndarray]:
        """The plant's parameter arrays (after ``x, tau``; the output record's also ``e``) by the
        manifest's names."""
        return {"robot": exp.robot.as_array(), "plant": exp.plant_array(), "surface": exp.surface.lift().as_array(),
                "e": np.asarray(exp.reference, float)}

    conditioning_name = "m/(|J|_F |J^+|_F)"

    def conditioning(self, q) -> np.ndarray:
        """The arm's conditioning at ``q`` (one state, or one per row): see :meth:`Robot.conditioning`."""
        return self._robot.conditioning(q)
