"""Matplotlib figures of twoball, one module per kind, and the one way to save them.

=================  ===========================================================
module             figures
=================  ===========================================================
``style``          the one style: fonts, colours, labels with units, limits
``waterfall``      u(phi) at many instants, closed form and FE nodes (Fig. 6)
``pole``           pole displacement, velocity, acceleration with lift-off
``eigen``          FE eigenvalue errors against l(l+1), eq. (3.11)
``energy``         energy decay of time stepping against the modal closed form
``study``          convergence studies: error against step, expected slopes
``sweep``          lift-off sweeps over one parameter or a grid of two
``precursor``      the pole before the wave front under each damping law
=================  ===========================================================

Every ``*_figure`` function returns a :class:`matplotlib.figure.Figure` (no
pyplot, no global state, Agg canvas: no window, any thread), drawn in the style
of :mod:`.style`; :func:`save_figure` writes one in any format matplotlib
writes (PDF, SVG, EPS, PNG, ...; chosen by the file suffix) through
:func:`twoball._common.staging.staged_file`, so a file is replaced whole or not at all.
matplotlib is imported only by these modules.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from twoball._common.choices import DPI

#: Resolution of raster files (PNG, JPEG, TIFF, ...) unless asked otherwise [dots per inch].
#: Accepted resolutions [dots per inch]; outside, a figure is too coarse to read or too big.
DPI_RANGE = (50, 1200)
#: Resolution of the PNGs of the verify, converge and reproduce reports (read on screen).
REPORT_DPI = 150
PLOT_KINDS: tuple[str, ...] = ("waterfall", "pole", "eigen", "precursor")
LABELS = {"fem": "finite elements", "legendre": "closed form (3.16)"}
#: Formats matplotlib lists but cannot write without more software (pgf needs LaTeX).
UNSUPPORTED_FORMATS = frozenset({"pgf"})


def figure_formats() -> dict[str, str]:
    """Suffix (without dot) -> description of every format matplotlib can write here."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    formats = FigureCanvasAgg(Figure()).get_supported_filetypes()
    return {k: v for k, v in formats.items() if k not in UNSUPPORTED_FORMATS}


def figure_format(path: str | os.PathLike[str], flag: str = "out") -> str:
    """The format of ``path`` from its suffix (``pdf``, ``svg``, ``png``, ...).

    Raises
    ------
    ParameterError
        Naming ``flag`` if the suffix is not a format matplotlib writes.
    """
    from twoball._common.errors import ParameterError

    suffix = Path(path).suffix.lower().lstrip(".")
    formats = figure_formats()
    if suffix not in formats:
        valid = "a file name ending in " + ", ".join(f".{k}" for k in sorted(formats))
        raise ParameterError(flag, valid, str(path))
    return suffix


def check_dpi(dpi: float | None, flag: str = "dpi") -> float:
    """``dpi`` checked against :data:`DPI_RANGE`; None gives :data:`DPI`."""
    from twoball._common.errors import ParameterError

    if dpi is None:
        return float(DPI)
    low, high = DPI_RANGE
    valid = f"a number of dots per inch in [{low}, {high}]"
    if isinstance(dpi, bool) or not isinstance(dpi, int | float):
        raise ParameterError(flag, valid, dpi)
    if not (math.isfinite(dpi) and low <= dpi <= high):
        raise ParameterError(flag, valid, dpi)
    return float(dpi)


def new_figure(width: float, height: float) -> Any:
    """A constrained-layout :class:`matplotlib.figure.Figure` of ``width`` x ``height`` inches."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


def save_figure(
    figure: Any,
    path: str | os.PathLike[str],
    flag: str = "out",
    dpi: float | None = None,
    dpi_flag: str = "dpi",
) -> Path:
    """Write ``figure`` to ``path`` in the format of its suffix, atomically.

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure.
    path : path-like
        Output file; ``.pdf``, ``.svg``, ``.eps``, ``.png``, ... (any format
        matplotlib writes).  Written beside, then renamed into place
        (:mod:`twoball._common.staging`).
    flag, dpi_flag : str
        Names of the file and resolution parameters in error messages.
    dpi : float, optional
        Resolution of raster formats [dots per inch], in :data:`DPI_RANGE`;
        default :data:`DPI`.  Vector formats keep their lines and text as such
        (only embedded images use it).

    Raises
    ------
    ParameterError
        Naming ``flag`` if ``path`` has no known figure suffix, is a folder or a
        symbolic link, or its folder is missing or not writable; naming
        ``dpi_flag`` if ``dpi`` is out of range.
    OSError
        Writing failed (full disk, ...); it names ``path``, and ``path`` is unchanged.
    """
    import matplotlib

    from twoball._common.staging import check_path_type, staged_file
    from twoball.verify.output.figures.style import style_rc

    out = Path(check_path_type(path, flag)).expanduser()
    kind = figure_format(out, flag)
    resolution = check_dpi(dpi, dpi_flag)
    metadata = {"Creator": "twoball"} if kind in ("pdf", "svg", "png", "eps", "ps") else None
    # the style's rcParams again: colours named "C0".."C5" resolve when drawn
    with staged_file(out, flag) as scratch, matplotlib.rc_context(style_rc()):
        figure.savefig(scratch, dpi=resolution, format=kind, metadata=metadata)
    return out


__all__ = [
    "DPI",
    "DPI_RANGE",
    "LABELS",
    "PLOT_KINDS",
    "REPORT_DPI",
    "UNSUPPORTED_FORMATS",
    "check_dpi",
    "figure_format",
    "figure_formats",
    "new_figure",
    "save_figure",
]
