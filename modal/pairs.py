"""The six body/ball pairs of Table 1 as presets, with the bodies' sizes and their sources.

Each :class:`Pair` names its lower ball by its preset in
:mod:`twoball.modal.presets` (mass, radius and excess pressure) and takes mu,
e2 and e12 from the paper's Table 1 (:data:`twoball.modal.icm.TABLE1`).  The
body's mass in a model is ``mu * m2`` -- the measured mass ratio times the
preset's mass -- and :attr:`Body.mass` records the published mass of such a
body beside it for comparison.

Contact radius rule (the radius ``R*`` of the body-ball contact):
a body touching the ball with a flat face (coin, nut) has ``R* = R2``, the
lower ball's radius; a ball of radius ``r1`` has ``R* = r1 R2 / (r1 + R2)``
(two spheres, Johnson, *Contact Mechanics*, 1985, §4.2).

Cap radius rule (the radius a of the cap over which the whole bounce averages
the ball's top, :attr:`Pair.cap_radius`): a flat face touches over its own
size, ``a`` = half its width (coin 10.15 mm, nut 2.5 mm); a ball over a disc of
the contact's radius of curvature, ``a = R*`` (tennis ball on the basketball
26.2 mm, 40 mm balls on the basketball 17.1 mm, on the tennis ball 12.5 mm).
A choice, stated: nothing in the paper fixes a.

Examples
--------
>>> p = PAIRS["basketball-tennis"]
>>> p.mu, p.e2, p.e12
(0.101, 0.8, 0.89)
>>> round(p.m1, 4), round(p.contact_radius, 5)
(0.0573, 0.02619)
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import ParameterError
from twoball.modal.icm.table1 import TABLE1, Table1Row
from twoball.modal.presets import MEASURED, Measured


@dataclass(frozen=True)
class Body:
    """The upper body of a pair.

    Attributes
    ----------
    name : str
        What it is.
    mass : float or None
        Published (nominal) mass [kg], None when no source gives one.
    radius : float
        Half its largest size [m] (a ball's radius).
    face_radius : float or None
        Radius of curvature of the face touching the lower ball [m]; None for a
        flat face.
    source : str
        Where the numbers come from, and which are assumed.
    """

    name: str
    mass: float | None
    radius: float
    face_radius: float | None
    source: str


_TENNIS = MEASURED["tennis"]

#: The upper bodies of Table 1.
BODIES: dict[str, Body] = {
    "coin": Body(
        name="UK one-penny coin (copper-plated steel, 1992-)",
        mass=3.56e-3,
        radius=20.3e-3 / 2.0,
        face_radius=None,
        source="Royal Mint specification of the 1p coin: 3.56 g, diameter 20.3 mm, "
        "thickness 1.65 mm (steel; 1.52 mm bronze before 1992); lies on its flat face",
    ),
    "nut": Body(
        name="hexagonal steel nut",
        mass=None,
        radius=2.5e-3,
        face_radius=None,
        source="the paper, §4: width about 5 mm, height 2 mm; no mass published "
        "(Table 1's mu gives 2.0 g, more than a 5 mm x 2 mm steel nut weighs, so "
        "'width' is probably the thread size); lies on its flat face",
    ),
    "table-tennis": Body(
        name="table tennis ball (40 mm)",
        mass=2.7e-3,
        radius=20.0e-3,
        face_radius=20.0e-3,
        source="ITTF Laws of Table Tennis 2.3 (diameter 40 mm, mass 2.7 g); the paper, "
        "§4: celluloid, international standard 40 mm",
    ),
    "tennis": Body(
        name="tennis ball",
        mass=_TENNIS.mass,
        radius=_TENNIS.radius,
        face_radius=_TENNIS.radius,
        source="the package's tennis preset (ITF Rules of Tennis, App. I: diameter "
        "6.54-6.86 cm, mass 56.0-59.4 g)",
    ),
    "tissue": Body(
        name="tissue-paper ball wrapped in cling film",
        mass=None,
        radius=20.0e-3,
        face_radius=20.0e-3,
        source="the paper, §4, gives neither mass nor size; mass from Table 1's mu; "
        "radius ASSUMED 20 mm, the table tennis ball's (Fig. 8 shows the two side by side)",
    ),
}


@dataclass(frozen=True)
class Pair:
    """One row of Table 1: a lower ball (a preset), an upper body, mu, e2, e12.

    Attributes
    ----------
    name : str
        The preset's name (``"basketball-tennis"``), as ``pair=`` takes it.
    lower : str
        The lower ball's preset in :data:`twoball.modal.presets.MEASURED`.
    body : Body
        The upper body.
    row : int
        Row of Table 1, from 1.
    """

    name: str
    lower: str
    body: Body
    row: int

    @property
    def table1(self) -> Table1Row:
        """The printed row of Table 1."""
        return TABLE1[self.row - 1]

    @property
    def mu(self) -> float:
        """Mass ratio ``m1 / m2`` (Table 1, measured by weighing)."""
        return self.table1.mu

    @property
    def e2(self) -> float:
        """Restitution of the lower ball on the floor (Table 1)."""
        return self.table1.e2

    @property
    def e12(self) -> float:
        """Restitution between the body and the lower ball (Table 1)."""
        return self.table1.e12

    @property
    def ball(self) -> Measured:
        """The lower ball's preset (R, mass, excess pressure and their sources)."""
        return MEASURED[self.lower]

    @property
    def m2(self) -> float:
        """Mass of the lower ball [kg], from its preset."""
        if self.ball.mass is None:
            raise ParameterError("lower", "a preset with a mass", self.lower)
        return self.ball.mass

    @property
    def m1(self) -> float:
        """Mass of the body in the models, ``mu * m2`` [kg]."""
        return self.mu * self.m2

    @property
    def contact_radius(self) -> float:
        """``R*`` of the body-ball contact [m] by the rule in the module docstring."""
        r2 = self.ball.radius
        r1 = self.body.face_radius
        return r2 if r1 is None else r1 * r2 / (r1 + r2)

    @property
    def cap_radius(self) -> float:
        """Radius a [m] of the contact cap of the whole bounce (module docstring).

        Examples
        --------
        >>> round(PAIRS["tennis-coin"].cap_radius * 1e3, 2)
        10.15
        >>> round(PAIRS["basketball-tennis"].cap_radius * 1e3, 1)
        26.2
        """
        if self.body.face_radius is None:
            return self.body.radius
        return self.contact_radius


def _pair(name: str, lower: str, body: str, row: int) -> Pair:
    return Pair(name=name, lower=lower, body=BODIES[body], row=row)


#: The six pairs of Table 1, by name, in the table's order.
PAIRS: dict[str, Pair] = {
    p.name: p
    for p in (
        _pair("tennis-coin", "tennis", "coin", 1),
        _pair("tennis-nut", "tennis", "nut", 2),
        _pair("tennis-table-tennis", "tennis", "table-tennis", 3),
        _pair("basketball-tennis", "basketball", "tennis", 4),
        _pair("basketball-tissue", "basketball", "tissue", 5),
        _pair("basketball-table-tennis", "basketball", "table-tennis", 6),
    )
}


def pair(name: str) -> Pair:
    """The preset ``name`` of :data:`PAIRS`, or :class:`ParameterError` naming the choices.

    Parameters
    ----------
    name : str
        For example ``"basketball-tennis"``.

    Returns
    -------
    Pair
        The preset.

    Examples
    --------
    >>> pair("tennis-coin").body.mass
    0.00356
    """
    try:
        return PAIRS[name]
    except (KeyError, TypeError):
        raise ParameterError("pair", "one of " + ", ".join(PAIRS), name) from None
