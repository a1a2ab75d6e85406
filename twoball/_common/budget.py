"""Resource guards: estimate memory and time before the work starts, refuse what cannot fit.

Every expensive path (the closed-form series, the finite-element mesh and eigen
solve, generalized-alpha stepping, sweeps, worker pools, frames) asks for an
:class:`Estimate` from the small formulas below and passes it to
:meth:`Budget.check` *before* it allocates anything.  Above the limit it raises
:class:`BudgetError` (a :class:`~twoball._common.errors.ParameterError`, so the
command line prints one line and exits with status 2)::

    --modes 100000 needs ~15 GiB of memory; limit 11.7 GiB (set --max-memory)

Limits
    Memory: ``--max-memory`` or ``TWOBALL_MAX_MEMORY`` (``12GiB``, ``500MB``,
    ``2e9``); default half the machine's physical memory -- the share one run may
    take while the desktop, other runs and the page cache keep the rest, so that a
    run near the limit is refused and never swaps or meets the OOM killer.
    Time: ``--max-time`` or ``TWOBALL_MAX_TIME`` (``3600``, ``90min``, ``2h``);
    default five minutes -- more than five times the slowest documented single run
    (generalized-alpha on the P2 level-3 sphere, 42 s; the series with N = 6000,
    48 s), so no ordinary run is refused, while a run that would look hung (N =
    20000: ~9 min) is refused at once and a deliberate long one says so with
    ``--max-time``.

Calibration (peak RSS from ``resource.getrusage`` of a child process, wall time
on the 2-core build machine; ``benchmarks/bench_budget.py`` prints them; the
estimates are meant to be right within a factor of 2-3, which is all a refusal
needs):

================================  ========================  =======================
run                               measured                  model
================================  ========================  =======================
liftoff N = 1000 / 3000 / 6000    218 / 480 / 873 MiB,      base + max(8 m (N+1),
                                  1.1 / 8.0 / 48 s          24 min(S, 4096) (N+1));
                                                            40 ns x S x (N+1)
FE sphere P1 L4 / L5, P2 L3 / L4  187 / 312, 159 / 283 MiB  base + 20 kB/DOF
(Krylov route)                    1.5 / 3.4, 1.6 / 5.9 s    0.6 ms/DOF
FE full route, P2 L3              171 MiB, 8 s              + 3 us x DOFs x (N+1)^2
alpha, P2 L2 / L3, axisym 8001    2.4 / 17 / 8 ms per step  0.3 ms + 1 us x DOFs
                                                            + 5 ns x DOFs x modes
================================  ========================  =======================

``S`` is the number of time samples of the bracketing grid, 16 per period of the
highest retained mode (:func:`twoball.modal.liftoff.bracketing_grid`), ``m`` the
Gauss points of eq. (3.12) (:func:`twoball.modal.legendre.quadrature_points`).

Only the standard library is imported here (``twoball --help`` stays cheap).
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from twoball._common.errors import ParameterError

KiB, MiB, GiB, TiB = 2**10, 2**20, 2**30, 2**40
DEFAULT_MEMORY_SHARE = 0.5  # of physical memory
FALLBACK_MEMORY = 4 * GiB  # when the machine's memory cannot be read
DEFAULT_MAX_SECONDS = 300.0
MEMORY_ENV = "TWOBALL_MAX_MEMORY"
TIME_ENV = "TWOBALL_MAX_TIME"
MAX_WORKERS_PER_CORE = 4

BASE_MEMORY = 100 * MiB  # interpreter, numpy, scipy (measured 89 MiB)
WORKER_MEMORY = 150 * MiB  # one pool worker (a forked interpreter with the solver loaded)
SECONDS_PER_TERM = 40e-9  # one complex exp-multiply-add of the series evaluation
MAX_QUADRATURE = 20000  # twoball.modal.legendre._MAX_QUADRATURE
CHUNK = 4096  # twoball.modal.series._CHUNK
SAMPLES_PER_PERIOD = 16
FE_BYTES_PER_DOF = 20 * KiB  # Krylov basis, LU fill, mesh and assembly (P1/P2, L3-L5)
FE_SECONDS_PER_DOF = 6e-4
FULL_ROUTE_SECONDS = 3e-6  # per DOF and eigenpair of the full eigen route
STEP_SECONDS = 3e-4  # per generalized-alpha step: Python overhead
STEP_SECONDS_PER_DOF = 1e-6  # sparse LU solves
STEP_SECONDS_PER_DOF_MODE = 5e-9  # low-rank modal damping (Woodbury)
STEP_BYTES = 160  # pole history and its three cubic splines per step
POINT_OVERHEAD_SECONDS = 3e-3  # one sweep point besides its series (case, report, reference)
POINT_BYTES = 8 * KiB  # one kept sweep point (case, report, candidates)
FRAME_FIELDS = 12  # doubles per node and frame: u, u_t, u_tt, u n, both backends

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
    """A duration: seconds or with a unit (``3600``, ``90min``, ``2h``)."""
    match = re.fullmatch(r"\s*([0-9.eE+-]+)\s*([a-zA-Z]*)\s*", str(text))
    valid = "a duration > 0 such as 3600, 90min or 2h"
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
    """``40 s``, ``25 min``, ``1 h``, ``3.1 h``, ``12 days``."""
    if seconds < 120:
        return f"{seconds:.2g} s"
    if seconds < 3600:
        return f"{seconds / 60:.0f} min"
    if seconds < 2 * 86400:
        return f"{seconds / 3600:.2g} h"
    return f"{seconds / 86400:.3g} days"


@dataclass(frozen=True)
class Estimate:
    """Peak memory [bytes] and wall time [s] a piece of work is expected to need."""

    memory: float
    seconds: float

    def __add__(self, other: Estimate) -> Estimate:
        """Work done one after the other: memories of the larger, times added."""
        return Estimate(max(self.memory, other.memory), self.seconds + other.seconds)


@dataclass(frozen=True)
class Budget:
    """Memory [bytes] and time [s] one run may use.

    Parameters
    ----------
    max_memory : int
        Peak memory limit [bytes]; default half the physical memory.
    max_seconds : float
        Wall-time limit [s]; default five minutes.
    """

    max_memory: int
    max_seconds: float = DEFAULT_MAX_SECONDS

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
        else:
            memory = parse_bytes(memory_text)
        seconds = DEFAULT_MAX_SECONDS if time_text is None else parse_seconds(time_text)
        return cls(memory, seconds)

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


def options(**values: object) -> str:
    """``--modes 100000 --t-end 1e+06`` from keyword values (None skipped; _ -> -)."""
    return " ".join(
        f"--{name.replace('_', '-')} {value:g}"
        if isinstance(value, float)
        else f"--{name.replace('_', '-')} {value}"
        for name, value in values.items()
        if value is not None
    )


# --- estimators -------------------------------------------------------------------


def legendre_omega(modes: int) -> float:
    """``omega_N = sqrt(N (N + 1))``, the highest retained frequency (dimensionless)."""
    return math.sqrt(modes * (modes + 1.0))


def grid_samples(omega_max: float, t_end: float) -> float:
    """Samples of the bracketing grid: 16 per period of ``omega_max`` over [0, t_end]."""
    return math.ceil(t_end * max(omega_max, 1.0) * SAMPLES_PER_PERIOD / (2.0 * math.pi)) + 1


def series_estimate(modes: int, t_end: float, terms: int | None = None) -> Estimate:
    """The closed-form lift-off with N modes over a window ``t_end`` (dimensionless).

    Memory: the larger of the Gauss rule's Vandermonde matrix of eq. (3.12),
    ``8 m (N + 1)`` bytes with ``m = min(N + 50, 20000)``, and the evaluation: the
    exponential tables, ``24 min(S, 4096) K`` bytes for K retained modes, and the
    grid's u, u_t, u_tt and force, ``48 S`` bytes.  Time: ``40 ns x S x K``.  ``terms`` is K when it
    differs from N + 1 (e.g. finite-element modes).
    """
    modes = int(modes)
    kept = modes + 1 if terms is None else int(terms)
    samples = grid_samples(legendre_omega(modes), t_end)
    points = min(modes + 50, MAX_QUADRATURE) if terms is None else 0
    # the Vandermonde matrix is freed before the evaluation starts: the larger one is the peak
    evaluation = 24.0 * min(samples, CHUNK) * kept + 48.0 * samples
    memory = BASE_MEMORY + max(8.0 * points * (modes + 1), evaluation)
    return Estimate(memory, SECONDS_PER_TERM * samples * kept)


def reference_estimate(t_end: float, modes: int = 240) -> Estimate:
    """The converged-series reference of the truncation guard (N up to ~240, the window)."""
    return series_estimate(modes, t_end)


def fem_dofs(mesh: object, level: int | None, elements: int | None, order: int) -> int:
    """Degrees of freedom of the finite-element space, in closed form (no mesh built).

    Icosphere of level L: ``20 4^L`` triangles, so ``10 4^L p^2 + 2`` DOFs for
    order p; ring sphere: ``4 n^2 + 2`` vertices with ``n ~ sqrt(10) 2^(L-1)``;
    axisymmetric line of E elements: ``p E + 1``.
    """
    if not isinstance(mesh, str):  # a SphereMesh (a user's file): its own size
        order = mesh.order if order is None else int(order)
        return len(mesh.cells) * order * order // 2 + 2  # closed surface: V = T / 2 + 2
    order = int(order)
    if mesh == "axisym":
        return order * int(400 if elements is None else elements) + 1
    level = 3 if level is None else int(level)
    if level > 60:  # 4^level overflows any machine: report it as such
        return 10**40
    if mesh == "ring":
        rows = max(2, round(math.sqrt(10.0) * 2.0 ** (level - 1)))
        return 4 * rows * rows * order * order + 2
    return 10 * 4**level * order * order + 2


def fem_estimate(dofs: int, modes: int = 30, route: str = "krylov", dimension: int = 2) -> Estimate:
    """Assembly, eigen solve (or Krylov series) and lift-off of a FE space of ``dofs``.

    Memory ``base + 20 kB/DOF`` (measured P1/P2, levels 3-5); time ``0.6 ms/DOF``
    on the Krylov route, plus ``3 us x DOFs x (N + 1)^2`` on the full route
    (every eigenpair below the cutoff: ``(N + 1)^2`` on the sphere, ``N + 1`` on
    the axisymmetric line, ``dimension`` 2 or 1).
    """
    pairs = (modes + 1) ** 2 if dimension == 2 else modes + 1
    memory = BASE_MEMORY + FE_BYTES_PER_DOF * dofs
    seconds = FE_SECONDS_PER_DOF * dofs
    if route == "full":
        memory += 8.0 * dofs * pairs
        seconds += FULL_ROUTE_SECONDS * dofs * pairs
    return Estimate(memory, seconds)


def alpha_estimate(dofs: int, pairs: int, t_end: float, dt: float) -> Estimate:
    """Generalized-alpha stepping of ``t_end / dt`` steps on ``dofs`` (dimensionless times).

    Per step ``0.3 ms + 1 us x DOFs + 5 ns x DOFs x pairs`` (the low-rank modal
    damping of ``pairs`` modes); 160 bytes per step for the pole history and its
    splines.
    """
    steps = math.ceil(t_end / dt)
    per_step = STEP_SECONDS + STEP_SECONDS_PER_DOF * dofs + STEP_SECONDS_PER_DOF_MODE * dofs * pairs
    return Estimate(BASE_MEMORY + STEP_BYTES * steps + 8.0 * dofs * pairs, steps * per_step)


def sweep_estimate(points: int, per_point: Estimate, workers: int = 1) -> Estimate:
    """``points`` solves of ``per_point`` each, on ``workers`` processes (limited by the cores)."""
    parallel = max(1, min(int(workers), os.cpu_count() or 1))
    seconds = points * (per_point.seconds + POINT_OVERHEAD_SECONDS) / parallel
    memory = per_point.memory + (parallel - 1) * WORKER_MEMORY + POINT_BYTES * points
    return Estimate(memory, seconds)


def check_workers(workers: int | None) -> None:
    """Refuse more than four workers per core (they only contend) or more than memory allows."""
    if workers is None:
        return
    cores = os.cpu_count() or 1
    if workers > MAX_WORKERS_PER_CORE * cores:
        raise ParameterError(
            "workers",
            f"an integer in [1, {MAX_WORKERS_PER_CORE * cores}] "
            f"({MAX_WORKERS_PER_CORE} per core, {cores} cores)",
            workers,
        )
    check(f"workers {workers}", Estimate(BASE_MEMORY + workers * WORKER_MEMORY, 0.0))


def frames_estimate(
    frames: int, nodes: int, modes: int, seconds_per_frame: float = 0.0
) -> Estimate:
    """Fields at ``frames`` instants on ``nodes`` nodes from ``modes`` modes (export, render, plot).

    Memory ``12 doubles x nodes x frames`` (u, u_t, u_tt and u n of both backends);
    time ``40 ns x frames x nodes x modes`` for the evaluation plus
    ``seconds_per_frame`` for drawing or writing each frame.
    """
    memory = BASE_MEMORY + 8.0 * FRAME_FIELDS * nodes * frames + 8.0 * nodes * modes
    seconds = frames * (SECONDS_PER_TERM * nodes * modes + seconds_per_frame)
    return Estimate(memory, seconds)


def check_series(modes: int, t_end: float, t_end_s: float | None = None) -> Estimate:
    """Refuse a closed-form lift-off (N modes, window ``t_end`` dimensionless) that cannot fit.

    The truncation guard's converged reference over the same window is included.
    """
    estimate = series_estimate(modes, t_end) + reference_estimate(t_end)
    return check(options(modes=int(modes), t_end=t_end_s), estimate)


def check_fem(
    mesh: str,
    level: int | None,
    elements: int | None,
    order: int,
    modes: int,
    route: str,
    *,
    scheme: str = "modal",
    dt: float | None = None,
    t_end: float = 4.0 * math.pi,
    step_accuracy: float = 0.2,
    time_unit_s: float | None = None,
) -> Estimate:
    """Refuse a finite-element run (mesh, eigen solve, and stepping for ``alpha``) that cannot fit.

    ``dt`` and ``t_end`` are dimensionless; ``time_unit_s`` (1/c in seconds) only
    turns dt back into the ``--dt`` the user typed for the message.
    """
    dofs = fem_dofs(mesh, level, elements, order)
    dimension = 1 if mesh == "axisym" else 2
    if route == "auto":
        route = "krylov" if dofs >= 2000 else "full"
    if scheme == "alpha":
        route = "full"
    size = options(level=level, elements=elements, order=order) or "the finite-element mesh"
    estimate = check(size, fem_estimate(dofs, modes, route, dimension))
    if scheme != "alpha":
        return estimate
    omega_cut = 0.5 * (legendre_omega(modes) + legendre_omega(modes + 1))
    step = dt if dt is not None else step_accuracy / omega_cut
    pairs = (modes + 1) ** 2 if dimension == 2 else modes + 1
    if dt is None:
        option = "scheme alpha"
    elif time_unit_s is None:
        option = f"dt (dt c = {dt:.3g})"
    else:
        option = options(dt=dt * time_unit_s)
    return check(option, estimate + alpha_estimate(dofs, pairs, t_end, step))


def check_sweep(
    points: int, modes: int, t_end: float, workers: int | None = None, reference: bool = False
) -> Estimate:
    """Refuse a sweep of ``points`` closed-form solves (N ``modes``, window ``t_end``).

    Workers: at most four per core, each ~150 MiB.  Per point: the series (and,
    with ``reference``, the truncation guard's converged series) plus ~3 ms of
    bookkeeping.
    """
    check_workers(workers)
    cores = os.cpu_count() or 1
    per_point = series_estimate(modes, t_end)
    if reference:
        per_point = per_point + reference_estimate(t_end)
    estimate = sweep_estimate(points, per_point, cores if workers is None else workers)
    return check(f"values ({points} points)", estimate)


def check_count(option: str, count: float, bytes_each: float = 8.0) -> Estimate:
    """Refuse an array of ``count`` items (e.g. the values of ``--values``) that cannot fit."""
    return check(option, Estimate(BASE_MEMORY + bytes_each * count, 0.0))


def check_frames(
    option: str,
    frames: int,
    mesh: str = "sphere",
    level: int | None = None,
    order: int = 2,
    modes: int = 30,
    seconds_per_frame: float = 0.0,
) -> Estimate:
    """Refuse ``frames`` field frames on the mesh (export, render, plot) that cannot fit.

    The mode count is the FE one, ``(N + 1)^2`` on the sphere (the Legendre
    backend has fewer); ``seconds_per_frame`` is the drawing or writing of a frame.
    """
    nodes = fem_dofs(mesh, level, None, order)
    pairs = (modes + 1) ** 2
    return check(option, frames_estimate(frames, nodes, pairs, seconds_per_frame))
