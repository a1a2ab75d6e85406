"""Observed order of accuracy, Richardson extrapolation and the grid convergence index.

Pure functions of numbers: nothing here knows about membranes, meshes or the
rest of the package.  A refinement study supplies a sequence of step sizes
``h`` (mesh size, 1/N, time step, ...) and the value of one quantity on each;
these functions turn them into orders, extrapolated values and error bands.

The grid convergence index (GCI) follows the five-step procedure of

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

import numpy as np
from numpy.typing import ArrayLike

Convergence = Literal["monotone", "oscillatory", "divergent", "exact"]
SAFETY_FACTOR = 1.25  # Celik et al. (2008) / Roache (1998), three or more grids
_MAX_ITERATIONS = 200
_ORDER_TOLERANCE = 1e-12


def _positive_finite(name: str, value: float) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return value


def observed_order(e_coarse: float, e_fine: float, h_coarse: float, h_fine: float) -> float:
    """Observed order between two grids, ``log(e_coarse/e_fine) / log(h_coarse/h_fine)``.

    Parameters
    ----------
    e_coarse, e_fine : float
        Error magnitudes on the coarse and the fine grid (absolute values are used).
    h_coarse, h_fine : float
        Step sizes, ``h_coarse != h_fine``, both > 0.

    Returns
    -------
    float
        The order p of ``e ~ C h**p``; NaN if either error is zero or not finite.

    References
    ----------
    Roache (1998), §5.4; Celik et al. (2008), eq. (3) with a known exact value.
    """
    h_coarse = _positive_finite("h_coarse", h_coarse)
    h_fine = _positive_finite("h_fine", h_fine)
    if h_coarse == h_fine:
        raise ValueError("the two step sizes must differ")
    a, b = abs(float(e_coarse)), abs(float(e_fine))
    if not (math.isfinite(a) and math.isfinite(b)) or a == 0.0 or b == 0.0:
        return math.nan
    return math.log(a / b) / math.log(h_coarse / h_fine)


def _sequence(h: ArrayLike, e: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    h = np.asarray(h, dtype=float).reshape(-1)
    e = np.abs(np.asarray(e, dtype=float).reshape(-1))
    if h.shape != e.shape:
        raise ValueError("h and the errors must have the same length")
    if h.size < 2:
        raise ValueError("a refinement sequence needs at least two steps")
    if not np.all(np.isfinite(h) & (h > 0)):
        raise ValueError("step sizes must be finite and > 0")
    return h, e


def step_orders(h: ArrayLike, e: ArrayLike) -> np.ndarray:
    """Observed order of every refinement step, ``log(e[k-1]/e[k]) / log(h[k-1]/h[k])``.

    Parameters
    ----------
    h : array_like, shape (n,)
        Step sizes, coarse to fine (any order; each step uses neighbours).
    e : array_like, shape (n,)
        Error magnitudes.

    Returns
    -------
    ndarray, shape (n - 1,)
        Orders; NaN where an error is zero or not finite.
    """
    h, e = _sequence(h, e)
    return np.array([observed_order(e[k - 1], e[k], h[k - 1], h[k]) for k in range(1, h.size)])


def error_ratios(e: ArrayLike) -> np.ndarray:
    """Ratios ``e[k-1] / e[k]`` of successive error magnitudes (NaN where e[k] = 0)."""
    e = np.abs(np.asarray(e, dtype=float).reshape(-1))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratios = e[:-1] / e[1:]
    return np.where(e[1:] > 0, ratios, np.nan)


@dataclass(frozen=True)
class OrderFit:
    """Least-squares fit ``log e = log C + p log h`` over a whole sequence.

    Attributes
    ----------
    order : float
        Slope p (NaN with fewer than two usable points).
    constant : float
        C of ``e ~ C h**p``.
    points : int
        Number of points used (zero or non-finite errors are left out).
    residual : float
        Root-mean-square residual of the fit in ``log e``.
    """

    order: float
    constant: float
    points: int
    residual: float


def least_squares_order(h: ArrayLike, e: ArrayLike) -> OrderFit:
    """Order from a least-squares line through ``(log h, log e)`` (Roache 1998, §5.4).

    Parameters
    ----------
    h, e : array_like, shape (n,)
        Step sizes and error magnitudes; points with ``e == 0`` are ignored.

    Returns
    -------
    OrderFit
    """
    h, e = _sequence(h, e)
    usable = np.isfinite(e) & (e > 0)
    if usable.sum() < 2 or np.unique(h[usable]).size < 2:
        return OrderFit(math.nan, math.nan, int(usable.sum()), math.nan)
    x, y = np.log(h[usable]), np.log(e[usable])
    slope, intercept = np.polyfit(x, y, 1)
    residual = float(np.sqrt(np.mean((y - (intercept + slope * x)) ** 2)))
    return OrderFit(float(slope), float(math.exp(intercept)), int(usable.sum()), residual)


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
            "order": _finite_or_none(self.order),
            "order_converged": self.order_converged,
            "convergence": self.convergence,
            "flagged": self.flagged,
            "extrapolated": _finite_or_none(self.extrapolated),
            "approximate_error": _finite_or_none(self.approximate_error),
            "extrapolated_error": _finite_or_none(self.extrapolated_error),
            "gci_fine": _finite_or_none(self.gci_fine),
            "gci_fine_absolute": _finite_or_none(self.gci_fine_absolute),
            "safety_factor": self.safety_factor,
        }


def _finite_or_none(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


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
    h1, h2, h3 = (_positive_finite("h", h) for h in steps)
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
            (f1, f2, f3), (h1, h2, h3), math.inf, True, kind, f1, 0.0, 0.0, 0.0, 0.0,
            safety_factor,
        )  # fmt: skip
    if kind == "divergent" or not (order > 0):
        return GCIResult(
            (f1, f2, f3), (h1, h2, h3), order, converged, "divergent", f1, approximate,
            math.nan, math.inf, math.inf, safety_factor,
        )  # fmt: skip
    extrapolated = richardson(f1, f2, r21, order)
    factor21 = r21**order
    gci_abs = 0.0 if math.isinf(factor21) else safety_factor * abs(eps21) / (factor21 - 1.0)
    gci_rel = gci_abs / abs(f1) if f1 != 0.0 else math.inf
    ext_error = abs((extrapolated - f1) / extrapolated) if extrapolated != 0.0 else math.nan
    return GCIResult(
        (f1, f2, f3), (h1, h2, h3), order, converged, kind, extrapolated, approximate,
        ext_error, gci_rel, gci_abs, safety_factor,
    )  # fmt: skip


@dataclass(frozen=True)
class OrderBand:
    """Expected order of a quantity and the band an observed order must fall in.

    Attributes
    ----------
    expected : float
        The theoretical order.
    below, above : float
        Allowed deviation below and above ``expected``; an observed order
        outside ``[expected - below, expected + above]`` fails -- too high is
        as suspicious as too low (a wrong reference or error cancellation).
    """

    expected: float
    below: float = 0.3
    above: float = 0.3

    def __post_init__(self) -> None:
        if not (math.isfinite(self.expected) and self.below >= 0 and self.above >= 0):
            raise ValueError("an order band needs a finite expected order and bands >= 0")

    @property
    def low(self) -> float:
        """Smallest accepted order."""
        return self.expected - self.below

    @property
    def high(self) -> float:
        """Largest accepted order."""
        return self.expected + self.above

    def contains(self, order: float) -> bool:
        """Whether ``order`` lies in the band (NaN never does)."""
        return bool(math.isfinite(order) and self.low <= order <= self.high)

    def describe(self) -> str:
        """``"2 [1.7, 2.3]"``: expected order and accepted interval."""
        return f"{self.expected:g} [{self.low:g}, {self.high:g}]"


ReferenceKind = Literal["exact", "reference", "richardson", "finest"]


@dataclass(frozen=True)
class SequenceAnalysis:
    """Everything a refinement study reports for one quantity.

    Attributes
    ----------
    steps, values : ndarray, shape (n,)
        Step sizes (coarse to fine) and the quantity on each grid.
    reference : float
        Value the errors are measured against.
    reference_kind : {"exact", "reference", "richardson", "finest"}
        Where the reference comes from: an exact value, an independent
        reference solution, the Richardson extrapolate of the three finest
        grids, or the finest grid itself (then its own error is left out).
    errors : ndarray, shape (n,)
        ``|value - reference|`` (NaN for the finest grid with ``finest``).
    ratios, orders : ndarray, shape (n - 1,)
        ``e[k-1]/e[k]`` and the observed order of each step.
    fit : OrderFit
        Least-squares order over all steps with an error.
    gci : GCIResult or None
        Three finest grids (None with fewer than three grids).
    extrapolated : float
        Richardson extrapolate of the two finest grids with the least-squares
        order (NaN if that order is not positive).
    """

    steps: np.ndarray
    values: np.ndarray
    reference: float
    reference_kind: ReferenceKind
    errors: np.ndarray
    ratios: np.ndarray
    orders: np.ndarray
    fit: OrderFit
    gci: GCIResult | None
    extrapolated: float

    @property
    def finest_order(self) -> float:
        """Observed order of the finest step with an error (NaN if none)."""
        finite = self.orders[np.isfinite(self.orders)]
        return float(finite[-1]) if finite.size else math.nan


def analyse(
    steps: ArrayLike,
    values: ArrayLike,
    reference: float | None = None,
    reference_kind: ReferenceKind = "exact",
    safety_factor: float = SAFETY_FACTOR,
) -> SequenceAnalysis:
    """Errors, observed orders, least-squares order, Richardson value and GCI of a sequence.

    Parameters
    ----------
    steps : array_like, shape (n,)
        Step sizes, strictly decreasing (coarse to fine), n >= 2.
    values : array_like, shape (n,)
        The quantity on each grid.
    reference : float, optional
        The exact or reference value.  Without it the errors are taken against
        the Richardson extrapolate of the three finest grids when they converge
        monotonically, else against the finest grid (whose error is then NaN).
    reference_kind : {"exact", "reference"}
        Label of a given ``reference``.
    safety_factor : float
        Fs of the GCI.

    Returns
    -------
    SequenceAnalysis
    """
    h = np.asarray(steps, dtype=float).reshape(-1)
    f = np.asarray(values, dtype=float).reshape(-1)
    if h.shape != f.shape or h.size < 2:
        raise ValueError("steps and values need the same length >= 2")
    if not np.all(np.diff(h) < 0):
        raise ValueError("steps must decrease strictly (coarse to fine)")
    three = None
    if h.size >= 3 and np.all(np.isfinite(f[-3:])):
        three = gci(f[::-1][:3], h[::-1][:3], safety_factor)
    if reference is not None:
        ref, kind = float(reference), reference_kind
        errors = np.abs(f - ref)
    elif three is not None and three.convergence == "monotone" and math.isfinite(three.order):
        ref, kind = three.extrapolated, "richardson"
        errors = np.abs(f - ref)
    else:
        ref, kind = float(f[-1]), "finest"
        errors = np.abs(f - ref)
        errors[-1] = np.nan
    ratios = error_ratios(errors)
    orders = step_orders(h, errors)
    usable = np.isfinite(errors)
    fit = (
        least_squares_order(h[usable], errors[usable])
        if usable.sum() >= 2
        else OrderFit(math.nan, math.nan, int(usable.sum()), math.nan)
    )
    extrapolated = math.nan
    if fit.order > 0:
        extrapolated = richardson(f[-1], f[-2], h[-2] / h[-1], fit.order)
    return SequenceAnalysis(h, f, ref, kind, errors, ratios, orders, fit, three, extrapolated)
