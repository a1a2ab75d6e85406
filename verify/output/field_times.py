"""Frame times of the field commands (export, render, plot), in seconds.

The frames of a :class:`twoball.verify.output.fields.BallModel`: evenly spaced
over the modelled window [0, t_end] (plus the lift-off), or given times, each
checked against the window; the one list syntax of ``--times``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless

from twoball._common.errors import ParameterError

if TYPE_CHECKING:
    from twoball.verify.output.fields import BallModel

DEFAULT_FRAMES = 25
MAX_FRAMES = 2000


def check_frames(frames: object, flag: str = "--frames") -> int:
    """Number of frames: an integer in [1, 2000]."""
    if isinstance(frames, bool) or not isinstance(frames, int | np.integer):
        raise ParameterError(flag, f"an integer in [1, {MAX_FRAMES}]", frames)
    if not (1 <= int(frames) <= MAX_FRAMES):
        raise ParameterError(flag, f"an integer in [1, {MAX_FRAMES}]", frames)
    return int(frames)


def parse_times(text: str, flag: str = "--times") -> tuple[float, ...]:
    """Times [s] in the one list syntax: ``0,0.005,0.01`` or ``0:0.01:3``.

    Each must be a finite number >= 0; they are returned sorted, without duplicates.
    """
    from twoball._common.ranges import SYNTAX, parse_values

    valid = "times >= 0 in seconds, e.g. 0,0.005,0.01 or 0:0.01:11"
    values = parse_values(text, flag, valid=valid)
    if any(v < 0 for v in values):
        raise ParameterError(flag, f"{SYNTAX} ({valid})", text)
    return tuple(sorted(set(values)))


def window_s(case: Case, t_end_s: float | None = None) -> float:
    """The modelled window [s]: ``t_end_s``, or 4 pi / c by default."""
    return t_end_dimensionless(case, t_end_s) * case.scalings.time


def check_times(end: float, times_s: Sequence[float], flag: str = "--times") -> np.ndarray:
    """``times_s`` [s] as a sorted array, each inside the modelled window [0, ``end``]."""
    times = np.asarray(sorted({float(t) for t in times_s}), dtype=float)
    if times.size == 0 or np.any(~np.isfinite(times)) or times.min() < 0 or times.max() > end:
        raise ParameterError(
            flag, f"times in [0, {end:.6g}] s (the modelled window)", list(times_s)
        )
    return times


def frame_times(
    model: BallModel,
    frames: int | None = None,
    times_s: Sequence[float] | None = None,
    backend: str = "fem",
    include_liftoff: bool = True,
) -> np.ndarray:
    """Frame times [s]: given ``times_s``, or ``frames`` evenly spaced over [0, t_end].

    With ``frames`` (default 25) the lift-off time of ``backend`` is added as an
    extra frame when ``include_liftoff`` is set and the body lifts off.
    """
    if times_s is not None:
        return check_times(model.t_end_s, times_s)
    count = DEFAULT_FRAMES if frames is None else check_frames(frames)
    times = np.linspace(0.0, model.t_end_s, count) if count > 1 else np.array([0.0])
    report = model.backend(backend).report
    if include_liftoff and report.result.lifted:
        times = np.union1d(times, [report.t_liftoff_s])
    return times


def liftoff_frame(model: BallModel, backend: str = "fem") -> np.ndarray:
    """The lift-off time [s] of ``backend`` as a one-frame array (t = 0 if no lift-off)."""
    report = model.backend(backend).report
    return np.array([report.t_liftoff_s if report.result.lifted else 0.0])
