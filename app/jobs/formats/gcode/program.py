"""The array-backed G-code program: what a loaded file is, answered from columns of numbers.

Why arrays: a plotter file of a million lines would be a million Operation
objects (and seconds of garbage collection) if built the plain way, yet the
preview, the limit check and the estimate only ever need columns of numbers.
:class:`GcodeProgram` therefore keeps one numpy array per property of an
operation (kind, source line, motion, feed, pen, end position) plus the text
each operation sends, and builds an :class:`Operation` only when one is asked
for (the runner's current line, a refusal message).
"""

from __future__ import annotations

import hashlib
import math
import operator
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import overload

import numpy as np
import numpy.typing as npt

from app.jobs.formats.gcode.sent_texts import SentTexts
from app.jobs.program import (
    LimitViolation,
    LineProblem,
    Operation,
    OpKind,
    Program,
    ProgramPath,
    SourceRef,
)

#: Operation kinds by code (the uint8 stored per operation).
KINDS: tuple[OpKind, ...] = tuple(OpKind)
KIND_CODE: Mapping[OpKind, int] = MappingProxyType({kind: i for i, kind in enumerate(KINDS)})
MOVE = KIND_CODE[OpKind.MOVE]
GCODE = KIND_CODE[OpKind.GCODE]
COMMENT = KIND_CODE[OpKind.COMMENT]
WAIT = KIND_CODE[OpKind.WAIT]
PEN_UP = KIND_CODE[OpKind.PEN_UP]
PEN_DOWN = KIND_CODE[OpKind.PEN_DOWN]

#: Motion per operation (uint8): the modal motion a MOVE ran with.
RAPID, LINEAR, CW_ARC, CCW_ARC, HOME = 0, 1, 2, 3, 4
NO_MOTION = 255


#: A line this machine cannot execute (the name the G-code modules have always used).
GcodeProblem = LineProblem


class GcodeData:
    """The arrays a :class:`GcodeProgram` is made of (one entry per operation unless noted)."""

    def __init__(
        self,
        file: str,
        columns: tuple[str, ...],
        kinds: npt.NDArray[np.uint8],
        lines: npt.NDArray[np.int32],
        motion: npt.NDArray[np.uint8],
        feed: npt.NDArray[np.float64],
        pen: npt.NDArray[np.bool_],
        pen_info: bool,
        positions: npt.NDArray[np.float64],
        named: npt.NDArray[np.uint16],
        texts: SentTexts,
        messages: dict[int, str],
        dwell_ops: npt.NDArray[np.int64],
        dwell_s: npt.NDArray[np.float64],
        arc_ops: npt.NDArray[np.int64],
        arc_points: npt.NDArray[np.float64],
    ) -> None:
        self.file = file
        #: The axis of each column of ``positions`` (and of ``arc_points``).
        self.columns = columns
        self.kinds = kinds
        self.lines = lines
        #: RAPID, LINEAR, CW_ARC, CCW_ARC or HOME for a MOVE, NO_MOTION otherwise.
        self.motion = motion
        #: The modal feed (mm/min) in force at each operation; NaN until a file sets one.
        self.feed = feed
        #: Pen down while the operation runs (from the file's pen commands; without any,
        #: G1/G2/G3 moves count as work).
        self.pen = pen
        self.pen_info = pen_info
        #: Machine position (mm; degrees for A B C) after each operation; NaN until set.
        self.positions = positions
        #: Bit ``c`` set: the operation (a MOVE) moves column ``c``.
        self.named = named
        #: What each operation sends (empty: not sent), made when asked for.
        self.sent = texts
        self.messages = messages
        #: G4 dwells: the operations and their seconds (sparse).
        self.dwell_ops = dwell_ops
        self.dwell_s = dwell_s
        #: Flattened arcs: inner vertices (before each arc's end) and their operations.
        self.arc_ops = arc_ops
        self.arc_points = arc_points

    def __len__(self) -> int:
        return len(self.kinds)

    def operation(self, index: int) -> Operation:
        kind = KINDS[int(self.kinds[index])]
        target: Mapping[str, float] = MappingProxyType({})
        if kind is OpKind.MOVE:
            bits = int(self.named[index])
            row = self.positions[index]
            target = MappingProxyType(
                {axis: float(row[c]) for c, axis in enumerate(self.columns) if bits & (1 << c)}
            )
        return Operation(
            kind,
            SourceRef(self.file, int(self.lines[index])),
            target,
            self.messages.get(index, ""),
            self.sent[index],
        )

    @cached_property
    def texts(self) -> list[str]:
        """Every operation's text as a list, made on first use and kept.

        For the callers that search all of them (a resume's ``G92`` offsets,
        the CoreXY's step-interval estimate); the load, the preview, the run
        and the fingerprint read :attr:`sent` and never make it.
        """
        return list(self.sent)

    def column_values(self, rows: npt.NDArray[np.float64], axes: Sequence[str]) -> np.ndarray:
        """``rows`` (n, columns) rearranged to ``axes``; NaN for axes the file never moves."""
        out = np.full((len(rows), len(axes)), np.nan)
        for i, axis in enumerate(axes):
            if axis in self.columns:
                out[:, i] = rows[:, self.columns.index(axis)]
        return out


class GcodeOperations(Sequence[Operation]):
    """The operations of a G-code program, each built when asked for (never all at once)."""

    def __init__(self, data: GcodeData) -> None:
        self._data = data

    def __len__(self) -> int:
        return len(self._data)

    @overload
    def __getitem__(self, index: int) -> Operation: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[Operation]: ...

    def __getitem__(self, index: int | slice) -> Operation | Sequence[Operation]:
        if isinstance(index, slice):
            return [self._data.operation(i) for i in range(*index.indices(len(self)))]
        i = operator.index(index)
        if i < 0:
            i += len(self)
        if not 0 <= i < len(self):
            raise IndexError(index)
        return self._data.operation(i)

    def __iter__(self) -> Iterator[Operation]:
        for i in range(len(self)):
            yield self._data.operation(i)


