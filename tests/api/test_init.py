"""The package face (twoball/__init__.py): its public names and version."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import pytest

import twoball


def test_public_names_and_version():
    for name in ("Case", "liftoff", "sweep", "fem", "converge", "check", "export", "render"):
        assert name in dir(twoball) and getattr(twoball, name) is not None
    assert twoball.ParameterError is twoball._common.errors.ParameterError
    assert re.fullmatch(r"\d+\.\d+(\.\d+)?\S*", twoball.__version__)


# --- What a notebook sees of the results: SI first in the reprs, one file vocabulary, signatures

ONE = twoball.Superposition(twoball.MeshOptions("sphere", level=1))


def test_liftoff_report_repr_leads_with_si() -> None:
    report = twoball.liftoff()
    text = repr(report)
    assert text.startswith(
        f"LiftoffReport(lifted=True, t_liftoff_s={report.t_liftoff_s!r}, "
        f"v_liftoff_m_s={report.v_liftoff_m_s!r}, ratio={report.ratio!r}"
    )
    assert "LiftoffResult" not in text  # the dimensionless internals stay out
    assert text.index("t_liftoff_s") < text.index("case=")


def test_contact_report_repr_leads_with_si() -> None:
    report = twoball.liftoff(body=twoball.Body(0.1))
    text = repr(report)
    assert text.startswith(
        f"ContactReport(lifted=True, t_liftoff_s={report.t_liftoff_s!r}, "
        f"v_liftoff_m_s={report.v_liftoff_m_s!r}"
    )
    assert f"impacts={len(report.history.impacts)}" in text
    assert "ContactHistory" not in text and "ContactEvent" not in text


def test_sweep_point_repr_leads_with_si() -> None:
    point = twoball.sweep({"damping": [0.13]}).points[0]
    assert repr(point).startswith(f"SweepPoint(index=(0,), t_liftoff_s={point.t_liftoff_s!r}")
    assert "LiftoffResult" not in repr(point)


def test_every_file_result_has_files_and_file(tmp_path: Path) -> None:
    exported = twoball.export(tmp_path / "ball.xdmf", solver=ONE, frames=2)
    rendered = twoball.render(
        tmp_path / "ball.png", solver=ONE, view=twoball.RenderOptions(size="64x48")
    )
    legendre = twoball.PlotOptions(backends=["legendre"])
    plotted = twoball.plot("pole", tmp_path / "pole.png", solver=ONE, figure=legendre)
    assert exported.file == exported.files[0] == tmp_path / "ball.xdmf"
    assert [f.name for f in exported.files] == ["ball.xdmf", "ball.h5"]
    for result in (rendered, plotted):
        assert result.files == [result.file]
    for result in (exported, rendered, plotted):
        assert all(f.is_file() for f in result.files)
        data = result.as_dict()
        assert data["file"] == str(result.file) and data["files"] == [str(f) for f in result.files]


def test_render_takes_warp_auto_as_the_command_line_does(tmp_path: Path) -> None:
    view = twoball.RenderOptions(warp="auto", size="64x48")
    auto = twoball.render(tmp_path / "auto.png", solver=ONE, view=view)
    default = twoball.render(
        tmp_path / "default.png", solver=ONE, view=twoball.RenderOptions(size="64x48")
    )
    assert auto.warp == default.warp > 1.0
    assert (tmp_path / "auto.png").read_bytes() == (tmp_path / "default.png").read_bytes()


@pytest.mark.parametrize("verb", ["check", "converge"])
def test_studies_have_real_signatures_and_return_types(verb: str) -> None:
    from twoball import _studies

    shown = inspect.signature(getattr(twoball, verb))
    runs = inspect.signature(getattr(_studies, verb))
    assert list(shown.parameters) == list(runs.parameters)
    assert "args" not in shown.parameters and "kwargs" not in shown.parameters
    expected = {"check": "VerifyResult", "converge": "StudyResult"}[verb]
    assert shown.return_annotation == expected == runs.return_annotation
    assert re.search(r"Parameters\n\s*-+\n\s*case : Case", getattr(twoball, verb).__doc__)
