"""A string-art job as the winder runs it: drill every nail, wait, then wind the thread.

The winder (docs/protocols.md §4) turns the board on a base (A, degrees), moves
the needle or drill radially (X, mm from the centre) and along the drill
axis tilted 74.333° to the board (Z, mm; 0 is retracted, the tool clear of
the board).  The program assumes the base at A = 0 when it starts (after
homing) and keeps A unwrapped: every turn is the shortest signed one from
where the base is, so none is longer than 180°.

1. **Drill phase**, as the firmware's ``vrt_cm``: Z 0 is the drill tip
   1 cm above the board (``DRILL_CLEARANCE_MM``), where the firmware raises
   it before drilling; the program starts by going there.  Per nail in
   index order: turn the base to the nail's angle, move the tool to the
   nail's radius, drill 1 cm above plus ``drill_depth_mm`` deep, measured
   square to the board and travelled along the axis tilted 74.333° to it
   (``along_drill_axis_mm``: 10 mm deep is 10.386 mm of Z past the
   surface, 20.773 mm of Z in all), wait 250 ms at the bottom (``G4``),
   back to Z 0.  X is where the tool meets the board's surface: the tilt
   moves the hole's bottom about ``10·cos(74.333°) ≈ 2.7 mm`` radially
   from it, which leans the nails as the original machine did; no offset
   is modelled.  Then, as the firmware, the base turns back to nail 0 and
   the tool goes to nail 0's radius.
2. **Wait** for the operator: "Insert the nails, tie the thread to nail 0"
   (the sequence's first nail).  Every driver is switched off (``M18``)
   while the machine waits, as the firmware does; the next move switches
   them on again.
3. **Winding**, as the original firmware did it.  The needle works between
   an inner radius (``needle_in_mm``, 2 cm, inside the innermost nail, for
   the whole board) and, per nail wrapped, an outer one (``needle_out_mm``,
   2 cm, outside that nail: the firmware's ``modul(f) + 2.0``); it crosses
   the nail ring only halfway between two neighbouring nails, and while
   outside it turns only across the nail it wraps; the gap between two
   nails is the direction of their midpoint (the firmware's, FIDELITY
   S0-26).  To start it goes out 2 cm beyond the board's edge (the
   firmware's ``polomer_matrice_cm + 2.0``, FIDELITY S0-19), turns to the
   gap between the first nail and the next one, moves in and turns back
   to the first nail's angle (nail 0: angle 0); the drill's driver is then
   switched off for the winding (``M18 Z0``, against overheating).  Then
   for each next nail ``k`` it turns (inside) the shorter way round to the
   gap beside ``k`` on the side it approaches from, moves out, turns across
   ``k`` to the gap on the other
   side — the thread wraps the nail — and moves in.

   Which entries are wound differs from the firmware on purpose (FIDELITY
   S0-22): its loop ``for(i=0; i<count-1; i++) omotej_hrebik(entry i+1)``
   wraps the 1st…(count-1)th entries, so it wraps the nail the thread is
   tied to (nothing gained: the thread is anchored there) and never the
   last one (a connection of the picture lost).  StepDeck ties the thread
   to the first entry and wraps the 2nd…last: every connection of the file
   is made once.

Every operation records the nail it serves (``nail_of_op``) and the
sequence entry (``entry_of_op``, -1 in the drill phase), so the preview
can show the current nail while the job runs.

A generator's sequence may hold millions of entries, four operations each:
the winding phase is computed with numpy (which way round each nail is
wrapped is a two-state recurrence, the only loop) and kept as columns; its
operations are made when asked for (:class:`StringArtOperations`), and the
limit check and the fingerprint read the columns.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path
from types import MappingProxyType
from typing import ClassVar, Literal, overload

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.jobs.formats.string_art.geometry import (
    DRILL_CLEARANCE_MM,
    DRILL_DEPTH_MM,
    DRILL_DWELL_S,
    NEEDLE_CLEARANCE_MM,
    along_drill_axis_mm,
    half_gaps,
    shortest_turn,
)
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams, read_string_art
from app.jobs.program import (
    JobFileError,
    LimitViolation,
    Operation,
    OpKind,
    Program,
    ProgramPath,
    SourceRef,
)
from app.profiles import MachineProfile

#: The winder's axes: base angle (deg), tool radius (mm), tool along the drill axis (mm).
AXES = ("A", "X", "Z")
_COLUMN = {name: i for i, name in enumerate(AXES)}
_KIND_CODES = {kind: i for i, kind in enumerate(OpKind)}
_KINDS = tuple(OpKind)


@dataclass(frozen=True)
class WindingSettings:
    """Where the needle goes round the nails and how deep the drill goes."""

    needle_in_mm: float = NEEDLE_CLEARANCE_MM  # inside the innermost nail while turning
    needle_out_mm: float = NEEDLE_CLEARANCE_MM  # outside the nail it wraps
    drill_depth_mm: float = DRILL_DEPTH_MM  # square to the board
    drill_clearance_mm: float = DRILL_CLEARANCE_MM  # the tip above the board at Z 0
    drill_dwell_s: float = DRILL_DWELL_S

    @property
    def drill_bottom_z(self) -> float:
        """Z at a hole's bottom: clearance and depth, along the tilted axis."""
        return along_drill_axis_mm(self.drill_clearance_mm + self.drill_depth_mm)


