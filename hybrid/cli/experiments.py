"""``python -m hybrid paper`` and ``python -m hybrid trace``: the schemes compared, end to end; and
``python -m hybrid generate --experiment NAME``: an experiment's closed loop as standalone C."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from hybrid import files
from hybrid.cli import common
from hybrid.cli.sweep import _base as factory_experiment
from hybrid.cli.sweep import setting_names
from hybrid.errors import HybridError
from hybrid.experiments import FACTORIES
from hybrid.experiments.experiment import BACKENDS
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.simulation import closed_loop
from hybrid.simulation.runner import simulate
from hybrid.sweeps import apply
from hybrid.validate import shown

#: the schemes each command compares, in the order of the table
SCHEMES = ("task", "khatib", "raibert_craig")
PRODUCTS = ("metrics.json", "metrics.csv", *(f"{c}.{ext}" for c in SCHEMES for ext in ("npz", "csv")))


PAPER = ("Compare the schemes on the paper's experiment. Runs the task law, Khatib's scheme and Raibert & Craig's "
         "on the paper's planar arm pressing on a disc and sliding along it (docs/conventions.md section 5) and "
         "writes into --out Figures 5-8 of the paper and an overlay of the three schemes, the metrics (printed as "
         "a table, metrics.json, metrics.csv) and each run's time series (SCHEME.npz, SCHEME.csv).")
TRACE = ("Compare the schemes on the 3-D experiment (UR5, sphere). Runs the task law, Khatib's scheme and "
         "Raibert & Craig's on the UR5 tracing a latitude circle on a sphere (docs/conventions.md section 10) "
         "and writes into --out their speed and force, their paths (in space, and as the deviation from the "
         "desired path, with the penetration), the metrics and each run's time series.")


def add_parser(sub) -> None:
    p = common.command(sub, "paper", PAPER, run_paper)
    t = common.command(sub, "trace", TRACE, run_trace)
    for q in (p, t):
        q.add_argument("--out", required=True, metavar="DIR", help="folder for figures, metrics and time series")
        q.add_argument("--force", action="store_true", help="overwrite earlier results in --out")
        q.add_argument("--no-integral", dest="integral", action="store_false",
                       help="drop the integral terms (KI2v = KIf = 0)")
        q.add_argument("--curvature", action="store_true", help="give every scheme the curvature term R'")
        q.add_argument("--no-series", dest="series", action="store_false",
                       help="write metrics and figures only, no time series (.npz, .csv)")
        common.add_format(q)
        common.add_verbose(q)
    p.add_argument("--backend", default="sympy", choices=BACKENDS,
                   help="which committed unit (two derivations of the same equations) runs the plant and the law "
                        "(default: sympy)")


def prepare_out(out: Path, force: bool) -> None:
    """Create ``out`` and check it is writable before the work; refuse to overwrite a file or
    earlier results unless ``force``."""
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is an existing file; give a folder (nothing was written)")
    figures = sorted(p.name for ext in common.FORMATS for p in out.glob(f"*.{ext}"))
    clash = [n for n in PRODUCTS if (out / n).exists()] + figures
    if clash and not force:
        raise HybridError(f"--out {out} already holds results ({', '.join(clash[:3])}...); "
                          "choose another folder or pass --force to overwrite them")
    files.writable_folder(out, "--out folder")


def format_table(metrics: dict[str, dict]) -> str:
    names = list(next(iter(metrics.values())))
    cols = list(metrics)
    w = max(len(n) for n in names)
    width = max(12, *(len(c) for c in cols))
    lines = [f"{'metric':<{w}}  " + "  ".join(f"{c:>{width}}" for c in cols)]
    lines += [f"{n:<{w}}  " + "  ".join(f"{metrics[c][n]:>{width}.4g}" for c in cols) for n in names]
    return "\n".join(lines)


def run_schemes(what: str, make, report) -> dict:
    """``{scheme: simulate(make(scheme))}`` for every scheme of :data:`SCHEMES`, told as one step."""
    results = {}
    with report.step(f"running {what}: {', '.join(SCHEMES)}"):
        experiments = {scheme: make(scheme) for scheme in SCHEMES}
        closed_loop.build_side_by_side(list(experiments.values()))
        for scheme, exp in experiments.items():
            results[scheme] = simulate(exp)
            report.detail(f"  {scheme}: {len(results[scheme].t):,} integration steps")
    return results


def write_comparison(results: dict, out: Path, figures, args) -> None:
    """Time series (unless ``--no-series``), metrics (JSON and CSV) and ``figures(results, out,
    formats)``; every file atomic, so an interrupted run leaves whole files or none."""
    report = args.report
    if args.series:
        with report.step("writing the time series (.npz, .csv)"):
            for scheme, res in results.items():
                for path in (res.save(out / f"{scheme}.npz", overwrite=True),
                             res.save_csv(out / f"{scheme}.csv", overwrite=True)):
                    report.detail(f"  wrote {path} ({path.stat().st_size / 2**20:.1f} MiB)")
    metrics = {c: r.metrics for c, r in results.items()}
    files.write_text(out / "metrics.json", json.dumps(metrics, indent=2) + "\n", overwrite=True)
    table = io.StringIO()
    w = csv.writer(table)
    w.writerow(["metric", *metrics])
    for name in next(iter(metrics.values())):
        w.writerow([name, *(metrics[c][name] for c in metrics)])
    files.write_text(out / "metrics.csv", table.getvalue(), overwrite=True)
    with report.step(f"drawing the figures ({', '.join(args.format)})"):
        written = figures(results, out, formats=tuple(args.format))
        for path in written:
            report.detail(f"  wrote {path}")
    print(format_table(metrics))
    series = " and time series (.npz, .csv)" if args.series else ""
    print(f"\nwrote {len(written)} figure files, metrics.json/csv{series} to {out}")


def run_paper(args) -> int:
    from hybrid.plots import paper_figures

    out = Path(args.out)
    prepare_out(out, args.force)
    results = run_schemes("the paper's experiment", lambda c: paper_experiment(
        controller=c, integral=args.integral, curvature=args.curvature, backend=args.backend), args.report)
    write_comparison(results, out, paper_figures, args)
    return 0


def run_trace(args) -> int:
    from hybrid.plots import trace_figures

    out = Path(args.out)
    prepare_out(out, args.force)
    results = run_schemes("the 3-D experiment", lambda c: tracing_experiment(
        controller=c, integral=args.integral, curvature=args.curvature), args.report)
    write_comparison(results, out, trace_figures, args)
    return 0


# ------------------------------------------------------------- generate --experiment


def add_generate_arguments(g) -> None:
    """``--experiment`` and ``--set`` of ``python -m hybrid generate``."""
    g.add_argument("--experiment", choices=tuple(FACTORIES),
                   help="write this experiment's controller and plant (NAME_controller.c/.h/.json, "
                        "NAME_plant.c/.h/.json) instead of a URDF arm's kernels")
    add_setting_argument(g, "with --experiment: ")


def add_setting_argument(p, when: str = "") -> None:
    """``--set KEY=VALUE``: an experiment's setting overridden (:func:`experiment_of`)."""
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", dest="settings",
                   help=f"{when}override a setting, as a sweep file's [base] or parameters name it "
                        "(duration=3.0, controller=khatib, KPf=3, F_d=15, contact.friction=0.1, "
                        "force_reference.after=25); VALUE is a TOML value, or else text; repeatable")


