"""``twoball bounce --body rigid|lumped|ball``: the upper body's kind and its own parameters.

``--body rigid`` (the default) is today's body (``--mass-ratio``,
``--contact-radius``, ``--restitution`` or ``--pair``).  ``--body lumped`` with
``--pair`` takes the pair's preset (:func:`twoball.body_preset`), whose fields
``--body-*`` change; without a pair it needs ``--mass-ratio``, ``--body-law``
and the law's fields.  ``--body ball`` takes the pair's ball body (the tennis
ball) or a ball of ``--body-preset``; ``--body-modes`` and ``--body-damping`` set
its Legendre degree and damping ratio.  ``--floor-alone`` drops the body alone on
a rigid floor (:func:`twoball.floor_alone`).  Every range is the API's; an
error names the flag typed.
"""

from __future__ import annotations

import argparse
from typing import Any

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.values import integer, number

__all__ = ["add_body_options", "elastic_body", "elastic_rows", "floor_alone_rows"]

#: ``--body-*`` flag -> the ContactLaw field it sets.
LAW_FIELDS = {
    "body_radius": "radius",
    "body_pressure": "pressure",
    "body_modulus": "youngs_modulus",
    "body_poisson": "poisson",
    "body_thickness": "thickness",
    "body_restitution": "restitution",
}
#: A law field -> the flag that sets it (for the messages).
FIELD_FLAGS = {field: "--" + dest.replace("_", "-") for dest, field in LAW_FIELDS.items()}
FIELD_FLAGS |= {"law": "--body-law", "steps": "--body-steps", "mass_ratio": "--mass-ratio"}


def add_body_options(parser: argparse.ArgumentParser) -> None:
    """The group of the body's kind (``--body``) and its own parameters."""
    group = parser.add_argument_group("the upper body's kind (docs: bodies)")
    group.add_argument(
        "--body",
        default="rigid",
        metavar="KIND",
        help="rigid (Newton's e12 on a cap; default), lumped (a point mass with its own contact "
        "law) or ball (a second modal ball: the tennis ball); with --pair, the pair's preset",
    )
    group.add_argument("--body-law", metavar="LAW", help="lumped body: pressure, reissner or hertz")
    group.add_argument("--body-radius", type=number, metavar="R1", help="its radius [m]")
    group.add_argument(
        "--body-pressure", type=number, metavar="P1", help="its excess pressure [Pa] (pressure)"
    )
    group.add_argument(
        "--body-modulus", type=number, metavar="E", help="Young's modulus [Pa] (reissner, hertz)"
    )
    group.add_argument("--body-poisson", type=number, metavar="NU", help="Poisson's ratio")
    group.add_argument(
        "--body-thickness", type=number, metavar="H", help="wall thickness [m] (reissner)"
    )
    group.add_argument(
        "--body-restitution",
        type=number,
        metavar="E",
        help="its restitution against a rigid floor (sets its dashpot; not the collision's e12)",
    )
    group.add_argument(
        "--body-steps", type=integer, metavar="N", help="steps per its contact time (default 100)"
    )
    group.add_argument(
        "--body-preset", metavar="NAME", help="ball body without --pair: its ball's preset"
    )
    group.add_argument(
        "--body-modes", type=integer, metavar="N", help="ball body: its Legendre degree (64)"
    )
    group.add_argument(
        "--body-damping", type=number, metavar="D", help="ball body: its modal damping ratio"
    )
    group.add_argument(
        "--floor-alone",
        action="store_true",
        help="drop the body alone on a rigid floor: its restitution and contact time back",
    )


def _given(args: argparse.Namespace, names: tuple[str, ...]) -> dict[str, Any]:
    return {n: getattr(args, n) for n in names if getattr(args, n, None) is not None}


def _flagged(error: ParameterError) -> ParameterError:
    """The error naming the ``--body-*`` flag that set the field (``kind``: ``--body``)."""
    flag = "--body" if error.name == "kind" else FIELD_FLAGS.get(str(error.name))
    return error if flag is None else ParameterError(flag, error.valid, error.got)


def elastic_body(args: argparse.Namespace) -> Any:
    """The elastic body of the options, None for ``--body rigid``.

    A pair's preset without changes is the kind name itself (``"lumped"``), so
    that ``twoball.bounce`` records it as the pair's.
    """
    kind = args.body
    law_options = _given(args, tuple(LAW_FIELDS) + ("body_law", "body_steps"))
    ball_options = _given(args, ("body_preset", "body_modes", "body_damping"))
    if kind == "rigid":
        extra = law_options | ball_options
        if extra:
            first = next(iter(extra))
            flag = "--" + first.replace("_", "-")
            raise ParameterError(flag, "given with --body lumped or ball", extra[first])
        return None
    if kind not in ("lumped", "ball"):
        raise ParameterError("--body", "one of rigid, lumped, ball", kind)
    for name in ("contact_radius", "restitution", "energy"):
        if getattr(args, name, None) is not None:
            valid = "left out with --body lumped or ball (the rigid body's; --body-restitution "
            raise ParameterError(name, valid + "is the body's own)", getattr(args, name))
    pair = getattr(args, "pair", None)
    if kind == "lumped":
        if ball_options:
            name = "--" + next(iter(ball_options)).replace("_", "-")
            raise ParameterError(name, "given with --body ball", next(iter(ball_options.values())))
        return _lumped(args, pair, law_options)
    if law_options:
        name = "--" + next(iter(law_options)).replace("_", "-")
        raise ParameterError(name, "given with --body lumped", next(iter(law_options.values())))
    return _ball(args, pair, ball_options)


