"""Finite-element pole motion: the entry point for the command line.

Two independent time discretisations of the semi-discrete membrane equation
(3.9) with a damping law (the paper's ratio D, or Rayleigh ``C = alpha M + beta
K``, :mod:`twoball.modal.damping`):

``modal``
    Superposition of finite-element eigenmodes in closed form, eqs. (3.14)-(3.16),
    returned as the shared :class:`twoball.modal.series.ModalSeries`; each mode
    with the law's ratio ``zeta(omega_k)`` (exact for Rayleigh damping, which the
    M-orthonormal eigenvectors diagonalise).
``alpha``
    Direct generalized-alpha stepping of ``M u'' + C u' + K u = 0`` from the
    filtered initial displacement, returned as
    :class:`twoball.modal.liftoff.SampledPoleMotion` (each of the pole's u, u_t, u_tt
    through its own cubic spline on the step grid); C is the low-rank modal
    damping of ratio D or the sparse Rayleigh matrix.

Both motions go to :func:`twoball.modal.liftoff.find_liftoff`; nothing here decides
lift-off, filters or scales.  Everything is dimensionless.
"""

from __future__ import annotations

import time as clock
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.monitor import Monitor, silent
from twoball.fem_membrane.alpha import GeneralizedAlpha, automatic_step
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.damping import ModalDamping, rayleigh_matrix, rayleigh_table
from twoball.fem_membrane.eigen import Eigenpairs, eigenpairs
from twoball.fem_membrane.initial import initial_moments
from twoball.fem_membrane.krylov import ROUTES, choose_route, krylov_modal_series
from twoball.fem_membrane.mesh import SphereMesh
from twoball.fem_membrane.modal import filtered_displacement, modal_series
from twoball.fem_membrane.ritz_field import field_times
from twoball.fem_membrane.space import Discretisation
from twoball.fem_membrane.validate import (
    DAMPING_MODELS,
    INITIAL_METHODS,
    TIME_SCHEMES,
    check_choice,
    check_dt,
    check_rho_inf,
    check_t_end,
)
from twoball.modal.damping import RAYLEIGH_LOW, Rayleigh
from twoball.modal.filters import FilterKind, SpectralFilter
from twoball.modal.initial import check_phi_a
from twoball.modal.liftoff import DEFAULT_T_END, PoleMotion, SampledPoleMotion
from twoball.modal.series import ModalSeries, check_law
from twoball.modal.stiffness import Stiffness

STEP_ACCURACY = 0.2  # automatic dt: omega_cut * dt <= 0.2


@dataclass
class ModalModel:
    """Space, eigenpairs and modal series of one finite-element run (dimensionless)."""

    space: Discretisation
    pairs: Eigenpairs | None
    moments: np.ndarray
    series: ModalSeries
    seconds: dict[str, float] = field(default_factory=dict)
    krylov: dict[str, Any] | None = None
    """Krylov route details (None on the full eigen route, where ``pairs`` is set)."""
    stiffness: Stiffness | None = None
    """Bending and gas (:mod:`twoball.fem_membrane.shell`); None: the membrane."""

    @property
    def filter(self) -> SpectralFilter:
        """The spectral filter of the series."""
        return self.series.filter


def as_filter(filter: SpectralFilter | FilterKind, modes: int = 30) -> SpectralFilter:
    """A SpectralFilter from a filter or a kind name (with ``modes``)."""
    if isinstance(filter, SpectralFilter):
        return filter
    return SpectralFilter(filter, modes)


