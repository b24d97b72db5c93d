"""The controller as standalone C (:meth:`hybrid.Controller.generate`): each step call timed alone
in C replaying a recorded run, its code size and its compile time."""

from __future__ import annotations

import struct
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from hybrid.bench.targets import STANDALONE_COMPILE, STANDALONE_P999, STANDALONE_SIZE, STANDALONE_STEP
from hybrid.errors import HybridError
from hybrid.experiments.panda import panda_experiment
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.native import compiler
from hybrid.simulation.runner import simulate

#: the arms of the standalone-controller rows: their experiments (the controller and a run to replay)
STANDALONE = {"paper": paper_experiment, "ur5": tracing_experiment, "panda": panda_experiment}

DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "%(prefix)s.h"
#define W (2 * %(PREFIX)s_NQ + 6 + %(target)d)  /* a sample: q, qd, wrench (and the desired point) */
static long long now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}
/* argv: samples file, number of samples, sample time, calls, output file: the calls' durations [ns],
   then those of back-to-back clock reads (the timer's own cost) */
int main(int argc, char **argv) {
    long n, calls, i, k, warm, pairs = 100000;
    double T, *s, tau[%(PREFIX)s_NQ], sink = 0.0;
    long long *d, t0, t1;
    %(prefix)s_controller c;
    FILE *f;
    int st;
    if (argc != 6) return 2;
    n = atol(argv[2]); T = atof(argv[3]); calls = atol(argv[4]);
    s = malloc(sizeof(double) * W * n);
    d = malloc(sizeof(long long) * (calls + pairs));
    if (!s || !d || !(f = fopen(argv[1], "rb")) || fread(s, sizeof(double) * W, n, f) != (size_t)n) return 2;
    fclose(f);
    memset(d, 0, sizeof(long long) * (calls + pairs));  /* the pages touched before timing */
    for (i = 0; i < pairs; ++i) { t0 = now_ns(); t1 = now_ns(); d[calls + i] = t1 - t0; }
    %(prefix)s_controller_init(&c);
    /* one pass through the samples untimed, then the timed calls. Each pass is the recorded run again:
       a new run (reset, untimed) from t = 0, t advancing by T every call, so every call is on time */
    warm = n;
    for (i = -warm; i < calls; ++i) {
        k = (i + warm) %% n;
        const double *x = s + W * k;
        double t = (double)k * T;
        if (k == 0) %(prefix)s_controller_reset(&c);
%(set_target)s
        t0 = now_ns();
        st = %(prefix)s_controller_step(&c, t, x, x + %(PREFIX)s_NQ, x + 2 * %(PREFIX)s_NQ, tau);
        t1 = now_ns();
        if (st != %(PREFIX)s_OK) {
            fprintf(stderr, "call %%ld (sample %%ld, t = %%.6f s): status %%s\n", i, k, t, %(prefix)s_status_name(st));
            return 3;
        }
        if (i >= 0) d[i] = t1 - t0;
        sink += tau[0];
    }
    if (!(f = fopen(argv[5], "wb")) || fwrite(d, sizeof(long long), calls + pairs, f) != (size_t)(calls + pairs))
        return 2;
    fclose(f);
    fprintf(stderr, "%%g\n", sink);
    return 0;
}
"""


def recorded_samples(exp) -> tuple[np.ndarray, bool]:
    """The control samples of a simulated run of ``exp``, one row each: q, qd, the sensor's wrench,
    and (when the controller follows a path) the desired point the caller writes into ``target``;
    and whether that last part is there."""
    run, plant, ctrl = simulate(exp), exp.plant(), exp.build_controller()
    nq, every = plant.nq, exp.steps_per_sample
    rows = []
    for k in range(exp.n_samples):
        x = run.state[k * every]
        row = [x[:nq], x[nq:2 * nq], plant.sensor_wrench(x)]
        if ctrl.path is not None:
            row.append(ctrl._desired(k * exp.sample_time))
        rows.append(np.concatenate(row))
    return np.array(rows), ctrl.path is not None


def text_bytes(obj: Path) -> int:
    """The size of the code in an ELF object: its ``.text`` sections (``.text``, ``.text.hot``, ...) [bytes]."""
    data = obj.read_bytes()
    if data[:4] != b"\x7fELF":
        raise HybridError(f"{obj.name} is not an ELF object")
    wide, order = data[4] == 2, "<" if data[5] == 1 else ">"
    if wide:
        shoff, = struct.unpack_from(order + "Q", data, 0x28)
        shentsize, shnum, shstrndx = struct.unpack_from(order + "HHH", data, 0x3A)
    else:
        shoff, = struct.unpack_from(order + "I", data, 0x20)
        shentsize, shnum, shstrndx = struct.unpack_from(order + "HHH", data, 0x2E)

    def section(i):  # (name offset, offset, size)
        base = shoff + i * shentsize
        if wide:
            name, = struct.unpack_from(order + "I", data, base)
            off, size = struct.unpack_from(order + "QQ", data, base + 0x18)
        else:
            name, = struct.unpack_from(order + "I", data, base)
            off, size = struct.unpack_from(order + "II", data, base + 0x10)
        return name, off, size

    strtab = section(shstrndx)[1]
    total = 0
    for i in range(shnum):
        name, _, size = section(i)
        label = data[strtab + name:data.index(b"\0", strtab + name)].decode()
        if label == ".text" or label.startswith(".text."):
            total += size
    return total


def standalone_step(folder: Path, prefix: str, samples: np.ndarray, target: bool, sample_time: float,
                    flags: list[str], calls: int) -> dict:
    """Compile the generated controller ``folder/prefix.c`` with ``flags`` (timed), and time ``calls``
    calls of its step, one by one, replaying ``samples`` on the sample clock. Returns the compile time
    [s], the object's ``.text`` [bytes], the timer's overhead and the calls' median, p99, p99.9 and
    maximum [ns], the overhead subtracted."""
    cc, _ = compiler.compiler()
    tag = "".join(c for c in "_".join(flags) if c.isalnum() or c == "_")
    obj, exe, out = (folder / f"{prefix}_{tag}{ext}" for ext in (".o", "", ".durations"))
    t0 = time.perf_counter()
    subprocess.run([cc, *flags, "-c", str(folder / f"{prefix}.c"), "-o", str(obj)], check=True, capture_output=True)
    compile_s = time.perf_counter() - t0
    nq = (samples.shape[1] - 6 - (9 if target else 0)) // 2
    set_target = (f"        memcpy(c.target, x + {2 * nq + 6}, sizeof c.target);" if target else "")
    driver = folder / f"{prefix}_driver.c"
    driver.write_text(DRIVER % {"prefix": prefix, "PREFIX": prefix.upper(), "target": 9 if target else 0,
                                "set_target": set_target})
    subprocess.run([cc, *flags, f"-I{folder}", str(driver), str(obj), "-o", str(exe), "-lm"],
                   check=True, capture_output=True)
    data = folder / f"{prefix}_samples.bin"
    np.ascontiguousarray(samples, "<f8").tofile(data)
    proc = subprocess.run([str(exe), str(data), str(len(samples)), repr(sample_time), str(calls), str(out)],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise HybridError(f"the {prefix} controller's timing driver failed (exit {proc.returncode}): "
                          f"{proc.stderr.strip() or 'no message'}")
    d = np.fromfile(out, "<i8")
    timer = float(np.median(d[calls:]))
    step = d[:calls] - timer
    p50, p99, p999 = np.percentile(step, [50, 99, 99.9], method="higher")
    return {"compile_s": compile_s, "text": text_bytes(obj), "timer_ns": timer, "median": float(p50),
            "p99": float(p99), "p99.9": float(p999), "max": float(step.max())}


def _spread(r: dict) -> str:
    return f"p99 {r['p99']:.0f}, p99.9 {r['p99.9']:.0f}, max {r['max']:.0f} ns"


def standalone_benchmarks(quick: bool, add) -> None:
    """The controller as standalone C (:meth:`hybrid.Controller.generate`) for each arm of ``STANDALONE``:
    its step's per-call times replaying a recorded run (median, p99, p99.9, maximum), its code size and
    compile time, with the runtime's flags and with plain ``-O2``. With ``quick``: the paper's arm, 1e4 calls."""
    calls = 10_000 if quick else 1_000_000
    bench_flags = [f for f in compiler.flags(compiler.compiler()[1]) if f != "-fPIC"]
    builds = {" ".join(bench_flags): bench_flags, "-O2": ["-O2"]}
    for name, factory in STANDALONE.items():
        if quick and name != "paper":
            continue
        exp = factory()
        samples, target = recorded_samples(exp)
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            exp.build_controller().generate(folder, name)
            got = {label: standalone_step(folder, name, samples, target, exp.sample_time, flags, calls)
                   for label, flags in builds.items()}
        (label, main), (other_label, other) = got.items()
        note = (f"{calls:,} calls, each timed alone by clock_gettime less the timer's own {main['timer_ns']:.0f} ns "
                f"(back-to-back reads); a {len(samples)}-sample run replayed, reset between passes; {label}")

        add(f"{name}: {STANDALONE_STEP}", main["median"], ratio=f"{_spread(main)}; {note}",
            **{k: main[k] for k in ("p99", "p99.9", "max", "timer_ns")}, calls=calls, flags=label)
        add(f"{name}: {STANDALONE_P999}", main["p99.9"], ratio=f"{main['p99.9'] / main['median']:.2f}x the median",
            of_median=main["p99.9"] / main["median"])
        add(f"{name}: {STANDALONE_STEP}, {other_label}", other["median"], ratio=_spread(other),
            **{k: other[k] for k in ("p99", "p99.9", "max", "timer_ns")}, calls=calls, flags=other_label)
        add(f"{name}: {STANDALONE_SIZE}", main["text"] / 1024, "KiB",
            ratio=f"{main['text']:,} bytes; {other_label}: {other['text']:,} bytes", bytes=main["text"],
            bytes_other=other["text"])
        add(f"{name}: {STANDALONE_COMPILE}", main["compile_s"], "s",
            ratio=f"{label}; {other_label}: {other['compile_s']:.2f} s", other_s=other["compile_s"])
