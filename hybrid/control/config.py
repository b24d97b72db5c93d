"""A controller described in a TOML file: ``read_controller_config(path, robot)`` is the
:class:`~hybrid.Controller` it describes (``python -m hybrid generate --controller FILE``).

The file gives the Controller's keywords but the robot. Every key is optional except the
surface's; a key left out takes the Controller's default. TOML has no null: ``"none"`` turns an
option off where the Controller takes None. ``hybrid/data/controller_ur5_sphere.toml`` is a
commented example (the shipped UR5 tracing a sphere).

Top level
    ``scheme``: ``"task"`` (default), ``"khatib"``, ``"raibert_craig"``, ``"fisher_mujtaba"``.
    ``sample_time`` [s] (default 0.01). ``integral``, ``curvature``, ``position_error``: true or
    false (defaults true, false, false). ``frame``: ``"actual"`` (default) or ``"desired"``.
    ``singular_tol`` (default 1e-3).
``[surface]`` (required)
    ``kind`` and its parameters [m]: ``"plane"`` (``point``, ``normal``: 3 numbers, or 2 for a
    vertical plane), ``"sphere"`` (``center``, ``radius``), ``"cylinder"`` (``point``, ``axis``,
    ``radius``), ``"circle"`` (``center`` = (x, y), ``radius``: the vertical cylinder through it),
    ``"implicit"`` (``phi``, a formula of x, y, z, as text; ``parameters``, a table of its other
    symbols' values).
``[task]``
    ``axes``: ``"all"`` (default for a 6-joint arm), ``"position"``, ``"planar"``, or a list of axis
    names (``t1``, ``t2``, ``n``, ``rot_t1``, ``rot_t2``, ``rot_n``). ``selection``: the
    force-controlled axes, a name or a list of names (default ``["n"]``; ``[]``: none).
    ``frame_direction``: the task frame's direction ``e``, 3 numbers in base axes (default z;
    ``reference``, its old name, reads too, with a warning).
``[gains]``
    ``KPv, KIv, KI2v`` (velocity axes), ``KPf, KDf, KIf`` (force axes): numbers >= 0 for every
    axis (the rest keep :class:`~hybrid.Gains`' defaults). ``[gains.AXIS]`` (e.g. ``[gains.n]``): the
    same keys for one axis, over those of ``[gains]``.
``[references]``
    ``force`` [N, N m] and ``velocity`` [m/s, rad/s]. Each is a number (the normal force, the speed
    along ``t1``), a step ``{before = ..., after = ..., at = ...}`` (``at`` in s), or a table of
    axis names, each with a number or a step (``[references.velocity]`` ``t1 = 0.1``). Other axes'
    references are 0; default 10 N on the normal.
``[limits]``
    ``torque``: ``"urdf"`` (default: the URDF's effort limits), ``"none"``, a number or one per joint
    [N m or N]. ``torque_step``: the largest torque change per sample, ``"none"`` (default), a number
    or one per joint. ``timing_tolerance``: a fraction of the sample time (default 0.25), or
    ``"none"``. ``integral``: anti-windup, the largest integral action per axis, or ``"none"``
    (default).
``[contact_loss]``
    Present: force axes hold their integral and approach below ``threshold`` [N] (default 0.5)
    at ``approach_speed`` [m/s] (default 0.02). Absent: off.
``[posture]``
    A null-space posture task (redundant tasks only: fewer axes than joints): ``q_rest`` (one
    number per joint), ``stiffness`` [1/s^2] and ``damping`` [1/s], a number or one per joint
    (defaults 25 and 10). Absent: off.
``[path]``
    The desired point's path, needed by (and only allowed with) ``frame = "desired"`` or
    ``position_error = true``: ``kind = "circle"`` (``center``, ``radius``) or ``"line"`` (``point``,
    ``direction``), and ``start``, the arc length where it starts [m] (default 0). The point moves
    along it at the velocity reference of ``t1`` (0 when it has none), as an experiment's does;
    the desired orientation is the base's.

Every refusal is a :class:`~hybrid.HybridError` whose first line reads
``FILE:LINE: KEY: what is wrong; what to give`` (the line of the key, or of its table).
"""

from __future__ import annotations

