"""The compiled step's numbers held by a controller, checked against their declarations.

Each number the step reads has a declared check (:data:`hybrid.spec.interfaces.CHECKS`, on the ports of
:data:`hybrid.spec.controller_step.CONTROLLER_STEP`); the standalone C checks the same at each sample. A
controller checks its numbers when they are set, and the settings a sample reads in Python (the sample time,
the timing and singular tolerances) at the sample, since they may change between samples.
"""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.spec.controller_step import CONTROLLER_STEP, SETTING_CHECKS
from hybrid.spec.interfaces import CHECKS, Dims
from hybrid.validate import shown


class CheckedParameters:
    """The checks of a controller's step numbers (its ``_params``, sized by its ``_dims``)."""

    _dims: Dims
    _params: tuple[np.ndarray, ...]
    sample_time: float
    timing_tolerance: float | None
    singular_tol: float

    def _checked_parameters(self, values: dict) -> tuple:
        """The step's parameters packed from ``values``, each refused unless its declared check allows it
        (:data:`hybrid.spec.interfaces.CHECKS`: the standalone C checks the same at each sample), then
        read-only: they change only through this check."""
        params = CONTROLLER_STEP.pack(values, self._dims)
        refused = CONTROLLER_STEP.refused(params, self._dims, self.sample_time)
        if refused:
            port, element, value, valid = refused[0]
            raise HybridError(f"the step's {port} {element} = {shown(value)}; give {valid}"
                              + (f" ({len(refused) - 1} more refused)" if len(refused) > 1 else ""))
        for p in params:
            p.flags.writeable = False
        return params

    def _refused_setting(self) -> tuple[str, object, str] | None:
        """The first of the settings a sample reads here (the sample time, the timing and singular
        tolerances) that its declared check refuses, as ``(name, value, what is valid)``, or a step's
        number whose check reads the sample time and refuses it at this one (a filter cutoff at or above
        Nyquist, a fault reaction's stop_time under two sample times), as the standalone C refuses its
        struct's. (The sample clock is the controller's own, only ever a finite ``t`` it served.)"""
        T = self.sample_time
        if not CHECKS["positive"].valid(T, T):
            return "sample_time", T, CHECKS["positive"].meaning
        refused = CONTROLLER_STEP.refused(self._params, self._dims, T)
        if refused:
            port, element, value, valid = refused[0]
            return f"the step's {port} {element} at sample_time = {T:g} s", value, valid
        settings = {"timing_tolerance": -1.0 if self.timing_tolerance is None else self.timing_tolerance,
                    "singular_tol": self.singular_tol}
        for name, check in SETTING_CHECKS.items():
            if not CHECKS[check].valid(settings[name], T):
                return name, getattr(self, name), CHECKS[check].meaning
        return None
