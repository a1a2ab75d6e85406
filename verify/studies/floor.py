"""Tables of the drop on the floor: presets, speeds, convergence, energy, rest, special case.

``python -m twoball.verify.studies.floor [names...]`` prints Markdown tables of
every number docs/bounce.rst quotes (a full run takes about half an hour on one
core, most of it the fine references of the convergence studies).  The drops
start from the SI case (:func:`twoball.modal.floor.inputs.resolve_drop`, as
``twoball.bounce`` does) and run on the Legendre modes and on axisymmetric P2
elements; convergence tables are dimensionless (R, 1/c, m2), the others SI.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from twoball._common.budget import check
from twoball._common.watch import Watch
from twoball.fem_membrane.floor import axisym_ball
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.floor.drop import DropResult, DropSettings, run_drop
from twoball.modal.floor.inputs import DropModel, resolve_drop
from twoball.modal.floor.options import Drop
from twoball.modal.floor.references import MEASURED_COMPRESSION, TABLE1_E2, pressure_area
from twoball.modal.floor.settle import settle
from twoball.modal.floor.system import floor_system
from twoball.modal.parameters import Case
from twoball.verify.studies.orders import least_squares_order, step_orders

__all__ = [
    "DT_RESOLUTION",
    "QUANTITIES",
    "RESOLUTION",
    "STEPS",
    "TABLES",
    "Convergence",
    "FloorRun",
    "drop_model",
    "main",
    "normalised_loss",
    "plastic_loss",
    "resolution_study",
    "run",
    "time_step_study",
]

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


#: The measured quantities whose convergence the studies follow (attributes of DropResult).
QUANTITIES = ("contact_time", "e2", "phi_a_max")
#: Time step [1/c] of the resolution studies: its own error of t_c stays below the
#: resolution's up to N = 1536 (at dt = 0.005 it does not from N = 384: the last floor
#: points are then released within one or two steps).
DT_RESOLUTION = 0.00125
#: Each backend's resolution study: the sizes (Legendre N, P2 elements E = N / 2) and the
#: fine reference.
RESOLUTION: dict[str, tuple[tuple[int, ...], int]] = {
    "legendre": ((32, 48, 64, 96, 128, 192, 256, 384, 768), 1536),
    "fem": ((16, 24, 32, 48, 64, 96, 128, 192), 384),
}
#: The time steps [1/c] of the time-step studies and their fine reference.
STEPS: tuple[tuple[float, ...], float] = ((0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125), 0.0003125)


@dataclass(frozen=True)
class Convergence:
    """A refinement study of one backend: the quantities against N (or E) or dt.

    Attributes
    ----------
    backend : {"legendre", "fem"}
    parameter : {"N", "dt"}
        What is refined: the resolution (Legendre degree N, P2 elements E) or the
        time step [1/c].
    sizes : tuple of float
        N (or E), or dt, coarse to fine.
    values : dict
        Each quantity of :data:`QUANTITIES` (and ``flattening_max``) at each size.
    reference : dict
        The same at the fine reference.
    reference_size : float
    fixed : float
        The time step of a resolution study, the size of a time-step study.
    """

    backend: str
    parameter: str
    sizes: tuple[float, ...]
    values: dict[str, np.ndarray] = field(repr=False)
    reference: dict[str, float]
    reference_size: float
    fixed: float

    @property
    def steps(self) -> np.ndarray:
        """The refinement's step sizes h: 1/N (or 1/E) or dt."""
        sizes = np.asarray(self.sizes, dtype=float)
        return 1.0 / sizes if self.parameter == "N" else sizes

    def errors(self, name: str) -> np.ndarray:
        """``|value - reference|`` of quantity ``name`` at each size."""
        return np.abs(self.values[name] - self.reference[name])

    def order(self, name: str, first: int = 0, last: int | None = None) -> float:
        """Least-squares order in h of quantity ``name`` over ``sizes[first:last]``."""
        window = slice(first, last)
        return float(least_squares_order(self.steps[window], self.errors(name)[window]).order)

    def step_orders(self, name: str) -> np.ndarray:
        """The observed order of every refinement step (errors against the reference)."""
        return step_orders(self.steps, self.errors(name))

    def difference_orders(self, name: str) -> np.ndarray:
        """Orders of successive differences over triples in a ratio-2 chain, no reference.

        ``log2((f(h) - f(h/2)) / (f(h/2) - f(h/4)))`` for the sizes that halve twice.
        """
        h = self.steps
        f = self.values[name]
        out = []
        for i in range(h.size):
            j = np.flatnonzero(np.isclose(h, h[i] / 2.0))
            k = np.flatnonzero(np.isclose(h, h[i] / 4.0))
            if j.size and k.size:
                a, b = f[i] - f[j[0]], f[j[0]] - f[k[0]]
                out.append(math.log2(abs(a / b)) if a * b > 0.0 else math.nan)
        return np.array(out)


