"""The resource guard: refuse, before it starts, work that cannot fit in memory or time.

Every expensive path's verb asks the work's cost model for an
:class:`~twoball._common.estimate.Estimate` (the closed-form series:
:mod:`twoball.modal.cost`; the finite elements: :mod:`twoball.fem_membrane.cost`;
the drop: :mod:`twoball.modal.floor.cost`; sweeps and worker pools:
:mod:`twoball.verify.sweeps.cost`; field frames: :mod:`twoball.verify.output.fields`)
and passes it to :func:`check` *before* anything is allocated.  The cost models
only estimate; the refusal is the edge's.  Above the limit it
raises :class:`BudgetError` (a :class:`~twoball._common.errors.ParameterError`,
so the command line prints one line and exits with status 2)::

    modes 100000 needs ~15 GiB of memory; limit 11.7 GiB (raise the memory limit, max_memory)

Limits
    Memory: ``max_memory`` (command line ``--max-memory``) or ``TWOBALL_MAX_MEMORY``
    (``12GiB``, ``500MB``, ``2e9``); default half the machine's physical memory --
    the share one run may take while the desktop, other runs and the page cache
    keep the rest, so that a run near the limit is refused and never swaps or
    meets the OOM killer -- or, under an address-space limit (``ulimit -v``), a
    third of the address space still free if that is less (sparse LU reserves
    about three times what the estimates count, :data:`ADDRESS_SPACE_PER_RESIDENT`).
    Under such a limit the address space an estimate maps (its ``address``, from
    the finite elements' cost model; else its memory) must also fit in what is
    left, whatever ``max_memory`` says: a run that would fail its allocations
    after a minute is refused at once.
    Time: ``max_time`` or ``TWOBALL_MAX_TIME`` (``3600``, ``90min``, ``2h``, or
    ``off``).  Given, it is both the refusal (no estimate above it starts) and the
    deadline (the work stops there).  Left out, each piece of work whose estimate
    is above five minutes is refused -- more than five times the slowest documented
    single run, so no ordinary run is refused, while a run that would look hung is
    refused at once and a deliberate long one says so -- and the deadline follows
    the estimates instead of a fixed five minutes: each accepted estimate moves
    it to at least :data:`ESTIMATE_SLACK` times the estimate from when that
    work starts (never below five minutes).  The estimates are right within a
    factor of 2-3 on an idle machine, and a shared one is slower again (the full
    reproduction: 107 s idle, 698 s with five jobs on two cores), so a run the
    estimates accepted is not killed for the machine's load, while one that has
    gone astray is still stopped.  A verb whose job is legitimately long and
    made of many estimated pieces has no default deadline at all
    (:func:`verb_default`: ``reproduce``).

The deadline
    Estimates are right within a factor of 2-3 at best, so the time limit is
    also a deadline: the outermost public verb (or command) starts its clock
    (:func:`running`), and the long loops of every solver -- the series
    evaluation chunks, the contact event loop, the generalized-alpha steps, the
    Krylov iterations, the drop's steps, sweep points, study runs -- tell their
    monitor what they do (:mod:`twoball._common.monitor`); the edge's monitor
    (:class:`twoball._common.watch.Watch`) calls :func:`check_deadline`.
    Past the limit it raises :class:`DeadlineError` (a
    :class:`~twoball._common.errors.NumericalError`: exit status 3, one line
    naming what was running).  Nested verbs share the outer clock.

Only the standard library is imported here.
"""

from __future__ import annotations

import functools
import math
import os
import re
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, TypeVar

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.estimate import BASE_MEMORY, Estimate, GiB, KiB, MiB, TiB, options

__all__ = [
    "BASE_MEMORY",
    "Budget",
    "BudgetError",
    "DeadlineError",
    "Estimate",
    "GiB",
    "KiB",
    "MiB",
    "TiB",
    "check",
    "check_all",
    "check_deadline",
    "current_budget",
    "limits",
    "options",
    "running",
    "set_budget",
    "timed",
    "verb_default",
]

