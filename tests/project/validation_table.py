"""The table of invalid command lines, generated from the parser.

Every numeric option of every subcommand (read from
:func:`twoball.cli.main.full_parser`, so an option added later is in the
table too) gets each value of :data:`BAD_NUMBERS` that lies outside its valid
range (:data:`RANGES`, which must name every numeric option), every path option
gets an empty, an over-long and three unwritable paths, and
:data:`NOT_APPLICABLE` lists options that do not apply to the chosen
subcommand, backend, mesh, study or file kind.  Each case is run in one child
interpreter (:data:`CHILD`) in its own empty folder.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass

PI_MINUS = repr(math.pi - 1e-9)  # 3.141592652589793: 1 + cos rounds to 0 in double
BAD_NUMBERS: tuple[str, ...] = (
    "-1",
    "0",
    "nan",
    "inf",
    "-inf",
    "1e-308",
    "1e308",
    PI_MINUS,
    "",
    "abc",
)
LONG_NAME = "a" * 300  # one component longer than NAME_MAX (255)
LONG_PATH = "/".join(["d" * 200] * 25)  # longer than PATH_MAX (4096)


@dataclass(frozen=True)
class Range:
    """The valid values of a numeric option: ``low <= x <= high`` (ends open if told)."""

    low: float = -math.inf
    high: float = math.inf
    low_open: bool = False
    high_open: bool = False
    integer: bool = False

    def accepts(self, text: str) -> bool:
        """Whether ``text`` is a valid value."""
        try:
            value = int(text) if self.integer else float(text)
        except ValueError:
            return False
        if not math.isfinite(value):
            return False
        above = value > self.low if self.low_open else value >= self.low
        below = value < self.high if self.high_open else value <= self.high
        return above and below


PHI_A_HIGH = math.pi - 1e-6  # eq. (3.7) keeps double precision up to here
#: Valid range of every numeric option (SI).  A new numeric option must be added here.
RANGES: dict[str, Range] = {
    "--radius": Range(1e-6, 1e6),
    "--wave-speed": Range(1e-6, 1e9),
    "--pressure": Range(1e-6, 1e12),
    "--mass": Range(1e-12, 1e12),
    "--v0": Range(-1e6, 1e6),  # |v0| > 0 and eq. (3.7) solvable: checked below
    "--phi-a": Range(math.pi / 2, PHI_A_HIGH, low_open=True),
    "--damping": Range(0.0, 1.0, high_open=True),
    "--modes": Range(1, 2000, integer=True),
    "--g": Range(1e-6, 1e6),
    "--t-end": Range(0.0, 10.0, low_open=True),
    "--level": Range(0, 6, integer=True),
    "--elements": Range(2, 10**5, integer=True),
    "--order": Range(1, 4, integer=True),
    "--dt": Range(1e-7, 1e-2),
    "--count": Range(1, 2000, integer=True),
    "--workers": Range(1, 64, integer=True),
    "--mu": Range(0.0, 1e6),
    "--e2": Range(0.0, 1.0),
    "--e12": Range(0.0, 1.0),
    "--dx": Range(0.0, 1e6),
    "--drop-height": Range(0.0, 1e6, low_open=True),
    "--centre-height": Range(0.0, 1e6, low_open=True),
    "--frames": Range(1, 2000, integer=True),
    "--time": Range(0.0, 4 * math.pi / 320),  # render: inside the default window
    "--fps": Range(1e-3, 1e3),
    "--warp": Range(0.0),  # or auto
    "--instants": Range(2, 2000, integer=True),
    "--max-degree": Range(1, 10**4, integer=True),
    "--dpi": Range(50, 1200),
    "--mass-ratio": Range(0.0, 100.0),
    "--contact-radius": Range(0.0, 0.12, low_open=True, high_open=True),  # (0, R) m
    "--restitution": Range(0.0, 1.0),
    "--bending": Range(0.0, 1e6),
    "--youngs-modulus": Range(0.0, 1e15, low_open=True),
    "--thickness": Range(0.0, 1.0, low_open=True),
    "--poisson": Range(0.0, 0.5),
    "--atmosphere": Range(0.0, 1e12),
    "--floor-restitution": Range(0.0, 1.0),
    "--gap": Range(0.0, 10.0),
    "--density": Range(0.0, 1e5, low_open=True),
    "--radial-orders": Range(1, 40, integer=True),
    "--pole-levels": Range(0, 8, integer=True),
    "--top-levels": Range(0, 8, integer=True),
    "--wall-cells": Range(1, 16, integer=True),
    # the shell's wall and spectrum (--ball shell): C / N0, h / R, p = N0 / C (its breathing
    # mode stable: 2 (1 + nu) - 2 p > 0 at the default nu = 0.5, no gas)
    "--wall-stiffness-ratio": Range(0.0, 1e6, low_open=True),
    # the elastic upper body (--body lumped|ball)
    "--body-radius": Range(0.0, 10.0, low_open=True),
    "--body-pressure": Range(0.0, 1e8, low_open=True),
    "--body-modulus": Range(0.0, 1e13, low_open=True),
    "--body-poisson": Range(-0.99, 0.5),
    "--body-thickness": Range(0.0, 0.02, low_open=True),  # at most its radius, 0.02 m here
    "--body-restitution": Range(0.0, 1.0, low_open=True),
    "--body-steps": Range(8, 10_000, integer=True),
    "--body-modes": Range(8, 2000, integer=True),
    "--body-damping": Range(0.0, 1.0, high_open=True),
    "--thickness-ratio": Range(0.0, 0.5),
    "--prestress-ratio": Range(0.0, 1.5, high_open=True),
    "--bootstrap": Range(0, 10_000, integer=True),
}
#: Values that a range accepts but the model refuses anyway, per option.
ALSO_BAD: dict[str, tuple[str, ...]] = {
    "--v0": ("0", "1e-308"),  # no contact angle solves eq. (3.7) / v0 must be nonzero
    "--t-end": ("1e-308",),  # a window shorter than one sample of the series
    "--modes": (),
    "--radius": (),
}

#: A valid lumped body of each law (the context of its flags' bad values).
LUMPED_LAWS: dict[str, tuple[str, ...]] = {
    "pressure": ("--body-radius", "--body-pressure"),
    "reissner": ("--body-radius", "--body-modulus", "--body-poisson", "--body-thickness"),
}
_LUMPED_VALUES = {
    "--body-radius": "0.02",
    "--body-pressure": "1e5",
    "--body-modulus": "2e9",
    "--body-poisson": "0.35",
    "--body-thickness": "0.0004",
    "--body-restitution": "0.9",
}


def _lumped_body(flag: str, law: str) -> list[str]:
    """A lumped body of ``law`` on the basketball, every option but ``flag`` given."""
    given = [*LUMPED_LAWS[law], "--body-restitution"]
    values = [v for other in given if other != flag for v in (other, _LUMPED_VALUES[other])]
    return ["--mass-ratio", "0.05", "--body", "lumped", "--body-law", law, *values]


#: A valid, cheap command line of each subcommand; ``{tmp}`` is the case's folder.
BASE: dict[str, list[str]] = {
    "liftoff": ["liftoff", "--json"],
    "bounce": ["bounce", "--modes", "16", "--json"],
    "eigen": ["eigen", "--json"],
    "sweep": ["sweep", "--param", "damping", "--values", "0:0.5:3", "--json"],
    "icm": ["icm", "--mu", "0.5", "--e2", "0.8", "--e12", "0.9", "--json"],
    "converge": ["converge", "modes", "--modes-list", "30,60,120", "--out", "{tmp}/c"],
    "verify": ["verify", "--fast", "--json", "--out", "{tmp}/r"],
    "export": ["export", "--level", "1", "--out", "{tmp}/x.vtu"],
    "render": ["render", "--level", "1", "--out", "{tmp}/x.png"],
    "plot": ["plot", "pole", "--level", "1", "--out", "{tmp}/p.png"],
    "reproduce": ["reproduce", "--only", "table1", "--out", "{tmp}/rep"],
    # an empty data file: every option is refused before the file is read
    "fit": ["fit", "--data", "{tmp}/a-file", "--param", "damping", "--json"],
}
#: Options that need a context to apply (the value is then checked for itself).
CONTEXT: dict[tuple[str, str], list[str]] = {
    ("liftoff", "--level"): ["--backend", "fem"],
    ("liftoff", "--order"): ["--backend", "fem"],
    ("liftoff", "--elements"): ["--backend", "fem", "--mesh", "axisym"],
    ("liftoff", "--dt"): ["--backend", "fem", "--scheme", "alpha"],
    ("eigen", "--elements"): ["--mesh", "axisym"],
    ("converge", "--order"): ["h"],
    ("render", "--frames"): ["--out", "{tmp}/x.gif"],
    ("render", "--fps"): ["--out", "{tmp}/x.gif"],
    ("plot", "--instants"): ["waterfall"],
    ("plot", "--max-degree"): ["eigen"],
    ("icm", "--dx"): ["--drop-height", "1"],
    ("sweep", "--workers"): ["--values", "0:0.5:3"],
    ("liftoff", "--contact-radius"): ["--mass-ratio", "0.01"],
    ("liftoff", "--restitution"): ["--mass-ratio", "0.01"],
    **{
        (command, flag): ["--mass-ratio", "0.01"]
        for command in ("export", "render", "plot")
        for flag in ("--contact-radius", "--restitution")
    },
    ("liftoff", "--bending"): ["--preset", "tennis"],
    ("liftoff", "--youngs-modulus"): ["--preset", "tennis", "--thickness", "0.003"],
    ("liftoff", "--thickness"): ["--preset", "tennis", "--youngs-modulus", "6e6"],
    ("liftoff", "--poisson"): [
        "--preset",
        "tennis",
        "--youngs-modulus",
        "6e6",
        "--thickness",
        "0.003",
    ],
    ("liftoff", "--atmosphere"): ["--preset", "tennis"],
    ("bounce", "--elements"): ["--backend", "fem"],
    ("bounce", "--order"): ["--backend", "fem"],
    ("bounce", "--modes"): [],
    **{
        ("bounce", flag): ["--mass-ratio", "0.05"]
        for flag in ("--gap", "--contact-radius", "--restitution")
    },
    ("bounce", "--frames"): ["--render", "{tmp}/x.gif"],
    ("sweep", "--gap"): ["--bounce", "--mass-ratio", "0.05"],  # refused before the --param
    **{  # the solid ball's and the thick wall's own flags
        (command, flag): context
        for command in ("bounce", "liftoff")
        for flag, context in (
            ("--density", ["--ball", "solid", "--youngs-modulus", "8e6", "--poisson", "0.45"]),
            ("--radial-orders", ["--ball", "solid"]),
            ("--pole-levels", ["--ball", "solid", "--backend", "fem"]),
            ("--top-levels", ["--ball", "solid", "--backend", "fem"]),
        )
    },
    ("bounce", "--wall-cells"): ["--ball", "thick"],
    **{  # the lumped body's own law (a pressurised ball; a thin shell: Reissner)
        ("bounce", flag): _lumped_body(flag, law)
        for law, flags in (
            ("pressure", LUMPED_LAWS["pressure"] + ("--body-restitution", "--body-steps")),
            ("reissner", LUMPED_LAWS["reissner"]),
        )
        for flag in flags
    },
    **{
        ("bounce", flag): ["--pair", "basketball-tennis", "--body", "ball"]
        for flag in ("--body-modes", "--body-damping")
    },
    # the shell (--ball shell): its wall on the drop, its spectrum dimensionless or physical
    ("bounce", "--wall-stiffness-ratio"): ["--ball", "shell"],
    ("bounce", "--thickness-ratio"): ["--ball", "shell", "--wall-stiffness-ratio", "4"],
    ("eigen", "--poisson"): ["--ball", "shell"],
    ("eigen", "--thickness-ratio"): ["--ball", "shell"],
    ("eigen", "--prestress-ratio"): ["--ball", "shell"],
    ("eigen", "--wall-stiffness-ratio"): ["--ball", "shell", "--preset", "tennis"],
    ("eigen", "--youngs-modulus"): [
        "--ball",
        "shell",
        "--preset",
        "tennis",
        "--thickness",
        "0.003",
    ],
    ("eigen", "--thickness"): ["--ball", "shell", "--preset", "tennis", "--youngs-modulus", "6e6"],
    **{
        ("eigen", flag): ["--ball", "shell", *others]
        for flag, others in (
            ("--radius", ["--mass", "0.057", "--pressure", "8e4", "--preset", "tennis"]),
            ("--mass", ["--radius", "0.033", "--pressure", "8e4", "--preset", "tennis"]),
            ("--pressure", ["--radius", "0.033", "--mass", "0.057", "--preset", "tennis"]),
        )
    },
    # twoball fit: the whole bounce's options checked with --model bounce
    ("fit", "--mass-ratio"): ["--model", "bounce"],
    # twoball sweep --bounce: the lower ball's and the body's kinds as bounce reads them
    ("sweep", "--elements"): ["--bounce", "--backend", "fem"],
    ("sweep", "--order"): ["--bounce", "--backend", "fem"],
    **{
        ("fit", flag): ["--model", "bounce", "--mass-ratio", "0.05"]
        for flag in ("--gap", "--contact-radius", "--restitution", "--floor-restitution", "--dt")
    },
}
CONTEXT |= {  # the kinds' own flags: bounce's context, on a sweep of the drop
    ("sweep", flag): ["--bounce", *context]
    for (command, flag), context in list(CONTEXT.items())
    if command == "bounce"
    and (flag.startswith("--body-") or flag in ("--wall-stiffness-ratio", "--thickness-ratio"))
    or flag in ("--density", "--radial-orders", "--wall-cells", "--pole-levels", "--top-levels")
    and command == "bounce"
}
#: Options of the base line that do not apply in a context (the drop's --modes is the
#: Legendre ball's: refused with --backend fem, where the mesh sets the resolution).
LEFT_OUT: dict[tuple[str, str], tuple[str, ...]] = {
    ("bounce", "--elements"): ("--modes",),
    ("bounce", "--order"): ("--modes",),
    ("bounce", "--pole-levels"): ("--modes",),
    ("bounce", "--top-levels"): ("--modes",),
}
#: Cases of the table the command line does not refuse yet, each with what it does instead:
#: the test holds them apart and fails when one is refused (then delete its entry).
KNOWN_GAPS: dict[tuple[str, ...], str] = {}
#: Options the base line already gives (a bad value replaces the base's).
PATH_OPTIONS = (
    "--out",
    "--plot",
    "--mesh-file",
    "--export",
    "--render",
    "--data",
    "--measured",
    "--csv",
)


def numeric_options(parser: argparse.ArgumentParser) -> dict[str, list[str]]:
    """Subcommand -> its options that take a number (:mod:`twoball.cli.values` types)."""
    from twoball.cli.values import integer, number

    found: dict[str, list[str]] = {}
    for name, sub in subparsers(parser).items():
        found[name] = [
            action.option_strings[0]
            for action in sub._actions
            if action.option_strings and action.type in (number, integer, float, int)
        ]
    return found


def all_options(parser: argparse.ArgumentParser) -> dict[str, list[str]]:
    """Subcommand -> every option flag it has."""
    return {
        name: [a.option_strings[0] for a in sub._actions if a.option_strings]
        for name, sub in subparsers(parser).items()
    }


def subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    """The subcommand parsers of ``parser``."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    raise AssertionError("no subcommands")