def _measure(result: DropResult) -> dict[str, float]:
    return {name: float(getattr(result, name)) for name in (*QUANTITIES, "flattening_max")}


def resolution_study(
    backend: str,
    sizes: Sequence[int] | None = None,
    reference: int | None = None,
    dt: float = DT_RESOLUTION,
    model: DropModel | None = None,
) -> Convergence:
    """The quantities against the resolution (Legendre N, or P2 elements E) at one dt.

    Defaults: :data:`RESOLUTION` of the backend at :data:`DT_RESOLUTION`, the basketball
    at 4.1 m/s, pressurised, modal D = 0.13 (``drop_model("basketball", "pressurised")``).
    """
    default_sizes, default_reference = RESOLUTION[backend]
    sizes = tuple(default_sizes if sizes is None else sizes)
    reference = default_reference if reference is None else reference
    values, ref = _measured(model, backend, [(n, dt) for n in sizes], (reference, dt))
    return Convergence(backend, "N", tuple(float(n) for n in sizes), values, ref, reference, dt)


def time_step_study(
    backend: str,
    size: int,
    steps: Sequence[float] | None = None,
    reference: float | None = None,
    model: DropModel | None = None,
) -> Convergence:
    """The quantities against the time step at one resolution (defaults: :data:`STEPS`)."""
    default_steps, default_reference = STEPS
    steps = tuple(default_steps if steps is None else steps)
    reference = default_reference if reference is None else reference
    values, ref = _measured(model, backend, [(size, dt) for dt in steps], (size, reference))
    return Convergence(backend, "dt", tuple(steps), values, ref, reference, float(size))


def _measured(
    model: DropModel | None,
    backend: str,
    runs: Sequence[tuple[int, float]],
    reference: tuple[int, float],
) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """The quantities of each (size, dt) run, by name, and those of the reference run.

    ``model``: default the basketball at 4.1 m/s, pressurised, modal D = 0.13.
    """
    model = drop_model("basketball", "pressurised", "modal") if model is None else model
    rows = [_measure(run(model, backend, size, dt).result) for size, dt in runs]
    values = {name: np.array([row[name] for row in rows]) for name in rows[0]}
    return values, _measure(run(model, backend, *reference).result)


def _convergence_lines(study: Convergence) -> list[str]:
    what = "N" if study.backend == "legendre" else "E"
    head = what if study.parameter == "N" else "dt"
    lines = [
        f"{study.backend}, against {head} "
        + (f"at dt = {study.fixed:g}" if study.parameter == "N" else f"at {what} = {study.fixed:g}")
        + f", reference {head} = {study.reference_size:g}",
        "",
        f"| {head} | t_c | e2 | phi_a,max | t_c error | e2 error | phi_a,max error |",
        "|---|---|---|---|---|---|---|",
    ]
    for k, size in enumerate(study.sizes):
        v = {name: study.values[name][k] for name in QUANTITIES}
        e = {name: study.errors(name)[k] for name in QUANTITIES}
        lines.append(
            f"| {size:g} | {v['contact_time']:.6f} | {v['e2']:.7f} | {v['phi_a_max']:.6f} | "
            f"{e['contact_time']:.2e} | {e['e2']:.2e} | {e['phi_a_max']:.2e} |"
        )
    ref = study.reference
    lines.append(
        f"| {study.reference_size:g} (ref) | {ref['contact_time']:.6f} | {ref['e2']:.7f} | "
        f"{ref['phi_a_max']:.6f} | | | |"
    )
    lines.append("")
    for name in QUANTITIES:
        steps = ", ".join(f"{o:.2f}" for o in study.step_orders(name))
        halves = ", ".join(f"{o:.2f}" for o in study.difference_orders(name))
        lines.append(
            f"- {name}: least-squares order {study.order(name):.2f} (all sizes); "
            f"step orders {steps}; orders of successive differences {halves or '-'}"
        )
    return lines


