"""
The first touch: approach speed, stiffness, the filter, noise and a nearly rigid surface
========================================================================================

How the force's overshoot, its settling and the contact losses after the first touch grow with the
approach speed, the environment's stiffness, the controller's filter and the sensor's noise, lag and
delay; and the paper's Appendix (a nearly rigid contact chatters) in the elastic model.

Every run starts 5 mm off the surface at rest (``start_gap``) and approaches at ``approach_speed``
until the measured force passes 0.5 N, then holds 10 N with no tangential motion
(:ref:`conventions §4 <conventions-loops>`); the metrics are those of
:ref:`conventions §8 <conventions-metrics>` (the first touch's settling band is 5 % of F_d). It
prints the study's tables (markdown, as the documentation's study of the first touch gives them)
and draws the touch on 1e5 and 1e8 N/m; ``--out DIR`` also writes the tables as CSV and the figure
as PNG. A few seconds once the compiled loops are built (about 30 s from an empty cache)::

    python examples/plot_first_touch.py [--out DIR]
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

import numpy as np

import hybrid
from hybrid.plots import plot_first_touch, save

GAP, F_D = 0.005, 10.0
SPEEDS = (0.01, 0.02, 0.05, 0.1, 0.2)
STIFFNESSES = (1e4, 1e5, 1e6)
ARMS = {"paper arm": hybrid.paper_experiment,
        "UR5": hybrid.tracing_experiment}


def base(make, **overrides):
    """A run from 5 mm off the surface onto 10 N, no tangential
    motion, 1.2 s."""
    return make(**{"start_gap": GAP, "approach_speed": 0.05,
                   "F_d": F_D, "v_d": 0.0, "duration": 1.2,
                   **overrides})


def number(value: float, digits: int = 2) -> str:
    """``value`` rounded, without a sign on a zero (a peak just below
    F_d is no overshoot, -0.00)."""
    text = f"{value:.{digits}f}"
    negative_zero = text.startswith("-") and float(text) == 0
    return text[1:] if negative_zero else text


def cell(row) -> str:
    """overshoot N / settling s / losses."""
    settle = row["first_touch_settling_s"]
    settle = "never" if math.isnan(settle) else f"{settle:.2f}"
    overshoot = number(row["first_touch_overshoot_N"])
    return f"{overshoot} / {settle} / {int(row['contact_losses'])}"


def markdown(header: list[str], rows: list[list]) -> str:
    lines = ["| " + " | ".join(header) + " |",
             "| " + " | ".join("---" for _ in header) + " |"]
    lines += ["| " + " | ".join(str(v) for v in row) + " |"
              for row in rows]
    return "\n".join(lines)


def speed_and_stiffness() -> tuple[str, list]:
    """Table 1: a sweep over approach speed and environment stiffness
    for each arm (compiled loop)."""
    rows, frames = [], []
    for arm, make in ARMS.items():
        table = hybrid.sweep(base(make), {
            "contact.stiffness": list(STIFFNESSES),
            "approach_speed": list(SPEEDS)})
        failed = table[table["status"] != "ok"]
        assert failed.empty, failed["error"].tolist()
        table.insert(0, "arm", arm)
        frames.append(table)
        for k in STIFFNESSES:
            part = table[table["contact.stiffness"] == k]
            part = part.set_index("approach_speed")
            rows.append([arm, f"{k:.0e}",
                         *(cell(part.loc[v]) for v in SPEEDS)])
    header = ["arm", "k_e [N/m]", *(f"{v:g} m/s" for v in SPEEDS)]
    return markdown(header, rows), frames


def _ripple(res) -> float:
    """The true normal force's standard deviation over the run's last
    0.3 s [N]."""
    return float(np.std(res.force_normal[res.t >= res.t[-1] - 0.3]))


def _impact(res) -> float:
    """The arm tip's speed towards the surface at the first touch
    [m/s]."""
    first = np.flatnonzero(res.contact_force > 0)[0]
    return float(-res.velocity_normal[first])


def _bouncing(res) -> tuple[float, float]:
    """After the first touch: the time out of contact [s] and the
    sensor tip's highest bounce [m]."""
    out = res.contact_force <= 0
    i0 = np.flatnonzero(~out)[0]
    time_out = float(np.sum(np.diff(res.t)[out[1:]][i0:]))
    return time_out, max(0.0, float(-res.penetration[i0:].min()))


