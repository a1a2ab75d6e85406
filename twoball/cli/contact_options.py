"""The options of an upper body of finite mass, defined once (docs: contact).

``liftoff``, ``export``, ``render`` and ``plot`` take the same group:
``--mass-ratio``, ``--contact-radius``, ``--restitution``, ``--energy``.  They
become one :class:`~twoball.Body`, which checks and refuses them.
"""

from __future__ import annotations

import argparse

import twoball
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError
from twoball.cli.values import number

__all__ = ["add_contact_options", "body_options"]

#: The API fields of the group, in the order of :class:`~twoball.Body`.
CONTACT_NAMES: tuple[str, ...] = ("mass_ratio", "contact_radius", "restitution", "energy")


def add_contact_options(
    parser: argparse.ArgumentParser, mass_help: str = "m1/m2 in [0, 100] (0: massless criteria)"
) -> argparse._ArgumentGroup:
    """Add the group; returns it (``liftoff`` adds ``--plot`` to it)."""
    group = parser.add_argument_group("upper body of finite mass (docs: contact)")
    group.add_argument("--mass-ratio", type=number, metavar="MU", help=mass_help)
    group.add_argument(
        "--contact-radius", type=number, metavar="A", help="contact cap radius a [m] (default R/10)"
    )
    group.add_argument(
        "--restitution", type=number, metavar="E", help="Newton's e at re-contact (default 0)"
    )
    group.add_argument(
        "--energy",
        help="energy at t = 0: "
        + " or ".join(_choices.ENERGY_OPTIONS)
        + " (ball: eq. (3.6), default)",
    )
    return group


def body_options(args: argparse.Namespace) -> twoball.Body | None:
    """The finite-mass options as one :class:`~twoball.Body` (None without ``--mass-ratio``)."""
    given = {n: getattr(args, n) for n in CONTACT_NAMES if getattr(args, n, None) is not None}
    if not given:
        return None
    if "mass_ratio" not in given:
        name = next(iter(given))
        raise ParameterError(name, "given only with mass_ratio", given[name])
    return twoball.Body(**given)
