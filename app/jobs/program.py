"""A job as the station runs it: an ordered list of machine-independent operations.

Every loader (point lists, Excellon drill files, string-art files, G-code)
produces the same :class:`Program`, so the preview, the
soft-limit check, the dry run and the runner exist once.  Each operation
keeps the file and line it came from, so every message about it can point
the operator at the source.
"""

from __future__ import annotations

import enum
import hashlib
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import ClassVar, Literal

import numpy as np

from app.jobs.names import clipped, shown
from app.jobs.texts import localized_format, number, translate


class OpKind(enum.Enum):
    MOVE = "move"  # to absolute axis positions (mm or degrees), travel unless the pen is down
    DRILL = "drill"  # one drill cycle where the tool is
    PEN_UP = "pen up"
    PEN_DOWN = "pen down"
    WAIT = "wait"  # for the operator to confirm (a message says what to do)
    COMMENT = "comment"  # shown while running, no motion
    GCODE = "gcode"  # a G-code line with no modelled motion (dwell, modal words), sent as written


@dataclass(frozen=True)
class SourceRef:
    file: str
    line: int

    def __str__(self) -> str:
        return f"{shown(self.file)}:{self.line}"


@dataclass(frozen=True)
class Operation:
    kind: OpKind
    source: SourceRef
    target: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))
    message: str = ""
    #: G-code text a G-code machine is sent as written (G-code files); empty: the dialect
    #: renders the operation from its kind and target.
    line: str = ""

    def describe(self) -> str:
        if self.kind is OpKind.MOVE:
            where = " ".join(f"{axis}{number(value, '.3f')}" for axis, value in self.target.items())
            return translate("JobFile", "move to {0}").format(where)
        # The kinds' words are translated where the window names them (context "Operation"):
        # a refusal listed "pen down" in English in a Czech window.
        kind = translate("Operation", self.kind.value)
        if self.kind in (OpKind.WAIT, OpKind.COMMENT) and self.message:
            return f"{kind}: {self.message}"
        if self.kind is OpKind.GCODE and self.line:
            return clipped(self.line)
        return kind


def move(source: SourceRef, **target: float) -> Operation:
    return Operation(OpKind.MOVE, source, MappingProxyType(dict(target)))


@dataclass(frozen=True)
class LineProblem:
    """A file line the machine cannot execute, found while loading: the runner refuses it."""

    line: int
    text: str
    reason: str

    def __str__(self) -> str:
        return translate("JobFile", "line {0}: {1} — {2}").format(
            self.line, clipped(self.text), self.reason
        )


@dataclass(frozen=True)
class ProgramPath:
    """The vertices a program's moves pass through, as arrays (preview, estimate, limits).

    ``coords[k]`` is the position (one column per requested axis, NaN where
    the axis was never set) after vertex ``k``; ``ops[k]`` the operation that
    reaches it (non-decreasing; an arc contributes several vertices with the
    same index) and ``pen[k]`` whether the pen was down on the way there.
    """

    coords: np.ndarray  # float64, shape (n, len(axes))
    ops: np.ndarray  # int64, shape (n,)
    pen: np.ndarray  # bool, shape (n,)

    def __len__(self) -> int:
        return len(self.ops)


