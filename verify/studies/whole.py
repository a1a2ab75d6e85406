"""Tables of the whole two-ball bounce: limits, backends, orders, sensitivity, the top's artefact.

``python -m twoball.verify.studies.whole [names...]`` prints Markdown tables of
the numbers docs/whole_bounce.rst quotes that the reproduction does not print
(Table 1 and the gap curves: ``twoball reproduce --only whole_table1,whole_gap``).
The runs start from the SI pair or body as ``twoball.bounce`` resolves them
(:func:`twoball.modal.floor.model.resolve_pair`, ``resolve_body``,
``resolve_drop``) and run on the Legendre modes or axisymmetric P2 elements.
A full run takes a few minutes on one core.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from twoball.fem_membrane.floor import axisym_ball
from twoball.modal.contact.body import Body
from twoball.modal.damping import ModalRatio
from twoball.modal.floor.ball import legendre_ball
from twoball.modal.floor.drop import DropResult, DropSettings, run_drop
from twoball.modal.floor.model import resolve_body, resolve_drop, resolve_pair
from twoball.modal.floor.options import Drop
from twoball.modal.floor.restitution import body_liftoff
from twoball.modal.floor.system import BodyOnTop, floor_system
from twoball.modal.parameters import Case
from twoball.modal.stiffness import Stiffness
from twoball.verify.studies.orders import least_squares_order

__all__ = ["TABLES", "WholeRun", "main", "whole"]

#: The defaults of ``twoball.bounce``: Legendre N, P2 elements, time step (units 1/c), window.
MODES, ELEMENTS, DT, WINDOW = 192, 96, 0.005, 10.0 * math.pi
PAIR = "basketball-tennis"


@dataclass(frozen=True)
class WholeRun:
    """One whole bounce (dimensionless result) with its case and body (SI)."""

    case: Case
    body: Body
    result: DropResult

    @property
    def v1(self) -> float:
        """v1 / |v0| (nan if the body did not leave)."""
        b = self.result.body
        return math.nan if b is None or b.v1 is None else b.v1 / self.result.settings.v0

    @property
    def v2(self) -> float:
        """v2 / |v0|."""
        b = self.result.body
        return math.nan if b is None or b.v2 is None else b.v2 / self.result.settings.v0


def whole(
    pair: str | None = PAIR,
    gap: float = 0.0,
    *,
    body: Body | None = None,
    case: Case | None = None,
    backend: str = "legendre",
    size: int | None = None,
    dt: float = DT,
) -> WholeRun:
    """One whole bounce of a pair (or a body on ``case``) at ``gap`` [m], as ``twoball.bounce``."""
    case, body, chosen = resolve_pair(case, body, pair)
    case = Case.preset("basketball") if case is None else case
    drop = Drop(gap=gap)
    resolved = resolve_body(case, body, chosen, drop)
    model = resolve_drop(case, drop)
    if backend == "legendre":
        ball = legendre_ball(size or MODES, model.spectrum, model.law)
    else:
        ball = axisym_ball(size or ELEMENTS, 2, model.spectrum, model.law)
    row = BodyOnTop(
        body.mass_ratio,
        ball.cap_average(resolved.cap_angle),
        resolved.cap_angle,
        body.restitution,
        gap / model.case.radius,
    )
    system = floor_system(ball, model.gamma, 0.0, row)
    window = WINDOW + 2.0 * row.gap / model.v0
    result = run_drop(system, DropSettings(model.v0, model.gamma, dt, window))
    return WholeRun(model.case, body, result)


def limit_a_table(masses: Sequence[float] = (0.05, 0.01, 1e-3, 1e-4)) -> str:
    """Limit (a): the body row on the special case against ``twoball.liftoff(body=...)``."""
    from twoball.modal.contact.report import legendre_contact

    case = Case.preset("basketball")
    theta = math.asin(0.0262 / case.radius)
    lines = [
        "| mu | v1 event-driven [m/s] | rel. error dt=0.005 | rel. error dt=0.0025 | "
        "t_l error [s] |",
        "|---|---|---|---|---|",
    ]
    for mu in masses:
        ref = legendre_contact(case, Body(mu, contact_radius=0.0262))
        errors, t_error = [], math.nan
        for dt in (0.005, 0.0025):
            run_ = body_liftoff(
                Stiffness(),
                ModalRatio(case.damping),
                case.modes,
                case.phi_a,
                case.gamma,
                dt,
                BodyOnTop(mu, np.zeros(1), theta),
            )
            errors.append(run_.v1 * case.scalings.velocity / ref.v_liftoff_m_s - 1.0)
            t_error = run_.t_liftoff / case.wave_speed - ref.t_liftoff_s
        lines.append(
            f"| {mu:g} | {ref.v_liftoff_m_s:.6f} | {errors[0]:.1e} | {errors[1]:.1e} | "
            f"{t_error:.1e} |"
        )
    return "\n".join(lines)


def limit_b_table(gaps: Sequence[float] = (0.1, 0.15, 0.2, 0.25, 0.5)) -> str:
    """Limit (b): large gaps against eqs. (2.1)-(2.5) with the run's e2 and e12_effective."""
    from twoball.modal.icm.impacts import post_impact_velocities

    body = Body(0.101, contact_radius=0.0262, restitution=0.89)
    lines = [
        "| g [m/s^2] | gap [mm] | sequence | e12_eff | whole v1 | (2.5) v1 | dv1 | dv2 | "
        "g t_c/|v0| |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for g in (9.81, 1e-6):
        for gap in gaps:
            run_ = whole(None, gap, body=body, case=Case.preset("basketball", g=g))
            r, b = run_.result, run_.result.body
            e2, e12 = r.e2, b.e12_effective
            if e12 is None:
                lines.append(f"| {g:g} | {gap * 1e3:g} | {b.sequence} | - | | | | | |")
                continue
            v0 = r.settings.v0
            delay = (gap / run_.case.radius) / ((1.0 + e2) * v0)
            gamma = r.settings.gamma
            v1, v2 = post_impact_velocities(
                -v0 - gamma * delay, e2 * v0 - gamma * delay, 0.101, e12
            )
            bound = gamma * r.contact_time / v0
            lines.append(
                f"| {g:g} | {gap * 1e3:g} | {b.sequence} | {e12:.3f} | {run_.v1:.4f} | "
                f"{v1 / v0:.4f} | {run_.v1 - v1 / v0:+.1e} | {run_.v2 - v2 / v0:+.1e} | "
                f"{bound:.3f} |"
            )
    return "\n".join(lines)


def limit_c_table() -> str:
    """Limit (c): D = 0, e12 = 1, touching: the energy and momentum books."""
    lines = [
        "| floor e | max abs(balance)/KE0 | momentum | mechanical loss/KE0 |",
        "|---|---|---|---|",
    ]
    for e in (0.0, 1.0):
        case = Case.preset("basketball", damping=0.0)
        case, body, chosen = resolve_pair(case, None, PAIR)
        body = Body(body.mass_ratio, contact_radius=body.contact_radius, restitution=1.0)
        model = resolve_drop(case, Drop())
        ball = legendre_ball(64, model.spectrum, ModalRatio(0.0))
        theta = math.asin(body.contact_radius / case.radius)
        row = BodyOnTop(body.mass_ratio, ball.cap_average(theta), theta, 1.0, 0.0)
        r = run_drop(
            floor_system(ball, model.gamma, e, row), DropSettings(model.v0, model.gamma, DT, WINDOW)
        )
        tr = r.trajectory
        scale = tr.kinetic[0]
        loss = -(tr.impact_work[-1] + tr.contact_work[-1]) / scale
        lines.append(
            f"| {e:g} | {np.max(np.abs(tr.balance)) / scale:.1e} | {r.impulse_balance:.1e} | "
            f"{loss:.2e} |"
        )
    return "\n".join(lines)


def backends_table(gaps: Sequence[float] = (0.0, 0.05)) -> str:
    """Legendre N = 192 against P2 with 96 elements: v1, v2 of basketball-tennis."""
    lines = [
        "| gap [mm] | Legendre v1/v2 | P2 v1/v2 | rel. diff. v1 | rel. diff. v2 |",
        "|---|---|---|---|---|",
    ]
    for gap in gaps:
        a, b = whole(PAIR, gap), whole(PAIR, gap, backend="fem")
        lines.append(
            f"| {gap * 1e3:g} | {a.v1:.5f} / {a.v2:.5f} | {b.v1:.5f} / {b.v2:.5f} | "
            f"{abs(b.v1 / a.v1 - 1):.1e} | {abs(b.v2 / a.v2 - 1):.1e} |"
        )
    return "\n".join(lines)


def orders_table() -> str:
    """Least-squares orders of v1 in 1/N, 1/E and dt (basketball-tennis, 0 and 50 mm)."""
    lines = ["| study | gap [mm] | sizes | reference | order of v1 |", "|---|---|---|---|---|"]
    studies = [
        ("legendre N", [32, 48, 64, 96, 128], 512, lambda n, g: whole(PAIR, g, size=n).v1),
        (
            "P2 elements E",
            [16, 24, 32, 48, 64],
            256,
            lambda n, g: whole(PAIR, g, backend="fem", size=n).v1,
        ),
    ]
    for name, sizes, reference, run_ in studies:
        for gap in (0.0, 0.05):
            values = np.array([run_(n, gap) for n in sizes])
            errors = np.abs(values - run_(reference, gap))
            order = least_squares_order(1.0 / np.array(sizes), errors).order
            lines.append(f"| {name} | {gap * 1e3:g} | {sizes} | {reference} | {order:.2f} |")
    steps = [0.04, 0.02, 0.01, 0.005, 0.0025]
    for gap in (0.0, 0.05):
        values = np.array([whole(PAIR, gap, size=64, dt=dt).v1 for dt in steps])
        errors = np.abs(values - whole(PAIR, gap, size=64, dt=0.000625).v1)
        order = least_squares_order(np.array(steps), errors).order
        lines.append(f"| dt (N = 64) | {gap * 1e3:g} | {steps} | 0.000625 | {order:.2f} |")
    return "\n".join(lines)


def sensitivity_table(pairs: Sequence[str] = ("basketball-tennis", "basketball-tissue")) -> str:
    """v1/v2 and e12_effective against the cap radius (x 0.5, 1, 2) and Newton's e12."""
    from twoball.modal.pairs import PAIRS

    lines = [
        "| pair | gap [mm] | a factor | e12 | v1 / v2 | e12_eff |",
        "|---|---|---|---|---|---|",
    ]
    for name in pairs:
        p = PAIRS[name]
        for gap in (0.0, 0.15):
            for factor in (0.5, 1.0, 2.0):
                for e in (0.0, p.e12, 1.0):
                    body = Body(p.mu, contact_radius=p.cap_radius * factor, restitution=e)
                    run_ = whole(None, gap, body=body, case=Case.preset(p.lower))
                    e12 = run_.result.body.e12_effective
                    lines.append(
                        f"| {name} | {gap * 1e3:g} | {factor:g} | {e:g} | {run_.v1:.3f} / "
                        f"{run_.v2:.3f} | {'-' if e12 is None else f'{e12:.3f}'} |"
                    )
    return "\n".join(lines)


def artefact_table(times: Sequence[float] = (0.1, 0.25, 0.5, 1.0, 1.5, 2.0)) -> str:
    """The ball alone: the velocity change of the tennis ball's cap over the centre's."""
    lines = [
        "| N | " + " | ".join(f"t = {t:g}/c" for t in times) + " |",
        "|---|" + "---|" * len(times),
    ]
    model = resolve_drop(Case.preset("basketball"), Drop())
    theta = math.asin(0.0262 / model.case.radius)
    for n in (96, 192, 384):
        ball = legendre_ball(n, model.spectrum, model.law)
        r = run_drop(
            floor_system(ball, model.gamma), DropSettings(model.v0, model.gamma, 0.0025, 40.0)
        )
        tr = r.trajectory
        cap = tr.v[:, 0] + tr.v[:, 1:] @ ball.cap_average(theta)
        cells = []
        for t in times:
            k = int(np.searchsorted(tr.t, t))
            free = -model.v0 - model.gamma * tr.t[k]
            cells.append(f"{(cap[k] - free) / (tr.v[k, 0] - free):+.2f}")
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


TABLES = {
    "limit_a": limit_a_table,
    "limit_b": limit_b_table,
    "limit_c": limit_c_table,
    "backends": backends_table,
    "orders": orders_table,
    "sensitivity": sensitivity_table,
    "artefact": artefact_table,
}


def main(names: Sequence[str] = ()) -> None:
    """Print the named tables (all by default)."""
    for name in names or TABLES:
        print(f"## {name}\n\n{TABLES[name]()}\n", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
