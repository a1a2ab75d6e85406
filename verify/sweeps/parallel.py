"""Run many independent, cheap tasks: in process, on a local process pool, or on Dask.

The closed-form lift-off takes a few milliseconds, so the cost of a parallel run is
dominated by starting workers and shipping tasks, not by the solves.  The choices
below were measured on two cores (see ``docs/reproduction.rst``):

* ``workers == 1``: a plain loop in the calling process, in order.  Nothing is
  pickled and no process is started; this is the reference every other mode must
  reproduce exactly.
* ``workers > 1``, no scheduler: a :class:`concurrent.futures.ProcessPoolExecutor`.
  On Linux it uses the ``fork`` start method, so the workers inherit the imported
  modules and are ready in tens of milliseconds (a ``spawn``-ed worker, and a Dask
  ``LocalCluster``, first has to import numpy and scipy again: 1-3 s).  The pool is
  started when the :class:`Runner` is entered, before any progress bar (and its
  thread) exists.  Elsewhere ``spawn`` is used.
* ``scheduler`` given: an existing ``dask.distributed`` scheduler (``tcp://host:port``).
  Dask is an optional dependency (``pip install twoball[dask]``); it is imported
  only on this path.  The workers must be able to import ``modal`` and ``verify``.

Tasks travel in chunks of consecutive items so that one message carries enough
work; results are put back in input order whatever order the chunks finish in.
A task that raises becomes an :class:`Outcome` with ``error`` set (exception type
and message) instead of aborting the run; so does every task of a chunk whose
worker died.
"""

from __future__ import annotations

import contextlib
import math
import os
import signal
import sys
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from numbers import Integral
from typing import Any

from twoball._common.budget import DeadlineError, check_deadline
from twoball._common.errors import ParameterError

#: Maps with fewer items than this run in the calling process even when workers
#: are available: shipping them costs more than solving them (a solve is ~3-5 ms).
MIN_PARALLEL_ITEMS = 16
#: Largest number of items sent to a worker in one message.
MAX_CHUNK = 32
#: Chunks aimed at per worker (load balance and progress granularity).
CHUNKS_PER_WORKER = 8
#: Seconds between two checks of the time limit while the pool's chunks run.
POLL_SECONDS = 0.5

VALID_RANGES = {"workers": "an integer >= 1"}
#: How long to try reaching a Dask scheduler before giving up.
CONNECT_TIMEOUT = "10s"


@dataclass(frozen=True)
class Outcome:
    """Result of one task: ``value`` on success, else ``error`` (type and message)."""

    value: Any = None
    error: str | None = None

    @property
    def ok(self) -> bool:
        """True if the task returned normally."""
        return self.error is None


def guarded(func: Callable[[Any], Any], item: Any) -> Outcome:
    """``func(item)`` as an :class:`Outcome`; an exception becomes ``error``."""
    try:
        return Outcome(func(item))
    except DeadlineError:  # the whole run stops at its time limit, not one point
        raise
    except Exception as exc:  # noqa: BLE001 - reported with the item, never lost
        return Outcome(None, f"{type(exc).__name__}: {exc}")


def run_chunk(func: Callable[[Any], Any], items: Sequence[Any]) -> list[Outcome]:
    """Run ``func`` over ``items`` in order (the unit of work sent to a worker)."""
    return [guarded(func, item) for item in items]


