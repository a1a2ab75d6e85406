"""Tables of the solid ball and the thick wall: spectrum, Hertz, backends, Table 1.

``python -m twoball.verify.studies.solid [names...]`` prints the Markdown tables
docs/solid.rst quotes:

``spectrum``
    Lamb's roots (closed form) against the issue's references, and the (r, z) P2
    eigenvalues' relative error on the half disc at levels 2-4 (order-4 decay).
``hertz``
    The undamped superball dropped at ``|v0| = 4.1, 1.0, 0.25`` m/s (and 0.06 with
    ``hertz_slow``): contact time and peak force against Hertz's, both backends,
    with the regime numbers (``t_H / T_2``, ``a / R``, floor points in the contact).
``agreement``
    The superball with a body of mu = 0.01 on both backends at growing resolution:
    the body's lift-off time and speed, the contact time.
``agreement_dt``
    The same at the default step, half and a quarter of it: the last separation
    ``t_l`` moves by 1e-3 to 3e-3 as the step is halved (the chatter's sequence
    changes), the body's speed and the impulse centroid ``t_J`` far less.
``thin``
    The annulus of h / R = 0.01 against the thin shell's two branches, n = 0..10.
``tennis``
    The tennis ball as the thick wall beside the shell (its wall at nu = 0.5 and at the
    thick wall's 0.45) and the measurements: the drop (e2, contact time) and Table 1's
    rows 1-3 at Delta x = 0.
``superball``
    The two-ball bounce on the superball beside a membrane and a shell of the same size
    and mass (the membrane's pressure chosen so that its pressure x area contact time is
    the superball's).

The whole run takes about forty minutes on one core (``agreement_dt`` half of it).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["TABLES", "drop", "impulse_centroid_s", "main"]


def drop(case: Any, ball: Any, body: Any = None, pair: str | None = None) -> Any:
    """One drop or whole bounce in SI (:func:`~twoball.modal.floor.bounce.simulate`)."""
    from twoball.modal.floor.bounce import bounce_problem, simulate

    return simulate(bounce_problem(case, ball=ball, body=body, pair=pair))


def _row(cells: Sequence[Any]) -> str:
    return "| " + " | ".join(str(c) for c in cells) + " |"


def _table(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    lines = [_row(header), _row(["---"] * len(header))]
    return "\n".join(lines + [_row(r) for r in rows])


def spectrum_table() -> str:
    """Lamb's roots against the references, and the FE eigenvalues' errors by level."""
    from twoball.fem_solid.eigen import axisymmetric_eigen
    from twoball.fem_solid.mesh import half_disc
    from twoball.modal.balls.solid import lamb_table

    references = {
        0.25: {(2, 1): 2.6399, (2, 2): 4.8653, (3, 1): 3.9163, (0, 1): 4.4400},
        1 / 3: {(2, 1): 2.6501, (3, 1): 3.9502, (0, 1): 5.4874},
        0.45: {(2, 1): 2.6615, (3, 1): 3.9882, (0, 1): 10.005},
    }
    rows = []
    for nu, values in references.items():
        table = lamb_table(nu, 3, 2)
        for (n, k), ref in values.items():
            eta = table.eta[(table.degree == n) & (table.radial_order == k)][0]
            fe = []
            for level in (2, 3, 4):
                eig = axisymmetric_eigen(half_disc(level), nu, 40, max_degree=14)
                found = np.sort(eig.eta[(eig.degree == n) & ~eig.rigid])
                fe.append(f"{abs(found[k - 1] / eta - 1):.1e}" if found.size >= k else "-")
            rows.append([f"{nu:.4g}", n, k, f"{eta:.6f}", ref, *fe])
    header = ["nu", "n", "k", "closed form", "reference", "FE level 2", "level 3", "level 4"]
    return _table(header, rows)


def _hertz_run(v0: float, ball: Any) -> dict[str, float]:

    from twoball.modal.balls.solid import solid_case

    case = solid_case("superball", v0=v0, g=1e-6)
    report = drop(case, ball)
    hertz = report.model["hertz"]
    _, force = report.result.force
    peak = float(force.max()) * report.mass_kg * case.radius * case.wave_speed**2
    return {
        "time": report.contact_time_s / hertz["contact_time_s"] - 1.0,
        "force": peak / hertz["peak_force_N"] - 1.0,
        "regime": hertz["quasi_static_ratio"],
        "angle": hertz["contact_angle_rad"],
        "speed": hertz["speed_ratio"],
        "points": hertz["contact_points_expected"],
        "t_ms": hertz["contact_time_s"] * 1e3,
        "e2": report.e2,
    }


#: (|v0| [m/s], Legendre N, finite-element pole levels on level 3)
HERTZ_CASES = ((4.1, 64, 0), (1.0, 112, 1), (0.25, 192, 2))


def hertz_table(cases: Sequence[tuple[float, int, int]] = HERTZ_CASES) -> str:
    """The drop against Hertz on both backends, with the regime numbers."""
    from twoball.fem_solid.ball import FESolidBall
    from twoball.modal.balls.solid import SolidBall

    rows = []
    for v0, modes, pole in cases:
        modal = _hertz_run(v0, SolidBall(modes=modes))
        fe = _hertz_run(v0, FESolidBall(level=3, pole_levels=pole))
        rows.append(
            [
                v0,
                f"{modal['speed']:.3g}",
                f"{modal['regime']:.2f}",
                f"{modal['angle']:.3f}",
                f"{modal['t_ms']:.3f}",
                f"{100 * modal['time']:+.2f}",
                f"{100 * fe['time']:+.2f}",
                f"{100 * modal['force']:+.2f}",
                f"{100 * fe['force']:+.2f}",
                f"{modal['e2']:.4f}",
            ]
        )
    header = [
        "|v0| [m/s]", "|v0|/c_s", "t_H/T_2", "a/R", "t_H [ms]", "t_c/t_H-1 [%] lamb",
        "fem", "F/F_H-1 [%] lamb", "fem", "e2",
    ]  # fmt: skip
    return _table(header, rows)


def agreement_table(balls: Sequence[Any] | None = None, mass_ratio: float = 0.01) -> str:
    """The superball with a body on both backends at growing resolution."""

    from twoball.fem_solid.ball import FESolidBall
    from twoball.modal.balls.solid import SolidBall, solid_case
    from twoball.modal.contact.body import Body

    if balls is None:
        balls = (
            SolidBall(modes=64),
            SolidBall(modes=128),
            SolidBall(modes=192, radial_orders=12),
            FESolidBall(level=3),
            FESolidBall(level=4),
            FESolidBall(level=4, top_levels=1),
        )
    case = solid_case("superball")
    rows = []
    for ball in balls:
        report = drop(case, ball, body=Body(mass_ratio))
        rows.append(
            [
                ball.label,
                report.result.system.ball.modes,
                f"{report.t_liftoff_s * 1e3:.5f}",
                f"{report.v1_m_s:.5f}",
                f"{report.v2_ratio:.5f}",
                f"{report.contact_time_s * 1e3:.5f}",
                report.result.body.contacts,
            ]
        )
    header = [
        "resolution",
        "coordinates",
        "t_l [ms]",
        "v1 [m/s]",
        "v2/|v0|",
        "t_c [ms]",
        "contacts",
    ]
    return _table(header, rows)


def impulse_centroid_s(report: Any) -> float:
    """The body's impulse-weighted mean contact time ``t_J = int t F dt / int F dt`` [s].

    An integral of the body's contact force over the whole bounce (from the first
    floor touch): the top's ringing, which moves the zero of the force at the last
    separation ``t_l`` by about a step, averages out of it.
    """
    t, force = report.result.body_force
    t = np.asarray(t, dtype=float)
    weight = np.asarray(force, dtype=float) * np.gradient(t)
    return float((t * weight).sum() / weight.sum()) / report.case.wave_speed


def agreement_dt_table(
    balls: Sequence[Any] | None = None,
    divisors: Sequence[int] = (1, 2, 4),
    mass_ratio: float = 0.01,
) -> str:
    """The body's lift-off on both backends at the default step and its halvings."""
    from twoball.fem_solid.ball import FESolidBall
    from twoball.modal.balls.solid import SolidBall, solid_case
    from twoball.modal.contact.body import Body
    from twoball.modal.floor.bounce import bounce_problem, simulate
    from twoball.modal.floor.inputs import DEFAULT_DT

    if balls is None:
        balls = (
            SolidBall(modes=64),
            SolidBall(modes=128),
            SolidBall(modes=192, radial_orders=12),
            FESolidBall(level=3),
        )
    case = solid_case("superball")
    rows = []
    for ball in balls:
        for divisor in divisors:
            dt = DEFAULT_DT / case.wave_speed / divisor
            problem = bounce_problem(case, ball=ball, body=Body(mass_ratio), dt=dt)
            report = simulate(problem)
            centroid = impulse_centroid_s(report) * 1e3
            rows.append(
                [
                    ball.label,
                    f"{dt * 1e6:.4g}",
                    f"{report.t_liftoff_s * 1e3:.5f}",
                    f"{report.v1_m_s:.5f}",
                    f"{centroid:.5f}",
                    report.result.body.contacts,
                ]
            )
    header = ["resolution", "dt [us]", "t_l [ms]", "v1 [m/s]", "t_J [ms]", "contacts"]
    return _table(header, rows)


