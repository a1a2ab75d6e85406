"""Nodal time series of both backends in SI, for files, pictures and plots.

A :class:`BallModel` holds, for one case and one sphere mesh, the damped and
filtered modal series of eq. (3.16) of each backend together with its mode
shapes at the mesh nodes:

``legendre``
    The closed form: modes ``P_n(cos phi)`` evaluated at the polar angle of
    every node (:func:`twoball.modal.legendre.legendre_series`).
``fem``
    The finite elements: M-orthonormal eigenvectors of eq. (3.9) on the mesh,
    read at the nodes (:mod:`fem_membrane`).

Both are :class:`twoball.modal.series.ModalSeries`, filtered by the same
:class:`twoball.modal.filters.SpectralFilter`, and each backend's lift-off comes from the
shared :func:`twoball.modal.report.report_liftoff`.  Inside, everything is
dimensionless (length R, time 1/c); every function here that returns numbers
returns SI (m, m/s, m/s^2, s) unless its docstring says otherwise.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from twoball._common.budget import BASE_MEMORY, Estimate, check, check_all
from twoball._common.choices import DEFAULT_FRAMES
from twoball._common.errors import ParameterError
from twoball._common.progress import Step, silent
from twoball._common.watch import Watch
from twoball.fem_membrane.mesh import SphereMesh, elevate, flatten, sphere_mesh
from twoball.fem_membrane.options import DEFAULT_INITIAL, FILE, SPHERE_KINDS, MeshOptions
from twoball.modal.contact.body import MAX_MASS_RATIO, Body
from twoball.modal.contact.report import check_contact_options, membrane_case
from twoball.modal.contact.states import ModalStates
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series, legendre_shapes
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport, report_liftoff, t_end_dimensionless
from twoball.modal.series import ModalSeries
from twoball.verify.output.options import BACKENDS, MAX_FRAMES
from twoball.verify.output.render import BallScene
from twoball.verify.output.series import TimeSeries

BackendName = Literal["fem", "legendre"]
#: A generated mesh kind, or the user's mesh (unit sphere, pole on +z; from a file).
MeshChoice = str | SphereMesh


@dataclass(frozen=True)
class Backend:
    """One solver's modal series with its mode shapes at the mesh nodes (dimensionless).

    Attributes
    ----------
    name : str
        ``fem`` or ``legendre``.
    series : ModalSeries
        Damped, filtered modes, eq. (3.16).
    shapes : ndarray, shape (K, P)
        Mode shapes at the P mesh nodes (rows follow ``series.omega``).
    report : LiftoffReport
        Lift-off of this backend (SI properties), criteria of §3(a).
    details : dict
        Backend facts for file metadata (degrees of freedom, modes, ...).
    """

    name: str
    series: ModalSeries
    shapes: np.ndarray
    report: LiftoffReport
    details: dict[str, float] = field(default_factory=dict)

    def values(self, t: np.ndarray, derivative: int = 0) -> np.ndarray:
        """u, u_t or u_tt at the nodes at dimensionless times ``t``, shape (T, P), dimensionless."""
        return self.series.field(np.atleast_1d(t), self.shapes, derivative)


@dataclass(frozen=True)
class BallModel:
    """A case solved by one or both backends on one sphere mesh.

    Attributes
    ----------
    case : Case
        The impact (SI).
    mesh : SphereMesh
        Unit-sphere mesh (dimensionless) whose nodes carry the fields.
    backends : dict of str -> Backend
        ``fem`` and/or ``legendre``.
    t_end : float
        Modelled window (dimensionless, unit 1/c).
    sigma, recontact : str
        Spectral filter and re-contact horizon used for both backends.
    source : dict or None
        The user's mesh file (:meth:`twoball.verify.output.fields.FieldMesh.source`): its
        ``path``, fitted ``radius`` and ``center`` (the file's length unit), unit
        ``pole`` direction in the file's frame, ...; None on a generated mesh.
    """

    case: Case
    mesh: SphereMesh
    backends: dict[str, Backend]
    t_end: float
    sigma: str = "lanczos"
    recontact: str = "window"
    source: dict[str, Any] | None = None

    @property
    def polar_angles(self) -> np.ndarray:
        """Polar angle phi [rad] of every node (0 at the pole on top)."""
        return node_polar_angles(self.mesh)

    @property
    def t_end_s(self) -> float:
        """Modelled window [s]."""
        return self.t_end * self.case.scalings.time

    def backend(self, name: str) -> Backend:
        """The backend called ``name`` (ParameterError naming ``backend`` if absent)."""
        if name not in self.backends:
            raise ParameterError("backend", "one of " + ", ".join(self.backends), name)
        return self.backends[name]

    def nodal(self, name: str, times_s: np.ndarray, derivative: int = 0) -> np.ndarray:
        """u [m], u_t [m/s] or u_tt [m/s^2] of backend ``name`` at the nodes, shape (T, P)."""
        scale = self.case.scalings
        units = (scale.length, scale.velocity, scale.acceleration)[derivative]
        t = np.atleast_1d(np.asarray(times_s, dtype=float)) / scale.time
        return self.backend(name).values(t, derivative) * units

    def body_height(self, name: str, times_s: np.ndarray) -> np.ndarray:
        """Radial position [m] of the upper body relative to the undeformed pole.

        Resting on the pole, ``u(t, 0)``, until the lift-off time t_l of backend
        ``name``; then the free flight of criterion (ii) of §3(a),
        ``s(t) = u_l + v_l (t - t_l) - g (t - t_l)^2 / 2`` (SI).
        """
        backend = self.backend(name)
        scale = self.case.scalings
        times_s = np.atleast_1d(np.asarray(times_s, dtype=float))
        pole = backend.series.pole(times_s / scale.time).u * scale.length
        report = backend.report
        if not report.result.lifted:
            return pole
        t_l, v_l = report.t_liftoff_s, report.v_liftoff_m_s
        u_l = report.result.displacement * scale.length
        dt = times_s - t_l
        flight = u_l + v_l * dt - 0.5 * self.case.g * dt * dt
        return np.where(dt >= 0.0, flight, pole)


# --------------------------------------------------------------------------- building
def node_polar_angles(mesh: SphereMesh) -> np.ndarray:
    """Polar angle [rad] of every node of a unit-sphere mesh, from its radial projection."""
    points = mesh.points
    cosine = points[:, 2] / np.linalg.norm(points, axis=1)
    return np.arccos(np.clip(cosine, -1.0, 1.0))


def build_mesh(
    case: Case,
    level: int | None,
    order: int | None,
    kind: MeshChoice = "sphere",
    geometry: str = "isoparametric",
) -> SphereMesh:
    """The unit-sphere mesh: icosphere (``sphere``), ring sphere (``ring``) or the user's.

    A user's :class:`SphereMesh` is raised to or flattened to ``order`` (default
    its own) as the finite-element space does (:func:`~twoball.fem_membrane.space.sphere_space`):
    with ``geometry="exact"`` only its vertices are kept and the other nodes are
    their radial projections, the nodes of the exact geometry.
    """
    if isinstance(kind, SphereMesh):
        order = kind.order if order is None else order
        base = flatten(kind) if geometry == "exact" else kind
        return elevate(base, order) if order > 1 else flatten(base)
    if kind not in SPHERE_KINDS:
        raise ParameterError("mesh", "one of " + ", ".join(SPHERE_KINDS), kind)
    return sphere_mesh(int(level or 0), int(order or 2), case.phi_a if kind == "ring" else None)


def legendre_backend(
    case: Case,
    mesh: SphereMesh,
    sigma: str,
    recontact: str,
    t_end: float,
    window_given: bool = True,
) -> Backend:
    """The closed form of eq. (3.16) with its Legendre modes at the nodes of ``mesh``.

    ``window_given``: whether the user gave the window ``t_end`` (for its warnings).
    """
    series = legendre_series(
        case.phi_a,
        case.damping_law,
        SpectralFilter(sigma, case.modes),
        stiffness=case.stiffness,
        monitor=Watch(),
    )
    shapes = legendre_shapes(node_polar_angles(mesh), case.modes)
    report = report_liftoff(
        case,
        series,
        backend="legendre",
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end * case.scalings.time,
        window_given=window_given,
        monitor=Watch(),
    )
    return Backend("legendre", series, shapes, report, {"modes": float(case.modes)})


def fem_nodal_series(
    case: Case,
    level: int | None,
    order: int | None,
    mesh: MeshChoice = "sphere",
    sigma: str = "lanczos",
    initial: str = "projection",
    route: str = "auto",
    t_end: float | None = None,
    geometry: str = "isoparametric",
) -> tuple[SphereMesh, ModalSeries, np.ndarray, dict[str, float]]:
    """Finite-element modal series (dimensionless), its mesh and its mode shapes at the nodes.

    The finite-element run is :func:`twoball.fem_membrane.solve.modal_model`: the isoparametric
    P1/P2 space of eq. (3.9) on the icosphere (or ring sphere) of ``level``, the
    initial displacement (3.10) projected or interpolated, all eigenpairs below the
    cutoff of the spectral filter, and the damping and filter of the closed form
    (eqs. (3.14)-(3.16)).  ``route``: ``full`` takes every
    eigenpair below the cutoff, ``krylov`` the Ritz pairs of the rational Krylov
    route, converged on the whole field over [0, ``t_end``]
    (:mod:`twoball.fem_membrane.ritz_field`), ``auto`` (default) Krylov from
    :data:`twoball.fem_membrane.krylov.AUTO_THRESHOLD` unknowns on, like the pole.
    For Lagrange elements on their own geometry every degree of freedom sits at a
    mesh node, so the mesh returned here has the degrees of freedom as its nodes
    (``doflocs``) and their numbering in its cells (skfem's local order: vertices,
    then edges 01, 12, 20 -- meshio's ``triangle6``), and the eigenvectors (or
    Ritz vectors) are the mode shapes at the nodes as they are.  ``mesh`` may be
    the user's unit-sphere mesh (``level`` None, ``order`` None for its own), and
    ``geometry`` ``exact`` maps the elements onto the sphere itself (the nodes
    are then the exact images).  The pole may lie inside an element of a user's
    mesh: the series reads it through the space's pole functional.

    Returns
    -------
    mesh : SphereMesh
        Unit sphere, P nodes = degrees of freedom.
    series : ModalSeries
    shapes : ndarray, shape (K, P)
        Eigenvectors at the nodes.
    details : dict
        ``dofs``, ``eigenpairs`` and ``eigen_seconds``.
    """
    from twoball.fem_membrane.solve import modal_model
    from twoball.fem_membrane.space import dof_mesh
    from twoball.modal.liftoff import DEFAULT_T_END

    own = isinstance(mesh, SphereMesh)
    if not own and mesh not in SPHERE_KINDS:
        raise ParameterError("mesh", "one of " + ", ".join(SPHERE_KINDS), mesh)
    from twoball.fem_membrane.cost import fem_work

    size = None if own and order is None else order
    check_all(fem_work(mesh, None if own else level, None, size, case.modes, route))
    model = modal_model(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        mesh=mesh,
        level=None if own else level,
        order=None if own and order is None else order,
        initial=initial,
        route=route,
        geometry=geometry,
        fields=True,
        t_end=DEFAULT_T_END if t_end is None else t_end,
        stiffness=case.stiffness,
        monitor=Watch(),
    )
    basis = model.space.basis
    if own:
        name = mesh.name
    else:
        name = ("icosphere" if mesh == "sphere" else "ring sphere") + f" level {level}"
    ring = case.phi_a if mesh == "ring" else None
    nodes = dof_mesh(basis, f"{name}, P{model.space.order}", ring)
    node = nodes.pole_node  # None: the pole inside an element (a user's mesh)
    if node is not None and node != model.space.pole:  # pragma: no cover - dof = node premise
        raise ValueError("the pole node is not the pole degree of freedom")
    details = {
        "dofs": float(model.space.dofs),
        "eigenpairs": float(len(model.pairs)),
        "eigen_seconds": float(model.seconds.get("eigen", float("nan"))),
    }
    return nodes, model.series, model.pairs.vectors.T, details


def fem_backend(
    case: Case,
    level: int | None,
    order: int | None,
    mesh: MeshChoice,
    sigma: str,
    recontact: str,
    t_end: float,
    initial: str = "projection",
    route: str = "auto",
    geometry: str = "isoparametric",
    window_given: bool = True,
) -> tuple[SphereMesh, Backend]:
    """The finite-element backend and its mesh, see :func:`fem_nodal_series`.

    Lift-off by the shared :func:`twoball.modal.report.report_liftoff`
    (``window_given``: whether the user gave the window, for its warnings).
    """
    nodes, series, shapes, details = fem_nodal_series(
        case, level, order, mesh, sigma, initial, route, t_end, geometry
    )
    report = report_liftoff(
        case,
        series,
        backend="fem",
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end * case.scalings.time,
        window_given=window_given,
        monitor=Watch(),
    )
    return nodes, Backend("fem", series, shapes, report, details)


def solve_backends(
    case: Case,
    field: FieldMesh,
    backends: Sequence[str],
    *,
    sigma: str,
    recontact: str,
    t_end: float,
    route: str,
    window_given: bool = True,
) -> BallModel:
    """``case`` solved by ``backends`` on the sphere mesh ``field`` (no upper body).

    The finite elements (when asked) give the mesh whose nodes carry the
    fields (:func:`fem_backend`); the closed form is evaluated at those nodes,
    or at the generated mesh's nodes without finite elements.  ``window_given``:
    whether the user gave the window ``t_end`` (for its warnings).
    """
    spec = field.spec
    initial = spec.initial or DEFAULT_INITIAL
    solved: dict[str, Backend] = {}
    if "fem" in backends:
        unit_mesh, solved["fem"] = fem_backend(
            case,
            spec.level,
            field.order,
            field.mesh,
            sigma,
            recontact,
            t_end,
            initial,
            route,
            spec.geometry,
            window_given,
        )
    else:
        unit_mesh = build_mesh(case, spec.level, field.order, field.mesh, spec.geometry)
    if "legendre" in backends:
        solved["legendre"] = legendre_backend(
            case, unit_mesh, sigma, recontact, t_end, window_given
        )
    return BallModel(case, unit_mesh, solved, t_end, sigma, recontact, source=field.source)


#: How progress lines name what a backend solves.
SOLVED_TEXT = {"fem": "the finite elements (fem)", "legendre": "the closed form (legendre)"}


def solved_text(backends: Sequence[str]) -> str:
    """``the finite elements (fem) and the closed form (legendre)``: what is solved."""
    return " and ".join(SOLVED_TEXT[name] for name in backends)


def ball_model(
    case: Case,
    field: FieldMesh | None = None,
    *,
    backends: Sequence[str] = BACKENDS,
    body: Any = None,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end_s: float | None = None,
    route: str = "auto",
    progress: Step | None = None,
) -> BallModel:
    """The solved ball behind every field output (files, pictures, plots): the one builder.

    Parameters
    ----------
    case : Case
        The impact (SI).
    field : FieldMesh, optional
        The sphere mesh (:func:`field_mesh`; default the level-3 P2 icosphere).
    backends : sequence of {"fem", "legendre"}
        Which solvers to run; the closed form is cheap, the FE eigenproblem is not.
    body : Body, optional
        An upper body of finite mass: the fields are then the membrane coupled
        to it (:func:`twoball.verify.output.fields.coupled_model`).
    sigma, recontact : str
        Spectral filter (eq. (3.16)) and re-contact horizon (§3(a)(ii)).
    t_end_s : float, optional
        Modelled window [s] (default 4 pi / c).
    route : {"auto", "full", "krylov"}
        FE mode shapes from every eigenpair (``full``), from the Ritz pairs of the
        rational Krylov route (``krylov``), or Krylov from 2000 unknowns (``auto``).
    progress : callable, optional
        Called with a short text as the solve starts.

    Returns
    -------
    BallModel
        A :class:`~twoball.verify.output.fields.CoupledModel` with a body.
    """
    from twoball._common.choices import ROUTES

    field = field_mesh(MeshOptions()) if field is None else field
    for name in backends:
        if name not in BACKENDS:
            raise ParameterError("backend", "one of " + ", ".join(BACKENDS), name)
    if route not in ROUTES:
        raise ParameterError("route", "one of " + ", ".join(ROUTES), route)
    if field.spec.initial is not None and "fem" not in backends:
        raise ParameterError(
            "initial",
            "left out without the fem backend (it sets the FE initial state)",
            field.spec.initial,
        )
    t_end = t_end_dimensionless(case, t_end_s)  # checked before any progress line
    say = progress or silent
    if body is not None:
        check_field_body(case, body, field, recontact=recontact, route=route)
        return coupled_model(
            case, backends, body, field.spec, sigma=sigma, t_end_s=t_end_s, progress=say
        )
    if field.spec.kind == FILE and field.loaded is None:
        field = replace(field, loaded=field.spec.load())
    say(f"solving {solved_text(backends)} on {field.spec.label}")
    return solve_backends(
        case,
        field,
        tuple(backends),
        sigma=sigma,
        recontact=recontact,
        t_end=t_end,
        route=route,
        window_given=t_end_s is not None,
    )


# --------------------------------------------------------------------------- products
def series_metadata(model: BallModel, backend: str) -> dict[str, float]:
    """Scalars for file metadata (SI): the case, the mesh and each backend's lift-off.

    On the user's mesh also ``mesh_file_radius`` and ``mesh_file_center_x``, ``_y``,
    ``_z`` (in the file's own length unit) and the unit pole direction in the
    file's frame, ``mesh_file_pole_x``, ``_y``, ``_z``.
    """
    case = model.case
    data: dict[str, float] = {
        "radius_m": case.radius,
        "wave_speed_1_s": case.wave_speed,
        "v0_m_s": case.v0,
        "phi_a_rad": case.phi_a,
        "damping": case.damping,
        "modes": float(case.modes),
        "g_m_s2": case.g,
        "t_end_s": model.t_end_s,
        "mesh_order": float(model.mesh.order),
        "nodes": float(len(model.mesh.points)),
    }
    if case.membrane.pressurised:  # omega^2 = lambda - s (docs/pressurised.rst)
        data["membrane_shift"] = case.membrane.shift
    if case.rayleigh is not None:  # the law that replaces D, in SI
        law = case.rayleigh_dict()
        data["rayleigh_alpha_1_s"] = float(law["alpha_1_s"])
        data["rayleigh_beta_s"] = float(law["beta_s"])
    if model.source is not None:  # the user's file: its own unit and frame
        data["mesh_file_radius"] = float(model.source["radius"])
        centre, pole = model.source["center"], model.source["pole"]
        for k, axis in enumerate("xyz"):
            data[f"mesh_file_center_{axis}"] = float(centre[k])
            data[f"mesh_file_pole_{axis}"] = float(pole[k])
    for name, solved in model.backends.items():
        report = solved.report
        data[f"lifted_{name}"] = 1.0 if report.result.lifted else 0.0
        if report.result.lifted:
            data[f"t_liftoff_{name}_s"] = report.t_liftoff_s
            data[f"v_liftoff_{name}_m_s"] = report.v_liftoff_m_s
        for key, value in solved.details.items():
            if not key.endswith("seconds"):  # run times would make equal exports differ
                data[f"{name}_{key}"] = float(value)
    main = model.backend(backend).report
    data["lifted"] = 1.0 if main.result.lifted else 0.0
    if main.result.lifted:
        data["t_liftoff_s"] = main.t_liftoff_s
        data["v_liftoff_m_s"] = main.v_liftoff_m_s
    return data


def field_series(model: BallModel, times_s: np.ndarray, backend: str = "fem") -> TimeSeries:
    """Point data of every frame in SI, ready for :func:`twoball.verify.output.series.write_series`.

    Node coordinates are ``R`` times the unit sphere [m].  Point data (shape (F, P)
    unless noted), all from eq. (3.16) evaluated in closed form:

    ``u_m``, ``u_t_m_s``, ``u_tt_m_s2``
        Radial displacement [m], velocity [m/s], acceleration [m/s^2] of ``backend``.
    ``displacement_m``
        ``u n`` with the outward unit normal n (shape (F, P, 3)) [m], for warping.
    ``u_fem_m``, ``u_legendre_m``, ``u_diff_m``
        Both backends' u [m] and ``u_fem - u_legendre`` (when both were solved).

    Field data: :func:`series_metadata` (``t_liftoff_s``, ``v_liftoff_m_s``, ...);
    text ``case`` (:func:`case_text`) and, on the user's mesh, ``mesh_file`` (JSON
    of :attr:`BallModel.source`).  Every name ends in its SI unit, but the
    ``mesh_file`` entries, which are in the file's units.
    """
    times_s = np.atleast_1d(np.asarray(times_s, dtype=float))
    scale = model.case.scalings
    points = model.mesh.points
    normal = points / np.linalg.norm(points, axis=1, keepdims=True)
    data: dict[str, np.ndarray] = {}
    u = model.nodal(backend, times_s, 0)
    data["u_m"] = u
    data["u_t_m_s"] = model.nodal(backend, times_s, 1)
    data["u_tt_m_s2"] = model.nodal(backend, times_s, 2)
    data["displacement_m"] = u[:, :, None] * normal[None, :, :]
    for name in BACKENDS:
        if name in model.backends:
            data[f"u_{name}_m"] = u if name == backend else model.nodal(name, times_s, 0)
    if "u_fem_m" in data and "u_legendre_m" in data:
        data["u_diff_m"] = data["u_fem_m"] - data["u_legendre_m"]
    return TimeSeries(
        points * scale.length,
        model.mesh.cells,
        times_s,
        data,
        series_metadata(model, backend),
        {"case": case_text(model, backend)}
        | ({} if model.source is None else {"mesh_file": json.dumps(model.source)}),
    )


def case_text(model: BallModel, backend: str) -> str:
    """The case and the fields' units in one line (a text of every exported file)."""
    c = model.case
    return (
        f"twoball {backend}: R = {c.radius:g} m, c = {c.wave_speed:g} 1/s, v0 = {c.v0:g} m/s, "
        f"phi_a = {c.phi_a:.6g} rad ({c.phi_a_source}), D = {c.damping:g}, N = {c.modes}, "
        f"g = {c.g:g} m/s^2; {_model_text(c)}fields u_m [m], u_t_m_s [m/s], "
        "u_tt_m_s2 [m/s^2], displacement_m [m]; time [s]"
    )


