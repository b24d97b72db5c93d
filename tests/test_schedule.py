"""The reordered C of a CasADi kernel (codegen/schedule.py): each statement once, after what it reads, and
the same numbers as CasADi's order and CasADi's own evaluation."""

from __future__ import annotations

import ctypes
import dataclasses
import re
import shutil
import subprocess
from collections import Counter

import casadi as ca
import numpy as np
import pytest
from hybrid.codegen import schedule, templates
from hybrid.codegen.casadi_backend import kernel_sources
from hybrid.codegen.kernel import Arg, Kernel


def kernel(order: str) -> Kernel:
    """Shared subexpressions, sines, a branch and constants, as the dynamics have them."""
    x = ca.SX.sym("x", 4)
    s, c = ca.sin(x[0]), ca.cos(x[0])
    u = s * x[1] - c * x[2]
    v = u * u + 0.25 * x[3]
    choice = ca.if_else(x[1] > x[2], u * x[3], v - x[0])  # CasADi: (c?a:0) + (!c?b:0)
    outs = ca.vertcat(u * v - s, ca.if_else(x[3] != 0, ca.tanh(x[1] / x[3]), 0) + v, c * u + 3.5 * v * x[2], s * c,
                      choice * x[0])
    return Kernel("k", (Arg("x", x, "1"),), (Arg("y", outs, "1"),), "test", order=order)


def statements(code: str) -> list[str]:
    return [line for line in code.split("\n") if re.match(r"^  (a\d+|res\[\d+\]\[\d+\])=", line)]


@pytest.mark.parametrize("order", schedule.ORDERS[1:])
def test_each_statement_once_after_what_it_reads(order):
    plain, _ = kernel_sources([kernel("printed")], "p")
    again, _ = kernel_sources([kernel(order)], "p")
    lines = statements(again)
    defined = set()
    for line in lines:
        target, expression = line.strip().rstrip(";").split("=", 1)
        assert set(re.findall(r"\ba\d+\b", expression)) <= defined, line
        assert target not in defined, line
        defined.add(target)

    def operations(code):  # the statements with the locals' names taken out
        return Counter(re.sub(r"\ba\d+\b", "a", line.strip()) for line in statements(code))

    # the one choice is one select: its two halves, their sum and the negation gone, the rest as CasADi's
    fused = Counter({"a=(a?a:0);": 2, "a=(!a);": 1, "a=(a+a);": 1})
    assert operations(again) == operations(plain) - fused + Counter({"a=(a?a:a);": 1})
    assert lines != statements(plain)


def test_an_unfamiliar_statement_leaves_the_function_as_it_is():
    text = "static int f() {\n  a0=arg[0][0];\n  casadi_copy(w, 2, w+2);\n  res[0][0]=a0;\n  return 0;\n}\n"
    assert schedule.reorder(text) == text


@pytest.mark.parametrize("order", schedule.ORDERS[1:])
def test_a_line_after_the_statements_that_reads_a_local_leaves_the_function_as_it_is(order):
    # CasADi's own guarded writes, as the backend's rewrite would leave them were CasADi to print them otherwise
    x = ca.SX.sym("x", 2)
    generator = ca.CodeGenerator("t.c", {"with_header": False})
    generator.add(ca.Function("f", [x], [ca.sin(x[0]) * x[1]]))
    dump = generator.dump()
    text = dump[dump.index("static int casadi_f0"):]
    text = text[:text.index("\n}\n") + 3]
    assert "if (res[0]!=0) res[0][0]=a0;" in text
    assert schedule.reorder(text, order) == text


def test_the_orders_differ_and_an_unknown_one_is_refused():
    bodies = {order: statements(kernel_sources([kernel(order)], "p")[0]) for order in schedule.ORDERS}
    assert len({tuple(b) for b in bodies.values()}) == len(schedule.ORDERS)
    with pytest.raises(ValueError, match="order 'fastest' is not one of printed, fewest_alive, longest_chain"):
        kernel("fastest")
    with pytest.raises(ValueError, match="not one of"):
        schedule.reorder("", "fastest")


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
def test_the_same_numbers_as_casadis_order_and_evaluation(tmp_path, rng):
    libraries = {}
    for order in schedule.ORDERS:
        code, table = kernel_sources([kernel(order)], "t")
        name, size = table["k"]
        source = tmp_path / f"k_{order}.c"
        source.write_text("#include <math.h>\n" + templates.render("hybrid_sincos.c.j2") + code
                          + f"\nvoid run(const double *x, double *y) {{ const double *arg[1] = {{x}};"
                          f" double *res[1] = {{y}}; double w[{size} + 1]; {name}(arg, res, 0, w, 0); }}\n")
        library = tmp_path / f"k_{order}.so"
        subprocess.run(["cc", "-O2", "-fPIC", "-shared", str(source), "-o", str(library), "-lm"], check=True)
        libraries[order] = ctypes.CDLL(str(library))
    k = kernel("printed")
    f = ca.Function("f", [k.inputs[0].expr], [k.outputs[0].expr])
    states = rng.uniform(-3, 3, (200, 4))  # both sides of the choice
    states[::5, 3] = 0.0  # the branch's other side
    for x in states:
        ys = []
        for order in schedule.ORDERS:
            y = np.zeros(k.outputs[0].expr.shape[0])
            libraries[order].run(x.ctypes.data_as(ctypes.c_void_p), y.ctypes.data_as(ctypes.c_void_p))
            ys.append(y)
        # bit for bit, but a zero's sign: a select keeps a chosen -0 that CasADi's sum made +0
        for y in ys[1:]:
            assert np.array_equal(y, ys[0]) and y[y != 0].tobytes() == ys[0][ys[0] != 0].tobytes()
        assert np.allclose(ys[1], np.array(f(x)).ravel(), rtol=1e-13, atol=1e-13)


def test_a_kernel_keeps_its_order_through_replace():
    assert dataclasses.replace(kernel("longest_chain"), doc="other").order == "longest_chain"


def test_the_sympy_printer_refuses_an_order_it_cannot_keep():
    import sympy as sp
    from hybrid.codegen.sympy_backend import kernel_body

    x = sp.Matrix(sp.symbols("x0:2"))
    with pytest.raises(ValueError, match="SymPy's printer keeps"):
        kernel_body(Kernel("k", (Arg("x", x, "1"),), (Arg("y", x * 2, "1"),), "test", order="fewest_alive"))