def thin_table(nu: float = 0.3, ratio: float = 0.01) -> str:
    """The annulus of h / R = ``ratio`` against the thin shell's branches (Omega)."""
    from twoball.fem_solid.eigen import axisymmetric_eigen
    from twoball.fem_solid.mesh import half_annulus
    from twoball.modal.shell.parameters import ShellParameters
    from twoball.modal.shell.spectrum import branches

    fe = axisymmetric_eigen(half_annulus(1.0 - ratio, 2, 256), nu, 90, max_degree=70)
    middle = 1.0 - ratio / 2.0
    omega = fe.eta * middle * math.sqrt((1.0 - nu) / 2.0)
    lower, upper = branches(ShellParameters.from_ratios(nu, thickness_ratio=ratio / middle), 11)
    rows = []
    for n in range(11):
        found = np.sort(omega[(fe.degree == n) & ~fe.rigid])
        refs = [lower[0]] if n == 0 else [upper[1]] if n == 1 else [lower[n], upper[n]]
        cells = [n]
        for value, ref in zip(found, refs, strict=False):
            cells += [f"{value:.6f}", f"{ref:.6f}", f"{abs(value / ref - 1) / ratio:.3f}"]
        rows.append(cells + [""] * (7 - len(cells)))
    header = ["n", "annulus", "shell", "|rel| / (h/R)", "annulus", "shell", "|rel| / (h/R)"]
    return _table(header, rows)


