"""Accuracy guards of the finite-element backend: time step and mesh resolution.

Each guard returns short warning strings (SI, actionable), empty when the run is
inside its trustworthy regime.  Both bound the same thing: the frequency error of
the modes the filter keeps (eq. (3.16)), which shifts their phase at lift-off.

Time step (generalized-alpha, :mod:`twoball.fem_membrane.alpha`)
    The scheme is second order: its numerical frequency of an undamped mode is
    ``omega_h = omega (1 - (omega dt)^2 / 12 + ...)`` for rho_inf = 1 (the
    trapezoidal rule: ``omega_h dt = 2 arctan(omega dt / 2)``).  The guard computes
    the relative frequency error of the highest retained mode exactly, from the
    eigenvalues of the scheme's amplification matrix for the given rho_inf, and
    warns above :data:`FREQUENCY_ERROR` = 1 %, i.e. ``omega_max dt > 0.35`` for
    rho_inf = 1.  The automatic step (``omega_cut dt = 0.2``) gives 0.33 %: quiet;
    ``dt`` = 3e-3 s (``omega_max dt = 29``, c = 320 1/s) aliases every mode above
    n = 2: warned.

Mesh (eigenvalue error of the retained modes, eq. (3.11))
    The relative error of the FE eigenvalue of degree l behaves like
    ``e_l = C (l h)^(2p)`` for elements of order p and mesh size h (the known
    rates: O(h^2) for P1, O(h^4) for P2).  C was fitted to the worst member of
    each degree-l cluster (measured: sphere P1 levels 3-4, P2 levels 2-3; ring P1
    level 4, P2 level 3; axisymmetric P1 100/400 and P2 50/100 elements; sphere P3
    and P4 levels 2-3 and axisymmetric P3/P4 25/50 elements at l = 10-20, where the
    Galerkin term dominates the geometric one; the fits agree within 40 % across
    sizes), see :data:`MESH_CONSTANTS`.  The guard
    evaluates it at the highest degree the filter keeps with weight >= 1/2 (l = 17
    of N = 30 for Lanczos; N for the printed and no filter) and warns above
    :data:`EIGENVALUE_ERROR` = 5 % (2.5 % in frequency).  Defaults (icosphere
    level 3, P2: 3 %; axisymmetric 400 P2: 1e-5) are quiet; icosphere level 2 P1
    (lift-off 5.76 ms instead of 9.88 ms) is warned.  Orders without a fitted
    constant (the ring sphere at P3/P4) get no estimate.

A user's mesh (eq. (3.11) on any triangulation)
    It has no level, but it has a size: T triangles of the unit sphere are
    given the icosphere's mesh size at the same count, ``h = 1.0515 sqrt(20 /
    T)`` (exactly the generated ``1.0515 / 2^level`` for ``T = 20 4^level``),
    times ``(sum_i A_i (A_i / mean A)^p / sum_i A_i)^(1 / 2p)`` for triangle
    areas ``A_i``: the error ``C (l h_i)^(2p)`` averaged over the surface, so a
    mesh with large and small triangles counts its large ones (1.004 for the
    icosphere itself, 1.008 for a gmsh sphere of 623 nodes), and the sphere's
    constant of its order.  A gmsh P1 sphere of 623 nodes (1242 triangles)
    gets 51 % like the generated level 3 P1 (642 nodes, 50 %): warned.
"""

from __future__ import annotations

import math

import numpy as np

from twoball.fem_membrane.alpha import AlphaParameters
from twoball.modal.filters import SpectralFilter, legendre_frequency

