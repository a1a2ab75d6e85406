"""The model's few helpers that the command line calls at run time, loaded on first use.

The command line imports only the face and the ground floor, so that ``--help``
loads no numerical library (the choices it shows come from
:mod:`twoball._common.choices`); these names are loaded from their modules the
first time they are used (PEP 562).
"""

from __future__ import annotations

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "flexural_rigidity": "twoball.modal.stiffness",
        "pair": "twoball.modal.pairs",
        "MEASURED": "twoball.modal.presets",
        "parse_times": "twoball.verify.output.fields",
        "make_grid": "twoball.verify.sweeps.sweeps",
    },
)

__all__: list[str] = []
