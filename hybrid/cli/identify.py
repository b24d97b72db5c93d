"""``python -m hybrid identify``: a robot's dynamics identified from a log of its motion and torques (a CSV or
Parquet table), reported, and the identified robot written."""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.cli import common
from hybrid.errors import HybridError
from hybrid.experiments.serialisation import robot_to_dict
from hybrid.models.dynamics_identification import POORLY_EXCITED, DynamicsIdentification, identify_dynamics
from hybrid.models.robot import Robot
from hybrid.models.urdf_writer import robot_urdf_text
from hybrid.spec.chain import linear_parameter_units
from hybrid.validate import listed, listed_in_full

IDENTIFY = ("Identify a robot's dynamics from a log of its torques. LOG is a CSV or Parquet table "
            "with the columns t [s], q[JOINT] and tau[JOINT] for each joint of the URDF's chain to --tip "
            "(qd[JOINT] and qdd[JOINT] too when they were measured), one row per sample, uniform in time. The "
            "positions and torques are low-pass filtered alike (--cutoff), differentiated, fitted by least "
            "squares and made physically consistent. Prints the base parameters with their standard deviations, "
            "the residual per joint, the condition number and the poorly excited parameters; --out writes the "
            "identified robot.")
#: the table formats read, by file suffix
READERS = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}
#: the robot file formats written, by file suffix: a URDF (``Robot.from_urdf(FILE, tip="tip")`` reads it) or
#: the JSON of an experiment's file
WRITERS = {".urdf": lambda robot: robot_urdf_text(robot),
           ".json": lambda robot: json.dumps(robot_to_dict(robot), indent=2) + "\n"}


def add_parser(sub) -> None:
    p = common.command(sub, "identify", IDENTIFY, run)
    p.add_argument("log", metavar="LOG", help="the log: a .csv or .parquet table (columns t, q[JOINT], tau[JOINT], "
                                              "optionally qd[JOINT], qdd[JOINT])")
    p.add_argument("--urdf", required=True, metavar="FILE", help="the robot's URDF file (its nominal model)")
    p.add_argument("--tip", required=True, metavar="LINK", help="the link that ends the chain (e.g. tool0)")
    p.add_argument("--cutoff", type=_hertz, metavar="HZ",
                   help="the low-pass filter's cutoff [Hz], below the log's Nyquist frequency (default: 20 Hz, at "
                        "most a quarter of the sampling rate; 5 to 10 times the excitation's highest frequency)")
    p.add_argument("--out", metavar="FILE",
                   help="write the identified robot (physically consistent) to FILE: a .urdf file (its tip link "
                        "named tip: hybrid.Robot.from_urdf(FILE, tip='tip') reads it) or a .json file (an "
                        "experiment's file's robot: hybrid.experiments.serialisation.robot_from_dict)")
    p.add_argument("--force", action="store_true", help="overwrite --out")
    common.add_verbose(p)


def _hertz(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"{text!r}: give the cutoff in Hz, a positive number")
    return value


def read_log(path, joints) -> dict[str, np.ndarray]:
    """The log's columns as arrays: ``t`` (N,), ``q`` and ``tau`` (N, n), ``qd`` and ``qdd`` (N, n) when
    the table has them for every joint (else None); ``unused``, the names of the columns not read."""
    path = files.regular_file(path, "log")
    kind = READERS.get(path.suffix.lower())
    if kind is None:
        raise HybridError(f"the log {path} is neither .csv nor .parquet; give a CSV or Parquet table")
    import pandas as pd

    try:
        if kind == "parquet":
            try:
                import pyarrow  # noqa: F401  (pandas reads Parquet through it)
            except ImportError:
                raise HybridError("reading a Parquet log needs pyarrow: pip install pyarrow (or give a CSV log)") \
                    from None
            table = pd.read_parquet(path)
        else:
            table = pd.read_csv(path)
    except HybridError:
        raise
    except Exception as exc:  # pandas' and pyarrow's parser errors have no common base
        raise HybridError(f"cannot read the log {path} as {kind.upper()} ({str(exc).splitlines()[0][:120]}); "
                          "give a table with a header row") from None
    columns = {str(c).strip(): c for c in table.columns}
    wanted = {"t": ["t"], **{what: [f"{what}[{j}]" for j in joints] for what in ("q", "tau", "qd", "qdd")}}
    missing = [c for what in ("t", "q", "tau") for c in wanted[what] if c not in columns]
    if missing:
        raise HybridError(f"the log {path.name} has no column {listed(missing, 3)}; give the columns t, q[JOINT] and "
                          f"tau[JOINT] for the joints {listed(joints)}" + listed_in_full(joints))
    out: dict[str, np.ndarray | None] = {}
    for what, names in wanted.items():
        present = [n in columns for n in names]
        if not all(present):
            if any(present):  # velocities and accelerations: all the joints' or none
                raise HybridError(f"the log has {what}[JOINT] columns but no {names[present.index(False)]}; give "
                                  f"{what} for every joint, or for none")
            out[what] = None
            continue
        arrays = []
        for name in names:
            values = pd.to_numeric(table[columns[name]], errors="coerce")
            bad = values.isna() & table[columns[name]].notna()
            if bad.any():
                row = int(np.argmax(bad.to_numpy()))
                raise HybridError(f"the log's column {name} has {table[columns[name]].iloc[row]!r} in data row {row}; "
                                  "give numbers")
            arrays.append(values.to_numpy(dtype=float))
        out[what] = arrays[0] if what == "t" else np.column_stack(arrays)
    read = {name for names in wanted.values() for name in names}
    out["unused"] = [name for name in columns if name not in read]
    return out


