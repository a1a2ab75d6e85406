"""
Finite elements against the closed form at the pole
====================================================

The same damped membrane problem, eq. (3.9) with the initial flattening of
eq. (3.10), solved by scikit-fem on a level-3 icosphere with quadratic
elements (2562 unknowns) and by the Legendre series.  Both backends hand
their pole motion to the same lift-off search, so the two lift-off times
below differ only by the discretisation error of the finite elements.
"""

# %%
import matplotlib.pyplot as plt
from twoball.verify.output.fields import ball_model
from twoball.verify.output.figures.pole import pole_figure

import twoball

case = twoball.Case.preset("basketball")
model = ball_model(case, level=3, order=2)

for name, backend in model.backends.items():
    report = backend.report
    print(
        f"{name:9s} t_l = {report.t_liftoff_s * 1e3:.5f} ms, v_l = {report.v_liftoff_m_s:.5f} m/s"
    )
fem, legendre = model.backends["fem"].report, model.backends["legendre"].report
print(f"relative difference of t_l: {abs(fem.t_liftoff_s / legendre.t_liftoff_s - 1):.1e}")

# %%
# Pole displacement, velocity and acceleration of both backends; the dots and
# dashed lines mark each backend's lift-off, the dotted line in the velocity
# panel is the body's free flight after it.  Under each quantity a smaller
# panel shows the difference finite elements minus closed form, which the
# upper panels cannot show: the curves lie on top of each other.  The figure
# functions of :mod:`twoball.verify.output.figures` return a pyplot-free
# :class:`matplotlib.figure.Figure` in the one style of the package
# (``save_figure`` writes it as PDF, SVG, PNG, ... by the file suffix, as
# ``twoball plot pole --out pole.pdf`` does); ``plt.figure`` adopts it so that
# ``plt.show`` displays it.
plt.figure(pole_figure(model))
plt.show()
