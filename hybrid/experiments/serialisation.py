"""An experiment as JSON-ready data and back (:meth:`hybrid.Experiment.to_dict`,
:meth:`hybrid.Experiment.from_dict`): its parts, its robot and its surfaces; and a paper run saved
in the form before experiments were one type."""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, fields

import numpy as np

from hybrid.control.fault import FaultReaction
from hybrid.control.loops import Gains
from hybrid.control.options import Posture
from hybrid.control.path_task import PathTask
from hybrid.control.references import Step
from hybrid.control.wrench_sensor import Tool, WrenchSensor
from hybrid.deprecation import renamed_keys
from hybrid.errors import HybridError
from hybrid.geometry.paths import CirclePath, LinePath
from hybrid.geometry.patterns import RasterPath, SpiralPath
from hybrid.geometry.surfaces import SURFACE_KINDS, Circle, Plane, Surface
from hybrid.geometry.waypoints import WaypointPath
from hybrid.models.planar_arm import Arm
from hybrid.models.robot import COULOMB_SPEED, Robot
from hybrid.models.urdf import JointLimits, LinkInertia
from hybrid.plants.contact import Contact, Sensor
from hybrid.spec.chain import Chain, Joint


def experiment_to_dict(exp) -> dict:
    """The settings of the experiment ``exp`` as JSON-ready data, from which :func:`experiment_from_dict`
    builds it again."""
    d = {f.name: getattr(exp, f.name) for f in fields(exp)}
    for name in ("sensor", "contact", "gains", "force_reference", "speed_reference", "fault_reaction"):
        d[name] = asdict(d[name])
    d["robot"] = robot_to_dict(exp.robot)
    d["surface"] = surface_to_dict(exp.surface)
    d["controller_surface"] = None if exp.controller_surface is None else surface_to_dict(exp.controller_surface)
    if exp.controller_robot is None:
        del d["controller_robot"]  # as saved before experiments took one (a sweep's saved base stays the same)
    else:
        d["controller_robot"] = robot_to_dict(exp.controller_robot)
    if exp.path_task is None:
        del d["path_task"]  # as saved before experiments took one
    else:
        d["path_task"] = path_task_to_dict(exp.path_task)
    d["path"] = None if exp.path is None else path_to_dict(exp.path, "path")
    d["start_point"] = None if exp.start_point is None else list(exp.start_point)
    d["frame_direction"] = list(exp.frame_direction)
    d["axes"] = list(exp.axes) if isinstance(exp.axes, tuple) else exp.axes
    d["posture"] = None if exp.posture is None else asdict(exp.posture)
    if exp.q0 is None:
        del d["q0"]  # as saved before the start took a seed (a sweep's saved base stays the same)
    else:
        d["q0"] = list(exp.q0)
    for name in ("wrench_sensor", "controller_wrench_sensor"):
        d[name] = None if d[name] is None else asdict(d[name])
    return {"kind": "experiment", **d}


def experiment_from_dict(cls: type, d: dict):
    """The experiment of class ``cls`` that :func:`experiment_to_dict` wrote; anything else is a HybridError."""
    try:
        return cls(**_settings(d))
    except (KeyError, TypeError, AttributeError, ValueError, IndexError) as exc:
        if isinstance(exc, HybridError):
            raise
        raise HybridError(f"not an experiment's settings ({type(exc).__name__}: {exc})") from None


def _settings(d: dict) -> dict:
    """The keyword arguments of the experiment ``d`` describes."""
    d = dict(d)
    kind = d.pop("kind", None)
    if kind is None and "arm" in d:  # a paper run saved before experiments were one type
        d = _from_paper_settings(d)
    elif kind == "tracing":
        raise ValueError("a 3-D run saved before experiments were one type names its robot only by name: "
                         "its arrays load with numpy.load")
    elif kind != "experiment":
        raise ValueError("no 'kind': 'experiment' entry")
    d = renamed_keys(d)  # saved before settings were renamed
    parts = {"sensor": Sensor, "contact": Contact, "gains": Gains, "force_reference": Step,
             "speed_reference": Step}
    for k, typ in parts.items():
        d[k] = typ(**d[k])
    if "fault_reaction" in d:  # saved since the step has one
        d["fault_reaction"] = FaultReaction(**d["fault_reaction"])
    d["robot"], d["surface"] = robot_from_dict(d["robot"]), surface_from_dict(d["surface"])
    if d.get("controller_surface") is not None:
        d["controller_surface"] = surface_from_dict(d["controller_surface"])
    if d.get("controller_robot") is not None:
        d["controller_robot"] = robot_from_dict(d["controller_robot"])
    if d["path"] is not None:
        d["path"] = path_from_dict(d["path"])
    if d.get("path_task") is not None:
        d["path_task"] = path_task_from_dict(d["path_task"])
    if d["posture"] is not None:
        d["posture"] = Posture(**d["posture"])
    for name in ("wrench_sensor", "controller_wrench_sensor"):
        if d.get(name) is not None:
            d[name] = WrenchSensor(**{**d[name], "tool": Tool(**d[name]["tool"])})
    if isinstance(d["axes"], list):
        d["axes"] = tuple(d["axes"])
    return d


