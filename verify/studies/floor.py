"""Tables of the drop on the floor: presets, speeds, convergence, energy, rest, special case.

``python -m twoball.verify.studies.floor [names...]`` prints Markdown tables of
every number docs/bounce.rst quotes (a full run takes a few minutes on one
core).  The drops start from the SI case (:func:`twoball.modal.floor.model.resolve_drop`,
as ``twoball.bounce`` does) and run on the Legendre modes and on axisymmetric
P2 elements; convergence tables are dimensionless (R, 1/c, m2), the others SI.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from twoball.fem_membrane.floor import axisym_ball
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.floor.ball import legendre_ball
from twoball.modal.floor.drop import DropResult, DropSettings, run_drop
from twoball.modal.floor.model import DropModel, resolve_drop
from twoball.modal.floor.options import Drop
from twoball.modal.floor.references import MEASURED_COMPRESSION, TABLE1_E2, pressure_area
from twoball.modal.floor.settle import settle
from twoball.modal.floor.system import floor_system
from twoball.modal.parameters import Case
from twoball.verify.studies.orders import least_squares_order

__all__ = ["TABLES", "FloorRun", "drop_model", "main", "run"]

#: The defaults of ``twoball.bounce``: Legendre N, P2 elements, time step (units 1/c), window.
MODES, ELEMENTS, DT, WINDOW = 192, 96, 0.005, 10.0 * math.pi


@dataclass(frozen=True)
class FloorRun:
    """One drop with the model it ran (dimensionless result, SI model)."""

    model: DropModel
    result: DropResult
    wall_s: float


def drop_model(
    preset: str = "basketball",
    membrane: str = "paper",
    damping: str = "modal",
    v0: float | None = None,
    restitution: float = 0.0,
    ratio: float | None = None,
) -> DropModel:
    """The drop of a preset in SI, as ``twoball.bounce`` resolves it."""
    case = Case.preset(preset) if v0 is None else Case.preset(preset, v0=v0)
    if ratio is not None:
        case = case.derive(damping=ratio)
    law = Rayleigh() if damping == "rayleigh" else None
    return resolve_drop(case, Drop(membrane=membrane, floor_restitution=restitution), law)


def run(
    model: DropModel, backend: str = "legendre", size: int | None = None, dt: float = DT
) -> FloorRun:
    """Drop ``model`` on the Legendre modes (size N) or P2 elements (size E)."""
    start = time.perf_counter()
    if backend == "legendre":
        ball = legendre_ball(size or MODES, model.spectrum, model.law)
    else:
        ball = axisym_ball(size or ELEMENTS, 2, model.spectrum, model.law)
    system = floor_system(ball, model.gamma, model.drop.floor_restitution)
    result = run_drop(system, DropSettings(model.v0, model.gamma, dt, WINDOW))
    return FloorRun(model, result, time.perf_counter() - start)


FIELDS = ("contact_time", "e2", "phi_a_max", "flattening_max")


def _impact_loss(r: DropResult) -> float:
    return -r.energy["impacts"] / (0.5 * r.settings.v0**2)


def _si(run_: FloorRun) -> dict[str, float]:
    case, r = run_.model.case, run_.result
    return {
        "t_c [ms]": r.contact_time / case.wave_speed * 1e3,
        "e2": r.e2,
        "phi_a,max [rad]": r.phi_a_max,
        "flattening [mm]": r.flattening_max * case.radius * 1e3,
        "t_max [ms]": r.t_max_compression / case.wave_speed * 1e3,
    }


def presets_table(v0: float = 4.1) -> str:
    """Basketball and tennis at ``v0``: both operators, both damping laws, both backends."""
    lines = [
        "| ball | membrane | damping | backend | t_c [ms] | e2 | phi_a,max [rad] | "
        "flattening [mm] | t_max [ms] | wall [s] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    refs = []
    for preset in ("basketball", "tennis"):
        for membrane in ("paper", "pressurised"):
            for damping in ("modal", "rayleigh"):
                model = drop_model(preset, membrane, damping, v0)
                for backend in ("legendre", "fem"):
                    r = run(model, backend)
                    v = _si(r)
                    lines.append(
                        f"| {preset} | {membrane} | {damping} | {backend} | "
                        f"{v['t_c [ms]']:.3f} | {v['e2']:.4f} | {v['phi_a,max [rad]']:.4f} | "
                        f"{v['flattening [mm]']:.3f} | {v['t_max [ms]']:.3f} | {r.wall_s:.2f} |"
                    )
        case = model.case
        pa = pressure_area(case.v0, case.radius, case.wave_speed)
        from twoball.modal.initial import phi_a_from_v0

        refs.append(
            f"- {preset}: pressure x area t_c = pi/c = {pa['contact_time_s'] * 1e3:.3f} ms, "
            f"flattening |v0|/c = {pa['flattening_max_m'] * 1e3:.2f} mm, phi_a = "
            f"{pa['phi_a_max_rad']:.4f} rad; eq. (3.7) phi_a = "
            f"{phi_a_from_v0(case.v0, case.radius, case.wave_speed):.4f} rad; measured "
            f"{MEASURED_COMPRESSION * 1e3:.2f} mm per m/s = "
            f"{MEASURED_COMPRESSION * case.v0 * 1e3:.2f} mm; Table 1 e2 = "
            f"{', '.join(f'{e:g}' for e in TABLE1_E2[preset])}; m2 = {model.mass:.4g} kg"
        )
    return "\n".join([*lines, "", *refs])


def speeds_table(speeds: Sequence[float] = (1.0, 2.0, 3.0, 4.1, 6.0, 8.0)) -> str:
    """The basketball against |v0|: compression, contact angle, contact time, restitution."""
    from twoball.modal.initial import phi_a_from_v0

    lines = [
        "| |v0| [m/s] | membrane | flattening [mm] | per m/s [mm] | phi_a,max | eq. (3.7) | "
        "p x a phi_a | p x a flattening [mm] | t_c [ms] | e2 |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for v0 in speeds:
        for membrane in ("paper", "pressurised"):
            model = drop_model("basketball", membrane, "modal", v0)
            r = run(model)
            v, case = _si(r), model.case
            pa = pressure_area(case.v0, case.radius, case.wave_speed)
            lines.append(
                f"| {v0:g} | {membrane} | {v['flattening [mm]']:.3f} | "
                f"{v['flattening [mm]'] / v0:.3f} | {v['phi_a,max [rad]']:.4f} | "
                f"{phi_a_from_v0(case.v0, case.radius, case.wave_speed):.4f} | "
                f"{pa['phi_a_max_rad']:.4f} | {pa['flattening_max_m'] * 1e3:.3f} | "
                f"{v['t_c [ms]']:.3f} | {v['e2']:.4f} |"
            )
    return "\n".join(lines)


def _orders(sizes: Sequence[float], values: Sequence[float], reference: float) -> float:
    errors = np.abs(np.asarray(values) - reference)
    return float(least_squares_order(sizes, errors).order)


def resolution_table(
    membrane: str = "pressurised",
    modes: Sequence[int] = (32, 64, 128, 256, 384),
    reference: int = 512,
) -> str:
    """Legendre N and P2 E = N / 2 at dt = 0.005 (the same floor point spacing, pi / N)."""
    model = drop_model("basketball", membrane, "modal")
    lines = [
        "| N / E | backend | t_c | e2 | phi_a,max | flattening | impact loss / KE0 | wall [s] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    runs: dict[str, list[DropResult]] = {"legendre": [], "fem": []}
    for n in modes:
        for backend, size in (("legendre", n), ("fem", n // 2)):
            r = run(model, backend, size)
            runs[backend].append(r.result)
            x = r.result
            lines.append(
                f"| {n} / {n // 2} | {backend} | {x.contact_time:.6f} | {x.e2:.7f} | "
                f"{x.phi_a_max:.5f} | {x.flattening_max:.8f} | {_impact_loss(x):.3e} | "
                f"{r.wall_s:.2f} |"
            )
    lines.append("")
    for backend, size in (("legendre", reference), ("fem", reference // 2)):
        ref = run(model, backend, size).result
        h = [1.0 / n for n in modes]
        orders = {
            name: _orders(h, [getattr(x, name) for x in runs[backend]], getattr(ref, name))
            for name in FIELDS
        }
        lines.append(
            f"- {backend}: least-squares orders in 1/N against N = {reference} "
            f"({', '.join(f'{k} {v:.2f}' for k, v in orders.items())}); reference t_c "
            f"{ref.contact_time:.6f}, e2 {ref.e2:.7f}, phi_a,max {ref.phi_a_max:.5f}"
        )
    gaps = [
        max(
            abs(a.contact_time / b.contact_time - 1),
            abs(a.e2 / b.e2 - 1),
            abs(a.phi_a_max / b.phi_a_max - 1),
        )
        for a, b in zip(runs["legendre"], runs["fem"], strict=True)
    ]
    lines.append(
        "- largest relative difference legendre / fem (t_c, e2, phi_a,max): "
        + ", ".join(f"N = {n}: {g:.1e}" for n, g in zip(modes, gaps, strict=True))
    )
    return "\n".join(lines)


def time_step_table(
    modes: int = 64, steps: Sequence[float] = (0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125)
) -> str:
    """One resolution against dt: errors against the finest step and least-squares orders."""
    model = drop_model("basketball", "pressurised", "modal")
    lines = [
        "| dt | backend | t_c | e2 | phi_a,max | flattening | impact loss / KE0 | steps |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for backend, size in (("legendre", modes), ("fem", modes // 2)):
        results = [run(model, backend, size, dt).result for dt in steps]
        for dt, x in zip(steps, results, strict=True):
            lines.append(
                f"| {dt:g} | {backend} | {x.contact_time:.7f} | {x.e2:.9f} | "
                f"{x.phi_a_max:.6f} | {x.flattening_max:.9f} | {_impact_loss(x):.5e} | "
                f"{x.steps} |"
            )
        ref = results[-1]
        parts = []
        for name in (*FIELDS, "impact loss"):
            get = _impact_loss if name == "impact loss" else (lambda r, n=name: getattr(r, n))
            errors = [abs(get(x) - get(ref)) for x in results[:-1]]
            parts.append(
                f"{name} {least_squares_order(steps[:-1], errors).order:.2f} "
                f"(errors {errors[0]:.1e} ... {errors[-1]:.1e})"
            )
        lines.append(f"\n- {backend}: least-squares orders in dt: " + "; ".join(parts))
    return "\n".join(lines)


def energy_table(modes: Sequence[int] = (32, 64, 128, 256)) -> str:
    """D = 0: the mechanical energy lost at impacts (e = 0) or kept (e = 1), the books."""
    lines = [
        "| e | N | dt | impact loss / KE0 | books error / KE0 | e2 |",
        "|---|---|---|---|---|---|",
    ]
    for e in (0.0, 1.0):
        model = drop_model("basketball", "pressurised", "modal", restitution=e, ratio=0.0)
        for n in modes:
            for dt in (0.01, 0.005, 0.0025):
                x = run(model, "legendre", n, dt).result
                kinetic = 0.5 * x.settings.v0**2
                lines.append(
                    f"| {e:g} | {n} | {dt:g} | {_impact_loss(x):.4e} | "
                    f"{x.energy['balance'] / kinetic:.1e} | {x.e2:.6f} |"
                )
    return "\n".join(lines)


def rest_table(modes: Sequence[int] = (120, 240, 480), elements: Sequence[int] = (60, 120)) -> str:
    """Settled under gravity (D = 0.9, pressurised): floor force and contact area."""
    model = drop_model("basketball", "pressurised", "modal", ratio=0.9)
    lines = [
        "| backend | size | force / weight - 1 | edge cap / (m2 g/P) | inner cap | outer cap | "
        "points |",
        "|---|---|---|---|---|---|---|",
    ]
    for backend, sizes in (("legendre", modes), ("fem", elements)):
        for n in sizes:
            if backend == "legendre":
                ball = legendre_ball(n, model.spectrum, model.law)
            else:
                ball = axisym_ball(n, 2, model.spectrum, model.law)
            r = settle(floor_system(ball, model.gamma))
            inner, outer = (a / r.pressure_area for a in r.contact_area)
            lines.append(
                f"| {backend} | {n} | {r.floor_force / r.weight - 1:.1e} | "
                f"{r.edge_area / r.pressure_area:.4f} | {inner:.4f} | {outer:.4f} | "
                f"{r.contact_points} |"
            )
    return "\n".join(lines)


def special_case_table(steps: Sequence[float] = (0.02, 0.01, 0.005, 0.0025)) -> str:
    """The restitution-only model on the drop's machinery against the closed form."""
    from twoball.modal.floor.restitution import restitution_only
    from twoball.modal.report import legendre_liftoff
    from twoball.modal.stiffness import Stiffness

    case = Case.preset("basketball")
    exact = legendre_liftoff(case).result
    paper = Stiffness()
    lines = [
        f"closed form (Lanczos, N = 30): t_l = {exact.t:.7f}, v_l = {exact.velocity:.7f}",
        "",
        "| dt | t_l error | v_l error |",
        "|---|---|---|",
    ]
    for dt in steps:
        r = restitution_only(paper, ModalRatio(case.damping), 30, case.phi_a, case.gamma, dt)
        lines.append(
            f"| {dt:g} | {r.result.t - exact.t:.2e} | {r.result.velocity - exact.velocity:.2e} |"
        )
    centre = restitution_only(
        paper, ModalRatio(case.damping), 30, case.phi_a, case.gamma, 0.0025, anchored=False
    ).result
    lines.append(
        f"\n- paper's operator, degree 1 carried by Z (the drop's own coordinates): t_l = "
        f"{centre.t:.5f}, v_l = {centre.velocity:.5f}"
    )
    model = drop_model("basketball", "pressurised", "modal")
    pressed = [
        restitution_only(
            model.spectrum, model.law, 30, case.phi_a, case.gamma, 0.005, anchored=a
        ).result
        for a in (True, False)
    ]
    lines.append(
        f"- pressurised with gas: degree 1 as a mode t_l = {pressed[0].t:.7f}, "
        f"carried by Z t_l = {pressed[1].t:.7f}, v_l = {pressed[0].velocity:.7f} / "
        f"{pressed[1].velocity:.7f}"
    )
    return "\n".join(lines)


TABLES: dict[str, Callable[[], str]] = {
    "presets": presets_table,
    "speeds": speeds_table,
    "resolution": resolution_table,
    "resolution_paper": lambda: resolution_table("paper", (64, 128, 256), 384),
    "time_step": time_step_table,
    "energy": energy_table,
    "rest": rest_table,
    "special_case": special_case_table,
}


def main(names: Sequence[str] = ()) -> None:
    """Print the tables ``names`` (all when empty)."""
    for name in names or TABLES:
        print(f"\n## {name}\n", flush=True)
        print(TABLES[name](), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
