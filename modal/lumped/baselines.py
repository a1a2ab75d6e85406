"""Every lumped model of §1(b) for one drop, as baselines beside the whole bounce (SI).

:func:`baselines` runs the four models of :data:`twoball.modal.lumped.MODELS`
for the same drop (impact speed, gap, gravity) and returns each one's
:meth:`~twoball.modal.lumped.result.LumpedResult.summary` (or the reason it
could not run) with its inputs and where they come from:

* a Table 1 pair (:func:`pair_inputs`): the pair's own constructors
  (``MODELS[name](pair)``): mu, e2, e12 of Table 1, the pressure rule's
  contact times (:mod:`twoball.modal.lumped.pair_inputs`);
* any other body (:func:`body_inputs`): the same rule with the masses, the
  ball's radius and excess pressure, the restitutions given (e2 as the caller
  measured it, e.g. the whole-bounce solver's own ball alone) and the body
  taken as a sphere of the cap radius a (``R* = a R / (a + R)``).

Nothing is fitted here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.lumped.bartz import Bartz2020
from twoball.modal.lumped.hertz import HertzViscoelastic
from twoball.modal.lumped.icm_baseline import ICMBaseline
from twoball.modal.lumped.pair_inputs import PairContacts, pair_contacts
from twoball.modal.lumped.spring_dashpot import TwoSpringDashpot
from twoball.modal.pairs import Pair

__all__ = ["BASELINE_NAMES", "BaselineInputs", "baselines", "body_inputs", "pair_inputs"]

#: The lumped models, in the order of :data:`twoball.modal.lumped.MODELS`.
BASELINE_NAMES: tuple[str, ...] = ("icm", "two-spring-dashpot", "bartz2020", "hertz-viscoelastic")


@dataclass(frozen=True)
class BaselineInputs:
    """The inputs of the lumped models for one pair of bodies (SI).

    Attributes
    ----------
    contacts : PairContacts
        Masses, restitutions, spring constants and contact times.
    pair : Pair or None
        The Table 1 pair they come from (its own constructors are used).
    """

    contacts: PairContacts
    pair: Pair | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready inputs with their source."""
        c = self.contacts
        return {
            "pair": None if self.pair is None else self.pair.name,
            "m1_kg": c.m1,
            "m2_kg": c.m2,
            "e2": c.e2,
            "e12": c.e12,
            "k2_N_m": c.k2,
            "k12_N_m": c.k12,
            "tau2_s": c.tau2,
            "tau12_s": c.tau12,
            "source": c.source,
        }


def pair_inputs(pair: Pair) -> BaselineInputs:
    """The inputs of a Table 1 pair (Table 1's mu, e2, e12; the pressure rule)."""
    return BaselineInputs(pair_contacts(pair), pair)


def body_inputs(
    m1: float,
    m2: float,
    radius: float,
    pressure: float,
    cap_radius: float,
    e2: float,
    e12: float,
    source: str,
) -> BaselineInputs:
    """The inputs of any body on a pressurised ball by the pressure rule (SI).

    Parameters
    ----------
    m1, m2 : float
        Masses [kg] of the body and the ball.
    radius, pressure : float
        The ball's radius R [m] and excess pressure P [Pa]: ``k2 = 2 pi R P``.
    cap_radius : float
        The body's contact radius a [m]: taken as a sphere of radius a,
        ``k12 = 2 pi R* P`` with ``R* = a R / (a + R)``.
    e2, e12 : float
        Restitutions of the floor and body-ball contacts.
    source : str
        Where e2 and e12 come from.
    """
    k2 = 2.0 * math.pi * radius * pressure
    r_star = cap_radius * radius / (cap_radius + radius)
    k12 = 2.0 * math.pi * r_star * pressure
    reduced = m1 * m2 / (m1 + m2)
    contacts = PairContacts(
        m1=m1,
        m2=m2,
        e2=e2,
        e12=e12,
        k2=k2,
        k12=k12,
        tau2=math.pi * math.sqrt(m2 / k2),
        tau12=math.pi * math.sqrt(reduced / k12),
        source=f"k = 2 pi R P (R = {radius:g} m, P = {pressure:g} Pa), R* = a R / (a + R) "
        f"with a = {cap_radius:.4g} m; {source}",
    )
    return BaselineInputs(contacts)


def _model(name: str, inputs: BaselineInputs) -> Any:
    if inputs.pair is not None:
        from twoball.modal.lumped import MODELS

        return MODELS[name](inputs.pair)
    c = inputs.contacts
    if name == "icm":
        return ICMBaseline(mu=c.m1 / c.m2, e2=c.e2, e12=c.e12, m2=c.m2)
    if name == "two-spring-dashpot":
        return TwoSpringDashpot(c.m1, c.m2, c.e2, c.e12, c.tau2, c.tau12, source=c.source)
    if name == "bartz2020":
        return Bartz2020.from_stiffness(c.m1, c.m2, c.k2, c.k12, c.e2, c.e12, source=c.source)
    return HertzViscoelastic(c.m1, c.m2, c.e2, c.e12, c.tau2, c.tau12, source=c.source)


def baselines(inputs: BaselineInputs, v0: float, dx: float, g: float) -> dict[str, Any]:
    """Every lumped model for the drop at ``|v0|`` [m/s] with gap ``dx`` [m] under ``g``.

    Returns
    -------
    dict
        ``{"inputs": ..., "models": {name: summary or {"error": why}}}``; a
        model that refuses its inputs (e.g. the force rule's ``e >= exp(-2)``)
        or the drop (the ICM's largest gap) says why instead of a number.

    Examples
    --------
    >>> from twoball.modal.pairs import PAIRS
    >>> out = baselines(pair_inputs(PAIRS["tennis-coin"]), 4.1, 0.0, 9.81)
    >>> round(out["models"]["icm"]["v1_ratio"], 3)
    1.516
    """
    models: dict[str, Any] = {}
    for name in BASELINE_NAMES:
        try:
            result = _model(name, inputs).run(v0=abs(v0), dx=dx, g=g)
        except (ParameterError, NumericalError, ZeroDivisionError) as error:
            text = " ".join(str(error).split()) or type(error).__name__
            models[name] = {"model": name, "error": text}
            continue
        models[name] = result.summary()
    return {"inputs": inputs.as_dict(), "models": models}