def modal_model(
    phi_a: float,
    damping: Any,
    filter: SpectralFilter | FilterKind = "lanczos",
    *,
    mesh: str = "sphere",
    level: int | None = None,
    elements: int | None = None,
    order: int = 2,
    initial: str = "projection",
    route: str = "full",
    geometry: str = "isoparametric",
    fields: bool = False,
    t_end: float = DEFAULT_T_END,
    stiffness: Stiffness | None = None,
    monitor: Monitor | None = None,
) -> ModalModel:
    """Assemble, project F (eq. (3.10)) and build the filtered modal series.

    ``route="full"`` (the reference) computes every eigenpair below the filter
    cutoff ``filter.omega_cut**2`` (eqs. (3.12), (3.16)); ``route="krylov"`` finds
    only the modes the pole and the initial displacement see, by the rational
    Krylov method of :mod:`twoball.fem_membrane.krylov` (pole motion exact to 1e-10
    relative; no eigenvector set, ``pairs`` is None); ``route="auto"`` takes
    Krylov from :data:`twoball.fem_membrane.krylov.AUTO_THRESHOLD` DOFs on.  See
    :func:`fem_pole_motion`.  ``geometry`` is that of
    :func:`twoball.fem_membrane.build.build_space`.

    ``fields=True`` asks for mode shapes on every node: on the Krylov route
    ``pairs`` then holds the Ritz pairs below the cutoff, and the Krylov method
    also stops on the whole filtered field (u, u_t, u_tt in the M-norm at
    instants over [0, ``t_end``], :mod:`twoball.fem_membrane.ritz_field`).

    ``stiffness`` (membrane operator, bending, gas) maps the Laplace-Beltrami
    spectrum to the pressure term's, the mixed bending form's and the gas
    term's (:func:`twoball.fem_membrane.shell.stiff_series`); ``pairs`` then
    hold the stiffened eigenvalues.  ``damping`` is the ratio D or a Rayleigh law
    in units of c (:func:`twoball.modal.series.check_law`), applied to the
    stiffened frequencies.

    ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is told as each stage
    starts (assembly, initial displacement, eigenpairs), within the eigen solve or
    the Krylov iteration, and by the series (:attr:`ModalSeries.monitor`); it may
    stop the work by raising.  Its cost (:func:`twoball.fem_membrane.cost.fem_work`)
    is the caller's to check before.
    """
    phi_a = check_phi_a(phi_a)
    damping = check_law(damping)
    filter = as_filter(filter)
    initial = check_choice("initial", initial, INITIAL_METHODS)
    seconds = {}
    say = monitor if monitor is not None else silent
    start = clock.perf_counter()
    say("mesh and assembly")
    space = build_space(
        mesh, level=level, elements=elements, order=order, phi_a=phi_a, geometry=geometry
    )
    say(f"initial displacement ({initial}) on {space.dofs} unknowns")
    moments = initial_moments(space, phi_a, initial)
    seconds["assembly"] = clock.perf_counter() - start
    route = choose_route(route, space.dofs)
    start = clock.perf_counter()
    say(f"eigenpairs below the cutoff on {space.dofs} unknowns ({route} route)")
    if route == "full":
        pairs = eigenpairs(space.stiffness, space.mass, filter.omega_cut**2, monitor=monitor)
        series = modal_series(pairs, moments, space.pole_row, damping, filter, monitor)
        krylov = None
    else:
        times = field_times(t_end, filter.omega_cut) if fields else None
        series, details = krylov_modal_series(
            space,
            moments,
            damping,
            filter,
            t_end=t_end,
            vectors=fields,
            field_times=times,
            monitor=monitor,
        )
        pairs, krylov = details.pairs, details.as_dict()
    if stiffness is not None and stiffness.active:
        from twoball.fem_membrane.shell import stiff_pairs, stiff_series

        series = stiff_series(series, space, stiffness)
        if pairs is not None:
            pairs = stiff_pairs(pairs, series)
    else:
        stiffness = None
    seconds["eigen"] = clock.perf_counter() - start
    return ModalModel(space, pairs, moments, series, seconds, krylov, stiffness)


def fit_band(filter: SpectralFilter, stiffness: Stiffness | None) -> tuple[float, float]:
    """Where a fitted Rayleigh law has ratio D: the ball's lowest vibrating mode and degree N.

    :meth:`twoball.modal.stiffness.Stiffness.fit_band`; sqrt(2) and ``omega_N`` for
    the paper's membrane.
    """
    if stiffness is None or not stiffness.active:
        return RAYLEIGH_LOW, filter.omega_n
    return stiffness.fit_band(filter.modes)


