"""Options of pictures and figures: :class:`RenderOptions` and :class:`PlotOptions`.

Validated when built (:class:`~twoball.ParameterError` naming the field and
its range); the verbs :func:`twoball.render` and :func:`twoball.plot` take
them as one argument each.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from twoball._common.choices import FIELD_BACKENDS
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked

__all__ = [
    "BACKENDS",
    "FPS_RANGE",
    "MAX_FRAMES",
    "PlotOptions",
    "RenderOptions",
    "check_frame_choice",
]

#: Frames per second of an animation.
FPS_RANGE = (1e-3, 1e3)
#: Most frames of an export or an animation.
MAX_FRAMES = 2000
#: The solvers of the field outputs: finite elements and the closed form.
BACKENDS = FIELD_BACKENDS


def check_frame_choice(frames: Any, name: str = "frames") -> int | tuple[float, ...] | None:
    """A frame count in [1, :data:`MAX_FRAMES`] or frame times >= 0 [s] (None: the default).

    The times are checked against the modelled window when the case is known
    (:func:`twoball.verify.output.fields.check_times`).
    """
    from numbers import Integral, Real

    if frames is None:
        return None
    valid = f"a frame count in [1, {MAX_FRAMES}] or a non-empty list of times >= 0 [s]"
    if isinstance(frames, Integral) and not isinstance(frames, bool):
        if not 1 <= int(frames) <= MAX_FRAMES:
            raise ParameterError(name, valid, frames)
        return int(frames)
    if isinstance(frames, (str, bytes, set, frozenset, dict)) or not hasattr(frames, "__len__"):
        raise ParameterError(name, valid, frames)
    times = list(frames)
    if not times or any(isinstance(t, bool) or not isinstance(t, Real) for t in times):
        raise ParameterError(name, valid, times)
    if not all(0.0 <= float(t) < float("inf") for t in times):
        raise ParameterError(name, valid, [float(t) for t in times])
    return tuple(float(t) for t in times)


@checked
@dataclass(frozen=True)
class RenderOptions:
    """Which instants are drawn, and how: one picture or an animation.

    Parameters
    ----------
    warp : float or "auto", optional
        Displacement magnification, a finite number >= 0; default (or
        ``"auto"``) automatic (:meth:`~twoball.verify.output.render.BallScene.auto_warp`:
        the wave after the initial flattening drawn at 15 % of R); a given warp
        must draw the largest displacement within R.
    size : (int, int) or "WxH", optional
        Image size in pixels, each side in [16, 4096] (default 640 x 480;
        MP4: rounded up to multiples of 16).
    fps : float, optional
        Frames per second of an animation, in [0.001, 1000] (default 20);
        not with a PNG.
    frames : int or sequence of float, optional
        A PNG: one time [s] in a sequence (default the lift-off).  An
        animation: a count of frames in [1, 2000] evenly spaced over [0,
        t_end] (default 60), or the frame times [s] (each >= 0 and within the
        modelled window, checked when the case is known).

    Examples
    --------
    >>> import twoball
    >>> twoball.RenderOptions(size="800x600", warp=2.0).size
    (800, 600)
    >>> twoball.RenderOptions(frames=[0.004, 0.01], fps=10).as_dict()["frames"]
    [0.004, 0.01]
    >>> twoball.RenderOptions(warp=-1)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: warp must be a finite number >= 0 (or auto), got -1
    """

    warp: float | str | None = None
    size: Any = None
    fps: float | None = None
    frames: Any = None

    def __post_init__(self) -> None:
        from twoball._common.errors import bounded
        from twoball.verify.output.render import check_size, check_warp

        warp = None if self.warp == "auto" else self.warp
        object.__setattr__(self, "warp", check_warp(warp, "warp"))
        if self.size is not None:
            object.__setattr__(self, "size", check_size(self.size, "size"))
        if self.fps is not None:
            object.__setattr__(self, "fps", bounded("fps", self.fps, *FPS_RANGE))
        object.__setattr__(self, "frames", check_frame_choice(self.frames))

    def as_dict(self) -> dict[str, Any]:
        """The fields (None: the default), for JSON and provenance."""
        size = None if self.size is None else list(self.size)
        frames = list(self.frames) if isinstance(self.frames, tuple) else self.frames
        return {"warp": self.warp, "size": size, "fps": self.fps, "frames": frames}


@checked
@dataclass(frozen=True)
class PlotOptions:
    """What a figure of :func:`twoball.plot` shows and at what resolution.

    Parameters
    ----------
    dpi : float, optional
        Resolution of raster formats (PNG, ...) [dots per inch], 50 to 1200;
        default 300.
    instants : int, optional
        Curves of the waterfall (default 24, as in Fig. 6), >= 2; ``waterfall`` only.
    levels : sequence of int, optional
        ``eigen`` only: icosphere levels in [0, 10] (default 1, 2, 3), as
        :class:`~twoball.MeshOptions` takes them.
    orders : sequence of int, optional
        ``eigen`` only: element orders 1 to 4 (default 1, 2).
    max_degree : int, optional
        ``eigen`` only: the largest degree l, >= 1.
    backends : sequence of {"fem", "legendre"}, optional
        ``waterfall`` and ``pole``: the solvers drawn (default both; with both,
        a panel of their difference).

    Examples
    --------
    >>> import twoball
    >>> twoball.PlotOptions(dpi=150, instants=12).as_dict()["instants"]
    12
    >>> twoball.PlotOptions(instants=1)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: instants must be an integer >= 2, got 1
    """

    dpi: float | None = None
    instants: int | None = None
    levels: Any = None
    orders: Any = None
    max_degree: int | None = None
    backends: Any = None

    def __post_init__(self) -> None:
        from twoball.verify.output.figures import check_dpi

        if self.dpi is not None:
            object.__setattr__(self, "dpi", check_dpi(self.dpi, "dpi"))
        instants = self.instants
        if instants is not None and (
            isinstance(instants, bool) or not isinstance(instants, int) or instants < 2
        ):
            raise ParameterError("instants", "an integer >= 2", instants)
        from twoball.fem_membrane.validate import LEVEL_RANGE, ORDER_RANGE, check_level, check_order

        low, high = LEVEL_RANGE
        valid = {
            "levels": f"a non-empty list of sphere levels, integers in [{low}, {high}]",
            "orders": f"a non-empty list of element orders, each {ORDER_RANGE}",
        }
        for name, check in (("levels", check_level), ("orders", check_order)):
            values = getattr(self, name)
            if values is None:
                continue
            try:
                if isinstance(values, (str, bytes, set, frozenset, dict)) or len(values) == 0:
                    raise TypeError
                checked = tuple(check(v) for v in values)
            except (ParameterError, TypeError):
                raise ParameterError(name, valid[name], values) from None
            object.__setattr__(self, name, checked)
        degree = self.max_degree
        if degree is not None and (
            isinstance(degree, bool) or not isinstance(degree, int) or degree < 1
        ):
            raise ParameterError("max_degree", "an integer >= 1", degree)
        if self.backends is not None:
            chosen = self.backends
            valid = "one of " + ", ".join(BACKENDS) + " or a non-empty list of them"
            if isinstance(chosen, str):  # one name (or "fem,legendre", as typed on a command line)
                chosen = [b.strip() for b in chosen.split(",")]
            if isinstance(chosen, (bytes, set, frozenset, dict)) or not hasattr(chosen, "__len__"):
                raise ParameterError("backends", valid, chosen)
            chosen = tuple(dict.fromkeys(chosen))
            if not chosen or any(not isinstance(b, str) or b not in BACKENDS for b in chosen):
                given = self.backends
                raise ParameterError(
                    "backends", valid, given if isinstance(given, str) else list(given)
                )
            object.__setattr__(self, "backends", chosen)

    def given(self) -> dict[str, Any]:
        """The fields that were given."""
        return {k: v for k, v in self.as_dict().items() if v is not None}

    def as_dict(self) -> dict[str, Any]:
        """The fields (None: the default), for JSON and provenance."""
        return {
            "dpi": self.dpi,
            "instants": self.instants,
            "levels": None if self.levels is None else list(self.levels),
            "orders": None if self.orders is None else list(self.orders),
            "max_degree": self.max_degree,
            "backends": None if self.backends is None else list(self.backends),
        }