def with_option(command: str, flag: str, value: str) -> list[str]:
    """The base line of ``command`` with its context for ``flag`` and ``flag value``."""
    argv = list(BASE[command])
    for left in LEFT_OUT.get((command, flag), ()):
        i = argv.index(left)
        del argv[i : i + 2]  # the flag and its value
    context = CONTEXT.get((command, flag), [])
    if command == "plot" and context and not context[0].startswith("-"):
        argv[1] = context[0]  # the plot kind
        context = context[1:]
        if argv[1] == "eigen":  # no mesh options: the eigen plot takes levels and orders
            argv = [w for w in argv if w not in ("--level", "1")]
    argv = _merge(argv, context)
    return _merge(argv, [flag, value])


def _merge(argv: list[str], extra: list[str]) -> list[str]:
    """``argv`` with ``extra``'s options replacing the same options of ``argv``."""
    argv = list(argv)
    k = 0
    while k < len(extra):
        flag = extra[k]
        has_value = k + 1 < len(extra) and not (
            extra[k + 1].startswith("--") and extra[k + 1] != "--"
        )
        if flag in argv and flag != "--param":
            i = argv.index(flag)
            takes = i + 1 < len(argv) and not argv[i + 1].startswith("--")
            del argv[i : i + (2 if takes else 1)]
        argv += [flag, extra[k + 1]] if has_value else [flag]
        k += 2 if has_value else 1
    return argv


