"""The machine's floating-point peak at the lanes' vector width, measured (the program: ``c/peak.c.j2``).

Each kind of vector operation the lanes execute is timed by a C program compiled as the lanes are (the
runtime's flags, ``hybrid_lanes.h``'s vector of ``HL_W`` doubles): its throughput, with independent
accumulators kept in registers, and its latency, one operation waiting on the last; pairs of kinds
timed together say which share a unit (a pair that takes as long as its two apart shares one; one that
takes as long as the slower of them does not). A chain of integer additions times the cycle.
"""

from __future__ import annotations

from hybrid.bench.harness import c_program_output
from hybrid.bench.templates import render

#: the kinds timed (codegen/census.py's), each as the C of one operation on the accumulator ``a`` (``b``
#: within 1e-9 of 1, ``c`` tiny: the accumulators stay near 1); ``select`` is a comparison and a blend
#: (one of each a time), ``bitwise`` an absolute value; and ``load``, a vector read from the first level
#: cache (``m``, taken in by a bitwise operation), which the census does not count (a kernel's reads of
#: what a run holds and of the compiler's spills are the compiler's choice)
KINDS = {"fma": "a * b + c", "mul": "a * b", "add": "a + c", "div": "a / b", "sqrt": "hl_sqrt(a)",
         "select": "hl_select(a < b, c, a)", "bitwise": "hl_fabs(a)", "load": "(hl_v)((hl_i)a ^ (hl_i)m)"}
#: the pairs timed together, half the accumulators each: whether adds run beside fused multiply-adds, a
#: division beside them, a square root beside a division
PAIRS = (("fma", "add"), ("fma", "div"), ("div", "sqrt"))
#: independent accumulators of a throughput: more than any latency in cycles over the cycles an
#: operation takes, and few enough to stay in 16 registers with the two operands
ACCUMULATORS = 12


def peak_source() -> str:
    """The C of the peak's program (``c/peak.c.j2``) for :data:`KINDS` and :data:`PAIRS`."""
    kinds = [{"name": k, "op": op, "alt": op} for k, op in KINDS.items()]
    kinds += [{"name": f"{a}_{b}", "op": KINDS[a], "alt": KINDS[b]} for a, b in PAIRS]
    return render("peak.c.j2", kinds=kinds, accumulators=ACCUMULATORS)


def parse_peak(text: str) -> dict:
    """The program's output as ``{"lanes": W, "cycle": ns, "kinds": {kind: (throughput, latency)}}``, the
    times in ns per vector operation (of ``W`` lanes); a pair's are per operation of either kind."""
    out: dict = {"kinds": {}}
    for line in text.splitlines():
        name, *values = line.split()
        if name == "lanes":
            out["lanes"] = int(values[0])
        elif name == "cycle":
            out["cycle"] = float(values[0])
        else:
            out["kinds"][name] = tuple(float(v) for v in values)
    return out


def machine_peak(operations: int = 20_000, repeat: int = 41) -> dict:
    """:func:`parse_peak` of the program run for ``operations`` operations per accumulator, ``repeat``
    times (the medians), with the lanes' flags on this machine."""
    return parse_peak(c_program_output(peak_source(), (), (str(operations), str(repeat))))


def shared(peak: dict, a: str, b: str) -> float:
    """How much kinds ``a`` and ``b`` share a unit, from their pair's time: 1 when together they take as
    long as one after the other, 0 when as long as the slower alone."""
    ta, tb = peak["kinds"][a][0], peak["kinds"][b][0]
    together = 2 * peak["kinds"][f"{a}_{b}"][0]  # one of each
    return min(max((together - max(ta, tb)) / min(ta, tb), 0.0), 1.0)
