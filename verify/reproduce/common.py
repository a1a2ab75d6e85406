"""Building blocks of ``twoball reproduce``: comparisons, sections, bisection, pole extrema.

Every part of the reproduction returns a :class:`Section`: prose, a table of
:class:`Comparison` rows (the paper's number, ours, the difference) and the
figures it wrote.  Nothing here is fitted to the paper.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from twoball._common.progress import TaskHook
from twoball._common.watch import Watch
from twoball.modal.filters import SpectralFilter, legendre_frequency
from twoball.modal.legendre import (
    legendre_coefficients_recurrence,
    legendre_series,
    quadrature_points,
)
from twoball.modal.liftoff import DEFAULT_T_END
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport, report_liftoff
from twoball.modal.series import ModalSeries
from twoball.verify.sweeps.parallel import Runner

#: Above this many Gauss points the coefficients come from the exact recurrence instead:
#: numpy's ``leggauss`` is a dense O(m^3) eigenproblem (0.3 s at m = 1000, 16 s at 3800),
#: cached per m only, and a bisection asks for a new m at nearly every step.
MAX_QUADRATURE_POINTS = 200


@dataclass(frozen=True)
class Comparison:
    """One number the paper states, beside ours.

    ``paper`` and ``ours`` are floats (or None when one side has no number);
    ``note`` says where the paper's number is and, if they differ, what we found.
    """

    quantity: str
    paper: float | None
    ours: float | None
    unit: str = ""
    source: str = ""
    note: str = ""
    digits: int = 4

    @property
    def difference(self) -> float | None:
        """ours - paper."""
        if self.paper is None or self.ours is None or not math.isfinite(self.ours):
            return None
        return self.ours - self.paper

    @property
    def relative(self) -> float | None:
        """``(ours - paper) / |paper|``."""
        d = self.difference
        if d is None or self.paper == 0:
            return None
        return d / abs(self.paper)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready."""
        return {
            "quantity": self.quantity,
            "paper": self.paper,
            "ours": self.ours,
            "unit": self.unit,
            "difference": self.difference,
            "relative_difference": self.relative,
            "source": self.source,
            "note": self.note,
        }


@dataclass
class Section:
    """A part of the report: title, prose paragraphs, comparisons, figures, extra data."""

    key: str
    title: str
    paragraphs: list[str] = field(default_factory=list)
    comparisons: list[Comparison] = field(default_factory=list)
    figures: list[tuple[str, str]] = field(default_factory=list)  # (file name, caption)
    tables: list[str] = field(default_factory=list)  # extra markdown tables
    data: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0


def fmt(value: float | None, digits: int = 4) -> str:
    """Number for the report: ``digits`` significant figures, or a dash."""
    if value is None:
        return "-"
    if isinstance(value, float) and not math.isfinite(value):
        return "none" if math.isnan(value) else str(value)
    return f"{value:.{digits}g}"


def comparison_table(rows: list[Comparison]) -> str:
    """Markdown table: quantity | paper | ours | ours - paper | note."""
    lines = [
        "| quantity | paper | ours | ours - paper | where / why |",
        "|---|---|---|---|---|",
    ]
    for r in rows:
        unit = f" {r.unit}" if r.unit else ""
        diff = "-"
        if r.difference is not None:
            diff = f"{r.difference:+.{r.digits}g}{unit}"
            if r.relative is not None:
                diff += f" ({100 * r.relative:+.1f} %)"
        note = " ".join(x for x in (f"[{r.source}]" if r.source else "", r.note) if x)
        paper = fmt(r.paper, r.digits) + (unit if r.paper is not None else "")
        ours = fmt(r.ours, r.digits) + (unit if r.ours is not None else "")
        lines.append(f"| {r.quantity} | {paper} | {ours} | {diff} | {note} |")
    return "\n".join(lines)


