"""The order of the examples gallery: by the number in each script's name (plot_10 after plot_9)."""

from __future__ import annotations

import re


def example_number(filename: str) -> tuple[int, str]:
    """``plot_10_drop.py`` -> ``(10, "plot_10_drop.py")``; a name without a number sorts last."""
    found = re.match(r"plot_(\d+)", str(filename))
    return (int(found.group(1)) if found else 10**6, str(filename))