def bad_values(flag: str) -> list[str]:
    """The values of :data:`BAD_NUMBERS` outside the valid range of ``flag``."""
    valid = RANGES[flag]
    also = ALSO_BAD.get(flag, ())
    return [v for v in BAD_NUMBERS if not valid.accepts(v) or v in also]


def numeric_cases(parser: argparse.ArgumentParser) -> list[tuple[str, list[str]]]:
    """(flag, argv) for every numeric option and each of its bad values."""
    cases = []
    for command, flags in numeric_options(parser).items():
        for flag in flags:
            for value in bad_values(flag):
                cases.append((flag, with_option(command, flag, value)))
    return cases


def path_cases(parser: argparse.ArgumentParser) -> list[tuple[str, list[str]]]:
    """(flag, argv) for every path option: empty, over-long and unwritable paths."""
    suffix = {
        "export": ".vtu",
        "render": ".png",
        "plot": ".png",
        "sweep": ".png",
        "liftoff": ".msh",
        "eigen": ".msh",
    }
    cases = []
    for command, flags in all_options(parser).items():
        for flag in flags:
            if flag not in PATH_OPTIONS:
                continue
            end = suffix.get(command, "")
            paths = [
                "",
                "{tmp}/" + LONG_NAME + end,
                LONG_PATH + end,
                "/proc/x/y" + end,
                "/proc/self/z" + end,  # an existing folder no one may write into
                "{tmp}/a-file/z" + end,  # a folder that is a file
            ]
            context = ["--backend", "fem"] if flag == "--mesh-file" and command == "liftoff" else []
            base = list(BASE[command])
            if flag == "--mesh-file" and "--level" in base:  # a file has its own size
                i = base.index("--level")
                del base[i : i + 2]
            for path in paths:
                cases.append((flag, _merge(_merge(base, context), [flag, path])))
    return cases


