"""The benchmark command: it runs and reports every entry, its targets are marked by the numbers given,
``--only`` picks groups, and the helpers it measures with do what they say (timings are never asserted)."""

import json
import os
import platform
import re
import subprocess

import numpy as np
import pytest
import sympy as sp
from hybrid.codegen import casadi_backend, census, controller_step, lanes, spatial_plant
from hybrid.codegen.kernel import Arg, Kernel

from hybrid import bench
from hybrid.bench import bound, eigen_race, harness, parts, peak, pinocchio_codegen, robots, runs, standalone, targets
from hybrid.bench.groups import benchmark_groups, select_groups
from hybrid.bench.report import format_table
from hybrid.cli.main import main
from hybrid.errors import HybridError
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.native import compiler, loader
from hybrid.spec.controller_step import CONTROLLER_STEP, WRENCH


def test_bench_quick_reports_every_benchmark():
    report = bench.run_benchmarks(quick=True)
    names = " ".join(r["name"] for r in report["results"])
    for part in ("sympy backend", "casadi backend", "one state", "batched", "plain NumPy", "lambdify",
                 "CasADi Function", "compiled", "regenerate", "ur5: r, rotation, J", "panda: generate + compile",
                 "panda: the same by Pinocchio", "panda: generated C size", "ur5: controller step from Python",
                 "1,000 paper runs by hybrid.sweep", "paper: standalone controller step in C",
                 "paper: standalone controller, .text", "paper: standalone controller, compile time",
                 targets.FIRST_SIMULATE, targets.COLD_PAPER, targets.ONE_RUN, targets.LOOP_RUN, targets.TRACE_ONE,
                 targets.TRACE_RUN, targets.SWEEP_3D, targets.LOOP_OPS, f"ur5: {targets.LAW_BATCHED}",
                 targets.PATH_FOLLOW, targets.PATH_SAMPLE, targets.PATH_RUN, targets.PART_FIT, targets.PART_SAMPLE,
                 targets.PART_RUN, targets.EXCITATION_QUICK, targets.IDENTIFY,
                 f"panda: {targets.constant_row('forward_dynamics', True)}", targets.peak_row("div"),
                 targets.census_row("paper"), targets.bound_row("paper"), targets.bound_row("3-D")):
        assert part in names
    if hasattr(os, "sched_setaffinity"):
        assert f"ur5: {targets.LAW_BATCHED_ONE_CORE}" in names
    if pinocchio_codegen.missing() is None:  # every side of each function, on both arms
        for arm in ("ur5", "panda"):
            for function in pinocchio_codegen.FUNCTIONS:
                assert {f"{arm}: {targets.dynamics_row(function, side)}" for side in pinocchio_codegen.SIDES} <= set(
                    r["name"] for r in report["results"])
    if eigen_race.missing() is None:  # the law and the step, ours and every hand-written form, on both arms
        for arm, forms in (("ur5", ("pinocchio", "pinocchio_rnea")), ("panda", ("pinocchio",))):
            for function in eigen_race.FUNCTIONS:
                assert {f"{arm}: {targets.eigen_row(function, side)}" for side in ("ours", *forms)} <= set(
                    r["name"] for r in report["results"])
    assert all(r["median"] > 0 for r in report["results"])
    # the targets are reported (met or not), never asserted
    assert {r["name"] for r in report["results"] if "target" in r} >= {
        "F* in C, sympy backend, per call", "F* from Python, one state (law(q, qdot, a, Fc))",
        "panda: r, rotation, J, J'q', B, n in C, per call (robot_terms)", targets.FIRST_SIMULATE, targets.COLD_PAPER,
        targets.ONE_RUN, targets.TRACE_ONE, targets.SWEEP_3D, targets.SWEEP_10000, targets.LOOP_OPS}
    by = {r["name"]: r for r in report["results"]}
    assert by[f"ur5: {targets.LAW_BATCHED}"]["ratio"].startswith("bitwise: ")
    assert by[targets.FIRST_SIMULATE]["import_s"] > 0 and "import hybrid" in by[targets.FIRST_SIMULATE]["ratio"]
    assert "the per-run share of a lanes batch" in by[targets.ONE_RUN]["ratio"]
    assert "target" in format_table(report).splitlines()[0]


