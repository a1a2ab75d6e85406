r"""Finite-element eigenpairs of the shell, the exact translation, the closed form's rows.

Space.  With ``exact_translation`` (default) the trial space is

    ``V_h = {u_h in FE space : (u_h, t)_M = 0}  (+)  span{t}``,   t = (cos(phi), -sin(phi)),

the finite-element space (after the pole conditions) restricted to fields
M-orthogonal to the rigid translation t, plus t itself.  It has the size of the
finite-element space, it contains t exactly (the plain space holds it only to the
interpolation error: its lowest eigenvalue is then ``O(h^4)``, not 0), and the
two parts are M-orthogonal, so the reduced mass matrix is block diagonal and as
well conditioned as the finite-element one.  A basis ``Z`` of the constrained
part is the last ``n - 1`` columns of the Householder ``Q`` of ``c = M t``.  Since t
carries no strain, ``K t = 0`` and t decouples: it is an eigenvector with
eigenvalue ``t K t / t M t``, which the quadrature gives to rounding (every
strain of t vanishes pointwise; the prestress and gas couplings vanish by
integration by parts and by ``int cos(phi) sin(phi) dphi = 0``).  This is the
global form of including rigid-body modes in curved shell elements (Cantin &
Clough 1968, AIAA J. 6:1057).  Every other eigenvector is M-orthogonal to t, so
its centre of mass does not move, as in the closed form.

Eigenpairs are dense (``scipy.linalg.eigh``), normalised to modal mass m
(``int (w^2 + v^2) dA = 4 pi R^2``) and signed so that ``w(0) >= 0``, as in
:mod:`twoball.modal.shell.modes`.  Dimensionless (Omega, length R).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg

from twoball.fem_shell.space import ShellSpace, shell_space
from twoball.modal.shell.impulse import (
    ImpulseResponse,
    gaussian_cap_average,
    modal_impulse_response,
)
from twoball.modal.shell.modes import legendre_table
from twoball.modal.shell.parameters import ShellParameters

__all__ = ["ShellFEModes", "fem_impulse", "fem_shell_modes"]

FOUR_PI = 4.0 * math.pi


@dataclass(frozen=True)
class ShellFEModes:
    """Finite-element eigenpairs of the shell, mass-normalised to m.

    Attributes
    ----------
    space : ShellSpace
        The discretisation.
    omega : ndarray, shape (K,)
        Omega_k ascending (``omega R sqrt(rho_s / C)``).
    vectors : ndarray, shape (n_dofs, K)
        Coefficients on all finite-element dofs (w first, then v; 0 on the pole
        conditions), without the translation's part.
    translation_amplitude : ndarray, shape (K,)
        The amount of t in each mode (1 for the translation, ~0 for the others;
        all 0 without ``exact_translation``).
    translation : int
        Index of the translation mode: the one with t (``exact_translation``), else
        the lowest mode.
    """

    space: ShellSpace
    omega: np.ndarray
    vectors: np.ndarray
    translation_amplitude: np.ndarray
    translation: int

    @property
    def count(self) -> int:
        """Number of modes K."""
        return int(self.omega.size)

    @property
    def nodes(self) -> np.ndarray:
        """The mesh nodes phi_i [rad]."""
        return self.space.nodes

    def radial(self, phi: np.ndarray | float) -> np.ndarray:
        """w_k(phi), shape (K, *phi.shape)."""
        phi = np.asarray(phi, dtype=float)
        rows, _ = self.space.sample_rows(phi.ravel())
        out = (rows @ self.vectors).T + np.outer(self.translation_amplitude, np.cos(phi.ravel()))
        return out.reshape((self.count,) + phi.shape)

    def meridional(self, phi: np.ndarray | float) -> np.ndarray:
        """v_k(phi), shape (K, *phi.shape)."""
        phi = np.asarray(phi, dtype=float)
        _, rows = self.space.sample_rows(phi.ravel())
        out = (rows @ self.vectors).T - np.outer(self.translation_amplitude, np.sin(phi.ravel()))
        return out.reshape((self.count,) + phi.shape)

    def vertical(self, phi: np.ndarray | float) -> np.ndarray:
        """``u_z = w cos(phi) - v sin(phi)`` of each mode, shape (K, *phi.shape)."""
        phi = np.asarray(phi, dtype=float)
        return self.radial(phi) * np.cos(phi) - self.meridional(phi) * np.sin(phi)

    def vertical_at_nodes(self) -> np.ndarray:
        """u_z of each mode at the mesh nodes, shape (K, E + 1)."""
        return self.vertical(self.nodes)

    def cap_average(self, theta: float, points: int = 8) -> np.ndarray:
        """Area average of u_z over the cap ``phi <= theta``; shape (K,).

        Composite Gauss-Legendre in phi over the elements the cap covers (the last
        one cut at theta), ``points`` per piece: the integrand is a piecewise
        polynomial times ``sin`` and ``cos``, integrated to rounding.  ``theta = 0``
        gives the value at the pole.
        """
        if not 0.0 <= theta <= math.pi:
            raise ValueError("theta must lie in [0, pi]")
        if theta == 0.0:
            return self.vertical(np.array([0.0]))[:, 0]
        edges = np.concatenate([self.nodes[self.nodes < theta], [theta]])
        nodes, weights = np.polynomial.legendre.leggauss(points)
        left, right = edges[:-1, None], edges[1:, None]
        phi = (0.5 * (left + right) + 0.5 * (right - left) * nodes).ravel()
        weight = (0.5 * (right - left) * weights).ravel() * np.sin(phi)
        return self.vertical(phi) @ weight / (1.0 - math.cos(theta))

    def centre_of_mass(self) -> np.ndarray:
        """Vertical displacement of the centre of mass per unit modal coordinate, shape (K,).

        ``(u, t)_M / (t, t)_M``: exactly the translation amplitude for the
        constrained modes (their finite-element part is M-orthogonal to t); with
        the plain space the inner product of the mode with t.
        """
        _, m_t, _, t_m_t, _ = self.space.translation_couplings
        return self.vectors.T @ m_t / t_m_t + self.translation_amplitude

    @cached_property
    def degrees(self) -> tuple[np.ndarray, np.ndarray]:
        """Dominant Legendre degree of each mode and its share of the modal mass.

        The fields are expanded in ``P_n`` (w) and ``dP_n/dphi`` (v) by
        Gauss-Legendre projection; the share of degree n is
        ``(W_n^2 + lambda V_n^2) / (2 n + 1)`` of the total 1.  For matching finite-
        element modes to the closed form's (degree, branch).
        """
        top = 2 * self.space.nodes.size * (self.space.v_order + 2)
        x, weights = np.polynomial.legendre.leggauss(top + 8)
        phi = np.arccos(x)
        values, slopes = legendre_table(top, x)
        lam = np.arange(top + 1) * (np.arange(top + 1) + 1.0)
        w, v = self.radial(phi), self.meridional(phi)
        big_w = (w * weights) @ values.T * (2 * np.arange(top + 1) + 1) / 2
        dphi = -np.sqrt(1 - x**2) * slopes  # dP_n/dphi at the points
        big_v = (v * weights) @ dphi.T * (2 * np.arange(top + 1) + 1) / 2
        big_v[:, 1:] /= lam[1:]
        share = (big_w**2 + lam * big_v**2) / (2 * np.arange(top + 1) + 1)
        return np.argmax(share, axis=1), np.max(share, axis=1)


def fem_shell_modes(
    parameters: ShellParameters,
    elements: int,
    *,
    v_order: int = 2,
    intorder: int = 12,
    exact_translation: bool = True,
) -> ShellFEModes:
    """All eigenpairs of the shell on ``elements`` elements (dense ``scipy.linalg.eigh``).

    Parameters
    ----------
    parameters : ShellParameters
        The shell.
    elements : int
        E >= 2 equal elements on ``[0, pi]``; about ``4 E`` modes (v P2).
    v_order : {1, 2, 3}
        Lagrange order of v.
    intorder : int
        Gauss rule's exact degree per element.
    exact_translation : bool
        Add the rigid translation exactly (module documentation); False: the
        plain finite-element space.

    Returns
    -------
    ShellFEModes
        Omega ascending; the translation's Omega is 0 to rounding with
        ``exact_translation``.
    """
    space = shell_space(parameters, elements, v_order=v_order, intorder=intorder)
    free = space.free
    stiffness = space.stiffness[np.ix_(free, free)]
    mass = space.mass[np.ix_(free, free)]
    n_all = space.stiffness.shape[0]
    if exact_translation:
        k_t, m_t, t_k_t, t_m_t, _ = space.translation_couplings
        coupling = m_t[free]
        q, _ = scipy.linalg.qr(coupling[:, None])
        basis = q[:, 1:]  # M-orthogonal to t: coupling @ basis = 0
        size = basis.shape[1] + 1
        reduced_k = np.empty((size, size))
        reduced_m = np.zeros((size, size))
        reduced_k[:-1, :-1] = basis.T @ stiffness @ basis
        reduced_k[:-1, -1] = reduced_k[-1, :-1] = basis.T @ k_t[free]
        reduced_k[-1, -1] = t_k_t
        reduced_m[:-1, :-1] = basis.T @ mass @ basis
        reduced_m[-1, -1] = t_m_t
        values, vectors = scipy.linalg.eigh(reduced_k, reduced_m)
        coefficients = basis @ vectors[:-1]
        amplitude = vectors[-1].copy()
    else:
        values, coefficients = scipy.linalg.eigh(stiffness, mass)
        amplitude = np.zeros(values.size)
    full = np.zeros((n_all, values.size))
    full[free] = coefficients * math.sqrt(FOUR_PI)  # unit M-norm -> modal mass 4 pi (= m)
    amplitude *= math.sqrt(FOUR_PI)
    # sign: w(0) >= 0 (u_z at the north pole), the closed form's convention
    rows, _ = space.sample_rows(np.array([0.0]))
    top = np.asarray(rows @ full).ravel() + amplitude
    sign = np.where(top < 0.0, -1.0, 1.0)
    full *= sign
    amplitude *= sign
    translation = int(np.argmax(np.abs(amplitude))) if exact_translation else 0
    omega = np.sqrt(np.clip(values, 0.0, None))
    return ShellFEModes(
        space=space,
        omega=omega,
        vectors=full,
        translation_amplitude=amplitude,
        translation=translation,
    )


def fem_impulse(modes: ShellFEModes, width: float, times: np.ndarray) -> ImpulseResponse:
    """The finite elements' response to the Gaussian impulse at the south pole.

    As :func:`twoball.modal.shell.impulse.closed_form_impulse`, with the load's
    averages integrated piecewise over the elements (units ``R / c_e`` and
    ``(J / m)(R / c_e)``).
    """
    velocities = gaussian_cap_average(modes.vertical, width, breaks=modes.nodes)
    top = modes.vertical(np.array([0.0]))[:, 0]
    return modal_impulse_response(
        modes.omega, top, modes.centre_of_mass(), velocities, times, width
    )
