"""One long compiled call in a child process started afresh, so that the parent stays responsive.

Some compiled calls hold the GIL for their whole run: :func:`scipy.linalg.eigh`
(dense LAPACK through f2py) froze a thread that ticks every 50 ms for 4.6 s on a
2000 x 2000 generalized problem, and for 5-6 s in each finite-element step of
``twoball verify`` (py-spy ``--gil``: 567 of 912 samples in ``eigh``).  While such
a call runs, the progress thread of :mod:`twoball._common.progress` cannot draw,
and Python runs no signal handler, so Ctrl-C waits for the call to end.

:func:`in_child` runs the call in a child process instead.  The child is a new
interpreter (``sys.executable``, the spawn way), never a fork of this process: a
fork made after BLAS or OpenMP thread pools exist may deadlock in the child on a
lock some pool thread held at the fork.  The call and its arguments travel by
pickle through a pipe, with this process's ``sys.path`` (the same modules are
found) and its BLAS and OpenMP thread counts (the child's libraries are started
with them: the environment variables of each library, and, when this process has
:mod:`threadpoolctl` loaded, each library's count as it is now), so that the same
code and the same library compute on the same data and the numbers are bit for
bit those of a call in process.  The parent waits in steps of
:data:`POLL_SECONDS`; between them its progress thread draws, a signal handler
raises at once (the child is then killed and reaped), and the deadline of the
time limit is checked (:func:`twoball._common.budget.check_deadline`).  The child
runs in a session of its own, so Ctrl-C at the terminal reaches the parent only;
on Linux it is also killed when the parent dies.

Starting the interpreter and importing what the call needs (numpy and scipy's
LAPACK) costs about a second; the call runs in process instead where that cannot
work: outside the main thread (signal handlers run only there), inside such a
child already, without an interpreter to start, for a call that does not pickle
(a lambda, a local function, a function of ``__main__``) or that the child cannot
load.  Only the standard library is imported here.
"""

from __future__ import annotations

import os
import pickle
import select
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from typing import Any, TypeVar

__all__ = ["POLL_SECONDS", "ChildDied", "can_spawn", "in_child"]

#: Seconds between two checks of the parent while the child works.
POLL_SECONDS = 0.1
_READ = 1 << 20
#: Set in a child's environment: a child computes in process (no child of its own).
CHILD_ENV = "TWOBALL_IN_CHILD"
#: Environment variables that set a thread pool's size, by threadpoolctl's API names.
THREAD_VARIABLES = {
    "openblas": ("OPENBLAS_NUM_THREADS",),
    "mkl": ("MKL_NUM_THREADS",),
    "blis": ("BLIS_NUM_THREADS",),
    "openmp": ("OMP_NUM_THREADS",),
}

_T = TypeVar("_T")

#: The child's program: read the call, compute, send the outcome, leave.  It ignores
#: SIGINT (the parent decides), keeps SIGTERM's default, and on Linux asks to be
#: killed with its parent.  Outcomes: (True, result), (False, exception), or
#: ("load", text) when the call could not be read here (the parent computes it then).
_PROGRAM = """
import os, pickle, signal, sys
signal.signal(signal.SIGINT, signal.SIG_IGN)
signal.signal(signal.SIGTERM, signal.SIG_DFL)
try:
    import ctypes
    ctypes.CDLL(None).prctl(1, int(signal.SIGKILL))  # PR_SET_PDEATHSIG
except Exception:
    pass
if os.getppid() != int(sys.argv[3]):  # the parent died before the request: leave
    os._exit(1)
status = 0
try:
    with os.fdopen(int(sys.argv[1]), "rb") as source:
        path, limits = pickle.load(source)
        sys.path[:] = path
        try:
            function, args = pickle.load(source)
        except MemoryError as error:  # out of memory here: the call would be no better off
            outcome = (False, error)
        except BaseException as error:
            outcome = ("load", f"{type(error).__name__}: {error}")
        else:
            if limits:
                try:
                    from threadpoolctl import ThreadpoolController
                except ImportError:
                    pass
                else:
                    pools = ThreadpoolController()
                    for filepath, count in limits:
                        pools.select(filepath=filepath).limit(limits=count)
            try:
                outcome = (True, function(*args))
            except BaseException as error:
                outcome = (False, error)
    try:
        data = pickle.dumps(outcome, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception as error:
        data = pickle.dumps((False, RuntimeError(f"{type(error).__name__}: {error}")))
    view = memoryview(data)
    sink = int(sys.argv[2])
    while view:
        view = view[os.write(sink, view):]
except BaseException:
    status = 1
finally:
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:
            pass
    os._exit(status)
"""


def can_spawn() -> bool:
    """Whether :func:`in_child` starts a child here (main thread, an interpreter, no child yet)."""
    return (
        bool(sys.executable)
        and not os.environ.get(CHILD_ENV)
        and threading.current_thread() is threading.main_thread()
    )


class ChildDied(RuntimeError):
    """The child ended without an outcome: killed, or crashed in compiled code.

    ``returncode`` is the child's exit status, ``-N`` when signal N ended it (an
    abort after a failed C++ allocation: SIGABRT; the OOM killer: SIGKILL).
    """

    def __init__(self, doing: str, returncode: int | None) -> None:
        super().__init__(
            f"the child process computing {doing} ended without a result (exit status {returncode})"
        )
        self.doing = doing
        self.returncode = returncode

    def __reduce__(self) -> tuple[type, tuple[str, int | None]]:
        return (type(self), (self.doing, self.returncode))


