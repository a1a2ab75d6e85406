"""The elastic ball on (r, z) finite elements as a lower ball: the solid and the thick wall.

:class:`FESolidBall` is the finite-element implementation of the solid ball beside
the closed form of :class:`~twoball.modal.balls.solid.SolidBall`: the same physics
(a :class:`~twoball.modal.balls.solid.SolidMaterial`, the case's radius and damping
law, ``c`` mapped as ``omega^2 / c^2 = eta^2 (c_s / (R c))^2``), another
discretisation: axisymmetric (m = 0) linear elasticity on the meridian half disc in
isoparametric P2 (:mod:`twoball.fem_solid.forms`, eqs. (A2)-(A3)), refined towards
the south pole where the floor's Hertz-like contact needs it.

:class:`ThickBall` is the same elasticity on the half annulus ``R - h <= r <= R``:
a hollow ball of wall thickness h without thin-shell assumptions (the tennis ball's
rubber wall), with the enclosed gas (its pressure change ``-kappa P_abs dV / V``
on the inner surface, a rank-one stiffness ``kappa P_abs / V (dV)^2``, eq. (T1)).
The inflation's prestress (the wall's initial hoop tension ``~ P R / 2`` and the
follower pressure on the inner surface, the thin membrane's ``(n - 1)(n + 2)``
operator) is **not** in this model: its linearisation about the inflated state
(the geometric stiffness of the initial stress and the load stiffness of the
pressure on the deforming inner surface) is not derived here.  For the tennis
ball it is a share ``p = N0 / C ~ 0.05`` of the wall's in-plane stiffness
(:class:`~twoball.modal.balls.shell.Wall`).

Coordinates: every eigenpair of the finite-element space (a dense generalized
eigenproblem: a change of coordinates exact to rounding, the contact core
integrates the finite-element equations), M-orthonormal in units of the ball's
mass; the rigid translation ``u_z = 1`` is set exactly (the drop's centre).  The
floor points are the P2 nodes of the outer arc with ``phi > pi / 2`` (vertices and
mid-edge nodes); their rows are the nodal ``u_z`` of every eigenvector.  Surface
fields between the nodes (pictures, the body's cap) are the quadratic
interpolation in ``phi`` through each arc facet's three nodes.  No numerical
library is imported until a ball is described.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.errors import NumericalError, ParameterError, check_labels, real_number
from twoball._common.keywords import checked
from twoball.modal.balls.solid import SolidMaterial, check_material, material_of

if TYPE_CHECKING:
    from skfem.mesh import MeshTri2

    from twoball.modal.balls.description import ModalBall
    from twoball.modal.parameters import Case

__all__ = [
    "DEFAULT_SOLID_LEVEL",
    "FESolidBall",
    "SolidSpace",
    "ThickBall",
    "ThickWall",
    "pole_refined_disc",
    "solid_space",
]

#: Uniform refinements of the half disc by default: 256 triangles, arc nodes pi / 64 apart.
DEFAULT_SOLID_LEVEL = 3
#: Levels the half disc takes.
SOLID_LEVEL_RANGE = (1, 6)
#: Extra refinements towards the south pole a ball takes.
POLE_LEVEL_RANGE = (0, 8)
#: Cells of the thick wall: across it, and along the half circle.
DEFAULT_THICK_CELLS = (2, 96)


def pole_refined_disc(
    level: int, pole_levels: int = 0, pole_angle: float = 0.6, top_levels: int = 0
) -> MeshTri2:
    """The half disc of :func:`~twoball.fem_solid.mesh.half_disc` refined towards the poles.

    ``level`` uniform refinements, then ``pole_levels`` refinements of the
    triangles within the distance ``pole_angle 2^-j`` (units R) of the south pole
    at the j-th (each halves the size there; red-green closure keeps the mesh
    conforming), and ``top_levels`` of those near the north pole (a body's cap),
    every new arc vertex moved onto the circle; P2 geometry.
    """
    from skfem import MeshTri1, MeshTri2

    from twoball.fem_solid.mesh import _project_arc, _quadratic_on_circle

    angles = np.linspace(0.0, math.pi, 5)
    arc = np.vstack([np.sin(angles), -np.cos(angles)])
    arc[0, [0, -1]] = 0.0
    p = np.hstack([np.zeros((2, 1)), arc])
    t = np.array([[0, i, i + 1] for i in range(1, 5)]).T
    mesh = MeshTri1(p, t)
    for _ in range(int(level)):
        mesh = _project_arc(mesh.refined())
    for pole, levels in ((-1.0, pole_levels), (1.0, top_levels)):
        for j in range(int(levels)):
            centres = mesh.p[:, mesh.t].mean(axis=1)
            near = np.hypot(centres[0], centres[1] - pole) < pole_angle * 2.0**-j
            if not near.any():
                break
            mesh = _project_arc(mesh.refined(np.flatnonzero(near)))
    return _quadratic_on_circle(MeshTri2.from_mesh(mesh), outer=1.0)


@dataclass(frozen=True, eq=False)
class SolidSpace:
    """Every eigenpair of an (r, z) elastic ball's P2 space, with its outer arc (R = 1).

    Attributes
    ----------
    eta_squared : ndarray, shape (K,)
        ``(omega R / c_s)^2`` (0 on the translation).
    vectors : ndarray, shape (dofs, K)
        M-orthonormal in units of the ball's mass (``x^T M x`` = the volume).
    translation : int
    arc_phi : ndarray
        Polar angles of the outer arc's P2 nodes, ascending from 0 to pi.
    arc_r, arc_z : ndarray, shape (len(arc_phi), K)
        Nodal ``u_r`` and ``u_z`` (cylindrical) there.
    basis : skfem Basis
        The vector P2 basis of ``vectors``.
    volume : float
        The mesh's volume (``4 pi / 3`` for the unit ball).
    """

    eta_squared: np.ndarray
    vectors: np.ndarray
    translation: int
    arc_phi: np.ndarray
    arc_r: np.ndarray
    arc_z: np.ndarray
    basis: Any = field(repr=False)
    volume: float = 0.0

    @property
    def size(self) -> int:
        """Number of eigenpairs K."""
        return int(self.eta_squared.size)

    def _interpolate(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Quadratic interpolation matrix in phi through each arc facet's three nodes."""
        phi = np.clip(np.asarray(phi, dtype=float).reshape(-1), 0.0, math.pi)
        nodes = self.arc_phi
        facets = (nodes.size - 1) // 2
        j = np.clip(np.searchsorted(nodes[::2], phi, side="right") - 1, 0, facets - 1)
        a, m, b = nodes[2 * j], nodes[2 * j + 1], nodes[2 * j + 2]
        la = (phi - m) * (phi - b) / ((a - m) * (a - b))
        lm = (phi - a) * (phi - b) / ((m - a) * (m - b))
        lb = (phi - a) * (phi - m) / ((b - a) * (b - m))
        return np.column_stack([2 * j, 2 * j + 1, 2 * j + 2]), np.column_stack([la, lm, lb])

    def surface(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(u_r, u_theta, u_z)`` (spherical radial, meridional, vertical) at ``phi``, (n, K)."""
        phi = np.asarray(phi, dtype=float).reshape(-1)
        index, weight = self._interpolate(phi)
        ur = np.einsum("pj,pjk->pk", weight, self.arc_r[index])
        uz = np.einsum("pj,pjk->pk", weight, self.arc_z[index])
        s, c = np.sin(phi)[:, None], np.cos(phi)[:, None]
        return ur * s + uz * c, ur * c - uz * s, uz

    def cap_average(self, theta: float) -> np.ndarray:
        """``u_z`` averaged over the cap ``phi <= theta`` (area weight ``sin(phi)``)."""
        if theta == 0.0:
            return self.surface(np.array([0.0]))[2][0]
        nodes = self.arc_phi[::2]
        edges = np.concatenate([nodes[nodes < theta], [theta]])
        x, w = np.polynomial.legendre.leggauss(6)
        a, b = edges[:-1, None], edges[1:, None]
        phi = (0.5 * (b - a) * x + 0.5 * (b + a)).ravel()
        weight = (0.5 * (b - a) * w).ravel() * np.sin(phi)
        uz = self.surface(phi)[2]
        return (weight @ uz) / (1.0 - math.cos(theta))


def _arc_nodes(basis: Any, outer: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Scalar P2 node indices of the circle of radius ``outer``, sorted by polar angle, and the
    vector dofs of u_r and u_z at them."""
    r_dofs, z_dofs = basis.split_indices()
    x = basis.doflocs[:, r_dofs]
    radius = np.hypot(x[0], x[1])
    on = np.flatnonzero(np.abs(radius - outer) < 1e-9)
    phi = np.arctan2(x[0, on], x[1, on])
    order = np.argsort(phi)
    on = on[order]
    return phi[order], r_dofs[on], z_dofs[on]


def solid_space(
    mesh: MeshTri2, poisson: float, *, gas: float = 0.0, inner: float | None = None
) -> SolidSpace:
    """Every eigenpair of eqs. (A2)-(A3) on ``mesh`` (mu = rho = R = 1), the translation exact.

    ``gas``: ``kappa P_abs / (mu V_gas)`` of an enclosed gas on the inner circle of
    radius ``inner`` (the thick wall's eq. (T1)), 0 for none.
    """
    import scipy.linalg as sla
    from skfem import Basis, ElementTriP2, ElementVector, FacetBasis, LinearForm, asm

    from twoball.fem_solid.eigen import _volume
    from twoball.fem_solid.forms import axisymmetric_elasticity, axisymmetric_mass, lame

    basis = Basis(mesh, ElementVector(ElementTriP2()), intorder=6)
    lam, mu = lame(poisson)
    k = asm(axisymmetric_elasticity(lam, mu), basis).toarray()
    m = asm(axisymmetric_mass(1.0), basis).toarray()
    if gas > 0.0 and inner is not None:
        ends = np.hypot(*mesh.p[:, mesh.facets])  # both vertices of a facet on the circle
        facets = np.flatnonzero(np.all(np.abs(ends - inner) < 1e-9, axis=0))
        fb = FacetBasis(mesh, basis.elem, facets=facets, intorder=6)

        @LinearForm
        def change(v, w):  # dV = int u . e_r 2 pi r ds on the inner circle (eq. T1)
            rr = np.hypot(w.x[0], w.x[1])
            return (v[0] * w.x[0] + v[1] * w.x[1]) / rr * 2.0 * math.pi * w.x[0]

        g = asm(change, fb)
        k = k + gas * np.outer(g, g)
    axis = basis.get_dofs(lambda x: np.abs(x[0]) < 1e-12).all("u^1")
    free = np.setdiff1d(np.arange(basis.N), axis)
    volume = _volume(basis)
    values, reduced = sla.eigh(k[np.ix_(free, free)], m[np.ix_(free, free)])
    vectors = np.zeros((basis.N, values.size))
    vectors[free] = reduced * math.sqrt(volume)
    # the translation u_z = 1 exactly (the eigensolver's is exact to rounding only)
    t = int(np.argmin(np.abs(values)))
    if abs(values[t]) > 1e-8 * max(1.0, float(values[-1])) and abs(values[t]) > 1e-6:
        raise NumericalError(f"solid_space: no rigid translation (lowest {values[t]:.3g})")
    _, z_dofs = basis.split_indices()
    unit = np.zeros(basis.N)
    unit[z_dofs] = 1.0
    share = (unit @ (m @ vectors)) / volume
    vectors -= np.outer(unit, share)
    vectors[:, t] = unit
    values = values.copy()
    values[t] = 0.0
    phi, r_at, z_at = _arc_nodes(basis)
    return SolidSpace(
        values, vectors, t, phi, vectors[r_at], vectors[z_at], basis=basis, volume=volume
    )


def space_description(
    space: SolidSpace, ratio: float, law: Any, label: str, *, gas_share: np.ndarray | None = None
) -> ModalBall:
    """The :class:`ModalBall` of a :class:`SolidSpace` (units R, 1/c with ``c_s / (R c) =
    ratio``, the ball's mass); floor points at the arc nodes with ``phi > pi / 2``."""
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.balls.membrane import mode_decay

    t = space.translation
    k = space.size
    w2 = np.maximum(space.eta_squared, 0.0) * ratio**2
    w2[t] = 0.0
    decay = np.asarray(mode_decay(law, w2), dtype=float).copy()
    decay[t] = 0.0
    lower = space.arc_phi > 0.5 * math.pi
    phi = space.arc_phi[lower]
    rows = space.arc_z[lower].copy()
    rows[:, t] = 1.0
    top = space.arc_z[0].copy()
    top[t] = 1.0

    def sample(index: int):
        def sampler(angles: np.ndarray) -> np.ndarray:
            out = space.surface(np.asarray(angles, dtype=float))[index].copy()
            out[:, t] = 0.0
            return out

        return sampler

    def averager(theta: float) -> np.ndarray:
        out = space.cap_average(theta).copy()
        out[t] = 1.0
        return out

    gas2 = np.zeros(k) if gas_share is None else gas_share * ratio**2
    ball = ModalBall(
        masses=np.ones(k),
        omega_squared=w2,
        gas_squared=gas2,
        decay=decay,
        centre=t,
        phi=phi,
        floor_rows=rows,
        top=top,
        label=label,
        bending=True,
        sampler=sample(0),
        tangential=sample(1),
        averager=averager,
    )
    from twoball.modal.balls.solid import register_cut

    register_cut(ball, lambda: fe_cut(space))
    return ball


def fe_cut(space: SolidSpace) -> Any:
    """The nodal vectors at the mesh's vertices, on its triangles
    (:class:`~twoball.modal.balls.solid.CutGrid`)."""
    from twoball.modal.balls.solid import CutGrid

    mesh = space.basis.mesh
    r_dofs, z_dofs = space.basis.split_indices()
    vertices = np.arange(mesh.nvertices)  # P2 nodes: the vertices first
    radial = space.vectors[r_dofs[vertices]].copy()
    axial = space.vectors[z_dofs[vertices]].copy()
    radial[:, space.translation] = 0.0
    axial[:, space.translation] = 0.0
    return CutGrid(mesh.p[:, : mesh.nvertices].T.copy(), mesh.t.T.copy(), radial, axial)


def _check_int(name: str, value: object, bounds: tuple[int, int]) -> int:
    low, high = bounds
    if (
        isinstance(value, bool)
        or not isinstance(value, int | np.integer)
        or not (low <= int(value) <= high)
    ):
        raise ParameterError(name, f"an integer in [{low}, {high}]", value)
    return int(value)


@checked
@dataclass(frozen=True)
class FESolidBall:
    """The elastic sphere on (r, z) P2 finite elements: a lower ball for the drop.

    Parameters
    ----------
    material : SolidMaterial, optional
        The material (default: the case's preset's,
        :data:`~twoball.modal.balls.solid.MATERIALS`).
    level : int
        Uniform refinements of the half disc in [1, 6] (default 3: 256 triangles,
        the arc's P2 nodes ``pi / 64`` apart).
    pole_levels : int
        Further refinements towards the south pole in [0, 8] (default 0), each
        halving the size within ``0.6 / 2^j`` R of it: the floor's contact radius
        needs several arc nodes (:func:`pole_refined_disc`).
    order : int
        The element order: 2 (P2, isoparametric) only.
    top_levels : int
        Refinements towards the north pole in [0, 8] (default 0): a body's cap.

    Examples
    --------
    >>> import twoball
    >>> twoball.FESolidBall(level=2).label
    'solid axisym level 2 P2'
    >>> twoball.FESolidBall(order=1)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: order must be 2 (isoparametric P2), got 1
    """

    material: SolidMaterial | None = None
    level: int = DEFAULT_SOLID_LEVEL
    pole_levels: int = 0
    order: int = 2
    top_levels: int = 0

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "solid"
    backend = "fem"
    #: Its build solves a dense eigenproblem (for the cost estimate).
    dense = True
    #: No excess pressure and no enclosed gas.
    pressurised = False

    def __post_init__(self) -> None:
        check_material(self.material)
        object.__setattr__(self, "level", _check_int("level", self.level, SOLID_LEVEL_RANGE))
        pole = _check_int("pole_levels", self.pole_levels, POLE_LEVEL_RANGE)
        object.__setattr__(self, "pole_levels", pole)
        top = _check_int("top_levels", self.top_levels, POLE_LEVEL_RANGE)
        object.__setattr__(self, "top_levels", top)
        if isinstance(self.order, bool) or self.order != 2:
            raise ParameterError("order", "2 (isoparametric P2)", self.order)

    @property
    def label(self) -> str:
        """``solid axisym level 3 P2`` (``+ 2 pole`` with pole refinements)."""
        pole = f" + {self.pole_levels} pole" if self.pole_levels else ""
        top = f" + {self.top_levels} top" if self.top_levels else ""
        return f"solid axisym level {self.level}{pole}{top} P2"

    def mesh(self) -> MeshTri2:
        """The half disc of this ball (:func:`pole_refined_disc`)."""
        return pole_refined_disc(self.level, self.pole_levels, top_levels=self.top_levels)

    def size(self, case: Case | None = None) -> tuple[int, int] | None:
        """Coordinates and floor points: known once the mesh is built (None before)."""
        return None

    def material_of(self, case: Case) -> SolidMaterial:
        """The material in use: the ball's, else the case's preset's."""
        return material_of(self.material, case)

    def mass(self, case: Case) -> float:
        """``(4/3) pi R^3 rho`` [kg]."""
        return self.material_of(case).mass(case.radius)

    def spacing(self) -> float:
        """The arc nodes' spacing at the south pole [rad]."""
        from skfem import Basis, ElementTriP2, ElementVector

        basis = Basis(self.mesh(), ElementVector(ElementTriP2()), intorder=2)
        phi, _, _ = _arc_nodes(basis)
        return float(phi[-1] - phi[-2])

    def summary(self, case: Case) -> dict[str, Any]:
        """The solid's block of the JSON's ``model``
        (:func:`~twoball.modal.balls.solid.solid_summary`)."""
        from twoball.modal.balls.solid import solid_summary

        return solid_summary(self.material_of(case), case, self.spacing())

    def space(self, case: Case) -> SolidSpace:
        """Every eigenpair of this ball's space for the case's material."""
        poisson = float(self.material_of(case).poisson)
        return _space(self.level, self.pole_levels, poisson, self.top_levels)

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The solid of ``case`` on this mesh (dimensionless: R, 1/c, its mass)."""
        material = self.material_of(case)
        if monitor is not None:
            monitor(f"eigenpairs of {self.label}")
        ratio = material.wave_speed(case.radius) / case.wave_speed
        return space_description(self.space(case), ratio, case.damping_law, self.label)

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "solid", "discretisation": "fem", "level": L, ...}``."""
        material = None if self.material is None else self.material.as_dict()
        return {
            "ball": self.kind,
            "discretisation": self.backend,
            "level": self.level,
            "pole_levels": self.pole_levels,
            "top_levels": self.top_levels,
            "order": self.order,
            "material": material,
        }


_SPACES: dict[tuple[Any, ...], SolidSpace] = {}


def _space(level: int, pole_levels: int, poisson: float, top_levels: int = 0) -> SolidSpace:
    """The solid's space, kept for the process (a drop and its ball-alone twin share it)."""
    key = ("solid", level, pole_levels, poisson, top_levels)
    if key not in _SPACES:
        if len(_SPACES) > 4:
            _SPACES.clear()
        mesh = pole_refined_disc(level, pole_levels, top_levels=top_levels)
        _SPACES[key] = solid_space(mesh, poisson)
    return _SPACES[key]


# --- the thick wall -------------------------------------------------------------------------

_VALID = {
    "youngs_modulus": "a Young's modulus in (0, 1e12] Pa",
    "thickness": "a wall thickness in (0, 1] m",
    "thickness_ratio": "h / R in (0, 0.9]",
    "density": "a density in (0, 1e5] kg/m^3",
}


def _positive(name: str, value: object, high: float) -> float:
    number = real_number(name, value, _VALID[name])
    if not (0.0 < number <= high and math.isfinite(number)):
        raise ParameterError(name, _VALID[name], value)
    return number


@checked
@dataclass(frozen=True)
class ThickWall:
    """The thick wall of a hollow elastic ball (SI): E, nu, the thickness and the density.

    Give ``thickness`` h [m] or ``thickness_ratio`` h / R; ``density`` rho
    [kg/m^3], or None: the case's preset's measured mass over the wall's volume
    ``(4/3) pi (R^3 - (R - h)^3)``.

    Examples
    --------
    >>> import twoball
    >>> twoball.ThickWall(youngs_modulus=6e6, thickness=3.2e-3).poisson
    0.45
    """

    youngs_modulus: float
    thickness: float | None = None
    poisson: float = 0.45
    thickness_ratio: float | None = None
    density: float | None = None
    source: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        check_labels(self, "source")
        set_ = object.__setattr__
        set_(self, "youngs_modulus", _positive("youngs_modulus", self.youngs_modulus, 1e12))
        if (self.thickness is None) == (self.thickness_ratio is None):
            raise ParameterError("thickness", "given, or thickness_ratio (one of them)", None)
        if self.thickness is not None:
            set_(self, "thickness", _positive("thickness", self.thickness, 1.0))
        else:
            set_(self, "thickness_ratio", _positive("thickness_ratio", self.thickness_ratio, 0.9))
        if self.density is not None:
            set_(self, "density", _positive("density", self.density, 1e5))
        SolidMaterial(1.0, self.youngs_modulus, self.poisson)  # validates nu

    def ratio(self, case: Case) -> float:
        """h / R."""
        if self.thickness_ratio is not None:
            return float(self.thickness_ratio)
        value = float(self.thickness) / case.radius
        if not value < 0.95:
            raise ParameterError("thickness", f"below the radius R = {case.radius:g} m", value)
        return value

    def volume(self, case: Case) -> float:
        """The wall's volume [m^3]."""
        inner = case.radius * (1.0 - self.ratio(case))
        return 4.0 / 3.0 * math.pi * (case.radius**3 - inner**3)

    def material(self, case: Case) -> SolidMaterial:
        """The wall's material: the density given, else the preset's mass over the volume."""
        density = self.density
        if density is None:
            from twoball.modal.presets import MEASURED

            measured = MEASURED.get(case.preset_name or "")
            if measured is None or measured.mass is None:
                valid = "given for a case without a preset mass (the wall's density)"
                raise ParameterError("density", valid, None)
            density = measured.mass / self.volume(case)
        return SolidMaterial(density, self.youngs_modulus, self.poisson)

    def as_dict(self) -> dict[str, Any]:
        """The wall as given (SI; None: not given)."""
        return {
            "youngs_modulus": self.youngs_modulus,
            "thickness": self.thickness,
            "thickness_ratio": self.thickness_ratio,
            "poisson": self.poisson,
            "density": self.density,
        }


#: Thick walls of the presets.
THICK_WALLS: dict[str, ThickWall] = {
    "tennis": ThickWall(
        youngs_modulus=6.0e6,
        thickness=3.2e-3,
        poisson=0.45,
        source="the tennis preset's wall (E = 6 MPa assumed, h = 3.2 mm: Cross 1999; Brody, "
        "Cross & Lindsey 2002), nu = 0.45 (rubber's 0.5 would lock the displacement "
        "elements), the density from the preset's 57.7 g over the wall's volume",
    ),
}


@checked
@dataclass(frozen=True)
class ThickBall:
    """A hollow elastic ball on the (r, z) half annulus in P2: the thick wall, with its gas.

    Parameters
    ----------
    wall : ThickWall, optional
        The wall (default the case's preset's, :data:`THICK_WALLS`).
    cells : tuple of int
        Cells across the wall and along the half circle (default (2, 96): the
        arc's P2 nodes ``pi / 192`` apart).
    gas : bool
        The enclosed gas's stiffness on the inner surface (eq. (T1)), with the
        drop's gas law and the case's pressure (default True).

    Examples
    --------
    >>> import twoball
    >>> twoball.ThickBall(cells=(2, 48)).label
    'thick axisym 2 x 48 P2'
    """

    wall: ThickWall | None = None
    cells: tuple[int, int] = DEFAULT_THICK_CELLS
    gas: bool = True

    kind = "thick"
    backend = "fem"
    dense = True
    pressurised = True

    def __post_init__(self) -> None:
        if self.wall is not None and not isinstance(self.wall, ThickWall):
            raise ParameterError("wall", "a twoball.ThickWall or None", type(self.wall).__name__)
        if not (isinstance(self.cells, tuple | list) and len(self.cells) == 2):
            raise ParameterError("cells", "two integers (across, along)", self.cells)
        across = _check_int("cells", self.cells[0], (1, 16))
        along = _check_int("cells", self.cells[1], (8, 1024))
        object.__setattr__(self, "cells", (across, along))
        if not isinstance(self.gas, bool):
            raise ParameterError("gas", "True or False (the enclosed gas's stiffness)", self.gas)

    @property
    def label(self) -> str:
        """``thick axisym 2 x 96 P2``."""
        return f"thick axisym {self.cells[0]} x {self.cells[1]} P2"

    def wall_of(self, case: Case) -> ThickWall:
        """The wall in use: the ball's, else the case's preset's."""
        if self.wall is not None:
            return self.wall
        name = case.preset_name or ""
        if name not in THICK_WALLS:
            valid = "given for a case without a preset thick wall (tennis has one)"
            raise ParameterError("wall", valid, None)
        return THICK_WALLS[name]

    def size(self, case: Case | None = None) -> tuple[int, int] | None:
        """Coordinates and floor points: known once built (None before)."""
        return None

    def mass(self, case: Case) -> float:
        """The wall's mass ``rho (4/3) pi (R^3 - (R - h)^3)`` [kg]."""
        wall = self.wall_of(case)
        return wall.material(case).density * wall.volume(case)

    def _gas(self, case: Case) -> float:
        """``kappa P_abs / (mu V_gas)`` (units R = mu = 1) of the case's gas, or 0."""
        from twoball.modal.stiffness import GAS_MODELS

        if not self.gas or case.gas == "none" or case.pressure is None:
            return 0.0
        wall = self.wall_of(case)
        inner = 1.0 - wall.ratio(case)
        absolute = float(case.pressure) + case.atmosphere
        mu = wall.material(case).shear_modulus
        return GAS_MODELS[case.gas] * absolute / mu / (4.0 / 3.0 * math.pi * inner**3)

    def space(self, case: Case) -> SolidSpace:
        """Every eigenpair of the wall's space (the gas in its stiffness)."""
        from twoball.fem_solid.mesh import half_annulus

        wall = self.wall_of(case)
        inner = 1.0 - wall.ratio(case)
        gas = self._gas(case)
        key = ("thick", inner, self.cells, wall.poisson, gas)
        if key not in _SPACES:
            if len(_SPACES) > 4:
                _SPACES.clear()
            mesh = half_annulus(inner, *self.cells)
            _SPACES[key] = solid_space(mesh, wall.poisson, gas=gas, inner=inner)
        return _SPACES[key]

    def summary(self, case: Case) -> dict[str, Any]:
        """The thick wall for the JSON's ``model``: the wall, the gas, the prestress left out."""
        wall = self.wall_of(case)
        material = wall.material(case)
        tension = None if case.pressure is None else float(case.pressure) * case.radius / 2.0
        stiffness = wall.youngs_modulus * wall.ratio(case) * case.radius / (1 - wall.poisson**2)
        return {
            "ball": "thick",
            "membrane": None,
            "bending_N_m": None,
            "bending_beta": None,
            "omega0_squared": None,
            "wall": {
                **wall.as_dict(),
                "thickness_ratio_used": wall.ratio(case),
                "density_kg_m3": material.density,
                "shear_speed_m_s": material.shear_speed,
                "source": wall.source,
            },
            "gas_stiffness": self._gas(case),
            "prestress": "left out (not derived): p = N0 / C = "
            + ("-" if tension is None else f"{tension / stiffness:.3g}"),
        }

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The thick wall of ``case`` (dimensionless: R, 1/c, its mass)."""
        material = self.wall_of(case).material(case)
        if monitor is not None:
            monitor(f"eigenpairs of {self.label}")
        ratio = material.wave_speed(case.radius) / case.wave_speed
        return space_description(self.space(case), ratio, case.damping_law, self.label)

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "thick", "discretisation": "fem", "cells": [...], ...}``."""
        wall = None if self.wall is None else self.wall.as_dict()
        return {
            "ball": self.kind,
            "discretisation": self.backend,
            "cells": list(self.cells),
            "gas": self.gas,
            "wall": wall,
        }
