"""Every number that crosses the C boundary is the declaration's (``hybrid/spec/``).

The compiled units' manifests are compared with the declarations argument by argument; a declaration
perturbed (two ports swapped, a size changed) makes the binding refuse the unit; the statuses' numbers in
the generated C are the declared ones, and Python names each as C does; the metrics come in the declared
order from NumPy, from the compiled loop and in the manifests.
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from test_standalone_controller import CController

import hybrid
from hybrid.control import controller as controller_module
from hybrid.control import controller_binding
from hybrid.errors import HybridError, NonFiniteError, SingularConfigurationError, TaskFrameError
from hybrid.native import units
from hybrid.native.binding import status_error
from hybrid.spec.controller_step import CONTROLLER_STEP, SAFE_STOP, STATE_NEXT
from hybrid.spec.interfaces import (
    KERNEL_STATUSES,
    PARAMETER,
    REFERENCE,
    STATE,
    STATUS_CODES,
    STATUSES,
    Dims,
    PerAxis,
    PerJoint,
    Port,
)
from hybrid.spec.metrics import METRIC_NAMES, metric_names

ROOT = __import__("pathlib").Path(__file__).resolve().parent.parent


def _sphere_controller(**kw) -> hybrid.Controller:
    return hybrid.Controller(hybrid.ur5(), hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15), "task", **kw)


def _dims(ctrl: hybrid.Controller) -> Dims:
    entry = ctrl._step.entry
    names = {a["name"]: tuple(a.get("names", ())) for a in entry["inputs"]}
    return Dims(ctrl.robot.joint_names, ctrl.axis_names, names["robot"], names["surface"])


@pytest.mark.parametrize("make", [
    lambda: hybrid.paper_experiment(controller="task").build_controller(),
    lambda: _sphere_controller(),
    lambda: hybrid.panda_experiment().build_controller(),  # the posture step
], ids=["paper", "ur5", "panda-posture"])
def test_compiled_steps_are_their_declaration(make):
    """Names, order, sizes and element names of every argument, and the units the declaration states
    where the kernel has no finer ones."""
    ctrl = make()
    ctrl._native()
    dims = _dims(ctrl)
    entry = ctrl._step.entry
    for ports, got in ((CONTROLLER_STEP.inputs, entry["inputs"]), (CONTROLLER_STEP.outputs, entry["outputs"])):
        assert [a["name"] for a in got] == [p.name for p in ports]
        for p, a in zip(ports, got):
            assert a["size"] == p.size_of(dims), p.name
            assert tuple(a.get("names", ())) == (p.element_names(dims) or ()), p.name
            if isinstance(a["unit"], str):
                assert a["unit"] == p.unit, p.name
    assert tuple(entry["batched"]["per_state"]) == CONTROLLER_STEP.per_sample
    # the controller's parameters are packed by name, in the declared order and sizes
    for (name, value), p in zip(ctrl.step_inputs().items(), [p for p in CONTROLLER_STEP.inputs
                                                               if p.role == PARAMETER]):
        assert name == p.name and value.size == p.size_of(dims)


def _perturbed(**changes):
    """CONTROLLER_STEP with its inputs changed: ``swap=(a, b)`` trades two ports' places; ``resize=(name, size)``."""
    inputs = list(CONTROLLER_STEP.inputs)
    if "swap" in changes:
        a, b = (next(i for i, p in enumerate(inputs) if p.name == n) for n in changes["swap"])
        inputs[a], inputs[b] = inputs[b], inputs[a]
    if "resize" in changes:
        name, size = changes["resize"]
        inputs = [dataclasses.replace(p, size=size) if p.name == name else p for p in inputs]
    return dataclasses.replace(CONTROLLER_STEP, inputs=tuple(inputs))


@pytest.mark.parametrize("change", [{"swap": ("yd_extra", "yd_rate")}, {"swap": ("gains", "steps")},
                                    {"swap": ("limits", "sensor")}, {"resize": ("target", "10")}],
                         ids=["same-size-swap", "parameters-swap", "last-two", "resized"])
