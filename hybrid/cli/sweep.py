"""``python -m hybrid sweep CONFIG.toml --out DIR``: a sweep from a file, with progress, incremental
results (Parquet, CSV on request), resuming, and heatmaps."""

from __future__ import annotations

import math
from dataclasses import fields
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid import sweeps as sw
from hybrid.control.loops import Gains
from hybrid.control.references import Step
from hybrid.errors import HybridError
from hybrid.experiments import FACTORIES
from hybrid.plants.contact import Contact, Sensor
from hybrid.sweeps import sweep
from hybrid.validate import MAX_NESTING, check_nesting, shown

DEMO = Path(__file__).resolve().parent.parent / "data" / "sweep_demo.toml"
SECTIONS = {"experiment", "base", "parameters", "sweep", "figures"}


def add_parser(sub) -> None:
    p = sub.add_parser("sweep", help="run a parameter sweep from a TOML file: metrics table, figures, resumable")
    p.add_argument("config", nargs="?", help="the sweep's TOML file (see hybrid/data/sweep_demo.toml)")
    p.add_argument("--demo", action="store_true", help="run the shipped demo study (model error, friction, speed)")
    p.add_argument("--out", required=True, help="folder for results.parquet, parts (resume) and figures")
    p.add_argument("--csv", action="store_true", help="also write results.csv")
    p.add_argument("--engine", default="local", choices=("local", "dask"))
    p.add_argument("--scheduler", help="a Dask scheduler's address, e.g. tcp://127.0.0.1:8786 (default: a local "
                   "cluster)")
    p.add_argument("--connect-timeout", type=float, default=sw.CONNECT_TIMEOUT, metavar="SECONDS",
                   help=f"how long to wait for the Dask scheduler (default {sw.CONNECT_TIMEOUT:g} s)")
    p.add_argument("--workers", type=int, help="processes (default: every core)")
    p.add_argument("--force", action="store_true", help="start afresh in a folder that holds another sweep")
    p.set_defaults(func=run)


def _value(name: str, value):
    """A TOML value as a setting: a list, ``{linspace = [first, last, count]}`` (evenly spaced values,
    both ends included), or a table with one distribution name (drawn values)."""

    if isinstance(value, dict) and list(value) == ["linspace"]:
        return _linspace(name, value["linspace"])
    if isinstance(value, dict):
        if len(value) != 1 or next(iter(value)) not in sw.DISTRIBUTIONS:
            raise HybridError(f"parameter {name!r}: a table must name one distribution "
                              f"({', '.join(sw.DISTRIBUTIONS)}), e.g. {{uniform = [0.0, 0.3]}}, or evenly "
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


def _base(kind: str, settings: dict):
    """The base experiment from the ``[base]`` table (``paper_experiment``'s keywords; a table for a
    reference becomes a Step, for ``sensor``/``contact``/``gains`` their dataclass)."""

    parts = {"sensor": Sensor, "contact": Contact, "gains": Gains}
    steps = ("force_reference", "speed_reference", "F_d", "v_d")
    made = {}
    for key, value in settings.items():
        if isinstance(value, dict):
            typ = Step if key in steps else parts.get(key)
            if typ is None:
                raise HybridError(f"[base] {key} = a table: only {', '.join(steps + tuple(parts))} take one")
            known = {f.name for f in fields(typ)}
            if not set(value) <= known:
                raise HybridError(f"[base] {key}: unknown {', '.join(sorted(set(value) - known))}; "
                                  f"{typ.__name__} has {', '.join(sorted(known))}")
            value = typ(**value)
        made[key] = value
    if not isinstance(kind, str) or kind not in FACTORIES:
        raise HybridError(f"experiment = {shown(kind, 60)}; give one of {', '.join(repr(k) for k in FACTORIES)}")
    return FACTORIES[kind](**made)


def read_config(path: Path) -> dict:
    """The sweep's settings from its TOML file, checked."""
    try:
        config = tomllib.loads(path.read_text())
    except OSError as exc:
        raise HybridError(f"cannot read the sweep file {path}: {exc.strerror}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise HybridError(f"{path} is not valid TOML: {exc}") from None
    except RecursionError:  # the TOML reader recurses into inline tables and arrays
        raise HybridError(f"{path}: tables or lists are nested too deeply to read; write them at most "
                          f"{MAX_NESTING} deep") from None
    check_nesting(str(path), config)
    unknown = set(config) - SECTIONS
    if unknown:
        raise HybridError(f"{path}: unknown key(s) {', '.join(sorted(unknown))}; a sweep file has "
                          f"{', '.join(sorted(SECTIONS))}")
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
    known = {"x", "y", "rows", "cols", "metrics"}
    if set(figures) - known:
        raise HybridError(f"[figures]: unknown {', '.join(sorted(set(figures) - known))}; it takes "
                          f"{', '.join(sorted(known))}")
    for key in ("x", "y", "rows", "cols"):
        if key in figures and (not isinstance(figures[key], str) or figures[key] not in parameters):
            raise HybridError(f"[figures] {key} = {shown(figures[key], 60)} is not a swept parameter "
                              f"({', '.join(parameters)})")
    if "x" not in figures or "y" not in figures:
        raise HybridError("[figures] needs x and y (two swept parameters)")
    wanted = figures.get("metrics", [])
    if not isinstance(wanted, list) or not all(isinstance(w, str) for w in wanted) or not set(wanted) <= set(metrics):
        unknown = [w for w in wanted if w not in metrics] if isinstance(wanted, list) else wanted
        raise HybridError(f"[figures] metrics = {unknown!r:.60}: give a list of the runs' metric names (below)\n"
                          f"  known: {', '.join(metrics)}")


def run(args) -> int:
    from hybrid.plots import sweep_heatmaps

    if bool(args.config) == bool(args.demo):
        raise HybridError("give a sweep file or --demo (one of the two)")
    if args.scheduler is not None and args.engine != "dask":
        raise HybridError("--scheduler is for --engine dask; add --engine dask, or leave --scheduler out")
    path = DEMO if args.demo else Path(args.config)
    config = read_config(path)
    base = _base(config.get("experiment", "paper"), config.get("base", {}))
    parameters = {k: _value(k, v) for k, v in config["parameters"].items()}
    options = config.get("sweep", {})
    unknown = set(options) - {"samples", "seed"}
    if unknown:
        raise HybridError(f"[sweep]: unknown {', '.join(sorted(unknown))}; it takes samples and seed")
    check_figures(config.get("figures"), parameters, sw.metric_names(base))
    out = Path(args.out)
    table = sweep(base, parameters, samples=options.get("samples"), seed=options.get("seed", 0),
                  engine=args.engine, client=args.scheduler, out=out, workers=args.workers, csv=args.csv,
                  force=args.force, progress=True, connect_timeout=args.connect_timeout)
    written = sweep_heatmaps(table, config.get("figures"), out)
    counts = table["status"].value_counts().to_dict()
    print(f"{len(table)} runs ({', '.join(f'{n} {s}' for s, n in counts.items())}); wrote results.parquet"
          f"{', results.csv' if args.csv else ''} and {len(written)} figures to {out}")
    return 0
