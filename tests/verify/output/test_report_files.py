"""Report folders (verify/output/report_files.py): written whole, never over a user's folder."""

import pytest

from twoball.verify.output.report_files import write_report_dir


def test_old_report_survives_a_failed_write(tmp_path):
    out = tmp_path / "report"
    write_report_dir(out, {"a.txt": lambda p: p.write_text("old")})

    def broken(path):
        path.write_text("half")
        raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_report_dir(out, {"a.txt": lambda p: p.write_text("new"), "b.txt": broken})
    assert (out / "a.txt").read_text() == "old" and not (out / "b.txt").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]
    write_report_dir(out, {"c.txt": lambda p: p.write_text("newer")})
    assert sorted(p.name for p in out.iterdir()) == [".twoball-output", "c.txt"]


def test_out_refuses_a_folder_that_is_not_a_report(tmp_path):
    from twoball._common.errors import ParameterError
    from twoball._common.staging import MARKER
    from twoball.verify.output.report_files import check_output_dir, write_report_dir

    foreign = tmp_path / "home"
    foreign.mkdir()
    (foreign / "thesis.tex").write_text("precious")
    with pytest.raises(ParameterError, match="out"):
        check_output_dir(foreign)
    assert (foreign / "thesis.tex").read_text() == "precious"
    report = tmp_path / "report"
    write_report_dir(report, {"a.txt": lambda p: p.write_text("1")})
    assert (report / MARKER).is_file()
    write_report_dir(report, {"a.txt": lambda p: p.write_text("2")})  # an earlier report
    assert (report / "a.txt").read_text() == "2"
