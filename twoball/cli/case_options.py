"""Command-line case options (SI) shared by every subcommand, turned into a :class:`Case`."""

from __future__ import annotations

import argparse
import math

from twoball._common.errors import ParameterError
from twoball.modal.filters import FILTER_KINDS
from twoball.modal.liftoff import HORIZONS
from twoball.modal.parameters import STANDARD_GRAVITY, Case
from twoball.modal.stiffness import GAS_MODELS, flexural_rigidity

VALID_RANGES: dict[str, str] = {
    "--radius": "a number in [1e-06, 1e+06] [m]",
    "--wave-speed": "a number in [1e-06, 1e+09] [1/s]",
    "--pressure": "a number in [1e-06, 1e+12] [Pa]",
    "--mass": "a number in [1e-12, 1e+12] [kg]",
    "--v0": "a nonzero speed with |v0| <= 1e+06 [m/s]",
    "--phi-a": "a number in (pi/2, pi - 1e-6] [rad]",
    "--damping": "a number in [0, 1)",
    "--modes": "an integer in [1, 1000000]",
    "--t-end": "a number > 0 [s]",
    "--bending": "a number in [0, 1e+06] [N m]",
    "--youngs-modulus": "a number in (0, 1e+15] [Pa]",
    "--thickness": "a number in (0, 1] [m]",
    "--poisson": "a number in [0, 0.5]",
    "--atmosphere": "a number in [0, 1e+12] [Pa]",
    "--max-memory": "a size > 0 such as 12GiB, 500MB or 2e9 (bytes)",
    "--max-time": "a duration > 0 such as 3600, 90min or 2h",
}


def add_case_options(parser: argparse.ArgumentParser) -> None:
    """Add the case options (all SI) to ``parser``."""
    group = parser.add_argument_group("case (SI units; defaults: the preset)")
    group.add_argument(
        "--preset",
        default="basketball",
        help="named case: basketball (Table 2), tennis, volleyball (docs: Stiffer balls)",
    )
    group.add_argument("--radius", type=float, metavar="R", help="ball radius R [m]")
    group.add_argument("--wave-speed", type=float, metavar="C", help="angular wave speed c [1/s]")
    group.add_argument("--pressure", type=float, metavar="P", help="excess pressure P [Pa]")
    group.add_argument("--mass", type=float, metavar="M", help="ball mass m [kg] (with --pressure)")
    group.add_argument("--v0", type=float, metavar="V", help="impact speed |v0| [m/s]")
    group.add_argument(
        "--phi-a",
        type=float,
        metavar="A",
        help="contact angle [rad]; default: the preset's measured angle at its own R, c, "
        "|v0|, else eq. (3.7)",
    )
    group.add_argument("--damping", type=float, metavar="D", help="modal damping ratio in [0, 1)")
    group.add_argument("--modes", type=int, metavar="N", help="Legendre modes N (default 30)")
    group.add_argument("--g", type=float, default=STANDARD_GRAVITY, help=argparse.SUPPRESS)
    stiff = parser.add_argument_group("stiffer balls (bending and gas; default: the preset's)")
    stiff.add_argument(
        "--bending", type=float, metavar="B", help="flexural rigidity B [N m] (0: membrane)"
    )
    stiff.add_argument(
        "--youngs-modulus", type=float, metavar="E", help="wall Young's modulus E [Pa]"
    )
    stiff.add_argument("--thickness", type=float, metavar="H", help="wall thickness h [m]")
    stiff.add_argument(
        "--poisson", type=float, metavar="NU", help="Poisson's ratio (default 0.5, rubber)"
    )
    stiff.add_argument("--gas", metavar="MODEL", help="enclosed gas: " + ", ".join(GAS_MODELS))
    stiff.add_argument(
        "--atmosphere", type=float, metavar="PA", help="ambient pressure [Pa] (101325)"
    )
    model = parser.add_argument_group("model")
    model.add_argument(
        "--sigma", choices=FILTER_KINDS, default="lanczos", help="spectral filter (eq. (3.16))"
    )
    model.add_argument(
        "--recontact",
        choices=HORIZONS,
        default="window",
        help="re-contact horizon: the whole window, or dt < t_l as in §3(a)(ii)",
    )
    model.add_argument(
        "--t-end", type=float, metavar="SECONDS", help="modelled window [s] (default 4 pi / c)"
    )
    limits = parser.add_argument_group("resource limits (refused before the work starts)")
    limits.add_argument("--max-memory", metavar="SIZE", help="e.g. 8GiB (default: half the RAM)")
    limits.add_argument("--max-time", metavar="DURATION", help="e.g. 90min (default: 5min)")


