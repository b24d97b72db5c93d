"""The SIMD-lanes backend: a kernel evaluated for ``HL_W`` states at once, one state per lane.

Any kernel (SymPy or CasADi) is first a CasADi ``Function`` (:func:`casadi_backend.kernel_function`);
its instruction list is printed here with every scalar a GCC/Clang vector of ``HL_W`` doubles
(``hl_v``), every array element a vector (structure of arrays: element ``i`` of lane ``l`` is
``a[i][l]``). Arithmetic, comparisons and selects are the compiler's vector operations; ``sin``,
``cos``, ``exp`` and ``tanh`` are our own vector polynomials (fdlibm's kernels for sin and cos,
Taylor's for exp, Cephes' for small tanh arguments; within an ulp or two of the C library), where a
lane whose argument is large or not finite takes the C library's value (so a lane never depends on
its neighbours); other functions are the C library's, lane by lane.

The lane count is chosen where the code is compiled, from the instruction set it targets (8 with
AVX-512, 4 with AVX, else 2): with ``-march=native`` that is this processor's; without it, a
portable build of the same source.
"""

from __future__ import annotations

import math

import casadi as ca

from .balance import balance
from .casadi_backend import kernel_function
from .kernel import Kernel
from .templates import render

#: the header every unit that evaluates kernels in lanes includes (the types, selects, tests and vector
#: polynomials; rendered from ``templates/hybrid_lanes.h.j2``, it compiles on its own), and the line that includes it
LANES_HEADER = "hybrid_lanes.h"
INCLUDE = f'#include "{LANES_HEADER}"'


def lanes_header() -> str:
    """The text of :data:`LANES_HEADER`, rendered from its template (which takes sin and cos from
    ``fdlibm_sincos.j2``, as the kernels' ``hybrid_sincos.c.j2`` does); ``generated/`` holds it, stamped,
    beside the units, and the runtime compiles them with that copy."""
    return render(f"{LANES_HEADER}.j2")

#: functions of the C library applied lane by lane: CasADi operation -> C function
_LIBM1 = {"OP_LOG": "log", "OP_TAN": "tan", "OP_ASIN": "asin", "OP_ACOS": "acos", "OP_ATAN": "atan",
          "OP_SINH": "sinh", "OP_COSH": "cosh", "OP_ASINH": "asinh", "OP_ACOSH": "acosh", "OP_ATANH": "atanh",
          "OP_FLOOR": "floor", "OP_CEIL": "ceil", "OP_ERF": "erf", "OP_EXPM1": "expm1", "OP_LOG1P": "log1p"}
_LIBM2 = {"OP_ATAN2": "atan2", "OP_FMOD": "fmod", "OP_HYPOT": "hypot", "OP_POW": "pow", "OP_CONSTPOW": "pow"}
#: the rest: CasADi operation -> C expression of the work variables {a} and {b}
_OPS = {"OP_ASSIGN": "{a}", "OP_ADD": "{a} + {b}", "OP_SUB": "{a} - {b}", "OP_MUL": "{a} * {b}",
        "OP_DIV": "{a} / {b}", "OP_NEG": "-{a}", "OP_SQ": "{a} * {a}", "OP_TWICE": "{a} + {a}",
        "OP_INV": "1.0 / {a}", "OP_SQRT": "hl_sqrt({a})", "OP_EXP": "hl_exp({a})", "OP_TANH": "hl_tanh({a})",
        "OP_FABS": "hl_fabs({a})", "OP_SIGN": "hl_sign({a})",
        "OP_COPYSIGN": "hl_copysign({a}, {b})", "OP_FMIN": "hl_fmin({a}, {b})", "OP_FMAX": "hl_fmax({a}, {b})",
        "OP_LT": "hl_bool({a} < {b})", "OP_LE": "hl_bool({a} <= {b})", "OP_EQ": "hl_bool({a} == {b})",
        "OP_NE": "hl_bool({a} != {b})", "OP_NOT": "hl_bool({a} == 0.0)",
        "OP_AND": "hl_bool(({a} != 0.0) & ({b} != 0.0))", "OP_OR": "hl_bool(({a} != 0.0) | ({b} != 0.0))",
        "OP_IF_ELSE_ZERO": "hl_select({a} != 0.0, {b}, hl_splat(0.0))"}
