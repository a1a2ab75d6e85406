"""The closed-form spectrum of the shell against its energy, the issue's equation and references."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg
from numpy.polynomial import legendre

from twoball.modal.shell.parameters import ShellParameters, shell_from_si
from twoball.modal.shell.spectrum import (
    branches,
    degree_matrices,
    frequency_residual,
    mode_vectors,
)

RNG_SEED = 31


def random_shells(count: int, seed: int = RNG_SEED) -> list[ShellParameters]:
    """Seeded random shells: nu in (0, 0.5], h/R in [0, 0.3], p >= 0 up to 50, a gas if needed."""
    rng = np.random.default_rng(seed)
    shells = []
    for _ in range(count):
        nu = 0.5 * (1.0 - rng.random())  # (0, 0.5]
        ratio = 0.3 * rng.random() ** 2
        prestress = 10.0 ** rng.uniform(-4.0, 1.7) if rng.random() < 0.8 else 0.0
        gas = 0.0 if prestress < 1.0 + nu else 2.0 * prestress + rng.random()
        shells.append(ShellParameters(nu, bending=ratio**2 / 12, prestress=prestress, gas=gas))
    return shells


def issue_equation(shell: ShellParameters, n: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Issue 31's frequency equation as printed, relative to the size of its terms."""
    nu, bh, p = shell.poisson, shell.bending, shell.prestress
    lam = n * (n + 1.0)
    o2 = omega**2
    trace = lam + 1 + 3 * nu + bh * (lam + 1) * (lam - 1 + nu) + p * (lam - 2)
    const = (lam - 2) * (
        (1 - nu**2) + bh * ((lam - 1) ** 2 - nu**2) + p * (lam - 1 + nu) * (1 + bh)
    )
    return relative(o2**2 - trace * o2 + const, o2**2 + abs(trace) * o2 + abs(const))


def relative(value: np.ndarray, size: np.ndarray) -> np.ndarray:
    """``value / size``; 0 where both are exactly 0 (the translation: every term vanishes)."""
    value, size = np.broadcast_arrays(value, size)
    out = np.full(value.shape, np.inf)
    out[size > 0] = value[size > 0] / size[size > 0]
    out[(size == 0) & (value == 0)] = 0.0
    return out


def test_both_branches_solve_the_issue_equation_to_1e10_for_n_up_to_40():
    """200 seeded shells, n = 1..40, both branches; n = 0 against 2 (1 + nu) - 2 p + g."""
    n = np.arange(0, 41, dtype=float)
    worst = 0.0
    for shell in random_shells(200):
        lower, upper = branches(shell, n)
        for omega in (lower[1:], upper[1:]):
            worst = max(worst, float(np.max(np.abs(issue_equation(shell, n[1:], omega)))))
        breathing = 2 * (1 + shell.poisson) - 2 * shell.prestress + shell.gas
        assert lower[0] ** 2 == pytest.approx(breathing, rel=1e-14)
        assert np.isnan(upper[0])
        assert np.max(np.abs(frequency_residual(shell, n, lower))) < 1e-12
    assert worst < 1e-10


def test_branches_are_the_generalized_eigenvalues_of_the_degree_matrices():
    """scipy.linalg.eigh of (K, M) per degree against the root formula, n = 1..40."""
    n = np.arange(1, 41)
    for shell in random_shells(40, seed=7):
        stiffness, mass = degree_matrices(shell, n)
        lower, upper = branches(shell, n)
        for i in range(n.size):
            values = scipy.linalg.eigh(stiffness[i], mass[i], eigvals_only=True)
            scale = values[1]
            assert abs(values[0] - lower[i] ** 2) <= 1e-12 * scale
            assert abs(values[1] - upper[i] ** 2) <= 1e-12 * scale


