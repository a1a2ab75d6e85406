"""The one figure style of twoball: fonts, colours, labels with units, curve limits.

Every figure of ``plot``, ``verify``, ``converge``, ``reproduce``, ``bounce
--plot`` and ``liftoff --plot`` is built inside :func:`styled` (a decorator
applying :data:`STYLE` through :func:`matplotlib.rc_context`, so no global state
changes; the figure carries :data:`MARK`) and labels its axes with
:func:`label`: a mathtext symbol and its SI unit in brackets, or
:data:`DIMENSIONLESS` for a pure number.  Text outside mathtext writes its
symbols in Unicode (φ, μ, |v₀|), never as ASCII stand-ins; no text is smaller
than :data:`MIN_FONT_PT` at the saved size; legends go where they cover no data
(``loc="best"`` or beside the panel); titles name the ball, pair or preset.  An axis carries at most
:data:`MAX_CURVES` curves (plus reference lines); crowded data is split into
small multiples with :func:`chunks`.  Comparisons of two solutions get a
difference panel below (:func:`difference_limits` zooms it past the first
samples of a filtered series).

matplotlib is imported only when a styled function runs (``import twoball``
stays light).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import numpy as np

#: The unit of a pure number, shown in the axis label like any other unit.
DIMENSIONLESS = "[–]"
#: Most curves (data lines) drawn on one axis; reference lines come on top.
MAX_CURVES = 6
#: Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")
#: Line styles cycled with the colours, so curves also differ in greyscale print.
LINE_STYLES = ("-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1)))
#: Marker of a lift-off instant, used the same way on every figure.
LIFTOFF_MARKER = "o"
#: ``gid`` of an axis holding a stack of shifted, non-overlapping curves (a waterfall):
#: the one kind of axis exempt from :data:`MAX_CURVES`.
STACKED = "twoball-stacked-curves"
#: Colour of reference lines (-g, expected slopes, zero).
REFERENCE_COLOUR = "0.25"

STYLE: dict[str, Any] = {
    "font.size": 9.0,
    "axes.titlesize": 9.5,
    "axes.labelsize": 9.0,
    "xtick.labelsize": 8.0,
    "ytick.labelsize": 8.0,
    "legend.fontsize": 8.0,
    "legend.framealpha": 0.85,
    "figure.titlesize": 10.5,
    "lines.linewidth": 1.2,
    "lines.markersize": 4.0,
    "axes.grid": True,
    "axes.grid.which": "both",
    "grid.alpha": 0.3,
    "grid.linewidth": 0.5,
    "axes.linewidth": 0.8,
    "mathtext.fontset": "dejavusans",
    "pdf.fonttype": 42,  # TrueType in PDF/PS: text stays text (journals ask for this)
    "ps.fonttype": 42,
    "svg.fonttype": "path",
    "savefig.facecolor": "white",
    "image.cmap": "viridis",
}

#: Smallest font size of any text at the saved size [pt] (tick labels and legends).
MIN_FONT_PT = 8.0
#: Attribute set (True) on every figure a :func:`styled` builder returns.
MARK = "twoball_styled"

Builder = TypeVar("Builder", bound=Callable[..., Any])


def style_rc() -> dict[str, Any]:
    """:data:`STYLE` with its colour and line-style cycle: the rcParams of every figure.

    Saving needs them too: a colour given as ``"C1"`` is looked up in the cycle
    when the figure is drawn, not when the line is made.
    """
    from cycler import cycler

    rc = dict(STYLE)
    rc["axes.prop_cycle"] = cycler(color=COLOURS[: len(LINE_STYLES)]) + cycler(
        linestyle=LINE_STYLES
    )
    return rc


def styled(builder: Builder) -> Builder:
    """Run ``builder`` (which creates and draws a figure) under :data:`STYLE`.

    The figure it returns carries the attribute :data:`MARK`.
    """

    @functools.wraps(builder)
    def run(*args: Any, **kwargs: Any) -> Any:
        import matplotlib

        with matplotlib.rc_context(style_rc()):
            made = builder(*args, **kwargs)
            if hasattr(made, "savefig"):  # a figure: it says it was built in the style
                _fix_cycle_colours(made)
                setattr(made, MARK, True)
        return made

    return run  # type: ignore[return-value]


def _fix_cycle_colours(figure: Any) -> None:
    """Replace colours named ``"C0"``.. on lines and texts by the style's own (hex).

    matplotlib looks such a name up in the colour cycle when it draws, so a
    figure saved outside the style would take the default cycle's colours.
    """
    import re

    from matplotlib.colors import to_hex
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

    cycle = re.compile(r"C\d+")
    for line in figure.findobj(Line2D):
        for get, put in (
            (line.get_color, line.set_color),
            (line.get_markerfacecolor, line.set_markerfacecolor),
            (line.get_markeredgecolor, line.set_markeredgecolor),
        ):
            value = get()
            if isinstance(value, str) and cycle.fullmatch(value):
                put(to_hex(value))
    for text in figure.findobj(Text):
        value = text.get_color()
        if isinstance(value, str) and cycle.fullmatch(value):
            text.set_color(to_hex(value))


def label(quantity: str, unit: str | None) -> str:
    """Axis label ``quantity [unit]``; ``unit`` None or ``""``: dimensionless ``[–]``.

    >>> label("$t$", "ms")
    '$t$ [ms]'
    >>> label(r"$v_l/|v_0|$", None)
    '$v_l/|v_0|$ [–]'
    """
    return f"{quantity} {DIMENSIONLESS}" if not unit else f"{quantity} [{unit}]"


def chunks(items: Sequence[Any], size: int = MAX_CURVES) -> list[list[Any]]:
    """``items`` in consecutive groups of at most ``size``, as evenly filled as possible."""
    items = list(items)
    if not items:
        return []
    count = -(-len(items) // size)
    per = -(-len(items) // count)
    return [items[k : k + per] for k in range(0, len(items), per)]


def grid_shape(panels: int, columns: int = 3) -> tuple[int, int]:
    """Rows and columns of a small-multiples grid of ``panels`` axes."""
    columns = max(1, min(columns, panels))
    return -(-panels // columns), columns


def difference_limits(values: np.ndarray, share: float = 99.0) -> tuple[float, float] | None:
    """Symmetric y limits covering ``share`` % of ``values`` (None if all zero or empty).

    A percentile: the first samples of a filtered series can dwarf the rest.
    """
    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite)]
    if not finite.size:
        return None
    spread = float(np.percentile(finite, share))
    if spread <= 0:
        return None
    return -1.1 * spread, 1.1 * spread


#: SI prefixes tried for a difference panel: factor, prefix (mathtext).
PREFIXES = ((1.0, ""), (1e3, "m"), (1e6, r"$\mu$"), (1e9, "n"))


def difference_unit(values_si: np.ndarray, unit: str) -> tuple[float, str]:
    """Factor and unit that put the typical size of ``values_si`` between 0.1 and 100.

    ``unit`` is the SI unit (``"m"``, ``"m/s"``, ``"m/s$^2$"``); the prefix goes
    on its first symbol (``"mm/s"``, ``"$\\mu$m"``).
    """
    finite = np.abs(values_si[np.isfinite(values_si)])
    size = float(np.percentile(finite, 99.0)) if finite.size else 0.0
    for factor, prefix in PREFIXES:
        if size * factor >= 0.1:
            return factor, prefix + unit
    factor, prefix = PREFIXES[-1]
    return factor, prefix + unit


def subject(case: Any) -> str:
    """What a figure shows, for its title: the case's preset (``basketball``) or ``custom ball``."""
    return getattr(case, "preset_name", None) or "custom ball"


def time_label(after: str = "") -> str:
    """The time axis label, in ms (``after`` appended, e.g. "after maximal compression")."""
    return label("$t$", "ms") + (f" {after}" if after else "")


def curves(axis: Any) -> list[Any]:
    """The data curves of ``axis``: drawn lines through more than two points.

    Not counted: reference rules and slopes (two points), single markers and
    marker-only series (scattered dots).
    """
    return [
        line
        for line in axis.get_lines()
        if len(np.atleast_1d(line.get_xdata())) > 2 and line.get_linestyle() not in ("None", "")
    ]
