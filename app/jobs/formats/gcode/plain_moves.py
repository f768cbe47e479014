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
#: Plain lines whose numbers are read in one numpy call.
NUMBERS_CHUNK = 65_536


class PlainMoves:
    """A file's plain moves: numbers per plain line and the runs placed so far."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.texts: list[str] = []
        self.g = np.empty(0)
        self.x = np.empty(0)
        self.y = np.empty(0)
        self.f = np.empty(0)
        self.runs: list[tuple[int, int, int]] = []  # (first plain line, end, first operation)
        self.lines = np.empty(0, dtype=np.int32)  # source line of each plain move

    def find(self, text: str, lines: list[str], allowed: bool) -> np.ndarray:
        """Which ``lines`` (``text`` split at its line ends) are plain moves; reads their numbers.

        ``allowed``: plain moves need no checks on this machine (else none is plain).
        """
        count = len(lines) - 1
        plain: np.ndarray
        if allowed:
            kinds = np.array(FAST_LINE.findall(text), dtype="<U1")
            plain = kinds != ""
        else:
            plain = np.zeros(count, dtype=bool)
        if len(plain) != count:  # cannot happen: one record per line
            raise JobFileError(
                self.file,
                0,
                QCoreApplication.translate("JobFile", "could not split the file into lines"),
            )
        plain_index = np.flatnonzero(plain)
        texts = [plain_code(lines[i]) for i in plain_index.tolist()]
        lengths = np.fromiter(map(len, texts), dtype=np.int64, count=len(texts))
        if len(texts) and int(lengths.max()) > MAX_LINE_CHARS:  # left to the full parser
            plain[plain_index[lengths > MAX_LINE_CHARS]] = False
            keep = lengths <= MAX_LINE_CHARS
            texts = [t for t, k in zip(texts, keep.tolist(), strict=True) if k]
            plain_index = plain_index[keep]
        self._numbers(texts)
        self.lines = (plain_index + 1).astype(np.int32)
        return plain

    def _numbers(self, texts: list[str]) -> None:
        """Every plain line's G, X, Y and F in one numpy parse (F NaN where not given)."""
        self.texts = texts
        n = len(texts)
        has_f = np.fromiter(("F" in t for t in texts), dtype=bool, count=n)
        per_line = 3 + has_f.astype(np.int64)
        # A chunk of lines at a time: the whole file joined, encoded and translated at once
        # was three copies of its text (75 MB for a million lines) at the load's peak.
        numbers = np.empty(int(per_line.sum()))
        filled = 0
        for first in range(0, n, NUMBERS_CHUNK):
            chunk = " ".join(texts[first : first + NUMBERS_CHUNK]).encode("ascii")
            read = np.fromstring(chunk.translate(FAST_LETTERS), dtype=np.float64, sep=" ")
            if filled + len(read) > len(numbers):  # cannot happen: see below
                break
            numbers[filled : filled + len(read)] = read
            filled += len(read)
        starts = np.cumsum(per_line) - per_line
        if filled != len(numbers):  # cannot happen: the pattern admits numbers only
            raise JobFileError(
                self.file,
                0,
                QCoreApplication.translate("JobFile", "could not read the coordinates"),
            )
        self.g = numbers[starts]
        self.x = numbers[starts + 1]
        self.y = numbers[starts + 2]
        self.f = np.full(n, np.nan)
        self.f[has_f] = numbers[starts[has_f] + 3]

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
                    ).format("G1", repr(self.texts[k0 + k])),
                )
        return [
            JobFileError(self.file, int(self.lines[k0 + k]), refused[k])
            for k in sorted(refused)[:limit]
        ]

    def place(
        self, k0: int, k1: int, st: State, texts: list[str], start_relative: set[int] | None = None
    ) -> None:
        """Plain moves k0…k1-1 as MOVE operations, placed by the modal state in force.

        Their texts are added to ``texts``, the texts of the operations so far.
        """
        self.runs.append((k0, k1, len(texts)))
        texts.extend(self.texts[k0:k1])
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
        ranks = np.arange(int(k1s[-1]))
        ops = ranks + np.repeat(op0s - k0s, k1s - k0s)
        lines[ops] = self.lines[ranks]
        motion[ops] = self.g[ranks].astype(np.uint8)
        feed[ops] = self.f[ranks]
        named[ops] = 0b11
        positions[ops, 0] = self.x[ranks]
        positions[ops, 1] = self.y[ranks]
