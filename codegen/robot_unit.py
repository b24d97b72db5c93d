"""Kernels of one serial arm (from its URDF), emitted by the CasADi backend.

The kinematic structure (joint origins, axes, types, the tip frame) is compiled in; the
``robot`` array (inertial parameters, joint friction, gravity) is a run-time input, so a
model error or a parameter sweep never recompiles (a deployed arm's may be compiled in:
:mod:`.constant_model`). Every solve is a factorisation.
"""

from __future__ import annotations

import casadi as ca

from . import body_frame as bf
from . import rigid_body as rb
from . import tip_kinematics as tk
from .constant_model import constant_kernels
from .controller_step import controller_kernels
from .emit import Unit, assemble
from .factor import ldl_solve
from .kernel import Arg, Kernel
from .safe_stop import safe_stop_kernel
from .spatial_plant import plant_kernels
from .surfaces import phi_of
from .task_law import AXIS_NAMES, frame_kernel, law_kernels, operational_space_kernels


def robot_kernels(chain: rb.Chain, defaults=None) -> tuple[Kernel, ...]:
    """``robot_terms`` (tip pose, ``J``, ``J' q'``, ``B``, ``n``), ``inverse_dynamics`` (RNEA) and
    ``forward_dynamics`` (``B^-1 (tau - n)`` by ``L D L^T``), each batched over states (the dynamics in
    body coordinates, :mod:`.body_frame`, and the kinematics from the same transforms,
    :mod:`.tip_kinematics`); with
    ``defaults`` (the URDF's ``robot`` array) also ``urdf_parameters``, which writes them."""
    n = chain.n
    names = tuple(j.name for j in chain.joints)
    q, qd, qdd, tau = (ca.SX.sym(s, n) for s in ("q", "qd", "qdd", "tau"))
    params = ca.SX.sym("robot", len(rb.parameter_names(chain)))
    tree = bf.link_transforms(chain, q)  # the kinematics and the dynamics in body coordinates
    fr = tk.placements(tree)
    B = bf.crba(tree, params)
    bias = bf.rnea(tree, params, qd)
    a_q = Arg("q", q, rb.joint_units(chain, "q"), names=names)
    a_qd = Arg("qd", qd, rb.joint_units(chain, "qd"), names=names)
    a_p = Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain))
    terms = Kernel(
        "robot_terms", (a_q, a_qd, a_p),
        (Arg("p", fr.tip_p, "m"), Arg("rotation", rb.row_major(fr.tip_R), "1", (3, 3)),
         Arg("J", rb.row_major(tk.frame_jacobian(tree, fr)), "m/rad, 1 (linear rows, then angular)", (6, n)),
         Arg("Jdqd", tk.classical_acceleration(tree, fr, qd), "m/s^2, rad/s^2"),
         Arg("B", rb.row_major(B), "kg m^2", (n, n)), Arg("n", bias, rb.joint_units(chain, "tau"))),
        "tip frame position p [m] and rotation (row-major) in base axes, frame Jacobian J (6 x n, "
        "LOCAL_WORLD_ALIGNED), J'(q, q') q' (classical), inertia B(q) (CRBA), n(q, q') (RNEA: "
        "Coriolis/centrifugal, gravity, viscosity)", batched=("q", "qd"))
    inverse = Kernel(
        "inverse_dynamics", (a_q, a_qd, Arg("qdd", qdd, rb.joint_units(chain, "qdd"), names=names), a_p),
        (Arg("tau", bf.rnea(tree, params, qd, qdd), rb.joint_units(chain, "tau")),),
        "inverse dynamics tau = B(q) q'' + n(q, q') by recursive Newton-Euler", batched=("q", "qd", "qdd"),
        order="fewest_alive")
    forward = Kernel(
        "forward_dynamics", (a_q, a_qd, Arg("tau", tau, rb.joint_units(chain, "tau"), names=names), a_p),
        (Arg("qdd", ldl_solve(B, tau - bias), rb.joint_units(chain, "qdd")),),
        "forward dynamics q'' = B(q)^-1 (tau - n(q, q')) by a square-root-free Cholesky factorisation of B "
        "(L D L^T)",
        batched=("q", "qd", "tau"))
    kernels = (terms, inverse, forward)
    if chain.n >= 6:  # a full-rank 6 x n Jacobian is possible: the operational space exists
        kernels += operational_space_kernels(chain)
    if defaults is None:
        return kernels
    values = Arg("robot", ca.SX(ca.DM([float(v) for v in defaults])), a_p.unit, names=a_p.names)
    urdf = Kernel("urdf_parameters", (), (values,),
                  "the robot array as the URDF gives it (inertial parameters, joint friction, gravity)")
    return (*kernels, urdf)


def inertia_kernel(chain: rb.Chain) -> Kernel:
    """``inertia``: the joint-space inertia ``B(q)`` alone, by the body-frame CRBA ``robot_terms`` forms it
    with (the benchmarks set it beside other implementations' CRBA)."""
    names = tuple(j.name for j in chain.joints)
    q, params = ca.SX.sym("q", chain.n), ca.SX.sym("robot", len(rb.parameter_names(chain)))
    B = bf.crba(bf.link_transforms(chain, q), params)
    return Kernel("inertia", (Arg("q", q, rb.joint_units(chain, "q"), names=names),
                              Arg("robot", params, rb.parameter_units(chain), names=rb.parameter_names(chain))),
                  (Arg("B", rb.row_major(B), "kg m^2", (chain.n, chain.n)),), "inertia B(q) (CRBA), row-major",
                  order="fewest_alive")