def report(found: DynamicsIdentification, log: str) -> str:
    """The identification in words: the samples, the conditioning, each base parameter, the residuals."""
    robot = found.nominal_robot
    units = dict(zip(found.base.names, linear_parameter_units(robot.chain)))
    filtered = "taken as it is" if found.cutoff_hz is None else f"filtered at {found.cutoff_hz:g} Hz"
    lines = [f"identified the dynamics of {robot.name} from {log}: {found.log_samples:,} samples at "
             f"{1 / found.sample_time:.6g} Hz, {filtered}; {found.samples:,} used (the filter's edges dropped, "
             "thinned to twice the cutoff)",
             f"condition number of the base regressor: {found.condition:.4g}", ""]
    consistent = found.consistent if found.consistent is not None else np.full(len(found.names), np.nan)
    width = max(len(n) for n in found.names)
    lines.append(f"{'base parameter':<{width}}  {'estimate':>12}  {'+- std':>10}  {'consistent':>12}  "
                 f"{'nominal':>12}  unit")
    for name, e, s, c, n in zip(found.names, found.estimate, found.std, consistent, found.nominal):
        lines.append(f"{name:<{width}}  {e:>12.6g}  {s:>10.3g}  {c:>12.6g}  {n:>12.6g}  {units.get(name, '')}")
    lines += ["(each base parameter is the one named plus the parameters the torques cannot tell from it: "
              "hybrid.base_parameters(robot).base_names())", "", "residual RMS per joint (least squares, consistent):"]
    joint_width = max(len(j) for j in robot.joint_names)
    rms = found.consistent_residual_rms if found.consistent_residual_rms is not None else found.residual_rms
    effort = dict(revolute="N m", prismatic="N")
    for joint, kind, a, b in zip(robot.joint_names, (j.kind for j in robot.chain.joints), found.residual_rms, rms):
        lines.append(f"  {joint:<{joint_width}}  {a:.4g}  {b:.4g} {effort[kind]}")
    poorly = ", ".join(found.poorly_excited) if found.poorly_excited else "none"
    lines.append(f"poorly excited (standard deviation over {100 * POORLY_EXCITED:g} % of the size): {poorly}")
    return "\n".join(lines)


def run(args) -> int:
    out = None
    if args.out is not None:
        out = files.output_path(args.out)
        if out.suffix.lower() not in WRITERS:
            raise HybridError(f"--out {out} is neither .urdf nor .json; give FILE.urdf or FILE.json")
        if out.exists() and not args.force:  # before the work, not after it
            raise HybridError(f"--out {out} exists; choose another name or pass --force to overwrite it")
    with args.report.step(f"reading the robot of {args.urdf} and the log {args.log}"):
        robot = Robot.from_urdf(args.urdf, args.tip)
        log = read_log(args.log, robot.joint_names)
    with args.report.step(f"identifying from {len(log['t']):,} samples"):
        found = identify_dynamics(robot, log["t"], log["q"], log["tau"], qd=log["qd"], qdd=log["qdd"],
                                  cutoff_hz=args.cutoff)
    print(report(found, Path(args.log).name))
    if log["unused"]:  # said, not silently passed over: a misspelt joint's column would be one
        print(f"columns not read (not t, q, qd, qdd or tau of the joints {listed(robot.joint_names)}): "
              f"{listed(log['unused'], 8)}")
    if out is not None:
        files.write_text(out, WRITERS[out.suffix.lower()](found.robot), overwrite=args.force)
        print(f"wrote {out}")
    return 0