def _from_paper_settings(d: dict) -> dict:
    """The settings of a paper run in the form saved before experiments were one type: the planar arm's
    parameters as ``arm``, the surface as a 2-D circle or line."""
    surface = dict(d.pop("surface"))
    kind = surface.pop("kind")
    lifted = Circle(**surface) if kind == "circle" else Plane(**surface)
    d["robot"], d["surface"] = {"closed_form": d.pop("arm")}, surface_to_dict(lifted)
    d["backend"] = "sympy" if d.get("backend") == "numpy" else d.get("backend", "sympy")
    d.update(path=None, frame_direction=[0.0, 0.0, 1.0], axes=None, posture=None)
    return d


# ------------------------------------------------------------- robots and surfaces as data


def robot_to_dict(robot: Robot) -> dict:
    """Everything that defines ``robot`` as JSON-ready data (and a digest of it, for sweeps' resume)."""
    d = robot.kind.to_dict()
    if d is None:
        limits = None if robot.limits is None else {k: np.asarray(v).tolist() for k, v in vars(robot.limits).items()}
        d = {"name": robot.name, "chain": asdict(robot.chain), "links": [asdict(lk) for lk in robot.links],
             "damping": list(robot.damping), "gravity": list(robot.gravity), "limits": limits}
        if any(robot.coulomb) or any(robot.offset) or any(v != COULOMB_SPEED for v in robot.coulomb_speed):
            # only then: a robot without them is saved (and its digest made) as before they existed
            d.update(coulomb=list(robot.coulomb), offset=list(robot.offset), coulomb_speed=list(robot.coulomb_speed))
    d["digest"] = hashlib.sha256(json.dumps(d, sort_keys=True).encode()).hexdigest()[:16]
    return d


def robot_from_dict(d: dict) -> Robot:
    if "closed_form" in d:
        return Robot.planar(Arm(**d["closed_form"]))
    c = d["chain"]

    def rows(m):
        return tuple(tuple(float(v) for v in row) for row in m)

    joints = tuple(Joint(j["name"], j["kind"], rows(j["rotation"]), tuple(j["translation"]), tuple(j["axis"]))
                   for j in c["joints"])
    chain = Chain(joints, rows(c["tip_rotation"]), tuple(c["tip_translation"]))
    links = tuple(LinkInertia(lk["mass"], tuple(lk["com"]), rows(lk["inertia"])) for lk in d["links"])
    limits = None if d["limits"] is None else JointLimits(**{k: np.array(v, float) for k, v in d["limits"].items()})
    friction = {k: tuple(d[k]) for k in ("coulomb", "offset", "coulomb_speed") if k in d}
    return Robot(d["name"], chain, links, tuple(d["damping"]), tuple(d["gravity"]), limits, **friction)


#: the paths a file names, by kind: the closed forms (their fields) and the paths drawn on a surface (the
#: surface and what they were made from)
PATH_KINDS = {cls.__name__: cls for cls in (CirclePath, LinePath, WaypointPath, RasterPath, SpiralPath)}


def path_to_dict(path, owner: str) -> dict:
    """A path as JSON-ready data (its kind and what makes it); a path of one's own is refused."""
    kind = type(path).__name__
    if PATH_KINDS.get(kind) is not type(path):
        raise HybridError(f"{owner} = {kind}: a path of one's own is not written to a file (only "
                          f"{', '.join(PATH_KINDS)}); keep the experiment in Python")
    if isinstance(path, (CirclePath, LinePath)):
        return {"kind": kind, **asdict(path)}
    return {"kind": kind, "surface": surface_to_dict(path.surface), **path.arguments()}


def path_from_dict(d: dict):
    """The path :func:`path_to_dict` wrote."""
    d = dict(d)
    cls = PATH_KINDS[d.pop("kind")]
    if "surface" in d:
        d["surface"] = surface_from_dict(d["surface"])
    return cls(**d)


def path_task_to_dict(task: PathTask) -> dict:
    """A path task as JSON-ready data; one whose speed or force is a function is refused."""
    d = {f.name: getattr(task, f.name) for f in fields(task)}
    for name in ("speed", "force", "tilt", "lead"):
        if callable(d[name]):
            raise HybridError(f"path_task.{name} is a function: a profile of one's own is not written to a file; "
                              "give a number, or keep the experiment in Python")
    d["path"] = path_to_dict(task.path, "path_task.path")
    return d


def path_task_from_dict(d: dict) -> PathTask:
    """The path task :func:`path_task_to_dict` wrote."""
    return PathTask(**{**d, "path": path_from_dict(d["path"])})


def surface_to_dict(surface: Surface) -> dict:
    arguments = getattr(surface, "arguments", None)
    if arguments is not None:  # a part: what it was made from (fitted again, the same, when read)
        return {"kind": surface.kind, **arguments()}
    if surface.kind.startswith("implicit"):
        return {"kind": "implicit", "phi": str(surface.phi), "parameters": dict(surface.parameters)}
    return {"kind": surface.kind, **{k: list(v) if isinstance(v, tuple) else v for k, v in asdict(surface).items()}}


def surface_from_dict(d: dict) -> Surface:
    d = dict(d)
    kind = d.pop("kind")
    if kind == "implicit":
        from hybrid.geometry.implicit import ImplicitSurface  # SymPy: loaded only for a user's surface

        return ImplicitSurface(d["phi"], d["parameters"])
    if kind not in SURFACE_KINDS:  # a part's kinds register when their module loads (SciPy: loaded for a part)
        import hybrid.geometry.parts  # noqa: F401
    return SURFACE_KINDS[kind](**d)
