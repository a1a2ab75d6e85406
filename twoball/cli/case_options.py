"""Command-line case options (SI) shared by every subcommand, turned into a :class:`Case`."""

from __future__ import annotations

import argparse

import twoball
from twoball import _lookup
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError, real_number
from twoball.cli.values import integer, number


def add_case_options(parser: argparse.ArgumentParser, window: str = "4 pi / c") -> None:
    """Add the case options (all SI) to ``parser``; ``window`` names the default ``--t-end``."""
    group = parser.add_argument_group("case (SI units; defaults: the preset)")
    group.add_argument(
        "--preset",
        default="basketball",
        help="named case: basketball (Table 2), tennis, volleyball (docs: Stiffer balls)",
    )
    group.add_argument("--radius", type=number, metavar="R", help="ball radius R [m]")
    group.add_argument("--wave-speed", type=number, metavar="C", help="angular wave speed c [1/s]")
    group.add_argument("--pressure", type=number, metavar="P", help="excess pressure P [Pa]")
    group.add_argument(
        "--mass", type=number, metavar="M", help="ball mass m [kg] (with --pressure)"
    )
    group.add_argument("--v0", type=number, metavar="V", help="impact speed |v0| [m/s]")
    group.add_argument(
        "--phi-a",
        type=number,
        metavar="A",
        help="contact angle [rad]; default: the preset's measured angle at its own R, c, "
        "|v0|, else eq. (3.7)",
    )
    group.add_argument("--damping", type=number, metavar="D", help="modal damping ratio in [0, 1)")
    group.add_argument("--modes", type=integer, metavar="N", help="Legendre modes N (default 30)")
    group.add_argument(
        "--g", type=number, default=_choices.STANDARD_GRAVITY, help=argparse.SUPPRESS
    )
    stiff = parser.add_argument_group("stiffer balls (bending and gas; default: the preset's)")
    stiff.add_argument(
        "--bending", type=number, metavar="B", help="flexural rigidity B [N m] (0: membrane)"
    )
    stiff.add_argument(
        "--youngs-modulus", type=number, metavar="E", help="wall Young's modulus E [Pa]"
    )
    stiff.add_argument("--thickness", type=number, metavar="H", help="wall thickness h [m]")
    stiff.add_argument(
        "--poisson", type=number, metavar="NU", help="Poisson's ratio (default 0.5, rubber)"
    )
    stiff.add_argument(
        "--gas", metavar="MODEL", help="enclosed gas: " + ", ".join(_choices.GAS_MODELS)
    )
    stiff.add_argument(
        "--atmosphere", type=number, metavar="PA", help="ambient pressure [Pa] (101325)"
    )
    stiff.add_argument(
        "--membrane",
        metavar="KIND",
        help="membrane operator: paper (n(n+1), default) or pressurised ((n-1)(n+2), "
        "consistent with T = P R / 2; needs --gas)",
    )
    group.add_argument(
        "--rayleigh",
        metavar="ALPHA,BETA",
        help="Rayleigh damping C = alpha M + beta K instead of the ratio D: alpha [1/s], beta [s]",
    )
    model = parser.add_argument_group("model")
    model.add_argument(
        "--sigma",
        choices=_choices.FILTER_KINDS,
        help="spectral filter (eq. (3.16)); default lanczos",
    )
    model.add_argument(
        "--recontact",
        choices=_choices.HORIZONS,
        help="re-contact horizon: the whole window (default), or dt < t_l as in §3(a)(ii)",
    )
    model.add_argument(
        "--t-end", type=number, metavar="SECONDS", help=f"modelled window [s] (default {window})"
    )
    add_limit_options(parser)


#: ``--max-time``'s default, as the help says it (the rule: :mod:`twoball._common.budget`).
TIME_DEFAULT_HELP = (
    "default: work estimated above 5min is refused, and a run stops at 10 times its "
    "estimate, at least 5min"
)