def _model_text(case: Case) -> str:
    """The membrane operator and damping law when not the paper's ('' otherwise)."""
    parts = []
    if case.membrane.pressurised:
        parts.append("membrane pressurised, omega^2 = (n - 1)(n + 2)")
    if case.rayleigh is not None:
        law = case.rayleigh_dict()
        parts.append(f"Rayleigh alpha = {law['alpha_1_s']:.6g} 1/s, beta = {law['beta_s']:.6g} s")
    return "".join(part + "; " for part in parts)


def ball_scene(model: BallModel, times_s: np.ndarray, backend: str = "fem") -> BallScene:
    """What :func:`twoball.verify.output.render.render_scene` draws, in SI, for ``backend``."""
    times_s = np.atleast_1d(np.asarray(times_s, dtype=float))
    scale = model.case.scalings
    report = model.backend(backend).report
    case = model.case
    label = (
        f"{'finite elements' if backend == 'fem' else 'closed form'}: R = {case.radius:g} m, "
        f"c = {case.wave_speed:g} 1/s, v0 = {case.v0:g} m/s, D = {case.damping:g}"
    )
    return BallScene(
        model.mesh.points * scale.length,
        model.mesh.cells,
        times_s,
        model.nodal(backend, times_s, 0),
        model.body_height(backend, times_s),
        case.radius,
        report.t_liftoff_s if report.result.lifted else None,
        label,
        settle_time=math.pi * scale.time,  # pi / c: the flattening has crossed the ball
    )


