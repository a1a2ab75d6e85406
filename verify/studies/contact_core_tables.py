"""Tables of the contact core's measurements (the bar, the ball on the floor, settling).

``python -m twoball.verify.studies.contact_core_tables [names...]`` prints
Markdown tables of the contact core's measurements: the bar benchmark's
errors and orders, and the drop's tables of :mod:`twoball.verify.studies.floor`
(the ball on the floor against N, elements and dt, the energy at D = 0, the
settled ball).  A full run takes a few minutes on one core.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence

from twoball.verify.studies.bar_drop import bar_study
from twoball.verify.studies.floor import TABLES as FLOOR_TABLES
from twoball.verify.studies.orders import least_squares_order


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


TABLES: dict[str, Callable[[], str]] = {"bar": bar_table, **FLOOR_TABLES}


def main(names: Sequence[str] = ()) -> None:
    """Print the tables ``names`` (all when empty)."""
    for name in names or TABLES:
        print(f"\n## {name}\n", flush=True)
        print(TABLES[name](), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])

__all__ = ["TABLES", "bar_table", "main"]
