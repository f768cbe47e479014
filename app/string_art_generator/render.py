"""What the wound piece looks like: the same thread model the generator chooses lines by.

Threads over a pixel let light through one after the other: each passes
``1 - alpha`` of what reaches it, so a pixel's darkness after threads with
opacities ``a1, a2 …`` is ``1 - (1 - a1)(1 - a2)…`` whatever their order.
The preview and the PNG use this with the real thread width at the board's
real size, so a darker preview means a darker piece, not a tuning choice.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.board import BoardRaster
from app.string_art_generator.lines import rasterise

#: Lines rasterised at once when rendering (keeps each numpy call short).
BATCH = 512


def render_darkness(
    params: StringArtParams, sequence: Sequence[int], size: int, thread_mm: float
) -> np.ndarray:
    """(size, size) darkness of the wound ``sequence`` on a ``size``-pixel raster of the board."""
    raster = BoardRaster(params, size)
    nails = raster.nails_px
    order = np.asarray(sequence, dtype=np.int64)
    a, b = order[:-1], order[1:]
    low, high = np.minimum(a, b), np.maximum(a, b)
    log_light = np.zeros(size * size, dtype=np.float64)
    for begin in range(0, len(low), BATCH):
        end = begin + BATCH
        lines = rasterise(
            nails[low[begin:end]], nails[high[begin:end]], size, thread_mm / raster.pixel_mm
        )
        log_light += np.bincount(
            lines.pixels, weights=np.log1p(-lines.alpha.astype(np.float64)), minlength=size * size
        )
    result: np.ndarray = (1.0 - np.exp(log_light)).reshape(size, size).astype(np.float32)
    return result


def to_grey(darkness: np.ndarray) -> np.ndarray:
    """Darkness 0…1 as an 8-bit grey picture (white board, black thread)."""
    result: np.ndarray = np.round((1.0 - np.clip(darkness, 0.0, 1.0)) * 255.0).astype(np.uint8)
    return result
