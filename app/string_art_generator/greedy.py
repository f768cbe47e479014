"""Choosing the nail sequence: at every nail, the line that brings the picture closest to the photo.

Weighted greedy on the residual darkness.  From the nail the thread is at,
every allowed line is scored by how much it lowers the squared error between
the thread picture and the target, with the thread model of :mod:`.render`:
a line darkens pixel ``p`` by ``d = (1 - c_p) · alpha_p`` (``c`` the darkness
so far), which changes the pixel's squared error by ``d · (2 (t_p - c_p) - d)``.
That is the line weighting: a line's pixels count by what the thread can
still do there, so a centre that many lines already cross (``c`` near the
target, or past it) stops attracting more of them, where plain darkest-line
greedy keeps drawing through it.  ``length_weight`` divides the score by the
line's length to that power (0: the error it removes; 1: per pixel).

The sequence ends at the line budget, or earlier when no line from the
current nail lowers the error any more (more thread would only spoil it).
The work is cut into chunks of a few milliseconds: the generator yields
between them, so a worker thread can report progress and stop, and the
GUI thread gets the interpreter back often.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.board import BoardRaster
from app.string_art_generator.lines import LineKey, LineTable, NailLines, build_table
from app.string_art_generator.render import render_darkness
from app.string_art_generator.shaping import aim

#: Lines chosen between two yields (about a millisecond each on a few hundred nails).
CHUNK_LINES = 8
#: The default least skip: a twentieth of the board's nails, at least 2.
SKIP_FRACTION = 20
#: The largest line table built (pixel entries; 8 bytes each, twice over: ~1.3 GB).
MAX_TABLE_ENTRIES = 80_000_000


def default_skip(nails: int) -> int:
    return max(2, nails // SKIP_FRACTION)


@dataclass(frozen=True)
class Settings:
    """How the sequence is made (the board is separate: ``StringArtParams``)."""

    lines: int = 4000  # the line budget: at most this many threads
    thread_mm: float = 0.15  # the real thread's width
    min_skip: int | None = None  # None: default_skip(nails)
    #: Raster pixels across the nail circle: 0.5 mm on a 26 cm circle, a few thread widths.
    resolution: int = 520
    length_weight: float = 0.0
    start_nail: int = 0
    #: Stop before the budget when no line lowers the error; False draws the whole budget
    #: (and tones the target to it: see shaping.py).
    stop_when_no_gain: bool = True
    #: How much the target's edges are deepened (shaping.py); 0 aims at the photo as it is.
    sharpen: float = 3.0

    def skip_for(self, nails: int) -> int:
        return default_skip(nails) if self.min_skip is None else self.min_skip

    def table_entries(self, params: StringArtParams) -> int:
        """About how many (pixel, opacity) pairs the line table holds: its memory / 8 bytes.

        Each nail has a line to every nail but its skipped neighbours; a line
        has two pixels per raster step along its longer axis, on average about
        0.6 of the raster across.
        """
        per_nail = max(0, params.nails - 1 - 2 * (self.skip_for(params.nails) - 1))
        return round(params.nails * per_nail * 1.2 * self.resolution)

    def fitted_resolution(self, params: StringArtParams) -> int:
        """The finest raster up to this one whose line table stays within MAX_TABLE_ENTRIES.

        Boards with many nails get a coarser raster rather than a refusal (the
        default of 520 px holds about 370 nails; 200 px about 580).
        """
        per_pixel = self.table_entries(params) / self.resolution
        if per_pixel <= 0:
            return self.resolution
        return max(16, min(self.resolution, int(MAX_TABLE_ENTRIES / per_pixel)))

    def check(self, params: StringArtParams) -> str | None:
        """Why these settings cannot make a sequence for ``params``, or None."""
        skip = self.skip_for(params.nails)
        if self.lines < 1:
            return "the line budget must be at least 1"
        if not 0 < self.thread_mm < 20:
            return f"thread width {self.thread_mm:g} mm: must be above 0 and below 20 mm"
        if not 16 <= self.resolution <= 2000:
            return f"resolution {self.resolution}: must be 16 … 2000 pixels"
        if skip < 1 or skip > params.nails // 2 - 1:
            return (
                f"minimum skip {skip}: must be 1 … {max(1, params.nails // 2 - 1)} "
                f"on {params.nails} nails"
            )
        if not 0 <= self.start_nail < params.nails:
            return f"start nail {self.start_nail} is not on a board of {params.nails} nails"
        if self.table_entries(params) > MAX_TABLE_ENTRIES:
            return (
                f"{params.nails} nails on a raster of {self.resolution} px would need about "
                f"{self.table_entries(params) * 8 / 1e9:.1f} GB for the lines between them: "
                "fewer nails or a smaller raster"
            )
        return None


@dataclass(frozen=True)
class Result:
    """A finished sequence with the pictures it was judged by."""

    params: StringArtParams
    settings: Settings
    sequence: tuple[int, ...]
    target: np.ndarray = field(repr=False)  # (size, size) darkness wanted
    darkness: np.ndarray = field(repr=False)  # (size, size) darkness the thread makes
    mask: np.ndarray = field(repr=False)  # (size, size) the board inside the nails
    stopped_early: bool  # no line lowered the error before the budget was used
    seconds: float

    @property
    def lines(self) -> int:
        return len(self.sequence) - 1


@dataclass(frozen=True)
class Progress:
    """Where a generation is: preparing the lines (``nails``) or winding (``threads``)."""

    phase: Literal["lines", "threads", "done"]
    done: int
    total: int
    darkness: np.ndarray | None = field(default=None, repr=False)
    result: Result | None = None


class Greedy:
    """The weighted greedy's state: the darkness so far and the nail the thread is at."""

    def __init__(
        self, table: LineTable, target: np.ndarray, settings: Settings, opacity: float = 1.0
    ) -> None:
        size = table.key.raster.size
        #: The share of a thread's opacity counted (below 1 when the budget is toned in).
        self.opacity = np.float32(opacity)
        self.table = table
        self.target = np.ascontiguousarray(target, dtype=np.float32).reshape(size * size)
        self.darkness = np.zeros(size * size, dtype=np.float32)
        self.length_weight = settings.length_weight
        self.sequence = [settings.start_nail]
        self._divisors = [
            np.power(block.lengths, settings.length_weight, dtype=np.float64)
            if settings.length_weight
            else None
            for block in table.nails
        ]

    def scores(self, block: NailLines, nail: int) -> np.ndarray:
        """Per line of ``block``: how much it lowers the squared error (weighted)."""
        if not len(block.others):
            return np.empty(0)
        pixels = block.pixels
        now = self.darkness[pixels]
        delta = (1.0 - now) * (block.alpha * self.opacity)
        gain = delta * (2.0 * (self.target[pixels] - now) - delta)
        score = np.add.reduceat(gain, block.starts).astype(np.float64)
        divisor = self._divisors[nail]
        if divisor is not None:
            score /= divisor
        return score

    def step(self, *, stop_when_no_gain: bool) -> bool:
        """Wind the best line from the current nail; False when there is none worth winding."""
        nail = self.sequence[-1]
        block = self.table.nails[nail]
        score = self.scores(block, nail)
        if not len(score):
            return False
        best = int(np.argmax(score))
        if stop_when_no_gain and score[best] <= 0.0:
            return False
        pixels, alpha = block.line(best)
        now = self.darkness[pixels]
        self.darkness[pixels] = now + (1.0 - now) * (alpha * self.opacity)
        self.sequence.append(int(block.others[best]))
        return True


