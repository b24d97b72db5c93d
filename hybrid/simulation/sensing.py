"""The plant's sensor as the controller reads it: a force/torque sensor's raw reading, a finite
bandwidth, a bias, noise and a delay (conventions §14).

At each control sample ``k`` the plant's elastic sensor gives the wrench ``F_k`` on the robot at the
tip (base axes). The controller is given

1. ``w_k``: ``F_k`` itself, or, when the experiment has a ``wrench_sensor`` (the true one), the raw
   reading that sensor gives for ``F_k`` at the true arm's tip pose (:func:`~hybrid.control.wrench_sensor.reading_of`:
   sensor axes, its sign, its bias and the tool's weight at the current orientation);
2. ``y_k = a y_(k-1) + (1 - a) w_k``, ``a = exp(-2 pi f_b T)``: a first-order lag of corner frequency
   ``f_b`` discretised at the sample time ``T`` (the continuous lag's value at the samples when the
   reading over each sample period is the one read at its end), started at ``y_0 = w_0`` (at rest
   before the run);
3. ``m_k = y_k + b + sigma * n_k``: the bias ``b`` and white Gaussian noise, ``n_k`` standard normal per
   component from the seeded generator, ``sigma`` the force's standard deviation on the force
   components and the moment's on the moments;
4. the delay: at sample ``k`` the controller gets ``m_max(k - d, 0)``;
5. a dropout: from the sensor's ``dropout_at`` for ``dropout_duration`` (``k T`` in that window) the
   controller gets NaN, which it refuses: its fault reaction acts, and the run applies each faulted
   sample's torque.

:class:`SensorSignal` is steps 2-4 on any sequence of readings; :func:`plant_reader` builds the whole
chain for an experiment's runs, or says there is none (the controller then gets ``F_k`` as before).
"""

from __future__ import annotations

from collections import deque

import numpy as np

from hybrid.control.wrench_sensor import reading_of
from hybrid.models.chain_terms import robot_terms
from hybrid.plants.contact import Sensor, lag_pole


class SensorSignal:
    """Steps 2-4 of the module docstring (lag, bias, noise, delay) on readings given one sample at a
    time: ``signal(w)`` returns what the controller gets at this sample. A new object starts afresh
    (the lag at its first reading, the delay line empty, the noise at its seed)."""

    def __init__(self, sensor: Sensor, sample_time: float):
        if not isinstance(sensor, Sensor):
            raise TypeError(f"a SensorSignal needs a hybrid.Sensor, got {type(sensor).__name__}")
        sensor.check_sampling(sample_time)
        #: the lag's pole ``a`` (0: no lag)
        self.pole = float(lag_pole(sensor.bandwidth_hz, sample_time))
        self.bias = np.array(sensor.bias)
        self.scale = np.repeat([sensor.force_noise, sensor.moment_noise], 3)
        self.delay = sensor.delay_samples
        self._noisy = bool(self.scale.any())
        self._sensor, self._T, self._k = sensor, sample_time, 0
        self._rng = np.random.default_rng(sensor.seed)
        self._lagged: np.ndarray | None = None
        self._line: deque = deque()

    def __call__(self, reading) -> np.ndarray:
        w = np.asarray(reading, float)
        if self._lagged is None or self.pole == 0.0:
            self._lagged = w.copy()
        else:
            self._lagged = self.pole * self._lagged + (1.0 - self.pole) * w
        m = self._lagged + self.bias
        if self._noisy:
            m = m + self.scale * self._rng.standard_normal(6)
        self._line.append(m)
        if len(self._line) > self.delay + 1:
            self._line.popleft()
        t, self._k = self._k * self._T, self._k + 1
        return np.full(6, np.nan) if self._sensor.dropped(t) else self._line[0].copy()


def plant_reader(exp, plant):
    """``read(x) -> reading`` for the runs of ``exp`` on ``plant``: what the controller is given at a
    sample whose plant state is ``x`` (steps 1-4 of the module docstring), one call per sample in order;
    None when that is the plant's own ``sensor_wrench(x)`` (no wrench sensor, every signal option off)."""
    sensor, true = exp.sensor, exp.wrench_sensor
    if sensor.ideal and true is None:
        return None
    signal = SensorSignal(sensor, exp.sample_time)
    robot, n = exp.robot, plant.nq
    gravity = np.array(robot.gravity)

    def read(x: np.ndarray) -> np.ndarray:
        F = plant.sensor_wrench(x)
        if true is not None:
            terms = robot_terms(robot, x[:n], x[n:2 * n])
            F = reading_of(true, F, terms["r"], terms["rotation"], gravity, robot)
        return signal(F)

    return read
