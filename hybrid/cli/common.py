"""What every command shares: one description per command (its first sentence is the summary the
top-level help lists), the options of the long commands, checked option values, and error messages in
the command line's words."""

from __future__ import annotations

import argparse
import difflib
import re
import textwrap

#: the figure formats the commands write (``--format``)
FORMATS = ("png", "pdf", "svg")


class HelpFormatter(argparse.HelpFormatter):
    """Plain text: each paragraph of a description wrapped on its own (blank lines kept), the commands'
    and options' help in a column wide enough for the longest command's name."""

    def __init__(self, prog, indent_increment=2, max_help_position=30, width=None):
        super().__init__(prog, indent_increment, max_help_position, width)

    def add_argument(self, action):
        super().add_argument(action)
        if isinstance(action, argparse._SubParsersAction) and action.help is not argparse.SUPPRESS:
            # argparse measures the commands' names one indent short: room for the longest, on its line
            longest = max(map(len, action.choices), default=0)
            self._action_max_length = max(self._action_max_length,
                                          longest + self._current_indent + self._indent_increment)

    def _fill_text(self, text, width, indent):
        paragraphs = [" ".join(p.split()) for p in text.strip().split("\n\n")]
        return "\n\n".join(textwrap.fill(p, width, initial_indent=indent, subsequent_indent=indent)
                           for p in paragraphs)


def summary(description: str) -> str:
    """The first sentence of ``description``: the line the top-level help lists."""
    first = re.split(r"(?<=[.!?])\s", description.strip(), maxsplit=1)[0]
    return first.rstrip(".")


def command(sub, name: str, description: str, func, *, parents=()) -> argparse.ArgumentParser:
    """The subcommand ``name``: its help is ``description`` and its line in the top-level list the
    description's first sentence; ``func(args)`` runs it."""
    p = sub.add_parser(name, help=summary(description), description=description, parents=list(parents),
                       formatter_class=HelpFormatter)
    p.add_argument("--debug", action="store_true", help="show the traceback of an error (and its details)")
    p.set_defaults(func=func)
    return p


def add_verbose(p) -> None:
    """``--verbose``/``-v``: a progress line on stderr for each step."""
    p.add_argument("-v", "--verbose", action="store_true",
                   help="report each step on stderr (compilation, runs, files written) with its time; without it, "
                        "one line for a step that takes more than a couple of seconds")


def add_format(p, what: str = "figures") -> None:
    """``--format png,pdf``: the figures' file formats."""
    p.add_argument("--format", default=["png"], type=formats, metavar="FMT[,FMT...]",
                   help=f"file formats of the {what}, comma-separated, from {', '.join(FORMATS)} "
                        "(default: png; pdf and svg are vector graphics)")


def formats(text: str) -> list[str]:
    """``--format``'s value as a list of formats, checked."""
    given = [f.strip().lower().lstrip(".") for f in text.split(",") if f.strip()]
    bad = [f for f in given if f not in FORMATS]
    if bad or not given:
        raise argparse.ArgumentTypeError(f"{text!r}: give one or more of {', '.join(FORMATS)}, comma-separated "
                                         f"(e.g. png,pdf){did_you_mean(bad[0], FORMATS) if bad else ''}")
    return list(dict.fromkeys(given))


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r}: give a whole number of at least 1")
    return value


def seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 0 < value <= 3600:  # NaN fails too
        raise argparse.ArgumentTypeError(f"{text!r}: give a number of seconds in (0, 3600]")
    return value


def did_you_mean(word: str, known) -> str:
    """``" (did you mean 'x'?)"`` for the known name closest to ``word``, or ``""``. Options are
    compared without their dashes."""
    known = [str(k) for k in known]
    bare = {k.lstrip("-"): k for k in known}
    close = difflib.get_close_matches(str(word).lstrip("-"), list(bare), n=1, cutoff=0.6)
    return f" (did you mean {bare[close[0]]!r}?)" if close else ""


#: the library's words for a keyword argument, and what the command line says instead
_PYTHON_WORDS = (
    (re.compile(r"\b\w+=True \((--[\w-]+)\)"), r"\1"),  # "pass force=True (--force)" -> "pass --force"
)


def cli_wording(message: str) -> str:
    """An error's message in the command line's words (its options, not the Python API's keywords)."""
    for pattern, replacement in _PYTHON_WORDS:
        message = pattern.sub(replacement, message)
    return message