def default_workers() -> int:
    """The number of cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def chunk_size(count: int, workers: int) -> int:
    """Items per message: about CHUNKS_PER_WORKER chunks per worker, at most MAX_CHUNK."""
    if count <= 0:
        return 1
    return max(1, min(MAX_CHUNK, math.ceil(count / (max(1, workers) * CHUNKS_PER_WORKER))))


def check_workers(workers: int | None) -> int:
    """``workers`` validated (default: all cores); ParameterError names ``workers``."""
    if workers is None:
        return default_workers()
    if isinstance(workers, bool) or not isinstance(workers, Integral) or workers < 1:
        raise ParameterError("workers", VALID_RANGES["workers"], workers)
    return int(workers)


SCHEDULER_VALID = (
    "the address of a running dask.distributed scheduler, [tcp|tls]://HOST[:PORT] "
    "(default port 8786)"
)
_ADDRESS = (
    r"(?:(?P<protocol>tcp|tls)://)?"
    r"(?P<host>\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9._-]*[A-Za-z0-9])?)"
    r"(?::(?P<port>[0-9]{1,5}))?"
)
#: Protocols of dask addresses taken as written (no TCP port to probe); ``inproc`` (a
#: scheduler in this process, as a threads-only LocalCluster has) is looked up instead.
_UNPROBED = ("ucx", "ws", "wss")
#: Seconds a scheduler's port has to accept a connection before it counts as absent.
PROBE_SECONDS = 2.0


def check_scheduler(address: object) -> str:
    """A scheduler address in the form dask reads, checked before anything connects.

    Empty, malformed (``::::``) or out-of-range ports are refused by their form;
    a well-formed address is probed with one TCP connection (``PROBE_SECONDS``)
    which must greet as a dask scheduler does (:func:`_dask_handshake`; not over
    TLS), so a scheduler that is not there -- or a web server, a proxy, a silent
    port -- is reported at once and no dask client is left waiting for it.
    """
    import re
    import socket

    if not isinstance(address, str) or not address.strip():
        raise ParameterError("scheduler", SCHEDULER_VALID, address)
    protocol, _, rest = address.strip().partition("://")
    if protocol == "inproc":  # a scheduler of this very process, or none
        if not (rest and _inproc_listening(address.strip())):
            raise ParameterError(
                "scheduler",
                SCHEDULER_VALID + "; no scheduler of this process listens there",
                address,
            )
        return address.strip()
    if rest and protocol in _UNPROBED and re.fullmatch(r"[\w.\[\]:/-]+", rest):
        return address.strip()  # not TCP: dask itself connects
    match = re.fullmatch(_ADDRESS, address.strip())
    port = None if match is None or match["port"] is None else int(match["port"])
    if match is None or (port is not None and not 1 <= port <= 65535):
        raise ParameterError("scheduler", SCHEDULER_VALID, address)
    host = match["host"].strip("[]")
    try:
        with socket.create_connection((host, port or 8786), timeout=PROBE_SECONDS) as probe:
            if match["protocol"] != "tls":  # TLS speaks after the client's hello
                _dask_handshake(probe, address)
    except OSError as error:
        reason = error.strerror or type(error).__name__
        raise ParameterError(
            "scheduler", SCHEDULER_VALID + f"; none answers there ({reason})", address
        ) from None
    return address.strip()


#: Largest first message of a dask scheduler's handshake [bytes] (measured: 58).
HANDSHAKE_BYTES = 1 << 20


def _dask_handshake(probe: Any, address: str) -> None:
    """Refuse what listens at ``address`` unless it greets as a dask scheduler does.

    A dask TCP listener writes its handshake first, unasked: an 8-byte length
    (little-endian) of a short message.  A web server, a proxy or a port that
    accepts and stays silent says nothing for :data:`PROBE_SECONDS` (or something
    else), which the dask client would wait on, or read as a length of exabytes.
    """
    import struct

    head = b""
    try:
        while len(head) < 8:
            chunk = probe.recv(8 - len(head))
            if not chunk:
                break
            head += chunk
    except TimeoutError:
        raise ParameterError(
            "scheduler",
            SCHEDULER_VALID + f"; what listens there said nothing in {PROBE_SECONDS:g} s "
            "(not a dask scheduler)",
            address,
        ) from None
    size = struct.unpack("<Q", head)[0] if len(head) == 8 else 0
    if not 0 < size <= HANDSHAKE_BYTES:
        shown = head.decode("ascii", "replace").split("\n")[0].strip() or "nothing"
        raise ParameterError(
            "scheduler",
            SCHEDULER_VALID + f"; what listens there is not a dask scheduler (it said {shown!r})",
            address,
        )


def _inproc_listening(address: str) -> bool:
    """Whether a dask scheduler of this process listens at the ``inproc://`` ``address``."""
    try:
        from distributed.comm.inproc import global_manager
    except ImportError:
        return False
    try:
        return global_manager.get_listener_for(address.removeprefix("inproc://")) is not None
    except Exception:  # noqa: BLE001 -- a malformed address: nobody listens there
        return False


def _start_method() -> str:
    return "fork" if sys.platform.startswith("linux") else "spawn"


def _noop() -> int:
    return 0


_PR_SET_PDEATHSIG = 1


