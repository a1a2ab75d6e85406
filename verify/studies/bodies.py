"""Tables of the elastic upper bodies: their inputs alone, e12 at large gaps, Table 1, row 4.

``python -m twoball.verify.studies.bodies [names...] [--cache FILE] [--workers N]``
prints the Markdown tables docs/bodies.rst quotes (all by default):

``presets``
    Each Table 1 body dropped alone on a rigid floor at 4.1 m/s: its stated
    restitution and its law's contact time against what comes back
    (:mod:`twoball.modal.upper.alone`).
``large_gaps``
    ``e12_effective`` of every pair at Delta x = 100-250 mm with each body
    kind (rigid: Newton's e12 of Table 1 on a cap; lumped; ball) beside the
    measured e12.  The inputs are fixed beforehand (:mod:`twoball.modal.bodies`):
    nothing is fitted to e12.
``table1``
    Table 1 at Delta x = 0 with each kind beside the measurements and the ICM.
``row4``
    Basketball and tennis ball at Delta x = 0: v1, v2, t_l, the contact, the
    disc and the books with each kind against the measured 1.8 / 0.61.
``collision``
    Two identical tennis membranes colliding in free space (the ball body's
    symmetric check), undamped, Newton's e = 0 and 1 at the rows.
``curves``
    v1 / |v0| and v2 / |v0| against Delta x for the three basketball pairs
    (Figs. 3 and 8) with each kind (the data of ``docs/make_body_figures.py``).

Every run is ``twoball.bounce``'s model at its defaults (Legendre N = 192,
dt = 0.005 / c, |v0| = 4.1 m/s) through :func:`~twoball.modal.floor.bounce.bounce_problem`
and :func:`~twoball.modal.floor.bounce.simulate`; runs are kept in ``--cache``
(JSON) so that the tables and the figures share them.  The whole set takes
about half an hour on two busy cores.
"""

from __future__ import annotations

import json
import math
import sys
from collections.abc import Iterable, Sequence
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Any

__all__ = ["GAPS", "KINDS", "TABLES", "Runs", "main", "run_one"]

#: The body kinds, in the tables' order.
KINDS = ("rigid", "lumped", "ball")
#: The large gaps [m] of e12_effective.
LARGE = (0.10, 0.15, 0.20, 0.25)
#: The gaps [m] of the curves (Figs. 3 and 8).
GAPS = (0.0, 0.005, 0.01, 0.015, 0.025, 0.035, 0.05, 0.075, 0.1, 0.15, 0.2, 0.25)
#: The basketball pairs of Figs. 3 and 8.
CURVE_PAIRS = ("basketball-tennis", "basketball-tissue", "basketball-table-tennis")


def has_ball(pair: str) -> bool:
    """Whether the pair's body has a ball body (the tennis ball)."""
    return pair.endswith("-tennis") and not pair.endswith("table-tennis")


def kinds_of(pair: str) -> tuple[str, ...]:
    """The kinds a pair's body has."""
    return KINDS if has_ball(pair) else KINDS[:2]


def run_one(key: tuple[str, str, float, str]) -> dict[str, Any]:
    """One whole bounce ``(pair, kind, gap [m], backend)`` at the defaults: its numbers (SI)."""
    import time

    from twoball._common.errors import NumericalError
    from twoball.fem_membrane.ball import FEBall
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.floor.bounce import bounce_problem, simulate
    from twoball.modal.floor.options import Drop

    pair, kind, gap, backend = key
    ball = LegendreBall() if backend == "legendre" else FEBall()
    start = time.perf_counter()
    problem = bounce_problem(drop=Drop(gap=gap), ball=ball, pair=pair, body=kind)
    try:
        report = simulate(problem)
    except NumericalError as error:  # kept, so that one failure does not lose the rest
        return {"pair": pair, "kind": kind, "gap": gap, "backend": backend, "error": str(error)}
    data = report.as_dict()
    contact = data.get("body_contact") or {}
    energy = data["energy_J"]
    return {
        "pair": pair,
        "kind": kind,
        "gap": gap,
        "backend": backend,
        "v1": data["v1_ratio"],
        "v2": data["v2_ratio"],
        "e2": data["e2"],
        "e12": data["e12_effective"],
        "t_l": data["t_liftoff_from_max_compression_s"],
        "t_liftoff": data["t_liftoff_s"],
        "body_left_first": data["body_left_first"],
        "sequence": data["sequence"],
        "contacts": data["body_contacts"],
        "duration": contact.get("duration_s"),
        "main_contact": contact.get("main_contact_s"),
        "peak_force": contact.get("peak_force_N"),
        "disc": contact.get("disc_max_radius_m"),
        "impulse_balance": data["impulse_balance"],
        "internal": energy.get("final_body_internal"),
        "body_dissipated": energy.get("body_dissipated"),
        "initial": energy["initial_kinetic"],
        "balance": energy["balance_error"],
        "steps": data["steps"],
        "wall": time.perf_counter() - start,
        "warnings": data["warnings"],
    }


