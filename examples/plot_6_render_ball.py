"""
A picture of the bouncing ball
==============================

pyvista renders the lower ball off screen, deformed by its finite-element
radial displacement and coloured by it in mm, with the upper body (a small
sphere of radius R/5) on the pole.  No display is needed.  The displacement
is magnified for visibility; the factor is printed in each picture.
"""

# %%
import shutil
import tempfile
from pathlib import Path

import matplotlib.image as mpimg
import matplotlib.pyplot as plt
from twoball.verify.output.fields import ball_model, ball_scene, liftoff_frame
from twoball.verify.output.render import render_scene

import twoball

model = ball_model(twoball.Case.preset("basketball"), level=3, order=2, backends=("fem",))
folder = Path(tempfile.mkdtemp())

# %%
# Two instants: 5 ms after maximal compression, while the wave runs up the
# ball, and the lift-off instant of the finite elements.
pictures = {
    "t = 5 ms": render_scene(folder / "ball_5ms.png", ball_scene(model, [0.005]), size=(480, 400)),
    "lift-off": render_scene(
        folder / "ball_liftoff.png", ball_scene(model, liftoff_frame(model)), size=(480, 400)
    ),
}

fig, axes = plt.subplots(1, 2, figsize=(9, 3.9), layout="constrained")
for ax, (title, path) in zip(axes, pictures.items(), strict=True):
    ax.imshow(mpimg.imread(path))
    ax.set_title(title)
    ax.set_axis_off()
plt.show()
shutil.rmtree(folder)  # the pictures are in the figure now
