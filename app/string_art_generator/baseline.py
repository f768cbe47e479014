"""Plain "darkest line" greedy, the method of the common open-source generators: the baseline.

From the current nail it takes the line whose pixels hold the most residual
darkness (each pixel counted by the thread's anti-aliased footprint, no
weighting by what is already drawn), then lightens the residual there by the
thread's opacity.  Same nails, skip, line table and budget as the weighted
method; it always uses the whole budget.  The benchmark and the tests
render both with the same thread model and compare their errors.
"""

from __future__ import annotations

import numpy as np

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.board import BoardRaster
from app.string_art_generator.lines import LineKey, line_table


def plain_greedy(
    params: StringArtParams,
    target: np.ndarray,
    lines: int,
    thread_mm: float,
    min_skip: int,
    start_nail: int = 0,
) -> tuple[int, ...]:
    size = target.shape[0]
    raster = BoardRaster(params, size)
    table = line_table(LineKey(raster, thread_mm, min_skip))
    residual = np.where(raster.mask, target, 0.0).astype(np.float32).reshape(size * size)
    sequence = [start_nail]
    for _ in range(lines):
        block = table.nails[sequence[-1]]
        score = np.add.reduceat(residual[block.pixels] * block.alpha, block.starts)
        best = int(np.argmax(score))
        pixels, alpha = block.line(best)
        residual[pixels] = np.maximum(residual[pixels] - alpha, 0.0)
        sequence.append(int(block.others[best]))
    return tuple(sequence)
