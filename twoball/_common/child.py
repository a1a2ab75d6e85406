"""One long compiled call in a forked child process, so that the parent stays responsive.

Some compiled calls hold the GIL for their whole run: :func:`scipy.linalg.eigh`
(dense LAPACK through f2py) froze a thread that ticks every 50 ms for 4.6 s on a
2000 x 2000 generalized problem, and for 5-6 s in each finite-element step of
``twoball verify`` (py-spy ``--gil``: 567 of 912 samples in ``eigh``).  While such
a call runs, the progress thread of :mod:`twoball._common.progress` cannot draw,
and Python runs no signal handler, so Ctrl-C waits for the call to end.

:func:`in_child` runs the call in a forked child instead: the same code and the
same library on the same data, so the numbers are bit for bit those of a call in
process.  The parent waits on a pipe in steps of :data:`POLL_SECONDS`; between
them its progress thread draws, a signal handler raises at once (the child is
then killed and reaped), and the deadline of the time limit is checked
(:func:`twoball._common.budget.check_deadline`).

Where ``fork`` is missing, outside the main thread, or inside a child already,
the call runs in process.  Only the standard library is imported here.
"""

from __future__ import annotations

import os
import pickle
import select
import signal
import threading
from collections.abc import Callable
from typing import Any, TypeVar

__all__ = ["POLL_SECONDS", "in_child"]

#: Seconds between two checks of the parent while the child works.
POLL_SECONDS = 0.1
_READ = 1 << 20

_T = TypeVar("_T")
_inside = {"child": False}


def can_fork() -> bool:
    """Whether :func:`in_child` forks here (POSIX, main thread, not in a child already)."""
    return (
        hasattr(os, "fork")
        and not _inside["child"]
        and threading.current_thread() is threading.main_thread()
    )


def in_child(function: Callable[..., _T], *args: Any, doing: str = "a long computation") -> _T:
    """``function(*args)`` computed in a forked child; its result (or exception) returned here.

    Parameters
    ----------
    function, args
        The call; its result and any exception it raises must pickle.
    doing : str
        What it computes, for the deadline's message (``"dense eigenpairs of
        2562 unknowns"``).

    Raises
    ------
    Whatever ``function`` raised; :class:`~twoball._common.budget.DeadlineError`
    past the time limit; the signal's exception on SIGINT/SIGTERM.  In each case
    the child is killed and reaped first.
    """
    if not can_fork():
        return function(*args)
    from twoball._common.budget import check_deadline

    check_deadline(doing)
    read, write = os.pipe()
    pid = os.fork()  # the child leaves by os._exit: no buffered output is written twice
    if pid == 0:  # the child: compute, send, leave without running the parent's clean-up
        os.close(read)
        _child(function, args, write)
    os.close(write)
    chunks: list[bytes] = []
    finished = False
    try:
        while True:
            ready, _, _ = select.select([read], [], [], POLL_SECONDS)
            if ready:
                chunk = os.read(read, _READ)
                if not chunk:
                    break
                chunks.append(chunk)
            else:
                check_deadline(doing)
        os.waitpid(pid, 0)
        finished = True
    finally:
        os.close(read)
        if not finished:  # an interrupt, the deadline: the child's work is not wanted
            _end(pid)
    if not chunks:
        raise RuntimeError(f"the child process computing {doing} ended without a result")
    ok, value = pickle.loads(b"".join(chunks))
    if ok:
        return value
    raise value


def _child(function: Callable[..., Any], args: tuple[Any, ...], write: int) -> None:
    """Run in the forked child: signals to the parent, the call, its pickled outcome."""
    _inside["child"] = True
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the group: the parent acts
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    status = 0
    try:
        try:
            outcome = (True, function(*args))
        except BaseException as error:  # noqa: BLE001 -- sent to the parent, raised there
            outcome = (False, error)
        try:
            data = pickle.dumps(outcome, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception as error:  # noqa: BLE001 -- an unpicklable result or exception
            data = pickle.dumps((False, RuntimeError(f"{type(error).__name__}: {error}")))
        view = memoryview(data)
        while view:
            view = view[os.write(write, view) :]
    except BaseException:  # noqa: BLE001 -- never return into the parent's code
        status = 1
    finally:
        os._exit(status)


def _end(pid: int) -> None:
    """Kill the child and reap it (it may have finished already)."""
    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    try:
        os.waitpid(pid, 0)
    except ChildProcessError:
        pass
