"""Where a serial chain's joint frames are, in NumPy: the origins a picture of the arm draws its links through.

The generated C computes the tip's kinematics (``r``, its rotation, ``J``) but no intermediate frame; a
picture needs every joint's origin. They follow from the :class:`~hybrid.spec.chain.Chain` the C is
generated from, by the same composition (``codegen.rigid_body.forward_kinematics``): each joint's
origin is its parent's frame moved by the joint's fixed translation; a revolute joint turns the frame
about its axis, a prismatic one slides its origin along it. The tests hold the last origin plus the
tip offset equal to the tip the generated C computes.
"""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.spec.chain import Chain


def _turns(axis: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """``Rot(axis, angle)`` for each angle (Rodrigues), shape ``(N, 3, 3)``."""
    k = axis / np.linalg.norm(axis)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    c, s = np.cos(angles)[:, None, None], np.sin(angles)[:, None, None]
    return np.eye(3) + s * K + (1.0 - c) * (K @ K)


def joint_frames(chain: Chain, q) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The frames of ``chain`` at the joint positions ``q`` (one state, ``(n,)``, or N states, ``(N, n)``).

    Returns ``(origins, rotations, tip, tip_rotation)`` in base axes [m]: the base's origin then
    each moving joint's, ``(n + 1, 3)`` (``(N, n + 1, 3)`` for N states); each joint frame's
    rotation after its joint's motion, ``(n, 3, 3)``; the tip frame's origin ``r`` ``(3,)`` and
    rotation ``(3, 3)`` (with a leading ``N`` for N states).
    """
    q = np.asarray(q, dtype=float)
    one = q.ndim == 1
    Q = np.atleast_2d(q)
    if Q.ndim != 2 or Q.shape[1] != chain.n:
        raise HybridError(f"q has shape {np.shape(q)}; give the chain's {chain.n} joint positions "
                          "(one state) or one row of them per state")
    N = len(Q)
    R = np.broadcast_to(np.eye(3), (N, 3, 3)).copy()
    p = np.zeros((N, 3))
    origins, rotations = [p], []
    for i, joint in enumerate(chain.joints):
        p = p + R @ np.asarray(joint.translation)
        R = R @ np.asarray(joint.rotation)
        axis = np.asarray(joint.axis, float)
        if joint.kind == "revolute":
            R = R @ _turns(axis, Q[:, i])
        else:  # prismatic: the origin slides along the axis (in the joint's frame before its motion)
            p = p + (R @ axis) * Q[:, i:i + 1]
        origins.append(p)
        rotations.append(R)
    tip = p + R @ np.asarray(chain.tip_translation)
    tip_rotation = R @ np.asarray(chain.tip_rotation)
    out = np.stack(origins, axis=1), np.stack(rotations, axis=1), tip, tip_rotation
    return tuple(x[0] for x in out) if one else out
