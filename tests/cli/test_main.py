"""The command line's entry point (twoball/cli/main.py): one-line errors, negative values."""

import json
import shutil
import subprocess
import sys

import pytest

from twoball.cli.main import join_negative_values, main


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--radius", "0"], "--radius"),
        (["liftoff", "--radius", "-0.1"], "--radius"),
        (["liftoff", "--damping", "1"], "--damping"),
        (["liftoff", "--damping", "-0.01"], "--damping"),
        (["liftoff", "--phi-a", "1.2"], "--phi-a"),
        (["liftoff", "--phi-a", "3.2"], "--phi-a"),
        (["liftoff", "--preset", "squash"], "--preset"),
        (["liftoff", "--modes", "0"], "--modes"),
        (["liftoff", "--v0", "0"], "--v0"),
        (["liftoff", "--wave-speed", "-3"], "--wave-speed"),
        (["liftoff", "--pressure", "77200"], "--pressure"),
        (["liftoff", "--wave-speed", "300", "--pressure", "1", "--mass", "1"], "--wave-speed"),
        (["liftoff", "--t-end", "-1"], "--t-end"),
        (["liftoff", "--sigma", "hann"], "--sigma"),
        (["liftoff", "--recontact", "never"], "--recontact"),
        (["liftoff", "--damping", "abc"], "--damping"),
        (["liftoff", "--radius", "nan"], "--radius"),
        (["sweep", "--param", "damping", "--values", "0:1"], "--values"),
        (["sweep", "--param", "damping", "--values", "a:b:3"], "--values"),
        (["sweep", "--param", "damping", "--values", "0:0.5:0"], "--values"),
        (["sweep", "--param", "modes", "--values", "1:2:3"], "--values"),
        (["sweep", "--param", "mass", "--values", "0:1:3"], "--param"),
        (["sweep", "--param", "damping", "--values", "0:1:3"], "--damping"),
    ],
)
def test_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert flag in lines[0] and "Traceback" not in err


def test_console_script_error_has_no_traceback():
    exe = shutil.which("twoball")
    cmd = [exe] if exe else [sys.executable, "-m", "twoball"]
    proc = subprocess.run(
        [*cmd, "liftoff", "--damping", "2"], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 2
    assert proc.stderr.strip() == "twoball: error: --damping must be in [0, 1), got 2.0"
    assert proc.stdout == ""


def test_negative_values_join_their_option_only():
    options = {"--values", "--g"}
    assert join_negative_values(["sweep", "--values", "-1:1:3"], options) == [
        "sweep",
        "--values=-1:1:3",
    ]
    assert join_negative_values(["--g", "-1e-3"], options) == ["--g=-1e-3"]
    assert join_negative_values(["--json", "-1"], options) == ["--json", "-1"]
    assert join_negative_values(["--values", "--json"], options) == ["--values", "--json"]


def test_cli_sweep_negative_start_is_a_value_not_an_option(capsys):
    """v0 is a speed: its sign is irrelevant, so -3:-1:3 runs the same cases as 3:1:3."""
    assert main(["sweep", "--param", "v0", "--values", "-3:-1:3", "--json"]) == 0
    negative = capsys.readouterr().out
    assert main(["sweep", "--param", "v0", "--values", "3,2,1", "--json"]) == 0
    positive = capsys.readouterr().out

    def rows(text):
        data = json.loads(text)
        data = data["results"] if isinstance(data, dict) else data
        return [(r["t_liftoff_s"], r["v_liftoff_m_s"]) for r in data]

    assert rows(negative) == rows(positive)