#: Options that do not apply: (flag named in the error, argv).
NOT_APPLICABLE: list[tuple[str, list[str]]] = [
    # the closed-form backend has no mesh and no time steps
    *[
        (flag, ["liftoff", flag, value])
        for flag, value in (
            ("--mesh", "sphere"),
            ("--mesh", "axisym"),
            ("--mesh-file", "{tmp}/ball.msh"),
            ("--pole", "0,0,1"),
            ("--level", "3"),
            ("--elements", "50"),
            ("--order", "2"),
            ("--scheme", "modal"),
            ("--scheme", "alpha"),
            ("--dt", "1e-5"),
            ("--route", "full"),
        )
    ],
    ("--level", ["liftoff", "--backend", "fem", "--mesh", "axisym", "--level", "2"]),
    ("--elements", ["liftoff", "--backend", "fem", "--mesh", "ring", "--elements", "50"]),
    ("--elements", ["liftoff", "--backend", "fem", "--mesh", "sphere", "--elements", "50"]),
    ("--elements", ["liftoff", "--backend", "fem", "--elements", "50"]),
    ("--dt", ["liftoff", "--backend", "fem", "--scheme", "modal", "--dt", "1e-5"]),
    ("--dt", ["liftoff", "--backend", "fem", "--dt", "1e-5"]),
    ("--route", ["liftoff", "--backend", "fem", "--scheme", "alpha", "--route", "krylov"]),
    ("--pole", ["liftoff", "--backend", "fem", "--pole", "0,0,1"]),
    ("--mesh", ["liftoff", "--backend", "fem", "--mesh", "bogus"]),
    ("--backend", ["liftoff", "--backend", "bogus"]),
    ("--mass", ["liftoff", "--pressure", "77200"]),
    ("--wave-speed", ["liftoff", "--pressure", "77200", "--mass", "0.567", "--wave-speed", "3"]),
    # the membrane operator and the damping law (docs/pressurised.rst)
    ("--membrane", ["liftoff", "--membrane", "flat"]),
    ("--gas", ["liftoff", "--membrane", "pressurised"]),  # unstable breathing without a gas
    ("--membrane", ["eigen", "--membrane", "flat"]),
    ("--rayleigh", ["liftoff", "--rayleigh", "-1,0"]),
    ("--rayleigh", ["liftoff", "--rayleigh", "1"]),
    ("--rayleigh", ["liftoff", "--rayleigh", "1,abc"]),
    ("--rayleigh", ["liftoff", "--mass-ratio", "0.1", "--rayleigh", "1,0"]),
    ("--damping", ["liftoff", "--rayleigh", "1,0", "--damping", "0.2"]),
    ("--damping-model", ["liftoff", "--rayleigh", "1,0", "--damping-model", "rayleigh"]),
    (
        "--membrane",
        ["converge", "modes", "--membrane", "pressurised", "--gas", "adiabatic"]
        + ["--pressure", "77200", "--mass", "0.567", "--phi-a", "2.6", "--out", "{tmp}/c"],
    ),
    ("--rayleigh", ["verify", "--fast", "--rayleigh", "1,0", "--out", "{tmp}/r"]),
    ("--param", ["sweep", "--param", "damping", "--values", "0.1,0.2", "--rayleigh", "1,0"]),
    ("--backend", ["plot", "precursor", "--backend", "fem", "--out", "{tmp}/p.png"]),
    ("--mesh", ["plot", "precursor", "--mesh", "sphere", "--out", "{tmp}/p.png"]),
    ("--level", ["eigen", "--mesh", "axisym", "--level", "2"]),
    ("--elements", ["eigen", "--mesh", "sphere", "--elements", "50"]),
    ("--pole", ["eigen", "--pole", "0,0,1"]),
    # a sweep replaces the base value of the swept parameter
    ("--v0", ["sweep", "--param", "v0", "--values", "2:4:3", "--v0", "3"]),
    ("--damping", ["sweep", "--param", "damping", "--values", "0:0.5:3", "--damping", "0.2"]),
    ("--modes", ["sweep", "--param", "modes", "--values", "10:30:3", "--modes", "20"]),
    ("--radius", ["sweep", "--param", "radius", "--values", "0.1:0.2:3", "--radius", "0.1"]),
    (
        "--wave-speed",
        ["sweep", "--param", "wave-speed", "--values", "300:400:3", "--wave-speed", "300"],
    ),
    ("--values", ["sweep", "--param", "damping", "--values", "0:0.5:3", "--values", "0:1:2"]),
    # two swept parameters (a grid) need two value lists
    ("--values", ["sweep", "--param", "damping", "--param", "v0", "--values", "0:0.5:3"]),
    (
        "--workers",
        ["sweep", "--param", "damping", "--values", "0:0.5:3", "--workers", "2"]
        + ["--scheduler", "tcp://127.0.0.1:1"],
    ),
    # swept values outside the parameter's range: refused before the first point
    # (named as the option they were typed in: --values, with the parameter)
    ("--values", ["sweep", "--param", "damping", "--values", "0:2:3"]),
    ("--values", ["sweep", "--param", "v0", "--values", "0:5:3"]),
    ("--values", ["sweep", "--param", "radius", "--values", "1e-308:1:3"]),
    ("--values", ["sweep", "--param", "modes", "--values", "0:30:3"]),
    ("--t-end", ["sweep", "--param", "damping", "--values", "0:0.5:3", "--t-end", "0"]),
    # the drop on the floor: a floor option with a model that cannot use it
    ("--gas", ["bounce", "--gas", "none", "--membrane", "pressurised"]),
    ("--drop-height", ["bounce", "--v0", "3", "--drop-height", "1"]),
    ("--drop-height", ["bounce", "--drop-height", "-0.5"]),
    # a drop height below the case's radius R (0.12 m for the basketball)
    ("--drop-height", ["bounce", "--drop-height", "0.05"]),
    ("--drop-height", ["bounce", "--preset", "tennis", "--drop-height", "0.03"]),
    ("--values", ["sweep", "--bounce", "--param", "drop-height", "--values", "0.05,0.5"]),
    ("--drop-height", ["liftoff", "--drop-height", "1"]),
    # the centre's height (the paper's x2): one height, not beside a speed, at least 2 R
    ("--centre-height", ["bounce", "--centre-height", "0.92", "--drop-height", "0.8"]),
    ("--centre-height", ["bounce", "--centre-height", "0.92", "--v0", "4.1"]),
    ("--centre-height", ["bounce", "--centre-height", "0.2"]),
    ("--floor-restitution", ["liftoff", "--floor-restitution", "1"]),
    ("--elements", ["bounce", "--elements", "20"]),
    ("--mesh", ["bounce", "--backend", "fem", "--mesh", "sphere"]),
    ("--modes", ["bounce", "--backend", "fem", "--modes", "20"]),
    ("--sigma", ["bounce", "--sigma", "none"]),
    ("--recontact", ["bounce", "--recontact", "paper"]),
    # the whole bounce: a body's options without a body, a pair with what it fixes
    ("--gap", ["bounce", "--gap", "0.1"]),
    ("--mass-ratio", ["bounce", "--mass-ratio", "0"]),
    ("--restitution", ["bounce", "--restitution", "0.5"]),
    ("--energy", ["bounce", "--mass-ratio", "0.1", "--energy", "both"]),
    ("--contact-radius", ["bounce", "--mass-ratio", "0.1", "--contact-radius", "0.2"]),
    ("--pair", ["bounce", "--pair", "bogus"]),
    ("--mass-ratio", ["bounce", "--pair", "basketball-tennis", "--mass-ratio", "0.1"]),
    ("--restitution", ["bounce", "--pair", "basketball-tennis", "--restitution", "0.5"]),
    ("--contact-radius", ["bounce", "--pair", "tennis-coin", "--contact-radius", "0.01"]),
    ("--preset", ["bounce", "--pair", "tennis-coin", "--preset", "tennis"]),
    ("--frames", ["bounce", "--frames", "5"]),
    ("--export", ["bounce", "--export", "{tmp}/x.bogus"]),
    ("--render", ["bounce", "--render", "{tmp}/x.bogus"]),
    ("--frames", ["bounce", "--frames", "5", "--export", "{tmp}/x.vtu"]),
    ("--gap", ["sweep", "--param", "damping", "--values", "0.1", "--gap", "0.1"]),
    ("--pair", ["sweep", "--param", "damping", "--values", "0.1", "--pair", "tennis-coin"]),
    ("--param", ["sweep", "--param", "gap", "--values", "0,0.1"]),
    (
        "--gap",
        ["sweep", "--bounce", "--param", "gap", "--values", "0,0.1", "--mass-ratio", "0.1"]
        + ["--gap", "0.1"],
    ),
    (
        "--values",
        ["sweep", "--bounce", "--param", "gap", "--values", "-1,0.1", "--mass-ratio", "0.1"],
    ),
    ("--gap", ["sweep", "--bounce", "--param", "gap", "--values", "0,0.1"]),
    (
        "--pair",
        ["sweep", "--bounce", "--param", "mass-ratio", "--values", "0.1"]
        + ["--pair", "basketball-tennis"],
    ),
    # the collision model
    *[
        (flag, ["icm", "--table1", flag, "0.5"])
        for flag in ("--mu", "--e2", "--e12", "--dx", "--drop-height")
    ],
    ("--drop-height", ["icm", "--mu", "0.5", "--e2", "0.8", "--e12", "0.9", "--dx", "0.1"]),
    ("--mu", ["icm", "--e2", "0.8", "--e12", "0.9"]),
    # refinement studies
    ("--mesh", ["converge", "modes", "--mesh", "sphere", "--out", "{tmp}/c"]),
    ("--order", ["converge", "modes", "--order", "2", "--out", "{tmp}/c"]),
    ("--levels", ["converge", "modes", "--levels", "1:2", "--out", "{tmp}/c"]),
    ("--modes", ["converge", "modes", "--modes", "20", "--out", "{tmp}/c"]),
    ("--modes-list", ["converge", "h", "--modes-list", "30,60,120", "--out", "{tmp}/c"]),
    ("--order", ["converge", "order", "--order", "2", "--out", "{tmp}/c"]),
    ("--levels", ["converge", "h", "--levels", "0:1", "--out", "{tmp}/c"]),
    ("--levels", ["converge", "h", "--levels", "3:2", "--out", "{tmp}/c"]),
    ("--modes-list", ["converge", "modes", "--modes-list", "0,10", "--out", "{tmp}/c"]),
    ("--fast", ["verify", "--fast", "--thorough", "--out", "{tmp}/r"]),
    # files and pictures
    ("--frames", ["export", "--level", "1", "--frames", "5", "--out", "{tmp}/x.vtu"]),
    ("--times", ["export", "--level", "1", "--times", "0,0.001", "--out", "{tmp}/x.vtu"]),
    ("--times", ["export", "--level", "1", "--times", "-1", "--out", "{tmp}/x.pvd"]),
    ("--times", ["export", "--level", "1", "--times", "1", "--out", "{tmp}/x.pvd"]),
    ("--times", ["export", "--level", "1", "--times", "nan", "--out", "{tmp}/x.pvd"]),
    ("--times", ["export", "--level", "1", "--times", "", "--out", "{tmp}/x.pvd"]),
    ("--format", ["export", "--level", "1", "--format", "bogus", "--out", "{tmp}/x.vtu"]),
    (
        "--route",
        [
            "export",
            "--level",
            "1",
            "--backend",
            "legendre",
            "--route",
            "full",
            "--out",
            "{tmp}/x.vtu",
        ],
    ),
    ("--mesh", ["export", "--mesh", "axisym", "--out", "{tmp}/x.vtu"]),
    # mesh files of the field commands: --pole needs one, --level does not apply to one,
    # the exact geometry not to the ring sphere, the eigen plot takes generated meshes only
    *[
        (flag, [*command, *extra])
        for command in (
            ["export", "--out", "{tmp}/x.vtu"],
            ["render", "--out", "{tmp}/x.png"],
            ["plot", "pole", "--out", "{tmp}/p.png"],
        )
        for flag, extra in (
            ("--pole", ["--pole", "0,0,1"]),
            ("--pole", ["--mesh", "sphere", "--pole", "0,0,1"]),
            ("--level", ["--mesh-file", "{tmp}/ball.msh", "--level", "1"]),
            ("--geometry", ["--mesh", "ring", "--geometry", "exact"]),
            ("--geometry", ["--geometry", "bogus"]),
            ("--mesh-file", ["--mesh-file", "{tmp}/a-file"]),
        )
    ],
    ("--order", ["export", "--level", "1", "--order", "3", "--out", "{tmp}/x.vtu"]),
    ("--order", ["render", "--level", "1", "--order", "4", "--out", "{tmp}/x.png"]),
    ("--mesh-file", ["plot", "eigen", "--mesh-file", "{tmp}/ball.msh", "--out", "{tmp}/p.png"]),
    ("--pole", ["plot", "eigen", "--pole", "0,0,1", "--out", "{tmp}/p.png"]),
    ("--geometry", ["plot", "eigen", "--geometry", "exact", "--out", "{tmp}/p.png"]),
    ("--initial", ["export", "--initial", "bogus", "--out", "{tmp}/x.vtu"]),
    ("--backend", ["export", "--backend", "bogus", "--out", "{tmp}/x.vtu"]),
    ("--fps", ["render", "--level", "1", "--fps", "10", "--out", "{tmp}/x.png"]),
    ("--frames", ["render", "--level", "1", "--frames", "5", "--out", "{tmp}/x.png"]),
    ("--time", ["render", "--level", "1", "--time", "0.001", "--out", "{tmp}/x.gif"]),
    (
        "--initial",
        ["render", "--backend", "legendre", "--initial", "interpolation"]
        + ["--out", "{tmp}/x.png"],
    ),
    ("--out", ["render", "--level", "1", "--out", "{tmp}/x.jpg"]),
    ("--warp", ["render", "--level", "1", "--warp", "-1", "--out", "{tmp}/x.png"]),
    ("--warp", ["render", "--level", "1", "--warp", "nan", "--out", "{tmp}/x.png"]),
    ("--size", ["render", "--level", "1", "--size", "0x0", "--out", "{tmp}/x.png"]),
    ("--size", ["render", "--level", "1", "--size", "big", "--out", "{tmp}/x.png"]),
    *[
        (flag, ["plot", "eigen", flag, value, "--out", "{tmp}/p.png"])
        for flag, value in (
            ("--radius", "0.2"),
            ("--v0", "3"),
            ("--damping", "0.2"),
            ("--sigma", "none"),
            ("--recontact", "paper"),
            ("--t-end", "0.01"),
            ("--backend", "fem"),
            ("--instants", "5"),
            ("--initial", "interpolation"),
            ("--level", "1"),
            ("--mesh", "ring"),
        )
    ],
    *[
        (flag, ["plot", "pole", "--level", "1", flag, value, "--out", "{tmp}/p.png"])
        for flag, value in (
            ("--levels", "1,2"),
            ("--orders", "1"),
            ("--max-degree", "5"),
            ("--instants", "5"),
        )
    ],
    # an upper body of finite mass: plot pole, render and export only, with its own rules
    ("--mass-ratio", ["plot", "eigen", "--mass-ratio", "0.1", "--out", "{tmp}/p.png"]),
    ("--mass-ratio", ["plot", "waterfall", "--mass-ratio", "0.1", "--out", "{tmp}/p.png"]),
    ("--mass-ratio", ["export", "--level", "1", "--mass-ratio", "0", "--out", "{tmp}/x.vtu"]),
    (
        "--mass-ratio",
        ["render", "--preset", "tennis", "--mass-ratio", "0.1", "--out", "{tmp}/x.png"],
    ),
    *[
        (flag, [*command, "--level", "1", flag, value, "--out", "{tmp}/x" + end])
        for command, end in ((["export"], ".vtu"), (["render"], ".png"), (["plot", "pole"], ".png"))
        for flag, value in (
            ("--contact-radius", "0.01"),
            ("--restitution", "0.5"),
            ("--energy", "both"),
        )
    ],
    (
        "--energy",
        [
            "export",
            "--level",
            "1",
            "--mass-ratio",
            "0.1",
            "--energy",
            "bogus",
            "--out",
            "{tmp}/x.vtu",
        ],
    ),
    (
        "--route",
        [
            "export",
            "--level",
            "1",
            "--mass-ratio",
            "0.1",
            "--route",
            "krylov",
            "--out",
            "{tmp}/x.vtu",
        ],
    ),
    (
        "--recontact",
        [
            "render",
            "--level",
            "1",
            "--mass-ratio",
            "0.1",
            "--recontact",
            "paper",
            "--out",
            "{tmp}/x.png",
        ],
    ),
    ("--levels", ["plot", "eigen", "--levels", "-1", "--out", "{tmp}/p.png"]),
    ("--orders", ["plot", "eigen", "--orders", "7", "--out", "{tmp}/p.png"]),
    ("--backend", ["plot", "pole", "--backend", "bogus", "--out", "{tmp}/p.png"]),
    ("plot kind", ["plot", "bogus", "--out", "{tmp}/p.png"]),
    ("--only", ["reproduce", "--only", "bogus", "--out", "{tmp}/rep"]),
    (
        "--workers",
        ["reproduce", "--only", "table1", "--workers", "2", "--out", "{tmp}/rep"]
        + ["--scheduler", "tcp://127.0.0.1:1"],
    ),
    ("--max-memory", ["liftoff", "--max-memory", "-1"]),
    ("--max-time", ["liftoff", "--max-time", "soon"]),
    ("--preset", ["liftoff", "--preset", "bogus"]),
]

