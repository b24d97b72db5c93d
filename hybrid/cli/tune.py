"""``python -m hybrid tune --objective METRIC --scenarios FILE.toml --out DIR``: an experiment's gains tuned
across scenarios with a stability margin kept on each (:func:`hybrid.tune`), written as JSON, CSV and a
figure."""

from __future__ import annotations

import argparse
import json
import math
import re
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid import files
from hybrid.cli import common
from hybrid.cli.experiments import experiment_of
from hybrid.cli.sweep import _value as distribution
from hybrid.errors import HybridError
from hybrid.experiments import FACTORIES
from hybrid.stability.tuning import tune
from hybrid.stability.tuning_problem import AGGREGATES, GAIN_NAMES
from hybrid.sweeps.engines import CONNECT_TIMEOUT
from hybrid.validate import MAX_NESTING, check_nesting, shown

#: the tables of a scenario file
SECTIONS = ("distributions", "draw", "scenario", "held_out")
#: what a tuning writes into --out, besides its figure (tuning.FORMAT)
PRODUCTS = ("tuning.json", "history.csv", "margins.csv", "runs.csv")
#: a commented scenario file (--print-example)
EXAMPLE = Path(__file__).resolve().parent.parent / "data" / "tune_scenarios.toml"

DESCRIPTION = ("Tune the gains over scenarios, keeping a margin. CMA-ES searches an experiment's gains (on a log "
               "scale between their bounds) for the smallest objective, a metric of the runs or a weighted sum of "
               "them, over the training scenarios; a candidate that loses the gain margin "
               "(--min-gain-margin) on any of them, by the sampled loops' model, is infeasible and not run. Each "
               "generation's runs go as one batch through the compiled sweeps (or to a Dask cluster).\n\n"
               "Writes into --out tuning.json (the gains, the objective before and after on the training and the "
               "held-out scenarios), history.csv (every candidate judged), margins.csv (the margins per scenario, by "
               "hybrid.stability), runs.csv (the final runs) and the figure tuning.png. The scenarios come from a "
               "TOML file (--scenarios; --print-example shows the format) and/or --scenario.")


class _PrintExample(argparse.Action):
    """``--print-example``: print the shipped scenario file and exit (no other argument needed)."""

    def __call__(self, parser, namespace, values, option_string=None):
        print(EXAMPLE.read_text(), end="")
        parser.exit()


def add_parser(sub) -> None:
    p = common.command(sub, "tune", DESCRIPTION, run)
    p.add_argument("--experiment", choices=tuple(FACTORIES), default="paper",
                   help="the experiment whose gains are tuned (default: paper)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", dest="settings",
                   help="override a setting of the experiment, as a sweep file's [base] or parameters name it "
                        "(duration=1.0, F_d=15, contact.friction=0.1); repeatable")
    p.add_argument("--objective", action="append", required=True, type=_weighted, metavar="METRIC[=WEIGHT]",
                   help="a metric of the runs to minimise (e.g. rms_force_error_N); repeat it with weights for a "
                        "weighted sum (--objective rms_force_error_N --objective force_overshoot_N=0.5)")
    p.add_argument("--aggregate", choices=AGGREGATES, default="mean",
                   help="a candidate's objective over the scenarios: their mean or the worst (default: mean)")
    p.add_argument("--scenarios", metavar="FILE.toml",
                   help="the scenarios: distributions to draw from and/or scenarios one by one (--print-example)")
    p.add_argument("--print-example", action=_PrintExample, nargs=0, help="print a commented scenario file and exit")
    p.add_argument("--scenario", action="append", default=[], type=_scenario, metavar="KEY=VALUE[,KEY=VALUE...]",
                   help="a training scenario, settings as a sweep names them (contact.stiffness=2e4,model_error=0.3); "
                        "repeatable, with or without --scenarios")
    p.add_argument("--held-out-scenario", action="append", default=[], type=_scenario,
                   metavar="KEY=VALUE[,KEY=VALUE...]", help="a held-out scenario (judged, not tuned on); repeatable")
    p.add_argument("--samples", type=_count, metavar="N",
                   help="training scenarios drawn from the file's [distributions] (default: its [draw] samples, "
                        "else 16)")
    p.add_argument("--held-out", type=_count, metavar="N",
                   help="held-out scenarios drawn from [distributions] (default: its [draw] held_out, else as many "
                        "as the training ones drawn)")
    p.add_argument("--gains", type=_gains, metavar="GAIN[,GAIN...]",
                   help=f"the gains to tune, from {', '.join(GAIN_NAMES)} (default: every gain the loops use)")
    p.add_argument("--bound", action="append", default=[], type=_bound, metavar="GAIN=LOW:HIGH",
                   help="a gain's range, 0 < LOW < HIGH (default: a tenth to ten times the experiment's); repeatable")
    p.add_argument("--min-gain-margin", type=_decibels, default=6.0, metavar="DB",
                   help="the gain margin every loop keeps on every training scenario [dB] (default: 6; 0: stable)")
    p.add_argument("--min-delay-margin", type=_count, default=0, metavar="SAMPLES",
                   help="the samples by which every loop's reading may be late, stable still (default: 0)")
    p.add_argument("--budget", type=common.positive_int, default=200, metavar="N",
                   help="candidate gains to judge, each on every training scenario (default: 200)")
    p.add_argument("--seed", type=_count, default=0, metavar="S",
                   help="the draws' and the search's seed: the same seed, the same gains (default: 0)")
    p.add_argument("--popsize", type=common.positive_int, metavar="N",
                   help="candidates per generation (default: CMA-ES's, 4 + 3 ln(gains))")
    p.add_argument("--workers", type=common.positive_int, metavar="N",
                   help="processes for the runs (default: one per core), or the local Dask cluster's workers")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on the Dask cluster of this scheduler, e.g. tcp://127.0.0.1:8786 "
                        "(pip install 'hybrid-decoupling[dask]')")
    p.add_argument("--connect-timeout", type=common.seconds, default=CONNECT_TIMEOUT, metavar="SECONDS",
                   help=f"how long to wait for the Dask scheduler (default {CONNECT_TIMEOUT:g} s)")
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the results and the figure")
    p.add_argument("--force", action="store_true", help="overwrite an earlier tuning's results in --out")
    common.add_format(p, "figure")
    common.add_verbose(p)


