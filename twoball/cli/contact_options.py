"""The options of an upper body of finite mass, defined once (docs: contact).

``liftoff``, ``export``, ``render`` and ``plot`` take the same group:
``--mass-ratio``, ``--contact-radius``, ``--restitution``, ``--energy``.  They
become the ``mass_ratio``, ``contact_radius`` [m], ``restitution`` and
``energy`` arguments of the API, which checks and refuses them
(:func:`twoball.modal.contact.report.check_contact_options`).
"""

from __future__ import annotations

import argparse

__all__ = ["CONTACT_NAMES", "VALID_RANGES", "add_contact_options", "contact_arguments"]

#: The API arguments of the group.
CONTACT_NAMES: tuple[str, ...] = ("mass_ratio", "contact_radius", "restitution", "energy")
#: As :mod:`twoball.modal.contact.report` (not imported here: it loads scipy, and
#: ``twoball liftoff`` on the closed form loads numpy only); the API checks the values.
MAX_MASS_RATIO = 100.0
ENERGY_OPTIONS: tuple[str, ...] = ("ball", "both")
VALID_RANGES: dict[str, str] = {
    "--mass-ratio": f"a number in [0, {MAX_MASS_RATIO:g}]",
    "--contact-radius": "a radius in (0, R) in metres",
    "--restitution": "a number in [0, 1]",
}


def add_contact_options(
    parser: argparse.ArgumentParser, mass_help: str = "m1/m2 in [0, 100] (0: massless criteria)"
) -> argparse._ArgumentGroup:
    """Add the group; returns it (``liftoff`` adds ``--plot`` to it)."""
    group = parser.add_argument_group("upper body of finite mass (docs: contact)")
    group.add_argument("--mass-ratio", type=float, metavar="MU", help=mass_help)
    group.add_argument(
        "--contact-radius", type=float, metavar="A", help="contact cap radius a [m] (default R/10)"
    )
    group.add_argument(
        "--restitution", type=float, metavar="E", help="Newton's e at re-contact (default 0)"
    )
    group.add_argument(
        "--energy",
        help="energy at t = 0: " + " or ".join(ENERGY_OPTIONS) + " (ball: eq. (3.6), default)",
    )
    return group


def contact_arguments(args: argparse.Namespace) -> dict:
    """The finite-mass options as API arguments (only those given)."""
    return {n: getattr(args, n) for n in CONTACT_NAMES if getattr(args, n, None) is not None}