def build_inertia_unit(chain: rb.Chain, prefix: str, info: dict, values=None) -> Unit:
    """C source, header and manifest of ``chain``'s :func:`inertia_kernel` alone; with ``values`` (a
    robot's array), compiled into it (:mod:`.constant_model`: the kernel then takes no ``robot`` array)."""
    kernels, model = constant_kernels((inertia_kernel(chain),), values) if values is not None else (
        (inertia_kernel(chain),), {})
    return assemble(prefix, "casadi", kernels,
                    f"joint-space inertia of the {chain.n}-joint serial arm '{info.get('robot', prefix)}'"
                    + (", its parameters compiled in" if values is not None else ""),
                    info={"robot": info, **model}, tool=f"CasADi {ca.__version__}", defines={"NQ": chain.n})


def build_robot_unit(chain: rb.Chain, prefix: str, info: dict, defaults=None, constant: bool = False) -> Unit:
    """C source, header and manifest of ``chain``'s kernels, deterministic in its inputs.

    ``info`` (robot name, tip, joint names, ...) goes into the manifest as it is; ``defaults``
    adds ``<prefix>_urdf_parameters(robot)`` returning the URDF's parameter values. With ``constant``,
    ``defaults`` (a robot's array) is compiled into the kernels instead, which take no ``robot`` array
    (:mod:`.constant_model`).
    """
    kernels, model = constant_kernels(robot_kernels(chain), defaults) if constant else (
        robot_kernels(chain, defaults), {})
    return assemble(prefix, "casadi", kernels,
                    f"rigid-body kernels of the {chain.n}-joint serial arm '{info.get('robot', prefix)}'"
                    + (", its parameters compiled in" if constant else ""),
                    info={"robot": info, **model}, tool=f"CasADi {ca.__version__}",
                    defines={"NQ": chain.n, "ROBOT_SIZE": len(rb.parameter_names(chain))})


def build_law_unit(chain: rb.Chain, spec, axes: tuple[int, ...], prefix: str, info: dict) -> Unit:
    """The task frame and decoupling law of ``chain`` on the surface ``spec`` for the task ``axes``."""
    return _task_unit(law_kernels(chain, spec, axes), "decoupling law", chain, spec, axes, prefix, info)


def build_controller_unit(chain: rb.Chain, spec, axes: tuple[int, ...], prefix: str, info: dict,
                          variant: dict) -> Unit:
    """One control sample (measurement, loops, law) of ``chain`` on ``spec`` for the task ``axes``;
    ``variant`` holds the compiled-in options (``desired_frame``, ``position_error``)."""
    kernels = (*controller_kernels(chain, spec, axes, **variant), safe_stop_kernel(chain))
    return _task_unit(kernels, "controller step", chain, spec, axes,
                      prefix, info, variant)


def build_plant_unit(chain: rb.Chain, spec, prefix: str, info: dict) -> Unit:
    """The 3-D experiment's plant (arm, sensor, contact on ``spec``) with its RK4 entry point."""
    return assemble(prefix, "casadi", plant_kernels(chain, spec),
                    f"plant of the 3-D experiment: the {chain.n}-joint arm '{info.get('robot', prefix)}', a 3-D "
                    f"elastic sensor and penalty contact with friction on a {spec.kind}",
                    info={"robot": info, "surface": {"kind": spec.kind, "parameters": list(spec.parameters),
                                                      "phi": str(phi_of(spec))}},
                    tool=f"CasADi {ca.__version__}", defines={"NQ": chain.n, "NX": 2 * chain.n + 6})


def build_frame_unit(spec, prefix: str) -> Unit:
    """The task frame on the surface ``spec`` alone (no robot): ``R_L``, ``R_L'`` and the normal."""
    return assemble(prefix, "casadi", (frame_kernel(spec),), f"task frame on a {spec.kind}",
                    info={"surface": {"kind": spec.kind, "parameters": list(spec.parameters),
                                      "phi": str(phi_of(spec))}},
                    tool=f"CasADi {ca.__version__}")


def _phi_text(spec) -> str:
    """The surface's ``phi`` as text for a manifest; an estimated surface has none (the controller estimates
    its normal)."""
    return "estimated online" if spec.estimated else str(phi_of(spec))


def _task_unit(kernels, what: str, chain: rb.Chain, spec, axes, prefix: str, info: dict,
               variant: dict | None = None) -> Unit:
    extra = {"variant": variant} if variant else {}
    return assemble(prefix, "casadi", kernels,
                    f"{what} of the {chain.n}-joint arm '{info.get('robot', prefix)}' on a {spec.kind}, "
                    f"task axes {', '.join(AXIS_NAMES[i] for i in axes)}",
                    info={"robot": info, "surface": {"kind": spec.kind, "parameters": list(spec.parameters),
                                                      "phi": _phi_text(spec)}, "axes": list(axes), **extra},
                    tool=f"CasADi {ca.__version__}", defines={"NQ": chain.n, "M": len(axes)})
