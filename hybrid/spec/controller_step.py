"""The control step's interface: one sample of measurement, loops and law (``codegen.controller_step``).

Every variant of the step (the decoupling law, Raibert & Craig's scheme, the law with a posture
task) takes these inputs and gives these outputs, in this order. The inputs that change at every
sample come first: the caller's measurement (:data:`~hybrid.spec.interfaces.ARGUMENT`), the state
the step keeps between samples (:data:`~hybrid.spec.interfaces.STATE`, each written back from the
output ``<name>_next``, or from ``tau`` for ``last_torque``) and the references the caller computes
(:data:`~hybrid.spec.interfaces.REFERENCE`); then the configuration
(:data:`~hybrid.spec.interfaces.PARAMETER`).

Arrays of mixed numbers have their layouts here: :data:`LOOP_GAINS`, :data:`OPTIONS` (with
:data:`OPTION_DOCS`), :data:`POSTURE`, :data:`LIMITS`, :data:`SENSOR`, :data:`ESTIMATE`, :data:`FAULT` (with
:data:`FAULT_DOCS`) and :data:`FAULT_STATE`.

:data:`SAFE_STOP` is the step's fault reaction: the torque of its safe state (conventions, "The fault
reaction"), which the standalone C and the :class:`hybrid.Controller` apply after :data:`FAULT`'s
``fault_samples`` consecutive faulted samples, until a reset.
"""

from __future__ import annotations

from hybrid.spec.interfaces import (
    ARGUMENT,
    PARAMETER,
    REFERENCE,
    STATE,
    Interface,
    Named,
    PerAxis,
    PerJoint,
    Port,
)

#: per-axis loop gains, in this order in the ``gains`` array: ``KP`` is ``KPv`` on a velocity axis and ``KPf``
#: on a force axis, ``KI`` is ``KIv`` or ``KIf``, ``KI2`` is ``KI2v`` (0 on a force axis), ``KD`` is ``KDf``
#: (0 on a velocity axis): the names of :class:`hybrid.Gains` by the axis's kind
LOOP_GAINS = ("KP", "KI", "KI2", "KD")
#: the ``options`` array: switches (0/1) and numbers
OPTIONS = ("curvature", "sample_time", "khatib", "integral_limit", "loss_threshold", "approach_speed",
           "pseudoinverse")
#: what each option means (the standalone controller's header documents its fields with these)
OPTION_DOCS = {
    "curvature": "1: the law feeds the task frame's rate R' forward (the curvature term), 0: not [1]",
    "sample_time": "the sample period T at which the integrals advance [s]",
    "khatib": "1: the law takes the desired force R^T Sigma F_d (Khatib's scheme), 0: the measured wrench [1]",
    "integral_limit": "anti-windup: the largest integral action per axis [m/s^2 or rad/s^2]; 1e300: off",
    "loss_threshold": "a force axis whose force falls below this has lost contact [N or N m]; -1e300: off",
    "approach_speed": "the speed at which a force axis that lost contact approaches the surface [m/s or rad/s]",
    "pseudoinverse": "Raibert & Craig's scheme: 1: the selected rows' pseudo-inverse (Fisher & Mujtaba), 0: J_y^-1",
}
#: what each option may be (:data:`hybrid.spec.interfaces.CHECKS`): the switches 0 or 1, the sample time > 0,
#: the anti-windup limit and the approach speed >= 0 (1e300: off), the loss threshold any number (-1e300: off)
OPTION_CHECKS = ("switch", "positive", "switch", "nonnegative", "finite", "nonnegative", "switch")
#: the posture task's per-joint numbers, in this order (n each) in the ``posture`` array
POSTURE = ("q_rest", "Kp", "Kd")
#: the torque limits' per-joint numbers, in this order (n each) in the ``limits`` array
LIMITS = ("tau_max", "rate_max")
#: the largest finite double: a limit of it is none (bounding a finite torque by it changes nothing)
NO_LIMIT = 1.7976931348623157e308
#: the force/torque sensor's numbers (``hybrid.control.wrench_sensor``): the mount (position, rotation in
#: tip axes, row-major), the sign, the tool (mass, centre of mass in sensor axes), the bias, the filter
SENSOR = ("r_x", "r_y", "r_z", *(f"R_{i}{j}" for i in range(3) for j in range(3)), "sign", "tool_mass",
          "tool_cx", "tool_cy", "tool_cz", "bias_fx", "bias_fy", "bias_fz", "bias_mx", "bias_my", "bias_mz",
          "cutoff_hz", "order")
