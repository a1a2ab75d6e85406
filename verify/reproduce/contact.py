"""Beyond the paper: v1/|v0| of an upper body of finite mass on the basketball.

The finite-mass contact solver (:mod:`twoball.modal.contact`, docs/contact.rst)
over mu = 1e-4 .. 0.2 at the default contact radius R/10, beside the massless
CEM, the ICM touching limit (2.6) and Table 1's measured basketball rows.
"""

from __future__ import annotations

import numpy as np

from twoball._common.budget import check, check_all
from twoball._common.watch import Watch
from twoball.modal.contact.body import Body
from twoball.modal.contact.cost import legendre_contact_work
from twoball.modal.contact.report import ContactReport, legendre_contact
from twoball.modal.cost import case_liftoff_work
from twoball.modal.icm.limits import touching_ratios
from twoball.modal.icm.table1 import TABLE1
from twoball.modal.parameters import Case
from twoball.modal.report import legendre_liftoff
from twoball.verify.reproduce.common import Comparison, Context, Section, new_figure, save

MASS_RATIOS = np.geomspace(1e-4, 0.2, 12)


def _contact(case: Case, body: Body) -> ContactReport:
    """The closed-form contact solution, refused first if it cannot fit, watched."""
    check_all(legendre_contact_work(case, body))
    return legendre_contact(case, body, monitor=Watch())


def part_contact(ctx: Context) -> Section:
    """The mu-curve of the finite-mass model against Table 1 (basketball rows) and the ICM."""
    case = Case.preset("basketball")
    rows = [r for r in TABLE1 if r.lower == "Basketball"]
    ratios = [_contact(case, Body(float(mu))).ratio for mu in MASS_RATIOS]
    check(*case_liftoff_work(case))
    massless = legendre_liftoff(case, reference=False, monitor=Watch()).ratio
    at_rows = {r.upper: _contact(case, Body(r.mu)).ratio for r in rows}
    fig, ax = new_figure(figsize=(6.6, 4.6))
    ax.semilogx(MASS_RATIOS, ratios, "o-", label="finite mass, a = R/10 (this model)")
    ax.axhline(massless, color="grey", ls="--", label="massless CEM (criteria (i)-(ii))")
    mu = np.geomspace(1e-4, 0.2, 100)
    for r, marker, color in zip(rows, ("s", "^", "D"), ("C2", "C3", "C4"), strict=True):
        icm = [touching_ratios(m, r.e2, r.e12)[0] for m in mu]
        label = f"ICM (2.6), e2 = {r.e2}, e12 = {r.e12}"
        ax.semilogx(mu, icm, ":", lw=1, color=color, label=label)
        ax.plot([r.mu], [r.measured_v1], marker, ms=8, color=color, label=f"measured: {r.upper}")
    ax.set_xlabel("mass ratio mu = m1/m2")
    ax.set_ylabel("v1 / |v0|")
    ax.set_title("Basketball, |v0| = 4.1 m/s, D = 0.13, N = 30")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    name = save(ctx, fig, "contact_mass_ratio.png")
    sec = Section("contact", "Beyond the paper: an upper body of finite mass (docs: contact)")
    sec.paragraphs.append(
        "The membrane model with a rigid upper body in unilateral, inelastic contact "
        "over a cap of radius R/10.  The paper has no such curve; the measured rows of "
        "Table 1 are shown for comparison (see docs/contact.rst for the discussion)."
    )
    sec.figures.append((name, "v1/|v0| against mu beside the massless CEM, ICM and Table 1."))
    for r in rows:
        sec.comparisons.append(
            Comparison(
                f"v1/|v0|, basketball + {r.upper.lower()} (mu = {r.mu:g})",
                r.measured_v1,
                at_rows[r.upper],
                "",
                "Table 1 (measured)",
                "Finite-mass membrane model, a = R/10: far below the measurement.",
            )
        )
    sec.data = {
        "mass_ratios": [float(m) for m in MASS_RATIOS],
        "ratios": [None if v is None else float(v) for v in ratios],
        "massless_ratio": massless,
    }
    return sec
