"""The paper's experiment as data: every setting of NOTES section 5, validated."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, fields, replace

import numpy as np

from .errors import HybridError
from .law import SINGULAR_TOL, check_singular_tol
from .parameters import Arm, Circle, Plane, _finite, _point, paper_arm
from .schemes import SCHEMES
from .validate import field_values

#: the schemes the NumPy reference path implements
NUMPY_SCHEMES = ("task", "khatib")
FRAMES = ("actual", "desired")
BACKENDS = ("sympy", "casadi", "numpy")


@dataclass(frozen=True)
class Step:
    """A reference that jumps from ``before`` to ``after`` at time ``at`` [s]."""

    before: float
    after: float
    at: float

    def __post_init__(self):
        _finite("Step", before=self.before, after=self.after, at=self.at)

    def __call__(self, t: float) -> float:
        return self.before if t < self.at else self.after

    def sampled(self, t: np.ndarray) -> np.ndarray:
        """The reference at each time of ``t`` [s] (one array operation)."""
        return np.where(np.asarray(t) < self.at, self.before, self.after).astype(float)

    def integral(self, t):
        """``int_0^t`` of the reference (arc length for a speed) [unit s]; ``t`` a time or an array."""
        if isinstance(t, np.ndarray):
            return self.before * np.minimum(t, self.at) + self.after * np.maximum(0.0, t - self.at)
        return self.before * min(t, self.at) + self.after * max(0.0, t - self.at)


@dataclass(frozen=True)
class Gains:
    """Loop gains of NOTES section 4 (task frame, per axis).

    Velocity: ``a_t = v_d' + KPv e_v + KIv int e_v + KI2v int int e_v``.
    Force: ``a_n = -KPf e_F - KDf v_n - KIf int e_F`` with ``e_F = F_d - F_c,n``.
    """

    KPv: float = 40.0     # 1/s
    KIv: float = 200.0    # 1/s^2
    KI2v: float = 1000.0  # 1/s^3
    KPf: float = 2.0      # 1/kg = 1/m_d
    KDf: float = 90.0     # 1/s = d_v/m_d
    KIf: float = 25.0     # 1/(kg s)

    def __post_init__(self):
        _finite("Gains", **field_values(self))
        for k, v in field_values(self).items():
            if v < 0:
                raise HybridError(f"gain {k} = {v} is negative; loop gains must be >= 0")


@dataclass(frozen=True)
class Sensor:
    """2-D elastic force sensor at the arm tip: tip mass on an isotropic spring-damper."""

    mass: float = 0.025       # m_s [kg]
    stiffness: float = 1000.0  # K_s [N/m]
    damping: float = 7.0      # D_s [N s/m]

    def __post_init__(self):
        _finite("Sensor", **field_values(self))
        if self.mass <= 0 or self.stiffness <= 0 or self.damping < 0:
            raise HybridError(f"Sensor needs mass > 0, stiffness > 0, damping >= 0; got {self}")


@dataclass(frozen=True)
class Contact:
    """Rigid surface as a unilateral penalty ``N = max(0, k_e delta + d_e delta')``, Coulomb friction."""

    stiffness: float = 1e5        # k_e [N/m]
    damping: float = 50.0         # d_e [N s/m]
    friction: float = 0.2         # gamma
    friction_smoothing: float = 1e-3  # v_eps of tanh(v_t / v_eps) [m/s]

    def __post_init__(self):
        _finite("Contact", **field_values(self))
        if self.stiffness <= 0 or self.damping < 0 or self.friction < 0 or self.friction_smoothing <= 0:
            raise HybridError("Contact needs stiffness > 0, damping >= 0, friction >= 0, "
                              f"friction_smoothing > 0; got {self}")


class RunSettings:
    """What every experiment derives from its settings (a mixin of the experiment dataclasses)."""

    @property
    def steps_per_sample(self) -> int:
        return round(self.sample_time / self.step)

    @property
    def n_samples(self) -> int:
        return math.ceil(self.duration / self.sample_time - 1e-9)

    def effective_gains(self) -> Gains:
        """The gains in force: without integral action ``KI2v = KIf = 0`` (NOTES section 4)."""
        return self.gains if self.integral else replace(self.gains, KI2v=0.0, KIf=0.0)

    def pressed_at(self, point, normal) -> tuple[np.ndarray, np.ndarray]:
        """The sensor tip ``s`` and the arm tip ``r`` at rest, the sensor tip on the surface at
        ``point`` (unit ``normal``) pressing with ``F_d(0)``: it penetrates ``F/k_e`` (the surface in
        equilibrium) and the arm tip sits ``F/K_s`` beyond it (the sensor spring in equilibrium)."""
        return pressed(point, normal, self.force_reference(0.0), self.contact.stiffness, self.sensor.stiffness)

    def plant_array(self) -> np.ndarray:
        """The ``plant[7]`` array of the generated C (sensor, then contact)."""
        s, c = self.sensor, self.contact
        return np.array([s.mass, s.stiffness, s.damping, c.stiffness, c.damping, c.friction,
                         c.friction_smoothing])


def pressed(point, normal, F0: float, k_e: float, K_s: float) -> tuple[np.ndarray, np.ndarray]:
    """:meth:`RunSettings.pressed_at` from the numbers it reads: the force ``F0`` [N], the surface's
    stiffness ``k_e`` and the sensor's ``K_s`` [N/m]."""
    s = np.asarray(point, float) - normal * max(F0, 0.0) / k_e
    return s, s - normal * F0 / K_s


@dataclass(frozen=True)
class Experiment(RunSettings):
    """One closed-loop run: plant, controller, references, integration settings.

    ``arm`` is the true arm; the controller's model is ``arm.with_model_error(model_error,
    viscous_compensation)``. ``frame``: task frame at the actual contact point ``R(r)`` or
    at the desired one ``R(r_d)`` (the paper's Figure 3). ``backend``: which committed unit
    runs the plant and the law in the Python runner (a run in the compiled loop,
    :mod:`hybrid.closed_loop`, does not depend on it), or ``"numpy"`` for the plain NumPy
    reference path.
    ``singular_tol``: the run stops when ``2 |det J| / |J|_F^2`` (about ``|sin q2|``) at a
    control sample falls below it.
    """

    controller: str = "task"
    integral: bool = True
    curvature: bool = False
    frame: str = "actual"
    model_error: float = 0.1
    viscous_compensation: float = 0.5
    arm: Arm = field(default_factory=paper_arm)
    surface: Circle | Plane = field(default_factory=lambda: Circle(center=(0.5, 0.0), radius=0.2))
    start_point: tuple[float, float] = (0.3, 0.0)
    elbow: int = 1
    sensor: Sensor = field(default_factory=Sensor)
    contact: Contact = field(default_factory=Contact)
    gains: Gains = field(default_factory=Gains)
    force_reference: Step = field(default_factory=lambda: Step(10.0, 20.0, 0.4))
    speed_reference: Step = field(default_factory=lambda: Step(0.3, 0.6, 1.0))
    duration: float = 2.0
    step: float = 1e-4
    sample_time: float = 1e-2
    backend: str = "sympy"
    singular_tol: float = SINGULAR_TOL

    def __post_init__(self):
        self._check_types()
        if self.controller not in SCHEMES:
            raise HybridError(f"unknown controller {self.controller!r}; choose one of {tuple(SCHEMES)}")
        if self.backend == "numpy" and self.controller not in NUMPY_SCHEMES:
            raise HybridError(f"the NumPy reference runs {' and '.join(NUMPY_SCHEMES)} only; use backend 'sympy' "
                              f"for {self.controller}")
        if self.backend not in BACKENDS:
            raise HybridError(f"unknown backend {self.backend!r}; choose one of {BACKENDS}")
        if not isinstance(self.arm, Arm):
            raise HybridError(f"arm must be a hybrid.Arm, got {type(self.arm).__name__}")
        if not isinstance(self.surface, (Circle, Plane)) or self.surface.dim != 2:
            raise HybridError(f"unknown surface {self.surface!r:.60} for the paper's experiment; give a "
                              "hybrid.Circle or a 2-D hybrid.Plane")
        if self.elbow not in (1, -1):
            raise HybridError(f"elbow = {self.elbow}; give +1 (q2 > 0) or -1 (q2 < 0)")
        check_timing(self)

    def _check_types(self) -> None:
        """Every field of the kind it must be: a bool is a bool, a reference a Step or a number."""
        check_common_types(self)
        if not isinstance(self.backend, str):
            raise HybridError(f"backend = {self.backend!r}; give its name as a string")
        if isinstance(self.elbow, bool) or not isinstance(self.elbow, (int, np.integer)):
            raise HybridError(f"elbow = {self.elbow!r}; give +1 (q2 > 0) or -1 (q2 < 0)")
        object.__setattr__(self, "start_point", _point("Experiment", "start_point", self.start_point))

    def desired_point(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``r_d(t)`` [m] on the surface, reached from ``start_point`` at the desired speed, and
        ``r_d'(t)`` [m/s] (along the tangent ``t = (-n_y, n_x)``)."""
        surf, vref = self.surface, self.speed_reference
        p = surf.at(surf.arc_coordinate(self.start_point) + vref.integral(t))
        n = surf.normal_at(p)
        return p, vref(t) * np.array([-n[1], n[0]])

    def controller_arm(self) -> Arm:
        """The controller's (wrong) model of the arm."""
        return self.arm.with_model_error(self.model_error, self.viscous_compensation)

    def to_dict(self) -> dict:
        d = asdict(self)
        d["surface"] = {"kind": self.surface.kind, **asdict(self.surface)}
        return d

    @classmethod
    def from_dict(cls, d: dict) -> Experiment:
        """The experiment :meth:`to_dict` wrote; anything else is a HybridError."""
        try:
            return cls._from_dict(d)
        except (KeyError, TypeError, AttributeError, ValueError) as exc:
            if isinstance(exc, HybridError):
                raise
            raise HybridError(f"not an experiment's settings ({type(exc).__name__}: {exc})") from None

    @classmethod
    def _from_dict(cls, d: dict) -> Experiment:
        d = dict(d)
        surf = dict(d.pop("surface"))
        kind = surf.pop("kind")
        surface = Circle(**surf) if kind == "circle" else Plane(**surf)
        parts = {"arm": Arm, "sensor": Sensor, "contact": Contact, "gains": Gains,
                 "force_reference": Step, "speed_reference": Step}
        for k, typ in parts.items():
            d[k] = typ(**d[k])
        d["start_point"] = tuple(d["start_point"])
        return cls(surface=surface, **d)



def check_common_types(exp) -> None:
    """The fields every experiment shares, of the kind they must be (references given as numbers
    become constant :class:`Step` references)."""
    owner = type(exp).__name__
    for name in ("integral", "curvature"):
        if not isinstance(getattr(exp, name), bool):
            raise HybridError(f"{name} = {getattr(exp, name)!r}; give True or False")
    for name in ("controller", "frame"):
        if not isinstance(getattr(exp, name), str):
            raise HybridError(f"{name} = {getattr(exp, name)!r}; give its name as a string")
    for name, typ in (("sensor", Sensor), ("contact", Contact), ("gains", Gains)):
        if not isinstance(getattr(exp, name), typ):
            raise HybridError(f"{name} = {getattr(exp, name)!r:.60}; give a hybrid.{typ.__name__}(...)")
    for name in ("force_reference", "speed_reference"):
        ref = getattr(exp, name)
        if isinstance(ref, (int, float, np.integer, np.floating)) and not isinstance(ref, bool):
            _finite(owner, **{name: ref})
            object.__setattr__(exp, name, Step(float(ref), float(ref), 0.0))  # a constant reference
        elif not isinstance(ref, Step):
            raise HybridError(f"{name} = {ref!r:.60}; give a hybrid.Step(before, after, at) or a number")
    _finite(owner, model_error=exp.model_error, viscous_compensation=exp.viscous_compensation)
    if exp.frame not in FRAMES:
        raise HybridError(f"unknown frame {exp.frame!r}; choose one of {FRAMES}")
    check_singular_tol(owner, exp.singular_tol)


def check_timing(exp) -> None:
    """The run's timing and physics settings, checked alike for every experiment: duration, RK4 step
    and sample time (whole multiples, fast enough for the contact), model error, stable loops."""
    owner = type(exp).__name__
    _finite(owner, duration=exp.duration, step=exp.step, sample_time=exp.sample_time)
    if exp.duration <= 0:
        raise HybridError(f"duration = {exp.duration} s; give a positive duration")
    if exp.step <= 0 or exp.sample_time <= 0:
        raise HybridError(f"step = {exp.step} s and sample_time = {exp.sample_time} s must be positive")
    ratio = exp.sample_time / exp.step
    if not math.isfinite(ratio) or ratio > 1e9:
        raise HybridError(f"step = {exp.step} s is too small for sample_time = {exp.sample_time} s "
                          "(over 1e9 steps a sample); give a step of at least sample_time / 1e9")
    if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
        raise HybridError(f"sample_time = {exp.sample_time} s is not a whole multiple of step = "
                          f"{exp.step} s; choose step = sample_time / k for a whole k")
    # fastest plant mode: sensor mass on the contact (and sensor) spring-dampers
    rate = max(math.sqrt((exp.contact.stiffness + exp.sensor.stiffness) / exp.sensor.mass),
               (exp.contact.damping + exp.sensor.damping) / exp.sensor.mass)
    if exp.step * rate > 1.0:
        raise HybridError(
            f"step = {exp.step} s is too large for the contact: its fastest mode is {rate:.3g} rad/s "
            f"and RK4 needs step * rate <= 1 for accuracy; use step <= {1.0 / rate:.2e} s")
    if exp.model_error <= -1 or exp.viscous_compensation < 0:
        raise HybridError(f"model_error = {exp.model_error} must be > -1 and viscous_compensation = "
                          f"{exp.viscous_compensation} >= 0")
    if abs(exp.duration / exp.sample_time - round(exp.duration / exp.sample_time)) > 1e-9 * exp.n_samples:
        k = max(1, round(exp.duration / exp.sample_time))
        raise HybridError(f"duration = {exp.duration} s is not a whole number of samples of "
                          f"{exp.sample_time} s; give duration = {k * exp.sample_time:g} s")
    from .loops import check_loops

    check_loops(exp)


#: short names of the references
REFERENCE_ALIASES = {"F_d": "force_reference", "v_d": "speed_reference"}


def setting_aliases() -> dict[str, str]:
    """Short names of settings and the paths they stand for: ``F_d`` / ``v_d`` for the references,
    each gain by its own name (``KPf`` for ``gains.KPf``)."""
    return {**REFERENCE_ALIASES, **{f.name: f"gains.{f.name}" for f in fields(Gains)}}


def with_overrides(cls, maker: str, overrides: dict):
    """``cls(**overrides)`` where the gains may also be given one by one (``KPv=50``) and ``F_d`` /
    ``v_d`` name the force / speed references; an unknown name lists the known ones."""
    names = {f.name for f in fields(cls)}
    gain_names = {f.name for f in fields(Gains)}
    aliases = REFERENCE_ALIASES
    gains = {k: overrides.pop(k) for k in list(overrides) if k in gain_names}
    for alias, name in aliases.items():
        if alias in overrides:
            overrides[name] = overrides.pop(alias)
    unknown = sorted(set(overrides) - names)
    if unknown:
        raise HybridError(f"unknown setting(s) {', '.join(unknown)} for {maker}; see the known ones below\n"
                          f"  known: {', '.join(sorted(names | gain_names | set(aliases)))}")
    if gains:
        base = overrides.get("gains", Gains())
        if not isinstance(base, Gains):
            raise HybridError(f"gains = {base!r:.60}; give a hybrid.Gains(...) to combine with {', '.join(gains)}")
        overrides["gains"] = replace(base, **gains)
    return cls(**overrides)


def paper_experiment(**overrides) -> Experiment:
    """The paper's experiment (NOTES section 5), with any setting overridden by keyword.

    Besides every field of :class:`Experiment`, the gains can be given one by one
    (``KPv=50``) and ``F_d`` / ``v_d`` replace the force / speed references.
    """
    return with_overrides(Experiment, "paper_experiment", overrides)