def _energy_matrix(shell: ShellParameters, n: int) -> tuple[np.ndarray, np.ndarray]:
    """K and M of degree n by quadrature of the strain energy (R = 1, C = 1, rho_s = 1).

    Independent of the module's algebra: the Love-Kirchhoff strains are evaluated
    pointwise from numpy's Legendre series and integrated over phi with
    Gauss-Legendre (interior points: cot(phi) is never evaluated at a pole).
    """
    nu, bh, p = shell.poisson, shell.bending, shell.prestress
    nodes, weights = np.polynomial.legendre.leggauss(160)
    phi = 0.5 * np.pi * (nodes + 1.0)
    weights = 0.5 * np.pi * weights * np.sin(phi)
    x, s, c = np.cos(phi), np.sin(phi), np.cos(phi)
    basis = legendre.Legendre.basis(n)
    pn, d1, d2 = basis(x), basis.deriv(1)(x), basis.deriv(2)(x)
    dphi = -s * d1  # dP/dphi
    dphi2 = s**2 * d2 - c * d1  # d2P/dphi2

    def fields(big_w: float, big_v: float) -> dict[str, np.ndarray]:
        w, dw, ddw = big_w * pn, big_w * dphi, big_w * dphi2
        v, dv = big_v * dphi, big_v * dphi2
        beta, dbeta = v - dw, dv - ddw
        return {
            "ephi": dv + w,
            "etheta": v * c / s + w,
            "kphi": dbeta,
            "ktheta": beta * c / s,
            "w": w,
            "dw": dw,
            "v": v,
        }

    def energy(a: dict, b: dict) -> float:
        membrane = (
            a["ephi"] * b["ephi"]
            + a["etheta"] * b["etheta"]
            + nu * (a["ephi"] * b["etheta"] + a["etheta"] * b["ephi"])
        )
        bending = (
            a["kphi"] * b["kphi"]
            + a["ktheta"] * b["ktheta"]
            + nu * (a["kphi"] * b["ktheta"] + a["ktheta"] * b["kphi"])
        )
        prestress = a["dw"] * b["dw"] - 2.0 * a["w"] * b["w"]
        return float(np.sum((membrane + bh * bending + p * prestress) * weights))

    def kinetic(a: dict, b: dict) -> float:
        return float(np.sum((a["w"] * b["w"] + a["v"] * b["v"]) * weights))

    unit = [fields(1.0, 0.0), fields(0.0, 1.0)]
    norm = 2.0 / (2 * n + 1)
    stiffness = np.array([[energy(a, b) for b in unit] for a in unit]) / norm
    mass = np.array([[kinetic(a, b) for b in unit] for a in unit]) / norm
    gas_volume = np.sum(pn * weights)  # int P_n sin(phi) dphi: 2 for n = 0, else 0
    stiffness[0, 0] += shell.gas * gas_volume**2 / 2.0 / norm  # (g / 4 pi)(2 pi <P>)^2 / (2 pi)
    return stiffness, mass


@pytest.mark.parametrize("n", [0, 1, 2, 3, 5, 8, 13])
def test_degree_matrices_are_the_energy_of_the_legendre_fields(n):
    """Step by step of the derivation: K and M against the energy integrals by quadrature."""
    for shell in random_shells(6, seed=n + 100):
        stiffness, mass = degree_matrices(shell, [n])
        expected_k, expected_m = _energy_matrix(shell, n)
        scale = np.abs(expected_k).max()
        if n == 0:  # V is absent: only the (W, W) entries
            stiffness, expected_k = stiffness[:, :1, :1], expected_k[:1, :1]
            mass, expected_m = mass[:, :1, :1], expected_m[:1, :1]
        assert np.allclose(stiffness[0], expected_k, rtol=0, atol=1e-11 * scale)
        assert np.allclose(mass[0], expected_m, rtol=0, atol=1e-12 * max(1, n * n))


def test_membrane_check_values_of_baker_and_the_issue():
    """nu = 0.3, p = beta_h = 0 (Omega lower / upper), to the 4 decimals given."""
    shell = ShellParameters(0.3)
    lower, upper = branches(shell, [2, 3, 5])
    assert np.round(lower, 4).tolist() == [0.7009, 0.8299, 0.9054]
    assert np.round(upper, 4).tolist() == [2.7219, 3.6347, 5.5750]


def test_membrane_shell_is_the_baker_formula_quoted_by_code_aster():
    """code_aster v2.03.007: ``sqrt(b +- sqrt(b^2 - 4 (1 - nu^2)(i^2 + i - 2))) / sqrt(2)``."""
    n = np.arange(1, 41, dtype=float)
    for nu in (0.01, 0.2, 0.3, 0.45, 0.5):
        lower, upper = branches(ShellParameters(nu), n)
        b = n**2 + n + 1 + 3 * nu
        root = np.sqrt(b**2 - 4 * (1 - nu**2) * (n**2 + n - 2))
        assert np.allclose(upper, np.sqrt((b + root) / 2), rtol=1e-13)
        assert np.allclose(lower, np.sqrt(np.clip(b - root, 0, None) / 2), rtol=1e-7, atol=1e-8)


