"""The damped, filtered modal series shared by every backend, eqs. (3.14)-(3.16).

Each mode k is a damped oscillator with undamped angular frequency ``omega_k``,
damping ratio D (the same for all modes), initial displacement ``q_k(0)`` and zero
initial velocity.  Its closed form is ``q_k(t) = Re(c_k exp(lambda_k t))`` with
``lambda_k = omega_k (-D + i sqrt(1 - D^2))`` and ``c_k = q_k(0) (1 - i D /
sqrt(1 - D^2))``: the cosine/sine pair of eq. (3.14) with ``b_n`` of eq. (3.15).
Everything here is dimensionless (length R, time 1/c).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike
from twoball.modal.filters import SpectralFilter

from twoball._common.errors import NumericalError, ParameterError

CHUNK = 4096  # time samples evaluated at once; bounds memory for large mode counts


class PoleState(NamedTuple):
    """Displacement, velocity and acceleration of the pole (dimensionless)."""

    u: np.ndarray
    u_t: np.ndarray
    u_tt: np.ndarray


def check_damping(damping: float) -> float:
    """Return ``damping`` as float if it lies in [0, 1), else raise ParameterError."""
    damping = float(damping)
    if not (0.0 <= damping < 1.0):
        raise ParameterError("damping", "in [0, 1)", damping)
    return damping


@dataclass(frozen=True)
class ModalSeries:
    """A truncated, filtered sum of damped modes, evaluated in closed form.

    Both backends build this type: the Legendre series (modes P_n, eq. (3.14))
    and the finite-element eigenpairs (M-orthonormal vectors).  Dimensionless.

    Parameters
    ----------
    omega : array_like, shape (K,)
        Undamped angular frequencies ``omega_k >= 0`` (0 for the constant mode).
    coefficients : array_like, shape (K,)
        Initial modal displacements ``q_k(0)``; initial velocities are zero (eq. (3.10)).
    pole_values : array_like, shape (K,)
        Mode shapes at the pole, ``phi_k(0)`` (1 for Legendre polynomials).
    damping : float
        Modal damping ratio D in [0, 1), eq. (3.14).
    filter : SpectralFilter
        Weights applied to each mode by its frequency, eq. (3.16).
    mode_norms : array_like, shape (K,), optional
        ``integral of phi_k^2 over the unit sphere`` (the M-norm); enters the energy
        only.  Defaults to ones (M-orthonormal modes).
    filter_omega : array_like, shape (K,), optional
        The frequency the filter weighs each mode by, when it is not ``omega``:
        the membrane frequency ``sqrt(n (n+1))`` of a mode stiffened by bending
        or gas (:func:`twoball.modal.stiffness.stiffen`), so that the filter of
        eq. (3.16) keeps acting on the degree n.  None: ``omega``.
    """

    omega: np.ndarray
    coefficients: np.ndarray
    pole_values: np.ndarray
    damping: float
    filter: SpectralFilter = field(default_factory=SpectralFilter)
    mode_norms: np.ndarray | None = None
    filter_omega: np.ndarray | None = None

    def __post_init__(self) -> None:
        omega = np.asarray(self.omega, dtype=float)
        coefficients = np.asarray(self.coefficients, dtype=float)
        pole_values = np.asarray(self.pole_values, dtype=float)
        if not (omega.shape == coefficients.shape == pole_values.shape) or omega.ndim != 1:
            raise ValueError("omega, coefficients and pole_values must be 1-D of equal length")
        for name, values in (("omega", omega), ("coefficients", coefficients)):
            if not np.all(np.isfinite(values)):
                raise NumericalError(f"modal series: {name} contains NaN or inf")
        if np.any(omega < 0):
            raise NumericalError("modal series: negative frequency (indefinite stiffness?)")
        norms = np.ones_like(omega) if self.mode_norms is None else np.asarray(self.mode_norms)
        object.__setattr__(self, "omega", omega)
        object.__setattr__(self, "coefficients", coefficients)
        object.__setattr__(self, "pole_values", pole_values)
        object.__setattr__(self, "mode_norms", norms.astype(float))
        object.__setattr__(self, "damping", check_damping(self.damping))
        if self.filter_omega is not None:
            by = np.asarray(self.filter_omega, dtype=float)
            if by.shape != omega.shape or not np.all(np.isfinite(by)):
                raise ValueError("filter_omega must be finite, one value per mode")
            object.__setattr__(self, "filter_omega", by)

    # --- derived quantities -------------------------------------------------
    @cached_property
    def weights(self) -> np.ndarray:
        """Filter weights sigma(omega_k), zero for modes beyond the cutoff."""
        by = self.omega if self.filter_omega is None else self.filter_omega
        return self.filter(by)

    @cached_property
    def retained(self) -> np.ndarray:
        """Boolean mask of the modes with a nonzero weight."""
        return self.weights != 0.0

    @property
    def max_frequency(self) -> float:
        """Largest undamped angular frequency among the retained modes."""
        kept = self.omega[self.retained]
        return float(kept.max()) if kept.size else 0.0

    @cached_property
    def pole_amplitudes(self) -> np.ndarray:
        """Filtered initial displacement of each mode at the pole, ``sigma_k q_k(0) phi_k(0)``."""
        return self.weights * self.coefficients * self.pole_values

    @cached_property
    def _exponents(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Retained indices, complex rates lambda_k and complex factors (1 - i D/sqrt(1-D^2))."""
        keep = np.flatnonzero(self.retained)
        root = np.sqrt(1.0 - self.damping**2)
        rates = self.omega[keep] * (-self.damping + 1j * root)
        factor = 1.0 - 1j * self.damping / root
        return keep, rates, factor

    # --- evaluation ---------------------------------------------------------
    @cached_property
    def _pole_matrix(self) -> np.ndarray:
        """(K, 3) complex amplitudes of u, u_t, u_tt at the pole for the retained modes."""
        keep, rates, factor = self._exponents
        amps = self.pole_amplitudes[keep] * factor
        return np.stack([amps, amps * rates, amps * rates**2], axis=1)

    def _evaluate(self, t: ArrayLike, amplitudes: np.ndarray) -> np.ndarray:
        """``Re(sum_k exp(lambda_k t) amplitudes[k])``, shape t.shape + amplitudes.shape[1:]."""
        _, rates, _ = self._exponents
        times = np.asarray(t, dtype=float)
        flat = times.reshape(-1)
        out = np.empty((flat.size,) + amplitudes.shape[1:])
        for start in range(0, flat.size, CHUNK):
            block = _exponential_table(flat[start : start + CHUNK], rates)
            out[start : start + CHUNK] = _product(block, amplitudes).real
        if not np.all(np.isfinite(out)):
            raise NumericalError("modal series: evaluation is not finite")
        return out.reshape(times.shape + amplitudes.shape[1:])

    def pole(self, t: ArrayLike) -> PoleState:
        """Pole displacement, velocity and acceleration at times ``t`` (dimensionless).

        Closed form of eq. (3.16) at phi = 0; vectorised over any array of times.
        """
        out = self._evaluate(t, self._pole_matrix)
        return PoleState(out[..., 0], out[..., 1], out[..., 2])

    def jerk(self, t: ArrayLike) -> np.ndarray:
        """Third time derivative of the pole displacement (dimensionless), closed form."""
        keep, rates, factor = self._exponents
        amps = (self.pole_amplitudes[keep] * factor * rates**3)[:, None]
        return self._evaluate(t, amps)[..., 0]

    def field(self, t: ArrayLike, shapes: np.ndarray, derivative: int = 0) -> np.ndarray:
        """Field values at P points, shape ``t.shape + (P,)`` (dimensionless).

        Parameters
        ----------
        t : array_like
            Times.
        shapes : ndarray, shape (K, P)
            Mode shapes evaluated at the P points (rows follow ``omega``).
        derivative : {0, 1, 2}
            0 for u, 1 for u_t, 2 for u_tt.
        """
        shapes = np.asarray(shapes, dtype=float)
        if shapes.shape[0] != self.omega.size:
            raise ValueError("shapes must have one row per mode")
        if derivative not in (0, 1, 2):
            raise ValueError("derivative must be 0, 1 or 2")
        keep, rates, factor = self._exponents
        scale = self.weights[keep] * self.coefficients[keep] * factor * rates**derivative
        return self._evaluate(t, scale[:, None] * shapes[keep])

    def modal_coordinates(self, t: ArrayLike, derivative: int = 0) -> np.ndarray:
        """Filtered modal coordinates sigma_k q_k(t) (or their time derivatives), shape t + (K,)."""
        return self.field(t, np.eye(self.omega.size), derivative)

    def energy(self, t: ArrayLike) -> np.ndarray:
        """Energy of the filtered series, ``1/2 sum_k m_k (q_k'^2 + omega_k^2 q_k^2)``.

        Dimensionless (unit T R^2); for D = 0 it is constant in time.  At t = 0 with
        no filter and N -> infinity it tends to -W / (T R^2) of eq. (3.5).
        """
        q = self.modal_coordinates(t, 0)
        qt = self.modal_coordinates(t, 1)
        return 0.5 * ((qt**2 + (self.omega * q) ** 2) * self.mode_norms).sum(axis=-1)


