"""The choices and defaults the command line offers, with the standard library only.

``twoball SUBCOMMAND --help`` builds its parser from these values, so it
imports no numerical library (numpy, scipy, scikit-fem).  Each value is
defined for the model in the module that acts on it (named beside it) and
repeated here; ``tests/api/test_choices.py`` holds every copy equal to its
source.  The few helpers the command line calls at run time (not for its
help) are loaded from their module on first use (PEP 562).
"""

from __future__ import annotations

from twoball._common.lazy import attach

# the case and the model
STANDARD_GRAVITY = 9.81  # modal/scalings.py
SIGMAS: tuple[str, ...] = ("lanczos", "printed", "none")  # modal/series_options.py
HORIZONS: tuple[str, ...] = ("window", "paper")  # modal/series_options.py
GAS_MODELS: tuple[str, ...] = ("none", "isothermal", "adiabatic")  # modal/stiffness.py
# finite elements and time
MESH_KINDS: tuple[str, ...] = ("sphere", "ring", "axisym")  # fem_membrane/validate.py
SPHERE_KINDS: tuple[str, ...] = ("sphere", "ring")  # fem_membrane/options.py
DEFAULT_LEVEL = 3  # fem_membrane/options.py
DEFAULT_ELEMENTS = 400  # fem_membrane/options.py
DEFAULT_ORDER = 2  # fem_membrane/options.py
LEVEL_RANGE: tuple[int, int] = (0, 10)  # fem_membrane/validate.py
# the upper body
ENERGY_OPTIONS: tuple[str, ...] = ("ball", "both")  # modal/contact/body.py
MAX_MASS_RATIO = 100.0  # modal/contact/body.py
# the verbs
FIELD_BACKENDS: tuple[str, ...] = ("fem", "legendre")  # verify/output/options.py
DEFAULT_FRAMES = 25  # verify/output/fields.py
FORMATS: tuple[str, ...] = ("xdmf", "vtu", "pvd")  # verify/output/series.py
DEFAULT_SIZE: tuple[int, int] = (640, 480)  # verify/output/render.py
DEFAULT_ANIMATION_FRAMES = 60  # twoball/_files.py
DPI = 300  # verify/output/figures/__init__.py
WATERFALL_INSTANTS = 24  # verify/output/figures/waterfall.py
SWEEP_PARAMETERS: dict[str, str] = {  # verify/sweeps/sweeps.py
    "damping": "damping",
    "v0": "v0",
    "wave-speed": "wave_speed",
    "radius": "radius",
    "modes": "modes",
    "mass-ratio": "mass_ratio",
    "bending": "bending",
}
STUDIES: tuple[str, ...] = ("h", "order", "modes", "dt")  # verify/studies/result.py
REPRODUCTION_PARTS: tuple[str, ...] = (  # verify/reproduce/driver.py (PARTS)
    "table2",
    "fig6",
    "fig10",
    "fig11",
    "fig12",
    "thresholds",
    "table1",
    "icm",
    "contact",
    "whole_table1",
    "whole_gap",
    "whole_timing",
)
REPRODUCTION_DIR = "twoball-reproduction"  # verify/reproduce/driver.py (DEFAULT_OUT)
REPRODUCTION_REPORT = "reproduction.md"  # verify/reproduce/driver.py (REPORT)

__getattr__, __dir__ = attach(
    __name__,
    {
        "flexural_rigidity": "twoball.modal.stiffness",
        "pair": "twoball.modal.pairs",
        "parse_times": "twoball.verify.output.fields",
        "make_grid": "twoball.verify.sweeps.sweeps",
    },
)

__all__: list[str] = []
