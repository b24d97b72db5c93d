"""What a program in lanes executes: its vector operations by kind, and its chain.

The census of a kernel counts the values of its lanes program (:func:`codegen.lanes._program`) that a
call computes, not those a run computes once (the fixed inputs' own), each as the vector operations its C
becomes (:data:`KINDS`): a product whose every use is a sum is fused into them, as GCC contracts products
and sums across statements (``-ffp-contract=fast``, its default for GNU C; Clang's default contracts
within a statement only, and the lanes' C has one operation a statement); the vector polynomials (sin
and cos, exp, tanh) count as the operations of their usual path in ``hybrid_lanes.h``
(:data:`POLYNOMIALS`). The chain is the longest path of latencies from a call's inputs to its outputs.

A closed loop's census (:func:`loop_census`) is per RK4 step of one run (of a group of lanes alike: a
vector operation is one operation of each lane): the four stages, the step's combinations and checks,
and a share of the sample's controller step and output record. The loop's other work (the metrics'
row, the record, the statuses) is not counted.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from .balance import LATENCY
from .closed_loop import SIGNALS, LoopSpec, _fixed, _parameters, stepping_kernel
from .kernel import Kernel
from .lanes import _TRIG, _closure, _program

#: the kinds of vector operation counted: fused multiply-adds, products, sums and differences, divisions,
#: square roots, comparisons, selects (blends of two vectors by a mask), bitwise and integer operations (an
#: absolute value, a sign, a mask's logic), and calls of the C library lane by lane (none in the loops)
KINDS = ("fma", "mul", "add", "div", "sqrt", "compare", "select", "bitwise", "libm")

#: CasADi operation -> the vector operations its C (codegen/lanes.py's) becomes
_OP_KINDS = {
    "OP_ADD": {"add": 1}, "OP_SUB": {"add": 1}, "OP_TWICE": {"add": 1}, "OP_MUL": {"mul": 1}, "OP_SQ": {"mul": 1},
    "OP_DIV": {"div": 1}, "OP_INV": {"div": 1}, "OP_SQRT": {"sqrt": 1},
    "OP_NEG": {"bitwise": 1}, "OP_FABS": {"bitwise": 1}, "OP_COPYSIGN": {"bitwise": 1},
    **{op: {"compare": 1, "select": 1} for op in ("OP_LT", "OP_LE", "OP_EQ", "OP_NE", "OP_NOT", "OP_IF_ELSE_ZERO")},
    **{op: {"compare": 2, "bitwise": 1, "select": 1} for op in ("OP_AND", "OP_OR", "OP_FMIN", "OP_FMAX")},
    "OP_SIGN": {"compare": 2, "select": 2}, "OP_ASSIGN": {}, "OP_INPUT": {}, "OP_CONST": {}}

#: the polynomials of ``hybrid_lanes.h`` on their usual path, as vector operations (their C counted by hand,
#: contracted as GCC does): ``sincos_near``, sin and cos of a stage's joint angle rotated from its step's
#: start (``hl_rotate``: no lane far from it); ``sincos``, both of any argument (``hl_sincos_poly``); ``exp``
#: (``hl_exp_poly``); ``tanh`` where every lane's argument is beyond 20 in size (a friction law sliding:
#: ``hl_tanh_poly``'s first path), ``tanh_below`` where one is not (``hl_tanh_below``: an exp, a division;
#: no lane below 0.625)
_EXP = {"add": 1, "mul": 1, "fma": 16, "compare": 1, "select": 1, "bitwise": 5}
POLYNOMIALS = {
    "sincos_near": {"add": 1, "mul": 3, "fma": 8, "bitwise": 1, "compare": 1},
    "sincos": {"add": 3, "mul": 3, "fma": 18, "compare": 5, "select": 4, "bitwise": 11},
    "exp": _EXP,
    "tanh": {"compare": 1, "bitwise": 2},
    "tanh_below": dict(Counter(_EXP) + Counter({"add": 2, "mul": 1, "div": 1, "compare": 5, "select": 2,
                                                 "bitwise": 3}))}
#: the latency [cycles] of each polynomial's path (codegen/balance.py's figures, the rotation's below its
#: full reduction's)
_POLY_LATENCY = {"sincos_near": LATENCY["OP_SIN"], "sincos": 2 * LATENCY["OP_SIN"], "exp": LATENCY["OP_EXP"],
                 "tanh": 3, "tanh_below": LATENCY["OP_EXP"] + LATENCY["OP_DIV"] + 9}
#: the latency of a fused multiply-add [cycles], where a caller gives none
FMA_LATENCY = 4


@dataclass(frozen=True)
class Census:
    """A program's vector operations by kind (:data:`KINDS`) and its chain [cycles, or the unit of the
    latencies given]."""

    counts: dict
    chain: float

    def total(self) -> float:
        """Every operation counted."""
        return sum(self.counts.values())


def _latency(op: str, latency: dict) -> float:
    """An operation's latency: the caller's for its kind where given (``add``, ``mul``, ``fma``, ``div``,
    ``sqrt``), else codegen/balance.py's."""
    kind = {"OP_ADD": "add", "OP_SUB": "add", "OP_TWICE": "add", "OP_MUL": "mul", "OP_SQ": "mul", "OP_DIV": "div",
            "OP_INV": "div", "OP_SQRT": "sqrt"}.get(op)
    if kind in latency:
        return latency[kind]
    return LATENCY.get(op, 3) * latency.get("cycle", 1.0)


