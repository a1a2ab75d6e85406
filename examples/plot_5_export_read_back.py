"""
Writing the fields and reading them back
========================================

The radial displacement of both backends on the sphere mesh, written by
meshio as an XDMF time series (XML + HDF5, readable by ParaView and pyvista)
and read back into a :class:`twoball.verify.output.series.TimeSeries`.  The
difference between the backends at lift-off is then plotted from the file,
not from memory.
"""

# %%
import shutil
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from twoball.verify.output.fields import ball_model, field_series, frame_times
from twoball.verify.output.series import read_series, write_series

import twoball

case = twoball.Case.preset("basketball")
model = ball_model(case, level=2, order=2)
series = field_series(model, frame_times(model, frames=6))

folder = Path(tempfile.mkdtemp())
written = write_series(folder / "series.xdmf", series)
print("written:", ", ".join(f"{p.name} ({p.stat().st_size} bytes)" for p in written))

back = read_series(folder / "series.xdmf")
print("frames:", len(back.times), "point data:", ", ".join(sorted(back.point_data)))
print(
    "largest change on the round trip [m]:",
    float(np.abs(back.point_data["u_m"] - series.point_data["u_m"]).max()),
)

# %%
# The lift-off time is stored with the file; pick the frame nearest to it and
# plot ``u_fem_m`` and ``u_legendre_m`` at every node against its polar angle.
t_l = back.field_data["t_liftoff_s"]
frame = int(np.argmin(np.abs(np.asarray(back.times) - t_l)))
points = back.points
phi = np.arccos(np.clip(points[:, 2] / np.linalg.norm(points, axis=1), -1.0, 1.0))
order = np.argsort(phi)

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5), layout="constrained")
top.plot(phi[order], 1e3 * back.point_data["u_legendre_m"][frame][order], label="closed form")
top.plot(phi, 1e3 * back.point_data["u_fem_m"][frame], ".", markersize=3, label="finite elements")
top.set_ylabel("u [mm]")
top.set_title(f"t = {1e3 * back.times[frame]:.3f} ms (lift-off at {1e3 * t_l:.3f} ms)")
top.legend()
bottom.plot(phi, 1e6 * back.point_data["u_diff_m"][frame], ".", markersize=3)
bottom.set_ylabel("u_fem - u_legendre [µm]")
bottom.set_xlabel("polar angle φ [rad] (0 at the upper body)")
plt.show()
shutil.rmtree(folder)  # the files were only needed for the round trip