def convergence_table(parameter: str = "N") -> str:
    """Both backends against N / E (at :data:`DT_RESOLUTION`) or dt (at N = 192, E = 96)."""
    lines: list[str] = []
    for backend, size in (("legendre", MODES), ("fem", ELEMENTS)):
        if parameter == "N":
            study = resolution_study(backend)
        else:
            study = time_step_study(backend, size)
        lines += [*_convergence_lines(study), ""]
    return "\n".join(lines)


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


def plastic_loss(v0: float, modes: int, dt: float, restitution: float = 0.0) -> DropResult:
    """The basketball at ``v0`` [m/s] without damping (D = 0), pressurised, Legendre N."""
    model = drop_model("basketball", "pressurised", "modal", v0, restitution, ratio=0.0)
    return run(model, "legendre", modes, dt).result


def normalised_loss(r: DropResult) -> float:
    """The energy lost at impacts over ``KE0 (v0 / (R c))^2 / 4``.

    A sphere falling on a plane touches along ``a(t) = sqrt(2 R V0 t)``; while that edge
    outruns the membrane's waves (speed ``c R``), ``t < V0 / (2 c^2 R)``, the material it
    sweeps, a mass fraction ``V0^2 / (4 c^2 R^2)``, meets the floor at V0 and is stopped
    (e = 0).  This estimate of the loss is ``KE0 V0^2 / (4 c^2 R^2)``: the ratio is 1.
    """
    v = r.settings.v0
    return -r.energy["impacts"] / (0.5 * v * v) / (0.25 * v * v)


def energy_table(
    speeds: Sequence[float] = (2.05, 4.1, 8.2),
    modes: Sequence[int] = (128, 192, 384),
    steps: Sequence[float] = (0.01, 0.005, 0.0025, 0.00125),
) -> str:
    """D = 0: the loss at impacts with e = 0 over its continuum estimate, and e = 1."""
    lines = [
        "| N | dt | " + " | ".join(f"{v:g} m/s" for v in speeds) + " |",
        "|---|---|" + "---|" * len(speeds),
    ]
    for n in modes:
        for dt in steps:
            ratios = [normalised_loss(plastic_loss(v, n, dt)) for v in speeds]
            lines.append(f"| {n} | {dt:g} | " + " | ".join(f"{x:.4f}" for x in ratios) + " |")
    ratios = [normalised_loss(plastic_loss(v, 768, 0.005)) for v in speeds]
    lines.append("| 768 | 0.005 | " + " | ".join(f"{x:.4f}" for x in ratios) + " |")
    lines += [
        "",
        "e = 1 (4.1 m/s, N = 192): impact loss / KE0, largest |E - E0| / KE0 over the run",
        "",
        "| dt | impact loss / KE0 | max |E - E0| / KE0 | e2 |",
        "|---|---|---|---|",
    ]
    for dt in (0.02, 0.01, 0.005, 0.0025, 0.00125):
        r = plastic_loss(4.1, 192, dt, 1.0)
        kinetic = 0.5 * r.settings.v0**2
        drift = float(np.max(np.abs(r.trajectory.energy - r.trajectory.energy[0])))
        lines.append(
            f"| {dt:g} | {-r.energy['impacts'] / kinetic:.1e} | {drift / kinetic:.1e} | "
            f"{r.e2:.6f} |"
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
    from twoball.modal.cost import case_liftoff_work
    from twoball.modal.floor.restitution import restitution_only
    from twoball.modal.report import legendre_liftoff
    from twoball.modal.stiffness import Stiffness

    case = Case.preset("basketball")
    check(*case_liftoff_work(case))
    exact = legendre_liftoff(case, monitor=Watch()).result
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
    "orders_resolution": lambda: convergence_table("N"),
    "orders_time_step": lambda: convergence_table("dt"),
    "presets": presets_table,
    "speeds": speeds_table,
    "resolution": resolution_table,
    "resolution_paper": lambda: resolution_table("paper", (64, 128, 256), 384),
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
