"""``python -m hybrid sweep CONFIG.toml --out DIR``: a sweep from a file, with progress, incremental
results (Parquet, CSV on request), resuming, and heatmaps."""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import fields, is_dataclass
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid import sweeps as sw
from hybrid.cli import common
from hybrid.control.loops import Gains
from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments import FACTORIES
from hybrid.experiments.experiment import Experiment
from hybrid.experiments.settings import PREFIX_ALIASES, setting_aliases
from hybrid.files import read_user_text
from hybrid.plants.contact import Contact, Sensor
from hybrid.sweeps import sweep
from hybrid.validate import MAX_NESTING, check_nesting, shown

DEMO = Path(__file__).resolve().parent.parent / "data" / "sweep_demo.toml"
SECTIONS = {"experiment", "base", "parameters", "sweep", "figures"}


DESCRIPTION = ("Run a parameter sweep from a TOML file (resumable). Every run's metrics go "
               "into --out as it finishes (results.parquet, and results.csv with --csv); the same sweep into the "
               "same folder resumes where it stopped. The file's [figures] table asks for heatmaps of metrics over "
               "two swept settings. --demo runs the shipped study, --print-demo prints its file (a commented "
               "example of the format).")


class _PrintDemo(argparse.Action):
    """``--print-demo``: print the shipped sweep file and exit (no other argument needed)."""

    def __call__(self, parser, namespace, values, option_string=None):
        sys.stdout.write(DEMO.read_text())
        parser.exit()


def add_parser(sub) -> None:
    p = common.command(sub, "sweep", DESCRIPTION, run)
    p.add_argument("config", nargs="?", metavar="CONFIG.toml",
                   help="the sweep's TOML file (--print-demo shows the format)")
    p.add_argument("--demo", action="store_true",
                   help="run the shipped demo study (model error, friction, speed; 10,140 runs) instead of a file")
    p.add_argument("--print-demo", action=_PrintDemo, nargs=0,
                   help="print the shipped demo study's TOML file (a commented example) and exit")
    p.add_argument("--out", required=True, metavar="DIR",
                   help="folder for results.parquet, parts/ (for resuming) and the heatmaps")
    p.add_argument("--csv", action="store_true", help="also write results.csv")
    p.add_argument("--engine", default="local", choices=sw.ENGINES,
                   help="where the runs go: local (processes on this machine) or dask (a Dask cluster; "
                        "pip install 'hybrid-decoupling[dask]') (default: local)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="with --engine dask: the scheduler's address, e.g. tcp://127.0.0.1:8786 "
                        "(default: a local cluster)")
    p.add_argument("--connect-timeout", type=common.seconds, default=sw.CONNECT_TIMEOUT, metavar="SECONDS",
                   help=f"how long to wait for the Dask scheduler (default {sw.CONNECT_TIMEOUT:g} s)")
    p.add_argument("--workers", type=common.positive_int, metavar="N",
                   help="processes (local) or workers of the local Dask cluster (default: one per core)")
    p.add_argument("--force", action="store_true", help="start afresh in a folder that holds another sweep")
    common.add_format(p, "heatmaps")
    common.add_verbose(p)


def _value(name: str, value):
    """A TOML value as a setting: a list, ``{linspace = [first, last, count]}`` (evenly spaced values,
    both ends included), or a table with one distribution name (drawn values)."""

    if isinstance(value, dict) and list(value) == ["linspace"]:
        return _linspace(name, value["linspace"])
    if isinstance(value, dict):
        if len(value) != 1 or next(iter(value)) not in sw.DISTRIBUTIONS:
            hint = common.did_you_mean(next(iter(value)), [*sw.DISTRIBUTIONS, "linspace"]) if len(value) == 1 else ""
            raise HybridError(f"parameter {name!r}: a table must name one distribution{hint}: "
                              f"{', '.join(sw.DISTRIBUTIONS)}, e.g. {{uniform = [0.0, 0.3]}}, or evenly "
                              "spaced values, {linspace = [first, last, count]}")
        kind, args = next(iter(value.items()))
        if not isinstance(args, list) or len(args) != 2:
            raise HybridError(f"parameter {name!r}: {kind} takes two numbers, e.g. {{{kind} = [0.0, 0.3]}}")
        return sw.DISTRIBUTIONS[kind](*args)
    if not isinstance(value, list):
        raise HybridError(f"parameter {name!r}: give a list of values or a distribution table, got {shown(value, 60)}")
    return value


