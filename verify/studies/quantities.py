"""Quantities of a refinement study: what is measured, its expected order, the analysis.

:func:`evaluate_quantity` hands one sequence (coarse to fine) to
:func:`twoball.verify.studies.orders.analyse` for errors, observed orders,
Richardson extrapolation and the GCI, leaves round-off out of the orders and
checks the observed order against the band the theory predicts.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from twoball.modal.parameters import Case
from twoball.verify.studies.gci import finite_or_none
from twoball.verify.studies.orders import (
    OrderBand,
    OrderFit,
    SequenceAnalysis,
    analyse,
    least_squares_order,
)

ROUNDOFF = 1e-11  # relative errors below this are round-off: they carry no order


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
            "errors": finite_list(a.errors),
            "relative_errors": finite_list(self.relative_errors),
            "ratios": finite_list(a.ratios),
            "orders": finite_list(a.orders),
            "least_squares_order": finite_or_none(a.fit.order),
            "checked_order": finite_or_none(self.checked_order),
            "richardson": finite_or_none(a.extrapolated),
            "gci": None if a.gci is None else a.gci.as_dict(),
            "passed": self.passed,
            "remark": self.remark,
        }


def finite_list(values: np.ndarray) -> list[float | None]:
    """The values as floats, None where not finite (JSON-ready)."""
    return [finite_or_none(v) for v in np.asarray(values, dtype=float)]


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
    elif usable.size < 2 and finite.any() and noise[np.flatnonzero(finite)[-1]]:
        # one error above round-off, then round-off (P4 on fine meshes): no order to observe
        remark = "round-off reached after one step"
        passed = None if spec.band is None else True
    else:
        passed = None if spec.band is None else spec.band.contains(checked)
    return QuantityResult(
        spec, list(labels), list(dofs), analysis, relative, checked, passed, remark
    )


def ms_per_unit(case: Case) -> float:
    """Milliseconds per dimensionless time unit 1/c."""
    return 1e3 * case.scalings.time


def liftoff_specs(case: Case, band: OrderBand | None) -> list[QuantitySpec]:
    """t_l, v_l, the pole trajectory and the end energy, all with the same band."""
    return [
        QuantitySpec("t_l", "t_l [ms]", ms_per_unit(case), band),
        QuantitySpec("v_l", "v_l [m/s]", case.scalings.velocity, band),
        QuantitySpec("pole_l2", "||u - u_ref||_L2 / ||u_ref|| (pole)", 1.0, band, True),
        QuantitySpec("energy_end", "E(t_end) [T R^2]", 1.0, band),
    ]