FPS_RANGE = (1e-3, 1e3)  # frames per second of an animation


def check_backend(backend: str) -> str:
    if backend not in BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
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
        given = self.spec.file
        path = os.path.abspath(given) if isinstance(given, (str, os.PathLike)) else None
        head = {"path": path, "length_unit": "the file's", "geometry": self.spec.geometry}
        return head | self.loaded.as_dict()


def field_mesh(mesh: Any = None, *, cells: bool = False, load: bool = True) -> FieldMesh:
    """Check the sphere mesh of a field output and read the user's mesh file.

    Parameters
    ----------
    mesh : MeshOptions, {"sphere", "ring"}, path, meshio.Mesh or MeshTri, optional
        A sphere (default the level-3 P2 icosphere), or the user's sphere (any
        radius, centre and length unit, 3- or 6-node triangles).
    cells : bool
        The fields become VTK cells (files, pictures): orders 1 and 2 only.
    load : bool
        Read the file now; False checks the options only (the file is then
        read by :func:`ball_model`).

    Raises
    ------
    ParameterError
        Naming the option, or ``mesh`` for a file that is not one closed sphere.
    """
    spec = MeshOptions.of(mesh).require(SPHERE_KINDS)
    if cells and spec.order is not None and spec.order > 2:  # VTK cells stop at quadratic
        raise ParameterError("order", "1 or 2 for field files and pictures", spec.order)
    return FieldMesh(spec, spec.load() if load and spec.kind == FILE else None)


