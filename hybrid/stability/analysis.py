"""Whether an experiment's sampled loops are stable, and by what margin: :func:`stability`.

The model is :mod:`hybrid.stability.model`'s, at the experiment's start (:mod:`hybrid.stability.experiment_loops`).
Each task axis's loop is judged alone (the axis's own mobility, gain and viscosity: the decoupled loop
the law makes), with its gain, phase and delay margins cut at the command ``a`` (python-control); the
whole closed loop, every axis coupled through the arm's inertia between samples, gives the verdict.
"""

from __future__ import annotations

import cmath
import math
import warnings
from dataclasses import dataclass, replace

import numpy as np

from hybrid.errors import HybridError
from hybrid.stability.experiment_loops import (
    MATRICES,
    arm_terms_at_start,
    axis_names,
    check_delay,
    check_experiment,
    loop_numbers,
)
from hybrid.stability.model import Structure, closed_loop
from hybrid.validate import checked_keywords


@checked_keywords
@dataclass(frozen=True)
class LoopStability:
    """One task axis's sampled loop, judged alone.

    Parameters
    ----------
    axis : str
        The task axis (``"t1"``, ``"n"``, ``"rot_t1"``, ...).
    loop : str
        ``"force"`` or ``"velocity"``.
    spectral_radius : float
        The largest modulus of the loop's poles (stable below 1; ``inf`` when a gain overflows).
    poles : numpy.ndarray
        The closed loop's poles (``z``-plane).
    damping, natural_frequency_hz : float
        The dominant pole's damping ratio and natural frequency [Hz] (of ``s = ln(z) / T``).
    gain_margin_db, phase_margin_deg : float
        The loop's gain margin [dB] (how far its gain may rise or fall: :func:`gain_margin`) and phase margin
        [deg], cut at the command ``a`` (``inf``: none; NaN for an unstable loop or without margins).
    delay_margin_samples : int
        How many more whole samples the force reading may be late with the loop still stable (the law's
        compensation is late with it): 0, not one more (and for an unstable loop).

    Examples
    --------
    >>> import hybrid
    >>> force = hybrid.stability(hybrid.paper_experiment()).loop("n")
    >>> force.loop, force.stable, force.delay_margin_samples >= 1
    ('force', True, True)
    """

    axis: str
    loop: str
    spectral_radius: float
    poles: np.ndarray
    damping: float
    natural_frequency_hz: float
    gain_margin_db: float
    phase_margin_deg: float
    delay_margin_samples: int

    @property
    def stable(self) -> bool:
        """Whether every pole lies inside the unit circle."""
        return self.spectral_radius < 1.0


