"""The axisymmetric line (fem_membrane/axisym.py).

Eigenvalues l (l + 1) at order 2p for P1 to P4.
"""

from __future__ import annotations

import numpy as np
import pytest

from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import lowest_eigenpairs

PHI_A = 2.6
BAND = 0.3  # observed order within +-0.3 of the expected one (too high fails too)


# Straight line, no geometric error: every Legendre eigenvalue n (n + 1) at order 2p, each on
# the pair of element counts where it is asymptotic and above round-off (measured on
# E = 12 .. 320, ratios 1.5 and 2: P1 2.00-2.01, P2 3.98-4.02, P3 5.96-6.13, P4 7.79-8.24;
# P4 n = 5 reaches round-off, ~1e-13, one pair earlier than the others).
AXISYM_SCHEDULE = {
    1: (((160, 320), range(2, 30)),),
    2: (((160, 320), range(3, 30)),),
    3: (((90, 135), range(4, 30)),),
    4: (((27, 40), range(5, 6)), ((40, 60), range(6, 30))),
}


def axisym_errors(elements: int, order: int) -> np.ndarray:
    """Relative errors of the eigenvalues n (n + 1), n = 1..29, on the axisymmetric line."""
    space = axisym_space(elements, PHI_A, order)
    values = lowest_eigenpairs(space.stiffness, space.mass, 30).values[1:]
    n = np.arange(1, 30)
    return np.abs(values / (n * (n + 1.0)) - 1.0)


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_axisymmetric_eigenvalues_converge_at_2p(order):
    """Every n = 1..29: exact for n <= p, else observed order 2p (+-0.3, too high fails too).

    The modes P_n(x) with n <= p are polynomials of degree n in x = cos(phi), in the
    space on the straight line: their eigenvalues are exact to round-off.
    """
    exact = axisym_errors(40, order)[:order]
    assert np.all(exact < 1e-11), exact
    for (coarse, fine), degrees in AXISYM_SCHEDULE[order]:
        pair = np.array([axisym_errors(e, order)[degrees.start - 1 : degrees.stop - 1]
                         for e in (coarse, fine)])  # fmt: skip
        assert pair[1].min() > 1e-12  # above round-off
        observed = np.log(pair[0] / pair[1]) / np.log(fine / coarse)
        assert np.all(np.abs(observed - 2 * order) < BAND), (coarse, fine, observed)
