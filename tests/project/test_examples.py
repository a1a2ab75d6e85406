"""The Examples section of every public verb and object runs, and shows what it prints.

The public surface is what ``import twoball`` offers (``twoball.__all__``); each
of its functions and classes must carry a numpydoc ``Examples`` section, and
every example there runs here as a doctest.
"""

from __future__ import annotations

import doctest
import inspect

import pytest

import twoball

#: Public names that are data or submodules, not documented verbs or objects.
NOT_VERBS = {"__version__", "fem"}


def public_objects() -> dict[str, object]:
    """Name -> the function or class ``twoball`` exports under it (``fem``: its verbs)."""
    objects = {name: getattr(twoball, name) for name in twoball.__all__ if name not in NOT_VERBS}
    for name in twoball.fem.__all__:
        objects[f"fem.{name}"] = getattr(twoball.fem, name)
    return objects


OBJECTS = public_objects()


@pytest.mark.parametrize("name", sorted(OBJECTS))
def test_every_public_object_has_an_examples_section(name):
    doc = inspect.getdoc(OBJECTS[name]) or ""
    assert "\nExamples\n--------\n" in doc, f"twoball.{name} has no Examples section"


@pytest.mark.parametrize("name", sorted(OBJECTS))
def test_examples_run(name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # an example that writes files writes them here
    finder = doctest.DocTestFinder(recurse=False)
    tests = finder.find(OBJECTS[name], f"twoball.{name}", globs={"twoball": twoball})
    examples = [t for t in tests if t.examples]
    assert examples, f"twoball.{name}: no example to run"
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    runner = doctest.DocTestRunner(optionflags=flags)
    for test in examples:
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"twoball.{name}: {result.failed} example(s) failed"
