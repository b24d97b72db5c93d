"""Read a serial chain from a URDF file: structure, inertial parameters, limits, damping, Coulomb friction.

The chain runs from the URDF's root link to the ``tip`` link. Fixed joints are merged;
joints off the chain (and any joint named in ``locked``) are locked at 0 or at the given
value, and the links they carry are merged into the link they hang from. Every problem is
a :class:`~hybrid.errors.URDFError` naming the element, its line, and what to do.
"""

from __future__ import annotations

import difflib
import math
import warnings
import xml.parsers.expat
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from hybrid.errors import LargeModelWarning, URDFError
from hybrid.files import read_user_text
from hybrid.spec.chain import COULOMB_SPEED, Chain, Joint, rotation_rpy
from hybrid.validate import inertia_problem, shown

MOVING = ("revolute", "continuous", "prismatic")
#: the largest URDF file read (a description, not a mesh)
MAX_URDF_BYTES = 64 * 2**20
KNOWN = (*MOVING, "fixed", "floating", "planar")


@dataclass
class Node:
    """An XML element with the line it starts on."""

    tag: str
    attrib: dict
    line: int
    children: list = field(default_factory=list)

    def find(self, tag: str) -> Node | None:
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[Node]:
        return [c for c in self.children if c.tag == tag]


def parse_xml(text: str, source: str) -> Node:
    """A tree of :class:`Node` (expat, so every element knows its line)."""
    parser = xml.parsers.expat.ParserCreate()
    stack: list[Node] = [Node("#document", {}, 0)]

    def start(tag, attrib):
        node = Node(tag, dict(attrib), parser.CurrentLineNumber)
        stack[-1].children.append(node)
        stack.append(node)

    parser.StartElementHandler = start
    parser.EndElementHandler = lambda tag: stack.pop()
    try:
        parser.Parse(text, True)
    except xml.parsers.expat.ExpatError as exc:
        raise URDFError(f"{source}: not well-formed XML at line {exc.lineno}, column {exc.offset} "
                        f"({xml.parsers.expat.ErrorString(exc.code)}); fix the file") from None
    root = stack[0].children[0] if stack[0].children else None
    if root is None or root.tag != "robot":
        raise URDFError(f"{source}: the root element is <{root.tag if root else ''}>, not <robot>; "
                        "give a URDF file")
    return root


@dataclass(frozen=True)
class LinkInertia:
    """Inertial parameters of one moving body in its joint's frame: mass [kg], centre of mass
    [m], inertia about the centre of mass [kg m^2] (3x3, symmetric)."""

    mass: float
    com: tuple[float, float, float]
    inertia: tuple[tuple[float, float, float], ...]

    def as_array(self) -> np.ndarray:
        I = np.asarray(self.inertia)  # noqa: E741
        return np.array([self.mass, *self.com, I[0, 0], I[0, 1], I[0, 2], I[1, 1], I[1, 2], I[2, 2]])


@dataclass(frozen=True)
class JointLimits:
    """Per moving joint: position bounds [rad or m] (infinite for continuous joints), velocity
    [rad/s or m/s] and effort [N m or N] limits (infinite where the URDF gives none)."""

    lower: np.ndarray
    upper: np.ndarray
    velocity: np.ndarray
    effort: np.ndarray


@dataclass(frozen=True)
class ParsedChain:
    name: str
    chain: Chain
    links: tuple[LinkInertia, ...]
    damping: tuple[float, ...]
    limits: JointLimits
    coulomb: tuple[float, ...] = ()
    offset: tuple[float, ...] = ()
    coulomb_speed: tuple[float, ...] = ()