import difflib
import json
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid.control.controller import Controller
from hybrid.control.loops import Gains
from hybrid.control.options import ContactLoss, Posture
from hybrid.control.references import Step
from hybrid.control.schemes import SCHEMES
from hybrid.deprecation import renamed_keys, warn_renamed
from hybrid.errors import HybridError
from hybrid.files import read_user_text
from hybrid.geometry.paths import CirclePath, LinePath
from hybrid.geometry.paths import Path as DesiredPath
from hybrid.geometry.surfaces import Circle, Cylinder, Plane, Sphere, Surface
from hybrid.geometry.task_axes import AXES, check_axes
from hybrid.spec.axes import AXIS_NAMES
from hybrid.validate import MAX_NESTING, checked_keywords, shown

Key = tuple[str, ...]

TOP = ("scheme", "sample_time", "integral", "curvature", "frame", "position_error", "singular_tol",
       "surface", "task", "gains", "references", "limits", "contact_loss", "posture", "path")
TABLES = ("surface", "task", "gains", "references", "limits", "contact_loss", "posture", "path")
#: each surface kind's parameters: (name, what it is)
SURFACES = {"plane": {"point": "vector", "normal": "vector"}, "sphere": {"center": "vector", "radius": "number"},
            "cylinder": {"point": "vector", "axis": "vector", "radius": "number"},
            "circle": {"center": "vector", "radius": "number"},
            "implicit": {"phi": "string", "parameters": "table"}}
PATHS = {"circle": {"center": "vector", "radius": "number", "start": "number"},
         "line": {"point": "vector", "direction": "vector", "start": "number"}}
GAINS = ("KPv", "KIv", "KI2v", "KPf", "KDf", "KIf")
STEP = ("before", "after", "at")
LIMITS = ("torque", "torque_step", "timing_tolerance", "integral")
#: the Controller's keywords as the file's keys (where a refusal of the Controller points)
KEYWORD_KEYS = {
    "scheme": ("scheme",), "sample_time": ("sample_time",), "integral": ("integral",), "curvature": ("curvature",),
    "frame": ("frame",), "position_error": ("position_error",), "singular_tol": ("singular_tol",),
    "surface": ("surface",), "axes": ("task", "axes"), "selection": ("task", "selection"),
    "frame_direction": ("task", "frame_direction"), "gains": ("gains",), "force_reference": ("references", "force"),
    "velocity_reference": ("references", "velocity"), "integral_limit": ("limits", "integral"),
    "torque_limit": ("limits", "torque"), "torque_step_limit": ("limits", "torque_step"),
    "timing_tolerance": ("limits", "timing_tolerance"), "contact_loss": ("contact_loss",),
    "posture": ("posture",), "path": ("path",)}
#: refusals of the Controller that do not start with the keyword they are about
_REFUSALS = ((re.compile(r"Posture |a posture task|the \w+ scheme maps the loops"), ("posture",)),
             (re.compile(r"the \w+ scheme commands"), ("gains",)),
             (re.compile(r"a \d+-joint arm cannot control|\d+ task axes need"), ("task", "axes")),
             (re.compile(r"unknown scheme"), ("scheme",)))


@dataclass(frozen=True)
class PathMotion:
    """The desired point ``r_d(t)`` [m] and ``r_d'(t)`` [m/s]: along ``path`` from its ``start`` at the
    speed ``speed`` (a :class:`~hybrid.Step`), the Controller's ``path`` callable."""

    path: DesiredPath
    speed: Step

    def __call__(self, t: float):
        s = self.path.start + self.speed.integral(t)
        return self.path.point_at(s), self.speed(t) * self.path.tangent_at(s)


