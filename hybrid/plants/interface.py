"""The plant interface: what the runner needs of the true arm, sensor and surface.

A plant has ``record`` (the names and units of its state and output columns, ``nq`` joints),
``advance(x, tau, nsteps, trajectory) -> steps done`` (RK4 steps with the torque held, in place,
stopping before a non-finite state), ``outputs(states)`` (the output record of each state),
``sensor_wrench(x)`` (the sensor's reading at a state), ``conditioning(q)`` and
``conditioning_name``. Three implement it: the paper's closed-form planar plant
(:mod:`hybrid.plants.planar`), the generated rigid-body plant of any arm
(:mod:`hybrid.plants.rigid_body`), and MuJoCo (:mod:`hybrid.plants.mujoco`). Each builds on this
module and on no other plant; :mod:`hybrid.plants.registry` names the plants a run can be given
(``hybrid.simulate(exp, plant=name)``).
"""

from __future__ import annotations

from functools import cached_property

import numpy as np


def plant_record(rhs: dict, outputs: dict) -> dict:
    """Names and units of a plant's state and output record, from its manifest entries."""
    x, tau, y = rhs["inputs"][0], rhs["inputs"][1], outputs["outputs"][0]
    return {"outputs": tuple(y["names"]), "output_units": tuple(y["unit"]), "state": tuple(x["names"]),
            "state_units": tuple(x["unit"]), "nq": tau["size"]}


class LoopPlant:
    """What the compiled closed loop needs of a generated plant: ``name`` (part of its unit's name),
    ``key()`` (what the generated code depends on, for the cache), ``kernels(generator)`` (its state
    derivative, its output record and the record's sensor-force columns, from the generator's
    modules), ``what`` (a line for the unit's header). Equal plants compare equal: they share a build."""


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


class GeneratedPlant(Plant):
    """A plant whose state derivative ``rhs`` (with its RK4 entry point) and output record ``outputs``
    are functions of the generated ``unit``; ``held`` are the inputs after ``(x, tau)``, ``shown`` those
    after ``x`` of the outputs. The unit is compiled when the plant is first advanced or read (a run of
    the compiled loop needs only its record's names)."""

    def __init__(self, unit, rhs: str, outputs: str, held: tuple, shown: tuple, integration_step: float,
                 force_columns: tuple[str, ...]):
        self._unit, self._names, self._held, self._shown = unit, (rhs, outputs), held, shown
        self.record = plant_record(unit.manifest_entry(rhs), unit.manifest_entry(outputs))
        self.nq, self.h, self.force_columns = self.record["nq"], integration_step, force_columns

    @cached_property
    def _bound(self) -> tuple:
        """``(rhs, outputs, steps-done cell, fast entry, its binding)``, compiled on first use."""
        rhs, outputs = (self._unit.function(n) for n in self._names)
        # one state through the one-state entry point (a sample's reading in about a microsecond)
        return (rhs, outputs, self._unit.module.ffi.new("int *"), *outputs.fast_bind(1, *self._shown))

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place, writing each step's state to ``trajectory``; steps done."""
        rhs, _, done, _, _ = self._bound
        rhs.integrate(x, tau, *self._held, h=self.h, nsteps=nsteps, trajectory=trajectory, done=done)
        return done[0]

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The output record of each state, in one native call."""
        states = np.ascontiguousarray(states)
        out = np.empty((len(states), len(self.record["outputs"])))
        # a partial run's last states may be non-finite: their records are kept as they come
        self._bound[1].batch_into(states, *self._shown, out, status=np.empty(len(states), dtype=np.intc))
        return out

    def _record_row(self, x: np.ndarray) -> np.ndarray:
        _, _, _, fast, binding = self._bound
        row = fast(binding, 0, x)
        # off the fast path (a non-finite state): the record as the batch gives it
        return self.outputs(x[None, :])[0] if row is None else row
