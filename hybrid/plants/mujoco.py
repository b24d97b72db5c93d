"""MuJoCo as the plant of any experiment: an independent rigid-body engine under the same controller,
runner, result object and metrics (optional extra ``hybrid-decoupling[mujoco]``).

The model (:func:`arm_spec`, :class:`MujocoPlant`):

- the arm: MuJoCo's own import of the robot's URDF, the file :meth:`hybrid.Robot.from_urdf` read
  (``robot.source``), edited with ``mujoco.MjSpec``: geoms and meshes removed (nothing collides, and
  mesh files need not be found), the joints the robot does not keep removed after placing their
  bodies at the locked positions, limits and friction loss off, joint viscosity the robot's
  ``damping`` (its Coulomb friction and offsets, the generated plant's formula, are passive forces
  below), gravity the robot's ``gravity``. The inertial parameters are MuJoCo's reading of the
  file, and the plant refuses a model whose mass matrix or tip differs from the robot's. A robot
  built otherwise (:meth:`hybrid.Robot.planar`, or changed after it was read) is given to MuJoCo as
  a URDF written from its own chain and parameters (:func:`robot_urdf`);
- the sensor tip: a body of mass ``m_s`` on three world slide joints (the paper's planar sensor
  stays at ``z = 0``, and gravity does not act on it, as in the planar plant);
- the sensor's spring-damper ``F_c = K_s (s - r) + D_s (s' - r')``, the penalty contact
  ``N = max(0, k_e delta + d_e delta')`` on the sensor tip's penetration ``delta = -phi / |grad phi|``
  and the Coulomb friction ``-gamma N tanh(|v_s| / v_eps) v_s / |v_s|`` against its sliding velocity
  are the generated plant's formulas, evaluated here (the surface's ``phi`` and its gradient in
  NumPy, from its :meth:`~hybrid.geometry.surfaces.Surface.phi_function`) in MuJoCo's passive-force
  callback, so at every RK4 stage; MuJoCo's own contact and constraints are disabled.

MuJoCo thus integrates the generated plant's equations with its own rigid-body dynamics, by RK4 at
the experiment's ``integration_step``, and the two agree to rounding: about 1e-13 N RMS in the normal force of
the 3-D runs, about 1e-10 N in the paper's, whose sticking friction (``gamma N / v_eps`` against
``m_s``) amplifies rounding as much as a one-ulp change of the start state does. The output record
is the generated plant's, computed from the state.
"""

from __future__ import annotations

import math
import sys

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.chain_terms import robot_terms
from hybrid.models.robot import Robot
from hybrid.models.urdf import read_chain
from hybrid.models.urdf_writer import robot_urdf_text
from hybrid.plants.interface import Plant

#: the mass [kg] (and inertia [kg m^2]) given to a moving body without, which MuJoCo refuses: it changes
#: the mass matrix by TINY times a squared distance, at the level of rounding. Also the sensor body's
#: rotational inertia, which nothing sees (it has no rotation)
TINY = 1e-12
#: the oldest MuJoCo the plant takes: 3.10 and 3.12 read the Panda's URDF inertia otherwise, and before 3.10
#: MuJoCo lacks the ``MjSpec`` and ``mj_fullM`` the plant calls
OLDEST_MUJOCO = (3, 14)
#: how far MuJoCo's mass matrix (relative to its largest entry, or 1) and tip [m] may be from the robot's
MODEL_TOL = 1e-9


def _mujoco():
    try:
        import mujoco
    except ImportError:
        raise HybridError("the MuJoCo plant needs MuJoCo: pip install 'hybrid-decoupling[mujoco]'") from None
    found = tuple(int(part) for part in mujoco.__version__.split(".")[:2] if part.isdigit())
    if found < OLDEST_MUJOCO:
        raise HybridError(f"the MuJoCo plant needs MuJoCo {'.'.join(map(str, OLDEST_MUJOCO))} or later, found "
                          f"{mujoco.__version__}: pip install -U 'hybrid-decoupling[mujoco]'")
    return mujoco


# -------------------------------------------------------------------------- robots


def robot_urdf(robot: Robot) -> str:
    """A URDF of ``robot`` written from its chain and parameters (:func:`hybrid.models.urdf_writer.robot_urdf_text`;
    a massless link gets :data:`TINY`, which MuJoCo needs)."""
    return robot_urdf_text(robot, least_mass=TINY)


def _file_of(robot: Robot) -> tuple[str, dict] | None:
    """The robot's URDF file and locked joints, when it is still what that file describes."""
    if robot.source is None:
        return None
    path, tip, locked = robot.source
    try:
        parsed = read_chain(path, tip, dict(locked))
    except HybridError:  # the file moved or changed: the robot's own parameters then
        return None
    if parsed.chain != robot.chain or parsed.links != robot.links:
        return None
    return path, dict(locked)