def resolve_law(
    damping: Any,
    damping_model: str,
    rayleigh: Rayleigh | None,
    filter: SpectralFilter,
    stiffness: Stiffness | None,
) -> tuple[float | Rayleigh, tuple[float, float] | None]:
    """The damping of a run: ratio D, or a Rayleigh law in units of c; and its fit band.

    ``damping_model="rayleigh"`` with a ratio D takes ``rayleigh`` (coefficients
    given) or the law fitted to D at :func:`fit_band` (returned as the second
    value, None otherwise); a Rayleigh law as ``damping`` is taken as it is.
    """
    law = check_law(damping)
    if isinstance(law, Rayleigh) or damping_model != "rayleigh":
        return law, None
    if rayleigh is not None and not rayleigh.fitted:
        return rayleigh, None
    band = fit_band(filter, stiffness)
    return Rayleigh.fit(law, *band), band


def rayleigh_info(law: Rayleigh, band: Any, omega: np.ndarray, ratio: float | None) -> dict:
    """The Rayleigh block of ``info``: coefficients (units of c), fit band, ratio table."""
    return {
        "alpha": law.alpha,
        "beta": law.beta,
        "omega_low": None if band is None else band[0],
        "omega_high": None if band is None else band[1],
        "table": rayleigh_table(law, omega, ratio),
    }


def alpha_motion(
    model: ModalModel,
    *,
    damping_model: str = "modal",
    dt: float | None = None,
    rho_inf: float = 1.0,
    t_end: float = DEFAULT_T_END,
    rayleigh: Rayleigh | None = None,
    monitor: Monitor | None = None,
) -> tuple[SampledPoleMotion, dict[str, Any]]:
    """Generalized-alpha stepping from the filtered initial displacement.

    ``u0 = Phi diag(sigma) Phi^T M u_proj`` (the filtered series at t = 0),
    ``u_t(0) = 0`` and ``M u_tt(0) = -K u0``; the sampled pole motion matches the
    modal series as dt -> 0.  The damping is the series' law: ratio D on every
    computed mode (low rank), or the sparse Rayleigh ``C = alpha M + beta K``
    with K the ball's operator (pressure term, bending and gas included).
    ``damping_model="rayleigh"`` on a series of ratio D takes ``rayleigh`` or
    the law fitted to D (:func:`resolve_law`) instead.  ``monitor`` is told
    every 16 steps (:meth:`~twoball.fem_membrane.alpha.GeneralizedAlpha.run`).

    Returns
    -------
    SampledPoleMotion, dict
        Pole samples and ``dt``, ``steps``, ``rho_inf`` (and ``rayleigh`` when
        the law was resolved here).
    """
    damping_model = check_choice("damping_model", damping_model, DAMPING_MODELS)
    dt = check_dt(dt)
    rho_inf = check_rho_inf(rho_inf)
    t_end = check_t_end(t_end)
    space, pairs, series = model.space, model.pairs, model.series
    if dt is None:
        dt = automatic_step(model.filter.omega_cut, t_end, STEP_ACCURACY)
    info: dict[str, Any] = {"dt": dt, "rho_inf": rho_inf}
    law, band = resolve_law(series.damping, damping_model, rayleigh, model.filter, model.stiffness)
    if band is not None or (isinstance(law, Rayleigh) and law is not series.damping):
        ratio = float(series.damping)
        info["rayleigh"] = rayleigh_info(law, band, series.omega[series.retained], ratio)
    start = clock.perf_counter()
    if model.stiffness is not None:
        from twoball.fem_membrane.shell import ShellAlpha, ShellOperator

        operator = ShellOperator(space, model.stiffness)
        if not isinstance(law, Rayleigh):
            law = ModalDamping.from_modes(space.mass, pairs, law)
        stepper = ShellAlpha(space.mass, operator, dt, law, rho_inf)
    else:
        if isinstance(law, Rayleigh):
            damping = rayleigh_matrix(law, space.mass, space.stiffness)
        else:
            damping = ModalDamping.from_modes(space.mass, pairs, law)
        stepper = GeneralizedAlpha(space.mass, space.stiffness, dt, damping, rho_inf)
    u0 = filtered_displacement(series, pairs)
    history = stepper.run(u0, np.zeros_like(u0), t_end, space.pole_row, monitor)
    info["steps"] = history.t.size - 1
    info["seconds_stepping"] = clock.perf_counter() - start
    # an integrator's u, u_t, u_tt are each O(dt^2), not derivatives of one another
    motion = SampledPoleMotion(
        history.t, history.u, history.u_t, history.u_tt, interpolation="splines"
    )
    return motion, info


