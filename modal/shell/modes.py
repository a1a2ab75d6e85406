r"""The shell's modes in closed form: spectrum, shapes, vertical rows, cap averages, centre of mass.

Mode k is ``w_k = W_k P_n(cos phi)``, ``v_k = V_k dP_n/dphi`` of degree ``n_k`` and
branch ``b_k`` (1 lower, 2 upper), ordered by degree then branch:
k = 0 is the breathing mode (n = 0, one mode), k = 1 the translation (n = 1,
lower branch, Omega = 0, ``(W, V) = (1, 1)``), k = 2 its upper partner, then
``k = 2 n - 1, 2 n`` for degree n >= 1; N degrees give ``2 N + 1`` modes.

Normalisation: every mode has modal mass ``int rho_s (w^2 + v^2) dA = m``, the
ball's mass (:func:`twoball.modal.shell.spectrum.mode_vectors`).  A displacement
``u = sum_k q_k phi_k`` then has kinetic energy ``(m / 2) sum_k q_k_t^2`` and the
translation's coordinate q_1 *is* the centre of mass's vertical displacement.

The vertical displacement of a material point is ``u_z = w cos(phi) - v sin(phi)``;
with ``x = cos(phi)`` and ``dP_n/dphi = -sin(phi) P_n'(x)``:

    ``u_z = W x P_n(x) + V (1 - x^2) P_n'(x)``,

a polynomial of degree n + 1 in x.  Over the polar cap ``phi <= theta`` its area
average ``int_{cos theta}^1 u_z dx / (1 - cos theta)`` is integrated exactly by
Gauss-Legendre in x with ``ceil((n + 2) / 2)`` points or more.  The centre of
mass moves by ``(1 / 4 pi) int u_z dOmega = (1/2) int_{-1}^1 u_z dx``; since
``int x P_n dx = (2/3) delta_n1`` and ``int (1 - x^2) P_n' dx = 2 int x P_n dx``,
it is ``delta_n1 (W + 2 V) / 3``: 1 for the translation and exactly 0 for its
upper partner (M-orthogonal to (1, 1): ``W + 2 V = 0``).  Everything here is
dimensionless (length R).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from twoball.modal.shell.parameters import ShellParameters
from twoball.modal.shell.spectrum import branches, mode_vectors

__all__ = ["ShellModes", "legendre_table", "shell_modes"]


def legendre_table(degree: int, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``P_n(x)`` and ``P_n'(x) = dP_n/dx`` for n = 0..degree, shape (degree + 1, *x.shape).

    Bonnet's recurrence ``(n + 1) P_{n+1} = (2 n + 1) x P_n - n P_{n-1}`` and
    ``P_{n+1}' = P_{n-1}' + (2 n + 1) P_n``; stable on [-1, 1].  Dimensionless.
    """
    x = np.asarray(x, dtype=float)
    values = np.empty((degree + 1,) + x.shape)
    slopes = np.empty_like(values)
    values[0], slopes[0] = 1.0, 0.0
    if degree >= 1:
        values[1], slopes[1] = x, 1.0
    for n in range(1, degree):
        values[n + 1] = ((2 * n + 1) * x * values[n] - n * values[n - 1]) / (n + 1)
        slopes[n + 1] = slopes[n - 1] + (2 * n + 1) * values[n]
    return values, slopes


