"""One palette for a whole GIF, holding the colour map of the colour bar.

A GIF stores at most 256 colours per frame.  Quantised frame by frame (what
Pillow does by default), the shaded ball takes most entries and the colour
bar is left with a dozen bands, which also change from frame to frame.
:func:`gif_bytes` instead builds one palette for all frames: ``BAR_COLOURS``
exact samples of the colour map plus a median cut of every frame's pixels,
and maps each frame onto it without dithering (text stays crisp).
"""

from __future__ import annotations

import io

import numpy as np

BAR_COLOURS = 96  # palette entries kept for the colour map (the rest: median cut)


def gif_palette(frames: np.ndarray, reserved: np.ndarray) -> np.ndarray:
    """A 256-colour palette (256, 3) for every frame of a GIF: ``reserved`` plus a median cut.

    The reserved colours (the colour map of the bar) are kept exactly, so the
    colour bar stays smooth; the rest is the median cut of all frames' pixels.
    One palette for all frames: colours do not flicker from frame to frame.
    """
    from PIL import Image

    reserved = np.asarray(reserved, dtype=np.uint8).reshape(-1, 3)
    free = 256 - len(reserved)
    pixels = frames.reshape(-1, 3)
    step = max(1, pixels.shape[0] // 400_000)  # a sample is enough for the median cut
    sample = pixels[::step]
    side = int(np.ceil(np.sqrt(sample.shape[0])))
    padded = np.concatenate([sample, np.repeat(sample[-1:], side * side - len(sample), axis=0)])
    image = Image.fromarray(padded.reshape(side, side, 3))
    cut = image.quantize(colors=free, method=Image.Quantize.MEDIANCUT)
    palette = np.asarray(cut.getpalette()[: 3 * free], dtype=np.uint8).reshape(-1, 3)
    palette = np.concatenate([reserved, palette])
    return np.concatenate([palette, np.zeros((256 - len(palette), 3), np.uint8)])


def colour_map_samples(name: str, count: int = BAR_COLOURS) -> np.ndarray:
    """``count`` evenly spaced colours (count, 3), uint8, of the matplotlib colour map ``name``."""
    from matplotlib import colormaps

    rgb = colormaps[name](np.linspace(0.0, 1.0, count))[:, :3]
    return np.round(rgb * 255).astype(np.uint8)


def gif_bytes(frames: np.ndarray, fps: float, colour_map: str) -> bytes:
    """An animated GIF of ``frames`` (F, H, W, 3) uint8 at ``fps``, looping, one palette."""
    from PIL import Image

    palette = Image.new("P", (1, 1))
    palette.putpalette(gif_palette(frames, colour_map_samples(colour_map)).ravel().tolist())
    indexed = [
        Image.fromarray(f).quantize(palette=palette, dither=Image.Dither.NONE) for f in frames
    ]
    buffer = io.BytesIO()
    indexed[0].save(
        buffer,
        format="GIF",
        save_all=True,
        append_images=indexed[1:],
        duration=round(1000.0 / fps),
        loop=0,
        optimize=False,
    )
    return buffer.getvalue()
