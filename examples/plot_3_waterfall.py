"""
Waterfall of the radial displacement
====================================

The radial displacement ``u(t, φ)`` of the lower ball at 24 instants spread
over the modelled window (cf. Fig. 6 of the paper): the initial flattening of
eq. (3.10) around the bottom (φ near π) runs up the ball as a wave and
reaches the upper body at the pole (φ = 0).  Lines: closed form; dots:
finite-element nodal values (level-3 P2 icosphere) against each node's polar
angle.
"""

# %%
import matplotlib.pyplot as plt
from twoball.verify.output.fields import ball_model
from twoball.verify.output.figures.waterfall import waterfall_figure

import twoball

model = ball_model(twoball.Case.preset("basketball"), level=3, order=2)
plt.figure(waterfall_figure(model))  # adopt the pyplot-free Figure for plt.show
plt.show()