def _floats(node: Node, attr: str, n: int, default, where: str) -> np.ndarray:
    raw = node.attrib.get(attr) if node is not None else None
    if raw is None:
        return np.array(default, dtype=float)
    try:
        vals = np.array([float(v) for v in raw.split()], dtype=float)
    except ValueError:
        vals = np.array([])
    if vals.shape != (n,) or not np.isfinite(vals).all():
        raise URDFError(f"{where}, <{node.tag}> at line {node.line}: {attr}=\"{raw}\" must be {n} finite numbers")
    return vals


def _scalar(node: Node | None, attr: str, default: float | None, where: str) -> float | None:
    if node is None or attr not in node.attrib:
        return default
    raw = node.attrib[attr]
    try:
        v = float(raw)
    except ValueError:
        v = math.nan
    if not math.isfinite(v):
        raise URDFError(f"{where}, <{node.tag}> at line {node.line}: {attr}=\"{raw}\" must be a finite number")
    return v


def _transform(node: Node | None, where: str) -> np.ndarray:
    """The 4x4 homogeneous transform of an ``<origin xyz rpy>`` element (identity if absent)."""
    T = np.eye(4)
    if node is not None:
        T[:3, :3] = rotation_rpy(*_floats(node, "rpy", 3, (0, 0, 0), where))
        T[:3, 3] = _floats(node, "xyz", 3, (0, 0, 0), where)
    return T


def _axis_rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


@dataclass
class _Body:
    """Accumulates rigidly attached links in one frame: mass, first moment, inertia about the frame origin."""

    m: float = 0.0
    h: np.ndarray = field(default_factory=lambda: np.zeros(3))
    I_O: np.ndarray = field(default_factory=lambda: np.zeros((3, 3)))

    def add(self, mass: float, com: np.ndarray, I_com: np.ndarray) -> None:
        self.m += mass
        self.h += mass * com
        self.I_O += I_com + mass * (com @ com * np.eye(3) - np.outer(com, com))

    def inertia(self) -> LinkInertia:
        c = self.h / self.m if self.m > 0 else np.zeros(3)
        I_c = self.I_O - self.m * (c @ c * np.eye(3) - np.outer(c, c))
        I_c = 0.5 * (I_c + I_c.T)
        return LinkInertia(float(self.m), tuple(map(float, c)), tuple(tuple(map(float, r)) for r in I_c))


def _link_inertial(link: Node, source: str) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass, centre of mass and inertia about it, in the link's frame; checked physically valid."""
    where = f"{source}: link '{link.attrib.get('name')}'"
    inertial = link.find("inertial")
    if inertial is None:
        return 0.0, np.zeros(3), np.zeros((3, 3))
    mass_node = inertial.find("mass")
    m = _scalar(mass_node, "value", 0.0, where)
    if m < 0:
        raise URDFError(f"{where} (line {mass_node.line}): mass {m} kg is negative; give a mass >= 0")
    T = _transform(inertial.find("origin"), where)
    node = inertial.find("inertia")
    keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    ixx, ixy, ixz, iyy, iyz, izz = (_scalar(node, k, 0.0, where) for k in keys)
    I = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])  # noqa: E741
    line = node.line if node is not None else inertial.line
    problem = inertia_problem(I)
    if problem:
        raise URDFError(f"{where} (line {line}): the inertia tensor {problem}; correct ixx..izz")
    R = T[:3, :3]
    return m, T[:3, 3], R @ I @ R.T


@dataclass(frozen=True)
class _Tree:
    """A URDF file's links and joints by name, and how they connect."""

    source: str  # the file's name, for messages
    root: Node
    links: dict  # name -> <link>
    joints: dict  # name -> <joint>
    parent_of: dict  # link -> the joint it is the child of
    children: dict  # link -> the joints it is the parent of, in the file's order
    ends: dict  # joint -> (parent link, child link)


