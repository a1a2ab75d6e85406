r"""The axisymmetric spectrum of the thin spherical shell, degree by degree, in closed form.

Model (Love-Kirchhoff kinematics, Kraus 1967 ch. 2, paper ref. [23])
--------------------------------------------------------------------------------
A complete sphere of radius R, axisymmetric, radial displacement w(phi) (outward)
and meridional displacement v(phi) (towards increasing phi), ``' = d/dphi``:

* membrane strains ``eps_phi = (v' + w) / R``, ``eps_theta = (v cot(phi) + w) / R``;
* rotation ``beta = (v - w') / R``, curvature changes ``kappa_phi = beta' / R``,
  ``kappa_theta = beta cot(phi) / R``;
* energy ``U = (C/2) int (eps_phi^2 + eps_theta^2 + 2 nu eps_phi eps_theta) dA
  + (D_b/2) int (kappa_phi^2 + kappa_theta^2 + 2 nu kappa_phi kappa_theta) dA
  + (N0/2) int (|grad_s w|^2 - 2 w^2 / R^2) dA + U_gas``, with
  ``C = E h / (1 - nu^2)``, ``D_b = E h^3 / (12 (1 - nu^2))``, ``N0 = P R / 2``;
  the third term is the second variation of ``N0 A - P V`` about the inflated
  sphere (it sees w only: to first order a tangential displacement moves points
  within the surface, and the first variation of ``N0 A - P V`` vanishes for
  every normal displacement, so the second-order normal motion caused by v
  does not enter); ``U_gas = kappa P_abs (dV)^2 / (2 V)``, ``dV = int w dA``;
* kinetic energy ``(rho_s / 2) int (w_t^2 + v_t^2) dA``, ``dA = 2 pi R^2 sin(phi) dphi``.

Derivation (every step; docs/shell.rst has the same with more words)
----------------------------------------------------------------------------------
1. Trial fields ``w = W P_n(cos phi)``, ``v = V P_n'`` with ``P_n' = dP_n/dphi``
   and ``lambda = n (n + 1)``.  Write ``a = P_n''``, ``b = cot(phi) P_n'``.
   Legendre's equation is ``a + b = -lambda P_n``.  With
   ``<f> = int_0^pi f sin(phi) dphi`` and ``N_n = <P_n^2> = 2 / (2 n + 1)``:

   * ``<P_n'^2> = lambda N_n`` (integrate ``P_n' (sin phi P_n')'`` by parts);
   * ``<a b> = int P_n'' P_n' cos(phi) dphi = [cos(phi) P_n'^2 / 2]_0^pi
     + (1/2) <P_n'^2> = lambda N_n / 2`` (``P_n'`` vanishes at both poles).

2. Membrane.  ``R eps_phi = V a + W P_n``, ``R eps_theta = V b + W P_n``.  Using
   ``eps_phi^2 + eps_theta^2 + 2 nu eps_phi eps_theta = (eps_phi + eps_theta)^2
   - 2 (1 - nu) eps_phi eps_theta``, ``R (eps_phi + eps_theta) = (2 W - lambda V) P_n``
   and ``R^2 eps_phi eps_theta = V^2 a b - lambda V W P_n^2 + W^2 P_n^2``:

       ``R^2 <...> = N_n [(2 W - lambda V)^2 - 2 (1 - nu) (lambda V^2 / 2 - lambda V W + W^2)]``
       ``          = N_n [2 (1 + nu) W^2 - 2 lambda (1 + nu) V W + lambda (lambda - 1 + nu) V^2]``.

3. Bending.  ``R beta = (V - W) P_n'``, so ``R^2 kappa_phi = (V - W) a`` and
   ``R^2 kappa_theta = (V - W) b``; by the same identity
   ``R^4 <...> = (V - W)^2 [<(a + b)^2> - 2 (1 - nu) <a b>]
   = (V - W)^2 N_n lambda (lambda - 1 + nu)``.
4. Prestress.  ``|grad_s w|^2 = W^2 P_n'^2 / R^2``:
   ``R^2 <...> = N_n (lambda - 2) W^2``.
5. Gas.  ``dV = 2 pi R^2 W <P_n> = 4 pi R^2 W`` for n = 0 and 0 otherwise.
6. Kinetic.  ``<w^2 + v^2> = N_n (W^2 + lambda V^2)``.

Every term carries ``pi R^2 N_n``; dividing by it and by ``C / R^2`` gives, per
degree, ``U = (1/2) (C / R^2) 2 pi R^2 N_n x^T K x`` and
``T = (1/2) rho_s 2 pi R^2 N_n x_t^T M x_t`` for ``x = (W, V)``, with
``L = lambda (lambda - 1 + nu)``, ``beta_h = D_b / (C R^2) = h^2 / (12 R^2)``,
``p = N0 / C``, ``g = 3 kappa P_abs R / C``::

    K = [[2 (1 + nu) + beta_h L + p (lambda - 2) + g delta_n0,  -lambda (1 + nu) - beta_h L],
         [-lambda (1 + nu) - beta_h L,                          L (1 + beta_h)           ]]
    M = diag(1, lambda)

and ``K x = Omega^2 M x`` with ``Omega^2 = rho_s R^2 omega^2 / C``.  For n >= 1,
``det(K - Omega^2 M) / lambda = Omega^4 - T Omega^2 + D`` with

    ``T = k11 + k22 / lambda = lambda + 1 + 3 nu + beta_h (lambda + 1)(lambda - 1 + nu)
    + p (lambda - 2)``,
    ``D = (k11 k22 - k12^2) / lambda``.

For D: the membrane block alone has ``det = lambda (1 - nu^2)(lambda - 2)``; the
bending block is ``beta_h L e e^T`` with ``e = (1, -1)``, which adds
``beta_h L e^T adj(K_m) e = beta_h L (lambda - 2)(lambda - 1 - nu)``; the prestress
``p (lambda - 2) e_1 e_1^T`` adds ``p (lambda - 2) k22 = p (lambda - 2) L (1 + beta_h)``
(the cofactor of k11).  Dividing by lambda::

    D = (lambda - 2) [(1 - nu^2) + beta_h ((lambda - 1)^2 - nu^2) + p (lambda - 1 + nu)(1 + beta_h)]

which is the issue's frequency equation term by term, its ``(1 + beta_h)`` included
(that factor is the bending part of k22, not a bending-prestress cross energy).

Checks and limits
-----------------
* p = beta_h = 0: ``Omega^4 - (lambda + 1 + 3 nu) Omega^2 + (1 - nu^2)(lambda - 2) = 0``,
  the membrane-shell equation of Baker 1961 (JASA 33:1749) as quoted in code_aster's
  validation case v2.03.007; with bending it equals, expanded, Hayek's equation
  quoted there (``a = beta_h``, ``b = lambda``): the same trace and
  ``a lambda (lambda^2 - 4 lambda + 5 - nu^2) + (1 - nu^2)(lambda - 2 - 2 a)``
  as constant.  The code_aster reference frequencies (R = 2.5 m, t = 0.1 m,
  E = 200 GPa, nu = 0.3, rho = 7800 kg/m^3) are reproduced to the digits printed.
* n = 0: ``v = 0``, ``Omega_0^2 = 2 (1 + nu) - 2 p + g``.
* n = 1: ``lambda = 2`` makes ``D = 0``: Omega = 0 with K's null vector (1, 1),
  i.e. ``w = cos(phi)``, ``v = -sin(phi)``: the rigid translation along z (all
  strains, the rotation and the prestress energy vanish).  The other root is
  ``Omega^2 = 3 (1 + nu)(1 + beta_h)`` with ``W = -2 V``.
* C -> 0 at fixed N0 (p -> infinity): ``Omega^2 = p (lambda - 2) + 2 (1 + nu)
  + beta_h L + O(1/p)`` for the *upper* root and ``(lambda - 1 + nu)(1 + beta_h) + O(1/p)``
  for the lower; in SI the upper branch tends to
  ``omega^2 = (n - 1)(n + 2) N0 / (rho_s R^2)`` (the pressurised membrane) and the
  lower one, mostly tangential, goes to 0 like C.  Issue 31 names the lower
  branch for this limit: the lower branch is the radial-like one only while C is
  large against N0; the two branches never cross (the coupling
  ``k12 = -lambda (1 + nu) - beta_h L`` is never 0) and exchange character near
  ``C / N0 ~ 1`` (docs/shell.rst has the numbers).

Everything here is dimensionless (units of :mod:`twoball.modal.shell.parameters`).
"""

