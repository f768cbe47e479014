"""A peer for the string-art benchmark: kaspar98/StringArt's greedy, rewritten here.

Origin: github.com/kaspar98/StringArt, ``generate.py`` (K. Kasper, an
algorithmics course project, 2020); the repository states no licence, so
none of its code is copied: this is the same algorithm written afresh from
its description and source, for measuring only (benchmark code, never
imported by the station; it needs scikit-image, the ``bench`` extra).

The method, as its ``generate.py`` does it for black thread on white:

* the photo's centred largest square is resized (``skimage.transform.resize``)
  to a 300 x 300 canvas, and the target is its lightness times 0.9;
* the canvas starts white (1.0); a thread subtracts 0.05 times the
  anti-aliasing value of ``skimage.draw.line_aa`` along its pixels, clipped
  to 0 … 1;
* from the current nail every nail is tried (no skip, itself included); a
  line's worth is the sum over its pixels of the squared error before minus
  after; the best (the last of equals) is pulled;
* it stops at the pull budget, or as soon as no line improves the picture
  (the original then fails on every later iteration too, with nothing drawn).

Two adaptations so that it runs on the benchmark's boards: the nails are
the board's (``nails`` evenly round a circle of radius 149 px centred on
the canvas, nail 0 at three o'clock, counter-clockwise, rounded to whole
pixels) instead of every fourth pixel of a drawn circle; and each line is
rasterised once for both directions (``line_aa`` from the lower nail), and
all lines from a nail scored in one numpy pass -- the same sums the
original adds up one nail at a time, about fifty times faster.
"""

from __future__ import annotations

import numpy as np

SIDE = 300
TARGET_SCALE = 0.9
STRENGTH = 0.05


def canvas_target(lightness: np.ndarray) -> np.ndarray:
    """The original's target: the largest centred square, resized to 300², times 0.9."""
    from skimage.transform import resize

    rows, columns = lightness.shape
    side = min(rows, columns)
    half = side // 2
    if rows <= columns:
        square = lightness[:, columns // 2 - half : columns // 2 + half]
    else:
        square = lightness[rows // 2 - half : rows // 2 + half, :]
    resized: np.ndarray = resize(square, (SIDE, SIDE)) * TARGET_SCALE
    return resized


def nail_pixels(nails: int) -> np.ndarray:
    """(nails, 2) (row, column) integer nail positions on the 300² canvas."""
    centre = SIDE // 2
    radius = SIDE // 2 - 1
    angle = 2.0 * np.pi * np.arange(nails) / nails
    rows = np.round(centre - radius * np.sin(angle)).astype(np.int64)
    columns = np.round(centre + radius * np.cos(angle)).astype(np.int64)
    return np.column_stack((rows, columns))


def kaspar98(lightness: np.ndarray, nails: int, pulls: int) -> list[int]:
    """The pull order (nail indices, starting at nail 0) for at most ``pulls`` threads."""
    from skimage.draw import line_aa

    target = canvas_target(lightness).ravel()
    canvas = np.ones(SIDE * SIDE)
    points = nail_pixels(nails)
    lines: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
    for a in range(nails):
        for b in range(a, nails):
            rr, cc, val = line_aa(*points[a], *points[b])
            lines[a, b] = (rr * SIDE + cc, val)
    blocks = []
    for a in range(nails):
        parts = [lines[min(a, b), max(a, b)] for b in range(nails)]
        sizes = np.array([len(p[0]) for p in parts])
        starts = np.concatenate(([0], np.cumsum(sizes)[:-1]))
        blocks.append(
            (np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts]), starts)
        )
    order = [0]
    for _ in range(pulls):
        pixels, value, starts = blocks[order[-1]]
        now = canvas[pixels]
        wanted = target[pixels]
        after = np.clip(now - STRENGTH * value, 0.0, 1.0)
        gain = np.add.reduceat((now - wanted) ** 2 - (after - wanted) ** 2, starts)
        best = len(gain) - 1 - int(np.argmax(gain[::-1]))  # the last of equals, as ``>=`` does
        if gain[best] <= 0.0:
            break
        line_pixels, line_value = lines[min(order[-1], best), max(order[-1], best)]
        canvas[line_pixels] = np.clip(canvas[line_pixels] - STRENGTH * line_value, 0.0, 1.0)
        order.append(best)
    return order