def field_warnings(model: Any, backend: str, field: FieldMesh) -> list[str]:
    """Accuracy warnings of ``backend``'s fields: its lift-off's, and the FE mesh resolution.

    As in :func:`twoball.liftoff`, a user's mesh is judged by its size and
    order (:func:`twoball.fem_membrane.guards.mesh_warnings`).
    """
    warnings = []  # the mesh's first, as in the lift-off report
    if backend == "fem":
        from twoball.fem_membrane.guards import mesh_warnings

        spec, series = field.spec, model.backend(backend).series
        if field.loaded is None:
            warnings += mesh_warnings(spec.kind, spec.level, None, spec.order, series.filter)
        else:
            surface = (field.loaded.mesh.points, field.loaded.mesh.cells)
            warnings += mesh_warnings("sphere", None, None, field.order, series.filter, surface)
    warnings += model.backend(backend).report.warnings
    return list(dict.fromkeys(warnings))  # a contact report has the mesh's already


def check_fps(fps: object) -> float:
    """Frames per second of an animation, in :data:`FPS_RANGE`."""
    from twoball._common.errors import bounded

    return bounded("fps", fps, *FPS_RANGE)


def eigen_sizes(
    levels: Sequence[int] | None, orders: Sequence[int] | None, max_degree: int | None
) -> tuple[list[int], list[int]]:
    """Levels and orders of the eigenvalue plot, each mesh checked against the budget."""
    from twoball._common.budget import check, options
    from twoball.fem_membrane.cost import fem_dofs, fem_estimate

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
            dofs = fem_dofs("sphere", spec.level, None, spec.order)
            check(size, fem_estimate(dofs, 30, "krylov", 2, spec.order))
    return list(levels), list(orders)