def case_from_options(args: argparse.Namespace) -> Case:
    """Build the case exactly as the Python API does: ``Case.preset(name, **changes)``.

    ``--pressure``/``--mass`` give c by eq. (3.8) (``Case.from_pressure``).  phi_a
    follows the rule of :class:`~twoball.modal.parameters.Case`: ``--phi-a`` if
    given, else the preset's measured angle at its own R, c, |v0|, else eq. (3.7).
    """
    apply_limits(args)
    if (args.pressure is None) != (args.mass is None):
        raise ParameterError("--pressure/--mass", "given together")
    if args.pressure is not None and args.wave_speed is not None:
        raise ParameterError("wave_speed", "given alone, not with --pressure and --mass")
    changes: dict[str, float] = {}
    for name in ("radius", "wave_speed", "v0", "phi_a", "damping", "modes"):
        value = getattr(args, name)
        if value is not None:
            changes[name] = value
    if args.g != STANDARD_GRAVITY:
        changes["g"] = args.g
    changes.update(_stiffness_changes(args))
    if args.pressure is not None:
        return Case.from_pressure(args.pressure, args.mass, preset=args.preset, **changes)
    return Case.preset(args.preset, **changes)


#: The options that describe the case (``--sigma`` etc. belong to the model).
CASE_OPTIONS = ("radius", "wave_speed", "pressure", "mass", "v0", "phi_a", "damping", "modes")


def case_options_given(args: argparse.Namespace) -> bool:
    """Whether any option of the case (or a preset or g other than the default) was given."""
    return (
        any(getattr(args, name) is not None for name in CASE_OPTIONS)
        or args.preset != "basketball"
        or args.g != STANDARD_GRAVITY
    )


def apply_limits(args: argparse.Namespace) -> None:
    """Set the resource limits of ``--max-memory`` and ``--max-time`` for this run."""
    from twoball._common.budget import Budget, set_budget

    set_budget(Budget.from_options(args.max_memory, args.max_time))


def _stiffness_changes(args: argparse.Namespace) -> dict[str, float | str]:
    """Bending (B, or E, h and nu) and gas options as :class:`Case` changes."""
    names = ("bending", "youngs_modulus", "thickness", "poisson", "atmosphere")
    for name in names:
        value = getattr(args, name, None)
        if value is not None and not math.isfinite(value):
            raise ParameterError(name, "a finite number", value)
    changes: dict[str, float | str] = {}
    material = (args.youngs_modulus, args.thickness)
    if args.bending is not None and any(v is not None for v in material):
        raise ParameterError("bending", "given alone, not with --youngs-modulus/--thickness")
    if (args.youngs_modulus is None) != (args.thickness is None):
        raise ParameterError("--youngs-modulus/--thickness", "given together")
    if args.poisson is not None and args.youngs_modulus is None:
        raise ParameterError("poisson", "given with --youngs-modulus and --thickness")
    if args.bending is not None:
        changes["bending"] = args.bending
    elif args.youngs_modulus is not None:
        poisson = 0.5 if args.poisson is None else args.poisson
        changes["bending"] = flexural_rigidity(args.youngs_modulus, args.thickness, poisson)
    if args.gas is not None:
        changes["gas"] = args.gas
    if args.atmosphere is not None:
        changes["atmosphere"] = args.atmosphere
    return changes


__all__ = [
    "VALID_RANGES",
    "add_case_options",
    "apply_limits",
    "case_from_options",
    "case_options_given",
]
