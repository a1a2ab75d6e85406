"""Finite-element runs of the studies: the discretisation, one modal run, and what it yields.

A :class:`FEMSpec` names a mesh (icosphere or the axisymmetric line), an element
order and a size; :func:`fem_run` assembles it with scikit-fem (through
:func:`twoball.fem_membrane.solve.modal_model`), builds the filtered modal
series and finds lift-off.  Dimensionless (length R, time 1/c).
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.budget import check_all
from twoball._common.watch import Watch
from twoball.modal.filters import FilterKind, SpectralFilter
from twoball.modal.liftoff import Horizon, find_liftoff
from twoball.modal.parameters import Case
from twoball.modal.series import ModalSeries
from twoball.verify.studies.reference import LegendreRun
from twoball.verify.studies.result import Progress, si

MESH_LABELS = {"sphere": "icosphere", "axisym": "axisym"}
# level 0 of the icosphere resolves no complete degree l >= 1 (nothing to compare)
LEVEL_LIMITS: dict[str, tuple[int, int]] = {"sphere": (1, 6), "axisym": (0, 8)}
# Levels (A:B) each finite-element study runs by default, per (study, mesh, order).
DEFAULT_LEVELS: dict[tuple[str, str, int], str] = {
    ("h", "sphere", 1): "2:5",
    ("h", "sphere", 2): "1:4",
    ("h", "axisym", 1): "1:5",
    ("h", "axisym", 2): "1:5",
    ("h", "sphere", 3): "1:3",
    ("h", "sphere", 4): "1:3",
    ("h", "axisym", 3): "0:3",
    ("h", "axisym", 4): "0:2",
    ("order", "sphere", 1): "1:3",
    ("order", "sphere", 2): "1:3",
    ("order", "axisym", 1): "1:4",
    ("order", "axisym", 2): "1:4",
    ("order", "sphere", 3): "1:3",
    ("order", "sphere", 4): "1:3",
    ("order", "axisym", 3): "1:4",
    ("order", "axisym", 4): "1:4",
    ("dt", "sphere", 1): "1:4",
    ("dt", "sphere", 2): "1:4",
    ("dt", "axisym", 1): "1:4",
    ("dt", "axisym", 2): "1:4",
    ("dt", "sphere", 3): "1:4",
    ("dt", "sphere", 4): "1:4",
    ("dt", "axisym", 3): "1:4",
    ("dt", "axisym", 4): "1:4",
}
AXISYM_BASE_ELEMENTS = 25  # axisym "level" k has 25 * 2**k elements
EIGEN_DEGREES = tuple(range(1, 7))  # l = 1..6 in every eigenvalue check


@dataclass(frozen=True)
class FEMSpec:
    """One finite-element discretisation.

    Attributes
    ----------
    mesh : {"sphere", "axisym"}
        Icosphere or the axisymmetric line x = cos(phi).
    order : {1, 2, 3, 4}
        Element (and, on the isoparametric sphere, geometry) order.
    size : int
        Icosphere level, or number of axisymmetric elements.
    geometry : {"isoparametric", "exact"}
        Discrete sphere (the line is exact either way).
    """

    mesh: str
    order: int
    size: int
    geometry: str = "isoparametric"

    @property
    def label(self) -> str:
        """Short description: ``sphere P1 L4``, ``sphere P4 L2 exact``, ``axisym P2 400 el.``."""
        if self.mesh == "axisym":
            return f"axisym P{self.order} {self.size} el."
        exact = " exact" if self.geometry == "exact" else ""
        return f"sphere P{self.order} L{self.size}{exact}"

    @property
    def step(self) -> float:
        """Mesh size h: ``sqrt(4 pi / triangles)`` on the icosphere, ``pi / elements`` on the line.

        Both are lengths on the unit sphere (dimensionless); refinement halves them.
        """
        if self.mesh == "axisym":
            return math.pi / self.size
        return math.sqrt(4.0 * math.pi / (20 * 4**self.size))

    @property
    def dimension(self) -> int:
        """Topological dimension (DOFs ~ h^-dimension)."""
        return 1 if self.mesh == "axisym" else 2

    def options(self) -> dict[str, Any]:
        """Keyword arguments of :func:`twoball.fem_membrane.solve.modal_model`."""
        if self.mesh == "axisym":
            return {"mesh": "axisym", "elements": self.size, "order": self.order}
        options = {"mesh": "sphere", "level": self.size, "order": self.order}
        if self.geometry != "isoparametric":
            options["geometry"] = self.geometry
        return options


def spec_from_level(mesh: str, order: int, level: int, geometry: str = "isoparametric") -> FEMSpec:
    """The discretisation of refinement level ``level`` (axisym: 25 * 2**level elements)."""
    if mesh == "axisym":
        return FEMSpec("axisym", order, AXISYM_BASE_ELEMENTS * 2**level)
    return FEMSpec("sphere", order, level, geometry)


@dataclass
class FEMRun:
    """A finite-element modal model of one case with its lift-off (dimensionless).

    ``model`` is :class:`twoball.fem_membrane.solve.ModalModel` (space, eigenpairs,
    initial moments, modal series).
    """

    spec: FEMSpec
    model: Any
    t: float | None
    velocity: float | None
    energy_end: float
    seconds: float

    @property
    def dofs(self) -> int:
        """Degrees of freedom."""
        return int(self.model.space.dofs)

    @property
    def series(self) -> ModalSeries:
        """The modal series (eq. (3.16) on the finite-element eigenpairs)."""
        return self.model.series


def fem_run(
    case: Case,
    spec: FEMSpec,
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
    route: str = "full",
) -> FEMRun:
    """Assemble, build the filtered modal series, and find lift-off.

    Uses :func:`twoball.fem_membrane.solve.modal_model`, the same path as
    ``fem_pole_motion(..., scheme="modal")``, and keeps the model for the
    eigenvalue and energy checks (``route="full"``; the Krylov route has no
    eigenvector set and serves lift-off checks only).
    """
    from twoball.fem_membrane.cost import fem_work
    from twoball.fem_membrane.solve import modal_model

    options = spec.options()
    check_all(
        fem_work(
            options["mesh"],
            options.get("level"),
            options.get("elements"),
            options["order"],
            case.modes,
            route,
        )
    )
    start = time.perf_counter()
    model = modal_model(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        route=route,
        monitor=Watch(),
        **spec.options(),
    )
    result = find_liftoff(model.series, case.gamma, t_end=t_end, horizon=recontact)
    energy = float(model.series.energy(np.array([t_end]))[0])
    return FEMRun(spec, model, result.t, result.velocity, energy, time.perf_counter() - start)


def cluster_means(values: np.ndarray, mesh: str, degrees: Sequence[int]) -> np.ndarray:
    """Mean of the discrete eigenvalues of each degree l (2l + 1 on the sphere, 1 on the line)."""
    values = np.sort(np.asarray(values, dtype=float))
    if mesh == "axisym":
        return np.array([values[deg] for deg in degrees])
    return np.array([values[deg * deg : (deg + 1) ** 2].mean() for deg in degrees])


def cluster_errors(values: np.ndarray, mesh: str, degrees: Sequence[int]) -> np.ndarray:
    """Largest relative error ``|lambda_h - l(l+1)| / l(l+1)`` within each degree's cluster."""
    values = np.sort(np.asarray(values, dtype=float))
    out = []
    for deg in degrees:
        exact = deg * (deg + 1.0)
        block = values[deg : deg + 1] if mesh == "axisym" else values[deg * deg : (deg + 1) ** 2]
        out.append(float(np.abs(block - exact).max() / exact))
    return np.array(out)