@dataclass(frozen=True)
class ControllerConfig:
    """A controller file, read and checked: the Controller's keywords but the robot
    (:meth:`build` makes the Controller of a robot)."""

    source: Source
    surface: Surface
    keywords: dict = field(default_factory=dict)
    #: ``[gains]``'s own numbers, and each ``[gains.AXIS]``'s
    gains: dict = field(default_factory=dict)
    axis_gains: dict = field(default_factory=dict)

    def build(self, robot) -> Controller:
        """The Controller of ``robot`` (a :class:`~hybrid.Robot`) this file describes."""
        keywords = dict(self.keywords)
        if self.axis_gains:
            axes = self.source.checked(("task", "axes"), check_axes, robot, keywords.get("axes"))
            names = [AXIS_NAMES[i] for i in axes]
            for name in self.axis_gains:
                if name not in names:
                    raise self.source.error(("gains", name), f"{name} is not one of the task axes "
                                            f"({', '.join(names)}); remove the table or add the axis to task.axes")
            keywords["gains"] = {n: Gains(**(self.gains | self.axis_gains.get(n, {}))) for n in names}
        elif self.gains:
            keywords["gains"] = Gains(**self.gains)
        try:
            return Controller(robot, self.surface, **keywords)
        except HybridError as exc:
            # a refusal of a value; not a failure to build the code (a subclass), which no key causes
            key = refused_key(str(exc), self.source) if type(exc) is HybridError else None
            if key is None:
                raise
            raise self.source.error(key, str(exc)) from exc


@checked_keywords
def read_controller_config(path, robot) -> Controller:
    """The :class:`~hybrid.Controller` of ``robot`` that the TOML file ``path`` describes.

    The keys are listed in :mod:`hybrid.control.config`; ``hybrid/data/controller_ur5_sphere.toml`` is
    a commented example.

    Parameters
    ----------
    path : str or pathlib.Path
        The TOML file.
    robot : Robot
        The robot it controls.

    Returns
    -------
    Controller
        The controller the file describes.

    Raises
    ------
    HybridError
        The file cannot be read, is not valid TOML, or a key is refused; the first line reads
        ``FILE:LINE: KEY: what is wrong; what to give``.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> import hybrid
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "controller.toml"
    >>> _ = path.write_text('''
    ... sample_time = 0.01
    ... [surface]
    ... kind = "circle"
    ... center = [0.5, 0.0]
    ... radius = 0.2
    ... ''')
    >>> robot = hybrid.Robot.planar(hybrid.paper_arm())
    >>> controller = hybrid.read_controller_config(path, robot)
    >>> type(controller).__name__, controller.sample_time
    ('Controller', 0.01)
    """
    return load_controller_config(path).build(robot)


def load_controller_config(path) -> ControllerConfig:
    """The TOML file ``path`` read and checked into a :class:`ControllerConfig` (no robot needed)."""
    text = read_user_text(path, "controller file")
    path = Path(path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"line (\d+)", str(exc))
        raise HybridError(f"{path}:{found.group(1) if found else '?'}: not valid TOML: {exc}") from None
    except RecursionError:  # the TOML reader recurses into inline tables and arrays
        raise HybridError(f"{path}: tables or lists are nested too deeply to read; write them at most "
                          f"{MAX_NESTING} deep") from None
    return _Reader(Source(path, key_lines(text))).read(data)


# ------------------------------------------------------------------ where a key is


@dataclass(frozen=True)
class Source:
    """A controller file's name and its keys' line numbers (``key_lines``), to point at a key."""

    path: Path
    lines: dict

    def line(self, key: Key) -> int | None:
        """The line of ``key``, else of the nearest table or inline table that holds it."""
        for n in range(len(key), 0, -1):
            if key[:n] in self.lines:
                return self.lines[key[:n]]
        return None

    def renamed(self, old: Key, new: Key) -> None:
        """Read the key ``old`` as ``new`` (its new name), with a warning at its line, which ``new``'s
        refusals then point at."""
        line = self.line(old)
        warn_renamed(old[-1], new[-1], f"{self.path}{'' if line is None else f':{line}'}: [{'.'.join(old[:-1])}]")
        if old in self.lines:
            self.lines[new] = self.lines[old]

    def error(self, key: Key, message: str) -> HybridError:
        """``FILE:LINE: KEY: message`` (``KEY = value: ...`` when the message starts with the value)."""
        line = self.line(key)
        where = f"{self.path}{'' if line is None else f':{line}'}"
        return HybridError(f"{where}: {'.'.join(key)}{' ' if message.startswith('= ') else ': '}{message}")

    def checked(self, key: Key, f: Callable, *args, **kwargs):
        """``f(*args, **kwargs)``, its refusal pointed at ``key`` (or at the one of ``key``'s keys it names)."""
        try:
            return f(*args, **kwargs)
        except HybridError as exc:
            raise self.error(_named(key, str(exc), self), str(exc)) from exc


