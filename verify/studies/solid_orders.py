"""The solid ball's finite-element eigenvalues against Lamb's roots: observed orders.

``twoball converge h --ball solid`` refines the (r, z) half disc
(:func:`~twoball.fem_solid.mesh.half_disc`, four triangles halved ``level`` times,
step ``h = 2^-level``) and measures the axisymmetric eigenvalues ``eta^2`` of the
lowest spheroidal modes against the squares of Lamb's roots
(:func:`~twoball.modal.balls.solid.lamb_table`, exact to round-off): the reference
is exact, so every error is the discretisation's.

Expected orders (Strang & Fix 1973, §6.3; Babuška & Osborn 1991, Thm. 10.4): a
Lagrange element of degree ``p`` on a smooth domain gives eigenvalue errors
O(h^2p) -- 2 for P1, 4 for P2 -- provided the boundary is represented well
enough.  The arc is the inscribed polygon for P1 (geometric eigenvalue error
O(h^2), the same order) and quadratic for P2 and P3 (isoparametric for P2; for P3
the arc's O(h^3) position error limits the eigenvalues to O(h^4): measured
4.1-4.4 from levels 1-4, not 6).
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence

import numpy as np

from twoball._common.errors import ParameterError
from twoball.verify.studies.orders import OrderBand
from twoball.verify.studies.quantities import QuantitySpec, evaluate_quantity
from twoball.verify.studies.result import Progress, StudyResult, quiet

__all__ = [
    "SOLID_BANDS",
    "SOLID_LEVELS",
    "SOLID_MODES",
    "parse_solid_levels",
    "run_solid_h_study",
    "solid_markdown",
]

#: (degree n, radial order k) of the modes measured: the lowest of degrees 0-3
#: and the second of degree 2
SOLID_MODES: tuple[tuple[int, int], ...] = ((2, 1), (0, 1), (1, 1), (3, 1), (2, 2))

#: Default levels per element order: each run under a few seconds (about 4 300
#: unknowns at the finest), the whole study about 10-20 s on one core.
SOLID_LEVELS: dict[int, tuple[int, ...]] = {1: (2, 3, 4, 5), 2: (1, 2, 3, 4)}

#: Expected eigenvalue order and band per element order.  P2 approaches 4 from
#: below (the modes of higher degree are pre-asymptotic at level 2: 3.4, 3.6, 3.8
#: for (3, 1)), hence the wider band below.  P3 is left out: on the quadratic arcs
#: its order tends to the geometry's 4 from above and is pre-asymptotic at every
#: affordable level (measured 4.2-5.1 between levels 2 and 3, 4.1-5.0 between 3 and 4).
SOLID_BANDS: dict[int, OrderBand] = {1: OrderBand(2.0, 0.3, 0.3), 2: OrderBand(4.0, 0.5, 0.3)}


def parse_solid_levels(text: str | None, element: int) -> tuple[int, ...]:
    """``"2:5"`` or ``"2,3,4,5"`` -> consecutive half-disc levels (default per element order)."""
    if text is None:
        return SOLID_LEVELS[element]
    from twoball._common.ranges import parse_values

    valid = "3 to 6 consecutive half-disc levels in 0..7, e.g. 1:4"
    try:
        if ":" in text:
            a, b = (int(v) for v in text.split(":"))
            values: list[int] = list(range(a, b + 1))
        else:
            values = [int(v) for v in parse_values(text, "levels", integer=True, valid=valid)]
    except ValueError:
        raise ParameterError("levels", valid, text) from None
    consecutive = all(b == a + 1 for a, b in zip(values[:-1], values[1:], strict=True))
    if not 3 <= len(values) <= 6 or min(values) < 0 or max(values) > 7 or not consecutive:
        raise ParameterError("levels", valid, text)
    return tuple(values)


def run_solid_h_study(
    poisson: float = 0.45,
    *,
    element: int = 2,
    levels: Sequence[int] | None = None,
    modes: Sequence[tuple[int, int]] = SOLID_MODES,
    progress: Progress = quiet,
) -> StudyResult:
    """Refine the half disc; the eigenvalues ``eta^2`` against Lamb's roots squared.

    Parameters
    ----------
    poisson : float
        Poisson's ratio (default 0.45, the superball preset's).
    element : {1, 2}
        Lagrange order of the displacement.
    levels : sequence of int, optional
        Consecutive half-disc levels (default :data:`SOLID_LEVELS`).
    modes : sequence of (n, k)
        The modes measured (degree, radial order).
    progress : callable
        Called with a short text as each level starts.

    Returns
    -------
    StudyResult
        ``study = "h"``; one quantity per mode, its band :data:`SOLID_BANDS`.
    """
    from twoball.fem_solid.eigen import axisymmetric_eigen
    from twoball.fem_solid.mesh import half_disc
    from twoball.modal.balls.solid import lamb_table

    if element not in SOLID_BANDS or isinstance(element, bool):
        raise ParameterError("order", "1 or 2 for the solid ball", element)
    chosen = tuple(SOLID_LEVELS[element] if levels is None else levels)
    start = time.perf_counter()
    top_n = max(n for n, _ in modes)
    top_k = max(k for _, k in modes)
    table = lamb_table(poisson, top_n, top_k)
    exact = {}
    for n, k in modes:
        found = table.eta[(table.degree == n) & (table.radial_order == k)]
        exact[(n, k)] = float(found[0]) ** 2
    values: dict[tuple[int, int], list[float]] = {m: [] for m in modes}
    runs, dofs = [], []
    for level in chosen:
        progress(f"P{element} level {level}")
        t0 = time.perf_counter()
        eig = axisymmetric_eigen(half_disc(level), poisson, 16, max_degree=10, element=element)
        for n, k in modes:
            found = np.sort(eig.eigenvalues[(eig.degree == n) & ~eig.rigid])
            values[(n, k)].append(float(found[k - 1]) if found.size >= k else math.nan)
        dofs.append(int(eig.basis.N))
        runs.append(
            {
                "label": f"P{element} level {level}",
                "dofs": int(eig.basis.N),
                "seconds": time.perf_counter() - t0,
            }
        )
    labels = [r["label"] for r in runs]
    steps = [2.0**-level for level in chosen]
    band = SOLID_BANDS[element]
    quantities = [
        evaluate_quantity(
            QuantitySpec(f"eta2_{n}_{k}", f"eta^2 (n = {n}, k = {k})", 1.0, band),
            labels,
            dofs,
            steps,
            values[(n, k)],
            exact[(n, k)],
            "exact",
        )
        for n, k in modes
    ]
    geometry = {1: "straight sides", 2: "quadratic arcs"}[element]
    notes = [
        f"eta^2 = omega^2 R^2 / c_s^2 of the half disc's P{element} ({geometry}) at nu = "
        f"{poisson:g} against Lamb's roots squared (exact); h = 2^-level.",
        "expected eigenvalue order 2p on a well represented boundary (P1: 2, P2: 4).",
    ]
    return StudyResult(
        study="h",
        title=f"solid ball: P{element} half disc, levels {chosen[0]}-{chosen[-1]}",
        step_name="h = 2^-level (the half disc's four triangles halved level times)",
        quantities=quantities,
        notes=notes,
        runs=runs,
        settings={"ball": "solid", "poisson": poisson, "element": element, "levels": chosen},
        seconds=time.perf_counter() - start,
    )


def solid_markdown(study: StudyResult) -> str:
    """The relative eigenvalue errors per level and the observed orders (Markdown)."""
    first = study.quantities[0]
    header = ["mode", *first.labels, "observed orders", "checked", "band", "result"]
    lines = ["| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    for q in study.quantities:
        errors = [f"{e:.2e}" for e in q.relative_errors]
        orders = ", ".join(f"{o:.2f}" for o in q.analysis.orders)
        band = q.spec.band
        bounds = "-" if band is None else f"[{band.low:g}, {band.high:g}]"
        verdict = "-" if q.passed is None else ("PASS" if q.passed else "FAIL")
        cells = [q.spec.label, *errors, orders, f"{q.checked_order:.2f}", bounds, verdict]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)