def in_child(function: Callable[..., _T], *args: Any, doing: str = "a long computation") -> _T:
    """``function(*args)`` computed in a child process; its result (or exception) returned here.

    Parameters
    ----------
    function, args
        The call; a function importable by name (a module's, not ``__main__``'s),
        arguments, result and any exception it raises that pickle.  Otherwise it
        runs in process.
    doing : str
        What it computes, for the deadline's message (``"dense eigenpairs of
        2562 unknowns"``).

    Raises
    ------
    Whatever ``function`` raised; :class:`~twoball._common.budget.DeadlineError`
    past the time limit; the signal's exception on SIGINT/SIGTERM.  In each case
    the child is killed and reaped first.  :class:`ChildDied` if the child ended
    without an outcome (a crash in compiled code, the OOM killer).
    """
    if not can_spawn():
        return function(*args)
    payload = _payload(function, args)
    if payload is None:
        return function(*args)
    from twoball._common.budget import check_deadline

    check_deadline(doing)
    to_child, source = os.pipe()  # the child reads ``to_child``, writes ``sink``
    outcome_fd, sink = os.pipe()
    open_fds = {to_child, source, outcome_fd, sink}
    process: subprocess.Popen[bytes] | None = None
    chunks: list[bytes] = []
    finished = False
    try:
        try:
            process = subprocess.Popen(
                [sys.executable, "-c", _PROGRAM, str(to_child), str(sink), str(os.getpid())],
                pass_fds=(to_child, sink),
                stdin=subprocess.DEVNULL,
                env=_environment(),
                start_new_session=True,  # Ctrl-C at the terminal reaches the parent only
            )
        except OSError:  # no interpreter to start (a frozen application): compute here
            finished = True
            return function(*args)
        for fd in (to_child, sink):
            os.close(fd)
            open_fds.discard(fd)
        os.set_blocking(source, False)
        pending = memoryview(payload)
        del payload
        checked = time.monotonic()
        while True:
            writing = [source] if source in open_fds else []
            readable, writable, _ = select.select([outcome_fd], writing, [], POLL_SECONDS)
            if writable:
                try:
                    pending = pending[os.write(source, pending) :]
                except BlockingIOError:
                    pass
                except BrokenPipeError:  # the child has gone: its outcome says why
                    pending = pending[:0]
                if not pending:  # all sent: the child sees the end of its input
                    os.close(source)
                    open_fds.discard(source)
                    pending = memoryview(b"")
            if readable:
                chunk = os.read(outcome_fd, _READ)
                if not chunk:
                    break
                chunks.append(chunk)
            now = time.monotonic()
            if now - checked >= POLL_SECONDS:
                checked = now
                check_deadline(doing)
        process.wait()
        finished = True
    finally:
        for fd in open_fds:
            os.close(fd)
        if process is not None and not finished:  # an interrupt, the deadline: not wanted
            _end(process)
    if not chunks:
        raise ChildDied(doing, process.returncode)
    ok, value = pickle.loads(b"".join(chunks))
    if ok == "load":  # the child could not import the call: compute it here
        return function(*args)
    if ok:
        return value
    raise value


def _payload(function: Callable[..., Any], args: tuple[Any, ...]) -> bytes | None:
    """The child's input: ``sys.path`` and the thread counts, then the call; None if it does not
    pickle (or names a function of ``__main__``, which the child does not have)."""
    if getattr(function, "__module__", None) == "__main__":
        return None
    try:
        call = pickle.dumps((function, args), protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 -- a lambda, a local function, an open file, ...
        return None
    header = pickle.dumps((list(sys.path), _thread_limits()), protocol=pickle.HIGHEST_PROTOCOL)
    return header + call


def _pools() -> list[dict[str, Any]]:
    """This process's BLAS and OpenMP thread pools as threadpoolctl sees them (none unloaded).

    :mod:`threadpoolctl` is used only when this process has loaded it already: a
    process that never did has changed no pool since its libraries read the
    environment, which the child inherits.
    """
    threadpoolctl = sys.modules.get("threadpoolctl")
    if threadpoolctl is None:
        return []
    try:
        return list(threadpoolctl.threadpool_info())
    except Exception:  # noqa: BLE001 -- an unexpected library: the environment alone
        return []


def _thread_limits() -> list[tuple[str, int]]:
    """Each loaded pool's library file and its thread count now (for the child to apply)."""
    return [
        (str(pool["filepath"]), int(pool["num_threads"]))
        for pool in _pools()
        if pool.get("filepath") and pool.get("num_threads")
    ]


def _environment() -> dict[str, str]:
    """The child's environment: this one, marked, with each pool's thread count set."""
    env = dict(os.environ)
    env[CHILD_ENV] = "1"
    counts: dict[str, int] = {}
    for pool in _pools():
        names = THREAD_VARIABLES.get(pool.get("internal_api", "")) or THREAD_VARIABLES.get(
            pool.get("user_api", ""), ()
        )
        for name in names:
            count = int(pool.get("num_threads") or 0)
            if count > 0:
                counts[name] = min(counts.get(name, count), count)
    env.update({name: str(count) for name, count in counts.items()})
    return env


def _end(process: subprocess.Popen[bytes]) -> None:
    """Kill the child and reap it (it may have finished already)."""
    try:
        process.kill()
    except ProcessLookupError:
        pass
    process.wait()
