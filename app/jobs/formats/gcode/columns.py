"""A G-code file's operations as they are parsed, in compact columns, and the arrays of them."""

from __future__ import annotations

from array import array
from collections.abc import Sequence
from typing import Any

import numpy as np
from PySide6.QtCore import QCoreApplication

from app.jobs.formats.gcode.pen import DOWN, UP
from app.jobs.formats.gcode.plain_moves import PlainMoves
from app.jobs.formats.gcode.program import (
    CCW_ARC,
    CW_ARC,
    LINEAR,
    MOVE,
    NO_MOTION,
    PEN_DOWN,
    PEN_UP,
    GcodeData,
)
from app.jobs.formats.gcode.sent_texts import SentTextsBuilder
from app.jobs.formats.gcode.state import Pending
from app.jobs.program import JobFileError


class OperationColumns:
    """Every operation's text, and the other lines' operations column by column.

    The plain moves' numbers stay with :class:`PlainMoves` until :meth:`data`.
    """

    def __init__(self) -> None:
        # Output, in operation order.
        self.texts = SentTextsBuilder()
        self.messages: dict[int, str] = {}
        # Compact columns (array, not list: a million lines of them must stay small).
        self.s_op = array("q")
        self.s_kind = array("B")
        self.s_line = array("i")
        self.s_motion = array("B")
        self.s_feed = array("d")
        self.s_named = array("H")
        self.pos_op = array("q")
        self.pos_col = array("q")
        self.pos_val = array("d")
        self.pen_ops = array("q")
        self.pen_states = array("B")
        self.dwell_ops = array("q")
        self.dwell_s = array("d")
        self.arc_ops = array("q")
        self.arc_blocks: list[np.ndarray] = []
        #: Pen lines sent as the profile's own pen command.
        self.translated = 0

    def add(self, number: int, pending: Sequence[Pending]) -> None:
        """The operations line ``number`` makes, appended after those so far."""
        for op in pending:
            index = len(self.texts)
            self.texts.append(op.text)
            self.s_op.append(index)
            self.s_kind.append(op.kind)
            self.s_line.append(number)
            self.s_motion.append(op.motion if op.kind == MOVE else NO_MOTION)
            self.s_feed.append(op.feed)
            named = 0
            for c, value in op.target.items():
                named |= 1 << c
                self.pos_op.append(index)
                self.pos_col.append(c)
                self.pos_val.append(value)
            self.s_named.append(named)
            pen = op.pen
            if op.kind in (PEN_UP, PEN_DOWN):
                pen = DOWN if op.kind == PEN_DOWN else UP
            if pen >= 0:
                self.pen_ops.append(index)
                self.pen_states.append(pen)
            if op.dwell:
                self.dwell_ops.append(index)
                self.dwell_s.append(op.dwell)
            if op.arc is not None and len(op.arc):
                self.arc_ops.extend([index] * len(op.arc))
                self.arc_blocks.append(op.arc)
            if op.message:
                self.messages[index] = op.message
            self.translated += op.translated

    def data(self, file: str, columns: Sequence[str], plain: PlainMoves) -> GcodeData:
        """The program's arrays: these columns and the plain moves, modal values carried."""
        n = len(self.texts)
        sent = self.texts.done()  # first: its build arrays go before the columns are made
        k = len(columns)
        if k > 16:
            raise JobFileError(file, 0, QCoreApplication.translate("JobFile", "more than 16 axes"))
        kinds = np.full(n, MOVE, dtype=np.uint8)
        lines = np.zeros(n, dtype=np.int32)
        motion = np.full(n, NO_MOTION, dtype=np.uint8)
        feed = np.full(n, np.nan)
        named = np.zeros(n, dtype=np.uint16)
        positions = np.full((n, k), np.nan)

        # Plain moves, placed run by run.
        plain.fill(lines, motion, feed, named, positions)
        plain.release()

        # Everything else.
        slow = _numbers(self.s_op, np.int64)
        kinds[slow] = _numbers(self.s_kind, np.uint8)
        lines[slow] = _numbers(self.s_line, np.int32)
        motion[slow] = _numbers(self.s_motion, np.uint8)
        feed[slow] = _numbers(self.s_feed, np.float64)
        named[slow] = _numbers(self.s_named, np.uint16)
        positions[_numbers(self.pos_op, np.int64), _numbers(self.pos_col, np.int64)] = _numbers(
            self.pos_val, np.float64
        )

        # Modal values carry forward: positions per axis, the feed.
        steps = np.arange(n)
        for c in range(k):
            valid = (named & (1 << c)) != 0
            positions[:, c] = positions[np.maximum.accumulate(np.where(valid, steps, 0)), c]
        if n:
            given = ~np.isnan(feed)
            feed = feed[np.maximum.accumulate(np.where(given, steps, 0))]

        # The pen: from the pen operations, or G1/G2/G3 as work when the file has none.
        pen_info = bool(self.pen_ops)
        if pen_info:
            events = _numbers(self.pen_ops, np.int64)
            states = _numbers(self.pen_states, np.uint8).astype(bool)
            last = np.searchsorted(events, steps, side="right") - 1
            pen = np.where(last >= 0, states[np.maximum(last, 0)], False)
        else:
            pen = (motion == LINEAR) | (motion == CW_ARC) | (motion == CCW_ARC)

        arc_points = np.full((len(self.arc_ops), k), np.nan)
        row = 0
        for block in self.arc_blocks:
            arc_points[row : row + len(block), : block.shape[1]] = block
            row += len(block)
        return GcodeData(
            file,
            tuple(columns),
            kinds,
            lines,
            motion,
            feed,
            pen,
            pen_info,
            positions,
            named,
            sent,
            self.messages,
            _numbers(self.dwell_ops, np.int64),
            _numbers(self.dwell_s, np.float64),
            _numbers(self.arc_ops, np.int64),
            arc_points,
        )


def _numbers(column: array[Any], dtype: type[np.generic]) -> np.ndarray:
    """An array column as numpy, without a copy through Python objects."""
    return np.frombuffer(column, dtype=dtype) if len(column) else np.zeros(0, dtype=dtype)