def tennis_table() -> str:
    """The tennis ball: thick wall, shell (nu = 0.5 and 0.45), measurements."""
    from twoball.fem_solid.ball import ThickBall
    from twoball.modal.balls.shell import ShellBall, Wall
    from twoball.modal.floor.references import TABLE1_E2
    from twoball.modal.pairs import pair as find_pair
    from twoball.modal.parameters import Case

    balls = {
        "thick wall (2 x 96 P2)": ThickBall(),
        "shell (nu 0.5)": ShellBall(),
        "shell (nu 0.45)": ShellBall(wall=Wall(youngs_modulus=6e6, thickness=3.2e-3, poisson=0.45)),
    }
    rows = []
    for name, ball in balls.items():
        alone = drop(Case.preset("tennis"), ball)
        cells = [name, f"{alone.e2:.3f}", f"{alone.contact_time_s * 1e3:.2f}"]
        for pair in ("tennis-coin", "tennis-nut", "tennis-table-tennis"):
            whole = drop(None, ball, pair=pair)
            cells.append(f"{whole.v1_ratio:.2f} / {whole.v2_ratio:.2f}")
        rows.append(cells)
    measured = ["measured (Table 1)", f"{TABLE1_E2['tennis'][0]:.2f}", "-"]
    for pair in ("tennis-coin", "tennis-nut", "tennis-table-tennis"):
        row = find_pair(pair).table1
        measured.append(f"{row.measured_v1:.2f} / {row.measured_v2:.2f}")
    rows.append(measured)
    header = ["tennis ball", "e2", "t_c [ms]", "coin v1/v2", "nut v1/v2", "table tennis v1/v2"]
    return _table(header, rows)


