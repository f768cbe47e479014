"""The independent score for string art: how a nail sequence looks as real thread on a real board.

Every generator (StepDeck's, the plain greedy, the kaspar98 reimplementation)
judges its own lines with its own internal picture; comparing those pictures
would let each grade its own homework.  This module draws the finished
sequence again, its own way, and scores that:

* the board is 260 mm across, the nails evenly round its rim, nail 0 at
  three o'clock and counting counter-clockwise (StepDeck's geometry for a
  circle), drawn ``SIZE`` pixels across (0.5 mm a pixel);
* each chord is a 0.15 mm thread: at every pixel step along the chord's
  major axis, the thread's area there (its width in pixels over the cosine
  of its slant) is shared among the pixels across it by a tent of their
  centres' perpendicular distance to the chord (one pixel either side) -- a
  wider, smoother footprint than the two-pixel Wu split that StepDeck's own
  line table uses, and exactly the thread's area whatever the slant;
* threads stack as filters: a pixel under opacities a1, a2 ... is
  ``1 - (1 - a1)(1 - a2)...`` dark;
* the picture is blurred by a Gaussian of 1 pixel, for the eye standing back;
* against the photo's darkness (its square crop resampled to the same
  raster, no contrast change), RMSE and SSIM are taken over the pixels
  inside the nail circle only.

Benchmark code: not imported by the station.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from PIL import Image

from app.string_art_generator.quality import gaussian_blur, ssim_map

BOARD_MM = 260.0
THREAD_MM = 0.15
SIZE = 520  # pixels across the board: 0.5 mm each
BLUR_PX = 1.0
#: Chords drawn in one numpy pass (bounds the memory of the samples).
BATCH = 256


@dataclass(frozen=True)
class Score:
    rmse: float  # root-mean-square darkness error on the board, 0 … 1
    ssim: float  # structural similarity on the board, 1 (same) … -1

    def __str__(self) -> str:
        return f"RMSE {self.rmse:.4f} SSIM {self.ssim:.4f}"


def nail_points(nails: int, size: int = SIZE) -> np.ndarray:
    """(nails, 2) nail centres as (column, row) pixels on the score's raster."""
    centre = (size - 1) / 2.0
    radius = size / 2.0 - 1.0
    angle = 2.0 * np.pi * np.arange(nails) / nails
    return np.column_stack((centre + radius * np.cos(angle), centre - radius * np.sin(angle)))


def board_mask(size: int = SIZE) -> np.ndarray:
    centre = (size - 1) / 2.0
    rows, columns = np.mgrid[0:size, 0:size]
    inside: np.ndarray = np.hypot(rows - centre, columns - centre) <= size / 2.0 - 1.0
    return inside


def thread_picture(sequence: np.ndarray | list[int] | tuple[int, ...], nails: int) -> np.ndarray:
    """(SIZE, SIZE) darkness 0 … 1 of the wound sequence, before the blur."""
    points = nail_points(nails)
    order = np.asarray(sequence, dtype=np.int64)
    width_px = THREAD_MM / (BOARD_MM / SIZE)
    log_light = np.zeros(SIZE * SIZE, dtype=np.float64)
    for begin in range(0, len(order) - 1, BATCH):
        chunk = order[begin : begin + BATCH + 1]
        pixels, opacity = _chords(points[chunk[:-1]], points[chunk[1:]], width_px)
        log_light += np.bincount(pixels, weights=np.log1p(-opacity), minlength=SIZE * SIZE)
    return (1.0 - np.exp(log_light)).reshape(SIZE, SIZE)


def _chords(a: np.ndarray, b: np.ndarray, width_px: float) -> tuple[np.ndarray, np.ndarray]:
    """Flat pixel indices and opacities of the chords ``a[k]`` → ``b[k]`` (tent footprint)."""
    keep = np.hypot(*(b - a).T) > 0.5
    a, b = a[keep], b[keep]
    d = b - a
    steep = np.abs(d[:, 1]) > np.abs(d[:, 0])
    # Walk the major axis one pixel at a time; the minor axis is where the chord is there.
    major_a = np.where(steep, a[:, 1], a[:, 0])
    major_b = np.where(steep, b[:, 1], b[:, 0])
    minor_a = np.where(steep, a[:, 0], a[:, 1])
    slope = np.where(steep, d[:, 0], d[:, 1]) / np.where(steep, d[:, 1], d[:, 0])
    cos = 1.0 / np.sqrt(1.0 + slope * slope)
    low = np.ceil(np.minimum(major_a, major_b)).astype(np.int64)
    high = np.floor(np.maximum(major_a, major_b)).astype(np.int64)
    counts = np.maximum(high - low + 1, 0)
    chord = np.repeat(np.arange(len(a)), counts)
    offset = np.arange(int(counts.sum())) - np.repeat(np.cumsum(counts) - counts, counts)
    major = low[chord] + offset
    minor = minor_a[chord] + (major - major_a[chord]) * slope[chord]
    base = np.floor(minor).astype(np.int64)
    across = base[:, None] + np.arange(-1, 3)[None, :]
    tent = np.maximum(0.0, 1.0 - np.abs(across - minor[:, None]) * cos[chord][:, None])
    # Each step along the major axis holds the thread's area there (width / cos), shared
    # by the tent: normalised, so the share does not depend on where the chord crosses.
    share = tent / tent.sum(axis=1, keepdims=True) * (width_px / cos[chord])[:, None]
    inside = (tent > 0) & (across >= 0) & (across < SIZE)
    is_steep = np.broadcast_to(steep[chord][:, None], across.shape)
    major_2d = np.broadcast_to(major[:, None], across.shape)
    row = np.where(is_steep, major_2d, across)[inside]
    column = np.where(is_steep, across, major_2d)[inside]
    pixels = row * SIZE + column
    opacity = np.minimum(share[inside], 0.999)
    return pixels, opacity


def photo_darkness(lightness: np.ndarray) -> np.ndarray:
    """The photo's centred square crop at the score's raster, as darkness 0 … 1."""
    rows, columns = lightness.shape
    side = min(rows, columns)
    top, left = (rows - side) // 2, (columns - side) // 2
    square = np.asarray(lightness[top : top + side, left : left + side], dtype=np.float32)
    image = Image.fromarray(square, mode="F").resize((SIZE, SIZE), Image.Resampling.LANCZOS)
    darkness: np.ndarray = 1.0 - np.clip(np.asarray(image, dtype=np.float64), 0.0, 1.0)
    return darkness


def score(
    sequence: np.ndarray | list[int] | tuple[int, ...], nails: int, lightness: np.ndarray
) -> Score:
    """The sequence on the board against the photo (lightness 0 … 1, any shape)."""
    seen = gaussian_blur(thread_picture(sequence, nails), sigma=BLUR_PX)
    wanted = photo_darkness(lightness)
    mask = board_mask()
    rmse = float(np.sqrt(np.mean((seen - wanted)[mask] ** 2)))
    return Score(rmse, float(ssim_map(wanted, seen)[mask].mean()))
