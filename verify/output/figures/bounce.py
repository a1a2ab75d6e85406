"""The drop on the floor: its history, and the contact against the impact speed (SI).

``drop_figure``: floor force, contact angle, the centre's height and the energy
books against time.  ``speeds_figure``: the largest contact angle and the
flattening against ``|v0|`` beside eq. (3.7), pressure x area (Cross 1999) and
the measurements (Table 2's phi_a = 2.6 at 4.1 m/s; 3.07 mm of compression per
m/s, Dowell & Krebs 1991).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from twoball.modal.floor.drop import DropResult
from twoball.modal.floor.references import MEASURED_COMPRESSION, pressure_area
from twoball.modal.parameters import Case
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import REFERENCE_COLOUR, label, styled, time_label

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["TABLE2", "drop_figure", "speeds_figure"]

#: Table 2 of the paper: the basketball's measured contact angle at 4.1 m/s.
TABLE2 = (4.1, 2.6)


@styled
def drop_figure(r: DropResult, case: Case, mass: float, title: str = "") -> Figure:
    """Four panels against time [ms]: floor force, contact angle, centre height, energy.

    ``r`` is the dimensionless drop of ``case``, ``mass`` the ball's mass m2 [kg].
    """
    to_ms = 1e3 / case.wave_speed
    force_unit = mass * case.radius * case.wave_speed**2  # m2 R c^2 [N]
    energy_unit = mass * case.scalings.velocity**2
    tr, system = r.trajectory, r.system
    fig = new_figure(6.8, 8.0)
    axes = fig.subplots(4, 1, sharex=True)
    mid, force = r.force
    axes[0].plot(mid * to_ms, force * force_unit, label="floor force")
    weight = mass * case.g
    axes[0].axhline(weight, color=REFERENCE_COLOUR, lw=0.8, ls=":", label="weight $m_2 g$")
    axes[0].set_ylabel(label("$F$", "N"))
    axes[0].legend(loc="upper right")
    pa = pressure_area(case.v0, case.radius, case.wave_speed)
    axes[1].plot(r.edge_t * to_ms, r.edge, ".", ms=2, label=r"contact edge $\phi_a(t)$")
    axes[1].axhline(r.phi_a_max, color="C1", lw=0.8, label=rf"$\phi_{{a,max}}$ = {r.phi_a_max:.4f}")
    axes[1].axhline(
        pa["phi_a_max_rad"], color=REFERENCE_COLOUR, lw=0.8, ls="--", label="pressure x area"
    )
    axes[1].set_ylabel(label(r"$\phi_a$", "rad"))
    axes[1].legend(loc="lower right")
    height = (tr.q[:, 0] - 1.0) * case.radius * 1e3
    axes[2].plot(tr.t * to_ms, height, label="centre $Z - R$")
    axes[2].axhline(0.0, color=REFERENCE_COLOUR, lw=0.6)
    if r.contact_time is not None:
        for ax in axes:
            ax.axvline(r.contact_time * to_ms, color=REFERENCE_COLOUR, lw=0.6, ls="-.")
    axes[2].set_ylabel(label("$Z - R$", "mm"))
    axes[2].legend(loc="lower right")
    parts = system.energies(tr.q, tr.v)
    membrane = parts["membrane_kinetic"] + parts["membrane_elastic"] + parts["gas"]
    gravity = parts["gravity"] - parts["gravity"][0]
    stacks = [
        (parts["rigid_kinetic"], "rigid kinetic"),
        (membrane, "membrane and gas"),
        (-tr.damping_work, "damped"),
        (-tr.impact_work - tr.contact_work, "lost at impacts"),
    ]
    t_ms = tr.t * to_ms
    axes[3].stackplot(
        t_ms,
        *[s * energy_unit for s, _ in stacks],
        labels=[name for _, name in stacks],
        alpha=0.8,
    )
    axes[3].plot(t_ms, gravity * energy_unit, color="k", lw=0.8, label="gravity $m_2 g (Z - R)$")
    axes[3].set_ylabel(label("$E$", "J"))
    axes[3].set_xlabel(time_label("after the first touch"))
    axes[3].legend(loc="center right", ncols=1)
    e2 = "-" if r.e2 is None else f"{r.e2:.4f}"
    fig.suptitle(
        f"Drop on the floor{': ' + title if title else ''}: |v0| = {case.v0:g} m/s, e2 = {e2}"
    )
    return fig


@styled
def speeds_figure(rows: Sequence[tuple[float, float, float]], case: Case) -> Figure:
    """phi_a,max [rad] and the largest flattening [m] against ``|v0|`` [m/s] (rows), with
    eq. (3.7), pressure x area and the measurements for the ball of ``case``."""
    from twoball.modal.initial import phi_a_from_v0

    if not rows:
        raise ValueError("no drops to draw")
    v0 = np.array([row[0] for row in rows])
    phi = np.array([row[1] for row in rows])
    flat = np.array([row[2] for row in rows]) * 1e3
    grid = np.linspace(max(0.2, 0.5 * v0.min()), 1.1 * v0.max(), 200)
    fig = new_figure(6.4, 6.4)
    axes = fig.subplots(2, 1, sharex=True)
    axes[0].plot(v0, phi, "o-", label=r"the drop: $\phi_{a,max}$")
    eq37 = [phi_a_from_v0(v, case.radius, case.wave_speed) for v in grid]
    axes[0].plot(grid, eq37, color=REFERENCE_COLOUR, ls="--", label="eq. (3.7)")
    area = [pressure_area(v, case.radius, case.wave_speed)["phi_a_max_rad"] for v in grid]
    axes[0].plot(grid, area, color=REFERENCE_COLOUR, ls=":", label="pressure x area")
    if case.preset_name == "basketball":
        axes[0].plot(*TABLE2, "s", color="C3", label="Table 2 (measured)")
    axes[0].set_ylabel(label(r"$\phi_{a,max}$", "rad"))
    axes[0].legend()
    axes[1].plot(v0, flat, "o-", label="the drop: largest flattening")
    axes[1].plot(
        grid, grid / case.wave_speed * 1e3, color=REFERENCE_COLOUR, ls=":", label="|v0| / c"
    )
    axes[1].plot(
        grid,
        MEASURED_COMPRESSION * grid * 1e3,
        color="C3",
        ls="-.",
        label="3.07 mm per m/s (measured)",
    )
    axes[1].set_ylabel(label("flattening", "mm"))
    axes[1].set_xlabel(label(r"impact speed $|v_0|$", "m/s"))
    axes[1].legend()
    axes[1].set_xlim(0.0, 1.1 * v0.max())
    if math.isfinite(phi.min()):
        axes[0].set_ylim(min(phi.min(), min(eq37)) - 0.02, math.pi)
    return fig
