"""``twoball bounce --body rigid|lumped|ball``, ``--body-*`` and ``--floor-alone``."""

from __future__ import annotations

import json

import pytest

from twoball.cli.main import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_a_pairs_lumped_body(capsys):
    code, out, err = run(
        capsys, "bounce", "--pair", "basketball-tennis", "--body", "lumped", "--modes", "16",
        "--json",
    )  # fmt: skip
    assert code == 0, err
    data = json.loads(out)
    assert data["body"]["kind"] == "lumped" and data["body"]["body_restitution"] == 0.83
    assert data["provenance"]["command"].startswith("twoball bounce --pair")
    code, out, _ = run(
        capsys, "bounce", "--pair", "basketball-tennis", "--body", "lumped", "--modes", "16",
        "--body-restitution", "0.9",
    )  # fmt: skip
    assert code == 0 and "its restitution on a rigid floor" in out and "0.9" in out


def test_floor_alone(capsys):
    code, out, err = run(
        capsys, "bounce", "--pair", "tennis-coin", "--body", "lumped", "--floor-alone", "--json"
    )
    assert code == 0, err
    data = json.loads(out)
    assert data["restitution"] == pytest.approx(0.6, abs=1e-3)
    assert data["provenance"]["command"].endswith("--floor-alone --json")
    code, out, _ = run(
        capsys, "bounce", "--body", "lumped", "--mass-ratio", "0.01", "--body-law", "hertz",
        "--body-radius", "0.01", "--body-modulus", "1e6", "--body-poisson", "0.4",
        "--body-restitution", "0.7", "--floor-alone",
    )  # fmt: skip
    assert code == 0 and "restitution" in out and "0.7" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--pair", "tennis-coin", "--body", "ball"], "--body must be rigid or lumped"),
        (["--body", "lumped", "--body-modes", "8"], "--body-modes must be given with --body ball"),
        (["--pair", "tennis-coin", "--body", "lumped", "--restitution", "0.5"], "--restitution"),
        (["--body", "lumped"], "--mass-ratio must be given"),
        (["--body", "lumped", "--mass-ratio", "0.1"], "--body-law must be given"),
        (["--body-restitution", "0.5"], "--body-restitution must be given with --body lumped"),
        (["--body", "soft"], "--body must be one of rigid, lumped, ball"),
        (
            [
                "--body",
                "lumped",
                "--mass-ratio",
                "0.1",
                "--body-law",
                "pressure",
                "--body-radius",
                "-1",
                "--body-pressure",
                "1e5",
                "--body-restitution",
                "0.8",
            ],
            "--body-radius must be",
        ),  # fmt: skip
        (["--pair", "tennis-coin", "--floor-alone"], "--floor-alone must be given with --body"),
        (["--pair", "basketball-tennis", "--body", "ball", "--mass-ratio", "0.1"], "--mass-ratio"),
    ],
)
def test_refusals_name_the_flag(capsys, argv, message):
    with pytest.raises(SystemExit) as stop:
        main(["bounce", *argv])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and len(err.strip().splitlines()) == 1, err
    assert err.startswith(f"twoball: error: {message}"), err
