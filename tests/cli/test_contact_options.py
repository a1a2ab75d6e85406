"""The upper-body option group (twoball/cli/contact_options.py): where it applies, its limits."""

from __future__ import annotations

import pytest

from twoball.cli.main import main

REFUSED = [
    (["plot", "eigen", "--mass-ratio", "0.1"], "--mass-ratio"),
    (["plot", "waterfall", "--mass-ratio", "0.1"], "--mass-ratio"),
    (["plot", "pole", "--mass-ratio", "0.1", "--contact-radius", "1"], "--contact-radius"),
    (["export", "--contact-radius", "0.01"], "--contact-radius"),
    (["export", "--mass-ratio", "0"], "--mass-ratio"),
    (["export", "--mass-ratio", "0.1", "--route", "krylov"], "--route"),
    (["render", "--mass-ratio", "0.1", "--recontact", "paper"], "--recontact"),
    (["render", "--mass-ratio", "-1"], "--mass-ratio"),
]


@pytest.mark.parametrize(("argv", "flag"), REFUSED)
def test_options_that_do_not_apply_are_refused(argv, flag, tmp_path, capsys):
    out = tmp_path / {"export": "x.xdmf", "render": "x.png", "plot": "p.png"}[argv[0]]
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--out", str(out)])
    assert stop.value.code == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and flag in err, err
    assert list(tmp_path.iterdir()) == []


def test_cli_option_constants_match_the_model():
    """The option group offers the model's own limits (modal/contact/body.py), both read
    from twoball/_common/choices.py."""
    from twoball._common import choices
    from twoball.cli.main import full_parser
    from twoball.modal.contact import body

    assert choices.MAX_MASS_RATIO is body.MAX_MASS_RATIO and body.MAX_MASS_RATIO == 100.0
    assert choices.ENERGY_OPTIONS is body.ENERGY_OPTIONS == ("ball", "both")
    (sub,) = (a for a in full_parser()._actions if hasattr(a, "choices") and a.choices)
    energy = next(a for a in sub.choices["liftoff"]._actions if "--energy" in a.option_strings)
    assert "ball or both" in energy.help
