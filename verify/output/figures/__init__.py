"""Matplotlib figures of twoball, one module per kind, and the one way to save them.

=================  ===========================================================
module             figures
=================  ===========================================================
``waterfall``      u(phi) at many instants, closed form and FE nodes (Fig. 6)
``pole``           pole displacement, velocity, acceleration with lift-off
``eigen``          FE eigenvalue errors against l(l+1), eq. (3.11)
``energy``         energy decay of time stepping against the modal closed form
``study``          convergence studies: error against step, expected slopes
``sweep``          lift-off sweeps over one parameter or a grid of two
=================  ===========================================================

Every ``*_figure`` function returns a :class:`matplotlib.figure.Figure` (no
pyplot, no global state, Agg canvas: no window, any thread); :func:`save_figure`
writes one as PNG through :func:`twoball.staging.staged_file`, so a PNG is
replaced whole or not at all.  matplotlib is imported only by these modules.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

DPI = 110
PLOT_KINDS: tuple[str, ...] = ("waterfall", "pole", "eigen")
LABELS = {"fem": "finite elements", "legendre": "closed form (3.16)"}


def new_figure(width: float, height: float) -> Any:
    """A constrained-layout :class:`matplotlib.figure.Figure` of ``width`` x ``height`` inches."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


def save_figure(
    figure: Any, path: str | os.PathLike[str], flag: str = "--out", dpi: float = DPI
) -> Path:
    """Write ``figure`` as PNG to ``path``, atomically (see :mod:`twoball.staging`).

    Raises
    ------
    ParameterError
        Naming ``flag`` if ``path`` does not end in ``.png``, is a folder or a
        symbolic link, or its folder is missing or not writable.
    OSError
        Writing failed (full disk, ...); it names ``path``, and ``path`` is unchanged.
    """
    from twoball.modal.errors import ParameterError

    from twoball.staging import staged_file

    out = Path(path).expanduser()
    if out.suffix.lower() != ".png":
        raise ParameterError(flag, "a file name ending in .png", str(path))
    with staged_file(out, flag) as scratch:
        figure.savefig(scratch, dpi=dpi, format="png")
    return out


REPORT_DPI = 120  # PNGs of the verify and converge reports
