"""The fast path of the G-code loader: plain ``G0``/``G1`` moves, read and placed with numpy.

Why a fast path: most lines of a large file are plain ``G1 X… Y… F…``.  One
compiled pattern over the whole text picks those out and their numbers are
parsed by numpy in one call; only the other lines (pen commands, modal words,
arcs, comments) go through the full per-line parser, and runs of plain lines
between them are placed with numpy (scale, G92 offset, or a cumulative sum
under G91).
"""

from __future__ import annotations

import math
import re

import numpy as np
import numpy.typing as npt
from PySide6.QtCore import QCoreApplication

from app.jobs.formats.gcode.sent_texts import SentTextsBuilder
from app.jobs.formats.gcode.state import State
from app.jobs.formats.gcode.words import MAX_LINE_CHARS, plain_code
from app.jobs.program import JobFileError
from protocol.gcode.words import NUMBER

#: One record per line: group 1 is the G0/G1 digit of a plain move (a comment may follow),
#: empty for any other line.
FAST_LINE = re.compile(
    rf"[ \t]*(?:G0?([01])[ \t]*X[ \t]*{NUMBER}[ \t]*Y[ \t]*{NUMBER}(?:[ \t]*F[ \t]*{NUMBER})?"
    rf"[ \t]*(?:;[^\n]*|\([^()\n]*\)[ \t]*)?\r?\n|[^\n]*\n)"
)
FAST_LETTERS = bytes.maketrans(b"GXYF\t\r", b"      ")
#: Plain lines read in one call (regex, numpy): short enough that the window, waiting for the
#: interpreter lock meanwhile, is not kept waiting long.
NUMBERS_CHUNK = 8_192


#: FAST_LINE on the file's UTF-8 bytes (the pattern is ASCII: the same lines match).
FAST_LINE_BYTES = re.compile(FAST_LINE.pattern.encode("ascii"))
_SPACES = np.zeros(256, dtype=bool)
_SPACES[[ord(" "), ord("\t")]] = True


