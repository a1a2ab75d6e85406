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
# :func:`twoball.plot` solves the case with both backends and writes the
# figure: the finite elements are a :class:`twoball.Superposition` (modal
# superposition) on the mesh of a :class:`twoball.MeshOptions`; its result
# carries each backend's lift-off report (SI).  The pictures of this example go to a
# scratch folder.
import shutil
import tempfile
from pathlib import Path

import matplotlib.image as mpimg
import matplotlib.pyplot as plt

import twoball

case = twoball.Case.preset("basketball")
solver = twoball.Superposition(twoball.MeshOptions("sphere", level=3, order=2))
folder = Path(tempfile.mkdtemp())
figure = twoball.PlotOptions(dpi=150)  # resolution of the PNG [dots per inch]
result = twoball.plot("pole", folder / "pole.png", case, solver=solver, figure=figure)

for name, report in result.reports.items():
    print(
        f"{name:9s} t_l = {report.t_liftoff_s * 1e3:.5f} ms, v_l = {report.v_liftoff_m_s:.5f} m/s"
    )
fem, legendre = result.reports["fem"], result.reports["legendre"]
print(f"relative difference of t_l: {abs(fem.t_liftoff_s / legendre.t_liftoff_s - 1):.1e}")

# %%
# Pole displacement, velocity and acceleration of both backends; the dots and
# dashed lines mark each backend's lift-off, the dotted line in the velocity
# panel is the body's free flight after it.  Under each quantity a smaller
# panel shows the difference finite elements minus closed form, which the
# upper panels cannot show: the curves lie on top of each other.  The file's
# suffix chooses the format (``pole.pdf`` or ``pole.svg`` for a paper, as
# ``twoball plot pole --out pole.pdf`` does); the PNG is shown here as written.
image = mpimg.imread(result.file)
height, width = image.shape[:2]
fig, ax = plt.subplots(figsize=(8, 8 * height / width), layout="constrained")
ax.imshow(image)
ax.set_axis_off()
plt.show()
shutil.rmtree(folder)  # the figure is on this page now
