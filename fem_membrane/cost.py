"""Cost model of the finite elements: mesh, eigen solve and time stepping, before they run.

Calibration (peak RSS of a child process, wall time on the 2-core build
machine; ``benchmarks/bench_budget.py``): sphere P1 L4 / L5 and P2 L3 / L4 on
the Krylov route measured 187 / 312 and 159 / 283 MiB, 1.5 / 3.4 and 1.6 /
5.9 s (model: ``base + 20 kB/DOF``, ``0.6 ms/DOF``); the full route on P2 L3
171 MiB and 8 s (``+ 3 us x DOFs x (N + 1)^2``); generalized-alpha on P2 L2 /
L3 and the 8001-node line 2.4 / 17 / 8 ms per step (``0.3 ms + 1 us x DOFs +
5 ns x DOFs x modes``).

The model only estimates; whether the work fits is decided at the edge, before
it starts (:func:`twoball._costs.check_fem`, :func:`twoball._costs.check_fem_contact`).
"""

from __future__ import annotations

import math
from typing import Any

from twoball._common.estimate import BASE_MEMORY, Estimate, KiB, options
from twoball.modal.cost import legendre_omega

__all__ = ["alpha_estimate", "fem_contact_work", "fem_dofs", "fem_estimate", "fem_work"]

FE_BYTES_PER_DOF = 20 * KiB  # Krylov basis, LU fill, mesh and assembly (P1/P2, L3-L5)
#: Address space mapped per DOF on a sphere, by order: SuperLU reserves (calloc) its fill
#: estimate, far more than it touches.  Measured VmPeak less the 350 MiB of a level-1
#: run: P2 L4 / L5 / L6 47 / 44 / 40 kB, P3 L4 / L5 60 / 56 kB, P4 L3 / L4 / L5
#: 80 / 74 / 73 kB per DOF (resident: 12-14 kB).
FE_ADDRESS_PER_DOF = {1: 48 * KiB, 2: 48 * KiB, 3: 64 * KiB, 4: 84 * KiB}
BASE_ADDRESS = 400 * 2**20  # interpreter, numpy, scipy, BLAS buffers (measured 352 MiB)
FE_SECONDS_PER_DOF = 6e-4
FULL_ROUTE_SECONDS = 3e-6  # per DOF and eigenpair of the full eigen route
STEP_SECONDS = 3e-4  # per generalized-alpha step: Python overhead
STEP_SECONDS_PER_DOF = 1e-6  # sparse LU solves
STEP_SECONDS_PER_DOF_MODE = 5e-9  # low-rank modal damping (Woodbury)
STEP_BYTES = 160  # pole history and its three cubic splines per step


def fem_dofs(mesh: object, level: int | None, elements: int | None, order: int) -> int:
    """Degrees of freedom of the finite-element space, in closed form (no mesh built).

    Icosphere of level L: ``20 4^L`` triangles, so ``10 4^L p^2 + 2`` DOFs for
    order p; ring sphere: ``4 n^2 + 2`` vertices with ``n ~ sqrt(10) 2^(L-1)``;
    axisymmetric line of E elements: ``p E + 1``.
    """
    if not isinstance(mesh, str):  # a SphereMesh (a user's file): its own size
        order = mesh.order if order is None else int(order)
        return len(mesh.cells) * order * order // 2 + 2  # closed surface: V = T / 2 + 2
    order = int(order)
    if mesh == "axisym":
        return order * int(400 if elements is None else elements) + 1
    level = 3 if level is None else int(level)
    if level > 60:  # 4^level overflows any machine: report it as such
        return 10**40
    if mesh == "ring":
        rows = max(2, round(math.sqrt(10.0) * 2.0 ** (level - 1)))
        return 4 * rows * rows * order * order + 2
    return 10 * 4**level * order * order + 2


def fem_estimate(
    dofs: int, modes: int = 30, route: str = "krylov", dimension: int = 2, order: int = 2
) -> Estimate:
    """Assembly, eigen solve (or Krylov series) and lift-off of a FE space of ``dofs``.

    Memory ``base + 20 kB/DOF`` (measured P1/P2, levels 3-5); time ``0.6 ms/DOF``
    on the Krylov route, plus ``3 us x DOFs x (N + 1)^2`` on the full route
    (every eigenpair below the cutoff: ``(N + 1)^2`` on the sphere, ``N + 1`` on
    the axisymmetric line, ``dimension`` 2 or 1).  Address space on a sphere:
    :data:`FE_ADDRESS_PER_DOF` of ``order`` (SuperLU's reserve), what an
    address-space limit (``ulimit -v``) must hold.
    """
    pairs = (modes + 1) ** 2 if dimension == 2 else modes + 1
    memory = BASE_MEMORY + FE_BYTES_PER_DOF * dofs
    seconds = FE_SECONDS_PER_DOF * dofs
    address = 0.0
    if dimension == 2:
        address = BASE_ADDRESS + FE_ADDRESS_PER_DOF.get(int(order), FE_ADDRESS_PER_DOF[4]) * dofs
    if route == "full":
        memory += 8.0 * dofs * pairs
        seconds += FULL_ROUTE_SECONDS * dofs * pairs
        address += 8.0 * dofs * pairs if address else 0.0
    return Estimate(memory, seconds, address)


