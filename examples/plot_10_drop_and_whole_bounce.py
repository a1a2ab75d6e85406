"""
The drop on the floor and the whole bounce, on both backends
============================================================

Beyond the paper's start, :func:`twoball.bounce` drops the lower ball on a
rigid floor with its centre free and follows it until it has left
(:doc:`/bounce`); with a body on top it is the whole two-ball bounce, the
body's launch an output of one contact problem (:doc:`/whole_bounce`).  The
ball is an object: :class:`twoball.LegendreBall` (the membrane on its
Legendre modes) or :class:`twoball.FEBall` (the same membrane on axisymmetric
finite elements), stepped by the one nonsmooth integrator,
:class:`twoball.MoreauJean`.  Both balls hand the contact core the same kind
of modal description, so the two backends differ only by their
discretisation.
"""

# %%
# The basketball dropped alone at 4.1 m/s (Table 2), then the pair of row 6 of
# Table 1, a table-tennis ball on the basketball, released touching it.  Each
# solver carries its ball and its defaults: N = 192 Legendre modes, or 96
# quadratic line elements (the same node spacing, pi / 192), the time step
# 0.005 / c.
import matplotlib.pyplot as plt

import twoball
from twoball.verify.output.figures.style import STYLE  # internal, see below

case = twoball.Case.preset("basketball")
balls = {"Legendre": twoball.LegendreBall(), "finite elements": twoball.FEBall()}
drops, wholes = {}, {}
for name, ball in balls.items():
    solver = twoball.MoreauJean(ball)
    drops[name] = twoball.bounce(case, solver=solver)
    wholes[name] = twoball.bounce(case, solver=solver, pair="basketball-table-tennis")

print(f"{'':31s}{'contact [ms]':>13s}{'e2':>8s}{'v1/|v0|':>9s}{'v2/|v0|':>9s}")
for title, reports in (("drop", drops), ("whole bounce", wholes)):
    for name, r in reports.items():
        v1 = "" if r.v1_ratio is None else f"{r.v1_ratio:9.4f}"
        v2 = "" if r.v2_ratio is None else f"{r.v2_ratio:9.4f}"
        print(
            f"{title + ', ' + name:31s}{r.contact_time_s * 1e3:13.3f}{r.e2:8.4f}{v1:>9s}{v2:>9s}"
            f"   ({r.model['resolution']})"
        )

# %%
# The backends' agreement: the largest relative difference of each number
# between the Legendre modes and the finite elements.  The drop alone has no
# body, so no v1.
for title, reports in (("drop", drops), ("whole bounce", wholes)):
    legendre, fem = reports["Legendre"], reports["finite elements"]
    names = ["contact_time_s", "e2"] + (["v1_ratio", "v2_ratio"] if legendre.has_body else [])
    gaps = {n: abs(getattr(fem, n) / getattr(legendre, n) - 1.0) for n in names}
    print(f"{title}: " + ", ".join(f"{n} {g:.1e}" for n, g in gaps.items()))
icm = wholes["Legendre"].icm_solver  # eqs. (2.1)-(2.5) with this run's e2 and e12
if icm is None:
    print("the body's and the floor's collisions overlap: the ICM (2.5) does not apply")
else:
    print(f"ICM with the run's own e2 and e12: v1/|v0| = {icm['v1_ratio']:.4f}")

# %%
# The history behind these numbers.  Each :class:`twoball.BounceReport` has
# its own figure (:meth:`~twoball.BounceReport.plot`, as ``twoball bounce
# --plot``); here the two backends are drawn on top of each other instead,
# from the report's dimensionless run ``result`` (length R, time 1/c, mass
# m2).  The run's attributes and the figure style ``STYLE`` are
# **internals**: their names may change without notice.  Top: the floor's
# force on the ball alone; middle: in the whole bounce, the gap between the
# body and the ball's top (zero while they touch); bottom: the velocities of
# the ball's centre and of the body.  Solid lines: Legendre; dashed: finite
# elements.  They lie on top of each other, apart from a few dips of the
# finite elements' force: each one is a step shortened to the instant a floor
# node touches (the force drawn is a step's impulse over its length).
c, R, speed = case.wave_speed, case.radius, case.scalings.velocity
styles = {"Legendre": "-", "finite elements": "--"}
with plt.rc_context(STYLE):
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7.5, 7.5), layout="constrained")
    for name, style in styles.items():
        drop = drops[name].result
        t_mid, force = drop.force
        newtons = drops[name].mass_kg * R * c**2  # the run's unit of force, m2 R c^2
        axes[0].plot(1e3 * t_mid / c, force * newtons, ls=style, color="C0", label=name)
        whole = wholes[name].result
        system, run = whole.system, whole.trajectory
        t_ms = 1e3 * run.t / c
        axes[1].plot(t_ms, 1e3 * R * system.body_gap(run.q), ls=style, color="C1", label=name)
        axes[2].plot(t_ms, run.v[:, system.centre] * speed, ls=style, color="C0",
                     label=f"ball's centre, {name}")  # fmt: skip
        axes[2].plot(t_ms, run.v[:, system.body_coordinate] * speed, ls=style, color="C1",
                     label=f"body, {name}")  # fmt: skip
    axes[0].set_title("The basketball alone: the floor's force")
    axes[1].set_title("A table-tennis ball on the basketball: the body above the ball's top")
    axes[2].set_title("The whole bounce: velocities")
    axes[0].set_ylabel("$F$ [N]")
    axes[1].set_ylabel("gap [mm]")
    axes[2].set_ylabel("velocity [m/s]")
    axes[2].set_xlabel("$t$ [ms] after the first floor touch")
    for ax in axes:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    plt.show()
