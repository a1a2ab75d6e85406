"""Draw the figure of the fit page: the worked example's data and the fitted model.

The docs build runs it (docs/conf.py, ``builder-inited``) and writes
``docs/_static/fit/drops_fit.png`` from ``docs/_static/fit/drops.csv``; by hand
(from the repository root)::

    python docs/make_fit_figures.py

It is ``twoball fit --data docs/_static/fit/drops.csv --param damping --param
wave-speed --plot docs/_static/fit/drops_fit.png``: the closed-form lift-off
fitted to eight drops by least squares, D and c with their standard errors, the
residuals below (about ten seconds of work).  Nothing is drawn by hand.
"""

from __future__ import annotations

from pathlib import Path

FOLDER = Path(__file__).resolve().parent / "_static" / "fit"
DATA = FOLDER / "drops.csv"
TARGET = FOLDER / "drops_fit.png"


def main(target: Path = TARGET) -> Path:
    """Fit D and c to the worked example's rows and save the figure to ``target``."""
    import matplotlib

    matplotlib.use("Agg")
    import twoball

    result = twoball.fit(DATA, ["damping", "wave-speed"])
    return result.plot(target, dpi=120)


if __name__ == "__main__":
    print(f"wrote {main()}")