def test_a_declaration_the_unit_does_not_match_is_refused(monkeypatch, change):
    """The binding fails loudly, before any call, when a port's place or size is not the compiled one's."""
    ctrl = hybrid.paper_experiment(controller="task").build_controller()
    x = hybrid.paper_experiment().initial_state()
    ctrl(0.0, x[:2], x[2:4], np.zeros(2))  # the unit is compiled and matches
    for module in (controller_module, controller_binding):  # the controller and the step's binding
        monkeypatch.setattr(module, "CONTROLLER_STEP", _perturbed(**change))
    try:
        perturbed = hybrid.paper_experiment(controller="task").build_controller()
    except (HybridError, RuntimeError) as exc:  # the controller's own layout check may see it first
        assert "declaration" in str(exc) or "disagree" in str(exc)
        return
    with pytest.raises(HybridError, match="does not match its declaration"):
        perturbed(0.0, x[:2], x[2:4], np.zeros(2))


def test_statuses_have_one_number_and_one_name_everywhere(tmp_path):
    codes = [s.code for s in STATUSES]
    assert len(set(codes)) == len(codes) and len({s.name for s in STATUSES}) == len(STATUSES)
    # the committed units' C macros
    for header in (m.with_suffix(".h") for m in (ROOT / "generated").glob("*.json")):  # each unit's header
        macros = dict(re.findall(r"#define HYBRID_(\w+) (\d+)", header.read_text()))
        assert {k: int(v) for k, v in macros.items() if k in STATUS_CODES} == \
            {k: STATUS_CODES[k] for k in KERNEL_STATUSES}, header.name
    # a standalone controller: its macros, its names for them, and the Python names of the kernels' statuses
    _sphere_controller().generate(tmp_path, "iface")
    c = CController(tmp_path, "iface")
    for s in STATUSES:
        assert getattr(c.lib, f"IFACE_{s.name}") == s.code
        assert c.name(s.code) == s.name
    assert c.name(max(codes) + 1) == "UNKNOWN"
    errors = {"SINGULAR": SingularConfigurationError, "FRAME_UNDEFINED": TaskFrameError,
              "EULER_SINGULAR": SingularConfigurationError, "NONFINITE": NonFiniteError}
    for name, kind in errors.items():
        assert type(status_error(STATUS_CODES[name], "here")) is kind, name


def test_standalone_struct_is_the_declaration(tmp_path):
    """Every parameter, reference and state port is a field of the standalone struct (the options as named
    scalars), its elements indexed by macros named from the declared element names."""
    ctrl = _sphere_controller()
    ctrl.generate(tmp_path, "decl")
    header = (tmp_path / "decl.h").read_text()
    ctrl._native()
    dims = _dims(ctrl)
    for p in CONTROLLER_STEP.inputs:
        if p.role not in (PARAMETER, REFERENCE, STATE) or p.name == "last_torque":
            continue
        names = p.element_names(dims)
        if p.name in ("options", "fault"):
            assert all(re.search(rf"double {n};", header) for n in names)
            continue
        assert re.search(rf"double {p.name}\[{p.size_of(dims)}\];", header), p.name
        if names and p.name not in ("robot", "surface"):
            macro = re.sub(r"[^A-Za-z0-9]+", "_", names[-1]).strip("_").upper()
            assert f"#define DECL_{p.name.upper()}_{macro} {len(names) - 1}" in header, p.name
    # the fault reaction's state, as the safe-stop kernel declares it
    state = SAFE_STOP.port("fault_state")
    assert re.search(rf"double fault_state\[{state.size_of(dims)}\];", header)
    assert f"#define DECL_FAULT_STATE_SAMPLES {state.size_of(dims) - 1}" in header
    # the gains: the same names in Python (PerAxis of LOOP_GAINS) and in C
    assert "#define DECL_GAINS_KP_N " in header and "KP_n" in CONTROLLER_STEP.port("gains").element_names(dims)


def test_metrics_come_in_the_declared_order():
    exp = hybrid.paper_experiment(controller="task")
    res = hybrid.simulate(exp)
    nq = 2
    assert tuple(res.metrics)[:len(metric_names(nq))] == metric_names(nq)
    plant, variant = hybrid.simulation.closed_loop.loop_of(exp)
    assert tuple(units.loop_unit(plant, dict(variant), 1).manifest["closed_loop"]["metrics"]) == metric_names(nq)
    t = np.linspace(0, 1, 101)
    m = hybrid.metrics(t, np.ones(101), np.ones(101), np.ones(101), np.ones(101), tau=np.ones((101, 3)))
    assert tuple(m) == metric_names(3)
    assert len(set(METRIC_NAMES)) == len(METRIC_NAMES)


