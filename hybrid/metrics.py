"""Metrics of a run (NOTES section 8), named with their units."""

from __future__ import annotations

import numpy as np

from .native import manifest


def _plant_record() -> dict:
    """Names and units of the planar plant's state and output record, from the unit's manifest."""
    functions = {f["name"]: f for f in manifest("sympy")["functions"]}
    x = functions["plant_rhs_circle"]["inputs"][0]
    tau = functions["plant_rhs_circle"]["inputs"][1]
    y = functions["plant_outputs_circle"]["outputs"][0]
    return {"outputs": tuple(y["names"]), "output_units": tuple(y["unit"]), "state": tuple(x["names"]),
            "state_units": tuple(x["unit"]), "nq": tau["size"]}


PLANT = _plant_record()
#: columns of the plant output record (``codegen.model.PLANT_OUTPUTS``, read from the manifest)
PLANT_OUTPUTS = PLANT["outputs"]


def settling_time(t: np.ndarray, y: np.ndarray, target: float, band: float) -> float:
    """Time from ``t[0]`` after which ``|y - target| <= band`` for good (NaN if never)."""
    outside = np.flatnonzero(np.abs(y - target) > band)
    if len(outside) == 0:
        return 0.0
    if outside[-1] == len(y) - 1:
        return float("nan")
    return float(t[outside[-1] + 1] - t[0])


def compute_metrics(res) -> dict:
    """Force overshoot and 2 % settling after the force step, steady-state force error, speed
    drop after the force step, force deviation and speed overshoot after the speed step,
    RMS errors, penetration, contact losses, peak torques. The step metrics are NaN when the
    reference does not step, or steps outside the run."""
    exp, t = res.experiment, res.t
    F, v = res.force_normal, res.velocity_tangential
    Fd, vd = res.force_reference, res.speed_reference
    fs, vs = exp.force_reference, exp.speed_reference
    end = t[-1]
    # the window after the force step ends at the speed step (the next disturbance), if later
    f_end = vs.at if vs.at > fs.at else end
    after_f = (t >= fs.at) & (t < f_end)
    after_v = t >= vs.at
    last = t >= end - 0.2
    in_contact = res.contact_force > 0
    losses = int(np.count_nonzero(in_contact[:-1] & ~in_contact[1:]))
    nan = float("nan")
    # every metric is always reported: one after a step that falls outside the run is NaN, not missing
    m = dict.fromkeys(("force_overshoot_N", "force_overshoot_percent", "force_settling_time_2pct_s",
                       "speed_drop_after_force_step_m_per_s", "force_deviation_after_speed_step_N",
                       "speed_overshoot_after_speed_step_m_per_s"), nan)
    if after_f.any() and fs.after != fs.before:
        step = fs.after - fs.before
        peak = F[after_f].max() if step >= 0 else F[after_f].min()
        m["force_overshoot_N"] = float((peak - fs.after) * np.sign(step))
        m["force_overshoot_percent"] = float(100 * m["force_overshoot_N"] / abs(step))
        m["force_settling_time_2pct_s"] = settling_time(t[after_f], F[after_f], fs.after, 0.02 * abs(fs.after))
        m["speed_drop_after_force_step_m_per_s"] = float(np.max(vd[after_f] - v[after_f]))
    if after_v.any() and vs.after != vs.before:
        m["force_deviation_after_speed_step_N"] = float(np.max(np.abs(F[after_v] - Fd[after_v])))
        m["speed_overshoot_after_speed_step_m_per_s"] = float(np.max(v[after_v]) - vs.after)
    m["steady_state_force_error_N"] = float(np.mean(Fd[last] - F[last]))
    m["steady_state_speed_error_m_per_s"] = float(np.mean(vd[last] - v[last]))
    m["rms_force_error_N"] = float(np.sqrt(np.mean((Fd - F) ** 2)))
    m["rms_speed_error_m_per_s"] = float(np.sqrt(np.mean((vd - v) ** 2)))
    m["max_penetration_m"] = float(res.penetration.max())
    m["contact_losses"] = losses
    m["time_out_of_contact_s"] = float(np.count_nonzero(~in_contact[1:]) * exp.step)
    m["peak_torque_joint1_Nm"] = float(np.abs(res.tau[:, 0]).max())
    m["peak_torque_joint2_Nm"] = float(np.abs(res.tau[:, 1]).max())
    return m