def fem_pole_motion(
    phi_a: float,
    damping: float,
    filter: SpectralFilter | FilterKind = "lanczos",
    *,
    mesh: str | SphereMesh = "sphere",
    level: int | None = None,
    elements: int | None = None,
    order: int | None = 2,
    scheme: str = "modal",
    damping_model: str = "modal",
    dt: float | None = None,
    rho_inf: float = 1.0,
    t_end: float = DEFAULT_T_END,
    initial: str = "projection",
    rayleigh: Rayleigh | None = None,
    route: str = "auto",
    geometry: str = "isoparametric",
    stiffness: Stiffness | None = None,
    monitor: Monitor | None = None,
) -> tuple[PoleMotion, dict[str, Any]]:
    """Pole motion of the damped membrane from finite elements (dimensionless).

    Solves eq. (3.9) with modal damping ratio D (eq. (3.14)) from the initial
    displacement F of eq. (3.10), Galerkin-projected (the discrete eq. (3.12)),
    filtered by frequency as in eq. (3.16).  Its cost
    (:func:`twoball.fem_membrane.cost.fem_work` with the scheme, step and window)
    is the caller's to check before.

    Parameters
    ----------
    phi_a : float
        Contact angle [rad] in (pi/2, pi).
    damping : float or Rayleigh
        Damping ratio D in [0, 1), or a Rayleigh law in units of c.
    filter : SpectralFilter or {"lanczos", "printed", "none"}
        Spectral filter; a kind name uses N = 30.  Its ``omega_cut`` is the
        eigenvalue cutoff, also for ``"none"``.
    mesh : {"sphere", "ring", "axisym"} or SphereMesh
        Icosphere, sphere with a ring of edges at phi_a, axisymmetric line, or
        a unit-sphere mesh such as a loaded file's
        (:func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`).
    level : int, optional
        Sphere refinement level in [0, 10] (default 3).
    elements : int, optional
        Axisymmetric elements >= 2 (default 400).
    order : {1, 2, 3, 4}, optional
        P1 on flat triangles or isoparametric P2, P3, P4; None with a
        SphereMesh: the mesh's own order.
    geometry : {"isoparametric", "exact"}
        The order-p interpolant of the sphere, or the sphere itself (icosphere
        and SphereMesh only).
    scheme : {"modal", "alpha"}
        Modal superposition or generalized-alpha stepping.
    route : {"auto", "full", "krylov"}
        ``modal`` only: every eigenpair below the cutoff (``full``, the reference),
        the rational Krylov route of :mod:`twoball.fem_membrane.krylov` (``krylov``), or
        Krylov from 2000 DOFs on (``auto``, default).  ``alpha``
        always uses the full eigenpairs.
    damping_model : {"modal", "rayleigh"}
        With a ratio D as ``damping``: ratio D on every mode (eq. (3.14)), or
        Rayleigh ``C = a M + b K`` of ``rayleigh`` (default: fitted to D at the
        lowest vibrating mode and omega_N, :func:`fit_band`).
        A Rayleigh law given as ``damping`` is used as it is.
    dt : float, optional
        Time step > 0; default ``omega_cut dt <= 0.2``.
    rho_inf : float
        Generalized-alpha spectral radius in [0, 1]; 1 =
        average acceleration.
    t_end : float
        End of the stepped window, default 4 pi.
    initial : {"projection", "interpolation"}
        Galerkin L2 projection of F, or nodal interpolation.
    rayleigh : Rayleigh, optional
        The law of ``damping_model="rayleigh"`` (units of c); None or fitted:
        fitted to D at :func:`fit_band`.
    stiffness : Stiffness, optional
        Membrane operator, bending and gas (:mod:`twoball.fem_membrane.shell`);
        None: the paper's membrane.
    monitor : Monitor, optional
        Told as the work goes on (:func:`modal_model`, :func:`alpha_motion`; a
        :class:`~twoball._common.monitor.Monitor`, which may stop it by raising).

    Returns
    -------
    motion : ModalSeries or SampledPoleMotion
        Anything :func:`twoball.modal.liftoff.find_liftoff` accepts.
    info : dict
        ``dofs``, ``modes_used`` (nonzero filter weight), ``modes_computed``,
        ``mesh``, ``order``, ``time_scheme``, ``damping_model``, ``initial``,
        ``omega_cut``, ``omega_next`` (first frequency above the cutoff),
        ``seconds`` (assembly, eigen, stepping); for ``alpha`` also ``dt``,
        ``steps``, ``rho_inf`` and, for Rayleigh damping, ``rayleigh`` with
        ``alpha``, ``beta``, ``omega_low``, ``omega_high`` and ``table`` (rows
        ``mode``, ``omega``, ``zeta``, ``ratio`` = zeta / D).
    """
    scheme = check_choice("scheme", scheme, TIME_SCHEMES)
    damping_model = check_choice("damping_model", damping_model, DAMPING_MODELS)
    dt = check_dt(dt)
    rho_inf = check_rho_inf(rho_inf)
    t_end = check_t_end(t_end)
    route = check_choice("route", route, ROUTES)
    if scheme == "alpha":
        if route == "krylov":
            raise ParameterError("route", "full or auto when scheme is alpha", route)
        route = "full"  # time stepping needs the eigenvectors for damping and filtering
    modes = as_filter(filter).modes
    ratio = None if isinstance(damping, Rayleigh) else float(check_law(damping))
    law, band = resolve_law(damping, damping_model, rayleigh, as_filter(filter, modes), stiffness)
    if isinstance(law, Rayleigh):
        damping_model = "rayleigh"
    model = modal_model(
        phi_a,
        law,
        filter,
        mesh=mesh,
        level=level,
        elements=elements,
        order=order,
        initial=initial,
        route=route,
        geometry=geometry,
        stiffness=stiffness,
        monitor=monitor,
    )
    space, pairs, series = model.space, model.pairs, model.series
    next_value = None if pairs is None else pairs.next_value
    info: dict[str, Any] = {
        "dofs": space.dofs,
        "route": "full" if model.krylov is None else "krylov",
        "modes_used": int(np.count_nonzero(series.retained)),
        "modes_computed": len(series.omega),
        "mesh": space.name,
        "mesh_kind": space.kind,
        "omega_max": series.max_frequency,
        "order": space.order,
        "geometry": space.geometry,
        "time_scheme": scheme,
        "damping_model": damping_model,
        "initial": initial,
        "omega_cut": series.filter.omega_cut,
        "omega_next": None if next_value is None else float(np.sqrt(max(next_value, 0.0))),
        "seconds": dict(model.seconds),
    }
    if model.krylov is not None:
        info["krylov"] = model.krylov
    if isinstance(law, Rayleigh):
        info["rayleigh"] = rayleigh_info(law, band, series.omega[series.retained], ratio)
    if scheme == "modal":
        return series, info
    motion, extra = alpha_motion(model, dt=dt, rho_inf=rho_inf, t_end=t_end, monitor=monitor)
    info["seconds"]["stepping"] = extra.pop("seconds_stepping")
    info.update(extra)
    return motion, info
