"""The solved ball behind ``export``, ``render`` and ``plot``, and the checks they share.

:func:`field_mesh` resolves and checks the sphere mesh of the fields: a
generated icosphere or ring sphere, or the user's mesh file, read and checked
as :func:`twoball.liftoff` reads it.  :func:`ball_model_of` solves a case with
one or both backends on it; the ``check_*`` functions refuse, before any work
starts, what those files cannot hold (initial method without finite elements,
frame rates, frame counts over the budget, eigenvalue plots of meshes that do
not fit).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

from twoball.mesh_options import FILE, SPHERE_KINDS, MeshOptions
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


@dataclass(frozen=True)
class FieldMesh:
    """The sphere mesh of the fields: the checked options and, for a file, the mesh read.

    Attributes
    ----------
    spec : MeshOptions
        Kind ``sphere``, ``ring`` or ``file``, level, order, pole, geometry.
    loaded : MeshInput or None
        The user's mesh, checked, on the unit sphere with its pole on +z
        (:func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`); None for a kind.
    """

    spec: MeshOptions
    loaded: Any = None

    @property
    def order(self) -> int:
        """Element order of the fields: the option's, or the file's own (1 or 2)."""
        return int(self.spec.order if self.loaded is None else self.loaded.mesh.order)

    @property
    def mesh(self) -> Any:
        """The kind name, or the user's unit-sphere :class:`SphereMesh` (pole on +z)."""
        return self.spec.kind if self.loaded is None else self.loaded.mesh

    @property
    def source(self) -> dict[str, Any] | None:
        """The user's mesh for the file metadata and the provenance (None for a kind).

        ``path`` (absolute; None for a mesh object), the fitted ``radius`` and
        ``center`` in the file's length unit, the unit ``pole`` direction in the
        file's frame, ``geometry``, and the figures of :meth:`MeshInput.as_dict`.
        """
        if self.loaded is None:
            return None
        given = self.spec.source
        path = os.path.abspath(given) if isinstance(given, (str, os.PathLike)) else None
        head = {"path": path, "length_unit": "the file's", "geometry": self.spec.geometry}
        return head | self.loaded.as_dict()


def field_mesh(
    mesh: Any,
    level: int | None,
    order: int | None,
    pole: Any = None,
    geometry: str | None = None,
    *,
    cells: bool = False,
    load: bool = True,
) -> FieldMesh:
    """Check the mesh options of a field command and read the user's mesh file.

    Parameters
    ----------
    mesh : {"sphere", "ring"}, path, meshio.Mesh or scikit-fem mesh, optional
        A sphere kind (default ``sphere``), or the user's sphere (any radius,
        centre and length unit, 3- or 6-node triangles).
    level, order, pole, geometry
        As in :meth:`MeshOptions.resolve` (``level`` refused with a file,
        ``pole`` without one, ``geometry="exact"`` on the ring sphere).
    cells : bool
        The fields become VTK cells (files, pictures): orders 1 and 2 only.
    load : bool
        Read the file now; False checks the options only (the file is then
        read by :func:`ball_model_of`, or by calling this again).

    Raises
    ------
    ParameterError
        Naming the option, or ``mesh`` for a file that is not one closed sphere.
    """
    spec = MeshOptions.resolve(
        mesh, level=level, order=order, pole=pole, geometry=geometry, kinds=SPHERE_KINDS
    )
    if cells and spec.order is not None and spec.order > 2:  # VTK cells stop at quadratic
        raise ParameterError("order", "1 or 2 for field files and pictures", spec.order)
    return FieldMesh(spec, spec.load() if load and spec.kind == FILE else None)


def field_warnings(model: Any, backend: str, field: FieldMesh) -> list[str]:
    """Accuracy warnings of ``backend``'s fields: its lift-off's, and the FE mesh resolution.

    As in :func:`twoball.liftoff`, the resolution of a user's mesh is not
    estimated (it has no level): only its lift-off's warnings are given.
    """
    warnings = list(model.backend(backend).report.warnings)
    if backend == "fem" and field.loaded is None:
        from twoball.fem_membrane.guards import mesh_warnings

        spec, series = field.spec, model.backend(backend).series
        warnings += mesh_warnings(spec.kind, spec.level, None, spec.order, series.filter)
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


def check_frame_budget(case: Case, count: int, name: str, field: FieldMesh) -> None:
    """Refuse ``count`` frames on the mesh when their memory or time cannot fit (budget).

    The nodes are those of the generated sphere of the level and order, or the
    user's mesh's own (its triangles at its order).
    """
    from twoball.budget import check_frames
    from twoball.verify.output.fields import MAX_FRAMES

    if count > MAX_FRAMES:  # the same cap for frames, times and instants
        if name in ("instants", "frames"):  # a count
            low = 2 if name == "instants" else 1
            raise ParameterError(name, f"an integer in [{low}, {MAX_FRAMES}]", count)
        raise ParameterError(name, f"at most {MAX_FRAMES} {name}", f"{count} {name}")
    spec = field.spec
    mesh = spec.kind if field.loaded is None else field.loaded.mesh
    check_frames(f"{name} ({count} frames)", count, mesh, spec.level, field.order, case.modes)


def ball_model_of(
    case: Case,
    backends: Sequence[str],
    field: FieldMesh,
    *,
    initial: str | None,
    sigma: str,
    recontact: str,
    t_end: float | None,
    progress: Step | None = None,
    route: str = "auto",
) -> Any:
    """Solve ``case`` with ``backends`` on the sphere mesh ``field`` (see ``BallModel``).

    On the user's mesh the model's ``source`` holds the file's path, radius,
    centre and pole (:attr:`FieldMesh.source`).
    """
    from twoball.fem_membrane.krylov import ROUTES
    from twoball.verify.output.fields import ball_model

    if route not in ROUTES:
        raise ParameterError("route", "one of " + ", ".join(ROUTES), route)
    initial = check_initial(initial, backends)
    from twoball.modal.report import t_end_dimensionless

    t_end_dimensionless(case, t_end)  # the window is checked before any progress line
    if field.spec.kind == FILE and field.loaded is None:
        field = replace(field, loaded=field.spec.load())
    (progress or silent)(f"solving {' and '.join(backends)} on {field.spec.label}")
    model = ball_model(
        case,
        field.spec.level,
        field.order,
        mesh=field.mesh,
        geometry=field.spec.geometry,
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end,
        backends=tuple(backends),
        initial=initial,
        route=route,
    )
    return replace(model, source=field.source)
