"""
A picture of the bouncing ball
==============================

pyvista renders the lower ball off screen, deformed by its finite-element
radial displacement and coloured by it in mm, with the upper body (a small
sphere of radius R/5) on the pole.  No display is needed.  The displacement
is magnified for visibility; the factor is printed in each picture.
"""

# %%
# :func:`twoball.render` solves the case with the finite elements of a
# :class:`twoball.Superposition` (on the mesh of a
# :class:`twoball.MeshOptions`) and writes a PNG (one instant: ``frames`` is a
# list of one time in seconds, by default the lift-off) or an animation
# (``.gif``, ``.mp4``: a frame count or a list of times).
# :class:`twoball.RenderOptions` sets the warp factor, the image size in
# pixels and the frames per second of an animation.
import shutil
import tempfile
from pathlib import Path

import matplotlib.image as mpimg
import matplotlib.pyplot as plt

import twoball

case = twoball.Case.preset("basketball")
solver = twoball.Superposition(twoball.MeshOptions("sphere", level=3, order=2))
view = twoball.RenderOptions(size=(480, 400))
at_5_ms = twoball.RenderOptions(size=(480, 400), frames=[0.005])
folder = Path(tempfile.mkdtemp())

# %%
# Two instants: 5 ms after maximal compression, while the wave runs up the
# ball, and the lift-off instant of the finite elements (the default).
pictures = {
    "t = 5 ms": twoball.render(folder / "ball_5ms.png", case, solver=solver, view=at_5_ms),
    "lift-off": twoball.render(folder / "ball_liftoff.png", case, solver=solver, view=view),
}
for title, result in pictures.items():
    print(f"{title}: t = {1e3 * result.times_s[0]:.3f} ms, warp x{result.warp:.1f}, {result.size}")

fig, axes = plt.subplots(1, 2, figsize=(9, 4.2), layout="constrained")
for ax, (title, result) in zip(axes, pictures.items(), strict=True):
    ax.imshow(mpimg.imread(result.file))
    ax.set_title(title)
    ax.set_axis_off()
plt.show()
shutil.rmtree(folder)  # the pictures are in the figure now
