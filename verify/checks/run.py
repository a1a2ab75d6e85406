"""``twoball verify``: every backend against the closed form, in one call, :func:`run_verify`.

It computes

* the Legendre series with the case's N (the reference of every finite-element
  run, which uses the same filter) and its converged limit N -> infinity;
* finite-element runs (axisymmetric and sphere, P1 and P2) by modal superposition,
  and the rational Krylov route where the configuration asks for it;
* direct generalized-alpha runs against modal superposition on the same mesh;
* eigenvalue, energy (eq. (3.5)) and energy-decay checks;

and returns the rows of the run table, the list of checks (each PASS or FAIL
against its tolerance) and what the plots need.  Dimensionless inside, SI out.
"""

from __future__ import annotations

import time

import numpy as np

from twoball._common.watch import Watch
from twoball.modal.converged import ConvergedReference, converged_legendre
from twoball.modal.filters import FilterKind
from twoball.modal.liftoff import Horizon
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.verify.checks.alpha import alpha_checks
from twoball.verify.checks.config import ROUTE_AGREEMENT, VerifyConfig, config
from twoball.verify.checks.fem import eigen_checks, energy_check, energy_order_check
from twoball.verify.checks.results import Check, RunRow, VerifyResult, bounded, liftoff_gap, run_row
from twoball.verify.output.figures.eigen import EigenErrors
from twoball.verify.output.figures.pole import Trace
from twoball.verify.studies.fem_runs import FEMRun, FEMSpec, fem_run
from twoball.verify.studies.reference import LegendreRun, legendre_run
from twoball.verify.studies.result import Progress, case_settings, si, time_step_text