def _spread(values, form: str) -> str:
    """The mean of several draws with their worst in brackets; one
    draw as it is."""
    if len(values) == 1:
        return f"{values[0]:{form}}"
    return f"{values.mean():{form}} ({values.max():{form}})"


def filter_and_noise(seeds: int = 5) -> tuple[str, list]:
    """Table 2: the controller's filter against the sensor's noise
    (the paper's arm, 1e5 N/m; Python runner), the mean over
    ``seeds`` noise draws (the worst in brackets); then the sensor's
    own lag and delay, noise-free."""
    rows, records = [], []
    filters = (("none", None), ("20 Hz", 20.0), ("5 Hz", 5.0))
    cases = [(noise, name, hybrid.Sensor(force_noise=noise), cutoff)
             for noise in (0.0, 0.1, 0.3, 1.0)
             for name, cutoff in filters]
    cases += [(0.0, name, sensor, None) for name, sensor in (
        ("sensor lag 20 Hz", hybrid.Sensor(bandwidth_hz=20.0)),
        ("sensor lag 5 Hz", hybrid.Sensor(bandwidth_hz=5.0)),
        ("delay 1 sample", hybrid.Sensor(delay_samples=1)),
        ("delay 2 samples", hybrid.Sensor(delay_samples=2)))]
    for noise, name, sensor, cutoff in cases:
        row = [f"{noise:g}", name]
        wrench_sensor = (None if cutoff is None
                         else hybrid.WrenchSensor(cutoff=cutoff))
        for speed in (0.05, 0.2):
            got = []
            for seed in range(seeds if noise > 0 else 1):
                drawn = dataclasses.replace(sensor, seed=seed)
                exp = base(hybrid.paper_experiment,
                           approach_speed=speed, sensor=drawn,
                           wrench_sensor=wrench_sensor)
                res = hybrid.simulate(exp)
                m = res.metrics
                got.append((m["first_touch_overshoot_N"],
                            m["first_touch_settling_s"],
                            _impact(res), _ripple(res)))
                records.append({
                    "noise_N": noise, "filter": name,
                    "approach_speed": speed, "seed": seed, **m,
                    "impact_speed_m_per_s": got[-1][2],
                    "ripple_N": got[-1][3]})
            got = np.array(got)
            settle = got[:, 1]
            never = int(np.isnan(settle).sum())
            if never == len(settle):
                shown = "never"
            else:
                shown = f"{np.nanmean(settle):.2f}"
                shown += f" ({never} never)" if never else ""
            row += [_spread(got[:, 0], ".2f"), shown,
                    _spread(got[:, 2], ".3f")]
            if speed == 0.05:
                ripple = got[:, 3].mean()
        rows.append([*row, f"{ripple:.3f}"])
    header = ["noise [N]", "filter",
              *(f"{what}, {v:g} m/s" for v in (0.05, 0.2)
                for what in ("overshoot [N]", "settling [s]",
                             "impact [m/s]")),
              "ripple [N]"]
    return markdown(header, rows), records


