"""The photo as the darkness the thread should make: cropped to the board, contrast set.

Darkness is 0 for white (bare board) and 1 for black (the board hidden by
thread).  The crop is a square of the photo centred where the operator
puts it (as a fraction of the photo's width and height) and ``1 / zoom`` of
the photo's shorter side across; it is resampled to the board's raster, so
the nail circle just fits inside it.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image, ImageOps, UnidentifiedImageError

#: Photos larger than this (in pixels) are refused: a decompression bomb, not a photo.
MAX_PIXELS = 80_000_000
#: The longest side of the copy the station works from (the board raster is far smaller).
WORKING_SIDE = 1200


class ImageError(ValueError):
    """The image cannot be read (the message says why, for the operator)."""


@dataclass(frozen=True)
class Adjust:
    """How the operator crops the photo and sets its contrast."""

    centre_x: float = 0.5  # crop centre, fraction of the photo's width
    centre_y: float = 0.5  # and of its height, from the top
    zoom: float = 1.0  # 1: the square fits the shorter side; 2: half of it
    contrast: float = 1.0  # about mid-grey: 1 unchanged, 2 twice as steep
    brightness: float = 0.0  # added to the lightness (-1 … 1)
    invert: bool = False  # white thread on a dark board (or a negative)


def load_image(path: Path) -> np.ndarray:
    """The photo as (rows, columns) lightness 0…1, float32 (its EXIF turn applied)."""
    Image.MAX_IMAGE_PIXELS = MAX_PIXELS
    try:
        with Image.open(path) as opened:
            grey = ImageOps.exif_transpose(opened).convert("L")
            grey.load()
    except (OSError, UnidentifiedImageError, Image.DecompressionBombError, ValueError) as exc:
        raise ImageError(f"{path.name}: not an image this station can read ({exc})") from exc
    if grey.width < 2 or grey.height < 2:
        raise ImageError(f"{path.name}: {grey.width} x {grey.height} pixels is too small")
    return np.asarray(grey, dtype=np.float32) / 255.0


def working_copy(lightness: np.ndarray, max_side: int = WORKING_SIDE) -> np.ndarray:
    """The photo shrunk to at most ``max_side`` pixels a side: enough for any board raster,
    and small enough that cropping it again as the operator turns a knob takes milliseconds."""
    rows, columns = lightness.shape[:2]
    scale = max_side / max(rows, columns)
    if scale >= 1.0:
        return lightness
    image = Image.fromarray(np.asarray(lightness * 255.0 + 0.5, dtype=np.uint8))
    size = (max(2, round(columns * scale)), max(2, round(rows * scale)))
    small = image.resize(size, Image.Resampling.LANCZOS)
    return np.asarray(small, dtype=np.float32) / 255.0


def crop_box(shape: tuple[int, int], adjust: Adjust) -> tuple[float, float, float, float]:
    """(left, top, right, bottom) of the square crop in photo pixels, kept inside the photo."""
    rows, columns = shape
    side = min(rows, columns) / max(adjust.zoom, 1.0)
    left = np.clip(adjust.centre_x * columns - side / 2, 0, columns - side)
    top = np.clip(adjust.centre_y * rows - side / 2, 0, rows - side)
    return float(left), float(top), float(left + side), float(top + side)


def lightness_square(lightness: np.ndarray, adjust: Adjust, size: int) -> np.ndarray:
    """The crop resampled to ``size``², lightness 0…1 (before contrast)."""
    image = Image.fromarray(np.asarray(lightness * 255.0 + 0.5, dtype=np.uint8))
    box = crop_box(lightness.shape[:2], adjust)
    square = image.resize((size, size), Image.Resampling.LANCZOS, box=box)
    return np.asarray(square, dtype=np.float32) / 255.0


def darkness(lightness: np.ndarray, adjust: Adjust) -> np.ndarray:
    """Lightness → the darkness to make, after contrast, brightness and inversion."""
    value = 1.0 - lightness if adjust.invert else lightness
    value = (value - 0.5) * adjust.contrast + 0.5 + adjust.brightness
    result: np.ndarray = (1.0 - np.clip(value, 0.0, 1.0)).astype(np.float32)
    return result


def target_darkness(lightness: np.ndarray, adjust: Adjust, size: int) -> np.ndarray:
    """(size, size) darkness 0…1 of the cropped, adjusted photo."""
    return darkness(lightness_square(lightness, adjust, size), adjust)