@dataclass(frozen=True, kw_only=True)
class StringArtProgram(Program):
    """The operations plus, per operation, the nail it serves and the A/X/Z after it."""

    job: StringArtJob
    #: The nail each operation serves (-1: none).
    nail_of_op: np.ndarray = field(compare=False, repr=False)
    #: The sequence entry each operation winds to (-1: drill phase).
    entry_of_op: np.ndarray = field(compare=False, repr=False)
    #: The axis each MOVE sets (0 A, 1 X, 2 Z; -1 for other operations) and its value.
    move_axis: np.ndarray = field(compare=False, repr=False)
    move_values: np.ndarray = field(compare=False, repr=False)
    kind_codes: np.ndarray = field(compare=False, repr=False)
    #: Index of the operator's WAIT between drilling and winding.
    wait_index: int = -1
    #: Model seconds on the profile it was built for (None without a profile).
    estimate_s: float | None = None
    needle_in_radius_mm: float = 0.0
    #: The largest outer radius (each nail's own is its radius plus ``needle_out_mm``).
    needle_out_radius_mm: float = 0.0
    #: The dwells at the holes' bottoms (``G4`` operations) and how long each is.
    dwell_ops: np.ndarray = field(
        default_factory=lambda: np.zeros(0, dtype=np.int64), compare=False, repr=False
    )
    dwell_s: float = 0.0
    preview_plane: ClassVar[Literal["axes", "board"]] = "board"

    def column_after(self, column: int, ops: np.ndarray) -> np.ndarray:
        """Axis ``column`` (0 A, 1 X, 2 Z) after each operation in ``ops`` (ascending; NaN
        until set).

        One column at a time, not kept: all three for 8 million operations
        were 192 MB held for the program's life.  And a chunk of operations
        at a time, carrying the last move on the axis: numpy's gathers hold
        the interpreter lock, and over millions at once the window waited
        for it a tenth of a second and more.
        """
        axis, values = self.move_axis, self.move_values
        out = np.empty(len(ops))
        carry = -1  # the last operation so far that set the axis
        for first in range(0, len(axis), COLUMN_CHUNK):
            if not len(ops) or first > ops[-1]:
                break  # past the last operation asked about: nothing more to carry
            stop = min(first + COLUMN_CHUNK, len(axis))
            last = np.where(axis[first:stop] == column, np.arange(first, stop), -1)
            np.maximum.accumulate(last, out=last)
            np.maximum(last, carry, out=last)
            carry = int(last[-1])
            lo, hi = np.searchsorted(ops, (first, stop))
            at = last[ops[lo:hi] - first]
            out[lo:hi] = np.where(at >= 0, values[np.maximum(at, 0)], np.nan)
        return out

    def axis_positions(self, ops: np.ndarray) -> np.ndarray:
        """(len(ops), 3): A, X, Z after each operation in ``ops`` (NaN until first set)."""
        return np.column_stack([self.column_after(column, ops) for column in range(len(AXES))])

    def _move_indices(self) -> np.ndarray:
        return np.flatnonzero(self.kind_codes == _KIND_CODES[OpKind.MOVE])

    def fingerprint(self) -> str:
        """The columns hashed: every operation's kind, axis and value, and what it serves."""
        digest = hashlib.sha256()
        # The arrays' own memory, not a tobytes() copy: copying 64 MB holds the interpreter
        # lock (the GUI thread waits), hashing a buffer does not.
        for column in (self.kind_codes, self.move_axis, self.move_values):
            digest.update(np.ascontiguousarray(column).data.cast("B"))
        # Hashed as the int32 it was kept as before (the same job, the same fingerprint, so a
        # checkpoint written then still resumes), a chunk at a time rather than a 32 MB copy.
        for first in range(0, len(self.nail_of_op), 1 << 20):
            digest.update(self.nail_of_op[first : first + (1 << 20)].astype(np.int32).data)
        digest.update(np.ascontiguousarray(self.entry_of_op).data.cast("B"))
        return digest.hexdigest()[:16]

    def limit_violations(self, limits: Mapping[str, tuple[float, float]]) -> list[LimitViolation]:
        """Every move outside the travel, from the columns (millions of moves, no loop)."""
        found: list[LimitViolation] = []
        for column, axis in enumerate(AXES):
            low, high = limits.get(axis, (math.nan, math.nan))
            values = self.move_values
            with np.errstate(invalid="ignore"):
                bad = (self.move_axis == column) & ~((values >= low) & (values <= high))
            for index in np.flatnonzero(bad).tolist():
                found.append(
                    LimitViolation(index, self[index], axis, float(values[index]), low, high)
                )
        found.sort(key=lambda v: v.index)
        return found

    def path(self, axes: Sequence[str]) -> ProgramPath:
        names = tuple(axes)
        moves = self._move_indices()
        coords = np.full((len(moves), len(names)), np.nan)
        for column, name in enumerate(names):
            if name in _COLUMN:
                coords[:, column] = self.column_after(_COLUMN[name], moves)
        return ProgramPath(coords, moves.astype(np.int64), np.zeros(len(moves), dtype=bool))

    def works_between(self, lo: int, hi: int) -> bool:
        """A plunge drills a nail: any Z move is work, never sent again silently.

        The relay's string-art seeds 41 and 59: a reopened port, 13 operations
        "that draw nothing" sent again, a nail drilled twice.  The winding
        phase's turns are not counted: the resume goes back along the winding
        (retrace) before it sends them again, so a turn resent from where it
        began winds its nail once (tests/e2e/test_e2e_string_art.py).
        """
        lo, hi = max(lo, 0), min(hi, len(self.kind_codes))
        if hi <= lo:
            return False
        moves = self.kind_codes[lo:hi] == _KIND_CODES[OpKind.MOVE]
        return bool(np.any(moves & (self.move_axis[lo:hi] == _COLUMN["Z"])))

    def preview_path(self, x_axis: str, y_axis: str | None) -> ProgramPath:
        """The board plane in mm whatever the axes: x = X·cos A, y = X·sin A; winding is work."""
        moves = self._move_indices()
        angle = np.radians(np.nan_to_num(self.column_after(0, moves)))
        radius = np.nan_to_num(self.column_after(1, moves))
        coords = np.column_stack((radius * np.cos(angle), radius * np.sin(angle)))
        pen = moves > self.wait_index
        return ProgramPath(coords, moves.astype(np.int64), pen)

    def preview_travel(self) -> tuple[ProgramPath, float]:
        """The board-plane path up to the wait (the drilling: travel) and how far from the
        centre the winding goes.

        The preview hides the winding under the thread it lays: for a
        2-million-entry job its 8 million vertices took seconds to lay out and
        held the interpreter lock (the window waited) only to be thrown away.
        """
        moves = self._move_indices()
        moves = moves[: int(np.searchsorted(moves, self.wait_index, side="right"))]
        angle = np.radians(np.nan_to_num(self.column_after(0, moves)))
        radius = np.nan_to_num(self.column_after(1, moves))
        coords = np.column_stack((radius * np.cos(angle), radius * np.sin(angle)))
        path = ProgramPath(coords, moves.astype(np.int64), np.zeros(len(moves), dtype=bool))
        reach = 0.0
        for first in range(max(self.wait_index + 1, 0), len(self.move_axis), COLUMN_CHUNK):
            piece = slice(first, first + COLUMN_CHUNK)
            values = self.move_values[piece][self.move_axis[piece] == _COLUMN["X"]]
            if len(values):
                reach = max(reach, float(np.nanmax(np.abs(values), initial=0.0)))
        return path, reach

    @cached_property
    def _kind_set(self) -> frozenset[OpKind]:
        # A count per code, not a sort: millions of operations in a few milliseconds.
        used = np.flatnonzero(np.bincount(self.kind_codes, minlength=len(_KINDS)))
        return frozenset(_KINDS[int(code)] for code in used)

    def kinds(self) -> frozenset[OpKind]:
        return self._kind_set

    def indices_of(self, kind: OpKind) -> np.ndarray:
        return np.flatnonzero(self.kind_codes == _KIND_CODES[kind]).astype(np.int64)

    def current_nail(self, done: int) -> int:
        """The nail the operation after the first ``done`` serves (the last one when all are)."""
        if not len(self.nail_of_op):
            return -1
        return int(self.nail_of_op[min(max(done, 0), len(self.nail_of_op) - 1)])

    def summary(self) -> str:
        return self.job.summary(self.estimate_s)


