"""The UR5 polishing a sphere and a cylinder along a raster: a study of path tasks.

    python examples/studies/path_study.py --out DIR [--quick]

The UR5 of the 3-D experiment follows a raster (:class:`hybrid.RasterPath`: five passes of 7 cm drawn in
the tangent plane, 1 cm apart, joined by semicircular turnarounds of 5 mm radius) near the top of a
sphere (radius 15 cm) and of a cylinder lying with its axis tilted (radius 10 cm, the passes across the
axis, around it), pressing with 10 N (:class:`hybrid.PathTask`, acceleration limit 0.5 m/s^2, cross-track
gain 20 1/s). Speeds 0.05, 0.1 and 0.2 m/s; friction 0.2, 0.35 and 0.5. Each run lasts the time its speed
profile plans (the turnarounds slowed to the turns' limit, the trapezoid at the ends) and a margin.

Per run: the run's path metrics (``res.metrics``), and from the follower replayed on the sensor tip
(:func:`hybrid.simulation.path_metrics.path_series`) until the path is done, split by its arc length into
the passes (``RasterPath.pass_arcs``) and the turnarounds: the distance from the path and the normal
force's error against the 10 N, RMS on the passes, on the worst pass and in the turnarounds; how far past
the end the tip comes to rest; the same distance for the arm's point (the arm tip brought along the normal
to the sensor tip's height: the sensor's deflection left out) and how far the sensor tip trails it. A run
holds when it completes the path without losing contact or leaving the joints' limits, within 1 mm RMS of
the path up to its end and 0.2 N RMS (2 %) of the force on the passes. Beyond the grid
(:data:`BEYOND`): a higher acceleration limit, friction 0.7, and at friction 0.5 half the force or a
stiffer sensor.

Writes ``runs.csv`` (one row per run), ``study.json`` (the same and the settings), ``table.md`` and the
figure ``path_force.png`` (the sensor tip's trace coloured by the measured normal force, the sphere's and
the cylinder's run at 0.1 m/s and friction 0.35) into ``--out``.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import time
from pathlib import Path

import numpy as np

import hybrid
from hybrid.control.path_task import PathFollower
from hybrid.geometry.surface_points import phi_and_normal
from hybrid.simulation.path_metrics import path_series
from hybrid.spec.path_follow import PATH_OUTPUT, PATH_SETTINGS, PATH_TABLE

SPEEDS = (0.05, 0.1, 0.2)
FRICTIONS = (0.2, 0.35, 0.5)
FORCE = 10.0  # [N]
#: the raster: passes, their length and spacing in the tangent plane [m]
PASSES, PASS_LENGTH, SPACING = 5, 0.07, 0.01
#: the parts, as in tests/test_path_task.py, and the raster's first point (near each one's top) and direction
SURFACES = {
    "sphere": (hybrid.Sphere((0.5, 0.0, 0.2), 0.15), (0.465, -0.02, 0.35)),
    "cylinder": (hybrid.Cylinder((0.5, 0.0, 0.0), (0.0, 0.6, 0.8), 0.1), (0.465, -0.02, 0.14)),
}
DIRECTION = (1.0, 0.0, 0.0)
#: a run's duration: the planned time times this, and this margin [s]
DURATION_FACTOR, DURATION_MARGIN = 1.25, 0.5
#: a run holds within these: the distance from the path, RMS [m]; the force error on the passes, RMS [N]
PATH_LIMIT, FORCE_LIMIT = 1e-3, 0.02 * FORCE
FIGURE_CASE = (0.1, 0.35)  # speed, friction


def raster(surface: str) -> hybrid.RasterPath:
    """The raster on ``surface`` ("sphere" or "cylinder")."""
    part, near = SURFACES[surface]
    return hybrid.RasterPath(part, part.project(np.array(near)), DIRECTION, PASS_LENGTH, SPACING, PASSES)


def planned_time(task: hybrid.PathTask, surface) -> float:
    """The time [s] the task's speed profile takes along the path: the table's speed (the turns' limit in
    the turnarounds) within the trapezoid from the start speed up and down to 0 at the end."""
    table, settings = task.table(surface)
    get = dict(zip(PATH_SETTINGS, settings))
    s = np.linspace(0.0, get["length"], 20001)
    a = get["acceleration"]
    v = np.minimum.reduce([np.interp(s, table[:, 0], table[:, PATH_TABLE.index("speed")]),
                           np.sqrt(get["speed_start"] ** 2 + 2 * a * s), np.sqrt(2 * a * (get["length"] - s))])
    mid = (v[1:] + v[:-1]) / 2  # the end's v = 0 is integrable: the midpoints keep it finite
    return float(np.sum(np.diff(s) / mid))


def experiment(surface: str, speed: float, friction: float, acceleration: float = 0.5, force: float = FORCE,
               **overrides) -> hybrid.Experiment:
    """The run on ``surface`` at ``speed`` [m/s] and ``friction`` (the task's ``acceleration`` [m/s^2] and
    ``force`` [N], any other experiment setting by keyword), long enough to complete the path."""
    path = raster(surface)
    task = hybrid.PathTask(path, speed=speed, force=force, acceleration=acceleration)
    duration = round(DURATION_FACTOR * planned_time(task, path.surface) + DURATION_MARGIN, 1)
    return hybrid.tracing_experiment(surface=path.surface, path_task=task, duration=duration,
                                     contact=hybrid.Contact(friction=friction), **overrides)


def _rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x ** 2))) if len(x) else float("nan")


def _max(x: np.ndarray) -> float:
    return float(x.max()) if len(x) else float("nan")


def arm_point(res) -> tuple[np.ndarray, np.ndarray]:
    """At each control sample: the arm tip moved along the surface's normal to the sensor tip's height (where
    the arm puts the tool in the tangent plane, the sensor's deflection left out), and how far the sensor tip
    trails it in the tangent plane [m] (the friction's deflection of the sensor's spring)."""
    exp = res.experiment
    rows = res.outputs[::exp.steps_per_sample][:exp.n_samples]
    names = res.record["outputs"]
    arm, tip = (rows[:, [names.index(f"{w}_{c}") for c in "xyz"]] for w in ("r", "s"))
    _, n = phi_and_normal(exp.surface, tip)
    along = np.einsum("ij,ij->i", arm - tip, n)[:, None] * n
    return arm - along, np.linalg.norm(arm - tip - along, axis=1)


def arm_path_error(res, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The follower replayed on ``points`` (one per control sample): the distance from the path [m] and
    whether the path is done."""
    exp = res.experiment
    follower = PathFollower(exp.path_task, exp.surface, exp.sample_time)
    out = np.empty((len(points), 2))
    for k, p in enumerate(points):
        got = follower.follow(p, np.zeros(3))
        out[k] = got[PATH_OUTPUT.index("path_error")], got[PATH_OUTPUT.index("done")]
        follower.advance()
    return out[:, 0], out[:, 1]


def split(res) -> dict:
    """The run's distance from the path and force error on the passes and in the turnarounds (until the
    path is done), each pass's force error, the time spent in the turnarounds, how far the sensor tip
    trails the arm, and the arm's own distance from the path."""
    exp = res.experiment
    series = path_series(res)
    len(series["s"])
    force_error = series["normal_force"] - series["normal_reference"]
    running = series["done"] == 0
    s = series["s"]
    passes = [running & (s >= a) & (s <= b) for a, b in exp.path_task.path.pass_arcs]
    on_pass = np.any(passes, axis=0)
    turn = running & ~on_pass
    err = series["path_error"]
    points, trail = arm_point(res)
    arm_error, arm_done = arm_path_error(res, points)
    after = series["done"] != 0
    row = {"path_error_rms_to_end_m": _rms(err[running]), "past_end_max_m": _max(err[after]),
           "path_error_rms_passes_m": _rms(err[on_pass]), "path_error_rms_turns_m": _rms(err[turn]),
           "path_error_max_passes_m": _max(err[on_pass]), "path_error_max_turns_m": _max(err[turn]),
           "force_rms_error_passes_N": _rms(force_error[on_pass]), "force_rms_error_turns_N": _rms(force_error[turn]),
           "force_max_error_passes_N": _max(np.abs(force_error[on_pass])),
           "force_max_error_turns_N": _max(np.abs(force_error[turn])),
           "time_in_turns_s": float(turn.sum() * exp.sample_time),
           "peak_speed_reference_m_per_s": float(series["speed"].max()),
           "trail_median_m": float(np.median(trail[running])) if running.any() else float("nan"),
           "arm_path_error_rms_m": _rms(arm_error[arm_done == 0]),
           "arm_path_error_max_m": _max(arm_error[arm_done == 0]),
           "arm_done": bool(arm_done[-1])}
    for k, mask in enumerate(passes, 1):
        row[f"force_rms_error_pass{k}_N"] = _rms(force_error[mask])
    row["force_rms_error_worst_pass_N"] = max(row[f"force_rms_error_pass{k}_N"] for k in range(1, len(passes) + 1))
    return row


def run(surface: str, speed: float, friction: float, group: str = "grid", case: str = "",
        **options) -> tuple[dict, hybrid.SimulationResult | None]:
    """One run's row (its settings, metrics, the passes' and turnarounds' errors, whether it holds) and
    result (None when it failed); ``options`` go to :func:`experiment`."""
    exp = experiment(surface, speed, friction, **options)
    path = exp.path_task.path
    row = {"group": group, "case": case, "surface": surface, "speed": speed, "friction": friction,
           "acceleration": exp.path_task.acceleration, "force": exp.path_task.force,
           "sensor_stiffness": exp.sensor.stiffness, "length_m": path.length,
           "planned_time_s": planned_time(exp.path_task, exp.surface), "duration_s": exp.duration}
    try:
        res = hybrid.simulate(exp)
    except hybrid.HybridError as exc:
        return {**row, "status": f"failed: {type(exc).__name__}", "holds": False, "why": "the run stopped"}, None
    m = res.metrics
    row.update(status="ok", **{k: m[k] for k in ("path_error_rms_m", "path_error_max_m", "path_time_s",
                                                 "path_travelled_m", "path_force_rms_error_N",
                                                 "path_speed_rms_error_m_per_s", "contact_losses",
                                                 "time_out_of_contact_s")}, **split(res))
    row["joint_limits_left"] = ", ".join(res.limit_violations)
    why = []
    if not (math.isfinite(row["path_time_s"]) and row["path_travelled_m"] >= path.length - 1e-3):
        why.append(f"incomplete ({row['path_travelled_m'] * 100:.1f} of {path.length * 100:.1f} cm)")
    if row["contact_losses"]:
        why.append(f"{int(row['contact_losses'])} contact losses")
    if row["path_error_rms_to_end_m"] > PATH_LIMIT:
        why.append(f"{row['path_error_rms_to_end_m'] * 1e3:.2f} mm RMS from the path")
    if row["force_rms_error_passes_N"] > FORCE_LIMIT:
        why.append(f"{row['force_rms_error_passes_N']:.2f} N RMS on the passes")
    if row["joint_limits_left"]:
        why.append(f"out of the joints' {row['joint_limits_left']} limits")
    row.update(holds=not why, why="; ".join(why))
    return row, res


#: beyond the grid, each on both surfaces: faster turnarounds (a higher acceleration limit), more friction,
#: and at friction 0.5 half the force or a sensor twice as stiff (its damping ratio kept)
BEYOND = (("acceleration 1 m/s^2", 0.2, 0.2, dict(acceleration=1.0)),
          ("acceleration 1 m/s^2", 0.2, 0.5, dict(acceleration=1.0)),
          ("acceleration 2 m/s^2", 0.2, 0.2, dict(acceleration=2.0)),
          ("acceleration 2 m/s^2", 0.2, 0.5, dict(acceleration=2.0)),
          ("friction 0.7", 0.1, 0.7, {}),
          ("force 5 N", 0.1, 0.5, dict(force=5.0)),
          ("sensor 2000 N/m", 0.1, 0.5, dict(sensor=hybrid.Sensor(stiffness=2000.0, damping=7.0 * math.sqrt(2)))))


def study(quick: bool = False) -> tuple[list[dict], dict]:
    """Every run's row, and the figure's results by surface."""
    rows, kept = [], {}
    speeds, frictions = ((FIGURE_CASE[0], 0.2), (FIGURE_CASE[1], 0.5)) if quick else (SPEEDS, FRICTIONS)
    for surface in SURFACES:
        for speed in speeds:
            for friction in frictions:
                row, res = run(surface, speed, friction)
                rows.append(row)
                if (speed, friction) == FIGURE_CASE and res is not None:
                    kept[surface] = res
    for case, speed, friction, options in BEYOND[:1 if quick else None]:
        for surface in SURFACES:
            rows.append(run(surface, speed, friction, "beyond", case, **options)[0])
    return rows, kept


def _mm(r: dict, key: str) -> str:
    v = r.get(key, float("nan"))
    return "" if v is None or not math.isfinite(v) else f"{v * 1e3:.2f}"


def _n(r: dict, key: str, fmt: str = ".3f") -> str:
    v = r.get(key, float("nan"))
    return "" if v is None or not math.isfinite(v) else format(v, fmt)


def table(rows: list[dict]) -> str:
    """The runs as Markdown: the contact's (the sensor tip's) distance from the path (the run's, on the
    passes, in the turnarounds), the arm's, how far the sensor tip trails the arm, the force error (the
    run's, on the passes, the worst pass, in the turnarounds), the time to complete against the planned
    time, and whether the run holds; the grid, then the runs beyond it."""
    out = []
    for group, first in (("grid", "surface | speed [m/s] | friction"), ("beyond", "case | surface | speed [m/s] | "
                                                                                 "friction")):
        chosen = [r for r in rows if r["group"] == group]
        if not chosen:
            continue
        out += ["" if out else None, f"| {first} | path error RMS [mm]: run / to the end / passes / turnarounds | max "
                "[mm]: passes / turnarounds / past the end | arm's point RMS [mm] | trail [mm] | force error RMS [N]: "
                "run / passes / worst pass / turnarounds | time [s]: done / planned | holds |",
                "|" + " --- |" * (first.count("|") + 8)]
        for r in chosen:
            head = f"| {r['case']} " * (group == "beyond") + f"| {r['surface']} | {r['speed']:g} | {r['friction']:g} |"
            if r["status"] != "ok":
                out.append(f"{head} {r['status']} |" + " |" * 6 + f" no: {r['why']} |")
                continue
            out.append(f"{head} {_mm(r, 'path_error_rms_m')} / {_mm(r, 'path_error_rms_to_end_m')} / "
                       f"{_mm(r, 'path_error_rms_passes_m')} / {_mm(r, 'path_error_rms_turns_m')} | "
                       f"{_mm(r, 'path_error_max_passes_m')} / {_mm(r, 'path_error_max_turns_m')} / "
                       f"{_mm(r, 'past_end_max_m')} | {_mm(r, 'arm_path_error_rms_m')}"
                       f"{'' if r['arm_done'] else ' (not done)'} | {_mm(r, 'trail_median_m')} | "
                       f"{_n(r, 'path_force_rms_error_N')} / {_n(r, 'force_rms_error_passes_N')} / "
                       f"{_n(r, 'force_rms_error_worst_pass_N')} / {_n(r, 'force_rms_error_turns_N')} | "
                       f"{_n(r, 'path_time_s', '.2f') or 'not done'} / {r['planned_time_s']:.2f} | "
                       f"{'yes' if r['holds'] else 'no: ' + r['why']} |")
    return "\n".join(x for x in out if x is not None) + "\n"


def figure(kept: dict, out: Path) -> Path | None:
    """``path_force.png``: per surface, the sensor tip's trace coloured by the measured normal force on a
    light wireframe of the surface, on one colour scale."""
    import matplotlib.pyplot as plt

    from hybrid.plots import plot_path_force

    if not kept:
        return None
    forces = np.concatenate([res.force_normal for res in kept.values()])
    lo, hi = np.percentile(forces, [0.5, 99.5])  # the start's transient would flatten the scale
    fig = plt.figure(figsize=(11.0, 5.0), layout="constrained")
    axes = [fig.add_subplot(1, len(kept), k + 1, projection="3d") for k in range(len(kept))]
    for ax, (surface, res) in zip(axes, kept.items()):
        plot_path_force(res, ax, vmin=lo, vmax=hi, colorbar=False)
        m = res.metrics
        ax.set_title(f"{surface}: {m['path_error_rms_m'] * 1e3:.2f} mm RMS from the path, "
                     f"{m['path_force_rms_error_N']:.2f} N RMS", fontsize=9)
    fig.colorbar(axes[-1].collections[-1], ax=axes, shrink=0.6, label="measured normal force [N]")
    speed, friction = FIGURE_CASE
    fig.suptitle(f"The UR5 along a 5-pass raster at {speed:g} m/s and {FORCE:g} N, friction {friction:g}: the "
                 "sensor tip's trace coloured by the measured normal force", fontsize=10)
    path = out / "path_force.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, type=Path, help="folder for the CSV, JSON, table and figure")
    parser.add_argument("--quick", action="store_true", help="two speeds and two frictions (the figure's and the "
                        "fastest, most frictional) instead of three, one case beyond the grid")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    began = time.perf_counter()
    rows, kept = study(args.quick)
    names = list(dict.fromkeys(k for r in rows for k in r))
    with open(args.out / "runs.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=names)
        writer.writeheader()
        writer.writerows(rows)
    exp = experiment("sphere", *FIGURE_CASE)
    settings = {"speeds": SPEEDS, "frictions": FRICTIONS, "force_N": FORCE, "passes": PASSES,
                "pass_length_m": PASS_LENGTH, "spacing_m": SPACING,
                "surfaces": {k: {"surface": repr(part), "near": near} for k, (part, near) in SURFACES.items()},
                "task": {k: v for k, v in vars(exp.path_task).items() if k in ("acceleration", "cross_track_gain",
                                                                               "spacing")},
                "robot": exp.robot.name, "model_error": exp.model_error, "sample_time_s": exp.sample_time,
                "gains": vars(exp.gains), "limits": {"path_error_rms_m": PATH_LIMIT, "force_rms_error_N": FORCE_LIMIT}}
    (args.out / "study.json").write_text(json.dumps({"settings": settings, "runs": rows}, indent=1, default=str))
    (args.out / "table.md").write_text(table(rows))
    written = figure(kept, args.out)
    print(table(rows))
    print(f"{len(rows)} runs in {time.perf_counter() - began:.0f} s; wrote runs.csv, study.json, table.md"
          + (f", {written.name}" if written else "") + f" into {args.out}")


if __name__ == "__main__":
    main()
