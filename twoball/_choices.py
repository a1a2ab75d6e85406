"""The choices, defaults and helpers the command line offers, from their one home below.

Every name is loaded on first use (PEP 562), so a subcommand imports only what
its options need: the command line builds its options from these and never
reaches below the face.  Each value is defined once, in the model or output
module that acts on it; this table only names where.
"""

from __future__ import annotations

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        # the case and the model
        "STANDARD_GRAVITY": "twoball.modal.scalings",
        "SIGMAS": ("twoball.modal.filters", "FILTER_KINDS"),
        "HORIZONS": "twoball.modal.liftoff",
        "GAS_MODELS": "twoball.modal.stiffness",
        "flexural_rigidity": "twoball.modal.stiffness",
        "DAMPING_LAWS": "twoball.modal.damping",
        # finite elements and time
        "MESH_KINDS": "twoball.fem_membrane.options",
        "SPHERE_KINDS": "twoball.fem_membrane.options",
        "DEFAULT_LEVEL": "twoball.fem_membrane.options",
        "DEFAULT_ELEMENTS": "twoball.fem_membrane.options",
        "DEFAULT_ORDER": "twoball.fem_membrane.options",
        "INITIAL_METHODS": "twoball.fem_membrane.options",
        "SCHEMES": "twoball.modal.stepping",
        "ROUTES": "twoball.modal.stepping",
        # the upper body
        "ENERGY_OPTIONS": "twoball.modal.contact.body",
        "MAX_MASS_RATIO": "twoball.modal.contact.body",
        "PAIRS": "twoball.modal.pairs",
        "pair": "twoball.modal.pairs",
        # the verbs
        "BACKENDS": "twoball._liftoff",
        "FIELD_BACKENDS": ("twoball.verify.output.fields", "BACKENDS"),
        "DEFAULT_FRAMES": "twoball.verify.output.fields",
        "MAX_FRAMES": "twoball.verify.output.fields",
        "parse_times": "twoball.verify.output.fields",
        "FORMATS": "twoball.verify.output.series",
        "DEFAULT_SIZE": "twoball.verify.output.render",
        "DEFAULT_ANIMATION_FRAMES": "twoball._files",
        "PLOT_KINDS": "twoball.verify.output.figures",
        "DPI": "twoball.verify.output.figures",
        "WATERFALL_INSTANTS": "twoball.verify.output.figures.waterfall",
        "SWEEP_PARAMETERS": "twoball.verify.sweeps.sweeps",
        "make_grid": "twoball.verify.sweeps.sweeps",
        "STUDIES": "twoball.verify.studies.result",
        "REPRODUCTION_PARTS": ("twoball.verify.reproduce.driver", "PARTS"),
        "REPRODUCTION_DIR": ("twoball.verify.reproduce.driver", "DEFAULT_OUT"),
        "REPRODUCTION_REPORT": ("twoball.verify.reproduce.driver", "REPORT"),
    },
)

__all__: list[str] = []