def appendix() -> tuple[str, str, dict]:
    """Table 3: a stiffer and stiffer surface (the paper's arm,
    0.05 m/s), each at an integration step that resolves it; and the
    sensor's own stiffness, which sets the sampled force loop's
    stability."""
    rows, shown = [], {}
    for k, h in ((1e5, 1e-4), (1e6, 1e-4), (1e7, 2e-5), (1e8, 5e-6)):
        exp = base(hybrid.paper_experiment,
                   contact=hybrid.Contact(stiffness=k),
                   integration_step=h, duration=0.6)
        res = hybrid.simulate(exp)
        m = res.metrics
        if k in (1e5, 1e8):
            shown[f"k_e = {k:.0e} N/m"] = res
        mass = exp.sensor.mass
        zeta = exp.contact.damping / (2 * math.sqrt(k * mass))
        out, bounce = _bouncing(res)
        rows.append([f"{k:.0e}", f"{h:g}", f"{zeta:.3f}",
                     int(m["contact_losses"]), f"{1000 * out:.1f}",
                     f"{1e6 * bounce:.0f}",
                     f"{res.contact_force.max():.0f}",
                     f"{m['first_touch_overshoot_N']:.2f}",
                     f"{m['first_touch_settling_s']:.2f}"])
    table = markdown(["k_e [N/m]", "integration step [s]",
                      "contact damping ratio", "contact losses",
                      "bouncing [ms]", "highest bounce [um]",
                      "surface's peak force [N]",
                      "measured overshoot [N]", "settling [s]"],
                     rows)
    rows = []
    for K_s in (1e3, 3e3, 8e3, 1e4, 1e5):
        judged = base(hybrid.paper_experiment,
                      sensor=hybrid.Sensor(stiffness=K_s),
                      allow_unstable=True)
        report = hybrid.stability(judged, margins=False)
        radius = report.loop("n").spectral_radius
        row = [f"{K_s:.0e}", f"{radius:.3f}"]
        for speed in (0.05, 0.2):
            try:
                exp = base(hybrid.paper_experiment,
                           approach_speed=speed,
                           sensor=hybrid.Sensor(stiffness=K_s))
            except hybrid.HybridError as exc:
                assert "unstable" in str(exc)
                refused = ["refused: the loop is unstable", ""]
                row += refused if speed == 0.05 else ["", ""]
                continue
            res = hybrid.simulate(exp)
            m = res.metrics
            row += [cell(m), f"{_impact(res):.3f}"]
        rows.append(row)
    sensor_table = markdown(
        ["sensor K_s [N/m]", "force loop's spectral radius (10 ms)",
         "0.05 m/s: overshoot / settling / losses", "impact [m/s]",
         "0.2 m/s: overshoot / settling / losses", "impact [m/s]"],
        rows)
    return table, sensor_table, shown


def main() -> None:
    parser = argparse.ArgumentParser(
        description="The first touch: approach speed, stiffness, "
                    "the filter, noise and a nearly rigid surface.")
    parser.add_argument("--out", type=Path, help="also write the "
                        "tables as CSV and the figure here")
    args = parser.parse_args()
    first, frames = speed_and_stiffness()
    print("Table 1: overshoot [N] / settling [s] / contact losses\n"
          "after the first touch\n")
    print(first)
    second, records = filter_and_noise()
    print("\nTable 2: the paper's arm on 1e5 N/m: the controller's\n"
          "filter, the sensor's noise, lag and delay\n")
    print(second)
    third, sensors, shown = appendix()
    print("\nTable 3: a nearly rigid surface (the paper's arm, "
          "0.05 m/s)\n")
    print(third)
    print("\nTable 4: the sensor's stiffness and the sampled force "
          "loop\n(surface 1e5 N/m)\n")
    print(sensors)
    if args.out:
        import pandas as pd

        args.out.mkdir(parents=True, exist_ok=True)
        pd.concat(frames).to_csv(
            args.out / "speed_and_stiffness.csv", index=False)
        pd.DataFrame(records).to_csv(
            args.out / "filter_and_noise.csv", index=False)
    title = ("the first touch at 0.05 m/s: the sensor's force, and "
             "the surface's on its tip")
    fig = plot_first_touch(shown, title)
    if args.out:
        print(f"\nwrote {save(fig, args.out / 'first_touch')[0]}")


if __name__ == "__main__":
    main()
