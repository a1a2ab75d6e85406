"""The command line's choices and defaults (twoball/_choices.py) equal the model's own.

``_choices`` repeats them with the standard library only, so that ``--help``
imports no numerical library; each copy is compared here with the value of the
module that acts on it.
"""

from __future__ import annotations

import importlib

import pytest

from twoball import _choices

#: name in _choices -> (module, name there, how the model's value reads as the copy)
SOURCES = {
    "STANDARD_GRAVITY": ("twoball.modal.scalings", "STANDARD_GRAVITY", None),
    "SIGMAS": ("twoball.modal.series_options", "FILTER_KINDS", None),
    "HORIZONS": ("twoball.modal.series_options", "HORIZONS", None),
    "GAS_MODELS": ("twoball.modal.stiffness", "GAS_MODELS", tuple),
    "MESH_KINDS": ("twoball.fem_membrane.validate", "MESH_KINDS", None),
    "SPHERE_KINDS": ("twoball.fem_membrane.options", "SPHERE_KINDS", None),
    "DEFAULT_LEVEL": ("twoball.fem_membrane.options", "DEFAULT_LEVEL", None),
    "DEFAULT_ELEMENTS": ("twoball.fem_membrane.options", "DEFAULT_ELEMENTS", None),
    "DEFAULT_ORDER": ("twoball.fem_membrane.options", "DEFAULT_ORDER", None),
    "LEVEL_RANGE": ("twoball.fem_membrane.validate", "LEVEL_RANGE", None),
    "ENERGY_OPTIONS": ("twoball.modal.contact.body", "ENERGY_OPTIONS", None),
    "MAX_MASS_RATIO": ("twoball.modal.contact.body", "MAX_MASS_RATIO", None),
    "FIELD_BACKENDS": ("twoball.verify.output.options", "BACKENDS", None),
    "DEFAULT_FRAMES": ("twoball.verify.output.fields", "DEFAULT_FRAMES", None),
    "FORMATS": ("twoball.verify.output.series", "FORMATS", None),
    "DEFAULT_SIZE": ("twoball.verify.output.render", "DEFAULT_SIZE", tuple),
    "DEFAULT_ANIMATION_FRAMES": ("twoball._files", "DEFAULT_ANIMATION_FRAMES", None),
    "DPI": ("twoball.verify.output.figures", "DPI", None),
    "WATERFALL_INSTANTS": ("twoball.verify.output.figures.waterfall", "WATERFALL_INSTANTS", None),
    "SWEEP_PARAMETERS": ("twoball.verify.sweeps.sweeps", "SWEEP_PARAMETERS", None),
    "STUDIES": ("twoball.verify.studies.result", "STUDIES", None),
    "REPRODUCTION_PARTS": ("twoball.verify.reproduce.driver", "PARTS", tuple),
    "REPRODUCTION_DIR": ("twoball.verify.reproduce.driver", "DEFAULT_OUT", None),
    "REPRODUCTION_REPORT": ("twoball.verify.reproduce.driver", "REPORT", None),
}


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_each_copy_equals_the_models_value(name):
    module, attribute, read = SOURCES[name]
    value = getattr(importlib.import_module(module), attribute)
    value = value if read is None else read(value)
    copy = getattr(_choices, name)
    assert copy == value and type(copy) is type(value), (copy, value)


def test_every_constant_has_its_source():
    constants = {n for n in vars(_choices) if n.isupper()}
    assert constants == set(SOURCES)


def test_the_helpers_are_the_models_own():
    from twoball.modal.pairs import pair
    from twoball.modal.stiffness import flexural_rigidity
    from twoball.verify.output.fields import parse_times
    from twoball.verify.sweeps.sweeps import make_grid

    assert _choices.pair is pair and _choices.flexural_rigidity is flexural_rigidity
    assert _choices.parse_times is parse_times and _choices.make_grid is make_grid