# ------------------------------------------------------------------ the targets


def _rows(**medians) -> list[dict]:
    return [{"name": name, "median": m, "unit": "ms"} for name, m in medians.items()]


def _marked(rows: list[dict]) -> dict:
    targets.mark_targets(rows)
    return {r["name"]: r for r in rows}


@pytest.mark.parametrize("name, met, missed", [
    (targets.ONE_RUN, 2.3, 2.31), (targets.SWEEP_10000, 2.8, 2.9), (targets.SWEEP_1000, 0.9, 1.1),
    (targets.TRACE_ONE, 24.0, 26.0), (targets.SWEEP_3D, 3.0, 3.1), (targets.FIRST_SIMULATE, 1.5, 1.6),
    (targets.COLD_PAPER, 7.9, 8.1), (f"ur5: {targets.LAW_BATCHED_ONE_CORE}", 120.0, 121.0),
    (targets.LOOP_OPS, targets.LOOP_OPS_REFERENCE * 2 / 3, targets.LOOP_OPS_REFERENCE * 2 / 3 + 1),
    (targets.IDENTIFY, 10.0, 10.1)])
def test_a_target_is_met_up_to_its_bound_and_missed_past_it(name, met, missed):
    for median, expected in ((met, True), (missed, False)):
        row = _marked([{"name": name, "median": median, "unit": "ms"}])[name]
        assert row["met"] is expected and row["target"].startswith("<=")
        text = format_table({"results": [row], "machine": {"python": "3", "cc": "cc"}})
        assert f"{row['target']}: {'met' if expected else 'MISSED'}" in text.splitlines()[1]


def test_targets_say_their_bounds():
    by = _marked(_rows(**{targets.ONE_RUN: 1.0, targets.SWEEP_10000: 1.0, targets.TRACE_ONE: 1.0,
                          targets.SWEEP_3D: 1.0, targets.FIRST_SIMULATE: 1.0, targets.COLD_PAPER: 1.0,
                          f"ur5: {targets.LAW_BATCHED_ONE_CORE}": 1.0, targets.LOOP_OPS: 1.0}))
    assert {n: r["target"] for n, r in by.items()} == {
        targets.ONE_RUN: "<= 2.3 ms", targets.SWEEP_10000: "<= 2.8 s", targets.TRACE_ONE: "<= 25 ms",
        targets.SWEEP_3D: "<= 3 s", targets.FIRST_SIMULATE: "<= 1.5 s", targets.COLD_PAPER: "<= 8 s",
        f"ur5: {targets.LAW_BATCHED_ONE_CORE}": "<= 120 ns",
        targets.LOOP_OPS: f"<= 2/3 of {targets.LOOP_OPS_REFERENCE:,}"}


def test_a_target_that_reads_another_row_needs_that_row():
    alone = _marked(_rows(**{targets.ONE_STATE: 300.0}))
    assert "target" not in alone[targets.ONE_STATE]  # its NumPy row did not run
    fast = _marked(_rows(**{targets.ONE_STATE: 300.0, targets.NUMPY_LAW: 300.0 * 70}))
    slow = _marked(_rows(**{targets.ONE_STATE: 300.0, targets.NUMPY_LAW: 300.0 * 69}))
    assert fast[targets.ONE_STATE]["met"] and not slow[targets.ONE_STATE]["met"]
    assert "target" not in fast[targets.NUMPY_LAW]
    comp, numpy = targets.experiment_row(2.0, "compiled"), targets.experiment_row(2.0, "NumPy")
    assert _marked(_rows(**{comp: 20.0, numpy: 2000.0}))[comp]["met"]
    assert not _marked(_rows(**{comp: 20.0, numpy: 1999.0}))[comp]["met"]
    quick = targets.experiment_row(0.2, "compiled")  # the target is for the full run
    assert "target" not in _marked(_rows(**{quick: 1.0, targets.experiment_row(0.2, "NumPy"): 1000.0}))[quick]


