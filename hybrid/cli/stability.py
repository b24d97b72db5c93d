"""``python -m hybrid stability``: an experiment's sampled loops, their margins, and the stable region."""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.cli import common
from hybrid.cli.experiments import add_setting_argument, experiment_of
from hybrid.errors import HybridError
from hybrid.experiments import FACTORIES
from hybrid.stability.analysis import stability
from hybrid.stability.maps import MOST_POINTS, stability_map

STABILITY = ("Judge an experiment's sampled loops, map their stable region. Prints each task axis's loop: its "
             "spectral radius (stable below 1), the dominant pole's damping and frequency, the gain and phase "
             "margins and how many more samples the force reading may be late (docs/howto/stability.rst). "
             "With --over, the stable region over a grid of settings as a table (map.csv) and a figure (map.png, "
             "the boundary drawn) in --out.")
#: the files the command writes into --out
PRODUCTS = ("stability.json", "map.csv")


def add_parser(sub) -> None:
    p = common.command(sub, "stability", STABILITY, run)
    p.add_argument("--experiment", default="paper", choices=tuple(FACTORIES),
                   help="the experiment whose loops are judged (default: paper)")
    add_setting_argument(p)
    p.add_argument("--over", action="append", default=[], metavar="NAME=VALUES", type=_over,
                   help="map the stable region over this setting (sample_time, sensor.stiffness, contact.stiffness, "
                        "sensor.delay_samples, sensor.bandwidth_hz, model_error, a gain KPf...): VALUES as "
                        "v1,v2,... or START:STOP:COUNT (evenly spaced) or START:STOP:COUNT:log; repeatable, the "
                        "grid is the product; needs --out")
    p.add_argument("--out", metavar="DIR", help="folder for stability.json and, with --over, map.csv and the figure")
    p.add_argument("--force", action="store_true", help="overwrite earlier results in --out")
    common.add_format(p, "map's figure")
    common.add_verbose(p)


def _over(text: str) -> tuple[str, np.ndarray]:
    """``NAME=VALUES`` as a setting's name and its values (see ``--over``)."""
    name, sep, values = text.partition("=")
    parts = values.split(":")
    try:
        if not sep or not name.strip():
            raise ValueError
        if len(parts) in (3, 4):
            start, stop, count = float(parts[0]), float(parts[1]), int(parts[2])
            if not (1 <= count <= MOST_POINTS and math.isfinite(start) and math.isfinite(stop)) \
                    or (len(parts) == 4 and (parts[3] != "log" or start <= 0 or stop <= 0)):
                raise ValueError  # (a count past the map's most points, refused before its values are made)
            grid = np.geomspace(start, stop, count) if len(parts) == 4 else np.linspace(start, stop, count)
        elif len(parts) == 1:
            grid = np.array([float(v) for v in values.split(",")])
        else:
            raise ValueError
        if not np.isfinite(grid).all():
            raise ValueError
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"--over {text!r}: give NAME=v1,v2,... or NAME=START:STOP:COUNT or NAME=START:STOP:COUNT:log (finite "
            f"numbers, positive ends for log, COUNT 1 to {MOST_POINTS:,}), e.g. sensor.stiffness=1e3:1e5:30:log"
        ) from None
    return name.strip(), grid


def run(args) -> int:
    exp = experiment_of(args.experiment, args.settings)
    over = dict(args.over)
    if len(over) != len(args.over):
        raise HybridError("--over names a setting twice; give each setting once")
    if over and not args.out:
        raise HybridError("--over maps the stable region into files: give --out DIR")
    out = Path(args.out) if args.out else None
    if out is not None:
        _prepare(out, args.force)
    with args.report.step(f"judging the {args.experiment} experiment's sampled loops"):
        report = stability(exp)
    print(report)
    if out is not None:
        files.write_text(out / "stability.json", json.dumps(_as_data(report), indent=2) + "\n", overwrite=True)
    if over:
        from hybrid.stability.figures import save_map

        size = math.prod(len(v) for v in over.values())
        with args.report.step(f"mapping the stable region over {', '.join(over)} ({size:,} points)"):
            smap = stability_map(exp, over)
        files.write_text(out / "map.csv", smap.table.to_csv(index=False), overwrite=True)
        written = save_map(smap, out / "map", tuple(args.format))
        print(f"\n{smap.stable_share:.1%} of the {size:,} points are stable; wrote map.csv, "
              f"{', '.join(p.name for p in written)} to {out}")
    return 0


def _prepare(out: Path, force: bool) -> None:
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is an existing file; give a folder (nothing was written)")
    clash = [n for n in PRODUCTS if (out / n).exists()] + sorted(p.name for p in out.glob("map.*"))
    if clash and not force:
        raise HybridError(f"--out {out} already holds results ({', '.join(sorted(set(clash))[:3])}); choose another "
                          "folder or pass --force to overwrite them")
    files.writable_folder(out, "--out folder")


def _as_data(report) -> dict:
    """The report as JSON-ready data (numbers as numbers; inf as a string, as JSON has none)."""
    def number(v):
        v = float(v)
        return v if math.isfinite(v) else str(v)  # "inf", "nan"

    return {"sample_time": report.sample_time, "spectral_radius": number(report.spectral_radius),
            "stable": report.stable,
            "loops": [{"axis": x.axis, "loop": x.loop, "spectral_radius": number(x.spectral_radius),
                       "damping": number(x.damping), "natural_frequency_hz": number(x.natural_frequency_hz),
                       "gain_margin_db": number(x.gain_margin_db), "phase_margin_deg": number(x.phase_margin_deg),
                       "delay_margin_samples": x.delay_margin_samples, "stable": x.stable,
                       "poles": [[z.real, z.imag] for z in np.asarray(x.poles, complex).tolist()]}
                      for x in report.loops]}