def _read_tree(path) -> _Tree:
    """Read and parse the URDF at ``path``; check its links and joints form one tree."""
    # meshes belong in their own files: a URDF is text of at most MAX_URDF_BYTES
    text = read_user_text(path, "URDF file", MAX_URDF_BYTES, error=URDFError)
    path = Path(path)
    source = path.name
    root = parse_xml(text, source)
    links = {}
    for link in root.findall("link"):
        name = link.attrib.get("name")
        if not name:
            raise URDFError(f"{source} (line {link.line}): a <link> has no name")
        if name in links:
            raise URDFError(f"{source} (line {link.line}): link '{name}' is defined twice")
        links[name] = link
    joints, parent_of, children, ends = {}, {}, {}, {}
    for j in root.findall("joint"):
        name, kind = j.attrib.get("name"), j.attrib.get("type")
        where = f"{source}: joint '{name}' (line {j.line})"
        if not name:
            raise URDFError(f"{source} (line {j.line}): a <joint> has no name")
        if name in joints:
            raise URDFError(f"{where}: defined twice")
        if kind not in KNOWN:
            raise URDFError(f"{where}: unknown type '{kind}'; URDF joints are {', '.join(KNOWN)}")
        p, c = j.find("parent"), j.find("child")
        pn, cn = (p.attrib.get("link") if p is not None else None), (c.attrib.get("link") if c is not None else None)
        for role, ln in (("parent", pn), ("child", cn)):
            if ln not in links:
                raise URDFError(f"{where}: its {role} link '{ln}' is not defined in the file")
        if cn in parent_of:
            raise URDFError(f"{where}: link '{cn}' is already the child of joint '{parent_of[cn]}'; "
                            "a closed kinematic chain is not a serial arm")
        joints[name] = j
        ends[name] = (pn, cn)
        parent_of[cn] = name
        children.setdefault(pn, []).append(name)
    roots = [ln for ln in links if ln not in parent_of]
    if len(roots) != 1:
        raise URDFError(f"{source}: expected one root link, found {len(roots)} ({', '.join(roots[:5])}); "
                        "the links must form one tree (a closed chain or a loose link breaks it)")
    return _Tree(source, root, links, joints, parent_of, children, ends)


def _joint_transform(tree: _Tree, name: str, value: float) -> np.ndarray:
    """Transform parent link -> child link of the joint ``name`` held at ``value``."""
    j = tree.joints[name]
    where = f"{tree.source}: joint '{name}'"
    T = _transform(j.find("origin"), where)
    kind = j.attrib["type"]
    if kind in MOVING and value:
        axis = _unit_axis(j, where)
        M = np.eye(4)
        if kind == "prismatic":
            M[:3, 3] = axis * value
        else:
            M[:3, :3] = _axis_rotation(axis, value)
        T = T @ M
    return T


