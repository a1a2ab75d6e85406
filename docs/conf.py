"""Sphinx configuration for the twoball documentation."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# Import twoball from this checkout: twoball/ sits at the repository root and maps
# the parts (modal/, fem_membrane/, verify/) beside it under its own name.
sys.path.insert(0, str(ROOT))

from twoball._version import __version__  # noqa: E402

project = "twoball"
author = "twoball developers"
copyright = "twoball developers"
release = __version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
]

exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]
root_doc = "index"

# autodoc: document in source order; members come from ``:members:`` in api.rst.
autodoc_member_order = "bysource"
autodoc_typehints = "signature"

# numpydoc: do not auto-generate member tables (autodoc lists the members), which
# would otherwise duplicate dataclass fields and properties.
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False

html_theme = "pydata_sphinx_theme"
html_title = f"twoball {release}"
html_theme_options = {
    "navigation_with_keys": False,
}
