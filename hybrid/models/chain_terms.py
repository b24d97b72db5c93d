"""The terms of a robot's chain from its generated C: ``r``, ``rotation``, ``J``, ``J' q'``, ``B``, ``n``.

One state through the one-state entry point bound to the robot's parameters (robots are immutable, so a
binding serves every call), or N states in one native call.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from hybrid.native.binding import is_batch

_ROBOT_KEYS = {"p": "r", "rotation": "rotation", "J": "J", "Jdqd": "Jdot_qdot", "B": "B", "n": "n"}


@lru_cache(maxsize=256)
def _fast_terms(robot):
    """``(call, binding, output names)`` of ``robot_terms`` bound to ``robot``'s parameters (the
    one-state entry point); robots are immutable, so a binding serves every call."""
    fn = robot.unit.function("robot_terms")
    return (*fn.fast_bind(2, robot.as_array()), tuple(n for n, _, _ in fn.outputs))


def robot_terms(robot, q, qdot) -> dict[str, np.ndarray]:
    """``r``, ``rotation``, ``J``, ``Jdot_qdot``, ``B``, ``n`` of ``robot`` (see :func:`hybrid.arm_terms`):
    one state, or N states in one native call."""
    fast, handle, names = _fast_terms(robot)
    out = fast(handle, -1, q, qdot)
    if out is not None:
        return {_ROBOT_KEYS[n]: v for n, v in zip(names, out)}
    terms = robot.unit.function("robot_terms")
    call = terms.batch if is_batch(q) else terms
    out = call(q, qdot, robot.as_array())
    return {_ROBOT_KEYS[k]: v for k, v in out.items()}