def test_a_target_on_a_ratio_reads_the_ratio():
    row = {"name": targets.IMPORT, "median": 100.0, "unit": "ms"}
    assert _marked([{**row, "ratio_value": 2.5}])[targets.IMPORT]["met"]
    assert not _marked([{**row, "ratio_value": 2.6}])[targets.IMPORT]["met"]
    p999 = f"ur5: {targets.STANDALONE_P999}"
    assert not _marked([{"name": p999, "median": 1.0, "unit": "ns", "of_median": 2.1}])[p999]["met"]


def test_the_targets_against_pinocchio_and_eigen_read_the_speedup():
    for arm, function, factor in (("ur5", "law", 5), ("panda", "law", 5), ("ur5", "step", 4), ("panda", "step", 4)):
        name = f"{arm}: {targets.eigen_row(function, 'ours')}"
        row = {"name": name, "median": 500.0, "unit": "ns"}
        assert _marked([{**row, "speedup": factor}])[name]["met"]
        missed = _marked([{**row, "speedup": factor - 0.01}])[name]
        assert not missed["met"] and missed["target"] == f">= {factor}x faster than Pinocchio + Eigen by hand"


def test_rows_without_a_target_have_none():
    by = _marked(_rows(**{targets.LOOP_RUN: 1.0, targets.TRACE_RUN: 1.0, "something else": 1.0}))
    assert not any("target" in r for r in by.values())


# ------------------------------------------------------------------ --only


def test_only_picks_the_groups_whose_label_contains_it():
    groups = [("F* in C (sympy backend)", None), ("paper runs: a sweep", None), ("3-D runs: a Sweep", None)]
    assert select_groups(groups, None) == groups
    assert [g[0] for g in select_groups(groups, "SWEEP")] == ["paper runs: a sweep", "3-D runs: a Sweep"]
    assert [g[0] for g in select_groups(groups, "f* in c")] == ["F* in C (sympy backend)"]
    with pytest.raises(HybridError, match="no benchmark group.*paper runs: a sweep"):
        select_groups(groups, "standalone")
    with pytest.raises(HybridError, match="--only needs"):
        select_groups(groups, " ")


def test_the_groups_are_named_apart_and_building_them_runs_nothing():
    rows = []
    groups = benchmark_groups(True, 1, lambda *a, **k: rows.append(a))
    labels = [label for label, _ in groups]
    assert len(set(labels)) == len(labels) and not rows
    for word in ("operations", "first use", "3-D runs", "standalone", "import hybrid"):
        assert len(select_groups(groups, word)) == 1


def test_bench_only_runs_the_chosen_group(capsys):
    assert main(["bench", "--quick", "--only", "GENERATED OPERATIONS"]) == 0
    out, err = capsys.readouterr()
    assert "[1/1] the 3-D closed loop's generated operations" in err
    lines = out.splitlines()
    assert lines[1].startswith(targets.LOOP_OPS) and lines[2] == ""  # one row, then the machine
    assert main(["bench", "--only", "no such group"]) == 2
    assert "no benchmark group" in capsys.readouterr().err


# ------------------------------------------------------------------ the helpers


def test_loop_operations_are_the_loop_kernels_counts():
    exp = tracing_experiment()
    got = runs.loop_operations(exp)
    chain, spec = exp.robot.chain, exp.surface.spec()
    rhs = {k.name: k for k in spatial_plant.plant_kernels(chain, spec)}["plant_rhs"]
    step = {k.name: k for k in controller_step.controller_kernels(chain, spec, tuple(range(6)))}["controller_step"]
    rhs_ops, step_ops = (casadi_backend.kernel_function(k).n_instructions() for k in (rhs, step))
    assert (got["rhs"], got["step"], got["steps_per_sample"]) == (rhs_ops, step_ops, exp.steps_per_sample)
    assert got["per_step"] == 4 * rhs_ops + step_ops / exp.steps_per_sample
    # fewer steps a sample: a larger share of the controller step in each
    fewer = runs.loop_operations(tracing_experiment(sample_time=exp.sample_time / 2))
    assert fewer["steps_per_sample"] == exp.steps_per_sample // 2 and fewer["per_step"] > got["per_step"]


