"""Tables of the contact core's measurements (the bar, the ball on the floor, settling).

``python -m twoball.verify.studies.contact_core_tables [names...]`` prints
Markdown tables of every number the contact core's notes quote: the bar
benchmark's errors and orders, the modal and axisymmetric-FE drops against N,
elements and dt, the energy budget at D = 0, and the settled ball.  A full run
takes a few minutes on one core.  Dimensionless units (R, 1/c, m2).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence

import numpy as np
from twoball.modal.floor_prototype import DropResult, FloorModel, drop, settle
from twoball.verify.studies.bar_drop import bar_study
from twoball.verify.studies.orders import least_squares_order

FIELDS = ("contact_time", "e2", "phi_a_max", "flattening_max", "energy_lost_impacts")
RAYLEIGH = (0.47273, 0.011818)  # zeta = alpha/(2 omega) + beta omega/2 = 0.13 at omega = 2, 20


def _row(label: str, r: DropResult) -> str:
    return (
        f"| {label} | {r.contact_time:.6f} | {r.e2:.7f} | {r.phi_a_max:.5f} | "
        f"{r.flattening_max:.7f} | {r.energy_lost_impacts:.3e} | {r.energy_error:.1e} | "
        f"{r.impulse_balance:.1e} | {r.steps} | {r.wall_s:.2f} |"
    )


HEADER = (
    "| run | t_c | e2 | phi_a,max | flattening | impact loss / KE0 | energy error | "
    "impulse balance | steps | wall [s] |\n|---|---|---|---|---|---|---|---|---|---|"
)


def _orders(steps: Sequence[float], results: Sequence[DropResult]) -> str:
    """Observed orders of successive differences ``log(d_k / d_k+1) / log(h_k / h_k+1)``."""
    lines = []
    for name in FIELDS:
        v = np.array([getattr(r, name) for r in results], dtype=float)
        d = np.abs(np.diff(v))
        with np.errstate(divide="ignore", invalid="ignore"):
            p = np.log(d[:-1] / d[1:]) / np.log(np.asarray(steps[:-2]) / np.asarray(steps[1:-1]))
        lines.append(f"- {name}: successive-difference orders {np.round(p, 2).tolist()}")
    return "\n".join(lines)


def modes_table(damping: float = 0.13, modes: Sequence[int] = (20, 40, 80, 160, 320)) -> str:
    """Modal drops against N (points N/2, dt = 0.01)."""
    runs = [drop(FloorModel(modes=n, points=n // 2, damping=damping), 0.01) for n in modes]
    rows = [_row(f"N = {n}", r) for n, r in zip(modes, runs, strict=True)]
    return "\n".join([HEADER, *rows, "", _orders([1 / n for n in modes], runs)])


def elements_table(
    damping: float = 0.13, elements: Sequence[int] = (10, 20, 40, 80, 160), **options: object
) -> str:
    """Axisymmetric P2 drops against the number of elements (dt = 0.01)."""
    from twoball.fem_membrane.floor_prototype import AxisymFloorModel, axisym_drop

    runs = [
        axisym_drop(AxisymFloorModel(elements=e, damping=damping, **options), 0.01)
        for e in elements
    ]
    rows = [_row(f"E = {e}", r) for e, r in zip(elements, runs, strict=True)]
    return "\n".join([HEADER, *rows, "", _orders([1 / e for e in elements], runs)])


def dt_table(
    model: FloorModel,
    steps: Sequence[float] = (0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125),
    localise: bool = True,
) -> str:
    """Drops of one model against dt; errors against the finest dt and least-squares orders."""
    runs = [drop(model, dt, localise=localise) for dt in steps]
    ref = runs[-1]
    lines = [HEADER, *[_row(f"dt = {dt}", r) for dt, r in zip(steps, runs, strict=True)], ""]
    for name in FIELDS:
        e = [abs(getattr(r, name) - getattr(ref, name)) for r in runs[:-1]]
        fit = least_squares_order(steps[:-1], e).order
        lines.append(f"- {name}: errors {[f'{x:.1e}' for x in e]}, least-squares order {fit:.2f}")
    return "\n".join(lines)


def bar_table() -> str:
    """Bar benchmark: errors and least-squares orders (dt = h, and dt = h/2)."""
    lines = []
    for case in ("clamped", "free"):
        for courant in (1.0, 0.5):
            study = bar_study(case, (20, 40, 80, 160, 320), courant=courant)
            lines.append(f"\n{case}, dt = {courant:g} h\n")
            lines.append("| elements | displacement | force L1 | impulse | energy loss |")
            lines.append("|---|---|---|---|---|")
            for r in study.runs:
                lines.append(
                    f"| {r.elements} | {r.displacement:.3e} | {r.force_l1:.3e} | "
                    f"{r.impulse:.3e} | {r.energy_loss:.3e} |"
                )
            fits = {
                n: round(least_squares_order(study.steps()[1:], study.errors(n)[1:]).order, 3)
                for n in ("displacement", "force_l1", "impulse", "energy_loss")
            }
            lines.append(f"\nleast-squares orders over 40..320: {fits}")
    return "\n".join(lines)


def settle_table(modes: Sequence[int] = (60, 90, 120, 180, 240, 360, 480)) -> str:
    """Settled ball (D = 0.9): floor force against weight, contact caps against m2 g / P."""
    lines = [
        "| N | force/weight - 1 | inner cap / (m2 g/P) | outer cap / (m2 g/P) | points | wall |",
        "|---|---|---|---|---|---|",
    ]
    for n in modes:
        r = settle(FloorModel(modes=n, points=n // 2, damping=0.9))
        inner, outer = (a / r.pressure_area for a in r.contact_area)
        lines.append(
            f"| {n} | {r.floor_force / r.weight - 1:.1e} | {inner:.3f} | {outer:.3f} | "
            f"{r.contact_points} | {r.wall_s:.1f} |"
        )
    return "\n".join(lines)


TABLES: dict[str, Callable[[], str]] = {
    "bar": bar_table,
    "modes": lambda: modes_table(0.13),
    "modes_undamped": lambda: modes_table(0.0),
    "elements": lambda: elements_table(0.13),
    "elements_undamped": lambda: elements_table(0.0),
    "dt": lambda: dt_table(FloorModel(modes=40, points=20, damping=0.13)),
    "dt_undamped": lambda: dt_table(FloorModel(modes=40, points=20, damping=0.0)),
    "dt_classical": lambda: dt_table(FloorModel(modes=40, points=20, damping=0.13), localise=False),
    "rayleigh_modes": lambda: "\n".join(
        [HEADER]
        + [
            _row(f"N = {n}", drop(FloorModel(modes=n, points=n // 2, rayleigh=RAYLEIGH), 0.01))
            for n in (40, 80, 160)
        ]
    ),
    "rayleigh_elements": lambda: elements_table(0.0, (20, 40, 80), rayleigh=RAYLEIGH),
    "restitution_one": lambda: "\n".join(
        [HEADER]
        + [
            _row(
                f"N = {n}",
                drop(FloorModel(modes=n, points=n // 2, damping=0.0, restitution=1.0), 0.01),
            )
            for n in (20, 40, 80, 160)
        ]
    ),
    "settle": settle_table,
}


def main(names: Sequence[str] = ()) -> None:
    """Print the tables ``names`` (all when empty)."""
    for name in names or TABLES:
        print(f"\n## {name}\n", flush=True)
        print(TABLES[name](), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])

__all__ = ["TABLES", "bar_table", "dt_table", "elements_table", "main", "modes_table"]
