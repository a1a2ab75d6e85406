"""
Lift-off from the closed form
=============================

The closed-form continuum elastic model (CEM) of §3 of the paper: the pole
motion of the lower ball is the filtered, damped Legendre series of
eqs. (3.12)-(3.16), and the upper body lifts off at the first instant where
the pole decelerates faster than gravity (criterion (i)) and the body's free
flight clears the ball (criterion (ii)).  No mesh is involved: this is the
reference every other backend is checked against.
"""

# %%
# The case: the ``basketball`` preset (Table 2 of the paper), in SI units.
import matplotlib.pyplot as plt
import numpy as np

import twoball
from twoball.modal.filters import SpectralFilter  # internal, see below
from twoball.modal.legendre import legendre_series  # internal, see below
from twoball.verify.output.figures.style import STYLE  # internal, see below

case = twoball.Case.preset("basketball")
print(f"R = {case.radius} m, c = {case.wave_speed} 1/s, |v0| = {case.v0} m/s")
print(f"phi_a = {case.phi_a} rad, D = {case.damping}, N = {case.modes}")

# %%
# Lift-off time (after maximal compression) and launch velocity of the upper
# body, from :func:`twoball.liftoff` with its default backend, the Legendre
# series.  The rebound ratio ``v_l / |v0|`` is the quantity of Figs. 11 and 12.
report = twoball.liftoff(case)
print(f"lifted: {report.lifted}")
print(f"t_l = {report.t_liftoff_s * 1e3:.4f} ms")
print(f"v_l = {report.v_liftoff_m_s:.4f} m/s (v_l / |v0| = {report.ratio:.4f})")

# %%
# The pole motion behind that number.  The public API returns the lift-off,
# not the whole pole curve, so this figure uses two **internals** (their names
# may change without notice): the series of
# :func:`twoball.modal.legendre.legendre_series` with the filter
# :class:`twoball.modal.filters.SpectralFilter`, and the plot style of the
# package's own figures.  The series works in dimensionless units (length R,
# time 1/c); ``case.scalings`` converts to SI.  Lift-off needs the pole
# acceleration to fall below ``-g``.
plt.rcParams.update(STYLE)

series = legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", case.modes))
scale = case.scalings
t = np.linspace(0.0, 4.0 * np.pi, 2000)  # the default window, 4 pi / c
u, u_t, u_tt = series.pole(t)
ms = t * scale.time * 1e3
t_l_ms = report.t_liftoff_s * 1e3

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), layout="constrained")
top.plot(ms, u_t * scale.velocity)
top.plot(t_l_ms, report.v_liftoff_m_s, "o", color="C3", label="lift-off")
top.set_ylabel("pole velocity $u_t$ [m/s]")
top.legend()
bottom.plot(ms, u_tt * scale.acceleration)
bottom.axhline(-case.g, color="k", linestyle=":", label="$-g$ (criterion (i))")
bottom.axvline(t_l_ms, color="C3", linestyle="--")
bottom.set_ylim(-40 * case.g, 40 * case.g)
bottom.set_ylabel("pole acceleration $u_{tt}$ [m/s$^2$]")
bottom.set_xlabel("time $t$ after maximal compression [ms]")
bottom.legend()
plt.show()

# %%
# The launch depends on the impact speed.  :func:`twoball.sweep` solves the
# closed form at every value; away from the preset's measured speed the
# contact angle phi_a follows from eq. (3.7), as in Fig. 12 of the paper
# (each point's ``case.phi_a_source`` says which rule gave phi_a).
speeds = np.linspace(1.0, 8.0, 15)
swept = twoball.sweep({"v0": speeds}, case)
ratios = [point.ratio for point in swept.points]  # NaN where nothing lifts off
print({point.case.phi_a_source for point in swept.points})

fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
ax.plot(speeds, ratios, "o-")
ax.set_xlabel("impact speed $|v_0|$ [m/s]")
ax.set_ylabel("rebound ratio $v_l/|v_0|$ [–]")
plt.show()