#: what each of the sensor's numbers may be: the tool's mass >= 0, the cutoff below Nyquist (0: no filter)
SENSOR_CHECKS = ("finite",) * 13 + ("nonnegative",) + ("finite",) * 9 + ("below_nyquist", "finite")
#: the step's settings that are no array of its own (the standalone struct's scalar fields, the
#: Controller's attributes), and what each may be: the timing check's tolerance (-1: no check) and the
#: least conditioning of the task Jacobian
SETTING_CHECKS = {"timing_tolerance": "fraction_or_off", "singular_tol": "fraction"}
#: the fault reaction's numbers (the ``fault`` array): how many consecutive faulted samples enter the safe
#: state, the joints' stopping time constant in it, the time over which it releases the torque the arm had
FAULT = ("fault_samples", "stop_time", "unload_time")
#: what each of the fault reaction's numbers means (the standalone header documents its fields with these)
FAULT_DOCS = {
    "fault_samples": "consecutive faulted samples (refused, late or early; one after a gap counts the sample "
                     "periods the gap spans, the timing checked) that enter the safe state [1]",
    "stop_time": "the safe state's time constant: the joints stop and hold, critically damped [s]; at least two "
                 "sample times",
    "unload_time": "the safe state releases the torque the arm had at the fault over this time [s]; 0: at once",
}
#: their defaults: 5 samples (5 ms at 1 kHz, 50 ms at 100 Hz), a 50 ms stop, the torque released over 0.2 s
FAULT_DEFAULTS = (5.0, 0.05, 0.2)
#: what each may be: a whole number of samples >= 1, a time of at least two sample times (the hold is a PD
#: law served once a sample: at ``stop_time`` <= ``sample_time`` its discrete poles leave the unit circle),
#: a time >= 0
FAULT_CHECKS = ("count", "sampled_time_constant", "nonnegative")
#: the fault reaction's state: the torque to release (the torque at the safe state's entry, then its
#: difference from the hold's torque there), the last finite joint positions (NaN before any), the positions
#: held (the entry's), the consecutive faulted samples, 1 in the safe state, the samples since its entry
FAULT_STATE = PerJoint(("tau_offset", "q_hold", "q_stop"), tail=("faults", "stopped", "samples"))
#: the estimator's state: the normal estimate, its rate, the last force, 1 once started, the compliance's
#: estimate and its information
ESTIMATE = ("n_x", "n_y", "n_z", "ndot_x", "ndot_y", "ndot_z", "F_x", "F_y", "F_z", "started", "c", "c_information")
#: a wrench's six numbers: force, then moment
WRENCH = ("f_x", "f_y", "f_z", "m_x", "m_y", "m_z")

#: the control step's interface: its inputs (arguments, run-time parameters, state) and outputs, in argument order
CONTROLLER_STEP = Interface(
    "controller_step",
    inputs=(
        Port("q", "nq", "rad or m", "joint positions", ARGUMENT, Named("joints")),
        Port("qd", "nq", "rad/s or m/s", "joint velocities", ARGUMENT, Named("joints")),
        Port("Fc", "6", "N, N m", "the measured wrench on the robot at the tip (base axes), or a force/torque "
             "sensor's raw reading", ARGUMENT, WRENCH),
        Port("integrals", "2*m", "per axis: unit of e times s, then times s^2", "the loops' integrals", STATE,
             PerAxis(("z1", "z2"))),
        Port("last_torque", "nq+1", "N m or N, then 1", "the torque last written, and 1 once there is one",
             STATE, PerJoint(("tau",), tail=("started",))),
        Port("filter", "13", "as the wrench (the sensor filter's state, two per component), then 1 once started",
             "the wrench filter's state", STATE),
        Port("estimate", f"{len(ESTIMATE)}",
             "1, 1/s, N, 1, m/N, N^2/s^2 (the normal's estimate, its rate, the last force, 1 once started, the "
             "compliance's estimate and its information)",
             "an estimated surface's state", STATE, ESTIMATE),
        Port("t", "1", "s", "the sample's time", ARGUMENT),
        Port("yd_extra", "m", "m/s, rad/s (velocity axes); N, N m (force axes)", "reference added per axis",
             REFERENCE, Named("axes")),
        Port("yd_rate", "m", "m/s^2, rad/s^2 (velocity axes; unused on force axes)",
             "reference rate per axis (velocity axes' feedforward)", REFERENCE, Named("axes")),
        Port("target", "9", "m, m/s, rad", "the desired point, its velocity and ZYX angles (desired frame, "
             "position error)", REFERENCE, ("p_x", "p_y", "p_z", "pd_x", "pd_y", "pd_z", "alpha", "beta", "gamma")),
        Port("steps", "3*m", "as yd_extra, then s", "the references' steps per axis: before, after, at",
             PARAMETER, PerAxis(("before", "after", "at")), check="finite"),
        Port("gains", "4*m", "per axis KP, KI, KI2, KD: hybrid.Gains' KPv, KIv, KI2v, 0 on a velocity axis and "
             "KPf, KIf, 0, KDf on a force axis", "the loops' gains per axis (LOOP_GAINS)", PARAMETER,
             PerAxis(LOOP_GAINS), check="nonnegative"),
        Port("selection", "m", "1 (1: force-controlled axis)", "1 on a force-controlled axis", PARAMETER,
             Named("axes"), check="switch"),
        Port("robot", "robot", "per parameter", "the controller's model of the arm", PARAMETER, Named("robot"),
             check="finite"),
        Port("surface", "surface", "m (lengths), 1 (directions)", "the surface's parameters", PARAMETER,
             Named("surface"), check="finite"),
        Port("e", "3", "1", "the task frame's reference direction (base axes)", PARAMETER, ("e_x", "e_y", "e_z"),
             check="finite"),
        Port("options", f"{len(OPTIONS)}", "1, s, 1, unit of a, N or N m, m/s or rad/s, 1",
             "switches and numbers (OPTIONS)", PARAMETER, OPTIONS, check=OPTION_CHECKS),
        Port("posture", "3*nq", "per joint: rad or m (q_rest), then 1/s^2 (Kp), then 1/s (Kd)",
             "the posture task's numbers (POSTURE)", PARAMETER, PerJoint(POSTURE), default=0.0,
             check=("finite", "nonnegative", "nonnegative")),
        Port("limits", "2*nq", "per joint: N m or N (tau_max), then N m or N per sample (rate_max); DBL_MAX: none",
             "the torque limits (LIMITS)", PARAMETER, PerJoint(LIMITS), default=NO_LIMIT, check="nonnegative"),
        Port("sensor", f"{len(SENSOR)}", "m, 1, 1, kg, m, N and N m, Hz, 1 (see hybrid/control/wrench_sensor.py)",
             "the force/torque sensor's numbers (SENSOR)", PARAMETER, SENSOR, default=0.0, check=SENSOR_CHECKS),
        Port("fault", f"{len(FAULT)}", "1, s, s", "the fault reaction's numbers (FAULT)", PARAMETER, FAULT,
             default=FAULT_DEFAULTS, check=FAULT_CHECKS),
    ),
    outputs=(
        Port("tau", "nq", "N m or N", "the joint torques, within the limits"),
        Port("integrals_next", "2*m", "as integrals", "the integrals after the sample"),
        Port("a", "m", "m/s^2, rad/s^2", "the loops' task acceleration (loop frame)", names=Named("axes")),
        Port("y", "m", "m/s, rad/s", "the task velocity (loop frame)", names=Named("axes")),
        Port("f", "m", "N, N m", "the task wrench (loop frame)", names=Named("axes")),
        Port("saturated", "1", "1 (1: a limit bounded the torque; the integrals were kept)",
             "whether a limit bounded the torque"),
        Port("filter_next", "13", "as filter", "the wrench filter's state after the sample"),
        Port("estimate_next", f"{len(ESTIMATE)}", "as estimate", "the estimate after the sample", names=ESTIMATE),
        Port("contact_wrench", "6", "N, N m", "the wrench on the robot at the tip the law used (base axes)",
             names=WRENCH),
    ),
    doc="one control sample: measurement, the task-frame loops, the control law, the torque limits",
)

