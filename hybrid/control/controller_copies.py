"""A :class:`~hybrid.Controller` copied or pickled: built again from what it was built from, then given its run.

A controller's compiled step, its binding and the views into its buffers belong to one object in one process:
they do not copy. A copy (``copy.copy``, ``copy.deepcopy``, ``pickle``) is therefore a controller built anew, by
the constructor, from the same robot, surface, scheme, task axes, selection and settings, so its buffers are its
own, and then given the state of the run: the loops' integrals, the torque last written, the sensor's filter, the
estimate, the sample clock, the fault reaction's state, a path task's progress, the step's numbers as they stand
(a path task's turn of ``e`` and its retreat, a part's expansion, a sensor set since) and the attributes as they
are now (a sample time or tolerance changed). On the same samples it gives the same torques, bit for bit, and
the two run on independently.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hybrid.control.step_checks import FIXED_BOUNDS
from hybrid.errors import HybridError


def rebuilt(cls: type, args: tuple, kwargs: dict[str, Any]):
    """``cls(*args, **kwargs)``: a copy's controller, built as a user builds one (what ``__reduce__`` names)."""
    return cls(*args, **kwargs)


class CopiedRun:
    """The copy and pickle protocol of a :class:`~hybrid.Controller` (module docstring): it reads the controller's
    arguments (``robot``, ``surface``, ``scheme``, ``axes``, ``selection``, ``_settings``) and its run's state."""

    def __reduce__(self):
        # the selection by axis name: what selection_of reads back unambiguously (an index is a task axis's)
        selection = tuple(name for name, chosen in zip(self.axis_names, self.selection) if chosen)
        keywords = {"axes": self.axes, "selection": selection, **self._settings}
        return rebuilt, (type(self), (self.robot, self.surface, self.scheme), keywords), self._run()

    def _run(self) -> dict[str, Any]:
        """The state of the run, as :meth:`__setstate__` takes it (arrays that :meth:`__setstate__` copies from)."""
        follower = None if self._path_task is None else self._path_task.follower
        outputs = getattr(self, "_out", None)  # the last sample's outputs (``last``), once the step is built
        # the settings as they are now: the public attributes, and the sample time (a property: it writes the step's)
        # (not the fixed bounds: the constructor gave the copy the same)
        attributes = ({k: v for k, v in vars(self).items() if not k.startswith("_") and k not in FIXED_BOUNDS}
                      | {"sample_time": self.sample_time})
        return {"attributes": attributes,
                "held": self._held, "params": self._params, "start_params": self._start_params,
                "clock": self._clock, "checked_settings": self._checked_settings, "sampled": self._sampled,
                "fault": self._fault.state,
                "path": None if follower is None else (follower.state, follower.served),
                "outputs": outputs}

    def __setstate__(self, run: dict[str, Any]) -> None:
        """Take over the run of the controller this one copies (built from the same arguments by :func:`rebuilt`);
        values are copied into this controller's own buffers, so a shallow copy shares none of them."""
        mine = [self._held, [self._fault.state], self._params]
        if _shapes(mine) != _shapes([run["held"], [run["fault"]], run["params"]]):
            raise HybridError("this controller's run does not fit the controller built from its settings (a pickle "
                              "written by another version of hybrid?); build it again: Controller(robot, surface, "
                              "scheme, tracking=..., limits=..., sensing=...) from the old one's records")
        for held, saved in zip(self._held, run["held"], strict=True):
            held[...] = saved
        for params in (run["params"], run["start_params"]):
            for a in params:  # the step's numbers change only by replacement, after their checks
                a.flags.writeable = False
        self._params, self._start_params = run["params"], run["start_params"]
        for name, value in run["attributes"].items():  # after the numbers: the sample time writes its own there
            setattr(self, name, value)
        self._clock, self._checked_settings, self._sampled = run["clock"], run["checked_settings"], run["sampled"]
        self._fault.state[...] = run["fault"]
        if run["path"] is not None:
            follower = self._path_task.follower
            follower.state[...], follower.served[...] = run["path"]
        if run["outputs"] is not None:  # the step was built: built here too (bound to the numbers just taken)
            self._native()
            for out, saved in zip(self._out, run["outputs"], strict=True):
                out[...] = np.asarray(saved)


def _shapes(groups: list) -> list[list[tuple[int, ...]]]:
    """The shapes of the arrays in each of ``groups``: a run fits a controller where they are the same."""
    return [[np.shape(a) for a in group] for group in groups]
