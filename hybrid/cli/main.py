"""Command line: ``python -m hybrid {regenerate,generate,paper,bench}``.

Bad usage or input prints one line on stderr and exits with status 2 (``--debug`` shows
the traceback).
"""

from __future__ import annotations

import argparse
import sys
import traceback
from pathlib import Path

from hybrid import bench
from hybrid.cli import experiments as experiment_cli
from hybrid.cli import sweep as sweep_cli
from hybrid.control.config import read_controller_config
from hybrid.errors import HybridError
from hybrid.models.robot import Robot
from hybrid.native import checkout
from hybrid.native.standalone import generate
from hybrid.native.units import generator


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, status 2, like every other bad input
        raise HybridError(f"{self.prog}: {message} (see --help)")


def _regenerate(args) -> int:
    target = Path(args.target) if args.target else None
    if target is None:
        checkout.generated_dir()  # an installed package refuses here, before the generator loads SymPy
    if args.check and target is not None and not target.is_dir():
        raise HybridError(f"--target {target} is not a folder of generated files")
    if target is not None and target.exists() and not target.is_dir():
        raise HybridError(f"--target {target} is a file; give a folder")
    regenerate = generator("regenerate")
    where = "generated/" if target is None else str(target)
    if args.check:
        problems = regenerate.check(target)
        if problems:
            print(f"{where} is out of date:\n" + "\n".join(problems), file=sys.stderr)
            return 1
        print(f"{where} is up to date")
        return 0
    try:
        changed = regenerate.write(target, force=args.force)
    except FileExistsError as exc:
        raise HybridError(str(exc)) from None
    except OSError as exc:
        raise HybridError(f"cannot write into {target or 'generated/'} ({exc.strerror or exc}); "
                          "give a writable --target") from None
    print(f"regenerated: {', '.join(changed)}" if changed else f"{where} was already up to date")
    return 0


def _lock(text: str) -> tuple[str, float]:
    name, sep, value = text.partition("=")
    try:
        return name, float(value) if sep else 0.0
    except ValueError:
        raise argparse.ArgumentTypeError(f"--lock {text!r}: give JOINT or JOINT=POSITION") from None


def _generate(args) -> int:
    if args.experiment is not None:
        if args.controller is not None:
            raise HybridError("--controller describes a controller for --urdf; an --experiment has its own: give one")
        return experiment_cli.run_generate(args)
    if args.settings:
        raise HybridError("--set overrides an experiment's settings: give --experiment too")
    if not args.urdf or not args.tip:
        raise HybridError("generate needs --urdf and --tip (a URDF arm's kernels or, with --controller, its "
                          "controller), or --experiment")
    if args.controller is None:
        written = generate(args.urdf, args.tip, args.out, args.name, dict(args.lock) or None, force=args.force)
    else:  # the controller the file describes, for this arm
        robot = Robot.from_urdf(args.urdf, args.tip, locked=dict(args.lock) or None)
        written = read_controller_config(args.controller, robot).generate(args.out, args.name, force=args.force)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="python -m hybrid", description=__doc__.split("\n\n")[0])
    p.add_argument("--debug", action="store_true", help="show tracebacks")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)

    r = sub.add_parser(
        "regenerate", help="rewrite generated/ from the symbolic models (in a checkout)",
        description="Rewrite generated/ of a checkout of the project's repository from codegen/. An installed "
                    "package has no generated/ of its own to rewrite, so there it refuses unless --target names "
                    "a folder.")
    r.add_argument("--check", action="store_true",
                   help="only compare; exit 1 when a file is missing, stale or edited by hand")
    r.add_argument("--force", action="store_true", help="overwrite generated files edited by hand")
    r.add_argument("--target", metavar="DIR",
                   help="write into (with --check: compare) DIR instead of the checkout's generated/; "
                        "works from an installed package too")
    r.set_defaults(func=_regenerate)

    g = sub.add_parser("generate", help="write standalone C99 (.c, .h, manifest .json) for a URDF arm, its "
                                        "controller, or an experiment's controller and plant",
                       description="Write standalone C99: the terms of a URDF arm's model; with --controller, the "
                                   "hybrid controller a TOML file describes for it; with --experiment, an "
                                   "experiment's controller and plant (a closed loop in C alone).")
    g.add_argument("--urdf", help="the robot's URDF file")
    g.add_argument("--tip", help="the link that ends the chain (e.g. tool0)")
    g.add_argument("--out", required=True, help="folder to write into")
    g.add_argument("--name", help="prefix of the files and C symbols (default: the robot's name)")
    g.add_argument("--lock", action="append", type=_lock, default=[], metavar="JOINT[=POSITION]",
                   help="hold this joint at POSITION (default 0); repeatable")
    g.add_argument("--controller", metavar="CONFIG.toml",
                   help="write the controller this TOML file describes (surface, scheme, task axes, gains, "
                        "references, limits; see hybrid/data/controller_ur5_sphere.toml) for the arm, in place "
                        "of the arm's terms alone")
    g.add_argument("--force", action="store_true", help="overwrite files with other content")
    experiment_cli.add_generate_arguments(g)
    g.set_defaults(func=_generate)


    experiment_cli.add_parser(sub)
    sweep_cli.add_parser(sub)
    bench.add_parser(sub)
    return p


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    debug = "--debug" in argv
    try:
        args = build_parser().parse_args(argv)
        return args.func(args)
    except HybridError as exc:
        if debug:
            traceback.print_exc()
        # one line: the error's first line names the value and the fix; --debug shows the rest
        print(f"error: {str(exc).splitlines()[0] if str(exc) else type(exc).__name__}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
