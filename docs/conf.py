"""Sphinx configuration for the twoball documentation."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# Import twoball from this checkout: twoball/ sits at the repository root and maps
# the parts (modal/, fem_membrane/, verify/) beside it under its own name.
sys.path.insert(0, str(ROOT))
# this folder too, for the gallery's order (gallery_order.py)
sys.path.insert(0, str(ROOT / "docs"))

from twoball._version import __version__  # noqa: E402

project = "twoball"
author = "twoball developers"
copyright = "twoball developers"
release = __version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "sphinxarg.ext",
    "sphinx_gallery.gen_gallery",
    "numpydoc",
]

exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]
root_doc = "index"
# Text stays as typed: no curly quotes, and ``--flag`` is not turned into an en dash
# followed by the flag's name (the CLI reference shows every option as written).
smartquotes = False

# autodoc: document in source order; members come from ``:members:`` in api.rst.
autodoc_member_order = "bysource"
autodoc_typehints = "signature"

# numpydoc: do not auto-generate member tables (autodoc lists the members), which
# would otherwise duplicate dataclass fields and properties.
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False


def _bundled_mathjax() -> Path:
    """The folder holding ``mathjax/`` (MathJax 3) in the sphinx-mathjax-offline package."""
    spec = importlib.util.find_spec("sphinx-mathjax-offline")  # its folder name has hyphens
    if spec is None or spec.origin is None:
        raise RuntimeError("the docs need the docs extra: pip install '.[docs]'")
    return Path(spec.origin).parent / "static"


# Formulas render without a network: MathJax is copied into _static/mathjax/
# and loaded from there (Sphinx's default mathjax_path is a CDN).  The package
# sphinx-mathjax-offline only supplies the files; its extension is not loaded
# (it copies them after the build and declares no parallel safety, which
# fails ``-W -j N``).
html_static_path = [str(_bundled_mathjax())]
mathjax_path = "mathjax/tex-chtml.js"

html_theme = "pydata_sphinx_theme"
html_title = f"twoball {release}"
html_theme_options = {
    "navigation_with_keys": False,
    # The navbar holds the sections of index.rst's toctree; the left sidebar
    # ("Section Navigation") lists the pages of the current section.
    "header_links_before_dropdown": 6,
    "show_nav_level": 1,
    "navigation_depth": 3,
}

# Examples gallery: every script in examples/ runs at build time and its
# figures are regenerated; the output folder docs/auto_examples/ is generated
# (git-ignored).
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "abort_on_example_error": True,
    "remove_config_comments": True,
    "within_subsection_order": "gallery_order.example_number",  # plot_10 after plot_9
    "min_reported_time": 10**9,  # no wall-clock times on the pages
    "write_computation_times": False,
}


def _figures(script: str):  # noqa: ANN202
    """A builder-inited hook that runs ``docs/<script>.py``'s ``main()`` at every build."""

    def draw(app) -> None:  # noqa: ANN001
        import importlib.util

        spec = importlib.util.spec_from_file_location(
            script, Path(__file__).resolve().parent / f"{script}.py"
        )
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        module.main()

    return draw


def setup(app):  # noqa: ANN001, ANN201
    # docs/_static/shell/causality.png (docs/shell.rst), docs/_static/fit/drops_fit.png
    # (docs/fit.rst), drawn anew at every build
    for script in ("make_shell_figures", "make_fit_figures"):
        app.connect("builder-inited", _figures(script))
