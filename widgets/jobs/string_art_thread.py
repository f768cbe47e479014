"""The string-art thread as the preview draws it, computed once per program off the GUI thread.

Up to :data:`EXACT_CONNECTIONS` connections the thread is drawn as it is
wound, one faint segment per connection, so where threads cross the colour
deepens.  A bigger job (a generator's 2 million connections) would take
seconds per paint that way, and on a board of N nails there are at most
N·(N-1)/2 different chords: the thread is then *merged*, each chord drawn
once with the opacity its k windings would build up together
(1 - (1 - a)^k for opacity a, which is what k blended copies of the same line give), in a
few bands of k.  The picture is the same up to the banding; the preview says
it shows the chords merged.  What is wound is merged the same way, counted
incrementally as the job advances (append-only: only the new connections are
added), so progress never rebuilds the whole.

Pure numpy, no Qt: the dock's loading thread builds it with the preview's geometry.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from app.jobs.formats.string_art.program import StringArtProgram

#: Connections drawn one by one; above this the chords are merged.
EXACT_CONNECTIONS = 20_000
#: The bands of windings per chord a merged thread is drawn in: [1], [2], [3, 4], [5, 8], …
BAND_EDGES = (1, 2, 3, 5, 9, 17, 33, 65)

_EMPTY = np.empty(0)


def band_of(counts: np.ndarray) -> np.ndarray:
    """The band (index into :data:`BAND_EDGES`) of each winding count (≥ 1)."""
    return np.searchsorted(np.asarray(BAND_EDGES), counts, side="right") - 1


def band_alpha(alpha: int, band: int) -> int:
    """The opacity (of 255) a chord of ``band`` is drawn with: k copies of ``alpha`` blended."""
    low = BAND_EDGES[band]
    high = BAND_EDGES[band + 1] - 1 if band + 1 < len(BAND_EDGES) else low * 2
    k = math.sqrt(low * high)  # the band's geometric middle
    opacity = 1.0 - math.pow(1.0 - alpha / 255, k)
    return max(1, min(255, round(255 * opacity)))


#: Connections numbered at a time by :func:`_chords_of` (each gather holds the interpreter lock).
CHORD_CHUNK = 1 << 18


def _chords_of(key: np.ndarray, keys: int) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(key, return_inverse=True)`` for keys below ``keys``, without a sort.

    Sorting two million connections held the interpreter lock a tenth of a
    second and more per call (the window waited); a table of the nail pairs
    (some hundred thousand) numbers them in a few gathers, a chunk at a time.
    """
    present = np.zeros(keys, dtype=bool)
    for first in range(0, len(key), CHORD_CHUNK):
        present[key[first : first + CHORD_CHUNK]] = True
    unique = np.flatnonzero(present)
    rank = np.cumsum(present, dtype=np.int64) - 1
    chord_of = np.empty(len(key), dtype=np.int64)
    for first in range(0, len(key), CHORD_CHUNK):
        chord_of[first : first + CHORD_CHUNK] = rank[key[first : first + CHORD_CHUNK]]
    return unique, chord_of


@dataclass(frozen=True)
class ThreadGeometry:
    """A string-art program's nails, thread and drill ends, as the preview needs them."""

    nail_xy: np.ndarray  # (nails, 2)
    #: Exact thread: x and y of each connection's two ends, flattened (connect="pairs").
    pairs: tuple[np.ndarray, np.ndarray]
    #: The connections wound (sequence entries - 1).
    connections: int
    #: Merged thread (empty when exact): each connection's chord id, and each chord's ends.
    chord_of: np.ndarray
    chord_ends: np.ndarray  # (chords, 2) nail indices
    #: The last operation of each nail's drill cycle, in drilling order.
    drill_ends: np.ndarray
    #: Merged thread: per band, the x and y pairs of the whole job's chords (:meth:`bands`
    #: of every connection), made here with the rest so the GUI thread only shows them.
    whole: tuple[tuple[np.ndarray, np.ndarray], ...] = field(default=(), compare=False)

    @property
    def merged(self) -> bool:
        return len(self.chord_ends) > 0

    @property
    def chords(self) -> int:
        return len(self.chord_ends)

    @classmethod
    def of(cls, program: StringArtProgram) -> ThreadGeometry:
        xy = program.job.nail_positions()
        sequence = program.job.indices
        connections = max(len(sequence) - 1, 0)
        drilling = np.flatnonzero((program.entry_of_op == -1) & (program.nail_of_op >= 0))
        nails = program.nail_of_op[drilling]
        last = np.append(nails[1:] != nails[:-1], True) if len(nails) else np.empty(0, bool)
        drill_ends = drilling[last]
        if connections <= EXACT_CONNECTIONS:
            visits = xy[sequence] if len(sequence) else np.empty((0, 2))
            pairs = (
                np.column_stack((visits[:-1, 0], visits[1:, 0])).ravel(),
                np.column_stack((visits[:-1, 1], visits[1:, 1])).ravel(),
            )
            empty = np.empty(0, dtype=np.int64)
            return cls(xy, pairs, connections, empty, np.empty((0, 2), np.int64), drill_ends)
        a, b = sequence[:-1], sequence[1:]
        low, high = np.minimum(a, b), np.maximum(a, b)
        key = low * len(xy) + high  # the same chord whichever way it is wound
        unique, chord_of = _chords_of(key, len(xy) * len(xy))
        ends = np.column_stack((unique // len(xy), unique % len(xy)))
        merged = cls(xy, (_EMPTY, _EMPTY), connections, chord_of.astype(np.int64), ends, drill_ends)
        return replace(merged, whole=tuple(merged.bands(merged.counts(connections))))

    def counts(self, upto: int) -> np.ndarray:
        """Windings per chord among the first ``upto`` connections."""
        return np.bincount(self.chord_of[:upto], minlength=self.chords)

    def bands(self, counts: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
        """Per band, the x and y pairs of the chords wound that often (connect="pairs")."""
        wound = np.flatnonzero(counts)
        band = band_of(counts[wound])
        out: list[tuple[np.ndarray, np.ndarray]] = []
        for k in range(len(BAND_EDGES)):
            ends = self.chord_ends[wound[band == k]]
            xy = self.nail_xy[ends.ravel()]
            out.append((xy[:, 0].copy(), xy[:, 1].copy()))
        return out


class WoundCounter:
    """Windings per chord of what is wound so far, counted append-only as the job goes on."""

    def __init__(self, thread: ThreadGeometry) -> None:
        self.thread = thread
        self.upto = 0
        self.counts = np.zeros(thread.chords, dtype=np.int64)

    def advance(self, upto: int) -> bool:
        """The first ``upto`` connections are wound; whether the counts changed."""
        upto = max(0, min(upto, self.thread.connections))
        if upto == self.upto:
            return False
        if upto > self.upto:
            np.add.at(self.counts, self.thread.chord_of[self.upto : upto], 1)
        else:  # back (a new run): recount
            self.counts = self.thread.counts(upto)
        self.upto = upto
        return True
