"""Smoke test: the benchmark command runs and reports every entry (timings are never asserted)."""

from hybrid import bench


def test_bench_quick_reports_every_benchmark():
    report = bench.run_benchmarks(quick=True)
    names = " ".join(r["name"] for r in report["results"])
    for part in ("sympy backend", "casadi backend", "one state", "batched", "plain NumPy", "lambdify",
                 "CasADi Function", "compiled", "regenerate", "ur5: r, rotation, J", "panda: generate + compile",
                 "panda: the same by Pinocchio", "panda: generated C size", "ur5: controller step from Python",
                 "1,000 paper runs by hybrid.sweep", "paper: standalone controller step in C",
                 "paper: standalone controller, .text", "paper: standalone controller, compile time"):
        assert part in names
    assert all(r["median"] > 0 for r in report["results"])
    # the targets are reported (met or not), never asserted
    assert {r["name"] for r in report["results"] if "target" in r} >= {
        "F* in C, sympy backend, per call", "F* from Python, one state (law(q, qdot, a, Fc))",
        "panda: r, rotation, J, J'q', B, n in C, per call (robot_terms)"}
    assert "target" in bench.format_table(report).splitlines()[0]
