"""The configurations of verify (verify/checks/config.py)."""

from __future__ import annotations


def test_thorough_verify_uses_the_fast_route_at_level_5_p2():
    from twoball.verify.checks.config import config

    specs = [(t.spec.mesh, t.spec.order, t.spec.size) for t in config("thorough").krylov]
    assert ("sphere", 2, 5) in specs
