"""A part's placement: its points moved by a rigid transform given as a 4 x 4 homogeneous matrix, whose rotation
is taken within its numbers' rounding and made orthonormal (a rotation in single precision is one only to about
1e-7); a scale, a shear or a reflection is refused."""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.validate import shown

#: how far a transform's rotation may be from orthonormal (``|R^T R - I|``), in its numbers' machine epsilon,
#: and at least (a rotation in single precision's digits, read as doubles)
ROUNDING, ROUNDING_DOUBLE = 100, 1e-6


def placed(v: np.ndarray, transform, what: str) -> np.ndarray:
    """``v`` (V x 3) moved by the rigid ``transform`` (4 x 4; None: as it is), its rotation re-orthonormalised
    (:func:`_rotation`)."""
    if transform is None:
        return v
    try:
        given = np.asarray(transform)
        T = given.astype(float)
    except (TypeError, ValueError):
        T = None
    if T is None or T.shape != (4, 4) or not np.isfinite(T).all():
        raise HybridError(f"{what}.transform = {shown(transform, 60)}; give the part's frame in the base as a 4 x 4 "
                          "homogeneous matrix")
    R = _rotation(T, given.dtype, what)
    if v.ndim != 2 or v.shape[1:] != (3,):
        return v  # checked_mesh says what is wrong
    return v @ R.T + T[:3, 3]


def _rotation(T: np.ndarray, dtype, what: str) -> np.ndarray:
    """The rotation of the homogeneous ``T`` made orthonormal to double precision (the nearest rotation: ``U V^T``
    of its singular value decomposition). Its numbers' rounding is allowed for: ``R^T R`` within
    :data:`ROUNDING` machine epsilons of ``dtype`` of the identity, and at least :data:`ROUNDING_DOUBLE` (a
    rotation in single precision's 7 digits, read from a file as doubles). Refused beyond: a scale, a shear, a
    reflection, a last row that is not ``0 0 0 1``."""
    floating = np.issubdtype(dtype, np.floating)
    if floating and np.finfo(dtype).eps > np.finfo(np.float32).eps:
        raise HybridError(f"{what}.transform is in {np.dtype(dtype).name}; give it in single or double precision")
    tolerance = max(ROUNDING_DOUBLE, ROUNDING * float(np.finfo(dtype if floating else float).eps))
    R = T[:3, :3]
    off = float(np.abs(R.T @ R - np.eye(3)).max())
    row = float(np.abs(T[3] - (0.0, 0.0, 0.0, 1.0)).max())
    turned = np.linalg.det(R) <= 0
    if off > tolerance or row > tolerance or turned:
        raise HybridError(f"{what}.transform is not a rigid motion (a rotation and a translation, last row 0 0 0 1): "
                          f"R^T R is {off:.2g} from the identity, its last row {row:.2g} from 0 0 0 1 (at most "
                          f"{tolerance:.2g}, its numbers' rounding){', a reflection' if turned else ''}; give scale "
                          "for a change of units")
    U, _, Vt = np.linalg.svd(R)
    return U @ Vt