@checked_keywords
@dataclass(frozen=True)
class Stability:
    """An experiment's sampled loops: each axis's (:class:`LoopStability`) and the whole's.

    Parameters
    ----------
    loops : tuple of LoopStability
        One per task axis, in the controller's order.
    spectral_radius : float
        The spectral radius of the whole closed loop (every axis, coupled through the arm): the verdict
        (each loop alone is its own :class:`LoopStability`).
    sample_time : float
        ``T`` [s].

    Examples
    --------
    A stiffer sensor on the paper's experiment (10 ms samples):

    >>> import hybrid
    >>> sensor = hybrid.Sensor(stiffness=2e4)
    >>> exp = hybrid.paper_experiment(sensor=sensor,
    ...                               allow_unstable=True)
    >>> stiff = hybrid.stability(exp)
    >>> stiff.stable, round(stiff.spectral_radius, 2)
    (False, 1.24)
    >>> sorted(stiff.table().columns)[:3]
    ['damping', 'delay_margin_samples', 'gain_margin_db']
    """

    loops: tuple[LoopStability, ...]
    spectral_radius: float
    sample_time: float

    @property
    def stable(self) -> bool:
        """Whether the whole closed loop is stable (its spectral radius below 1)."""
        return self.spectral_radius < 1.0

    def loop(self, axis: str) -> LoopStability:
        """The loop of one task axis.

        Parameters
        ----------
        axis : str
            The axis's name (``"n"``, ``"t1"``, ...).

        Returns
        -------
        LoopStability
            Its loop.

        Raises
        ------
        HybridError
            No task axis of that name.
        """
        for loop in self.loops:
            if loop.axis == axis:
                return loop
        raise HybridError(f"no task axis {axis!r}; the loops are {', '.join(x.axis for x in self.loops)}")

    def table(self):
        """The loops as a table.

        Returns
        -------
        pandas.DataFrame
            One row per task axis (its index), a column per :class:`LoopStability` number.
        """
        import pandas as pd

        rows = [{k: getattr(loop, k) for k in ("axis", "loop", "spectral_radius", "damping", "natural_frequency_hz",
                                               "gain_margin_db", "phase_margin_deg", "delay_margin_samples", "stable")}
                for loop in self.loops]
        return pd.DataFrame(rows).set_index("axis")

    def __str__(self) -> str:
        verdict = "stable" if self.stable else "UNSTABLE"
        lines = [f"sampled loops at T = {self.sample_time:g} s: {verdict} (spectral radius "
                 f"{shown_radius(self.spectral_radius)})"]
        for x in self.loops:
            late = f"{'>= ' * (x.delay_margin_samples == MOST_DELAY)}{x.delay_margin_samples}"
            lines.append(f"  {x.axis:7s} {x.loop:8s} radius {shown_radius(x.spectral_radius)}  damping "
                         f"{x.damping:.3g}  {x.natural_frequency_hz:.3g} Hz  GM {x.gain_margin_db:.3g} dB  PM "
                         f"{x.phase_margin_deg:.3g} deg  delay margin {late} samples")
        return "\n".join(lines)


def shown_radius(radius: float, digits: int = 4) -> str:
    """``radius`` to ``digits`` significant digits, or as many more as tell it from 1 (a radius of
    0.99999 is stable, and does not print as 1)."""
    for d in range(digits, 18):
        text = f"{radius:.{d}g}"
        if radius == 1.0 or not math.isfinite(radius) or float(text) != 1.0:
            break
    return text


@checked_keywords
def stability(exp, *, margins: bool = True) -> Stability:
    """The stability of ``exp``'s sampled loops and their margins, from their small-signal model.

    Parameters
    ----------
    exp : Experiment
        Any experiment with a force axis; its loops are taken in contact at its start.
    margins : bool
        Work out each loop's gain, phase and delay margins (python-control); False leaves them NaN
        (faster).

    Returns
    -------
    Stability
        Per axis and for the whole closed loop.

    Raises
    ------
    HybridError
        The experiment's start cannot be worked out, it has no force axis, or its reading is later than the
        model takes (:data:`~hybrid.stability.experiment_loops.MOST_DELAY_SAMPLES`).

    Examples
    --------
    >>> import hybrid
    >>> report = hybrid.stability(hybrid.paper_experiment())
    >>> report.stable, round(report.loop("n").spectral_radius, 3)
    (True, 0.888)
    """
    check_experiment(exp, "stability")
    if not isinstance(margins, (bool, np.bool_)):
        raise HybridError(f"margins = {margins!r}; give True (work out the margins) or False")
    st, p, names = _loops(exp)
    return stability_of(st, p, names, margins=margins)


def _loops(exp) -> tuple[Structure, dict, tuple[str, ...]]:
    """``exp``'s model (:func:`~hybrid.stability.experiment_loops.loop_numbers`) and its axes' names, the arm's
    terms at the start worked out once."""
    terms = arm_terms_at_start(exp)
    st, p = loop_numbers(exp, terms)
    return st, p, axis_names(terms["axes"])