def kernel_census(kernel: Kernel, fixed: tuple[str, ...] | None = None, near: int = 0, contract: bool = True,
                  latency: dict | None = None, tanh_below: float = 1.0) -> Census:
    """The census of ``kernel``'s lanes function as :func:`codegen.lanes.lanes_function` prints it with
    ``fixed`` and ``near``: the operations of one call, and its chain. ``contract``: products fused into the
    sums that use them (GCC). ``latency``: each kind's latency (``add``, ``mul``, ``fma``, ``div``, ``sqrt``)
    and ``cycle``, the unit codegen/balance.py's other latencies are multiplied by; by default its cycles.
    ``tanh_below``: the share of the calls of tanh where a lane's argument is below 20 in size (a friction
    law near rest), whose path is the longer (:data:`POLYNOMIALS`); the data decide it, not the program."""
    lat = dict(latency or {})
    lat.setdefault("fma", FMA_LATENCY * lat.get("cycle", 1.0))
    ops, order, outputs, invariant = _program(kernel, fixed)
    cached = set() if fixed is None else {v for v in range(len(ops)) if invariant[v]}
    needed = _closure(ops, [v for _, _, v in outputs], stop=cached)
    hot = [v for v in order if v in needed and v not in cached]
    here = set(hot)
    users: dict[int, list[int]] = {}
    for v in hot:
        for a in set(ops[v][1]):
            users.setdefault(a, []).append(v)
    stored = {v for _, _, v in outputs}
    fused: dict[int, int] = {}  # a sum -> the product it absorbed
    if contract:  # GCC's rule: a product whose every use is a sum, in order, each such use not yet fused
        for v in hot:
            uses = users.get(v, [])
            if (ops[v][0] in ("OP_MUL", "OP_SQ") and v not in stored and uses
                    and all(ops[u][0] in ("OP_ADD", "OP_SUB") and u not in fused for u in uses)):
                for u in uses:
                    fused[u] = v
    counts: Counter = Counter()
    ready: dict[int, float] = {}
    trig_done: set[int] = set()
    absorbed = set(fused.values())
    for v in hot:
        op, args, extra = ops[v]
        wait = max((ready.get(a, 0.0) for a in args), default=0.0)
        if op in _TRIG:
            arg = ops[args[0]]
            poly = "sincos_near" if arg[0] == "OP_INPUT" and arg[2][0] == 0 and arg[2][1] < near else "sincos"
            if args[0] not in trig_done:  # sin and cos of one argument: one call
                trig_done.add(args[0])
                counts.update(POLYNOMIALS[poly])
            ready[v] = wait + _POLY_LATENCY[poly] * lat.get("cycle", 1.0)
        elif op == "OP_EXP":
            counts.update(POLYNOMIALS["exp"])
            ready[v] = wait + _POLY_LATENCY["exp"] * lat.get("cycle", 1.0)
        elif op == "OP_TANH":
            for poly, share in (("tanh", 1.0 - tanh_below), ("tanh_below", tanh_below)):
                counts.update({k: share * n for k, n in POLYNOMIALS[poly].items()})
            ready[v] = wait + max(_POLY_LATENCY["tanh"], tanh_below * _POLY_LATENCY["tanh_below"]) * lat.get(
                "cycle", 1.0)
        elif op in _OP_KINDS:
            if v in absorbed:  # computed within each sum that uses it
                ready[v] = max((ready.get(a, 0.0) for a in args), default=0.0)
                continue
            if v in fused:
                counts["fma"] += 1
                ready[v] = wait + lat["fma"]
                continue
            counts.update(_OP_KINDS[op])
            ready[v] = wait + (_latency(op, lat) if _OP_KINDS[op] else 0.0)
        else:  # the C library, lane by lane
            counts["libm"] += 1
            ready[v] = wait + _latency(op, lat)
    chain = max((ready.get(v, 0.0) for _, _, v in outputs if v in here), default=0.0)
    return Census({k: counts.get(k, 0) for k in KINDS}, chain)