_OPS.update({op: f"hl_{f}({{a}})" for op, f in _LIBM1.items()})
_OPS.update({op: f"hl_{f}({{a}}, {{b}})" for op, f in _LIBM2.items()})
#: sin and cos: one sincos call (hl_sincos, or hl_sincos_near from an RK4 step's start) gives both
_TRIG = ("OP_SIN", "OP_COS")
_BY_CODE = {getattr(ca, name): name for name in (*_OPS, *_TRIG, "OP_CONST", "OP_INPUT", "OP_OUTPUT")}
#: the operations with a polynomial that leaves some lanes to the C library (see LANES_HEADER), sin and cos too
_POLY = {"OP_EXP": "hl_exp_poly({a}, odd)", "OP_TANH": "hl_tanh_poly({a}, odd)"}


def _constant(value: float) -> str:
    if math.isnan(value):
        return "hl_splat(NAN)"
    if math.isinf(value):
        return f"hl_splat({'-' if value < 0 else ''}INFINITY)"
    return f"hl_splat({value!r})"


def libm_maps() -> str:
    """The lane-by-lane C library functions a lanes kernel may call (defined once per unit)."""
    ones = "".join(f"HL_MAP1(hl_{f}, {f})\n" for f in sorted(set(_LIBM1.values())))
    twos = "".join(f"HL_MAP2(hl_{f}, {f})\n" for f in sorted(set(_LIBM2.values())))
    return ones + twos


def _program(kernel: Kernel, fixed: tuple[str, ...] | None):
    """The kernel's CasADi instructions as values (single assignment): ``(ops, outputs, invariant)``.

    ``ops[v] = (operation, argument values, constant or input element)``; ``outputs`` lists
    ``(output, element, value)``; ``invariant[v]`` says that ``v`` depends on the ``fixed`` inputs
    and constants only. A divisor used twice or more, or invariant, becomes one reciprocal
    (``OP_INV``) and products: divisions are the slowest vector operations, and an invariant
    reciprocal leaves the loop altogether (the result changes within rounding).
    """
    f = kernel_function(kernel, sympy_cse=True)
    ops, outputs, slot = [], [], {}
    for k in range(f.n_instructions()):
        code, ins, out = f.instruction_id(k), f.instruction_input(k), f.instruction_output(k)
        op = _BY_CODE.get(code)
        if op is None:
            raise NotImplementedError(f"the lanes backend cannot print CasADi operation {code} of kernel "
                                      f"{kernel.name}; add it to codegen/lanes.py")
        if op == "OP_OUTPUT":
            outputs.append((out[0], out[1], slot[ins[0]]))
            continue
        if op == "OP_INPUT":
            ops.append((op, (), (ins[0], ins[1])))
        elif op == "OP_CONST":
            ops.append((op, (), float(f.instruction_constant(k))))
        else:
            ops.append((op, tuple(slot[i] for i in ins[:2 if "{b}" in _OPS.get(op, "") else 1]), None))
        slot[out[0]] = len(ops) - 1
    fixed_inputs = {i for i, a in enumerate(kernel.inputs) if a.name in (fixed or ())}
    invariant = []
    for op, args, extra in ops:
        invariant.append(extra[0] in fixed_inputs if op == "OP_INPUT" else all(invariant[a] for a in args))
    divisors: dict[int, int] = {}
    for op, args, _ in ops:
        if op == "OP_DIV":
            divisors[args[1]] = divisors.get(args[1], 0) + 1
    shared = {d for d, n in divisors.items() if n > 1 or invariant[d]}
    reciprocal: dict[int, int] = {}
    for v in range(len(ops)):
        op, args, extra = ops[v]
        if op == "OP_DIV" and args[1] in shared:
            d = args[1]
            if d not in reciprocal:  # a new value after the divisor's: single assignment holds
                ops.append(("OP_INV", (d,), None))
                invariant.append(invariant[d])
                reciprocal[d] = len(ops) - 1
            ops[v] = ("OP_MUL", (args[0], reciprocal[d]), None)
    balance(ops, invariant, outputs, _schedule(ops))
    return ops, _schedule(ops, [v for _, _, v in outputs]), outputs, invariant


def _schedule(ops, roots=()) -> list[int]:
    """An order of the values in which every value follows its arguments: depth first from ``roots``
    (then from the other values, in order), each argument just before its first user, the one on the
    longer path first (as Sethi and Ullman order a tree). A value then lives briefly: the compiler
    keeps the order of straight-line code, so this is what decides how many registers it needs and
    how much it spills."""
    height = [0] * len(ops)
    for v in _postorder(ops, range(len(ops)), lambda v: ops[v][1]):
        height[v] = 1 + max((height[a] for a in ops[v][1]), default=-1)
    return _postorder(ops, [*roots, *range(len(ops))],
                      lambda v: sorted(ops[v][1], key=lambda a: (-height[a], a)))


