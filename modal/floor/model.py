"""From a case in SI to the dimensionless drop: impact speed, pressure, mass, spectrum, damping.

The one place where the drop reads the ball's membrane operator, its gas and
its damping law (:func:`resolve_drop`); the face (``twoball.bounce``) and the
studies (:mod:`twoball.verify.studies.floor`) both start here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from twoball.modal.damping import RAYLEIGH_LOW, ModalRatio, Rayleigh
from twoball.modal.floor.ball import BallSpectrum
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case

from twoball._common.errors import ParameterError

__all__ = ["DropModel", "resolve_drop"]


@dataclass(frozen=True)
class DropModel:
    """A drop ready for the solvers.

    Attributes
    ----------
    case : Case
        The ball at the drop's impact speed ``|v0|`` (SI).
    drop : Drop
        The options as given.
    pressure : float
        Excess pressure P [Pa] (the case's, else its preset's measured one).
    gas : str
        The gas law used.
    spectrum : BallSpectrum
        Membrane operator, bending and gas (dimensionless).
    law : ModalRatio or Rayleigh
        The damping law in units of c (a fitted Rayleigh law fitted).
    notes, warnings : tuple of str
    """

    case: Case
    drop: Drop
    pressure: float
    gas: str
    spectrum: BallSpectrum
    law: ModalRatio | Rayleigh
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def mass(self) -> float:
        """The ball's mass ``m2 = 2 pi R P / c^2`` [kg] (``T = P R / 2 = rho c^2 R^2``)."""
        return 2.0 * math.pi * self.case.radius * self.pressure / self.case.wave_speed**2

    @property
    def v0(self) -> float:
        """Impact speed ``|v0| / (R c)`` (dimensionless)."""
        return self.case.v0 / self.case.scalings.velocity

    @property
    def gamma(self) -> float:
        """``g / (R c^2)``."""
        return self.case.gamma


def resolve_drop(case: Case, drop: Drop, damping: Any = None) -> DropModel:
    """The drop of ``case`` with ``drop``'s options and the damping law ``damping``.

    Raises
    ------
    ParameterError
        A drop height whose speed the case refuses, no pressure known, the
        pressurised membrane without gas.
    """
    notes: list[str] = []
    warnings: list[str] = []
    case = _impact(case, drop)
    pressure = _pressure(case, notes)
    spectrum, gas = _spectrum(case, drop, pressure, warnings)
    return DropModel(
        case, drop, pressure, gas, spectrum, _law(case, damping), tuple(notes), tuple(warnings)
    )


def _impact(case: Case, drop: Drop) -> Case:
    """The case at the drop's impact speed ``sqrt(2 g H)``, eq. (2.1), if a height is given."""
    if drop.drop_height is None:
        return case
    speed = math.sqrt(2.0 * case.g * drop.drop_height)
    try:
        return case.derive(v0=speed)
    except ParameterError:
        raise ParameterError(
            "drop_height",
            "a height > 0 [m] whose impact speed sqrt(2 g H) the model can take",
            drop.drop_height,
        ) from None


def _pressure(case: Case, notes: list[str]) -> float:
    """Excess pressure P [Pa]: the case's, else its preset's measured one."""
    if case.pressure is not None:
        return float(case.pressure)
    from twoball.modal.presets import MEASURED

    measured = MEASURED.get(case.preset_name or "")
    if measured is None or measured.pressure is None:
        raise ParameterError(
            "pressure",
            "given for the drop (its tension T = P R / 2 sets the ball's mass 2 pi R P / c^2 "
            "and the gas): Case.from_pressure, or a preset",
            None,
        )
    mass = 2.0 * math.pi * case.radius * measured.pressure / case.wave_speed**2
    notes.append(
        f"P = {measured.pressure:g} Pa, the {case.preset_name} preset's measured excess "
        f"pressure: m2 = 2 pi R P / c^2 = {mass:.4g} kg"
    )
    return float(measured.pressure)


def _spectrum(
    case: Case, drop: Drop, pressure: float, warnings: list[str]
) -> tuple[BallSpectrum, str]:
    """The ball's spectrum (membrane operator, bending, gas) and the gas law used."""
    from twoball.modal.stiffness import stiffness_from_si

    gas = drop.gas or (case.gas if case.gas != "none" else "adiabatic")
    if drop.membrane == "pressurised" and gas == "none":
        raise ParameterError(
            "gas",
            "isothermal or adiabatic with the pressurised membrane (without gas its breathing "
            "mode has omega_0^2 = -2: unstable)",
            gas,
        )
    stiffness = stiffness_from_si(
        radius=case.radius,
        pressure=pressure,
        bending=case.bending,
        gas=gas,
        atmosphere=case.atmosphere,
    )
    if gas == "none":
        warnings.append(
            "no gas on the paper's membrane: the breathing mode has omega_0 = 0, so the "
            "floor's push shrinks the mean radius for good and the ball hardly bounces "
            "(use the gas: isothermal or adiabatic)"
        )
    return BallSpectrum(stiffness, drop.membrane), gas


def _law(case: Case, damping: Any) -> ModalRatio | Rayleigh:
    """The damping law in units of c (``Rayleigh()`` fitted to D at sqrt(2) and omega_N)."""
    if damping is None:
        return ModalRatio(case.damping)
    if isinstance(damping, Rayleigh) and damping.fitted:
        high = math.sqrt(case.modes * (case.modes + 1.0))
        return Rayleigh.fit(case.damping, RAYLEIGH_LOW, high)
    if not isinstance(damping, (ModalRatio, Rayleigh)):
        raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", damping)
    return damping
