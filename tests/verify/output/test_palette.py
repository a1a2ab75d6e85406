"""The palettes of an animated GIF (verify/output/palette.py): no banding, exact colours."""

from __future__ import annotations

import imageio.v3 as iio
import numpy as np

from twoball.verify.output.palette import (
    FIXED_COLOURS,
    colour_map_samples,
    gif_bytes,
    gif_palette,
    nearest_indices,
)


def shaded_frames(count: int = 3) -> np.ndarray:
    """Frames like a rendered ball: a lit sphere coloured by a smooth field on white, with a
    black caption and an unlit colour bar; the field moves from frame to frame."""
    from matplotlib import colormaps

    h, w = 160, 200
    y, x = np.mgrid[0:h, 0:w]
    frames = np.full((count, h, w, 3), 255, np.uint8)
    inside = (x - 90) ** 2 + (y - 85) ** 2 < 60**2
    light = np.clip(1.0 - ((x - 70) ** 2 + (y - 60) ** 2) / (2 * 80.0**2), 0.25, 1.0)
    for k in range(count):
        field = 0.5 + 0.15 * np.sin((y + 7 * k) / 30.0) * np.cos((x - 5 * k) / 45.0)
        rgb = colormaps["coolwarm"](field)[..., :3] * light[..., None]
        frames[k][inside] = np.round(255 * rgb[inside]).astype(np.uint8)
        frames[k, 5:12, 5:60] = 0  # the caption
        bar = colormaps["coolwarm"](np.linspace(1.0, 0.0, 120))[:, :3]
        frames[k, 20:140, 180:190] = np.round(255 * bar)[:, None, :]
    return frames


def test_gif_keeps_a_smooth_ball_without_bands():
    frames = shaded_frames()
    gif = iio.imread(gif_bytes(frames, 10.0, "coolwarm"), index=None, extension=".gif")[..., :3]
    error = np.abs(gif.astype(int) - frames.astype(int))
    ball = np.any(frames < 250, axis=-1)
    # one palette for all frames, looked up by Pillow (its colour cache drops low bits):
    # 0.92 levels on average, 2.3 on the ball, up to 20, about 218 shades of the ball
    assert error.mean() < 0.7, error.mean()
    assert error[ball].mean() < 1.7, error[ball].mean()
    assert error[ball].max() <= 12, error[ball].max()
    for frame, original in zip(gif, frames, strict=True):
        assert np.all(frame[original.min(axis=-1) == 255] == 255)  # background exact
        assert np.all(frame[5:12, 5:60] == 0)  # caption exact
        shades = len(np.unique(frame[ball[0]].reshape(-1, 3), axis=0))
        assert shades >= 230, shades


def test_palette_keeps_the_reserved_colours_and_maps_exactly():
    frame = shaded_frames(1)[0]
    reserved = np.concatenate([colour_map_samples("coolwarm"), np.array(FIXED_COLOURS, np.uint8)])
    palette = gif_palette(frame, reserved)
    assert palette.shape == (256, 3)
    held = {tuple(c) for c in palette}
    assert all(tuple(c) in held for c in reserved)
    index = nearest_indices(frame, palette)
    distance = np.linalg.norm(palette[index].astype(float) - frame, axis=-1)
    best = np.min(
        np.linalg.norm(frame[..., None, :].astype(float) - palette[None, None], axis=-1), axis=-1
    )
    np.testing.assert_allclose(distance, best)