def alpha_estimate(dofs: int, pairs: int, t_end: float, dt: float) -> Estimate:
    """Generalized-alpha stepping of ``t_end / dt`` steps on ``dofs`` (dimensionless times).

    Per step ``0.3 ms + 1 us x DOFs + 5 ns x DOFs x pairs`` (the low-rank modal
    damping of ``pairs`` modes); 160 bytes per step for the pole history and its
    splines.
    """
    steps = math.ceil(t_end / dt)
    per_step = STEP_SECONDS + STEP_SECONDS_PER_DOF * dofs + STEP_SECONDS_PER_DOF_MODE * dofs * pairs
    return Estimate(BASE_MEMORY + STEP_BYTES * steps + 8.0 * dofs * pairs, steps * per_step)


def fem_work(
    mesh: Any,
    level: int | None,
    elements: int | None,
    order: int | None,
    modes: int,
    route: str,
    *,
    scheme: str = "modal",
    dt: float | None = None,
    t_end: float = 4.0 * math.pi,
    step_accuracy: float = 0.2,
    time_unit_s: float | None = None,
) -> list[tuple[str, Estimate]]:
    """A finite-element run: mesh and eigen solve, then for ``alpha`` the stepping too.

    Each stage is named by the options that set its size (``level 9 order 2``,
    ``dt 1e-09``) with its estimate, the stepping's including the eigen solve
    before it; the edge refuses the run if a stage cannot fit
    (:func:`twoball._costs.check_fem`).  ``mesh`` a kind name or a
    :class:`~twoball.fem_membrane.mesh.SphereMesh`.  ``dt`` and ``t_end`` are
    dimensionless; ``time_unit_s`` (1/c in seconds) only turns dt back into
    seconds, as the user gave it, for the name.
    """
    dofs = fem_dofs(mesh, level, elements, order)
    dimension = 1 if mesh == "axisym" else 2
    if route == "auto":
        route = "krylov" if dofs >= 2000 else "full"
    if scheme == "alpha":
        route = "full"
    size = options(level=level, elements=elements, order=order) or "the finite-element mesh"
    fe_order = order if order is not None else getattr(mesh, "order", 2)
    estimate = fem_estimate(dofs, modes, route, dimension, fe_order)
    if scheme != "alpha":
        return [(size, estimate)]
    omega_cut = 0.5 * (legendre_omega(modes) + legendre_omega(modes + 1))
    step = dt if dt is not None else step_accuracy / omega_cut
    pairs = (modes + 1) ** 2 if dimension == 2 else modes + 1
    if dt is None:
        option = "scheme alpha"
    elif time_unit_s is None:
        option = f"dt (dt c = {dt:.3g})"
    else:
        option = options(dt=dt * time_unit_s)
    return [(size, estimate), (option, estimate + alpha_estimate(dofs, pairs, t_end, step))]


def fem_contact_work(
    case: Any, body: Any, mesh: Any = None, t_end_s: float | None = None
) -> list[tuple[str, Estimate]]:
    """The work of :func:`twoball.fem_membrane.contact.fem_contact_solution`, with its costs.

    The mesh and the full eigen route, the contact solver on every mode below the
    cutoff (at most ``(N + 1)^2`` on a sphere, ``N + 1`` on the line, up to
    ``omega_{N+1}``: an upper bound of the modes it finds), and the closed-form
    reference of its truncation block
    (:func:`twoball.modal.contact.cost.legendre_contact_work`).  The options of
    ``body``, ``mesh`` and the window ``t_end_s`` [s] are checked first, as the
    solve checks them.
    """
    from twoball._common.errors import ParameterError
    from twoball.fem_membrane.options import MeshOptions
    from twoball.modal.contact.cost import legendre_contact_work, solve_work
    from twoball.modal.contact.report import check_contact_options
    from twoball.modal.report import t_end_dimensionless

    check_contact_options(case, body)
    spec = MeshOptions.of(mesh).require(files=False)
    if spec.geometry != "isoparametric":
        raise ParameterError("geometry", "isoparametric with a body of finite mass", spec.geometry)
    work = fem_work(spec.kind, spec.level, spec.elements, spec.order, case.modes, "full")
    t_end = t_end_dimensionless(case, t_end_s)
    dofs = fem_dofs(spec.kind, spec.level, spec.elements, spec.order)
    pairs = case.modes + 1 if spec.kind == "axisym" else (case.modes + 1) ** 2
    top = legendre_omega(case.modes + 1)  # the cutoff lies between N and N + 1
    work.append(solve_work(case.modes, min(dofs, pairs), top, t_end, body.mass_ratio))
    return work + legendre_contact_work(case, body, t_end_s)[1:]