def _added(*parts: tuple[float, dict]) -> dict:
    """The sum of ``weight x counts`` over ``parts``, by kind."""
    return {k: sum(w * c.get(k, 0) for w, c in parts) for k in KINDS}


def loop_census(spec: LoopSpec, steps_per_sample: int, contract: bool = True, latency: dict | None = None,
                tanh_below: float = 1.0) -> dict:
    """The census of the closed loop ``spec`` (:func:`codegen.closed_loop.build_closed_loop_unit`'s kernels,
    as it prints them) per RK4 step of one run, a control sample being ``steps_per_sample`` steps.

    Returns ``counts`` by kind and their ``total``; the step's ``chain``: its four stages, each after a
    fused multiply-add of its input, the step's last combination, and a share of the sample's longest
    chain; and the parts' counts: ``stages`` (the first stage's kernel, the derivative with the record, and
    three of the derivative alone), ``rk4`` (the combinations), ``checks`` (the joints' rebase, the states'
    and signals' finite check) and ``sample`` (the controller step and the output record, a share per
    step). ``contract``, ``latency`` and ``tanh_below``: :func:`kernel_census`'s."""
    lat = dict(latency or {})
    cycle = lat.get("cycle", 1.0)
    nx, nq = spec.rhs.inputs[0].size, spec.rhs.inputs[1].size
    held, shown = _fixed(spec, spec.rhs, 2), _fixed(spec, spec.outputs, 1)
    stepping = stepping_kernel(spec)
    first, other = (kernel_census(k, fixed, nq, contract, lat, tanh_below) for k, fixed in (
        (stepping, held + shown), (spec.rhs, held)))
    once = [kernel_census(spec.step, tuple(a.name for a in _parameters(spec.step)), 0, contract, lat, tanh_below),
            kernel_census(spec.outputs, shown, 0, contract, lat, tanh_below)]
    per = max(int(steps_per_sample), 1)
    ns = len(spec.force_columns) + len(SIGNALS)
    rk4 = {"fma": 5 * nx, "add": 2 * nx}  # three stage inputs x + c k, then x + h/6 (k1 + 2 (k2 + k3) + k4)
    checks = {"add": nq + 2 * (nx + ns), "bitwise": 2 * nq + 1, "compare": nq + 2}
    staged = _added((1, first.counts), (3, other.counts))
    sample = _added(*((1 / per, c.counts) for c in once))
    counts = _added((1, staged), (1, rk4), (1, checks), (1, sample))
    chain = (first.chain + 3 * other.chain + 4 * lat.get("fma", FMA_LATENCY * cycle) + lat.get("add", 3 * cycle)
             + max(c.chain for c in once) / per)
    return {"counts": counts, "total": sum(counts.values()), "chain": chain, "stages": staged, "rk4": rk4,
            "checks": checks, "sample": sample}