def _lock(mj, spec, keep: tuple[str, ...], locked: dict) -> None:
    """Remove every joint ``keep`` does not name, its body placed at the joint's locked position (0
    unless ``locked`` says otherwise; a joint of another kind held at its origin, as the robot's
    reading of the URDF holds it)."""
    for joint in list(spec.joints):
        if joint.name in keep:
            continue
        value, body = float(locked.get(joint.name, 0.0)), joint.parent
        if value and joint.type in (mj.mjtJoint.mjJNT_SLIDE, mj.mjtJoint.mjJNT_HINGE):
            R = np.zeros(9)
            mj.mju_quat2Mat(R, np.asarray(body.quat, float))
            axis, anchor = np.asarray(joint.axis, float), np.asarray(joint.pos, float)
            if joint.type == mj.mjtJoint.mjJNT_SLIDE:
                body.pos = body.pos + R.reshape(3, 3) @ (axis / np.linalg.norm(axis) * value)
            else:  # a turn about the joint's axis through its anchor, in the body's frame
                turn, quat, Rt = np.zeros(4), np.zeros(4), np.zeros(9)
                mj.mju_axisAngle2Quat(turn, axis / np.linalg.norm(axis), value)
                mj.mju_mulQuat(quat, np.asarray(body.quat, float), turn)
                mj.mju_quat2Mat(Rt, turn)
                body.pos = body.pos + R.reshape(3, 3) @ (anchor - Rt.reshape(3, 3) @ anchor)
                body.quat = quat
        spec.delete(joint)


def arm_spec(robot: Robot):
    """MuJoCo's model of ``robot`` as a ``mujoco.MjSpec``, and the URDF file it read (None: one written
    by :func:`robot_urdf`): MuJoCo's inertial parameters, the robot's joints, viscosities and gravity (its
    Coulomb friction and offsets are :class:`MujocoPlant`'s passive forces), no geoms, meshes, limits or
    friction loss (module docstring)."""
    mj = _mujoco()
    found = _file_of(robot)
    try:
        spec = mj.MjSpec.from_file(found[0]) if found else mj.MjSpec.from_string(robot_urdf(robot))
    except ValueError as exc:
        where = f"the URDF {found[0]}" if found else f"the URDF written for '{robot.name}'"
        raise HybridError(f"MuJoCo cannot read {where}: {str(exc).splitlines()[0]}") from None
    # nothing collides: the geoms go, and the meshes they referenced (their files need not be found)
    for element in (*spec.geoms, *spec.meshes, *spec.equalities, *spec.actuators, *spec.tendons, *spec.sensors):
        spec.delete(element)
    _lock(mj, spec, robot.joint_names, found[1] if found else {})
    missing = [name for name in robot.joint_names if name not in {j.name for j in spec.joints}]
    if missing:
        raise HybridError(f"MuJoCo's reading of the robot has no joint {missing[0]!r}; give the robot as "
                          "Robot.from_urdf read it")
    for joint, damping in zip((spec.joint(name) for name in robot.joint_names), robot.damping):
        joint.damping = [damping, 0.0, 0.0]
        joint.frictionloss, joint.armature, joint.stiffness = 0.0, 0.0, [0.0, 0.0, 0.0]
        joint.limited = mj.mjtLimited.mjLIMITED_FALSE
    for body in spec.bodies[1:]:
        if not body.joints:
            continue
        if not body.explicitinertial:  # a link without <inertial>: massless, as the robot reads it
            body.explicitinertial, body.ipos, body.iquat = True, [0.0] * 3, [1.0, 0.0, 0.0, 0.0]
            body.mass, body.fullinertia = 0.0, [0.0] * 6
        # MuJoCo refuses a moving body without mass or inertia
        body.mass = max(body.mass, TINY)
        full = np.isfinite(body.fullinertia[0])
        if np.abs(body.fullinertia[:3] if full else body.inertia).max() < TINY:
            body.fullinertia = [TINY, TINY, TINY, 0.0, 0.0, 0.0]
    # the inertial parameters are the file's, none made up from geoms
    spec.compiler.inertiafromgeom = mj.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    spec.compiler.balanceinertia = False
    spec.option.gravity = list(robot.gravity)
    return spec, found[0] if found else None


# --------------------------------------------------------------------------- plant


def _ignore(message) -> None:
    """A MuJoCo warning handler that drops the warning."""


