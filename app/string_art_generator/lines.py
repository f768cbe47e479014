"""Every nail-pair line as anti-aliased pixels with the thread's opacity, built once per board.

A line is rasterised the way Xiaolin Wu's algorithm does: one sample per
whole pixel along its major axis, shared between the two pixels either side
of the true line in proportion to how near each is.  The thread's opacity in
a pixel is the share of the pixel the thread covers: its width in pixels,
times ``sqrt(1 + slope²)`` (a slanted thread crosses more of a column), times
the pixel's Wu share, at most 1.  A thread 0.25 mm wide on pixels of 1 mm
thus darkens the pixels it runs through by about a quarter each, as the real
thread does seen from a distance.

The lines of each nail are kept together (``NailLines``), so that choosing
the next nail is a gather and a segmented sum over one contiguous block.
A line is rasterised from its lower-numbered nail to the higher one, so both
ends hold the same pixels.  Tables are cached per board, resolution, thread
and skip (the few last used), because building one takes about a second and
the operator usually generates again with another image or contrast.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from app.string_art_generator.board import BoardRaster, min_gap

#: The most a single thread can darken a pixel (a pixel fully behind thread still shows
#: the board through the gaps of the next turns).
MAX_ALPHA = 0.98
#: Tables kept in memory (each a few tens of MB for a few hundred nails).
CACHED_TABLES = 2


@dataclass(frozen=True)
class Raster:
    """Pixels of a batch of lines: line ``k`` is ``pixels[starts[k]:starts[k + 1]]``."""

    pixels: np.ndarray  # flat pixel index (row * size + column), int32
    alpha: np.ndarray  # the thread's opacity in that pixel, float32
    starts: np.ndarray  # (lines + 1,) int64


def rasterise(
    p0: np.ndarray, p1: np.ndarray, size: int, thread_px: float, *, max_alpha: float = MAX_ALPHA
) -> Raster:
    """Wu lines from ``p0[k]`` to ``p1[k]`` ((k, 2) column, row) on a ``size``² raster."""
    d = p1 - p0
    steep = np.abs(d[:, 1]) > np.abs(d[:, 0])
    major0 = np.where(steep, p0[:, 1], p0[:, 0])
    major1 = np.where(steep, p1[:, 1], p1[:, 0])
    minor0 = np.where(steep, p0[:, 0], p0[:, 1])
    dmajor = np.where(steep, d[:, 1], d[:, 0])
    dminor = np.where(steep, d[:, 0], d[:, 1])
    slope = np.divide(dminor, dmajor, out=np.zeros_like(dminor), where=dmajor != 0)
    first = np.ceil(np.minimum(major0, major1)).astype(np.int64)
    last = np.floor(np.maximum(major0, major1)).astype(np.int64)
    last = np.maximum(last, first)  # nails closer than a pixel still make one sample
    counts = last - first + 1
    line_of = np.repeat(np.arange(len(p0)), counts)
    sample_starts = np.concatenate(([0], np.cumsum(counts)))
    local = np.arange(int(sample_starts[-1])) - np.repeat(sample_starts[:-1], counts)
    major = first[line_of] + local
    minor = minor0[line_of] + (major - major0[line_of]) * slope[line_of]
    low = np.floor(minor)
    share_high = minor - low
    low_i = low.astype(np.int64)
    is_steep = steep[line_of]
    column_low = np.where(is_steep, low_i, major)
    row_low = np.where(is_steep, major, low_i)
    column_high = column_low + is_steep
    row_high = row_low + ~is_steep
    strength = thread_px * np.sqrt(1.0 + slope * slope)[line_of]
    pixels = np.empty((len(major), 2), dtype=np.int32)
    pixels[:, 0] = row_low * size + column_low
    pixels[:, 1] = row_high * size + column_high
    alpha = np.empty((len(major), 2), dtype=np.float32)
    alpha[:, 0] = np.minimum(strength * (1.0 - share_high), max_alpha)
    alpha[:, 1] = np.minimum(strength * share_high, max_alpha)
    return Raster(pixels.ravel(), alpha.ravel(), 2 * sample_starts)


@dataclass(frozen=True)
class NailLines:
    """The lines from one nail to every nail it may go to, one contiguous block."""

    others: np.ndarray  # (m,) the nail at the far end of each line
    starts: np.ndarray  # (m,) where each line begins in ``pixels`` (for np.add.reduceat)
    ends: np.ndarray  # (m,) where it ends
    lengths: np.ndarray  # (m,) its length in pixels
    pixels: np.ndarray
    alpha: np.ndarray

    def line(self, k: int) -> tuple[np.ndarray, np.ndarray]:
        """Pixels and opacity of the ``k``-th line of this nail."""
        a, b = int(self.starts[k]), int(self.ends[k])
        return self.pixels[a:b], self.alpha[a:b]


@dataclass(frozen=True)
class LineKey:
    """What a table depends on."""

    raster: BoardRaster
    thread_mm: float
    min_skip: int


@dataclass(frozen=True)
class LineTable:
    key: LineKey
    nails: tuple[NailLines, ...]

    @property
    def entries(self) -> int:
        """Stored (pixel, opacity) pairs: the table's size."""
        return sum(len(n.pixels) for n in self.nails)

    def between(self, a: int, b: int) -> tuple[np.ndarray, np.ndarray]:
        block = self.nails[a]
        k = int(np.searchsorted(block.others, b))
        if k >= len(block.others) or block.others[k] != b:
            raise ValueError(f"no line from nail {a} to nail {b} on this board")
        return block.line(k)


