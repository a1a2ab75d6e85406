"""Regenerate the elastic-body figures of docs/bodies.rst from the study's runs.

Run from outside the checkout with the package installed (about half an hour
on two busy cores; with a kept cache, seconds)::

    python docs/make_body_figures.py --cache runs.json --workers 2

It runs (or reads from ``--cache``) the whole bounces of
:mod:`twoball.verify.studies.bodies` -- the three basketball pairs against
Delta x with each body kind (Figs. 3 and 8), every pair at large gaps and at
Delta x = 0 -- and draws into ``docs/_static/bodies/``:

* ``bodies_gap_<pair>.png``: v1 / |v0| and v2 / |v0| against Delta x with the
  rigid, lumped and ball bodies, the ICM (2.5) with Table 1's e12, and Table
  1's point at Delta x -> 0;
* ``bodies_e12.png``: the mean ``e12_effective`` at 100-250 mm of each pair and
  kind against the measured e12;
* ``bodies_table1.png``: v1 / |v0| at Delta x = 0 of each pair and kind
  against the measurements and the ICM printed.

Nothing is drawn by hand.
"""

from __future__ import annotations

import argparse
from pathlib import Path

TARGET = Path(__file__).resolve().parent / "_static" / "bodies"
STYLE = {"rigid": ("C0", "o"), "lumped": ("C3", "s"), "ball": ("C2", "^")}


def gap_figure(pair: str, data: dict, path: Path) -> None:
    """v1 and v2 against the gap with each kind, the ICM and Table 1's point."""
    import matplotlib.pyplot as plt
    import numpy as np

    from twoball.modal.icm.impacts import icm_velocities
    from twoball.modal.pairs import PAIRS

    p = PAIRS[pair]
    v0, g = 4.1, 9.81
    gaps = np.linspace(0.0, 0.25, 101)
    icm = np.array([icm_velocities(x, v0, p.e2, p.e12, p.mu, g) for x in gaps]) / v0
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharex=True)
    for ax, index, label in ((axes[0], "v1", "v1 / |v0|"), (axes[1], "v2", "v2 / |v0|")):
        column = 0 if index == "v1" else 1
        ax.plot(gaps * 1e3, icm[:, column], "k--", lw=1, label="ICM (2.5), Table 1's e12")
        for kind, curve in data.items():
            colour, marker = STYLE[kind]
            ax.plot(
                np.array(curve["gap"]) * 1e3,
                curve[index],
                color=colour,
                marker=marker,
                ms=4,
                label=f"{kind} body",
            )
        measured = p.table1.measured_v1 if index == "v1" else p.table1.measured_v2
        ax.plot([0.0], [measured], "k*", ms=12, label="Table 1, measured (gap -> 0)")
        ax.set_xlabel("gap Delta x [mm]")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{pair}: the whole bounce with each body kind, |v0| = 4.1 m/s")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def e12_figure(means: dict, path: Path) -> None:
    """Mean e12_effective at 100-250 mm of each pair and kind against the measured e12."""
    import matplotlib.pyplot as plt

    from twoball.modal.pairs import PAIRS

    fig, ax = plt.subplots(figsize=(6, 5))
    for kind, (colour, marker) in STYLE.items():
        xs = [PAIRS[p].e12 for p in means if kind in means[p]]
        ys = [means[p][kind] for p in means if kind in means[p]]
        ax.plot(xs, ys, color=colour, marker=marker, ls="none", ms=7, label=f"{kind} body")
    for pair in means:  # Table 1's row number beside its highest point
        ax.annotate(f"row {PAIRS[pair].row}", (PAIRS[pair].e12, max(means[pair].values())),
                    fontsize=7, xytext=(4, 4 if PAIRS[pair].row != 6 else -10),
                    textcoords="offset points")  # fmt: skip
    ax.plot([0, 1], [0, 1], "k--", lw=1, label="e12_effective = measured e12")
    ax.set_xlim(0.3, 1.0)
    ax.set_ylim(0.0, 1.0)
    ax.set_xlabel("measured e12 (Table 1)")
    ax.set_ylabel("e12_effective, mean over 100-250 mm")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def table1_figure(rows: dict, path: Path) -> None:
    """v1 / |v0| at Delta x = 0 of each pair and kind, the measurements and the ICM printed."""
    import matplotlib.pyplot as plt

    from twoball.modal.pairs import PAIRS

    names = list(rows)
    fig, ax = plt.subplots(figsize=(9, 4.5))
    x = range(len(names))
    ax.plot(x, [PAIRS[n].table1.measured_v1 for n in names], "k*", ms=12, label="measured")
    ax.plot(x, [PAIRS[n].table1.icm_v1 for n in names], "kx", ms=9, label="ICM printed")
    for k, (kind, (colour, marker)) in enumerate(STYLE.items()):
        xs = [i + 0.12 * (k - 1) for i, n in enumerate(names) if kind in rows[n]]
        ys = [rows[n][kind] for n in names if kind in rows[n]]
        ax.plot(xs, ys, color=colour, marker=marker, ls="none", ms=7, label=f"{kind} body")
    ax.set_xticks(list(x), [f"{PAIRS[n].row}: {n}" for n in names], rotation=20, fontsize=8)
    ax.set_ylabel("v1 / |v0| at Delta x = 0")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    """Run the study's whole bounces (or read them) and draw the three kinds of figure."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cache", default=None, help="JSON file of the runs (kept)")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    args = parser.parse_args(argv)
    import matplotlib

    matplotlib.use("Agg")
    from twoball.modal.pairs import PAIRS
    from twoball.verify.studies.bodies import LARGE, Runs, curves, kinds_of

    runs = Runs(args.cache, args.workers)
    TARGET.mkdir(parents=True, exist_ok=True)
    for pair, data in curves(runs).items():
        path = TARGET / f"bodies_gap_{pair}.png"
        gap_figure(pair, data, path)
        print(f"wrote {path}")
    runs.ensure([(p, k, g, "legendre") for p in PAIRS for k in kinds_of(p) for g in LARGE])
    means: dict[str, dict[str, float]] = {}
    for pair in PAIRS:
        means[pair] = {}
        for kind in kinds_of(pair):
            values = [runs.get(pair, kind, g)["e12"] for g in LARGE]
            values = [v for v in values if v is not None]
            if values:
                means[pair][kind] = sum(values) / len(values)
    e12_figure(means, TARGET / "bodies_e12.png")
    print(f"wrote {TARGET / 'bodies_e12.png'}")
    runs.ensure([(p, k, 0.0, "legendre") for p in PAIRS for k in kinds_of(p)])
    rows = {p: {k: runs.get(p, k, 0.0)["v1"] for k in kinds_of(p)} for p in PAIRS}
    table1_figure(rows, TARGET / "bodies_table1.png")
    print(f"wrote {TARGET / 'bodies_table1.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
