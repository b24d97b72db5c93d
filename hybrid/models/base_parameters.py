"""A robot's base parameters: the combinations of ``pi`` that the joint torques determine.

Not every parameter of ``tau = Y(q, q', q'') pi`` (:func:`hybrid.regressor`) changes the torques:
some columns of ``Y`` are zero at every state (a parameter without effect) and some are combinations
of others (two parameters whose effects cannot be told apart). Stacked over many random states,
``Y``'s independent columns are found numerically by a rank-revealing QR factorisation taken column by
column in ``pi``'s order (a column kept unless it is a combination of those kept before it: the
choice is then the structure's, not the states'); each other column is ``Y_1 beta_j``, so
``Y pi = Y_1 (pi_1 + beta pi_2)`` and the base parameters ``pi_1 + beta pi_2`` are what data can
identify.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.regressor import regressor
from hybrid.models.robot import Robot, as_robot
from hybrid.validate import checked_keywords

#: a column whose part independent of the columns kept is below this fraction of the largest column's
#: norm depends on them (rounding leaves about 1e-16; an independent part is a few hundredths)
DEPENDENT_TOL = 1e-10


@checked_keywords
@dataclass(frozen=True)
class BaseParameters:
    """The base parameters of ``tau = Y pi``: ``pi_b = pi[independent] + beta @ pi[dependent]``, with
    ``tau = Y[:, independent] @ pi_b`` (see :func:`base_parameters`).

    Parameters
    ----------
    names : tuple of str
        The names of ``pi`` (:func:`hybrid.regressor`'s).
    independent : tuple of int
        The columns of ``Y`` kept, in ``pi``'s order.
    dependent : tuple of int
        The other columns, in ``pi``'s order.
    beta : numpy.ndarray
        ``(len(independent), len(dependent))``: ``Y[:, dependent] = Y[:, independent] @ beta`` at every
        state (a column of zeros: a parameter without effect on the torques).

    Examples
    --------
    >>> import hybrid
    >>> base = hybrid.base_parameters(hybrid.ur5())
    >>> len(base.independent) + len(base.dependent) == len(base.names)
    True
    """

    names: tuple[str, ...]
    independent: tuple[int, ...]
    dependent: tuple[int, ...]
    beta: np.ndarray

    def base_names(self) -> tuple[str, ...]:
        """Each base parameter as the combination of ``pi`` it stands for, in words.

        Returns
        -------
        tuple of str
            ``"name + c * other + ..."`` per base parameter.
        """
        out = []
        for row, i in enumerate(self.independent):
            terms = [self.names[i]] + [f"{b:+.6g} * {self.names[j]}" for b, j in zip(self.beta[row], self.dependent)
                                        if b != 0.0]
            out.append(" ".join(terms))
        return tuple(out)

    def of(self, pi) -> np.ndarray:
        """The base parameters of the parameters ``pi`` (:func:`hybrid.linear_parameters`'s).

        Parameters
        ----------
        pi : array_like
            ``len(names)`` numbers.

        Returns
        -------
        numpy.ndarray
            ``pi[independent] + beta @ pi[dependent]``.
        """
        pi = np.asarray(pi, dtype=float)
        if pi.shape != (len(self.names),):
            raise HybridError(f"pi has shape {pi.shape}; give the {len(self.names)} parameters of the regressor")
        return pi[list(self.independent)] + self.beta @ pi[list(self.dependent)]

    def regressor(self, Y) -> np.ndarray:
        """The base regressor: the independent columns of ``Y`` (one state's or N states').

        Parameters
        ----------
        Y : array_like
            ``(..., n, len(names))``, as :func:`hybrid.regressor` gives it.

        Returns
        -------
        numpy.ndarray
            ``Y[..., independent]``: ``tau = Y_b @ of(pi)``.
        """
        return np.asarray(Y)[..., list(self.independent)]


def _states(robot: Robot, rng, count: int):
    """``count`` random states: positions within the joint limits (within a turn where there are none)."""
    lower, upper = np.full(robot.n, -np.pi), np.full(robot.n, np.pi)
    if robot.limits is not None:
        finite = np.isfinite(robot.limits.lower) & np.isfinite(robot.limits.upper)
        lower[finite], upper[finite] = robot.limits.lower[finite], robot.limits.upper[finite]
    return (rng.uniform(lower, upper, (count, robot.n)), rng.normal(0, 1, (count, robot.n)),
            rng.normal(0, 1, (count, robot.n)))


def independent_columns(W: np.ndarray, tol: float = DEPENDENT_TOL) -> list[int]:
    """The columns of ``W`` a QR factorisation kept in order keeps: each column whose part orthogonal to
    the columns kept before it is above ``tol`` times the largest column's norm (the parts of the others
    are rounding, about 1e-16 of it). Taken in ``pi``'s order, the choice is the structure's: a
    parameter is kept unless it is a combination of those before it, at any states (almost surely)."""
    scale = np.linalg.norm(W, axis=0).max(initial=0.0)
    basis = np.zeros((W.shape[0], 0))
    kept: list[int] = []
    for j in range(W.shape[1]):
        w = W[:, j].astype(float)
        for _ in range(2):  # orthogonalised twice: Gram-Schmidt's rounding made negligible
            w = w - basis @ (basis.T @ w)
        rest = np.linalg.norm(w)
        if rest > tol * scale:
            basis = np.column_stack([basis, w / rest])
            kept.append(j)
    return kept


@checked_keywords
def base_parameters(robot: Robot, *, states: int = 200, seed: int = 0) -> BaseParameters:
    """The base parameters of ``robot``'s ``tau = Y pi``, from ``Y`` stacked over random states.

    A parameter is kept unless its column of ``Y`` is a combination of those of the parameters before
    it in ``pi`` (or zero): which are kept depends on the structure and gravity's direction only, and
    the combinations are exact to rounding (a column that is a combination of others at ``states``
    random states is one at every state, almost surely).

    Parameters
    ----------
    robot : Robot
        The arm (its structure and gravity).
    states : int
        How many random states ``Y`` is stacked over (positions within the joint limits, velocities and
        accelerations standard normal); enough that ``states * n`` is well above ``len(pi)``.
    seed : int
        The random states' seed.

    Returns
    -------
    BaseParameters
        The columns kept, the others and their combinations.

    Raises
    ------
    HybridError
        ``robot`` is not a robot, or too few states.

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> base = hybrid.base_parameters(robot)
    >>> q = [0.3, -1.2, 1.4, 0.2, 1.1, -0.4]
    >>> qd, qdd = [0.5] * 6, [1.0] * 6
    >>> Y, _ = hybrid.regressor(robot, q, qd, qdd)
    >>> pi = hybrid.linear_parameters(robot)
    >>> bool(np.allclose(base.regressor(Y) @ base.of(pi), Y @ pi))
    True
    """
    robot = as_robot(robot)
    if isinstance(states, bool) or not isinstance(states, (int, np.integer)) or states * robot.n < 11 * robot.n:
        raise HybridError(f"states = {states!r}; give a whole number of at least 11 (the regressor has 11 columns "
                          "per joint), a few hundred to be safe")
    Y, names = regressor(robot, *_states(robot, np.random.default_rng(seed), int(states)))
    W = Y.reshape(-1, Y.shape[-1])
    kept = independent_columns(W)
    others = [j for j in range(W.shape[1]) if j not in kept]
    beta = np.linalg.lstsq(W[:, kept], W[:, others], rcond=None)[0] if others else np.zeros((len(kept), 0))
    beta[np.abs(beta) < 1e-12] = 0.0  # rounding of an exact zero
    beta.setflags(write=False)
    return BaseParameters(names, tuple(kept), tuple(others), beta)