def stability_of(st: Structure, p: dict, names, *, margins: bool = True) -> Stability:
    """:func:`stability` from the model's numbers (one setting, no batch axes)."""
    T = float(p["sample_time"])
    loops = []
    for i, name in enumerate(names):
        sub, q = axis_alone(st, p, i)
        with np.errstate(all="ignore"):
            m = closed_loop(sub, q)
        poles = _poles(m["A"])
        radius = _radius(poles)
        damping, frequency = _dominant(poles, T)
        ok = margins and radius < 1.0
        gm = 20 * math.log10(gain_margin(sub, q)) if ok else math.nan
        pm = _phase_margin(m, T) if ok else math.nan
        late = delay_margin(sub, q) if ok else 0
        loops.append(LoopStability(name, "force" if st.force[i] else "velocity", radius, poles, damping, frequency,
                                   gm, pm, late))
    return Stability(tuple(loops), _whole_radius(st, p), T)


def axis_alone(st: Structure, p: dict, i: int) -> tuple[Structure, dict]:
    """The structure and numbers of task axis ``i`` alone (its diagonal entries of the matrices)."""
    sub = replace(st, force=(st.force[i],), linear=(st.linear[i],), integrals=(st.integrals[i],))
    q = dict(p)
    for k in MATRICES:
        if k in q:
            M = np.asarray(q[k], float)
            q[k] = M[..., i:i + 1, i:i + 1]
    return sub, q


def loop_radius(st: Structure, p: dict):
    """The spectral radius of the closed loop of ``st`` and ``p`` (a float), or of each of a batch of them
    (an array): ``inf`` for a loop whose matrix overflows, that one alone."""
    with np.errstate(all="ignore"):
        A = closed_loop(st, p)["A"]
    finite = np.isfinite(A).all(axis=(-2, -1))
    radius = np.full(A.shape[:-2], np.inf)
    if finite.any():
        try:
            radius[finite] = np.abs(np.linalg.eigvals(A[finite])).max(axis=-1)
        except np.linalg.LinAlgError:  # no convergence somewhere (entries near overflow): each alone
            radius[finite] = [_radius(_poles(a)) for a in A[finite]]
    return float(radius) if radius.ndim == 0 else radius


def _poles(A: np.ndarray) -> np.ndarray:
    if not np.isfinite(A).all():
        return np.full(A.shape[:-1], np.inf, dtype=complex)
    try:
        return np.linalg.eigvals(A)
    except np.linalg.LinAlgError:  # no convergence: entries near overflow, unstable by far
        return np.full(A.shape[:-1], np.inf, dtype=complex)


def _radius(poles: np.ndarray) -> float:
    r = np.max(np.abs(poles), axis=-1)
    return np.where(np.isfinite(r), r, np.inf) if np.ndim(r) else (float(r) if math.isfinite(r) else math.inf)


def _dominant(poles: np.ndarray, T: float) -> tuple[float, float]:
    """The damping ratio and natural frequency [Hz] of the pole of largest modulus."""
    if not np.isfinite(poles).all():
        return math.nan, math.nan
    z = poles[np.argmax(np.abs(poles))]
    if abs(z) == 0:
        return 1.0, math.inf
    s = np.log(complex(z)) / T
    wn = abs(s)
    return (-s.real / wn if wn else 1.0), wn / (2 * math.pi)


