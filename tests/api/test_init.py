"""The package face (twoball/__init__.py): its public names and version."""

from __future__ import annotations

import re

import twoball


def test_public_names_and_version():
    for name in ("Case", "liftoff", "sweep", "fem", "converge", "verify", "export", "render"):
        assert name in dir(twoball) and getattr(twoball, name) is not None
    assert twoball.ParameterError is twoball._common.errors.ParameterError
    assert re.fullmatch(r"\d+\.\d+(\.\d+)?\S*", twoball.__version__)