def superball_table(mass_ratio: float = 0.01) -> str:
    """The two-ball bounce on the superball beside a membrane and a shell of its size and mass."""

    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.balls.shell import ShellBall, Wall
    from twoball.modal.balls.solid import MATERIALS, SolidBall, solid_case
    from twoball.modal.contact.body import Body
    from twoball.modal.parameters import Case

    case = solid_case("superball")
    solid = drop(case, SolidBall())
    radius, mass = case.radius, MATERIALS["superball"].mass(case.radius)
    # the membrane's pressure whose pressure x area contact time pi sqrt(m / (2 pi R P)) is the
    # superball's contact time
    pressure = mass * (math.pi / solid.contact_time_s) ** 2 / (2.0 * math.pi * radius)
    membrane_case = Case.from_pressure(
        pressure, mass, preset=None, radius=radius, v0=case.v0, damping=0.0
    )
    balls = {
        "solid (Lamb, N = 64)": (case, SolidBall()),
        "membrane (N = 192)": (membrane_case, LegendreBall()),
        "shell (C/N0 = 4, h/R = 1/30)": (
            membrane_case,
            ShellBall(wall=Wall(wall_stiffness_ratio=4.0, thickness_ratio=1 / 30)),
        ),
    }
    rows = []
    for name, (ball_case, ball) in balls.items():
        alone = drop(ball_case, ball)
        whole = drop(ball_case, ball, body=Body(mass_ratio))
        rows.append(
            [
                name,
                f"{alone.contact_time_s * 1e3:.3f}",
                f"{alone.e2:.3f}",
                f"{whole.v1_ratio:.3f}",
                f"{whole.v2_ratio:.3f}",
                f"{whole.t_liftoff_s * 1e3:.3f}",
                whole.result.body.contacts,
            ]
        )
    header = ["lower ball", "t_c [ms]", "e2", "v1/|v0|", "v2/|v0|", "t_l [ms]", "contacts"]
    note = (
        f"\n\nR = {radius} m, m = {mass:.4g} kg, |v0| = {case.v0} m/s, D = 0, mu = {mass_ratio}, "
        f"a = R/10, e12 = 0; the membrane's and the shell's P = {pressure:.4g} Pa "
        f"(c = {membrane_case.wave_speed:.4g} 1/s)."
    )
    return _table(header, rows) + note


TABLES = {
    "spectrum": spectrum_table,
    "hertz": hertz_table,
    "hertz_slow": lambda: hertz_table(((0.06, 280, 3),)),
    "agreement": agreement_table,
    "agreement_dt": agreement_dt_table,
    "thin": thin_table,
    "tennis": tennis_table,
    "superball": superball_table,
}


def main(names: Sequence[str] = ()) -> None:
    """Print the tables named (default every one but ``hertz_slow``)."""
    chosen = list(names) or [n for n in TABLES if n != "hertz_slow"]
    for name in chosen:
        if name not in TABLES:
            raise SystemExit(f"unknown table {name!r}: one of {', '.join(TABLES)}")
        print(f"## {name}\n\n{TABLES[name]()}\n", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
