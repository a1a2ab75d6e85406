"""
Stiffer balls: bending and the enclosed gas
===========================================

The paper's membrane fits a basketball.  A tennis ball also has a bending-stiff
rubber wall and, like every ball, a gas inside whose compression resists the
breathing mode n = 0.  This example computes the rebound ratio ``v_l / |v0|``
and the lift-off time t_l of the closed form (Legendre series with
``omega_n^2 = n (n+1) (1 + beta (n (n+1) - 2))`` and ``omega_0^2`` of the gas,
see :doc:`/stiff_balls`) against the bending ratio beta and against the
excess pressure P, for the ``tennis`` preset beside the basketball.  The
dotted lines are the estimated time the ball stays on the floor after maximal
compression, ``pi / (2 c)``: lift-off after it means the rigid-body bounce has
already taken over (the paper's "question of timing").
"""

# %%
# The two balls.  The basketball is built from its measured pressure and mass
# (Table 2: P = 77.2 kPa, m = 0.567 kg), so that bending and gas can be given
# for it too; the tennis ball is the preset (pressurised, rubber wall, gas
# compressed adiabatically).
import matplotlib.pyplot as plt
import numpy as np

import twoball

MASS = {"basketball": 0.567, "tennis": 0.0577}
PRESSURE = {"basketball": 77200.0, "tennis": 82700.0}
GAS = {"basketball": "none", "tennis": "adiabatic"}


def ball(name: str, pressure: float | None = None, **changes) -> twoball.Case:
    """The ball at excess pressure P [Pa] (c by eq. (3.8)), with ``changes``."""
    p = PRESSURE[name] if pressure is None else pressure
    base = "basketball" if name == "basketball" else "tennis"
    return twoball.Case.from_pressure(p, MASS[name], preset=base, **changes)


def outcome(case: twoball.Case) -> tuple[float, float, float]:
    """``v_l / |v0|`` [–], t_l [ms] and the floor time [ms] (NaN without lift-off)."""
    report = twoball.liftoff(case)  # the closed form (Legendre series)
    if not report.lifted:
        return np.nan, np.nan, case.floor_time * 1e3
    return report.ratio, report.t_liftoff_s * 1e3, case.floor_time * 1e3


for name in MASS:
    case = ball(name, gas=GAS[name])
    ratio, t_l, floor = outcome(case)
    print(
        f"{name}: c = {case.wave_speed:.0f} 1/s, beta = {case.stiffness.beta:.4f}, "
        f"omega_0^2 = {case.stiffness.gas:.2f}: v_l/|v0| = {ratio:.3f}, "
        f"t_l = {t_l:.3f} ms, floor ~ {floor:.3f} ms"
    )

# %%
# Against the bending ratio beta = B / (T R^2), T = P R / 2: B is set so that
# each ball has the beta on the axis (gas as for the ball).
betas = np.linspace(0.0, 0.04, 17)
fig, axes = plt.subplots(2, 2, figsize=(9, 6.5), layout="constrained", sharex="col")
for k, name in enumerate(MASS):
    tension = PRESSURE[name] * ball(name).radius / 2.0
    rows = [
        outcome(ball(name, bending=b * tension * ball(name).radius ** 2, gas=GAS[name]))
        for b in betas
    ]
    ratio, t_l, floor = np.array(rows).T
    axes[0, 0].plot(betas, ratio, "o-", color=f"C{k}", label=name)
    axes[1, 0].plot(betas, t_l, "o-", color=f"C{k}", label=f"{name}: t_l")
    axes[1, 0].plot(betas, floor, ":", color=f"C{k}", label=f"{name}: floor pi/(2c)")
axes[0, 0].set_ylabel("v_l / |v0| [–]")
axes[1, 0].set_ylabel("time after maximal compression [ms]")
axes[1, 0].set_xlabel("bending ratio beta = B / (T R^2) [–]")
axes[1, 0].set_yscale("log")
axes[0, 0].legend()

# %%
# Against the excess pressure P: c follows from P, m and R (eq. (3.8)); the
# tennis ball keeps its wall (B fixed, so beta = 2 B / (P R^3) falls as P
# rises) and its gas; the basketball stays the paper's membrane.
pressures = np.linspace(30e3, 150e3, 13)
for k, name in enumerate(MASS):
    bending = twoball.Case.preset("tennis").bending if name == "tennis" else 0.0
    rows = [outcome(ball(name, p, bending=bending, gas=GAS[name])) for p in pressures]
    ratio, t_l, floor = np.array(rows).T
    axes[0, 1].plot(pressures / 1e3, ratio, "o-", color=f"C{k}", label=name)
    axes[1, 1].plot(pressures / 1e3, t_l, "o-", color=f"C{k}", label=f"{name}: t_l")
    axes[1, 1].plot(pressures / 1e3, floor, ":", color=f"C{k}", label=f"{name}: floor")
axes[1, 1].set_xlabel("excess pressure P [kPa]")
axes[1, 1].set_yscale("log")
axes[1, 1].legend(fontsize="small")
fig.suptitle("Closed form with bending and gas: tennis ball beside basketball")
plt.show()

# %%
# The gas alone changes the tennis ball most: its breathing mode re-expands
# the flattened ball at once and the top's first deceleration launches the
# body within a millisecond, well before the ball leaves the floor; bending
# stiffens the short waves.  Without either the tennis ball behaves like a
# small basketball and lifts off after it has left the floor.
for changes in ({}, {"gas": "none"}, {"bending": 0.0}, {"gas": "none", "bending": 0.0}):
    settings = {"bending": twoball.Case.preset("tennis").bending, "gas": "adiabatic", **changes}
    ratio, t_l, floor = outcome(ball("tennis", **settings))
    print(f"tennis {changes or 'preset'}: v_l/|v0| = {ratio:.3f}, t_l = {t_l:.3f} ms")
