r"""The shell on the meridian: mesh, spaces, pole conditions and the matrices (scikit-fem).

Unknowns on a 1-D mesh of ``phi in [0, pi]`` (length unit R):

``w``
    radial displacement, cubic Hermite (values and ``dw/dphi`` at the nodes, C^1:
    scikit-fem's ``ElementLineHermite`` evaluated in local coordinates,
    :class:`ElementLineHermiteLocal`), because the bending energy holds ``w''``;
``v``
    meridional displacement, Lagrange of order 1, 2 (default) or 3.

Pole conditions.  A smooth axisymmetric field on the sphere has a radial part even
and a tangential part odd about each pole, so ``v = 0`` and ``w' = 0`` at
``phi = 0, pi``.  They are also forced by the energy: ``eps_theta = (v cot(phi) + w) / R``
has a finite integral ``int eps_theta^2 sin(phi) dphi`` only if ``v -> 0`` at the poles
(else ``v^2 / phi`` is not integrable), and then ``kappa_theta = beta cot(phi) / R``
needs ``beta = (v - w') / R -> 0``, i.e. ``w' -> 0``.  Both are imposed by removing
those degrees of freedom (the ``dw/dphi`` values of the end nodes and the end values
of v).  Every admissible discrete field then has ``v = O(phi)`` and ``beta = O(phi)``
near a pole: ``v cot(phi)`` and ``beta cot(phi)`` are bounded and smooth, and the
integrands ``(...)^2 sin(phi)`` vanish at the poles.

Quadrature.  Gauss-Legendre on every element (``intorder``, default 2 * 3 + 6 = 12:
7 points): its points are interior, so ``cot(phi)`` is never evaluated at a pole;
the integrands are smooth (polynomials times ``sin``, ``cos`` and the bounded
ratios above), so the quadrature error decays faster than any power of the
element size and stays below the discretisation error (measured: the eigenvalues
move by < 1e-13 relative from intorder 12 to 20).

Forms, with ``dA = 2 pi R^2 sin(phi) dphi`` and the energy of
:mod:`twoball.modal.shell.spectrum` in units of C (stiffness) and ``rho_s R^2``
(mass):

* membrane ``int (e_phi e_phi' + e_theta e_theta' + nu (e_phi e_theta' + e_theta e_phi')) dA``
  with ``e_phi = v' + w``, ``e_theta = v cot(phi) + w``;
* bending ``beta_h`` times the same in ``k_phi = beta'``, ``k_theta = beta cot(phi)``,
  ``beta = v - w'``;
* prestress ``p int (w' w'' - 2 w w'') dA`` (second variation of ``N0 A - P V``);
* gas ``(g / 4 pi) m m^T`` with ``m_i = int w_i dA`` (rank one: the gas sees the
  volume change ``int w dA``);
* mass ``int (w w' + v v') dA``.

The rigid translation ``t = (w, v) = (cos(phi), -sin(phi))`` is not a piecewise
polynomial in phi, so the plain space holds it only approximately.
:mod:`twoball.fem_shell.modes` adds it exactly; this module provides its
couplings (``K t``, ``M t``, ``m . t``) by the same quadrature.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse
from skfem import (
    Basis,
    BilinearForm,
    DiscreteField,
    ElementLineHermite,
    ElementLineP1,
    ElementLineP2,
    ElementLinePp,
    Functional,
    LinearForm,
    MeshLine1,
    asm,
)

from twoball.modal.shell.parameters import ShellParameters

__all__ = ["ElementLineHermiteLocal", "ShellSpace", "shell_space"]

TWO_PI = 2.0 * math.pi


class ElementLineHermiteLocal(ElementLineHermite):
    """scikit-fem's cubic Hermite line element, evaluated in the element's own coordinate.

    Same degrees of freedom and the same functions as ``ElementLineHermite``
    (value and ``du/dx`` at both vertices).  scikit-fem builds that element from
    the power basis ``1, x, x^2, x^3`` in the global coordinate and inverts a
    Vandermonde matrix per element, whose condition number grows like
    ``(x / h)^3``: on ``[0, pi]`` with 256 elements the basis is only good to
    ~1e-9.  Here the four functions are the Hermite cubics of the reference
    coordinate ``s = (x - x_0) / h`` (``1 - 3s^2 + 2s^3``, ``h (s - 2s^2 + s^3)``,
    ``3s^2 - 2s^3``, ``h (s^3 - s^2)``), exact to rounding on any mesh (affine
    line elements only).
    """

    def gbasis(self, mapping, X, i, tind=None):  # noqa: D102 -- scikit-fem's interface
        mesh = mapping.mesh
        if tind is None:
            tind = np.arange(mesh.t.shape[1])
        x = mapping.F(X, tind=tind)[0]
        length = mesh.p[0, mesh.t[1, tind]] - mesh.p[0, mesh.t[0, tind]]
        h = length.reshape((-1,) + (1,) * (x.ndim - 1))
        s = np.broadcast_to(X[0], x.shape)
        if i == 0:
            value, slope, curve = (
                1 - 3 * s**2 + 2 * s**3,
                (6 * s**2 - 6 * s) / h,
                (12 * s - 6) / h**2,
            )
        elif i == 1:
            value, slope, curve = h * (s - 2 * s**2 + s**3), 1 - 4 * s + 3 * s**2, (6 * s - 4) / h
        elif i == 2:
            value, slope, curve = 3 * s**2 - 2 * s**3, (6 * s - 6 * s**2) / h, (6 - 12 * s) / h**2
        elif i == 3:
            value, slope, curve = h * (s**3 - s**2), 3 * s**2 - 2 * s, (6 * s - 2) / h
        else:
            self._index_error()
        shape = x.shape
        return (
            DiscreteField(
                value=np.broadcast_to(value, shape).copy(),
                grad=np.broadcast_to(slope, shape).copy()[None],
                hess=np.broadcast_to(curve, shape).copy()[None, None],
            ),
        )


def _lagrange(order: int):
    """The Lagrange line element of v: P1, P2 (nodal) or P3 (scikit-fem's hierarchical)."""
    if order == 1:
        return ElementLineP1()
    if order == 2:
        return ElementLineP2()
    if order == 3:
        return ElementLinePp(3)
    raise ValueError(f"v_order must be 1, 2 or 3, got {order!r}")


def _radial_strains(value, slope, curvature, cot):
    """Strain measures of a radial field w (R = 1): e_phi, e_theta, k_phi, k_theta, w', w."""
    return value, value, -curvature, -slope * cot, slope, value


def _meridional_strains(value, slope, cot):
    """Strain measures of a meridional field v: e_phi, e_theta, k_phi, k_theta, w', w."""
    zero = np.zeros_like(value)
    return slope, value * cot, slope, value * cot, zero, zero


def _energy_density(a, b, parameters: ShellParameters):
    """The bilinear energy density of two strain tuples (units C, R = 1)."""
    nu, bh, p = parameters.poisson, parameters.bending, parameters.prestress
    membrane = a[0] * b[0] + a[1] * b[1] + nu * (a[0] * b[1] + a[1] * b[0])
    bending = a[2] * b[2] + a[3] * b[3] + nu * (a[2] * b[3] + a[3] * b[2])
    prestress = a[4] * b[4] - 2.0 * a[5] * b[5]
    return membrane + bh * bending + p * prestress


def _translation_strains(phi):
    """The strain tuple of ``t = (cos(phi), -sin(phi))``, its w and its v.

    Its membrane strains and curvature changes vanish identically
    (``v' + w = -cos + cos``, ``v cot + w = -cos + cos``, ``beta = v - w' = 0``) and
    are written as exact zeros: evaluated, ``cot(phi)`` near the poles would turn
    their rounding into couplings of 1e-9.  Only the prestress's ``(w', w)`` remain.
    """
    c, s = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(phi)
    return (zero, zero, zero, zero, -s, c), c, -s


@dataclass(frozen=True)
class ShellSpace:
    """The discretised shell: bases, free degrees of freedom and the assembled matrices.

    Attributes
    ----------
    parameters : ShellParameters
        nu, beta_h, p, g.
    nodes : ndarray
        The mesh nodes phi_i [rad], 0 = phi_0 < ... < phi_E = pi.
    v_order : int
        Lagrange order of v.
    intorder : int
        Polynomial degree integrated exactly by the Gauss rule of each element.
    """

    parameters: ShellParameters
    nodes: np.ndarray
    v_order: int = 2
    intorder: int = 12

    @cached_property
    def mesh(self) -> MeshLine1:
        """The scikit-fem line mesh of the nodes."""
        return MeshLine1.init_tensor(np.asarray(self.nodes, dtype=float))

    @cached_property
    def radial_basis(self) -> Basis:
        """Cubic Hermite basis of w."""
        return Basis(self.mesh, ElementLineHermiteLocal(), intorder=self.intorder)

    @cached_property
    def meridional_basis(self) -> Basis:
        """Lagrange basis of v (same quadrature points as w's)."""
        return Basis(self.mesh, _lagrange(self.v_order), intorder=self.intorder)

    @property
    def sizes(self) -> tuple[int, int]:
        """Numbers of w and v degrees of freedom before the pole conditions."""
        return self.radial_basis.N, self.meridional_basis.N

    @cached_property
    def free(self) -> np.ndarray:
        """Indices (w first, then v) kept by the pole conditions ``w' = v = 0`` at phi = 0, pi."""
        n_w, n_v = self.sizes
        ends = [0, self.mesh.p.shape[1] - 1]
        fixed_w = self.radial_basis.nodal_dofs[1, ends]  # dw/dphi at the poles
        fixed_v = self.meridional_basis.nodal_dofs[0, ends] + n_w  # v at the poles
        return np.setdiff1d(np.arange(n_w + n_v), np.concatenate([fixed_w, fixed_v]))

    def _block(self, kind_u: str, kind_v: str, mass: bool) -> scipy.sparse.csr_matrix:
        bases = {"w": self.radial_basis, "v": self.meridional_basis}
        parameters = self.parameters

        def strains(field, kind, cot):
            if kind == "w":
                return _radial_strains(np.asarray(field), field.grad[0], field.hess[0, 0], cot)
            return _meridional_strains(np.asarray(field), field.grad[0], cot)

        @BilinearForm
        def form(u, v, w):
            phi = w.x[0]
            area = TWO_PI * np.sin(phi)
            if mass:
                same = float(kind_u == kind_v)
                return same * np.asarray(u) * np.asarray(v) * area
            cot = np.cos(phi) / np.sin(phi)
            return _energy_density(strains(u, kind_u, cot), strains(v, kind_v, cot), parameters) * (
                area
            )

        return asm(form, bases[kind_u], bases[kind_v])

    def _assemble(self, mass: bool) -> np.ndarray:
        blocks = [[self._block(u, v, mass) for u in ("w", "v")] for v in ("w", "v")]
        return scipy.sparse.bmat(blocks).toarray()

    @cached_property
    def stiffness(self) -> np.ndarray:
        """K on all degrees of freedom (units C; membrane + bending + prestress + gas)."""
        matrix = self._assemble(mass=False)
        gas = self.volume_vector
        return matrix + self.parameters.gas / (4.0 * math.pi) * np.outer(gas, gas)

    @cached_property
    def mass(self) -> np.ndarray:
        """M on all degrees of freedom (units ``rho_s R^2``; the constant w = 1 has mass 4 pi)."""
        return self._assemble(mass=True)

    @cached_property
    def volume_vector(self) -> np.ndarray:
        """``m_i = int w_i dA`` (0 for the v degrees of freedom): the volume change per dof."""

        @LinearForm
        def volume(v, w):
            return np.asarray(v) * TWO_PI * np.sin(w.x[0])

        n_v = self.sizes[1]
        return np.concatenate([asm(volume, self.radial_basis), np.zeros(n_v)])

    @cached_property
    def translation_couplings(self) -> tuple[np.ndarray, np.ndarray, float, float, float]:
        """``K t``, ``M t`` (on all dofs), ``t K t``, ``t M t`` and ``m . t`` by quadrature.

        ``t = (cos(phi), -sin(phi))``; exactly ``K t = 0``, ``t K t = 0``,
        ``t M t = 4 pi`` and ``m . t = 0`` (the quadrature gives them to rounding).
        """
        parameters = self.parameters

        def coupling(kind: str, mass: bool):
            @LinearForm
            def form(v, w):
                phi = w.x[0]
                area = TWO_PI * np.sin(phi)
                strains_t, t_w, t_v = _translation_strains(phi)
                if mass:
                    return (t_w if kind == "w" else t_v) * np.asarray(v) * area
                cot = np.cos(phi) / np.sin(phi)
                if kind == "w":
                    mine = _radial_strains(np.asarray(v), v.grad[0], v.hess[0, 0], cot)
                else:
                    mine = _meridional_strains(np.asarray(v), v.grad[0], cot)
                return _energy_density(strains_t, mine, parameters) * area

            basis = self.radial_basis if kind == "w" else self.meridional_basis
            return asm(form, basis)

        k_t = np.concatenate([coupling("w", False), coupling("v", False)])
        m_t = np.concatenate([coupling("w", True), coupling("v", True)])

        @Functional
        def energy(w):
            strains_t, _, _ = _translation_strains(w.x[0])
            return _energy_density(strains_t, strains_t, parameters) * TWO_PI * np.sin(w.x[0])

        @Functional
        def kinetic(w):
            _, t_w, t_v = _translation_strains(w.x[0])
            return (t_w**2 + t_v**2) * TWO_PI * np.sin(w.x[0])

        @Functional
        def volume(w):
            return np.cos(w.x[0]) * TWO_PI * np.sin(w.x[0])

        basis = self.radial_basis
        t_k_t = float(asm(energy, basis))
        t_m_t = float(asm(kinetic, basis))
        gas_t = float(asm(volume, basis))
        k_t = k_t + self.parameters.gas / (4.0 * math.pi) * self.volume_vector * gas_t
        t_k_t += self.parameters.gas / (4.0 * math.pi) * gas_t**2
        return k_t, m_t, t_k_t, t_m_t, gas_t

    def sample_rows(
        self, phi: np.ndarray
    ) -> tuple[scipy.sparse.csr_matrix, scipy.sparse.csr_matrix]:
        """Sparse rows giving w(phi) and v(phi) from all degrees of freedom (w first, then v)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        if np.any((phi < 0.0) | (phi > math.pi)):
            raise ValueError("phi must lie in [0, pi]")
        points = np.clip(phi, self.nodes[0], self.nodes[-1])[None, :]
        n_w, n_v = self.sizes
        radial = self.radial_basis.probes(points)
        meridional = self.meridional_basis.probes(points)
        zeros_w = scipy.sparse.csr_matrix((phi.size, n_v))
        zeros_v = scipy.sparse.csr_matrix((phi.size, n_w))
        return (
            scipy.sparse.hstack([radial, zeros_w]).tocsr(),
            scipy.sparse.hstack([zeros_v, meridional]).tocsr(),
        )


def shell_space(
    parameters: ShellParameters,
    elements: int,
    *,
    v_order: int = 2,
    intorder: int = 12,
) -> ShellSpace:
    """The shell on ``elements`` equal elements in phi (:class:`ShellSpace`).

    Parameters
    ----------
    parameters : ShellParameters
        The shell.
    elements : int
        Number of elements E >= 2 on ``[0, pi]``.
    v_order : {1, 2, 3}
        Lagrange order of v (w is cubic Hermite).
    intorder : int
        Gauss rule's exact polynomial degree per element.
    """
    if isinstance(elements, bool) or int(elements) != elements or elements < 2:
        raise ValueError(f"elements must be an integer >= 2, got {elements!r}")
    nodes = np.linspace(0.0, math.pi, int(elements) + 1)
    _lagrange(v_order)  # refuses a bad order early
    return ShellSpace(parameters=parameters, nodes=nodes, v_order=v_order, intorder=intorder)