def projection_energy(model: Any) -> float:
    """``1/2 u0^T K u0`` of the Galerkin projection u0 of F (unit T R^2; eq. (3.5) discrete)."""
    return projected_strain_energy(model.space, model.moments)


def projected_strain_energy(space: Any, load: np.ndarray) -> float:
    """``1/2 u0^T K u0`` with ``M u0 = load`` (unit T R^2; eq. (3.5) discrete).

    ``space`` is a :class:`twoball.fem_membrane.space.Discretisation` (``mass``,
    ``stiffness``); ``load`` holds the moments of F on its basis.
    """
    from scipy.sparse.linalg import splu

    u0 = splu(space.mass.tocsc()).solve(load)
    return 0.5 * float(u0 @ (space.stiffness @ u0))


def fem_sequence(
    case: Case,
    specs: Sequence[FEMSpec],
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
    progress: Progress,
) -> list[FEMRun]:
    """One :func:`fem_run` per discretisation, in order, announced to ``progress``."""
    runs = []
    for spec in specs:
        progress(f"{spec.label}: assembly and eigenpairs")
        runs.append(fem_run(case, spec, sigma, recontact, t_end))
    return runs


def fem_row(case: Case, run: FEMRun, reference: LegendreRun) -> dict[str, Any]:
    """One run-table row of a finite-element run (SI), with its differences to ``reference``."""
    scale = case.scalings
    row: dict[str, Any] = {
        "label": run.spec.label,
        "backend": "fem",
        "dofs": run.dofs,
        "h": run.spec.step,
        "modes_computed": len(run.model.pairs),
        "t_liftoff_s": si(run.t, scale.time),
        "v_liftoff_m_s": si(run.velocity, scale.velocity),
        "energy_end": run.energy_end,
        "seconds": run.seconds,
    }
    if run.t is not None and reference.t is not None and reference.velocity is not None:
        row["t_rel_diff"] = (run.t - reference.t) / reference.t
        row["v_rel_diff"] = (run.velocity - reference.velocity) / reference.velocity
    return row
