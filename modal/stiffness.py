"""Stiffer balls: bending stiffness and the enclosed gas, in closed form.

The paper's membrane (eq. (3.1), ``rho u_tt = T Delta_s u``) is extended by two
terms, both linear in the radial displacement u (§3 names both as the physics a
tennis ball needs):

Bending
    ``rho u_tt = T Delta_s u - (B / R^2) Delta_s (Delta_s + 2) u`` with the flexural
    rigidity ``B = E h^3 / (12 (1 - nu^2))`` [N m] and Delta_s the Laplace-Beltrami
    operator of the sphere of radius R.  On P_n (``Delta_s P_n = -n (n+1) P_n /
    R^2``) the bending term gives ``B n (n+1) (n (n+1) - 2) / R^4``: the factor
    ``(n - 1) n (n + 1) (n + 2)`` of the linearised bending energy of a closed
    spherical shell (Helfrich 1973, Z. Naturforsch. 28c 693; Milner & Safran 1987,
    Phys. Rev. A 36 4371), which leaves the rigid translations n = 1 free of
    bending energy.  In units ``c^2 = T / (rho R^2)``::

        omega_n^2 = n (n + 1) (1 + beta (n (n + 1) - 2)),   beta = B / (T R^2).

Gas
    An ideal gas of absolute pressure ``P_abs = P + P_atm`` filling ``V = 4 pi R^3 /
    3`` changes its pressure by ``-kappa P_abs dV / V`` (kappa = 1 isothermal, 1.4
    adiabatic), and ``dV = R^2 int u dOmega`` sees only the mean of u: only n = 0
    is stiffened.  For ``u = a_0`` the force per area is ``-3 kappa P_abs a_0 / R``,
    so ``rho omega_0^2 = 3 kappa P_abs / R`` and, dimensionless,
    ``omega_0^2 = 3 kappa P_abs R / T``; with the paper's ``T = P R / 2`` (§4(b))
    this is ``6 kappa (P + P_atm) / P`` -- the breathing mode then oscillates
    instead of keeping its initial mean displacement a_0 (eq. (3.13)) for ever.

Membrane operator
    The paper's ``T Delta_s`` or the operator consistent with the pressure,
    ``T (Delta_s + 2 / R^2)`` (:mod:`twoball.modal.membrane`).  With it the
    membrane part of ``omega_n^2`` is ``lambda - 2 = (n - 1)(n + 2)`` instead of
    ``lambda = n (n + 1)``; bending keeps its Helfrich factor and the gas adds
    to the breathing mode as before::

        omega_n^2 = (n - 1)(n + 2) (1 + beta n (n + 1)),   omega_0^2 = gas - 2,

    since ``(lambda - 2) + beta lambda (lambda - 2) = (lambda - 2)(1 + beta lambda)``.
    With ``T = P R / 2``, ``omega_0^2 = 6 kappa P_abs / P - 2``: the gas term
    above is ``3 kappa P_abs R / T`` and the membrane's ``-2 u^2 / R^2`` takes 2
    (the energy ``6 pi kappa P_abs R a_0^2 - 4 pi T a_0^2`` of u = a_0).  Without
    gas the pressurised breathing mode is unstable (omega_0^2 = -2) and refused.

Everything here is dimensionless except :func:`stiffness_from_si`.  The
classical thin-shell theory of Kraus / Baker (refs [22, 23]) couples the
radial motion to tangential displacements and to the extensional stiffness
``E h``; it has two branches and no radial-only equation, so the radial model
above (radial motion only, with the shell's bending-energy factor) is kept:
it reduces exactly to the paper's membrane for beta = 0 and no gas.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from twoball._common.choices import GAS_MODELS as GAS_LAWS
from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.membrane import Membrane
from twoball.modal.series import ModalSeries

GAS_MODELS: dict[str, float] = dict(zip(GAS_LAWS, (0.0, 1.0, 1.4), strict=True))
"""Polytropic exponent kappa of the enclosed gas (0: no gas term)."""

ATMOSPHERE = 101325.0  # Pa, standard atmosphere (ISO 2533)


@dataclass(frozen=True)
class Stiffness:
    """Dimensionless spectrum of the ball: membrane operator, bending ratio, gas stiffness.

    Parameters
    ----------
    beta : float
        ``B / (T R^2)`` >= 0.
    gas : float
        ``3 kappa P_abs R / T`` >= 0 (0: no gas): omega_0^2 of the paper's
        membrane; the pressurised one's is ``gas - 2``.
    membrane : Membrane
        The membrane operator (:mod:`twoball.modal.membrane`; default the paper's).
        ``pressurised`` needs ``gas > 2`` (its breathing mode is held by the gas only).
    """

    beta: float = 0.0
    gas: float = 0.0
    membrane: Membrane = Membrane()

    def __post_init__(self) -> None:
        for name in ("beta", "gas"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
                raise ParameterError(name, "a finite number >= 0", value)
        object.__setattr__(self, "membrane", Membrane.of(self.membrane))
        if self.membrane.pressurised and self.gas <= self.membrane.shift:
            raise ParameterError(
                "gas",
                "a gas term > 2 with the pressurised membrane (omega_0^2 = gas - 2; at "
                "constant pressure its breathing mode is unstable)",
                self.gas,
            )

    @property
    def active(self) -> bool:
        """True when anything departs from the paper's membrane."""
        return self.beta > 0.0 or self.gas > 0.0 or self.membrane.pressurised

    @property
    def breathing(self) -> float:
        """omega_0^2 of the breathing mode (n = 0): ``gas - s`` (0 for the paper's without gas)."""
        return self.gas - self.membrane.shift

    def omega_squared(self, membrane: np.ndarray) -> np.ndarray:
        """omega^2 of the modes of Laplace-Beltrami eigenvalue lambda (every mode but n = 0).

        Paper: ``lambda (1 + beta (lambda - 2))``; pressurised:
        ``(lambda - 2)(1 + beta lambda)`` (see the module documentation).
        """
        lam = np.asarray(membrane, dtype=float)
        if self.membrane.pressurised:
            return self.membrane.eigenvalues(lam) * (1.0 + self.beta * lam)
        return lam * (1.0 + self.beta * (lam - 2.0))

    def legendre_omega(self, n: np.ndarray) -> np.ndarray:
        """Angular frequencies of the Legendre modes n (omega_0^2 = gas - s), dimensionless."""
        n = np.asarray(n, dtype=float)
        if self.membrane.pressurised:  # (n - 1)(n + 2) exactly: omega_1 = 0
            squared = self.membrane.legendre(n) * (1.0 + self.beta * (n * (n + 1.0)))
        else:
            squared = self.omega_squared(n * (n + 1.0))
        squared = np.where(n == 0, self.breathing, squared)
        return np.sqrt(squared)

    def fit_band(self, modes: int) -> tuple[float, float]:
        """Frequencies a fitted Rayleigh law matches its ratio at (dimensionless).

        The lowest vibrating degree's (1 for the paper's membrane, 2 for the
        pressurised one; the breathing mode aside) and degree N's, the filter's
        cutoff; for the paper's membrane ``sqrt(2)`` and ``sqrt(N (N + 1))``.
        """
        low, high = self.legendre_omega(np.array([self.membrane.lowest_degree, modes]))
        return float(low), float(high)

    def membrane_value(self, omega_squared: np.ndarray) -> np.ndarray:
        """Inverse of :meth:`omega_squared` on lambda >= 2 (the root >= 0 of a quadratic)."""
        w2 = np.asarray(omega_squared, dtype=float)
        if self.membrane.pressurised:  # beta lambda^2 + (1 - 2 beta) lambda - (2 + w2) = 0
            b, rhs = 1.0 - 2.0 * self.beta, 2.0 + w2
            return 2.0 * rhs / (b + np.sqrt(b * b + 4.0 * self.beta * rhs))
        if self.beta == 0.0:
            return w2.copy()
        b = 1.0 - 2.0 * self.beta
        return 2.0 * w2 / (b + np.sqrt(b * b + 4.0 * self.beta * w2))

    def as_dict(self) -> dict[str, float | str]:
        """``beta``, ``omega0_squared`` (of the breathing mode) and ``membrane``."""
        return {"beta": self.beta, "omega0_squared": self.breathing, **self.membrane.as_dict()}


def stiffness_from_si(
    *,
    radius: float,
    pressure: float | None,
    bending: float = 0.0,
    gas: str = "none",
    atmosphere: float = ATMOSPHERE,
    membrane: Membrane | str = "paper",
) -> Stiffness:
    """The dimensionless :class:`Stiffness` of a ball in SI.

    Parameters
    ----------
    radius : float
        R [m].
    pressure : float or None
        Excess (gauge) pressure P [Pa]: tension ``T = P R / 2`` (§4(b)); needed
        unless bending is 0 and gas is "none".
    bending : float
        Flexural rigidity B [N m] >= 0.
    gas : {"none", "isothermal", "adiabatic"}
        Compression law of the enclosed gas (kappa 0, 1, 1.4).
    atmosphere : float
        Ambient pressure [Pa]; the gas is at ``P + atmosphere``.
    membrane : Membrane or {"paper", "pressurised"}
        The membrane operator (:mod:`twoball.modal.membrane`); ``pressurised``
        needs a gas (isothermal or adiabatic) to hold its breathing mode.

    Returns
    -------
    Stiffness
        ``beta = 2 B / (P R^3)``, ``gas = 6 kappa (P + P_atm) / P``, the membrane.
    """
    if gas not in GAS_MODELS:
        raise ParameterError("gas", "one of " + ", ".join(GAS_MODELS), gas)
    if not (math.isfinite(bending) and bending >= 0):
        raise ParameterError("bending", "a finite number >= 0 [N m]", bending)
    membrane = Membrane.of(membrane)
    if membrane.pressurised and gas == "none":
        raise ParameterError(
            "gas",
            "isothermal or adiabatic with the pressurised membrane (at constant pressure its "
            "breathing mode is unstable, omega_0^2 = -2; the gas gives 6 kappa P_abs / P - 2)",
            gas,
        )
    if bending == 0.0 and gas == "none":
        return Stiffness()
    if pressure is None:
        raise ParameterError(
            "pressure",
            "given with bending or gas: it sets the tension T = P R / 2 (Case.from_pressure, "
            "or a preset's own: Case.preset(name, bending=...))",
            None,
        )
    if not (math.isfinite(pressure) and pressure > 0):
        raise ParameterError("pressure", "a finite number > 0 [Pa]", pressure)
    if not (math.isfinite(atmosphere) and atmosphere >= 0):
        raise ParameterError("atmosphere", "a finite number >= 0 [Pa]", atmosphere)
    tension = pressure * radius / 2.0
    beta = bending / (tension * radius**2)
    kappa = GAS_MODELS[gas]
    omega0_sq = 3.0 * kappa * (pressure + atmosphere) * radius / tension
    return Stiffness(beta=beta, gas=omega0_sq, membrane=membrane)


CONSTANT_MODE = 1e-6  # membrane eigenvalue below which a mode is the constant (n = 0) one
#: Most negative omega^2 taken for a discretisation error of a zero mode (the FE n = 1
#: cluster of the pressurised membrane, ``lambda_h - 2``): clipped to 0 above, refused below.
ZERO_MODE_TOLERANCE = 0.05


def stiffen(series: ModalSeries, stiffness: Stiffness, surface_ratio: float = 1.0) -> ModalSeries:
    """A membrane modal series with its frequencies mapped to the stiffened ball's.

    Every membrane eigenvalue ``lambda = omega^2`` becomes
    :meth:`Stiffness.omega_squared` of it (``lambda (1 + beta (lambda - 2))``,
    or ``(lambda - 2)(1 + beta lambda)`` for the pressurised membrane) and the
    constant mode's (``lambda < 1e-6``, exactly one) becomes ``gas *
    surface_ratio - s``; shapes, coefficients and pole values are kept and the
    filter keeps weighing each mode by its membrane frequency ``sqrt(lambda)``.
    Exact for the Legendre modes, and for finite elements whose bending term is
    the mixed form ``K M^-1 K`` on the membrane's own space, whose pressure term
    is ``-2 M`` and whose gas term is ``(gas / 4 pi) m m^T`` with ``m = M 1``
    (:mod:`twoball.fem_membrane.shell`): the membrane eigenvectors diagonalise
    all three, and ``surface_ratio`` is the discrete area ``1^T M 1`` over 4 pi.

    The pressurised n = 1 cluster maps to ``lambda_h - 2``: zero up to the
    membrane's own eigenvalue error at l = 1 (round-off on the axisymmetric
    line, where ``P_1 = x`` lies in the space; ``O(h^2p)`` or the geometric
    error on a sphere mesh, of either sign).  Values down to
    ``-ZERO_MODE_TOLERANCE`` are that error and become 0; below, NumericalError.
    Dimensionless.
    """
    if not stiffness.active:
        return series
    membrane = series.omega if series.filter_omega is None else series.filter_omega
    squared = membrane**2
    constant = np.flatnonzero(squared < CONSTANT_MODE)
    if constant.size > 1:
        raise NumericalError(f"stiffen: {constant.size} constant modes (one expected)")
    raw = stiffness.omega_squared(squared)
    lowest = np.delete(raw, constant).min(initial=0.0)
    if lowest < -ZERO_MODE_TOLERANCE:
        raise NumericalError(
            f"stiffen: omega^2 = {lowest:.3g} < 0 beyond a discretisation error of a zero mode"
        )
    mapped = np.clip(raw, 0.0, None)
    if stiffness.beta == 0.0 and not stiffness.membrane.pressurised:
        omega = series.omega.copy()
    else:
        omega = np.sqrt(mapped)
    if constant.size and (stiffness.gas > 0.0 or stiffness.membrane.pressurised):
        omega[constant] = math.sqrt(stiffness.gas * surface_ratio - stiffness.membrane.shift)
    return replace(series, omega=omega, filter_omega=membrane)


def flexural_rigidity(youngs_modulus: float, thickness: float, poisson: float = 0.5) -> float:
    """``B = E h^3 / (12 (1 - nu^2))`` [N m] from E [Pa], h [m] and nu in [0, 1/2].

    A B above the range of :class:`~twoball.modal.parameters.Case` (1e6 N m) is
    refused here, naming ``youngs_modulus`` (what was given), not ``bending``.
    """
    from twoball._common.errors import bounded
    from twoball.modal.scalings import BENDING_RANGE

    youngs_modulus = bounded("youngs_modulus", youngs_modulus, 0.0, 1e15, "Pa", low_open=True)
    thickness = bounded("thickness", thickness, 0.0, 1.0, "m", low_open=True)
    poisson = bounded("poisson", poisson, 0.0, 0.5)
    bending = youngs_modulus * thickness**3 / (12.0 * (1.0 - poisson**2))
    if bending > BENDING_RANGE[1]:
        valid = (
            f"such that B = E h^3 / (12 (1 - nu^2)) is at most {BENDING_RANGE[1]:g} N m "
            f"(here h = {thickness:g} m, nu = {poisson:g}: B = {bending:.4g} N m)"
        )
        raise ParameterError("youngs_modulus", valid, youngs_modulus)
    return bending


def floor_contact_time(wave_speed: float) -> float:
    """Half the floor contact time of a pressurised ball [s]: ``pi / (2 c)``.

    A ball of excess pressure P pressed flat on a floor by delta carries the
    force ``P * pi * 2 R delta`` (pressure times the contact area ``pi (2 R
    delta)``), a linear spring ``k = 2 pi R P`` (Cross 1999, Am. J. Phys. 67 222,
    paper ref. [14]; Hubbard & Stronge 2001, ref. [25]).  The half period
    ``(pi / 2) sqrt(m / k)`` from maximum compression to leaving the floor, with
    ``m = 4 pi R^2 rho`` and ``T = P R / 2 = rho c^2 R^2``, is exactly
    ``pi / (2 c)``: a quarter of the dimensionless time pi.  Bending stiffness
    and gas compression only stiffen the ball, so this is an upper bound then.
    """
    return math.pi / (2.0 * wave_speed)


__all__ = [
    "ATMOSPHERE",
    "GAS_MODELS",
    "Stiffness",
    "flexural_rigidity",
    "floor_contact_time",
    "stiffen",
    "stiffness_from_si",
]