def run_verify(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    configuration: VerifyConfig | None = None,
    progress: Progress | None = None,
) -> VerifyResult:
    """Run every backend and every check of ``twoball verify``.

    Parameters
    ----------
    case : Case
        The impact (SI).
    sigma, recontact, t_end_s
        Filter, re-contact horizon and window, as for ``twoball liftoff``.
    configuration : VerifyConfig, optional
        Default: :func:`config` ``("default")``.
    progress : callable(str), optional
        Called with a description before each step.

    Returns
    -------
    VerifyResult
    """
    clock = time.perf_counter()
    configuration = configuration or config("default")
    say = progress or (lambda _: None)
    t_end = t_end_dimensionless(case, t_end_s)
    scale = case.scalings
    say(f"Legendre series N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    say("converged Legendre reference (N doubled)")
    limit = converged_legendre(
        case,
        sigma,
        recontact,
        t_end,
        configuration.reference_tolerance,
        case.modes,
        monitor=Watch(),
    )
    rows = [
        run_row(
            case,
            "legendre",
            f"N = {case.modes}",
            case.modes + 1,
            reference.t,
            reference.velocity,
            reference.seconds,
            reference,
            limit,
        ),
        run_row(
            case,
            "legendre N->inf",
            f"N = {limit.modes}, unfiltered",
            limit.modes + 1,
            limit.t,
            limit.velocity,
            limit.seconds,
            reference,
            limit,
        ),
    ]
    checks = [reference_check(limit, configuration.reference_tolerance)]
    traces = [
        Trace(f"Legendre N = {case.modes}", reference.series, reference.t, reference.velocity)
    ]
    if limit.series is not None:
        traces.append(
            Trace(
                f"Legendre N -> inf ({limit.modes}, unfiltered)",
                limit.series,
                limit.t,
                limit.velocity,
            )
        )
    eigen: list[EigenErrors] = []
    fem_runs: dict[FEMSpec, FEMRun] = {}
    for target in configuration.fem:
        say(f"finite elements {target.spec.label}")
        run = fem_run(case, target.spec, sigma, recontact, t_end)
        fem_runs[target.spec] = run
        rows.append(_fem_row(case, "fem modal", run, len(run.model.pairs), reference, limit))
        traces.append(Trace(f"FE modal {target.spec.label}", run.series, run.t, run.velocity))
        checks.append(
            bounded(
                f"lift-off {target.spec.label}",
                f"{target.spec.label} ({run.dofs} DOFs) against Legendre N = {case.modes}: "
                "largest relative difference in t_l and v_l",
                liftoff_gap(run.t, run.velocity, reference.t, reference.velocity),
                target.liftoff,
            )
        )
        more, table = eigen_checks(run, target)
        checks += more
        eigen.append(table)
        checks.append(energy_check(case, run, target)[0])
    for target in configuration.krylov:
        say(f"finite elements {target.spec.label}, Krylov route")
        fast = fem_run(case, target.spec, sigma, recontact, t_end, route="krylov")
        label = f"{target.spec.label} krylov"
        modes = len(fast.model.series.omega)
        rows.append(_fem_row(case, "fem krylov", fast, modes, reference, limit))
        traces.append(Trace(f"FE Krylov {target.spec.label}", fast.series, fast.t, fast.velocity))
        checks.append(
            bounded(
                f"lift-off {label}",
                f"{target.spec.label} ({fast.dofs} DOFs, rational Krylov route) against "
                f"Legendre N = {case.modes}: largest relative difference in t_l and v_l",
                liftoff_gap(fast.t, fast.velocity, reference.t, reference.velocity),
                target.liftoff,
            )
        )
        full = fem_runs.get(target.spec)
        if full is not None:
            checks.append(
                bounded(
                    f"routes agree {target.spec.label}",
                    f"{target.spec.label}: Krylov route against the full eigen route "
                    f"({full.seconds:.1f} s vs {fast.seconds:.1f} s): relative difference "
                    "in t_l and v_l",
                    liftoff_gap(fast.t, fast.velocity, full.t, full.velocity),
                    ROUTE_AGREEMENT,
                )
            )
    energy_curves: list[tuple[str, np.ndarray, np.ndarray]] = []
    bound = None
    for target in configuration.alpha:
        say(f"generalized-alpha {target.spec.label}, {time_step_text(target.dt, scale.time)}")
        modal = fem_runs.get(target.spec)
        if modal is None:
            modal = fem_run(case, target.spec, sigma, recontact, t_end)
            fem_runs[target.spec] = modal
            modes = len(modal.model.pairs)
            rows.append(_fem_row(case, "fem modal", modal, modes, reference, limit))
        more, alpha_rows, alpha_traces, curves = alpha_checks(
            case, target, modal, recontact, t_end, reference, limit
        )
        rows += alpha_rows
        checks += more
        traces += alpha_traces
        energy_curves.append((f"alpha {curves['label']}", curves["times"], curves["alpha"]))
        energy_curves.append((f"modal {curves['label']}", curves["times"], curves["closed"]))
        bound = bound or curves["bound"]
    if configuration.energy_pair is not None and configuration.energy_band is not None:
        checks.append(
            energy_order_check(case, configuration, fem_runs, sigma, recontact, t_end, say)
        )
    notes = [
        f"Reference of the finite elements: the Legendre series with N = {case.modes} and "
        f"sigma = {sigma}, the limit of finite elements that use the same filter; the "
        f"converged series (N = {limit.modes}) is the N -> infinity limit.",
        "Lift-off of generalized-alpha: the step samples interpolated field by field with "
        "cubic splines, as the backend returns them.  One quintic Hermite spline through the "
        "same samples would make u_tt first-order accurate between the steps "
        "(results.json: liftoff_gap_to_modal_hermite).",
    ]
    settings = case_settings(case, sigma, recontact, t_end)
    settings["configuration"] = configuration.name
    settings["reference"] = {
        "modes": limit.modes,
        "converged": limit.converged,
        "t_liftoff_s": si(limit.t, scale.time),
        "v_liftoff_m_s": si(limit.velocity, scale.velocity),
    }
    return VerifyResult(
        case,
        configuration,
        settings,
        rows,
        checks,
        traces,
        eigen,
        energy_curves,
        bound,
        limit,
        time.perf_counter() - clock,
        notes,
    )


def reference_check(limit: ConvergedReference, tolerance: float) -> Check:
    """The converged Legendre reference settled: last change of t_l and v_l, clear flight."""
    history = limit.history
    change = None
    if len(history) >= 2:
        change = max(
            abs(history[-1][2] - history[-2][2]) / abs(history[-1][2]),
            abs(history[-1][1] - history[-2][1]) / abs(history[-1][1]),
        )
    return Check(
        "Legendre reference converged",
        f"N doubled to {limit.modes}: last relative change of t_l and v_l, and free flight "
        "after lift-off clear of the pole",
        change,
        tolerance,
        bool(limit.converged and limit.clear and change is not None),
    )


def _fem_row(
    case: Case,
    backend: str,
    run: FEMRun,
    modes: int,
    reference: LegendreRun,
    limit: ConvergedReference,
) -> RunRow:
    """The run-table row of a finite-element run with ``modes`` modes computed."""
    details = {"modes_computed": modes, "h": run.spec.step}
    return run_row(
        case,
        backend,
        run.spec.label,
        run.dofs,
        run.t,
        run.velocity,
        run.seconds,
        reference,
        limit,
        details,
    )
