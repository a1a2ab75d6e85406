"""What ``twoball verify`` runs and the tolerance of each check: :func:`config`.

Meshes and bounds are dimensionless; every tolerance is relative.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball.modal.converged import REFERENCE_TOLERANCE
from twoball.verify.studies.fem_runs import FEMSpec
from twoball.verify.studies.orders import OrderBand


@dataclass(frozen=True)
class FEMTarget:
    """A finite-element run of ``verify`` and its tolerances (relative).

    Attributes
    ----------
    spec : FEMSpec
    liftoff : float
        Bound on ``max(|dt_l|/t_l, |dv_l|/v_l)`` against the Legendre series
        with the same N and filter.
    eigen : float
        Bound on the largest relative eigenvalue error for l = 1..6.
    energy : float
        Bound on ``|1/2 u0^T K u0 - (-W)| / (-W)`` (eq. (3.5)).
    """

    spec: FEMSpec
    liftoff: float
    eigen: float
    energy: float


@dataclass(frozen=True)
class AlphaTarget:
    """The direct time-stepping check: generalized-alpha against modal superposition.

    Attributes
    ----------
    spec : FEMSpec
        Mesh of both runs.
    dt : float
        Time step (dimensionless, unit 1/c).
    liftoff : float
        Bound on ``max(|dt_l|/t_l, |dv_l|/v_l)`` between the two time schemes (the
        stepped samples as the backend interpolates them: per-field cubic splines).
    trajectory : float
        Bound on ``||u_alpha - u_modal||_L2 / ||u_modal||`` of the pole over [0, t_end].
    energy : float
        Bound on ``max_t |E_alpha(t) - E_modal(t)| / E_modal(0)`` (total energy).
    modal_energy : float
        Bound on ``max_{k,t} |E_k,alpha(t) - E_k,modal(t)| / E_modal(0)`` (every mode).
    bound : float
        Allowed excess of a stepped mode's energy over the band
        ``E_k(0) exp(-2 D omega_k t) [1/(1+D), 1/(1-D)]`` (relative), for modes with
        at least 1e-6 of the initial energy while they keep 1e-6 of their own.  The
        stepping error of a mode grows like omega^3 dt^2 t, so this bound is loose.
    """

    spec: FEMSpec
    dt: float
    liftoff: float
    trajectory: float
    energy: float
    modal_energy: float
    bound: float


@dataclass(frozen=True)
class VerifyConfig:
    """Which runs ``verify`` makes, with their tolerances."""

    name: str
    fem: tuple[FEMTarget, ...]
    alpha: tuple[AlphaTarget, ...]
    energy_pair: tuple[FEMSpec, FEMSpec] | None = None
    energy_band: OrderBand | None = None
    reference_tolerance: float = REFERENCE_TOLERANCE
    krylov: tuple[FEMTarget, ...] = ()
    """Meshes solved by the fast rational Krylov route: lift-off only."""


# Tolerances: lift-off (axisym P2 400 el. 1e-6; sphere P2 level 3 1e-3,
# level 4 1e-4; sphere P1 level 4 2 %); eigenvalue and energy bounds about twice the errors
# the convergence studies measure on these meshes (eigenvalues: orders 2 and 4 for P1 and
# P2).  The energy of the projected F converges slowly on the icosphere (order ~1: the kink
# of F at phi_a cuts through the triangles; P2 oscillates more than P1 there), fast on the
# axisymmetric line, which has a node at the kink (order P + 1).
DEFAULT_FEM: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("axisym", 2, 400), liftoff=1e-6, eigen=2e-8, energy=3e-7),
    FEMTarget(FEMSpec("sphere", 1, 4), liftoff=2e-2, eigen=3e-2, energy=2e-2),
    FEMTarget(FEMSpec("sphere", 2, 3), liftoff=1e-3, eigen=1.5e-3, energy=6e-2),
)
THOROUGH_EXTRA: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("axisym", 2, 800), liftoff=1e-7, eigen=2e-9, energy=4e-8),
    FEMTarget(FEMSpec("sphere", 1, 5), liftoff=5e-3, eigen=8e-3, energy=1.5e-2),
    FEMTarget(FEMSpec("sphere", 2, 4), liftoff=1e-4, eigen=1e-4, energy=3e-2),
    # P3 and P4, measured: axisym P3 200 el. 6.6e-12 | 6.3e-12 | 1.6e-9, P4 100 el.
    # 1.3e-13 | 2.0e-13 | 1.4e-10 (round-off for lift-off and eigenvalues); sphere P3 L2
    # 8.4e-4 | 2.3e-4 | 5.5e-2, P4 L2 1.2e-5 | 4.5e-6 | 3.2e-2 (lift-off | eigen | energy)
    FEMTarget(FEMSpec("axisym", 3, 200), liftoff=2e-11, eigen=2e-11, energy=4e-9),
    FEMTarget(FEMSpec("axisym", 4, 100), liftoff=1e-12, eigen=1e-12, energy=4e-10),
    FEMTarget(FEMSpec("sphere", 3, 2), liftoff=2e-3, eigen=5e-4, energy=0.1),
    FEMTarget(FEMSpec("sphere", 4, 2), liftoff=3e-5, eigen=1e-5, energy=6e-2),
)
# The fast route on the finest meshes: lift-off against Legendre N = 30 (the P2 sphere's
# ladder above, 1e-3 at level 3 and 1e-4 at level 4, continued to 1e-5 at level 5) and,
# where the full route ran too, route agreement.
THOROUGH_KRYLOV: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("sphere", 2, 4), liftoff=1e-4, eigen=0.0, energy=0.0),
    FEMTarget(FEMSpec("sphere", 2, 5), liftoff=1e-5, eigen=0.0, energy=0.0),
    # P4 on level 3, isoparametric and exact sphere: measured 2.0e-7 and 1.9e-7 (v_l)
    FEMTarget(FEMSpec("sphere", 4, 3), liftoff=5e-7, eigen=0.0, energy=0.0),
    FEMTarget(FEMSpec("sphere", 4, 3, "exact"), liftoff=5e-7, eigen=0.0, energy=0.0),
)
ROUTE_AGREEMENT = 1e-6  # Krylov against the full eigen route, relative in t_l and v_l
DEFAULT_ALPHA = AlphaTarget(
    FEMSpec("axisym", 2, 100), dt=0.0025, liftoff=1e-4, trajectory=2e-4, energy=1e-4,
    modal_energy=5e-5, bound=4e-2,
)  # fmt: skip
THOROUGH_ALPHA = AlphaTarget(
    FEMSpec("sphere", 1, 3), dt=0.0025, liftoff=1e-4, trajectory=2e-4, energy=1e-4,
    modal_energy=5e-5, bound=4e-2,
)  # fmt: skip
ENERGY_BAND = OrderBand(3.0, 0.4, 0.4)  # P2 L2 projection, kink at a node: order P + 1


def config(name: str = "default") -> VerifyConfig:
    """The named configuration: ``default`` (< 60 s), ``thorough`` or ``fast`` (tests only)."""
    pair = (FEMSpec("axisym", 2, 100), FEMSpec("axisym", 2, 400))
    if name == "default":
        return VerifyConfig("default", DEFAULT_FEM, (DEFAULT_ALPHA,), pair, ENERGY_BAND)
    if name == "thorough":
        return VerifyConfig(
            "thorough",
            DEFAULT_FEM + THOROUGH_EXTRA,
            (DEFAULT_ALPHA, THOROUGH_ALPHA),
            pair,
            ENERGY_BAND,
            krylov=THOROUGH_KRYLOV,
        )
    if name == "fast":  # coarse meshes with loose bounds: exercises every code path in seconds
        fem = (
            FEMTarget(FEMSpec("axisym", 2, 100), liftoff=1e-5, eigen=4e-6, energy=2e-5),
            FEMTarget(FEMSpec("sphere", 1, 3), liftoff=0.1, eigen=0.15, energy=0.2),
        )
        alpha = AlphaTarget(
            FEMSpec("axisym", 1, 50), dt=0.005, liftoff=1e-3, trajectory=1e-3, energy=1e-3,
            modal_energy=2e-4, bound=0.15,
        )  # fmt: skip
        pair = (FEMSpec("axisym", 2, 100), FEMSpec("axisym", 2, 200))
        return VerifyConfig("fast", fem, (alpha,), pair, ENERGY_BAND)
    raise ValueError(f"unknown verify configuration {name!r}")
