"""The paper's experiment with MuJoCo as the plant: an independent physics engine under the same
controller, runner, result object and metrics (optional extra ``hybrid-decoupling[mujoco]``).

The MJCF model, written from the experiment (:func:`model_xml`):

- the arm: two hinge joints about z with the paper's inertias and joint viscosity (MuJoCo's
  ``damping``), no gravity (a SCARA); MuJoCo computes its dynamics and integrates by RK4 at the
  experiment's ``step``;
- the sensor tip: a body of mass ``m_s`` on two world slide joints (x, y) carrying a small sphere.
  Its isotropic spring-damper to the arm tip, ``F_c = K_s (s - r) + D_s (s' - r')``, is a passive
  force added in MuJoCo's passive-force callback at every RK4 stage: MuJoCo has no element for it
  (a tendon damps only along its length; slide joints on the moving link would damp the velocity
  seen in the rotating link frame);
- the surface: a geom (a cylinder for a circle, a box for a plane) on its own body, mounted on two
  slide joints with MuJoCo ``stiffness = k_e`` and ``damping = d_e`` and a small mass: the surface's
  compliance. The contact between sensor tip and surface is MuJoCo's, frictionless (``condim = 1``)
  and nearly rigid (``solimp = 0.9999``, ``solref = (-rate^2, -2 rate)`` with ``rate = 2.5 / step``,
  its stiffest stable setting), active within ``MARGIN``: the sensor tip then
  penetrates ``delta = N / k_e`` through the mount, the penalty of NOTES section 5. (MuJoCo's own
  soft contact cannot be that penalty: with impedance ``d`` it accelerates as
  ``a = (1 - d) a_0 - d (b delta' + k delta)``, a compliance that scales the other forces too.)
- friction: Coulomb with NOTES section 5's ``tanh(v / v_eps)`` smoothing, on the sensor tip's
  sliding velocity relative to the surface, with the normal force the mount carries, as a passive
  force (MuJoCo's soft friction cone has its own stick-slip transition, a different model).

With these settings the paper's run agrees with :func:`hybrid.simulate` to about 1 mN RMS in the
normal force and 0.1 mm/s RMS in the speed (tested). The output record is the generated plant's,
computed from the state: its ``N`` and ``friction`` columns are the penalty formulas of the sensor
tip's state.
"""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.plants.compiled import NativePlant

#: the surface's mass on its compliant mount, per unit of d_e * step [kg / (N s/m * s)]: the mount's
#: fastest pole, -d_e / mass, then sits at 1.25 / step, inside RK4's stability limit (4 g at 0.1 ms)
SURFACE_MASS_PER_DAMPING_STEP = 0.8
#: the contact's own (nearly rigid) reference dynamics, critically damped, per 1 / step: the
#: stiffest stable setting (2.5e4 rad/s at 0.1 ms)
CONTACT_RATE_PER_STEP = 2.5
#: the contact is active within this distance [m] and rests at it (the geom is moved back by as much),
#: so a sensor tip placed on the surface is in contact from the first step
MARGIN = 1e-6
#: the sensor tip's sphere radius [m] (the surface geom is moved back by as much)
SENSOR_RADIUS = 1e-3


def _mujoco():
    try:
        import mujoco
    except ImportError:
        raise HybridError("the MuJoCo plant needs MuJoCo: pip install 'hybrid-decoupling[mujoco]'") from None
    return mujoco


def model_xml(exp) -> str:
    """The MJCF text of ``exp``'s arm, sensor and surface (module docstring)."""
    arm, s, c = exp.arm, exp.sensor, exp.contact
    if arm.gravity != 0:
        raise HybridError("the MuJoCo plant models the paper's SCARA (no gravity); give an Arm with gravity=0")
    tiny = 1e-9  # MuJoCo needs positive masses and inertias; the paper's link 1 has only I1
    rate = CONTACT_RATE_PER_STEP / exp.step
    # heavy enough that the mount's modes, -d_e / m and sqrt(k_e / m), stay within RK4's reach
    mount_mass = max(SURFACE_MASS_PER_DAMPING_STEP * c.damping * exp.step, 0.5 * c.stiffness * exp.step**2)
    surf = exp.surface
    if surf.kind == "circle":
        # the geom shrinks by the sensor sphere's radius: contact starts where the sensor tip's centre touches
        shape, pos, size, euler = "cylinder", (*surf.center, 0.0), f"{surf.radius - SENSOR_RADIUS - MARGIN} 0.05", 0.0
    else:
        n = np.asarray(surf.normal, float) / np.linalg.norm(surf.normal)
        centre = np.asarray(surf.point, float) - (0.5 + SENSOR_RADIUS + MARGIN) * n  # a 1 m thick box
        shape, pos, size, euler = "box", (*centre, 0.0), "0.5 5 0.05", np.degrees(np.arctan2(n[1], n[0]))
    # the surface's compliance: the geom's body on two slide joints, spring k_e and damper d_e
    mount = (f'<body name="surface" pos="{pos[0]} {pos[1]} 0">'
             f'<joint name="w_x" type="slide" axis="1 0 0" stiffness="{c.stiffness}" damping="{c.damping}"/>'
             f'<joint name="w_y" type="slide" axis="0 1 0" stiffness="{c.stiffness}" damping="{c.damping}"/>'
             f'<inertial pos="0 0 0" mass="{max(mount_mass, tiny)}" diaginertia="{tiny} {tiny} {tiny}"/>'
             f'<geom name="surface" type="{shape}" size="{size}" euler="0 0 {euler}"/></body>')
    return f"""<mujoco model="paper_experiment">
  <option timestep="{exp.step}" integrator="RK4" gravity="0 0 0" cone="elliptic"/>
  <default><geom contype="1" conaffinity="1" condim="1"
      solref="{-rate**2} {-2 * rate}" solimp="0.9999 0.9999 0.001 0.5 2" margin="{MARGIN}"/></default>
  <worldbody>
    <body name="link1">
      <joint name="q1" type="hinge" axis="0 0 1" damping="{arm.V1}"/>
      <inertial pos="{arm.d1} 0 0" mass="{max(arm.m1, tiny)}" diaginertia="{arm.I1 / 2} {arm.I1 / 2} {arm.I1}"/>
      <body name="link2" pos="{arm.L1} 0 0">
        <joint name="q2" type="hinge" axis="0 0 1" damping="{arm.V2}"/>
        <inertial pos="{arm.d2} 0 0" mass="{max(arm.m2, tiny)}" diaginertia="{arm.I2 / 2} {arm.I2 / 2} {arm.I2}"/>
        <site name="tip" pos="{arm.L2} 0 0"/>
      </body>
    </body>
    <body name="sensor">
      <joint name="s_x" type="slide" axis="1 0 0"/>
      <joint name="s_y" type="slide" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="{s.mass}" diaginertia="{tiny} {tiny} {tiny}"/>
      <geom name="sensor_tip" type="sphere" size="{SENSOR_RADIUS}" contype="2" conaffinity="1"/>
    </body>
    {mount}
  </worldbody>
  <contact><exclude body1="link1" body2="link2"/></contact>
</mujoco>"""


