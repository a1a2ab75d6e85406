"""The user's measured points drawn over the model's figures (``--measured FILE.csv``).

The rows of a measured file (:mod:`twoball.verify.fit.data`: ``v0_m_s``,
``gap_m``, ``phi_a_rad``, ``v1_m_s``, ``v2_m_s``, ``t_liftoff_s``) go on the
panels that show the same quantity:

* a lift-off sweep (:func:`~twoball.verify.output.figures.sweep.sweep_figure`,
  one parameter): ``v1_m_s / |v0|`` on the ``v_l/|v0|`` panel and
  ``t_liftoff_s`` on the ``t_l`` panel (:func:`sweep_overlay`);
* a sweep of the whole bounce
  (:func:`~twoball.verify.output.figures.bounce.gap_figure`): ``v1_m_s / |v0|``,
  ``v2_m_s / |v0|`` and ``t_liftoff_s`` on their panels; a sweep of the drop
  (:func:`~twoball.verify.output.figures.bounce.speeds_figure`,
  :func:`~twoball.verify.output.figures.drop_sweep.drop_sweep_figure`):
  ``phi_a_rad`` on the contact angle's panel, ``v2_m_s / |v0|`` on e2's
  (:func:`bounce_sweep_overlay`);
* one drop or whole bounce (:func:`~twoball.verify.output.figures.bounce.drop_figure`,
  :func:`~twoball.verify.output.figures.bounce.whole_figure`): ``v1_m_s`` and
  ``v2_m_s`` as lines on the velocity panel, ``t_liftoff_s`` as a marker
  there, ``phi_a_rad`` as a line on the contact angle's panel
  (:func:`bounce_overlay`).

A row is placed at its own value of the swept input (``v0_m_s`` for a v0
sweep, ``gap_m`` for a gap sweep); against a parameter no column holds (the
damping, the mass ratio) its measurement is a horizontal line.  Rows measured
at another ``|v0|`` (or gap) than the figure's are left out.  Each plan says in
its :attr:`Overlay.notes` what it does not draw; :func:`draw_overlay` draws it.

Examples
--------
>>> data = Measurements.from_columns({"v0_m_s": [4.1, 3.0], "v1_m_s": [3.7, 2.5]})
>>> plan = sweep_overlay(data, "damping", 4.1)
>>> plan.notes
('1 row(s) of rows at another |v0| than 4.1 m/s not drawn',)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from twoball.verify.fit.data import Measurements
from twoball.verify.output.figures.style import styled

__all__ = [
    "MEASURED_COLOUR",
    "Overlay",
    "bounce_overlay",
    "bounce_sweep_overlay",
    "draw_overlay",
    "drawable",
    "overlay_for",
    "sweep_overlay",
]

#: Colour and marker of the measured points on every figure.
MEASURED_COLOUR = "#882255"
MARKER = "X"
#: Dashes of measured values drawn as lines (one per quantity on a panel).
LINE_DASHES = ((0, (4, 2)), (0, (1, 1.5)), (0, (6, 2, 1, 2)))
#: Relative agreement of a row's |v0| (and absolute of its gap [m]) with the figure's.
SAME_V0 = 1e-6
SAME_GAP = 1e-9


@dataclass(frozen=True)
class Layer:
    """Measured values for one panel: the panel's y-label words, x (None: lines), y, sigma."""

    panel: tuple[str, ...]
    name: str
    x: np.ndarray | None
    y: np.ndarray
    sigma: np.ndarray | None

    @property
    def shown(self) -> np.ndarray:
        """Where there is something to draw."""
        ok = np.isfinite(self.y)
        return ok if self.x is None else ok & np.isfinite(self.x)


@dataclass(frozen=True)
class Overlay:
    """The measured points a figure takes (``layers``) and what it leaves out (``notes``)."""

    layers: tuple[Layer, ...]
    notes: tuple[str, ...]


def drawable(kind: str, parameter: str | None = None, body: bool = False) -> tuple[str, ...]:
    """The measured columns a figure shows (``kind``: ``sweep``, ``bounce-sweep``, ``bounce``).

    ``parameter`` is the swept one; ``body`` whether the bounce has one.
    """
    if kind == "sweep":
        return ("v1_m_s", "t_liftoff_s")
    if kind == "bounce-sweep":
        if body:
            return ("v1_m_s", "v2_m_s", "t_liftoff_s")
        return ("phi_a_rad",) if parameter in ("v0", "drop-height") else ("v2_m_s", "phi_a_rad")
    return ("v1_m_s", "v2_m_s", "t_liftoff_s", "phi_a_rad") if body else ("phi_a_rad",)


def _name(data: Measurements) -> str:
    return "measured" if data.source == "rows" else f"measured ({Path(data.source).name})"


