"""The converged limit N -> infinity of the Legendre series (modal/converged.py)."""

import pytest
from twoball.modal.converged import converged_legendre
from twoball.modal.parameters import preset


def test_converged_reference_settles_to_1e7():
    case = preset("basketball")
    limit = converged_legendre(case)
    assert limit.converged and limit.clear
    (_, t0, v0), (_, t1, v1) = limit.history[-2:]
    assert abs(v1 - v0) <= 1e-7 * abs(v1) and abs(t1 - t0) <= 1e-7 * t1
    assert limit.velocity * case.scalings.velocity == pytest.approx(3.94537, abs=1e-5)
