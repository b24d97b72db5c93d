"""The benchmarks' report: the machine it ran on, the ratios between rows of different groups, and
the table printed (name, median, target met or missed, ratio)."""

from __future__ import annotations

import os
import platform
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

from hybrid.bench.targets import ONE_STATE
from hybrid.native import compiler


def machine() -> dict:
    """What the numbers were measured on: the processor, its cores and SIMD, Python, the libraries, the C compiler."""
    out = {"python": platform.python_version(), "machine": platform.machine(), "system": platform.platform()}
    try:
        cpu = [ln for ln in Path("/proc/cpuinfo").read_text().splitlines() if ln.startswith("model name")]
        out["cpu"] = cpu[0].split(":", 1)[1].strip() if cpu else platform.processor()
    except OSError:
        out["cpu"] = platform.processor()
    out["cores"] = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    try:
        flags = next(ln for ln in Path("/proc/cpuinfo").read_text().splitlines() if ln.startswith("flags")).split()
        out["simd"] = next((f for f in ("avx512f", "avx2", "avx", "sse4_2") if f in flags), "")
    except (OSError, StopIteration):
        pass
    for pkg in ("numpy", "cffi", "sympy", "casadi", "pin"):
        try:
            out[pkg] = version(pkg)
        except PackageNotFoundError:
            pass
    out["cc"] = compiler.compiler()[1]
    return out


def relative_ratios(results: list[dict]) -> None:
    """The ratio columns that compare rows of different groups (those of rows that ran)."""
    by = {r["name"]: r for r in results}
    if ONE_STATE in by:
        ours_py = by[ONE_STATE]["median"]
        for r in results:
            if r["name"].startswith("F* in plain") or r["name"].startswith("F* by"):
                r["ratio"] = f"{r['median'] / ours_py:.0f}x slower than one compiled call"
    comp = next((r for r in results if r["name"].startswith("paper experiment") and r["name"].endswith("compiled")),
                None)
    slow = next((r for r in results if r["name"].startswith("paper experiment") and r["name"].endswith("NumPy")), None)
    if comp and slow:
        slow["ratio"] = f"{slow['median'] / comp['median']:.0f}x slower than compiled"


def _number(v: float) -> str:
    """A median as the table shows it: four significant digits, a count of 10,000 or more in full."""
    return f"{v:.0f}" if 1e4 <= abs(v) < 1e9 else f"{v:.4g}"


def format_table(report: dict) -> str:
    rows = report["results"]
    w = max((len(r["name"]) for r in rows), default=len("benchmark"))
    t = max((len(r.get("target", "")) for r in rows), default=0) + 6
    lines = [f"{'benchmark':<{w}}  {'median':>13}  {'target':<{t}}  ratio"]
    for r in rows:
        target = f"{r['target']}: {'met' if r['met'] else 'MISSED'}" if "target" in r else ""
        lines.append(f"{r['name']:<{w}}  {_number(r['median']):>9} {r['unit']:<3}  {target:<{t}}  "
                     f"{r.get('ratio', '')}")
    m = report["machine"]
    lines.append(f"\n{m.get('cpu')}, {m.get('cores')} cores, {m.get('simd') or 'no'} SIMD | Python {m['python']} | "
                 f"numpy {m.get('numpy')} | {m['cc']}")
    return "\n".join(lines)
