"""A job file's source lines, kept for showing an operation as the file wrote it.

Read on the loading thread with the program (:mod:`widgets.jobs.loading`), bounded
(:data:`SOURCE_LINES_MAX_BYTES`), and kept as one text with line starts rather than
millions of strings.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import overload

import numpy as np

from app.jobs.program import JobFileError
from app.jobs.reading import read_job_text

#: Files larger than this are not kept in memory for showing source lines.
SOURCE_LINES_MAX_BYTES = 8_000_000


def file_size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:
        return 0


def read_lines(path: Path | None) -> Sequence[str]:
    """The job file's lines, for showing an operation's source as written (empty if unreadable).

    Skipped for very large files: the operations carry their own text, and a copy of
    a million lines is memory for nothing.
    """
    if path is None or file_size(path) > SOURCE_LINES_MAX_BYTES:
        return ()
    try:
        text = read_job_text(path, SOURCE_LINES_MAX_BYTES, latin1_fallback=True)
    except JobFileError:
        return ()
    return split_lines(text)


#: Characters split at a time: one ``str.splitlines`` holds the interpreter lock
#: throughout, and on 8 MB that kept the GUI thread waiting for a quarter of a second.
SPLIT_CHUNK_CHARS = 65_536


class SourceLines(Sequence[str]):
    """A file's lines as ``str.splitlines`` gives them, kept as the text and where each starts.

    Not a list of millions of strings: that was a hundred megabytes for a
    generator's 2-million-entry ``poradi.txt``, and every full garbage
    collection walked all two million (on whichever thread it fell, holding
    the interpreter lock).  A line is cut from the text when it is shown.
    """

    def __init__(self, text: str, starts: np.ndarray) -> None:
        self._text = text
        #: Where each line starts, then where the text ends (int64).
        self._starts = starts

    def __len__(self) -> int:
        return len(self._starts) - 1

    @overload
    def __getitem__(self, index: int) -> str: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[str]: ...

    def __getitem__(self, index: int | slice) -> str | Sequence[str]:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError(index)
        # The line with its line end (one of those splitlines knows), cut off as splitlines does.
        piece = self._text[int(self._starts[index]) : int(self._starts[index + 1])].splitlines()
        return piece[0] if piece else ""


def split_lines(text: str) -> SourceLines:
    """``text.splitlines()`` in pieces, so the GUI thread gets the lock between them."""
    lengths: list[np.ndarray] = []
    start = 0
    while start < len(text):
        end = start + SPLIT_CHUNK_CHARS
        if end < len(text):
            # Cut just after an LF, always a line end (a CR LF pair stays whole); a piece
            # with none runs on to the next (a file of CRs alone is split in one go).
            cut = text.rfind("\n", start, end)
            if cut < 0:
                cut = text.find("\n", end)
            end = cut + 1 if cut >= 0 else len(text)
        else:
            end = len(text)
        piece = text[start:end].splitlines(keepends=True)
        lengths.append(np.fromiter(map(len, piece), dtype=np.int64, count=len(piece)))
        start = end
    starts = np.zeros(1 + sum(len(part) for part in lengths), dtype=np.int64)
    if len(starts) > 1:
        np.cumsum(np.concatenate(lengths), out=starts[1:])
    return SourceLines(text, starts)
