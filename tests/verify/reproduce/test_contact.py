"""The contact part of the reproduction (verify/reproduce/contact.py)."""

from __future__ import annotations

import twoball
from twoball import Body
from twoball.modal.parameters import Case

BASKETBALL = Case.preset("basketball")


def test_reproduce_contact_part(tmp_path):
    """The reproduce figure's curve is the API's, and falls with the mass ratio."""
    from twoball.verify.reproduce.common import Context
    from twoball.verify.reproduce.contact import part_contact
    from twoball.verify.sweeps.parallel import Runner

    with Runner(workers=1) as runner:
        section = part_contact(Context(tmp_path, runner))
    ratios = section.data["ratios"]
    assert (tmp_path / "contact_mass_ratio.png").stat().st_size > 0
    mu = section.data["mass_ratios"][-1]
    assert ratios[-1] == twoball.liftoff(BASKETBALL, body=Body(mu)).ratio
    assert all(b < a for a, b in zip(ratios, ratios[1:], strict=False))
