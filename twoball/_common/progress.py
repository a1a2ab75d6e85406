"""Progress of long work on standard error: the one mechanism of every command.

A :class:`Reporter` is what the library's ``progress`` callbacks are given:

* called with a short text, ``reporter("fem P2 level 3")``, it starts the next
  step (a :data:`Step` callback, as :func:`twoball.verify` and
  :func:`twoball.converge` take);
* ``reporter.task(label, total)`` starts a counted task and returns its
  ``update(done)`` (a :data:`TaskHook`, as ``twoball reproduce`` takes);
* ``reporter.update(done)`` sets the count of its own total (sweeps).

On a terminal it draws one status line (spinner, step, counts, elapsed time),
redrawn four times a second by a background thread and erased when the work ends.  Anywhere
else (a CI log, a pipe, a file) it prints plain lines such as
``twoball: verify: 3/12 fem P2 level 3 (14 s)``: one when the work begins, then
at most one every :data:`INTERVAL` seconds (a background thread also prints one
while a single step runs long), and a last ``done`` line.  With ``delay`` the
reporter stays silent unless the work outlasts it, so quick runs print nothing.
``twoball --quiet`` (:func:`set_quiet`) silences every reporter; warnings and
errors are printed elsewhere and are not affected.  The background thread
starts with the first report, not on entering: a process pool started
in between forks without it (see :mod:`twoball.verify.sweeps.parallel`).  Nothing goes to standard
output, so ``--json`` output stays clean.

Only the standard library is used.
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable
from typing import Any, TextIO

from twoball._common.keywords import checked

__all__ = [
    "INTERVAL",
    "activity",
    "check_progress",
    "Reporter",
    "Step",
    "TaskHook",
    "is_quiet",
    "set_activity",
    "set_quiet",
    "silent",
]

#: Seconds between two progress lines (plain-text mode).
INTERVAL = 3.0
#: Seconds a reporter with a delay waits before its first output (quick runs: none).
QUICK = 2.0

Step = Callable[[str], None]
"""A progress callback: called with a short text as each step starts."""
TaskHook = Callable[[str, int], Callable[[int], None]]
"""``hook(label, total)`` starts a counted task and returns its ``update(done)``."""

_QUIET = False
#: What the solvers are doing right now (e.g. "eigenpairs: slice 3 of 24"), shown after
#: the step's text; set by :func:`set_activity` (the long loops, through
#: :func:`twoball._common.budget.check_deadline`), cleared when a step starts.
_ACTIVITY: dict[str, str | None] = {"text": None}


def set_activity(text: str | None) -> None:
    """Say what the work is doing now (None: nothing beyond the step); cheap, any thread."""
    _ACTIVITY["text"] = text


def activity() -> str | None:
    """What :func:`set_activity` last said (None after a step started)."""
    return _ACTIVITY["text"]


def set_quiet(quiet: bool) -> None:
    """Silence (True) or allow (False) every progress report of this process."""
    global _QUIET
    _QUIET = bool(quiet)


def is_quiet() -> bool:
    """True after ``set_quiet(True)`` (``twoball --quiet``)."""
    return _QUIET


def silent(_: str) -> None:
    """A :data:`Step` that says nothing."""
    return None


def _ignore(_: int) -> None:
    return None


@checked
class Reporter:
    """Progress of one command on standard error (a context manager).

    Parameters
    ----------
    name : str
        What runs, first word of every line (``verify``, ``export``, ...).
    total : int, optional
        Number of steps >= 0, if known (shown as ``k/total``).
    stream : file, optional
        Where to write (default: standard error at the time of entering).
    terminal : bool, optional
        Draw one status line (True) or print lines (False); default: whether
        ``stream`` is a terminal.
    interval : float
        Seconds between two lines, a finite number > 0.
    delay : float
        Print nothing unless the work lasts longer than this [s], a finite number >= 0.

    Raises
    ------
    ParameterError
        Naming the argument and its valid range.
    enabled : bool, optional
        Default: not :func:`is_quiet`.

    Examples
    --------
    >>> import twoball
    >>> with twoball.Reporter("demo", enabled=False) as progress:
    ...     progress("first step")
    ...     progress("second step")
    >>> progress._count
    2
    """

    def __init__(
        self,
        name: str,
        total: int | None = None,
        *,
        stream: TextIO | None = None,
        terminal: bool | None = None,
        interval: float = INTERVAL,
        delay: float = 0.0,
        enabled: bool | None = None,
    ) -> None:
        from numbers import Integral

        from twoball._common.errors import ParameterError, real_number

        if not isinstance(name, str):
            raise ParameterError("name", "a text (what runs)", name)
        if total is not None and (
            isinstance(total, bool) or not isinstance(total, Integral) or total < 0
        ):
            raise ParameterError("total", "an integer >= 0 (or None: unknown)", total)
        seconds = real_number("interval", interval, "a finite number of seconds > 0")
        if not seconds > 0.0:
            raise ParameterError("interval", "a finite number of seconds > 0", interval)
        wait = real_number("delay", delay, "a finite number of seconds >= 0")
        if not wait >= 0.0:
            raise ParameterError("delay", "a finite number of seconds >= 0", delay)
        self.name = name
        self.total = None if total is None else int(total)
        self.interval = seconds
        self.delay = wait
        self.enabled = (not _QUIET) if enabled is None else bool(enabled)
        self._stream = stream
        self._terminal = terminal
        self._lock = threading.RLock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._count = 0  # steps begun (shown in lines)
        self._completed = 0  # steps finished (shown by the bar)
        self._text = ""
        self._task: list[Any] | None = None  # [label, done, total] of the latest task
        self._begun = False
        self._lines = 0
        self._last = -float("inf")
        self._start = time.monotonic()
        self._bar: int | None = None  # status-line redraws on a terminal (None: none shown)

    # ------------------------------------------------------------------ context
    def __enter__(self) -> Reporter:
        self._start = time.monotonic()
        if not self.enabled:
            return self
        if self._stream is None:
            self._stream = sys.stderr
        if self._terminal is None:
            isatty = getattr(self._stream, "isatty", None)
            self._terminal = bool(isatty and isatty())
        return self  # no thread yet: a process pool may still fork (see _show)

    def __exit__(self, kind: type[BaseException] | None, *exc: object) -> None:
        set_activity(None)
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        with self._lock:
            if self._bar is not None:
                self._erase()
            elif kind is None and self._lines:
                counted = f" {self.total}/{self.total}" if self.total else ""
                self._write(f"done{counted} ({self._elapsed():.0f} s)")

    # ------------------------------------------------------------------ callbacks
    def __call__(self, text: str) -> None:
        """Start the next step, described by ``text``."""
        with self._lock:
            self._count += 1
            self._completed = self._count - 1
            self._text = text
            self._task = None
            set_activity(None)
            self._show()

    def update(self, completed: int, text: str | None = None) -> None:
        """Set the number of steps done (and optionally the text)."""
        with self._lock:
            self._count = self._completed = int(completed)
            if text is not None:
                self._text = text
            self._show()

    def task(self, label: str, total: int) -> Callable[[int], None]:
        """Start a counted task; returns ``update(done)`` (a :data:`TaskHook`)."""
        if not self.enabled:
            return _ignore
        with self._lock:
            entry = [label, 0, int(total)]
            self._task = entry
            self._show(label=label)

        def update(done: int) -> None:
            with self._lock:
                entry[1] = int(done)
                self._task = entry
                self._show(label=label)

        return update

    # ------------------------------------------------------------------ output
    def _elapsed(self) -> float:
        return time.monotonic() - self._start

    def _message(self) -> str:
        if self._task is not None:
            label, done, total = self._task
            return f"{label} {done}/{total}"
        now = activity()
        if self.total:
            text = f"{min(self._count, self.total)}/{self.total} {self._text}".rstrip()
        else:
            text = self._text or ("" if now else "working")
        return f"{text}: {now}" if now and text else (now or text)

    def _write(self, message: str) -> None:
        assert self._stream is not None
        try:
            self._stream.write(f"twoball: {self.name}: {message}\n")
            self._stream.flush()
        except (OSError, ValueError):  # a closed or full stderr never stops the work
            self.enabled = False
        self._lines += 1
        self._last = time.monotonic()

    def _show(self, label: str | None = None) -> None:
        """Show the current state: the bar now, a line when one is due (lock held)."""
        if not self.enabled or self._stream is None:
            return
        self._begun = True
        if self._thread is None:  # started with the work, after any pool has forked
            self._thread = threading.Thread(target=self._beat, name="twoball-progress", daemon=True)
            self._thread.start()
        if self._elapsed() < self.delay:
            return
        if self._terminal:
            self._draw(label)
            return
        if self._lines == 0 or time.monotonic() - self._last >= self.interval:
            self._write(f"{self._message()} ({self._elapsed():.0f} s)")

    def _draw(self, label: str | None) -> None:
        """Redraw the one status line of a terminal (lock held): spinner, step, counts, time."""
        if self._bar is None:
            self._bar = 0  # frames drawn; the line is erased on exit
        self._bar += 1
        spin = "|/-\\"[self._bar % 4]
        parts = [f"{spin} {self.name}"]
        if self._text:
            parts.append(self._text)
        now = activity()
        if now:
            parts.append(now)
        if self.total:
            parts.append(f"[{min(self._completed, self.total)}/{self.total}]")
        if self._task is not None:
            name, done, total = self._task
            parts.append(f"{label or name} {done}/{total}")
        parts.append(f"{self._elapsed():.0f} s")
        line = "  ".join(parts)
        width = _terminal_width(self._stream)
        if len(line) > width - 1:
            line = line[: max(width - 2, 10)] + "…"
        try:
            self._stream.write("\r\x1b[2K" + line)
            self._stream.flush()
        except (OSError, ValueError):
            self.enabled = False

    def _erase(self) -> None:
        """Remove the status line of a terminal (lock held)."""
        try:
            self._stream.write("\r\x1b[2K")
            self._stream.flush()
        except (OSError, ValueError):
            pass
        self._bar = None

    def _beat(self) -> None:
        """Background: a line while one step runs long; the bar after a delay."""
        while not self._stop.wait(0.25):
            with self._lock:
                if not self.enabled or self._elapsed() < self.delay:
                    continue
                if self._terminal:
                    self._draw(None)  # the time moves even while a step runs long
                elif self._begun or self.delay > 0:
                    if time.monotonic() - self._last >= self.interval:
                        self._write(f"{self._message()} ({self._elapsed():.0f} s)")


def _terminal_width(stream: Any) -> int:
    """Columns of the terminal behind ``stream`` (80 if it cannot be told)."""
    import os

    try:
        columns = os.get_terminal_size(stream.fileno()).columns
    except (AttributeError, OSError, ValueError):
        return 80
    return columns if columns >= 20 else 80


def check_progress(progress: Any, name: str = "progress") -> Any:
    """``progress`` itself if it is None or callable (a :class:`Reporter`, a function).

    Anything else raises :class:`~twoball._common.errors.ParameterError` naming it,
    before any work (a text or a number would fail only at the first report).
    """
    if progress is None or callable(progress):
        return progress
    from twoball._common.errors import ParameterError

    shown = progress if isinstance(progress, str | int | float) else type(progress).__name__
    raise ParameterError(name, "a callable (e.g. a twoball.Reporter) or None", shown)
