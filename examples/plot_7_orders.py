"""
Error per unknown and per second, P1 to P4
==========================================

The same lift-off computed on icospheres with elements of order 1 to 4
(isoparametric: the geometry has the order of the elements), each against the
Legendre series with the same N = 30 and filter -- the limit of the finite
elements as h -> 0.  Left: the relative error of the lift-off time and
velocity against the number of unknowns; right: against the CPU seconds the whole
finite-element solve took (mesh, assembly, load, the rational Krylov route,
lift-off search) on the machine that built these pages.  Higher orders reach
a given error with fewer unknowns and in less time; the P3 velocity profits
least, its geometric error being O(h^4) like P2's (see the method page).
"""

# %%
# :func:`twoball.liftoff` with the solver :class:`twoball.Superposition`
# (modal superposition on finite elements) carries the mesh as a
# :class:`twoball.MeshOptions` and the eigen route (``route="krylov"``);
# ``extra["dofs"]`` of its report is the number of unknowns.
import time

import matplotlib.pyplot as plt

import twoball

case = twoball.Case.preset("basketball")
exact = twoball.liftoff(case)  # Legendre series, N = 30, Lanczos filter
LEVELS = {1: (3, 4, 5), 2: (2, 3, 4), 3: (2, 3), 4: (1, 2, 3)}

rows = {}
for order, levels in LEVELS.items():
    rows[order] = []
    for level in levels:
        mesh = twoball.MeshOptions("sphere", level=level, order=order)
        start = time.process_time()
        report = twoball.liftoff(case, solver=twoball.Superposition(mesh, route="krylov"))
        seconds = time.process_time() - start
        t_error = abs(report.t_liftoff_s / exact.t_liftoff_s - 1.0)
        v_error = abs(report.v_liftoff_m_s / exact.v_liftoff_m_s - 1.0)
        rows[order].append((report.extra["dofs"], seconds, t_error, v_error))
        print(f"P{order} level {level}: {report.extra['dofs']:6d} DOFs, {seconds:6.2f} s, "
              f"t_l error {t_error:.1e}, v_l error {v_error:.1e}")  # fmt: skip

# %%
# Solid lines: t_l; dashed: v_l.
fig, axes = plt.subplots(1, 2, figsize=(10, 4), layout="constrained", sharey=True)
for order, data in rows.items():
    dofs, seconds, t_err, v_err = zip(*data, strict=True)
    line = axes[0].loglog(dofs, t_err, "o-", label=f"P{order}")[0]
    axes[0].loglog(dofs, v_err, "s--", color=line.get_color())
    axes[1].loglog(seconds, t_err, "o-", color=line.get_color(), label=f"P{order}")
    axes[1].loglog(seconds, v_err, "s--", color=line.get_color())
axes[0].set_xlabel("unknowns (DOFs)")
axes[1].set_xlabel("CPU seconds (finite-element solve) [s]")
axes[0].set_ylabel("relative error against Legendre N = 30 [–]")
axes[0].legend(title="solid t_l, dashed v_l")
plt.show()