#: Options that used to be ignored (or to give a traceback, or to blame another
#: option): each is now refused in one line naming the option the user gave.
NO_LONGER_IGNORED: list[tuple[str, list[str]]] = [
    ("--geometry", ["liftoff", "--mass-ratio", "0.1", "--geometry", "exact"]),
    ("--phi-a", ["sweep", "--param", "v0", "--values", "2:4:3", "--phi-a", "2.5"]),
    ("--phi-a", ["sweep", "--param", "radius", "--values", "0.1:0.2:3", "--phi-a", "2.5"]),
    (
        "--pressure",
        ["sweep", "--param", "wave-speed", "--values", "300:400:3"]
        + ["--pressure", "77200", "--mass", "0.567"],
    ),
    (
        "--pressure",
        ["sweep", "--param", "radius", "--values", "0.1:0.2:3"]
        + ["--pressure", "77200", "--mass", "0.567"],
    ),
    (
        "--recontact",
        ["plot", "waterfall", "--level", "1", "--recontact", "paper"] + ["--out", "{tmp}/p.png"],
    ),
    *[
        ("--atmosphere", [*argv, "--atmosphere", "50000"])
        for argv in (
            ["liftoff"],
            ["liftoff", "--preset", "tennis", "--gas", "none"],
            ["sweep", "--param", "damping", "--values", "0:0.5:3"],
            ["converge", "modes", "--out", "{tmp}/c"],
            ["verify", "--fast", "--out", "{tmp}/r"],
            ["export", "--level", "1", "--out", "{tmp}/x.vtu"],
            ["render", "--level", "1", "--out", "{tmp}/x.png"],
            ["plot", "pole", "--level", "1", "--out", "{tmp}/p.png"],
        )
    ],
    ("--levels", ["converge", "h", "--levels", "", "--out", "{tmp}/c"]),
    ("--modes-list", ["converge", "modes", "--modes-list", "", "--out", "{tmp}/c"]),
    ("--scheduler", ["sweep", "--param", "damping", "--values", "0:0.5:3", "--scheduler", ""]),
    ("--scheduler", ["sweep", "--param", "damping", "--values", "0:0.5:3", "--scheduler", "::::"]),
    ("--scheduler", ["reproduce", "--only", "table1", "--scheduler", "", "--out", "{tmp}/rep"]),
    # |u| is known once solved: refused then, after the progress line (--quiet: none)
    ("--warp", ["render", "-q", "--level", "1", "--warp", "1e308", "--out", "{tmp}/x.png"]),
    ("--plot", ["liftoff", "--mass-ratio", "0", "--plot", "{tmp}/x.png"]),
    ("--youngs-modulus", ["liftoff", "--youngs-modulus", "1e7", "--thickness", "1"]),
    ("--mesh-file", ["converge", "--study", "h", "--mesh-file", "X", "--out", "{tmp}/c"]),
    ("--modes", ["verify", "--modes", "3", "--fast", "--out", "{tmp}/r"]),
    (
        "--modes-list",
        ["converge", "--study", "modes", "--modes-list", "30,100000,1000000"]
        + ["--out", "{tmp}/c"],
    ),
    # (a body of finite mass on N = 2000 modes, once refused by the event-driven solver's
    # budget at 1.2 h, is stepped by the contact core in seconds: no longer a refusal)
    ("--modes", ["liftoff", "--preset", "tennis", "--modes", "960", "--max-time", "20s"]),
    ("--radius", ["liftoff", "--radius", "1", "--radius", "2"]),
    # a base value the sweep would replace: the height sets |v0|, E and h set B
    ("--v0", ["sweep", "--bounce", "--param", "drop-height", "--values", "1,2", "--v0", "3"]),
    (
        "--youngs-modulus",
        ["sweep", "--param", "bending", "--values", "0,1"]
        + ["--youngs-modulus", "1e6", "--thickness", "0.001"],
    ),
    # the closed form alone has no finite elements: no eigen route
    ("--route", ["render", "--backend", "legendre", "--route", "full", "--out", "{tmp}/x.png"]),
    (
        "--route",
        ["plot", "pole", "--backend", "legendre", "--route", "full", "--out", "{tmp}/p.png"],
    ),
    # a massless body in a sweep of the whole bounce: refused before the first point
    ("--values", ["sweep", "--bounce", "--param", "mass-ratio", "--values", "0,0.1"]),
    # the eigen plot has no case: the stiff ball's options too
    ("--bending", ["plot", "eigen", "--bending", "1", "--out", "{tmp}/p.png"]),
    ("--gas", ["plot", "eigen", "--gas", "adiabatic", "--out", "{tmp}/p.png"]),
    # an output onto an input, two outputs with one path
    # (``{tmp}/ball.vtu`` is a readable sphere mesh the harness writes)
    ("--out", ["export", "--mesh-file", "{tmp}/ball.vtu", "--out", "{tmp}/ball.vtu"]),
    ("--render", ["bounce", "--plot", "{tmp}/same.png", "--render", "{tmp}/same.png"]),
]
NOT_APPLICABLE.extend(NO_LONGER_IGNORED)