def _linspace(name: str, args) -> list[float]:
    usage = (f"parameter {name!r}: linspace takes the first and last values and a whole count of 1 to "
             f"1,000,000, e.g. {{linspace = [0.0, 0.5, 11]}}; got {shown(args, 60)}")
    numbers = (isinstance(args, list) and len(args) == 3 and not any(isinstance(a, bool) for a in args)
               and all(isinstance(a, (int, float)) for a in args))
    try:
        first, last, count = (float(args[0]), float(args[1]), args[2]) if numbers else (0.0, 0.0, 0)
    except (TypeError, ValueError, OverflowError):
        raise HybridError(usage) from None
    if not (isinstance(count, int) and 1 <= count <= 1_000_000 and math.isfinite(first) and math.isfinite(last)):
        raise HybridError(usage)
    if count > 1 and first == last:
        raise HybridError(f"parameter {name!r}: linspace from {first:g} to itself gives {count} equal values; give "
                          "two different ends, or a count of 1")
    # rounded to 12 digits of the span: 0.3, not 0.30000000000000004, and 0, not 1e-17, in the table and
    # on the figures' axes
    span = abs(last - first) or abs(first) or 1.0
    digits = max(0, 12 - math.floor(math.log10(span)))
    return [round(first + (last - first) * i / max(count - 1, 1), digits) + 0.0 for i in range(count)]


#: keywords a factory takes besides the experiment's fields, the gains and F_d / v_d
FACTORY_KEYWORDS = {"paper": ("arm",), "tracing": ("latitude",)}


def _base(kind: str, settings: dict, where: str = "[base]"):
    """The base experiment from the ``[base]`` table (``paper_experiment``'s keywords; a table for a
    reference becomes a Step, for ``sensor``/``contact``/``gains`` their dataclass). ``where`` names
    the settings' place in an error (``[base]``, ``--set``)."""

    parts = {"sensor": Sensor, "contact": Contact, "gains": Gains}
    steps = ("force_reference", "speed_reference", "F_d", "v_d")
    made = {}
    for key, value in settings.items():
        if key == "path_task":  # a path on a surface, its profiles: Python objects, not a TOML value
            raise HybridError(f"{where} path_task: a path task is made in Python (hybrid.PathTask), not given as a "
                              "setting; run it with hybrid.simulate or hybrid.sweep, write its C with "
                              "Experiment.generate")
        if isinstance(value, dict):
            typ = Step if key in steps else parts.get(key)
            if typ is None:
                raise HybridError(f"{where} {key} = a table: only {', '.join(steps + tuple(parts))} take one")
            known = {f.name for f in fields(typ)}
            if not set(value) <= known:
                wrong = sorted(set(value) - known)
                raise HybridError(f"{where} {key}: unknown {', '.join(wrong)}{common.did_you_mean(wrong[0], known)}; "
                                  f"{typ.__name__} has {', '.join(sorted(known))}")
            value = typ(**value)
        made[key] = value
    if not isinstance(kind, str) or kind not in FACTORIES:
        raise HybridError(f"experiment = {shown(kind, 60)}{common.did_you_mean(kind, FACTORIES)}; give one of "
                          f"{', '.join(repr(k) for k in FACTORIES)}")
    known = factory_keywords(kind)
    unknown = [k for k in made if k not in known]
    try:
        return FACTORIES[kind](**made)
    except HybridError as exc:
        if unknown and str(exc).startswith("unknown setting"):
            raise HybridError(f"{where} {unknown[0]}: unknown setting of the {kind} experiment"
                              f"{common.did_you_mean(unknown[0], known)}; known: {', '.join(sorted(known))}") from None
        raise


