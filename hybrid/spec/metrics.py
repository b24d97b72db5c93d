"""The metrics of a run (conventions §8), declared once: their names, units and meanings, in order.

:func:`hybrid.metrics` computes them from a run's time series in NumPy, the compiled closed loop
(``codegen.closed_loop``) on the fly in C, and both report them in this order under these names
(then one peak torque per joint, :func:`metric_names`). The windows they are taken over: after the
force step until the speed step (or the end), after the speed step, the last
:data:`STEADY_WINDOW_S` seconds, and from the first touch until the force reference next changes.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Metric:
    """One number a run is judged by: its name (which carries its unit), its unit, its meaning, and the
    short label a figure's axis shows (before its unit)."""

    name: str
    unit: str
    label: str
    doc: str

    @property
    def axis_label(self) -> str:
        """The label with its unit, as a figure's axis shows it."""
        return f"{self.label} [{self.unit}]"


#: the built-in metrics of a run, in order (the peak torques, one per joint, follow them)
METRICS = (
    Metric("force_overshoot_N", "N", "force overshoot after the force step",
           "the normal force's peak past the force step's value, signed by the step"),
    Metric("force_overshoot_percent", "%", "force overshoot after the force step",
           "the overshoot as a percentage of the force step"),
    Metric("force_settling_time_2pct_s", "s", "force settling time (2 % band)",
           "the time after the force step until the force stays within 2 % of its value (of the step's size when "
           "it steps to 0)"),
    Metric("speed_drop_after_force_step_m_per_s", "m/s", "speed drop after the force step",
           "the largest speed error after the force step"),
    Metric("force_deviation_after_speed_step_N", "N", "force deviation after the speed step",
           "the largest force error after the speed step"),
    Metric("speed_overshoot_after_speed_step_m_per_s", "m/s", "speed overshoot after the speed step",
           "the speed's peak past the speed step's value"),
    Metric("steady_state_force_error_N", "N", "steady-state force error",
           "the mean force error over the last 0.2 s"),
    Metric("steady_state_speed_error_m_per_s", "m/s", "steady-state speed error",
           "the mean speed error over the last 0.2 s"),
    Metric("rms_force_error_N", "N", "RMS force error",
           "the RMS force error over the run"),
    Metric("rms_speed_error_m_per_s", "m/s", "RMS speed error",
           "the RMS speed error over the run"),
    Metric("max_penetration_m", "m", "largest penetration",
           "the sensor tip's largest penetration into the surface"),
    Metric("contact_losses", "count", "contact losses",
           "how often the surface's normal force dropped to 0"),
    Metric("time_out_of_contact_s", "s", "time out of contact",
           "the time the surface's normal force was 0"),
    Metric("first_touch_time_s", "s", "time of the first touch",
           "the time of the first sample in contact"),
    Metric("first_touch_overshoot_N", "N", "force overshoot after the first touch",
           "the force's peak past its reference after the first touch, until the force reference next changes"),
    Metric("first_touch_settling_s", "s", "settling after the first touch (5 % band)",
           "the time after the first touch until the force stays within 5 % of its reference there"),
)
#: a run along a path task's metrics (:class:`hybrid.PathTask`), after the others
PATH_METRICS = (
    Metric("path_error_rms_m", "m", "RMS path error",
           "the RMS of the sensor tip's distance from the path (in the surface's tangent plane) while on it"),
    Metric("path_error_max_m", "m", "largest path error", "the largest distance of the sensor tip from the path"),
    Metric("path_time_s", "s", "time to complete the path",
           "when the sensor tip came within 1 mm of the path's end (NaN: not within the run, or a closed path "
           "without laps)"),
    Metric("path_travelled_m", "m", "arc length travelled", "the arc length along the path the tip covered"),
    Metric("path_force_rms_error_N", "N", "RMS force error along the path",
           "the RMS of the normal force's error from the task's force at the tip's place, while following "
           "the path once the force came within 5 % of it"),
    Metric("path_speed_rms_error_m_per_s", "m/s", "RMS speed error along the path",
           "the RMS of the tip's speed along the path's tangent less the task's speed reference, while following it"),
    Metric("path_contact_losses", "count", "contact losses along the path",
           "how often the normal force dropped to 0 while following the path (the retreat's lift-off not counted)"),
    Metric("path_end_peak_force_N", "N", "largest force from the release on",
           "the largest normal force from the release of the force at the path's end on (NaN: never released)"),
)
#: the metrics' names, in order
METRIC_NAMES = tuple(m.name for m in METRICS)
#: a joint's peak torque, after the metrics (``j`` counts from 1)
PEAK_TORQUE = "peak_torque_joint{j}_Nm"
#: the first touch's metrics
FIRST_TOUCH = ("first_touch_time_s", "first_touch_overshoot_N", "first_touch_settling_s")
#: the first touch's settling band, a fraction of the force reference at the touch
TOUCH_BAND = 0.05
#: the settling band after the force step, a fraction of the force's value
SETTLING_BAND = 0.02
#: the steady state's window: the run's last this many seconds
STEADY_WINDOW_S = 0.2
#: how near [m] the path's end the sensor tip completes it (it trails the arm tip the follower steers by the
#: sensor's deflection under friction, a fraction of a millimetre): ``path_time_s``
PATH_END_TOL_M = 1e-3
#: the path's force error is taken once the force is within this fraction of its reference:
#: ``path_force_rms_error_N``
PATH_SETTLED_BAND = 0.05
#: where the sensor tip's nearest point on the path is looked for: this far [m] behind the arm tip's progress
#: and ahead of it (``path_error_rms_m``, ``path_error_max_m``)
PATH_BEHIND_M, PATH_AHEAD_M = 0.05, 0.01


def metric_names(nq: int) -> tuple[str, ...]:
    """Every metric of a run of an arm of ``nq`` joints, in order: :data:`METRICS`, then the peak torques."""
    return (*METRIC_NAMES, *(PEAK_TORQUE.format(j=j + 1) for j in range(nq)))
