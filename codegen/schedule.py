"""The order of a CasADi kernel's C statements, chosen to keep few values alive and the long chains going.

CasADi prints an SX function as straight-line statements ``aN=...;`` in the order of a depth-first
walk from its outputs: a value the walk reaches early for one output and needs again for another
stays alive in between, and a kernel with more live values than the processor has registers stores
and reloads them (for the recursive Newton-Euler algorithm, about a third of its instructions). The
compiler's scheduler moves statements only within a basic block, and the inline sines and cosines
(:mod:`.casadi_backend`) split the code into many.

:func:`reorder` lists the statements again, each once, after all it reads, choosing each time among
those whose operands are computed: first the one that leaves the fewest values alive (the operands
it is the last to read, net of the value it defines); of equals, an operation before a read of an
array or a constant (an operation takes those from memory), then the one that starts the longest
chain of statements to an output (a sine, a cosine or a ``tanh`` counted as twenty operations: begun
early, their latency overlaps the rest), then the one reading the most recent value. Every value
gets its own name; the operations are CasADi's, unchanged: the results are the same but where the
compiler fuses a product and a sum into one multiply-add, which it may pair otherwise in the new
order (a rounding).

Two orders are on offer (:data:`ORDERS`, a kernel's ``order``): ``"fewest_alive"``, the choice as
above, and ``"longest_chain"``, the longest chain first, then the fewest alive and the rest as above:
more values alive, hence more spills, but every long chain begun as early as it can be. It is the faster
where a kernel's time is its chains' (a redundant task's law: its two Cholesky factorisations, each a chain
of square roots and divisions); the rounding is the same kind (the multiply-adds paired otherwise).
``"printed"`` leaves the order CasADi printed.

One rewrite comes first (:func:`_selects`): CasADi writes a choice ``if_else(c, a, b)`` as
``(c?a:0) + (!c?b:0)``, a negation, two selects and a sum, where C has the one select ``(c?a:b)``. Its
value is the same for every ``c`` (a NaN or any non-zero ``c`` is true in both), ``a`` and ``b`` (the
unchosen side, even infinite or NaN, is not added), but for the sign of a zero: ``-0`` chosen stays
``-0`` where the sum made it ``+0``.
"""

from __future__ import annotations

import re

#: a statement of CasADi's straight-line C: ``aN=expression;`` or ``res[i][j]=expression;``
_STATEMENT = re.compile(r"^  (a\d+|res\[\d+\]\[\d+\])=(.*);$")
#: a local's name in an expression
_LOCAL = re.compile(r"\ba(\d+)\b")
#: an expression that only reads: an input array's element or a number
_READ = re.compile(r"arg\[\d+\]\[\d+\]|-?[0-9.]+(?:e[-+]?\d+)?")
#: an operand as :func:`_parse` writes it
_OPERAND = re.compile(r"@(\d+)@")
#: a call to a sine, a cosine or a tanh, and the operations its latency is counted as
_CALL, _CALL_COST = re.compile(r"\b(?:hybrid_sin|hybrid_cos|tanh)\("), 20
_DECLARATION = re.compile(r"^  casadi_real a\d+(?:, a\d+)*;$")
#: the orders a kernel's statements may be printed in (module docstring)
ORDERS = ("printed", "fewest_alive", "longest_chain")


def reorder(function: str, order: str = "fewest_alive") -> str:
    """``function`` (one CasADi function's C) with its statements in ``order`` (:data:`ORDERS`, the module's
    docstring); unchanged for ``"printed"`` or where it holds any line but declarations of locals, the
    statements and what CasADi puts before and after them (reading no local)."""
    if order not in ORDERS:
        raise ValueError(f"order {order!r}: not one of {', '.join(ORDERS)}")
    if order == "printed":
        return function
    lines = function.split("\n")
    first = next((i for i, line in enumerate(lines) if _STATEMENT.match(line)), None)
    if first is None:
        return function
    last = max(i for i, line in enumerate(lines) if _STATEMENT.match(line))
    if any(not _STATEMENT.match(line) for line in lines[first:last + 1]):
        return function
    # a line around the statements that reads a local (CasADi's guarded write ``if (res[0]!=0) res[0][0]=a0;``)
    # would read a value renamed or dropped
    if any(_LOCAL.search(line) and not _DECLARATION.match(line) for line in lines[:first] + lines[last + 1:]):
        return function
    nodes = _selects(_parse(lines[first:last + 1]))
    chosen = _schedule(nodes, chains_first=order == "longest_chain")
    width = len(str(len(nodes)))
    name = {k: f"a{k:0{width}d}" for k, node in enumerate(nodes) if not node[0].startswith("res")}
    body = [f"  {name.get(k, nodes[k][0])}={_OPERAND.sub(lambda m: name[int(m.group(1))], nodes[k][1])};"
            for k in chosen]
    head = [line for line in lines[:first] if not _DECLARATION.match(line)]
    declarations = [f"  casadi_real {', '.join(list(name.values())[i:i + 12])};" for i in range(0, len(name), 12)]
    return "\n".join(head + declarations + body + lines[last + 1:])


