"""Tree-height reduction of a value program: sums and products regrouped by when their terms are ready.

A symbolic backend writes a sum of many terms as a left-leaning chain, ``((a + b) - c) + d ...``,
in whatever order its expression tree had; when a term that comes late (one behind a square root and
a division, say) sits near the front, every later addition waits for it. A run alone is bound by such
chains, not by the number of operations. This pass flattens each chain of additions (and negations)
and each chain of products whose inner results are used once, and rebuilds it as a tree that
combines the two terms ready first, then the next two (Huffman's construction on ready times, from a
rough latency per operation), so the late term meets an almost finished sum. Terms that depend on
the fixed inputs alone are combined first, among themselves, so their sum or product is one more
value computed once, outside the hot code.

The operations are the same kind and about as many; the grouping differs, so results change within
rounding (a sum of n terms: n - 1 roundings either way), NaN, infinities and signed zeros come out as
in any grouping, and an intermediate product may overflow where the backend's order did not (factors
beyond about 1e154 on both sides of one below 1e-154: not the magnitudes of a robot's numbers). Every
lane runs the same program, so a state gives the same bits wherever it sits in a batch. The pass is
deterministic: ties break on the values' order, so the same program gives the same C.

A program here is :func:`codegen.lanes._program`'s: ``ops[v] = (operation, argument values, extra)``
in single assignment, ``invariant[v]`` whether ``v`` depends on the fixed inputs alone, and the
outputs' values.
"""

from __future__ import annotations

import heapq

#: rough latencies in cycles (a recent x86-64 core); only their order matters much
LATENCY = {"OP_INPUT": 0, "OP_CONST": 0, "OP_ASSIGN": 0, "OP_NEG": 1, "OP_FABS": 1, "OP_COPYSIGN": 1,
           "OP_IF_ELSE_ZERO": 2, "OP_FMIN": 2, "OP_FMAX": 2, "OP_LT": 2, "OP_LE": 2, "OP_EQ": 2, "OP_NE": 2,
           "OP_NOT": 2, "OP_AND": 2, "OP_OR": 2, "OP_INV": 13, "OP_DIV": 13, "OP_SQRT": 20, "OP_SIN": 25,
           "OP_COS": 25, "OP_EXP": 30, "OP_TANH": 15}
#: anything not listed (additions, products, the C library's functions as a floor)
DEFAULT_LATENCY = 3
_SUM = ("OP_ADD", "OP_SUB", "OP_NEG")


def ready_times(ops, invariant, order) -> list[int]:
    """Each value's ready time on the longest path from the hot inputs (invariant values: 0), in
    ``order`` (arguments first)."""
    t = [0] * len(ops)
    for v in order:
        op, args, _ = ops[v]
        t[v] = 0 if invariant[v] else max((t[a] for a in args), default=0) + LATENCY.get(op, DEFAULT_LATENCY)
    return t


def balance(ops: list, invariant: list, outputs: list, order: list) -> None:
    """Regroup ``ops``' sums and products in place (new values appended, ``invariant`` extended);
    ``order`` lists the values arguments first."""
    uses, users = [0] * len(ops), [[] for _ in ops]
    for u, (_, args, _) in enumerate(ops):
        for a in args:
            uses[a] += 1
            users[a].append(u)
    for _, _, v in outputs:
        uses[v] += 2  # an output is a root: never folded into a user
    t = ready_times(ops, invariant, order)

    def kinds_of(op):
        return _SUM if op in _SUM else ("OP_MUL",) if op == "OP_MUL" else ()

    def inner(v, kinds) -> bool:  # a value folded into its one user's chain
        return ops[v][0] in kinds and uses[v] == 1 and not invariant[v]

    def terms(root, kinds):
        """``root``'s sum as ``[(sign, value)]``, or its product as ``[(1, value)]``."""
        out, stack = [], [(1, root)]
        while stack:
            sign, v = stack.pop()
            op, args = ops[v][:2]
            if v != root and not inner(v, kinds):
                out.append((sign, v))
            elif op == "OP_NEG":
                stack.append((-sign, args[0]))
            elif op == "OP_SUB":
                stack += [(sign, args[0]), (-sign, args[1])]
            else:
                stack += [(sign, args[0]), (sign, args[1])]
        return out

    def new(op, args) -> int:
        ops.append((op, args, None))
        invariant.append(all(invariant[a] for a in args))
        t.append(0 if invariant[-1] else max(t[a] for a in args) + LATENCY.get(op, DEFAULT_LATENCY))
        return len(ops) - 1

    for root in order:
        kinds = kinds_of(ops[root][0])
        if not kinds or invariant[root] or (inner(root, kinds) and ops[users[root][0]][0] in kinds):
            continue  # not a chain, computed once, or part of a longer chain (regrouped with its root)
        parts = terms(root, kinds)
        if len(parts) < 3:
            continue
        heap = [(t[v], v, sign) for sign, v in parts]  # by ready time, then by value: deterministic
        heapq.heapify(heap)
        while len(heap) > 2:
            (_, a, sa), (_, b, sb) = heapq.heappop(heap), heapq.heappop(heap)
            op, s = _combine(kinds, a, sa, b, sb)
            v = new(*op)
            heapq.heappush(heap, (t[v], v, s))
        (_, a, sa), (_, b, sb) = heap
        op, s = _combine(kinds, a, sa, b, sb)
        # the whole sum negated: its positive part as a value, then one negation
        ops[root] = ("OP_NEG", (new(*op),), None) if s < 0 else (*op, None)


def _combine(kinds, a, sa, b, sb):
    """``sa a + sb b`` (a product: ``a b``) as ``((operation, arguments), sign)``."""
    if kinds != _SUM:
        return ("OP_MUL", (a, b)), 1
    if sa == sb:
        return ("OP_ADD", (a, b)), sa
    return ("OP_SUB", (a, b) if sa > 0 else (b, a)), 1