def factory_keywords(kind: str) -> set[str]:
    """The names the factory of experiment ``kind`` takes: the experiment's fields, the gains,
    ``F_d``/``v_d`` and its own keywords."""
    return ({f.name for f in fields(Experiment)} | set(setting_aliases()) | set(FACTORY_KEYWORDS.get(kind, ())))


def setting_names(base) -> list[str]:
    """Every name a sweep's ``[parameters]`` (or ``--set``) may give for ``base``: its fields, the short
    names, and dotted paths into its parts (``contact.friction``)."""
    names = list(setting_aliases())

    def walk(obj, prefix: str, depth: int) -> None:
        for f in fields(obj):
            names.append(prefix + f.name)
            value = getattr(obj, f.name)
            if depth < 3 and is_dataclass(value) and not isinstance(value, type):
                walk(value, f"{prefix}{f.name}.", depth + 1)

    walk(base, "", 0)
    for short, long in PREFIX_ALIASES.items():  # arm.m2 for robot.closed_form.m2
        names += [short + n[len(long):] for n in names if n.startswith(long)]
    return names


def check_parameter_names(base, parameters) -> None:
    """``[parameters]`` names settings of ``base``: an unknown one is refused with the nearest known one."""
    try:
        sw.check_names(base, parameters)
    except HybridError as exc:
        if not str(exc).startswith("unknown setting"):
            raise
        names = setting_names(base)
        wrong = next((n for n in parameters if n not in names), None)
        if wrong is None:
            raise
        raise HybridError(f"[parameters]: unknown setting {wrong!r}{common.did_you_mean(wrong, names)}; give a "
                          "setting of the experiment (model_error, controller, KPf) or a dotted path into one "
                          "(contact.friction, gains.KPf, speed_reference.before)") from None


def read_config(path: Path) -> dict:
    """The sweep's settings from its TOML file, checked."""
    try:
        config = tomllib.loads(read_user_text(path, "sweep file"))
    except tomllib.TOMLDecodeError as exc:
        raise HybridError(f"{path} is not valid TOML: {exc}") from None
    except RecursionError:  # the TOML reader recurses into inline tables and arrays
        raise HybridError(f"{path}: tables or lists are nested too deeply to read; write them at most "
                          f"{MAX_NESTING} deep") from None
    check_nesting(str(path), config)
    unknown = sorted(set(config) - SECTIONS)
    if unknown:
        raise HybridError(f"{path}: unknown key(s) {', '.join(unknown)}{common.did_you_mean(unknown[0], SECTIONS)}; "
                          f"a sweep file has {', '.join(sorted(SECTIONS))}")
    if not isinstance(config.get("parameters"), dict) or not config["parameters"]:
        raise HybridError(f"{path} has no [parameters] table: nothing to sweep")
    for table in ("base", "sweep", "figures"):
        if not isinstance(config.get(table, {}), dict):
            raise HybridError(f"{path}: {table} must be a table ([{table}] with its keys)")
    return config


