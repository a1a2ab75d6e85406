"""Signals: SIGINT and SIGTERM become an exception, held back while output is committed.

:func:`raise_on_signals` turns both signals into :class:`Interrupted` (exit
status 128 + signal number: 130, 143), so every ``finally`` runs and scratch is
removed; :func:`deferred_signals` holds them back while a sequence of renames
commits output (see :mod:`twoball._common.staging`) and raises afterwards;
:func:`held_signals` holds them back while a foreign library runs (VTK: its
imports, renders and callbacks) and :func:`checkpoint` raises them at a safe
point in between (between two frames).

Testing hook: with ``TWOBALL_TEST_PAUSE=STAGE`` in the environment,
:func:`pause` prints ``twoball-test-pause: STAGE`` on standard error at that
stage and sleeps (up to 60 s) so a test can signal the process at a known
point.  Only the standard library is imported.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import time
from collections.abc import Iterator

PAUSE_ENV = "TWOBALL_TEST_PAUSE"
PAUSE_SECONDS = 60.0


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM arrived; ``exit_status`` is 128 + the signal number (130, 143)."""

    def __init__(self, signum: int) -> None:
        self.signum = int(signum)
        super().__init__(signal.Signals(self.signum).name)

    @property
    def exit_status(self) -> int:
        """Conventional exit status of a process ended by this signal."""
        return 128 + self.signum


_HANDLED = (signal.SIGINT, signal.SIGTERM)
_deferral = {"depth": 0, "pending": None}


def _in_main_thread() -> bool:
    """Whether this is the main thread (Python runs signal handlers only there).

    A process that never imported :mod:`threading` has started no thread through
    it, so it runs in its main thread; threading is not imported for the answer
    (the command line's ``--help`` does without it).
    """
    threading = sys.modules.get("threading")
    return threading is None or threading.current_thread() is threading.main_thread()


def _raise_interrupted(signum: int, frame: object) -> None:
    if _deferral["depth"] > 0:  # inside a commit or clean-up: raise when it is over
        _deferral["pending"] = signum
        return
    raise Interrupted(signum)


@contextlib.contextmanager
def raise_on_signals() -> Iterator[None]:
    """While active, SIGINT and SIGTERM raise :class:`Interrupted` in the main thread.

    Outside the main thread this does nothing (Python runs signal handlers
    only there).  The previous handlers come back on exit.
    """
    if not _in_main_thread():
        yield
        return
    previous = {s: signal.getsignal(s) for s in _HANDLED}
    for s in _HANDLED:
        signal.signal(s, _raise_interrupted)
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)


@contextlib.contextmanager
def sigterm_raises() -> Iterator[None]:
    """Make SIGTERM raise (for API callers) unless someone already handles it."""
    if _in_main_thread() and signal.getsignal(signal.SIGTERM) == signal.SIG_DFL:
        with raise_on_signals():
            yield
    else:
        yield


@contextlib.contextmanager
def deferred_signals() -> Iterator[None]:
    """Hold SIGINT/SIGTERM back until the block ends, then raise :class:`Interrupted`.

    Used around commits (a sequence of renames) and scratch clean-up so that a
    signal can neither split a commit nor leave scratch behind.  Only signals
    that reach :func:`raise_on_signals`' handler are held back.
    """
    _deferral["depth"] += 1
    try:
        yield
    finally:
        _deferral["depth"] -= 1
        pending = _deferral["pending"]
        if _deferral["depth"] == 0 and pending is not None:
            _deferral["pending"] = None
            raise Interrupted(pending)


@contextlib.contextmanager
def held_signals() -> Iterator[None]:
    """Hold SIGINT/SIGTERM back while foreign code runs; :func:`checkpoint` raises them.

    An exception raised inside a C++ library's callback, or inside the
    initialisation of a C extension module being imported, may crash the
    interpreter (measured: SIGSEGV when a signal reached VTK's module import,
    ``render`` 0.5 s into its scratch) or be swallowed by the library, which
    then carries on.  In this block the signal is only recorded; the caller
    calls :func:`checkpoint` at safe points (between frames), and the end of
    the block raises a signal still pending.  In the main thread, SIGINT with
    Python's own handler and SIGTERM with the system's default get the handler
    of :func:`raise_on_signals` for the block (a caller's own handler is left
    alone), so API callers are covered as well as the command line.
    """
    installed = {}
    if _in_main_thread():
        for s in _HANDLED:
            current = signal.getsignal(s)
            if current in (signal.default_int_handler, signal.SIG_DFL):
                installed[s] = current
                signal.signal(s, _raise_interrupted)
    try:
        with deferred_signals():
            yield
    finally:
        for s, handler in installed.items():
            signal.signal(s, handler)


def checkpoint() -> None:
    """Raise :class:`Interrupted` now for a signal held back so far (a safe point)."""
    pending = _deferral["pending"]
    if pending is not None:
        _deferral["pending"] = None
        raise Interrupted(pending)


def pause(stage: str) -> None:
    """Test hook: stop at ``stage`` if ``TWOBALL_TEST_PAUSE`` names it (see the module doc)."""
    if os.environ.get(PAUSE_ENV) != stage:
        return
    sys.stderr.write(f"twoball-test-pause: {stage}\n")
    sys.stderr.flush()
    end = time.monotonic() + PAUSE_SECONDS
    while time.monotonic() < end and _deferral["pending"] is None:
        time.sleep(0.02)  # a signal's handler raises here (or is held back: then stop)