DEFAULT_MEMORY_SHARE = 0.5  # of physical memory
FALLBACK_MEMORY = 4 * GiB  # when the machine's memory cannot be read
DEFAULT_MAX_SECONDS = 300.0
#: The default deadline: at least this many times each accepted estimate from its start.
ESTIMATE_SLACK = 10.0
#: Words that turn the time limit off (``--max-time off``).
OFF = ("off", "none")
MEMORY_ENV = "TWOBALL_MAX_MEMORY"
TIME_ENV = "TWOBALL_MAX_TIME"

#: Address space mapped per byte of the estimates (resident memory): SuperLU reserves
#: (calloc) its fill estimate for every factorisation and touches a fraction; measured
#: sphere L5 P4: 9.5 GB mapped at 1.6 GB resident, estimate 3.3 GB.
ADDRESS_SPACE_PER_RESIDENT = 3.0

_UNITS = {
    "": 1,
    "b": 1,
    "k": 10**3,
    "kb": 10**3,
    "m": 10**6,
    "mb": 10**6,
    "g": 10**9,
    "gb": 10**9,
    "t": 10**12,
    "tb": 10**12,
    "kib": KiB,
    "mib": MiB,
    "gib": GiB,
    "tib": TiB,
}
_SECONDS = {"": 1.0, "s": 1.0, "min": 60.0, "m": 60.0, "h": 3600.0}


class BudgetError(ParameterError):
    """A run would exceed the memory or time budget (refused before it starts)."""

    def __init__(self, option: str, message: str) -> None:
        ValueError.__init__(self, message)
        self.name = option
        self.valid = message
        self.got = None


