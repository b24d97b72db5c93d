"""Tree-height reduction of the lanes backend's programs (codegen.balance): the same values within
rounding as CasADi evaluates them, and no longer a chain of dependent operations, on a chain built to
need it and on the plants of the paper's and the 3-D closed loops."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest
import sympy as sp
from hybrid.codegen import balance, lanes
from hybrid.codegen.casadi_backend import kernel_function
from hybrid.codegen.kernel import Arg, Kernel

import hybrid
from hybrid.native import units

#: each operation as NumPy computes it (written from CasADi's definitions, not from the C printer)
_NUMPY = {
    "OP_ASSIGN": lambda a: a, "OP_ADD": np.add, "OP_SUB": np.subtract, "OP_MUL": np.multiply,
    "OP_DIV": np.divide, "OP_NEG": np.negative, "OP_SQ": np.square, "OP_TWICE": lambda a: a + a,
    "OP_INV": lambda a: 1.0 / a, "OP_SQRT": np.sqrt, "OP_SIN": np.sin, "OP_COS": np.cos, "OP_EXP": np.exp,
    "OP_TANH": np.tanh, "OP_FABS": np.abs, "OP_SIGN": np.sign, "OP_COPYSIGN": np.copysign,
    "OP_FMIN": np.fmin, "OP_FMAX": np.fmax, "OP_LT": lambda a, b: (a < b) * 1.0,
    "OP_LE": lambda a, b: (a <= b) * 1.0, "OP_EQ": lambda a, b: (a == b) * 1.0, "OP_NE": lambda a, b: (a != b) * 1.0,
    "OP_NOT": lambda a: (a == 0) * 1.0, "OP_AND": lambda a, b: ((a != 0) & (b != 0)) * 1.0,
    "OP_OR": lambda a, b: ((a != 0) | (b != 0)) * 1.0, "OP_IF_ELSE_ZERO": lambda a, b: np.where(a != 0, b, 0.0),
    "OP_ATAN2": np.arctan2, "OP_POW": np.power, "OP_CONSTPOW": np.power, "OP_HYPOT": np.hypot,
    "OP_LOG": np.log, "OP_ATAN": np.arctan, "OP_ASIN": np.arcsin, "OP_ACOS": np.arccos,
}


def _interpret(program, kernel: Kernel, inputs: list[np.ndarray]) -> list[np.ndarray]:
    """The program's outputs at ``inputs`` (one array per kernel input, elements x points)."""
    ops, order, outputs, _ = program
    value: dict[int, np.ndarray] = {}
    with np.errstate(all="ignore"):
        for v in order:
            op, args, extra = ops[v]
            if op == "OP_INPUT":
                value[v] = inputs[extra[0]][extra[1]]
            elif op == "OP_CONST":
                value[v] = np.full(inputs[0].shape[1], extra)
            else:
                value[v] = _NUMPY[op](*(value[a] for a in args))
    out = [np.full((a.size, inputs[0].shape[1]), np.nan) for a in kernel.core_outputs()]
    for o, i, v in outputs:
        out[o][i] = value[v]
    return out


def _casadi(kernel: Kernel, inputs: list[np.ndarray]) -> list[np.ndarray]:
    f = kernel_function(kernel)
    n = inputs[0].shape[1]
    res = f.map(n)(*[ca.DM(x) for x in inputs])
    return [np.array(r).reshape(-1, n) for r in (res if isinstance(res, (list, tuple)) else [res])]


def _program(kernel, fixed, balanced: bool, monkeypatch):
    if not balanced:
        monkeypatch.setattr(lanes, "balance", lambda *args: None)
    program = lanes._program(kernel, fixed)
    monkeypatch.undo()
    return program


def _depth_and_size(program) -> tuple[int, int]:
    """The latest output's ready time, and the number of operations the outputs need that are not
    computed once (the hot code)."""
    ops, order, outputs, invariant = program
    t = balance.ready_times(ops, invariant, order)
    need = lanes._closure(ops, [v for _, _, v in outputs])
    return max(t[v] for _, _, v in outputs), sum(1 for v in need if not invariant[v] and ops[v][0] != "OP_INPUT")


def _check(kernel, fixed, inputs, monkeypatch, rtol):
    before = _program(kernel, fixed, False, monkeypatch)
    after = _program(kernel, fixed, True, monkeypatch)
    want = _casadi(kernel, inputs)
    for program in (before, after):
        for got, ref in zip(_interpret(program, kernel, inputs), want):
            np.testing.assert_allclose(got, ref, rtol=rtol, atol=rtol * np.abs(ref).max())
    return _depth_and_size(before), _depth_and_size(after)


def test_a_late_term_at_the_front_of_a_sum_meets_an_almost_finished_sum(monkeypatch, rng):
    """A square root in front of seven more terms and a product of four, one factor late: the sum
    waits for it once, not seven times; the invariant factors are multiplied once, outside."""
    x = sp.symbols("x0:8", real=True)
    k = sp.symbols("k0:2", real=True)
    late = sp.sqrt(x[0] ** 2 + 1)
    total = late - x[1] + x[2] * x[3] - x[4] + x[5] - x[6] + x[7] - 2 * x[1] * x[2]
    product = late * x[1] * k[0] * k[1]
    kernel = Kernel("chain", (Arg("x", sp.Matrix(x)), Arg("k", sp.Matrix(k))),
                    (Arg("y", sp.Matrix([total, -total, product])),), "a sum and a product with a late term")
    inputs = [rng.uniform(-2, 2, (8, 64)), rng.uniform(0.5, 2, (2, 64))]
    (depth0, size0), (depth1, size1) = _check(kernel, ("k",), inputs, monkeypatch, 1e-14)
    sqrt_ready = 3 + 3 + balance.LATENCY["OP_SQRT"]  # x0^2, + 1, sqrt
    assert depth1 <= sqrt_ready + 2 * balance.DEFAULT_LATENCY + balance.LATENCY["OP_NEG"] < depth0
    assert size1 <= size0


@pytest.mark.parametrize("make", [hybrid.paper_experiment, hybrid.tracing_experiment], ids=["paper", "ur5"])
def test_the_closed_loops_plants_keep_their_values_and_shorten_their_chains(make, monkeypatch, rng):
    """The plant right-hand sides the closed loops run (the planar arm on its circle; the UR5 on its
    sphere): equal within rounding to CasADi's evaluation, balanced or not; the balanced chain is
    shorter and has no more operations."""
    exp = make()
    spec = units.loop_spec(exp.plant_class.loop_plant(exp), exp.build_controller().step_variant())
    kernel = spec.rhs
    fixed = tuple(a.name for a in kernel.inputs[2:])
    blocks = exp.plant_class.inputs(exp)  # the plant's parameters, as a run's row holds them
    n = 32
    x = np.stack([exp.initial_state()] * n, axis=1) + rng.normal(0, 0.05, (kernel.inputs[0].size, n))
    tau = rng.normal(0, 5, (kernel.inputs[1].size, n))
    inputs = [x, tau, *(np.repeat(np.asarray(blocks[a.name], float).reshape(-1, 1), n, axis=1)
                        for a in kernel.inputs[2:])]
    (depth0, size0), (depth1, size1) = _check(kernel, fixed, inputs, monkeypatch, 1e-12)
    assert depth1 < depth0 and size1 <= size0
