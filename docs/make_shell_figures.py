"""Draw the shell page's figure: the top and the centre after the floor touch, membrane and shell.

The docs build runs it (docs/conf.py, ``builder-inited``) and writes
``docs/_static/shell/causality.png``; by hand (from the repository root)::

    python docs/make_shell_figures.py

The basketball dropped at 4.1 m/s: the vertical displacement of the top (the mean
over the tennis ball's 26.2 mm contact cap) and of the centre, each from the free
fall the floor interrupts, against the time after the first floor touch, for the
radial membrane (Legendre N = 192) and the shell (the default wall C/N0 = 4,
Legendre N = 128) with the adiabatic gas and without it (D = 0), with the
in-plane arrival pi R / c_e and the pressure wave's pi / c marked.  A few seconds
of work; nothing is drawn by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

TARGET = Path(__file__).resolve().parent / "_static" / "shell" / "causality.png"


def main(target: Path = TARGET) -> Path:
    """Compute the four responses and save the two-panel figure to ``target``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.balls.shell import WALLS, ShellBall
    from twoball.verify.studies.shell import responses, without_gas

    c = 320.0
    arrival = math.pi / (c * math.sqrt(WALLS["basketball"].wall_stiffness_ratio))
    runs = [
        ("membrane (radial), D = 0.13", LegendreBall(), 0.13, "C3", "-"),
        ("shell, adiabatic gas, D = 0.13", ShellBall(), 0.13, "C0", "-"),
        ("shell, no gas, D = 0", without_gas(ShellBall()), 0.0, "C0", "--"),
    ]
    figure, (top_axis, ratio_axis) = plt.subplots(2, 1, figsize=(7.0, 6.4), sharex=True)
    for label, ball, damping, colour, style in runs:
        t, top, centre = responses(ball, damping=damping)
        keep = t <= 0.012
        ms = t[keep] * 1e3
        top_axis.plot(ms, top[keep] * 1e3, color=colour, ls=style, label=f"top, {label}")
        if style == "-":
            top_axis.plot(ms, centre[keep] * 1e3, color=colour, ls=":", label=f"centre, {label}")
        ratio = np.where(centre == 0.0, 0.0, top / np.where(centre == 0.0, 1.0, centre))
        ratio_axis.plot(ms, ratio[keep], color=colour, ls=style, label=label)
    for axis in (top_axis, ratio_axis):
        axis.axvline(arrival * 1e3, color="0.4", lw=0.8)
        axis.axvline(0.5 * arrival * 1e3, color="0.7", lw=0.8, ls="--")
        axis.axvline(math.pi / c * 1e3, color="0.4", lw=0.8, ls="-.")
        axis.grid(alpha=0.3)
    top_axis.set_ylabel("vertical displacement [mm]\n(from the free fall)")
    top_axis.legend(fontsize=7, loc="lower left")
    ratio_axis.set_ylim(-2.5, 1.5)
    ratio_axis.set_ylabel("top / centre")
    ratio_axis.set_xlabel(
        "time after the first floor touch [ms]  (lines: 0.5 pi R/c_e, pi R/c_e, pi/c)"
    )
    ratio_axis.legend(fontsize=7, loc="lower right")
    top_axis.set_title("Basketball at 4.1 m/s: the top learns of the floor by a wave (shell)")
    figure.tight_layout()
    target.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(target, dpi=110)
    plt.close(figure)
    return target


if __name__ == "__main__":
    print(f"wrote {main()}")
