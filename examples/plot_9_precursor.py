"""
The pole's precursor under each damping law
===========================================

Before the wave front from the flattened cap can reach the pole (at
``t = phi_a / c``), an undamped membrane's pole is at rest.  The paper's modal
ratio D damps each mode by ``2 D omega``, an operator that is not local in
space: the pole sinks long before the front (2.7 mm at 0.1/c before it for the
basketball), and the tail falls only algebraically.  Rayleigh damping
``C = alpha M + beta K`` is local and causal; its ``beta K`` part smears the
front over a width ~ sqrt(beta t), a tail that falls like a Gaussian.  The
Rayleigh law here has the same ratio as D at ``omega_1 = sqrt(2)`` and at the
energy-weighted mean frequency of the motion (5.76): comparable dissipation
(see :doc:`/pressurised`).
"""

# %%
import matplotlib.pyplot as plt

import twoball
from twoball.modal.report import t_end_dimensionless
from twoball.verify.output.figures.precursor import law_curves, precursor_figure

case = twoball.Case.preset("basketball")
curves = law_curves(case)
for curve in curves:
    before = curve.precursor(case)
    print(
        f"{curve.label}: u = {before['u_before_front_0.1_m'] * 1e3:+.3f} mm at 0.1/c and "
        f"{before['u_before_front_0.6_m'] * 1e3:+.2e} mm at 0.6/c before the front"
    )
plt.figure(precursor_figure(case, curves, t_end_dimensionless(case, None)))
plt.show()
