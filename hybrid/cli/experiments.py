"""``python -m hybrid paper`` and ``python -m hybrid trace``: the schemes compared, end to end."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

from hybrid import files
from hybrid.errors import HybridError
from hybrid.experiments.experiment import BACKENDS
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.simulation.runner import simulate

#: the schemes each command compares, in the order of the table
SCHEMES = ("task", "khatib", "raibert_craig")
PRODUCTS = ("metrics.json", "metrics.csv", *(f"{c}.{ext}" for c in SCHEMES for ext in ("npz", "csv")))


def add_parser(sub) -> None:
    p = sub.add_parser("paper", help="run the schemes on the paper's experiment; write figures and metrics")
    t = sub.add_parser("trace", help="run the schemes on the 3-D experiment (UR5 on a sphere, conventions §10); "
                                     "write figures and metrics")
    for q in (p, t):
        q.add_argument("--out", required=True, help="folder for figures, metrics and time series")
        q.add_argument("--force", action="store_true", help="overwrite earlier results in --out")
        q.add_argument("--no-integral", dest="integral", action="store_false", help="drop the integral terms")
        q.add_argument("--curvature", action="store_true", help="give every scheme the curvature term R'")
    p.add_argument("--backend", default="sympy", choices=BACKENDS,
                   help="which committed unit (two derivations of the same equations) runs the plant and the law")
    p.set_defaults(func=run_paper)
    t.set_defaults(func=run_trace)


def prepare_out(out: Path, force: bool) -> None:
    """Create ``out`` and check it is writable before the work; refuse to overwrite a file or
    earlier results unless ``force``."""
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is an existing file; give a folder (nothing was written)")
    clash = [n for n in PRODUCTS if (out / n).exists()] + sorted(p.name for p in out.glob("*.png"))
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


def write_comparison(results: dict, out: Path, figures) -> None:
    """Time series, metrics (JSON and CSV) and ``figures(results, out)``; every file atomic, so an
    interrupted run leaves whole files or none."""
    for scheme, res in results.items():
        res.save(out / f"{scheme}.npz", overwrite=True)
        res.save_csv(out / f"{scheme}.csv", overwrite=True)
    metrics = {c: r.metrics for c, r in results.items()}
    files.write_text(out / "metrics.json", json.dumps(metrics, indent=2) + "\n", overwrite=True)
    table = io.StringIO()
    w = csv.writer(table)
    w.writerow(["metric", *metrics])
    for name in next(iter(metrics.values())):
        w.writerow([name, *(metrics[c][name] for c in metrics)])
    files.write_text(out / "metrics.csv", table.getvalue(), overwrite=True)
    written = figures(results, out)
    print(format_table(metrics))
    print(f"\nwrote {len(written)} figures, metrics.json/csv and time series (.npz, .csv) to {out}")


def run_paper(args) -> int:
    from hybrid.plots import paper_figures

    out = Path(args.out)
    prepare_out(out, args.force)
    results = {c: simulate(paper_experiment(controller=c, integral=args.integral, curvature=args.curvature,
                                            backend=args.backend)) for c in SCHEMES}
    write_comparison(results, out, paper_figures)
    return 0


def run_trace(args) -> int:
    from hybrid.plots import trace_figures

    out = Path(args.out)
    prepare_out(out, args.force)
    results = {c: simulate(tracing_experiment(controller=c, integral=args.integral, curvature=args.curvature))
               for c in SCHEMES}
    write_comparison(results, out, trace_figures)
    return 0
