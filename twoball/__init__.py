"""twoball -- lift-off from a vibrating spherical membrane (the two-ball bounce).

The public API is loaded lazily: ``import twoball`` costs almost nothing, and
each name below imports its module on first use.
"""

from __future__ import annotations

import os as _os

from ._version import __version__

# In a source checkout the parts (modal/, fem_membrane/, verify/) sit beside this
# folder; installed, setuptools maps them to twoball/modal, ... (pyproject.toml).
_HERE = _os.path.dirname(__file__)
if not _os.path.isdir(_os.path.join(_HERE, "modal")):
    __path__.append(_os.path.dirname(_HERE))  # noqa: F821 -- the package's own __path__

__all__ = ["__version__"]
