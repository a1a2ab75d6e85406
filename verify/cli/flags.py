"""The one table from parameter names (Python API, model layer) to command-line flags.

The model layer and :mod:`twoball`'s public functions raise
:class:`~twoball.modal.errors.ParameterError` naming their parameters
(``damping``, ``phi_a``, ``level``); the command line prints the flag the user
typed instead (``--damping``, ``--phi-a``, ``--level``).  Names not in the
table (already a flag, or internal) are printed as they are.
"""

from __future__ import annotations

from twoball.modal.errors import ParameterError

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
    # model
    "sigma": "--sigma",
    "recontact": "--recontact",
    "t_end": "--t-end",
    "backend": "--backend",
    "backends": "--backends",
    # finite elements
    "mesh": "--mesh",
    "level": "--level",
    "elements": "--elements",
    "order": "--order",
    "time": "--time",
    "dt": "--dt",
    "route": "--route",
    "damping_model": "--damping-model",
    "rho_inf": "--rho-inf",
    "initial": "--initial",
    "count": "--count",
    "mesh_file": "--mesh-file",
    "pole": "--pole",
    # sweeps, studies, reports
    "values": "--values",
    "param": "--param",
    "workers": "--workers",
    "scheduler": "--scheduler",
    "study": "--study",
    "levels": "--levels",
    "orders": "--orders",
    "modes_list": "--modes-list",
    "thorough": "--thorough",
    "fast": "--fast",
    # files and pictures
    "out": "--out",
    "format": "--format",
    "frames": "--frames",
    "times": "--times",
    "fps": "--fps",
    "size": "--size",
    "warp": "--warp",
    "instants": "--instants",
    "max_degree": "--max-degree",
    "kind": "plot kind",
    # independent collision model
    "mu": "--mu",
    "e2": "--e2",
    "e12": "--e12",
    "dx": "--dx",
    "drop_height": "--drop-height",
}


def flag_of(name: str) -> str:
    """The command-line flag of parameter ``name`` (``name`` itself if it has none)."""
    return FLAGS.get(name, name)


def cli_message(error: ParameterError) -> str:
    """``error`` as one line naming the flag: ``--damping must be in [0, 1), got 2.0``."""
    text = f"{flag_of(error.name)} must be {error.valid}"
    if error.got is not None:
        text += f", got {error.got!r}"
    return text
