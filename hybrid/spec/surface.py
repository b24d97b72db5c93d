"""What the code generator needs of a surface (:class:`SurfaceSpec`), and the built-in surfaces' ``phi``.

Each built-in surface (plane, sphere, cylinder) is ``phi(p, theta)`` of the point ``p`` (3) and its
run-time parameters ``theta`` (named in :data:`PARAMETERS`, in ``as_array`` order), written once here:
the generator compiles it, and the runtime's surface classes (:mod:`hybrid.geometry.surfaces`) evaluate
the same function with NumPy's or SymPy's numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

#: at or below this ``|grad phi|`` (and where it is not a finite number: the formula undefined there) a
#: surface has no normal, and no task frame: the generated frame's guard and the runtime's ``normal_at`` say so
NORMAL_TOL = 1e-12


@dataclass(frozen=True)
class SurfaceSpec:
    """What the code generator needs of a surface: ``kind`` (it names the generated code), the
    names of its run-time parameters, and ``phi``: a SymPy expression of ``x, y, z`` and those
    parameters (a user's surface), or a built-in surface's ``formula(p, theta, sqrt)`` of the point
    ``p`` (3) and the parameters ``theta`` (in ``as_array`` order), written once in :data:`FORMULAS`."""

    kind: str
    parameters: tuple[str, ...]
    phi: object = None
    #: ``phi`` as canonical text (SymPy's ``srepr``), which identifies it
    phi_text: str = "built-in"
    formula: object = None
    #: True for a surface the controller estimates (its parameters are the estimator's tuning): the
    #: task frame comes from the estimate, not from ``phi``
    estimated: bool = False

    def key(self) -> str:
        """A stable text identifying the surface's expression (for cache keys)."""
        return f"{self.kind}:{','.join(self.parameters)}:{self.phi_text}"


def plane_phi(p, theta, sqrt):
    """A plane through ``theta[0:3]`` with normal ``theta[3:6]`` (towards the robot): ``n^T (p - point) / |n|``."""
    n = theta[3:6]
    return sum(n[i] * (p[i] - theta[i]) for i in range(3)) / sqrt(sum(v * v for v in n))


def sphere_phi(p, theta, sqrt):
    """A sphere of centre ``theta[0:3]`` and radius ``theta[3]``: ``|p - c| - radius``."""
    return sqrt(sum((p[i] - theta[i]) ** 2 for i in range(3))) - theta[3]


def cylinder_phi(p, theta, sqrt):
    """A cylinder about the line through ``theta[0:3]`` along ``theta[3:6]``, of radius ``theta[6]``:
    ``|(I - u u^T)(p - point)| - radius``."""
    u = theta[3:6]
    d = [p[i] - theta[i] for i in range(3)]
    along = sum(u[i] * d[i] for i in range(3)) / sum(v * v for v in u)
    return sqrt(sum((d[i] - u[i] * along) ** 2 for i in range(3))) - theta[6]


def quadric_phi(p, theta, sqrt):
    """A surface's second-order expansion about the point ``theta[0:3]``: its ``phi`` there ``theta[3]``, its
    gradient ``theta[4:7]`` and its Hessian's upper triangle ``theta[7:13]`` (xx, xy, xz, yy, yz, zz):
    ``phi_0 + g^T d + d^T H d / 2`` with ``d = p - p_0`` (a part's surface about the point of contact)."""
    d = [p[i] - theta[i] for i in range(3)]
    hxx, hxy, hxz, hyy, hyz, hzz = theta[7:13]
    quadratic = (hxx * d[0] * d[0] + hyy * d[1] * d[1] + hzz * d[2] * d[2]
                 + 2 * (hxy * d[0] * d[1] + hxz * d[0] * d[2] + hyz * d[1] * d[2]))
    return theta[3] + sum(theta[4 + i] * d[i] for i in range(3)) + quadratic / 2


#: each built-in surface's ``phi(p, theta, sqrt)``, by kind
FORMULAS = {"plane": plane_phi, "sphere": sphere_phi, "cylinder": cylinder_phi, "quadric": quadric_phi}
#: each built-in surface's run-time parameters, in ``as_array`` order, by kind
PARAMETERS = {"plane": ("p_x", "p_y", "p_z", "n_x", "n_y", "n_z"), "sphere": ("c_x", "c_y", "c_z", "rho"),
              "cylinder": ("p_x", "p_y", "p_z", "u_x", "u_y", "u_z", "rho"),
              "quadric": ("p_x", "p_y", "p_z", "phi", "g_x", "g_y", "g_z", "h_xx", "h_xy", "h_xz", "h_yy", "h_yz",
                          "h_zz")}

