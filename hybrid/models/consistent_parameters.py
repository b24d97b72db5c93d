"""Physically consistent parameters: the full ``pi`` that fits the torques best with every link a rigid body.

Least squares gives the base parameters (:func:`hybrid.identify_dynamics`), and nothing keeps them
physical: with noise or a poor excitation a link's mass may come out negative, or its inertia one no body
has. Here the full ``pi`` (:func:`hybrid.linear_parameters`'s) minimises

``|R (B pi - pi_b)|^2 / s^2 + PRIOR_WEIGHT * P(pi)``

subject to, for each link, its pseudo-inertia ``J = [[0.5 tr(I_O) 1 - I_O, h], [h^T, m]]`` (``h = m c``)
being positive definite, ``J >= MARGIN * S`` (``J`` is the second moment of the link's mass distribution,
``[[int r r^T dm, int r dm], [int r^T dm, m]]``, positive semi-definite exactly when a body of nonnegative
density has those ``m``, ``h``, ``I_O``: Wensing, Kim and Slotine, IEEE RA-L 2018), and the viscous and
Coulomb frictions ``>= 0``: a convex semidefinite program (cvxpy, solved by Clarabel).

- **The data term does not grow with the log.** ``R`` is the triangular factor of the stacked base
  regressor (``W_b = Q R``, so ``R^T R = W_b^T W_b``: a Cholesky factor, ``p x p``) and ``pi_b`` its
  least-squares estimate; ``|W_b B pi - t|^2 = |R (B pi - pi_b)|^2 + |t - W_b pi_b|^2``, where ``B`` maps
  ``pi`` to its base parameters. ``s^2`` is the estimate's residual variance per row: a base parameter
  moved by one standard deviation costs 1. It is at least :data:`NOISE_FLOOR` squared times the
  torques' sum of squares (for exact data, a simulation's: the program's numbers then span a range its
  solver resolves).
- **The prior fixes what the data cannot see.** ``P`` is the squared distance from the robot's nominal
  (URDF) parameters: each link's pseudo-inertia difference scaled by its size ``S = diag(m l^2, m l^2,
  m l^2, m)`` (nominal mass; ``l`` the RMS distance of its mass from the joint frame's origin), each
  friction parameter by the torque it could explain (the joint's RMS torque over its RMS speed for a
  viscosity, its RMS torque for a Coulomb friction or an offset). Its weight :data:`PRIOR_WEIGHT` makes
  a link 100 % off its nominal cost a tenth of a standard deviation: the base parameters move from the
  data's best by well under their standard deviations, and the directions of ``pi`` the torques do not
  depend on (the parameters' combinations that are not base parameters) take the nominal's values as
  nearly as the constraints allow.
"""

from __future__ import annotations

import warnings

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.base_parameters import BaseParameters
from hybrid.models.regressor import LINK_PARAMETERS, NONNEGATIVE, linear_parameters
from hybrid.models.robot import Robot

#: the prior's weight against the data: a link 100 % off its nominal pseudo-inertia costs this (a base
#: parameter one standard deviation off costs 1)
PRIOR_WEIGHT = 1e-2
#: each link's pseudo-inertia is at least this share of its size ``S`` (strictly physical: a mass > 0, an
#: inertia about the centre of mass with margin to the triangle inequality)
MARGIN = 1e-6
#: the torque error per row the data term assumes at the least, as a share of the torques' root sum of squares
#: over every row (exact data)
NOISE_FLOOR = 1e-5

#: ``vec(J) = PSEUDO_INERTIA @ [m, mcx, mcy, mcz, IOxx, IOxy, IOxz, IOyy, IOyz, IOzz]``, ``J`` row by row:
#: ``[[0.5 tr(I_O) 1 - I_O, h], [h^T, m]]``
PSEUDO_INERTIA = np.zeros((16, LINK_PARAMETERS))
for (_r, _c), _terms in {
        (0, 0): {4: -0.5, 7: 0.5, 9: 0.5}, (1, 1): {4: 0.5, 7: -0.5, 9: 0.5}, (2, 2): {4: 0.5, 7: 0.5, 9: -0.5},
        (0, 1): {5: -1.0}, (0, 2): {6: -1.0}, (1, 2): {8: -1.0},
        (0, 3): {1: 1.0}, (1, 3): {2: 1.0}, (2, 3): {3: 1.0}, (3, 3): {0: 1.0}}.items():
    for _k, _v in _terms.items():
        PSEUDO_INERTIA[4 * _r + _c, _k] = PSEUDO_INERTIA[4 * _c + _r, _k] = _v


def pseudo_inertia(link_parameters) -> np.ndarray:
    """A link's pseudo-inertia ``[[0.5 tr(I_O) 1 - I_O, h], [h^T, m]]`` (4 x 4) from its 10 parameters
    of ``pi`` (``m, mcx, mcy, mcz, IOxx, IOxy, IOxz, IOyy, IOyz, IOzz``)."""
    return (PSEUDO_INERTIA @ np.asarray(link_parameters, dtype=float)).reshape(4, 4)


def base_map(base: BaseParameters) -> np.ndarray:
    """``B`` (``p x len(pi)``) with ``base.of(pi) = B @ pi``."""
    B = np.zeros((len(base.independent), len(base.names)))
    B[np.arange(len(base.independent)), list(base.independent)] = 1.0
    B[:, list(base.dependent)] = base.beta
    return B