@dataclass(frozen=True, eq=False, kw_only=True)
class GcodeProgram(Program):
    """A G-code file as the station runs it, answered from arrays (see the module doc)."""

    #: Lines this machine cannot execute, by line; the runner refuses the job while any remain.
    unsupported: tuple[GcodeProblem, ...] = ()
    data: GcodeData = field(repr=False)

    def unexecutable_lines(self) -> Sequence[LineProblem]:
        return self.unsupported

    @property
    def axes(self) -> tuple[str, ...]:
        d = self.data
        first: list[tuple[int, str]] = []
        for c, axis in enumerate(d.columns):
            hits = np.flatnonzero(d.named & (1 << c))
            if len(hits):
                first.append((int(hits[0]), axis))
        return tuple(axis for _, axis in sorted(first))

    def fingerprint(self) -> str:
        """Hash of what is sent and of the kinds: the same file for the same machine."""
        d = self.data
        digest = hashlib.sha256()
        digest.update(d.kinds.tobytes())
        for piece in d.sent.encoded_joined():  # the same bytes as all joined at once
            digest.update(piece)
        digest.update(repr(sorted(d.messages.items())).encode("utf-8", "surrogatepass"))
        return digest.hexdigest()[:16]

    def positions(self) -> Iterator[tuple[int, Mapping[str, float], bool]]:
        d = self.data
        for index in np.flatnonzero(d.kinds == MOVE).tolist():
            row = d.positions[index]
            where = {a: float(row[c]) for c, a in enumerate(d.columns) if not math.isnan(row[c])}
            yield index, where, bool(d.pen[index])

    def path(self, axes: Sequence[str]) -> ProgramPath:
        """Every move's end on ``axes``, with each arc's inner vertices before its end."""
        d = self.data
        ops = np.flatnonzero(d.kinds == MOVE).astype(np.int64)
        coords = d.column_values(d.positions[ops], axes)
        pen = d.pen[ops]
        if len(d.arc_ops):
            at = np.searchsorted(ops, d.arc_ops)
            coords = np.insert(coords, at, d.column_values(d.arc_points, axes), axis=0)
            pen = np.insert(pen, at, d.pen[d.arc_ops])
            ops = np.insert(ops, at, d.arc_ops)
        return ProgramPath(coords, ops, pen)

    def kinds(self) -> frozenset[OpKind]:
        counts = np.bincount(self.data.kinds, minlength=len(KINDS))
        return frozenset(KINDS[i] for i in np.flatnonzero(counts))

    def indices_of(self, kind: OpKind) -> np.ndarray:
        return np.flatnonzero(self.data.kinds == KIND_CODE[kind]).astype(np.int64)

    def kind_and_line(self, index: int) -> tuple[OpKind, str]:
        # From the arrays: building each line's operation (its target's mapping) cost a
        # running job about as much as the rest of sending the line.
        d = self.data
        if index < 0:
            index += len(d)
        if not 0 <= index < len(d):
            raise IndexError(index)
        return KINDS[int(d.kinds[index])], d.sent[index]

    def limit_violations(self, limits: Mapping[str, tuple[float, float]]) -> list[LimitViolation]:
        """One entry per move and axis outside the travel; arcs are judged by their vertices."""
        d = self.data
        found: dict[tuple[int, int], float] = {}
        nan_range = (math.nan, math.nan)
        arc_named = d.named[d.arc_ops] if len(d.arc_ops) else d.named[:0]
        for c, axis in enumerate(d.columns):
            low, high = limits.get(axis, nan_range)
            bit = 1 << c
            values = d.positions[:, c]
            with np.errstate(invalid="ignore"):
                bad = ((d.named & bit) != 0) & ~((values >= low) & (values <= high))
            for index in np.flatnonzero(bad).tolist():
                found[(index, c)] = float(values[index])
            if len(d.arc_ops):
                inner = d.arc_points[:, c]
                with np.errstate(invalid="ignore"):
                    out = np.flatnonzero(
                        ((arc_named & bit) != 0) & ~((inner >= low) & (inner <= high))
                    )
                # Per arc, its vertex farthest outside (in numpy: an arc has many vertices).
                if not len(out):
                    continue
                ops, values = d.arc_ops[out], inner[out]
                if math.isnan(low) or math.isnan(high):
                    beyond = np.full(len(values), math.inf)
                else:
                    beyond = np.maximum(low - values, values - high)
                order = np.lexsort((beyond, ops))
                last = np.flatnonzero(np.append(ops[order][1:] != ops[order][:-1], True))
                for k in order[last].tolist():
                    key = (int(ops[k]), c)
                    value = float(values[k])
                    if key not in found or _beyond(value, low, high) > _beyond(
                        found[key], low, high
                    ):
                        found[key] = value
        violations: list[LimitViolation] = []
        built: dict[int, Operation] = {}
        for index, c in sorted(found):
            op = built.get(index) or built.setdefault(index, d.operation(index))
            low, high = limits.get(d.columns[c], nan_range)
            violations.append(LimitViolation(index, op, d.columns[c], found[(index, c)], low, high))
        return violations


def _beyond(value: float, low: float, high: float) -> float:
    """How far ``value`` lies outside low…high (unknown limits: infinitely)."""
    if math.isnan(low) or math.isnan(high):
        return math.inf
    return max(low - value, value - high)