def allowed_pairs(raster: BoardRaster, min_skip: int) -> np.ndarray:
    """(nails, nails) bool: the thread may run between these two nails.

    Never to itself, never to a nail fewer than ``min_skip`` places away round
    the board, and on a polygon never along an edge (it would lie on the
    nails in between).
    """
    n = raster.params.nails
    index = np.arange(n)
    gap = min_gap(n, index[:, None], index[None, :])
    ok: np.ndarray = (gap >= max(1, min_skip)) & ~raster.same_edge()
    return ok


def nail_lines(raster: BoardRaster, nail: int, others: np.ndarray, thread_mm: float) -> NailLines:
    nails = raster.nails_px
    low = np.minimum(nail, others)
    high = np.maximum(nail, others)
    lines = rasterise(nails[low], nails[high], raster.size, thread_mm / raster.pixel_mm)
    lengths = np.hypot(*(nails[high] - nails[low]).T)
    return NailLines(
        others=others.astype(np.int64),
        starts=lines.starts[:-1].copy(),
        ends=lines.starts[1:].copy(),
        lengths=lengths,
        pixels=lines.pixels,
        alpha=lines.alpha,
    )


_cache: OrderedDict[LineKey, LineTable] = OrderedDict()
_cache_lock = threading.Lock()


def cached_table(key: LineKey) -> LineTable | None:
    with _cache_lock:
        table = _cache.get(key)
        if table is not None:
            _cache.move_to_end(key)
        return table


def build_table(key: LineKey) -> Iterator[int | LineTable]:
    """The table for ``key``: yields the nails done so far, then the table (cached).

    One nail's lines at a time, so a worker can report progress and stop,
    and no single numpy call holds the interpreter for long.
    """
    table = cached_table(key)
    if table is None:
        allowed = allowed_pairs(key.raster, key.min_skip)
        blocks = []
        for nail in range(key.raster.params.nails):
            others = np.flatnonzero(allowed[nail])
            blocks.append(nail_lines(key.raster, nail, others, key.thread_mm))
            yield nail + 1
        table = LineTable(key, tuple(blocks))
        with _cache_lock:
            _cache[key] = table
            while len(_cache) > CACHED_TABLES:
                _cache.popitem(last=False)
    yield table


def line_table(key: LineKey) -> LineTable:
    """The table for ``key``, built at once when it is not cached."""
    for item in build_table(key):
        if isinstance(item, LineTable):
            return item
    raise AssertionError("build_table always ends with the table")