def markdown_table(header: list[str], rows: list[list[str]]) -> str:
    """A plain markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


# --- the solver with a fallback for extreme contact angles -------------------


def series_for(case: Case, sigma: str = "lanczos") -> ModalSeries:
    """The Legendre series of ``case``; exact recurrence when quadrature gets expensive.

    For phi_a very close to pi/2 (radii below ~0.3 mm in the threshold search) the
    quadrature of :func:`twoball.modal.legendre.legendre_coefficients` needs thousands of
    Gauss points; the three-term recurrence gives the same coefficients (agreement
    measured by the report) at no cost.
    """
    if quadrature_points(case.modes, case.phi_a) <= MAX_QUADRATURE_POINTS:
        return legendre_series(
            case.phi_a, case.damping, SpectralFilter(sigma, case.modes), monitor=Watch()
        )
    n = np.arange(case.modes + 1)
    return ModalSeries(
        omega=legendre_frequency(n),
        coefficients=legendre_coefficients_recurrence(case.phi_a, case.modes),
        pole_values=np.ones(n.size),
        damping=case.damping,
        filter=SpectralFilter(sigma, case.modes),
        mode_norms=4.0 * np.pi / (2 * n + 1),
        monitor=Watch(),
    )


def liftoff(case: Case, recontact: str = "window", sigma: str = "lanczos") -> LiftoffReport:
    """Lift-off with the shared criteria, via :func:`series_for`."""
    return report_liftoff(
        case,
        series_for(case, sigma),
        backend="legendre",
        sigma=sigma,
        recontact=recontact,
        monitor=Watch(),
    )


@dataclass(frozen=True)
class AccelerationMinima:
    """Smallest pole acceleration [m/s^2] over the window, three ways.

    ``overall``: over [0, t_end] (the literal Fig. 11(a) quantity; t = 0 included).
    ``moving_up``: only where the pole moves upwards (u_t > 0).
    ``main_wave``: only after ``main_wave_from_s`` (default 5 ms, as in docs/theory.rst).
    Times in seconds; None when the set is empty.
    """

    overall: float
    t_overall: float
    moving_up: float | None
    t_moving_up: float | None
    main_wave: float | None
    t_main_wave: float | None
    initial: float


def acceleration_minima(
    case: Case,
    sigma: str = "lanczos",
    t_end: float = DEFAULT_T_END,
    samples_per_period: int = 64,
    main_wave_from_s: float = 5e-3,
) -> AccelerationMinima:
    """Minima of the pole acceleration u_tt(t, 0) in SI (see :class:`AccelerationMinima`).

    Sampled at ``samples_per_period`` points per period of the highest mode; the
    unconstrained minima are refined by a bounded scalar search around the best sample.
    """
    series = series_for(case, sigma)
    scale = case.scalings
    omega = max(series.max_frequency, 1.0)
    count = math.ceil(t_end * omega * samples_per_period / (2 * math.pi)) + 1
    t = np.linspace(0.0, t_end, count)
    state = series.pole(t)
    acc = state.u_tt

    def refine(mask: np.ndarray) -> tuple[float | None, float | None]:
        if not mask.any():
            return None, None
        idx = np.flatnonzero(mask)
        k = int(idx[np.argmin(acc[idx])])
        best_t, best_a = t[k], acc[k]
        lo, hi = t[max(k - 1, 0)], t[min(k + 1, count - 1)]
        if hi > lo and mask[max(k - 1, 0)] and mask[min(k + 1, count - 1)]:
            res = minimize_scalar(
                lambda x: float(series.pole(np.array([x])).u_tt[0]),
                bounds=(lo, hi),
                method="bounded",
                options={"xatol": 1e-10},
            )
            if res.fun < best_a:
                best_t, best_a = float(res.x), float(res.fun)
        return best_a * scale.acceleration, best_t * scale.time

    overall, t_overall = refine(np.ones(count, dtype=bool))
    moving_up = state.u_t > 0
    moving_up[0] = False  # u_t(0) = 0 exactly; its computed sign is round-off
    up, t_up = refine(moving_up)
    main, t_main = refine(t * scale.time >= main_wave_from_s)
    return AccelerationMinima(
        overall, t_overall, up, t_up, main, t_main, float(acc[0] * scale.acceleration)
    )


# --- bisection for thresholds --------------------------------------------------


@dataclass(frozen=True)
class Threshold:
    """Boundary of a yes/no property along one parameter.

    ``value`` is the refined boundary (None if the scan found no change); ``bracket``
    the final interval; ``transitions`` every change seen on the scan grid (more than
    one means the property is not monotone there); ``errors`` failed evaluations.
    """

    value: float | None
    bracket: tuple[float, float] | None
    transitions: tuple[tuple[float, float], ...]
    evaluations: int
    errors: tuple[str, ...] = ()
    scan: tuple[tuple[float, bool | None], ...] = ()


def find_threshold(
    lifts: Callable[[float], bool],
    lo: float,
    hi: float,
    *,
    lifts_above: bool,
    log: bool = False,
    scan_points: int = 25,
    rtol: float = 1e-5,
) -> Threshold:
    """Bisect the boundary of ``lifts`` in [lo, hi] after a coarse scan.

    ``lifts_above`` says on which side lift-off happens (True: for values above the
    threshold, as for v0, c, R; False: below it, as for the damping).  The boundary
    refined is the one closest to the no-lift-off end of the range; all sign changes
    of the scan are reported.  A failing evaluation is recorded and skipped (the
    bisection then nudges its midpoint).
    """
    errors: list[str] = []
    evaluations = 0

    def evaluate(x: float) -> bool | None:
        nonlocal evaluations
        evaluations += 1
        try:
            return bool(lifts(x))
        except Exception as exc:  # noqa: BLE001 - reported in the threshold
            errors.append(f"{x:.6g}: {type(exc).__name__}: {exc}")
            return None

    grid = np.geomspace(lo, hi, scan_points) if log else np.linspace(lo, hi, scan_points)
    scan = [(float(x), evaluate(float(x))) for x in grid]
    known = [(x, v) for x, v in scan if v is not None]
    transitions = tuple(
        (a[0], b[0]) for a, b in zip(known[:-1], known[1:], strict=True) if a[1] != b[1]
    )
    if not transitions:
        return Threshold(None, None, (), evaluations, tuple(errors), tuple(scan))
    # the boundary next to the no-lift-off end: lowest change if lift-off is above
    a, b = transitions[0] if lifts_above else transitions[-1]
    fa = dict(known)[a]
    while True:
        if log:
            if b / a - 1.0 <= rtol:
                break
            mid = math.sqrt(a * b)
        else:
            if b - a <= rtol * max(abs(a), abs(b), 1e-12):
                break
            mid = 0.5 * (a + b)
        value = evaluate(mid)
        nudge = 0
        while value is None and nudge < 3:
            nudge += 1
            mid = a + (mid - a) * (1 - 1e-3 * nudge)
            value = evaluate(mid)
        if value is None:
            break
        if value == fa:
            a = mid
        else:
            b = mid
    boundary = math.sqrt(a * b) if log else 0.5 * (a + b)
    return Threshold(boundary, (a, b), transitions, evaluations, tuple(errors), tuple(scan))


@dataclass
class Context:
    """What a part of the reproduction needs: where to write, where to run, progress.

    ``progress(label, total)`` starts a progress task and returns its update
    function ``update(done)``.
    """

    directory: Path
    runner: Runner
    progress: TaskHook = lambda label, total: _ignore  # twoball._common.progress.Reporter.task
    monitor: Any = None  # handed to the runs (twoball._common.monitor.Monitor)

    def path(self, name: str) -> Path:
        """A file in the output directory."""
        return self.directory / name


def _ignore(done: int) -> None:
    return None


def new_figure(*args: Any, figsize: tuple[float, float], **kwargs: Any) -> tuple[Any, Any]:
    """A constrained-layout figure of ``figsize`` inches and its ``subplots(*args, **kwargs)``.

    No pyplot: call it inside a function decorated with
    :func:`~twoball.verify.output.figures.style.styled` so that the one figure
    style applies.
    """
    from twoball.verify.output.figures import new_figure as blank

    figure = blank(*figsize)
    return figure, figure.subplots(*args, **kwargs)


def save(ctx: Context, figure: Any, name: str) -> str:
    """Write ``figure`` as ``name`` (PNG) into the output directory.

    Through :func:`twoball.verify.output.figures.save_figure`, the one way
    twoball saves a figure, at the resolution of the reports.
    """
    from twoball.verify.output.figures import REPORT_DPI, save_figure

    save_figure(figure, ctx.path(name), dpi=REPORT_DPI)
    return name