def setting(text: str) -> tuple[str, object]:
    """``KEY=VALUE`` as a name and a value: VALUE read as a TOML value (a number, true/false, a quoted
    string, a list, an inline table), or else as text (``controller=khatib``)."""
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key or not value.strip():
        raise HybridError(f"--set {shown(text, 60)}: give KEY=VALUE, e.g. --set duration=3.0")
    try:
        return key, tomllib.loads(f"v = {value}")["v"]
    except tomllib.TOMLDecodeError:
        return key, value.strip()


def experiment_of(kind: str, settings: list[str]):
    """The experiment ``kind`` with the ``--set`` overrides: plain names go to its factory (as a sweep
    file's ``[base]`` table), dotted paths (``contact.friction``) then set that one field."""
    pairs = [setting(text) for text in settings]
    names = [k for k, _ in pairs]
    twice = sorted({k for k in names if names.count(k) > 1})
    if twice:
        raise HybridError(f"--set {twice[0]} is given twice; give each setting once")
    exp = factory_experiment(kind, {k: v for k, v in pairs if "." not in k}, where="--set")
    dotted = {k: v for k, v in pairs if "." in k}
    if not dotted:
        return exp
    names = setting_names(exp)
    wrong = [k for k in dotted if k not in names]
    if wrong:
        raise HybridError(f"--set {wrong[0]}: unknown setting of the {kind} experiment"
                          f"{common.did_you_mean(wrong[0], names)}; give a dotted path into one of its settings "
                          "(contact.friction, gains.KPf, force_reference.after)")
    return apply(exp, dotted)


def run_generate(args) -> int:
    """``python -m hybrid generate --experiment NAME [--set KEY=VALUE ...] --out DIR [--name PREFIX]``."""
    given = [flag for flag, value in (("--urdf", args.urdf), ("--tip", args.tip), ("--lock", args.lock)) if value]
    if given:
        raise HybridError(f"--experiment writes an experiment's controller and plant; {', '.join(given)} name a URDF "
                          "arm's kernels: give one or the other")
    exp = experiment_of(args.experiment, args.settings)
    with args.report.step(f"generating the {args.experiment} experiment's controller and plant as C"):
        written = exp.generate(args.out, args.name, force=args.force)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
