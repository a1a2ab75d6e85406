"""The reproduction's parts (verify/reproduce/driver.py): single numbers, no partial output."""

import pytest

from twoball.verify.reproduce import driver as rep
from twoball.verify.reproduce.common import (
    Context,
)
from twoball.verify.sweeps.parallel import Runner


def context(tmp_path):
    return Context(tmp_path, Runner(workers=1))


def by_quantity(section):
    return {c.quantity: c for c in section.comparisons}


def test_table2_wave_speed_from_pressure(tmp_path):
    sec = rep.PARTS["table2"](context(tmp_path))
    c = by_quantity(sec)["c from P = 77200 Pa, m = 0.567 kg, R = 0.12 m"]
    assert c.paper == 320.0 and c.ours == pytest.approx(320.40, abs=0.01)
    ratio = by_quantity(sec)["t_l for the same case"]
    assert ratio.ours == pytest.approx(0.0099, abs=5e-5)


def test_fig10_bounds_are_pi_over_the_measured_times(tmp_path):
    sec = rep.PARTS["fig10"](context(tmp_path))
    q = by_quantity(sec)
    assert q["lower bound of c, pi / 0.014 s"].ours == pytest.approx(224.4, abs=0.1)
    assert q["upper bound of c, pi / 0.009 s"].ours == pytest.approx(349.1, abs=0.1)
    assert q["phi_a for |v0| = 4.1 m/s, c = 320 1/s"].ours == pytest.approx(2.5928, abs=1e-4)
    assert (tmp_path / "fig10_phi_a_vs_v0.png").stat().st_size > 10_000


def test_table1_and_icm_curves(tmp_path):
    ctx = context(tmp_path)
    table1 = rep.PARTS["table1"](ctx)
    assert len(table1.comparisons) == 12
    rows13 = [c for c in table1.comparisons if c.quantity[:5] in ("row 1", "row 2", "row 3")]
    assert all(abs(c.difference) < 0.05 for c in rows13)
    curves = rep.PARTS["icm"](ctx)
    q = by_quantity(curves)
    assert q["Fig. 3 curve at dx = 0: v1/|v0|"].ours == pytest.approx(2.1, abs=0.05)
    assert {f for f, _ in curves.figures} == {
        "fig03_icm_basketball_tennis.png",
        "fig08_icm_basketball_light.png",
    }


def test_failure_keeps_the_finished_parts_and_none_of_the_broken_one(tmp_path, monkeypatch):
    """A part that fails leaves no file of its own; the parts finished before it stay, with
    a report that names the missing part."""

    def broken(ctx):
        (ctx.directory / "half.png").write_bytes(b"x")
        raise RuntimeError("disk full")

    monkeypatch.setitem(rep.PARTS, "fig10", broken)
    with pytest.raises(RuntimeError):
        rep.reproduce(tmp_path / "rep", ["table2", "fig10"])
    assert [p.name for p in tmp_path.iterdir()] == ["rep"]
    assert not (tmp_path / "rep" / "half.png").exists()
    report = (tmp_path / "rep" / "reproduction.md").read_text()
    assert "Incomplete: 1 part(s) missing: fig10." in report