def _phase_margin(m: dict, T: float) -> float:
    """The phase margin [deg] of one axis's loop cut at its command (python-control); ``inf``: none.

    python-control finds the gain crossings as the roots of a polynomial, which for these loops (integrators,
    a delay, a lightly damped sensor) holds spurious ones (``|L|`` = 13 there on the paper's velocity loop)
    and inexact ones (``|L|`` = 0.985 at 1 ms): each is taken as a guess, refined on the loop's own response
    (:func:`_crossing_near`), and dropped when no crossing is near it.
    """
    import control

    A, B, C = m["A_open"], m["B_open"], m["command"][..., :m["A_open"].shape[-1]]
    loop = control.ss(A, -B, C, np.zeros((1, 1)), dt=T)  # the loop closes with u = C X: positive feedback
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its note that it computes on the frequency response: the same margin
        _, _, _, _, guesses, _ = control.stability_margins(loop, returnall=True)

        def response(w: float) -> complex:  # L(e^{jwT}) closed by negative feedback: margin = 180 - |phase|
            return complex(np.asarray(loop(np.exp(1j * w * T))).reshape(-1)[0])

        found = [_crossing_near(response, w, math.pi / T) for w in np.atleast_1d(guesses) if np.isfinite(w) and w > 0]
        phases = [180.0 - abs(math.degrees(cmath.phase(response(w)))) for w in found if w is not None]
    return float(min(phases)) if phases else math.inf


def _crossing_near(response, w: float, nyquist: float) -> float | None:
    """The frequency nearest ``w`` (within 30 %, below ``nyquist``) where ``|response|`` crosses 1, to
    rounding (Brent's method on the bracket found); None when there is none."""
    from scipy.optimize import brentq

    def excess(x: float) -> float:
        return abs(response(x)) - 1.0

    here = excess(w) > 0
    for k in range(1, 15):  # outward in steps of 2 %, both ways
        for other in (w * 1.02 ** k, w / 1.02 ** k):
            if other < nyquist and (excess(other) > 0) != here:
                lo, hi = sorted((w, other))
                return float(brentq(excess, lo, hi, xtol=1e-12 * hi))
    return None


#: the largest loop gain factor :func:`gain_margin` looks for
MOST_GAIN = 1e3


def gain_margin(st: Structure, p: dict) -> float:
    """The factor by which the loop's gain may rise, or fall, with the loop still stable (the smaller of the
    two, as a factor >= 1): the command ``a`` times it (``M``, a controller's model that much heavier, or
    lighter, than the arm); ``inf`` past :data:`MOST_GAIN` both ways.

    A loop with integrals is stable only above a gain too (a PI² loop needs ``KPv KIv`` above
    ``KI2v``): a margin that looked up only would miss it. Found on the model itself (bisection on the
    spectral radius), exact where a loop transfer function's phase crossings (at the Nyquist frequency
    among them) are easily missed.
    """
    def radius(k: np.ndarray) -> np.ndarray:  # of the loop at each gain factor of k, in one batch
        q = {name: np.broadcast_to(np.asarray(v, float), k.shape + np.shape(v)) for name, v in p.items()}
        gain = q["gain"] * k.reshape(k.shape + (1,) * np.ndim(p["gain"]))
        return np.atleast_1d(loop_radius(st, dict(q, gain=gain)))

    down = _stable_through(radius, 0.8)
    return min(_stable_through(radius, 1.25), 1.0 / down if down > 0 else math.inf)


def _stable_through(radius, step: float) -> float:
    """The gain factor up to which (``step`` > 1) or down to which (``step`` < 1) the loop stays stable:
    its powers of ``step``, then the bracket they find narrowed sixteenfold ten times (to about 1e-12);
    ``inf`` (``0``) past :data:`MOST_GAIN` (its inverse)."""
    steps = step ** np.arange(1, math.floor(math.log(MOST_GAIN) / abs(math.log(step))) + 1)
    lost = np.flatnonzero(~(radius(steps) < 1.0))
    if not lost.size:
        return math.inf if step > 1 else 0.0
    lo, hi = (steps[lost[0] - 1] if lost[0] else 1.0), steps[lost[0]]
    for _ in range(10):
        inner = lo * (hi / lo) ** (np.arange(1, 16) / 16)
        lost = np.flatnonzero(~(radius(inner) < 1.0))
        lo, hi = (inner[lost[0] - 1] if lost[0] else lo, inner[lost[0]]) if lost.size else (inner[-1], hi)
    return float(lo)


#: how many extra samples of the reading's delay :func:`delay_margin` tries
MOST_DELAY = 20