from __future__ import annotations

import numpy as np

from twoball.modal.shell.parameters import ShellParameters

__all__ = [
    "branches",
    "degree_matrices",
    "frequency_coefficients",
    "frequency_residual",
    "mode_vectors",
]


def _degrees(degrees: np.ndarray | int) -> np.ndarray:
    """Degrees n as a float array (``int`` N means 0..N)."""
    if np.ndim(degrees) == 0 and isinstance(degrees, (int, np.integer)):
        return np.arange(int(degrees) + 1, dtype=float)
    n = np.asarray(degrees, dtype=float)
    if np.any(n < 0) or np.any(n != np.round(n)):
        raise ValueError("degrees must be integers >= 0")
    return n


def degree_matrices(
    parameters: ShellParameters, degrees: np.ndarray | int
) -> tuple[np.ndarray, np.ndarray]:
    """Stiffness K and mass M of each degree (steps 2-6 of the module's derivation).

    Parameters
    ----------
    parameters : ShellParameters
        nu, beta_h, p, g.
    degrees : array of int, or int N (meaning 0..N)
        The Legendre degrees n.

    Returns
    -------
    K, M : ndarray, shape (len(degrees), 2, 2)
        In units of ``C / R^2`` and ``rho_s`` per ``2 pi R^2 N_n`` (``N_n = 2/(2n+1)``)
        for the unknowns (W, V) of ``w = W P_n(cos phi)``, ``v = V dP_n/dphi``:
        ``K x = Omega^2 M x``.  For n = 0 the V row and column are those of an
        absent unknown (``dP_0/dphi = 0``): ``K[1, 1] = M[1, 1] = 0``.
    """
    n = _degrees(degrees)
    nu, bh, p = parameters.poisson, parameters.bending, parameters.prestress
    lam = n * (n + 1.0)
    bend = lam * (lam - 1.0 + nu)  # L = lambda (lambda - 1 + nu), step 2 / step 3
    stiffness = np.empty(n.shape + (2, 2))
    stiffness[..., 0, 0] = 2.0 * (1.0 + nu) + bh * bend + p * (lam - 2.0)
    stiffness[..., 0, 0] += np.where(n == 0, parameters.gas, 0.0)  # step 5
    stiffness[..., 0, 1] = stiffness[..., 1, 0] = -lam * (1.0 + nu) - bh * bend
    stiffness[..., 1, 1] = bend + bh * bend
    mass = np.zeros_like(stiffness)
    mass[..., 0, 0] = 1.0
    mass[..., 1, 1] = lam
    return stiffness, mass


