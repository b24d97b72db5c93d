"""The optimisation behind :func:`hybrid.excitation_trajectory`: Fourier coefficients that make the stacked
base regressor well conditioned within joint limits and a box for the tool.

The variables are each joint's coefficients (:mod:`hybrid.models.fourier`), in a basis of those that
start and end at rest when asked. The objective is ``log cond W``, ``W`` the stacked base regressor at the
samples (the log evens its scale); its gradient is ``d log s_1 - d log s_p``, ``d log s = v^T W^T dW v /
s^2`` from the extreme eigenpairs of ``W^T W``, ``dW`` by forward differences: the regressor of all the
perturbed trajectories in batched calls. The limits are SLSQP's constraints, one per joint and kind
(position, speed, acceleration) and one per axis of the box: the values at the samples in units of their
limit are linear in the coefficients (the tool's position is not: its Jacobian is the tip's position
Jacobian, the generated C's, times the basis), and their largest, smoothed (``log sum exp``, which
overestimates it by a few per cent), is at most 1. A few smooth constraints rather than one per sample and
limit keep SQP's subproblems small.

Each linear algebra operation of the search is small and there are thousands of them: none is left to a
threaded BLAS (products by ``einsum``, two eigenpairs by LAPACK's MRRR), whose threads cost more than
they save at these sizes, many times more on a busy machine.

A solution is then made safe for all times, not only at its samples (:meth:`Design.certified`): on a
grid ten times as dense, each value's largest magnitude plus half a spacing times an analytic bound on
its rate (:func:`hybrid.models.fourier.grid_bound`) bounds it everywhere; a joint whose bound passes a
limit has its coefficients scaled down until none does (``q - q0``, ``q'``, ``q''`` scale with them).
The box is checked on a denser grid still, each point's distance to the faces less what the tool can
move in half a spacing (its velocity there, and a bound on its acceleration from the joints' bounds and
their distances to the tool along the chain); the coefficients of all joints are shrunk together until it
holds (at scale 0 the tool is at its start, inside).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import minimize

from hybrid.models import fourier
from hybrid.models.base_parameters import BaseParameters
from hybrid.models.regressor import regressor
from hybrid.models.robot import Robot
from hybrid.models.terms import arm_terms

#: the optimisation's samples times this is the grid on which a solution is checked and scored
DENSE = 10
#: a forward difference's step in the coefficients [rad/s or m/s] (they are of order 0.1 to 1)
STEP = 1e-6
#: the most bytes of the regressor of one batched call of the gradient's
CHUNK_BYTES = 2**26
#: below this condition number the Gram matrix's eigenvalues give the singular values to 1e-8 (its rounding,
#: 1e-16 of the largest eigenvalue, is 1e-8 of the smallest)
GRAM_CONDITION = 1e4
#: the smoothing of the largest of a limit's values at the samples (they are in units of the limit: the
#: smooth maximum overestimates the largest by at most 0.005 log(2 samples), a few per cent)
TEMPERATURE = 0.005
#: the points per period of the grid the box is checked on (at least the dense grid's)
BOX_GRID = 10_000
#: the box is kept by shrinking the motion by this factor at a time ...
SHRINK = 0.9
#: ... but not below this scale of it (the tool then cannot move in the box: refused)
SMALLEST_SCALE = 1e-4


@dataclass(frozen=True)
class Limits:
    """What a trajectory keeps, per joint: position bounds [rad or m] (infinite: none), speed and
    acceleration bounds (positive; speed infinite: none); and the tool's box ``(3, 2)`` [m], base axes,
    rows x, y, z, columns lower and upper (None: no box)."""

    lower: np.ndarray
    upper: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    box: np.ndarray | None


class Design:
    """The optimisation problem of one robot, limits, period, harmonics and samples: its variables are the
    coefficients ``X`` ``(n, m)`` in the basis ``N`` ``(2 K, m)`` (``(a_i, b_i) = N X_i``)."""

    def __init__(self, robot: Robot, base: BaseParameters, period: float, harmonics: int, center: np.ndarray,
                 limits: Limits, samples: int, rest: bool):
        self.robot, self.base, self.period, self.K = robot, base, period, harmonics
        self.center, self.limits, self.n = center, limits, robot.n
        self.N = fourier.rest_basis(period, harmonics) if rest else np.eye(2 * harmonics)
        self.m = self.N.shape[1]
        self.t, self.dense_t = grid(period, samples), grid(period, samples * DENSE)
        self.B = [P @ self.N for P in fourier.basis(period, harmonics, self.t)]  # (S, m) each
        self.dense_B = [P @ self.N for P in fourier.basis(period, harmonics, self.dense_t)]
        if limits.box is not None:  # the box's grid: denser again
            box_t = grid(period, max(BOX_GRID, len(self.dense_t)))
            self.box_B = [P @ self.N for P in fourier.basis(period, harmonics, box_t)[:2]]
        self.start_tip = arm_terms(robot, center[None], np.zeros((1, self.n)))["r"][0]
        self._family = self._families()
        self._cache: tuple[bytes, tuple] | None = None

    # ------------------------------------------------------------------ the trajectory of coefficients

    def coefficients(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(a, b)``, each ``(n, K)``, of the variables ``X``."""
        C = X @ self.N.T
        return C[:, :self.K], C[:, self.K:]

    def states(self, X: np.ndarray, dense: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``q, q', q''`` ``(..., S, n)`` at the samples (or the dense grid) of ``X`` ``(..., n, m)``."""
        Bq, Bv, Ba = self.dense_B if dense else self.B
        return (self.center + np.einsum("sm,...nm->...sn", Bq, X), np.einsum("sm,...nm->...sn", Bv, X),
                np.einsum("sm,...nm->...sn", Ba, X))

    def stacked(self, X: np.ndarray, dense: bool = False) -> np.ndarray:
        """The stacked base regressor ``W`` ``(..., S n, p)`` of ``X`` ``(..., n, m)``."""
        q, qd, qdd = self.states(X, dense)
        lead = q.shape[:-1]
        Y, _ = regressor(self.robot, *(a.reshape(-1, self.n) for a in (q, qd, qdd)))
        Wb = self.base.regressor(Y)
        return Wb.reshape(*lead[:-1], lead[-1] * self.n, Wb.shape[-1])

    def condition(self, X: np.ndarray) -> float:
        """The condition number of ``W`` on the dense grid."""
        largest, smallest = extreme_singular_values(self.stacked(X, dense=True))
        return largest / smallest if smallest > 0 else float("inf")

    # ------------------------------------------------------------------ objective

    def _extremes(self, x: np.ndarray):
        """``(W, s, V)`` at ``x``: ``W`` and its largest and smallest singular values and right singular
        vectors, as the Gram matrix's extreme eigenpairs (a small symmetric problem, two eigenpairs of it
        only: LAPACK's MRRR, which needs no threaded BLAS; squaring the condition number costs nothing where
        the search goes, far below 1e7)."""
        key = x.tobytes()
        if self._cache is None or self._cache[0] != key:
            W = self.stacked(x.reshape(self.n, self.m))
            G = np.einsum("rp,rq->pq", W, W)  # no threaded BLAS either: a small product
            p = len(G)
            pairs = [eigh(G, driver="evr", subset_by_index=[k, k]) for k in (p - 1, 0)]
            s = np.sqrt(np.maximum([e[0] for e, _ in pairs], np.finfo(float).tiny))
            self._cache = (key, (W, s, np.hstack([v for _, v in pairs])))
        return self._cache[1]

    def objective(self, x: np.ndarray) -> float:
        """``log cond W`` at the samples."""
        _, s, _ = self._extremes(x)
        return float(np.log(s[0]) - np.log(s[1]))

    def gradient(self, x: np.ndarray) -> np.ndarray:
        """The objective's gradient: ``d log s = v^T W^T dW v / s^2`` of the extreme singular values, ``dW`` by
        forward differences (each variable moves one joint's trajectory: the perturbed trajectories in
        batched calls of at most :data:`CHUNK_BYTES` of regressor)."""
        W, s, V = self._extremes(x)
        X = x.reshape(self.n, self.m)
        p = self.n * self.m
        WV = np.einsum("rp,pk->rk", W, V)
        chunk = max(1, CHUNK_BYTES // (8 * len(self.t) * self.n * len(self.base.names)))
        d = np.empty((p, 2))
        for lo in range(0, p, chunk):
            moved = np.arange(lo, min(lo + chunk, p))
            perturbed = np.broadcast_to(X, (len(moved), self.n, self.m)).copy()
            perturbed.reshape(len(moved), p)[np.arange(len(moved)), moved] += STEP
            D = (self.stacked(perturbed) - W) / STEP  # (chunk, S n, P)
            d[moved] = np.einsum("rk,jrk->jk", WV, np.einsum("jrc,ck->jrk", D, V)) / s**2
        return d[:, 0] - d[:, 1]

    # ------------------------------------------------------------------ constraints

    def _families(self) -> list[tuple[int, np.ndarray]]:
        """Per joint and kind (position, speed, acceleration) with a finite limit, ``(joint, M)``: ``M X_i`` are
        the values at the samples in units of their limits' room (``<= 1`` within them), both signs."""
        lim, found = self.limits, []
        rooms = ((self.B[0], lim.upper - self.center, self.center - lim.lower), (self.B[1], lim.velocity, lim.velocity),
                 (self.B[2], lim.acceleration, lim.acceleration))
        for i in range(self.n):
            for basis, above, below in rooms:
                rows = [sign * basis / room for sign, room in ((1.0, above[i]), (-1.0, below[i])) if np.isfinite(room)]
                if rows:
                    found.append((i, np.vstack(rows)))
        return found

    def _joint_constraints(self, x: np.ndarray, jacobian: bool) -> np.ndarray:
        """``1 - smooth max`` of each family's values (its limit holds where ``>= 0``), or its Jacobian."""
        X = x.reshape(self.n, self.m)
        out = np.zeros((len(self._family), self.n, self.m)) if jacobian else np.zeros(len(self._family))
        for row, (i, M) in enumerate(self._family):
            value, weights = _smooth_max(np.einsum("rm,m->r", M, X[i]))
            if jacobian:
                out[row, i] = -np.einsum("r,rm->m", weights, M)
            else:
                out[row] = 1.0 - value
        return out.reshape(len(self._family), -1) if jacobian else out

    def _box_constraints(self, x: np.ndarray, jacobian: bool) -> np.ndarray:
        """The same for the tool's position along each axis with a finite side (in units of the room from
        the start to the side), or its Jacobian (the tip's position Jacobian times the basis)."""
        q = self.states(x.reshape(self.n, self.m))[0]
        terms = arm_terms(self.robot, q, np.zeros_like(q))
        out = []
        for d, (lo, hi) in enumerate(self.limits.box):
            rooms = [(sign, room) for sign, room in ((1.0, hi - self.start_tip[d]), (-1.0, self.start_tip[d] - lo))
                     if np.isfinite(room)]
            if not rooms:
                continue
            values = np.concatenate([sign * (terms["r"][:, d] - self.start_tip[d]) / room for sign, room in rooms])
            value, weights = _smooth_max(values)
            if jacobian:
                rate = np.einsum("sn,sm->snm", terms["J"][:, d, :], self.B[0]).reshape(len(self.t), -1)
                out.append(-np.einsum("r,rp->p", weights, np.vstack([sign * rate / room for sign, room in rooms])))
            else:
                out.append(1.0 - value)
        return np.array(out)

    def bounds(self) -> list[tuple[float, float]]:
        """Bounds on the variables that every trajectory within the acceleration limits meets, so that no
        step of the search runs away: by Parseval, the mean of ``q''^2`` is ``sum_k (w k r_k)^2 / 2``, at most
        ``acc^2``, so ``|X_i|^2 = sum_k r_k^2 <= 2 acc^2 / w^2 sum_k 1 / k^2 < (2 acc / w)^2``."""
        largest = 2.0 * self.limits.acceleration / fourier.fundamental(self.period)
        return [(-x, x) for x in np.repeat(largest, self.m)]

    def constraints(self) -> list[dict]:
        """SLSQP's constraints: the joint limits and the box (``>= 0`` where kept) with their Jacobians."""
        out = [{"type": "ineq", "fun": lambda x: self._joint_constraints(x, False),
                "jac": lambda x: self._joint_constraints(x, True)}] if self._family else []
        if self.limits.box is not None and np.isfinite(self.limits.box).any():
            out.append({"type": "ineq", "fun": lambda x: self._box_constraints(x, False),
                        "jac": lambda x: self._box_constraints(x, True)})
        return out

    # ------------------------------------------------------------------ safe for all times

    def joint_bounds(self, X: np.ndarray):
        """Bounds for all times, per joint: ``(highest q, lowest q, largest |q'|, largest |q''|)``, from the
        dense grid and the analytic bounds on each one's rate."""
        a, b = self.coefficients(X)
        _, speed, acceleration, jerk = fourier.amplitude_bounds(self.period, a, b)
        q, qd, qdd = self.states(X, dense=True)
        h = self.period / len(self.dense_t)
        return (fourier.grid_bound(q.max(axis=0), speed, h), -fourier.grid_bound(-q.min(axis=0), speed, h),
                fourier.grid_bound(np.abs(qd).max(axis=0), acceleration, h),
                fourier.grid_bound(np.abs(qdd).max(axis=0), jerk, h))

    def _joint_scale(self, X: np.ndarray, grow: bool) -> np.ndarray:
        """Per joint, the largest scale of its coefficients (``<= 1`` unless ``grow``) that keeps its limits
        for all times (the bounds scale with the coefficients, the offsets ``q0`` do not)."""
        high, low, speed, acceleration = self.joint_bounds(X)
        lim, c = self.limits, self.center
        with np.errstate(divide="ignore", invalid="ignore"):
            ratios = [(lim.upper - c) / (high - c), (c - lim.lower) / (c - low), lim.velocity / speed,
                      lim.acceleration / acceleration]
        scale = np.full(self.n, np.inf if grow else 1.0)
        for r in ratios:
            scale = np.minimum(scale, np.where(np.isnan(r), 1.0, r))
        return np.where(np.isinf(scale), 1.0, scale)  # a joint that does not move

    def box_margin(self, X: np.ndarray) -> float:
        """The smallest distance for all times of the tool inside the box (negative: outside): on a grid of
        :data:`BOX_GRID` points, each point's distance less what the tool can move in half a spacing,
        ``|v| dt + A dt^2 / 2`` per axis, ``v`` its velocity there and ``A`` a bound on its acceleration."""
        box = self.limits.box
        a, b = self.coefficients(X)
        excursion, speed, acceleration, _ = fourier.amplitude_bounds(self.period, a, b)
        reach = _reach_beyond(self.robot, np.abs(self.center) + excursion)
        # a = sum_i q_i'' z_i x (p - o_i) + q_i' (z_i' x (p - o_i) + z_i x (p' - o_i')) (a prismatic joint's
        # terms without the lever): |z_i'| is at most the sum of the joint speeds, |p - o_i| the reach, and
        # |p' - o_i'| the tool's speed bound (the joints before i turn p - o_i, shorter than their reach)
        tool_speed = speed @ reach
        tool_acceleration = acceleration @ reach + 2.0 * speed.sum() * tool_speed
        Bq, Bv = self.box_B
        q, qd = self.center + np.einsum("sm,nm->sn", Bq, X), np.einsum("sm,nm->sn", Bv, X)
        terms = arm_terms(self.robot, q, qd)
        v = np.einsum("sdn,sn->sd", terms["J"][:, :3, :], qd)
        dt = 0.5 * self.period / len(Bq)
        room = np.minimum(terms["r"] - box[:, 0], box[:, 1] - terms["r"]) - np.abs(v) * dt
        return float(room.min() - 0.5 * tool_acceleration * dt**2)

    def certified(self, X: np.ndarray, grow: bool = False) -> tuple[np.ndarray, float]:
        """``X`` scaled down (or, with ``grow``, each joint's up or down to its tightest limit) until the limits
        hold for all times, and the common scale the box then took (1: none; 0: the tool cannot move in it):
        shrunk by :data:`SHRINK` until inside, then halfway back towards the last scale outside a few times."""
        X = X * self._joint_scale(X, grow)[:, None]
        if self.limits.box is None or self.box_margin(X) >= 0.0:
            return X, 1.0
        inside, outside = 1.0, 1.0
        while self.box_margin(inside * X) < 0.0:
            inside, outside = inside * SHRINK, inside
            if inside < SMALLEST_SCALE:
                return 0.0 * X, 0.0
        for _ in range(6):
            middle = 0.5 * (inside + outside)
            inside, outside = (middle, outside) if self.box_margin(middle * X) >= 0.0 else (inside, middle)
        return inside * X, inside

    # ------------------------------------------------------------------ the search

    def optimised(self, seed: int, restarts: int, iterations: int) -> tuple[np.ndarray, float, float, float]:
        """The best of ``restarts`` optimisations of at most ``iterations`` from random starts: ``(X, its
        condition, its start's condition, the smallest box scale met)``, each solution made safe for all
        times."""
        rng = np.random.default_rng(seed)
        constraints = self.constraints()
        best, smallest = None, 1.0
        for _ in range(restarts):
            # a random motion as large as the limits let it be: the unoptimised trajectory
            X0, scale = self.certified(rng.standard_normal((self.n, self.m)), grow=True)
            smallest = min(smallest, scale)
            if scale == 0.0:
                continue
            start = self.condition(X0)
            found = minimize(self.objective, X0.ravel(), jac=self.gradient, method="SLSQP", constraints=constraints,
                             bounds=self.bounds(), options={"maxiter": iterations, "ftol": 1e-9})
            X = found.x.reshape(self.n, self.m) if np.isfinite(found.x).all() else X0
            X, scale = self.certified(X)
            smallest = min(smallest, scale)
            kept = (X, self.condition(X)) if scale > 0.0 else (X0, start)
            if kept[1] > start:  # the optimisation lost ground (a poor local step): the start is kept
                kept = (X0, start)
            if best is None or kept[1] < best[1]:
                best = (*kept, start)
        if best is None:
            return np.zeros((self.n, self.m)), float("inf"), float("inf"), 0.0
        return (*best, smallest)


def extreme_singular_values(W: np.ndarray) -> tuple[float, float]:
    """The largest and smallest singular values of ``W``: from its Gram matrix's eigenvalues (a small
    product and problem, no threaded BLAS) where they are exact to 1e-8, that is where the condition number
    is below :data:`GRAM_CONDITION`; else from ``W``'s singular value decomposition."""
    eigenvalues = np.linalg.eigvalsh(np.einsum("rp,rq->pq", W, W))
    if eigenvalues[0] > eigenvalues[-1] / GRAM_CONDITION**2:
        return float(np.sqrt(eigenvalues[-1])), float(np.sqrt(eigenvalues[0]))
    s = np.linalg.svd(W, compute_uv=False)
    return float(s[0]), float(s[-1])


def grid(period: float, count: int) -> np.ndarray:
    """``count`` times evenly spread over a period, half a spacing off its start: there a trajectory made at
    rest has ``q' = 0`` to rounding, where a Coulomb friction column's sign would be rounding's."""
    return (np.arange(count) + 0.5) * (period / count)


def _smooth_max(values: np.ndarray) -> tuple[float, np.ndarray]:
    """``TEMPERATURE log sum exp(values / TEMPERATURE)`` (between the largest value and that plus
    ``TEMPERATURE log len(values)``) and its gradient, the softmax weights."""
    top = values.max()
    e = np.exp((values - top) / TEMPERATURE)
    total = e.sum()
    return float(top + TEMPERATURE * np.log(total)), e / total


def _reach_beyond(robot: Robot, slide: np.ndarray) -> np.ndarray:
    """Per joint, a bound on the tool's speed per unit of the joint's: for a revolute joint its distance to
    the tool, at most the lengths along the chain beyond it (the joints' origin offsets, the prismatic
    joints' slides, at most ``slide``, and the tool's offset); for a prismatic joint 1."""
    chain = robot.chain
    prismatic = np.array([j.kind != "revolute" for j in chain.joints])
    steps = [np.linalg.norm(j.translation) for j in chain.joints] + [np.linalg.norm(chain.tip_translation)]
    steps = np.array(steps) + np.append(np.where(prismatic, slide, 0.0), 0.0)
    beyond = np.cumsum(steps[::-1])[::-1]  # beyond[i]: from joint i - 1's origin to the tool, along the chain
    return np.where(prismatic, 1.0, beyond[1:])
