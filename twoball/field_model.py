"""The solved ball behind ``export``, ``render`` and ``plot``, and the checks they share.

:func:`ball_model_of` solves a case with one or both backends on a generated
sphere mesh; the ``check_*`` functions refuse, before any work starts, what
those files cannot hold (initial method without finite elements, frame rates,
frame counts over the budget, eigenvalue plots of meshes that do not fit).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from twoball.mesh_options import SPHERE_KINDS, MeshOptions
from twoball.modal.errors import ParameterError
from twoball.modal.parameters import Case
from twoball.progress import Step, silent

FIELD_BACKENDS: tuple[str, ...] = ("fem", "legendre")
INITIAL_METHODS: tuple[str, ...] = ("projection", "interpolation")
FPS_RANGE = (1e-3, 1e3)  # frames per second of an animation


def check_backend(backend: str) -> str:
    if backend not in FIELD_BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(FIELD_BACKENDS), backend)
    return backend


def field_warnings(model: Any, backend: str, order: int | None, level: int | None) -> list[str]:
    """Accuracy warnings of ``backend``'s fields: its lift-off's, and the FE mesh resolution."""
    warnings = list(model.backend(backend).report.warnings)
    if backend == "fem":
        from twoball.fem_membrane.guards import mesh_warnings

        kind = "ring" if model.mesh.ring is not None else "sphere"
        order = MeshOptions.resolve(None, level=level, order=order).order
        warnings += mesh_warnings(kind, level, None, order, model.backend(backend).series.filter)
    return warnings


def check_initial(initial: str | None, backends: Sequence[str]) -> str:
    """``initial`` (default projection); refused when no finite-element backend is solved."""
    if initial is None:
        return "projection"
    if "fem" not in backends:
        raise ParameterError(
            "initial", "left out without the fem backend (it sets the FE initial state)", initial
        )
    if initial not in INITIAL_METHODS:
        raise ParameterError("initial", "one of " + ", ".join(INITIAL_METHODS), initial)
    return initial


def check_fps(fps: object) -> float:
    """Frames per second of an animation, in :data:`FPS_RANGE`."""
    from twoball.modal.errors import bounded

    return bounded("fps", fps, *FPS_RANGE)


def eigen_sizes(
    levels: Sequence[int] | None, orders: Sequence[int] | None, max_degree: int | None
) -> tuple[list[int], list[int]]:
    """Levels and orders of the eigenvalue plot, each mesh checked against the budget."""
    from twoball.budget import check, fem_dofs, fem_estimate, options

    levels = [1, 2, 3] if levels is None else levels
    orders = [1, 2] if orders is None else orders
    for name, values in (("levels", levels), ("orders", orders)):
        if isinstance(values, (str, bytes)) or not isinstance(values, Sequence) or not values:
            raise ParameterError(name, "a non-empty list of integers", values)
    if max_degree is not None and (
        isinstance(max_degree, bool) or not isinstance(max_degree, int) or max_degree < 1
    ):
        raise ParameterError("max_degree", "an integer >= 1", max_degree)
    for order in orders:
        for level in levels:
            try:
                spec = MeshOptions.resolve(None, level=level, order=order, files=False)
            except ParameterError as error:  # named as the list the value came from
                name = "levels" if error.name == "level" else "orders"
                raise ParameterError(name, f"a list of {error.valid}", error.got) from None
            size = options(level=spec.level, order=spec.order)
            check(size, fem_estimate(fem_dofs("sphere", spec.level, None, spec.order), 30))
    return list(levels), list(orders)


def check_frame_budget(
    case: Case, count: int, name: str, level: int | None, order: int | None
) -> None:
    """Refuse ``count`` frames on the mesh when their memory or time cannot fit (budget)."""
    from twoball.budget import check_frames
    from twoball.verify.output.fields import MAX_FRAMES

    if count > MAX_FRAMES:  # the same cap for frames, times and instants
        if name in ("instants", "frames"):  # a count
            low = 2 if name == "instants" else 1
            raise ParameterError(name, f"an integer in [{low}, {MAX_FRAMES}]", count)
        raise ParameterError(name, f"at most {MAX_FRAMES} {name}", f"{count} {name}")
    spec = MeshOptions.resolve(None, level=level, order=order)
    check_frames(f"{name} ({count} frames)", count, "sphere", spec.level, spec.order, case.modes)


def ball_model_of(
    case: Case,
    backends: Sequence[str],
    *,
    mesh: str | None,
    level: int | None,
    order: int | None,
    initial: str,
    sigma: str,
    recontact: str,
    t_end: float | None,
    progress: Step | None = None,
    cells: bool = False,
    route: str = "auto",
) -> Any:
    """Solve ``case`` with ``backends`` on the sphere mesh of the options (see ``BallModel``)."""
    from twoball.fem_membrane.krylov import ROUTES
    from twoball.verify.output.fields import ball_model

    if route not in ROUTES:
        raise ParameterError("route", "one of " + ", ".join(ROUTES), route)
    spec = MeshOptions.resolve(mesh, level=level, order=order, kinds=SPHERE_KINDS, files=False)
    if cells and spec.order > 2:  # VTK and pyvista cells stop at quadratic triangles
        raise ParameterError("order", "1 or 2 for field files and pictures", spec.order)
    initial = check_initial(initial, backends)
    if initial not in INITIAL_METHODS:
        raise ParameterError("initial", "one of " + ", ".join(INITIAL_METHODS), initial)
    from twoball.modal.report import t_end_dimensionless

    t_end_dimensionless(case, t_end)  # the window is checked before any progress line
    (progress or silent)(f"solving {' and '.join(backends)} on {spec.label}")
    return ball_model(
        case,
        spec.level,
        spec.order,
        mesh=spec.kind,
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end,
        backends=tuple(backends),
        initial=initial,
        route=route,
    )
