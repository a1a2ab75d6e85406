"""Richardson extrapolation and the grid convergence index (GCI) of three grids.

Pure functions of numbers, like :mod:`twoball.verify.studies.orders`.  The GCI
follows the five-step procedure of

    I. B. Celik, U. Ghia, P. J. Roache, C. J. Freitas, H. Coleman, P. E. Raad,
    "Procedure for estimation and reporting of uncertainty due to
    discretization in CFD applications", J. Fluids Eng. 130 (2008) 078001,

which builds on P. J. Roache, *Verification and Validation in Computational
Science and Engineering*, Hermosa (1998).  Grids are numbered as there: 1 is
the finest, 3 the coarsest, ``r21 = h2/h1`` and ``r32 = h3/h2``; the safety
factor is 1.25 for three or more grids.  Convergence is classified by the
ratio ``R = eps21/eps32`` of successive changes (``eps21 = phi2 - phi1``):
``0 <= R < 1`` monotone, ``-1 < R < 0`` oscillatory, ``|R| >= 1`` divergent.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

Convergence = Literal["monotone", "oscillatory", "divergent", "exact"]
SAFETY_FACTOR = 1.25  # Celik et al. (2008) / Roache (1998), three or more grids
_MAX_ITERATIONS = 200
_ORDER_TOLERANCE = 1e-12


def positive_finite(name: str, value: float) -> float:
    """``value`` as a float; ``ValueError`` naming ``name`` unless it is finite and > 0."""
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return value


def richardson(f_fine: float, f_coarse: float, ratio: float, order: float) -> float:
    """Richardson extrapolate ``(r**p f_fine - f_coarse) / (r**p - 1)``.

    Parameters
    ----------
    f_fine, f_coarse : float
        The quantity on the fine and the coarse grid.
    ratio : float
        Refinement ratio ``r = h_coarse / h_fine > 1``.
    order : float
        Order p > 0 (formal or observed); ``inf`` returns ``f_fine``.

    Returns
    -------
    float
        The estimate of the exact value (Celik et al. 2008, eq. (6)).
    """
    ratio = float(ratio)
    if not (math.isfinite(ratio) and ratio > 1.0):
        raise ValueError(f"the refinement ratio must be > 1, got {ratio!r}")
    order = float(order)
    if not order > 0:
        raise ValueError(f"the order must be > 0, got {order!r}")
    if math.isinf(order):
        return float(f_fine)
    factor = ratio**order
    if math.isinf(factor):
        return float(f_fine)
    return (factor * float(f_fine) - float(f_coarse)) / (factor - 1.0)


def classify(eps21: float, eps32: float) -> Convergence:
    """Convergence type of three grids from their changes ``eps21``, ``eps32``.

    ``R = eps21 / eps32``: ``0 <= R < 1`` monotone, ``-1 < R < 0`` oscillatory,
    ``|R| >= 1`` divergent (monotone or oscillatory); both zero is ``exact``.
    (Celik et al. 2008 flag ``eps32/eps21 < 0`` as oscillatory; the bands on R
    follow Stern et al. 2001 and Roache 1998.)
    """
    eps21, eps32 = float(eps21), float(eps32)
    if eps21 == 0.0 and eps32 == 0.0:
        return "exact"
    if eps32 == 0.0:
        return "divergent"
    ratio = eps21 / eps32
    if abs(ratio) >= 1.0:
        return "divergent"
    return "monotone" if ratio >= 0.0 else "oscillatory"


def three_grid_order(f1: float, f2: float, f3: float, r21: float, r32: float) -> tuple[float, bool]:
    """Apparent order of three grids, Celik et al. (2008) eqs. (3a)-(3c).

    Solves ``p = |ln|eps32/eps21| + q(p)| / ln r21`` with
    ``q(p) = ln((r21**p - s) / (r32**p - s))`` and ``s = sign(eps32/eps21)`` by
    fixed-point iteration (a single step when ``r21 == r32``).

    Parameters
    ----------
    f1, f2, f3 : float
        The quantity on the fine, medium and coarse grid.
    r21, r32 : float
        Refinement ratios ``h2/h1`` and ``h3/h2``, both > 1.

    Returns
    -------
    order : float
        p (``inf`` if ``eps21 == 0``; NaN if ``eps32 == 0``).
    converged : bool
        Whether the fixed-point iteration converged.
    """
    for name, r in (("r21", r21), ("r32", r32)):
        if not (math.isfinite(r) and r > 1.0):
            raise ValueError(f"{name} must be > 1, got {r!r}")
    eps21, eps32 = float(f2) - float(f1), float(f3) - float(f2)
    if eps32 == 0.0:
        return math.nan, True
    if eps21 == 0.0:
        return math.inf, True
    quotient = eps32 / eps21
    s = 1.0 if quotient > 0 else -1.0
    log_quotient = math.log(abs(quotient))
    log_r21 = math.log(r21)
    order = abs(log_quotient) / log_r21
    if r21 == r32:
        return order, True
    for _ in range(_MAX_ITERATIONS):
        a, b = r21**order - s, r32**order - s
        if a <= 0.0 or b <= 0.0:  # only possible for s = +1 and p -> 0
            return order, False
        new = abs(log_quotient + math.log(a / b)) / log_r21
        if abs(new - order) <= _ORDER_TOLERANCE * max(1.0, abs(new)):
            return new, True
        order = new
    return order, False


@dataclass(frozen=True)
class GCIResult:
    """Discretisation-error estimate of the finest of three grids (Celik et al. 2008).

    Attributes
    ----------
    values : tuple of float
        ``(phi1, phi2, phi3)``, finest first.
    steps : tuple of float
        ``(h1, h2, h3)``.
    order : float
        Apparent order p (eq. (3)); ``inf`` when the two finest grids agree exactly.
    order_converged : bool
        Whether the fixed-point iteration for p converged.
    convergence : {"monotone", "oscillatory", "divergent", "exact"}
        Type of the sequence (see :func:`classify`).
    extrapolated : float
        ``phi_ext21`` (eq. (4)); equals phi1 for a divergent or exact sequence.
    approximate_error : float
        ``e_a21 = |(phi1 - phi2)/phi1|`` (eq. (5)); inf if phi1 = 0.
    extrapolated_error : float
        ``e_ext21 = |(phi_ext21 - phi1)/phi_ext21|``.
    gci_fine : float
        ``GCI_fine21 = Fs e_a21 / (r21**p - 1)`` (eq. (6)), relative.
    gci_fine_absolute : float
        The same without dividing by ``|phi1|`` (for quantities near zero).
    safety_factor : float
        Fs.
    """

    values: tuple[float, float, float]
    steps: tuple[float, float, float]
    order: float
    order_converged: bool
    convergence: Convergence
    extrapolated: float
    approximate_error: float
    extrapolated_error: float
    gci_fine: float
    gci_fine_absolute: float
    safety_factor: float

    @property
    def flagged(self) -> bool:
        """True for an oscillatory or divergent sequence, or a p that did not converge."""
        return self.convergence in ("oscillatory", "divergent") or not self.order_converged

    def as_dict(self) -> dict[str, object]:
        """JSON-ready dictionary (non-finite numbers as None)."""
        return {
            "values": list(self.values),
            "steps": list(self.steps),
            "order": finite_or_none(self.order),
            "order_converged": self.order_converged,
            "convergence": self.convergence,
            "flagged": self.flagged,
            "extrapolated": finite_or_none(self.extrapolated),
            "approximate_error": finite_or_none(self.approximate_error),
            "extrapolated_error": finite_or_none(self.extrapolated_error),
            "gci_fine": finite_or_none(self.gci_fine),
            "gci_fine_absolute": finite_or_none(self.gci_fine_absolute),
            "safety_factor": self.safety_factor,
        }


def finite_or_none(value: float | None) -> float | None:
    """``value`` as a float, or None when it is None or not finite (for JSON)."""
    return float(value) if value is not None and math.isfinite(value) else None


def gci(
    values: Sequence[float],
    steps: Sequence[float],
    safety_factor: float = SAFETY_FACTOR,
) -> GCIResult:
    """Grid convergence index of the finest grid from three grids (Celik et al. 2008).

    Parameters
    ----------
    values : sequence of 3 floats
        ``(phi1, phi2, phi3)``: the quantity on the fine, medium and coarse grid.
    steps : sequence of 3 floats
        ``(h1, h2, h3)`` with ``h1 < h2 < h3``.
    safety_factor : float
        Fs; 1.25 for three grids (Roache 1998).

    Returns
    -------
    GCIResult
        Apparent order, extrapolated value, relative errors, GCI and the type
        of convergence.  Oscillatory and divergent sequences are flagged
        (``result.flagged``); for a divergent one the order is reported but
        the extrapolate is phi1 and the GCI is inf.
    """
    if len(values) != 3 or len(steps) != 3:
        raise ValueError("the GCI needs exactly three grids")
    f1, f2, f3 = (float(v) for v in values)
    h1, h2, h3 = (positive_finite("h", h) for h in steps)
    if not all(math.isfinite(v) for v in (f1, f2, f3)):
        raise ValueError("the three values must be finite")
    if not h1 < h2 < h3:
        raise ValueError("steps must satisfy h1 < h2 < h3 (finest first)")
    r21, r32 = h2 / h1, h3 / h2
    eps21, eps32 = f2 - f1, f3 - f2
    kind = classify(eps21, eps32)
    order, converged = three_grid_order(f1, f2, f3, r21, r32)
    approximate = abs(eps21 / f1) if f1 != 0.0 else (0.0 if eps21 == 0.0 else math.inf)
    if kind == "exact":
        return GCIResult(
            (f1, f2, f3),
            (h1, h2, h3),
            math.inf,
            True,
            kind,
            f1,
            0.0,
            0.0,
            0.0,
            0.0,
            safety_factor,
        )
    if kind == "divergent" or not (order > 0):
        return GCIResult(
            (f1, f2, f3),
            (h1, h2, h3),
            order,
            converged,
            "divergent",
            f1,
            approximate,
            math.nan,
            math.inf,
            math.inf,
            safety_factor,
        )
    extrapolated = richardson(f1, f2, r21, order)
    factor21 = r21**order
    gci_abs = 0.0 if math.isinf(factor21) else safety_factor * abs(eps21) / (factor21 - 1.0)
    gci_rel = gci_abs / abs(f1) if f1 != 0.0 else math.inf
    ext_error = abs((extrapolated - f1) / extrapolated) if extrapolated != 0.0 else math.nan
    return GCIResult(
        (f1, f2, f3),
        (h1, h2, h3),
        order,
        converged,
        kind,
        extrapolated,
        approximate,
        ext_error,
        gci_rel,
        gci_abs,
        safety_factor,
    )