def check_frame_budget(case: Case, count: int, name: str, field: FieldMesh) -> None:
    """Refuse ``count`` frames on the mesh when their memory or time cannot fit (budget).

    The nodes are those of the generated sphere of the level and order, or the
    user's mesh's own (its triangles at its order).
    """

    if count > MAX_FRAMES:  # the same cap for frames, times and instants
        if name in ("instants", "frames"):  # a count
            low = 2 if name == "instants" else 1
            raise ParameterError(name, f"an integer in [{low}, {MAX_FRAMES}]", count)
        if name == "times":  # frames given as their times
            raise ParameterError("frames", f"at most {MAX_FRAMES} times [s]", f"{count} times")
        raise ParameterError(name, f"at most {MAX_FRAMES} {name}", f"{count} {name}")
    spec = field.spec
    mesh = spec.kind if field.loaded is None else field.loaded.mesh
    check_frames_budget(
        f"{name} ({count} frames)", count, mesh, spec.level, field.order, case.modes
    )


def check_frames(frames: object, name: str = "frames") -> int:
    """Number of frames: an integer in [1, 2000]."""
    if isinstance(frames, bool) or not isinstance(frames, int | np.integer):
        raise ParameterError(name, f"an integer in [1, {MAX_FRAMES}]", frames)
    if not (1 <= int(frames) <= MAX_FRAMES):
        raise ParameterError(name, f"an integer in [1, {MAX_FRAMES}]", frames)
    return int(frames)