def frequency_coefficients(
    parameters: ShellParameters, degrees: np.ndarray | int
) -> tuple[np.ndarray, np.ndarray]:
    """T and D of ``Omega^4 - T Omega^2 + D = 0`` for each degree (n >= 1; gas-free).

    ``T = lambda + 1 + 3 nu + beta_h (lambda + 1)(lambda - 1 + nu) + p (lambda - 2)``,
    ``D = (lambda - 2) [(1 - nu^2) + beta_h ((lambda - 1)^2 - nu^2)
    + p (lambda - 1 + nu)(1 + beta_h)]`` (the derivation's result).  At n = 0
    the same polynomial has the roots ``2 (1 + nu - p)`` and
    ``-(1 - nu)(1 + beta_h)``; the gas is added by :func:`frequency_residual`.
    Dimensionless.
    """
    n = _degrees(degrees)
    nu, bh, p = parameters.poisson, parameters.bending, parameters.prestress
    lam = n * (n + 1.0)
    trace = lam + 1.0 + 3.0 * nu + bh * (lam + 1.0) * (lam - 1.0 + nu) + p * (lam - 2.0)
    constant = (lam - 2.0) * (
        (1.0 - nu**2) + bh * ((lam - 1.0) ** 2 - nu**2) + p * (lam - 1.0 + nu) * (1.0 + bh)
    )
    return trace, constant


