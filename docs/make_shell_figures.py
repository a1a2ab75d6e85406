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
    from twoball.verify.output.figures import save_figure

    target.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(causality_figure(), target, dpi=110)


def causality_figure():  # noqa: ANN201 -- a matplotlib Figure
    """The two panels, in the package's figure style (:mod:`twoball.verify.output.figures`)."""
    from twoball.verify.output.figures.style import styled

    return styled(_draw)()


def _draw():  # noqa: ANN202
    import numpy as np

    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.balls.shell import WALLS, ShellBall
    from twoball.verify.output.figures import new_figure
    from twoball.verify.output.figures.style import DIMENSIONLESS, label, time_label
    from twoball.verify.studies.shell import WithoutGas, responses

    c = 320.0
    arrival = math.pi / (c * math.sqrt(WALLS["basketball"].wall_stiffness_ratio))
    runs = [
        ("membrane (radial), D = 0.13", LegendreBall(), 0.13, "C3", "-"),
        ("shell, adiabatic gas, D = 0.13", ShellBall(), 0.13, "C0", "-"),
        ("shell, no gas, D = 0", WithoutGas(ShellBall()), 0.0, "C0", "--"),
    ]
    figure = new_figure(7.0, 6.6)
    top_axis, ratio_axis = figure.subplots(2, 1, sharex=True)
    for name, ball, damping, colour, style in runs:
        t, top, centre = responses(ball, damping=damping)
        keep = t <= 0.012
        ms = t[keep] * 1e3
        top_axis.plot(ms, top[keep] * 1e3, color=colour, ls=style, label=f"top, {name}")
        if style == "-":
            top_axis.plot(ms, centre[keep] * 1e3, color=colour, ls=":", label=f"centre, {name}")
        ratio = np.where(centre == 0.0, 0.0, top / np.where(centre == 0.0, 1.0, centre))
        ratio_axis.plot(ms, ratio[keep], color=colour, ls=style, label=name)
    marks = (
        (0.5 * arrival, {"color": "0.7", "ls": "--"}, r"$\pi R/(2 c_e)$"),
        (arrival, {"color": "0.4", "ls": "-"}, r"$\pi R/c_e$"),
        (math.pi / c, {"color": "0.4", "ls": "-."}, r"$\pi/c$"),
    )
    for axis in (top_axis, ratio_axis):
        for when, style, name in marks:
            axis.axvline(
                when * 1e3, lw=0.8, zorder=0.5, **style, label=name if axis is ratio_axis else None
            )
    top_axis.set_ylabel(label("vertical displacement from the free fall", "mm"))
    top_axis.legend(loc="upper left")
    ratio_axis.set_ylim(-2.5, 1.5)
    ratio_axis.set_ylabel(f"top / centre {DIMENSIONLESS}")
    ratio_axis.set_xlabel(time_label("after the first floor touch"))
    ratio_axis.legend(loc="lower right", ncols=2)
    top_axis.set_title("Basketball at 4.1 m/s: the top learns of the floor by a wave (shell)")
    return figure


if __name__ == "__main__":
    print(f"wrote {main()}")