def read_chain(path, tip: str, locked: dict | None = None) -> ParsedChain:
    """The serial chain from the URDF at ``path`` to the link ``tip`` (see the module doc)."""
    tree = _read_tree(path)
    source, root, links, joints = tree.source, tree.root, tree.links, tree.joints
    parent_of, children, ends = tree.parent_of, tree.children, tree.ends
    if tip not in links:
        near = ", ".join(sorted(links)[:12])
        raise URDFError(f"{source}: no link named '{tip}' for the tip; links are: {near}"
                        + (" ..." if len(links) > 12 else ""))
    locked = dict(locked or {})
    for name, value in locked.items():
        if name not in joints:
            raise URDFError(f"locked names joint '{name}', which {source} does not define")
        if not isinstance(value, (int, float, np.integer, np.floating)) or isinstance(value, bool) \
                or not math.isfinite(value):
            raise URDFError(f"locked['{name}'] = {shown(value)}; give a finite joint position (rad or m)")

    # the chain: tip up to the root
    path_joints = []
    link = tip
    while link in parent_of:
        if parent_of[link] in path_joints:  # a loop of links that never reaches the root
            raise URDFError(f"{source}: the links above the tip '{tip}' form a closed loop (through joint "
                            f"'{parent_of[link]}'); a serial arm's chain must reach the root")
        path_joints.append(parent_of[link])
        link = ends[parent_of[link]][0]
    path_joints.reverse()

    def moving(name: str) -> bool:
        return joints[name].attrib["type"] in MOVING and name not in locked

    def merge_subtree(body: _Body, link_name: str, T: np.ndarray, skip: str | None) -> None:
        """Add ``link_name`` (placed by ``T`` in the body frame) and every link rigidly hung from it.

        Walked with an explicit stack: a branch of thousands of links cannot exhaust Python's recursion.
        """
        stack = [(link_name, T, skip)]
        while stack:
            name, T_link, skip_joint = stack.pop()
            m, c, I_c = _link_inertial(links[name], source)
            R = T_link[:3, :3]
            body.add(m, R @ c + T_link[:3, 3], R @ I_c @ R.T)
            for jn in reversed(children.get(name, [])):  # reversed: popped in the file's order
                if jn == skip_joint:  # the chain goes on through it
                    continue
                # off the chain (any type, mimic or not): held at its locked value, 0 by default
                stack.append((ends[jn][1], T_link @ _joint_transform(tree, jn, locked.get(jn, 0.0)), None))

    # walk the chain, merging fixed and locked joints into the next origin
    chain_joints, bodies, damping, coulomb, offset, speeds, lims = [], [], [], [], [], [], []
    T_acc = np.eye(4)
    body = _Body()  # the base body: its mass does not move, but keep the structure uniform
    for idx, jn in enumerate(path_joints):
        j = joints[jn]
        kind = j.attrib["type"]
        where = f"{source}: joint '{jn}'"
        at = f"{where} (line {j.line})"
        next_on_path = path_joints[idx + 1] if idx + 1 < len(path_joints) else None
        if kind in ("floating", "planar") and jn not in locked:
            raise URDFError(f"{at}: a {kind} joint lies on the chain from '{link}' to '{tip}'; "
                            "only revolute, continuous and prismatic joints can be controlled "
                            "(lock it with locked={'" + jn + "': 0.0}, or pick another tip)")
        if j.find("mimic") is not None and moving(jn):
            raise URDFError(f"{at}: a mimic joint lies on the chain; mimic joints are not supported "
                            "on the controlled chain (lock it with locked={...}, or pick another tip)")
        if not moving(jn):
            T_acc = T_acc @ _joint_transform(tree, jn, locked.get(jn, 0.0))
            merge_subtree(body, ends[jn][1], T_acc, next_on_path)
            continue
        if chain_joints:
            bodies.append(body)
        body = _Body()
        origin = T_acc @ _transform(j.find("origin"), where)
        axis = _unit_axis(j, where)
        chain_joints.append(Joint(jn, "prismatic" if kind == "prismatic" else "revolute",
                                  tuple(tuple(map(float, r)) for r in origin[:3, :3]),
                                  tuple(map(float, origin[:3, 3])), tuple(map(float, axis))))
        dyn = j.find("dynamics")
        d = _scalar(dyn, "damping", 0.0, where)
        if d < 0:
            raise URDFError(f"{at}: damping {d} is negative; give a viscosity >= 0")
        damping.append(d)
        c = _scalar(dyn, "friction", 0.0, where)
        if c < 0:
            raise URDFError(f"{at}: friction {c} is negative; give a Coulomb friction >= 0")
        coulomb.append(c)
        # the library's own attributes (hybrid.models.urdf_writer writes them; other readers pass over them)
        offset.append(_scalar(dyn, "offset", 0.0, where))
        v = _scalar(dyn, "coulomb_speed", COULOMB_SPEED, where)
        if v <= 0:
            raise URDFError(f"{at}: coulomb_speed {v} is not positive; give the smooth sign's speed > 0")
        speeds.append(v)
        lims.append(_limits(j, kind, where))
        T_acc = np.eye(4)
        merge_subtree(body, ends[jn][1], T_acc, next_on_path)
    if not chain_joints:
        raise URDFError(f"{source}: no moving joint between the root '{link}' and the tip '{tip}'; "
                        "pick a tip further along the arm")
    check_chain_size(len(chain_joints), f"{source}: the chain from '{link}' to '{tip}'")
    bodies.append(body)
    if sum(b.m for b in bodies) <= 0:
        raise URDFError(f"{source}: every link from '{link}' to '{tip}' has zero mass; the arm needs "
                        "<inertial> masses to have dynamics")
    last = bodies[-1]
    if last.m == 0 and not np.any(last.I_O):
        raise URDFError(f"{source}: the links moved by the last joint '{chain_joints[-1].name}' have no mass "
                        "and no inertia, so B(q) is singular; give them <inertial> data or pick an earlier tip")
    chain = Chain(tuple(chain_joints), tuple(tuple(map(float, r)) for r in T_acc[:3, :3]),
                  tuple(map(float, T_acc[:3, 3])))
    lo, hi, vel, eff = (np.array(c, dtype=float) for c in zip(*lims))
    return ParsedChain(root.attrib.get("name", Path(path).stem), chain, tuple(b.inertia() for b in bodies),
                       tuple(damping), JointLimits(lo, hi, vel, eff), tuple(coulomb), tuple(offset), tuple(speeds))


