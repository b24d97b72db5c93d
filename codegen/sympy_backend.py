"""SymPy backend: common-subexpression elimination and C99 printing of a kernel's body."""

from __future__ import annotations

import sympy as sp
from sympy.printing.c import C99CodePrinter

from .model import Kernel


class KernelPrinter(C99CodePrinter):
    """C99 printer that spells small integer powers as products.

    ``pow(x, 3)`` is a library call at ``-O2`` without ``-ffast-math``; ``x*x*x`` is not.
    """

    def _print_Pow(self, expr):
        base, exp = expr.base, expr.exp
        if exp.is_Integer and 2 <= abs(int(exp)) <= 4:
            b = self.parenthesize(base, 1000)  # always parenthesise a compound base
            prod = "*".join([b] * abs(int(exp)))
            return prod if exp > 0 else f"1.0/({prod})"
        if exp == -1:
            return f"1.0/{self.parenthesize(base, 1000)}"
        if exp == sp.Rational(-1, 2):
            return f"1.0/sqrt({self._print(base)})"
        return super()._print_Pow(expr)


_PRINTER = KernelPrinter()


def kernel_body(kernel: Kernel, indent: str = "    ") -> str:
    """C statements computing a kernel's outputs from its input arrays.

    Inputs are read into ``const double`` locals named after the array (``q0 = q[0]``),
    the shared subexpressions become locals ``x0, x1, ...``, and outputs are stored
    last, so an output array may alias nothing but must not alias an input.
    """
    if kernel.order != "printed":
        raise ValueError(f"kernel {kernel.name}: order {kernel.order!r} reorders CasADi's C; SymPy's printer keeps "
                         "its common subexpressions in their own order")
    outputs = kernel.core_outputs()
    exprs = [e for a in outputs for e in a.expr]
    replacements, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("x"), order="none")
    used = set().union(*(e.free_symbols for _, e in replacements), *(e.free_symbols for e in reduced))
    lines = []
    for a in kernel.inputs:
        reads = [f"const double {s} = {a.name}[{i}];" for i, s in enumerate(a.expr) if s in used]
        lines += reads or [f"(void){a.name};  /* not needed by this kernel */"]
    for sym, e in replacements:
        lines.append(f"const double {sym} = {_PRINTER.doprint(e)};")
    k = 0
    for a in outputs:
        for i in range(a.size):
            lines.append(f"{a.name}[{i}] = {_PRINTER.doprint(reduced[k])};")
            k += 1
    return "\n".join(indent + line for line in lines)