_BARE = r"[A-Za-z0-9_-]+|\"(?:[^\"\\]|\\.)*\"|'[^']*'"
_DOTTED = rf"(?:{_BARE})(?:\s*\.\s*(?:{_BARE}))*"
_HEADER = re.compile(rf"\s*\[\[?\s*({_DOTTED})\s*\]\]?")
_ASSIGN = re.compile(rf"\s*({_DOTTED})\s*=")
_STRING = re.compile(r"\"(?:[^\"\\]|\\.)*\"|'[^']*'")


def _parts(dotted: str) -> Key:
    return tuple(p[1:-1] if p[0] in "\"'" else p for p in re.findall(_BARE, dotted))


def key_lines(text: str) -> dict[Key, int]:
    """Each table's and key's line (1-based) in a TOML text, by its full key: a light scan of
    ``[table]`` headers and ``key =`` lines (inline tables' keys too; lines that continue a value,
    a multi-line string or list, skipped), not a parser."""
    lines: dict[Key, int] = {}
    table: Key = ()
    quote, depth = None, 0  # inside a multi-line string: its delimiter; open brackets of a value
    for number, line in enumerate(text.splitlines(), 1):
        if quote is not None:
            if line.count(quote) % 2:
                quote = None
            continue
        code = _STRING.sub('""', line).split("#")[0]
        if depth == 0:
            header, assign = _HEADER.match(line), _ASSIGN.match(line)
            if header:
                table = _parts(header.group(1))
                lines.setdefault(table, number)
                continue
            if assign:
                key = (*table, *_parts(assign.group(1)))
                lines.setdefault(key, number)
                for inline in re.finditer(rf"[{{,]\s*({_DOTTED})\s*=", line[assign.end():]):
                    lines.setdefault((*key, *_parts(inline.group(1))), number)
        depth = max(0, depth + sum(code.count(c) for c in "[{") - sum(code.count(c) for c in "]}"))
        for delimiter in ('"""', "'''"):
            if line.count(delimiter) % 2:
                quote = delimiter
                break
    return lines


def _named(key: Key, message: str, source: Source) -> Key:
    """``key``, or its key that a refusal's first words name (``Sphere.radius = ...``: ``radius``)."""
    for word in re.findall(r"\w+", message.split("\n")[0])[:3]:
        if (*key, word) in source.lines:
            return (*key, word)
    return key


def refused_key(message: str, source: Source) -> Key | None:
    """The file's key a refusal of the Controller is about, from its first words (the keyword it names);
    None when it names none."""
    first = message.split("\n")[0]
    key = next((k for pattern, k in _REFUSALS if pattern.match(first)), None)
    if key is None:
        word = re.match(r"(?:Controller\.)?(\w+)", first)
        key = KEYWORD_KEYS.get(word.group(1)) if word else None
    if key is None:
        return None
    axis = re.search(r"names axis (\w+)", first)  # a reference given on an axis of the other kind
    if axis is not None and (*key, axis.group(1)) in source.lines:
        return (*key, axis.group(1))
    return _named(key, first, source)


# ------------------------------------------------------------------ reading


