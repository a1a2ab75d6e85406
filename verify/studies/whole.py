"""Tables of the whole two-ball bounce: limits, backends, orders, sensitivity, the top's artefact.

``python -m twoball.verify.studies.whole [names...]`` prints Markdown tables of
the numbers docs/whole_bounce.rst quotes that the reproduction does not print
(Table 1 and the gap curves: ``twoball reproduce --only whole_table1,whole_gap``).
The runs start from the SI pair or body as ``twoball.bounce`` resolves them
(:func:`twoball.modal.floor.inputs.resolve_pair`, ``resolve_body``,
``resolve_drop``) and run on the Legendre modes or axisymmetric P2 elements.
A full run takes a few minutes on one core.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from twoball._common.watch import Watch
from twoball.fem_membrane.floor import axisym_ball
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.contact.body import Body
from twoball.modal.damping import ModalRatio
from twoball.modal.floor.drop import DropResult, DropSettings, run_drop
from twoball.modal.floor.inputs import resolve_body, resolve_drop, resolve_pair
from twoball.modal.floor.options import Drop
from twoball.modal.floor.restitution import body_liftoff
from twoball.modal.floor.system import BodyOnTop, floor_system, release_delay
from twoball.modal.parameters import Case
from twoball.modal.stiffness import Stiffness
from twoball.verify.studies.orders import least_squares_order

__all__ = ["TABLES", "Precursor", "WholeRun", "main", "precursor", "whole"]

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
    delay: float = 0.0,
) -> WholeRun:
    """One whole bounce of a pair (or a body on ``case``) at ``gap`` [m], as ``twoball.bounce``.

    ``delay`` [s]: the body is released that long after the ball instead (both
    touching at rest before): at the floor touch it is ``|v0| tau - g tau^2 / 2``
    higher and ``g tau`` slower (:func:`~twoball.modal.floor.system.release_delay`);
    then ``gap`` must be 0.
    """
    case, body, chosen = resolve_pair(case, body, pair)
    case = Case.preset("basketball") if case is None else case
    drop = Drop(gap=gap)
    resolved = resolve_body(case, body, chosen, drop)
    model = resolve_drop(case, drop)
    if backend == "legendre":
        ball = legendre_ball(size or MODES, model.spectrum, model.law)
    else:
        ball = axisym_ball(size or ELEMENTS, 2, model.spectrum, model.law)
    start, speed = gap / model.case.radius, None
    if delay:
        if gap:
            raise ValueError("give a gap or a release delay, not both")
        start, speed = release_delay(delay * model.case.wave_speed, model.v0, model.gamma)
    row = BodyOnTop(
        body.mass_ratio,
        ball.cap_average(resolved.cap_angle),
        resolved.cap_angle,
        body.restitution,
        start,
        speed=speed,
    )
    system = floor_system(ball, model.gamma, 0.0, row)
    window = WINDOW + 2.0 * row.gap / model.v0
    result = run_drop(system, DropSettings(model.v0, model.gamma, dt, window))
    return WholeRun(model.case, body, result)


def limit_a_table(masses: Sequence[float] = (0.05, 0.01, 1e-3, 1e-4)) -> str:
    """Limit (a): the body row on the special case against the exact event-driven solver.

    (:func:`~twoball.modal.contact.report.legendre_contact` with ``exact=True``:
    ``twoball.liftoff(body=...)`` steps the same row by the same core now.)
    """
    from twoball.modal.contact.report import legendre_contact

    case = Case.preset("basketball")
    theta = math.asin(0.0262 / case.radius)
    lines = [
        "| mu | v1 event-driven [m/s] | rel. error dt=0.005 | rel. error dt=0.0025 | "
        "t_l error [s] |",
        "|---|---|---|---|---|",
    ]
    for mu in masses:
        body = Body(mu, contact_radius=0.0262)
        ref = legendre_contact(case, body, reference=False, exact=True, monitor=Watch())
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
    from twoball.modal.icm.impacts import icm_velocities

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
            gamma = r.settings.gamma
            v1, v2 = icm_velocities(gap / run_.case.radius, v0, e2, e12, 0.101, gamma)
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
    """Orders of v1 and the spread of v2 in 1/N, 1/E and dt (basketball-tennis, 0 and 50 mm).

    Each study against its fine reference: the least-squares order of v1 and the
    largest distance of v2 from the reference over the finer half of the sizes
    (N >= 96, E >= 48, dt <= 0.01: v2 has a noise floor, no clean order).
    """
    lines = [
        "| study | gap [mm] | sizes | reference | order of v1 | v2: largest distance (finer) |",
        "|---|---|---|---|---|---|",
    ]

    def legendre(n, gap):
        return whole(PAIR, gap, size=n)

    def fem(n, gap):
        return whole(PAIR, gap, backend="fem", size=n)

    studies = [
        ("legendre N", [32, 48, 64, 96, 128], 512, 96, legendre),
        ("P2 elements E", [16, 24, 32, 48, 64], 256, 48, fem),
    ]
    for name, sizes, reference, fine, run_ in studies:
        for gap in (0.0, 0.05):
            runs = [run_(n, gap) for n in sizes]
            ref = run_(reference, gap)
            errors = np.abs(np.array([r.v1 for r in runs]) - ref.v1)
            order = least_squares_order(1.0 / np.array(sizes), errors).order
            v2 = max(abs(r.v2 - ref.v2) for n, r in zip(sizes, runs, strict=True) if n >= fine)
            lines.append(
                f"| {name} | {gap * 1e3:g} | {sizes} | {reference} | {order:.2f} | {v2:.1e} |"
            )
    steps = [0.04, 0.02, 0.01, 0.005, 0.0025]
    for backend, size in (("legendre", 64), ("fem", 32)):
        for gap in (0.0, 0.05):
            runs = [whole(PAIR, gap, backend=backend, size=size, dt=dt) for dt in steps]
            ref = whole(PAIR, gap, backend=backend, size=size, dt=0.000625)
            errors = np.abs(np.array([r.v1 for r in runs]) - ref.v1)
            order = least_squares_order(np.array(steps), errors).order
            v2 = max(abs(r.v2 - ref.v2) for dt, r in zip(steps, runs, strict=True) if dt <= 0.01)
            lines.append(
                f"| dt ({backend} {size}) | {gap * 1e3:g} | {steps} | 0.000625 | {order:.2f} | "
                f"{v2:.1e} |"
            )
    return "\n".join(lines)


def defaults_table(gaps: Sequence[float] = (0.0, 0.05)) -> str:
    """The defaults against fine references of their own (Legendre N = 512, P2 E = 256)."""
    lines = [
        "| gap [mm] | N=192 vs 512: v1 / v2 | E=96 vs 256: v1 / v2 | 512 vs 256: v1 / v2 |",
        "|---|---|---|---|",
    ]
    for gap in gaps:
        a, b = whole(PAIR, gap), whole(PAIR, gap, backend="fem")
        fa, fb = whole(PAIR, gap, size=512), whole(PAIR, gap, backend="fem", size=256)
        cells = [
            f"{abs(x.v1 / y.v1 - 1):.1e} / {abs(x.v2 / y.v2 - 1):.1e}"
            for x, y in ((a, fa), (b, fb), (fa, fb))
        ]
        lines.append(f"| {gap * 1e3:g} | " + " | ".join(cells) + " |")
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


@dataclass(frozen=True)
class Precursor:
    """The top's non-causal start on one ball (SI where a unit is given).

    The drop's membrane moves only radially and its degree-1 content is carried
    by the centre Z (mass m2).  A floor force F then accelerates the centre by
    ``F / m2`` and every point's radial displacement by ``-3 F cos(phi) / m2``
    (the removed degree-1 part of the load), at once: the cap of half-angle
    theta around the top moves, on average, at ``F / m2 (1 - 3 (1 + cos
    theta) / 2) = -F (1 + 3 cos theta) / (2 m2)``, i.e. -2 F / m2 for a point,
    before any wave can have reached it (a causal membrane leaves it at rest
    until about ``pi / c``).

    Attributes
    ----------
    ball : str
        The preset.
    damping : float
        The ratio D of the run.
    cap_radius : float
        a [m] of the cap whose mean is the top.
    closed_form : float
        ``-(1 + 3 cos theta) / 2``: the ratio of the cap's velocity change to the
        centre's at the first instants (-2 for theta -> 0).
    ratios : tuple of (float, float)
        ``(t [s], ratio)`` measured: both velocity changes from the free fall.
    opening : float
        Largest depth [m] of the top below a body falling freely from touching.
    t_opening : float
        When [s] (from the first floor touch).
    t_strike : float or None
        When [s] the top first comes back to the free-falling body.
    strike_speed : float or None
        The top's speed relative to the body there, over ``|v0|``.
    t_wave : float
        ``pi / c`` [s]: when the wave from the south pole reaches the top.
    """

    ball: str
    damping: float
    cap_radius: float
    closed_form: float
    ratios: tuple[tuple[float, float], ...]
    opening: float
    t_opening: float
    t_strike: float | None
    strike_speed: float | None
    t_wave: float


def precursor(
    ball: str = "basketball",
    cap_radius: float = 0.0262,
    damping: float | None = None,
    *,
    modes: int = MODES,
    dt: float = DT,
    times: Sequence[float] = (0.05, 0.1, 0.25, 0.5, 1.0),
) -> Precursor:
    """The ball alone dropped at the defaults; its top (the mean over a cap of radius
    ``cap_radius`` [m]) against a body falling freely from touching it (``damping``:
    the ratio D, None for the preset's; ``times`` in units 1/c)."""
    case = Case.preset(ball) if damping is None else Case.preset(ball, damping=damping)
    model = resolve_drop(case, Drop())
    shell = legendre_ball(modes, model.spectrum, model.law)
    theta = math.asin(cap_radius / model.case.radius)
    cap = shell.cap_average(theta)
    c, radius, v0, gamma = model.case.wave_speed, model.case.radius, model.v0, model.gamma
    r = run_drop(floor_system(shell, gamma), DropSettings(v0, gamma, dt, 1.5 * math.pi))
    tr = r.trajectory
    centre = shell.centre  # the cap's average holds the translation's entry 1
    top = 1.0 + tr.q @ cap
    speed = tr.v @ cap
    body = 2.0 - v0 * tr.t - 0.5 * gamma * tr.t**2  # free fall from touching
    body_speed = -v0 - gamma * tr.t
    ratios = []
    for t in times:
        k = int(np.searchsorted(tr.t, t))
        change = tr.v[k, centre] - body_speed[k]
        ratios.append((t / c, float((speed[k] - body_speed[k]) / change)))
    depth = body - top
    k = int(np.argmax(depth))
    back = np.flatnonzero(depth[k:] <= 0.0)
    strike = strike_speed = None
    if back.size:
        j = k + int(back[0])
        # the crossing between the step ends, linear in the depth
        s = tr.t[j - 1] + depth[j - 1] / (depth[j - 1] - depth[j]) * (tr.t[j] - tr.t[j - 1])
        strike = float(s) / c
        strike_speed = float((speed[j] - body_speed[j]) / v0)
    return Precursor(
        ball,
        float(model.case.damping),
        cap_radius,
        -(1.0 + 3.0 * math.cos(theta)) / 2.0,
        tuple(ratios),
        float(depth[k]) * radius,
        float(tr.t[k]) / c,
        strike,
        strike_speed,
        math.pi / c,
    )


#: The tops of the precursor table: (ball, cap radius [m], the pair whose cap it is).
PRECURSOR_CAPS = (
    ("basketball", 0.0262, "basketball-tennis"),
    ("basketball", 0.0171, "basketball-tissue"),
    ("tennis", 0.01015, "tennis-coin"),
)


def artefact_table() -> str:
    """The degree-1 artefact: the top's start against the closed form and against pi/c."""
    lines = [
        "| ball | cap a [mm] (pair) | D | closed form | ratio at t = 0.05, 0.1, 0.25, 0.5, 1 /c "
        "| deepest [mm] at [ms] | top strikes the body [ms] | relative speed / abs(v0) "
        "| pi/c [ms] |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for ball, radius, pair in PRECURSOR_CAPS:
        for damping in (None, 0.0):
            p = precursor(ball, radius, damping)
            ratios = ", ".join(f"{r:+.2f}" for _, r in p.ratios)
            strike = "-" if p.t_strike is None else f"{p.t_strike * 1e3:.2f}"
            rel = "-" if p.strike_speed is None else f"{p.strike_speed:.2f}"
            lines.append(
                f"| {ball} | {radius * 1e3:g} ({pair}) | {p.damping:g} | {p.closed_form:+.3f} | "
                f"{ratios} | {p.opening * 1e3:.2f} at {p.t_opening * 1e3:.2f} | {strike} | "
                f"{rel} | {p.t_wave * 1e3:.2f} |"
            )
    return "\n".join(lines)


def artefact_sensitivity_table(
    pairs: Sequence[str] = (
        "basketball-tennis",
        "basketball-tissue",
        "tennis-coin",
        "tennis-table-tennis",
    ),
    delays: Sequence[float] = (0.002, 0.004),
) -> str:
    """v1, v2 and the body's first touch at Delta x = 0, at a gap just deeper than the
    precursor's opening, and with the body released ``delays`` [s] after the ball."""
    from twoball.modal.pairs import PAIRS

    lines = [
        "| pair | start | first body touch [ms] | pi/c [ms] | v1/abs(v0) | v2/abs(v0) | "
        "t_l [ms] | contacts | body first |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name in pairs:
        p = PAIRS[name]
        opening = precursor(p.lower, p.cap_radius).opening
        gap = math.ceil(opening * 1.02e4) / 1e4  # the next 0.1 mm above the opening
        starts = [("touching", 0.0, 0.0), (f"gap {gap * 1e3:.1f} mm", gap, 0.0)]
        starts += [("gap 10 mm", 0.01, 0.0)]
        starts += [(f"released {tau * 1e3:g} ms later", 0.0, tau) for tau in delays]
        for label, g, tau in starts:
            run_ = whole(name, g, delay=tau)
            r, b = run_.result, run_.result.body
            c = run_.case.wave_speed
            first = b.intervals[0].start / c if b.intervals else math.nan
            t_l = (b.t_liftoff - r.t_max_compression) / c if b.t_liftoff is not None else math.nan
            lines.append(
                f"| {name} | {label} | {first * 1e3:.2f} | {math.pi / c * 1e3:.2f} | "
                f"{run_.v1:.3f} | {run_.v2:.3f} | {t_l * 1e3:.2f} | {b.contacts} | "
                f"{b.body_left_first} |"
            )
    return "\n".join(lines)


TABLES = {
    "limit_a": limit_a_table,
    "limit_b": limit_b_table,
    "limit_c": limit_c_table,
    "backends": backends_table,
    "defaults": defaults_table,
    "orders": orders_table,
    "sensitivity": sensitivity_table,
    "artefact": artefact_table,
    "artefact_sensitivity": artefact_sensitivity_table,
}


def main(names: Sequence[str] = ()) -> None:
    """Print the named tables (all by default)."""
    for name in names or TABLES:
        print(f"## {name}\n\n{TABLES[name]()}\n", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
