"""Robot kinds: what a robot does by what it is, written once per kind.

Every :class:`~hybrid.Robot` is a serial chain with run-time parameters; its :attr:`~hybrid.Robot.kind`
adds what depends on how it is known: :class:`SerialChain` (any arm, e.g. from a URDF: numerical inverse
kinematics, the generated rigid-body plant, forces in space) or :class:`ClosedFormArm` (the paper's
planar arm, whose terms, plant, inverse kinematics and law also exist in closed form: forces in its
plane, the planar task axes, its plant on a surface's cross-section). Code that serves every robot asks
the kind; nothing else tests which kind a robot is.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.surfaces import Surface
from hybrid.geometry.task_axes import AXES
from hybrid.models.chain_terms import robot_terms
from hybrid.models.planar_arm import Arm, dynamics, kinematics
from hybrid.validate import finite_array, shown


class SerialChain:
    """Any serial arm: its terms from the generated rigid-body code, its start by numerical inverse kinematics."""

    #: the task axes a controller uses unless told (:data:`hybrid.geometry.task_axes.AXES`)
    default_axes = "all"
    #: the measure :meth:`conditioning` computes
    conditioning_name = "m/(|J|_F |J^+|_F)"
    #: the numbers of a measured force without moments (base axes)
    force_size = 3
    #: the name of its generated plant in the plants' registry (:mod:`hybrid.plants.registry`)
    plant = "rigid_body"
    #: whether the sensor's own mass weighs on it in a plant (a chain moves in gravity; the planar arm's
    #: plane is horizontal to its sensor's spring)
    sensor_weighs = True
    #: the settings of the closed form, with their defaults (another robot leaves them out)
    closed_form_settings: dict = {"elbow": 1, "backend": "sympy"}

    #: the closed form's parameters (None: it has none)
    arm: Arm | None = None
    #: whether its inverse kinematics begins at a seed ``q0`` (the closed form's does not: its elbow picks)
    seeded = True

    def conditioning(self, robot, q) -> np.ndarray:
        rows = np.atleast_2d(np.asarray(q, float))
        J = robot_terms(robot, rows, np.zeros_like(rows))["J"]
        s = np.linalg.svd(J, compute_uv=False)
        cond = min(J.shape[1:]) / np.sqrt(np.sum(s**2, axis=-1) * np.sum(1.0 / s**2, axis=-1))
        return cond if np.ndim(q) == 2 else cond[0]

    def reach(self) -> tuple[float, float] | None:
        return None

    def rest_terms(self, robot, q) -> dict[str, np.ndarray]:
        """At rest at each row of ``q`` (N x n): the tip ``r`` [m] (its coordinates in the robot's space: 3,
        the planar arm's 2), the frame Jacobian ``J`` (N x 6 x n, linear rows first, base axes), ``B``
        and the gravity torque ``g`` [N m]."""
        rows = np.atleast_2d(np.asarray(q, float))
        t = robot_terms(robot, rows, np.zeros_like(rows))
        return {"r": t["r"], "J": t["J"], "B": t["B"], "g": t["n"]}  # at rest n is gravity's alone

    def inverse_kinematics(self, robot, position, rotation, q0, tol: float, elbow: int) -> np.ndarray:
        """Damped least squares from ``q0`` (default: mid-range of the limits) to the tip's ``position``
        (and ``rotation``), see :meth:`hybrid.Robot.inverse_kinematics`."""
        p_goal = finite_array("position", position, (3,))
        R_goal = None if rotation is None else finite_array("rotation", rotation, (3, 3))
        if q0 is None:
            lo, hi = np.maximum(robot.limits.lower, -np.pi), np.minimum(robot.limits.upper, np.pi)
            q = 0.5 * (lo + hi)
        else:
            q = np.array(finite_array("q0", q0, (robot.n,)))
        zeros = np.zeros(robot.n)
        for _ in range(200):
            terms = robot_terms(robot, q, zeros)
            err = p_goal - terms["r"]
            J = terms["J"] if R_goal is not None else terms["J"][:3]
            if R_goal is not None:
                R = terms["rotation"]
                # orientation error: 1/2 sum of column cross products (small-angle rotation vector)
                err = np.concatenate([err, 0.5 * sum(np.cross(R[:, i], R_goal[:, i]) for i in range(3))])
            if np.abs(err).max() < tol:
                return q
            lam = 1e-4 + np.dot(err, err)
            q = q + J.T @ np.linalg.solve(J @ J.T + lam * np.eye(len(err)), err)
        raise HybridError(f"inverse kinematics did not reach the pose (position {np.round(p_goal, 4).tolist()} m, "
                          f"error {np.abs(err).max():.2g}): it may be out of reach; move it or give q0 near a solution")

    def with_model_error(self, robot, inertial: float, viscous_compensation: float):
        """The controller's model of ``robot`` where this kind makes it itself (None: scale the links)."""
        return None

    def check_link_change(self) -> None:
        """Refuse changing one link's parameters where they are not the robot's own (a chain's are)."""

    def check_surface(self, surface) -> None:
        """Refuse a surface this kind cannot run on (every surface serves a chain)."""

    def section(self, surface):
        """The surface as this kind's plant and closed form see it: a chain sees it whole (None)."""
        return None

    def closed_form_section(self, surface, axes: tuple[int, ...], frame_direction) -> object | None:
        """The cross-section on which this kind's closed-form law serves ``surface`` on the task ``axes`` with
        the task frame's direction ``frame_direction``; None where it has no closed form that applies."""
        return None

    def check_settings(self, robot, frame_direction, settings: dict) -> None:
        """Refuse an experiment's closed-form settings a chain has none of (``settings``: by name)."""
        for name, default in self.closed_form_settings.items():
            if settings.get(name, default) != default:
                raise HybridError(f"{name} = {settings[name]!r} is a setting of the planar arm's closed form; "
                                  f"leave it out for the robot {robot.name!r}")

    def tool_rotation(self, rotation):
        """The tool's orientation the start asks for (``rotation()``, computed only where it is used)."""
        return rotation()

    def plant_printer(self, backend: str) -> str:
        """The printer of its plant's standalone C, given the experiment's ``backend`` setting (a chain's
        plant is CasADi's)."""
        return "casadi"

    def to_dict(self) -> dict | None:
        """What rebuilds the robot (None: the robot is saved as a chain, its parts one by one)."""
        return None


@dataclass(frozen=True)
class ClosedFormArm(SerialChain):
    """The paper's planar arm (conventions §3): two revolute joints about base z, its numbers ``arm``."""

    arm: Arm
    default_axes = "planar"
    conditioning_name = "2|det J|/|J|_F^2"
    force_size = 2
    plant = "planar"
    sensor_weighs = False
    seeded = False

    def conditioning(self, robot, q) -> np.ndarray:
        return self.arm.conditioning(np.asarray(q, float).T)

    def reach(self) -> tuple[float, float]:
        return self.arm.reach()

    def rest_terms(self, robot, q) -> dict[str, np.ndarray]:
        # the closed form in NumPy (no native unit to build): its plane's rows of the frame Jacobian, both
        # joints turning about base z
        rows = np.atleast_2d(np.asarray(q, float))
        p = self.arm.as_array()
        kin = [kinematics(row, (0.0, 0.0), p) for row in rows]
        dyn = [dynamics(row, (0.0, 0.0), p) for row in rows]
        J = np.zeros((len(rows), 6, 2))
        J[:, :2] = [k[1] for k in kin]
        J[:, 5] = 1.0
        return {"r": np.array([k[0] for k in kin]), "J": J, "B": np.array([d[0] for d in dyn]),
                "g": np.array([d[1] for d in dyn])}

    def inverse_kinematics(self, robot, position, rotation, q0, tol: float, elbow: int) -> np.ndarray:
        """In closed form (``elbow`` +1 for ``q2 > 0``, -1 for ``q2 < 0``; the orientation follows from the
        position)."""
        return self.arm.inverse_kinematics(np.asarray(position, float)[:2], elbow)

    def with_model_error(self, robot, inertial: float, viscous_compensation: float):
        """The closed form's own model error: the same numbers, its parameters kept."""
        return type(robot).planar(self.arm.with_model_error(inertial, viscous_compensation))

    def check_link_change(self) -> None:
        raise HybridError("the planar arm's links are its closed form's parameters; change them there: "
                          "Robot.planar(dataclasses.replace(arm, m2=...)), or sweep 'arm.m2'")

    def check_surface(self, surface) -> None:
        if surface.cross_section() is None:
            raise HybridError(f"the planar arm needs a planar surface (a hybrid.Circle or a 2-D hybrid.Plane: a "
                              f"cylinder or a plane along base z), got {shown(surface, 60)}")

    def section(self, surface):
        """The surface's cross-section in the arm's plane (:meth:`Surface.cross_section`)."""
        return surface.cross_section()

    def closed_form_section(self, surface, axes: tuple[int, ...], frame_direction) -> object | None:
        """The cross-section, for a surface of the library's with one, the planar task axes ``(t1, n)`` and
        the task frame's direction ``e = z``."""
        planar = tuple(axes) == AXES["planar"] and tuple(frame_direction) == (0.0, 0.0, 1.0)
        if not isinstance(surface, Surface) or not planar:
            return None
        return surface.cross_section()

    def check_settings(self, robot, frame_direction, settings: dict) -> None:
        if tuple(frame_direction) != (0.0, 0.0, 1.0):
            raise HybridError(f"frame_direction = {tuple(frame_direction)}: the planar arm's task frame has e = z (its "
                              "plant records in it); leave frame_direction out")

    def tool_rotation(self, rotation):
        return None  # the arm's orientation follows from its position

    def plant_printer(self, backend: str) -> str:
        return backend

    def to_dict(self) -> dict:
        return {"closed_form": asdict(self.arm)}


#: the kind of every robot without a closed form
SERIAL_CHAIN = SerialChain()