def parse_times(text: str, name: str = "times") -> tuple[float, ...]:
    """Times [s] in the one list syntax: ``0,0.005,0.01`` or ``0:0.01:3``.

    Each must be a finite number >= 0; they are returned sorted, without duplicates.
    """
    from twoball._common.ranges import SYNTAX, parse_values

    valid = "times >= 0 in seconds, e.g. 0,0.005,0.01 or 0:0.01:11"
    values = parse_values(text, name, valid=valid)
    if any(v < 0 for v in values):
        raise ParameterError(name, f"{SYNTAX} ({valid})", text)
    return tuple(sorted(set(values)))


def window_s(case: Case, t_end_s: float | None = None) -> float:
    """The modelled window [s]: ``t_end_s``, or 4 pi / c by default."""
    return t_end_dimensionless(case, t_end_s) * case.scalings.time


def check_times(end: float, times_s: Sequence[float], name: str = "times") -> np.ndarray:
    """``times_s`` [s] as a sorted array, each inside the modelled window [0, ``end``].

    Each time must be a real number (a nested list or a text is refused by name).
    """
    from numbers import Real

    valid = f"times in [0, {end:.6g}] s (the modelled window)"
    given = list(times_s)
    if any(isinstance(t, bool) or not isinstance(t, Real) for t in given):
        raise ParameterError(name, valid, given)
    times = np.asarray(sorted({float(t) for t in given}), dtype=float)
    if times.size == 0 or np.any(~np.isfinite(times)) or times.min() < 0 or times.max() > end:
        raise ParameterError(name, valid, given)
    return times


def frame_times(
    model: BallModel,
    frames: int | None = None,
    times_s: Sequence[float] | None = None,
    backend: str = "fem",
    include_liftoff: bool = True,
) -> np.ndarray:
    """Frame times [s]: given ``times_s``, or ``frames`` evenly spaced over [0, t_end].

    With ``frames`` (default 25) the lift-off time of ``backend`` is added as an
    extra frame when ``include_liftoff`` is set and the body lifts off.
    """
    if times_s is not None:
        return check_times(model.t_end_s, times_s)
    count = DEFAULT_FRAMES if frames is None else check_frames(frames)
    times = np.linspace(0.0, model.t_end_s, count) if count > 1 else np.array([0.0])
    report = model.backend(backend).report
    if include_liftoff and report.result.lifted:
        times = np.union1d(times, [report.t_liftoff_s])
    return times


def liftoff_frame(model: BallModel, backend: str = "fem") -> np.ndarray:
    """The lift-off time [s] of ``backend`` as a one-frame array (t = 0 if no lift-off)."""
    report = model.backend(backend).report
    return np.array([report.t_liftoff_s if report.result.lifted else 0.0])


#: Per-frame field data of an export with a body of finite mass (name: unit).
FRAME_FIELDS: dict[str, str] = {
    "s_m": "the body's height above the undeformed pole [m]",
    "s_t_m_s": "the body's velocity [m/s]",
    "contact": "1 while the body is on the membrane, 0 in flight",
}


def check_field_body(
    case: Case, body: Body, field: Any, *, recontact: str | None = None, route: str = "auto"
) -> None:
    """Refuse what the fields of a body of finite mass cannot be computed with.

    The checks of :func:`~twoball.modal.contact.report.check_contact_options`
    (the radius against R; no bending or gas), ``mass_ratio > 0`` (0, the
    massless criteria, has no body to draw), the ``window`` re-contact horizon
    (events are simulated), a route giving every eigenpair (``auto`` or
    ``full``: the field is rebuilt from the modes), a generated, isoparametric
    mesh (``field``: a :class:`~twoball.verify.output.fields.FieldMesh`).
    """
    from twoball.fem_membrane.options import FILE

    check_contact_options(case, body)
    if body.mass_ratio == 0.0:
        valid = f"in (0, {MAX_MASS_RATIO:g}] for fields and plots (0 has no body to draw)"
        raise ParameterError("mass_ratio", valid, body.mass_ratio)
    if recontact not in (None, "window"):
        valid = "window with mass_ratio (events are simulated)"
        raise ParameterError("recontact", valid, recontact)
    if route not in ("auto", "full"):
        raise ParameterError("route", "auto or full with mass_ratio (every eigenpair)", route)
    spec = field.spec
    if spec.kind == FILE:
        valid = "a generated mesh (sphere or ring) with mass_ratio, not a mesh file"
        path = isinstance(spec.file, str | os.PathLike)
        raise ParameterError("mesh", valid, os.fspath(spec.file) if path else "a mesh object")
    if spec.geometry != "isoparametric":
        raise ParameterError("geometry", "isoparametric with mass_ratio", spec.geometry)


