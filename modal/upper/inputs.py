"""An elastic upper body checked against the whole bounce (SI), before any work.

:func:`resolve_elastic` is what :func:`twoball.modal.floor.inputs.resolve_body`
hands a :class:`~twoball.modal.upper.options.LumpedBody` or a
:class:`~twoball.modal.upper.options.BallBody` to; :func:`pair_body` is the
pair's preset body of a kind (``pair=..., body="lumped"``).
"""

from __future__ import annotations

import math
from typing import Any

from twoball._common.errors import ParameterError
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case
from twoball.modal.upper.options import BODY_KINDS, BallBody, LumpedBody

__all__ = ["pair_body", "resolve_elastic"]


def pair_body(pair: str, kind: str) -> Any:
    """The preset body of ``pair`` as ``kind`` (:func:`twoball.modal.bodies.preset_body`)."""
    if kind not in BODY_KINDS:
        raise ParameterError("body", "a body object or one of " + ", ".join(BODY_KINDS), kind)
    from twoball.modal.bodies import preset_body

    return preset_body(pair, kind)


def resolve_elastic(case: Case, body: Any, pair: Any, drop: Drop) -> tuple[str, ...]:
    """Check an elastic body against the case's ball; the notes of how it was read.

    :func:`~twoball.modal.floor.inputs.resolve_body` makes the
    :class:`~twoball.modal.floor.inputs.WholeBody` (a lumped body's contact disc
    and a ball body's rows replace the rigid body's cap: its ``contact_radius``
    and ``cap_angle`` are NaN; the disc is an output, ``disc_max``).  A ball
    body's rows must stay within the lower ball (``rho sin(reach) < 1``: they are
    paired by horizontal radius).

    Raises
    ------
    ParameterError
        Another kind of object, or a ball body whose rows reach beyond the lower ball.
    """
    if not isinstance(body, (LumpedBody, BallBody)):
        raise ParameterError("body", "a twoball.Body, LumpedBody or BallBody", type(body).__name__)
    notes = []
    if isinstance(body, LumpedBody):
        law = body.law
        notes.append(
            f"lumped body ({law.law} law): mu = {body.mass_ratio:g}, its restitution on a rigid "
            f"floor e = {law.restitution:g} (its own, not the collision's e12); the contact "
            f"disc grows as a^2 = {law.disc_factor:g} R* delta, R* = "
            f"{law.effective_radius(case.radius) * 1e3:.4g} mm"
        )
    else:
        rho = body.case.radius / case.radius
        if rho * math.sin(body.reach) >= 1.0:
            valid = f"a reach with rho sin(reach) < 1 (rho = R1 / R = {rho:.3g})"
            raise ParameterError("reach", valid, body.reach)
        notes.append(
            f"ball body: {body.ball.label} of the {body.case.preset_name or 'given'} ball "
            f"(R1 = {body.case.radius:g} m), its points within {body.reach:g} rad of its "
            "south pole against the lower ball's top (Newton's e = 0 there)"
        )
    if pair is not None:
        notes.append(f"pair {pair.name} (Table 1 row {pair.row}): the body's preset, not e12")
    return tuple(notes)