class _Builder:
    """Collects operations and their per-operation arrays."""

    def __init__(self) -> None:
        self.ops: list[Operation] = []
        self.nails: list[int] = []
        self.entries: list[int] = []
        self.rows: list[tuple[float, float, float]] = []
        self.where = [math.nan, math.nan, math.nan]
        self.angle = 0.0  # the base is at A = 0 when the program starts

    def add(self, op: Operation, nail: int, entry: int) -> None:
        """A motionless operation (comment, wait)."""
        self.ops.append(op)
        self.nails.append(nail)
        self.entries.append(entry)
        self.rows.append((self.where[0], self.where[1], self.where[2]))

    def move(
        self, source: SourceRef, axis: str, value: float, message: str, nail: int, entry: int
    ) -> None:
        self.where[_COLUMN[axis]] = value
        self.add(
            Operation(OpKind.MOVE, source, MappingProxyType({axis: value}), message), nail, entry
        )

    def turn_to(self, angle: float, source: SourceRef, message: str, nail: int, entry: int) -> None:
        """Turn the base the shorter way to ``angle`` (mod 360), keeping A unwrapped."""
        self.angle += shortest_turn(self.angle, angle)
        self.move(source, "A", self.angle, message, nail, entry)

    def turn_by(self, delta: float, source: SourceRef, message: str, nail: int, entry: int) -> None:
        self.angle += delta
        self.move(source, "A", self.angle, message, nail, entry)