def _lumped(args: argparse.Namespace, pair: str | None, options: dict[str, Any]) -> Any:
    fields = {LAW_FIELDS[k]: v for k, v in options.items() if k in LAW_FIELDS}
    steps = options.get("body_steps")
    try:
        if pair is not None:
            if getattr(args, "mass_ratio", None) is not None:
                valid = "left out with --pair (its mu)"
                raise ParameterError("mass_ratio", valid, args.mass_ratio)
            if "body_law" in options:
                valid = "left out with --pair (its preset's law)"
                raise ParameterError("law", valid, args.body_law)
            if not fields and steps is None:
                return "lumped"
            extra = {} if steps is None else {"steps": steps}
            return twoball.body_preset(pair, "lumped", **fields, **extra)
        if getattr(args, "mass_ratio", None) is None:
            raise ParameterError("mass_ratio", "given for --body lumped without --pair", None)
        if "body_law" not in options:
            raise ParameterError("law", "given for --body lumped without --pair", None)
        restitution = fields.pop("restitution", None)
        if restitution is None:
            raise ParameterError("restitution", "given for a lumped body (on a rigid floor)", None)
        law = twoball.ContactLaw(options["body_law"], restitution, **fields)
        extra = {} if steps is None else {"steps": steps}
        return twoball.LumpedBody(args.mass_ratio, law, **extra)
    except ParameterError as error:
        raise _flagged(error) from None


def _ball(args: argparse.Namespace, pair: str | None, options: dict[str, Any]) -> Any:
    if getattr(args, "mass_ratio", None) is not None:
        valid = "left out with --body ball (its mass is its ball's)"
        raise ParameterError("mass_ratio", valid, args.mass_ratio)
    changes: dict[str, Any] = {}
    if "body_modes" in options:
        try:
            changes["ball"] = twoball.LegendreBall(options["body_modes"])
        except ParameterError as error:
            raise ParameterError("--body-modes", error.valid, error.got) from None
    if "body_damping" in options:
        try:
            changes["damping"] = twoball.ModalRatio(options["body_damping"])
        except ParameterError as error:
            raise ParameterError("--body-damping", error.valid, error.got) from None
    if pair is not None:
        if "body_preset" in options:
            raise ParameterError("--body-preset", "left out with --pair", args.body_preset)
        try:
            body = twoball.body_preset(pair, "ball")  # refused here for a body with none
        except ParameterError as error:
            raise _flagged(error) from None
        if not changes:
            return "ball"
        from dataclasses import replace

        return replace(body, restitution=None, **changes)
    try:
        case = twoball.Case.preset(options.get("body_preset", "tennis"))
    except ParameterError as error:
        raise ParameterError("--body-preset", error.valid, error.got) from None
    return twoball.BallBody(case=case, **changes)


def floor_alone_rows(result: Any) -> list[tuple[str, str]]:
    """The human-readable rows of ``--floor-alone`` (SI)."""
    from twoball.cli.console import number as fixed

    rows = [
        ("body", result.kind),
        ("mass [g]", f"{result.mass * 1e3:.4g}"),
        ("|v0| [m/s]", f"{result.speed:g}"),
        ("restitution", fixed(result.restitution)),
        ("  stated", fixed(result.stated_restitution)),
        ("contact time [ms]", fixed(result.contact_time, 1e3)),
        ("  its law's (damped)", fixed(result.stated_contact_time, 1e3)),
        ("  undamped closed form", fixed(result.undamped_contact_time, 1e3)),
        ("peak force [N]", fixed(result.peak_force)),
        ("peak compression [mm]", fixed(result.peak_compression, 1e3)),
        ("energy dissipated [J]", f"{result.energy['dissipated']:.4g}"),
        ("books' largest error [J]", f"{result.energy['balance']:.2g}"),
    ]
    return rows


def elastic_rows(data: dict[str, Any]) -> list[tuple[str, str]]:
    """The rows of an elastic body in the whole bounce's table (from its JSON, SI)."""
    from twoball.cli.console import number as fixed

    body, contact = data["body"], data["body_contact"]
    stated = body["body_restitution"]
    return [
        (
            "body: kind, mu, mass [g]",
            f"{body['kind']}, {body['mass_ratio']:.4g}, {body['mass_kg'] * 1e3:.4g}",
        ),
        ("  its restitution on a rigid floor", "-" if stated is None else f"{stated:g}"),
        ("  gap [mm]", f"{body['gap_m'] * 1e3:g}"),
        ("  contact: duration [ms]", fixed(contact["duration_s"], 1e3)),
        ("  contact: peak force [N]", fixed(contact["peak_force_N"])),
        ("  contact disc, largest radius [mm]", fixed(contact["disc_max_radius_m"], 1e3)),
        ("  its internal energy at the end [J]", f"{data['energy_J']['final_body_internal']:.4g}"),
        ("  its own dissipation [J]", f"{data['energy_J']['body_dissipated']:.4g}"),
    ]
