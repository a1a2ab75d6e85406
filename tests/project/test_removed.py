"""What version 0.3 removed has no shim: the 0.2 keywords, Stepping, Series, the callable verify.

The project was a week old: the keywords of version 0.2 and the
option bags they moved into are gone, and a call that still uses them is a
``TypeError`` naming the keyword (Python's own, before any work), never a
warning that lets it run.  The new spellings are tested with each verb.
"""

from __future__ import annotations

import importlib
import warnings

import pytest

import twoball

#: verb -> keywords of version 0.2 (or of the option bags that replaced them) it no longer takes
REMOVED = {
    "liftoff": (
        "level", "t_end", "mass_ratio", "contact_radius", "sigma", "recontact",
        "damping_model", "backend", "mesh", "stepping", "series",
    ),
    "bounce": ("backend", "mesh", "stepping"),
    "sweep": (
        "t_end", "sigma", "recontact", "contact_radius", "scheduler", "backend", "mesh",
        "stepping", "series",
    ),
    "export": ("level", "order", "times", "time", "format", "mesh", "stepping", "series"),
    "render": ("level", "time", "size", "warp", "frames", "mesh", "stepping", "series"),
    "plot": ("dpi", "levels", "orders", "backends", "mesh", "stepping", "series"),
    "converge": ("sigma", "recontact", "t_end", "stepping", "series"),
    "check": ("sigma", "recontact", "t_end", "series"),
    "reproduce": ("scheduler",),
}  # fmt: skip

#: the positional arguments each verb needs before its keywords
LEADING = {"export": ("x.vtu",), "render": ("x.png",), "plot": ("pole", "p.png")}


@pytest.mark.parametrize(
    ("verb", "keyword"), [(verb, keyword) for verb, keys in REMOVED.items() for keyword in keys]
)
def test_a_removed_keyword_is_a_type_error_without_a_warning(verb, keyword, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(TypeError, match=f"unexpected keyword argument '{keyword}'"):
            getattr(twoball, verb)(*LEADING.get(verb, ()), **{keyword: None})
    assert not caught, [str(w.message) for w in caught]
    assert list(tmp_path.iterdir()) == []  # refused before any work


def test_fem_eigen_takes_a_mesh_object_not_its_old_keywords():
    for keyword in ("level", "elements", "order"):
        with pytest.raises(TypeError, match=f"unexpected keyword argument '{keyword}'"):
            twoball.fem.eigen("axisym", **{keyword: 2})


@pytest.mark.parametrize("name", ["Stepping", "Series", "verify"])
def test_the_option_bags_and_the_callable_verify_are_gone(name):
    """``twoball.verify`` is the subpackage only (the verb is ``twoball.check``)."""
    assert name not in twoball.__all__
    if name == "verify":
        package = importlib.import_module("twoball.verify")
        assert twoball.verify is package and not callable(twoball.verify)
        assert callable(twoball.check)
    else:
        with pytest.raises(AttributeError):
            getattr(twoball, name)


def test_fem_solve_is_gone():
    """The lift-off on finite elements is liftoff(solver=Superposition(...)); fem keeps spectra."""
    assert not hasattr(twoball.fem, "solve") and "solve" not in twoball.fem.__all__
    assert all(name.endswith("eigen") for name in twoball.fem.__all__)


@pytest.mark.parametrize("module", ["twoball._choices", "twoball._bundles", "twoball._files"])
def test_the_removed_modules_are_gone(module):
    with pytest.raises(ModuleNotFoundError):
        importlib.import_module(module)


def test_keywords_that_never_existed_are_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'levle'"):
        twoball.liftoff(levle=2)