def _turn(current: np.ndarray, target: np.ndarray) -> np.ndarray:
    """:func:`shortest_turn` on arrays."""
    result: np.ndarray = (target - current + 180.0) % 360.0 - 180.0
    return result


#: Operations read at a time by :meth:`StringArtProgram.column_after`.
COLUMN_CHUNK = 1 << 18

#: Entries computed at a time: the temporaries of a chunk stay a few megabytes however long
#: the list (a whole 2-million-entry list at once took about 150 MB of them).
WINDING_CHUNK = 131_072


def _fill_winding_angles(
    sequence: np.ndarray,
    angles: np.ndarray,
    before: np.ndarray,
    after: np.ndarray,
    start: float,
    rows: np.ndarray,
) -> None:
    """Per further entry, the base's unwrapped angle after the turn to the gap beside its
    nail (``rows[:, 0]``) and after the wrap round it (``rows[:, 2]``), in degrees.

    Entry ``k`` is approached counter-clockwise when the shortest turn from
    where the base is (the gap the previous wrap ended in) to the nail is
    not negative; where that gap is depends on which way the previous nail
    was wrapped, so the direction is a two-state recurrence.  Both answers
    are computed for every entry; an entry whose two answers agree fixes the
    direction whatever came before, and between two such entries each one
    keeps or flips it, so the chain is a running parity (no Python loop per
    entry).  Chunk by chunk, each carrying the previous chunk's last gap
    ends, direction and angle: the sums are made in the same order as one
    pass over the whole list would, so the angles are the same to the bit.
    """
    nails_all = sequence[1:]
    # ``start``: where the base stands after the step in (the first nail's angle); the
    # step-in leaves the needle where a counter-clockwise wrap would have.
    prev_ccw_end, prev_cw_end, prev_counter, angle_now = start, start, True, start
    for first in range(0, len(nails_all), WINDING_CHUNK):
        nails = nails_all[first : first + WINDING_CHUNK]
        angle = angles[nails]
        end_ccw = angle + after[nails]  # where a wrap approached counter-clockwise ends
        end_cw = angle - before[nails]
        from_ccw = np.concatenate(([prev_ccw_end], end_ccw[:-1]))
        from_cw = np.concatenate(([prev_cw_end], end_cw[:-1]))
        if_ccw = _turn(from_ccw, angle) >= 0  # the direction after a counter-clockwise wrap
        if_cw = _turn(from_cw, angle) >= 0  # … after a clockwise one
        fixed = if_ccw == if_cw
        flips = np.cumsum(~if_ccw & if_cw, dtype=np.int64)
        reset = np.maximum.accumulate(np.where(fixed, np.arange(len(nails)), -1))
        at = np.maximum(reset, 0)
        base = np.where(reset >= 0, if_ccw[at], prev_counter)
        since = flips - np.where(reset >= 0, flips[at], 0)
        counter = base ^ ((since & 1) == 1)
        previous = np.where(np.concatenate(([prev_counter], counter[:-1])), from_ccw, from_cw)
        gap = np.where(counter, end_cw, end_ccw)  # the gap on the side it is approached from
        span = before[nails] + after[nails]
        steps = np.empty(2 * len(nails) + 1)
        steps[0] = angle_now
        steps[1::2] = _turn(previous, gap)
        steps[2::2] = np.where(counter, span, -span)
        unwrapped = np.cumsum(steps)  # added in order, as turn after turn on the machine
        chunk = rows[first : first + len(nails)]
        chunk[:, 0] = unwrapped[1::2]
        chunk[:, 2] = unwrapped[2::2]
        prev_ccw_end, prev_cw_end = float(end_ccw[-1]), float(end_cw[-1])
        prev_counter, angle_now = bool(counter[-1]), float(unwrapped[-1])


