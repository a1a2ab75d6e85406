"""The damped, filtered modal series shared by every backend, eqs. (3.14)-(3.16).

Each mode k is a damped oscillator ``q'' + 2 zeta_k omega_k q' + omega_k^2 q = 0``
with undamped angular frequency ``omega_k``, initial displacement ``q_k(0)`` and
zero initial velocity.  With the paper's ratio D on every mode (eq. (3.14)) its
closed form is ``q_k(t) = Re(c_k exp(lambda_k t))`` with ``lambda_k = omega_k (-D
+ i sqrt(1 - D^2))`` and ``c_k = q_k(0) (1 - i D / sqrt(1 - D^2))``: the
cosine/sine pair of eq. (3.14) with ``b_n`` of eq. (3.15).

A damping law (:mod:`twoball.modal.damping`) gives each mode its own ratio
``zeta_k = law.ratios(omega_k)``, any value >= 0; with ``d_k = 2 zeta_k omega_k``
(the law's ``decay``, finite at omega = 0):

* ``zeta < 1`` (under-damped): one complex exponential as above, with zeta_k;
* ``zeta > 1`` (over-damped): two real ones, ``lambda_slow = -omega^2 / (d/2 +
  s)`` and ``lambda_fast = -d/2 - s``, ``s = omega sqrt(zeta^2 - 1)`` (no
  cancellation), ``q = q_0 (lambda_fast e^(lambda_slow t) - lambda_slow
  e^(lambda_fast t)) / (lambda_fast - lambda_slow)``;
* ``|zeta - 1| <= CRITICAL_BAND`` (critical): ``q = q_0 (1 + omega t) e^(-omega t)``,
  a secular term ``t e^(lambda t)``.  The exact solution is analytic in zeta, so
  this costs at most ``O(CRITICAL_BAND)``; outside the band the amplitudes of
  the two forms grow like ``1 / sqrt(|zeta - 1|)`` and lose
  ``eps / sqrt(2 CRITICAL_BAND)`` to cancellation: both below 1e-10 relative;
* ``omega = 0`` (the constant mode, the free translation): ``q = q_0`` for any
  damping, since the initial velocity is zero.

Everything here is dimensionless (length R, time 1/c).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.damping import ModalRatio, Rayleigh, is_law
from twoball.modal.filters import SpectralFilter

CHUNK = 4096  # time samples evaluated at once; bounds memory for large mode counts
CRITICAL_BAND = 1e-10  # |zeta - 1| below which a mode is taken as critically damped


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


def check_law(damping: object) -> float | Rayleigh:
    """A modal series' damping: the ratio D of the paper's law (a float or a
    :class:`ModalRatio`, checked), or a Rayleigh law with its coefficients (in
    units of c).  Anything else raises :class:`ParameterError` naming ``damping``."""
    if isinstance(damping, ModalRatio):
        return damping.ratio
    if isinstance(damping, Rayleigh):
        if damping.fitted:
            raise ParameterError("damping", "a Rayleigh law with alpha and beta here", damping)
        return damping
    if is_law(damping) or isinstance(damping, (str, bytes)) or damping is None:
        raise ParameterError("damping", "a ratio in [0, 1) or a damping law", damping)
    return check_damping(damping)


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
    damping : float, ModalRatio or Rayleigh
        Modal damping ratio D in [0, 1) on every mode, eq. (3.14) (a
        :class:`~twoball.modal.damping.ModalRatio` is kept as its ratio), or a
        Rayleigh law in units of c: ratio ``zeta(omega_k)`` per mode, any value.
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
    monitor : Monitor, optional
        Told before every chunk of :data:`CHUNK` time samples after the first
        (:class:`~twoball._common.monitor.Monitor`; it may stop the evaluation by
        raising).  Not part of the series' value: left out of comparisons and its
        repr; series derived from this one keep it.
    """

    omega: np.ndarray
    coefficients: np.ndarray
    pole_values: np.ndarray
    damping: float | Rayleigh
    filter: SpectralFilter = field(default_factory=SpectralFilter)
    mode_norms: np.ndarray | None = None
    filter_omega: np.ndarray | None = None
    monitor: Monitor | None = field(default=None, compare=False, repr=False)

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
        object.__setattr__(self, "damping", check_law(self.damping))
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
        """Largest undamped angular frequency among the retained modes.

        With a damping law, the fast rate ``|lambda_fast|`` of an over-damped
        mode counts too: it sets the sampling of the lift-off search.
        """
        kept = self.omega[self.retained]
        highest = float(kept.max()) if kept.size else 0.0
        if self.law_terms is not None:
            real = self.law_terms[1][self.law_terms[1].imag == 0.0].real
            highest = max(highest, float(np.abs(real).max(initial=0.0)))
        return highest

    @property
    def law(self) -> ModalRatio | Rayleigh:
        """The damping law: ``ModalRatio(D)`` or the Rayleigh law (units of c)."""
        return self.damping if isinstance(self.damping, Rayleigh) else ModalRatio(self.damping)

    @cached_property
    def decay(self) -> np.ndarray:
        """``2 zeta_k omega_k`` of every mode: the coefficient of q' (units of c)."""
        if isinstance(self.damping, Rayleigh):
            return self.damping.decay(self.omega)
        return 2.0 * self.damping * self.omega

    @cached_property
    def ratios(self) -> np.ndarray:
        """Damping ratio zeta_k of every mode (inf for omega = 0 under a Rayleigh law)."""
        return self.law.ratios(self.omega)

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

    @cached_property
    def law_terms(
        self,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None] | None:
        """The exponential terms of the retained modes under a damping law (module doc).

        ``(modes, rates, factors, secular)``: term j belongs to mode ``modes[j]``
        and contributes ``Re(q(0) (factors[j] + secular[j] t) exp(rates[j] t))``;
        ``secular`` is None without a critically damped mode.  None for the
        paper's single ratio D (:attr:`_exponents`).
        """
        if not isinstance(self.damping, Rayleigh):
            return None
        keep = np.flatnonzero(self.retained)
        omega, decay = self.omega[keep], self.decay[keep]
        modes, rates, factors, secular = [], [], [], []
        for k, w, d in zip(keep, omega, decay, strict=True):
            if w == 0.0:  # constant or free mode: q' (0) = 0 keeps it at q(0)
                modes.append(k), rates.append(0.0), factors.append(1.0), secular.append(0.0)
                continue
            zeta = d / (2.0 * w)
            if abs(zeta - 1.0) <= CRITICAL_BAND:  # q0 (1 + w t) exp(-w t)
                modes.append(k), rates.append(-w), factors.append(1.0), secular.append(w)
            elif zeta < 1.0:
                root = np.sqrt(1.0 - zeta * zeta)
                modes.append(k)
                rates.append(w * (-zeta + 1j * root))
                factors.append(1.0 - 1j * zeta / root)
                secular.append(0.0)
            else:
                s = w * np.sqrt((zeta - 1.0) * (zeta + 1.0))
                slow, fast = -w * w / (0.5 * d + s), -0.5 * d - s
                gap = fast - slow  # = -2 s
                modes += [k, k]
                rates += [slow, fast]
                factors += [fast / gap, -slow / gap]
                secular += [0.0, 0.0]
        secular_array = np.asarray(secular, dtype=complex)
        return (
            np.asarray(modes, dtype=int),
            np.asarray(rates, dtype=complex),
            np.asarray(factors, dtype=complex),
            secular_array if np.any(secular_array != 0.0) else None,
        )

    def _law_amplitudes(
        self, amplitudes: np.ndarray, derivative: int
    ) -> tuple[np.ndarray, np.ndarray | None]:
        """Term amplitudes of the ``derivative``-th time derivative, from mode amplitudes.

        ``amplitudes`` has one row per term (the mode's); returns the factors of
        ``exp(lambda t)`` and of ``t exp(lambda t)`` (None without critical modes):
        ``d^k/dt^k (a + b t) e^(lambda t) = (a lambda^k + k b lambda^(k-1) + b
        lambda^k t) e^(lambda t)``.
        """
        _, rates, factors, secular = self.law_terms
        power = rates**derivative
        base = amplitudes * (factors * power)[:, None]
        if secular is None:
            return base, None
        if derivative > 0:
            base = base + amplitudes * (secular * derivative * rates ** (derivative - 1))[:, None]
        return base, amplitudes * (secular * power)[:, None]

    # --- evaluation ---------------------------------------------------------
    @cached_property
    def _pole_matrix(self) -> np.ndarray | tuple[np.ndarray, np.ndarray | None]:
        """(K, 3) complex amplitudes of u, u_t, u_tt at the pole for the retained modes.

        Under a damping law the pair of :meth:`_law_amplitudes` for the three.
        """
        if self.law_terms is not None:
            modes = self.law_terms[0]
            amps = self.pole_amplitudes[modes][:, None]
            parts = [self._law_amplitudes(amps, k) for k in range(3)]
            plain = np.concatenate([p[0] for p in parts], axis=1)
            if parts[0][1] is None:
                return plain, None
            return plain, np.concatenate([p[1] for p in parts], axis=1)
        keep, rates, factor = self._exponents
        amps = self.pole_amplitudes[keep] * factor
        return np.stack([amps, amps * rates, amps * rates**2], axis=1)

    def _evaluate(
        self, t: ArrayLike, amplitudes: np.ndarray, secular: np.ndarray | None = None
    ) -> np.ndarray:
        """``Re(sum_k exp(lambda_k t) (amplitudes[k] + t secular[k]))``.

        Shape ``t.shape + amplitudes.shape[1:]``; ``secular`` only under a damping
        law with a critically damped mode.
        """
        rates = self._exponents[1] if self.law_terms is None else self.law_terms[1]
        times = np.asarray(t, dtype=float)
        flat = times.reshape(-1)
        out = np.empty((flat.size,) + amplitudes.shape[1:])
        monitor = self.monitor
        for start in range(0, flat.size, CHUNK):
            if start and monitor is not None:
                monitor(f"the modal series at sample {start} of {flat.size}")
            chunk = flat[start : start + CHUNK]
            block = _exponential_table(chunk, rates)
            values = _product(block, amplitudes).real
            if secular is not None:
                grow = _product(block, secular).real
                values = values + chunk.reshape((-1,) + (1,) * (grow.ndim - 1)) * grow
            out[start : start + CHUNK] = values
        if not np.all(np.isfinite(out)):
            raise NumericalError("modal series: evaluation is not finite")
        return out.reshape(times.shape + amplitudes.shape[1:])

    def pole(self, t: ArrayLike) -> PoleState:
        """Pole displacement, velocity and acceleration at times ``t`` (dimensionless).

        Closed form of eq. (3.16) at phi = 0; vectorised over any array of times.
        """
        if self.law_terms is not None:
            out = self._evaluate(t, *self._pole_matrix)
        else:
            out = self._evaluate(t, self._pole_matrix)
        return PoleState(out[..., 0], out[..., 1], out[..., 2])

    def jerk(self, t: ArrayLike) -> np.ndarray:
        """Third time derivative of the pole displacement (dimensionless), closed form."""
        if self.law_terms is not None:
            modes = self.law_terms[0]
            plain, grow = self._law_amplitudes(self.pole_amplitudes[modes][:, None], 3)
            return self._evaluate(t, plain, grow)[..., 0]
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
        if self.law_terms is not None:
            modes = self.law_terms[0]
            scale = (self.weights * self.coefficients)[modes][:, None] * shapes[modes]
            return self._evaluate(t, *self._law_amplitudes(scale, derivative))
        keep, rates, factor = self._exponents
        scale = self.weights[keep] * self.coefficients[keep] * factor * rates**derivative
        return self._evaluate(t, scale[:, None] * shapes[keep])

    def modal_coordinates(self, t: ArrayLike, derivative: int = 0) -> np.ndarray:
        """Filtered modal coordinates sigma_k q_k(t) (or their time derivatives), shape t + (K,)."""
        return self.field(t, np.eye(self.omega.size), derivative)

    def mean_frequency(self) -> float:
        """Energy-weighted mean frequency of the filtered initial data (dimensionless).

        ``sum_k E_k omega_k / sum_k E_k`` with ``E_k = m_k omega_k^2 (sigma_k
        q_k(0))^2 / 2``, the energy each mode holds at t = 0: the dominant
        frequency of the motion (5.757 for the basketball, N = 30, Lanczos).
        """
        energies = self.mode_norms * (self.omega * self.weights * self.coefficients) ** 2
        total = float(energies.sum())
        if total <= 0.0:
            raise NumericalError("modal series: no mode holds energy at t = 0")
        return float((energies * self.omega).sum() / total)

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
