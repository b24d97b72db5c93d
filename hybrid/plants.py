"""Plants: the true arm, sensor and surface, advanced by fixed-step RK4 between control samples.

A plant has ``advance(x, tau, nsteps, trajectory) -> steps done`` (in place, stopping before a
non-finite state) and ``outputs(states)`` (the ``PLANT_OUTPUTS`` record of each state).
"""

from __future__ import annotations

import numpy as np

from .experiment import Experiment
from .law import planar_unit
from .native import manifest


def _plant_record() -> dict:
    """Names and units of the planar plant's state and output record, from the unit's manifest."""
    functions = {f["name"]: f for f in manifest("sympy")["functions"]}
    x = functions["plant_rhs_circle"]["inputs"][0]
    tau = functions["plant_rhs_circle"]["inputs"][1]
    y = functions["plant_outputs_circle"]["outputs"][0]
    return {"outputs": tuple(y["names"]), "output_units": tuple(y["unit"]), "state": tuple(x["names"]),
            "state_units": tuple(x["unit"]), "nq": tau["size"]}


PLANT = _plant_record()
#: columns of the plant output record (``codegen.model.PLANT_OUTPUTS``, read from the manifest)
PLANT_OUTPUTS = PLANT["outputs"]


class NativePlant:
    """Arm + sensor + surface, integrated by the compiled RK4 (the ``integrator`` of ``plant_rhs``)."""

    def __init__(self, exp: Experiment):
        unit = planar_unit(exp.backend)
        kind = exp.surface.kind
        self._rhs = unit.function(f"plant_rhs_{kind}")
        self._outputs = unit.function(f"plant_outputs_{kind}")
        self._arm, self._plant, self._surface = exp.arm.as_array(), exp.plant_array(), exp.surface.as_array()
        self._done = unit.module.ffi.new("int *")
        self.h = exp.step

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place, writing each step's state to ``trajectory``; steps done."""
        self._rhs.integrate(x, tau, self._arm, self._plant, self._surface, h=self.h, nsteps=nsteps,
                            trajectory=trajectory, done=self._done)
        return self._done[0]

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The output record (``PLANT_OUTPUTS``) of each state, in one native call."""
        states = np.ascontiguousarray(states)
        out = np.empty((len(states), len(PLANT_OUTPUTS)))
        # a partial run's last states may be non-finite: their records are kept as they come
        self._outputs.batch_into(states, self._arm, self._plant, self._surface, out,
                                 status=np.empty(len(states), dtype=np.intc))
        return out