def _limits(j: Node, kind: str, where: str) -> tuple[float, float, float, float]:
    """A moving joint's ``<limit>``: lower, upper, velocity, effort (infinite where not given), checked."""
    lim = j.find("limit")
    lo = _scalar(lim, "lower", -math.inf, where) if kind != "continuous" else -math.inf
    hi = _scalar(lim, "upper", math.inf, where) if kind != "continuous" else math.inf
    if kind == "revolute" and lim is not None and "lower" not in lim.attrib and "upper" not in lim.attrib:
        lo, hi = -math.inf, math.inf
    velocity, effort = (_scalar(lim, k, math.inf, where) for k in ("velocity", "effort"))
    at = f"{where}, <limit> at line {lim.line if lim is not None else j.line}"
    if lo > hi:
        raise URDFError(f"{at}: lower=\"{lo:g}\" is above upper=\"{hi:g}\"; give lower <= upper")
    for name, value in (("velocity", velocity), ("effort", effort)):
        if value < 0:
            raise URDFError(f"{at}: {name}=\"{value:g}\" is negative; give a limit >= 0 (URDF limits are "
                            "magnitudes)")
    return lo, hi, velocity, effort


#: above this many moving joints a chain warns (:class:`~hybrid.errors.LargeModelWarning`): the first
#: build of each of its units takes a minute or more. Measured on two shared cores, the rigid-body unit
#: alone (generate, then ``cc -O2``): 6 joints 2 s, 24 joints 16 s, 48 joints 2.5 min, growing about as
#: the cube of the joints; a law, controller or closed loop of the same arm takes longer still.
WARN_JOINTS = 32
#: the most moving joints a chain may have (about 25 min for its rigid-body unit alone)
MAX_JOINTS = 100


def check_chain_size(n: int, what: str) -> None:
    """Refuse a chain of more than :data:`MAX_JOINTS` moving joints; warn above :data:`WARN_JOINTS`."""
    if n > MAX_JOINTS:
        raise URDFError(f"{what} has {n} moving joints; at most {MAX_JOINTS} are supported (generating its "
                        f"code would take hours); lock joints with locked={{...}} or pick an earlier tip")
    if n > WARN_JOINTS:
        warnings.warn(f"{what} has {n} moving joints: generating and compiling its code takes about "
                      f"{expected_minutes(n)} per unit the first time (cached afterwards); lock joints with "
                      "locked={...} to shorten it", LargeModelWarning, stacklevel=4)