_FIT = ["fit", "--data", "{tmp}/a-file", "--param", "damping"]
#: twoball fit: its own options and the file, each refused naming the flag.
FIT_REFUSALS: list[tuple[str, list[str]]] = [
    ("--data", _FIT),  # an empty file
    ("--data", ["fit", "--data", "{tmp}", "--param", "damping"]),  # a folder
    ("--data", ["fit", "--data", "{tmp}/none.csv", "--param", "damping"]),
    ("--param", [*_FIT, "--param", "restitution"]),  # the closed form has no e12
    ("--model", [*_FIT, "--model", "whole"]),
    ("--pair", [*_FIT, "--pair", "tennis-coin"]),  # a pair needs the whole bounce
    ("--pair", [*_FIT, "--model", "bounce", "--pair", "bogus"]),
    ("--phi-a", [*_FIT, "--model", "bounce", "--phi-a", "2.6"]),
    ("--energy", [*_FIT, "--model", "bounce", "--mass-ratio", "0.1", "--energy", "both"]),
    ("--start", [*_FIT, "--start", "damping=2"]),
    ("--start", [*_FIT, "--start", "wave-speed=300"]),
    ("--bounds", [*_FIT, "--bounds", "damping=0.5:0.1"]),
    ("--bounds", [*_FIT, "--bounds", "damping=0.1"]),
]
NOT_APPLICABLE.extend(FIT_REFUSALS)