def frequency_residual(
    parameters: ShellParameters,
    degrees: np.ndarray | int,
    omega: np.ndarray,
    *,
    relative: bool = True,
) -> np.ndarray:
    """The frequency equation ``Omega^4 - T Omega^2 + D`` at given Omega (gas at n = 0).

    The gas stiffens n = 0 only: there ``Omega^2 - g`` replaces ``Omega^2``.
    With ``relative`` the value is divided by ``Omega^4 + |T| Omega^2 + |D|``
    (so a root gives rounding, ~1e-16, whatever the size of lambda).
    Dimensionless.
    """
    n = _degrees(degrees)
    trace, constant = frequency_coefficients(parameters, n)
    squared = np.asarray(omega, dtype=float) ** 2
    squared = squared - np.where(n == 0, parameters.gas, 0.0)
    value = squared**2 - trace * squared + constant
    if not relative:
        return value
    scale = squared**2 + np.abs(trace) * np.abs(squared) + np.abs(constant)
    return value / np.where(scale > 0.0, scale, 1.0)


def branches(
    parameters: ShellParameters, degrees: np.ndarray | int
) -> tuple[np.ndarray, np.ndarray]:
    """Omega of the lower and the upper branch of each degree.

    The roots of ``Omega^4 - T Omega^2 + D`` (:func:`frequency_coefficients`),
    the lower one as ``2 D / (T + sqrt(T^2 - 4 D))`` (no cancellation: it is
    exactly 0 at n = 1, where ``lambda - 2 = 0``).  n = 0 has one mode: its
    ``Omega_0 = sqrt(2 (1 + nu) - 2 p + g)`` is returned as the lower branch
    and the upper one is NaN.  Dimensionless (``Omega = omega R sqrt(rho_s / C)``).
    """
    n = _degrees(degrees)
    trace, constant = frequency_coefficients(parameters, n)
    root = np.sqrt(np.clip(trace**2 - 4.0 * constant, 0.0, None))
    upper = 0.5 * (trace + root)
    lower = 2.0 * constant / (trace + root)
    breathing = n == 0
    lower = np.where(breathing, parameters.breathing_squared, lower)
    upper = np.where(breathing, np.nan, upper)
    return np.sqrt(lower), np.sqrt(upper)


def mode_vectors(
    parameters: ShellParameters, degrees: np.ndarray, omega: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(W, V) of the modes of degrees n and frequencies Omega, of unit modal mass.

    The null vector of ``K - Omega^2 M`` from its first row,
    ``(-k12, k11 - Omega^2)`` (``|k12| >= lambda (1 + nu) >= 2`` for n >= 1, so this
    row never degenerates); n = 0 is ``(1, 0)``.  Scaled by its largest component
    first, then to ``(W^2 + lambda V^2) / (2 n + 1) = 1``, i.e. the modal mass
    ``int rho_s (w^2 + v^2) dA`` equals the ball's mass ``m = 4 pi R^2 rho_s``; the
    sign makes ``W >= 0`` (the mode's vertical displacement at the north pole,
    ``u_z(0) = W``).  The translation (n = 1, Omega = 0) comes out as ``(1, 1)``
    exactly: ``w = cos(phi)``, ``v = -sin(phi)``, ``u_z = 1``.  Dimensionless
    (lengths in units of the modal coordinate, which for this normalisation is
    the displacement of a rigid translation).
    """
    n = _degrees(degrees)
    stiffness, _ = degree_matrices(parameters, n)
    lam = n * (n + 1.0)
    first = -stiffness[..., 0, 1]
    second = stiffness[..., 0, 0] - np.asarray(omega, dtype=float) ** 2
    breathing = n == 0
    first = np.where(breathing, 1.0, first)
    second = np.where(breathing, 0.0, second)
    largest = np.maximum(np.abs(first), np.abs(second))
    first, second = first / largest, second / largest
    norm = np.sqrt((first**2 + lam * second**2) / (2.0 * n + 1.0))
    sign = np.where(first < 0.0, -1.0, 1.0)
    return sign * first / norm, sign * second / norm