def _exponential_table(times: np.ndarray, rates: np.ndarray) -> np.ndarray:
    """``exp(outer(times, rates))``; on a uniform grid from a few exponentials only.

    For ``t_j = t_0 + j h`` the table factors as ``exp(lambda (t_0 + m B h)) *
    exp(lambda r h)`` with ``j = m B + r``: two small tables of exponentials and one
    product each, accurate to a few ulp (no error growth with j).
    """
    count = times.size
    if count < 64:
        return np.exp(np.multiply.outer(times, rates))
    step = (times[-1] - times[0]) / (count - 1)
    uniform = step > 0 and np.all(
        np.abs(times - (times[0] + step * np.arange(count))) <= 1e-13 * (abs(times[-1]) + step)
    )
    if not uniform:
        return np.exp(np.multiply.outer(times, rates))
    block = int(np.sqrt(count)) + 1
    inner = np.exp(np.multiply.outer(step * np.arange(block), rates))  # (B, K)
    outer = np.exp(
        np.multiply.outer(times[0] + step * block * np.arange(-(-count // block)), rates)
    )
    return (outer[:, None, :] * inner[None, :, :]).reshape(-1, rates.size)[:count]


def _product(table: np.ndarray, amplitudes: np.ndarray) -> np.ndarray:
    """``table @ amplitudes``; narrow products avoid BLAS, whose threads only add overhead."""
    if amplitudes.ndim == 2 and amplitudes.shape[1] <= 8:
        return np.einsum("tk,kc->tc", table, amplitudes)
    return table @ amplitudes