FREQUENCY_ERROR = 0.01  # relative frequency error of the highest retained mode (time step)
EIGENVALUE_ERROR = 0.05  # relative eigenvalue error at the last half-weight degree (mesh)
ICOSAHEDRON_EDGE = 1.0515  # edge of the icosahedron inscribed in the unit sphere
#: (mesh kind, order) -> C of e_l = C (l h)^(2p); h = edge length (sphere, ring) or pi / E.
MESH_CONSTANTS: dict[tuple[str, int], float] = {
    ("sphere", 1): 0.10,
    ("sphere", 2): 1.3e-3,
    ("ring", 1): 0.14,
    ("ring", 2): 2.0e-3,
    ("axisym", 1): 0.09,
    ("axisym", 2): 1.4e-3,
    ("sphere", 3): 1.0e-5,
    ("sphere", 4): 5.0e-8,
    ("axisym", 3): 1.05e-5,
    ("axisym", 4): 4.3e-8,
}


def alpha_frequency_error(omega_dt: float, rho_inf: float = 1.0) -> float:
    """Relative frequency error ``|omega_h / omega - 1|`` of generalized-alpha at ``omega dt``.

    From the eigenvalues of the amplification matrix of ``u'' + omega^2 u = 0``
    (Chung & Hulbert 1993); ``omega_h dt`` is the argument of the principal pair.
    """
    p = AlphaParameters(rho_inf)
    w2 = omega_dt * omega_dt
    # x_{n+1} = A x_n for x = (u, u_t dt, u_tt dt^2): the equation at n + 1 - alpha and
    # the Newmark updates, all scaled by dt
    lhs = np.array(
        [
            [(1.0 - p.alpha_f) * w2, 0.0, 1.0 - p.alpha_m],
            [1.0, 0.0, -p.beta],
            [0.0, 1.0, -p.gamma],
        ]
    )
    rhs = np.array(
        [
            [-p.alpha_f * w2, 0.0, -p.alpha_m],
            [1.0, 1.0, 0.5 - p.beta],
            [0.0, 1.0, 1.0 - p.gamma],
        ]
    )
    values = np.linalg.eigvals(np.linalg.solve(lhs, rhs))
    # the principal pair is complex; the third (spurious) root is real
    pair = values[np.abs(values.imag) > 1e-14 * np.abs(values)]
    if pair.size == 0:
        return 1.0  # no oscillation left at all
    phase = float(np.max(np.abs(np.angle(pair))))
    return abs(phase / omega_dt - 1.0)


def time_step_warnings(
    omega_max: float, dt: float, rho_inf: float = 1.0, time_unit_s: float = 1.0
) -> list[str]:
    """Warn when dt is too coarse for the highest retained mode (module docstring).

    Parameters
    ----------
    omega_max : float
        Highest retained angular frequency (dimensionless, unit c).
    dt : float
        Time step (dimensionless, unit 1/c).
    rho_inf : float
        Generalized-alpha spectral radius in [0, 1].
    time_unit_s : float
        1/c [s], to state dt in seconds.
    """
    if not (omega_max > 0 and dt > 0):
        return []
    error = alpha_frequency_error(omega_max * dt, rho_inf)
    if error <= FREQUENCY_ERROR:
        return []
    largest = _largest_step(omega_max, rho_inf)
    return [
        f"time step too coarse: omega_max dt = {omega_max * dt:.3g} gives a "
        f"{min(error, 9.99):.0%} frequency error of the highest retained mode (limit "
        f"{FREQUENCY_ERROR:.0%}); use a time step dt <= {largest * time_unit_s:.3g} s "
        "or the default"
    ]


def _largest_step(omega_max: float, rho_inf: float) -> float:
    """Largest dt with a frequency error <= FREQUENCY_ERROR (bisection on omega dt)."""
    low, high = 0.0, 2.0
    for _ in range(50):
        mid = 0.5 * (low + high)
        if alpha_frequency_error(mid, rho_inf) <= FREQUENCY_ERROR:
            low = mid
        else:
            high = mid
    return low / omega_max


def mesh_size(mesh: str, level: int | None, elements: int | None) -> float:
    """Mesh size h: icosahedron edge / 2^level (sphere, ring), pi / E (axisymmetric)."""
    if mesh == "axisym":
        return math.pi / (400 if elements is None else elements)
    return ICOSAHEDRON_EDGE / 2.0 ** (3 if level is None else level)


