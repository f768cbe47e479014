"""What each operation of a G-code program sends, kept as spans of the file's own bytes.

Why: a plotter file of a million lines kept as a million ``str`` objects is
80 MB of object headers and pointers, a third of the load's peak.  Most
operations send their line exactly as written (a plain ``G1 X… Y…`` without
spaces around it or a comment), so the file's text is kept once, as UTF-8
bytes, and each operation as the span of it that it sends; the texts the
parser had to change (pen commands translated, comments cut, words left out)
are kept apart as strings.  A text is made when it is asked for.
"""

from __future__ import annotations

import operator
import re
from array import array
from collections.abc import Iterator, Sequence
from typing import overload

import numpy as np
import numpy.typing as npt

#: Texts made at a time when all are wanted (the fingerprint, a list for old callers).
CHUNK = 65_536


class SentTexts(Sequence[str]):
    """Per operation: ``buffer[starts[i]:ends[i]]`` decoded, or ``extra[-1 - starts[i]]``."""

    def __init__(
        self,
        buffer: bytes,
        starts: np.ndarray,
        ends: np.ndarray,
        extra: list[str],
    ) -> None:
        self.buffer = buffer
        self.starts = starts
        self.ends = ends
        self.extra = extra

    def __len__(self) -> int:
        return len(self.starts)

    @overload
    def __getitem__(self, index: int) -> str: ...

    @overload
    def __getitem__(self, index: slice) -> list[str]: ...

    def __getitem__(self, index: int | slice) -> str | list[str]:
        if isinstance(index, slice):
            first, stop, step = index.indices(len(self))
            if step != 1:
                return [self._text(i) for i in range(first, stop, step)]
            return self._run(first, stop)
        i = operator.index(index)
        if i < 0:
            i += len(self)
        if not 0 <= i < len(self):
            raise IndexError(index)
        return self._text(i)

    def __iter__(self) -> Iterator[str]:
        for first in range(0, len(self), CHUNK):
            yield from self._run(first, min(first + CHUNK, len(self)))

    def _text(self, i: int) -> str:
        start = int(self.starts[i])
        if start < 0:
            return self.extra[-1 - start]
        return self.buffer[start : int(self.ends[i])].decode("utf-8", "surrogatepass")

    def _run(self, first: int, stop: int) -> list[str]:
        buffer, extra = self.buffer, self.extra
        return [
            extra[-1 - s] if s < 0 else buffer[s:e].decode("utf-8", "surrogatepass")
            for s, e in zip(
                self.starts[first:stop].tolist(), self.ends[first:stop].tolist(), strict=True
            )
        ]

    def matching(self, patterns: Sequence[re.Pattern[str]], stop: int) -> list[int]:
        """Operations before ``stop`` whose text any of ``patterns`` (ASCII) finds something in.

        One pass a pattern over the file's bytes: making a million strings to
        search them took seconds (a start part-way or a resume looks for a few
        modal words).  Patterns that begin with a literal are searched fastest.
        """
        stop = min(stop, len(self))
        if stop <= 0:
            return []
        starts, ends = self.starts[:stop], self.ends[:stop]
        found: set[int] = set()
        spans = np.flatnonzero(starts >= 0)
        if len(spans):
            first, last = starts[spans], ends[spans]
            end = int(last.max())
            for pattern in patterns:
                raw = re.compile(pattern.pattern.encode("ascii"), pattern.flags & ~re.UNICODE)
                hits = [(m.start(), m.end()) for m in raw.finditer(self.buffer, 0, end)]
                if not hits:
                    continue
                at = np.array(hits, dtype=np.int64)
                k = np.searchsorted(first, at[:, 0], side="right") - 1
                inside = (k >= 0) & (at[:, 1] <= last[np.maximum(k, 0)])
                found.update(spans[np.unique(k[inside])].tolist())
        # The texts of their own (pen commands translated, comments cut): few distinct ones.
        own = np.flatnonzero(starts < 0)
        if len(own):
            seen: dict[str, bool] = {}

            def matches(text: str) -> bool:
                known = seen.get(text)
                if known is None:
                    known = seen[text] = any(p.search(text) for p in patterns)
                return known

            hit = np.fromiter(map(matches, self.extra), dtype=bool, count=len(self.extra))
            found.update(own[hit[-1 - starts[own]]].tolist())
        return sorted(found)

    def any(self) -> bool:
        """Whether any operation sends anything."""
        spans = self.starts >= 0
        return bool(np.any(self.ends[spans] > self.starts[spans])) or any(self.extra)

    def encoded_joined(self) -> Iterator[bytes]:
        """``"\\n".join(self).encode("utf-8", "surrogatepass")`` in pieces (the fingerprint)."""
        for first in range(0, len(self), CHUNK):
            piece = "\n".join(self._run(first, min(first + CHUNK, len(self))))
            yield (b"\n" if first else b"") + piece.encode("utf-8", "surrogatepass")


class SentTextsBuilder:
    """The texts of the operations so far, appended in operation order."""

    def __init__(self) -> None:
        self.buffer = b""
        self.starts = array("q")
        self.ends = array("q")
        self.extra: list[str] = []

    def set_buffer(self, buffer: bytes) -> None:
        """The file's bytes the spans are of (before any text is added)."""
        self.buffer = buffer
        # Offsets of 4 bytes for any file the size cap allows: a million lines' spans in 8 MB.
        code = "i" if len(buffer) < 2**31 - 1 else "q"
        self.starts, self.ends = array(code), array(code)

    def __len__(self) -> int:
        return len(self.starts)

    def append(self, text: str) -> None:
        """A text of its own (not a span of the file)."""
        self.starts.append(-1 - len(self.extra))
        self.ends.append(0)
        self.extra.append(text)

    def extend_spans(
        self,
        starts: npt.NDArray[np.int64],
        ends: npt.NDArray[np.int64],
        own: Sequence[tuple[int, str]] = (),
    ) -> None:
        """Spans of ``buffer`` in order; ``own``: (position in the run, text) where a span is
        not what is sent (its start is ignored there)."""
        at = len(self.starts)
        kind = np.int32 if self.starts.itemsize == 4 else np.int64
        self.starts.frombytes(np.ascontiguousarray(starts, dtype=kind).tobytes())
        self.ends.frombytes(np.ascontiguousarray(ends, dtype=kind).tobytes())
        for k, text in own:
            self.starts[at + k] = -1 - len(self.extra)
            self.ends[at + k] = 0
            self.extra.append(text)

    def done(self) -> SentTexts:
        """The texts, their spans as numpy (the builder is not used after)."""
        kind = np.int32 if self.starts.itemsize == 4 else np.int64
        starts = np.frombuffer(self.starts, dtype=kind).copy() if len(self.starts) else None
        ends = np.frombuffer(self.ends, dtype=kind).copy() if len(self.ends) else None
        self.starts, self.ends = array(self.starts.typecode), array(self.ends.typecode)
        if starts is None or ends is None:
            starts = ends = np.zeros(0, dtype=kind)
        return SentTexts(self.buffer, starts, ends, self.extra)
