"""The controller as standalone C (:meth:`hybrid.Controller.generate`): each step call timed alone
in C replaying a recorded run (the driver: ``c/driver.c.j2``), its code size and its compile time."""

from __future__ import annotations

import struct
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from hybrid.bench.targets import STANDALONE_COMPILE, STANDALONE_P999, STANDALONE_SIZE, STANDALONE_STEP
from hybrid.bench.templates import render
from hybrid.errors import HybridError
from hybrid.experiments.panda import panda_experiment
from hybrid.experiments.paper import paper_experiment
from hybrid.experiments.tracing import tracing_experiment
from hybrid.native import compiler
from hybrid.simulation.runner import simulate
from hybrid.spec.controller_step import CONTROLLER_STEP, WRENCH

#: the arms of the standalone-controller rows: their experiments (the controller and a run to replay)
STANDALONE = {"paper": paper_experiment, "ur5": tracing_experiment, "panda": panda_experiment}
#: the desired point's numbers in a sample (the step's ``target``: point, velocity, ZYX angles)
TARGET = int(CONTROLLER_STEP.port("target").size)


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


def driver_source(prefix: str, width: int, target: bool) -> str:
    """The C program timing the step of the standalone controller ``prefix``, call by call, on samples
    of ``width`` numbers: q, qd, the wrench and (with ``target``) the desired point."""
    target_size = TARGET if target else 0
    return render("driver.c.j2", prefix=prefix, PREFIX=prefix.upper(), wrench=len(WRENCH), target=target_size,
                  nq=(width - len(WRENCH) - target_size) // 2)


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
    driver = folder / f"{prefix}_driver.c"
    driver.write_text(driver_source(prefix, samples.shape[1], target))
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