def _postorder(ops, roots, arguments) -> list[int]:
    """Every value reachable from ``roots`` after the values ``arguments(v)`` lists for it."""
    done, order = set(), []
    for root in roots:
        stack = [(root, iter(arguments(root)))] if root not in done else []
        while stack:
            v, pending = stack[-1]
            a = next((a for a in pending if a not in done), None)
            if a is not None:
                stack.append((a, iter(arguments(a))))
                continue
            stack.pop()
            if v not in done:
                done.add(v)
                order.append(v)
    return order


def lanes_function(kernel: Kernel, name: str | None = None, fixed: tuple[str, ...] | None = None,
                   storage: str = "static", near: int = 0, apart: bool = False) -> str:
    """``static void <name>(const hl_v *input..., hl_v *output...)``: the kernel on ``HL_W`` lanes.

    Arguments are the kernel's inputs, then its core outputs (outputs, then each guard's measure),
    each an array of ``hl_v`` (one vector per element). Outputs may not alias inputs.

    With ``fixed`` input names (numbers a run holds, such as its parameters; possibly none) what
    depends on them alone is computed once, by ``<name>_pre(fixed inputs..., hl_v *pre)`` into
    ``<NAME>_NPRE`` vectors, and ``<name>(other inputs..., const hl_v *pre, outputs...)`` reads it.
    ``storage`` declares ``<name>`` (a caller may have it inlined). With ``near = n`` the functions take a
    last argument ``const hl_v *base``, ``(x0, sin x0, cos x0)`` for each of the first ``n`` elements of the
    first input, and take sin and cos of those elements by rotating from there (``hl_sincos_near``).

    With ``apart`` the functions called out of line (``<name>_pre`` and the exact functions' pass, and
    ``<name>`` itself where ``storage`` is ``HL_APART``) are defined in a unit's second part, for a
    build that compiles a unit in two parts at once (:data:`codegen.closed_loop.PARTS` defines the
    macros); elsewhere they are declared.
    """
    ops, order, outputs, invariant = _program(kernel, fixed)
    outs = kernel.core_outputs()
    name = name or kernel.name + "_lanes"
    used_hot = {a for v in order if not invariant[v] for a in ops[v][1]} | {v for _, _, v in outputs}
    split = fixed is not None
    fixed = fixed or ()
    cached = [v for v in order if invariant[v] and v in used_hot] if split else []
    slot = {v: i for i, v in enumerate(cached)}

    # sin and cos of one argument: one reduction, both polynomials
    trig: dict = {}
    for v, (op, args, _) in enumerate(ops):
        if op in ("OP_SIN", "OP_COS"):
            trig.setdefault(args[0], {})[op] = v
    partner = {d[o]: d[other] for d in trig.values() if len(d) == 2
               for o, other in (("OP_SIN", "OP_COS"), ("OP_COS", "OP_SIN"))}

    def near_slot(v) -> int | None:  # the base slot of a sin or cos of one of the first `near` state elements
        arg = ops[ops[v][1][0]]
        return arg[2][1] if arg[0] == "OP_INPUT" and arg[2][0] == 0 and arg[2][1] < near else None

    def body(values, read_cached: bool, either: bool = False, stores: dict | None = None) -> list[str]:
        """C statements of ``values``: the exact functions, or with ``either`` the exact ones or the
        polynomials as the core's ``exact`` says; ``stores[v]``, the statements storing ``v``, follow it
        (an output written as soon as it is known is not held in a register to the end)."""
        def pick(exact: str, poly: str) -> str:
            return f"(exact ? {exact} : {poly})" if either else exact

        lines, fused = [], set()
        here = set(values)
        for v in values:
            op, args, extra = ops[v]
            if v in fused:
                continue
            if op in _TRIG and not (read_cached and v in slot):
                p = partner.get(v)
                pair = (v, p) if p is not None and p in here and not (read_cached and p in slot) else (v, None)
                fused.update(x for x in pair if x is not None)
                s_, c_ = (f"v{x}" if x is not None else f"t{v}" for x in (pair if op == "OP_SIN" else pair[::-1]))
                k = near_slot(v)
                f, at = ("hl_sincos_near", f", base + {3 * k}") if k is not None else ("hl_sincos", "")
                where = f"v{args[0]}{at}, &{s_}, &{c_}"
                lines.append(f"    hl_v {s_}, {c_};")
                lines.append(f"    if (exact) {f}({where}); else {f}_poly({where}, odd);" if either
                             else f"    {f}({where});")
                lines += [line for x in pair if x is not None for line in (stores or {}).get(x, ())]
                continue
            if read_cached and v in slot:
                rhs = f"pre[{slot[v]}]"
            elif op == "OP_INPUT":
                rhs = f"{kernel.inputs[extra[0]].name}[{extra[1]}]"
            elif op == "OP_CONST":
                rhs = _constant(extra)
            else:
                a_, b_ = f"v{args[0]}", f"v{args[1]}" if len(args) > 1 else ""
                rhs = _OPS[op].format(a=a_, b=b_)
                if op in _POLY:
                    rhs = pick(rhs, _POLY[op].format(a=a_))
            lines.append(f"    const hl_v v{v} = {rhs};")
            lines += (stores or {}).get(v, ())
        return lines

    def define(signature: str, lines: list[str], there: bool) -> list[str]:
        """A function's definition; one compiled apart (``there``) is defined in the unit's second part
        only and declared elsewhere."""
        whole = [f"{signature} {{", *lines, "}"]
        return ["#if HL_IN_PART(2)", *whole, "#else", f"{signature};", "#endif"] if there else whole

    # the storage of what the loop calls out of line, and whether the function itself is one of them
    out_of_line, main_apart = ("HL_APART" if apart else "static"), storage == "HL_APART"

    text = []
    hot_inputs = [a for a in kernel.inputs if a.name not in fixed]
    if split:
        pre_inputs = [a for a in kernel.inputs if a.name in fixed]
        pre_params = ", ".join([*(f"const hl_v *{a.name}" for a in pre_inputs), "hl_v *pre"])
        needed = _closure(ops, cached)
        text += [f"#define {name.upper()}_NPRE {max(len(cached), 1)}",
                 *define(f"{out_of_line} void {name}_pre({pre_params})",
                         [*body([v for v in order if v in needed], False),
                          *(f"    pre[{slot[v]}] = v{v};" for v in cached),
                          *(f"    (void){a.name};" for a in pre_inputs), "    (void)pre;"], apart), ""]
    params = ([f"const hl_v *{a.name}" for a in hot_inputs] + (["const hl_v *pre"] if split else [])
              + [f"hl_v *{a.name}" for a in outs] + (["const hl_v *base"] if near else []))
    needed = _closure(ops, [v for _, _, v in outputs], stop=set(slot))
    hot = [v for v in order if v in needed]
    unused = [*(f"    (void){a.name};" for a in hot_inputs), *(["    (void)pre;"] if split else []),
              *(["    (void)base;"] if near else [])]
    store: dict[int, list[str]] = {}
    for o, i, v in outputs:
        store.setdefault(v, []).append(f"    {outs[o].name}[{i}] = v{v};")
    if not any(ops[v][0] in (*_POLY, *_TRIG) and v not in slot for v in hot):
        return "\n".join([*text, *define(f"{storage} void {name}({', '.join(params)})",
                                          [*unused, *body(hot, True, stores=store)], main_apart), ""])
    # one core, twice: on the polynomials, and where a lane is odd everything again on the exact functions
    # (the outputs, written first, do not alias the inputs)
    args = ", ".join([*(a.name for a in hot_inputs), *(["pre"] if split else []), *(a.name for a in outs),
                      *(["base"] if near else [])])
    text += [f"static inline __attribute__((always_inline)) void {name}_core({', '.join(params)}, const int exact, "
             "hl_i *odd) {", *unused, "    (void)odd;", *body(hot, True, either=True, stores=store), "}", "",
             *define(f"{out_of_line} __attribute__((noinline, cold)) void {name}_exact({', '.join(params)})",
                     [f"    {name}_core({args}, 1, NULL);"], apart), "",
             *define(f"{storage} void {name}({', '.join(params)})",
                     ["    hl_i odd = hl_splat(0.0) != 0.0;", f"    {name}_core({args}, 0, &odd);",
                      f"    if (hl_any(odd)) {name}_exact({args});"], main_apart), ""]
    return "\n".join(text)


def _closure(ops, roots, stop=frozenset()) -> set[int]:
    """The values ``roots`` need (themselves included), not looking past those in ``stop``."""
    need, stack = set(), list(roots)
    while stack:
        v = stack.pop()
        if v in need:
            continue
        need.add(v)
        if v not in stop:
            stack.extend(ops[v][1])
    return need