class PlainMoves:
    """A file's plain moves: numbers per plain line and the runs placed so far.

    What a plain line sends is its span of the file's bytes (``starts``,
    ``ends``), or, where that is not the text as written (spaces around it, a
    comment after it), a text of its own in ``own`` (by plain-line number).
    """

    def __init__(self, file: str) -> None:
        self.file = file
        self.buffer = b""
        self.starts = np.zeros(0, dtype=np.int64)
        self.ends = np.zeros(0, dtype=np.int64)
        self.own: dict[int, str] = {}
        self._own_ranks = np.zeros(0, dtype=np.int64)
        self.g = np.empty(0)
        self.x = np.empty(0)
        self.y = np.empty(0)
        self.f = np.empty(0)
        self.runs: list[tuple[int, int, int]] = []  # (first plain line, end, first operation)
        self.lines = np.empty(0, dtype=np.int32)  # source line of each plain move

    def __len__(self) -> int:
        return len(self.starts)

    def text(self, k: int) -> str:
        """What plain move ``k`` sends."""
        own = self.own.get(k)
        if own is not None:
            return own
        return self.buffer[int(self.starts[k]) : int(self.ends[k])].decode("ascii")

    def _own_between(self, k0: int, k1: int) -> list[int]:
        """The plain moves k0…k1-1 with texts of their own (a run's few, not all of them)."""
        ranks = self._own_ranks
        found: list[int] = ranks[np.searchsorted(ranks, k0) : np.searchsorted(ranks, k1)].tolist()
        return found

    def find(
        self,
        buffer: bytes,
        line_starts: np.ndarray,
        line_ends: np.ndarray,
        allowed: bool,
    ) -> np.ndarray:
        """Which lines (of ``buffer``, the file's UTF-8, between ``line_starts`` and
        ``line_ends``) are plain moves; reads their numbers.

        ``allowed``: plain moves need no checks on this machine (else none is plain).
        """
        count = len(line_ends)
        plain: np.ndarray
        if allowed:
            # A chunk of lines per call: one call over the whole file holds the interpreter
            # lock for as long as it takes (tenths of a second), and the window waits.
            found: list[bytes] = []
            for first in range(0, count, NUMBERS_CHUNK):
                last = min(first + NUMBERS_CHUNK, count) - 1
                found += FAST_LINE_BYTES.findall(
                    buffer, int(line_starts[first]), int(line_ends[last]) + 1
                )
            plain = np.array(found, dtype="S1") != b""
            del found
        else:
            plain = np.zeros(count, dtype=bool)
        if len(plain) != count:  # cannot happen: one record per line
            raise JobFileError(
                self.file,
                0,
                QCoreApplication.translate("JobFile", "could not split the file into lines"),
            )
        self.buffer = buffer
        plain_index = np.flatnonzero(plain)
        starts, ends = line_starts[plain_index], line_ends[plain_index]
        # Sent as written unless spaces surround it or a comment follows (``plain_code``).
        data = np.frombuffer(buffer, dtype=np.uint8)
        comments = np.flatnonzero((data == ord(";")) | (data == ord("(")))
        following = np.searchsorted(comments, starts)
        commented = following < len(comments)
        commented[commented] = comments[following[commented]] < ends[commented]
        del comments, following
        own = np.flatnonzero(
            commented | _SPACES[data[starts]] | _SPACES[data[np.maximum(ends - 1, 0)]]
        )
        texts = {
            int(k): plain_code(buffer[starts[k] : ends[k]].decode("utf-8", "surrogatepass"))
            for k in own.tolist()
        }
        lengths = ends - starts
        for k, text in texts.items():
            lengths[k] = len(text)
        if len(lengths) and int(lengths.max()) > MAX_LINE_CHARS:  # left to the full parser
            plain[plain_index[lengths > MAX_LINE_CHARS]] = False
            keep = lengths <= MAX_LINE_CHARS
            renumber = np.cumsum(keep) - 1
            texts = {int(renumber[k]): t for k, t in texts.items() if keep[k]}
            plain_index, starts, ends = plain_index[keep], starts[keep], ends[keep]
        self.starts, self.ends, self.own = starts, ends, texts
        self._own_ranks = np.array(sorted(texts), dtype=np.int64)
        self._numbers()
        self.lines = (plain_index + 1).astype(np.int32)
        return plain

    def _numbers(self) -> None:
        """Every plain line's G, X, Y and F, one numpy parse per chunk (F NaN where not given).

        A chunk of lines at a time, straight into the columns: the whole file's
        plain lines joined, and all their numbers, were two more copies of it at
        the load's peak.
        """
        n = len(self.starts)
        self.g, self.x, self.y = np.empty(n), np.empty(n), np.empty(n)
        self.f = np.full(n, np.nan)
        buffer, own = self.buffer, self.own
        for first in range(0, n, NUMBERS_CHUNK):
            stop = min(first + NUMBERS_CHUNK, n)
            pieces = [
                buffer[s:e]
                for s, e in zip(
                    self.starts[first:stop].tolist(), self.ends[first:stop].tolist(), strict=True
                )
            ]
            for k in self._own_between(first, stop):
                pieces[k - first] = own[k].encode("ascii")
            has_f = np.fromiter((b"F" in p for p in pieces), dtype=bool, count=len(pieces))
            values = np.fromstring(b" ".join(pieces).translate(FAST_LETTERS), sep=" ")
            del pieces
            per_line = 3 + has_f.astype(np.int64)
            at = np.cumsum(per_line) - per_line
            if len(values) != int(per_line.sum()):  # cannot happen: the pattern admits numbers
                raise JobFileError(
                    self.file,
                    0,
                    QCoreApplication.translate("JobFile", "could not read the coordinates"),
                )
            self.g[first:stop] = values[at]
            self.x[first:stop] = values[at + 1]
            self.y[first:stop] = values[at + 2]
            self.f[first:stop][has_f] = values[at[has_f] + 3]

    def check_feeds(
        self, k0: int, k1: int, feed: float, required: bool, limit: int = 1000
    ) -> list[JobFileError]:
        """Plain moves k0…k1-1 as GRBL checks them: F not negative (error:4), and a G1 only
        once a feed rate is set (error:22, where the machine needs one); ``feed``: the feed
        in force before the run (NaN: never set).  The first ``limit`` refusals, in order."""
        f = self.f[k0:k1]
        refused: dict[int, str] = {}
        for k in np.flatnonzero(f < 0)[:limit].tolist():
            refused[k] = QCoreApplication.translate(
                "JobFile", "negative value: {0} cannot be negative (error:4)"
            ).format(f"F{f[k]:g}")
        if required:
            # The feed in force at each line: its own F, else the last one before it.
            known = ~np.isnan(f) & (f >= 0)
            steps = np.arange(len(f))
            last = np.maximum.accumulate(np.where(known, steps, -1)) if len(f) else steps
            in_force = np.where(last >= 0, f[np.maximum(last, 0)], feed)
            with np.errstate(invalid="ignore"):
                bad = np.flatnonzero((self.g[k0:k1] != 0) & ~(in_force > 0))
            for k in bad[:limit].tolist():
                refused.setdefault(
                    k,
                    QCoreApplication.translate(
                        "JobFile", "feed rate undefined: {0} before any F sets one (error:22): {1}"
                    ).format("G1", repr(self.text(k0 + k))),
                )
        return [
            JobFileError(self.file, int(self.lines[k0 + k]), refused[k])
            for k in sorted(refused)[:limit]
        ]

    def place(
        self,
        k0: int,
        k1: int,
        st: State,
        texts: SentTextsBuilder,
        start_relative: set[int] | None = None,
    ) -> None:
        """Plain moves k0…k1-1 as MOVE operations, placed by the modal state in force.

        Their texts are added to ``texts``, the texts of the operations so far.
        """
        self.runs.append((k0, k1, len(texts)))
        own = [(k - k0, self.own[k]) for k in self._own_between(k0, k1)]
        texts.extend_spans(self.starts[k0:k1], self.ends[k0:k1], own)
        scale = st.scale
        if st.relative:
            for column, values in ((0, self.x), (1, self.y)):
                start = st.position[column]
                if math.isnan(start) and start_relative is not None:
                    start_relative.add(column)
                steps = np.concatenate(
                    ([0.0 if math.isnan(start) else start], values[k0:k1] * scale)
                )
                values[k0:k1] = np.cumsum(steps)[1:]  # added in order, as line by line
        else:
            for column, values in ((0, self.x), (1, self.y)):
                if scale != 1.0 or st.offset[column] != 0.0:
                    values[k0:k1] = values[k0:k1] * scale + st.offset[column]
        if scale != 1.0:
            self.f[k0:k1] *= scale
        given = np.flatnonzero(~np.isnan(self.f[k0:k1]))
        if len(given):
            st.feed = float(self.f[k0 + int(given[-1])])
        st.position[0] = float(self.x[k1 - 1])
        st.position[1] = float(self.y[k1 - 1])
        st.motion = int(self.g[k1 - 1])

    def release(self) -> None:
        """Let the numbers and spans go once :meth:`fill` has put them in the program."""
        empty = np.empty(0)
        self.g, self.x, self.y, self.f = empty, empty, empty, empty
        self.starts = self.ends = np.zeros(0, dtype=np.int64)
        self.lines = np.empty(0, dtype=np.int32)
        self.runs = []
        self.own, self._own_ranks = {}, np.zeros(0, dtype=np.int64)

    def fill(
        self,
        lines: npt.NDArray[np.int32],
        motion: npt.NDArray[np.uint8],
        feed: npt.NDArray[np.float64],
        named: npt.NDArray[np.uint16],
        positions: npt.NDArray[np.float64],
    ) -> None:
        """The plain moves' entries of the program's columns (indexed by operation)."""
        if not self.runs:
            return
        # The runs cover the plain moves in order, so plain move r is operation r + shift.
        k0s, k1s, op0s = (np.array(v, dtype=np.int64) for v in zip(*self.runs, strict=True))
        count = int(k1s[-1])
        kind = np.int32 if len(lines) < 2**31 - 1 else np.int64
        ops: np.ndarray = np.arange(count, dtype=kind)
        ops += np.repeat((op0s - k0s).astype(kind), k1s - k0s)
        # Each column let go once placed: the load's peak memory is here.
        lines[ops] = self.lines[:count]
        motion[ops] = self.g[:count].astype(np.uint8)
        feed[ops] = self.f[:count]
        named[ops] = 0b11
        positions[ops, 0] = self.x[:count]
        positions[ops, 1] = self.y[:count]