class MujocoPlant(NativePlant):
    """The paper's plant simulated by MuJoCo; state ``x = (q, q', s, s')`` as the generated plant's,
    whose output record (computed from the state) it shares."""

    def __init__(self, exp):
        self.mj = _mujoco()
        super().__init__(exp)
        self.exp = exp
        self.model = self.mj.MjModel.from_xml_string(model_xml(exp))
        self.data = self.mj.MjData(self.model)
        self._tip = self.model.site("tip").id
        self._jac = np.zeros((3, self.model.nv))
        self._last = None  # (state, MuJoCo qpos, qvel) after the last advance

    # the sensor's spring-damper and the friction, added to MuJoCo's passive forces at every evaluation
    def _passive(self, model, data) -> None:
        sensor, c = self.exp.sensor, self.exp.contact
        self.mj.mj_jacSite(model, data, self._jac, None, self._tip)
        r, rd = data.site_xpos[self._tip][:2], (self._jac @ data.qvel)[:2]
        s, sd = data.qpos[2:4], data.qvel[2:4]
        F = sensor.stiffness * (s - r) + sensor.damping * (sd - rd)
        data.qfrc_passive[:2] += self._jac[:2, :2].T @ F
        data.qfrc_passive[2:4] -= F
        if c.friction:
            w, wd = data.qpos[4:6], data.qvel[4:6]
            normal = self._normal(s, w)
            # the normal force is what the surface's mount carries: N n = -(k_e w + d_e w')
            N = max(0.0, -normal @ (c.stiffness * w + c.damping * wd))
            tangent = np.array([-normal[1], normal[0]])
            f = -c.friction * N * np.tanh(tangent @ (sd - wd) / c.friction_smoothing) * tangent
            data.qfrc_passive[2:4] += f
            data.qfrc_passive[4:6] -= f

    def _normal(self, s: np.ndarray, w) -> np.ndarray:
        """The surface's unit normal at the sensor tip, the surface displaced by its mount's ``w``."""
        surf = self.exp.surface
        if surf.kind == "circle":
            rel = s - np.asarray(surf.center) - w
            return rel / np.linalg.norm(rel)
        return np.asarray(surf.normal, float) / np.linalg.norm(surf.normal)

    def _set(self, x: np.ndarray) -> None:
        """MuJoCo's state for the plant state ``x``: the surface mount continues from where the last
        step left it when ``x`` is that step's state, else it starts at rest, displaced by the
        sensor tip's penetration (the penalty's static deflection)."""
        d = self.data
        if self._last is not None and np.array_equal(x, self._last[0]):
            d.qpos[:], d.qvel[:] = self._last[1], self._last[2]
            return
        d.qpos[:4], d.qvel[:4] = x[[0, 1, 4, 5]], x[[2, 3, 6, 7]]
        penetration = self._record_row(x)[self.record["outputs"].index("penetration")]
        d.qpos[4:6], d.qvel[4:6] = -self._normal(x[4:6], 0.0) * max(penetration, 0.0), 0.0

    def _state(self) -> np.ndarray:
        d = self.data
        return np.array([d.qpos[0], d.qpos[1], d.qvel[0], d.qvel[1], d.qpos[2], d.qpos[3], d.qvel[2], d.qvel[3]])

    def advance(self, x: np.ndarray, tau: np.ndarray, nsteps: int, trajectory: np.ndarray) -> int:
        """Advance ``x`` in place by ``nsteps`` MuJoCo RK4 steps with ``tau`` held; steps done (MuJoCo
        resets a state it finds unstable: that counts as the state going non-finite)."""
        mj, d = self.mj, self.data
        self._set(x)
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[:2] = tau
        previous = mj.get_mjcb_passive()
        mj.set_mjcb_passive(self._passive)
        try:
            for k in range(nsteps):
                mj.mj_step(self.model, d)
                state = self._state()
                if d.warning[mj.mjtWarning.mjWARN_BADQACC].number or not np.isfinite(state).all():
                    return k
                x[:] = trajectory[k] = state
        finally:
            mj.set_mjcb_passive(previous)
        self._last = (x.copy(), d.qpos.copy(), d.qvel.copy())
        return nsteps