def check_figures(figures: dict | None, parameters, metrics) -> None:
    """The ``[figures]`` table names swept parameters and known metrics (checked before any run)."""
    if not figures:
        return
    known = {"x", "y", "rows", "cols", "metrics", "ratio"}
    if set(figures) - known:
        wrong = sorted(set(figures) - known)
        raise HybridError(f"[figures]: unknown {', '.join(wrong)}{common.did_you_mean(wrong[0], known)}; it takes "
                          f"{', '.join(sorted(known))}")
    for key in ("x", "y", "rows", "cols"):
        if key in figures and (not isinstance(figures[key], str) or figures[key] not in parameters):
            raise HybridError(f"[figures] {key} = {shown(figures[key], 60)} is not a swept parameter"
                              f"{common.did_you_mean(figures[key], parameters)}; swept: {', '.join(parameters)}")
    if "x" not in figures or "y" not in figures:
        raise HybridError("[figures] needs x and y (two swept parameters)")
    wanted = figures.get("metrics", [])
    if not isinstance(wanted, list) or not all(isinstance(w, str) for w in wanted) or not set(wanted) <= set(metrics):
        unknown = [w for w in wanted if w not in metrics] if isinstance(wanted, list) else wanted
        hint = common.did_you_mean(unknown[0], metrics) if isinstance(unknown, list) and unknown else ""
        raise HybridError(f"[figures] metrics = {shown(unknown, 60)}{hint}: give a list of the runs' metric names "
                          f"({', '.join(metrics)})")
    check_ratio(figures, parameters)


def check_ratio(figures: dict, parameters) -> None:
    """``ratio = [A, B]`` divides the panels of ``rows = A`` by those of ``rows = B`` (two values of the
    ``rows`` parameter, e.g. the task law over Khatib's scheme)."""
    if "ratio" not in figures:
        return
    ratio, rows = figures["ratio"], figures.get("rows")
    if rows is None:
        raise HybridError("[figures] ratio divides one value of rows by another: give rows too")
    values = parameters[rows]
    listed = values if isinstance(values, list) else []
    if not (isinstance(ratio, list) and len(ratio) == 2 and all(r in listed for r in ratio) and ratio[0] != ratio[1]):
        raise HybridError(f"[figures] ratio = {shown(ratio, 60)}: give two values of {rows} (the rows), e.g. "
                          f"{shown(listed[:2], 60)}, to show the first over the second")


def run(args) -> int:
    from hybrid.plots import sweep_heatmaps

    if bool(args.config) == bool(args.demo):
        raise HybridError("give a sweep file or --demo (one of the two)")
    if args.scheduler is not None and args.engine != "dask":
        raise HybridError("--scheduler is for --engine dask; add --engine dask, or leave --scheduler out")
    report = args.report
    path = DEMO if args.demo else Path(args.config)
    config = read_config(path)
    base = _base(config.get("experiment", "paper"), config.get("base", {}))
    check_parameter_names(base, config["parameters"])
    parameters = {k: _value(k, v) for k, v in config["parameters"].items()}
    options = config.get("sweep", {})
    unknown = sorted(set(options) - {"samples", "seed"})
    if unknown:
        raise HybridError(f"[sweep]: unknown {', '.join(unknown)}{common.did_you_mean(unknown[0], ('samples', 'seed'))}"
                          "; it takes samples and seed")
    drawn = [k for k, v in parameters.items() if not isinstance(v, list)]
    if drawn and "samples" not in options:
        raise HybridError(f"[parameters] {drawn[0]} draws random values: it needs samples = N in [sweep] (the number "
                          "of draws), or a list of values")
    check_figures(config.get("figures"), parameters, sw.metric_names(base))
    out = Path(args.out)
    report.detail(f"sweeping {path} into {out} ({args.engine} engine)")
    table = sweep(base, parameters, samples=options.get("samples"), seed=options.get("seed", 0),
                  engine=args.engine, client=args.scheduler, out=out, workers=args.workers, csv=args.csv,
                  force=args.force, progress=True, connect_timeout=args.connect_timeout)
    written = []
    if config.get("figures"):
        with report.step(f"drawing the heatmaps ({', '.join(args.format)})"):
            written = sweep_heatmaps(table, config["figures"], out, formats=tuple(args.format))
            for figure in written:
                report.detail(f"  wrote {figure}")
    counts = table["status"].value_counts().to_dict()
    print(f"{len(table)} runs ({', '.join(f'{n} {s}' for s, n in counts.items())}); wrote results.parquet"
          f"{', results.csv' if args.csv else ''} and {len(written)} figure files to {out}")
    return 0
