"""Signals: SIGINT and SIGTERM become an exception, held back while output is committed.

:func:`raise_on_signals` turns both signals into :class:`Interrupted` (exit
status 128 + signal number: 130, 143), so every ``finally`` runs and scratch is
removed; :func:`deferred_signals` holds them back while a sequence of renames
commits output (see :mod:`twoball._common.staging`) and raises afterwards;
:func:`held_signals` holds them back while a foreign library runs (VTK: its
imports, renders and callbacks) and :func:`checkpoint` raises them at a safe
point in between (between two frames).

After a commit
    The output is in place: a signal that arrives during the commit, or after
    it while the command finishes (its summary, its return), no longer undoes
    anything, so it is *held* (:func:`committed_signals`): raised at the next
    piece of work (:func:`resume`, called by every long loop through the
    deadline check and by the next writer), or, if the command ends first,
    returned by :func:`finish` -- the command line then reports the interrupt
    (status 130 / 143) with its output complete.  A held signal is delivered
    again after :data:`HOLD_SECONDS` if the work goes on without a check, so an
    interrupt still acts within a second.
The end of a run
    :func:`finish` marks the run's status as decided: from then on both
    signals are ignored (the command line ignores them through the interpreter's
    teardown), so a signal in the last moments can neither print a traceback
    nor kill the process with the raw signal after its output was committed.

Testing hook: with ``TWOBALL_TEST_PAUSE=STAGE`` in the environment,
:func:`pause` prints ``twoball-test-pause: STAGE`` on standard error at that
stage and sleeps (up to 60 s) so a test can signal the process at a known
point (the stages of :mod:`twoball._common.staging`: ``begin``, ``staged``,
``commit``, and ``commit-folder`` for a report folder, whose files may be
committed inside it first; ``part`` after each part of a reproduction is
committed).  Only the standard library is imported.
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
#: depth: nested blocks holding signals back; pending: the signal held; hold: an output
#: was committed and no work has started since; finished: the run's status is decided.
_deferral: dict[str, object] = {"depth": 0, "pending": None, "hold": False, "finished": False}
#: Seconds a signal held after a commit waits for the next check before it is delivered again.
HOLD_SECONDS = 0.5


def _in_main_thread() -> bool:
    """Whether this is the main thread (Python runs signal handlers only there).

    A process that never imported :mod:`threading` has started no thread through
    it, so it runs in its main thread; threading is not imported for the answer
    (the command line's ``--help`` does without it).
    """
    threading = sys.modules.get("threading")
    return threading is None or threading.current_thread() is threading.main_thread()


def _raise_interrupted(signum: int, frame: object) -> None:
    if _deferral["finished"]:  # the run's status is decided: it stands
        return
    if _deferral["depth"] > 0 or _deferral["hold"]:  # a commit, a clean-up, or just after
        _deferral["pending"] = signum
        if not _deferral["depth"]:
            _redeliver_later()
        return
    raise Interrupted(signum)


def _redeliver_later() -> None:
    """Deliver a signal held after a commit again in :data:`HOLD_SECONDS` if still held."""
    import threading

    main = threading.main_thread().ident

    def again() -> None:
        signum = _deferral["pending"]
        if _deferral["hold"] and signum is not None and not _deferral["finished"]:
            _deferral["hold"], _deferral["pending"] = False, None
            with contextlib.suppress(OSError, ValueError, RuntimeError):
                signal.pthread_kill(main, signum)  # type: ignore[arg-type]

    timer = threading.Timer(HOLD_SECONDS, again)
    timer.daemon = True
    timer.start()


@contextlib.contextmanager
def raise_on_signals(restore: bool = True) -> Iterator[None]:
    """While active, SIGINT and SIGTERM raise :class:`Interrupted` in the main thread.

    Outside the main thread this does nothing (Python runs signal handlers
    only there).  The previous handlers come back on exit, unless ``restore`` is
    False: the command line keeps its handler through the interpreter's teardown,
    where, after :func:`finish`, it ignores both signals.
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
        if restore:
            for s, handler in previous.items():
                signal.signal(s, handler)
            if previous[signal.SIGINT] is not _raise_interrupted:  # the outermost: afresh
                _deferral.update(pending=None, hold=False, finished=False)


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
            if _deferral["hold"]:  # after a commit: held until the next work, or dropped
                _redeliver_later()
            else:
                _deferral["pending"] = None
                raise Interrupted(pending)


@contextlib.contextmanager
def committed_signals() -> Iterator[None]:
    """:func:`deferred_signals` around the commit of an output, then hold them.

    Once the block has run to its end the output is in place: a signal that
    arrived meanwhile, or arrives before the next work starts (:func:`resume`),
    is held -- raised there, or dropped when the run ends first, so the run
    reports the success it had (see the module documentation).  If the block
    raises, a pending signal is raised as :func:`deferred_signals` does.
    """
    with deferred_signals():
        yield
        _deferral["hold"] = True


def resume() -> None:
    """Work starts again after a commit: end the hold, raising a signal held meanwhile."""
    if _deferral["hold"] and not _deferral["depth"]:
        _deferral["hold"] = False
        pending = _deferral["pending"]
        if pending is not None:
            _deferral["pending"] = None
            raise Interrupted(pending)


def finish(process: bool = False) -> int | None:
    """The run's status is decided: signals from now on are ignored; the held one is returned.

    Called by the command line when its command has ended (any way); the
    outermost :func:`raise_on_signals` starts afresh when it restores the
    previous handlers (a run called in process, as the tests do).  ``process``:
    the process ends with this run, and both signals are ignored by the system
    (``SIG_IGN``) -- the interpreter's finalisation puts back the default action
    for Python handlers (measured: killed by the raw signal after the output was
    written), not for an ignored signal.

    Returns
    -------
    int or None
        The signal held since the last commit and not yet acted on (the output
        is complete, the run was interrupted all the same), else None.
    """
    held = _deferral["pending"] if _deferral["hold"] or _deferral["depth"] else None
    if _deferral["finished"]:
        held = None
    _deferral.update(finished=True, pending=None, hold=False)
    if process and _in_main_thread():
        for s in _HANDLED:
            signal.signal(s, signal.SIG_IGN)
    return None if held is None else int(held)  # type: ignore[call-overload]


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


def pause(stage: str, seconds: float = PAUSE_SECONDS) -> None:
    """Test hook: stop at ``stage`` if ``TWOBALL_TEST_PAUSE`` names it (see the module doc).

    ``seconds``: the longest stop (where signals are ignored, the whole of it).
    """
    if os.environ.get(PAUSE_ENV) != stage:
        return
    sys.stderr.write(f"twoball-test-pause: {stage}\n")
    sys.stderr.flush()
    end = time.monotonic() + seconds
    while time.monotonic() < end and _deferral["pending"] is None:
        time.sleep(0.02)  # a signal's handler raises here (or is held back: then stop)