#: The numbers of a run (:func:`run_one`).
FIELDS = (
    "v1", "v2", "e2", "e12", "t_l", "t_liftoff", "body_left_first", "sequence", "contacts",
    "duration", "main_contact", "peak_force", "disc", "impulse_balance", "internal",
    "body_dissipated", "initial", "balance", "steps", "wall",
)  # fmt: skip


class Runs:
    """Whole bounces by ``(pair, kind, gap, backend)``, computed once and kept in a JSON file."""

    def __init__(self, cache: str | Path | None = None, workers: int = 1) -> None:
        self.path = None if cache is None else Path(cache)
        self.workers = max(1, int(workers))
        self.data: dict[str, dict[str, Any]] = {}
        if self.path is not None and self.path.is_file():
            self.data = json.loads(self.path.read_text())

    @staticmethod
    def key(pair: str, kind: str, gap: float, backend: str = "legendre") -> str:
        return f"{pair}|{kind}|{gap:.4f}|{backend}"

    def ensure(self, keys: Iterable[tuple[str, str, float, str]]) -> None:
        """Compute the runs not kept yet (on ``workers`` processes) and save them."""
        todo = [k for k in dict.fromkeys(keys) if self.key(*k) not in self.data]
        if not todo:
            return
        pool = ProcessPoolExecutor(self.workers) if self.workers > 1 else None
        try:
            results = pool.map(run_one, todo) if pool is not None else map(run_one, todo)
            for k, r in zip(todo, results, strict=True):
                self.data[self.key(*k)] = r
                if self.path is not None:  # kept as they come
                    self.path.write_text(json.dumps(self.data, indent=1, sort_keys=True) + "\n")
        finally:
            if pool is not None:
                pool.shutdown()

    def get(self, pair: str, kind: str, gap: float, backend: str = "legendre") -> dict[str, Any]:
        """The run's numbers (a failed run: ``error`` and every number None)."""
        self.ensure([(pair, kind, gap, backend)])
        out = self.data[self.key(pair, kind, gap, backend)]
        if "error" in out:
            return {k: None for k in FIELDS} | out
        return out


def _f(value: float | None, digits: int = 3) -> str:
    return (
        "-"
        if value is None or (isinstance(value, float) and math.isnan(value))
        else (f"{value:.{digits}f}")
    )


