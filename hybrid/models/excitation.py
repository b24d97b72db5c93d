"""Optimal excitation trajectories for identifying a robot's dynamics: :func:`excitation_trajectory`.

Identification (:func:`hybrid.identify_dynamics`) is as good as the data: the stacked base regressor ``W``
of the samples must be well conditioned, so that torque noise and model error do not blow up in the
estimate of any base parameter. Following Swevers et al. (1997), each joint follows a finite Fourier
series (:mod:`hybrid.models.fourier`): periodic, so that measurements can be averaged over periods and
their noise estimated, with ``q'`` and ``q''`` in closed form (no differentiation of noisy
measurements needed when the reference is tracked well) and a band limited to ``K`` harmonics of
``1 / period`` (no resonance excited beyond it). Its coefficients minimise the condition number of ``W``
over one period's samples, within the joints' position, speed and acceleration limits and, when given, a
box the tool must stay in.

The method (:mod:`hybrid.models.excitation_design`): SciPy's SLSQP from a few seeded random starts,
each a random motion as large as the limits let it be (the unoptimised trajectory whose condition number
is reported beside the optimised one). An SQP method keeps the limits as constraints, with their
Jacobians, exactly: the values at the samples are linear in the coefficients (the tool's position is
smooth in them), and their largest, smoothed, is at most the limit. A penalty with L-BFGS-B would trade
violations against conditioning and need its weight tuned per robot. The objective ``log cond W`` is
smooth where the extreme singular values are simple, and its gradient comes from ``W``'s extreme singular
vectors and batched regressor calls; it has many local minima, hence the restarts (the best kept: the
result is a function of the seed). A solution is then made safe for all times: bounded on a grid ten
times as dense as the samples, plus half a spacing times an analytic bound on each value's rate, and
scaled down where a bound passes a limit, so no limit holds only at the samples.
"""

from __future__ import annotations

import csv
import math
import types
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.errors import HybridError
from hybrid.models import fourier
from hybrid.models.base_parameters import base_parameters
from hybrid.models.dynamics_identification import UNEXCITED, unexcited
from hybrid.models.excitation_design import DENSE, Design, Limits, extreme_singular_values, grid
from hybrid.models.regressor import regressor
from hybrid.models.robot import Robot, as_robot
from hybrid.models.terms import arm_terms
from hybrid.models.urdf import JointLimits
from hybrid.native import generator
from hybrid.user_warnings import warn
from hybrid.validate import check_c_name, checked_keywords, listed, listed_in_full, shown, whole_number

#: the acceleration limit of every joint unless given [rad/s^2 or m/s^2]: well below the shipped arms' own
#: (the Panda's are 7.5 to 20 rad/s^2), enough for a period of seconds to sweep a joint's range
DEFAULT_ACCELERATION = 2.0
#: a condition number above this is warned of (the identified parameters are as many times as sensitive to the
#: torques' noise as the best excited ones; optimised trajectories of the shipped arms reach 20 to 60)
POOR_CONDITION = 1e5
#: the most harmonics taken (more is a band no controller tracks at a period of seconds)
MAX_HARMONICS = 50
#: the most optimisation samples per period (the dense grid is ten times as many)
MAX_SAMPLES = 2_000
#: the most seeded restarts
MAX_RESTARTS = 100
#: the most iterations of one optimisation
MAX_ITERATIONS = 100_000
#: the folder of the C template
C_FOLDER = Path(__file__).resolve().parent / "c"
#: the rows of a CSV file computed and written at a time
CSV_BLOCK = 10_000
#: the limits a trajectory takes, by name
LIMIT_NAMES = ("lower", "upper", "velocity", "acceleration")


