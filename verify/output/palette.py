"""The palettes of an animated GIF: each frame its own 256 colours, the colour map kept exact.

A GIF stores at most 256 colours per frame.  Two things band a smoothly shaded
ball: a palette shared by all frames spends its entries on every frame's
colours at once, and Pillow maps pixels onto a given palette through a cache
keyed by the colour with its low bits dropped, so that neighbouring shades
fall into one entry (the white background became 253).  :func:`gif_bytes`
therefore gives each frame its own palette (a local colour table):
``BAR_COLOURS`` exact samples of the colour map (the colour bar stays smooth)
and white and black (background and text stay exact), plus a median cut of the
frame's pixels refined by one k-means pass, and maps every pixel to its
nearest palette colour exactly (Euclidean in RGB), without dithering (text
stays crisp).
"""

from __future__ import annotations

import io

import numpy as np

BAR_COLOURS = 64  # palette entries kept for the colour map (the rest: the frame's own)
#: Colours kept exactly in every frame: the background white and the text black.
FIXED_COLOURS = ((255, 255, 255), (0, 0, 0))
#: Pixels sampled from a frame for its median cut (enough for 256 colours, and fast).
CUT_SAMPLE = 100_000


def gif_palette(frames: np.ndarray, reserved: np.ndarray) -> np.ndarray:
    """A 256-colour palette (256, 3) for ``frames`` (..., 3): ``reserved`` plus a median cut.

    ``reserved`` (the colour map of the bar, :data:`FIXED_COLOURS`) is kept
    exactly; the remaining entries are the median cut of the pixels, refined
    by one k-means pass.  Unused entries are black.
    """
    from PIL import Image

    reserved = np.unique(np.asarray(reserved, dtype=np.uint8).reshape(-1, 3), axis=0)
    free = 256 - len(reserved)
    pixels = np.asarray(frames, dtype=np.uint8).reshape(-1, 3)
    sample = pixels[:: max(1, pixels.shape[0] // CUT_SAMPLE)]
    side = int(np.ceil(np.sqrt(sample.shape[0])))
    padded = np.concatenate([sample, np.repeat(sample[-1:], side * side - len(sample), axis=0)])
    image = Image.fromarray(padded.reshape(side, side, 3))
    cut = image.quantize(colors=free, method=Image.Quantize.MEDIANCUT, kmeans=1)
    palette = np.asarray(cut.getpalette()[: 3 * free], dtype=np.uint8).reshape(-1, 3)
    palette = np.concatenate([reserved, palette])
    return np.concatenate([palette, np.zeros((256 - len(palette), 3), np.uint8)])


def nearest_indices(frame: np.ndarray, palette: np.ndarray) -> np.ndarray:
    """Index (H, W), uint8, of the palette colour nearest to each pixel of ``frame`` (H, W, 3).

    Exact (Euclidean distance in RGB), searched once per distinct colour.
    """
    from scipy.spatial import cKDTree

    rgb = np.asarray(frame, dtype=np.uint8)
    packed = (rgb[..., 0].astype(np.int32) << 16) | (rgb[..., 1].astype(np.int32) << 8)
    packed |= rgb[..., 2]
    distinct, back = np.unique(packed.ravel(), return_inverse=True)
    colours = np.stack([(distinct >> 16) & 255, (distinct >> 8) & 255, distinct & 255], axis=1)
    _, index = cKDTree(np.asarray(palette, dtype=float)).query(colours.astype(float))
    return np.asarray(index, dtype=np.uint8)[back].reshape(rgb.shape[:2])


def colour_map_samples(name: str, count: int = BAR_COLOURS) -> np.ndarray:
    """``count`` evenly spaced colours (count, 3), uint8, of the matplotlib colour map ``name``."""
    from matplotlib import colormaps

    rgb = colormaps[name](np.linspace(0.0, 1.0, count))[:, :3]
    return np.round(rgb * 255).astype(np.uint8)


def gif_bytes(frames: np.ndarray, fps: float, colour_map: str) -> bytes:
    """An animated GIF of ``frames`` (F, H, W, 3) uint8 at ``fps``, looping, a palette per frame."""
    from PIL import Image

    reserved = np.concatenate([colour_map_samples(colour_map), np.array(FIXED_COLOURS, np.uint8)])
    indexed = []
    for frame in frames:
        palette = gif_palette(frame, reserved)
        index = nearest_indices(frame, palette)
        image = Image.frombytes("P", (index.shape[1], index.shape[0]), index.tobytes())
        image.putpalette(palette.ravel().tolist())
        indexed.append(image)
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
