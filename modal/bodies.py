"""The upper bodies of Table 1 as elastic bodies: each value with its source.

Every body has a lumped law (:class:`~twoball.modal.upper.laws.ContactLaw`)
set from its own properties, never from Table 1's e12; the tennis ball also
has a ball body (the tennis preset's membrane, :class:`~twoball.modal.upper.options.BallBody`).
Each value says where it comes from: a cited measurement, a material table,
or "assumed: ..." where nothing better was found.  The tissue ball is the
weakest: nothing about it is measured (its radius, stiffness and restitution
are all assumed).  A body's mass in a pair is ``mu m2`` (Table 1's mu times
the lower ball's preset mass, as :mod:`twoball.modal.pairs`), so the same body
is a little heavier or lighter on the two lower balls.

=================  =========  =========================  ==================  =================
body               law        stiffness from             e on a rigid floor  ball body
=================  =========  =========================  ==================  =================
coin (1p)          hertz      steel rim, R1 0.8 mm       0.60 (assumed)      --
nut                hertz      steel edge, R1 0.5 mm      0.60 (assumed)      --
table tennis ball  reissner   celluloid shell            0.905 (ITTF rule)   -- (a shell ball)
tennis ball        pressure   2 pi R1 P1, 82.7 kPa       0.83 (Table 1 e2)   tennis membrane
tissue ball        hertz      E = 1 MPa (assumed)        0.50 (assumed)      --
=================  =========  =========================  ==================  =================

The table tennis ball's continuum body would be the shell ball (docs/shell.rst)
(tangential displacement and bending); the membrane has no in-plane stiffness
and would hold it by pressure it does not have, so no ball body is offered.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.modal.upper.laws import ContactLaw
from twoball.modal.upper.options import BODY_KINDS, BallBody, LumpedBody

__all__ = ["BODIES", "TENNIS_BALL_DAMPING", "BodyPreset", "preset_body"]

#: The tennis membrane's modal damping ratio D for the ball body: its drop alone on a
#: rigid floor at 4.1 m/s (Legendre N = 64, dt = 0.005 / c1) gives e = 0.830, Table 1's
#: e2 of the tennis ball (measured by the paper, §4(a)); the tennis preset's own D = 0.13
#: (taken from the basketball) gives 0.822.
TENNIS_BALL_DAMPING = 0.1219

_STEEL = "material table: steel E = 200 GPa, nu = 0.30"


@dataclass(frozen=True)
class BodyPreset:
    """One of Table 1's upper bodies as an elastic body.

    Attributes
    ----------
    name : str
        The body's name in :data:`twoball.modal.pairs.BODIES`.
    law : ContactLaw
        Its lumped law (SI).
    sources : dict
        Field of ``law`` -> where the value comes from.
    ball : bool
        A ball body exists (the tennis ball's membrane).
    """

    name: str
    law: ContactLaw
    sources: dict[str, str] = field(default_factory=dict)
    ball: bool = False

    @property
    def source(self) -> str:
        """The sources in one line."""
        return "; ".join(f"{k}: {v}" for k, v in self.sources.items())


#: The bodies by name (those of :data:`twoball.modal.pairs.BODIES`).
BODIES: dict[str, BodyPreset] = {
    "coin": BodyPreset(
        "coin",
        ContactLaw("hertz", 0.60, radius=0.8e-3, youngs_modulus=200e9, poisson=0.30),
        {
            "law": "Hertz on the rim (a coin dropped flat lands on its rim at the slightest "
            "tilt; on the tennis ball its own compliance is negligible against the ball's)",
            "radius": "assumed: the rim rounded to half the 1.65 mm thickness (Royal Mint 1p)",
            "youngs_modulus, poisson": _STEEL + " (copper-plated steel, 1992-)",
            "restitution": "assumed: 0.60 (no measurement of a coin on a rigid floor found)",
        },
    ),
    "nut": BodyPreset(
        "nut",
        ContactLaw("hertz", 0.60, radius=0.5e-3, youngs_modulus=200e9, poisson=0.30),
        {
            "law": "Hertz on an edge of the hexagon (a nut lands on an edge)",
            "radius": "assumed: a chamfered edge of 0.5 mm radius",
            "youngs_modulus, poisson": _STEEL,
            "restitution": "assumed: 0.60 (no measurement found)",
        },
    ),
    "table-tennis": BodyPreset(
        "table-tennis",
        ContactLaw(
            "reissner",
            math.sqrt(0.250 / 0.305),
            radius=20.0e-3,
            youngs_modulus=2.4e9,
            poisson=0.35,
            thickness=0.4e-3,
        ),
        {
            "law": "Reissner's thin-shell indentation, k = 4 E h^2 / (R sqrt(3 (1 - nu^2))); "
            "its buckling beyond a deflection of a few h (Pauchard & Rica 1998) is not "
            "modelled (at 4.1 m/s the undamped deflection is about 2.5 h)",
            "radius": "ITTF Laws of Table Tennis 2.3.1: 40 mm diameter",
            "youngs_modulus, poisson": "assumed: celluloid E = 2.4 GPa, nu = 0.35 (polymer "
            "tables give about 1.5-2.5 GPa)",
            "thickness": "assumed: 0.4 mm wall",
            "restitution": "ITTF Technical Leaflet T3 (the ball): dropped from 305 mm onto a "
            "steel block it rebounds 240-260 mm; sqrt(250/305) = 0.905 at 2.45 m/s, taken "
            "at every speed (the law's restitution does not depend on it)",
        },
    ),
    "tennis": BodyPreset(
        "tennis",
        ContactLaw("pressure", 0.83, radius=0.0335, pressure=82700.0),
        {
            "law": "pressure x area, k = 2 pi R* P (Cross 1999); the rubber wall's own "
            "stiffness is left out (it stiffens the ball: a measured tennis ball contact "
            "on a rigid floor is 4-5 ms against this law's 5.6 ms)",
            "radius, pressure": "the tennis preset: ITF Rules of Tennis App. I, 12 psi = "
            "82.7 kPa excess (twoball.modal.presets)",
            "restitution": "Table 1's e2 of the tennis ball, 0.83 (the paper, §4(a): dropped "
            "alone from 0.2-1 m)",
            "ball": f"the tennis preset's membrane on Legendre N = 64, modal damping D = "
            f"{TENNIS_BALL_DAMPING} so that its drop alone gives e = 0.830 at 4.1 m/s",
        },
        ball=True,
    ),
    "tissue": BodyPreset(
        "tissue",
        ContactLaw("hertz", 0.50, radius=20.0e-3, youngs_modulus=1.0e6, poisson=0.30),
        {
            "law": "Hertz for a soft solid ball (the weakest preset: nothing about it is measured)",
            "radius": "assumed: 20 mm, the table tennis ball's (twoball.modal.pairs)",
            "youngs_modulus, poisson": "assumed: E = 1 MPa, nu = 0.3 for crumpled tissue in "
            "cling film",
            "restitution": "assumed: 0.50",
        },
    ),
}


def _ball_body(preset: BodyPreset, lower: str) -> BallBody:
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.damping import ModalRatio
    from twoball.modal.parameters import Case

    return BallBody(
        case=Case.preset("tennis"),
        ball=LegendreBall(64),
        damping=ModalRatio(TENNIS_BALL_DAMPING),
        restitution=preset.law.restitution,
        name=f"{preset.name} ball (membrane) on the {lower}",
        source=preset.sources["ball"],
    )


@checked(name="twoball.body_preset")
def preset_body(pair: str, kind: str = "lumped", **changes: Any) -> Any:
    """The upper body of a Table 1 pair as ``kind`` (``rigid``, ``lumped`` or ``ball``).

    Parameters
    ----------
    pair : str
        A pair of :data:`twoball.modal.pairs.PAIRS` (``"basketball-tennis"``, ...).
    kind : str
        ``rigid``: :class:`twoball.Body` with Table 1's mu, e12 and cap radius
        (today's body); ``lumped``: :class:`~twoball.modal.upper.options.LumpedBody`
        with mu and the body's law; ``ball``: the body's
        :class:`~twoball.modal.upper.options.BallBody` (the tennis ball only).
    **changes
        Fields of the lumped law to change (``restitution=0.9``, ...), or of the
        body (``steps``).

    Examples
    --------
    >>> import twoball
    >>> body = twoball.body_preset("basketball-tennis", "lumped")
    >>> body.law.law, body.restitution, round(body.mass_ratio, 3)
    ('pressure', 0.83, 0.101)
    >>> try:
    ...     twoball.body_preset("basketball-tissue", "ball")
    ... except twoball.ParameterError as error:
    ...     print(error.name, "|", error.got)
    kind | ball
    """
    from twoball.modal.pairs import pair as find_pair

    chosen = find_pair(pair)
    if kind not in BODY_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(BODY_KINDS), kind)
    preset = BODIES[_body_name(chosen)]
    if kind == "rigid":
        from twoball.modal.contact.body import Body

        if changes:
            raise ParameterError("changes", "left out for the rigid body", sorted(changes))
        return Body(chosen.mu, contact_radius=chosen.cap_radius, restitution=chosen.e12)
    if kind == "ball":
        if not preset.ball:
            valid = "rigid or lumped for this body (a ball body exists for the tennis ball only)"
            raise ParameterError("kind", valid, kind)
        body = _ball_body(preset, chosen.lower)
        return replace(body, **changes) if changes else body
    steps = changes.pop("steps", None)
    law = replace(preset.law, **changes) if changes else preset.law
    extra = {} if steps is None else {"steps": steps}
    return LumpedBody(
        chosen.mu,
        law,
        name=f"{preset.name} on the {chosen.lower} (lumped, {law.law})",
        source=preset.source,
        **extra,
    )


def _body_name(chosen: Any) -> str:
    from twoball.modal.pairs import BODIES as PAIR_BODIES

    for name, body in PAIR_BODIES.items():
        if body is chosen.body:
            return name
    raise ParameterError("pair", "a pair of Table 1", chosen.name)
