"""Refinement studies of the finite elements: the mesh size h, and P1 against P2 at equal DOFs.

Eigenvalues against l (l + 1), the projected strain energy against -W of
eq. (3.5), and lift-off, pole trajectory and end energy against the Legendre
series with the same filter and N (the limit of the finite elements as h -> 0).
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from twoball.modal.filters import FilterKind
from twoball.modal.initial import deformation_work
from twoball.modal.liftoff import Horizon
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.verify.studies.fem_runs import (
    AXISYM_BASE_ELEMENTS,
    EIGEN_DEGREES,
    MESH_LABELS,
    FEMRun,
    FEMSpec,
    cluster_means,
    fem_row,
    fem_sequence,
    projection_energy,
    spec_from_level,
)
from twoball.verify.studies.orders import OrderBand
from twoball.verify.studies.quantities import (
    QuantityResult,
    QuantitySpec,
    evaluate_quantity,
    liftoff_specs,
)
from twoball.verify.studies.reference import LegendreRun, legendre_row, legendre_run
from twoball.verify.studies.result import Progress, StudyResult, case_settings, quiet
from twoball.verify.studies.trajectory import TrajectoryNorm

# Expected orders in h (element order P).  Eigenvalues: 2P (Babuska & Osborn 1991; on the
# sphere P2 needs the curved isoparametric geometry, a flat P1 polyhedron adds O(h^2)).  On an
# isoparametric sphere of order P the geometric error adds O(h^(P+1)) for odd P and O(h^(P+2))
# for even P (Demlow 2009, equispaced nodes): min(2P, P+1 | P+2) is 2, 4, 4, 6 for P = 1..4;
# at P3, P4 the low clusters l = 1, 2 show it on the default levels, the higher ones are in
# transition from 2P (reported, not checked); the exact sphere and the line give 2P.  The
# pole quantities are sums over modes with eigenvalue-accurate frequencies: 2P as well.  The
# strain energy of the L2-projected F: P + 1 on the axisymmetric line, whose node at the kink
# leaves only the jump term [F'] e(x_a) = O(h^(P+1)); about 1 on the icosphere, where the kink
# cuts the triangles and F is only in H^(3/2-) there.
EIGEN_BAND = {
    1: OrderBand(2.0, 0.3, 0.3),
    2: OrderBand(4.0, 0.5, 0.5),
    3: OrderBand(6.0, 0.5, 0.5),
    4: OrderBand(8.0, 0.5, 0.5),
}
GEOMETRIC_RATE = {1: 2.0, 2: 4.0, 3: 4.0, 4: 6.0}  # isoparametric sphere: min(2P, P+1 | P+2)
GEOMETRIC_DEGREES = (1, 2)  # clusters whose geometric rate the default levels show at P3, P4


def eigen_band(mesh: str, order: int, geometry: str, degree: int) -> OrderBand | None:
    """Expected order of the cluster ``degree`` (see the comment above EIGEN_BAND)."""
    if mesh == "axisym" or geometry == "exact" or order <= 2:
        return EIGEN_BAND[order]
    if degree in GEOMETRIC_DEGREES:
        return OrderBand(GEOMETRIC_RATE[order], 0.5, 0.5)
    return None


LIFTOFF_BAND = {
    ("axisym", 1): OrderBand(2.0, 0.3, 0.4),
    ("axisym", 2): OrderBand(4.0, 0.5, 0.5),
    ("sphere", 1): OrderBand(2.0, 0.4, 0.5),
    ("sphere", 2): OrderBand(4.0, 0.6, 0.6),
    ("axisym", 3): OrderBand(6.0, 0.5, 0.5),  # measured 5.8-6.1 (order study, 100-400 DOFs)
    ("axisym", 4): OrderBand(8.0, 0.5, 0.6),  # measured 7.9-8.3
}  # sphere P3, P4: reported, not checked (see LIFTOFF_NOTE)
LIFTOFF_NOTE = (
    "P3 and P4 on the sphere: t_l, v_l, the pole trajectory and the end energy are reported "
    "with their observed orders, not checked against a band: on the default levels they are "
    "not yet asymptotic, and v_l, a point value, converges at the pointwise rate of the "
    "elements (P + 1, or P + 2 at a vertex for even P), not at 2P (docs/verification.rst)."
)
ENERGY_BAND = {
    ("axisym", 1): OrderBand(2.0, 0.3, 0.3),
    ("axisym", 2): OrderBand(3.0, 0.4, 0.4),
    ("sphere", 1): OrderBand(1.0, 0.5, 1.0),
    ("sphere", 2): OrderBand(1.0, 0.5, 1.0),
    ("axisym", 3): OrderBand(4.0, 0.4, 0.4),
    ("axisym", 4): OrderBand(5.0, 0.5, 0.5),
    ("sphere", 3): OrderBand(1.0, 0.5, 1.0),
    ("sphere", 4): OrderBand(1.0, 0.5, 1.0),
}
# v_l on the icosphere: a point value.  The per-degree pole amplitudes sum_k q_k(0) phi_k(pole)
# carry the pointwise error of the elements, whose sign changes from degree to degree and from
# level to level (a smooth datum without the kink of F shows the same), so at P1, P2 the sum
# does not settle into one order on the default levels (observed local orders 2.3 to 3.0 for
# P1 on levels 3-5, and 10, 2.0, 5.0 for P2 on levels 2-5, while t_l keeps 3.7-4.0).  Its
# observed order is stated, not checked; t_l, the trajectory and the energy carry the band.
UNCHECKED_ON_SPHERE = ("v_l",)
SPHERE_NOTE = (
    "v_l on the icosphere is reported with its observed order but not checked against a band: "
    "it is a point value, and the pointwise errors of the modes at the pole change sign from "
    "degree to degree and level to level, which makes its convergence irregular on these "
    "levels (t_l, the pole trajectory and the energies are checked)."
)


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
    mesh, order, geometry = spec0.mesh, spec0.order, spec0.geometry
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
                f"lambda_{deg}{suffix}",
                f"lambda_{deg}{suffix} (exact {exact:g})",
                1.0,
                eigen_band(mesh, order, geometry, deg),
            )
            out.append(evaluate_quantity(spec, labels, dofs, steps, means[:, j], exact, "exact"))
    if want("strain_energy"):
        energy = [projection_energy(r.model) for r in runs]
        spec = QuantitySpec(
            f"strain_energy{suffix}",
            f"1/2 u0^T K u0{suffix} [T R^2] vs -W (3.5)",
            1.0,
            ENERGY_BAND[(mesh, order)],
        )
        exact = -deformation_work(case.phi_a)
        out.append(evaluate_quantity(spec, labels, dofs, steps, energy, exact, "exact"))
    band = LIFTOFF_BAND.get((mesh, order))
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
        out.append(
            evaluate_quantity(_suffixed(specs["pole_l2"], suffix), labels, dofs, steps, values, 0.0)
        )
    if want("energy_end"):
        values = [r.energy_end for r in runs]
        out.append(
            evaluate_quantity(
                _suffixed(specs["energy_end"], suffix),
                labels,
                dofs,
                steps,
                values,
                reference.energy_end,
            )
        )
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
    progress: Progress = quiet,
    geometry: str = "isoparametric",
) -> StudyResult:
    """Mesh refinement at fixed element order: eigenvalues, W, t_l, v_l, trajectory, energy.

    Step h: ``sqrt(4 pi / triangles)`` (sphere) or ``pi / elements`` (axisym).
    ``geometry`` (sphere only): ``isoparametric`` or ``exact``.
    """
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    specs = [spec_from_level(mesh, order, level, geometry) for level in levels]
    progress(f"Legendre N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    runs = fem_sequence(case, specs, sigma, recontact, t_end, progress)
    study = StudyResult(
        "h",
        f"{MESH_LABELS[mesh]} P{order}{' exact' if geometry == 'exact' else ''}, "
        f"levels {levels[0]}..{levels[-1]} "
        f"({specs[0].label} to {specs[-1].label})",
        "h = sqrt(4 pi / triangles)" if mesh == "sphere" else "h = pi / elements",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    study.quantities = fem_quantities(case, runs, reference, t_end)
    study.runs = [legendre_row(case, reference)] + [fem_row(case, r, reference) for r in runs]
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
    if order >= 3 and mesh == "sphere":
        study.notes.append(LIFTOFF_NOTE)
    if mesh == "sphere" and geometry == "isoparametric" and order >= 3:
        study.notes.append(
            f"Isoparametric P{order}: the geometric error O(h^{GEOMETRIC_RATE[order]:g}) "
            f"(Demlow 2009) is checked on the clusters l = 1, 2; the higher clusters are in "
            f"transition from 2P = {2 * order} and reported only (geometry exact gives 2P)."
        )
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


ORDER_STUDY_ORDERS: tuple[int, ...] = (1, 2, 3, 4)
ORDER_STUDY_KEYS = ("lambda_6", "t_l", "v_l", "pole_l2")


def order_spec(mesh: str, order: int, level: int, geometry: str = "isoparametric") -> FEMSpec:
    """The order-``order`` discretisation with about the DOFs of P2 on ``level``.

    Sphere: P1 one level finer, P3 and P4 one level coarser (P1 L+1, P2 L and P4
    L-1 have exactly ``40 4^L + 2`` DOFs; P3 L-1 has ``22.5 4^L + 2``, the nearest
    P3 count below).  Line: ``2 E / p`` elements for the
    P2 line's E (``p E + 1`` DOFs, equal up to rounding for P3).
    """
    if mesh == "axisym":
        elements = AXISYM_BASE_ELEMENTS * 2**level
        return FEMSpec("axisym", order, max(2, round(2 * elements / order)))
    shift = {1: 1, 2: 0, 3: -1, 4: -1}[order]
    return FEMSpec("sphere", order, max(0, level + shift), geometry)


def run_order_study(
    case: Case,
    *,
    mesh: str = "sphere",
    levels: Sequence[int] = (1, 2, 3),
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    progress: Progress = quiet,
    order: int | None = None,
    orders: Sequence[int] = ORDER_STUDY_ORDERS,
    geometry: str = "isoparametric",
) -> StudyResult:
    """P1 to P4 at (about) equal numbers of unknowns.

    For each P2 level, every order runs with about the same degrees of freedom
    (:func:`order_spec`).  The step of each point is the DOF spacing
    ``DOFs^(-1/d)`` (d = 2 on the sphere, 1 on the line), so the sequences share
    one axis and their orders in h carry over.  The eigenvalue lambda_6 and the
    pole trajectory are checked against their bands (where the order has one);
    t_l and v_l are compared by their errors (their orders are checked by
    ``converge h``).  The run rows carry DOFs and seconds (error per DOF and per
    second); the notes state how much smaller each order's error is at equal DOFs.
    """
    del order  # every order of ``orders`` is run
    clock = time.perf_counter()
    t_end = t_end_dimensionless(case, t_end_s)
    progress(f"Legendre N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    names = ", ".join(f"P{p}" for p in orders)
    study = StudyResult(
        "order",
        f"{MESH_LABELS[mesh]} {names} at about the DOFs of P2 on levels {levels[0]}..{levels[-1]}"
        + (" (exact geometry)" if geometry == "exact" and mesh == "sphere" else ""),
        "h = DOFs^(-1/2)" if mesh == "sphere" else "h = 1/DOFs",
        settings=case_settings(case, sigma, recontact, t_end),
    )
    by_order: dict[int, list[FEMRun]] = {}
    for p in orders:
        specs = [order_spec(mesh, p, level, geometry) for level in levels]
        runs = fem_sequence(case, specs, sigma, recontact, t_end, progress)
        by_order[p] = runs
        steps = [r.dofs ** (-1.0 / r.spec.dimension) for r in runs]
        if len(set(steps)) < len(steps):  # clamped to level 0 twice: drop the repeat
            keep = [0] + [k for k in range(1, len(runs)) if steps[k] < steps[k - 1]]
            runs, steps = [runs[k] for k in keep], [steps[k] for k in keep]
            by_order[p] = runs
        if len(runs) < 2:
            continue
        quantities = fem_quantities(
            case, runs, reference, t_end, steps, suffix=f" (P{p})", keys=ORDER_STUDY_KEYS
        )
        for q in quantities:
            if q.spec.key.split(" ")[0] in ("t_l", "v_l"):
                q = replace(q, spec=replace(q.spec, band=None), passed=None)
            study.quantities.append(q)
        study.runs += [fem_row(case, r, reference) for r in runs]
    study.runs.insert(0, legendre_row(case, reference))
    study.notes.extend(_order_notes(case, by_order, reference))
    study.seconds = time.perf_counter() - clock
    return study


def _order_notes(
    case: Case, by_order: dict[int, list[FEMRun]], reference: LegendreRun
) -> list[str]:
    """Errors of t_l and v_l of every order at about equal DOFs, against P1 and P2."""
    notes: list[str] = []
    if reference.velocity is None or reference.t is None:
        return notes

    def error(run: FEMRun, t: bool) -> float:
        value, ref = (run.t, reference.t) if t else (run.velocity, reference.velocity)
        if value is None or ref is None:
            return math.nan
        return abs(value - ref) / abs(ref)

    if 1 in by_order and 2 in by_order:
        for p1, p2 in zip(by_order[1], by_order[2], strict=False):
            notes.append(
                f"{p2.dofs} DOFs: {p2.spec.label} against {p1.spec.label} ({p1.dofs} DOFs): "
                f"v_l error {error(p2, False):.2e} against {error(p1, False):.2e} "
                f"({error(p1, False) / error(p2, False):.3g} times smaller with P2), t_l error "
                f"{error(p2, True):.2e} against {error(p1, True):.2e} "
                f"({error(p1, True) / error(p2, True):.3g} times smaller with P2)."
            )
    for p, runs in by_order.items():
        if p <= 2 or 2 not in by_order:
            continue
        for high, p2 in zip(runs, by_order[2], strict=False):
            notes.append(
                f"{high.spec.label} ({high.dofs} DOFs, {high.seconds:.2g} s) against "
                f"{p2.spec.label} ({p2.dofs} DOFs, {p2.seconds:.2g} s): t_l error "
                f"{error(high, True):.2e} against {error(p2, True):.2e}, v_l error "
                f"{error(high, False):.2e} against {error(p2, False):.2e}."
            )
    return notes
