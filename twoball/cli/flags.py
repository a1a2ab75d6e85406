"""The one table from parameter names (Python API, model layer) to command-line flags.

The model layer and :mod:`twoball`'s public functions raise
:class:`~twoball._common.errors.ParameterError` naming their parameters
(``damping``, ``phi_a``, ``level``); the command line prints the flag the user
typed instead (``--damping``, ``--phi-a``, ``--level``).  Names not in the
table (already a flag, or internal) are printed as they are.
"""

from __future__ import annotations

from argparse import Namespace

from twoball._common.errors import ParameterError

FLAGS: dict[str, str] = {
    # case (SI)
    "preset": "--preset",
    "radius": "--radius",
    "wave_speed": "--wave-speed",
    "pressure": "--pressure",
    "mass": "--mass",
    "v0": "--v0",
    "phi_a": "--phi-a",
    "damping": "--damping",
    "modes": "--modes",
    "g": "--g",
    "bending": "--bending",
    "youngs_modulus": "--youngs-modulus",
    "thickness": "--thickness",
    "poisson": "--poisson",
    "gas": "--gas",
    "atmosphere": "--atmosphere",
    "membrane": "--membrane",
    "rayleigh": "--rayleigh",
    "alpha": "--rayleigh",
    "beta": "--rayleigh",
    # model
    "sigma": "--sigma",
    "recontact": "--recontact",
    "series": "--sigma",
    "t_end": "--t-end",
    "backend": "--backend",
    "backends": "--backend",
    # upper body of finite mass (contact)
    "mass_ratio": "--mass-ratio",
    "contact_radius": "--contact-radius",
    "restitution": "--restitution",
    "energy": "--energy",
    "plot": "--plot",
    # finite elements
    "mesh": "--mesh",
    "level": "--level",
    "elements": "--elements",
    "order": "--order",
    "time": "--time",
    "scheme": "--scheme",
    "dt": "--dt",
    "route": "--route",
    "damping_model": "--damping-model",
    "rho_inf": "--rho-inf",
    "initial": "--initial",
    "count": "--count",
    "mesh_file": "--mesh-file",
    "file": "--mesh-file",
    "pole": "--pole",
    "geometry": "--geometry",
    # sweeps, studies, reports
    "values": "--values",
    "param": "--param",
    "workers": "--workers",
    "scheduler": "--scheduler",
    "study": "converge STUDY",
    "levels": "--levels",
    "orders": "--orders",
    "modes_list": "--modes-list",
    "thorough": "--thorough",
    "fast": "--fast",
    # fits to measured data (twoball fit) and their overlays
    "data": "--data",
    "params": "--param",
    "model": "--model",
    "start": "--start",
    "bounds": "--bounds",
    "bootstrap": "--bootstrap",
    "measured": "--measured",
    "csv": "--csv",
    # resource limits
    "max_memory": "--max-memory",
    "max_time": "--max-time",
    # files and pictures
    "out": "--out",
    "dpi": "--dpi",
    "format": "--format",
    "frames": "--frames",
    "times": "--times",
    "fps": "--fps",
    "size": "--size",
    "warp": "--warp",
    "instants": "--instants",
    "max_degree": "--max-degree",
    "offset": "--offset",
    "only": "--only",
    "kind": "plot kind",
    # independent collision model
    "mu": "--mu",
    "e2": "--e2",
    "e12": "--e12",
    "dx": "--dx",
    "drop_height": "--drop-height",
    # the drop on the floor, the whole bounce
    "floor_restitution": "--floor-restitution",
    "centre_height": "--centre-height",
    "gap": "--gap",
    "pair": "--pair",
    "export": "--export",
    "render": "--render",
    "body": "--mass-ratio",
    # the shell ball (--ball shell) and its spectrum
    "ball": "--ball",
    "wall": "--ball",
    "wall_stiffness_ratio": "--wall-stiffness-ratio",
    "thickness_ratio": "--thickness-ratio",
    "prestress_ratio": "--prestress-ratio",
    "prestress": "--prestress-ratio",
    # the elastic upper body (--body lumped|ball): the API's fields under their own flags
    "body_radius": "--body-radius",
    "body_pressure": "--body-pressure",
    "body_modulus": "--body-modulus",
    "body_poisson": "--body-poisson",
    "body_thickness": "--body-thickness",
    "body_restitution": "--body-restitution",
    "body_steps": "--body-steps",
    "body_modes": "--body-modes",
    "body_damping": "--body-damping",
    "body_law": "--body-law",
    "body_preset": "--body-preset",
    "floor_alone": "--floor-alone",
    # the solid ball and the thick wall (--ball solid|thick)
    "density": "--density",
    "radial_orders": "--radial-orders",
    "pole_levels": "--pole-levels",
    "top_levels": "--top-levels",
    "wall_cells": "--wall-cells",
}
#: Names that are also the paper's symbols (phi_a: the contact angle of eq. (3.7)): in the
#: prose of a message they stay the symbol; as the parameter refused they become the flag.
SYMBOLS = frozenset({"phi_a"})
#: A snake_case word of a message (a Python keyword), not inside quotes or a dotted name.
_KEYWORD = r"(?<![\w.'\"-])[a-z][a-z0-9]*(?:_[a-z0-9]+)+(?![\w'\"(-])"