def test_bending_is_hayek_equation_quoted_by_code_aster():
    """Hayek's bending-corrected equation (a = t^2 / 12 R^2, b = i (i + 1)) as printed there."""
    n = np.arange(1, 41, dtype=float)
    for shell in random_shells(50, seed=3):
        shell = ShellParameters(shell.poisson, shell.bending)
        nu, a, b = shell.poisson, shell.bending, n * (n + 1)
        lower, upper = branches(shell, n)
        for omega in (lower, upper):
            o2 = omega**2
            middle = 1 + 3 * nu - a * (1 - nu) + b * (1 + a * nu + a * b)
            bend = a * b * (b**2 - 4 * b + 5 - nu**2)
            # (1 - nu^2)(b - 2 (1 + a)) as printed, its two parts apart: "2 (1 + a)"
            # would round a away at the n = 1 root (relative 1e-7 for a ~ 1e-9)
            membrane = (1 - nu**2) * (b - 2) - 2 * a * (1 - nu**2)
            size = o2**2 + middle * o2 + abs(bend) + abs(membrane)  # the terms' sizes
            residual = relative(o2**2 - middle * o2 + bend + membrane, size)
            assert np.max(np.abs(residual)) < 1e-12


def test_code_aster_reference_frequencies():
    """v2.03.007 (R = 2.5 m, t = 0.1 m, E = 200 GPa, nu = 0.3, 7800 kg/m^3): Hz of n = 2..10."""
    radius, thickness, density = 2.5, 0.1, 7800.0
    shell = shell_from_si(
        youngs_modulus=2e11,
        thickness=thickness,
        poisson=0.3,
        radius=radius,
        mass=4 * math.pi * radius**2 * thickness * density,
    )
    reference = [237.25, 282.85, 305.24, 324.17, 346.76, 376.68, 416.0, 465.75, 526.20]
    printed = [0.005] * 6 + [0.5] + [0.005] * 2  # half a unit of the last digit shown ("416.")
    lower, _ = branches(shell.parameters, np.arange(2, 11))
    assert np.all(np.abs(shell.frequency_hz(lower) - reference) <= printed)


def test_breathing_mode_with_prestress_and_gas():
    for shell in random_shells(30, seed=11):
        lower, _ = branches(shell, [0])
        expected = 2 * (1 + shell.poisson) - 2 * shell.prestress + shell.gas
        assert lower[0] == pytest.approx(math.sqrt(expected), rel=1e-15)


def test_degree_one_is_the_translation_exactly():
    """n = 1: Omega = 0 and (W, V) = (1, 1) bit for bit; the other root 3 (1 + nu)(1 + beta_h)."""
    for shell in random_shells(100, seed=5):
        lower, upper = branches(shell, [1])
        assert lower[0] == 0.0
        assert upper[0] ** 2 == pytest.approx(3 * (1 + shell.poisson) * (1 + shell.bending))
        big_w, big_v = mode_vectors(shell, np.array([1, 1]), np.array([lower[0], upper[0]]))
        assert (big_w[0], big_v[0]) == (1.0, 1.0)
        assert big_w[1] == pytest.approx(-2.0 * big_v[1], rel=1e-13)  # M-orthogonal to (1, 1)


def test_vanishing_wall_stiffness_gives_the_pressurised_membrane_on_the_upper_branch():
    """C -> 0 at fixed N0: the upper branch's rho_s R^2 omega^2 / N0 = Omega^2 / p -> (n-1)(n+2).

    Not the lower branch: that one is tangential and its
    ``Omega^2 -> (lambda - 1 + nu)(1 + beta_h)``, i.e. omega^2 ~ C -> 0.  The
    upper branch's error is ``(2 (1 + nu) + beta_h L) / p + O(1/p^2)``
    (``L = lambda (lambda - 1 + nu)``: the trace minus the lower root).
    """
    n = np.arange(2, 12, dtype=float)
    lam = n * (n + 1)
    for nu, bh in ((0.3, 0.0), (0.5, 1e-3)):
        first_order = 2 * (1 + nu) + bh * lam * (lam - 1 + nu)
        errors = []
        for p in (1e2, 1e4, 1e6):
            shell = ShellParameters(nu, bh, p, gas=3.0 * p)
            lower, upper = branches(shell, n)
            errors.append(np.max(np.abs(upper**2 / p - (lam - 2))))
            assert np.allclose(lower**2, (lam - 1 + nu) * (1 + bh), rtol=20 / p)
            assert np.allclose(p * (upper**2 / p - (lam - 2)), first_order, rtol=50 / p)
            assert np.all(lower**2 / p < 0.1 * (lam - 2))  # nowhere near the membrane value
        assert errors[1] < errors[0] / 50 and errors[2] < errors[1] / 50


def test_frequency_residual_is_relative_and_zero_at_the_roots():
    shell = ShellParameters(0.25, 1e-3, 0.05, 0.7)
    n = np.arange(0, 401, dtype=float)
    lower, upper = branches(shell, n)
    assert np.max(np.abs(frequency_residual(shell, n, lower))) < 1e-13
    assert np.max(np.abs(frequency_residual(shell, n[1:], upper[1:]))) < 1e-13
    assert np.min(np.abs(frequency_residual(shell, n[2:], 1.01 * lower[2:]))) > 1e-4
