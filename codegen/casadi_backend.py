"""CasADi backend: the same SymPy outputs rebuilt as CasADi SX and emitted by CasADi's generator.

CasADi performs its own common-subexpression elimination and code generation; only its
static kernel function is kept, since its exported helpers (checkout, sparsity, work
sizes) serve CasADi's own calling convention, not ours.
"""

from __future__ import annotations

import re

import casadi as ca
import sympy as sp

from .model import Kernel
from .schedule import reorder

_UNARY = {sp.sin: ca.sin, sp.cos: ca.cos, sp.tan: ca.tan, sp.tanh: ca.tanh, sp.Abs: ca.fabs, sp.exp: ca.exp,
          sp.log: ca.log, sp.asin: ca.asin, sp.acos: ca.acos, sp.atan: ca.atan, sp.sinh: ca.sinh,
          sp.cosh: ca.cosh}


def to_sx(expr: sp.Expr, symbols: dict, memo: dict):
    """Translate a SymPy expression into CasADi SX, reusing translated subtrees."""
    if expr in memo:
        return memo[expr]
    if expr.is_Symbol:
        out = symbols[expr]
    elif expr.is_Number or expr.is_number and not expr.free_symbols:  # 3, 1/2, pi, E, sqrt(2)
        out = ca.SX(float(expr))
    elif expr.is_Add:
        out = sum((to_sx(a, symbols, memo) for a in expr.args[1:]), to_sx(expr.args[0], symbols, memo))
    elif expr.is_Mul:
        out = to_sx(expr.args[0], symbols, memo)
        for a in expr.args[1:]:
            out = out * to_sx(a, symbols, memo)
    elif expr.is_Pow:
        base, exp = to_sx(expr.base, symbols, memo), expr.exp
        if exp == sp.Rational(1, 2):
            out = ca.sqrt(base)
        elif exp == sp.Rational(-1, 2):
            out = 1 / ca.sqrt(base)
        elif exp.is_Integer and int(exp) < 0:
            out = 1 / base ** int(-exp) if int(exp) != -1 else 1 / base
        elif exp.is_number:
            out = base ** float(exp) if not exp.is_Integer else base ** int(exp)
        else:  # a symbolic exponent
            out = base ** to_sx(exp, symbols, memo)
    elif type(expr) in _UNARY:
        out = _UNARY[type(expr)](to_sx(expr.args[0], symbols, memo))
    elif isinstance(expr, (sp.Max, sp.Min)):
        args = [to_sx(a, symbols, memo) for a in expr.args]
        pick = ca.fmax if isinstance(expr, sp.Max) else ca.fmin
        out = args[0]
        for a in args[1:]:
            out = pick(out, a)
    elif isinstance(expr, sp.Piecewise):
        out = to_sx(expr.args[-1][0], symbols, memo)
        for value, cond in reversed(expr.args[:-1]):
            out = ca.if_else(to_sx(cond, symbols, memo), to_sx(value, symbols, memo), out)
    elif isinstance(expr, sp.StrictGreaterThan):
        out = to_sx(expr.lhs, symbols, memo) > to_sx(expr.rhs, symbols, memo)
    elif isinstance(expr, sp.StrictLessThan):
        out = to_sx(expr.lhs, symbols, memo) < to_sx(expr.rhs, symbols, memo)
    else:
        raise NotImplementedError(f"CasADi backend cannot translate {type(expr).__name__}: {expr}")
    memo[expr] = out
    return out


