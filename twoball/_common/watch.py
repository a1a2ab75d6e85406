"""The edge's monitor: what the verbs hand the numerics so that limits, interrupts and
progress behave.

:class:`Watch` is a :class:`~twoball._common.monitor.Monitor`.  Told what the
work is doing, it shows it on the progress line, lets a signal held since the
last commit act (:func:`twoball._common.signals.resume`) and stops the work past
the time limit (:func:`twoball._common.budget.check_deadline`, exit status 3).
A long compiled call goes to a child process
(:func:`twoball._common.child.in_child`), so that the progress line keeps moving,
an interrupt acts at once and the time limit is watched while it runs, with the
same numbers.  A watch has no state: it pickles, so a task on a process pool
carries it.  Only the standard library is imported here.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

__all__ = ["Watch"]

_T = TypeVar("_T")


class Watch:
    """The verbs' monitor: the time limit, the progress line's activity, held signals."""

    __slots__ = ()

    def __call__(self, doing: str) -> None:
        """Show ``doing``, let a held signal act, stop past the time limit."""
        from twoball._common.budget import check_deadline

        check_deadline(doing)

    def long_call(self, function: Callable[..., _T], *args: Any, doing: str) -> _T:
        """``function(*args)`` in a child process, watched (:func:`twoball._common.child.in_child`).

        The same numbers as a call in process, while the progress line moves.
        """
        from twoball._common.child import in_child

        return in_child(function, *args, doing=doing)

    def __reduce__(self) -> tuple[type[Watch], tuple[()]]:
        return (Watch, ())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Watch)

    def __hash__(self) -> int:
        return hash(Watch)