def physical_memory() -> int | None:
    """The machine's physical memory [bytes], or None if the OS does not say."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):
        return None


def address_space_left() -> int | None:
    """Bytes the process may still map under its address-space limit (``ulimit -v``), or None.

    ``RLIMIT_AS`` less the virtual size already mapped (``/proc/self/statm``; 0 where
    it cannot be read).  None without such a limit.
    """
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    except (ImportError, AttributeError, OSError, ValueError):
        return None
    if soft == resource.RLIM_INFINITY or soft < 0:
        return None
    used = 0
    try:
        with open("/proc/self/statm") as statm:
            used = int(statm.read().split()[0]) * int(os.sysconf("SC_PAGE_SIZE"))
    except (OSError, ValueError, IndexError, AttributeError):
        pass
    return max(int(soft) - used, 0)


def parse_bytes(text: str | float, option: str = "max_memory") -> int:
    """A memory size: a number of bytes or with a unit (``12GiB``, ``500MB``, ``2e9``)."""
    match = re.fullmatch(r"\s*([0-9.eE+-]+)\s*([a-zA-Z]*)\s*", str(text))
    valid = "a size > 0 such as 12GiB, 500MB or 2e9 (bytes)"
    if not match or match.group(2).lower() not in _UNITS:
        raise ParameterError(option, valid, text)
    try:
        value = float(match.group(1)) * _UNITS[match.group(2).lower()]
    except ValueError:
        raise ParameterError(option, valid, text) from None
    if not (math.isfinite(value) and value > 0):
        raise ParameterError(option, valid, text)
    return int(value)


def parse_seconds(text: str | float, option: str = "max_time") -> float:
    """A duration: seconds or with a unit (``3600``, ``90min``, ``2h``); ``off``: infinite."""
    if isinstance(text, str) and text.strip().lower() in OFF:
        return math.inf
    match = re.fullmatch(r"\s*([0-9.eE+-]+)\s*([a-zA-Z]*)\s*", str(text))
    valid = "a duration > 0 such as 3600, 90min or 2h, or off"
    if not match or match.group(2).lower() not in _SECONDS:
        raise ParameterError(option, valid, text)
    try:
        value = float(match.group(1)) * _SECONDS[match.group(2).lower()]
    except ValueError:
        raise ParameterError(option, valid, text) from None
    if not (math.isfinite(value) and value > 0):
        raise ParameterError(option, valid, text)
    return value


def format_bytes(size: float) -> str:
    """``15 GiB``, ``11.7 GiB``, ``350 MiB`` (two or three significant digits)."""
    for unit, scale in (("TiB", TiB), ("GiB", GiB), ("MiB", MiB), ("KiB", KiB)):
        if size >= scale:
            value = size / scale
            return f"{value:.3g} {unit}"
    return f"{size:.0f} B"


def format_seconds(seconds: float) -> str:
    """``40 s``, ``25 min``, ``1 h``, ``3.1 h``, ``12 days``; ``off`` for no limit."""
    if math.isinf(seconds):
        return "off"
    if seconds < 120:
        return f"{seconds:.2g} s"
    if seconds < 3600:
        return f"{seconds / 60:.0f} min"
    if seconds < 2 * 86400:
        return f"{seconds / 3600:.2g} h"
    return f"{seconds / 86400:.3g} days"


@dataclass(frozen=True)
class Budget:
    """Memory [bytes] and time [s] one run may use.

    Parameters
    ----------
    max_memory : int
        Peak memory limit [bytes]; default half the physical memory.
    max_seconds : float
        Wall-time limit [s] (``inf``: none); default five minutes.
    follows : bool
        The time limit is the default (not given): the deadline follows the
        accepted estimates (:data:`ESTIMATE_SLACK`), and a verb may set its own
        default (:func:`verb_default`).
    """

    max_memory: int
    max_seconds: float = DEFAULT_MAX_SECONDS
    follows: bool = False

    @classmethod
    def default(cls) -> Budget:
        """From ``TWOBALL_MAX_MEMORY`` / ``TWOBALL_MAX_TIME``, else the defaults."""
        return cls.from_options(None, None)

    @classmethod
    def from_options(
        cls, max_memory: str | float | None = None, max_time: str | float | None = None
    ) -> Budget:
        """The budget of ``--max-memory`` and ``--max-time`` (or their environment variables)."""
        memory_text = max_memory if max_memory is not None else os.environ.get(MEMORY_ENV)
        time_text = max_time if max_time is not None else os.environ.get(TIME_ENV)
        if memory_text is None:
            total = physical_memory()
            memory = int(DEFAULT_MEMORY_SHARE * total) if total else FALLBACK_MEMORY
            left = address_space_left()  # under ``ulimit -v`` the address space is the limit
            if left is not None:
                memory = min(memory, int(left / ADDRESS_SPACE_PER_RESIDENT))
        else:
            memory = parse_bytes(memory_text)
        if time_text is None:
            return cls(memory, DEFAULT_MAX_SECONDS, follows=True)
        return cls(memory, parse_seconds(time_text))

    def check(self, option: str, estimate: Estimate) -> Estimate:
        """Raise :class:`BudgetError` naming ``option`` if ``estimate`` exceeds a limit.

        ``option`` is how the user asked for the work, e.g. ``"modes 100000"``.
        """
        if not (estimate.memory <= self.max_memory):
            raise BudgetError(
                option.split()[0] if option else "max_memory",
                f"{option} needs ~{format_bytes(estimate.memory)} of memory; "
                f"limit {format_bytes(self.max_memory)} (raise the memory limit, max_memory)",
            )
        if not (estimate.seconds <= self.max_seconds):
            raise BudgetError(
                option.split()[0] if option else "max_time",
                f"{option} needs ~{format_seconds(estimate.seconds)}; "
                f"limit {format_seconds(self.max_seconds)} (raise the time limit, max_time)",
            )
        if self.follows:
            _follow(estimate.seconds)
        left = address_space_left()  # ``ulimit -v``: whatever the memory limit says
        mapped = max(estimate.address, estimate.memory)
        if left is not None and not (mapped <= left):
            raise BudgetError(
                option.split()[0] if option else "max_memory",
                f"{option} needs ~{format_bytes(mapped)} of address space (sparse LU and "
                f"the renderer reserve more than they touch); {format_bytes(left)} left "
                "under the address-space "
                "limit (ulimit -v): choose a smaller size, or raise that limit",
            )
        return estimate


_current: Budget | None = None


def current_budget() -> Budget:
    """The budget in force: the one set by :func:`set_budget`, else :meth:`Budget.default`."""
    return _current if _current is not None else Budget.default()


def set_budget(budget: Budget | None) -> Budget | None:
    """Make ``budget`` the one in force (None: back to the default); returns the previous."""
    global _current
    previous, _current = _current, budget
    return previous


@contextmanager
def limits(
    max_memory: str | float | None = None, max_time: str | float | None = None
) -> Iterator[Budget]:
    """``with limits("4GiB", "10min"):`` -- a budget for the enclosed work only."""
    budget = Budget.from_options(max_memory, max_time)
    previous = set_budget(budget)
    try:
        yield budget
    finally:
        set_budget(previous)


def check(option: str, estimate: Estimate) -> Estimate:
    """:meth:`Budget.check` with the budget in force."""
    return current_budget().check(option, estimate)


def check_all(work: Iterable[tuple[str, Estimate]]) -> Estimate | None:
    """:func:`check` each stage of a piece of work in turn; the last estimate (None: no stage).

    ``work`` as a cost model describes it: ``(option, estimate)`` pairs, e.g.
    :func:`twoball.fem_membrane.cost.fem_work` (the mesh, then the stepping).
    """
    estimate = None
    for option, stage in work:
        estimate = check(option, stage)
    return estimate


class DeadlineError(NumericalError):
    """The work ran past the time limit (``max_time``) and was stopped (exit status 3)."""


#: The clock of the time limit: when the outermost verb started (None: no clock),
#: and the limit in force with the moment it was read (re-read at most once a second).
#: ``follows``: whether that limit is the default; ``follow``: where the estimates put it.
_clock: dict[str, float | None] = {
    "start": None,
    "limit": None,
    "read": None,
    "follows": None,
    "follow": None,
}
_LIMIT_REFRESH_S = 1.0

_F = TypeVar("_F", bound=Callable[..., Any])


@contextmanager
def running() -> Iterator[None]:
    """Start the clock of the time limit for the enclosed work (unless one runs already)."""
    if _clock["start"] is not None:  # a verb inside a verb (or a command): one clock
        yield
        return
    _clock.update(start=time.monotonic(), limit=None, read=None, follow=None)
    try:
        yield
    finally:
        _clock.update(start=None, limit=None, read=None, follow=None)


def timed(function: _F) -> _F:
    """Decorator of a public verb: its work runs on the clock of :func:`running`."""

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        with running():
            return function(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


def _follow(seconds: float) -> None:
    """An estimate was accepted under the default limit: the deadline is at least
    :data:`ESTIMATE_SLACK` times it from now (on the running clock)."""
    start = _clock["start"]
    if start is None or not math.isfinite(seconds):
        return
    until = time.monotonic() - start + ESTIMATE_SLACK * seconds
    _clock["follow"] = max(_clock["follow"] or 0.0, until)


@contextmanager
def verb_default(seconds: float) -> Iterator[None]:
    """The verb's own default time limit (``inf``: none) while the budget's is the default.

    A limit given (``max_time``, ``--max-time``, ``TWOBALL_MAX_TIME``) stands.
    """
    budget = current_budget()
    if not budget.follows:
        yield
        return
    previous = set_budget(Budget(budget.max_memory, seconds, follows=True))
    _clock["read"] = None  # the deadline reads the new limit at once
    try:
        yield
    finally:
        set_budget(previous)
        _clock["read"] = None


def elapsed() -> float | None:
    """Seconds since the clock started (None without one)."""
    start = _clock["start"]
    return None if start is None else time.monotonic() - start


def check_deadline(doing: str) -> None:
    """Raise :class:`DeadlineError` if the work has run past the time limit.

    ``doing`` says what was running (``"the contact event loop at t = 3.1 of
    12.6"``); it is also what the progress line shows after the step
    (:func:`twoball._common.progress.set_activity`).  Cheap enough for every pass
    of a long loop (one clock read; the limit itself is read again at most once
    a second).
    """
    from twoball._common.progress import set_activity
    from twoball._common.signals import resume

    set_activity(doing)
    resume()  # work goes on after a commit: a signal held since then acts here
    start = _clock["start"]
    if start is None:
        return
    now = time.monotonic()
    read = _clock["read"]
    if read is None or now - read > _LIMIT_REFRESH_S:
        budget = current_budget()
        _clock.update(limit=budget.max_seconds, read=now, follows=float(budget.follows))
    limit = _clock["limit"]
    assert limit is not None
    follows = bool(_clock["follows"])
    if follows:  # the default limit: the accepted estimates move it
        limit = max(limit, _clock["follow"] or 0.0)
    if now - start > limit:
        which = "the default time limit" if follows else "the time limit"
        raise DeadlineError(
            f"stopped at {which} {format_seconds(limit)} after "
            f"{format_seconds(now - start)}, while {doing} (raise the time limit, max_time)"
        )