def delay_margin(st: Structure, p: dict) -> int:
    """How many more whole samples the reading may be late with the loop still stable (0: not one more;
    :data:`MOST_DELAY` at most)."""
    for extra in range(1, MOST_DELAY + 1):
        if not loop_radius(replace(st, delay=st.delay + extra), p) < 1.0:
            return extra - 1
    return MOST_DELAY


#: what each kind of loop needs to be stable (conventions §4, §15), said when one is not
NEEDS = {"force": "needs KDf*KPf > KIf, KDf*T well below 2 and sqrt(KPf*k)*T well below 2 (k the sensor and the "
                  "contact in series)",
         "velocity": "needs KPv*KIv > KI2v and KPv*T well below 2"}


def check_stable(exp) -> None:
    """Refuse ``exp`` when its sampled loops are predicted unstable, unless ``exp.allow_unstable``.

    Raises
    ------
    HybridError
        A loop, or the loops coupled, with a spectral radius of at least 1: which, why, what to change; a
        reading later than the model takes.
    """
    if exp.allow_unstable:
        return
    check_delay(exp.sensor.delay_samples)
    try:
        st, p, names = _loops(exp)
    except HybridError:
        return  # no start to take the loops at: the run refuses it, saying why
    if _whole_radius(st, p) < 1.0:
        return
    report = stability_of(st, p, names, margins=False)  # which loop, to say so
    unstable = [x for x in report.loops if not x.stable]
    g, T = exp.effective_gains(), exp.sample_time
    if unstable:
        x = max(unstable, key=lambda loop: loop.spectral_radius)
        what, rule = f"the {x.loop} loop on {x.axis}", NEEDS[x.loop]
        radius = x.spectral_radius
    else:
        what, rule = "the loops coupled through the arm", "each is stable alone: lower the gains or sample_time"
        radius = report.spectral_radius
    why = (f"spectral radius {shown_radius(radius, 3)} >= 1" if math.isfinite(radius) else
           f"a gain times sample_time or the stiffness overflows: {_largest(g)}")
    scale = np.diag(np.asarray(p["gain"], float))
    note = (f"; the controller's model scales every loop's gain by {scale.max():.3g} (model_error)"
            if abs(scale.max() - 1.0) > 1e-6 else "")
    raise HybridError(
        f"{what} is unstable at sample_time {T} s ({why}): lower the gains, soften the sensor or shorten sample_time, "
        "or give allow_unstable=True to run it anyway\n"
        f"  it {rule}{note}; hybrid.stability(exp) gives the margins\n"
        f"  gains {g}, sensor {exp.sensor.stiffness:g} N/m, contact {exp.contact.stiffness:g} N/m")


def _whole_radius(st: Structure, p: dict) -> float:
    """The whole closed loop's spectral radius (the verdict: each loop alone is worked out only to say which
    is unstable), remembered: a sweep's runs mostly share their loops."""
    key = (st, tuple((k, np.asarray(v, float).tobytes()) for k, v in sorted(p.items())))
    found = _RADII.get(key)
    if found is None:
        found = _RADII[key] = loop_radius(st, p)
        if len(_RADII) > 4096:
            _RADII.pop(next(iter(_RADII)))
    return found


_RADII: dict = {}


def _largest(g) -> str:
    name, value = max(vars(g).items(), key=lambda item: item[1])
    return f"{name} = {value:.3g}"


def predicted_note(exp) -> str:
    """Why a run diverged, when its loops were predicted unstable (run with ``allow_unstable``), or ``""``."""
    if not exp.allow_unstable:
        return ""
    try:
        st, p, _ = _loops(exp)
    except HybridError:
        return ""
    radius = _whole_radius(st, p)
    if radius < 1.0:
        return ""
    return (f"its loops were predicted unstable (spectral radius {shown_radius(radius, 3)}; it ran "
            "with allow_unstable=True): hybrid.stability(exp) says which")
