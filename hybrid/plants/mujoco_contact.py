"""MuJoCo's own contact against a part's mesh: the independent check of a run on a part (``plant="mujoco_contact"``).

:class:`MujocoContactPlant` is :class:`~hybrid.plants.mujoco.MujocoPlant` (MuJoCo's arm, the sensor tip on
three slide joints, the sensor's spring-damper) but for the contact: the part is the
:class:`~hybrid.MeshSurface`'s own facets and the sensor tip a sphere of :data:`TIP_RADIUS`, and MuJoCo's
collision detection and soft-contact solver give the normal force and the friction, not the library's fitted
surface and penalty formula. What differs, and why:

- the surface: MuJoCo collides with the facets, the controller's frame is the fitted smooth surface's; the sensor
  tip's centre rides a tip radius off the facets. MuJoCo collides a mesh geom through its convex hull, which is the
  part only where the part is closed, convex and worked from outside: such a part is one mesh geom. Any other part
  (not convex, open, or worked from inside) is a rigid flex of its facets, which MuJoCo collides triangle by
  triangle (its documented non-convex mesh collision): the facets themselves, each thickened by
  :data:`FACET_RADIUS` (which the tip's sphere gives up). A flex's cost per step grows with its triangles, so it
  holds the facets near the sensor tip (:class:`FacetWindow`), rewritten before the tip can reach one it does not
  hold. A flex has no inside: the tip pressed deeper into it than :data:`DEEPEST` of its radius is refused
  (:class:`~hybrid.HybridError`), before it could pass through;
- the normal force: MuJoCo's soft constraint, ``a_1 + d (b v + k r) = (1 - d) a_0`` with a constant
  impedance ``d`` (:data:`IMPEDANCE`) and the reference's stiffness and damping (``solref`` negative)
  ``k = (1 - d) k_e / (d m_s)``, ``b = (1 - d) d_e / (d m_s)`` for the sensor tip's mass ``m_s``: at rest under a
  force ``F`` on one contact the overlap is ``F / k_e``, as the penalty's (``tests/test_parts.py`` measures it), but
  the force is the solver's, not ``N = max(0, k_e delta + d_e delta')``. Each contact acts so: where the tip
  touches ``n`` facets at once (in a valley between facets of a concave part) the overlap is about ``F / (n k_e)``;
- the friction: MuJoCo's elliptic friction cone with the contact's coefficient, where the generated plant
  smooths Coulomb's law with ``tanh(|v| / v_eps)``.

The record is the generated plant's formulas read on MuJoCo's states (its force columns are the sensor's
spring: what the controller measures), but for its contact columns (``N``, ``friction``, ``penetration``):
MuJoCo's own contact forces and overlap at each state.
"""

from __future__ import annotations

import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.part_fit import kd_tree
from hybrid.plants.mujoco import MujocoPlant

#: the sensor tip's radius [m] in MuJoCo's collision: its centre rides this far off the facets
TIP_RADIUS = 1e-3
#: MuJoCo's contact impedance ``d``, the same at every overlap (``solimp``'s d0 and d_width)
IMPEDANCE = 0.9
#: the flex's radius [m] (MuJoCo needs one above 0): each facet thickened by this on both sides, taken off the
#: tip's sphere so that the tip's centre still rides :data:`TIP_RADIUS` off the facets
FACET_RADIUS = 1e-6
#: the radius [m] about the sensor tip within which the flex holds every facet (fewer where more than
#: :data:`WINDOW_SLOTS` facets lie there), and the flex's triangles
WINDOW, WINDOW_SLOTS = 0.01, 256
#: the deepest overlap of the facets the flex takes, a share of :data:`TIP_RADIUS`: the tip's centre would pass the
#: facets at 1 (MuJoCo's contact then pushes it through); the overlap at rest is ``F / k_e``
DEEPEST = 0.5
#: how far beyond the part's bounding box [m] the flex's unused triangles are parked (out of any arm's reach)
PARKED = 100.0
#: the largest distance [m] of a vertex in front of a neighbouring facet's plane in a part taken as convex
CONVEX_TOL = 1e-7


