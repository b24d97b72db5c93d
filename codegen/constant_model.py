"""A constant model: a robot's kernels with its ``robot`` array compiled in as numbers.

The run-time-parameter kernels (:mod:`.robot_unit`) serve every parameter value from one build, as a
sweep or an identified model needs. A deployed arm has one set of parameters: put in as numbers,
CasADi folds what they make trivial as it rebuilds each expression (a product with an exact 0, a sum
with 0, a product with 1: a link's centre of mass on its axis, an inertia's zero products, a
joint without Coulomb friction, the gravity's zero components) and computes every product of two
parameters (a link's first moment ``m c``, its inertia about the joint frame's origin) once, here.
Its common subexpressions are then eliminated on the folded expressions (:func:`.casadi_backend.kernel_function`).
No number is rounded or snapped: the kernels are the run-time ones' at these values, to rounding.
"""

from __future__ import annotations

import dataclasses

import casadi as ca

from hybrid.spec.chain import parameter_digest

from .kernel import Kernel

#: the input the constant model removes: the run-time parameters
PARAMETERS = "robot"


def constant_kernels(kernels: tuple[Kernel, ...], values) -> tuple[tuple[Kernel, ...], dict]:
    """``kernels`` with their ``robot`` input replaced by the numbers ``values``, and what the unit's
    manifest says of the model (``{"model": {"constant": True, "robot": values, "robot_sha256": ...}}``:
    the numbers exactly, JSON's floats round-trip, and their :func:`hybrid.spec.chain.parameter_digest`).

    A kernel without the input is kept as it is; one more, ``constant_parameters``, writes the numbers
    compiled in (for a C caller to check or log them).
    """
    values = [float(v) for v in values]
    arrays = {a.expr.shape[0] for k in kernels for a in k.inputs if a.name == PARAMETERS}
    if arrays != {len(values)}:
        raise ValueError(f"a constant model needs {', '.join(map(str, sorted(arrays)))} parameters, "
                         f"got {len(values)}")
    folded = tuple(_folded(k, ca.DM(values)) for k in kernels)
    template = next(a for k in kernels for a in k.inputs if a.name == PARAMETERS)
    written = Kernel("constant_parameters", (), (dataclasses.replace(template, expr=ca.SX(ca.DM(values))),),
                     "the robot array compiled into this unit's kernels (inertial parameters, joint friction, "
                     "gravity)")
    model = {"constant": True, "robot": values, "robot_sha256": parameter_digest(values)}
    return (*folded, written), {"model": model}


def _folded(kernel: Kernel, values: ca.DM) -> Kernel:
    """``kernel`` without its ``robot`` input, the numbers in its place in every output and guard."""
    params = next((a for a in kernel.inputs if a.name == PARAMETERS), None)
    if params is None:
        return kernel
    exprs = [a.expr for a in kernel.outputs] + [g.expr for g in kernel.guards]
    # all at once: a subexpression the outputs share stays one node
    out = ca.substitute(exprs, [params.expr], [ca.SX(values)])
    outputs = tuple(dataclasses.replace(a, expr=e) for a, e in zip(kernel.outputs, out))
    guards = tuple(dataclasses.replace(g, expr=e) for g, e in zip(kernel.guards, out[len(outputs):]))
    return dataclasses.replace(kernel, inputs=tuple(a for a in kernel.inputs if a is not params), outputs=outputs,
                               guards=guards,
                               doc=f"{kernel.doc}; the robot's parameters compiled in (a constant model)")