def _unused(data: Measurements, shown: Sequence[str], where: str) -> list[str]:
    """Notes on the measured columns the figure does not show."""
    skipped = [
        c
        for c in data.columns
        if not c.startswith("sigma_") and c not in shown and c not in ("v0_m_s", "gap_m")
    ]
    if not skipped:
        return []
    return [f"{', '.join(skipped)} of {data.source} not drawn: {where} shows {', '.join(shown)}"]


def _rows_at(data: Measurements, v0: float | None, gap: float | None) -> tuple[np.ndarray, list]:
    """The rows measured at ``|v0|`` and the gap of the figure (a blank or absent input: any)."""
    keep = np.ones(data.rows, dtype=bool)
    notes = []
    if v0 is not None:
        speeds = np.abs(data.column("v0_m_s"))
        other = np.isfinite(speeds) & (np.abs(speeds - v0) > SAME_V0 * v0)
        if other.any():
            notes.append(
                f"{int(other.sum())} row(s) of {data.source} at another |v0| than "
                f"{v0:g} m/s not drawn"
            )
        keep &= ~other
    if gap is not None:
        gaps = data.column("gap_m")
        other = np.isfinite(gaps) & (np.abs(gaps - gap) > SAME_GAP)
        if other.any():
            notes.append(
                f"{int(other.sum())} row(s) of {data.source} at another gap than "
                f"{gap * 1e3:g} mm not drawn"
            )
        keep &= ~other
    return keep, notes


def _placed(data: Measurements, column: str, what: str) -> tuple[np.ndarray, list[str]]:
    """The rows that give ``column`` (the figure's abscissa), and a note on those that do not."""
    keep = np.isfinite(data.column(column))
    notes = []
    if not keep.all():
        notes.append(
            f"{int((~keep).sum())} row(s) of {data.source} without {column} not drawn ({what})"
        )
    return keep, notes


def _layer(
    data: Measurements,
    panel: tuple[str, ...],
    column: str,
    keep: np.ndarray,
    x: np.ndarray | None,
    scale: np.ndarray | float,
    name: str | None = None,
) -> Layer:
    y = np.where(keep, data.column(column) * scale, np.nan)
    sigma = data.sigma(column)
    return Layer(panel, name or _name(data), x, y, None if sigma is None else sigma * scale)


def _overlay(data: Measurements, layers: list[Layer], notes: list[str]) -> Overlay:
    if not any(layer.shown.any() for layer in layers):
        notes.append(f"nothing of {data.source} drawn")
    return Overlay(tuple(layers), tuple(notes))


def sweep_overlay(data: Measurements, parameter: str, v0: float) -> Overlay:
    """The measured rows on a one-parameter lift-off sweep (module docstring).

    ``v0`` is the sweep's ``|v0|`` (its base case's; unused for a v0 sweep).
    """
    notes = _unused(data, drawable("sweep"), "the lift-off sweep")
    speeds = np.abs(data.column("v0_m_s"))
    if parameter == "v0":
        keep, more = _placed(data, "v0_m_s", "a v0 sweep places a row at its |v0|")
        x, speed = speeds, speeds
    else:
        keep, more = _rows_at(data, v0, None)
        x, speed = None, np.where(np.isfinite(speeds), speeds, v0)
    layers = [
        _layer(data, ("v_l",), "v1_m_s", keep, x, 1.0 / speed),
        _layer(data, ("t_l",), "t_liftoff_s", keep, x, 1e3),
    ]
    return _overlay(data, layers, notes + more)


def bounce_sweep_overlay(
    data: Measurements, parameter: str, v0: float | None, body: bool
) -> Overlay:
    """The measured rows on a sweep of the drop or of the whole bounce (module docstring).

    ``v0`` is the sweep's ``|v0|`` (None for a sweep of v0 or of the drop
    height); ``body`` whether the bounce has one.
    """
    shown = drawable("bounce-sweep", parameter, body)
    notes = _unused(data, shown, "the sweep's figure")
    speeds = np.abs(data.column("v0_m_s"))
    if parameter in ("v0", "drop-height"):
        keep, more = _placed(data, "v0_m_s", "the figure is against |v0|")
        x, speed = speeds, speeds
    elif parameter == "gap":
        keep, more = _rows_at(data, v0, None)
        placed, also = _placed(data, "gap_m", "a gap sweep places a row at its gap")
        keep, more = keep & placed, more + also
        x, speed = data.column("gap_m") * 1e3, np.where(np.isfinite(speeds), speeds, v0)
    else:
        keep, more = _rows_at(data, v0, None)
        x, speed = None, np.where(np.isfinite(speeds), speeds, v0)
    if body:
        layers = [
            _layer(data, ("v_1/|v_0|",), "v1_m_s", keep, x, 1.0 / speed),
            _layer(data, ("v_2/|v_0|",), "v2_m_s", keep, x, 1.0 / speed),
            _layer(data, ("time",), "t_liftoff_s", keep, x, 1e3),
        ]
    else:
        layers = [_layer(data, (r"\phi_{a,max}",), "phi_a_rad", keep, x, 1.0)]
        if "v2_m_s" in shown:
            layers.append(_layer(data, ("e_2",), "v2_m_s", keep, x, 1.0 / speed))
    return _overlay(data, layers, notes + more)