class StringArtOperations(Sequence[Operation]):
    """A string-art program's operations: the drill phase kept, the winding made on demand."""

    #: Translated once per program (an operation is made each time it is read).
    _STEPS = (
        str(QT_TRANSLATE_NOOP("JobFile", "turn beside it")),
        str(QT_TRANSLATE_NOOP("JobFile", "needle out")),
        str(QT_TRANSLATE_NOOP("JobFile", "round the nail")),
        str(QT_TRANSLATE_NOOP("JobFile", "needle in")),
    )

    def __init__(
        self,
        job: StringArtJob,
        head: tuple[Operation, ...],
        a_turn: np.ndarray,
        a_wrap: np.ndarray,
        r_in: float,
        r_out: np.ndarray,
        tail: Operation,
    ) -> None:
        self.job = job
        self.head = head
        self.a_turn = a_turn
        self.a_wrap = a_wrap
        self.r_in = r_in
        self.r_out = r_out
        self.tail = tail
        self.size = len(head) + 4 * len(a_turn) + 1
        self._steps = tuple(QCoreApplication.translate("JobFile", s) for s in self._STEPS)
        self._label = QCoreApplication.translate("JobFile", "nail {0} ({1}/{2}): {3}")

    def __len__(self) -> int:
        return self.size

    @overload
    def __getitem__(self, index: int) -> Operation: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[Operation]: ...

    def __getitem__(self, index: int | slice) -> Operation | Sequence[Operation]:
        if isinstance(index, slice):
            return [self._make(i) for i in range(*index.indices(self.size))]
        if index < 0:
            index += self.size
        if not 0 <= index < self.size:
            raise IndexError(index)
        return self._make(index)

    def __iter__(self) -> Iterator[Operation]:
        return (self._make(i) for i in range(self.size))

    def _make(self, index: int) -> Operation:
        winding = index - len(self.head)
        if winding < 0:
            return self.head[index]
        if index == self.size - 1:
            return self.tail
        entry, step = divmod(winding, 4)
        entry += 1
        total = len(self.job.sequence)
        nail = self.job.sequence[entry]
        message = self._label.format(nail, entry + 1, total, self._steps[step])
        if step == 0:
            target = {"A": float(self.a_turn[entry - 1])}
        elif step == 2:
            target = {"A": float(self.a_wrap[entry - 1])}
        else:
            target = {"X": float(self.r_out[entry - 1]) if step == 1 else self.r_in}
        return Operation(
            OpKind.MOVE, self.job.entry_source(entry), MappingProxyType(target), message
        )


