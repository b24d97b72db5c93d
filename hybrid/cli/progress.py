"""Progress of the long commands on stderr.

A command's steps (``with report.step("running the schemes"):``) are told once each: at once and with
their time under ``--verbose``, else only when one lasts more than :data:`QUIET_FOR` seconds. The
library reports its own slow work, compiling and generating code on first use, through the ``hybrid``
logger at INFO (silent unless a program asks, as the command line does here): with ``--verbose``
every such line is shown, without it one line says that code is being compiled.
"""

from __future__ import annotations

import contextlib
import logging
import sys
import threading
import time
from collections.abc import Iterator

#: how long [s] a step runs before it is told without --verbose
QUIET_FOR = 2.0
#: what the one line without --verbose says of the library's slow work
COMPILING = "compiling the generated C on first use, cached for later runs"


class Progress:
    """Tells a command's steps on ``stream`` (stderr by default)."""

    def __init__(self, verbose: bool = False, stream=None, quiet_for: float = QUIET_FOR):
        self.verbose, self.quiet_for = bool(verbose), quiet_for
        self.stream = stream if stream is not None else sys.stderr
        self._lock = threading.Lock()
        self._current: dict | None = None  # the step under way: its text and whether it was told
        self._compiling_told = False

    def say(self, text: str) -> None:
        with self._lock:
            print(text, file=self.stream, flush=True)

    def detail(self, text: str) -> None:
        """A line for ``--verbose`` only."""
        if self.verbose:
            self.say(text)

    @contextlib.contextmanager
    def step(self, text: str) -> Iterator[None]:
        """One step of the command, told as the module docstring says."""
        state = {"text": text, "told": False}
        t0 = time.perf_counter()
        self._current = state
        timer = None
        if self.verbose:
            self._tell(state)
        else:
            timer = threading.Timer(self.quiet_for, self._tell, (state,))
            timer.daemon = True
            timer.start()
        try:
            yield
        finally:
            if timer is not None:
                timer.cancel()
            self._current = None
            self.detail(f"  {text}: done in {time.perf_counter() - t0:.2f} s")

    def _tell(self, state: dict, why: str = "") -> None:
        if not state["told"]:
            state["told"] = True
            self.say(f"{state['text']}{why} ...")

    def slow_work(self, message: str) -> None:
        """The library's report of slow work (a unit compiled, code generated)."""
        if self.verbose:
            self.say(f"  {message}")
            return
        state = self._current
        if self._compiling_told:
            return
        self._compiling_told = True
        if state is not None and not state["told"]:
            self._tell(state, f" ({COMPILING})")
        elif state is None:
            self.say(f"{COMPILING} ...")


class _LibraryLog(logging.Handler):
    """The ``hybrid`` logger's records, shown through a :class:`Progress`."""

    def __init__(self, progress: Progress):
        super().__init__(logging.INFO)
        self.progress = progress

    def emit(self, record: logging.LogRecord) -> None:
        try:
            message = record.getMessage().removeprefix("hybrid: ")
            if record.levelno >= logging.WARNING:
                self.progress.say(f"warning: {message}")
            elif getattr(record, "slow", False):
                self.progress.slow_work(message)
            else:
                self.progress.detail(f"  {message}")
        except Exception:  # noqa: BLE001 - a report must never break the command
            self.handleError(record)


@contextlib.contextmanager
def reporting(verbose: bool = False, stream=None) -> Iterator[Progress]:
    """A :class:`Progress` for one command, with the library's log shown through it while the block
    runs (the logger is left as it was afterwards)."""
    progress = Progress(verbose, stream)
    logger = logging.getLogger("hybrid")
    handler, level = _LibraryLog(progress), logger.level
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    try:
        yield progress
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)
