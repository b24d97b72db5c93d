"""A robot's base parameters identified from measured joint torques by ordinary least squares.

The dynamics are linear in the base parameters (:func:`hybrid.base_parameters`): at each of N samples
``tau_k = Y_b(q_k, q'_k, q''_k) pi_b``. Stacked, ``W pi_b = t`` (``W``: ``N n`` rows, one column per
base parameter) is solved by least squares through ``W``'s singular value decomposition; the residual's
variance ``sigma^2 = |t - W pi_b|^2 / (N n - p)`` gives the estimate's covariance ``sigma^2 (W^T W)^-1``
(independent torque errors of one variance, the model exact). A trajectory that does not excite every
base parameter leaves ``W`` rank deficient: the parameters of its singular directions are refused by
name rather than given an arbitrary value.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.base_parameters import BaseParameters, base_parameters
from hybrid.models.regressor import linear_parameters, regressor
from hybrid.models.robot import Robot, as_robot
from hybrid.validate import shown

#: a singular value of the stacked base regressor below this fraction of the largest is a direction the
#: data did not excite (rounding leaves about 1e-16; a parameter excited at all is far above 1e-8)
UNEXCITED = 1e-8
#: a base parameter is named as not excited when this much of it (the norm of its unit vector's
#: projection on the singular directions) lies in them
UNEXCITED_SHARE = 0.1


@dataclass(frozen=True)
class DynamicsIdentification:
    """What :func:`identify_dynamics` found: the base parameters ``pi_b`` of ``tau = Y_b pi_b``.

    Parameters
    ----------
    robot : Robot
        The arm identified (its structure and gravity give the regressor; its own parameters are the
        nominal model).
    base : BaseParameters
        The base parameters (:func:`hybrid.base_parameters`); ``base.base_names()`` says which
        combination of :func:`hybrid.linear_parameters` each stands for.
    names : tuple of str
        Each base parameter by the parameter of ``pi`` it is kept for (``base.independent``'s names).
    estimate : numpy.ndarray
        The base parameters' least-squares estimate (SI units of ``pi``).
    std : numpy.ndarray
        Their standard deviations, from the residual's variance and ``(W^T W)^-1`` (NaN where the fit
        leaves no residual: a one-joint arm with exactly as many samples as base parameters).
    nominal : numpy.ndarray
        The base parameters of the robot's own model, ``base.of(linear_parameters(robot))``.
    residual_rms : numpy.ndarray
        The RMS over the samples of the torque the fit leaves unexplained, per joint [N m or N].
    condition : float
        The condition number of the stacked base regressor ``W``.
    samples : int
        How many samples the fit used.

    Examples
    --------
    See :func:`identify_dynamics`, which makes one.

    >>> import hybrid
    >>> hybrid.DynamicsIdentification.__name__
    'DynamicsIdentification'
    """

    robot: Robot
    base: BaseParameters
    names: tuple[str, ...]
    estimate: np.ndarray
    std: np.ndarray
    nominal: np.ndarray
    residual_rms: np.ndarray
    condition: float
    samples: int

    def torque(self, q, qd, qdd) -> np.ndarray:
        """The joint torques the identified model predicts, ``Y_b(q, q', q'') pi_b``.

        Parameters
        ----------
        q, qd, qdd : array_like
            Joint positions, velocities and accelerations, one per joint; or ``(N, n)`` each.

        Returns
        -------
        numpy.ndarray
            ``(n,)``, or ``(N, n)`` for N states [N m or N].

        Raises
        ------
        HybridError
            A state of the wrong size or not finite.
        """
        Y, _ = regressor(self.robot, q, qd, qdd)
        return self.base.regressor(Y) @ self.estimate


def _samples(name: str, value, n: int) -> np.ndarray:
    """``value`` as an ``(N, n)`` array of finite numbers."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise HybridError(f"{name} = {shown(value, 60)}; give an (N, {n}) array of numbers, one row per sample") \
            from None
    if arr.ndim != 2 or arr.shape[1] != n:
        raise HybridError(f"{name} has shape {arr.shape}; give an (N, {n}) array, one row of {n} joint values per "
                          "sample")
    if not np.isfinite(arr).all():
        k, j = np.argwhere(~np.isfinite(arr))[0]
        raise HybridError(f"{name}[{k}, {j}] = {arr[k, j]}; give finite numbers (drop the samples where the "
                          "measurement failed)")
    return arr


def unexcited(W: np.ndarray, names, below: float = UNEXCITED) -> tuple[str, ...]:
    """The ``names`` of ``W``'s columns that lie in its singular directions (relative singular value
    below ``below``, default :data:`UNEXCITED`): the parameters the data cannot tell from combinations of
    the others (with a larger ``below``: those they tell apart worst)."""
    _, s, Vt = np.linalg.svd(W, full_matrices=True)
    s = np.concatenate([s, np.zeros(W.shape[1] - len(s))])  # fewer rows than columns: those directions too
    null = Vt[s < below * max(s[0], np.finfo(float).tiny)]
    share = np.linalg.norm(null, axis=0)
    return tuple(name for name, x in zip(names, share) if x > UNEXCITED_SHARE)


def identify_dynamics(robot: Robot, q, qd, qdd, tau) -> DynamicsIdentification:
    """The base parameters of ``robot`` that fit measured joint torques, by ordinary least squares.

    Parameters
    ----------
    robot : Robot
        The arm: its structure and gravity give the regressor, its parameters the nominal model the
        estimate is reported beside.
    q, qd, qdd : array_like
        ``(N, n)`` each: the joint positions, velocities and accelerations of N samples (a trajectory
        that moves every joint over its range, with varied speeds and accelerations).
    tau : array_like
        ``(N, n)``: the joint torques measured at those samples [N m or N].

    Returns
    -------
    DynamicsIdentification
        The estimate, its standard deviations, the residual and the conditioning.

    Raises
    ------
    HybridError
        Arrays of the wrong shape or different lengths, not finite, fewer samples than base parameters, or
        samples that do not excite every base parameter (named).

    Examples
    --------
    Torques of the UR5's own model at random states give back its base parameters:

    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> rng = np.random.default_rng(0)
    >>> q, qd, qdd = rng.uniform(-3, 3, (100, 6)), rng.normal(0, 1, (100, 6)), rng.normal(0, 1, (100, 6))
    >>> Y, _ = hybrid.regressor(robot, q, qd, qdd)
    >>> found = hybrid.identify_dynamics(robot, q, qd, qdd, Y @ hybrid.linear_parameters(robot))
    >>> bool(np.allclose(found.estimate, found.nominal))
    True
    >>> bool(np.allclose(found.torque(q[0], qd[0], qdd[0]), Y[0] @ hybrid.linear_parameters(robot)))
    True
    """
    robot = as_robot(robot)
    n = robot.n
    arrays = {name: _samples(name, value, n) for name, value in (("q", q), ("qd", qd), ("qdd", qdd), ("tau", tau))}
    lengths = {name: len(a) for name, a in arrays.items()}
    if len(set(lengths.values())) > 1:
        raise HybridError(f"q, qd, qdd and tau have {', '.join(map(str, lengths.values()))} samples; give one row "
                          "of each per sample, all the same length")
    base = base_parameters(robot)
    p, N = len(base.independent), lengths["q"]
    names = tuple(base.names[i] for i in base.independent)
    if N < p:
        raise HybridError(f"{N} samples for {p} base parameters; give at least {p} samples, several times as many "
                          "for a precise estimate")
    Y, _ = regressor(robot, arrays["q"], arrays["qd"], arrays["qdd"])
    W, t = base.regressor(Y).reshape(N * n, p), arrays["tau"].reshape(N * n)
    U, s, Vt = np.linalg.svd(W, full_matrices=False)
    if s[-1] < UNEXCITED * s[0]:
        missing = unexcited(W, names)
        raise HybridError(f"the samples do not excite the base parameters {', '.join(missing)}; excite the arm more "
                          "(a richer trajectory: every joint over its range, varied speeds and accelerations)")
    estimate = Vt.T @ ((U.T @ t) / s)
    residual = (t - W @ estimate).reshape(N, n)
    dof = N * n - p  # at least p (n - 1) >= 0; a one-joint arm with N = p fits exactly and has none
    variance = float(residual.ravel() @ residual.ravel()) / dof if dof > 0 else float("nan")
    std = np.sqrt(variance * ((Vt.T / s) ** 2).sum(axis=1))
    rms, nominal = np.sqrt((residual**2).mean(axis=0)), base.of(linear_parameters(robot))
    for a in (estimate, std, rms, nominal):
        a.setflags(write=False)
    return DynamicsIdentification(robot, base, names, estimate, std, nominal, rms, float(s[0] / s[-1]), N)