def _worker_init(parent: int) -> None:
    """Set up a pool worker: it ends with its parent and leaves signals to the parent.

    * Linux: ``prctl(PR_SET_PDEATHSIG, SIGKILL)`` -- the kernel kills the worker
      when the parent dies, however it dies (SIGKILL included).  Elsewhere the
      parent's ``finally`` (:meth:`Runner.close`) is the only guard.
    * SIGINT is ignored (Ctrl-C reaches the whole process group; the parent
      handles it and terminates the workers), SIGTERM is the default (the
      parent's ``terminate`` ends the worker at once, without a traceback).
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        import ctypes

        try:
            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        except (OSError, AttributeError):  # pragma: no cover - no prctl: parent's finally only
            pass
    if os.getppid() != parent:  # the parent died before prctl took effect
        os._exit(1)


class Runner:
    """Where tasks run; use as a context manager so pools and clients are closed.

    Parameters
    ----------
    workers : int, optional
        Local worker processes (default: all cores); 1 means strictly serial.
        Refused together with ``scheduler`` (the cluster decides).
    scheduler : str, optional
        Address of a running ``dask.distributed`` scheduler.
    """

    def __init__(self, workers: int | None = None, scheduler: str | None = None) -> None:
        if scheduler and workers is not None:
            raise ParameterError(
                "workers", "left out with scheduler (the cluster decides)", workers
            )
        self.workers = check_workers(workers)
        self.scheduler = None if scheduler is None else check_scheduler(scheduler)
        self._pool: ProcessPoolExecutor | None = None
        self._client: Any = None

    # --- life cycle -------------------------------------------------------
    @property
    def mode(self) -> str:
        """``serial``, ``processes`` or ``dask``."""
        if self.scheduler:
            return "dask"
        return "serial" if self.workers == 1 else "processes"

    def describe(self) -> str:
        """One line for people: where the tasks run."""
        if self.mode == "dask":
            return f"dask scheduler {self.scheduler}"
        if self.mode == "processes":
            return f"{self.workers} local processes ({_start_method()})"
        return "serial (in process)"

    def __enter__(self) -> Runner:
        if self.mode == "dask":
            self._client = _connect(self.scheduler)
        elif self.mode == "processes":
            import multiprocessing

            context = multiprocessing.get_context(_start_method())
            self._pool = ProcessPoolExecutor(
                self.workers,
                mp_context=context,
                initializer=_worker_init,
                initargs=(os.getpid(),),
            )
            from twoball._common.signals import pause

            try:
                # start every worker now, before a progress bar starts its thread
                for future in [self._pool.submit(_noop) for _ in range(self.workers)]:
                    future.result()
                pause("pool")
            except BaseException:  # __exit__ is not called when __enter__ raises
                self.close(abort=True)
                raise
        return self

    def __exit__(self, kind: type[BaseException] | None, *exc: object) -> None:
        self.close(abort=kind is not None)

    def close(self, abort: bool = False) -> None:
        """Shut the pool down / disconnect from the scheduler (the scheduler keeps running).

        ``abort`` (an exception or a signal is on its way): the workers are
        terminated and reaped at once instead of finishing their tasks.
        """
        if self._pool is not None:
            pool, self._pool = self._pool, None
            if abort:
                _terminate(pool)
            else:
                pool.shutdown(wait=True, cancel_futures=True)
        if self._client is not None:
            self._client.close()
            self._client = None

    @property
    def capacity(self) -> int:
        """Tasks that can run at once (dask: the cluster's threads)."""
        if self._client is not None:
            return max(1, sum(self._client.nthreads().values()))
        return self.workers

    # --- mapping ------------------------------------------------------------
    def map(
        self,
        func: Callable[[Any], Any],
        items: Sequence[Any],
        progress: Callable[[int], None] | None = None,
        min_parallel: int = MIN_PARALLEL_ITEMS,
        chunk: int | None = None,
    ) -> list[Outcome]:
        """``func`` over ``items``; outcomes in input order; ``progress(done)`` as they finish.

        ``func`` and the items must be picklable (a module-level function or a
        dataclass instance with ``__call__``) unless the runner is serial.  Maps
        shorter than ``min_parallel`` run in this process; ``chunk`` overrides the
        items per message (use 1 for tasks that take much longer than a solve).
        """
        items = list(items)
        if progress is not None:  # the progress line starts now (any pool has forked)
            progress(0)
        parallel = self._pool is not None or self._client is not None
        if not parallel or len(items) < max(1, min_parallel):
            return self._serial(func, items, progress)
        size = chunk or chunk_size(len(items), self.capacity)
        starts = list(range(0, len(items), size))
        chunks = [items[s : s + size] for s in starts]
        results: list[Outcome | None] = [None] * len(items)
        done = 0
        workers = f"{self.capacity} workers" if self.capacity > 1 else "1 worker"

        def waiting() -> None:  # while no chunk finishes: the deadline, what runs
            check_deadline(f"item {done + 1} of {len(items)} ({workers})")

        waiting()
        for start, outcomes in self._chunks(func, starts, chunks, waiting):
            check_deadline(f"item {done + 1} of {len(items)}")
            results[start : start + len(outcomes)] = outcomes
            done += len(outcomes)
            if progress is not None:
                progress(done)
        return [r if r is not None else Outcome(None, "lost: no result returned") for r in results]

    def _serial(self, func, items, progress) -> list[Outcome]:
        out = []
        for k, item in enumerate(items):
            check_deadline(f"item {k + 1} of {len(items)}")
            out.append(guarded(func, item))
            if progress is not None:
                progress(k + 1)
        return out

    def _chunks(self, func, starts, chunks, waiting=None):
        """Yield ``(start, outcomes)`` per chunk as they finish; failures become errors.

        ``waiting()`` is called every :data:`POLL_SECONDS` while no local chunk
        finishes (the deadline of the time limit)."""
        if self._client is not None:
            from distributed import as_completed as dask_completed

            futures = self._client.map(
                run_chunk, [func] * len(chunks), chunks, pure=False, retries=0
            )
            where = {f.key: (s, len(c)) for f, s, c in zip(futures, starts, chunks, strict=True)}
            for future in dask_completed(futures, loop=self._client.loop):
                start, length = where[future.key]
                yield start, _result(future, length)
            return
        futures = {
            self._pool.submit(run_chunk, func, chunk): (start, len(chunk))
            for start, chunk in zip(starts, chunks, strict=True)
        }
        pending = set(futures)
        while pending:
            finished, pending = wait(pending, timeout=POLL_SECONDS, return_when=FIRST_COMPLETED)
            if not finished and waiting is not None:
                waiting()
            for future in finished:
                start, length = futures[future]
                yield start, _result(future, length)


def _terminate(pool: ProcessPoolExecutor) -> None:
    """End the pool's workers now (SIGTERM, then SIGKILL after 2 s) and reap them."""
    from twoball._common.signals import deferred_signals

    with deferred_signals():
        processes = list((getattr(pool, "_processes", None) or {}).values())
        for process in processes:
            with contextlib.suppress(Exception):
                process.terminate()
        for process in processes:
            with contextlib.suppress(Exception):
                process.join(2.0)
                if process.is_alive():
                    process.kill()
                    process.join(1.0)
        pool.shutdown(wait=True, cancel_futures=True)


def _result(future: Any, length: int) -> list[Outcome]:
    try:
        return list(future.result())
    except Exception as exc:  # noqa: BLE001 - a dead worker loses its chunk, not the run
        return [Outcome(None, f"worker failed: {type(exc).__name__}: {exc}")] * length


def _connect(address: str | None) -> Any:
    try:
        from distributed import Client
    except ImportError:
        raise ParameterError(
            "scheduler", "used with dask installed (pip install 'twoball[dask]')", address
        ) from None
    import dask

    try:
        with dask.config.set({"distributed.comm.timeouts.connect": CONNECT_TIMEOUT}):
            return Client(address, timeout=CONNECT_TIMEOUT, set_as_default=False)
    except BaseException as exc:  # noqa: BLE001 -- one line, and no half-built client left
        _close_unfinished(exc)
        if not isinstance(exc, Exception):  # an interrupt: the client is closed, pass it on
            raise
        raise ParameterError(
            "scheduler",
            f"the address of a running dask.distributed scheduler ({type(exc).__name__}: "
            f"{' '.join(str(exc).split())[:120]})",
            address,
        ) from None


def _close_unfinished(error: BaseException) -> None:
    """Close the dask client whose constructor raised ``error`` (found in its traceback).

    Left alone, its ``__del__`` closes it at exit and prints a traceback when the
    scheduler is gone or never answered.
    """
    from distributed import Client

    trace = error.__traceback__
    while trace is not None:
        client = trace.tb_frame.f_locals.get("self")
        if isinstance(client, Client):
            with contextlib.suppress(BaseException):
                client.close(timeout=2)
            with contextlib.suppress(BaseException):  # __del__ finds it closed, says nothing
                client.status = "closed"
            return
        trace = trace.tb_next


def dask_available() -> bool:
    """True if ``dask.distributed`` can be imported."""
    try:
        import distributed  # noqa: F401
    except ImportError:
        return False
    return True
