"""twoball.verify: the verb and the subpackage are one name; its progress steps."""

from __future__ import annotations

import twoball


def test_verify_is_callable_and_the_subpackage(tmp_path):
    # twoball.verify is both the verb and the subpackage twoball.verify.* (already imported)
    import twoball.verify.checks.run as checks

    assert twoball.verify.checks.run is checks
    result = twoball.verify(fast=True, out=tmp_path / "report")
    assert result.passed and (tmp_path / "report" / "report.md").is_file()
    settings = result.as_dict()["settings"]
    assert settings["phi_a_source"] == "measured (basketball)"
    assert callable(twoball.converge) and callable(twoball.fem.solve)


def test_verify_steps_counts_the_progress_calls(tmp_path):
    import twoball
    from twoball._studies import verify_steps

    said: list[str] = []
    twoball.verify(fast=True, progress=said.append, out=tmp_path / "report")
    assert len(said) == verify_steps(fast=True) and said[-1].startswith("writing ")
    assert verify_steps(fast=True, out=False) == len(said) - 1
    assert said[0].startswith("Legendre series N = 30")