#: Numbers written with a digit separator (Python's float("0_01") is 1.0, int("4_1") 41)
#: or in another script's digits (float("\u0664.\u0661") is 4.1): refused as not numbers,
#: wherever text is read as a number.
DIGIT_SEPARATORS: list[tuple[str, list[str]]] = [
    ("--gap", ["bounce", "--mass-ratio", "0.05", "--gap", "0_01"]),
    ("--v0", ["liftoff", "--v0", "4_1"]),
    ("--v0", ["liftoff", "--v0", "\u0664.\u0661"]),
    ("--modes", ["liftoff", "--modes", "3_0"]),
    ("--drop-height", ["bounce", "--drop-height", "1_0"]),
    ("--mu", ["icm", "--mu", "0_5", "--e2", "0.8", "--e12", "0.9"]),
    ("--start", [*_FIT, "--start", "damping=0_1"]),
    ("--bounds", [*_FIT, "--bounds", "damping=0_1:0.2"]),
    ("--values", ["sweep", "--param", "damping", "--values", "0_1,0.2"]),
    ("--values", ["sweep", "--param", "damping", "--values", "0:0_5:3"]),
    ("--values", ["sweep", "--bounce", "--param", "drop-height", "--values", "0_5,1"]),
    ("--max-time", ["liftoff", "--max-time", "2_0s"]),
    ("--max-memory", ["liftoff", "--max-memory", "1_0GiB"]),
    ("--times", ["export", "--level", "1", "--times", "0,0_001", "--out", "{tmp}/x.pvd"]),
    (
        "--pole",
        ["export", "--mesh-file", "{tmp}/ball.vtu", "--pole", "0,0_1,1"] + ["--out", "{tmp}/y.vtu"],
    ),
    ("--size", ["render", "--level", "1", "--size", "64x4_8", "--out", "{tmp}/x.png"]),
    ("--rayleigh", ["liftoff", "--rayleigh", "1_0,0"]),
    ("--levels", ["converge", "h", "--levels", "0:1_0", "--out", "{tmp}/c"]),
    ("--modes-list", ["converge", "modes", "--modes-list", "30,6_0", "--out", "{tmp}/c"]),
    ("--levels", ["plot", "eigen", "--levels", "1_0", "--out", "{tmp}/p.png"]),
    ("--gas", ["eigen", "--ball", "shell", "--gas", "0_1"]),
    # the shell's ratios as typed: '' is not 0, h / R at most 0.5, p >= 0 by its own name
    ("--thickness-ratio", ["eigen", "--ball", "shell", "--thickness-ratio", "0.6"]),
    ("--prestress-ratio", ["eigen", "--ball", "shell", "--prestress-ratio", "1.5"]),
    (
        "--prestress-ratio",
        ["eigen", "--ball", "shell", "--poisson", "0.3", "--prestress-ratio", "1.31"],
    ),
]
NOT_APPLICABLE.extend(DIGIT_SEPARATORS)

