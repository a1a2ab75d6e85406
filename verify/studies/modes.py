"""The truncation study of the Legendre series: N = 30, 60, 120, ... against N -> infinity.

Step h = 1/N.  Dimensionless inside, SI in the run rows and the notes.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.watch import Watch
from twoball.modal.converged import (
    PAPER_MODES,
    ConvergedReference,
    converged_legendre,
    unfiltered_series,
)
from twoball.modal.filters import FilterKind
from twoball.modal.liftoff import Horizon
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.verify.studies.gci import finite_or_none
from twoball.verify.studies.orders import OrderBand
from twoball.verify.studies.quantities import evaluate_quantity, liftoff_specs
from twoball.verify.studies.reference import LegendreRun, legendre_row, legendre_run
from twoball.verify.studies.result import Progress, StudyResult, case_settings, quiet, si
from twoball.verify.studies.trajectory import TrajectoryNorm

DEFAULT_MODES: tuple[int, ...] = (30, 60, 120, 240, 480)
MODES_BANDS: dict[str, OrderBand | None] = {
    # sigma = 1 - (pi omega_n / omega_N)^2 / 6 + ... (Lanczos) or 1 - (omega_n/omega_N)^2 / 6
    # (printed): every retained low mode is off by O(N^-2); the damped tail is exponentially small.
    "lanczos": OrderBand(2.0, 0.3, 0.3),
    "printed": OrderBand(2.0, 0.3, 0.3),
    "none": None,  # plain truncation of a damped series: faster than any power at t > 0
}


def parse_modes(text: str) -> tuple[int, ...]:
    """``"30,60,120,240"`` (or a range, :mod:`twoball._common.ranges`) -> increasing mode counts.

    At least 3 and at most 16 counts, each >= 1, strictly increasing.
    """
    from twoball._common.ranges import parse_values

    valid = "increasing integers >= 1, 3 to 16 of them, e.g. 30,60,120,240"
    values = parse_values(text, "modes_list", integer=True, valid=valid)
    increasing = all(b > a for a, b in zip(values[:-1], values[1:], strict=True))
    if not 3 <= len(values) <= 16 or min(values) < 1 or not increasing:
        raise ParameterError("modes_list", valid, text)
    return tuple(int(v) for v in values)


def check_modes_study(modes: Sequence[int], t_end: float) -> None:
    """Refuse a truncation study that cannot fit (``t_end`` dimensionless), before any work.

    Its work: one closed-form lift-off per N (:func:`twoball.modal.cost.series_estimate`),
    the converged reference and the unfiltered trajectory reference at 4 max(N).
    """
    from twoball._common.budget import check
    from twoball.modal.cost import reference_estimate, series_estimate

    estimate = reference_estimate(t_end) + series_estimate(4 * max(modes), t_end)
    for n in modes:
        estimate = estimate + series_estimate(n, t_end)
    check("modes_list " + ",".join(str(n) for n in modes), estimate)


def run_modes_study(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    modes: Sequence[int] = DEFAULT_MODES,
    progress: Progress = quiet,
) -> StudyResult:
    """Truncation study of the Legendre series: N = 30, 60, 120, ... against the limit.

    The errors of t_l, v_l and E(t_end) are measured against the converged
    series (:func:`converged_legendre`); the pole trajectory against the finest N.
    The step is h = 1/N.  The truncation error of N = 30 is stated in the notes.
    """
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    progress("converged Legendre reference")
    limit = converged_legendre(case, sigma, recontact, t_end, monitor=Watch())
    runs: list[LegendreRun] = []
    for n in modes:
        progress(f"Legendre N = {n}")
        runs.append(legendre_run(case, n, sigma, recontact, t_end))
    labels = [f"N = {r.modes}" for r in runs]
    dofs = [r.modes + 1 for r in runs]
    steps = [1.0 / r.modes for r in runs]
    band = MODES_BANDS[sigma]
    specs = liftoff_specs(case, band)
    study = StudyResult(
        "modes",
        f"Legendre series, sigma = {sigma}, N = {', '.join(str(n) for n in modes)}",
        "h = 1/N",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    lifted = all(r.t is not None for r in runs)
    if lifted and limit.t is not None:
        study.quantities.append(
            evaluate_quantity(specs[0], labels, dofs, steps, [r.t for r in runs], limit.t)
        )
        study.quantities.append(
            evaluate_quantity(
                specs[1], labels, dofs, steps, [r.velocity for r in runs], limit.velocity
            )
        )
    # the unfiltered series with 4x the finest N: its L2 tail (~N^-3/2 from the kink at
    # t = 0) is a few per cent of the finest filtered error
    progress(f"Legendre trajectory reference, N = {4 * max(modes)} unfiltered")
    tail = unfiltered_series(case, 4 * max(modes), Watch())
    norm = TrajectoryNorm(tail, t_end, frequency=max(r.series.max_frequency for r in runs))
    l2 = [norm.relative_error(r.series) for r in runs]
    study.quantities.append(evaluate_quantity(specs[2], labels, dofs, steps, l2, 0.0))
    study.quantities.append(
        evaluate_quantity(
            specs[3], labels, dofs, steps, [r.energy_end for r in runs], limit.energy_end
        )
    )
    study.runs = [legendre_row(case, r) for r in runs]
    study.notes.extend(_truncation_notes(case, runs, limit, sigma, recontact, t_end))
    study.settings["reference"] = _reference_dict(case, limit)
    study.seconds = time.perf_counter() - clock
    return study


def _reference_dict(case: Case, limit: ConvergedReference) -> dict[str, Any]:
    scale = case.scalings
    return {
        "kind": "Legendre series, N -> infinity (unfiltered limit, N doubled)",
        "t_liftoff_s": si(limit.t, scale.time),
        "v_liftoff_m_s": si(limit.velocity, scale.velocity),
        "energy_end": finite_or_none(limit.energy_end),
        "modes": limit.modes,
        "converged": limit.converged,
        "tolerance": limit.tolerance,
        "clear_flight": limit.clear,
        "history": [
            {"modes": n, "t_liftoff_s": t * scale.time, "v_liftoff_m_s": v * scale.velocity}
            for n, t, v in limit.history
        ],
    }


def _truncation_notes(
    case: Case,
    runs: Sequence[LegendreRun],
    limit: ConvergedReference,
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
) -> list[str]:
    """The truncation error of the paper's N = 30 against the converged series, in words."""
    scale = case.scalings
    if limit.t is None or limit.velocity is None:
        return ["The converged series does not lift off in the window: no truncation error."]
    state = "converged" if limit.converged else "NOT converged"
    notes = [
        f"Converged reference: N = {limit.modes} ({state} to {limit.tolerance:.0e} relative), "
        f"t_l = {limit.t * scale.time * 1e3:.9f} ms, "
        f"v_l = {limit.velocity * scale.velocity:.9f} m/s."
    ]
    paper = next((r for r in runs if r.modes == PAPER_MODES), None)
    if paper is None:
        paper = legendre_run(case, PAPER_MODES, sigma, recontact, t_end)
    if paper.t is not None and paper.velocity is not None:
        dt = (paper.t - limit.t) / limit.t
        dv = (paper.velocity - limit.velocity) / limit.velocity
        notes.append(
            f"Truncation error of N = {PAPER_MODES} (the paper's choice, sigma = {sigma}) "
            f"against the converged series: t_l {dt:+.3e} relative "
            f"({(paper.t - limit.t) * scale.time * 1e6:+.4f} us), v_l {dv:+.3e} relative "
            f"({(paper.velocity - limit.velocity) * scale.velocity:+.5f} m/s), "
            f"ratio v_l/|v0| {paper.velocity * scale.velocity / case.v0:.5f} vs "
            f"{limit.velocity * scale.velocity / case.v0:.5f}."
        )
    return notes