def presets_table(runs: Runs | None = None) -> str:
    """Each body alone on a rigid floor at 4.1 m/s: stated against measured."""
    from twoball.modal.bodies import preset_body
    from twoball.modal.pairs import PAIRS
    from twoball.modal.upper.alone import ball_alone, lumped_alone

    lines = [
        "| pair | body's law | k [N/m or N/m^1.5] | m1 [g] | e stated | e alone | "
        "contact stated [ms] | contact alone [ms] | undamped closed form [ms] | "
        "peak compression [mm] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, pair in PAIRS.items():
        body = preset_body(name, "lumped")
        alone = lumped_alone(body, pair.m1, 4.1)
        lines.append(
            f"| {name} | {body.law.law} | {body.law.stiffness():.4g} | {pair.m1 * 1e3:.3g} | "
            f"{body.restitution:.3f} | {alone.restitution:.4f} | "
            f"{alone.stated_contact_time * 1e3:.4g} | {alone.contact_time * 1e3:.4g} | "
            f"{alone.undamped_contact_time * 1e3:.4g} | {alone.peak_compression * 1e3:.3g} |"
        )
    body = preset_body("basketball-tennis", "ball")
    alone, _ = ball_alone(body, 4.1)
    lines.append(
        f"| (ball body) | tennis membrane, N = 64, D = {body.damping.ratio:g} | - | "
        f"{alone.mass * 1e3:.3g} | {body.restitution:.3f} | {alone.restitution:.4f} | - | "
        f"{alone.contact_time * 1e3:.4g} | - | {alone.peak_compression * 1e3:.3g} |"
    )
    return "\n".join(lines)


def large_gaps_table(runs: Runs | None = None, gaps: Sequence[float] = LARGE) -> str:
    """e12_effective at large gaps with each kind beside the measured e12 (Table 1)."""
    from twoball.modal.pairs import PAIRS

    runs = Runs() if runs is None else runs
    keys = [(p, k, g, "legendre") for p in PAIRS for k in kinds_of(p) for g in gaps]
    runs.ensure(keys)
    head = " | ".join(f"{g * 1e3:g} mm" for g in gaps)
    lines = [
        f"| pair | measured e12 | kind | {head} | mean | mean / measured |",
        "|---|---|---|" + "---|" * len(gaps) + "---|---|",
    ]
    for name, pair in PAIRS.items():
        for kind in kinds_of(name):
            values = [runs.get(name, kind, g)["e12"] for g in gaps]
            ok = [v for v in values if v is not None]
            mean = sum(ok) / len(ok) if ok else None
            ratio = None if mean is None else mean / pair.e12
            cells = " | ".join(_f(v) for v in values)
            lines.append(
                f"| {name} | {pair.e12:g} | {kind} | {cells} | {_f(mean)} | {_f(ratio, 2)} |"
            )
    return "\n".join(lines)


def table1_table(runs: Runs | None = None) -> str:
    """Table 1 at Delta x = 0: measured, the ICM printed, and each kind (v1 / v2 over |v0|)."""
    from twoball.modal.icm.table1 import TABLE1
    from twoball.modal.pairs import PAIRS

    runs = Runs() if runs is None else runs
    runs.ensure([(p, k, 0.0, "legendre") for p in PAIRS for k in kinds_of(p)])
    lines = [
        "| row | pair | measured | ICM printed | rigid | lumped | ball | "
        "t_l rigid / lumped / ball [ms] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for name, pair in PAIRS.items():
        row = TABLE1[pair.row - 1]
        cells, times = [], []
        for kind in KINDS:
            if kind not in kinds_of(name):
                cells.append("-")
                times.append("-")
                continue
            r = runs.get(name, kind, 0.0)
            cells.append(f"{_f(r['v1'])} / {_f(r['v2'])}")
            times.append(_f(None if r["t_l"] is None else r["t_l"] * 1e3, 2))
        measured = f"{row.measured_v1:g} / {row.measured_v2:g}"
        icm = f"{row.icm_v1:g} / {row.icm_v2:g}"
        lines.append(
            f"| {pair.row} | {name} | {measured} | {icm} | "
            + " | ".join(cells)
            + " | "
            + " / ".join(times)
            + " |"
        )
    return "\n".join(lines)


def row4_table(runs: Runs | None = None) -> str:
    """Basketball and tennis ball at Delta x = 0 with each kind (Table 1's row 4: 1.8 / 0.61)."""
    runs = Runs() if runs is None else runs
    pair = "basketball-tennis"
    runs.ensure([(pair, k, 0.0, b) for k in KINDS for b in ("legendre", "fem")])
    lines = [
        "| kind | backend | v1/abs(v0) | v2/abs(v0) | t_l [ms] | body contact [ms] (main) | "
        "peak force [N] | disc [mm] | body first | momentum books | energy books [J] |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for kind in KINDS:
        for backend in ("legendre", "fem"):
            r = runs.get(pair, kind, 0.0, backend)
            tl = None if r["t_l"] is None else r["t_l"] * 1e3
            main = r.get("main_contact")
            dur = None if main is None else main * 1e3
            disc = None if r["disc"] is None else r["disc"] * 1e3
            lines.append(
                f"| {kind} | {backend} | {_f(r['v1'], 4)} | {_f(r['v2'], 4)} | {_f(tl, 2)} | "
                f"{_f(dur, 2)} | {_f(r['peak_force'], 1)} | {_f(disc, 1)} | "
                f"{r['body_left_first']} | {r['impulse_balance']:.1e} | {r['balance']:.1e} |"
            )
    lines.append("| measured (Table 1, row 4) | | 1.8 | 0.61 | | | | | | | |")
    return "\n".join(lines)


def collision_table(runs: Runs | None = None, modes: Sequence[int] = (32, 64)) -> str:
    """Two undamped tennis membranes colliding head-on at +-4.1 m/s in free space."""
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.damping import ModalRatio
    from twoball.modal.floor.inputs import resolve_drop
    from twoball.modal.floor.options import Drop
    from twoball.modal.parameters import Case
    from twoball.modal.upper.collide import free_collision

    inputs = resolve_drop(Case.preset("tennis"), Drop(), ModalRatio(0.0))
    lines = [
        "| N | Newton e at the rows | centre of mass max abs(v) | mirror (rel.) | "
        "energy books (rel.) | lost at impacts | centres' kinetic left | vibration left | "
        "e between the centres | contact [ms] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for n in modes:
        ball = LegendreBall(n).describe(inputs.case)
        for e in (0.0, 1.0):
            r = free_collision(ball, inputs.v0, restitution=e)
            contact = (r.contact_time or math.nan) / inputs.case.wave_speed * 1e3
            lines.append(
                f"| {n} | {e:g} | {r.centre_of_mass:.1e} | {r.mirror:.1e} | "
                f"{r.energy_balance:.1e} | {r.impact_loss:.4f} | {r.rigid_left:.4f} | "
                f"{r.vibration_left:.4f} | {r.restitution:.4f} | {contact:.3f} |"
            )
    return "\n".join(lines)


def curves(runs: Runs, pairs: Sequence[str] = CURVE_PAIRS, gaps: Sequence[float] = GAPS) -> dict:
    """``{pair: {kind: {"gap", "v1", "v2", "t_l"}}}`` of the gap curves (Figs. 3 and 8)."""
    runs.ensure([(p, k, g, "legendre") for p in pairs for k in kinds_of(p) for g in gaps])
    out: dict[str, dict[str, dict[str, list]]] = {}
    for pair in pairs:
        out[pair] = {}
        for kind in kinds_of(pair):
            rows = [runs.get(pair, kind, g) for g in gaps]
            out[pair][kind] = {
                "gap": list(gaps),
                "v1": [r["v1"] for r in rows],
                "v2": [r["v2"] for r in rows],
                "t_l": [r["t_l"] for r in rows],
                "e12": [r["e12"] for r in rows],
            }
    return out


def curves_table(runs: Runs | None = None) -> str:
    """The curves as a table: v1 / v2 over |v0| per gap, pair and kind."""
    runs = Runs() if runs is None else runs
    data = curves(runs)
    lines = []
    for pair, kinds in data.items():
        head = " | ".join(kinds)
        lines += [f"**{pair}**", "", f"| gap [mm] | {head} |", "|---|" + "---|" * len(kinds)]
        for i, gap in enumerate(GAPS):
            cells = " | ".join(f"{_f(k['v1'][i])} / {_f(k['v2'][i])}" for k in kinds.values())
            lines.append(f"| {gap * 1e3:g} | {cells} |")
        lines.append("")
    return "\n".join(lines)


TABLES = {
    "presets": presets_table,
    "large_gaps": large_gaps_table,
    "table1": table1_table,
    "row4": row4_table,
    "collision": collision_table,
    "curves": curves_table,
}


def main(argv: Sequence[str] = ()) -> None:
    """Print the named tables (all by default); ``--cache FILE``, ``--workers N``."""
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="tables: " + ", ".join(TABLES))
    parser.add_argument("--cache", default=None, help="JSON file of the runs (kept)")
    parser.add_argument("--workers", type=int, default=1)
    args = parser.parse_args(list(argv))
    unknown = [n for n in args.names if n not in TABLES]
    if unknown:
        parser.error(f"unknown tables {unknown}: choose from {', '.join(TABLES)}")
    runs = Runs(args.cache, args.workers)
    for name in args.names or TABLES:
        print(f"## {name}\n\n{TABLES[name](runs)}\n", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
