"""The membrane operator of the ball: the paper's, or the one consistent with its pressure.

Dimensionless (frequencies in units of ``c = sqrt(T / rho) / R``, eq. (3.8)).

``paper``
    Eq. (3.1): ``rho u_tt = T Delta_s u``.  On the Legendre polynomials
    ``omega_n^2 = n (n + 1)`` (eq. (3.11)); the degree-1 modes vibrate at
    ``sqrt(2)`` and the mean (n = 0) keeps its initial value a_0 (eq. (3.13)).
``pressurised``
    The second variation of ``T dA - P dV`` for a sphere whose tension
    balances the excess pressure, ``P = 2 T / R`` (Laplace's law; the paper's
    ``T = P R / 2`` of §4(b)).  For a radial displacement u the area and the
    volume change by

        ``dA = int (2 u / R + u^2 / R^2 + |grad_s u|^2 / 2) dS``,
        ``dV = int (u + u^2 / R + u^3 / (3 R^2)) dS``,

    so that ``T dA - P dV`` has no first-order term (the equilibrium) and the
    quadratic part ``(T / 2) int (|grad_s u|^2 - 2 u^2 / R^2) dS``.  The
    operator is ``-T (Delta_s + 2 / R^2)``: on P_n

        ``omega_n^2 = n (n + 1) - 2 = (n - 1)(n + 2)`` (units c^2),

    the spectrum of Rayleigh's oscillating bubble and drop (Rayleigh 1879,
    Proc. R. Soc. 29 71; Lamb, Hydrodynamics §275), of the vesicle
    fluctuation spectrum (Milner & Safran 1987, Phys. Rev. A 36 4371) and the
    membrane limit of the pressurised elastic shell (Kuo, Hunt & Lister 2013,
    ICSV20; code_aster validation case v2.03.007, ``i^2 + i - 2``).  n = 1 is
    then a free rigid translation (omega_1 = 0), and n = 0, the breathing
    mode, has ``omega_0^2 = -2``: at constant pressure a sphere held by its
    tension is unstable.  Only the enclosed gas holds it: with the gas term of
    :mod:`twoball.modal.stiffness`, ``omega_0^2 = 6 kappa P_abs / P - 2``.

The paper's operator drops the ``-2 u^2 / R^2`` term; it is the limit of a
membrane whose tension is not set by the pressure.  Bending (the Helfrich form
``beta (n - 1) n (n + 1) (n + 2)``) adds to either unchanged
(:class:`twoball.modal.stiffness.Stiffness`).  The finite-element form of the
extra term is ``-2 M`` (:meth:`twoball.fem_membrane.space.Discretisation.operator`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked

__all__ = ["MEMBRANES", "Membrane", "square_integral"]

#: Coefficient s of the mass-like term of each operator, ``omega^2 = lambda - s``.
MEMBRANES: dict[str, float] = {"paper": 0.0, "pressurised": 2.0}


def square_integral(phi_a: float) -> float:
    """``int F^2 dOmega / (2 pi) = 1 - x_a^2 - 2 x_a log(-x_a)`` for F of eq. (3.10).

    With ``L = 1 + x_a = 2 sin^2((pi - phi_a) / 2)`` (no cancellation) it is
    ``(2 - L) L + 2 (1 - L) log(1 - L) = sum_{k >= 3} 2 L^k / (k (k - 1))``: the
    series for L < 1/2 (the closed form would lose everything as phi_a -> pi,
    where the value is ~L^3 / 3), the closed form above.  Dimensionless.
    """
    length = 2.0 * math.sin((math.pi - phi_a) / 2.0) ** 2
    if length >= 0.5:
        return (2.0 - length) * length + 2.0 * (1.0 - length) * math.log1p(-length)
    total, power, k = 0.0, length**3, 3
    while True:
        term = 2.0 * power / (k * (k - 1))
        total += term
        if term <= 1e-17 * total:
            return total
        power *= length
        k += 1


@checked
@dataclass(frozen=True)
class Membrane:
    """The membrane operator: ``paper`` (eq. (3.1)) or ``pressurised`` (``T = P R / 2``).

    Parameters
    ----------
    kind : {"paper", "pressurised"}
        ``paper``: ``omega_n^2 = n (n + 1)``; ``pressurised``: the second variation
        of ``T dA - P dV`` at ``P = 2 T / R``, ``omega_n^2 = (n - 1)(n + 2)``
        (units c^2; see the module documentation and docs/pressurised.rst).

    Examples
    --------
    >>> import twoball
    >>> twoball.Membrane("pressurised").legendre([0, 1, 2, 3]).tolist()
    [-2.0, 0.0, 4.0, 10.0]
    >>> twoball.Membrane().as_dict()
    {'membrane': 'paper'}
    >>> twoball.Membrane("flat")
    Traceback (most recent call last):
    ...
    twoball.ParameterError: membrane must be one of paper, pressurised, got 'flat'
    """

    kind: str = "paper"

    def __post_init__(self) -> None:
        if not isinstance(self.kind, str) or self.kind not in MEMBRANES:
            raise ParameterError("membrane", "one of " + ", ".join(MEMBRANES), self.kind)

    @classmethod
    def of(cls, value: Any) -> Membrane:
        """``value`` as a :class:`Membrane`: one already, or its kind name."""
        return value if isinstance(value, Membrane) else cls(value)

    @property
    def shift(self) -> float:
        """s of ``omega^2 = lambda - s`` on a Laplace-Beltrami eigenvalue lambda: 0 or 2."""
        return MEMBRANES[self.kind]

    @property
    def pressurised(self) -> bool:
        """True for the operator consistent with the pressure (``shift`` 2)."""
        return self.shift != 0.0

    @property
    def lowest_degree(self) -> int:
        """The lowest Legendre degree that vibrates without gas: 1 (paper) or 2 (pressurised)."""
        return 2 if self.pressurised else 1

    def legendre(self, n: Any) -> np.ndarray:
        """Membrane eigenvalues of the degrees ``n``: ``n (n + 1)`` or ``(n - 1)(n + 2)``.

        Exact in floating point for integer n (products of small integers).
        """
        n = np.asarray(n, dtype=float)
        if self.pressurised:
            return (n - 1.0) * (n + 2.0)
        return n * (n + 1.0)

    def eigenvalues(self, laplace: Any) -> np.ndarray:
        """``lambda - s`` for Laplace-Beltrami eigenvalues ``lambda`` (Legendre or FE)."""
        values = np.asarray(laplace, dtype=float)
        return values - self.shift if self.pressurised else values.copy()

    def energy_shape(self, phi_a: float) -> float:
        """What the ``-s u^2`` term adds to the right-hand side of eq. (3.7) (v0^2 / (R c)^2).

        ``-(s / 2) int F^2 dOmega / (2 pi)`` with ``int F^2 dOmega = 2 pi (1 - x_a^2
        - 2 x_a log(-x_a))``, ``x_a = cos(phi_a)`` (F of eq. (3.10)); 0 for the paper's.
        """
        if not self.pressurised:
            return 0.0
        return -0.5 * self.shift * square_integral(phi_a)

    def as_dict(self) -> dict[str, str]:
        """``{"membrane": kind}``."""
        return {"membrane": self.kind}