def test_standalone_driver_replays_a_run_that_follows_a_path(tmp_path):
    """The step's driver with the desired point in each sample (the quick benchmark replays runs without)."""
    exp = paper_experiment(duration=0.5, frame="desired")
    samples, target = standalone.recorded_samples(exp)
    nq = exp.plant().nq
    # a sample as the driver reads it: q, qd, the wrench and the target, their sizes the declaration's
    assert target and samples.shape[1] == 2 * nq + len(WRENCH) + int(CONTROLLER_STEP.port("target").size)
    exp.build_controller().generate(tmp_path, "pe")
    got = standalone.standalone_step(tmp_path, "pe", samples, target, exp.sample_time, ["-O1"], 200)
    assert got["text"] > 0 and got["median"] <= got["p99"] <= got["max"]
    driver = (tmp_path / "pe_driver.c").read_text()
    assert f"memcpy(c.target, x + {2 * nq + len(WRENCH)}, sizeof c.target);" in driver


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity"), reason="no thread affinity on this system")
def test_on_one_core_pins_the_measurement_and_gives_the_cpus_back():
    before = os.sched_getaffinity(0)
    assert harness.on_one_core(lambda: float(len(os.sched_getaffinity(0)))) == 1.0
    assert os.sched_getaffinity(0) == before
    with pytest.raises(ZeroDivisionError):
        harness.on_one_core(lambda: 1 / 0)
    assert os.sched_getaffinity(0) == before


def test_alone_is_bitwise_compares_the_bits():
    rng = np.random.default_rng(3)
    batch = (rng.normal(size=(1000, 3)), rng.normal(size=(1000, 3)))
    assert robots.alone_is_bitwise(lambda x, y: x * y + 1.0, batch)
    # a state's numbers that depend on the others in its batch
    assert not robots.alone_is_bitwise(lambda x, y: x - x.mean(axis=0), batch)
    # -0.0 equals 0.0, but not bitwise
    assert not robots.alone_is_bitwise(lambda x, y: np.full((len(x), 1), 0.0 if len(x) > 1 else -0.0), batch)


# ------------------------------------------------------------------ the lanes against the floating-point bound

#: GCC's x86-64 vector instructions by the census's kind (AT&T mnemonics)
_ASM_KINDS = (("fma", r"vf(n?)m(add|sub)\d+pd"), ("mul", r"vmulpd"), ("add", r"v(add|sub)pd"), ("div", r"vdivpd"),
              ("sqrt", r"vsqrtpd"))
_X86_GCC = platform.machine() in ("x86_64", "AMD64") and compiler.is_gcc(compiler.compiler()[1])


def _compiled_kinds(source: str, function: str) -> dict:
    """The arithmetic vector instructions GCC emits for ``function`` of ``source`` (four lanes, AVX2), by kind."""
    asm = subprocess.run([compiler.compiler()[0], "-O3", "-fno-math-errno", "-std=gnu99", "-march=x86-64-v3",
                          f"-I{loader.source_dir()}", "-S", "-o", "-", "-x", "c", "-"],
                         input=source, capture_output=True, text=True, check=True).stdout
    body = asm[asm.index(f"\n{function}:"):]
    body = body[:body.index(".size")]
    mnemonics = [line.split()[0] for line in body.splitlines() if line.strip()]
    return {kind: sum(bool(re.fullmatch(pattern, m)) for m in mnemonics) for kind, pattern in _ASM_KINDS}