#: Refusals whose line must also say the right value or leave out a wrong one:
#: (argv, words the line holds, words it must not hold).
MESSAGES: list[tuple[list[str], tuple[str, ...], tuple[str, ...]]] = [
    (["bounce", "--recontact", "paper"], ("--recontact", "got 'paper'"), ("lanczos",)),
    (["bounce", "--sigma", "none"], ("--sigma", "got 'none'"), ()),
    (
        ["plot", "eigen", "--v0", "3", "--out", "{tmp}/p.png"],
        ("--v0 must be left out with kind eigen", "got 3.0"),
        ("Case",),
    ),
    (
        ["sweep", "--param", "v0", "--values", "0,1"],
        ("--values must be a nonzero speed", "for --param v0", "got 0.0"),
        ("--v0 ",),
    ),
    (
        ["sweep", "--bounce", "--param", "mass-ratio", "--values", "0,0.1"],
        ("--values must be a number in (0, 100]", "for --param mass-ratio", "got 0.0"),
        (),
    ),
    (["converge", "--out", "{tmp}/c"], ("converge STUDY must be given", "h, order"), ("'none'",)),
    # the keywords a valid range names are flags too; a body comes from either flag
    (
        ["bounce", "--gap", "0.1"],
        ("--gap must be", "(--mass-ratio or --pair)", "got 0.1"),
        ("mass_ratio",),
    ),
    (["liftoff", "--restitution", "0.5"], ("given only with --mass-ratio, got 0.5",), ("--pair",)),
    (
        ["converge", "modes", "--levels", "1:2", "--out", "{tmp}/c"],
        ("use --modes-list",),
        ("modes_list",),
    ),
    (
        ["eigen", "--ball", "shell", "--poisson", "0.3", "--prestress-ratio", "1.31"],
        ("--prestress-ratio must be a number in [0, 1.3) at nu = 0.3, g = 0", "got 1.31"),
        ("prestress_ratio", "--wall-stiffness-ratio"),
    ),
    (["render", "--pair", "basketball-tennis"], ("twoball bounce --pair NAME --render FILE",), ()),
    # paths as the user typed them, relative ones too (the case runs in its own folder)
    *[
        (argv, (f"got '{path}'",), ("/" + path,))
        for argv, path in (
            (["render", "--level", "1", "--out", "nodir/x.png"], "nodir/x.png"),
            (["bounce", "--modes", "16", "--plot", "nodir/x.png"], "nodir/x.png"),
            (
                ["sweep", "--param", "damping", "--values", "0,0.1", "--csv", "nodir/x.csv"],
                "nodir/x.csv",
            ),
            (["export", "--mesh-file", "a-file", "--out", "a-file"], "a-file"),
            (["reproduce", "--only", "table1", "--out", "a-file"], "a-file"),
        )
    ],
    # budget refusals: this subcommand's flags, the defaults said to be defaults
    (
        ["bounce", "--max-time", "0.01s"],
        ("--dt 1.5625e-05 (the default) --t-end 0.0981748 (the default) needs ~",),
        (),
    ),
    (
        ["bounce", "--modes", "100", "--dt", "1e-5", "--max-time", "0.01s"],
        ("--modes 100 --dt 1e-05 --t-end 0.0981748 (the default) needs ~",),
        (),
    ),
    (
        ["render", "--level", "1", "--out", "{tmp}/x.gif", "--max-time", "0.01s"],
        ("--frames (60 frames) (the default) needs ~",),
        ("--frames)",),
    ),
    (
        ["liftoff", "--max-time", "0.001s"],
        ("--modes 30 (the default) needs ~",),
        (),
    ),
]

#: Unit slips that run (exit 0) and must warn with the value probably meant:
#: (argv, words of the warning).  ``--modes 16`` keeps the drops short.
UNIT_SLIPS: list[tuple[list[str], tuple[str, ...]]] = [
    (
        ["bounce", "--modes", "16", "--drop-height", "1000"],
        ("H = 1000 m", "140.1 m/s", "did you mean 1 m (1000 mm)"),
    ),
    (["bounce", "--modes", "16", "--v0", "140"], ("|v0| = 140 m/s", "did you mean 0.14 m/s")),
    (["bounce", "--modes", "16", "--v0", "4100"], ("did you mean 4.1 m/s (4100 mm/s)",)),
    (["bounce", "--modes", "16", "--radius", "120"], ("R = 120 m", "did you mean 0.12 m (120 mm)")),
    (
        # the window's default holds twice the 5 m gap's closing time (156k steps): 50 ms
        ["bounce", "--modes", "16", "--mass-ratio", "0.1", "--gap", "5", "--t-end", "0.05"],
        ("gap Delta x = 5 m", "did you mean 0.005 m (5 mm)"),
    ),
    (
        ["sweep", "--bounce", "--modes", "16", "--param", "drop-height", "--values", "500,1000"],
        ("2 of 2 values", "drop-height = 500", "H = 500 m", "did you mean 0.5 m (500 mm)"),
    ),
    (["liftoff", "--radius", "120"], ("R = 120 m", "did you mean 0.12 m (120 mm)")),
    (["liftoff", "--wave-speed", "3.2e5"], ("c = 320000 1/s", "did you mean 320 1/s")),
    (
        ["liftoff", "--pressure", "77200", "--mass", "567"],
        ("m = 567 kg", "did you mean 0.567 kg (567 g)"),
    ),
    (
        ["bounce", "--modes", "16", "--pressure", "77200", "--mass", "567"],
        ("m = 567 kg", "did you mean 0.567 kg (567 g)"),
    ),
    (
        ["sweep", "--param", "wave-speed", "--values", "3.2e5,3.3e5"],
        ("2 of 2 values", "wave-speed = 320000", "c = 320000 1/s", "did you mean 320 1/s"),
    ),
]
