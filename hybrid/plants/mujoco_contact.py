"""MuJoCo's own contact against a part's mesh: the independent check of a run on a part (``plant="mujoco_contact"``).

:class:`MujocoContactPlant` is :class:`~hybrid.plants.mujoco.MujocoPlant` (MuJoCo's arm, the sensor tip on
three slide joints, the sensor's spring-damper) but for the contact: the part is a mesh geom of the
:class:`~hybrid.MeshSurface`'s own facets and the sensor tip a sphere of :data:`TIP_RADIUS`, and MuJoCo's
collision detection and soft-contact solver give the normal force and the friction, not the library's fitted
surface and penalty formula. What differs, and why:

- the surface: MuJoCo collides with the mesh (its convex hull: a convex part only), the controller's frame is
  the fitted smooth surface's; the sensor tip's centre rides a tip radius off the facets;
- the normal force: MuJoCo's soft constraint, ``a_1 + d (b v + k r) = (1 - d) a_0`` with a constant
  impedance ``d`` (:data:`IMPEDANCE`) and the reference's stiffness and damping (``solref`` negative)
  ``k = (1 - d) k_e / (d m_s)``, ``b = (1 - d) d_e / (d m_s)`` for the sensor tip's mass ``m_s``: at rest under a
  force ``F`` the overlap is ``F / k_e``, as the penalty's (``tests/test_parts.py`` measures it), but the force
  is the solver's, not ``N = max(0, k_e delta + d_e delta')``;
- the friction: MuJoCo's elliptic friction cone with the contact's coefficient, where the generated plant
  smooths Coulomb's law with ``tanh(|v| / v_eps)``.

The record is the generated plant's formulas read on MuJoCo's states (its force columns are the sensor's
spring: what the controller measures), but for its contact columns (``N``, ``friction``, ``penetration``):
MuJoCo's own contact forces and overlap at each state.
"""

from __future__ import annotations

import numpy as np

from hybrid.errors import HybridError
from hybrid.plants.mujoco import MujocoPlant

#: the sensor tip's radius [m] in MuJoCo's collision
TIP_RADIUS = 1e-3
#: MuJoCo's contact impedance ``d``, the same at every overlap (``solimp``'s d0 and d_width)
IMPEDANCE = 0.9


class MujocoContactPlant(MujocoPlant):
    """MuJoCo as the plant of ``exp`` on its part (a :class:`~hybrid.MeshSurface`), with MuJoCo's own collision
    and contact (module docstring)."""

    def __init__(self, exp, robot, sensor_gravity: bool = True):
        part = exp.surface
        if getattr(part, "faces", None) is None:
            raise HybridError("plant='mujoco_contact' collides with a part's facets: give the experiment a "
                              "hybrid.MeshSurface, or take plant='mujoco' (the library's contact)")
        import trimesh

        if part.flip or not trimesh.Trimesh(part.vertices, part.faces, process=False).is_convex:
            raise HybridError("plant='mujoco_contact': MuJoCo collides with a mesh's convex hull, from outside; this "
                              "part is not convex (or is worked from inside, flip=True): take plant='mujoco' (the "
                              "library's contact)")
        super().__init__(exp, robot, sensor_gravity)

    def _collides(self, spec, sensor) -> bool:
        mj, part, contact = self.mj, self.exp.surface, self.exp.contact
        mass = self.exp.sensor.mass
        spec.add_mesh(name="part", uservert=np.asarray(part.vertices, float).ravel().tolist(),
                      userface=np.asarray(part.faces, int).ravel().tolist())
        spec.option.cone = mj.mjtCone.mjCONE_ELLIPTIC
        soft = (1 - IMPEDANCE) / (IMPEDANCE * mass)
        settings = {"contype": 1, "conaffinity": 1, "condim": 3, "friction": [contact.friction, 0.0, 0.0],
                    "solref": [-soft * contact.stiffness, -soft * contact.damping],
                    "solimp": [IMPEDANCE, IMPEDANCE, 1e-3, 0.5, 2.0]}
        spec.worldbody.add_geom(type=mj.mjtGeom.mjGEOM_MESH, meshname="part", **settings)
        sensor.add_geom(type=mj.mjtGeom.mjGEOM_SPHERE, size=[TIP_RADIUS, 0.0, 0.0], **settings)
        return True

    def _surface_force(self, s: np.ndarray, sd: np.ndarray) -> np.ndarray:
        return np.zeros(len(s))  # MuJoCo's contact acts through its constraints

    def outputs(self, states: np.ndarray) -> np.ndarray:
        """The generated plant's record of each state, its contact columns MuJoCo's: ``N`` the normal force of
        the tip's contacts [N], ``friction`` their tangential force [N], ``penetration`` the deepest overlap
        [m] (0 out of contact)."""
        out = super().outputs(states)
        names = self.record["outputs"]
        columns = [names.index(c) for c in ("N", "friction", "penetration")]
        mj, model, data, force = self.mj, self.model, self.data, np.zeros(6)

        def read() -> None:  # the constraint forces need the sensor's spring among the forces they balance
            for row, x in zip(out, states):
                self._set(x)
                data.qfrc_applied[:] = 0.0
                mj.mj_forward(model, data)
                normal = tangential = overlap = 0.0
                for i in range(data.ncon):
                    mj.mj_contactForce(model, data, i, force)
                    normal += force[0]
                    tangential += float(np.hypot(force[1], force[2]))
                    overlap = max(overlap, -float(data.contact[i].dist))
                row[columns] = normal, tangential, overlap
        self._with_passive(read)
        return out