@pytest.mark.skipif(not _X86_GCC, reason="counts GCC's x86-64 instructions")
def test_the_census_of_a_kernel_is_what_the_compiler_emits():
    """Sums, products (some fused), a shared divisor, a square root: the census of the lanes function counts
    the instructions GCC compiles it to, kind by kind; uncontracted, each fused pair is a product and a sum."""
    x, k = sp.symbols("x0:6", real=True), sp.symbols("k0:2", real=True)
    ys = [x[0] * x[1] + x[2] * k[0], (x[3] - x[4]) / (x[5] + k[1]), sp.sqrt(x[0] ** 2 + x[1] ** 2 + 1) * k[0],
          x[2] * x[3] * x[4] - x[5] / k[1], (x[0] + x[1]) * (x[2] - x[3]) / (x[5] + k[1]), x[4] * x[4] - 3 * x[0]]
    kernel = Kernel("probe", (Arg("x", sp.Matrix(x)), Arg("k", sp.Matrix(k))), (Arg("y", sp.Matrix(ys)),), "probe")
    text = lanes.lanes_function(kernel, "probe_lanes", ("k",), "static")
    source = (f'#define HL_W 4\n#include "hybrid_lanes.h"\n{text}\n'
              "void probe(const hl_v *x, const hl_v *pre, hl_v *y) { probe_lanes(x, pre, y); }\n")
    fused = census.kernel_census(kernel, ("k",)).counts
    assert {k: fused[k] for k, _ in _ASM_KINDS} == _compiled_kinds(source, "probe")
    assert fused["fma"] > 0 and fused["div"] == 1 and fused["sqrt"] == 1  # one division: the divisor is shared
    apart = census.kernel_census(kernel, ("k",), contract=False).counts
    assert apart["fma"] == 0 and apart["mul"] == fused["mul"] + fused["fma"]
    assert apart["add"] == fused["add"] + fused["fma"]


@pytest.mark.skipif(not _X86_GCC, reason="counts GCC's x86-64 instructions")
@pytest.mark.parametrize("poly, call", [
    ("sincos_near", "void p(hl_v x, const hl_v *b, hl_v *s, hl_v *c, hl_i *o) { *o = hl_rotate(x, b, s, c); }"),
    ("sincos", "void p(hl_v x, hl_v *s, hl_v *c, hl_i *o) { hl_sincos_poly(x, s, c, o); }"),
    ("exp", "hl_v p(hl_v x, hl_i *o) { return hl_exp_poly(x, o); }")])
def test_the_census_of_a_polynomial_is_what_the_compiler_emits(poly, call):
    got = _compiled_kinds(f'#define HL_W 4\n#include "hybrid_lanes.h"\n{call}\n', "p")
    assert got == {k: census.POLYNOMIALS[poly].get(k, 0) for k, _ in _ASM_KINDS}


def test_the_peak_program_gives_positive_finite_times_for_every_kind():
    got = peak.machine_peak(operations=2000, repeat=3)
    assert got["lanes"] in (1, 2, 4, 8, 16) and 0 < got["cycle"] < 10
    assert set(got["kinds"]) == set(peak.KINDS) | {f"{a}_{b}" for a, b in peak.PAIRS}
    assert all(np.isfinite(t) and t > 0 for times in got["kinds"].values() for t in times)
    assert all(0 <= peak.shared(got, a, b) <= 1 for a, b in peak.PAIRS)


def _peak(fma_add_pair: float) -> dict:
    """A machine of four lanes whose every kind takes 1 ns (a division 8, a square root 16), latency 4 ns; adds
    and fused multiply-adds take ``fma_add_pair`` ns an operation together; a division and a square root share."""
    kinds = {k: (1.0, 4.0) for k in peak.KINDS} | {"div": (8.0, 12.0), "sqrt": (16.0, 20.0)}
    return {"lanes": 4, "cycle": 0.25, "kinds": kinds | {"fma_add": (fma_add_pair, 4.0), "fma_div": (4.0, 4.0),
                                                         "div_sqrt": (12.0, 12.0)}}


