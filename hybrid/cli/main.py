"""The command line, ``hybrid COMMAND`` or ``python -m hybrid COMMAND``: every command and its
options are in ``--help``.

Bad usage or input prints one line on stderr and exits with status 2 (``--debug`` shows
the traceback).
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import traceback
import warnings
from pathlib import Path

from hybrid import bench
from hybrid.cli import common, progress
from hybrid.cli import experiments as experiment_cli
from hybrid.cli import identify as identify_cli
from hybrid.cli import regenerate as regenerate_cli
from hybrid.cli import stability as stability_cli
from hybrid.cli import sweep as sweep_cli
from hybrid.cli import tune as tune_cli
from hybrid.control.config import read_controller_config
from hybrid.deprecation import MESSAGE
from hybrid.errors import HybridError
from hybrid.models.robot import Robot
from hybrid.native import checkout
from hybrid.native.standalone import generate


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, status 2, like every other bad input
        if re.search(r"arguments are required: COMMAND$", message):
            commands = next(a for a in self._actions if isinstance(a, argparse._SubParsersAction))
            raise HybridError(f"{self.prog}: give a command ({', '.join(commands.choices)}; see {self.prog} --help)")
        choice = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)", message)
        hint = common.did_you_mean(choice.group(1), re.findall(r"'([^']*)'", choice.group(2))) if choice else ""
        raise HybridError(f"{self.prog}: {message}{hint} (see {self.prog} --help)")


def _regenerate(args) -> int:
    target = Path(args.target) if args.target else None
    if target is None:
        checkout.generated_dir()  # an installed package refuses here, before the generator loads SymPy
    if args.check and target is not None and not target.is_dir():
        raise HybridError(f"--target {target} is not a folder of generated files")
    if target is not None and target.exists() and not target.is_dir():
        raise HybridError(f"--target {target} is a file; give a folder")
    where = "generated/" if target is None else str(target)
    if args.check:
        problems = regenerate_cli.check(target)
        if problems:
            print(f"{where} is out of date:\n" + "\n".join(problems), file=sys.stderr)
            return 1
        print(f"{where} is up to date")
        return 0
    try:
        changed = regenerate_cli.write(target, force=args.force)
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
    if args.constant_model and (args.experiment is not None or args.controller is not None or not args.urdf):
        raise HybridError("--constant-model compiles a URDF arm's parameters into its kernels: give it with --urdf "
                          "and --tip alone (not with --controller or --experiment)")
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
        with args.report.step(f"generating C99 for the arm of {args.urdf}"):
            written = generate(args.urdf, args.tip, args.out, args.name, dict(args.lock) or None, force=args.force,
                               constant_model=args.constant_model)
    else:  # the controller the file describes, for this arm
        with args.report.step(f"generating C99 for the controller of {args.controller}"):
            robot = Robot.from_urdf(args.urdf, args.tip, locked=dict(args.lock) or None)
            written = read_controller_config(args.controller, robot).generate(args.out, args.name, force=args.force)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


DESCRIPTION = """\
Task-space decoupling hybrid force/velocity control (De Luca & Manes): the schemes compared on the
paper's experiment and on a 3-D one, parameter sweeps, standalone C for your robot and its
controller, and benchmarks."""

EPILOG = """\
Run '{prog} COMMAND --help' for a command's options. Bad usage or input prints one line on stderr
and exits with status 2 (--debug shows the traceback)."""

REGENERATE = ("Rewrite generated/ from codegen/ (in a checkout). Rewrites generated/ of a checkout of the "
              "project's repository from the symbolic models in codegen/, deterministically. An installed "
              "package has no generated/ of its own to rewrite, so there it refuses unless --target names a "
              "folder.")
GENERATE = ("Write standalone C99 for a URDF arm or an experiment. The files are NAME.c, NAME.h and the "
            "manifest NAME.json. With --urdf and --tip: the terms of a URDF arm's model; with --controller "
            "too, the hybrid controller a TOML file describes for it; with --experiment, an experiment's "
            "controller and plant (a closed loop in C alone).")


def build_parser(prog: str = "hybrid") -> argparse.ArgumentParser:
    p = _Parser(prog=prog, description=DESCRIPTION, epilog=EPILOG.format(prog=prog),
                formatter_class=common.HelpFormatter)
    p.add_argument("--debug", action="store_true", help="show the traceback of an error (and its details)")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", title="commands", required=True, parser_class=_Parser,
                           help="the command to run; each has its own --help")

    r = common.command(sub, "regenerate", REGENERATE, _regenerate)
    r.add_argument("--check", action="store_true",
                   help="only compare; exit 1 when a file is missing, stale or edited by hand")
    r.add_argument("--force", action="store_true", help="overwrite generated files edited by hand")
    r.add_argument("--target", metavar="DIR",
                   help="write into (with --check: compare) DIR instead of the checkout's generated/; "
                        "works from an installed package too")

    g = common.command(sub, "generate", GENERATE, _generate)
    g.add_argument("--urdf", metavar="FILE", help="the robot's URDF file")
    g.add_argument("--tip", metavar="LINK", help="the link that ends the chain (e.g. tool0)")
    g.add_argument("--out", required=True, metavar="DIR", help="folder to write into")
    g.add_argument("--name", metavar="PREFIX",
                   help="prefix of the files and C symbols: ASCII letters, digits and single _, a letter first, "
                   "not a C keyword or system header's name (default: made of the robot's name)")
    g.add_argument("--lock", action="append", type=_lock, default=[], metavar="JOINT[=POSITION]",
                   help="hold this joint at POSITION [rad or m] (default 0); repeatable")
    g.add_argument("--controller", metavar="CONFIG.toml",
                   help="write the controller this TOML file describes (surface, scheme, task axes, gains, "
                        "references, limits; see hybrid/data/controller_ur5_sphere.toml) for the arm, in place "
                        "of the arm's terms alone")
    g.add_argument("--constant-model", action="store_true",
                   help="compile the URDF's inertial parameters, friction and gravity into the arm's kernels as "
                        "numbers (a constant model: fewer operations, no robot array; with --urdf alone)")
    g.add_argument("--force", action="store_true", help="overwrite files with other content")
    experiment_cli.add_generate_arguments(g)
    common.add_verbose(g)

    experiment_cli.add_parser(sub)
    sweep_cli.add_parser(sub)
    stability_cli.add_parser(sub)
    tune_cli.add_parser(sub)
    identify_cli.add_parser(sub)
    bench.add_parser(sub)
    return p


def parse(argv: list[str], prog: str = "hybrid") -> argparse.Namespace:
    """The command line's arguments; an unknown option is refused naming the command it was given to
    (and the nearest option that command has)."""
    parser = build_parser(prog)
    args, extra = parser.parse_known_args(argv)
    if extra:
        commands = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        command = commands.choices[args.command]
        options = [o for a in command._actions for o in a.option_strings]
        hint = common.did_you_mean(extra[0].split("=")[0], options) if extra[0].startswith("-") else ""
        raise HybridError(f"{command.prog}: unrecognized argument{'s' if len(extra) > 1 else ''} "
                          f"{' '.join(extra)}{hint} (see {command.prog} --help)")
    return args


def main(argv: list[str] | None = None, prog: str | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); ``prog`` is the program's name in
    help and errors (default: as invoked, ``hybrid`` when ``argv`` is given)."""
    if prog is None:
        prog = os.path.basename(sys.argv[0]) if argv is None and sys.argv and sys.argv[0] else "hybrid"
    argv = sys.argv[1:] if argv is None else argv
    debug = "--debug" in argv
    try:
        args = parse(argv, prog)
        with progress.reporting(getattr(args, "verbose", False)) as report, warnings.catch_warnings():
            # a renamed setting's old name (a sweep file's, --set's, a controller file's) is told on stderr
            warnings.filterwarnings("always", MESSAGE, DeprecationWarning)
            warnings.showwarning = lambda message, *_, **__: report.say(f"warning: {message}")
            args.report = report
            return args.func(args)
    except HybridError as exc:
        if debug:
            traceback.print_exc()
        # one line: the error's first line names the value and the fix; --debug shows the rest
        line = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        print(f"error: {common.cli_wording(line)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
