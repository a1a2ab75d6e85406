"""
Writing the fields and reading them back
========================================

The radial displacement of both backends on the sphere mesh, written by
:func:`twoball.export` as an XDMF time series (XML + HDF5, readable by
ParaView and pyvista) and read back from the file.  The difference between
the backends at lift-off is then plotted from the file, not from memory.
"""

# %%
# Six frames evenly spaced over the modelled window plus the lift-off instant,
# on the level-2 P2 icosphere (a quick mesh: its lift-off differs from the
# closed form by about 0.2 %), given as the mesh of the finite elements'
# solver, :class:`twoball.Superposition`.  Every point-data name ends in its SI unit.
import json
import shutil
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import twoball
from twoball.verify.output.series import read_series  # internal, see below

case = twoball.Case.preset("basketball")
folder = Path(tempfile.mkdtemp())
solver = twoball.Superposition(twoball.MeshOptions("sphere", level=2))
written = twoball.export(folder / "series.xdmf", case, solver=solver, frames=6)
print("written:", ", ".join(f"{p.name} ({p.stat().st_size} bytes)" for p in written.files))
print(f"{written.nodes} nodes, {written.cells} cells of type {written.cell_type}")
print("frames [ms]:", ", ".join(f"{1e3 * t:.3f}" for t in written.times_s))
print("point data:", ", ".join(written.point_data))

# %%
# meshio's own readers refuse these files (the case and the provenance are
# texts in every time step), so the series is read with the package's reader,
# :func:`twoball.verify.output.series.read_series`: an **internal**, whose
# name may change without notice.  pyvista and ParaView read the files as they
# are (:doc:`/gallery`).
back = read_series(folder / "series.xdmf")
print("frames:", len(back.times), "point data:", ", ".join(sorted(back.point_data)))
print("case:", back.text["case"])
provenance = json.loads(back.text["provenance"])
print("written by", provenance["call"]["function"], "of twoball", provenance["twoball"])
t_l = back.field_data["t_liftoff_s"]
t_result = written.report.t_liftoff_s  # the ExportResult's lift-off report
print(f"lift-off in the file {1e3 * t_l:.4f} ms, in the result {1e3 * t_result:.4f} ms")

# %%
# The lift-off instant is one of the frames; plot ``u_fem_m`` and
# ``u_legendre_m`` at every node against its polar angle, and their difference.
frame = int(np.argmin(np.abs(np.asarray(back.times) - t_l)))
points = back.points
phi = np.arccos(np.clip(points[:, 2] / np.linalg.norm(points, axis=1), -1.0, 1.0))
order = np.argsort(phi)

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5), layout="constrained")
top.plot(phi[order], 1e3 * back.point_data["u_legendre_m"][frame][order], label="closed form")
top.plot(phi, 1e3 * back.point_data["u_fem_m"][frame], ".", markersize=3, label="finite elements")
top.set_ylabel("u [mm]")
top.set_title(f"t = {1e3 * back.times[frame]:.3f} ms (lift-off of the finite elements)")
top.legend()
bottom.plot(phi, 1e6 * back.point_data["u_diff_m"][frame], ".", markersize=3)
bottom.set_ylabel("u_fem - u_legendre [µm]")
bottom.set_xlabel("polar angle φ [rad] (0 at the upper body)")
plt.show()
shutil.rmtree(folder)  # the files were only needed for the round trip