# ------------------------------------------------------------------ option values


def _count(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r}: give a whole number of at least 0")
    return value


def _decibels(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0 <= value <= 60:
        raise argparse.ArgumentTypeError(f"{text!r}: give a gain margin in dB, from 0 to 60")
    return value


def _weighted(text: str) -> tuple[str, float]:
    name, sep, weight = text.partition("=")
    try:
        value = float(weight) if sep else 1.0
    except ValueError:
        value = math.nan
    if not name.strip() or not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r}: give METRIC or METRIC=WEIGHT, e.g. force_overshoot_N=0.5")
    return name.strip(), value


def _gains(text: str) -> tuple[str, ...]:
    return tuple(g.strip() for g in text.split(",") if g.strip())


def _bound(text: str) -> tuple[str, tuple[float, float]]:
    name, _, span = text.partition("=")
    low, colon, high = span.partition(":")
    try:
        values = (float(low), float(high))
    except ValueError:
        values = None
    if not name.strip() or not colon or values is None:
        raise argparse.ArgumentTypeError(f"{text!r}: give GAIN=LOW:HIGH, e.g. KPf=0.5:8")
    return name.strip(), values


def _scenario(text: str) -> dict:
    """``KEY=VALUE,KEY=VALUE`` as settings, each VALUE a TOML value (a number, true/false, a quoted string), or
    else text."""
    settings = {}
    for part in re.split(r",(?=\s*[\w.]+\s*=)", text):
        key, sep, value = part.partition("=")
        key = key.strip()
        if not sep or not key or not value.strip():
            raise argparse.ArgumentTypeError(f"{text!r}: give KEY=VALUE[,KEY=VALUE...], e.g. "
                                             "contact.stiffness=2e4,model_error=0.3")
        if key in settings:
            raise argparse.ArgumentTypeError(f"{text!r} gives {key} twice; give each setting once")
        try:
            settings[key] = tomllib.loads(f"v = {value}")["v"]
        except tomllib.TOMLDecodeError:
            settings[key] = value.strip()
    return settings


# ------------------------------------------------------------------ the scenario file