def flag_of(name: str, args: Namespace | None = None) -> str:
    """The command-line flag of parameter ``name`` (``name`` itself if it has none).

    ``mesh`` is ``--mesh-file`` when the mesh came from ``--mesh-file`` (the API
    takes a kind name or a file as the same ``mesh`` argument); ``case`` is the
    first case option given (the API takes them together as one ``Case``).
    """
    if name == "mesh" and getattr(args, "mesh_file", None) is not None:
        return "--mesh-file"
    if name == "mesh" and args is not None and getattr(args, "mesh", None) is None:
        # the mesh options came from its fields alone: name the first one given
        for option in ("level", "elements", "order", "geometry", "pole"):
            if getattr(args, option, None) is not None:
                return FLAGS[option]
    if name == "damping" and getattr(args, "damping_model", None) is not None:
        return "--damping-model"  # the law the option chose
    if name == "rayleigh" and getattr(args, "rayleigh", None) is None:
        if getattr(args, "damping_model", None) is not None:
            return "--damping-model"  # the fitted law of --damping-model rayleigh
    if name == "series" and getattr(args, "sigma", None) is None:
        if getattr(args, "recontact", None) is not None:
            return "--recontact"  # the rules came from --recontact alone
    if name == "workers" and getattr(args, "scheduler", None) is not None:
        if getattr(args, "workers", None) is None:
            return "--scheduler"  # the API's workers took the scheduler's address
    if name == "frames" and getattr(args, "times", None) is not None:
        return "--times"
    if name == "frames" and getattr(args, "time", None) is not None:
        return "--time"
    if name == "case" and args is not None:  # the case came from the first case option given
        for option in ("preset", "radius", "wave_speed", "pressure", "mass", "v0", "phi_a"):
            if getattr(args, option, None) not in (None, "basketball"):
                return FLAGS[option]
        for option in ("damping", "modes", "rayleigh", "membrane", "g"):
            if getattr(args, option, None) is not None and option != "g":
                return FLAGS[option]
        return "--g"
    if name in FLAGS:
        return FLAGS[name]
    if args is not None and hasattr(args, name):  # the option of the same name
        return "--" + name.replace("_", "-")
    return name


def cli_message(error: ParameterError, args: Namespace | None = None) -> str:
    """``error`` as one line naming the flag: ``--damping must be in [0, 1), got 2.0``.

    The message keeps its own wording; only the parameter name it starts with
    becomes the flag.
    """
    text = " ".join(str(error).split())  # one line
    from twoball._common.budget import BudgetError

    if isinstance(error, BudgetError):  # "modes 100000 t_end 2 needs ...": every name a flag
        asked, needs, rest = text.partition(" needs ")
        asked = budget_flags(asked, args)
        return asked + needs + limit_flags(rest)  # the advice names the limit's flag
    name = str(error.name)
    valid = " ".join(str(error.valid).split())
    if valid and valid in text:  # the keywords the valid range names, as flags too
        text = text.replace(valid, keywords_as_flags(valid, args), 1)
    if text.startswith(name):
        return flag_of(name, args) + text[len(name) :]
    return text


def limit_flags(text: str) -> str:
    """``text`` with the limits' parameter names as their flags (``max_time`` -> ``--max-time``).

    For messages that reach the command line by another way than a raised error: a
    sweep point's error, a report written by a stopped run.
    """
    import re

    return re.sub(r"(?<![\w-])(max_time|max_memory)\b", lambda m: FLAGS[m.group(1)], text)


def keywords_as_flags(text: str, args: Namespace | None = None) -> str:
    """``text`` with each Python keyword that has a flag written as the flag the user types.

    ``given only with mass_ratio`` -> ``given only with --mass-ratio or --pair`` (where
    the subcommand takes a pair: it sets the body too); ``use modes_list`` -> ``use
    --modes-list``.  The paper's symbols (:data:`SYMBOLS`) and quoted words stay.
    """
    import re

    def flag(match: re.Match[str]) -> str:
        word = match.group(0)
        if word in SYMBOLS or word not in FLAGS:
            return word
        shown = flag_of(word, args)
        if word == "mass_ratio" and args is not None and hasattr(args, "pair"):
            return f"{shown} or --pair"
        return shown

    return re.sub(_KEYWORD, flag, text)


def budget_flags(asked: str, args: Namespace | None = None) -> str:
    """The work a budget refusal names, in this subcommand's flags.

    ``dt 1.5625e-05 t_end 0.098`` -> ``--dt 1.5625e-05 (the default) --t-end 0.098
    (the default)``: a name becomes its flag when the subcommand has that option,
    marked ``(the default)`` when the user did not give it; a name the subcommand
    has no option for stays a name.  Words inside parentheses (``frames (25
    frames)``) are the value's own.
    """
    out: list[str] = []
    depth, pending = 0, False
    for word in asked.split(" "):
        bare = word.rstrip("),")
        if depth == 0 and not pending and bare in FLAGS:
            shown, pending = _budget_flag(bare, args)
            out.append(shown + word[len(bare) :])
        else:
            out.append(word)
            if pending and depth + word.count("(") - word.count(")") == 0:
                out[-1] += " (the default)"
                pending = False
        depth += word.count("(") - word.count(")")
    return " ".join(out)


def _budget_flag(name: str, args: Namespace | None) -> tuple[str, bool]:
    """``(flag, is the default)`` of ``name`` for this subcommand, or ``(name, False)``."""
    flag = flag_of(name, args)
    if args is None or not flag.startswith("--"):
        return flag, False
    dest = flag[2:].replace("-", "_")
    value = getattr(args, dest, None)
    if dest in getattr(args, "_given_once", {}) or isinstance(value, list):
        return flag, False  # given (an option given in turns, like --values, is a list)
    if dest in vars(args):  # an option of this subcommand, left at its default
        return flag, True
    return name, False
