"""``python -m twoball``: the same program as the ``twoball`` console script.

Run from a source tree whose dependencies are not installed, a command stops
with one line naming the missing package and the command that installs it
(exit status 2) instead of a traceback: ``twoball: numpy is missing; install
with: pip install .``.  ``twoball --help`` needs none of them.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

#: Import name -> distribution of each package ``pip install twoball`` brings (pyproject.toml).
REQUIRED = {
    "numpy": "numpy",
    "scipy": "scipy",
    "skfem": "scikit-fem",
    "meshio": "meshio",
    "h5py": "h5py",
    "matplotlib": "matplotlib",
    "rich": "rich",
    "threadpoolctl": "threadpoolctl",
}
#: Import name -> (distribution, extra of pyproject.toml) of the optional packages.
OPTIONAL = {
    "pyvista": ("pyvista", "render"),
    "vtk": ("vtk", "render"),
    "imageio": ("imageio", "render"),
    "imageio_ffmpeg": ("imageio-ffmpeg", "render"),
    "dask": ("dask", "dask"),
    "distributed": ("distributed", "dask"),
}
EXIT_MISSING = 2


def missing_message(name: str) -> str | None:
    """The one line for the missing import ``name`` (None if twoball does not depend on it).

    In a source tree (``pyproject.toml`` beside the package) the command
    installs that tree, ``.`` when it is the working folder; otherwise
    ``twoball`` from the package index.  An optional package names its extra.

    >>> missing_message("os.path") is None
    True
    """
    top = name.partition(".")[0]
    if top in REQUIRED:
        distribution, extra = REQUIRED[top], ""
    elif top in OPTIONAL:
        distribution, extra = OPTIONAL[top]
    else:
        return None
    root = Path(__file__).resolve().parent.parent
    if (root / "pyproject.toml").is_file():
        try:
            here = Path.cwd().resolve() == root
        except OSError:  # the working folder was removed
            here = False
        target = "." if here else os.fspath(root)
    else:
        target = "twoball"
    spec = f"'{target}[{extra}]'" if extra else target
    return f"twoball: {distribution} is missing; install with: pip install {spec}"


def run() -> int:
    """:func:`twoball.cli.main.main`, a missing dependency said in one line."""
    try:
        from twoball.cli.main import main

        return main()
    except ModuleNotFoundError as error:
        line = missing_message(error.name or "")
        if line is None:
            raise
        print(line, file=sys.stderr)
        return EXIT_MISSING


if __name__ == "__main__":
    raise SystemExit(run())