def read_scenarios(path: Path) -> dict:
    """The scenario file's ``distributions``, ``scenarios``, ``held_out`` (list or count) and ``samples``,
    checked (see :data:`EXAMPLE`)."""
    try:
        config = tomllib.loads(files.read_user_text(path, "scenario file"))
    except tomllib.TOMLDecodeError as exc:
        raise HybridError(f"{path} is not valid TOML: {exc}") from None
    except RecursionError:
        raise HybridError(f"{path}: tables or lists are nested too deeply to read; write them at most "
                          f"{MAX_NESTING} deep") from None
    check_nesting(str(path), config)
    unknown = sorted(set(config) - set(SECTIONS))
    if unknown:
        raise HybridError(f"{path}: unknown table {unknown[0]}{common.did_you_mean(unknown[0], SECTIONS)}; a scenario "
                          f"file has {', '.join(SECTIONS)}")
    for table in ("distributions", "draw"):
        if not isinstance(config.get(table, {}), dict):
            raise HybridError(f"{path}: {table} must be a table ([{table}] with its keys)")
    for table in ("scenario", "held_out"):
        if not isinstance(config.get(table, []), list):
            raise HybridError(f"{path}: {table} must be an array of tables ([[{table}]] for each scenario)")
    draw = config.get("draw", {})
    unknown = sorted(set(draw) - {"samples", "held_out"})
    if unknown:
        raise HybridError(f"{path}: [draw] {unknown[0]}{common.did_you_mean(unknown[0], ('samples', 'held_out'))}: "
                          "it takes samples and held_out")
    if "held_out" in draw and config.get("held_out"):
        raise HybridError(f"{path}: held-out scenarios both drawn ([draw] held_out) and listed ([[held_out]]); "
                          "keep one")
    distributions = {k: distribution(k, v) for k, v in config.get("distributions", {}).items()} or None
    if "draw" in config and distributions is None:
        raise HybridError(f"{path}: [draw] draws from [distributions], which it lacks; add it, or drop [draw]")
    return {"distributions": distributions, "scenarios": config.get("scenario", []),
            "held_out": config.get("held_out") or draw.get("held_out"), "samples": draw.get("samples")}


# ------------------------------------------------------------------ the command


def prepare_out(out: Path, force: bool) -> None:
    """Create ``out`` and check it is writable before the work; refuse to overwrite a tuning's results
    unless ``force``."""
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is an existing file; give a folder (nothing was written)")
    clash = [n for n in (*PRODUCTS, *(f"tuning.{f}" for f in common.FORMATS)) if (out / n).exists()]
    if clash and not force:
        raise HybridError(f"--out {out} already holds a tuning's results ({', '.join(clash[:3])}...); choose another "
                          "folder or pass --force to overwrite them")
    files.writable_folder(out, "--out folder")


def run(args) -> int:
    from hybrid.plots import save

    report = args.report
    given = read_scenarios(Path(args.scenarios)) if args.scenarios else {"distributions": None, "scenarios": [],
                                                                        "held_out": None, "samples": None}
    if args.held_out is not None and args.held_out_scenario:
        raise HybridError("--held-out N draws the held-out scenarios and --held-out-scenario lists them; give one")
    scenarios = [*given["scenarios"], *args.scenario]
    held_out = args.held_out_scenario or (args.held_out if args.held_out is not None else given["held_out"])
    samples = args.samples if args.samples is not None else given["samples"] if given["samples"] is not None else 16
    if not scenarios and given["distributions"] is None:
        raise HybridError("no scenario to tune on: give --scenarios FILE.toml (--print-example shows one) or "
                          "--scenario KEY=VALUE,...")
    names = [name for name, _ in args.objective]
    if len(set(names)) != len(names):
        raise HybridError(f"--objective names {shown(names, 60)}: a metric twice; give each once")
    exp = experiment_of(args.experiment, args.settings)
    out = Path(args.out)
    prepare_out(out, args.force)
    result = tune(exp, dict(args.objective), scenarios or None, distributions=given["distributions"],
                  samples=samples, held_out=held_out, aggregate=args.aggregate, budget=args.budget, seed=args.seed,
                  gains=args.gains, bounds=dict(args.bound) or None, min_gain_margin_db=args.min_gain_margin,
                  min_delay_margin_samples=args.min_delay_margin, popsize=args.popsize, client=args.scheduler,
                  workers=args.workers, progress=True, connect_timeout=args.connect_timeout)
    with report.step("writing the results"):
        summary = {"experiment": args.experiment, "settings": list(args.settings), **result.to_dict()}
        files.write_text(out / "tuning.json", json.dumps(summary, indent=2, allow_nan=False) + "\n", overwrite=True)
        for name, table in (("history", result.history), ("margins", result.margins), ("runs", result.runs)):
            files.write_with(out / f"{name}.csv", lambda tmp, t=table: t.to_csv(tmp, index=False), overwrite=True)
        written = save(result.figure(), out / "tuning", formats=tuple(args.format))
    for path in written:
        report.detail(f"  wrote {path}")
    print(result)
    print(f"wrote {', '.join(PRODUCTS)} and {len(written)} figure file{'s' * (len(written) > 1)} to {out}")
    return 0