def expected_minutes(n: int) -> str:
    """The rough time to generate and compile the rigid-body unit of an ``n``-joint chain (measured
    2.5 min at 48 joints, scaled as the cube of the joints)."""
    minutes = 2.5 * (n / 48) ** 3
    return f"{minutes:.0f} minutes" if minutes >= 1.5 else "a minute"


def _unit_axis(j: Node, where: str) -> np.ndarray:
    axis = _floats(j.find("axis"), "xyz", 3, (1.0, 0.0, 0.0), where)
    axis = axis / max(float(np.max(np.abs(axis))), 1e-300)  # scaled first: huge components do not overflow
    norm = float(np.linalg.norm(axis))
    if norm < 1e-12:
        raise URDFError(f"{where} (line {j.line}): the joint axis is zero; "
                        "give a direction, e.g. <axis xyz=\"0 0 1\"/>")
    return axis / norm


def rigid_offset(path, tip: str, frame: str, locked: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The pose ``(r [m], R)`` of the URDF link ``frame`` in the axes of the link ``tip`` of the file at
    ``path``: ``r`` its origin and ``R`` its axes (3 x 3, columns), both in tip axes.

    ``frame`` must be rigidly attached to ``tip``: joined to it by fixed joints only (joints named in
    ``locked``, ``{joint name: position}``, count as fixed at that position), in either direction along
    the tree: beyond the tip (a sensor's or tool's frame past the flange), above it (the flange's link),
    or on a branch of a link rigidly above it. ``frame == tip`` gives the identity.
    """
    tree = _read_tree(path)
    locked = dict(locked or {})
    for name in locked:
        if name not in tree.joints:
            raise URDFError(f"locked names joint {shown(name, 60)}, which {tree.source} does not define")
    for role, name in (("tip", tip), ("frame", frame)):
        if not isinstance(name, str) or name not in tree.links:
            near = difflib.get_close_matches(str(name), tree.links, n=1)
            hint = f"did you mean '{near[0]}'?" if near else f"links are: {', '.join(sorted(tree.links)[:12])}"
            raise URDFError(f"{role} = {shown(name, 60)} is not a link of {tree.source}; give a link name ({hint})")

    def up(link: str) -> list[str]:
        """The joints from ``link`` up to the root, nearest first."""
        out = []
        while link in tree.parent_of and tree.parent_of[link] not in out:  # a loop of links ends the walk
            out.append(tree.parent_of[link])
            link = tree.ends[out[-1]][0]
        return out

    tip_up, frame_up = up(tip), up(frame)
    common = set(tip_up) & set(frame_up)  # the joints above the two links' lowest common ancestor
    tip_up = [j for j in tip_up if j not in common]
    frame_up = [j for j in frame_up if j not in common]
    for jn in tip_up + frame_up:  # nearest the tip first, then the frame's side
        kind = tree.joints[jn].attrib["type"]
        if kind != "fixed" and jn not in locked:
            fix = (f"; a joint held still can be locked where the robot is read (Robot.from_urdf(..., "
                   f"locked={{'{jn}': position}}))") if jn in frame_up else ", a joint of the arm's chain"
            raise URDFError(
                f"frame = '{frame}' is not rigidly attached to the tip '{tip}'; give a frame joined to it by fixed "
                f"joints only\n  the sensor must be rigidly attached to the tip's link: in {tree.source}, '{frame}' "
                f"moves with joint '{jn}' ({kind}){fix}")

    def pose(joints_up: list[str]) -> np.ndarray:
        """The link at the bottom of ``joints_up`` in the axes of the link at its top."""
        T = np.eye(4)
        for jn in reversed(joints_up):
            T = T @ _joint_transform(tree, jn, locked.get(jn, 0.0))
        return T

    A, B = pose(tip_up), pose(frame_up)  # the tip and the frame in the axes of their common ancestor
    R = A[:3, :3].T @ B[:3, :3]
    return A[:3, :3].T @ (B[:3, 3] - A[:3, 3]), R