def _needle_in_radius(job: StringArtJob, settings: WindingSettings, radii: np.ndarray) -> float:
    """Where the needle goes in, inside the nails; a board too small for it is refused."""
    r_in = float(radii.min()) - settings.needle_in_mm
    if r_in < 0:
        where = job.param_source("polomer_matrice")
        raise JobFileError(
            where.file,
            where.line,
            QCoreApplication.translate(
                "JobFile",
                "a board of {0:g} cm radius leaves no room for the needle {1:g} mm inside "
                "the nails",
            ).format(job.params.radius_cm, settings.needle_in_mm),
        )
    return r_in


def _drill_phase(
    b: _Builder,
    job: StringArtJob,
    settings: WindingSettings,
    angles: np.ndarray,
    radii: np.ndarray,
) -> list[int]:
    """Every nail's hole, drilled in turn, then back to nail 0: the dwells' operation indices."""
    nails = job.params.nails
    at_param = job.param_source("pocet_hrebiku")
    bottom = settings.drill_bottom_z
    dwell = f"G4 S{settings.drill_dwell_s:g}"
    dwell_ops: list[int] = []

    b.add(
        Operation(
            OpKind.COMMENT,
            at_param,
            message=QCoreApplication.translate("JobFile", "drill phase: {0} nails").format(nails),
        ),
        -1,
        -1,
    )
    # The labels' texts are translated once; each nail only fills them in.
    above = QCoreApplication.translate("JobFile", "{0:g} mm above the board").format(
        settings.drill_clearance_mm
    )
    b.move(
        at_param, "Z", 0.0, QCoreApplication.translate("JobFile", "drill {0}").format(above), -1, -1
    )
    drill_nail = QCoreApplication.translate("JobFile", "drill nail {0}")
    turn_base = QCoreApplication.translate("JobFile", "{0}: turn the base")
    to_radius = QCoreApplication.translate("JobFile", "{0}: tool to its radius")
    drill = QCoreApplication.translate("JobFile", "{0}: drill")
    at_bottom = QCoreApplication.translate("JobFile", "{0}: at the bottom")
    back_up = QCoreApplication.translate("JobFile", "{0}: back {1}")
    for nail in range(nails):
        label = drill_nail.format(nail)
        b.turn_to(float(angles[nail]), at_param, turn_base.format(label), nail, -1)
        b.move(at_param, "X", float(radii[nail]), to_radius.format(label), nail, -1)
        b.move(at_param, "Z", bottom, drill.format(label), nail, -1)
        dwell_ops.append(len(b.ops))
        b.add(Operation(OpKind.GCODE, at_param, message=at_bottom.format(label), line=dwell),
              nail, -1)  # fmt: skip
        b.move(at_param, "Z", 0.0, back_up.format(label, above), nail, -1)
    zero = QCoreApplication.translate("JobFile", "back to nail 0")
    b.turn_to(float(angles[0]), at_param, turn_base.format(zero), 0, -1)
    b.move(at_param, "X", float(radii[0]), to_radius.format(zero), 0, -1)

    return dwell_ops


