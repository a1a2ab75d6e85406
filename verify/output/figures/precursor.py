"""The pole's precursor under each damping law: its motion before the wave front can arrive.

The flattened cap (eq. (3.10)) is at rest outside ``phi > phi_a``; a disturbance
travelling at the membrane's angular speed c reaches the pole (phi = 0) at
``t = phi_a / c`` at the earliest.  An undamped membrane's pole stays at rest
until then.  The paper's modal ratio D damps every mode by ``2 D omega``, the
non-local operator ``2 D sqrt(-Delta_s) d/dt``: the pole sinks long before the
front (2.7 mm at 0.1/c before it for the basketball), a tail that does not
vanish as N grows.  Rayleigh damping ``alpha M + beta K`` is local and causal:
``alpha`` alone keeps the front sharp (the telegraph equation), and ``beta``
(Kelvin-Voigt) smears it over a width ~ sqrt(beta t), a tail that falls like a
Gaussian rather than algebraically.  :func:`precursor_figure` draws both beside
the undamped membrane (``twoball plot precursor``).

The Rayleigh law compared with D has the same ratio at the lowest vibrating
mode (``omega_1 = sqrt(2)``) and at the dominant frequency of the motion, the
energy-weighted mean frequency of the filtered initial data
(:meth:`twoball.modal.series.ModalSeries.mean_frequency`, 5.76 for the
basketball): comparable dissipation where the energy is (one transit, t = pi/c,
leaves 3.8 % of the energy under D, 5.3 % under the matched law).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.watch import Watch
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import DEFAULT_T_END, LiftoffResult, find_liftoff
from twoball.modal.parameters import Case
from twoball.modal.series import ModalSeries
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import (
    LIFTOFF_MARKER,
    LINE_STYLES,
    REFERENCE_COLOUR,
    label,
    styled,
    subject,
    time_label,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Modes of the series whose precursor is drawn: a multiple of the case's N, so
#: that the tail belongs to the damping law and not to the truncation.
CONVERGED_FACTOR = 8
#: Share of ``phi_a / c`` before the front at which the precursor is reported.
BEFORE_FRONT = (0.1, 0.3, 0.6)


@dataclass(frozen=True)
class LawCurve:
    """One damping law's pole motion (dimensionless) and its lift-off.

    Attributes
    ----------
    label : str
        Legend entry.
    law : ModalRatio or Rayleigh
        The law in units of c.
    series : ModalSeries
        The case's own series (N modes, its filter): lift-off and panel (a).
    converged : ModalSeries
        The same law on ``CONVERGED_FACTOR`` N modes (Lanczos): the precursor.
    result : LiftoffResult
        Criteria (i)-(ii) of §3(a) on ``series``.
    """

    label: str
    law: Any
    series: ModalSeries
    converged: ModalSeries
    result: LiftoffResult

    def precursor(self, case: Case) -> dict[str, float]:
        """u [m] of the converged series at ``phi_a/c - d/c`` for d in :data:`BEFORE_FRONT`."""
        times = case.phi_a - np.array(BEFORE_FRONT)
        u = self.converged.pole(times).u * case.scalings.length
        return {f"u_before_front_{d:g}_m": float(v) for d, v in zip(BEFORE_FRONT, u, strict=True)}


def matched_rayleigh(case: Case, series: ModalSeries) -> Rayleigh:
    """The Rayleigh law (units of c) with the case's ratio D at omega_1 and at the dominant mode.

    The lowest vibrating mode's frequency (:meth:`~twoball.modal.stiffness.Stiffness.fit_band`)
    and ``series.mean_frequency()``, the energy-weighted mean of the initial data.
    """
    low = case.stiffness.fit_band(case.modes)[0]
    return Rayleigh.fit(case.damping, low, series.mean_frequency())


def law_curves(
    case: Case, sigma: str = "lanczos", recontact: str = "window", t_end: float = DEFAULT_T_END
) -> list[LawCurve]:
    """The case's law, the other law matched to it, and the undamped membrane.

    With the paper's ratio D: D, the Rayleigh law of :func:`matched_rayleigh`
    and D = 0.  With a Rayleigh law of the case: that law, the ratio D and D = 0.
    ``t_end`` dimensionless.
    """
    own = case.damping_law
    base = legendre_series(
        case.phi_a,
        ModalRatio(case.damping),
        SpectralFilter(sigma, case.modes),
        stiffness=case.stiffness,
        monitor=Watch(),
    )
    laws: list[tuple[str, Any]] = []
    ratio = f"modal ratio D = {case.damping:g} (3.14)"
    if isinstance(own, Rayleigh):
        laws.append((_rayleigh_label("Rayleigh (the case's)", own), own))
        laws.append((ratio, ModalRatio(case.damping)))
    else:
        laws.append((ratio, own))
        matched = matched_rayleigh(case, base)
        laws.append(
            (
                _rayleigh_label(r"Rayleigh, same ratio at $\omega_1$ and $\omega_E$", matched),
                matched,
            )
        )
    laws.append(("undamped (D = 0)", ModalRatio(0.0)))
    curves = []
    for name, law in laws:
        series = legendre_series(
            case.phi_a,
            law,
            SpectralFilter(sigma, case.modes),
            stiffness=case.stiffness,
            monitor=Watch(),
        )
        converged = legendre_series(
            case.phi_a,
            law,
            SpectralFilter("lanczos", CONVERGED_FACTOR * case.modes),
            stiffness=case.stiffness,
            monitor=Watch(),
        )
        result = find_liftoff(series, case.gamma, t_end=t_end, horizon=recontact)
        curves.append(LawCurve(name, law, series, converged, result))
    return curves


def _rayleigh_label(text: str, law: Rayleigh) -> str:
    return f"{text}: α = {law.alpha:.3g} c, β = {law.beta:.3g}/c"


@styled
def precursor_figure(
    case: Case, curves: list[LawCurve], t_end: float, samples: int = 3000
) -> Figure:
    """Pole displacement under each law: (a) the window, (b) before the front, (c) |u| in log.

    (a) The case's series (N modes, its filter) over ``[0, t_end]`` with each
    law's lift-off (dot).  (b) The converged series up to just past the front
    ``phi_a / c`` (dashed line): anything left of it is the precursor.  (c) The
    same, ``|u|`` on a logarithmic scale, showing how each tail falls.  SI units;
    ``t_end`` dimensionless.
    """
    scale = case.scalings
    to_ms = scale.time * 1e3
    to_mm = scale.length * 1e3
    figure = new_figure(7.5, 9.0)
    axes = figure.subplots(3, 1)
    t = np.linspace(0.0, t_end, samples)
    front = case.phi_a
    early = np.linspace(0.25 * front, 1.08 * front, samples)
    tail = np.linspace(0.2 * front, front, samples)
    for k, curve in enumerate(curves):
        style = {"color": f"C{k}", "linestyle": LINE_STYLES[k % len(LINE_STYLES)]}
        u = curve.series.pole(t).u
        axes[0].plot(t * to_ms, u * to_mm, label=curve.label, **style)
        if curve.result.lifted:
            t_l = curve.result.t
            mark = curve.series.pole(np.array([t_l])).u[0]
            axes[0].plot(t_l * to_ms, mark * to_mm, LIFTOFF_MARKER, color=f"C{k}")
        axes[1].plot(early * to_ms, curve.converged.pole(early).u * to_mm, **style)
        magnitude = np.abs(curve.converged.pole(tail).u) * to_mm
        axes[2].semilogy(tail * to_ms, np.where(magnitude > 0, magnitude, np.nan), **style)
    for axis in axes[1:]:
        axis.axvline(front * to_ms, color=REFERENCE_COLOUR, linewidth=0.8, linestyle="--")
    axes[1].annotate(
        r"front arrives, $\varphi_a / c$",
        xy=(front * to_ms, 0.06),
        xycoords=("data", "axes fraction"),
        xytext=(-4, 0),
        textcoords="offset points",
        ha="right",
        fontsize=8,
    )
    axes[2].set_ylim(1e-7, None)
    axes[0].set_ylabel(label("$u(t, 0)$", "mm"))
    axes[1].set_ylabel(label("$u(t, 0)$", "mm"))
    axes[2].set_ylabel(label(r"$|u(t, 0)|$", "mm"))
    # the laws' curves fill panel (a): their legend goes below the figure, over no data
    handles, names = axes[0].get_legend_handles_labels()
    figure.legend(handles, names, loc="outside lower center", ncols=2)
    axes[0].set_title(f"(a) N = {case.modes}, the case's series; dots: lift-off", fontsize=9)
    axes[1].set_title(
        f"(b) before the front (N = {CONVERGED_FACTOR * case.modes}, converged)", fontsize=9
    )
    axes[2].set_title(
        "(c) the precursor's tail (the undamped curve: the truncation's level)", fontsize=9
    )
    for axis in axes:
        axis.set_xlabel(time_label("after maximal compression"))
    figure.suptitle(
        f"{subject(case)}: pole displacement under each damping law, the paper's ratio "
        "is non-local\n"
        f"($R$ = {case.radius:g} m, $c$ = {case.wave_speed:g} 1/s, "
        + r"$\varphi_a$"
        + f" = {case.phi_a:.4g})",
        fontsize=9,
    )
    return figure


def precursor_rows(case: Case, curves: list[LawCurve]) -> list[tuple[str, str]]:
    """One row per law: lift-off (SI) and the precursor 0.1/c before the front [mm]."""
    scale = case.scalings
    rows = []
    for curve in curves:
        result = curve.result
        if result.lifted:
            text = (
                f"{result.t * scale.time * 1e3:.4f} ms, {result.velocity * scale.velocity:.4f} m/s"
            )
        else:
            text = "no lift-off"
        before = curve.precursor(case)[f"u_before_front_{BEFORE_FRONT[0]:g}_m"] * 1e3
        rows.append((curve.label, f"{text}; u = {before:.4g} mm at 0.1/c before the front"))
    return rows


__all__ = [
    "BEFORE_FRONT",
    "CONVERGED_FACTOR",
    "LawCurve",
    "law_curves",
    "matched_rayleigh",
    "precursor_figure",
    "precursor_rows",
]