def bounce_overlay(data: Measurements, v0: float, gap: float | None, body: bool) -> Overlay:
    """The measured rows at one drop's ``|v0|`` (and gap [m]; None without a body)."""
    shown = drawable("bounce", None, body)
    where = "the bounce's figure" if body else "the drop's figure"
    notes = _unused(data, shown, where)
    keep, more = _rows_at(data, v0, gap)
    name = _name(data)
    layers = []
    if body:
        layers += [
            _layer(data, ("velocity",), "v1_m_s", keep, None, 1.0, f"{name}: v1"),
            _layer(data, ("velocity",), "v2_m_s", keep, None, 1.0, f"{name}: v2"),
        ]
        t = np.where(keep, data.column("t_liftoff_s") * 1e3, np.nan)
        v1 = np.where(np.isfinite(data.column("v1_m_s")), data.column("v1_m_s"), 0.0)
        layers.append(Layer(("velocity",), f"{name}: lift-off", t, np.where(keep, v1, np.nan),
                            None))  # fmt: skip
    layers.append(_layer(data, (r"\phi_a",), "phi_a_rad", keep, None, 1.0))
    return _overlay(data, layers, notes + more)


def _axis(figure: Any, words: tuple[str, ...]) -> Any:
    """The panel whose y label holds every one of ``words`` (None if there is none)."""
    for ax in figure.axes:
        text = ax.get_ylabel()
        if text and all(word in text for word in words):
            return ax
    return None


def _legend(ax: Any) -> None:
    """The panel's legend drawn again (with the measured entries), where it stood."""
    old = ax.get_legend()
    if old is None:
        ax.legend(loc="best")
        return
    box = old.get_bbox_to_anchor().transformed(ax.transAxes.inverted())
    anchor = (box.x0, box.y0, box.width, box.height)
    ax.legend(loc=getattr(old, "_loc", "best"), bbox_to_anchor=anchor)


@styled
def draw_overlay(figure: Any, overlay: Overlay) -> None:
    """Draw ``overlay``'s layers on the panels of ``figure`` that show their quantities."""
    touched = []
    named: set[tuple[int, str]] = set()
    lines: dict[int, int] = {}  # lines drawn per panel: each layer of lines its own dash
    for layer in overlay.layers:
        ax = _axis(figure, layer.panel)
        seen = layer.shown
        if ax is None or not seen.any():
            continue
        label = None if (id(ax), layer.name) in named else layer.name
        named.add((id(ax), layer.name))
        if layer.x is None:
            dash = LINE_DASHES[lines.get(id(ax), 0) % len(LINE_DASHES)]
            lines[id(ax)] = lines.get(id(ax), 0) + 1
            for value in layer.y[seen]:
                ax.axhline(value, color=MEASURED_COLOUR, lw=1.0, ls=dash, label=label)
                label = None
        else:
            errors = None if layer.sigma is None else layer.sigma[seen]
            ax.errorbar(layer.x[seen], layer.y[seen], yerr=errors, fmt=MARKER,
                        color=MEASURED_COLOUR, ms=7, capsize=2, ls="none", label=label,
                        zorder=5)  # fmt: skip
        if ax not in touched:
            touched.append(ax)
    for ax in touched:
        _legend(ax)


def overlay_for(result: Any, data: Measurements) -> Overlay:
    """The overlay of ``data`` on the figure of ``result``: a lift-off sweep
    (:class:`~twoball.SweepResult`, one parameter), a sweep of the drop
    (:class:`~twoball.BounceSweep`) or one drop (:class:`~twoball.BounceReport`)."""
    if hasattr(result, "points"):
        return sweep_overlay(data, result.parameters[0], result.points[0].case.v0)
    if hasattr(result, "reports"):
        done = [r for r in result.reports if r is not None]
        body = any(r.has_body for r in done)
        v0 = None if result.parameter in ("v0", "drop-height") or not done else done[0].case.v0
        return bounce_sweep_overlay(data, result.parameter, v0, body)
    return bounce_overlay(
        data, result.case.v0, result.drop.gap if result.has_body else None, result.has_body
    )