@dataclass(frozen=True)
class CoupledModel(BallModel):
    """A :class:`BallModel` whose fields are the membrane coupled to the body.

    Each backend's ``report`` is its :class:`~twoball.modal.contact.report.ContactReport`
    (``system`` and ``history`` of the contact solver), ``shapes`` its modes at
    the mesh nodes, one row per mode of ``report.motion``.
    """

    _states: dict = field(default_factory=dict, init=False, compare=False, repr=False)

    def contact(self, name: str) -> Any:
        """The contact report of backend ``name``."""
        return self.backend(name).report

    def states(self, name: str, times_s: np.ndarray) -> ModalStates:
        """Modal state of backend ``name`` at ``times_s`` [s] (dimensionless values).

        Computed once per backend and times (matrix exponentials are the cost of an
        export: measured 21 of 24 s at level 2).
        """
        t = np.atleast_1d(np.asarray(times_s, dtype=float)) / self.case.scalings.time
        key = (name, t.tobytes())  # u, u_t, u_tt, the body and the caption share one solve
        if key not in self._states:
            report = self.contact(name)
            self._states[key] = report.motion.states(t)
        return self._states[key]

    def nodal(self, name: str, times_s: np.ndarray, derivative: int = 0) -> np.ndarray:
        """Coupled u [m], u_t [m/s] or u_tt [m/s^2] at the nodes, shape (T, P).

        ``u = sum_k q_k phi_k`` with ``q`` from the contact solver: eq. (C1) with
        the contact force while the body is on.
        """
        scale = self.case.scalings
        unit = (scale.length, scale.velocity, scale.acceleration)[derivative]
        modal = self.states(name, times_s).modal(derivative)
        return modal @ self.backend(name).shapes * unit

    def body_height(self, name: str, times_s: np.ndarray) -> np.ndarray:
        """The body's height s [m] above the undeformed pole (the contact solution)."""
        return self.states(name, times_s).body_height * self.case.scalings.length

    def motion(self, name: str, times_s: np.ndarray) -> dict[str, np.ndarray]:
        """Cap-averaged membrane and body at ``times_s`` [s], in SI.

        Keys: ``cap_m``, ``cap_t_m_s``, ``cap_tt_m_s2`` (``b . q`` and its
        derivatives, the cap average of eq. (C3)), ``s_m``, ``s_t_m_s``,
        ``s_tt_m_s2`` (the body), ``contact`` (bool).
        """
        scale = self.case.scalings
        states = self.states(name, times_s)
        b = self.contact(name).motion.contact
        return {
            "cap_m": states.modal(0) @ b * scale.length,
            "cap_t_m_s": states.modal(1) @ b * scale.velocity,
            "cap_tt_m_s2": states.modal(2) @ b * scale.acceleration,
            "s_m": states.body_height * scale.length,
            "s_t_m_s": states.body_velocity * scale.velocity,
            "s_tt_m_s2": states.body_acceleration * scale.acceleration,
            "contact": states.contact,
        }


def coupled_model(
    case: Case,
    backends: Sequence[str],
    body: Body,
    mesh: Any,
    *,
    sigma: str = "lanczos",
    t_end_s: float | None = None,
    progress: Step | None = None,
) -> CoupledModel:
    """Solve the contact problem with ``backends`` and put their modes on one sphere mesh.

    ``fem``: :func:`twoball.fem_membrane.contact.fem_contact_fields` (full
    eigen route on the mesh of the :class:`~twoball.fem_membrane.options.MeshOptions`
    ``mesh``); its nodes carry the fields.  ``legendre``:
    :func:`twoball.modal.contact.report.legendre_contact` with ``P_n(cos phi)``
    at the same nodes (or at the generated mesh's nodes).
    """
    from twoball.modal.contact.report import legendre_contact
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.legendre import legendre_series, legendre_shapes
    from twoball.modal.report import t_end_dimensionless

    t_end = t_end_dimensionless(case, t_end_s)
    say = progress or silent
    solved: dict[str, Backend] = {}
    mu = body.mass_ratio
    if "fem" in backends:
        from twoball.fem_membrane.contact import fem_contact_fields
        from twoball.fem_membrane.cost import fem_contact_work

        say(f"contact of a body of mass ratio {mu:g} on the finite elements")
        check_all(fem_contact_work(case, body, mesh, t_end_s))
        nodes, shapes, series, report = fem_contact_fields(
            case, body, mesh, sigma=sigma, t_end_s=t_end_s, monitor=Watch()
        )
        details = {k: float(v) for k, v in report.extra.items() if isinstance(v, (int, float))}
        solved["fem"] = Backend("fem", series, shapes, report, details)
    else:
        membrane = membrane_case(case, mu, body.energy)
        nodes = build_mesh(membrane, mesh.level, mesh.order, mesh.kind)
    if "legendre" in backends:
        from twoball.modal.contact.cost import legendre_contact_work

        say(f"contact of a body of mass ratio {mu:g} on the closed form")
        check_all(legendre_contact_work(case, body, t_end_s))
        report = legendre_contact(case, body, sigma=sigma, t_end_s=t_end_s, monitor=Watch())
        membrane = report.membrane or case
        series = legendre_series(
            membrane.phi_a, case.damping, SpectralFilter(sigma, case.modes), monitor=Watch()
        )
        shapes = legendre_shapes(node_polar_angles(nodes), case.modes)
        solved["legendre"] = Backend("legendre", series, shapes, report, {"modes": case.modes})
    return CoupledModel(case, nodes, solved, t_end, sigma, "window")