def _winding_start(
    b: _Builder,
    job: StringArtJob,
    settings: WindingSettings,
    angles: np.ndarray,
    after: np.ndarray,
    r_in: float,
) -> tuple[int, float]:
    """The WAIT for the nails and the thread, then the needle's way round the first nail.

    Returns the WAIT's operation index and the radius the needle starts out at.
    """
    first = job.sequence[0]
    at_first = job.entry_source(0)
    b.add(
        Operation(
            OpKind.COMMENT,
            at_first,
            message=QCoreApplication.translate("JobFile", "winding: {0} connections").format(
                job.connections
            ),
        ),
        -1,
        -1,
    )
    b.add(
        Operation(
            OpKind.GCODE,
            at_first,
            message=QCoreApplication.translate("JobFile", "drivers off while waiting"),
            line="M18",
        ),
        -1,
        -1,
    )
    wait_index = len(b.ops)
    b.add(
        Operation(
            OpKind.WAIT,
            at_first,
            message=QCoreApplication.translate(
                "JobFile", "Insert the nails, tie the thread to nail {0}"
            ).format(first),
        ),
        first,
        0,
    )
    step_in = QCoreApplication.translate("JobFile", "start at nail {0}").format(first)
    # The firmware starts out beyond the board, not the nail: ``polomer_matrice_cm + 2.0``.
    first_out = job.params.radius_cm * 10.0 + settings.needle_out_mm
    b.move(
        at_first,
        "X",
        first_out,
        QCoreApplication.translate("JobFile", "{0}: needle out").format(step_in),
        first,
        0,
    )
    b.turn_to(
        float(angles[first] + after[first]),
        at_first,
        QCoreApplication.translate("JobFile", "{0}: turn").format(step_in),
        first,
        0,
    )
    b.move(
        at_first,
        "X",
        r_in,
        QCoreApplication.translate("JobFile", "{0}: needle in").format(step_in),
        first,
        0,
    )
    b.turn_to(
        float(angles[first]),
        at_first,
        QCoreApplication.translate("JobFile", "{0}: turn back").format(step_in),
        first,
        0,
    )
    b.add(
        Operation(
            OpKind.GCODE,
            at_first,
            message=QCoreApplication.translate("JobFile", "drill driver off while winding"),
            line="M18 Z0",
        ),
        first,
        0,
    )
    return wait_index, first_out


def build_program(
    job: StringArtJob,
    profile: MachineProfile | None = None,
    settings: WindingSettings | None = None,
) -> StringArtProgram:
    """Drill phase, the operator's WAIT, winding phase (see the module notes)."""
    settings = settings or WindingSettings()
    if profile is not None:
        names = {axis.name for axis in profile.axes}
        missing = [axis for axis in AXES if axis not in names]
        if missing:
            raise ValueError(f"{profile.name} lacks the winder's axes {', '.join(missing)}")
    angles, radii = job.nail_polar()
    before, after = half_gaps(angles, job.nail_positions())
    r_in = _needle_in_radius(job, settings, radii)
    b = _Builder()
    sequence = job.sequence
    total = len(sequence)
    dwell_ops = _drill_phase(b, job, settings, angles, radii)
    wait_index, first_out = _winding_start(b, job, settings, angles, after, r_in)
    last = sequence[-1]
    tail = Operation(
        OpKind.COMMENT,
        job.entry_source(total - 1),
        message=QCoreApplication.translate(
            "JobFile", "winding done: tie the thread off at nail {0}"
        ).format(last),
    )
    winding = total - 1
    head = len(b.ops)
    size = head + 4 * winding + 1
    indices = job.indices
    # Every column is made at its full size once and filled in place, the winding as an
    # (entries, 4) view of it: a 2-million-entry list is 8 million operations, and a
    # concatenated copy of each column would double the load's peak memory.
    move_values = np.empty(size)
    move_values[:head] = [next(iter(op.target.values())) if op.target else math.nan for op in b.ops]
    move_values[-1] = math.nan
    rows = move_values[head : head + 4 * winding].reshape(winding, 4)
    rows[:, 1] = radii[indices[1:]]
    rows[:, 1] += settings.needle_out_mm
    rows[:, 3] = r_in
    _fill_winding_angles(indices, angles, before, after, b.angle, rows)
    r_out = rows[:, 1]
    r_out_max = float(max(first_out, float(r_out.max()) if len(r_out) else first_out))
    move_axis = np.empty(size, dtype=np.int8)
    move_axis[:head] = [_COLUMN[next(iter(op.target))] if op.target else -1 for op in b.ops]
    move_axis[head:-1].reshape(winding, 4)[:] = (0, 1, 0, 1)
    move_axis[-1] = -1
    kind_codes = np.full(size, _KIND_CODES[OpKind.MOVE], dtype=np.int8)
    kind_codes[:head] = [_KIND_CODES[op.kind] for op in b.ops]
    kind_codes[-1] = _KIND_CODES[OpKind.COMMENT]
    nail_of_op = np.empty(size, dtype=np.int16)  # MAX_NAILS fits
    nail_of_op[:head] = b.nails
    nail_of_op[head:-1].reshape(winding, 4)[:] = indices[1:, None]
    nail_of_op[-1] = last
    entry_of_op = np.empty(size, dtype=np.int32)
    entry_of_op[:head] = b.entries
    entry_of_op[head:-1].reshape(winding, 4)[:] = np.arange(1, total, dtype=np.int32)[:, None]
    entry_of_op[-1] = total - 1
    operations = StringArtOperations(job, tuple(b.ops), rows[:, 0], rows[:, 2], r_in, r_out, tail)
    program = StringArtProgram(
        name=job.name,
        operations=operations,
        source=job.poradi_path,
        notes=(job.summary(),),
        job=job,
        nail_of_op=nail_of_op,
        entry_of_op=entry_of_op,
        move_axis=move_axis,
        move_values=move_values,
        kind_codes=kind_codes,
        wait_index=wait_index,
        needle_in_radius_mm=r_in,
        needle_out_radius_mm=r_out_max,
        dwell_ops=np.array(dwell_ops, dtype=np.int64),
        dwell_s=settings.drill_dwell_s,
    )
    if profile is None:
        return program
    seconds = winder_seconds(program, profile)
    return _with_estimate(program, seconds)


