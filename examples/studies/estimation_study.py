"""The normal estimator on surfaces the controller is not told: a study.

    python examples/studies/estimation_study.py --out DIR [--quick]

The UR5 of the 3-D experiment traces three surfaces: the sphere (its latitude circle 60 degrees from the
top), a cylinder about base z (its circle at the sphere run's start height) and an uneven plane, bumps
``z = z0 + h sin(k x) sin(k y)`` (h = 5 mm, wavelength 15 cm) along the line ``x = x0`` where
``sin(k x0) = cos(k x0)``: there the slope is ``h k / sqrt 2`` (8.4 degrees) all along the path, its
direction turning once per wavelength, so the normal tilts along the motion and across it in turn. Three
controllers side by side: told the exact surface, told a flat plane (through the start point, with the
start's normal) and estimating the normal online (``hybrid.EstimatedSurface``, the fusion of force and
velocity; started at the start's normal, given the sensor spring's compliance). Friction 0, 0.2, 0.5;
constant speeds 0.05, 0.15, 0.3 m/s; the force reference steps from 10 N to 20 N at 0.5 s. The force-only
and velocity-only estimators run on the sphere at 0.15 m/s. Then where estimation degrades: the speed
reference stepping (0.15 to 0.3 m/s at 1.5 s), bumps of shorter wavelengths, a ledge (a step down of 5 or
10 mm within about 2 mm) that the tip flies off.

Besides the metrics (``rms_force_error_N`` reads the sensor's force in the task frame at the arm tip),
each row has the RMS error of the surface's own normal force against ``F_d`` (``rms_contact_force_error_N``):
with friction the arm tip runs ahead of the contact point by the friction's deflection, and the exact
surface's frame there is tilted from the contact's normal.

Writes ``runs.csv`` (one row per run), ``study.json`` (the same and the settings), ``table.md`` (the
summary tables) and the figures ``estimation_sphere.png``, ``estimation_bumps.png`` into ``--out``.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import math
import time
from pathlib import Path

import numpy as np

import hybrid
from hybrid.control.references import Step
from hybrid.experiments.tracing import SPHERE_CENTER

FRICTIONS = (0.0, 0.2, 0.5)
SPEEDS = (0.05, 0.15, 0.3)
CONTROLLERS = ("exact", "flat", "fusion")
#: the bumps: height [m], wavelength [m], mean height [m]; the path's length [m] (at most 3 s of it)
BUMP_HEIGHT, BUMP_WAVELENGTH, BUMP_Z0, BUMP_PATH = 0.005, 0.15, 0.15, 0.6
FIGURE_SURFACES = ("sphere", "bumps")


def bumps(wavelength: float = BUMP_WAVELENGTH, height: float = BUMP_HEIGHT) -> dict:
    """The uneven plane's settings for :func:`hybrid.tracing_experiment`: the surface, the start point
    (where the bumps' height is ``z0``), the task frame's direction (base x: ``t1`` runs along -y) and the
    straight path along -y."""
    k = 2 * math.pi / wavelength
    x0 = (math.pi / 4 + 2 * math.pi * round(0.47 * k / (2 * math.pi))) / k  # sin(k x0) = cos(k x0), near 0.47 m
    y0 = 2 * math.pi * round(0.3 * k / (2 * math.pi)) / k  # sin(k y0) = 0, near 0.3 m
    surface = hybrid.ImplicitSurface("z - z0 - h*sin(k*x)*sin(k*y)", {"z0": BUMP_Z0, "h": height, "k": k})
    start = (x0, y0, BUMP_Z0)
    return dict(surface=surface, start_point=start, frame_direction=(1.0, 0.0, 0.0),
                path=hybrid.LinePath(start, (0.0, -1.0, 0.0)))


def ledge(drop: float, width: float = 0.001) -> dict:
    """A plane at ``z0`` with a step down of ``drop`` [m] over about ``width`` [m] at ``y = 0.1 m``, crossed
    along -y from ``y = 0.3 m`` (at x = 0.47 m)."""
    surface = hybrid.ImplicitSurface("z - z0 + d*(1 + tanh((y1 - y)/w))/2",
                                     {"z0": BUMP_Z0, "d": drop, "w": width, "y1": 0.1})
    start = (0.47, 0.3, BUMP_Z0)
    return dict(surface=surface, start_point=start, frame_direction=(1.0, 0.0, 0.0),
                path=hybrid.LinePath(start, (0.0, -1.0, 0.0)))


def cylinder() -> dict:
    """A cylinder about base z of the sphere's latitude circle's radius, through the sphere run's start."""
    start = hybrid.tracing_experiment().initial_state()[12:15]
    d = start[:2] - np.array([0.5, 0.0])
    d /= np.linalg.norm(d)
    return dict(surface=hybrid.Cylinder((0.5, 0.0, 0.2), (0, 0, 1), 0.13),
                start_point=(0.5 + 0.13 * d[0], 0.13 * d[1], start[2]))


def experiment(surface: str, friction: float, speed, wavelength: float = BUMP_WAVELENGTH,
               **overrides) -> hybrid.Experiment:
    """The run on ``surface`` ("sphere", "cylinder", "bumps") at ``friction``; ``speed`` a number [m/s]
    or a :class:`hybrid.Step`."""
    if surface.startswith("ledge"):  # "ledge 5 mm"
        kw, path = ledge(float(surface.split()[1]) / 1000), 0.4
    else:
        kw, path = {"sphere": dict, "cylinder": cylinder, "bumps": lambda: bumps(wavelength)}[surface](), BUMP_PATH
    top = speed.after if isinstance(speed, Step) else speed
    duration = round(min(3.0, path / top), 2) if surface not in ("sphere", "cylinder") else 3.0
    ref = speed if isinstance(speed, Step) else Step(speed, speed, 0.0)
    return hybrid.tracing_experiment(speed_reference=ref, contact=hybrid.Contact(friction=friction),
                                     duration=duration, **kw, **overrides)


def told(exp: hybrid.Experiment, controller: str):
    """What the controller is told of the surface: ``"exact"`` (None: the true one), ``"flat"`` (the
    tangent plane at the start) or an estimator's method."""
    start = exp.initial_state()[12:15]
    normal = exp.surface.normal_at(start)
    if controller == "exact":
        return None
    if controller == "flat":
        return hybrid.Plane(tuple(start), tuple(normal))
    return hybrid.EstimatedSurface(method=controller)  # its defaults: the start and the compliance its own


def run(exp: hybrid.Experiment, controller: str) -> tuple[dict, hybrid.SimulationResult | None]:
    """One run's row (its metrics, the normal-angle errors) and result (None when it failed)."""
    surface = told(exp, controller)
    row = {"controller": controller}
    try:
        res = hybrid.simulate(dataclasses.replace(exp, controller_surface=surface))
    except hybrid.HybridError as exc:  # the flat plane may lose the surface altogether
        return {**row, "status": f"failed: {type(exc).__name__}"}, None
    m = res.metrics
    t = res.sample_t
    if res.normal_estimate is not None:
        err = res.normal_angle_error_deg
    elif isinstance(surface, hybrid.Plane):  # the plane's normal against the surface's
        err = np.degrees(np.arccos(np.clip(res.true_normal @ np.asarray(surface.normal), -1.0, 1.0)))
    else:
        err = np.zeros(len(t))
    late, steady = t >= 0.5, t >= 1.0
    row.update(status="ok", angle_rms_deg=float(np.sqrt(np.mean(err[late] ** 2))),
               angle_max_deg=float(err[late].max()),
               angle_max_after_1s_deg=float(err[steady].max()) if steady.any() else float("nan"),
               rms_force_error_N=m["rms_force_error_N"],
               rms_contact_force_error_N=float(np.sqrt(np.mean((res.force_reference - res.contact_force) ** 2))),
               rms_speed_error_m_per_s=m["rms_speed_error_m_per_s"],
               contact_losses=int(m["contact_losses"]), time_out_of_contact_s=m["time_out_of_contact_s"])
    step = exp.speed_reference
    if step.after != step.before:  # the speed step's transient
        window = (t >= step.at) & (t < step.at + 0.5)
        row["angle_max_after_speed_step_deg"] = float(err[window].max())
    return row, res


def study(quick: bool = False) -> tuple[list[dict], dict]:
    """Every run's row, and the results the figures draw."""
    rows, kept = [], {}
    frictions, speeds = ((0.2,), (0.15,)) if quick else (FRICTIONS, SPEEDS)

    def add(group: str, exp, controller: str, **labels):
        row, res = run(exp, controller)
        rows.append({"group": group, **labels, **row})
        return res

    for surface in ("sphere", "cylinder", "bumps"):
        for friction in frictions:
            for speed in speeds:
                exp = experiment(surface, friction, speed)
                for controller in CONTROLLERS:
                    res = add("grid", exp, controller, surface=surface, friction=friction, speed=speed)
                    if controller == "fusion" and surface in FIGURE_SURFACES and speed in (0.15, 0.3):
                        kept[(surface, friction, speed)] = res
    for friction in frictions:  # each estimator alone
        exp = experiment("sphere", friction, 0.15)
        for method in ("force", "velocity"):
            add("methods", exp, method, surface="sphere", friction=friction, speed=0.15)
    for surface in ("sphere", "cylinder", "bumps"):  # the speed reference's step
        for friction in frictions:
            exp = experiment(surface, friction, Step(0.15, 0.3, 1.5))
            for controller in ("exact", "fusion"):
                add("speed step", exp, controller, surface=surface, friction=friction, speed="0.15-0.3")
    for wavelength in (() if quick else (0.2, 0.1, 0.075, 0.05)):  # sharper bumps
        for speed in (0.15, 0.3):
            exp = experiment("bumps", 0.2, speed, wavelength=wavelength)
            for controller in ("exact", "fusion"):
                add("wavelength", exp, controller, surface=f"bumps {wavelength * 100:g} cm", friction=0.2,
                    speed=speed)
    for drop in (() if quick else (5, 10)):  # a step down: the tip flies off and lands
        for friction in (0.2, 0.5):
            exp = experiment(f"ledge {drop} mm", friction, 0.3)
            for controller in ("exact", "fusion"):
                add("ledge", exp, controller, surface=f"ledge {drop} mm", friction=friction, speed=0.3)
    return rows, kept


#: the envelope's factors, each swept alone about the sphere's run at friction 0.2 and 0.15 m/s (the full
#: list, then the quick one): the speed [m/s], the friction, the sphere's radius [m] (the normal turns at
#: speed / radius against the estimator's 30 ms), the sensor's force noise [N], the sensor's compliance
#: [mm/N] (its spring; the estimator learns it), the compliance the estimator is given [x the true one] and
#: the start's angle [deg] from the true normal
ENVELOPE = {"speed": ((0.02, 0.05, 0.1, 0.15, 0.3, 0.5), (0.05, 0.15, 0.3)),
            "friction": ((0.0, 0.1, 0.2, 0.35, 0.5, 0.7), (0.0, 0.2, 0.5)),
            "radius": ((0.04, 0.06, 0.1, 0.15, 0.25), (0.06, 0.15, 0.25)),
            "force noise": ((0.0, 0.1, 0.3, 0.5, 1.0), (0.0, 0.3, 1.0)),
            "sensor compliance": ((0.25, 0.5, 1.0, 2.0, 4.0), (0.5, 1.0, 2.0)),
            "compliance given": ((0.1, 0.3, 1.0, 3.0, 10.0), (0.1, 1.0, 10.0)),
            "start angle": ((0.0, 30.0, 60.0, 90.0), (0.0, 90.0))}
ENVELOPE_UNITS = {"speed": "m/s", "friction": "", "radius": "m", "force noise": "N", "sensor compliance": "mm/N",
                  "compliance given": "x true", "start angle": "deg"}


def envelope_case(factor: str, value: float) -> tuple[hybrid.Experiment, hybrid.EstimatedSurface]:
    """The run of the envelope's ``factor`` at ``value`` and the estimator it runs (defaults but the factor)."""
    friction, speed, estimator, overrides = 0.2, 0.15, {}, {}
    if factor == "speed":
        speed = value
    elif factor == "friction":
        friction = value
    elif factor == "radius":
        overrides["surface"] = hybrid.Sphere(SPHERE_CENTER, value)
    elif factor == "force noise":
        overrides["sensor"] = hybrid.Sensor(force_noise=value)
    elif factor == "sensor compliance":
        overrides["sensor"] = hybrid.Sensor(stiffness=1000.0 / value)
    exp = hybrid.tracing_experiment(speed_reference=Step(speed, speed, 0.0), contact=hybrid.Contact(friction=friction),
                                    **overrides)
    if factor == "compliance given":
        estimator["compliance"] = value / exp.sensor.stiffness
    elif factor == "start angle":
        start = exp.initial_state()[12:15]
        n = exp.surface.normal_at(start)
        across = np.cross(n, (0.0, 0.0, 1.0)) if abs(n[2]) < 0.99 else np.array([1.0, 0.0, 0.0])
        across /= np.linalg.norm(across)
        a = math.radians(value)
        estimator["initial_normal"] = tuple(math.cos(a) * n + math.sin(a) * across)
    return exp, hybrid.EstimatedSurface(**estimator)


def envelope(quick: bool = False) -> list[dict]:
    """Each factor of :data:`ENVELOPE` swept alone: the estimate's largest angle after 0.5 s and after 1 s,
    and its RMS force error over the exact surface's (the same run told the exact surface)."""
    rows = []
    for factor, (full, short) in ENVELOPE.items():
        for value in short if quick else full:
            exp, est = envelope_case(factor, value)
            row = {"factor": factor, "value": value}
            try:
                told = hybrid.simulate(exp)
                res = hybrid.simulate(dataclasses.replace(exp, controller_surface=est))
            except hybrid.HybridError as exc:
                rows.append({**row, "status": f"failed: {type(exc).__name__}"})
                continue
            err, t = res.normal_angle_error_deg, res.sample_t
            rows.append({**row, "status": "ok", "angle_max_after_0.5s_deg": float(err[t >= 0.5].max()),
                         "angle_max_after_1s_deg": float(err[t >= 1.0].max()),
                         "force_error_ratio": res.metrics["rms_force_error_N"] / told.metrics["rms_force_error_N"],
                         "contact_losses": int(res.metrics["contact_losses"])})
    return rows


def envelope_table(rows: list[dict]) -> str:
    """The envelope as Markdown: per factor and value, the angles and the force-error ratio."""
    out = ["| factor | value | largest angle after 0.5 s / 1 s [deg] | force error / exact's | contact losses |",
           "| --- | --- | --- | --- | --- |"]
    for r in rows:
        unit = ENVELOPE_UNITS[r["factor"]]
        value = f"{r['value']:g} {unit}".strip()
        if r["status"] != "ok":
            out.append(f"| {r['factor']} | {value} | fails | | |")
            continue
        out.append(f"| {r['factor']} | {value} | {r['angle_max_after_0.5s_deg']:.2f} / "
                   f"{r['angle_max_after_1s_deg']:.2f} | {r['force_error_ratio']:.2f} | {r['contact_losses']} |")
    return "\n".join(out) + "\n"


def envelope_figure(rows: list[dict], out: Path) -> Path:
    """``estimation_envelope.png``: per factor, the largest angle after 0.5 s and after 1 s (left axis, log)
    and the force-error ratio (right axis) against the factor's value; the targets dashed (2 degrees, 1.5x)."""
    import matplotlib.pyplot as plt
    from matplotlib import ticker

    factors = list(ENVELOPE)
    fig, axes = plt.subplots(2, (len(factors) + 1) // 2, figsize=(13, 6))
    for ax, factor in zip(axes.flat, factors):
        ok = [r for r in rows if r["factor"] == factor and r["status"] == "ok"]
        x = [r["value"] for r in ok]
        ax.plot(x, [r["angle_max_after_0.5s_deg"] for r in ok], "o-", color="tab:blue", label="angle after 0.5 s")
        ax.plot(x, [r["angle_max_after_1s_deg"] for r in ok], "s:", color="tab:blue", label="angle after 1 s")
        ax.axhline(2.0, color="tab:blue", lw=0.8, ls="--")
        ax.set_yscale("log")
        ax.set_xlabel(f"{factor} [{ENVELOPE_UNITS[factor]}]" if ENVELOPE_UNITS[factor] else factor, fontsize=8)
        ax.set_ylabel("largest angle [deg]", fontsize=8, color="tab:blue")
        twin = ax.twinx()
        twin.plot(x, [r["force_error_ratio"] for r in ok], "^-", color="tab:red", label="force error / exact's")
        twin.axhline(1.5, color="tab:red", lw=0.8, ls="--")
        twin.set_ylabel("force error / exact's", fontsize=8, color="tab:red")
        if factor in ("compliance given", "sensor compliance"):
            ax.set_xscale("log")
        for axis in (ax.xaxis, ax.yaxis) if factor in ("compliance given", "sensor compliance") else (ax.yaxis,):
            axis.set_major_formatter(ticker.FormatStrFormatter("%g"))
            axis.set_minor_formatter(ticker.NullFormatter())
        ax.set_ylim(min(0.5, ax.get_ylim()[0]), max(3.0, ax.get_ylim()[1]))
        ax.tick_params(labelsize=7)
        twin.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(factors):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=6, loc="upper left")
    fig.suptitle("The estimator's defaults on the sphere (friction 0.2, 0.15 m/s, force step at 0.5 s), each factor "
                 "alone; dashed: 2 degrees, 1.5x", fontsize=9)
    fig.tight_layout()
    path = out / "estimation_envelope.png"
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def _case(r: dict) -> tuple:
    """A run's case (the estimators alone compare with the grid's run of their case)."""
    return ("grid" if r["group"] == "methods" else r["group"], r["surface"], r["friction"], str(r["speed"]))


def with_ratios(rows: list[dict]) -> list[dict]:
    """Each run's RMS force and speed errors over those of the run told the exact surface."""
    exact = {_case(r): r for r in rows if r["controller"] == "exact" and r["status"] == "ok"}
    for r in rows:
        ref = exact.get(_case(r))
        if ref is not None and r["status"] == "ok":
            r["force_error_ratio"] = r["rms_force_error_N"] / ref["rms_force_error_N"]
            r["speed_error_ratio"] = r["rms_speed_error_m_per_s"] / ref["rms_speed_error_m_per_s"]
    return rows


def _cell(r: dict | None, key: str, fmt: str) -> str:
    if r is None or r["status"] != "ok":
        return "fails" if r is not None else ""
    v = r.get(key)
    return "" if v is None or (isinstance(v, float) and math.isnan(v)) else format(v, fmt)


def tables(rows: list[dict]) -> str:
    """The summary as Markdown: per surface, friction and speed, the estimate's normal angle and each
    controller's force error and contact losses."""
    index = {(r["group"], r["surface"], r["friction"], str(r["speed"]), r["controller"]): r for r in rows}
    out = ["| surface | friction | speed [m/s] | angle RMS / max [deg] | RMS force error [N]: exact, flat, "
           "estimated | RMS contact-force error [N]: exact, estimated | RMS speed error [mm/s]: exact, "
           "estimated | losses: flat, estimated |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    keys = sorted({k[1:4] for k in index if k[0] == "grid"}, key=lambda k: (k[0] != "sphere", k[0], k[1], k[2]))
    for surface, friction, speed in keys:
        get = {c: index.get(("grid", surface, friction, speed, c)) for c in CONTROLLERS}
        est = get["fusion"]
        angle = f"{_cell(est, 'angle_rms_deg', '.2f')} / {_cell(est, 'angle_max_deg', '.1f')}"
        force = ", ".join(_cell(get[c], "rms_force_error_N", ".2f") for c in CONTROLLERS)
        speed_err = ", ".join(_cell(get[c], "rms_speed_error_m_per_s", ".1f") if get[c] is None or get[c][
            "status"] != "ok" else f"{get[c]['rms_speed_error_m_per_s'] * 1000:.1f}" for c in ("exact", "fusion"))
        losses = ", ".join(_cell(get[c], "contact_losses", "d") for c in ("flat", "fusion"))
        contact = ", ".join(_cell(get[c], "rms_contact_force_error_N", ".2f") for c in ("exact", "fusion"))
        out.append(f"| {surface} | {friction:g} | {speed} | {angle} | {force} | {contact} | {speed_err} | {losses} |")
    out += ["", "| case | estimator | angle RMS / max [deg] | max after 1 s [deg] | force error / exact's | RMS "
            "contact-force error [N]: exact, estimated | losses: exact, estimated |",
            "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if r["group"] in ("methods", "speed step", "wavelength", "ledge") and r["controller"] != "exact":
            ref = index.get((*_case(r), "exact"))
            what = f"{r['surface']}, friction {r['friction']:g}, {r['speed']} m/s"
            if r["group"] == "speed step":
                what += f" (max in the 0.5 s after the step {_cell(r, 'angle_max_after_speed_step_deg', '.1f')})"
            out.append(f"| {what} | {r['controller']} | {_cell(r, 'angle_rms_deg', '.2f')} / "
                       f"{_cell(r, 'angle_max_deg', '.1f')} | {_cell(r, 'angle_max_after_1s_deg', '.1f')} | "
                       f"{_cell(r, 'force_error_ratio', '.2f')} | {_cell(ref, 'rms_contact_force_error_N', '.2f')}, "
                       f"{_cell(r, 'rms_contact_force_error_N', '.2f')} | {_cell(ref, 'contact_losses', 'd')}, "
                       f"{_cell(r, 'contact_losses', 'd')} |")
    return "\n".join(out) + "\n"


def figures(kept: dict, out: Path) -> list[Path]:
    """The estimate against the true normal (components) and the angle error, per surface."""
    import matplotlib.pyplot as plt

    from hybrid.plots import plot_normal_estimate

    written = []
    for surface in FIGURE_SURFACES:
        runs = {k: v for k, v in kept.items() if k[0] == surface and v is not None}
        if not runs:
            continue
        fig, axes = plt.subplots(2, 1, figsize=(7, 5.2), sharex=True)
        shown = runs.get((surface, 0.2, 0.15)) or next(iter(runs.values()))
        plot_normal_estimate(shown, axes[0])
        axes[0].set_xlabel("")
        axes[0].legend(fontsize=6, ncol=3, loc="lower left")
        e = shown.experiment
        axes[0].set_title(f"UR5 on the {surface}: the estimated normal (solid) and the true one (dashed), "
                          f"friction {e.contact.friction:g}, {e.speed_reference.before:g} m/s", fontsize=8)
        colors = {0.0: "tab:green", 0.2: "tab:blue", 0.5: "tab:red"}
        for (_, friction, speed), res in sorted(runs.items()):
            plot_normal_estimate(res, axes[1], angle=True, label=f"friction {friction:g}, {speed:g} m/s",
                                 color=colors.get(friction))
            axes[1].lines[-1].set_linestyle("-" if speed == 0.15 else ":")
        axes[1].axvline(0.5, color="0.5", lw=0.8, ls="--")
        axes[1].text(0.51, axes[1].get_ylim()[1] * 0.9, "force step", fontsize=7, color="0.4")
        axes[1].legend(fontsize=6, ncol=2)
        fig.tight_layout()
        path = out / f"estimation_{surface}.png"
        fig.savefig(path, dpi=150)
        plt.close(fig)
        written.append(path)
    return written


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, type=Path, help="folder for the CSV, JSON, tables and figures")
    parser.add_argument("--quick", action="store_true", help="one friction and speed, no wavelength sweep, three "
                        "values (or two) per factor of the envelope")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    began = time.perf_counter()
    rows, kept = study(args.quick)
    rows = with_ratios(rows)
    sweep = envelope(args.quick)
    with open(args.out / "envelope.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=sorted({k for r in sweep for k in r}, key=lambda k: list(
            sweep[0]).index(k) if k in sweep[0] else 99))
        writer.writeheader()
        writer.writerows(sweep)
    names = sorted({k for r in rows for k in r}, key=lambda k: list(rows[0]).index(k) if k in rows[0] else 99)
    with open(args.out / "runs.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=names)
        writer.writeheader()
        writer.writerows(rows)
    settings = {"frictions": FRICTIONS, "speeds": SPEEDS, "bumps": {"height_m": BUMP_HEIGHT, "wavelength_m":
                BUMP_WAVELENGTH, "z0_m": BUMP_Z0, "path_m": BUMP_PATH}, "estimator": hybrid.EstimatedSurface().__dict__,
                "envelope": ENVELOPE}
    (args.out / "study.json").write_text(json.dumps({"settings": settings, "runs": rows, "envelope": sweep},
                                                    indent=1, default=str))
    (args.out / "table.md").write_text(tables(rows) + "\n" + envelope_table(sweep))
    written = [*figures(kept, args.out), envelope_figure(sweep, args.out)]
    print(tables(rows))
    print(envelope_table(sweep))
    print(f"{len(rows) + 2 * len(sweep)} runs in {time.perf_counter() - began:.0f} s; wrote runs.csv, envelope.csv, "
          "study.json, table.md, "
          + ", ".join(p.name for p in written) + f" into {args.out}")


if __name__ == "__main__":
    main()