@checked_keywords
@dataclass(frozen=True, eq=False)
class ExcitationTrajectory:
    """A periodic excitation trajectory, a Fourier series per joint (:func:`excitation_trajectory` makes one).

    Joint ``i`` follows ``q_i(t) = q0_i + sum_k a_ik / (w k) sin(w k t) - b_ik / (w k) cos(w k t)`` over the
    harmonics ``k`` from 1 to ``K``, ``w = 2 pi / period``.

    Parameters
    ----------
    robot : Robot
        The arm it excites.
    period : float
        Its period [s].
    center : numpy.ndarray
        ``q0``, per joint [rad or m]: where it oscillates about (and, made at rest, starts and ends).
    a, b : numpy.ndarray
        ``(n, K)``: the coefficients of the joint speeds' cosines and sines [rad/s or m/s].
    samples : int
        The samples per period it was optimised on; :attr:`condition` is taken on ten times as many.
    limits : mapping or None
        The limits it was made to keep for all times: ``"lower"``, ``"upper"`` [rad or m], ``"velocity"``
        and ``"acceleration"``, per joint (infinite: none).
    box : numpy.ndarray or None
        ``(3, 2)``: the box [m] (base axes; rows x, y, z; columns lower, upper) the tool was kept in.
    start_condition : float
        The condition number of the start its optimisation ran from (NaN when not optimised).

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.Robot.planar(hybrid.paper_arm())
    >>> traj = hybrid.ExcitationTrajectory(
    ...     robot, 2.0, np.zeros(2), np.array([[0.5], [0.2]]),
    ...     np.zeros((2, 1)))
    >>> q, qd, qdd = traj.sample([0.0, 0.5])
    >>> q.round(3).tolist()
    [[0.0, 0.0], [0.159, 0.064]]
    """

    robot: Robot
    period: float
    center: np.ndarray
    a: np.ndarray
    b: np.ndarray
    samples: int = 100
    limits: Mapping | None = None
    box: np.ndarray | None = None
    start_condition: float = math.nan

    def __post_init__(self):
        robot = as_robot(self.robot)
        n = robot.n
        object.__setattr__(self, "robot", robot)
        object.__setattr__(self, "period", _positive("period", self.period, "the trajectory's period in s"))
        center = _numbers("center", self.center, (n,))
        a, b = _numbers("a", self.a, (n, -1)), _numbers("b", self.b, (n, -1))
        if a.shape != b.shape or a.shape[1] < 1:
            raise HybridError(f"a has shape {a.shape} and b {b.shape}; give both ({n}, K): one row per joint, one "
                              "column per harmonic")
        for name, value in (("center", center), ("a", a), ("b", b)):
            value.setflags(write=False)
            object.__setattr__(self, name, value)
        object.__setattr__(self, "samples", whole_number("samples", self.samples, 1, MAX_SAMPLES))

    @property
    def harmonics(self) -> int:
        """``K``, the harmonics of ``1 / period`` per joint."""
        return self.a.shape[1]

    def sample(self, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Joint positions, speeds and accelerations at the times ``t`` (periodic: any time).

        Parameters
        ----------
        t : array_like
            Times [s], one or a sequence.

        Returns
        -------
        q, qd, qdd : numpy.ndarray
            ``(N, n)`` each, one row per time [rad, rad/s, rad/s^2; m for a prismatic joint].

        Raises
        ------
        HybridError
            Times that are not finite numbers.
        """
        try:
            times = np.atleast_1d(np.asarray(t, dtype=float))
        except (TypeError, ValueError):
            times = np.array([np.nan])
        if times.ndim != 1 or not np.isfinite(times).all():
            raise HybridError(f"t = {shown(t, 60)}; give a time or a sequence of finite times in s")
        return fourier.evaluate(self.period, self.center, self.a, self.b, times)

    @cached_property
    def condition(self) -> float:
        """The condition number of the stacked base regressor over one period: ``samples * 10`` times ``t =
        (k + 1/2) period / (samples * 10)``."""
        q, qd, qdd = self.sample(grid(self.period, self.samples * DENSE))
        Y, _ = regressor(self.robot, q, qd, qdd)
        Wb = base_parameters(self.robot).regressor(Y)
        largest, smallest = extreme_singular_values(Wb.reshape(-1, Wb.shape[-1]))
        return largest / smallest if smallest > 0 else math.inf

    def to_csv(self, path, rate: float = 100.0, *, periods: int = 1, overwrite: bool = False) -> Path:
        """Write the trajectory sampled at ``rate`` as CSV: columns ``t``, ``q[joint]``, ``qd[joint]``,
        ``qdd[joint]`` (SI units), rows ``t = k / rate`` over ``periods`` periods from 0.

        Parameters
        ----------
        path : str or path-like
            The file (written whole or not at all).
        rate : float
            Samples per second [Hz].
        periods : int
            How many periods.
        overwrite : bool
            Replace an existing file (otherwise refused).

        Returns
        -------
        pathlib.Path
            ``path``.

        Raises
        ------
        HybridError
            A rate or count that is not positive, an existing file without ``overwrite``, or a write that
            failed.
        """
        rate = _positive("rate", rate, "the samples per second in Hz")
        periods = whole_number("periods", periods, 1, 10_000)
        count = max(1, math.ceil(periods * self.period * rate - 1e-9))
        if count > 10**7:
            raise HybridError(f"{count} rows ({periods} periods of {self.period} s at {rate} Hz); give a lower rate "
                              "or fewer periods (at most 10^7 rows)")
        columns = ["t", *(f"{kind}[{name}]" for kind in ("q", "qd", "qdd") for name in self.robot.joint_names)]

        def write(tmp: Path) -> None:  # in blocks of rows: the table is never whole in memory
            with open(tmp, "w", newline="") as f:
                csv.writer(f, lineterminator="\n").writerow(columns)
                for first in range(0, count, CSV_BLOCK):
                    t = np.arange(first, min(first + CSV_BLOCK, count)) / rate
                    np.savetxt(f, np.column_stack([t, *self.sample(t)]), delimiter=",", fmt="%.17g")

        return files.write_with(path, write, overwrite)

    def to_c(self, path, prefix: str = "excitation", *, overwrite: bool = False) -> Path:
        """Write a C99 header for a controller: the coefficients and ``static inline void
        <prefix>_sample(double t, double q[], double qd[], double qdd[])``, which gives what :meth:`sample`
        gives (rounding aside). It needs only ``math.h`` (link with ``-lm``).

        Parameters
        ----------
        path : str or path-like
            The header (written whole or not at all).
        prefix : str
            The prefix of its names (``<prefix>_sample``, ``<PREFIX>_JOINTS``, ...).
        overwrite : bool
            Replace an existing file (otherwise refused).

        Returns
        -------
        pathlib.Path
            ``path``.

        Raises
        ------
        HybridError
            A prefix that cannot name C symbols, an existing file without ``overwrite``, or a write that
            failed.
        """
        prefix = check_c_name("prefix", prefix)
        literal = np.vectorize(lambda v: repr(float(v)), otypes=[str])
        text = generator.api().template_environment(C_FOLDER).get_template("excitation.h.j2").render(
            prefix=prefix, PREFIX=prefix.upper(), robot=_comment(self.robot.name),
            joints=", ".join(_comment(name) for name in self.robot.joint_names), n=self.robot.n,
            harmonics=self.harmonics, period=repr(self.period), omega=repr(fourier.fundamental(self.period)),
            center=literal(self.center).tolist(), a=literal(self.a).tolist(), b=literal(self.b).tolist())
        return files.write_text(path, text, overwrite)


@checked_keywords
def excitation_trajectory(robot: Robot, *, period: float = 10.0, harmonics: int = 5, limits=None, box=None,
                          start=None, safety: float = 0.9, rest: bool = True, samples: int = 100,
                          restarts: int = 3, iterations: int = 100, seed: int = 0) -> ExcitationTrajectory:
    """A periodic joint trajectory that excites ``robot``'s base parameters well, within its limits.

    Each joint follows a Fourier series of ``harmonics`` harmonics of ``1 / period`` about ``start``
    (:class:`ExcitationTrajectory`) whose coefficients minimise the condition number of the stacked base
    regressor (:func:`hybrid.base_parameters`) over ``samples`` points of a period: SLSQP from
    ``restarts`` random starts drawn from ``seed``, the best kept (see :mod:`hybrid.models.excitation`).
    The limits then hold for all times, not only at the samples (checked on a grid ten times as dense,
    with an analytic bound between its points).

    Parameters
    ----------
    robot : Robot
        The arm (its structure, gravity and limits).
    period : float
        The period [s]: the lowest frequency is ``1 / period``.
    harmonics : int
        Harmonics per joint (the highest frequency is ``harmonics / period``); at least 2 with ``rest``.
    limits : mapping, JointLimits or None
        Limits to keep, any of ``"lower"``, ``"upper"`` [rad or m], ``"velocity"`` [rad/s or m/s] and
        ``"acceleration"`` [rad/s^2 or m/s^2], each one number per joint or one for all (infinite: none;
        acceleration must be finite), kept as given. Those not given: the robot's URDF limits times
        ``safety`` (the position range shrunk about its middle), and :data:`DEFAULT_ACCELERATION`.
    box : array_like or None
        ``(3, 2)``: the box the tool must stay in [m], base axes, rows x, y, z, columns lower and upper
        (infinite: no bound), around the tool's position at ``start``.
    start : array_like or None
        ``q0``, the joint positions the motion oscillates about and, with ``rest``, starts and ends at;
        default the middle of each position range (0 where it is unbounded).
    safety : float
        The fraction of the URDF's position ranges and speed limits used, in (0, 1].
    rest : bool
        Start and end at ``start`` at rest (``q' = q'' = 0``): the arm can be brought there slowly and
        the trajectory run from it, and repeated.
    samples : int
        The samples per period the condition number and the limits are optimised on.
    restarts : int
        The optimisations from random starts.
    iterations : int
        The most iterations of each (SLSQP's; the condition number still falls a little beyond 100).
    seed : int
        The random starts' seed: the same seed, the same trajectory.

    Returns
    -------
    ExcitationTrajectory
        The coefficients, the condition number reached and the start's.

    Raises
    ------
    HybridError
        A period, count or factor out of range; limits of the wrong shape, not numbers, or that leave a
        joint no motion (a position range without width, a zero speed or acceleration limit, a start on
        or beyond a limit); a box that is empty or does not hold the tool at the start, or in which the
        tool cannot move; a trajectory that within the limits leaves base parameters unexcited (named).

    Warns
    -----
    UserWarning
        A condition number above :data:`POOR_CONDITION`, naming the base parameters excited worst.

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.Robot.planar(hybrid.paper_arm())
    >>> traj = hybrid.excitation_trajectory(
    ...     robot, period=4.0, harmonics=3, samples=24, restarts=1,
    ...     limits={"velocity": 2.0, "acceleration": 5.0})
    >>> bool(traj.condition < traj.start_condition)
    True
    >>> q, qd, qdd = traj.sample(np.linspace(0.0, 4.0, 401))
    >>> within = np.abs(qd).max() <= 2.0 and np.abs(qdd).max() <= 5.0
    >>> bool(within), np.allclose(q[0], q[-1])
    (True, True)
    """
    robot = as_robot(robot)
    period = _positive("period", period, "the trajectory's period in s, e.g. 10")
    if not isinstance(rest, bool):
        raise HybridError(f"rest = {shown(rest, 40)}; give True (start and end at rest) or False")
    harmonics = whole_number("harmonics", harmonics, 1, MAX_HARMONICS)
    if rest and harmonics == 1:
        raise HybridError("harmonics = 1 cannot start and end at rest (that takes three of each joint's 2 K "
                          "coefficients); give harmonics >= 2, or rest=False")
    safety = _positive("safety", safety, "a fraction of the URDF's limits in (0, 1], e.g. 0.9")
    if safety > 1.0:
        raise HybridError(f"safety = {safety}; give a fraction of the URDF's limits in (0, 1], e.g. 0.9")
    samples = whole_number("samples", samples, 4 * harmonics, MAX_SAMPLES)
    restarts = whole_number("restarts", restarts, 1, MAX_RESTARTS)
    iterations = whole_number("iterations", iterations, 0, MAX_ITERATIONS)
    seed = whole_number("seed", seed, 0, 2**63 - 1)
    lower, upper, velocity, acceleration = _joint_limits(robot, limits, safety)
    center = _start(robot, start, lower, upper)
    box = _box(robot, box, center)
    base = base_parameters(robot)
    names = tuple(base.names[i] for i in base.independent)
    if samples * robot.n < len(names):
        raise HybridError(f"samples = {samples} gives {samples * robot.n} torques for {len(names)} base parameters; "
                          f"give samples >= {-(-len(names) // robot.n)}, several times as many")
    design = Design(robot, base, period, harmonics, center, Limits(lower, upper, velocity, acceleration, box),
                    samples, rest)
    X, _, start_condition, box_scale = design.optimised(seed, restarts, iterations)
    if box_scale == 0.0 and not X.any():
        raise HybridError("the tool cannot move in the box from the start: any motion of the joints leaves it; "
                          "give a larger box (it must leave room on every side) or another start")
    W = design.stacked(X, dense=True)
    s = extreme_singular_values(W)
    if s[-1] < UNEXCITED * s[0]:
        missing = unexcited(W, names)
        raise HybridError(f"within these limits the trajectory does not excite the base parameters {listed(missing)}; "
                          "give wider limits or box, a longer period or more harmonics" + listed_in_full(missing))
    if s[0] > POOR_CONDITION * s[-1]:
        warn(f"within these limits the trajectory's condition number is {s[0] / s[-1]:.3g}: it barely excites the "
             f"base parameters {listed(unexcited(W, names, 1.0 / POOR_CONDITION))}, whose estimates will amplify "
             "the torques' noise about as much; give wider limits or box, a longer period or more harmonics",
             UserWarning)
    a, b = design.coefficients(X)
    kept = types.MappingProxyType(dict(zip(LIMIT_NAMES, (lower, upper, velocity, acceleration))))
    return ExcitationTrajectory(robot, period, center, a, b, samples, kept, box, start_condition)


# ---------------------------------------------------------------------------------------------- inputs


def _positive(name: str, value, what: str) -> float:
    """``value`` as a finite number above 0, else a HybridError saying ``what`` it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not math.isfinite(value) or value <= 0:
        raise HybridError(f"{name} = {shown(value, 40)}; give {what} (a finite number above 0)")
    return float(value)


def _numbers(name: str, value, shape: tuple[int, ...]) -> np.ndarray:
    """``value`` as finite numbers of ``shape`` (``-1``: any length there), else a HybridError."""
    try:
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError):
        arr = np.array([np.nan])
    if arr.ndim != len(shape) or any(s != -1 and s != d for s, d in zip(shape, arr.shape)) \
            or not np.isfinite(arr).all():
        want = " x ".join("K" if s == -1 else str(s) for s in shape)
        raise HybridError(f"{name} = {shown(value, 60)}; give {want} finite numbers")
    return arr


def _joint_limits(robot: Robot, limits, safety: float) -> tuple[np.ndarray, ...]:
    """``(lower, upper, velocity, acceleration)`` per joint: those given, the rest the URDF's times ``safety``
    and the default acceleration; each checked to leave every joint some motion."""
    n, urdf = robot.n, robot.limits
    lower, upper = (np.full(n, -np.inf), np.full(n, np.inf)) if urdf is None else (urdf.lower, urdf.upper)
    bounded = np.isfinite(lower) & np.isfinite(upper)
    middle, half = _middle(lower, upper), np.where(bounded, safety * (upper - lower) / 2, np.inf)
    found = {"lower": np.where(bounded, middle - half, lower), "upper": np.where(bounded, middle + half, upper),
             "velocity": safety * (np.full(n, np.inf) if urdf is None else urdf.velocity),
             "acceleration": np.full(n, DEFAULT_ACCELERATION)}
    if isinstance(limits, JointLimits):
        limits = {"lower": limits.lower, "upper": limits.upper, "velocity": limits.velocity}
    if limits is not None and not isinstance(limits, Mapping):
        raise HybridError(f"limits = {shown(limits, 60)}; give a dict of any of {', '.join(LIMIT_NAMES)} (one "
                          "number per joint, or one for all), a hybrid JointLimits, or None for the robot's")
    for key, value in (limits or {}).items():
        if key not in LIMIT_NAMES:
            raise HybridError(f"limits has the key {shown(key, 40)}; give only {', '.join(LIMIT_NAMES)}")
        try:
            arr = np.broadcast_to(np.asarray(value, dtype=float), (n,)).copy()
        except (TypeError, ValueError):
            raise HybridError(f"limits[{key!r}] = {shown(value, 60)}; give {n} numbers (one per joint) or one for "
                              "all") from None
        if np.isnan(arr).any():
            raise HybridError(f"limits[{key!r}] = {shown(value, 60)} has NaN; give numbers (inf for no limit)")
        found[key] = arr
    names = robot.joint_names
    for i, name in enumerate(names):
        lo, hi, v, acc = (found[k][i] for k in LIMIT_NAMES)
        if not lo < hi:
            raise HybridError(f"joint '{name}': the position range [{lo:.6g}, {hi:.6g}] has no width, so it cannot "
                              "move; give lower < upper")
        if not v > 0:
            raise HybridError(f"joint '{name}': the velocity limit {v:.6g} leaves it no motion; give a limit above 0")
        if not 0 < acc < np.inf:
            raise HybridError(f"joint '{name}': the acceleration limit {acc:.6g}; give a finite limit above 0, e.g. "
                              f"{DEFAULT_ACCELERATION}")
    for arr in found.values():
        arr.setflags(write=False)
    return tuple(found[k] for k in LIMIT_NAMES)


def _middle(lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """The middle of each range, 0 where a side is unbounded."""
    bounded = np.isfinite(lower) & np.isfinite(upper)
    return np.where(bounded, (np.where(bounded, lower, 0.0) + np.where(bounded, upper, 0.0)) / 2, 0.0)


def _start(robot: Robot, start, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """``q0``: given, or the middle of each position range (0 where a side is unbounded); strictly within
    the ranges."""
    if start is None:
        center = _middle(lower, upper)
    else:
        center = _numbers("start", start, (robot.n,))
    for name, q, lo, hi in zip(robot.joint_names, center, lower, upper):
        if not lo < q < hi:
            raise HybridError(f"joint '{name}': the start {q:.6g} is not inside its position range [{lo:.6g}, "
                              f"{hi:.6g}], so it cannot oscillate about it; give a start inside")
    center.setflags(write=False)
    return center


def _box(robot: Robot, box, center: np.ndarray) -> np.ndarray | None:
    """The box as ``(3, 2)`` numbers, checked to be a box and to hold the tool at ``center`` strictly."""
    if box is None:
        return None
    try:
        arr = np.array(box, dtype=float)
    except (TypeError, ValueError):
        arr = np.array([np.nan])
    if arr.shape != (3, 2) or np.isnan(arr).any():
        raise HybridError(f"box = {shown(box, 60)}; give ((x_lo, x_hi), (y_lo, y_hi), (z_lo, z_hi)) in m, base "
                          "axes (inf for no bound)")
    tip = arm_terms(robot, center[None], np.zeros((1, robot.n)))["r"][0]
    for axis, (lo, hi), x in zip("xyz", arr, tip):
        if not lo < hi:
            raise HybridError(f"the box's {axis} range [{lo:.6g}, {hi:.6g}] is empty; give lower < upper")
        if not lo < x < hi:
            raise HybridError(f"the box's {axis} range [{lo:.6g}, {hi:.6g}] does not hold the tool's start {axis} = "
                              f"{x:.6g} m; give a box around it or another start")
    arr.setflags(write=False)
    return arr


def _comment(name: str) -> str:
    """``name`` safe inside a C comment: ASCII, no comment end, no trigraph."""
    return ascii(name)[1:-1].replace("*/", "*\\/").replace("??", "?\\?")
