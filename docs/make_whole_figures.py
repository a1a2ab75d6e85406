"""Regenerate the whole-bounce figures of docs/whole_bounce.rst from ``twoball reproduce``.

Run from the repository root (a few minutes on two cores)::

    python docs/make_whole_figures.py            # all cores
    python docs/make_whole_figures.py --workers 1

It runs the reproduction's whole-bounce parts (``whole_table1``, ``whole_gap``,
``whole_timing``) into a temporary folder and copies their figures into
``docs/_static/whole/``: the Table 1 comparison, the Delta x curves of the
three basketball pairs and t_l against Delta x.  Nothing is drawn by hand.
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
from pathlib import Path

#: The figures the page embeds (names as ``twoball reproduce`` writes them).
FIGURES = (
    "whole_table1.png",
    "whole_gap_basketball-tennis.png",
    "whole_gap_basketball-tissue.png",
    "whole_gap_basketball-table-tennis.png",
    "whole_timing.png",
)
TARGET = Path(__file__).resolve().parent / "_static" / "whole"


def main(argv: list[str] | None = None) -> int:
    """Reproduce the three whole-bounce parts and copy their figures into the docs."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=None, help="worker processes")
    args = parser.parse_args(argv)
    import twoball

    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "reproduction"
        twoball.reproduce(
            out,
            only="whole_table1,whole_gap,whole_timing",
            workers=args.workers,
            command="python docs/make_whole_figures.py",
        )
        TARGET.mkdir(parents=True, exist_ok=True)
        for name in FIGURES:
            shutil.copyfile(out / name, TARGET / name)
            print(f"wrote {TARGET / name}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
