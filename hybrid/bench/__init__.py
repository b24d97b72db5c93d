"""``python -m hybrid bench``: how fast the generated law and the runner are, against alternatives.

Medians over repeated runs; ratios are computed within the same run. Timings are
information, never pass/fail. The parts, one module each: :mod:`~hybrid.bench.harness` (how a
measurement is made), the groups (:mod:`~hybrid.bench.groups` and a module for each kind),
:mod:`~hybrid.bench.targets` (the rows' names and their targets, as data) and
:mod:`~hybrid.bench.report` (the machine, the ratios, the table). Not imported by ``import hybrid``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from hybrid import files
from hybrid.bench.groups import benchmark_groups, select_groups
from hybrid.bench.report import format_table, machine, relative_ratios
from hybrid.bench.targets import mark_targets
from hybrid.cli import common
from hybrid.errors import HybridError


def run_benchmarks(quick: bool = False, only: str | None = None) -> dict:
    """Every benchmark, or with ``only`` those of the groups whose progress label contains it (any
    case); returns ``{"machine": ..., "results": [{name, median, unit, ...}]}``."""
    rep = 3 if quick else 7
    results = []

    def add(name, ns, unit="ns", **extra):
        results.append({"name": name, "median": ns, "unit": unit, **extra})

    chosen = select_groups(benchmark_groups(quick, rep, add), only)
    for k, (label, run) in enumerate(chosen, 1):
        _progress(k, len(chosen), label)
        run()
    relative_ratios(results)
    mark_targets(results)
    return {"machine": machine(), "quick": quick, "results": results}


def _progress(i: int, total: int, what: str) -> None:
    print(f"[{i}/{total}] {what} ...", file=sys.stderr, flush=True)


DESCRIPTION = ("Time the generated law, the runner and alternatives. Medians over repeated runs, with "
               "ratios computed within the same run and each target said met or missed; timings are information, "
               "never pass/fail. Takes minutes (--quick: fewer repeats and a shorter experiment).")


def add_parser(sub) -> None:
    p = common.command(sub, "bench", DESCRIPTION, _run)
    p.add_argument("--quick", action="store_true", help="fewer repeats, a shorter experiment")
    p.add_argument("--only", metavar="SUBSTRING",
                   help="run only the benchmark groups whose progress label contains SUBSTRING (any case)")
    p.add_argument("--json", metavar="FILE", help="also write the results as JSON to this file")
    p.add_argument("--force", action="store_true", help="let --json replace an existing file")
    common.add_verbose(p)


def _run(args) -> int:
    if args.json is not None and not args.json.strip():
        raise HybridError("--json needs a file name")
    if args.json and Path(args.json).is_dir():
        raise HybridError(f"--json {args.json} is a folder; give a file name")
    if args.json and Path(args.json).exists() and not args.force:
        raise HybridError(f"--json {args.json} exists; choose another name or add --force to replace it")
    report = run_benchmarks(args.quick, args.only)
    print(format_table(report))
    if args.json:
        files.write_text(Path(args.json), json.dumps(report, indent=2) + "\n", overwrite=True)
    return 0