@dataclass(frozen=True)
class Program:
    """Operations in order, plus the array views large programs override to stay fast.

    A G-code file of a million lines is not kept as a million Operation
    objects: its subclass serves ``operations`` lazily and answers
    :meth:`path`, :meth:`kinds` and :meth:`limit_violations` from arrays.
    """

    name: str
    operations: Sequence[Operation]
    source: Path | None = None
    #: What the loader wants the operator to know (e.g. the travel its ordering saved).
    notes: tuple[str, ...] = ()
    #: Axes the job moves relative to wherever the machine stands when it starts (a G-code
    #: file's G91 or G92 before it set them); its positions on them are as if that were 0,
    #: so the runner starts it only from there.
    start_relative: tuple[str, ...] = ()
    #: What :meth:`preview_path` gives: "axes", the two axes asked for as they are (the
    #: preview projects them on a polar machine), or "board", the work's own plane in mm
    #: whatever the axes (a job that knows its geometry projects itself, and better).
    preview_plane: ClassVar[Literal["axes", "board"]] = "axes"

    def __len__(self) -> int:
        return len(self.operations)

    def __iter__(self) -> Iterator[Operation]:
        return iter(self.operations)

    def __getitem__(self, index: int) -> Operation:
        return self.operations[index]

    @property
    def axes(self) -> tuple[str, ...]:
        """Axis names the program moves, in order of first use."""
        seen: dict[str, None] = {}
        for op in self.operations:
            for axis in op.target:
                seen.setdefault(axis)
        return tuple(seen)

    def fingerprint(self) -> str:
        """Identifies the program in a checkpoint: a resumed job must be the same job."""
        digest = hashlib.sha256()
        for op in self.operations:
            digest.update(repr((op.kind.value, sorted(op.target.items()), op.message)).encode())
        return digest.hexdigest()[:16]

    def positions(self) -> Iterator[tuple[int, Mapping[str, float], bool]]:
        """(operation index, position after it, pen down) for every MOVE, tracking the pen."""
        where: dict[str, float] = {}
        pen_down = False
        for index, op in enumerate(self.operations):
            if op.kind is OpKind.PEN_DOWN:
                pen_down = True
            elif op.kind is OpKind.PEN_UP:
                pen_down = False
            elif op.kind is OpKind.MOVE:
                where.update(op.target)
                yield index, dict(where), pen_down

    def path(self, axes: Sequence[str]) -> ProgramPath:
        """Every MOVE's end position on ``axes`` (NaN until an axis is first set)."""
        rows: list[list[float]] = []
        ops: list[int] = []
        pen: list[bool] = []
        for index, where, pen_down in self.positions():
            rows.append([where.get(axis, np.nan) for axis in axes])
            ops.append(index)
            pen.append(pen_down)
        coords = np.array(rows, dtype=np.float64).reshape(len(rows), len(axes))
        return ProgramPath(coords, np.array(ops, dtype=np.int64), np.array(pen, dtype=bool))

    def works_between(self, lo: int, hi: int) -> bool | None:
        """Whether operations ``[lo, hi)`` do work that running them again would repeat.

        None: the pen says (a plotter's pen-down strokes).  A machine without a
        pen (the winder: its plunges drill, its moves wind) answers itself, so a
        resume never sends its work again silently.
        """
        return None

    def preview_path(self, x_axis: str, y_axis: str | None) -> ProgramPath:
        """What the preview draws in the plane: the two axes as they are (polar jobs project)."""
        if y_axis is None:
            flat = self.path((x_axis,))
            zeros = np.zeros((len(flat), 1))
            return ProgramPath(np.hstack([flat.coords, zeros]), flat.ops, flat.pen)
        return self.path((x_axis, y_axis))

    def unexecutable_lines(self) -> Sequence[LineProblem]:
        """File lines this machine cannot execute (G-code files name them while loading)."""
        return ()

    def kinds(self) -> frozenset[OpKind]:
        """The operation kinds the program uses (capability checks without a full scan)."""
        return frozenset(op.kind for op in self.operations)

    def kind_and_line(self, index: int) -> tuple[OpKind, str]:
        """Operation ``index``'s kind and its :attr:`Operation.line` ("" when the dialect
        renders it): what a running job reads of every line, without building the operation."""
        op = self[index]
        return op.kind, op.line

    def indices_of(self, kind: OpKind) -> np.ndarray:
        """Indices of the operations of ``kind``, ascending."""
        found = [i for i, op in enumerate(self.operations) if op.kind is kind]
        return np.array(found, dtype=np.int64)

    def limit_violations(self, limits: Mapping[str, tuple[float, float]]) -> list[LimitViolation]:
        """Every move that would leave the machine's travel (or names an axis it lacks)."""
        found: list[LimitViolation] = []
        for index, op in enumerate(self.operations):
            for axis, value in op.target.items():
                low, high = limits.get(axis, (float("nan"), float("nan")))
                if not low <= value <= high:  # NaN limits (unknown axis) always fail
                    found.append(LimitViolation(index, op, axis, value, low, high))
        return found


@dataclass(frozen=True)
class LimitViolation:
    index: int
    operation: Operation
    axis: str
    value: float
    low: float
    high: float

    def __str__(self) -> str:
        if math.isnan(self.low) or math.isnan(self.high):  # an axis the machine does not have
            return localized_format(
                translate("JobFile", "{0}: {1} — {2} {3:g}: the machine has no {2} axis"),
                self.operation.source,
                self.operation.describe(),
                self.axis,
                self.value,
            )
        return localized_format(
            translate("JobFile", "{0}: {1} — {2} {3:g} is outside {4:g}…{5:g}"),
            self.operation.source,
            self.operation.describe(),
            self.axis,
            self.value,
            self.low,
            self.high,
        )


def check_limits(
    program: Program, limits: Mapping[str, tuple[float, float]]
) -> list[LimitViolation]:
    """Every move that would leave the machine's travel (or names an axis it lacks)."""
    return program.limit_violations(limits)


class JobFileError(ValueError):
    """A job file the station refuses, with the file, the line and the reason."""

    def __init__(self, file: str, line: int, reason: str) -> None:
        super().__init__(f"{shown(file)}:{line}: {reason}")
        self.file = file
        self.line = line
        self.reason = reason
        #: Further refusals of the same file, in file order (a G-code file's every bad line).
        self.more: tuple[JobFileError, ...] = ()
