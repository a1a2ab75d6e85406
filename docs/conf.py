"""Sphinx configuration for the twoball documentation."""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# The packages (modal, fem_membrane, verify) sit flat at the repository root.
sys.path.insert(0, str(ROOT))

with (ROOT / "pyproject.toml").open("rb") as fh:
    _project = tomllib.load(fh)["project"]
# The version is dynamic (pyproject.toml reads twoball/_version.py): read it there.
_version: dict[str, str] = {}
exec((ROOT / "twoball" / "_version.py").read_text(), _version)  # noqa: S102

project = "twoball"
author = "twoball developers"
copyright = "twoball developers"
release = _project.get("version") or _version["__version__"]
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