def generate(params: StringArtParams, target: np.ndarray, settings: Settings) -> Iterator[Progress]:
    """Make the sequence for ``target`` ((resolution, resolution) darkness) step by step.

    Yields progress every few milliseconds: first the line table per nail
    (skipped when cached), then every ``CHUNK_LINES`` threads, and last a
    ``done`` with the result.  Stop iterating to cancel: nothing is kept.
    """
    reason = params.check() or settings.check(params)
    if reason is not None:
        raise ValueError(reason)
    size = settings.resolution
    if target.shape != (size, size):
        raise ValueError(f"target is {target.shape}, the raster is {size} x {size}")
    begun = time.perf_counter()
    raster = BoardRaster(params, size)
    key = LineKey(raster, settings.thread_mm, settings.skip_for(params.nails))
    table: LineTable | None = None
    for item in build_table(key):
        if isinstance(item, LineTable):
            table = item
        else:
            yield Progress("lines", item, params.nails)
    assert table is not None
    mask = raster.mask
    fill = 0 if settings.stop_when_no_gain else settings.lines
    work, opacity = aim(target, mask, table, sharpen=settings.sharpen, fill_budget=fill)
    greedy = Greedy(table, work, settings, opacity=opacity)
    stopped = False
    while greedy.sequence and len(greedy.sequence) - 1 < settings.lines and not stopped:
        for _ in range(min(CHUNK_LINES, settings.lines - (len(greedy.sequence) - 1))):
            if not greedy.step(stop_when_no_gain=settings.stop_when_no_gain):
                stopped = True
                break
        yield Progress(
            "threads",
            len(greedy.sequence) - 1,
            settings.lines,
            # While a budget is toned in this is the share counted (lighter than the thread
            # will be): the finished picture below is the real one.
            darkness=greedy.darkness.reshape(size, size).copy(),
        )
    if greedy.opacity < 1.0:
        # The picture as the real thread makes it, not the share the greedy counted.
        darkness = render_darkness(params, greedy.sequence, size, settings.thread_mm)
    else:
        darkness = greedy.darkness.reshape(size, size).copy()
    result = Result(
        params=params,
        settings=settings,
        sequence=tuple(greedy.sequence),
        target=np.asarray(target, dtype=np.float32),
        darkness=darkness,
        mask=mask,
        stopped_early=stopped,
        seconds=time.perf_counter() - begun,
    )
    yield Progress("done", result.lines, settings.lines, darkness=darkness, result=result)


def run(params: StringArtParams, target: np.ndarray, settings: Settings) -> Result:
    """The whole generation at once (the command line, tests)."""
    for progress in generate(params, target, settings):
        if progress.result is not None:
            return progress.result
    raise AssertionError("generate always ends with a result")