def contact_series(series: TimeSeries, model: CoupledModel, backend: str) -> TimeSeries:
    """``series`` with the body's path of ``backend`` and its events (SI).

    Frame data (:data:`FRAME_FIELDS`): ``s_m`` [m], ``s_t_m_s`` [m/s],
    ``contact`` (1 or 0).  Field data: ``mass_ratio``, ``contact_radius_m`` [m],
    ``restitution``, ``impacts``, ``events``.  Texts ``upper_body`` (the options and
    the frame data's units) and ``contact_events``: the JSON
    list of :meth:`~twoball.modal.contact.report.ContactReport.events_si`
    (``kind``, ``t_s``, ``height_m``, ``velocity_m_s``, ``impulse_N_s`` and
    ``energy_loss_J`` per kg of membrane mass).
    """
    report = model.contact(backend)
    motion = model.motion(backend, series.times)
    frame_data = {
        "s_m": motion["s_m"],
        "s_t_m_s": motion["s_t_m_s"],
        "contact": motion["contact"].astype(float),
    }
    field_data = {
        **series.field_data,
        "mass_ratio": report.mass_ratio,
        "contact_radius_m": report.contact_radius_m,
        "restitution": report.restitution,
        "impacts": float(len(report.history.impacts)),
        "events": float(len(report.history.events)),
    }
    described = "; ".join(f"{name}: {text}" for name, text in FRAME_FIELDS.items())
    text = {
        **series.text,
        "contact_events": json.dumps(report.events_si()),
        "upper_body": (
            f"upper body of mass ratio {report.mass_ratio:g} ({backend}), contact radius "
            f"{report.contact_radius_m:g} m, restitution {report.restitution:g}, energy "
            f"{report.energy}; the membrane is coupled to it (docs/contact.rst); per frame "
            f"{described}; contact_events: JSON list of the events (SI)"
        ),
    }
    return replace(series, field_data=field_data, text=text, frame_data=frame_data)


def contact_scene(model: CoupledModel, times_s: np.ndarray, backend: str) -> Any:
    """The scene of :func:`~twoball.verify.output.fields.ball_scene` with the body's contact.

    The membrane is the coupled field, the body at its height ``s(t)``; the
    caption marks the frames in contact (:class:`twoball.verify.output.render.ContactScene`).
    """
    from twoball.verify.output.render import ContactScene

    scene = ball_scene(model, times_s, backend)
    report = model.contact(backend)
    impacts = [e["t_s"] for e in report.events_si() if e["kind"] == "impact"]
    return ContactScene(
        scene.points,
        scene.cells,
        scene.times,
        scene.u,
        scene.body,
        scene.radius,
        scene.t_liftoff,
        f"{scene.label}, mu = {report.mass_ratio:g}",
        settle_time=scene.settle_time,
        contact=model.states(backend, scene.times).contact,
        impacts=np.array(impacts),
        mass_ratio=report.mass_ratio,
    )


# --------------------------------------------------------------------------- cost
DOUBLES_PER_FRAME_NODE = 12  # u, u_t, u_tt and u n of both backends


def frames_estimate(
    frames: int, nodes: int, modes: int, seconds_per_frame: float = 0.0
) -> Estimate:
    """Fields at ``frames`` instants on ``nodes`` nodes from ``modes`` modes (export, render, plot).

    Memory ``12 doubles x nodes x frames`` (u, u_t, u_tt and u n of both backends);
    time ``40 ns x frames x nodes x modes`` for the evaluation plus
    ``seconds_per_frame`` for drawing or writing each frame.
    """
    from twoball.modal.cost import SECONDS_PER_TERM

    memory = BASE_MEMORY + 8.0 * DOUBLES_PER_FRAME_NODE * nodes * frames + 8.0 * nodes * modes
    seconds = frames * (SECONDS_PER_TERM * nodes * modes + seconds_per_frame)
    return Estimate(memory, seconds)


def check_frames_budget(
    option: str,
    frames: int,
    mesh: str = "sphere",
    level: int | None = None,
    order: int = 2,
    modes: int = 30,
    seconds_per_frame: float = 0.0,
) -> Estimate:
    """Refuse ``frames`` field frames on the mesh (export, render, plot) that cannot fit.

    The mode count is the FE one, ``(N + 1)^2`` on the sphere (the Legendre
    backend has fewer); ``seconds_per_frame`` is the drawing or writing of a frame.
    """
    from twoball.fem_membrane.cost import fem_dofs

    nodes = fem_dofs(mesh, level, None, order)
    pairs = (modes + 1) ** 2
    return check(option, frames_estimate(frames, nodes, pairs, seconds_per_frame))