def _with_estimate(program: StringArtProgram, seconds: float) -> StringArtProgram:
    return replace(program, estimate_s=seconds, notes=(program.job.summary(seconds),))


def move_seconds(distance: np.ndarray, speed: float, acceleration: float) -> np.ndarray:
    """A trapezoid (triangle when short) from rest to rest over ``distance``."""
    distance = np.abs(distance)
    ramp = speed * speed / acceleration  # distance to reach top speed and stop again
    cruise = distance / speed + speed / acceleration
    short = 2.0 * np.sqrt(distance / acceleration)
    return np.where(distance >= ramp, cruise, short)


def _forward_filled(coords: np.ndarray) -> np.ndarray:
    """NaN (an axis not yet set) replaced by the last value set, or 0 before any."""
    known = ~np.isnan(coords)
    rows = np.arange(len(coords))[:, None]
    last = np.maximum.accumulate(np.where(known, rows, -1), axis=0)
    filled = np.take_along_axis(coords, np.maximum(last, 0), axis=0)
    return np.where(last >= 0, filled, 0.0)


def winder_seconds(program: Program, profile: MachineProfile) -> float:
    """Model time of ``program``'s moves on ``profile``: one trapezoid per axis and move,
    axes of one move together (the longest counts), moves one after the other, from 0.

    A closed-form estimate from the profile's top speed and acceleration, plus
    the drill's dwells; the operator's waits and the link's round trips are
    not counted.
    """
    names = [axis.name for axis in profile.axes]
    path = program.path(names)
    if not len(path):
        return 0.0
    coords = _forward_filled(path.coords)
    steps = np.diff(np.vstack((np.zeros(len(names)), coords)), axis=0)
    times = np.zeros(len(coords))
    for column, axis in enumerate(profile.axes):
        times = np.maximum(
            times, move_seconds(steps[:, column], axis.max_speed, axis.max_acceleration)
        )
    dwells = getattr(program, "dwell_ops", ())
    return float(times.sum()) + len(dwells) * float(getattr(program, "dwell_s", 0.0))


def load_string_art_program(
    path: Path,
    axis_names: Sequence[str],
    params: StringArtParams | None = None,
    profile: MachineProfile | None = None,
) -> StringArtProgram:
    """The job loader's work: read either file of the pair (or a nail list with ``params``)
    and build the winder's program; JobFileError (or NeedsNailCount) says why not."""
    missing = [axis for axis in AXES if axis not in axis_names]
    if missing:
        raise JobFileError(
            path.name,
            0,
            QCoreApplication.translate(
                "JobFile",
                "a string-art job needs the winder's axes A, X and Z (profile string-art); "
                "this machine has {0}",
            ).format(", ".join(axis_names) or QCoreApplication.translate("JobFile", "none")),
        )
    return build_program(read_string_art(path, params), profile)
