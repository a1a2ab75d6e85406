"""The time-step study: generalized-alpha against modal superposition on one mesh.

c dt = 0.01 / 2^level (dimensionless; dt = 0.01 / (2^level c) seconds, which is
what labels and run rows show, the dimensionless value beside it); the reference
is the modal series of the same mesh, so only the time discretisation is measured.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

from twoball._common.watch import Watch
from twoball.modal.filters import FilterKind
from twoball.modal.liftoff import Horizon, find_liftoff
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.verify.studies.fem_runs import FEMSpec, fem_row, fem_run
from twoball.verify.studies.orders import OrderBand
from twoball.verify.studies.quantities import (
    QuantitySpec,
    evaluate_quantity,
    liftoff_specs,
    ms_per_unit,
)
from twoball.verify.studies.reference import legendre_run
from twoball.verify.studies.result import (
    Progress,
    StudyResult,
    case_settings,
    quiet,
    si,
    time_step_text,
)
from twoball.verify.studies.trajectory import TrajectoryNorm, hermite_resample

DT_LEVEL_LIMITS = (0, 8)
DT_BASE = 0.01  # dt of level 0 (dimensionless; omega_N dt = 0.3 for N = 30)
DT_MESH_SIZE = {"sphere": 2, "axisym": 100}  # fixed mesh of the dt study
DT_BAND = OrderBand(2.0, 0.3, 0.3)


def run_dt_study(
    case: Case,
    *,
    mesh: str = "axisym",
    order: int = 2,
    levels: Sequence[int] = (1, 2, 3, 4),
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    progress: Progress = quiet,
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
    unit = case.scalings.time  # s per unit of dimensionless time
    labels = [time_step_text(dt, unit) for dt in dts]
    rows: list[dict[str, Any]] = []
    values: dict[str, list[float]] = {k: [] for k in ("t", "v", "t_q", "v_q", "l2", "knots")}
    steps_count = []
    for dt in dts:
        progress(f"{spec.label}: generalized-alpha {time_step_text(dt, unit)}")
        start = time.perf_counter()
        motion, info = alpha_motion(
            base.model, dt=dt, t_end=t_end, rho_inf=rho_inf, monitor=Watch()
        )
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
            ("t", result.t),
            ("v", result.velocity),
            ("t_q", quintic.t),
            ("v_q", quintic.velocity),
            ("l2", norm.relative_error(motion)),
            ("knots", knots),
        ):
            values[key].append(math.nan if value is None else float(value))
        steps_count.append(int(info["steps"]))
        rows.append(
            {
                "label": time_step_text(dt, unit),
                "backend": "fem alpha",
                "dt_s": dt * unit,
                "c_dt": dt,
                "dofs": base.dofs,
                "steps": int(info["steps"]),
                "t_liftoff_s": si(result.t, case.scalings.time),
                "v_liftoff_m_s": si(result.velocity, case.scalings.velocity),
                "t_liftoff_hermite_s": si(quintic.t, case.scalings.time),
                "seconds": time.perf_counter() - start,
            }
        )
    study = StudyResult(
        "dt",
        f"generalized-alpha (rho_inf = {rho_inf:g}) against modal superposition, {spec.label}",
        "h = c dt (dimensionless; the time step in seconds is dt = h / c)",
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
        "pole_samples",
        "max |pole state - modal| at the steps (u, u_tt; relative)",
        1.0,
        DT_BAND,
        True,
    )
    study.quantities.append(
        evaluate_quantity(knot_spec, labels, steps_count, dts, values["knots"], 0.0)
    )
    if base.t is not None and not any(math.isnan(x) for x in values["t_q"]):
        quintic_spec = QuantitySpec(
            "t_l_hermite",
            "t_l, quintic Hermite through the samples [ms] (no band)",
            ms_per_unit(case),
        )
        study.quantities.append(
            evaluate_quantity(quintic_spec, labels, steps_count, dts, values["t_q"], base.t)
        )
    study.runs = [fem_row(case, base, legendre_run(case, case.modes, sigma, recontact, t_end))]
    study.runs[0]["backend"] = "fem modal"
    study.runs += rows
    study.notes.append(
        f"Reference: modal superposition on the same mesh ({spec.label}, {base.dofs} DOFs, "
        f"{len(base.model.pairs)} eigenpairs, filter sigma = {sigma}), "
        f"t_l = {si(base.t, case.scalings.time * 1e3)} ms; the errors measure the time "
        "discretisation alone.  The 'steps' column (the JSON's 'dofs') holds the number of steps."
    )
    study.seconds = time.perf_counter() - clock
    return study
