"""A robot's dynamics identified from a log of its motion and joint torques.

The log's times, positions and torques (velocities and accelerations when measured) are filtered,
differentiated and thinned (:mod:`hybrid.models.log_signals`). The dynamics are linear in the base
parameters (:func:`hybrid.base_parameters`): at each sample kept ``tau_k = Y_b(q_k, q'_k, q''_k) pi_b``.
Stacked, ``W pi_b = t`` (``W``: ``M n`` rows, one column per base parameter) is solved by least squares
through a QR factorisation taken a block of samples at a time (memory bounded for any log): per joint
the triangular factor of ``[W_j t_j]`` (its rows), then of them all, ``R``. ``R`` gives the estimate, the
condition number, the residual of each joint for any parameters, and the estimate's covariance
``(W^T W)^-1 (sum_j s_j^2 W_j^T W_j) (W^T W)^-1`` (independent torque errors, each joint's of its own
variance ``s_j^2``, from its residual). A trajectory that does not excite every base parameter leaves
``W`` rank deficient: the parameters of its singular directions are refused by name rather than given an
arbitrary value.

The full parameters come from :func:`~hybrid.models.consistent_parameters.consistent_parameters`
(every link a rigid body, frictions >= 0; ``consistent=True``) or, without it, from the estimate with the
parameters the torques do not see at their nominal values.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.base_parameters import BaseParameters, base_parameters
from hybrid.models.consistent_parameters import consistent_parameters, link_scales, link_sizes
from hybrid.models.log_signals import LogSignals, log_signals
from hybrid.models.regressor import coulomb_columns, linear_parameters, regressor, with_linear_parameters
from hybrid.models.robot import Robot, as_robot
from hybrid.validate import checked_keywords, listed, listed_in_full

#: a singular value of the stacked base regressor below this fraction of the largest is a direction the
#: data did not excite (rounding leaves about 1e-16; a parameter excited at all is far above 1e-8)
UNEXCITED = 1e-8
#: a base parameter is named as not excited when this much of it (the norm of its unit vector's
#: projection on the singular directions) lies in them
UNEXCITED_SHARE = 0.1
#: a base parameter is poorly excited when its standard deviation is more than this share of its size
#: (the largest of its estimate, its nominal value and :data:`SIZE_FLOOR` of its link's scale)
POORLY_EXCITED = 0.1
#: the least size of a base parameter, as a share of its scale (a link's: the nominal mass ``m``, ``m l``,
#: ``m l^2`` for a mass, a first moment, an inertia; a joint's friction: the value that makes the joint's RMS
#: torque): one whose value is nearly zero (a product of inertia of a symmetric link, a friction the arm does
#: not have) is judged against that, not against zero
SIZE_FLOOR = 1e-2
#: samples per native regressor call and QR block: memory bounded whatever the log's length
CHUNK = 8192
#: the logged torques are refused as in other units when the factor that best scales the nominal model's
#: torques onto them is not within this factor of 1 (an arm perturbed by 30 %, with friction its URDF lacks,
#: measured 0.9-1.2; N mm or mN m give 1000, kN m 1e-3)
UNITS_FACTOR = 10.0
#: a joint's logged torques are refused as of the opposite sign when their correlation with the nominal
#: model's is below this (measured on arms 30 % off with friction and payloads the model lacks: -0.06 at the
#: least, on a wrist; a flip is caught on the joints the model predicts with a correlation above 0.5)
AGAINST = -0.5


@checked_keywords
@dataclass(frozen=True)
class DynamicsIdentification:
    """What :func:`identify_dynamics` found: the base parameters ``pi_b`` of ``tau = Y_b pi_b`` by least
    squares, and the full parameters ``pi`` of a robot.

    Parameters
    ----------
    nominal_robot : Robot
        The arm given (its structure and gravity give the regressor; its parameters are the nominal model).
    base : BaseParameters
        The base parameters (:func:`hybrid.base_parameters`); ``base.base_names()`` says which
        combination of :func:`hybrid.linear_parameters` each stands for.
    names : tuple of str
        Each base parameter by the parameter of ``pi`` it is kept for (``base.independent``'s names).
    estimate : numpy.ndarray
        The base parameters' least-squares estimate (SI units of ``pi``).
    std : numpy.ndarray
        Their standard deviations (NaN where the fit leaves no residual to judge by).
    nominal : numpy.ndarray
        The base parameters of the nominal model, ``base.of(linear_parameters(nominal_robot))``.
    parameters : numpy.ndarray
        The full ``pi``: the physically consistent estimate, or (``consistent=False``) the estimate with
        the parameters the torques do not see at their nominal values.
    consistent : numpy.ndarray or None
        The consistent estimate's base parameters, ``base.of(parameters)``; None with ``consistent=False``.
    residual_rms : numpy.ndarray
        Per joint, the RMS over the samples of the torque the least-squares fit leaves [N m or N].
    consistent_residual_rms : numpy.ndarray or None
        The same of the consistent estimate.
    condition : float
        The condition number of the stacked base regressor, unweighted (the motion's, as
        :func:`hybrid.excitation_trajectory` reports it, whatever the weights).
    poorly_excited : tuple of str
        The base parameters whose standard deviation is more than 10 % of their size: the largest of the
        estimate, the nominal value and 1 % of its scale: for a link's parameter the link's (its nominal mass
        ``m``, ``m l``, ``m l^2`` for a mass, first moment, inertia; ``l`` the RMS distance of its mass from
        the joint's origin), for a joint's friction parameter the value that alone would make the joint's
        RMS torque in the log (a friction the arm does not have is not judged against zero).
    samples : int
        The samples the fit used (the log's, less the filter's edges, thinned).
    log_samples : int
        The log's samples.
    cutoff_hz : float or None
        The filter's cutoff [Hz]; None for a log taken as it is.
    sample_time : float
        The log's step [s].

    Examples
    --------
    See :func:`identify_dynamics`, which makes one.

    >>> import hybrid
    >>> hybrid.DynamicsIdentification.__name__
    'DynamicsIdentification'
    """

    nominal_robot: Robot
    base: BaseParameters
    names: tuple[str, ...]
    estimate: np.ndarray
    std: np.ndarray
    nominal: np.ndarray
    parameters: np.ndarray
    consistent: np.ndarray | None
    residual_rms: np.ndarray
    consistent_residual_rms: np.ndarray | None
    condition: float
    poorly_excited: tuple[str, ...]
    samples: int
    log_samples: int
    cutoff_hz: float | None
    sample_time: float

    @cached_property
    def robot(self) -> Robot:
        """The identified arm: the nominal one with :attr:`parameters` (:func:`hybrid.with_linear_parameters`),
        for a controller or a plant (``hybrid.Experiment(controller_robot=found.robot)``).

        Raises
        ------
        HybridError
            The parameters are not physical (``consistent=False`` on poor data): identify with
            ``consistent=True``; or the nominal arm is the planar arm's closed form, whose parameters are its
            ``Arm``'s: identify its serial chain, ``dataclasses.replace(robot, closed_form=None)``.
        """
        if self.nominal_robot.closed_form is not None:
            raise HybridError("the planar arm's closed form takes no identified parameters (they are its Arm's); "
                              "for an identified robot, identify its serial chain: "
                              "dataclasses.replace(robot, closed_form=None)")
        return with_linear_parameters(self.nominal_robot, self.parameters)

    def torque(self, q, qd, qdd) -> np.ndarray:
        """The joint torques the identified model predicts, ``Y_b(q, q', q'') pi_b`` (the consistent
        estimate's base parameters; the least-squares one's with ``consistent=False``).

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
        Y, _ = regressor(self.nominal_robot, q, qd, qdd)
        return self.base.regressor(Y) @ (self.estimate if self.consistent is None else self.consistent)


def unexcited(W: np.ndarray, names, below: float = UNEXCITED) -> tuple[str, ...]:
    """The ``names`` of ``W``'s columns that lie in its singular directions (relative singular value
    below ``below``, default :data:`UNEXCITED`): the parameters the data cannot tell from combinations of
    the others (with a larger ``below``: those they tell apart worst)."""
    _, s, Vt = np.linalg.svd(W, full_matrices=True)
    s = np.concatenate([s, np.zeros(W.shape[1] - len(s))])  # fewer rows than columns: those directions too
    null = Vt[s < below * max(s[0], np.finfo(float).tiny)]
    share = np.linalg.norm(null, axis=0)
    return tuple(name for name, x in zip(names, share) if x > UNEXCITED_SHARE)


def _against_nominal(robot: Robot, signals: LogSignals, factors: np.ndarray, nominal: np.ndarray) -> None:
    """Refuse a log that is not the nominal arm's in the library's units: positions beyond the joints' limits
    by more than their range (degrees, or another zero), torques scaled from the nominal model's by more than
    :data:`UNITS_FACTOR` (other units), or a joint's torques running against the nominal model's (correlation
    below :data:`AGAINST`: its sign flipped). ``factors``' inner products are those of the regressor's rows
    and the torques."""
    joints = robot.joint_names
    if robot.limits is not None:
        lower, upper = (np.asarray(x, float) for x in (robot.limits.lower, robot.limits.upper))
        span = upper - lower
        beyond = (signals.q < lower - span) | (signals.q > upper + span)
        if beyond.any():
            k, j = np.argwhere(beyond)[0]
            raise HybridError(f"q[{signals.rows[k]}, {j}] = {signals.q[k, j]:.4g} (joint {joints[j]}) is beyond the "
                              f"joint's limits [{lower[j]:.4g}, {upper[j]:.4g}] by more than their span; give the "
                              "positions in radians and metres (numpy.radians of degrees), about the URDF's zero")
    p = len(nominal)
    predicted = factors[:, :, :p] @ nominal  # per joint, ||W_j pi_0|| and <W_j pi_0, tau_j> are these vectors'
    measured = factors[:, :, p]
    power = (predicted**2).sum(axis=1)
    if power.sum() <= 0:
        return
    scale = float((predicted * measured).sum() / power.sum())
    if scale < 0:
        raise HybridError(f"the logged torques are {scale:.3g} times the nominal model's along the log's motion (their "
                          "sign is flipped); give each joint's torque on its link, positive along its axis (-tau)")
    if not 1 / UNITS_FACTOR <= scale <= UNITS_FACTOR:
        raise HybridError(f"the logged torques are {scale:.3g} times the nominal model's along the log's motion; "
                          "give them in N m and N (N mm or mN m: / 1000) of the URDF's arm and joints, or its "
                          "placeholder masses rough values (robot.with_link)")
    # a joint's correlation with the nominal model: 0.7-1 where the model holds, down to -0.1 on wrists whose
    # torques are mostly friction or a payload the model lacks; a sign flipped where it holds gives -0.7 to -1
    norms = np.sqrt(power * (measured**2).sum(axis=1))
    correlation = (predicted * measured).sum(axis=1) / np.where(norms > 0, norms, np.inf)
    against = (correlation < AGAINST) & (power > 1e-12 * power.max())  # (a joint the model gives no torque: rounding)
    if against.any():
        j = int(np.argmax(against))
        raise HybridError(f"joint {joints[j]}'s logged torques run against the nominal model's along the log's motion "
                          f"(their sign flipped?); give each joint's torque positive along its axis (-tau[:, {j}])")


def joint_factors(robot: Robot, base: BaseParameters, signals: LogSignals) -> np.ndarray:
    """``(n, p + 1, p + 1)``: per joint ``j`` the triangular factor of ``[W_j t_j]`` (its rows of the
    base regressor and its torques), folded in a block of :data:`CHUNK` samples at a time; ``|F_j [x, -1]|``
    is the joint's residual norm for the base parameters ``x``."""
    n, p = robot.n, len(base.independent)
    factors = [np.zeros((0, p + 1))] * n
    for start in range(0, len(signals.q), CHUNK):
        part = slice(start, start + CHUNK)
        Y, _ = regressor(robot, signals.q[part], signals.qd[part], signals.qdd[part])
        if signals.sign is not None:  # the Coulomb columns filtered as the torques were (log_signals)
            Y[:, np.arange(n), coulomb_columns(n)] = signals.sign[part]
        rows = np.concatenate([base.regressor(Y).transpose(1, 0, 2), signals.tau[part].T[..., None]], axis=2)
        # one joint at a time: NumPy's batched QR is many times slower than its calls one by one
        factors = [np.linalg.qr(np.vstack([f, r]), mode="r") for f, r in zip(factors, rows)]
    return np.stack([np.vstack([f, np.zeros((p + 1 - len(f), p + 1))]) for f in factors])


def _scales(robot: Robot, base: BaseParameters, signals: LogSignals, torque: np.ndarray,
            speed: np.ndarray) -> np.ndarray:
    """Each base parameter's scale: its independent parameter's link scale (``m``, ``m l`` or ``m l^2`` of the
    nominal link), or for a joint's friction parameter the value that makes the joint's RMS torque ``torque``
    in the log (its viscosity's RMS speed ``speed``, its Coulomb friction's RMS smooth sign, its offset's 1)."""
    per_link = link_scales(*link_sizes(linear_parameters(robot), robot.n)).ravel()
    n = robot.n
    sign = np.tanh(signals.qd / np.asarray(robot.coulomb_speed)) if signals.sign is None else signals.sign
    column = {"damping": speed, "coulomb": np.sqrt((sign**2).mean(axis=0)), "offset": np.ones(n)}
    joint = [torque[k % n] / max(column[name.partition("[")[0]][k % n], 1e-300)
             for k, name in enumerate(base.names[len(per_link):])]
    return np.concatenate([per_link, joint])[list(base.independent)]


def _residual_rms(factors: np.ndarray, x: np.ndarray, samples: int) -> np.ndarray:
    """Per joint, the RMS over ``samples`` of the torque the base parameters ``x`` leave."""
    return np.linalg.norm(factors @ np.append(x, -1.0), axis=1) / math.sqrt(samples)


@checked_keywords
def identify_dynamics(robot: Robot, t, q, tau, *, qd=None, qdd=None, cutoff_hz=None, smooth: bool = True,
                      weighted: bool = True, consistent: bool = True) -> DynamicsIdentification:
    """The dynamics of ``robot`` identified from a log of its motion and joint torques.

    The log is filtered, differentiated and thinned (:mod:`hybrid.models.log_signals`: a zero-phase
    Butterworth low-pass on ``q`` and ``tau`` alike, central differences, the filter's edges dropped), the
    base parameters fitted by least squares (weighted: each joint's rows by the inverse of its torque
    noise's standard deviation, which an unweighted fit's residual estimates, as Gautier and Khalil's
    weighted least squares), and (``consistent=True``) the full parameters found nearest
    the data with every link a rigid body and frictions ``>= 0``
    (:mod:`hybrid.models.consistent_parameters`).

    Parameters
    ----------
    robot : Robot
        The arm: its structure and gravity give the regressor, its parameters the nominal model the
        estimate is reported beside (and the consistent estimate is regularised toward).
    t : array_like
        ``(N,)``: the samples' times [s], uniform (within 2 % of a step), at least 10 Hz.
    q : array_like
        ``(N, n)``: the joint positions [rad or m] of a trajectory that moves every joint over its range,
        with varied speeds and accelerations.
    tau : array_like
        ``(N, n)``: the joint torques measured [N m or N].
    qd, qdd : array_like or None
        ``(N, n)``: measured velocities and accelerations; None: differences of the filtered ``q``.
    cutoff_hz : float or None
        The low-pass filter's cutoff [Hz], below the Nyquist frequency; None: 20 Hz (at most a quarter of
        the sampling rate), for trajectories of a few hertz. Give 5 to 10 times the excitation's highest
        frequency for another.
    smooth : bool
        False: the log is taken as it is (no filter, no samples dropped but those the differences need):
        signals already filtered, or exact ones.
    weighted : bool
        Weight each joint's torques by the inverse of its noise's standard deviation (estimated from the
        unweighted fit's residual); False: ordinary least squares. Weighting matters where the joints'
        torques differ in size (a wrist's are a tenth of a shoulder's), and their noise with them: measured
        on the study of the how-to, the wrists' inertial parameters come out several times as accurate.
    consistent : bool
        Find the physically consistent full parameters (a convex program with cvxpy); False: least
        squares alone (``.robot`` then refuses parameters that are not physical).

    Returns
    -------
    DynamicsIdentification
        The estimates, their standard deviations, the residuals, the conditioning and the identified
        robot (``.robot``).

    Raises
    ------
    HybridError
        Arrays of the wrong shape or lengths, or not of real numbers (complex, boolean, text), a table (a
        DataFrame) of the joints in another order than the robot's, a sample not finite (named by its row and
        joint), times not strictly increasing or not uniform or sampled below 10 Hz (times in milliseconds),
        a cutoff not below the Nyquist frequency, a log too short for the filter and the parameters, a log
        not in the nominal arm's units or conventions (positions beyond the joints' limits by more than
        their span, as in degrees; torques more than 10 times larger or smaller than the nominal model's
        along the log, or of the opposite sign, all or one joint's), or a trajectory that does not excite
        every base parameter (named).

    Examples
    --------
    A UR5 whose links are 20 % heavier than its URDF says, logged at 1 kHz along a few sines:

    >>> import numpy as np
    >>> import hybrid
    >>> robot = hybrid.ur5()
    >>> heavier = robot.with_model_error(inertial=0.2)
    >>> t = np.arange(0, 20, 1e-3)[:, None]
    >>> w = 2 * np.pi * np.array([0.2, 0.5, 0.9, 1.4, 2.0, 2.7])
    >>> slow = 0.7 * w
    >>> q = np.sin(w * t) + np.sin(slow * t + 1)
    >>> qd = w * np.cos(w * t) + slow * np.cos(slow * t + 1)
    >>> qdd = -w**2 * np.sin(w * t) - slow**2 * np.sin(slow * t + 1)
    >>> Y, _ = hybrid.regressor(robot, q, qd, qdd)
    >>> tau = Y @ hybrid.linear_parameters(heavier)
    >>> found = hybrid.identify_dynamics(robot, t[:, 0], q, tau)
    >>> want = found.base.of(hybrid.linear_parameters(heavier))
    >>> error = np.abs(found.estimate - want).max()
    >>> bool(error < 1e-3 * np.abs(want).max()), found.cutoff_hz
    (True, 20.0)
    >>> # physically consistent: a controller's or a plant's robot
    >>> model = found.robot
    >>> error = np.abs(found.torque(q, qd, qdd) - tau).max()
    >>> bool(error < 2e-3 * np.abs(tau).max())
    True
    """
    robot = as_robot(robot)
    for flag, value, meaning in (("consistent", consistent, "physically consistent parameters"),
                                 ("weighted", weighted, "each joint weighted by its noise")):
        if not isinstance(value, (bool, np.bool_)):
            raise HybridError(f"{flag} = {value!r}; give True ({meaning}) or False")
    base = base_parameters(robot)
    p, n = len(base.independent), robot.n
    names = tuple(base.names[i] for i in base.independent)
    signals = log_signals(robot.joint_names, t, q, tau, qd=qd, qdd=qdd, cutoff_hz=cutoff_hz, smooth=smooth, least=p,
                          coulomb_speed=robot.coulomb_speed)
    M = len(signals.q)
    factors = joint_factors(robot, base, signals)
    nominal = base.of(linear_parameters(robot))
    _against_nominal(robot, signals, factors, nominal)
    whole = np.linalg.qr(factors.reshape(-1, p + 1), mode="r")
    R, z = whole[:p, :p], whole[:p, p]
    s = np.linalg.svd(R, compute_uv=False)
    if s[-1] < UNEXCITED * s[0]:
        missing = unexcited(R, names)
        raise HybridError(f"the samples do not excite the base parameters {listed(missing)}; excite the arm more (a "
                          "richer trajectory: every joint over its range, varied speeds and accelerations)"
                          + listed_in_full(missing))
    estimate = np.linalg.solve(R, z)
    rss = _residual_rms(factors, estimate, M) ** 2 * M
    dof = M - p / n  # each joint's share of the M n - p degrees of freedom
    variance = rss / dof if dof > 0 else np.full(n, np.nan)
    torque_rms, speed_rms = (np.sqrt((x**2).mean(axis=0)) for x in (signals.tau, signals.qd))
    if weighted and dof > 0 and (np.sqrt(variance) > 1e-9 * torque_rms).all():  # else the log is exact: no noise
        # each joint's rows over its noise's standard deviation, relative to their geometric mean (the rows keep
        # their scale: the consistent program's solver needs it), at most a million times apart
        sigma = np.sqrt(variance)
        sigma = np.maximum(sigma, 1e-6 * sigma.max())
        weights = np.exp(np.log(sigma).mean()) / sigma
        whole = np.linalg.qr((factors * weights[:, None, None]).reshape(-1, p + 1), mode="r")
        R, z = whole[:p, :p], whole[:p, p]
        estimate = np.linalg.solve(R, z)
        rss = _residual_rms(factors, estimate, M) ** 2 * M
        variance = rss / dof
    else:
        weights = np.ones(n)
    # the estimate's covariance (W^T O W)^-1 W^T O Sigma O W (W^T O W)^-1: O the weights squared (R's rows),
    # Sigma each joint's noise variance
    inverse = np.linalg.inv(R)
    bread = inverse @ inverse.T
    meat = np.einsum("j,jai,jak->ik", variance * weights**4, factors[:, :, :p], factors[:, :, :p])
    std = np.sqrt(np.clip(np.diag(bread @ meat @ bread), 0.0, None))
    floor = SIZE_FLOOR * _scales(robot, base, signals, torque_rms, speed_rms)
    size = np.maximum(np.maximum(np.abs(estimate), np.abs(nominal)), floor)
    poorly = tuple(name for name, sd, v in zip(names, std, size) if sd > POORLY_EXCITED * v)
    if consistent:
        parameters = consistent_parameters(
            robot, base, R, estimate, noise_variance=float((rss * weights**2).sum()) / max(M * n - p, 1), rows=M * n,
            torque_rms=torque_rms, speed_rms=speed_rms)
        fitted = base.of(parameters)
    else:
        parameters = linear_parameters(robot)
        parameters[list(base.independent)] = estimate - base.beta @ parameters[list(base.dependent)]
        fitted = None
    found = {"estimate": estimate, "std": std, "nominal": nominal, "parameters": parameters, "consistent": fitted,
             "residual_rms": np.sqrt(rss / M),
             "consistent_residual_rms": None if fitted is None else _residual_rms(factors, fitted, M)}
    for a in found.values():
        if a is not None:
            a.setflags(write=False)
    return DynamicsIdentification(robot, base, names, **found, condition=float(s[0] / s[-1]), poorly_excited=poorly,
                                  samples=M, log_samples=signals.log_samples,
                                  cutoff_hz=signals.cutoff_hz, sample_time=signals.sample_time)
