"""The joint-torque regressor of a serial chain: ``tau = Y(q, q', q'') pi``, as a CasADi kernel.

The ``robot`` array holds each link's centre of mass ``c`` and its inertia about ``c``: the
dynamics are not linear in those (``m c`` and ``m c c^T`` appear). They are linear in each link's
mass ``m``, first moment ``h = m c`` and inertia ``I_O = I_c + m (|c|^2 1 - c c^T)`` about the
joint frame's origin, all in the joint frame (:data:`hybrid.spec.chain.LINEAR`), and in the joint
friction's viscosities, Coulomb frictions and offsets (:data:`hybrid.spec.chain.LINEAR_FRICTION`).
With those as ``pi`` (:func:`hybrid.spec.chain.linear_parameter_names`), the recursive Newton-Euler
algorithm of :mod:`.body_frame` is written on symbols ``pi`` and ``Y`` is its Jacobian with respect
to them: exact, since ``tau`` is linear in ``pi``, and checked to be free of them. Gravity and the
Coulomb friction's smooth-sign speeds stay inputs: ``tau`` is linear in ``pi`` for given ``g`` and ``v_s``.
"""

from __future__ import annotations

import casadi as ca

from . import body_frame as bf
from . import rigid_body as rb
from .emit import Unit, assemble
from .kernel import Arg, Kernel


def link_inertias(tree: bf.Tree, pi) -> list[rb.Inertia]:
    """Each link's spatial inertia from its :data:`~hybrid.spec.chain.LINEAR` parameters in ``pi``
    (about the joint frame's origin), moved to the tree's origin of the link (slid along the joint
    axis by ``slide_i``, :class:`.body_frame.BodyFrames`)."""
    k, out = len(rb.LINEAR), []
    for i, joint in enumerate(tree.chain.joints):
        m, hx, hy, hz, ixx, ixy, ixz, iyy, iyz, izz = (pi[i * k + j] for j in range(k))
        inertia = rb.Inertia(m, ca.vertcat(hx, hy, hz),
                             ca.vertcat(ca.horzcat(ixx, ixy, ixz), ca.horzcat(ixy, iyy, iyz),
                                        ca.horzcat(ixz, iyz, izz)))
        slide = tree.frames.slide[i]
        if slide:  # the joint frame's origin is at -slide a_i from the tree's: X^T I X by that translation
            eye = ca.SX.eye(3)
            inertia = bf.LinkTransform(eye, eye, -slide * rb._vec(joint.axis)).inertia(inertia)
        out.append(inertia)
    return out


def regressor_kernel(chain: rb.Chain) -> Kernel:
    """``regressor``: ``Y`` (n x 13 n, row-major) of ``tau = Y pi`` at each state, gravity and the smooth
    sign's speeds inputs.

    Raises
    ------
    ValueError
        ``Y`` depends on ``pi`` (the dynamics written are not linear in it).
    """
    n = chain.n
    names = tuple(j.name for j in chain.joints)
    q, qd, qdd = (ca.SX.sym(s, n) for s in ("q", "qd", "qdd"))
    g, vs = ca.SX.sym("g", 3), ca.SX.sym("coulomb_speed", n)
    pi = ca.SX.sym("pi", len(rb.linear_parameter_names(chain)))
    tree = bf.link_transforms(chain, q)
    # the robot array the RNEA reads its friction and gravity from (the FRICTION blocks: the linear ones,
    # then the smooth sign's speeds); its inertial entries are unused
    robot = ca.vertcat(ca.SX.zeros(len(rb.INERTIAL) * n), pi[len(rb.LINEAR) * n:], vs, g)
    # the Coulomb term as a plain product: the run-time branch on F_c = 0 would make Y depend on F_c
    friction = rb.joint_friction(chain, robot, qd, linear=True)
    tau = bf.rnea(tree, robot, qd, qdd, bodies=link_inertias(tree, pi), friction=friction)
    Y = ca.jacobian(tau, pi)
    if ca.depends_on(Y, pi):
        raise ValueError("the regressor depends on the parameters: tau is not linear in them")
    return Kernel(
        "regressor",
        (Arg("q", q, rb.joint_units(chain, "q"), names=names), Arg("qd", qd, rb.joint_units(chain, "qd"), names=names),
         Arg("qdd", qdd, rb.joint_units(chain, "qdd"), names=names), Arg("g", g, "m/s^2"),
         Arg("coulomb_speed", vs, rb.joint_units(chain, "qd"), names=names)),
        (Arg("Y", rb.row_major(Y), "the joint's effort unit per the parameter's (joint rows, parameter columns)",
             (n, Y.shape[1])),),
        "joint-torque regressor Y(q, q', q'') of tau = Y pi, pi per link (m, m c, I about the joint frame's "
        "origin), then the joints' viscosities, Coulomb frictions (smooth sign tanh(q'/coulomb_speed)) and offsets; "
        "gravity g in base axes", batched=("q", "qd", "qdd"))


def build_regressor_unit(chain: rb.Chain, prefix: str, info: dict) -> Unit:
    """C source, header and manifest of ``chain``'s regressor, deterministic in its inputs; ``info`` (robot
    name, joints) goes into the manifest, with the names of ``pi``."""
    names = rb.linear_parameter_names(chain)
    return assemble(prefix, "casadi", (regressor_kernel(chain),),
                    f"joint-torque regressor of the {chain.n}-joint serial arm '{info.get('robot', prefix)}'",
                    info={"robot": info, "parameters": list(names),
                          "parameter_units": list(rb.linear_parameter_units(chain))},
                    tool=f"CasADi {ca.__version__}", defines={"NQ": chain.n, "NPI": len(names)})
