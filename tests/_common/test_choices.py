"""One source of the choices and defaults: ``twoball/_common/choices.py`` (standard library only).

The option objects that act on a choice and the command line's ``--help`` read
it from there, so no value is written twice.  Each module that acts on a
constant holds the very object of ``choices`` (not an equal copy); the option
objects accept exactly the listed values and refuse others naming them; the
parser offers the same values and defaults.  That ``twoball SUBCOMMAND --help``
loads no numerical library is tested in tests/project/test_startup.py.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import sys

import pytest

import twoball
from twoball._common import choices
from twoball.cli.main import full_parser

#: choice -> the modules (and their names for it) that act on it
USERS = {
    "STANDARD_GRAVITY": [("twoball.modal.scalings", "STANDARD_GRAVITY")],
    "FILTER_KINDS": [
        ("twoball.modal.filters", "FILTER_KINDS"),
        ("twoball._solvers", "FILTER_KINDS"),
    ],
    "HORIZONS": [("twoball.modal.liftoff", "HORIZONS"), ("twoball._solvers", "HORIZONS")],
    "GAS_MODELS": [
        ("twoball.modal.stiffness", "GAS_LAWS"),
        ("twoball.modal.floor.options", "GAS_LAWS"),
    ],
    "MESH_KINDS": [
        ("twoball.fem_membrane.options", "MESH_KINDS"),
        ("twoball.fem_membrane.build", "MESH_KINDS"),
    ],
    "SPHERE_KINDS": [("twoball.fem_membrane.options", "SPHERE_KINDS")],
    "DEFAULT_LEVEL": [("twoball.fem_membrane.options", "DEFAULT_LEVEL")],
    "DEFAULT_ELEMENTS": [("twoball.fem_membrane.options", "DEFAULT_ELEMENTS")],
    "DEFAULT_ORDER": [("twoball.fem_membrane.options", "DEFAULT_ORDER")],
    "LEVEL_RANGE": [("twoball.fem_membrane.validate", "LEVEL_RANGE")],
    "ROUTES": [("twoball._solvers", "ROUTES"), ("twoball.fem_membrane.krylov", "ROUTES")],
    "ENERGY_OPTIONS": [("twoball.modal.contact.body", "ENERGY_OPTIONS")],
    "MAX_MASS_RATIO": [("twoball.modal.contact.body", "MAX_MASS_RATIO")],
    "FIELD_BACKENDS": [("twoball.verify.output.options", "FIELD_BACKENDS")],
    "DEFAULT_FRAMES": [("twoball.verify.output.fields", "DEFAULT_FRAMES")],
    "FORMATS": [("twoball.verify.output.series", "FORMATS")],
    "DEFAULT_SIZE": [("twoball.verify.output.render", "DEFAULT_SIZE")],
    "DEFAULT_ANIMATION_FRAMES": [("twoball._fields", "DEFAULT_ANIMATION_FRAMES")],
    "DPI": [("twoball.verify.output.figures", "DPI")],
    "WATERFALL_INSTANTS": [("twoball.verify.output.figures.waterfall", "WATERFALL_INSTANTS")],
    "SWEEP_PARAMETERS": [("twoball.verify.sweeps.sweeps", "SWEEP_PARAMETERS")],
    "STUDIES": [("twoball.verify.studies.result", "STUDIES")],
    "REPRODUCTION_PARTS": [("twoball.verify.reproduce.driver", "REPRODUCTION_PARTS")],
    "REPRODUCTION_DIR": [("twoball.verify.reproduce.driver", "REPRODUCTION_DIR")],
    "REPRODUCTION_REPORT": [("twoball.verify.reproduce.driver", "REPRODUCTION_REPORT")],
    "FIT_MODELS": [("twoball.cli.fit", "_choices.FIT_MODELS")],
    "FIT_PARAMETERS": [("twoball.verify.fit.models", "FIT_PARAMETERS")],
    "FIT_MODEL_COLUMNS": [("twoball.verify.fit.models", "FIT_MODEL_COLUMNS")],
    "MEASURED_COLUMNS": [("twoball.verify.fit.data", "MEASURED_COLUMNS")],
    "SIGMA_PREFIX": [("twoball.verify.fit.data", "SIGMA_PREFIX")],
}


@pytest.mark.parametrize("name", sorted(USERS))
def test_each_user_holds_the_choices_own_object(name):
    """Not an equal copy: the same object, so a change in choices.py reaches every user."""
    value = getattr(choices, name)
    for module, attribute in USERS[name]:
        held = importlib.import_module(module)
        for part in attribute.split("."):
            held = getattr(held, part)
        assert held is value, (module, attribute, held, value)


def test_every_choice_has_a_user_and_is_exported():
    constants = {n for n in vars(choices) if n.isupper()}
    assert constants == set(choices.__all__) == set(USERS)


def test_choices_imports_the_standard_library_only():
    tree = ast.parse(inspect.getsource(choices))
    imported = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            imported |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            imported.add((node.module or "").split(".")[0])
    assert imported <= set(sys.stdlib_module_names) | {"__future__"}, imported


def test_the_command_lines_helpers_are_the_models_own():
    """``twoball/_lookup.py`` (what the command line calls at run time) loads the model's
    functions themselves, on first use."""
    from twoball import _lookup
    from twoball.modal.pairs import pair
    from twoball.modal.stiffness import flexural_rigidity
    from twoball.verify.output.fields import parse_times
    from twoball.verify.sweeps.sweeps import make_grid

    assert _lookup.pair is pair and _lookup.flexural_rigidity is flexural_rigidity
    assert _lookup.parse_times is parse_times and _lookup.make_grid is make_grid


# --- the option objects act on exactly the listed values ------------------------------


@pytest.mark.parametrize(
    ("name", "values", "build"),
    [
        ("sigma", choices.FILTER_KINDS, lambda v: twoball.ClosedForm(sigma=v)),
        ("recontact", choices.HORIZONS, lambda v: twoball.ClosedForm(recontact=v)),
        ("route", choices.ROUTES, lambda v: twoball.Superposition("axisym", route=v)),
        ("energy", choices.ENERGY_OPTIONS, lambda v: twoball.Body(0.1, energy=v)),
        ("gas", choices.GAS_MODELS, lambda v: twoball.Drop(gas=v)),
        ("backends", choices.FIELD_BACKENDS, lambda v: twoball.PlotOptions(backends=[v])),
    ],
)
def test_the_option_objects_take_the_listed_values_and_name_them(name, values, build):
    for value in values:
        build(value)  # each listed value is taken
    with pytest.raises(twoball.ParameterError) as caught:
        build("bogus")
    assert caught.value.name == name
    assert all(value in caught.value.valid for value in values), caught.value.valid


def test_the_option_objects_defaults_and_limits_are_the_choices():
    mesh = twoball.MeshOptions()
    assert (mesh.kind, mesh.level, mesh.order) == ("sphere", choices.DEFAULT_LEVEL, 2)
    assert mesh.order == choices.DEFAULT_ORDER
    assert twoball.MeshOptions("axisym").elements == choices.DEFAULT_ELEMENTS
    for kind in choices.MESH_KINDS:
        assert twoball.MeshOptions(kind).kind == kind
    assert twoball.Body(choices.MAX_MASS_RATIO).mass_ratio == choices.MAX_MASS_RATIO
    with pytest.raises(twoball.ParameterError) as caught:
        twoball.Body(choices.MAX_MASS_RATIO * (1 + 1e-12))
    assert caught.value.name == "mass_ratio" and f"{choices.MAX_MASS_RATIO:g}" in str(caught.value)
    low, high = choices.LEVEL_RANGE
    assert twoball.MeshOptions(level=low).level == low
    with pytest.raises(twoball.ParameterError) as caught:
        twoball.MeshOptions(level=high + 1)
    assert caught.value.name == "level"


# --- the command line offers the same values --------------------------------------------


def _subcommands() -> dict:
    (sub,) = (a for a in full_parser()._actions if isinstance(a.choices, dict))
    return sub.choices


def _option(parser, flag: str):
    return next(a for a in parser._actions if flag in a.option_strings)


def test_the_command_lines_choices_are_the_choices():
    commands = _subcommands()
    for command in ("liftoff", "sweep", "export", "render", "verify"):
        parser = commands[command]
        assert tuple(_option(parser, "--sigma").choices) == choices.FILTER_KINDS, command
        assert tuple(_option(parser, "--recontact").choices) == choices.HORIZONS, command
    swept = _option(commands["sweep"], "--param").choices
    assert set(choices.SWEEP_PARAMETERS) <= set(swept)
    for command in ("liftoff", "sweep", "export"):
        energy = _option(commands[command], "--energy").help
        assert " or ".join(choices.ENERGY_OPTIONS) in energy, (command, energy)


def test_the_command_lines_defaults_are_the_choices():
    commands = _subcommands()
    liftoff = commands["liftoff"]
    assert f"(default {choices.DEFAULT_LEVEL})" in _option(liftoff, "--level").help
    assert f"(default {choices.DEFAULT_ELEMENTS})" in _option(liftoff, "--elements").help
    assert f"(default {choices.DEFAULT_ORDER})" in _option(liftoff, "--order").help
    for kind in choices.MESH_KINDS:
        assert kind in _option(liftoff, "--mesh").help
    render = commands["render"]
    frames = _option(render, "--frames").help
    assert f"(default {choices.DEFAULT_ANIMATION_FRAMES})" in frames, frames
    width, height = choices.DEFAULT_SIZE
    assert _option(render, "--size").default == f"{width}x{height}"
    assert f"(default {choices.DEFAULT_FRAMES};" in _option(commands["export"], "--frames").help