def _shown(value) -> str:
    """A value as the file writes it (``true``, ``"text"``), cut short."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value if len(value) <= 60 else value[:57] + "...")
    return shown(value)


class _Reader:
    """The file's tables read one by one into the Controller's keywords, each value checked at its key."""

    def __init__(self, source: Source):
        self.source = source

    def error(self, key: Key, message: str) -> HybridError:
        return self.source.error(key, message)

    # -------------------------------------------------------------- values

    def known(self, key: Key, table: dict, allowed, what: str) -> None:
        """Refuse a key of ``table`` that is not ``allowed``, with the nearest allowed one."""
        lowered = {a.lower(): a for a in allowed}
        for k in table:
            if k not in allowed:
                close = difflib.get_close_matches(k.lower(), list(lowered), n=1, cutoff=0.6)
                hint = f"did you mean {lowered[close[0]]!r}? " if close else ""
                raise self.error((*key, k), f"unknown key; {hint}{what} takes {', '.join(allowed)}")

    def table(self, key: Key, value) -> dict:
        if not isinstance(value, dict):
            raise self.error(key, f"= {_shown(value)}: give a table ([{'.'.join(key)}] and its keys)")
        return value

    def number(self, key: Key, value, unit: str = "") -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.error(key, f"= {_shown(value)}: give a number{unit}")
        try:
            if math.isfinite(float(value)):
                return float(value)
        except OverflowError:
            pass
        raise self.error(key, f"= {_shown(value)}: give a finite number{unit}")

    def boolean(self, key: Key, value) -> bool:
        if not isinstance(value, bool):
            raise self.error(key, f"= {_shown(value)}: give true or false")
        return value

    def choice(self, key: Key, value, choices) -> str:
        if not isinstance(value, str) or value not in choices:
            close = difflib.get_close_matches(value, list(choices), n=1) if isinstance(value, str) else []
            hint = f"did you mean {json.dumps(close[0])}? " if close else ""
            raise self.error(key, f"= {_shown(value)}: {hint}give one of {', '.join(json.dumps(c) for c in choices)}")
        return value

    def string(self, key: Key, value, what: str) -> str:
        if not isinstance(value, str):
            raise self.error(key, f"= {_shown(value)}: give {what} as a string")
        return value

    def numbers(self, key: Key, value, what: str) -> tuple[float, ...]:
        if not isinstance(value, list) or not value:
            raise self.error(key, f"= {_shown(value)}: give {what}, a list of numbers")
        return tuple(self.number(key, v, f" in the list ({what})") for v in value)

    def number_or_list(self, key: Key, value, what: str):
        return self.numbers(key, value, what) if isinstance(value, list) else self.number(key, value, f" ({what})")

    def axis_names(self, key: Key, value, what: str) -> list[str]:
        names = [value] if isinstance(value, str) else value
        if not isinstance(names, list):
            raise self.error(key, f"= {_shown(value)}: give {what}, a list of axis names ({', '.join(AXIS_NAMES)})")
        for name in names:
            self.choice(key, name, AXIS_NAMES)
        return names

    # -------------------------------------------------------------- tables

    def read(self, data: dict) -> ControllerConfig:
        self.known((), data, TOP, "a controller file")
        for name in TABLES:
            if name in data:
                self.table((name,), data[name])
        kw: dict = {}
        top = {"sample_time": self.number, "singular_tol": self.number, "integral": self.boolean,
               "curvature": self.boolean, "position_error": self.boolean}
        for name, read in top.items():
            if name in data:
                kw[name] = read((name,), data[name])
        if "scheme" in data:
            kw["scheme"] = self.choice(("scheme",), data["scheme"], tuple(SCHEMES))
        if "frame" in data:
            kw["frame"] = self.choice(("frame",), data["frame"], ("actual", "desired"))
        if "surface" not in data:
            raise self.error(("surface",), "missing; add a [surface] table with kind and its parameters "
                             "(e.g. kind = \"sphere\", center, radius)")
        surface = self.surface(data["surface"])
        kw |= self.task(data.get("task", {}))
        gains, axis_gains = self.gains(data.get("gains", {}))
        kw |= self.references(data.get("references", {}))
        kw |= self.limits(data.get("limits", {}))
        if "contact_loss" in data:
            kw["contact_loss"] = self.contact_loss(data["contact_loss"])
        if "posture" in data:
            kw["posture"] = self.posture(data["posture"])
        needs_path = kw.get("frame") == "desired" or kw.get("position_error", False)
        if "path" in data and not needs_path:
            raise self.error(("path",), "a path is used only by frame = \"desired\" or position_error = true; "
                             "remove [path], or set one of them")
        if needs_path:
            if "path" not in data:
                key = ("frame",) if kw.get("frame") == "desired" else ("position_error",)
                raise self.error(key, "needs the desired point's path: add a [path] table (kind = \"circle\" with "
                                 "center and radius, or \"line\" with point and direction)")
            kw["path"] = PathMotion(self.path(data["path"]), self.path_speed(kw.get("velocity_reference")))
        return ControllerConfig(self.source, surface, kw, gains, axis_gains)

    def shape(self, key: Key, table: dict, kinds: dict, what: str):
        """``table``'s ``kind`` and its parameters, read by the types in ``kinds``."""
        if "kind" not in table:
            raise self.error(key, f"has no kind; add kind = one of {', '.join(json.dumps(k) for k in kinds)}")
        kind = self.choice((*key, "kind"), table["kind"], tuple(kinds))
        params = kinds[kind]
        self.known(key, table, ("kind", *params), f"a {kind} {what}")
        got = {}
        for name, typ in params.items():
            k = (*key, name)
            if name not in table:
                continue
            value = table[name]
            if typ == "number":
                got[name] = self.number(k, value, " [m]")
            elif typ == "vector":
                got[name] = self.numbers(k, value, "coordinates [m]")
            elif typ == "string":
                got[name] = self.string(k, value, "a formula of x, y, z")
            else:
                got[name] = {p: self.number((*k, p), v) for p, v in self.table(k, value).items()}
        return kind, got

    def surface(self, table: dict) -> Surface:
        kind, got = self.shape(("surface",), table, SURFACES, "surface")
        missing = [p for p in SURFACES[kind] if p not in got and p != "parameters"]
        if missing:
            raise self.error(("surface",), f"a {kind} needs {', '.join(missing)}; add them to [surface]")
        if kind == "implicit":
            from hybrid.geometry.implicit import ImplicitSurface  # SymPy: loaded only for a formula

            return self.source.checked(("surface",), ImplicitSurface, got["phi"], got.get("parameters", {}))
        make = {"plane": Plane, "sphere": Sphere, "cylinder": Cylinder, "circle": Circle}[kind]
        return self.source.checked(("surface",), make, **got)

    def path(self, table: dict) -> DesiredPath:
        kind, got = self.shape(("path",), self.table(("path",), table), PATHS, "path")
        missing = [p for p in PATHS[kind] if p not in got and p != "start"]
        if missing:
            raise self.error(("path",), f"a {kind} path needs {', '.join(missing)}; add them to [path]")
        return self.source.checked(("path",), CirclePath if kind == "circle" else LinePath, **got)

    @staticmethod
    def path_speed(velocity) -> Step:
        """The speed along the path: the velocity reference of ``t1`` (0 when it has none), as a Step."""
        if isinstance(velocity, Mapping):
            velocity = velocity.get("t1", 0.0)
        if velocity is None:
            velocity = 0.0
        return velocity if isinstance(velocity, Step) else Step(velocity, velocity, 0.0)

    def task(self, table: dict) -> dict:
        if "reference" in table:  # the old name of frame_direction
            if "frame_direction" in table:
                raise self.error(("task", "reference"), "and frame_direction are both given; keep frame_direction "
                                 "(reference is its old name)")
            self.source.renamed(("task", "reference"), ("task", "frame_direction"))
            table = renamed_keys(table, {"reference": "frame_direction"})
        self.known(("task",), table, ("axes", "selection", "frame_direction"), "[task]")
        kw: dict = {}
        if "axes" in table:
            value = table["axes"]
            if isinstance(value, str):
                kw["axes"] = self.choice(("task", "axes"), value, tuple(AXES))
            else:
                names = self.axis_names(("task", "axes"), value, "the task axes")
                kw["axes"] = tuple(AXIS_NAMES.index(n) for n in names)
        if "selection" in table:
            kw["selection"] = tuple(self.axis_names(("task", "selection"), table["selection"],
                                                    "the force-controlled axes"))
        if "frame_direction" in table:
            kw["frame_direction"] = self.numbers(("task", "frame_direction"), table["frame_direction"],
                                                 "a direction (x, y, z) in base axes")
        return kw

    def gain_values(self, key: Key, table: dict) -> dict:
        self.known(key, table, GAINS, f"[{'.'.join(key)}]")
        values = {g: self.number((*key, g), v) for g, v in table.items()}
        for g, v in values.items():
            if v < 0:
                raise self.error((*key, g), f"= {v:g}: loop gains are >= 0; give a number >= 0")
        return values

    def gains(self, table: dict) -> tuple[dict, dict]:
        self.known(("gains",), table, (*GAINS, *AXIS_NAMES), "[gains] (gains, or a table per axis)")
        own = self.gain_values(("gains",), {k: v for k, v in table.items() if k in GAINS})
        axes = {}
        for name in (k for k in table if k in AXIS_NAMES):
            axes[name] = self.gain_values(("gains", name), self.table(("gains", name), table[name]))
        return own, axes

    def reference(self, key: Key, value):
        """A number, or a step table ``{before, after, at}``."""
        if isinstance(value, dict):
            self.known(key, value, STEP, "a step")
            missing = [s for s in STEP if s not in value]
            if missing:
                raise self.error(key, f"a step needs before, after and at; add {', '.join(missing)}")
            return Step(*(self.number((*key, s), value[s]) for s in STEP))
        return self.number(key, value, " or a step {before = ..., after = ..., at = ...}")

    def references(self, table: dict) -> dict:
        self.known(("references",), table, ("force", "velocity"), "[references]")
        kw = {}
        for name, keyword in (("force", "force_reference"), ("velocity", "velocity_reference")):
            if name not in table:
                continue
            key, value = ("references", name), table[name]
            if not isinstance(value, dict):
                kw[keyword] = self.reference(key, value)
                continue
            self.known(key, value, (*STEP, *AXIS_NAMES), "a reference (a step, or a table of axis names)")
            if any(k in STEP for k in value) and any(k in AXIS_NAMES for k in value):
                raise self.error(key, "mixes axis names and a step's keys; give a step {before, after, at}, or "
                                 "one reference (a number or a step) per axis name")
            if any(k in STEP for k in value):
                kw[keyword] = self.reference(key, value)
            else:  # one per axis (an empty table: every axis's reference 0)
                kw[keyword] = {axis: self.reference((*key, axis), v) for axis, v in value.items()}
        return kw

    def limits(self, table: dict) -> dict:
        self.known(("limits",), table, LIMITS, "[limits]")
        kw = {}
        if "torque" in table:
            kw["torque_limit"] = self.limit(("limits", "torque"), table["torque"],
                                            "a number [N m or N] or one per joint", ("urdf",), listed=True)
        if "torque_step" in table:
            kw["torque_step_limit"] = self.limit(("limits", "torque_step"), table["torque_step"],
                                                 "a number [N m or N per sample] or one per joint", listed=True)
        if "timing_tolerance" in table:
            kw["timing_tolerance"] = self.limit(("limits", "timing_tolerance"), table["timing_tolerance"],
                                                "a fraction of the sample time (0.25: 25 %)")
        if "integral" in table:
            kw["integral_limit"] = self.limit(("limits", "integral"), table["integral"],
                                              "the largest integral action [m/s^2 or rad/s^2]")
        return kw

    def limit(self, key: Key, value, what: str, words: tuple = (), listed: bool = False):
        """``"none"`` as None, one of the other ``words`` as it is, else a number (or a list, ``listed``)."""
        if isinstance(value, str):
            if value in ("none", *words):
                return None if value == "none" else value
            named = ", ".join(json.dumps(w) for w in (*words, "none"))
            raise self.error(key, f"= {_shown(value)}: give {named} or {what}")
        if listed and isinstance(value, list):
            return self.numbers(key, value, what)
        return self.number(key, value, f" ({what}) or \"none\"")

    def contact_loss(self, table: dict) -> ContactLoss:
        self.known(("contact_loss",), table, ("threshold", "approach_speed"), "[contact_loss]")
        got = {k: self.number(("contact_loss", k), v) for k, v in table.items()}
        return self.source.checked(("contact_loss",), ContactLoss, **got)

    def posture(self, table: dict) -> Posture:
        self.known(("posture",), table, ("q_rest", "stiffness", "damping"), "[posture]")
        if "q_rest" not in table:
            raise self.error(("posture",), "has no q_rest; add q_rest = [...], the rest posture (one number per "
                             "joint [rad or m])")
        got = {"q_rest": self.numbers(("posture", "q_rest"), table["q_rest"], "the rest posture (one per joint)")}
        for name in ("stiffness", "damping"):
            if name in table:
                got[name] = self.number_or_list(("posture", name), table[name], "one number, or one per joint")
        return self.source.checked(("posture",), Posture, **got)
