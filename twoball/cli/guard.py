"""How a command ends when it is interrupted or cannot write: one line, a fixed exit status.

* SIGINT -> ``twoball: interrupted``, exit 130; SIGTERM -> the same line, exit 143
  (:func:`twoball._common.staging.raise_on_signals` turns both into an exception, so the
  writers' clean-up runs and no traceback is printed).  A signal that arrives while
  the output is committed waits for the commit: the output is then complete, and the
  run still ends with the line and 130 / 143 once the command has returned.
* An :class:`OSError` (full disk, read-only file system, no permission, name too
  long, ...) -> ``twoball: error: cannot write PATH: REASON``, exit 2 when the
  cause lies with the user's path or disk, else 3.
* A :class:`MemoryError` the resource estimates did not foresee -> one line,
  exit 3.
* Standard output that is closed or full (``--json > /dev/full``) -> one line,
  exit 2; a reader that stopped early (``| head``) -> exit 0, silently.

Only the standard library is imported here.
"""

from __future__ import annotations

import errno
import os
import sys
from collections.abc import Callable

from twoball._common.signals import finish, pause, raise_on_signals

TYPE_CHECKING = False  # typing is not imported at start-up: annotations only
if TYPE_CHECKING:
    from typing import Any

EXIT_USAGE = 2
EXIT_NUMERICAL = 3
#: errno values that describe the user's path or disk (exit 2); others exit 3.
USER_ERRNOS = frozenset(
    {
        errno.ENOSPC,
        errno.EDQUOT,
        errno.EFBIG,
        errno.EROFS,
        errno.EACCES,
        errno.EPERM,
        errno.ENAMETOOLONG,
        errno.ENOENT,
        errno.ENOTDIR,
        errno.EISDIR,
        errno.EEXIST,
        errno.ENOTEMPTY,
        errno.EXDEV,
        errno.ELOOP,
    }
)


def guarded(command: Callable[..., int], *args: Any, process: bool = False) -> int:
    """Run ``command(*args)`` and map interrupts and I/O failures to one line and a status.

    The signal handlers are installed first and the status, once decided, stands
    (:func:`~twoball._common.signals.finish`): a signal held since the last output
    was committed turns a status of 0 or 1 into 130 / 143 (the output complete),
    one after the status is decided changes nothing, and with ``process`` (the console script:
    the whole process is this run) the handler stays through the interpreter's
    teardown and ignores both signals there -- no traceback, no death by the raw
    signal after the output was written.
    """
    with raise_on_signals(restore=not process):
        try:
            status = _outcome(command, *args)
        finally:
            held = finish(process)
            pause("finished", 1.0)  # test hook: a signal now changes nothing
    if held is not None and status in (0, 1):
        # the signal came while the output was committed: it is complete, and the run
        # still says it was interrupted (a script's `trap` or `timeout` sees 130 / 143)
        _quiet_stdout()
        sys.stderr.write("twoball: interrupted\n")
        return 128 + held
    return status


def leave(status: int) -> None:
    """End this process now with ``status``: the interrupted console script's last step.

    Every clean-up of the run has been done by then (scratch removed, workers and
    child processes ended, the one line written); what is left is the
    interpreter's teardown of a thousand modules, 0.6-0.8 s on a loaded two-core
    machine (0.03 s this way), which would make an interrupt take longer than
    the second it is promised.  The ``atexit`` functions still run; standard
    output and error are flushed first.
    """
    import atexit

    try:
        atexit._run_exitfuncs()
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError, AttributeError):
                pass
        os._exit(status)


def _outcome(command: Callable[..., int], *args: Any) -> int:
    """The status of ``command(*args)``, interrupts and I/O failures mapped to one line.

    Each failure is reported with the status already decided (signals ignored), so
    a second Ctrl-C cannot cut its one line short.
    """
    try:
        status = command(*args)
        _flush_stdout()
        return status
    except KeyboardInterrupt as interrupt:
        finish()
        _quiet_stdout()
        sys.stderr.write("twoball: interrupted\n")
        return int(getattr(interrupt, "exit_status", 130))
    except (MemoryError, RuntimeError) as error:
        # an allocation the estimates did not foresee; SuperLU reports its own
        # failed allocations as RuntimeError("SUPERLU_MALLOC failed ...")
        if isinstance(error, RuntimeError) and "MALLOC" not in str(error):
            raise
        finish()
        _quiet_stdout()
        detail = " ".join(str(error).split()) or "an allocation failed"
        sys.stderr.write(
            f"twoball: error: out of memory ({detail}); choose a smaller size, or give "
            "the process more memory\n"
        )
        return EXIT_NUMERICAL
    except BrokenPipeError:  # output piped into a reader that stopped (e.g. `head`)
        finish()
        _quiet_stdout()
        return 0
    except OSError as error:
        finish()
        _quiet_stdout()
        sys.stderr.write(f"twoball: error: {describe(error)}\n")
        return EXIT_USAGE if error.errno in USER_ERRNOS else EXIT_NUMERICAL


def describe(error: OSError) -> str:
    """``cannot write PATH: REASON``; an error naming no path came from standard output.

    Every file twoball writes goes through :mod:`twoball._common.staging`, which names
    the user's path in its errors; what is left unnamed is the console.
    """
    reason = error.strerror or str(error)
    where = "standard output" if error.filename is None else os.fsdecode(error.filename)
    return f"cannot write {where}: {reason}"


def _flush_stdout() -> None:
    """Flush standard output now, so a full or closed one fails here, not at exit."""
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        raise
    except OSError as error:
        raise OSError(error.errno, error.strerror, "standard output") from None


def _quiet_stdout() -> None:
    """Point standard output at /dev/null so the interpreter's last flush cannot fail."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError, AttributeError):
        pass