def link_sizes(pi0: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Each link's mass scale [kg] and squared length scale [m^2] from the nominal parameters (a massless
    link takes a hundredth of the arm's mean mass and the arm's mean length)."""
    links = pi0[:LINK_PARAMETERS * n].reshape(n, LINK_PARAMETERS)
    mass = links[:, 0]
    second = np.array([np.trace(pseudo_inertia(p)[:3, :3]) for p in links])  # int |r|^2 dm
    heavy = mass > 0
    if not heavy.any():
        raise HybridError("the robot's nominal links have no mass; give a nominal model with masses (a URDF's) to "
                          "regularise the identification toward")
    mean_mass = float(mass[heavy].mean())
    length2 = np.where(heavy, second / np.where(heavy, mass, 1.0), np.nan)
    mean_length2 = float(np.nanmean(np.where(length2 > 0, length2, np.nan))) if (length2 > 0).any() else 0.01
    length2 = np.where(np.isfinite(length2) & (length2 > 1e-6 * mean_length2), length2, mean_length2)
    return np.where(heavy, mass, 1e-2 * mean_mass), length2


def link_scales(mass: np.ndarray, length2: np.ndarray) -> np.ndarray:
    """``(n, 10)``: each link parameter's scale, ``m``, ``m l`` (3) and ``m l^2`` (6), from the links'
    :func:`link_sizes`."""
    return np.column_stack([mass, *(mass * np.sqrt(length2),) * 3, *(mass * length2,) * 6])


def consistent_parameters(robot: Robot, base: BaseParameters, R: np.ndarray, estimate: np.ndarray, *,
                          noise_variance: float, rows: int, torque_rms: np.ndarray,
                          speed_rms: np.ndarray) -> np.ndarray:
    """The full ``pi`` nearest the data with every link physical (see the module's description).

    Parameters
    ----------
    robot : Robot
        The arm; its parameters are the nominal ones the prior is about.
    base : BaseParameters
        Its base parameters.
    R : numpy.ndarray
        ``(p, p)``: the triangular factor of the stacked base regressor.
    estimate : numpy.ndarray
        ``(p,)``: the base parameters' least-squares estimate.
    noise_variance : float
        The least squares' residual variance per row [(N m)^2].
    rows : int
        The rows of the stacked regressor (samples times joints).
    torque_rms, speed_rms : numpy.ndarray
        ``(n,)``: each joint's RMS torque and speed in the data (the friction parameters' scales).

    Returns
    -------
    numpy.ndarray
        ``pi``: each link's pseudo-inertia positive definite, viscous and Coulomb frictions ``>= 0``.

    Raises
    ------
    HybridError
        The solver found no solution (its status named).
    """
    import cvxpy as cp

    n, names = robot.n, base.names
    pi0 = linear_parameters(robot)
    mass, length2 = link_sizes(pi0, n)
    # the variables are pi / scale: each of order one, which the solver's accuracy needs
    link_scale = link_scales(mass, length2)
    kinds = [name.partition("[")[0] for name in names[LINK_PARAMETERS * n:]]
    joint_of = [names.index(name) % n for name in names[LINK_PARAMETERS * n:]]
    torque = np.maximum(np.asarray(torque_rms, float), 1e-12)
    speed = np.maximum(np.asarray(speed_rms, float), 1e-12)
    joint_scale = np.array([torque[j] / speed[j] if kind == "damping" else torque[j]
                            for kind, j in zip(kinds, joint_of)])
    scale = np.concatenate([link_scale.ravel(), joint_scale])
    s = np.sqrt(max(float(noise_variance), NOISE_FLOOR**2 * rows * float(np.mean(torque**2))))
    A = R @ base_map(base) * scale / s
    b = R @ estimate / s
    y = cp.Variable(len(names))
    y0 = pi0 / scale
    prior, constraints = [], []
    for i in range(n):
        size = np.sqrt(np.array([mass[i] * length2[i]] * 3 + [mass[i]]))
        # vec(S^-1/2 J S^-1/2) of the link's scaled parameters
        M = (PSEUDO_INERTIA * np.outer(1 / size, 1 / size).ravel()[:, None]) * link_scale[i]
        block = y[LINK_PARAMETERS * i:LINK_PARAMETERS * (i + 1)]
        constraints.append(cp.reshape(M @ block, (4, 4), order="C") >> MARGIN * np.eye(4))
        prior.append(M @ (block - y0[LINK_PARAMETERS * i:LINK_PARAMETERS * (i + 1)]))
    for k, kind in enumerate(kinds, start=LINK_PARAMETERS * n):
        if kind in NONNEGATIVE:
            constraints.append(y[k] >= 0)
    prior.append(y[LINK_PARAMETERS * n:] - y0[LINK_PARAMETERS * n:])
    cost = cp.sum_squares(A @ y - b) + PRIOR_WEIGHT * cp.sum_squares(cp.hstack(prior))
    problem = cp.Problem(cp.Minimize(cost), constraints)
    hint = ("check the torques' units against the URDF's (N m, N): torques far from the nominal model's scale "
            "leave the program no solution; or identify with consistent=False")
    try:
        with warnings.catch_warnings():  # an inaccurate solution is accepted: its residual is reported
            warnings.simplefilter("ignore", UserWarning)
            problem.solve(solver=cp.CLARABEL)
    except cp.error.SolverError as exc:
        raise HybridError(f"the consistent parameters' program failed ({str(exc).splitlines()[0][:80]}); {hint}") \
            from None
    if problem.status not in (cp.OPTIMAL, cp.OPTIMAL_INACCURATE) or y.value is None:
        raise HybridError(f"the consistent parameters' program ended {problem.status}; {hint}")
    return np.asarray(y.value) * scale