class MujocoPlant(Plant):
    """MuJoCo as the plant of ``exp``, whose arm is ``robot``; state ``x = (q, q', s, s')`` and output
    record those of ``exp``'s generated plant (``s`` 2-D for the paper's planar plant, whose sensor
    tip feels no gravity: ``sensor_gravity=False``)."""

    def __init__(self, exp, robot: Robot, sensor_gravity: bool = True):
        self.mj = mj = _mujoco()
        self.exp, self.robot = exp, robot
        self._coulomb, self._coulomb_speed, self._offset = (np.array(getattr(robot, k), float)
                                                            for k in ("coulomb", "coulomb_speed", "offset"))
        # the joints' Coulomb friction and offsets, when the robot has any (every RK4 stage calls _passive)
        self._joint_friction = bool(self._coulomb.any() or self._offset.any())
        self.generated = exp.plant()  # the record, the sensor's reading and the conditioning
        self.record, self.nq = self.generated.record, robot.n
        self.conditioning, self.conditioning_name = self.generated.conditioning, self.generated.conditioning_name
        self.force_columns = self.generated.force_columns
        self.dim = (len(self.record["state"]) - 2 * robot.n) // 2  # the sensor tip's coordinates (2 or 3)
        self._phi = exp.surface.phi_function()  # p -> (phi, grad phi)

        spec, self.source = arm_spec(robot)
        last = spec.joint(robot.joint_names[-1]).parent
        last.add_site(name="tip", pos=list(robot.chain.tip_translation))
        sensor = spec.worldbody.add_body(name="sensor_tip", mass=exp.sensor.mass, ipos=[0, 0, 0],
                                         inertia=[TINY, TINY, TINY], gravcomp=0.0 if sensor_gravity else 1.0)
        sensor.explicitinertial = True
        for axis in np.eye(3):
            sensor.add_joint(type=mj.mjtJoint.mjJNT_SLIDE, axis=list(axis))
        opt = spec.option
        opt.timestep, opt.integrator = exp.integration_step, mj.mjtIntegrator.mjINT_RK4
        D = mj.mjtDisableBit
        # no limits or friction loss (the generated plant has none); a bad state is reported, not reset
        opt.disableflags |= D.mjDSBL_LIMIT | D.mjDSBL_EQUALITY | D.mjDSBL_FRICTIONLOSS | D.mjDSBL_AUTORESET
        if not self._collides(spec, sensor):  # our contact replaces MuJoCo's
            opt.disableflags |= D.mjDSBL_CONSTRAINT | D.mjDSBL_CONTACT
        try:
            self.model = spec.compile()
        except ValueError as exc:
            raise HybridError(f"MuJoCo cannot build the model of '{robot.name}': {str(exc).splitlines()[0]}") from None
        self.data = mj.MjData(self.model)
        n = robot.n
        dofs = [int(self.model.joint(name).dofadr[0]) for name in robot.joint_names]
        if dofs != list(range(n)) or self.model.nv != n + 3:
            raise HybridError(f"MuJoCo orders the joints of '{robot.name}' otherwise ({dofs}); give a serial arm")
        self._site = self.model.site("tip").id
        self._jac = np.zeros((3, self.model.nv))
        self._check_model()

    # ------------------------------------------------------------------ checks

    def mass_matrix(self, q) -> np.ndarray:
        """MuJoCo's joint-space inertia ``B(q)`` of the arm."""
        mj, d = self.mj, self.data
        d.qpos[:] = 0.0
        d.qpos[:self.nq] = q
        mj.mj_forward(self.model, d)
        M = np.zeros((self.model.nv, self.model.nv))
        mj.mj_fullM(self.model, d, M)
        return M[:self.nq, :self.nq]

    def _check_model(self) -> None:
        """Refuse a MuJoCo model whose mass matrix or tip differs from the robot's at a few poses."""
        limits = self.robot.limits
        lo = -np.pi if limits is None else np.maximum(limits.lower, -np.pi)
        hi = np.pi if limits is None else np.minimum(limits.upper, np.pi)
        for q in np.random.default_rng(0).uniform(lo, hi, (3, self.nq)):
            B_mj = self.mass_matrix(q)
            terms = robot_terms(self.robot, q, np.zeros(self.nq))
            dB = np.abs(B_mj - terms["B"]).max() / max(1.0, np.abs(terms["B"]).max())
            dr = np.abs(self.data.site_xpos[self._site] - terms["r"]).max()
            if dB > MODEL_TOL or dr > MODEL_TOL:
                raise HybridError(
                    f"MuJoCo's model of '{self.robot.name}' differs from the robot's at q = {np.round(q, 3).tolist()} "
                    f"(mass matrix by {dB:.2g} of its size, tip by {dr:.2g} m); MuJoCo read "
                    f"{self.source or 'a URDF written from the robot'}: check its inertial and joint data")

    # ------------------------------------------------------------------ physics

    def _collides(self, spec, sensor) -> bool:
        """Add what MuJoCo's own contact needs to ``spec`` (the sensor tip's body ``sensor``); False: none (the
        contact is the generated plant's formula, :meth:`_passive`)."""
        return False

    def _passive(self, model, data) -> None:
        """The sensor's spring-damper, the penalty contact and the friction, and the joints' Coulomb friction
        and offsets (the generated plant's ``F_c tanh(q' / v_s) + tau_0``), as passive forces."""
        n, sensor = self.nq, self.exp.sensor
        self.mj.mj_jacSite(model, data, self._jac, None, self._site)
        J = self._jac[:, :n]
        qvel = data.qvel
        s, sd = data.qpos[n:], qvel[n:]
        Fc = sensor.stiffness * (s - data.site_xpos[self._site]) + sensor.damping * (sd - J @ qvel[:n])
        data.qfrc_passive[:n] += J.T @ Fc
        if self._joint_friction:
            data.qfrc_passive[:n] -= self._coulomb * np.tanh(qvel[:n] / self._coulomb_speed) + self._offset
        data.qfrc_passive[n:] += self._surface_force(s, sd) - Fc

    def _surface_force(self, s: np.ndarray, sd: np.ndarray) -> np.ndarray:
        """The surface's penalty contact and friction on the sensor tip at ``s`` moving at ``sd`` (the generated
        plant's formulas; NaN where no contact is defined)."""
        c = self.exp.contact
        force = np.zeros(len(s))
        phi, grad = self._phi(s)
        norm = math.sqrt(grad @ grad)
        if not (math.isfinite(phi) and 0.0 < norm <= sys.float_info.max):
            # no contact is defined here (the surface's formula is undefined at s, or it has no normal): the
            # state goes NaN, as the generated plant's does, and the runner says where
            return np.full(len(s), math.nan)
        normal = grad / norm
        delta, speed = -phi / norm, normal @ sd
        if delta > 0:
            N = max(0.0, c.stiffness * delta - c.damping * speed)
            slide = sd - speed * normal
            # as the generated plant: |v_s| kept off 0 by far less than v_eps
            w = math.sqrt(slide @ slide + (1e-9 * c.friction_smoothing) ** 2)
            force += N * normal - (c.friction * N * math.tanh(w / c.friction_smoothing) / w) * slide
        return force

    def _set(self, x: np.ndarray) -> None:
        n, k, d = self.nq, self.dim, self.data
        d.qpos[:], d.qvel[:] = 0.0, 0.0
        d.qpos[:n], d.qvel[:n] = x[:n], x[n:2 * n]
        d.qpos[n:n + k], d.qvel[n:n + k] = x[2 * n:2 * n + k], x[2 * n + k:]

    def _state(self) -> np.ndarray:
        n, k, d = self.nq, self.dim, self.data
        return np.concatenate([d.qpos[:n], d.qvel[:n], d.qpos[n:n + k], d.qvel[n:n + k]])

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place by ``nsteps`` MuJoCo RK4 steps with ``tau`` held; steps done (it stops
        before a non-finite state). MuJoCo's passive-force callback is one for the whole process: one
        MuJoCo plant advances at a time (a sweep's processes each have their own)."""
        d = self.data
        self._set(x)
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[:self.nq] = tau

        def steps() -> int:
            for k in range(nsteps):
                self._step()
                state = self._state()
                if not np.isfinite(state).all():
                    return k
                x[:] = trajectory[k] = state
            return nsteps
        return self._with_passive(steps)

    def _step(self) -> None:
        """One MuJoCo step (RK4, the passive forces installed)."""
        self.mj.mj_step(self.model, self.data)

    def _with_passive(self, run):
        """``run()`` with this plant's passive forces installed as MuJoCo's callback (one for the whole process),
        and MuJoCo's printed warnings silenced (a diverging state is the runner's to report, as the generated
        plant's); both as they were after."""
        mj = self.mj
        previous = mj.get_mjcb_passive(), mj.get_mju_user_warning()
        mj.set_mjcb_passive(self._passive)
        mj.set_mju_user_warning(_ignore)
        try:
            return run()
        finally:
            mj.set_mjcb_passive(previous[0])
            mj.set_mju_user_warning(previous[1])

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The generated plant's output record of each state."""
        return self.generated.outputs(states)

    def _record_row(self, x: np.ndarray) -> np.ndarray:
        return self.generated._record_row(x)


def mujoco_plant(exp) -> MujocoPlant:
    """MuJoCo as the plant of ``exp``: the arm read by MuJoCo, the sensor, contact and friction of the
    generated plant (the closed-form planar plant's sensor tip has no gravity: nor has MuJoCo's then)."""
    return MujocoPlant(exp, exp.robot, sensor_gravity=exp.robot.kind.sensor_weighs)