def hull_is_part(vertices: np.ndarray, faces: np.ndarray) -> bool:
    """Whether the mesh is its own convex hull, seen from the side its normals point to: closed, in one piece, its
    normals outward and every edge convex (the vertex of each facet opposite an edge no farther than
    :data:`CONVEX_TOL` in front of the other facet's plane): then MuJoCo's mesh geom, which collides through the
    hull, is the part."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    v, f = np.asarray(vertices, float), np.asarray(faces, np.int64)
    count = len(v)
    # each directed edge (a -> b) of a facet, and the vertex of that facet opposite it
    a, b, opposite = (np.concatenate([f[:, i], f[:, (i + 1) % 3], f[:, (i + 2) % 3]]) for i in range(3))
    owner = np.tile(np.arange(len(f)), 3)
    key, reverse = a * count + b, b * count + a
    order = np.argsort(key)
    at = np.searchsorted(key[order], reverse)
    at = np.minimum(at, len(key) - 1)
    if not np.array_equal(key[order][at], reverse):
        return False  # an edge with one facet: open
    neighbour = owner[order][at]  # the facet across each edge
    if connected_components(coo_matrix((np.ones(len(owner)), (owner, neighbour)), shape=(len(f),) * 2),
                            directed=False)[0] != 1:
        return False
    p0, p1, p2 = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    normal = np.cross(p1 - p0, p2 - p0)
    if np.einsum("ij,ij->", p0, normal) <= 0:  # six times the enclosed volume: normals inward
        return False
    unit = normal / np.linalg.norm(normal, axis=1, keepdims=True)
    ahead = np.einsum("ij,ij->i", v[opposite[order][at]] - v[a], unit[owner])
    return bool(ahead.max() <= CONVEX_TOL)


class FacetWindow:
    """The part's facets near the sensor tip, in MuJoCo's flex of :data:`WINDOW_SLOTS` triangles (each its own
    three vertices; all the part's where it has no more): every facet within :attr:`reach` of :attr:`centre`,
    rewritten about the tip before the tip's sphere could reach a facet beyond.

    Parameters
    ----------
    triangles : numpy.ndarray
        The part's facets, F x 3 x 3 [m].
    """

    def __init__(self, triangles: np.ndarray):
        self.triangles = triangles
        self.centroids = triangles.mean(axis=1)
        # no point of a facet lies farther from its centroid than its farthest vertex
        self.spread = np.linalg.norm(triangles - self.centroids[:, None], axis=2).max(axis=1)
        self.widest = float(self.spread.max())
        self.slots = min(WINDOW_SLOTS, len(triangles))
        self.tree = kd_tree(self.centroids) if len(triangles) > self.slots else None
        self.parked = (self.centroids.max(axis=0) + PARKED) + 1e-3 * np.eye(3)
        self.centre, self.reach = None, -math.inf

    def holds(self, tip: np.ndarray, margin: float) -> bool:
        """Whether every facet within ``margin`` of ``tip`` is held."""
        return self.centre is not None and math.dist(tip, self.centre) + margin < self.reach

    def move(self, tip: np.ndarray, vertices: np.ndarray, margin: float) -> None:
        """Hold the facets about ``tip`` in the flex's ``vertices`` (MuJoCo's model's, 3 slots x 3 rows): every
        facet within :data:`WINDOW` of it, or the nearest where more lie there; refused where those within
        ``margin`` of it do not fit."""
        self.centre = np.array(tip, float)
        if self.tree is None:
            vertices[:] = self.triangles.reshape(-1, 3)
            self.reach = math.inf
            return
        near = np.asarray(self.tree.query_ball_point(tip, WINDOW + self.widest), dtype=np.int64)
        # no point of a facet is nearer the tip than its centroid's distance less its spread
        nearest = np.linalg.norm(self.centroids[near] - tip, axis=1) - self.spread[near]
        self.reach = WINDOW
        if len(near) > self.slots:
            order = np.argsort(nearest)
            self.reach = min(WINDOW, float(nearest[order[self.slots]]))
            near = near[order[:self.slots]]
        if self.reach <= margin:
            raise HybridError(f"plant='mujoco_contact': more than {self.slots} of the part's facets lie within "
                              f"{margin * 1e3:.3g} mm of the sensor tip; give a coarser mesh where the tool works "
                              "(trimesh: mesh.simplify_quadric_decimation)")
        held = np.concatenate([self.triangles[near], np.broadcast_to(self.parked, (self.slots - len(near), 3, 3))])
        vertices[:] = held.reshape(-1, 3)


class MujocoContactPlant(MujocoPlant):
    """MuJoCo as the plant of ``exp`` on its part (a :class:`~hybrid.MeshSurface`), with MuJoCo's own collision
    and contact (module docstring)."""

    def __init__(self, exp, robot, sensor_gravity: bool = True):
        part = exp.surface
        if getattr(part, "faces", None) is None:
            raise HybridError("plant='mujoco_contact' collides with a part's facets: give the experiment a "
                              "hybrid.MeshSurface, or take plant='mujoco' (the library's contact)")
        triangles = np.asarray(part.vertices, float)[np.asarray(part.faces, np.int64)]
        # a closed convex part worked from outside is MuJoCo's mesh geom (its hull is the part), else a flex
        self.window = None if hull_is_part(part.vertices, part.faces) else FacetWindow(triangles)
        super().__init__(exp, robot, sensor_gravity)

    def _collides(self, spec, sensor) -> bool:
        mj, part, contact = self.mj, self.exp.surface, self.exp.contact
        mass = self.exp.sensor.mass
        spec.option.cone = mj.mjtCone.mjCONE_ELLIPTIC
        soft = (1 - IMPEDANCE) / (IMPEDANCE * mass)
        settings = {"contype": 1, "conaffinity": 1, "condim": 3, "friction": [contact.friction, 0.0, 0.0],
                    "solref": [-soft * contact.stiffness, -soft * contact.damping],
                    "solimp": [IMPEDANCE, IMPEDANCE, 1e-3, 0.5, 2.0]}
        radius = TIP_RADIUS
        if self.window is None:
            spec.add_mesh(name="part", uservert=np.asarray(part.vertices, float).ravel().tolist(),
                          userface=np.asarray(part.faces, int).ravel().tolist())
            spec.worldbody.add_geom(type=mj.mjtGeom.mjGEOM_MESH, meshname="part", **settings)
        else:  # the facets near the tip, each triangle its own three vertices, fixed in the world
            flex = spec.add_flex(name="part", dim=2, radius=FACET_RADIUS, vertbody=["world"],
                                 vert=np.tile(self.window.parked, (self.window.slots, 1)).ravel().tolist(),
                                 elem=list(range(3 * self.window.slots)), **settings)
            flex.selfcollide = mj.mjtFlexSelf.mjFLEXSELF_NONE
            radius -= FACET_RADIUS
        sensor.add_geom(type=mj.mjtGeom.mjGEOM_SPHERE, size=[radius, 0.0, 0.0], **settings)
        return True

    def _surface_force(self, s: np.ndarray, sd: np.ndarray) -> np.ndarray:
        return np.zeros(len(s))  # MuJoCo's contact acts through its constraints

    # ------------------------------------------------------------------ the flex's window and depth

    def _follow(self) -> None:
        """Hold the facets about the sensor tip, with a margin of the tip's radius and twice its travel in a step."""
        n, d = self.nq, self.data
        tip, speed = d.qpos[n:n + 3], math.sqrt(d.qvel[n:n + 3] @ d.qvel[n:n + 3])
        margin = 2 * TIP_RADIUS + 2 * speed * self.model.opt.timestep
        if not math.isfinite(margin + tip.sum()):
            return  # a state gone non-finite: the runner stops there and says why
        if not self.window.holds(tip, margin):
            self.window.move(tip, self.model.flex_vert, margin)

    def _set(self, x: np.ndarray) -> None:
        super()._set(x)
        if self.window is not None:
            self._follow()

    def _step(self) -> None:
        super()._step()
        if self.window is None:
            return
        d = self.data
        if d.ncon:
            deepest = -float(d.contact.dist[:d.ncon].min())
            if deepest > DEEPEST * TIP_RADIUS:
                tip = np.round(d.qpos[self.nq:self.nq + 3], 4).tolist()
                raise HybridError(
                    f"plant='mujoco_contact': the sensor tip pressed {deepest * 1e3:.3g} mm into the part's facets "
                    f"at {tip} m (at most {DEEPEST * TIP_RADIUS * 1e3:g} mm: MuJoCo's facets have no inside, the tip "
                    "would pass through); give a smaller force or a stiffer contact (Contact.stiffness)")
        self._follow()

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