def add_limit_options(
    parser: argparse.ArgumentParser, time_default: str = TIME_DEFAULT_HELP
) -> None:
    """``--max-memory`` and ``--max-time``, the resource limits of every long verb."""
    limits = parser.add_argument_group(
        "resource limits (refused before the work starts, stopped at the deadline)"
    )
    limits.add_argument("--max-memory", metavar="SIZE", help="e.g. 8GiB (default: half the RAM)")
    limits.add_argument(
        "--max-time",
        metavar="DURATION",
        help=f"e.g. 90min, 2h or off; refusal and deadline at once ({time_default})",
    )


def case_from_options(args: argparse.Namespace) -> twoball.Case:
    """Build the case exactly as the Python API does: ``Case.preset(name, **changes)``.

    ``--pressure``/``--mass`` give c by eq. (3.8) (``Case.from_pressure``).  phi_a
    follows the rule of :class:`~twoball.Case`: ``--phi-a`` if
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
    if args.g != _choices.STANDARD_GRAVITY:
        changes["g"] = args.g
    changes.update(_stiffness_changes(args))
    if getattr(args, "rayleigh", None) is not None:
        if args.damping is not None:
            valid = "left out with --rayleigh ALPHA,BETA (the law has its own coefficients)"
            raise ParameterError("damping", valid, args.damping)
        changes["rayleigh"] = rayleigh_option(args.rayleigh)
    if args.pressure is not None:
        return twoball.Case.from_pressure(args.pressure, args.mass, preset=args.preset, **changes)
    return twoball.Case.preset(args.preset, **changes)


#: The options that describe the case (``--sigma`` etc. belong to the model).
CASE_OPTIONS = (
    "radius",
    "wave_speed",
    "pressure",
    "mass",
    "v0",
    "phi_a",
    "damping",
    "modes",
    "rayleigh",
    "membrane",
)


def case_options_given(args: argparse.Namespace) -> bool:
    """Whether any option of the case (or a preset or g other than the default) was given."""
    return first_case_option(args) is not None


def first_case_option(args: argparse.Namespace) -> tuple[str, object] | None:
    """The first option of the case given (name and value as typed), or None."""
    if args.preset != "basketball":
        return "preset", args.preset
    stiffness = ("bending", "youngs_modulus", "thickness", "poisson", "gas", "atmosphere")
    for name in (*CASE_OPTIONS, *stiffness):
        if getattr(args, name, None) is not None:
            return name, getattr(args, name)
    if args.g != _choices.STANDARD_GRAVITY:
        return "g", args.g
    return None


def rayleigh_option(text: str) -> twoball.Rayleigh:
    """``--rayleigh ALPHA,BETA`` (SI: alpha [1/s], beta [s]) as a :class:`~twoball.Rayleigh`."""
    parts = [p.strip() for p in str(text).split(",")]
    if len(parts) != 2:
        raise ParameterError("rayleigh", "two numbers ALPHA,BETA (alpha [1/s], beta [s])", text)
    alpha, beta = (number(p) for p in parts)
    return twoball.Rayleigh(alpha, beta)


def apply_limits(args: argparse.Namespace) -> None:
    """Set the resource limits of ``--max-memory`` and ``--max-time`` for this run."""
    from twoball._common.budget import Budget, set_budget

    set_budget(Budget.from_options(args.max_memory, args.max_time))


def _stiffness_changes(args: argparse.Namespace) -> dict[str, float | str]:
    """Bending (B, or E, h and nu) and gas options as :class:`Case` changes."""
    names = ("bending", "youngs_modulus", "thickness", "poisson", "atmosphere")
    for name in names:
        value = getattr(args, name, None)
        if value is not None:
            real_number(name, value, "a finite number")
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
        changes["bending"] = _lookup.flexural_rigidity(args.youngs_modulus, args.thickness, poisson)
    if args.gas is not None:
        changes["gas"] = args.gas
    if getattr(args, "membrane", None) is not None:
        changes["membrane"] = args.membrane
    if args.atmosphere is not None:
        changes["atmosphere"] = args.atmosphere
    return changes


__all__ = [
    "add_case_options",
    "add_limit_options",
    "apply_limits",
    "case_from_options",
    "case_options_given",
    "rayleigh_option",
]