def test_ports_and_packing():
    dims = Dims(("j1", "j2"), ("t1", "n"), ("a", "b", "c"), ("r",))
    assert [Port("x", s, "", "").size_of(dims) for s in ("nq", "2*m", "nq+1", "3*nq + 2", "robot", "7")] == \
        [2, 4, 3, 8, 3, 7]
    with pytest.raises(ValueError, match="not a sum"):
        Port("x", "nq*2", "", "").size_of(dims)
    assert PerAxis(("z1", "z2")).names(dims) == ("z1_t1", "z2_t1", "z1_n", "z2_n")
    assert PerJoint(("tau",), tail=("started",)).names(dims) == ("tau_j1", "tau_j2", "started")
    required = {"steps": np.zeros(6), "gains": np.ones(8), "selection": [0, 1], "robot": [1, 2, 3], "surface": [4],
                "e": [0, 0, 1], "options": np.ones(7)}
    packed = CONTROLLER_STEP.pack(required, dims)
    by_name = dict(zip(CONTROLLER_STEP.parameters, packed))
    assert by_name["limits"].tolist() == [np.finfo(float).max] * 4  # a parameter not given: its default
    assert by_name["posture"].tolist() == [0.0] * 6 and by_name["gains"].tolist() == [1.0] * 8
    for name in required:  # no neutral value: refused when left out
        with pytest.raises(HybridError, match=f"{name} has no neutral value"):
            CONTROLLER_STEP.pack({k: v for k, v in required.items() if k != name}, dims)
    with pytest.raises(HybridError, match="no parameter q"):
        CONTROLLER_STEP.pack({"q": [0, 0]}, dims)
    with pytest.raises(HybridError, match="takes 3 numbers"):
        CONTROLLER_STEP.pack({**required, "e": [0, 1]}, dims)
    # every state has an output it advances to, and the per-sample inputs come before the parameters
    assert set(STATE_NEXT) == set(CONTROLLER_STEP.named(STATE))
    assert all(out in {p.name for p in CONTROLLER_STEP.outputs} for out in STATE_NEXT.values())
    roles = [p.role == PARAMETER for p in CONTROLLER_STEP.inputs]
    assert roles == sorted(roles)


def test_every_parameter_declares_its_values_and_c_reads_the_same_rule(tmp_path):
    """Each parameter of the step states what values its elements may take, and each check's C expression
    (compiled here) and Python predicate agree on numbers at and around every edge, NaN and infinities."""
    import subprocess

    from hybrid.spec.interfaces import CHECKS, PARAMETER, Dims

    dims = Dims(("a", "b", "c"), ("t1", "n"), ("",) * 4, ("",) * 2)
    for p in CONTROLLER_STEP.inputs:
        if p.role == PARAMETER:
            assert p.check and all(p.checks(dims)) and len(p.checks(dims)) == p.size_of(dims), p.name
    T = 0.01
    xs = [float("nan"), float("inf"), -float("inf"), -1.0, -0.5, -0.0, 0.0, 5e-324, 0.5, 1.0 - 2 ** -53, 1.0, 2.0,
          0.5 / T - 1e-12, 0.5 / T, 1e300, float(np.finfo(float).max)]
    def c_number(x: float) -> str:
        return repr(x) if np.isfinite(x) else "NAN" if np.isnan(x) else "INFINITY" if x > 0 else "-INFINITY"

    lines = ["#include <math.h>", "#include <stdio.h>", "int main(void) {",
             f"    const double xs[{len(xs)}] = {{{', '.join(c_number(x) for x in xs)}}};",
             "    const double T = 0.01;", "    int i;", f"    for (i = 0; i < {len(xs)}; ++i) {{",
             "        const double x = xs[i];"]
    lines += [f'        printf("%d ", (int)({c.c}));' for c in CHECKS.values()]
    lines += ['        printf("\\n");', "    }", "    (void)T;", "    return 0;", "}"]
    (tmp_path / "checks.c").write_text("\n".join(lines) + "\n")
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", str(tmp_path / "checks.c"), "-o",
                    str(tmp_path / "checks"), "-lm"], check=True)
    got = subprocess.run([str(tmp_path / "checks")], check=True, capture_output=True, text=True).stdout.split("\n")
    for x, row in zip(xs, got):
        assert [int(v) for v in row.split()] == [int(bool(c.valid(x, T))) for c in CHECKS.values()], x