def half_weight_degree(filter: SpectralFilter) -> int:
    """Highest degree l <= N whose filter weight is at least 1/2."""
    n = np.arange(filter.modes + 1)
    weights = filter(legendre_frequency(n))
    kept = np.flatnonzero(weights >= 0.5)
    return int(kept.max()) if kept.size else 0


def eigenvalue_error_estimate(mesh: str, order: int, h: float, degree: int) -> float | None:
    """``C (l h)^(2p)``: relative eigenvalue error of degree l (None: no fitted C)."""
    constant = MESH_CONSTANTS.get((mesh, int(order)))
    if constant is None:
        return None
    return constant * (degree * h) ** (2 * int(order))


def surface_size(points: np.ndarray, cells: np.ndarray, order: int) -> float:
    """Mesh size h of any triangulation of the unit sphere, on the icosphere's scale.

    ``1.0515 sqrt(20 / T)`` for T triangles, times the area average of
    ``(A_i / mean A)^p`` to the power ``1 / (2p)`` (module docstring); the
    corners ``cells[:, :3]`` of ``points`` (dimensionless, unit sphere) span the
    flat triangles whose areas are measured.
    """
    corners = np.asarray(points)[np.asarray(cells)[:, :3]]
    areas = 0.5 * np.linalg.norm(
        np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1
    )
    p = int(order)
    spread = float(np.sum(areas * (areas / areas.mean()) ** p) / areas.sum()) ** (0.5 / p)
    return ICOSAHEDRON_EDGE * math.sqrt(20.0 / len(areas)) * spread


def mesh_warnings(
    mesh: str,
    level: int | None,
    elements: int | None,
    order: int,
    filter: SpectralFilter,
    surface: tuple[np.ndarray, np.ndarray] | None = None,
) -> list[str]:
    """Warn when the mesh under-resolves the modes the filter keeps (module docstring).

    ``surface`` (points and cells of a user's unit-sphere mesh) replaces the
    generated mesh's level: its size comes from :func:`surface_size` and the
    error from the sphere's constant of ``order``.
    """
    degree = half_weight_degree(filter)
    if surface is not None:
        points, cells = surface
        h = surface_size(points, cells, order)
        error = eigenvalue_error_estimate("sphere", order, h, degree)
        size = f"your mesh: {len(cells)} triangles, h = {h:.3g} R"
    else:
        h = mesh_size(mesh, level, elements)
        error = eigenvalue_error_estimate(mesh, order, h, degree)
        size = (
            f"{400 if elements is None else elements} elements"
            if mesh == "axisym"
            else f"level {3 if level is None else level}"
        )
    quality = []
    if surface is not None:  # a user's mesh: its triangles near the pole
        from twoball.fem_membrane.quality import pole_quality_warnings

        quality = pole_quality_warnings(*surface)
    if error is None or error <= EIGENVALUE_ERROR:
        return quality
    return [
        f"mesh under-resolves the retained modes: estimated eigenvalue error "
        f"{min(error, 9.99):.0%} at degree l = {degree} (P{order}, {size}; limit "
        f"{EIGENVALUE_ERROR:.0%}); refine the mesh or raise the element order",
        *quality,
    ]


def fem_warnings(
    info: dict,
    filter: SpectralFilter,
    *,
    level: int | None = None,
    elements: int | None = None,
    time_unit_s: float = 1.0,
    surface: tuple[np.ndarray, np.ndarray] | None = None,
) -> list[str]:
    """Mesh and time-step warnings of one run from its ``info`` (:func:`fem_pole_motion`).

    ``surface``: the points and cells of a user's mesh (on the unit sphere),
    whose size stands in for the level (:func:`mesh_warnings`).
    """
    warnings = []
    if info["mesh_kind"] is not None:
        warnings += mesh_warnings(
            info["mesh_kind"], level, elements, info["order"], filter, surface
        )
    if info.get("time_scheme") == "alpha" and "dt" in info:
        omega = info.get("omega_max") or filter.omega_n
        warnings += time_step_warnings(omega, info["dt"], info.get("rho_inf", 1.0), time_unit_s)
    return warnings
