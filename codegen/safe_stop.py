"""The control step's fault reaction: the torque of its safe state (:data:`hybrid.spec.controller_step.SAFE_STOP`).

After ``fault_samples`` consecutive faulted samples (a refused input or parameter, the law failing, a
sample late or early) the standalone step and the :class:`hybrid.Controller` stop serving the law and
apply, until a reset,

    tau = tau_hold + s (tau_entry - tau_hold,entry),   tau_hold = B(q) w + n(q, q'),
    w = (q_stop - q) / tau_s^2 - 2 q' / tau_s,   s = max(0, 1 - k T / unload_time)

within the torque limits (the rate bound from the torque last written, then the magnitude's, as the
law's): ``tau_hold`` is the inverse dynamics of the controller's model for a critically damped hold
of every joint at ``q_stop``, the positions at the safe state's entry, with the time constant
``tau_s = stop_time`` (gravity, the velocity terms and the joints' viscosity compensated): the arm
brakes and comes back to rest there (with a wrong model, near it: the hold's stiffness
``B / tau_s^2`` bounds the drift a gravity error would cause), and a velocity into the part at the
entry brings the tool no deeper than ``tau_s / e`` times it. The hold acts in full from the entry; the
difference between the torque the arm had then (pressing on the part) and the hold's there is
released linearly over ``unload_time`` (``k`` the samples since then, ``T`` the sample time), so the
torque is continuous at the entry and the pressing decays at a bounded rate. The kernel works the
difference out at the entry (``samples`` 0: ``tau_offset`` holds the entry's torque) and gives it back
as ``tau_offset_next``, which the caller keeps. The hold keeps the tool where it was: the part of the
contact force the tool's and sensor's compliance stores stays (as an industrial arm's protective stop
keeps it). This is a controlled stop with the drives kept on (the stop category 2 of IEC 60204-1, as an
industrial arm's protective stop): the arm neither falls (a power-off) nor clamps the tool against the
part at the force it had (a brake), and the contact force decays at a bounded rate instead of
vanishing in one sample.
"""

from __future__ import annotations

import casadi as ca

from hybrid.spec.controller_step import FAULT, SAFE_STOP
from hybrid.spec.interfaces import Dims

from . import body_frame as bf
from . import rigid_body as rb
from .controller_step import bounded
from .kernel import Kernel, declared


def safe_stop_kernel(chain: rb.Chain) -> Kernel:
    """The ``safe_stop`` kernel of ``chain`` (module docstring)."""
    n = chain.n
    dims = Dims(tuple(j.name for j in chain.joints), (), rb.parameter_names(chain), ())
    sym = {p.name: ca.SX.sym(p.name, p.size_of(dims)) for p in SAFE_STOP.inputs}
    q, qd, last, state, params, fault, limits = (sym[k] for k in (
        "q", "qd", "last_torque", "fault_state", "robot", "fault", "limits"))
    T = sym["sample_time"]
    f = {name: fault[i] for i, name in enumerate(FAULT)}
    tree = bf.link_transforms(chain, q)
    tau_s = f["stop_time"]
    hold = bf.rnea(tree, params, qd, (state[2 * n:3 * n] - q) / (tau_s * tau_s) - 2 * qd / tau_s)
    samples = state[3 * n + 2]
    offset = ca.if_else(samples == 0, state[:n] - hold, state[:n])
    elapsed = samples * T
    share = ca.if_else(elapsed >= f["unload_time"], 0, 1 - elapsed / f["unload_time"])
    out = bounded(hold + share * offset, last, limits)
    joint_units = {"q": rb.joint_units(chain, "q"), "qd": rb.joint_units(chain, "qd"),
                   "last_torque": (*rb.joint_units(chain, "tau"), "1"), "robot": rb.parameter_units(chain)}
    return Kernel("safe_stop", declared(SAFE_STOP.inputs, dims, sym, joint_units),
                  declared(SAFE_STOP.outputs, dims, {"tau": out, "tau_offset_next": offset},
                           {"tau": rb.joint_units(chain, "tau"), "tau_offset_next": rb.joint_units(chain, "tau")}),
                  "the safe state's torque: the arm stopped and held at q_stop by its model's inverse dynamics "
                  "(time constant stop_time) and the torque at the fault's difference from it released over "
                  "unload_time, within the limits")