def _parse(statements: list[str]) -> list[tuple[str, str, list[int]]]:
    """Each statement as ``(target, expression with operands as @k@, operands k)``, the locals renamed
    to the statement that defines each value (CasADi reuses a local for successive values)."""
    defined: dict[str, int] = {}
    nodes = []
    for line in statements:
        target, expression = _STATEMENT.match(line).groups()
        operands: list[int] = []

        def operand(m, operands=operands):
            operands.append(defined[f"a{m.group(1)}"])
            return f"@{operands[-1]}@"

        nodes.append((target, _LOCAL.sub(operand, expression), sorted(set(operands))))
        if target.startswith("a"):
            defined[target] = len(nodes) - 1
    return nodes


#: ``(c?a:0)``, ``(!c)`` and a sum of two operands, as :func:`_parse` writes them
_HALF, _NOT = re.compile(r"\(@(\d+)@\?@(\d+)@:0\)"), re.compile(r"\(!@(\d+)@\)")
_SUM = re.compile(r"\(@(\d+)@\+@(\d+)@\)")


def _selects(nodes: list[tuple[str, str, list[int]]]) -> list[tuple[str, str, list[int]]]:
    """``nodes`` with each ``(c?a:0) + (!c?b:0)`` (the two halves read by the sum alone) written ``(c?a:b)``
    (module docstring), without the statements then read by none, renumbered."""
    readers = [0] * len(nodes)
    for _, _, operands in nodes:
        for j in operands:
            readers[j] += 1
    nodes = list(nodes)
    for k, (target, expression, _) in enumerate(nodes):
        total = _SUM.fullmatch(expression)
        halves = [int(i) for i in total.groups()] if total else []
        parts = [_HALF.fullmatch(nodes[i][1]) for i in halves]
        if not halves or not all(parts) or any(readers[i] != 1 for i in halves):
            continue
        (c, a), (d, b) = ((int(x) for x in part.groups()) for part in parts)
        if _negates(nodes[d][1], c):
            nodes[k] = (target, f"(@{c}@?@{a}@:@{b}@)", sorted({c, a, b}))
        elif _negates(nodes[c][1], d):
            nodes[k] = (target, f"(@{d}@?@{b}@:@{a}@)", sorted({d, a, b}))
    kept = [False] * len(nodes)
    for k in reversed(range(len(nodes))):
        kept[k] = kept[k] or nodes[k][0].startswith("res")
        if kept[k]:
            for j in nodes[k][2]:
                kept[j] = True
    number = {k: i for i, k in enumerate(k for k in range(len(nodes)) if kept[k])}
    return [(target, _OPERAND.sub(lambda m: f"@{number[int(m.group(1))]}@", expression),
             [number[j] for j in operands]) for k, (target, expression, operands) in enumerate(nodes) if kept[k]]


def _negates(expression: str, c: int) -> bool:
    """Whether ``expression`` is ``(!c)``."""
    negation = _NOT.fullmatch(expression)
    return negation is not None and int(negation.group(1)) == c


def _schedule(nodes: list[tuple[str, str, list[int]]], chains_first: bool) -> list[int]:
    """The statements' order: a list schedule that keeps the fewest values alive, greedily; with
    ``chains_first``, that starts the longest chain first."""
    users: list[list[int]] = [[] for _ in nodes]
    for k, (_, _, operands) in enumerate(nodes):
        for j in operands:
            users[j].append(k)
    reads = [not operands and _READ.fullmatch(expression) is not None for _, expression, operands in nodes]
    height = [0] * len(nodes)  # the longest chain of statements from each to an output
    for k in reversed(range(len(nodes))):
        own = 0 if reads[k] else _CALL_COST if _CALL.search(nodes[k][1]) else 1
        height[k] = own + max((height[u] for u in users[k]), default=0)
    unread = [len(u) for u in users]  # the readers of each value not yet placed
    waiting = [len(operands) for _, _, operands in nodes]
    ready = [k for k, count in enumerate(waiting) if count == 0]
    placed_at: dict[int, int] = {}
    order: list[int] = []

    def cost(k: int) -> tuple:
        target, _, operands = nodes[k]
        freed = sum(1 for j in operands if unread[j] == 1)
        alive = 0 if target.startswith("res") or not users[k] else 1
        recent = max((placed_at[j] for j in operands), default=-1)
        if chains_first:
            return -height[k], alive - freed, reads[k], -recent, k
        return alive - freed, reads[k], -height[k], -recent, k

    while ready:
        k = min(ready, key=cost)
        ready.remove(k)
        placed_at[k] = len(order)
        order.append(k)
        for j in nodes[k][2]:
            unread[j] -= 1
        for u in users[k]:
            waiting[u] -= 1
            if waiting[u] == 0:
                ready.append(u)
    return order
