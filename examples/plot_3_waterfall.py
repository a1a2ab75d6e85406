"""
Waterfall of the radial displacement
====================================

The radial displacement ``u(t, φ)`` of the lower ball at 24 instants spread
over the modelled window (cf. Fig. 6 of the paper): the initial flattening of
eq. (3.10) around the bottom (φ near π) runs up the ball as a wave and
reaches the upper body at the pole (φ = 0).  Lines: closed form; dots:
finite-element nodal values (level-3 P2 icosphere) against each node's polar
angle; the narrow panel on the right: their difference [µm].
"""

# %%
# :func:`twoball.plot` with ``"waterfall"`` draws the figure into a file (any
# format matplotlib writes); the finite elements are a
# :class:`twoball.Superposition` on its mesh, and :class:`twoball.PlotOptions`
# sets the number of instants and the resolution of a raster file.
import shutil
import tempfile
from pathlib import Path

import matplotlib.image as mpimg
import matplotlib.pyplot as plt

import twoball

folder = Path(tempfile.mkdtemp())
result = twoball.plot(
    "waterfall",
    folder / "waterfall.png",
    twoball.Case.preset("basketball"),
    solver=twoball.Superposition(twoball.MeshOptions("sphere", level=3, order=2)),
    figure=twoball.PlotOptions(instants=24, dpi=150),
)
for label, text in result.rows:
    print(f"{label}: {text}")

image = mpimg.imread(result.file)
height, width = image.shape[:2]
fig, ax = plt.subplots(figsize=(8, 8 * height / width), layout="constrained")
ax.imshow(image)
ax.set_axis_off()
plt.show()
shutil.rmtree(folder)  # the figure is on this page now
