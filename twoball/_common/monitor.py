"""The monitor handed to long numerical work: told what it does, it may stop it.

Numerical code (:mod:`twoball.modal`, :mod:`twoball.fem_membrane`) imports no
runtime policy -- no time limit, signal, child process or progress line.  A
long loop takes one optional callback instead, a :class:`Monitor`, and calls it
with a short text of what it is doing (``"the drop: step 812, 40 % of the
window"``) as often as is cheap; the callback may raise to stop the work (a
time limit, an interrupt).  A compiled call that holds the interpreter for
seconds goes through :func:`long_call`, which the monitor may run elsewhere
(its ``long_call`` attribute) so that it stays responsive.

The verbs build the monitor at the edge (:class:`twoball._common.watch.Watch`:
the time limit, the progress line's activity, signals held since a commit);
without one, numerical code runs unobserved (:func:`silent`).  Only the
standard library is imported here.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol, TypeVar, runtime_checkable

__all__ = ["Monitor", "long_call", "silent"]

_T = TypeVar("_T")


@runtime_checkable
class Monitor(Protocol):
    """A callback told what long work is doing; it may raise to stop it.

    Optionally with ``long_call(function, *args, doing=...)``: how a long
    compiled call is run (default: in process, see :func:`long_call`).
    """

    def __call__(self, doing: str) -> None:
        """Told what the work is doing now (raise to stop it)."""
        ...


def silent(doing: str) -> None:
    """The monitor that observes nothing (numerical code without a caller's policy)."""
    return None


def long_call(monitor: Monitor | None, function: Callable[..., _T], *args: Any, doing: str) -> _T:
    """``function(*args)``, through ``monitor.long_call`` where the monitor has one.

    A compiled call that holds the interpreter for seconds (dense LAPACK
    eigenpairs) cannot be watched from inside; the monitor at the edge may run
    it where the caller stays responsive (another process) and must return
    the same numbers.  Without one the call runs here, after one call of the
    monitor itself.
    """
    if monitor is not None:
        runner = getattr(monitor, "long_call", None)
        if runner is not None:
            return runner(function, *args, doing=doing)
        monitor(doing)
    return function(*args)
