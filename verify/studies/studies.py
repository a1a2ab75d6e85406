"""Convergence studies of both backends: refinement in h, element order, modes and time step.

A study runs one backend on a sequence of discretisations, collects scalar
quantities (eigenvalues, t_l, v_l, the energy at t_end, ...) and error norms
(the pole trajectory in L2 over the modelled window), and hands every
sequence to :func:`twoball.verify.studies.orders.analyse` for errors, observed orders,
Richardson extrapolation and the GCI.  Each quantity carries the order the
theory predicts and a band; the observed order is checked against it.

Everything is computed dimensionless (length R, time 1/c) and shown in SI.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.polynomial.legendre import leggauss
from twoball.modal.errors import ParameterError
from twoball.modal.filters import FilterKind, SpectralFilter, legendre_frequency
from twoball.modal.initial import deformation_work
from twoball.modal.legendre import legendre_coefficients_recurrence, legendre_series
from twoball.modal.liftoff import (
    Horizon,
    PoleMotion,
    SampledPoleMotion,
    find_liftoff,
    flight_clearance,
)
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.modal.roots import bracketed_roots
from twoball.modal.series import ModalSeries
from twoball.verify.studies.orders import (
    OrderBand,
    OrderFit,
    SequenceAnalysis,
    analyse,
    least_squares_order,
)

STUDIES: tuple[str, ...] = ("h", "order", "modes", "dt")
PAPER_MODES = 30  # the truncation used throughout the paper (§3(b))
REFERENCE_TOLERANCE = 1e-7  # relative change of v_l that stops the doubling of N
REFERENCE_MAX_MODES = 3840
Progress = Callable[[str], None]
ROUNDOFF = 1e-11  # relative errors below this are round-off: they carry no order


def _quiet(_: str) -> None:
    return None


# --------------------------------------------------------------------------- references
@dataclass(frozen=True)
class LegendreRun:
    """One closed-form run (dimensionless results, SI through ``case``)."""

    modes: int
    sigma: str
    t: float | None
    velocity: float | None
    energy_end: float
    seconds: float
    series: ModalSeries


def legendre_run(
    case: Case, modes: int, sigma: FilterKind, recontact: Horizon, t_end: float
) -> LegendreRun:
    """Lift-off and end energy of the filtered Legendre series with ``modes`` modes."""
    start = time.perf_counter()
    series = legendre_series(case.phi_a, case.damping, SpectralFilter(sigma, modes))
    result = find_liftoff(series, case.gamma, t_end=t_end, horizon=recontact)
    energy = float(series.energy(np.array([t_end]))[0])
    return LegendreRun(
        modes, sigma, result.t, result.velocity, energy, time.perf_counter() - start, series
    )


@dataclass(frozen=True)
class ConvergedReference:
    """The N -> infinity limit of the Legendre lift-off (dimensionless).

    Every filter tends to 1 mode by mode as N grows, so all filtered series share
    one limit: the unfiltered damped series (3.14).  For t > 0 its terms decay
    like exp(-D sqrt(n(n+1)) t), so at the lift-off time it converges
    exponentially in N (for D > 0).  It is found by following the lift-off
    root of the N = 30 filtered series into the unfiltered series while N
    doubles, until t_l and v_l change by less than ``tolerance`` (relative).
    For D = 0 the series converges only algebraically at t_l; the doubling stops
    once the changes no longer shrink by a factor 4 per step (``converged``
    False: the check of ``verify`` then fails).

    Attributes
    ----------
    t, velocity : float or None
        Lift-off time and velocity of the limit (None if not found).
    energy_end : float
        Energy of the limit at t_end (unit T R^2).
    modes : int
        N of the last (accepted) step.
    converged : bool
        Whether the changes fell below ``tolerance`` before ``REFERENCE_MAX_MODES``.
    history : list of (N, t, v)
        The sequence of the doubling.
    clear : bool
        Whether the free flight after lift-off stays above the pole on the
        checked samples (criterion (ii) for the limit).
    """

    t: float | None
    velocity: float | None
    energy_end: float
    modes: int
    converged: bool
    tolerance: float
    history: tuple[tuple[int, float, float], ...]
    clear: bool
    seconds: float
    series: ModalSeries | None


def unfiltered_series(case: Case, modes: int) -> ModalSeries:
    """The damped Legendre series (3.14) truncated at ``modes`` without a filter.

    Coefficients from the exact three-term recurrence
    (:func:`twoball.modal.legendre.legendre_coefficients_recurrence`, an independent
    second method; agrees with the quadrature of eq. (3.12) to ~1e-13 and needs
    no Gauss rule, which is what makes thousands of modes cheap).
    """
    n = np.arange(modes + 1)
    return ModalSeries(
        omega=legendre_frequency(n),
        coefficients=legendre_coefficients_recurrence(case.phi_a, modes),
        pole_values=np.ones(n.size),
        damping=case.damping,
        filter=SpectralFilter("none", modes),
        mode_norms=4.0 * np.pi / (2 * n + 1),
    )


def _track_root(
    series: ModalSeries, gamma: float, guess: float, width: float
) -> tuple[float, float] | None:
    """The downward zero of ``u_tt + gamma`` nearest ``guess`` within ``guess +- width``."""
    samples = max(2001, int(40 * width * max(series.max_frequency, 1.0)))
    grid = np.linspace(max(guess - width, 1e-9), guess + width, samples)
    force = series.pole(grid).u_tt + gamma
    down = np.flatnonzero((force[:-1] > 0.0) & (force[1:] <= 0.0))
    if down.size == 0:
        return None
    k = down[np.argmin(np.abs(grid[down] - guess))]
    root = bracketed_roots(
        lambda t, i: series.pole(t).u_tt + gamma, grid[k : k + 1], grid[k + 1 : k + 2]
    )[0]
    return float(root), float(series.pole(np.array([root])).u_t[0])


def converged_legendre(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end: float = 4 * math.pi,
    tolerance: float = REFERENCE_TOLERANCE,
    start_modes: int = PAPER_MODES,
    max_modes: int = REFERENCE_MAX_MODES,
) -> ConvergedReference:
    """The converged Legendre lift-off: N doubled from ``2 start_modes`` until it settles.

    See :class:`ConvergedReference`.  The lift-off of the Lanczos-filtered series
    with ``start_modes`` modes (criteria (i)-(ii)) picks the root to follow,
    whatever ``sigma`` is: the limit is the same for every filter, and without a
    filter the truncated series lifts off spuriously on its Gibbs oscillations.
    """
    del sigma  # every filter has the same limit
    clock = time.perf_counter()
    base = legendre_run(case, start_modes, "lanczos", recontact, t_end)
    if base.t is None:
        return ConvergedReference(
            None, None, math.nan, start_modes, False, tolerance, (), False, 0.0, None
        )
    guess, width = base.t, 0.05 * base.t
    history: list[tuple[int, float, float]] = []
    changes: list[float] = []
    modes, converged, series = start_modes, False, None
    while modes < max_modes:
        modes *= 2
        series = unfiltered_series(case, modes)
        found = _track_root(series, case.gamma, guess, width)
        if found is None:
            break
        history.append((modes, *found))
        guess = found[0]
        if len(history) >= 2:
            (_, t0, v0), (_, t1, v1) = history[-2], history[-1]
            change = max(abs(t1 - t0) / abs(t1), abs(v1 - v0) / abs(v1))
            changes.append(change)
            if change <= tolerance:
                converged = True
                break
            # damped series converge exponentially; changes that merely halve (D = 0: the
            # kink of F keeps travelling undamped) will not reach the tolerance -- stop
            if len(changes) >= 3 and changes[-1] > 0.25 * changes[-2] > 0.0625 * changes[-3]:
                break
    if not history or series is None:
        return ConvergedReference(
            None, None, math.nan, modes, False, tolerance, tuple(history), False, 0.0, None
        )
    _, t_l, v_l = history[-1]
    end = t_end if recontact == "window" else min(2 * t_l, t_end)
    clear = v_l > 0 and flight_clearance(series, case.gamma, t_l, end) > 0.0
    energy = float(series.energy(np.array([t_end]))[0])
    return ConvergedReference(
        t_l,
        v_l,
        energy,
        modes,
        converged,
        tolerance,
        tuple(history),
        clear,
        time.perf_counter() - clock,
        series,
    )


# --------------------------------------------------------------------------- time norms
class TrajectoryNorm:
    """L2(0, t_end) norms of the pole displacement against one reference motion.

    Composite 8-point Gauss-Legendre quadrature on uniform panels; the
    reference is sampled once.  ``frequency`` sets the panel count (the fastest
    mode that matters; default the reference's).  Dimensionless.
    """

    def __init__(self, reference: PoleMotion, t_end: float, frequency: float | None = None) -> None:
        fastest = max(float(reference.max_frequency if frequency is None else frequency), 1.0)
        panels = min(20000, 64 + math.ceil(t_end * fastest / math.pi))
        nodes, weights = leggauss(8)
        edges = np.linspace(0.0, t_end, panels + 1)
        half = 0.5 * np.diff(edges)
        self.times = (edges[:-1, None] + half[:, None] * (nodes[None, :] + 1.0)).ravel()
        self.weights = (half[:, None] * weights[None, :]).ravel()
        self.reference = reference.pole(self.times).u
        self.norm = float(np.sqrt(np.sum(self.weights * self.reference**2)))

    def error(self, motion: PoleMotion) -> float:
        """``||u - u_ref||`` in L2(0, t_end)."""
        u = motion.pole(self.times).u
        return float(np.sqrt(np.sum(self.weights * (u - self.reference) ** 2)))

    def relative_error(self, motion: PoleMotion) -> float:
        """``||u - u_ref|| / ||u_ref||``."""
        return self.error(motion) / self.norm


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class QuantitySpec:
    """What is measured and what order it should converge with.

    Attributes
    ----------
    key : str
        Machine name (``v_l``, ``lambda_3``, ``pole_l2``, ...).
    label : str
        Human label with its unit.
    scale : float
        Dimensionless value times ``scale`` gives the unit of ``label``.
    band : OrderBand or None
        Expected order and accepted band; None: reported, not checked.
    error_norm : bool
        The values are already error norms (relative, reference 0).
    """

    key: str
    label: str
    scale: float = 1.0
    band: OrderBand | None = None
    error_norm: bool = False


@dataclass(frozen=True)
class QuantityResult:
    """One quantity over one refinement sequence, analysed.

    Attributes
    ----------
    spec : QuantitySpec
    labels : list of str
        Name of each discretisation (``level 3``, ``N = 60``, ``dt = 0.01``).
    dofs : list of int
        Degrees of freedom (or modes) of each.
    analysis : SequenceAnalysis
    relative_errors : ndarray
        Errors divided by ``|reference|`` (already relative for error norms).
    checked_order : float
        Least-squares order over the finest (up to) three grids with an error;
        this is the order compared with the band.
    passed : bool or None
        None when the quantity has no band.
    remark : str
        ``exact to round-off`` when the discretisation reproduces the reference
        (e.g. lambda_1 = 2 with P1 on the axisymmetric line, where P_1(x) = x is
        in the space): no order can be observed and none is required.
    """

    spec: QuantitySpec
    labels: list[str]
    dofs: list[int]
    analysis: SequenceAnalysis
    relative_errors: np.ndarray
    checked_order: float
    passed: bool | None
    remark: str = ""

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (dimensionless values; ``scale`` converts to the label's unit)."""
        a = self.analysis
        return {
            "key": self.spec.key,
            "label": self.spec.label,
            "scale": self.spec.scale,
            "error_norm": self.spec.error_norm,
            "expected_order": None if self.spec.band is None else self.spec.band.expected,
            "band": None if self.spec.band is None else [self.spec.band.low, self.spec.band.high],
            "labels": self.labels,
            "dofs": self.dofs,
            "steps": a.steps.tolist(),
            "values": a.values.tolist(),
            "reference": a.reference,
            "reference_kind": a.reference_kind,
            "errors": _list(a.errors),
            "relative_errors": _list(self.relative_errors),
            "ratios": _list(a.ratios),
            "orders": _list(a.orders),
            "least_squares_order": _num(a.fit.order),
            "checked_order": _num(self.checked_order),
            "richardson": _num(a.extrapolated),
            "gci": None if a.gci is None else a.gci.as_dict(),
            "passed": self.passed,
            "remark": self.remark,
        }


def _num(value: float) -> float | None:
    return float(value) if value is not None and math.isfinite(value) else None


def _list(values: np.ndarray) -> list[float | None]:
    return [_num(v) for v in np.asarray(values, dtype=float)]


def evaluate_quantity(
    spec: QuantitySpec,
    labels: Sequence[str],
    dofs: Sequence[int],
    steps: Sequence[float],
    values: Sequence[float],
    reference: float | None,
    reference_kind: str = "reference",
) -> QuantityResult:
    """Analyse one sequence (coarse to fine) and check its order against the band.

    Relative errors at round-off level (below ``ROUNDOFF``) carry no order: they
    are left out of the orders and fits, and a quantity whose every error is at
    round-off passes as exact.
    """
    if spec.error_norm:
        reference = 0.0
    kind: Any = reference_kind
    analysis = analyse(steps, values, reference, kind)
    scale = 1.0 if spec.error_norm or analysis.reference == 0 else abs(analysis.reference)
    relative = analysis.errors / scale
    noise = np.isfinite(relative) & (relative <= ROUNDOFF)
    if noise.any():
        orders = analysis.orders.copy()
        ratios = analysis.ratios.copy()
        bad = noise[:-1] | noise[1:]
        orders[bad], ratios[bad] = math.nan, math.nan
        keep = np.isfinite(relative) & ~noise
        fit = (
            least_squares_order(analysis.steps[keep], analysis.errors[keep])
            if keep.sum() >= 2
            else OrderFit(math.nan, math.nan, int(keep.sum()), math.nan)
        )
        analysis = replace(analysis, orders=orders, ratios=ratios, fit=fit)
    usable = np.flatnonzero(np.isfinite(relative) & ~noise)[-3:]
    checked = math.nan
    if usable.size >= 2:
        checked = least_squares_order(analysis.steps[usable], analysis.errors[usable]).order
    remark = ""
    finite = np.isfinite(relative)
    if finite.any() and np.all(noise[finite]):
        remark = "exact to round-off"
        passed = None if spec.band is None else True
    else:
        passed = None if spec.band is None else spec.band.contains(checked)
    return QuantityResult(
        spec, list(labels), list(dofs), analysis, relative, checked, passed, remark
    )


@dataclass
class StudyResult:
    """A finished convergence study: its quantities, notes and timings.

    Attributes
    ----------
    study : str
        ``h``, ``order``, ``modes`` or ``dt``.
    title : str
        One line describing the discretisations.
    step_name : str
        What the step size h is (``h = sqrt(4 pi / triangles)``, ``1/N``, ...).
    quantities : list of QuantityResult
    notes : list of str
        Statements for the reader (e.g. the truncation error of N = 30).
    runs : list of dict
        One row per discretisation: label, DOFs, t_l, v_l, seconds (SI).
    settings : dict
        The case and options used.
    """

    study: str
    title: str
    step_name: str
    quantities: list[QuantityResult] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    runs: list[dict[str, Any]] = field(default_factory=list)
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def passed(self) -> bool:
        """True when every quantity with a band observed an order inside it."""
        return all(q.passed is not False for q in self.quantities)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary of the whole study."""
        return {
            "study": self.study,
            "title": self.title,
            "step": self.step_name,
            "passed": self.passed,
            "seconds": self.seconds,
            "settings": self.settings,
            "notes": self.notes,
            "runs": self.runs,
            "quantities": [q.as_dict() for q in self.quantities],
        }


def case_settings(case: Case, sigma: str, recontact: str, t_end: float) -> dict[str, Any]:
    """The case and model options as a JSON-ready dictionary (SI)."""
    return {
        "radius_m": case.radius,
        "wave_speed_1_s": case.wave_speed,
        "v0_m_s": case.v0,
        "phi_a": case.phi_a,
        "phi_a_source": case.phi_a_source,
        "damping": case.damping,
        "modes": case.modes,
        "g_m_s2": case.g,
        "gamma": case.gamma,
        "sigma": sigma,
        "recontact": recontact,
        "t_end_s": t_end * case.scalings.time,
    }


def _ms(case: Case) -> float:
    return 1e3 * case.scalings.time


def liftoff_specs(case: Case, band: OrderBand | None) -> list[QuantitySpec]:
    """t_l, v_l, the pole trajectory and the end energy, all with the same band."""
    return [
        QuantitySpec("t_l", "t_l [ms]", _ms(case), band),
        QuantitySpec("v_l", "v_l [m/s]", case.scalings.velocity, band),
        QuantitySpec("pole_l2", "||u - u_ref||_L2 / ||u_ref|| (pole)", 1.0, band, True),
        QuantitySpec("energy_end", "E(t_end) [T R^2]", 1.0, band),
    ]


# --------------------------------------------------------------------------- modes study
DEFAULT_MODES: tuple[int, ...] = (30, 60, 120, 240, 480)
MODES_BANDS: dict[str, OrderBand | None] = {
    # sigma = 1 - (pi omega_n / omega_N)^2 / 6 + ... (Lanczos) or 1 - (omega_n/omega_N)^2 / 6
    # (printed): every retained low mode is off by O(N^-2); the damped tail is exponentially small.
    "lanczos": OrderBand(2.0, 0.3, 0.3),
    "printed": OrderBand(2.0, 0.3, 0.3),
    "none": None,  # plain truncation of a damped series: faster than any power at t > 0
}


def parse_modes(text: str) -> tuple[int, ...]:
    """``"30,60,120"`` or ``"30:480"`` (doubling) -> increasing mode counts."""
    valid = "N1,N2,... or NMIN:NMAX (doubling), integers >= 1, increasing, at least 3"
    try:
        if ":" in text:
            low, high = (int(p) for p in text.split(":"))
            values: list[int] = []
            n = low
            while n <= high and low >= 1:
                values.append(n)
                n *= 2
        else:
            values = [int(p) for p in text.split(",")]
    except ValueError:
        raise ParameterError("--modes-list", valid, text) from None
    increasing = all(b > a for a, b in zip(values[:-1], values[1:], strict=True))
    if len(values) < 3 or min(values) < 1 or not increasing:
        raise ParameterError("--modes-list", valid, text)
    return tuple(values)


def run_modes_study(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    modes: Sequence[int] = DEFAULT_MODES,
    progress: Progress = _quiet,
) -> StudyResult:
    """Truncation study of the Legendre series: N = 30, 60, 120, ... against the limit.

    The errors of t_l, v_l and E(t_end) are measured against the converged
    series (:func:`converged_legendre`); the pole trajectory against the finest N.
    The step is h = 1/N.  The truncation error of N = 30 is stated in the notes.
    """
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    progress("converged Legendre reference")
    limit = converged_legendre(case, sigma, recontact, t_end)
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
    tail = unfiltered_series(case, 4 * max(modes))
    norm = TrajectoryNorm(tail, t_end, frequency=max(r.series.max_frequency for r in runs))
    l2 = [norm.relative_error(r.series) for r in runs]
    study.quantities.append(evaluate_quantity(specs[2], labels, dofs, steps, l2, 0.0))
    study.quantities.append(
        evaluate_quantity(
            specs[3], labels, dofs, steps, [r.energy_end for r in runs], limit.energy_end
        )
    )
    study.runs = [_legendre_row(case, r) for r in runs]
    study.notes.extend(_truncation_notes(case, runs, limit, sigma, recontact, t_end))
    study.settings["reference"] = _reference_dict(case, limit)
    study.seconds = time.perf_counter() - clock
    return study


def _legendre_row(case: Case, run: LegendreRun) -> dict[str, Any]:
    scale = case.scalings
    return {
        "label": f"N = {run.modes}",
        "backend": "legendre",
        "dofs": run.modes + 1,
        "t_liftoff_s": None if run.t is None else run.t * scale.time,
        "v_liftoff_m_s": None if run.velocity is None else run.velocity * scale.velocity,
        "energy_end": run.energy_end,
        "seconds": run.seconds,
    }


def _reference_dict(case: Case, limit: ConvergedReference) -> dict[str, Any]:
    scale = case.scalings
    return {
        "kind": "Legendre series, N -> infinity (unfiltered limit, N doubled)",
        "t_liftoff_s": None if limit.t is None else limit.t * scale.time,
        "v_liftoff_m_s": None if limit.velocity is None else limit.velocity * scale.velocity,
        "energy_end": _num(limit.energy_end),
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


# --------------------------------------------------------------------------- FE layer
MESH_LABELS = {"sphere": "icosphere", "axisym": "axisym"}
LEVEL_LIMITS: dict[str, tuple[int, int]] = {"sphere": (0, 6), "axisym": (0, 8)}
AXISYM_BASE_ELEMENTS = 25  # axisym "level" k has 25 * 2**k elements
EIGEN_DEGREES = tuple(range(1, 7))  # l = 1..6 in every eigenvalue check


@dataclass(frozen=True)
class FEMSpec:
    """One finite-element discretisation.

    Attributes
    ----------
    mesh : {"sphere", "axisym"}
        Icosphere or the axisymmetric line x = cos(phi).
    order : {1, 2}
        Element (and, on the sphere, geometry) order.
    size : int
        Icosphere level, or number of axisymmetric elements.
    """

    mesh: str
    order: int
    size: int

    @property
    def label(self) -> str:
        """Short description, e.g. ``sphere P1 L4`` or ``axisym P2 400 el.``."""
        if self.mesh == "axisym":
            return f"axisym P{self.order} {self.size} el."
        return f"sphere P{self.order} L{self.size}"

    @property
    def step(self) -> float:
        """Mesh size h: ``sqrt(4 pi / triangles)`` on the icosphere, ``pi / elements`` on the line.

        Both are lengths on the unit sphere (dimensionless); refinement halves them.
        """
        if self.mesh == "axisym":
            return math.pi / self.size
        return math.sqrt(4.0 * math.pi / (20 * 4**self.size))

    @property
    def dimension(self) -> int:
        """Topological dimension (DOFs ~ h^-dimension)."""
        return 1 if self.mesh == "axisym" else 2

    def options(self) -> dict[str, Any]:
        """Keyword arguments of :func:`twoball.fem_membrane.solve.modal_model`."""
        if self.mesh == "axisym":
            return {"mesh": "axisym", "elements": self.size, "order": self.order}
        return {"mesh": "sphere", "level": self.size, "order": self.order}


def spec_from_level(mesh: str, order: int, level: int) -> FEMSpec:
    """The discretisation of refinement level ``level`` (axisym: 25 * 2**level elements)."""
    if mesh == "axisym":
        return FEMSpec("axisym", order, AXISYM_BASE_ELEMENTS * 2**level)
    return FEMSpec("sphere", order, level)


@dataclass
class FEMRun:
    """A finite-element modal model of one case with its lift-off (dimensionless).

    ``model`` is :class:`twoball.fem_membrane.solve.ModalModel` (space, eigenpairs,
    initial moments, modal series).
    """

    spec: FEMSpec
    model: Any
    t: float | None
    velocity: float | None
    energy_end: float
    seconds: float

    @property
    def dofs(self) -> int:
        """Degrees of freedom."""
        return int(self.model.space.dofs)

    @property
    def series(self) -> ModalSeries:
        """The modal series (eq. (3.16) on the finite-element eigenpairs)."""
        return self.model.series


def fem_run(
    case: Case,
    spec: FEMSpec,
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
    route: str = "full",
) -> FEMRun:
    """Assemble, build the filtered modal series, and find lift-off.

    Uses :func:`twoball.fem_membrane.solve.modal_model`, the same path as
    ``fem_pole_motion(..., time="modal")``, and keeps the model for the
    eigenvalue and energy checks (``route="full"``; the Krylov route has no
    eigenvector set and serves lift-off checks only).
    """
    from twoball.fem_membrane.solve import modal_model

    start = time.perf_counter()
    model = modal_model(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        route=route,
        **spec.options(),
    )
    result = find_liftoff(model.series, case.gamma, t_end=t_end, horizon=recontact)
    energy = float(model.series.energy(np.array([t_end]))[0])
    return FEMRun(spec, model, result.t, result.velocity, energy, time.perf_counter() - start)


def cluster_means(values: np.ndarray, mesh: str, degrees: Sequence[int]) -> np.ndarray:
    """Mean of the discrete eigenvalues of each degree l (2l + 1 on the sphere, 1 on the line)."""
    values = np.sort(np.asarray(values, dtype=float))
    if mesh == "axisym":
        return np.array([values[deg] for deg in degrees])
    return np.array([values[deg * deg : (deg + 1) ** 2].mean() for deg in degrees])


def cluster_errors(values: np.ndarray, mesh: str, degrees: Sequence[int]) -> np.ndarray:
    """Largest relative error ``|lambda_h - l(l+1)| / l(l+1)`` within each degree's cluster."""
    values = np.sort(np.asarray(values, dtype=float))
    out = []
    for deg in degrees:
        exact = deg * (deg + 1.0)
        block = values[deg : deg + 1] if mesh == "axisym" else values[deg * deg : (deg + 1) ** 2]
        out.append(float(np.abs(block - exact).max() / exact))
    return np.array(out)


def projection_energy(model: Any) -> float:
    """``1/2 u0^T K u0`` of the Galerkin projection u0 of F (unit T R^2; eq. (3.5) discrete)."""
    from scipy.sparse.linalg import splu

    space = model.space
    u0 = splu(space.mass.tocsc()).solve(model.moments)
    return 0.5 * float(u0 @ (space.stiffness @ u0))


# --------------------------------------------------------------------------- h and order
DEFAULT_LEVELS: dict[tuple[str, str, int], str] = {
    ("h", "sphere", 1): "2:5",
    ("h", "sphere", 2): "1:4",
    ("h", "axisym", 1): "1:5",
    ("h", "axisym", 2): "1:5",
    ("order", "sphere", 1): "1:3",
    ("order", "sphere", 2): "1:3",
    ("order", "axisym", 1): "1:4",
    ("order", "axisym", 2): "1:4",
    ("dt", "sphere", 1): "1:4",
    ("dt", "sphere", 2): "1:4",
    ("dt", "axisym", 1): "1:4",
    ("dt", "axisym", 2): "1:4",
}
# Expected orders in h (element order P).  Eigenvalues: 2P (Babuska & Osborn 1991; on the
# sphere P2 needs the curved isoparametric geometry, a flat P1 polyhedron adds O(h^2)).  The
# pole quantities are sums over modes with eigenvalue-accurate frequencies: 2P as well.  The
# strain energy of the L2-projected F: P + 1 on the axisymmetric line, whose node at the kink
# leaves only the jump term [F'] e(x_a) = O(h^(P+1)); about 1 on the icosphere, where the kink
# cuts the triangles and F is only in H^(3/2-) there.
EIGEN_BAND = {1: OrderBand(2.0, 0.3, 0.3), 2: OrderBand(4.0, 0.5, 0.5)}
LIFTOFF_BAND = {
    ("axisym", 1): OrderBand(2.0, 0.3, 0.4),
    ("axisym", 2): OrderBand(4.0, 0.5, 0.5),
    ("sphere", 1): OrderBand(2.0, 0.4, 0.5),
    ("sphere", 2): OrderBand(4.0, 0.6, 0.6),
}
ENERGY_BAND = {
    ("axisym", 1): OrderBand(2.0, 0.3, 0.3),
    ("axisym", 2): OrderBand(3.0, 0.4, 0.4),
    ("sphere", 1): OrderBand(1.0, 0.5, 1.0),
    ("sphere", 2): OrderBand(1.0, 0.5, 1.0),
}
# v_l on the icosphere: the kink of F crosses the triangles at positions that change from
# level to level, which adds an irregular component to this one point value (observed local
# orders 2.3 to 3.0 for P1 on levels 3-5, and 10, 2.0, 5.0 for P2 on levels 2-5 while t_l
# keeps 3.7-4.0).  Its observed order is stated, not checked; t_l, the trajectory and the
# energy carry the band.
UNCHECKED_ON_SPHERE = ("v_l",)
SPHERE_NOTE = (
    "v_l on the icosphere is reported with its observed order but not checked against a band: "
    "the kink of F at phi_a cuts the triangles at level-dependent places, which makes the "
    "convergence of this point value irregular (t_l, the pole trajectory and the energies are "
    "checked)."
)


def _fem_sequence(
    case: Case,
    specs: Sequence[FEMSpec],
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
    progress: Progress,
) -> list[FEMRun]:
    runs = []
    for spec in specs:
        progress(f"{spec.label}: assembly and eigenpairs")
        runs.append(fem_run(case, spec, sigma, recontact, t_end))
    return runs


def _fem_row(case: Case, run: FEMRun, reference: LegendreRun) -> dict[str, Any]:
    scale = case.scalings
    row: dict[str, Any] = {
        "label": run.spec.label,
        "backend": "fem",
        "dofs": run.dofs,
        "h": run.spec.step,
        "modes_computed": len(run.model.pairs),
        "t_liftoff_s": None if run.t is None else run.t * scale.time,
        "v_liftoff_m_s": None if run.velocity is None else run.velocity * scale.velocity,
        "energy_end": run.energy_end,
        "seconds": run.seconds,
    }
    if run.t is not None and reference.t is not None and reference.velocity is not None:
        row["t_rel_diff"] = (run.t - reference.t) / reference.t
        row["v_rel_diff"] = (run.velocity - reference.velocity) / reference.velocity
    return row


def fem_quantities(
    case: Case,
    runs: Sequence[FEMRun],
    reference: LegendreRun,
    t_end: float,
    steps: Sequence[float] | None = None,
    suffix: str = "",
    keys: Sequence[str] | None = None,
) -> list[QuantityResult]:
    """Eigenvalues, W, lift-off, trajectory and end energy of a FE sequence, analysed.

    The lift-off quantities are measured against the Legendre series with the
    same filter and N (the limit of the finite elements as h -> 0); the
    eigenvalues against l (l + 1); the projected strain energy against -W of
    eq. (3.5).
    """
    spec0 = runs[0].spec
    mesh, order = spec0.mesh, spec0.order
    steps = [r.spec.step for r in runs] if steps is None else list(steps)
    labels = [r.spec.label for r in runs]
    dofs = [r.dofs for r in runs]
    out: list[QuantityResult] = []

    def want(key: str) -> bool:
        return keys is None or key in keys

    means = np.array([cluster_means(r.model.pairs.values, mesh, EIGEN_DEGREES) for r in runs])
    for j, deg in enumerate(EIGEN_DEGREES):
        if want(f"lambda_{deg}"):
            exact = deg * (deg + 1.0)
            spec = QuantitySpec(
                f"lambda_{deg}{suffix}", f"lambda_{deg}{suffix} (exact {exact:g})", 1.0,
                EIGEN_BAND[order],
            )  # fmt: skip
            out.append(evaluate_quantity(spec, labels, dofs, steps, means[:, j], exact, "exact"))
    if want("strain_energy"):
        energy = [projection_energy(r.model) for r in runs]
        spec = QuantitySpec(
            f"strain_energy{suffix}", f"1/2 u0^T K u0{suffix} [T R^2] vs -W (3.5)", 1.0,
            ENERGY_BAND[(mesh, order)],
        )  # fmt: skip
        exact = -deformation_work(case.phi_a)
        out.append(evaluate_quantity(spec, labels, dofs, steps, energy, exact, "exact"))
    band = LIFTOFF_BAND[(mesh, order)]
    specs = {s.key: s for s in liftoff_specs(case, band)}
    lifted = all(r.t is not None for r in runs) and reference.t is not None
    if lifted and want("t_l"):
        spec = _suffixed(specs["t_l"], suffix)
        values = [r.t for r in runs]
        out.append(evaluate_quantity(spec, labels, dofs, steps, values, reference.t))
    if lifted and want("v_l"):
        spec = _suffixed(specs["v_l"], suffix)
        if mesh == "sphere" and "v_l" in UNCHECKED_ON_SPHERE:
            spec = replace(spec, band=None)
        values = [r.velocity for r in runs]
        out.append(evaluate_quantity(spec, labels, dofs, steps, values, reference.velocity))
    if want("pole_l2"):
        norm = TrajectoryNorm(reference.series, t_end)
        values = [norm.relative_error(r.series) for r in runs]
        out.append(evaluate_quantity(_suffixed(specs["pole_l2"], suffix), labels, dofs, steps,
                                     values, 0.0))  # fmt: skip
    if want("energy_end"):
        values = [r.energy_end for r in runs]
        out.append(
            evaluate_quantity(
                _suffixed(specs["energy_end"], suffix), labels, dofs, steps, values,
                reference.energy_end,
            )
        )  # fmt: skip
    return out


def _suffixed(spec: QuantitySpec, suffix: str) -> QuantitySpec:
    if not suffix:
        return spec
    label = (
        spec.label.replace(" [", f"{suffix} [", 1) if " [" in spec.label else spec.label + suffix
    )
    return QuantitySpec(spec.key + suffix, label, spec.scale, spec.band, spec.error_norm)


def run_h_study(
    case: Case,
    *,
    mesh: str = "sphere",
    order: int = 1,
    levels: Sequence[int] = (2, 3, 4, 5),
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    progress: Progress = _quiet,
) -> StudyResult:
    """Mesh refinement at fixed element order: eigenvalues, W, t_l, v_l, trajectory, energy.

    Step h: ``sqrt(4 pi / triangles)`` (sphere) or ``pi / elements`` (axisym).
    """
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    specs = [spec_from_level(mesh, order, level) for level in levels]
    progress(f"Legendre N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    runs = _fem_sequence(case, specs, sigma, recontact, t_end, progress)
    study = StudyResult(
        "h",
        f"{MESH_LABELS[mesh]} P{order}, levels {levels[0]}..{levels[-1]} "
        f"({specs[0].label} to {specs[-1].label})",
        "h = sqrt(4 pi / triangles)" if mesh == "sphere" else "h = pi / elements",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    study.quantities = fem_quantities(case, runs, reference, t_end)
    study.runs = [_legendre_row(case, reference)] + [_fem_row(case, r, reference) for r in runs]
    study.notes.append(
        f"Lift-off reference: Legendre series N = {case.modes}, sigma = {sigma} (the same filter "
        "as the finite elements, i.e. their limit as h -> 0); eigenvalues against l (l + 1); "
        "1/2 u0^T K u0 of the projected F against -W of eq. (3.5)."
    )
    study.notes.extend(_finest_statement(case, runs[-1], reference))
    v_l = next((q for q in study.quantities if q.spec.key == "v_l"), None)
    if v_l is not None:
        study.notes.append(
            f"Observed order of v_l against the Legendre reference: least-squares "
            f"{v_l.analysis.fit.order:.2f} over all levels, {v_l.checked_order:.2f} over the "
            f"finest three; finest relative error {v_l.relative_errors[-1]:.2e}."
        )
    if mesh == "sphere":
        study.notes.append(SPHERE_NOTE)
    study.seconds = time.perf_counter() - clock
    return study


def _finest_statement(case: Case, run: FEMRun, reference: LegendreRun) -> list[str]:
    if run.t is None or reference.t is None or reference.velocity is None:
        return ["The finest finite-element run or the reference does not lift off."]
    scale = case.scalings
    return [
        f"Finest mesh ({run.spec.label}, {run.dofs} DOFs): t_l = "
        f"{run.t * scale.time * 1e3:.9f} ms ({(run.t - reference.t) / reference.t:+.2e}), "
        f"v_l = {run.velocity * scale.velocity:.9f} m/s "
        f"({(run.velocity - reference.velocity) / reference.velocity:+.2e}) against the "
        f"Legendre N = {case.modes} values {reference.t * scale.time * 1e3:.9f} ms, "
        f"{reference.velocity * scale.velocity:.9f} m/s."
    ]


def run_order_study(
    case: Case,
    *,
    mesh: str = "sphere",
    levels: Sequence[int] = (1, 2, 3),
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    progress: Progress = _quiet,
    order: int | None = None,
) -> StudyResult:
    """P1 against P2 at equal numbers of unknowns.

    P2 runs on the given levels and P1 one level finer, which has the same
    degrees of freedom (every edge midpoint of level L is a vertex of level
    L + 1; on the line twice the elements).  The step of each point is the DOF
    spacing ``DOFs^(-1/d)`` (d = 2 on the sphere, 1 on the line), so both
    sequences share one axis and their orders in h carry over.  The eigenvalue
    lambda_6 and the pole trajectory are checked against their bands; t_l and
    v_l are compared by their errors (their orders are checked by ``--study h``).
    The notes state how much smaller the P2 error is at equal DOFs.
    """
    del order  # both orders are run
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    progress(f"Legendre N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    study = StudyResult(
        "order",
        f"{MESH_LABELS[mesh]} P2 on levels {levels[0]}..{levels[-1]} against P1 one level finer "
        "(equal DOFs)",
        "h = DOFs^(-1/2)" if mesh == "sphere" else "h = 1/DOFs",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    keys = ("lambda_6", "t_l", "v_l", "pole_l2")
    by_order: dict[int, list[FEMRun]] = {}
    for p in (1, 2):
        specs = [spec_from_level(mesh, p, level + (p == 1)) for level in levels]
        runs = _fem_sequence(case, specs, sigma, recontact, t_end, progress)
        by_order[p] = runs
        steps = [r.dofs ** (-1.0 / r.spec.dimension) for r in runs]
        for q in fem_quantities(case, runs, reference, t_end, steps, suffix=f" (P{p})", keys=keys):
            if q.spec.key.split(" ")[0] in ("t_l", "v_l"):
                q = replace(q, spec=replace(q.spec, band=None), passed=None)
            study.quantities.append(q)
        study.runs += [_fem_row(case, r, reference) for r in runs]
    study.runs.insert(0, _legendre_row(case, reference))
    study.notes.extend(_order_notes(case, by_order, reference))
    study.seconds = time.perf_counter() - clock
    return study


def _order_notes(
    case: Case, by_order: dict[int, list[FEMRun]], reference: LegendreRun
) -> list[str]:
    """Errors of t_l and v_l for P2 and for P1 with the same DOFs."""
    notes: list[str] = []
    if reference.velocity is None or reference.t is None:
        return notes

    def error(run: FEMRun, t: bool) -> float:
        value, ref = (run.t, reference.t) if t else (run.velocity, reference.velocity)
        if value is None or ref is None:
            return math.nan
        return abs(value - ref) / abs(ref)

    for p1, p2 in zip(by_order[1], by_order[2], strict=True):
        notes.append(
            f"{p2.dofs} DOFs: {p2.spec.label} against {p1.spec.label} ({p1.dofs} DOFs): "
            f"v_l error {error(p2, False):.2e} against {error(p1, False):.2e} "
            f"({error(p1, False) / error(p2, False):.3g} times smaller with P2), t_l error "
            f"{error(p2, True):.2e} against {error(p1, True):.2e} "
            f"({error(p1, True) / error(p2, True):.3g} times smaller with P2)."
        )
    return notes


# --------------------------------------------------------------------------- dt study
DT_LEVEL_LIMITS = (0, 8)
DT_BASE = 0.01  # dt of level 0 (dimensionless; omega_N dt = 0.3 for N = 30)
DT_MESH_SIZE = {"sphere": 2, "axisym": 100}  # fixed mesh of the dt study
DT_BAND = OrderBand(2.0, 0.3, 0.3)


def hermite_resample(motion: Any) -> SampledPoleMotion:
    """The samples of a sampled motion re-interpolated by one quintic Hermite spline.

    For comparison only: direct time stepping gives u, u_t and u_tt that are each
    O(dt^2) but not derivatives of one another, so this interpolant's u_tt is
    O(dt) between the steps (the finite-element backend uses per-field splines).
    """
    t = np.asarray(motion.times)
    state = motion.pole(t)
    return SampledPoleMotion(t, state.u, state.u_t, state.u_tt, interpolation="hermite")


def run_dt_study(
    case: Case,
    *,
    mesh: str = "axisym",
    order: int = 2,
    levels: Sequence[int] = (1, 2, 3, 4),
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    progress: Progress = _quiet,
    rho_inf: float = 1.0,
) -> StudyResult:
    """Generalized-alpha against modal superposition on one mesh: dt = 0.01 / 2^level.

    The reference is the modal series of the same mesh (same eigenpairs, filter
    and modal damping), so only the time discretisation is measured.  t_l and
    v_l come from the motion as the backend returns it (per-field cubic splines
    of the step samples); t_l of a quintic Hermite interpolant of the same
    samples is reported beside them, without an order band, to show why.
    """
    from twoball.fem_membrane.solve import alpha_motion

    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    spec = FEMSpec(mesh, order, DT_MESH_SIZE[mesh])
    progress(f"{spec.label}: assembly and eigenpairs")
    base = fem_run(case, spec, sigma, recontact, t_end)
    norm = TrajectoryNorm(base.series, t_end)
    dts = [DT_BASE / 2**level for level in levels]
    labels = [f"dt = {dt:g}" for dt in dts]
    rows: list[dict[str, Any]] = []
    values: dict[str, list[float]] = {k: [] for k in ("t", "v", "t_q", "v_q", "l2", "knots")}
    steps_count = []
    for dt in dts:
        progress(f"{spec.label}: generalized-alpha dt = {dt:g}")
        start = time.perf_counter()
        motion, info = alpha_motion(base.model, dt=dt, t_end=t_end, rho_inf=rho_inf)
        result = find_liftoff(motion, case.gamma, t_end=t_end, horizon=recontact)
        quintic = find_liftoff(hermite_resample(motion), case.gamma, t_end=t_end, horizon=recontact)
        exact = base.series.pole(motion.times)
        sampled = motion.pole(motion.times)
        knots = max(
            float(np.max(np.abs(sampled.u - exact.u))) / max(np.max(np.abs(exact.u)), 1e-300),
            float(np.max(np.abs(sampled.u_tt - exact.u_tt)))
            / max(np.max(np.abs(exact.u_tt[motion.times > 0.5])), 1e-300),
        )
        for key, value in (
            ("t", result.t), ("v", result.velocity), ("t_q", quintic.t),
            ("v_q", quintic.velocity), ("l2", norm.relative_error(motion)), ("knots", knots),
        ):  # fmt: skip
            values[key].append(math.nan if value is None else float(value))
        steps_count.append(int(info["steps"]))
        rows.append(
            {
                "label": f"dt = {dt:g}",
                "backend": "fem alpha",
                "dofs": base.dofs,
                "steps": int(info["steps"]),
                "t_liftoff_s": _si(result.t, case.scalings.time),
                "v_liftoff_m_s": _si(result.velocity, case.scalings.velocity),
                "t_liftoff_hermite_s": _si(quintic.t, case.scalings.time),
                "seconds": time.perf_counter() - start,
            }
        )
    study = StudyResult(
        "dt",
        f"generalized-alpha (rho_inf = {rho_inf:g}) against modal superposition, {spec.label}",
        "h = dt (dimensionless, unit 1/c)",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    specs = {s.key: s for s in liftoff_specs(case, DT_BAND)}
    if base.t is not None and not any(math.isnan(x) for x in values["t"] + values["v"]):
        study.quantities.append(
            evaluate_quantity(specs["t_l"], labels, steps_count, dts, values["t"], base.t)
        )
        study.quantities.append(
            evaluate_quantity(specs["v_l"], labels, steps_count, dts, values["v"], base.velocity)
        )
    study.quantities.append(
        evaluate_quantity(specs["pole_l2"], labels, steps_count, dts, values["l2"], 0.0)
    )
    knot_spec = QuantitySpec(
        "pole_samples", "max |pole state - modal| at the steps (u, u_tt; relative)", 1.0,
        DT_BAND, True,
    )  # fmt: skip
    study.quantities.append(
        evaluate_quantity(knot_spec, labels, steps_count, dts, values["knots"], 0.0)
    )
    if base.t is not None and not any(math.isnan(x) for x in values["t_q"]):
        quintic_spec = QuantitySpec(
            "t_l_hermite", "t_l, quintic Hermite through the samples [ms] (no band)", _ms(case)
        )
        study.quantities.append(
            evaluate_quantity(quintic_spec, labels, steps_count, dts, values["t_q"], base.t)
        )
    study.runs = [_fem_row(case, base, legendre_run(case, case.modes, sigma, recontact, t_end))]
    study.runs[0]["backend"] = "fem modal"
    study.runs += rows
    study.notes.append(
        f"Reference: modal superposition on the same mesh ({spec.label}, {base.dofs} DOFs, "
        f"{len(base.model.pairs)} eigenpairs, filter sigma = {sigma}), "
        f"t_l = {_si(base.t, case.scalings.time * 1e3)} ms; the errors measure the time "
        "discretisation alone.  The column 'DOFs' holds the number of steps."
    )
    study.seconds = time.perf_counter() - clock
    return study


def _si(value: float | None, scale: float) -> float | None:
    return None if value is None else value * scale
