"""How the lower ball is dropped on the floor: the option object of ``twoball.bounce`` (SI).

No numerical library is imported here.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from twoball._common.choices import GAS_MODELS as GAS_LAWS
from twoball._common.errors import ParameterError, real_number
from twoball._common.keywords import checked

__all__ = ["GAS_LAWS", "Drop"]
#: Largest drop height H [m] (as ``twoball icm`` takes, :data:`twoball.modal.icm.inputs.UPPER`).
DROP_HEIGHT_MAX = 1e6
#: Largest gap Delta x [m] between the body and the ball's top at the floor impact.
GAP_MAX = 10.0


@checked
@dataclass(frozen=True)
class Drop:
    """One drop of the lower ball on a rigid floor, validated when built (SI).

    Parameters
    ----------
    drop_height : float, optional
        Height H [m] in (0, 1e6] of the ball's lowest point above the floor at release (as
        in ``twoball icm``): the impact speed is ``|v0| = sqrt(2 g H)``, eq.
        (2.1), in place of the case's ``v0``.  ``twoball.bounce`` refuses a
        height below the case's radius R (a slower impact is given by its speed,
        the case's ``v0``).
    gas : {"none", "isothermal", "adiabatic"}, optional
        The enclosed gas (:mod:`twoball.modal.stiffness`); default the case's own,
        else ``adiabatic`` at the case's excess pressure and ambient pressure:
        the drop needs a breathing mode that springs back.
    floor_restitution : float
        Newton's coefficient e in [0, 1] at every floor point (default 0: the
        floor stops the arriving membrane; 1 keeps the mechanical energy).
    membrane : Membrane or {"paper", "pressurised"}, optional
        The membrane operator of the drop (:class:`~twoball.Membrane`); default
        ``pressurised``, the operator whose degree 1 is a free translation, as
        the drop's free centre needs (the case's own ``membrane`` field is the
        operator of the lift-off verbs).  ``paper`` takes the paper's n(n + 1)
        for degrees n != 1 (its spring on degree 1 has nothing to act on: the
        translation is the centre's).
    centre_height : float, optional
        Height x2 [m] in (0, 1e6] of the ball's centre above the floor at release (the
        paper's x2, §2), instead of ``drop_height``: the lowest point falls
        ``x2 - R`` (R the case's radius), so ``|v0| = sqrt(2 g (x2 - R))``.
        Refused with ``drop_height``, and below ``2 R`` (a fall below R).
    gap : float
        The whole bounce (with an upper body): the gap Delta x [m] in [0, 10]
        between the body's lowest point and the ball's top when the ball first
        touches the floor, both falling at ``|v0|`` (the paper's Delta x, §2;
        default 0: touching).  A drop without a body refuses a gap > 0.

    Examples
    --------
    >>> import twoball
    >>> twoball.Drop(drop_height=0.857).as_dict()["drop_height"]
    0.857
    >>> twoball.Drop(gap=0.05).gap
    0.05
    >>> twoball.Drop(centre_height=0.92).fall(0.12)  # the lowest point's fall [m]
    0.8
    >>> twoball.Drop(drop_height=-1.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    twoball.ParameterError: drop_height must be a height in (0, 1e6] [m] ... got -1.0
    """

    drop_height: float | None = None
    gas: str | None = None
    floor_restitution: float = 0.0
    membrane: Any = None
    gap: float = 0.0
    centre_height: float | None = None

    VALID = {  # noqa: RUF012 -- a class constant, not a field
        "drop_height": "a height in (0, "
        + f"{DROP_HEIGHT_MAX:g}".replace("e+0", "e")
        + "] [m] of the lowest point above the floor",
        "centre_height": "a height in (0, "
        + f"{DROP_HEIGHT_MAX:g}".replace("e+0", "e")
        + "] [m] of the centre above the floor",
        "gas": "one of " + ", ".join(GAS_LAWS),
        "floor_restitution": "in [0, 1]",
        "gap": f"a gap in [0, {GAP_MAX:g}] [m] between the body and the ball's top",
    }

    def __post_init__(self) -> None:
        if self.drop_height is not None:
            height = real_number("drop_height", self.drop_height, self.VALID["drop_height"])
            if not (0.0 < height <= DROP_HEIGHT_MAX):
                raise ParameterError("drop_height", self.VALID["drop_height"], self.drop_height)
            object.__setattr__(self, "drop_height", height)
        if self.centre_height is not None:
            valid = self.VALID["centre_height"]
            centre = real_number("centre_height", self.centre_height, valid)
            if not (0.0 < centre <= DROP_HEIGHT_MAX):
                raise ParameterError("centre_height", valid, self.centre_height)
            if self.drop_height is not None:
                valid = "left out with drop_height (one height: the centre's or the lowest point's)"
                raise ParameterError("centre_height", valid, self.centre_height)
            object.__setattr__(self, "centre_height", centre)
        if self.gas is not None and self.gas not in GAS_LAWS:
            raise ParameterError("gas", self.VALID["gas"], self.gas)
        valid = self.VALID["floor_restitution"]
        e = real_number("floor_restitution", self.floor_restitution, valid)
        if not 0.0 <= e <= 1.0:
            raise ParameterError("floor_restitution", valid, self.floor_restitution)
        object.__setattr__(self, "floor_restitution", e)
        gap = real_number("gap", self.gap, self.VALID["gap"])
        if not (math.isfinite(gap) and 0.0 <= gap <= GAP_MAX):
            raise ParameterError("gap", self.VALID["gap"], self.gap)
        object.__setattr__(self, "gap", gap)
        if self.membrane is not None:
            from twoball.modal.membrane import Membrane

            object.__setattr__(self, "membrane", Membrane.of(self.membrane))

    def fall(self, radius: float) -> float | None:
        """The lowest point's height H [m] above the floor at release (None: no height given).

        ``drop_height`` as given, or ``centre_height - radius`` (the ball's radius R [m]).
        """
        if self.centre_height is not None:
            return self.centre_height - radius
        return self.drop_height

    def as_dict(self) -> dict[str, Any]:
        """The fields as given (None: the default), for JSON and provenance."""
        out = asdict(self)
        out["membrane"] = None if self.membrane is None else self.membrane.kind
        return out