def kernel_function(kernel: Kernel, sympy_cse: bool = False) -> ca.Function:
    """The kernel as a CasADi ``Function`` of its input arrays (also used by the benchmarks).

    A kernel written in CasADi SX is used as it is; one written in SymPy is translated, with
    ``sympy_cse`` after SymPy's own elimination of common subexpressions (fewer operations than
    CasADi's alone finds in a SymPy tree: one reciprocal of a determinant, not one per use).
    """
    outputs = kernel.core_outputs()
    if all(isinstance(a.expr, ca.SX) for a in (*kernel.inputs, *outputs)):
        args, outs = [a.expr for a in kernel.inputs], [a.expr for a in outputs]
    else:
        symbols, args = {}, []
        for a in kernel.inputs:
            v = ca.SX.sym(a.name, a.size)
            args.append(v)
            symbols.update({s: v[i] for i, s in enumerate(a.expr)})
        memo: dict = {}
        exprs = [e for a in outputs for e in a.expr]
        if sympy_cse:
            replacements, exprs = sp.cse(exprs, symbols=sp.numbered_symbols("_cse"), order="none")
            for sym, e in replacements:
                symbols[sym] = to_sx(e, symbols, memo)
        exprs = iter([to_sx(e, symbols, memo) for e in exprs])
        outs = [ca.vertcat(*[next(exprs) for _ in range(a.size)]) for a in outputs]
    # our C fills every element of an output: structural zeros must become stored zeros
    outs = [ca.densify(o) for o in outs]
    outs = ca.cse(outs)  # jointly: a subexpression shared by two outputs is computed once
    return ca.Function(kernel.name, args, outs, [a.name for a in kernel.inputs], [a.name for a in outputs])


_FUNCTION_START = re.compile(r"^(?:static int (casadi_f\d+)|casadi_real (casadi_\w+))\(", re.M)
_SPARSITY = re.compile(r"^#define casadi_s\d+ .*$\n?", re.M)
#: CasADi's statements ``aN=sin(aM);`` and ``aN=cos(aM);``: the kernels take the inline ones of
#: ``templates/hybrid_sincos.c.j2`` instead of the C library's calls
_SINCOS = re.compile(r"(?<==)(sin|cos)\(")
#: CasADi's reads and writes that test their array for NULL first: a core passes every array (the
#: caller's, which the header requires), and tested at every element they cost a branch each
_READ, _WRITE = re.compile(r"arg\[(\d+)\]\? (arg\[\1\]\[\d+\]) : 0;"), re.compile(r"if \(res\[\d+\]!=0\) (?=res\[)")


def _function_at(text: str, start: int) -> str:
    """The C function definition starting at ``start``, up to its matching brace."""
    depth, i = 0, text.index("{", start)
    while True:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
        if depth == 0:
            return text[start:i] + "\n"


def kernel_sources(kernels: list[Kernel], prefix: str) -> tuple[str, dict[str, tuple[str, int]]]:
    """C of CasADi's static kernel functions, and for each kernel its C name and work size.

    Returns ``(code, {kernel name: (casadi function name, sz_w)})``. Kept from CasADi's
    file: its symbol-prefix macros, its math helpers (made ``static``) and its static
    kernels; dropped: its exported API, version stamp and sparsity tables. The kernels' sines and
    cosines are ``hybrid_sin`` and ``hybrid_cos`` (``templates/hybrid_sincos.c.j2``, which the unit
    includes before them), and they read and write their arrays without testing each for NULL.
    """
    cg = ca.CodeGenerator(f"{prefix}.c", {"with_header": False, "casadi_real": "double",
                                           "casadi_int": "int", "prefix": f"{prefix}_"})
    funcs = [kernel_function(k) for k in kernels]
    for f in funcs:
        cg.add(f)
    dump = cg.dump()
    preamble = _SPARSITY.sub("", dump[:dump.index("/* Symbol visibility")]).strip()
    helpers, names, kernels_c = [], [], []
    for m in _FUNCTION_START.finditer(dump):
        body = _function_at(dump, m.start())
        if m.group(1):
            names.append(m.group(1))
            # the work array is ours to size; CasADi's mem and iw go unused
            head, rest = body.split("{", 1)
            body = f"{head}{{\n  (void)arg; (void)iw; (void)mem; (void)w;{rest}"
            body = _WRITE.sub("", _READ.sub(r"\2;", _SINCOS.sub(r"hybrid_\1(", body)))
            kernels_c.append(reorder(body, kernels[len(names) - 1].order))
        else:
            helpers.append("static " + body)
    if len(names) != len(funcs):
        raise RuntimeError(f"expected {len(funcs)} CasADi kernels, found {len(names)}: "
                           "CasADi's code layout changed; update codegen/casadi_backend.py")
    table = {k.name: (n, int(f.sz_w())) for k, n, f in zip(kernels, names, funcs)}
    return "\n".join([preamble, *helpers, *kernels_c]), table
