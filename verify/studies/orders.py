"""Observed order of accuracy of a refinement sequence, and its analysis.

Pure functions of numbers: nothing here knows about membranes, meshes or the
rest of the package.  A refinement study supplies a sequence of step sizes
``h`` (mesh size, 1/N, time step, ...) and the value of one quantity on each;
these functions turn them into errors, observed orders and least-squares
orders (Roache 1998, §5.4), and :func:`analyse` adds the Richardson
extrapolate and the grid convergence index of :mod:`twoball.verify.studies.gci`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from twoball.verify.studies.gci import SAFETY_FACTOR, GCIResult, gci, positive_finite, richardson


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
    h_coarse = positive_finite("h_coarse", h_coarse)
    h_fine = positive_finite("h_fine", h_fine)
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
