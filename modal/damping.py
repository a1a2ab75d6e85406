"""Damping laws: one object per law, giving the damping ratio of a mode of frequency omega.

A law is shared by every backend: the closed form and finite-element modal
superposition damp mode n by its ratio ``zeta(omega_n)`` (any ratio >= 0:
over-damped modes too, :class:`twoball.modal.series.ModalSeries`);
finite-element time stepping builds its damping operator from the same law
(:mod:`twoball.fem_membrane.damping`).

Units: a ratio is a pure number.  Rayleigh's coefficients are SI at the public
API (alpha [1/s], beta [s], :class:`twoball.Case` ``rayleigh``) and
dimensionless inside the solvers (alpha in units of c, beta in units of 1/c):
:meth:`Rayleigh.scaled` converts, and ``zeta(omega)`` is the same function in
either system as long as omega is in the same units (rad/s, or units of c).

:class:`ModalRatio`
    One ratio D for every mode, eq. (3.14): the paper's law.  As an operator
    ``2 D sqrt(-Delta_s) d/dt`` it is non-local (M. H. Scott, "Be careful with
    modal damping", 2019; Kelly, McGough & Meerschaert, JASA 124, 2008).
:class:`Rayleigh`
    ``C = alpha M + beta K`` (mass- and stiffness-proportional, local and
    causal): ``zeta(omega) = alpha / (2 omega) + beta omega / 2``.  Without
    ``alpha`` and ``beta`` it is fitted to the case's ratio D at the lowest
    vibrating mode (omega_1 = sqrt(2) for the paper's membrane, omega_2 = 2 for
    the pressurised one) and at degree N, the spectral filter's cutoff
    (:meth:`twoball.modal.stiffness.Stiffness.fit_band`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from twoball._common.errors import ParameterError, real_number
from twoball._common.keywords import checked

__all__ = ["DAMPING_LAWS", "ModalRatio", "Rayleigh", "damping_law", "is_law", "with_damping"]

#: Lower fitting frequency of a fitted Rayleigh law: omega_1 of the sphere.
RAYLEIGH_LOW = math.sqrt(2.0)


@checked
@dataclass(frozen=True)
class ModalRatio:
    """The paper's modal damping: ratio ``ratio`` on every mode, eq. (3.14).

    Parameters
    ----------
    ratio : float
        Damping ratio D in [0, 1).

    Examples
    --------
    >>> import twoball
    >>> law = twoball.ModalRatio(0.13)
    >>> law.as_dict()
    {'law': 'modal', 'ratio': 0.13}
    >>> twoball.ModalRatio(1.5)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: ratio must be in [0, 1), got 1.5
    """

    ratio: float

    name = "modal"

    def __post_init__(self) -> None:
        value = real_number("ratio", self.ratio, "in [0, 1)")
        if not 0.0 <= value < 1.0:
            raise ParameterError("ratio", "in [0, 1)", self.ratio)
        object.__setattr__(self, "ratio", value)

    def ratios(self, omega: Any) -> Any:
        """``zeta`` of modes of frequencies ``omega`` (array-like): ``D`` everywhere."""
        import numpy as np

        return np.full(np.shape(omega), self.ratio)

    def decay(self, omega: Any) -> Any:
        """``2 zeta omega = 2 D omega``: the coefficient of q' in each mode's equation."""
        import numpy as np

        return 2.0 * self.ratio * np.asarray(omega, dtype=float)

    def scaled(self, wave_speed: float) -> ModalRatio:
        """The law in units of c: a ratio has no unit, so itself."""
        return self

    def as_dict(self) -> dict[str, Any]:
        """``{"law": "modal", "ratio": D}``."""
        return {"law": self.name, "ratio": self.ratio}


@checked
@dataclass(frozen=True)
class Rayleigh:
    """Rayleigh (Kelvin-Voigt) damping ``C = alpha M + beta K``: local and causal.

    Each mode of frequency omega has the ratio ``zeta = alpha / (2 omega) + beta
    omega / 2`` (the decay ``2 zeta omega = alpha + beta omega^2``); modes with
    zeta >= 1 are critically or over-damped (real exponentials).  K is the
    ball's own stiffness (membrane operator, bending, gas).

    Parameters
    ----------
    alpha : float, optional
        Mass-proportional coefficient >= 0 [1/s] (at the API; in units of c
        inside the solvers, :meth:`scaled`).
    beta : float, optional
        Stiffness-proportional coefficient >= 0 [s] (in units of 1/c inside).

    Give both, or neither: then the law is fitted so that the ratio equals the
    case's D at the lowest vibrating mode (omega_1 = sqrt(2) for the paper's
    membrane) and at degree N, the spectral filter's cutoff.

    Examples
    --------
    >>> import twoball
    >>> law = twoball.Rayleigh(alpha=0.1, beta=0.01)
    >>> round(float(law.ratios(2.0)), 6)
    0.035
    >>> law.scaled(320.0).beta  # beta c: the same law in units of c
    3.2
    >>> twoball.Rayleigh.fit(0.13, 2**0.5, 30.0).alpha > 0
    True
    >>> twoball.Rayleigh(alpha=-1.0, beta=0.0)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: alpha must be a finite number >= 0 [1/s], got -1.0
    """

    alpha: float | None = None
    beta: float | None = None

    name = "rayleigh"

    def __post_init__(self) -> None:
        for field, unit in (("alpha", "1/s"), ("beta", "s")):
            value = getattr(self, field)
            if value is not None:
                valid = f"a finite number >= 0 [{unit}]"
                number = real_number(field, value, valid)
                if number < 0.0:
                    raise ParameterError(field, valid, value)
                object.__setattr__(self, field, number)
        if (self.alpha is None) != (self.beta is None):
            given, other = ("alpha", "beta") if self.beta is None else ("beta", "alpha")
            valid = f"given together with {other} (or neither: fitted to D)"
            raise ParameterError(given, valid, getattr(self, given))

    @property
    def fitted(self) -> bool:
        """True when alpha and beta are left to the solver (fitted to D)."""
        return self.alpha is None

    @classmethod
    def fit(cls, ratio: float, omega_low: float, omega_high: float) -> Rayleigh:
        """The law whose ratio is ``ratio`` at ``omega_low`` and ``omega_high``.

        ``alpha = 2 D w1 w2 / (w1 + w2)``, ``beta = 2 D / (w1 + w2)``.
        """
        ratio = ModalRatio(ratio).ratio
        low, high = float(omega_low), float(omega_high)
        if not (math.isfinite(low) and math.isfinite(high) and 0.0 < low < high):
            raise ParameterError(
                "rayleigh_frequencies", "two finite frequencies 0 < w1 < w2", (low, high)
            )
        return cls(2.0 * ratio * low * high / (low + high), 2.0 * ratio / (low + high))

    def ratios(self, omega: Any) -> Any:
        """``zeta(omega) = alpha / (2 omega) + beta omega / 2`` (inf at omega = 0)."""
        import numpy as np

        if self.fitted:
            raise ParameterError("damping", "a Rayleigh law with alpha and beta here", self)
        omega = np.asarray(omega, dtype=float)
        with np.errstate(divide="ignore"):
            return self.alpha / (2.0 * omega) + 0.5 * self.beta * omega

    def decay(self, omega: Any) -> Any:
        """``2 zeta omega = alpha + beta omega^2``: finite at omega = 0 too."""
        import numpy as np

        if self.fitted:
            raise ParameterError("damping", "a Rayleigh law with alpha and beta here", self)
        omega = np.asarray(omega, dtype=float)
        return self.alpha + self.beta * omega * omega

    def scaled(self, wave_speed: float) -> Rayleigh:
        """The same law in units of c: ``alpha / c`` and ``beta c`` (a fitted law stays so).

        ``wave_speed`` is c [1/s]; alpha [1/s] and beta [s] become dimensionless.
        """
        if self.fitted:
            return self
        return Rayleigh(self.alpha / wave_speed, self.beta * wave_speed)

    def as_dict(self) -> dict[str, Any]:
        """``{"law": "rayleigh", "alpha": ..., "beta": ...}`` (None: fitted to D)."""
        return {"law": self.name, "alpha": self.alpha, "beta": self.beta}


#: The laws by name (the command line's choices).
DAMPING_LAWS: dict[str, type] = {ModalRatio.name: ModalRatio, Rayleigh.name: Rayleigh}


def is_law(value: Any) -> bool:
    """Whether ``value`` is a damping law object (not a bare ratio)."""
    return isinstance(value, (ModalRatio, Rayleigh))


def damping_law(law: Any, ratio: float) -> ModalRatio | Rayleigh:
    """``law`` as a law object: None is the paper's :class:`ModalRatio` with ``ratio``.

    Raises :class:`ParameterError` naming ``damping`` for anything else.
    """
    if law is None:
        return ModalRatio(ratio)
    if isinstance(law, (ModalRatio, Rayleigh)):
        return law
    raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", law)


def with_damping(case: Any, law: Any) -> Any:
    """``case`` with the verb's damping law folded in (None: the case as it is).

    A :class:`ModalRatio` sets the paper's ratio D; a :class:`Rayleigh` law (SI,
    or ``Rayleigh()`` fitted to D) becomes the case's ``rayleigh``, which every
    solver reads through :attr:`twoball.Case.damping_law`.  A law that
    contradicts the case's own Rayleigh law is refused.
    """
    if law is not None and not isinstance(law, (ModalRatio, Rayleigh)):
        raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", law)
    if law is not None and case.rayleigh is not None and law != case.rayleigh:
        valid = "left out when the case has its own Rayleigh law (one damping law)"
        raise ParameterError("damping", valid, law.as_dict())
    if isinstance(law, ModalRatio) and law.ratio != case.damping:
        return case.derive(damping=law.ratio)
    if isinstance(law, Rayleigh) and law != case.rayleigh:
        return case.derive(rayleigh=law)
    return case
