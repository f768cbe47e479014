"""Three test pictures for the string-art generator, made here (no photo in the repo).

* a gradient disc: lightness falling smoothly from one side to the other,
  inside a disc, on white;
* a face-like pattern: an oval face, two eyes, a nose and a mouth in greys;
* a high-contrast logo: a black ring and a bar crossing it, on white.

Each is lightness 0 (black) … 1 (white), ``size``² pixels, float32.
"""

from __future__ import annotations

import numpy as np


def _grid(size: int) -> tuple[np.ndarray, np.ndarray]:
    """Coordinates -1 … 1 across the square, y up."""
    axis = (np.arange(size, dtype=np.float64) + 0.5) / size * 2.0 - 1.0
    x, y = np.meshgrid(axis, -axis)
    return x, y


def gradient_disc(size: int) -> np.ndarray:
    x, y = _grid(size)
    inside = x * x + y * y <= 0.95**2
    shade = 0.1 + 0.85 * (x + 0.95) / 1.9
    return np.where(inside, shade, 1.0).astype(np.float32)


def face(size: int) -> np.ndarray:
    x, y = _grid(size)
    image = np.full((size, size), 0.92)
    image[(x / 0.62) ** 2 + (y / 0.8) ** 2 <= 1.0] = 0.7  # the face
    image[(x / 0.7) ** 2 + ((y - 0.55) / 0.4) ** 2 <= 1.0] = 0.25  # hair, over the top
    image[(x / 0.55) ** 2 + ((y - 0.35) / 0.3) ** 2 <= 1.0] = 0.7  # forehead below the hair
    for side in (-1, 1):
        image[((x - side * 0.24) / 0.12) ** 2 + ((y - 0.12) / 0.07) ** 2 <= 1.0] = 0.1  # eyes
        image[((x - side * 0.24) / 0.16) ** 2 + ((y - 0.26) / 0.025) ** 2 <= 1.0] = 0.3  # brows
    image[(np.abs(x) <= 0.05) & (y <= 0.05) & (y >= -0.2)] = 0.45  # the nose
    image[((x / 0.25) ** 2 + ((y + 0.42) / 0.06) ** 2) <= 1.0] = 0.2  # the mouth
    shading = 0.12 * x  # light from the left
    return np.clip(image + shading, 0.0, 1.0).astype(np.float32)


def logo(size: int) -> np.ndarray:
    x, y = _grid(size)
    r = np.hypot(x, y)
    ring = (r >= 0.45) & (r <= 0.62)
    bar = (np.abs(y - 0.6 * x) <= 0.1) & (r <= 0.8)
    return np.where(ring | bar, 0.0, 1.0).astype(np.float32)


TEST_IMAGES = {"gradient disc": gradient_disc, "face pattern": face, "logo": logo}
