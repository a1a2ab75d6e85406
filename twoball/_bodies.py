"""``twoball.floor_alone``: an elastic upper body dropped alone on a rigid floor, in SI.

The check of a body's inputs before it rides the whole bounce
(``twoball bounce --body lumped|ball --pair NAME --floor-alone``): its own
restitution and contact time come back from the same integrator.  The model
is :mod:`twoball.modal.upper.alone`; docs/bodies.rst explains it.
"""

from __future__ import annotations

from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked

__all__ = ["floor_alone"]


@checked
def floor_alone(
    body: Any = None,
    *,
    pair: str | None = None,
    kind: str = "lumped",
    v0: float | None = None,
    case: Any = None,
    mass: float | None = None,
    dt: float | None = None,
) -> Any:
    """Drop an elastic body alone on a rigid floor and measure its bounce (SI).

    Parameters
    ----------
    body : LumpedBody or BallBody, optional
        The body (or give ``pair`` and ``kind``).
    pair : str, optional
        A Table 1 pair: its preset body of ``kind`` (:func:`twoball.body_preset`),
        of mass ``mu m2``.
    kind : {"lumped", "ball"}
        With ``pair``.
    v0 : float, optional
        Impact speed [m/s] (default the case's |v0|: 4.1, the paper's drops from
        0.92 m).
    case : Case, optional
        The lower ball the body rides (default the pair's, else the basketball):
        a lumped body's mass is ``mu m2`` with its m2 (``2 pi R P / c^2``).
    mass : float, optional
        A lumped body's mass [kg] instead.
    dt : float, optional
        A ball body's time step [s] (default 0.005 / c of its ball).

    Returns
    -------
    AloneResult
        ``restitution`` and ``contact_time`` measured beside the body's stated
        ``stated_restitution`` and its law's ``stated_contact_time``, the peak
        force and compression, the energy books; ``as_dict()`` for JSON.

    Examples
    --------
    >>> import twoball
    >>> alone = twoball.floor_alone(pair="basketball-tennis")
    >>> round(alone.restitution, 3), round(alone.contact_time * 1e3, 1)
    (0.83, 5.5)
    """
    from twoball.modal.parameters import Case
    from twoball.modal.upper.alone import ball_alone, lumped_alone
    from twoball.modal.upper.options import BallBody, LumpedBody

    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case (the lower ball)", type(case).__name__)
    chosen = None
    if pair is not None:
        from twoball.modal.bodies import preset_body
        from twoball.modal.pairs import pair as find_pair

        if body is not None:
            raise ParameterError("body", "left out with pair (the pair's preset)", body)
        if kind not in ("lumped", "ball"):
            raise ParameterError("kind", "lumped or ball (a rigid body has no contact law)", kind)
        chosen = find_pair(pair)
        body = preset_body(pair, kind)
        if case is None:
            case = Case.preset(chosen.lower)
    case = Case.preset("basketball") if case is None else case
    speed = case.v0 if v0 is None else v0
    if isinstance(body, LumpedBody):
        if mass is None:
            from twoball.modal.floor.inputs import resolve_drop
            from twoball.modal.floor.options import Drop

            mass = body.mass_ratio * resolve_drop(case, Drop()).mass
        result = lumped_alone(body, mass, speed)
    elif isinstance(body, BallBody):
        if mass is not None:
            raise ParameterError("mass", "left out for a ball body (its ball's own)", mass)
        result = ball_alone(body, speed, dt, target=body.restitution)[0]
    else:
        raise ParameterError("body", "a twoball.LumpedBody or BallBody, or a pair", body)
    from dataclasses import replace

    from twoball._common.provenance import block

    arguments = {"body": body.as_dict(), "pair": pair, "kind": kind, "v0": speed, "dt": dt}
    return replace(result, provenance=block(case, "twoball.floor_alone", arguments))