#: the step's state inputs and the outputs that carry them to the next sample
STATE_NEXT = {"integrals": "integrals_next", "last_torque": "tau", "filter": "filter_next",
              "estimate": "estimate_next"}

#: the torque of the safe state (the fault reaction): the arm stopped and held at ``q_stop`` (the inverse
#: dynamics of its model for a critically damped hold of time constant ``stop_time``) plus the difference
#: between the torque it had at the entry and the hold's there, released linearly over ``unload_time``,
#: within the torque limits. The caller gives the joint positions (the last finite ones where the sample's
#: are not) and velocities (0 where not finite), and keeps ``tau_offset_next`` in ``fault_state``
SAFE_STOP = Interface(
    "safe_stop",
    inputs=(
        Port("q", "nq", "rad or m", "joint positions (the last finite ones)", ARGUMENT, Named("joints")),
        Port("qd", "nq", "rad/s or m/s", "joint velocities (0 where not finite)", ARGUMENT, Named("joints")),
        Port("last_torque", "nq+1", "N m or N, then 1", "the torque last written, and 1 once there is one",
             STATE, PerJoint(("tau",), tail=("started",))),
        Port("fault_state", "3*nq+3", "N m or N, then rad or m (twice), then 1, 1, 1", "the fault reaction's state "
             "(FAULT_STATE)", STATE, FAULT_STATE),
        Port("robot", "robot", "per parameter", "the controller's model of the arm", PARAMETER, Named("robot"),
             check="finite"),
        Port("fault", f"{len(FAULT)}", "1, s, s", "the fault reaction's numbers (FAULT)", PARAMETER, FAULT,
             default=FAULT_DEFAULTS, check=FAULT_CHECKS),
        Port("limits", "2*nq", "per joint: N m or N (tau_max), then N m or N per sample (rate_max); DBL_MAX: none",
             "the torque limits (LIMITS)", PARAMETER, PerJoint(LIMITS), default=NO_LIMIT, check="nonnegative"),
        Port("sample_time", "1", "s", "the sample period T", PARAMETER, check="positive"),
    ),
    outputs=(
        Port("tau", "nq", "N m or N", "the safe state's joint torques, within the limits"),
        Port("tau_offset_next", "nq", "N m or N", "the torque to release, as fault_state keeps it after the sample"),
    ),
    doc="the safe state's torque: stop and hold by the model's inverse dynamics, release the entry torque",
)
