"""Options of pictures and figures: :class:`RenderOptions` and :class:`PlotOptions`.

Validated when built (:class:`~twoball.ParameterError` naming the field and
its range); the verbs :func:`twoball.render` and :func:`twoball.plot` take
them as one argument each.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from twoball._common.errors import ParameterError

__all__ = ["FPS_RANGE", "PlotOptions", "RenderOptions"]

#: Frames per second of an animation.
FPS_RANGE = (1e-3, 1e3)


@dataclass(frozen=True)
class RenderOptions:
    """How a picture or an animation is drawn.

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

    Examples
    --------
    >>> import twoball
    >>> twoball.RenderOptions(size="800x600", warp=2.0).size
    (800, 600)
    >>> twoball.RenderOptions(warp=-1)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: warp must be a finite number >= 0 (or auto), got -1
    """

    warp: float | str | None = None
    size: Any = None
    fps: float | None = None

    def __post_init__(self) -> None:
        from twoball.verify.output.render import check_size, check_warp

        from twoball._common.errors import bounded

        warp = None if self.warp == "auto" else self.warp
        object.__setattr__(self, "warp", check_warp(warp, "warp"))
        if self.size is not None:
            object.__setattr__(self, "size", check_size(self.size, "size"))
        if self.fps is not None:
            object.__setattr__(self, "fps", bounded("fps", self.fps, *FPS_RANGE))

    def as_dict(self) -> dict[str, Any]:
        """The fields (None: the default), for JSON and provenance."""
        size = None if self.size is None else list(self.size)
        return {"warp": self.warp, "size": size, "fps": self.fps}


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
        }