def test_the_bound_adds_each_kind_at_its_peak_and_the_unit_bound_takes_the_busiest():
    counts = {"fma": 100, "mul": 50, "add": 120, "div": 10, "sqrt": 2, "compare": 20, "select": 10, "bitwise": 8}
    # per lane: 1/4 ns an operation, a comparison or select half of that, a division 2 ns, a square root 4 ns
    per_step = (100 + 50 + 120 + 8) / 4 + (20 + 10) / 8 + 10 * 2 + 2 * 4
    apart = bound.bounds(counts, 400.0, 1000, _peak(0.5))  # adds beside the fused multiply-adds
    assert apart["sum"] == pytest.approx(1000 * per_step / 1e6)
    assert sum(apart["shares"].values()) == pytest.approx(1.0)
    # the units: fma + mul (150 / 4 ns), add (30 ns), the divider (10 x 2 + 2 x 4 = 28 ns)
    assert apart["busiest"] == ("fma", "mul") and apart["unit"] == pytest.approx(1000 * 150 / 4 / 1e6)
    assert apart["chain"] == pytest.approx(1000 * 400.0 / 4 / 1e6)  # a group's chain over its four lanes
    together = bound.bounds(counts, 400.0, 1000, _peak(1.0))  # adds on the same unit
    assert together["busiest"] == ("fma", "mul", "add") and together["unit"] == pytest.approx(1000 * 270 / 4 / 1e6)
    assert ("div", "sqrt") in bound.units_of(_peak(1.0))


def test_bench_only_reports_the_lanes_against_their_bound(capsys):
    assert main(["bench", "--quick", "--only", "floating-point bound"]) == 0
    out = capsys.readouterr().out
    rows = [line for line in out.splitlines()[1:] if line.strip()][:-1]  # the rows, not the machine
    names = [targets.peak_row(k) for k in peak.KINDS]
    names += [f(loop) for loop in bound.LOOPS for f in (targets.census_row, targets.bound_row)]
    assert [r[:len(n)] for r, n in zip(rows, names)] == names
    for row, name in zip(rows, names):
        value = float(row[len(name):].split()[0].replace(",", ""))
        assert np.isfinite(value) and value > 0


def test_bench_only_reports_the_frame_on_a_part_and_counts_its_instructions(tmp_path):
    """The parts group alone gives its four rows; the frame on a part, where valgrind is installed, with
    callgrind's instructions a call: more than the sphere's (the part's expansion precedes its frame), its
    frame's fewer than its whole; a program whose loop calls a function of 100 additions counts 100 more a call
    than one of none."""
    out = tmp_path / "parts.json"
    assert main(["bench", "--quick", "--only", "parts:", "--json", str(out)]) == 0
    rows = {r["name"]: r for r in json.loads(out.read_text())["results"]}
    assert set(rows) == {targets.PART_FIT, targets.PART_FRAME, targets.PART_SAMPLE, targets.PART_RUN}
    frame = rows[targets.PART_FRAME]
    assert frame["median"] > 0 and frame["of_formula"] > 0 and "rounds taking turns" in frame["ratio"]
    if not pinocchio_codegen.can_count():
        pytest.skip("valgrind's callgrind is not installed")
    assert frame["sphere_instructions"] < frame["instructions"] and 0 < frame["frame_instructions"] < frame[
        "instructions"]
    unit = tmp_path / "unit.c"
    counts = {}
    for adds in (0, 100):
        unit.write_text("double f(double x) {\n" + "    x = x + 1e-3;\n" * adds + "    return x;\n}\n")
        source = ("#include <stdlib.h>\n#include <stdio.h>\ndouble f(double);\nint main(int argc, char **argv) {\n"
                  "    long i, n = atol(argv[1]);\n    double s = 0.0;\n    for (i = 0; i < n; ++i) s = f(s);\n"
                  '    printf("%g\\n", s);\n    return 0;\n}\n')
        counts[adds] = parts.instructions(source, unit, (), (), ("main", "f"), calls=1000)
    assert counts[100]["f"] - counts[0]["f"] == pytest.approx(100, abs=1)
    # main's printf, once over the calls, prints another number
    assert counts[100]["main"] - counts[0]["main"] == pytest.approx(100, abs=5)