@dataclass(frozen=True)
class ShellModes:
    """The closed-form modes of degrees 0..N (both branches), mass-normalised to m.

    Attributes
    ----------
    parameters : ShellParameters
        The shell.
    degree, branch : ndarray of int, shape (2N + 1,)
        Degree n and branch (1 lower, 2 upper; n = 0 has branch 1 only) of mode k.
    omega : ndarray, shape (2N + 1,)
        ``Omega_k = omega_k R sqrt(rho_s / C)``.
    radial_amplitude, meridional_amplitude : ndarray, shape (2N + 1,)
        W_k and V_k.
    """

    parameters: ShellParameters
    degree: np.ndarray
    branch: np.ndarray
    omega: np.ndarray
    radial_amplitude: np.ndarray
    meridional_amplitude: np.ndarray

    @property
    def count(self) -> int:
        """Number of modes, ``2 N + 1``."""
        return int(self.degree.size)

    @property
    def max_degree(self) -> int:
        """N."""
        return int(self.degree.max())

    @property
    def translation(self) -> int:
        """Index of the rigid translation (n = 1, lower branch): 1."""
        return int(np.flatnonzero((self.degree == 1) & (self.branch == 1))[0])

    def _tables(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        x = np.cos(np.asarray(phi, dtype=float))
        values, slopes = legendre_table(self.max_degree, x)
        return x, values[self.degree], slopes[self.degree]

    def _amplitudes(self, ndim: int) -> tuple[np.ndarray, np.ndarray]:
        shape = (-1,) + (1,) * ndim
        return self.radial_amplitude.reshape(shape), self.meridional_amplitude.reshape(shape)

    def radial(self, phi: np.ndarray | float) -> np.ndarray:
        """w_k(phi), shape (2N + 1, *phi.shape) (units of the modal coordinate)."""
        x, values, _ = self._tables(phi)
        big_w, _ = self._amplitudes(x.ndim)
        return big_w * values

    def meridional(self, phi: np.ndarray | float) -> np.ndarray:
        """``v_k = V_k dP_n/dphi = -V_k sin(phi) P_n'(cos phi)``, shape (2N + 1, *phi.shape)."""
        phi = np.asarray(phi, dtype=float)
        _, _, slopes = self._tables(phi)
        _, big_v = self._amplitudes(phi.ndim)
        return -big_v * np.sin(phi) * slopes

    def vertical(self, phi: np.ndarray | float) -> np.ndarray:
        """``u_z = w cos(phi) - v sin(phi)`` of each mode at phi, shape (2N + 1, *phi.shape).

        Evaluated as ``W x P_n(x) + V (1 - x^2) P_n'(x)`` (no division at the poles);
        the translation's row is 1 everywhere.
        """
        phi = np.asarray(phi, dtype=float)
        x, values, slopes = self._tables(phi)
        big_w, big_v = self._amplitudes(x.ndim)
        return big_w * x * values + big_v * np.sin(phi) ** 2 * slopes

    def cap_average(self, theta: np.ndarray | float) -> np.ndarray:
        """Area average of u_z over the cap ``phi <= theta`` around the north pole.

        Exact (Gauss-Legendre in ``x = cos(phi)`` on ``[cos theta, 1]`` with
        ``N // 2 + 2`` points: u_z is a polynomial of degree n + 1 in x).  At
        ``theta = 0`` the value at the pole, ``W_k``; at ``theta = pi`` the centre
        of mass's displacement.  Shape (2N + 1, *theta.shape); theta in [0, pi].
        """
        theta = np.asarray(theta, dtype=float)
        if np.any((theta < 0.0) | (theta > np.pi)):
            raise ValueError("theta must lie in [0, pi]")
        nodes, weights = np.polynomial.legendre.leggauss(self.max_degree // 2 + 2)
        low = np.cos(theta)[..., None]
        half = 0.5 * (1.0 - low)  # the interval's half-length
        x = low + half * (nodes + 1.0)  # (*theta.shape, q)
        values, slopes = legendre_table(self.max_degree, x)
        values, slopes = values[self.degree], slopes[self.degree]
        big_w, big_v = self._amplitudes(x.ndim)
        integrand = big_w * x * values + big_v * (1.0 - x**2) * slopes
        mean = 0.5 * np.sum(integrand * weights, axis=-1)  # integral / (1 - cos theta)
        pole = self.radial_amplitude.reshape((-1,) + (1,) * theta.ndim)
        return np.where(theta > 0.0, mean, pole)

    def centre_of_mass(self) -> np.ndarray:
        """Vertical displacement of the centre of mass per unit modal coordinate.

        ``delta_n1 (W + 2 V) / 3``: 1 for the translation, 0 for every other mode
        (to rounding for the n = 1 upper branch).  Shape (2N + 1,).
        """
        value = (self.radial_amplitude + 2.0 * self.meridional_amplitude) / 3.0
        return np.where(self.degree == 1, value, 0.0)

    def squared_frequencies(self) -> np.ndarray:
        """``Omega_k^2`` (the modal stiffnesses in units of ``m C / (rho_s R^2)``)."""
        return self.omega**2


def shell_modes(parameters: ShellParameters, max_degree: int) -> ShellModes:
    """The modes of degrees 0..N of the shell, both branches (:class:`ShellModes`).

    Parameters
    ----------
    parameters : ShellParameters
        nu, beta_h, p, g.
    max_degree : int
        N >= 1 (the translation needs n = 1).

    Returns
    -------
    ShellModes
        ``2 N + 1`` modes; cost O(N) (N = 400 takes well under a millisecond).
    """
    if isinstance(max_degree, bool) or int(max_degree) != max_degree or max_degree < 1:
        raise ValueError(f"max_degree must be an integer >= 1, got {max_degree!r}")
    max_degree = int(max_degree)
    n = np.arange(max_degree + 1)
    lower, upper = branches(parameters, n)
    degree = np.concatenate([[0], np.repeat(n[1:], 2)])
    branch = np.concatenate([[1], np.tile([1, 2], max_degree)])
    omega = np.concatenate([[lower[0]], np.column_stack([lower[1:], upper[1:]]).ravel()])
    big_w, big_v = mode_vectors(parameters, degree, omega)
    return ShellModes(
        parameters=parameters,
        degree=degree,
        branch=branch,
        omega=omega,
        radial_amplitude=big_w,
        meridional_amplitude=big_v,
    )
