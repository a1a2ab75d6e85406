"""Spectral filters of the truncated modal series, eq. (3.16).

A filter is written as a function of a mode's (dimensionless, undamped) angular
frequency ``omega`` so that any backend -- the Legendre series or finite-element
eigenpairs -- applies exactly the same weights.  The cutoff is the frequency of
the highest Legendre mode kept, ``omega_N = sqrt(N (N + 1))``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from twoball._common.choices import FILTER_KINDS
from twoball._common.errors import ParameterError

FilterKind = Literal["lanczos", "printed", "none"]


def legendre_frequency(n: int | np.ndarray) -> np.ndarray:
    """Undamped angular frequency ``omega_n = sqrt(n (n + 1))`` of the Legendre mode n.

    Dimensionless (time unit 1/c); eq. (3.11).
    """
    n = np.asarray(n, dtype=float)
    return np.sqrt(n * (n + 1.0))


@dataclass(frozen=True)
class SpectralFilter:
    """Weights sigma(omega) applied to every mode of a truncated series, eq. (3.16).

    Parameters
    ----------
    kind : {"lanczos", "printed", "none"}
        ``lanczos`` (default): ``sinc(pi omega / omega_N)`` -- the Lanczos sigma
        factor, which vanishes at the cutoff.  ``printed``: ``sin(omega/omega_N) /
        (omega/omega_N)``, literally as printed in eq. (3.16) (no factor pi; it only
        falls to sin(1) = 0.84 at the cutoff).  ``none``: plain truncation.
    modes : int
        Legendre truncation N >= 1; sets ``omega_N = sqrt(N (N + 1))``.

    Notes
    -----
    Every kind truncates: modes with ``omega`` above the midpoint between
    ``omega_N`` and ``omega_{N+1}`` get weight 0.  For Legendre modes that is
    exactly ``n <= N``; for finite-element eigenfrequencies, which deviate slightly
    from ``sqrt(l (l + 1))``, it keeps the whole cluster of degree N and nothing of
    degree N + 1.  The Lanczos weight is zero at ``omega_N`` already, so for it the
    truncation point is immaterial.
    """

    kind: FilterKind = "lanczos"
    modes: int = 30

    def __post_init__(self) -> None:
        if self.kind not in FILTER_KINDS:
            raise ParameterError("sigma", "one of " + ", ".join(FILTER_KINDS), self.kind)
        if int(self.modes) != self.modes or self.modes < 1:
            raise ParameterError("modes", "an integer >= 1", self.modes)

    @property
    def omega_n(self) -> float:
        """Cutoff frequency ``omega_N = sqrt(N (N + 1))`` (dimensionless)."""
        return float(legendre_frequency(self.modes))

    @property
    def omega_cut(self) -> float:
        """Frequency above which a mode is dropped: midway between omega_N and omega_{N+1}."""
        return 0.5 * float(legendre_frequency(self.modes) + legendre_frequency(self.modes + 1))

    def __call__(self, omega: np.ndarray) -> np.ndarray:
        """Weights sigma(omega) for angular frequencies ``omega`` (dimensionless), eq. (3.16)."""
        omega = np.asarray(omega, dtype=float)
        ratio = omega / self.omega_n
        if self.kind == "lanczos":
            weight = np.where(ratio < 1.0, np.sinc(ratio), 0.0)  # np.sinc(x) = sin(pi x)/(pi x)
        elif self.kind == "printed":
            weight = np.sinc(ratio / np.pi)
        else:
            weight = np.ones_like(omega)
        return np.where(omega <= self.omega_cut, weight, 0.0)
