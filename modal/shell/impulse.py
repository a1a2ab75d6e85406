r"""Causality: the free shell struck at the south pole, by modal superposition.

A vertical impulse J (upwards, as a floor gives) is spread over a narrow cap
around the south pole, ``f_z(phi, t) = J g(phi) delta(t) / int g dA`` with the
Gaussian ``g = exp(-psi^2 / (2 eps^2))`` of the geodesic angle ``psi = pi - phi``
from the south pole (width eps [rad], arc width eps R).  No floor, no gravity.
The work of f_z on a mode is ``int f_z u_z dA`` with ``u_z = w cos(phi) - v sin(phi)``,
so with modes of modal mass m each modal coordinate starts with the velocity

    ``q_k_t(0) = (J / m) <u_z,k>_g``,   ``<u_z,k>_g = int g u_z,k dA / int g dA``,

and ``q_k(t) = q_k_t(0) sin(omega_k t) / omega_k`` (``q_k_t(0) t`` for omega_k = 0).
The translation's ``<u_z>_g = 1`` moves the centre of mass by exactly ``J t / m``;
the top (north pole) moves by ``sum_k u_z,k(0) q_k(t)``.

In-plane waves travel at ``c_e = sqrt(C / rho_s)``: the top should stay still
until about ``pi R / c_e`` (then move up with the centre), unlike the radial-only
membrane with a separate centre coordinate, whose top moves down at once.
Two parts of the model are not causal, and the study shows both:

* Kirchhoff bending: flexural waves are dispersive with group speed about
  ``2 sqrt(beta_h) n c_e`` at degree n, above c_e from about ``n = 1.3 R / h``
  (nu = 1/2; :func:`superluminal_degree`), where thin-shell theory no longer
  holds anyway (wavelengths of a few h).  A load of width ``eps >~ 2 h / R``
  keeps those degrees out (its weights are ``exp(-(n eps)^2 / 2)``); narrower
  loads give flexural precursors before ``pi R / c_e``.
* The enclosed gas: its uniform pressure follows the volume at once (no
  acoustic delay), so the top moves at once, upwards, by
  ``top / centre = g t^2 / 6 + O(t^4)`` (the breathing mode's frequency moved by
  the gas; t in ``R / c_e``).  A real gas carries that signal at the speed of
  sound, across the ball in ``2 R / c_sound``.

Units: time ``R / c_e``, displacement ``(J / m)(R / c_e)`` (so the centre of mass
is at ``t``).  Functions take the modes' frequencies and rows so that the closed
form (:class:`twoball.modal.shell.modes.ShellModes`) and the finite elements
(:mod:`twoball.fem_shell`) share them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from twoball.modal.shell.modes import ShellModes, shell_modes
from twoball.modal.shell.parameters import ShellParameters
from twoball.modal.shell.spectrum import branches

__all__ = [
    "ImpulseResponse",
    "causality_study",
    "closed_form_impulse",
    "gaussian_cap_average",
    "modal_impulse_response",
    "superluminal_degree",
]


def gaussian_cap_average(
    vertical: Callable[[np.ndarray], np.ndarray],
    width: float,
    *,
    breaks: np.ndarray | None = None,
    points: int = 24,
    reach: float = 12.0,
) -> np.ndarray:
    """``<u_z,k>_g``: the Gaussian-weighted average of each mode's u_z around the south pole.

    Parameters
    ----------
    vertical : callable
        ``phi -> u_z`` of every mode, shape (modes, len(phi)).
    width : float
        eps [rad] > 0 of ``g = exp(-(pi - phi)^2 / (2 eps^2))``.
    breaks : array, optional
        Angles phi where u_z is not smooth (finite-element nodes): the quadrature
        is composite over them.
    points : int
        Gauss-Legendre points per piece (pieces are at most eps / 2 long).
    reach : float
        g is integrated over ``psi <= reach * eps`` (``exp(-72)`` beyond 12 eps).

    Returns
    -------
    ndarray, shape (modes,)
        Dimensionless.
    """
    if not width > 0.0:
        raise ValueError("width must be > 0")
    top = min(np.pi, reach * width)
    edges = np.linspace(0.0, top, int(np.ceil(top / (0.5 * width))) + 1)
    if breaks is not None:
        psi_breaks = np.pi - np.asarray(breaks, dtype=float)
        inside = psi_breaks[(psi_breaks > 0.0) & (psi_breaks < top)]
        edges = np.unique(np.concatenate([edges, inside]))
    nodes, weights = np.polynomial.legendre.leggauss(points)
    left, right = edges[:-1, None], edges[1:, None]
    psi = (0.5 * (left + right) + 0.5 * (right - left) * nodes).ravel()
    weight = (0.5 * (right - left) * weights).ravel()
    density = np.exp(-0.5 * (psi / width) ** 2) * np.sin(psi) * weight
    rows = vertical(np.pi - psi)
    return rows @ density / density.sum()


@dataclass(frozen=True)
class ImpulseResponse:
    """The top's and the centre of mass's vertical displacement after the impulse.

    Attributes
    ----------
    times : ndarray
        t in units of ``R / c_e``.
    top, centre : ndarray
        Vertical displacements of the north pole and of the centre of mass, in
        units of ``(J / m)(R / c_e)`` (so ``centre == times`` up to rounding).
    width : float
        The load's width eps [rad].
    """

    times: np.ndarray
    top: np.ndarray
    centre: np.ndarray
    width: float

    def ratio(self) -> np.ndarray:
        """``top / centre`` (0 where the centre has not moved, t = 0)."""
        safe = np.where(self.centre != 0.0, self.centre, 1.0)
        return np.where(self.centre != 0.0, self.top / safe, 0.0)

    def quiet_ratio(self, until: float) -> float:
        """``max |top / centre|`` over ``0 < t <= until`` (units R / c_e)."""
        mask = (self.times > 0.0) & (self.times <= until)
        return float(np.max(np.abs(self.ratio()[mask]), initial=0.0))

    def arrival(self, threshold: float = 1e-3) -> float:
        """First time ``|top| = threshold |centre|`` (linear interpolation), NaN if never.

        Units of ``R / c_e``; compare with pi (the in-plane wave's ``pi R / c_e``).
        """
        excess = np.abs(self.ratio()) - threshold
        above = np.flatnonzero(excess > 0.0)
        if above.size == 0:
            return float("nan")
        i = int(above[0])
        if i == 0:
            return float(self.times[0])
        t0, t1, e0, e1 = self.times[i - 1], self.times[i], excess[i - 1], excess[i]
        return float(t0 + (t1 - t0) * (-e0) / (e1 - e0))

    def sign_at_arrival(self, threshold: float = 1e-3) -> float:
        """Sign of ``top / centre`` where it first exceeds the threshold (+1: same way)."""
        ratio = self.ratio()
        above = np.flatnonzero(np.abs(ratio) > threshold)
        return float(np.sign(ratio[above[0]])) if above.size else float("nan")


def modal_impulse_response(
    omega: np.ndarray,
    top_rows: np.ndarray,
    centre_rows: np.ndarray,
    velocities: np.ndarray,
    times: np.ndarray,
    width: float,
    *,
    chunk: int = 512,
) -> ImpulseResponse:
    """Superpose ``q_k(t) = q_k_t(0) sin(omega_k t) / omega_k`` onto the top and the centre.

    Parameters
    ----------
    omega : ndarray, shape (modes,)
        Omega_k >= 0 (units ``c_e / R``); 0 for the translation.
    top_rows, centre_rows : ndarray, shape (modes,)
        u_z of each mode at the north pole, and its centre-of-mass displacement.
    velocities : ndarray, shape (modes,)
        ``q_k_t(0)`` in units of ``J / m``.
    times : ndarray
        t in units ``R / c_e``.
    width : float
        The load's eps, kept with the result.

    ``sin(omega t) / omega = t sinc(omega t / pi)`` covers omega = 0 exactly.
    """
    times = np.asarray(times, dtype=float)
    top = np.empty_like(times)
    centre = np.empty_like(times)
    top_weights = np.asarray(top_rows) * velocities
    centre_weights = np.asarray(centre_rows) * velocities
    for start in range(0, times.size, chunk):
        t = times[start : start + chunk, None]
        shapes = t * np.sinc(omega[None, :] * t / np.pi)
        top[start : start + chunk] = shapes @ top_weights
        centre[start : start + chunk] = shapes @ centre_weights
    return ImpulseResponse(times=times, top=top, centre=centre, width=float(width))


def closed_form_impulse(modes: ShellModes, width: float, times: np.ndarray) -> ImpulseResponse:
    """The closed form's response to the Gaussian impulse at the south pole.

    Parameters
    ----------
    modes : ShellModes
        Degrees 0..N, both branches (:func:`twoball.modal.shell.modes.shell_modes`).
    width : float
        eps [rad]; degrees with ``n eps`` >> 1 carry ``exp(-(n eps)^2 / 2)``, so N
        of a few times ``1 / eps`` converges the sum.
    times : ndarray
        t in units of ``R / c_e``.
    """
    velocities = gaussian_cap_average(modes.vertical, width)
    return modal_impulse_response(
        modes.omega,
        modes.radial_amplitude,  # u_z at phi = 0 is W P_n(1) = W
        modes.centre_of_mass(),
        velocities,
        times,
        width,
    )


def superluminal_degree(parameters: ShellParameters, max_degree: int = 4000) -> int | None:
    """The lowest degree n whose group speed ``Omega(n + 1) - Omega(n)`` exceeds c_e on a branch.

    The group speed ``d omega / dk`` with ``k = (n + 1/2) / R`` is ``dOmega/dn`` in
    units of c_e; degrees from this n on carry signals faster than the in-plane
    wave.  None if there is none up to ``max_degree`` (the membrane shell with
    nu >~ 0.1: its upper branch approaches c_e from below).  Dimensionless.
    """
    lower, upper = branches(parameters, np.arange(1, max_degree + 2))
    fast = (np.diff(lower) > 1.0) | (np.diff(upper) > 1.0)
    hits = np.flatnonzero(fast)
    return int(hits[0]) + 1 if hits.size else None


def causality_study(
    parameters: ShellParameters,
    width: float,
    *,
    max_degree: int | None = None,
    t_end: float = 1.5 * np.pi,
    samples: int = 3001,
) -> ImpulseResponse:
    """The top and the centre after a Gaussian impulse of width eps at the south pole.

    Parameters
    ----------
    parameters : ShellParameters
        The shell (``gas = 0`` to study the wall's own causality; see the module).
    width : float
        eps [rad]; the arc width is eps R.
    max_degree : int, optional
        N; default ``ceil(12 / eps)`` (the load's weights are below ``exp(-72)``
        beyond, and the observed arrival no longer moves).
    t_end : float
        Last time, units ``R / c_e`` (default 1.5 pi, past the arrival at pi).
    samples : int
        Number of equally spaced times from 0.

    Returns
    -------
    ImpulseResponse
        ``arrival()`` is to be compared with pi (``pi R / c_e``),
        ``quiet_ratio(0.5 * pi)`` with 1e-3, ``sign_at_arrival()`` with +1.
    """
    if max_degree is None:
        max_degree = int(np.ceil(12.0 / width))
    modes = shell_modes(parameters, max_degree)
    return closed_form_impulse(modes, width, np.linspace(0.0, t_end, samples))
