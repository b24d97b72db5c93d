"""``python -m hybrid paper``: the paper's comparison, end to end."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

from . import files
from .errors import HybridError
from .experiment import paper_experiment
from .simulation import simulate

PRODUCTS = ("metrics.json", "metrics.csv", "task.npz", "khatib.npz", "task.csv", "khatib.csv",
            "overlay_speed_force.png")


def add_parser(sub) -> None:
    p = sub.add_parser("paper", help="run both controllers on the paper's experiment; write figures and metrics")
    p.add_argument("--out", required=True, help="folder for figures, metrics and time series")
    p.add_argument("--force", action="store_true", help="overwrite earlier results in --out")
    p.add_argument("--no-integral", dest="integral", action="store_false", help="drop the integral terms")
    p.add_argument("--curvature", action="store_true", help="give both controllers the curvature term R'")
    p.add_argument("--backend", default="sympy", choices=("sympy", "casadi", "numpy"))
    p.set_defaults(func=run)


def prepare_out(out: Path, force: bool) -> None:
    """Create ``out`` and check it is writable before the work; refuse to overwrite a file or
    earlier results unless ``force``."""
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is an existing file; give a folder (nothing was written)")
    clash = [n for n in PRODUCTS if (out / n).exists()] + sorted(p.name for p in out.glob("figure*.png"))
    if clash and not force:
        raise HybridError(f"--out {out} already holds results ({', '.join(clash[:3])}...); "
                          "choose another folder or pass --force to overwrite them")
    files.writable_folder(out, "--out folder")


def format_table(metrics: dict[str, dict]) -> str:
    names = list(next(iter(metrics.values())))
    cols = list(metrics)
    w = max(len(n) for n in names)
    lines = [f"{'metric':<{w}}  " + "  ".join(f"{c:>12}" for c in cols)]
    lines += [f"{n:<{w}}  " + "  ".join(f"{metrics[c][n]:>12.4g}" for c in cols) for n in names]
    return "\n".join(lines)


def run(args) -> int:
    from .plots import paper_figures

    out = Path(args.out)
    prepare_out(out, args.force)
    results = {}
    for ctrl in ("khatib", "task"):
        exp = paper_experiment(controller=ctrl, integral=args.integral, curvature=args.curvature,
                               backend=args.backend)
        results[ctrl] = simulate(exp)
    # every product is written atomically: an interrupted run leaves whole files or none
    for ctrl, res in results.items():
        res.save(out / f"{ctrl}.npz", overwrite=True)
        res.save_csv(out / f"{ctrl}.csv", overwrite=True)
    metrics = {c: r.metrics for c, r in results.items()}
    files.write_text(out / "metrics.json", json.dumps(metrics, indent=2) + "\n", overwrite=True)
    table = io.StringIO()
    w = csv.writer(table)
    w.writerow(["metric", *metrics])
    for name in metrics["task"]:
        w.writerow([name, *(metrics[c][name] for c in metrics)])
    files.write_text(out / "metrics.csv", table.getvalue(), overwrite=True)
    figures = paper_figures(results, out)
    print(format_table(metrics))
    print(f"\nwrote {len(figures)} figures, metrics.json/csv and time series (.npz, .csv) to {out}")
    return 0
