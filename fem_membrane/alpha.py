"""Generalized-alpha time stepping (Chung & Hulbert 1993) of ``M u'' + C u' + K u = 0``.

The semi-discrete form of the damped membrane equation (3.1)/(3.9).  One step
from t_n to t_{n+1} = t_n + dt enforces the equation at the intermediate
instants ``n + 1 - alpha_m`` (inertia) and ``n + 1 - alpha_f`` (damping and
stiffness) together with the Newmark updates

    u_{n+1} = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1})
    v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}),

with ``alpha_m = (2 rho - 1) / (rho + 1)``, ``alpha_f = rho / (rho + 1)``,
``gamma = 1/2 - alpha_m + alpha_f``, ``beta = (1 - alpha_m + alpha_f)^2 / 4``
for the spectral radius at infinite frequency ``rho = rho_inf`` in [0, 1]:
second-order accurate, unconditionally stable; ``rho_inf = 1`` is Newmark's
average-acceleration (trapezoidal) rule, without numerical dissipation.

The effective matrix ``S = (1 - alpha_m) M + (1 - alpha_f)(gamma dt C + beta dt^2 K)``
is factorised once.  Low-rank modal damping ``C = U diag(c) U^T`` is added by the
Woodbury identity ``S^{-1} = A^{-1} - W (I + diag(s) U^T W)^{-1} diag(s) W^T``
with ``A`` the sparse part, ``W = A^{-1} U`` and ``s = (1 - alpha_f) gamma dt c``,
so the sparse factorisation is reused and no dense n x n matrix is formed.
Dimensionless.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sl
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from twoball._common.errors import NumericalError
from twoball._common.monitor import Monitor
from twoball.fem_membrane.damping import ModalDamping
from twoball.fem_membrane.space import PoleFunctional, pole_value
from twoball.fem_membrane.validate import check_dt, check_rho_inf, check_t_end


@dataclass(frozen=True)
class AlphaParameters:
    """Generalized-alpha parameters for a given ``rho_inf`` in [0, 1]."""

    rho_inf: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "rho_inf", check_rho_inf(self.rho_inf))

    @property
    def alpha_m(self) -> float:
        """Weight of a_n in the inertia term."""
        return (2.0 * self.rho_inf - 1.0) / (self.rho_inf + 1.0)

    @property
    def alpha_f(self) -> float:
        """Weight of u_n, v_n in the stiffness and damping terms."""
        return self.rho_inf / (self.rho_inf + 1.0)

    @property
    def gamma(self) -> float:
        """Newmark gamma (second-order accuracy)."""
        return 0.5 - self.alpha_m + self.alpha_f

    @property
    def beta(self) -> float:
        """Newmark beta (maximal high-frequency dissipation for the given rho_inf)."""
        return 0.25 * (1.0 - self.alpha_m + self.alpha_f) ** 2


@dataclass(frozen=True)
class PoleHistory:
    """Pole displacement, velocity and acceleration on the time grid (dimensionless)."""

    t: np.ndarray
    u: np.ndarray
    u_t: np.ndarray
    u_tt: np.ndarray


class GeneralizedAlpha:
    """Generalized-alpha integrator with a once-factorised effective matrix.

    Parameters
    ----------
    mass, stiffness : sparse matrices
        M and K (dimensionless).
    dt : float
        Time step > 0.
    damping : ModalDamping, sparse matrix or None
        Low-rank modal damping, a sparse C (e.g. Rayleigh), or none.
    rho_inf : float
        Spectral radius at infinite frequency in [0, 1].
    """

    def __init__(
        self,
        mass: sp.spmatrix,
        stiffness: sp.spmatrix,
        dt: float,
        damping: ModalDamping | sp.spmatrix | None = None,
        rho_inf: float = 1.0,
    ) -> None:
        self.dt = check_dt(dt)
        self.parameters = p = AlphaParameters(rho_inf)
        self.mass = sp.csr_matrix(mass)
        self.stiffness = sp.csr_matrix(stiffness)
        self.damping = damping
        weight_c = (1.0 - p.alpha_f) * p.gamma * self.dt
        matrix = (1.0 - p.alpha_m) * self.mass + (1.0 - p.alpha_f) * p.beta * self.dt**2 * (
            self.stiffness
        )
        if damping is not None and not isinstance(damping, ModalDamping):
            matrix = matrix + weight_c * sp.csr_matrix(damping)
        self._lu = splu(sp.csc_matrix(matrix))
        self._mass_lu: object | None = None
        self._lowrank = None
        if isinstance(damping, ModalDamping):
            scale = weight_c * damping.rates
            correction = self._lu.solve(np.asfortranarray(damping.basis))  # W = A^{-1} U
            small = np.eye(scale.size) + scale[:, None] * (damping.basis.T @ correction)
            self._lowrank = (damping.basis, scale, correction, sl.lu_factor(small))

    def _damp(self, v: np.ndarray) -> np.ndarray:
        if self.damping is None:
            return np.zeros_like(v)
        return self.damping @ v

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """Apply the inverse of the effective matrix S (Woodbury for low-rank damping)."""
        y = self._lu.solve(rhs)
        if self._lowrank is not None:
            basis, scale, correction, small = self._lowrank
            y = y - correction @ sl.lu_solve(small, scale * (basis.T @ y))
        return y

    def initial_acceleration(self, u0: np.ndarray, v0: np.ndarray) -> np.ndarray:
        """a0 from ``M a0 = -K u0 - C v0``."""
        if self._mass_lu is None:
            self._mass_lu = splu(sp.csc_matrix(self.mass))
        return self._mass_lu.solve(-(self.stiffness @ u0) - self._damp(v0))

    def run(
        self,
        u0: np.ndarray,
        v0: np.ndarray,
        t_end: float,
        pole: PoleFunctional,
        monitor: Monitor | None = None,
    ) -> PoleHistory:
        """Integrate from t = 0 to the first step at or after ``t_end``.

        Returns the pole's u, u_t, u_tt at ``t_n = n dt`` (dimensionless); ``pole``
        is the pole's degree of freedom or the pole functional (a sparse row).  The
        scheme's own acceleration a_{n+1} approximates u'' at t_{n+1} to first
        order only when ``alpha_m != alpha_f`` (rho_inf < 1); the recorded u_tt
        is then the consistent ``M^{-1} (-K u_{n+1} - C v_{n+1})`` (second order,
        one extra mass solve per step).  For rho_inf = 1 the two coincide.
        ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is told every 16
        steps; it may stop the run by raising.
        """
        t_end = check_t_end(t_end)
        steps = max(1, math.ceil(t_end / self.dt - 1e-9))
        p, dt = self.parameters, self.dt
        M, K = self.mass, self.stiffness
        d = np.array(u0, dtype=float)
        v = np.array(v0, dtype=float)
        a = self.initial_acceleration(d, v)
        consistent = p.alpha_m != p.alpha_f
        history = np.empty((steps + 1, 3))

        def at(x: np.ndarray) -> float:
            return pole_value(pole, x)

        history[0] = at(d), at(v), at(a)
        for n in range(steps):
            if n % 16 == 0 and monitor is not None:
                monitor(f"generalized-alpha step {n} of {steps}")
            d_pred = d + dt * v + dt * dt * (0.5 - p.beta) * a
            v_pred = v + dt * (1.0 - p.gamma) * a
            rhs = -(p.alpha_m * (M @ a))
            rhs -= K @ ((1.0 - p.alpha_f) * d_pred + p.alpha_f * d)
            if self.damping is not None:
                rhs -= self._damp((1.0 - p.alpha_f) * v_pred + p.alpha_f * v)
            a = self.solve(rhs)
            d = d_pred + p.beta * dt * dt * a
            v = v_pred + p.gamma * dt * a
            if consistent:  # a_{n+1} of the scheme is only first-order accurate
                history[n + 1] = at(d), at(v), at(self.initial_acceleration(d, v))
            else:
                history[n + 1] = at(d), at(v), at(a)
        if not np.all(np.isfinite(history)):
            raise NumericalError("generalized-alpha: the solution is not finite")
        t = dt * np.arange(steps + 1)
        if t[-1] < t_end:  # only by round-off: the grid must cover [0, t_end]
            t[-1] = t_end
        return PoleHistory(t, history[:, 0], history[:, 1], history[:, 2])


def automatic_step(omega_max: float, t_end: float, accuracy: float = 0.2) -> float:
    """Largest dt with ``omega_max dt <= accuracy`` that divides ``t_end`` into whole steps."""
    steps = max(1, math.ceil(t_end * omega_max / accuracy))
    return t_end / steps
