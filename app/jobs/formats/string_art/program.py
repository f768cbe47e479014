"""A string-art job as the winder runs it: drill every nail, wait, then wind the thread.

The winder (PROTOCOLS.md §4) turns the board on a base (A, degrees), moves
the needle or drill radially (X, mm from the centre) and along the drill
axis tilted 74.333° to the board (Z, mm; 0 is retracted, the tool clear of
the board).  The program assumes the base at A = 0 when it starts (after
homing) and keeps A unwrapped: every turn is the shortest signed one from
where the base is, so none is longer than 180°.

1. **Drill phase**, per nail in index order: turn the base to the nail's
   angle, move the tool to the nail's radius, drill ``drill_depth_mm`` deep
   along the tool axis (Z), back out (Z 0).  X is where the tool meets the
   board's surface: the 74.333° tilt moves the hole's bottom about
   ``10·cos(74.333°) ≈ 2.7 mm`` radially from it, which leans the nails as
   the original machine did; no offset is modelled.  Then the tool moves
   out beyond the nails, clear of the holes.
2. **Wait** for the operator: "Insert the nails, tie the thread to nail 0"
   (the sequence's first nail).
3. **Winding**, as the original firmware did it.  The needle works between
   an inner radius (``needle_in_mm`` inside the innermost nail) and an
   outer one (``needle_out_mm`` outside the outermost); it crosses the nail
   ring only halfway between two neighbouring nails.  It steps in once
   between the first nail and the next one; then for each next nail ``k``
   it turns (inside) the shorter way round to the gap beside ``k`` on the
   side it approaches from, moves out, turns across ``k`` to the gap on the
   other side — the thread wraps the nail — and moves in.  One radius
   inside and one outside for the whole board keep the needle clear of
   every nail while it turns, also on a polygon whose mid-edge nails are
   nearer the centre than its corners.

Every operation records the nail it serves (``nail_of_op``) and the
sequence entry (``entry_of_op``, -1 in the drill phase), so the preview
can show the current nail while the job runs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import ClassVar, Literal

import numpy as np

from app.jobs.formats.string_art.geometry import DRILL_DEPTH_MM, half_gaps, shortest_turn
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams, read_string_art
from app.jobs.program import (
    JobFileError,
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

    needle_in_mm: float = 5.0  # inside the innermost nail while turning
    needle_out_mm: float = 5.0  # outside the outermost nail while wrapping one
    drill_depth_mm: float = DRILL_DEPTH_MM


@dataclass(frozen=True, kw_only=True)
class StringArtProgram(Program):
    """The operations plus, per operation, the nail it serves and the A/X/Z after it."""

    job: StringArtJob
    #: The nail each operation serves (-1: none).
    nail_of_op: np.ndarray = field(compare=False, repr=False)
    #: The sequence entry each operation winds to (-1: drill phase).
    entry_of_op: np.ndarray = field(compare=False, repr=False)
    #: (operations, 3): A, X, Z after each operation (NaN until first set).
    axis_positions: np.ndarray = field(compare=False, repr=False)
    kind_codes: np.ndarray = field(compare=False, repr=False)
    #: Index of the operator's WAIT between drilling and winding.
    wait_index: int = -1
    #: Model seconds on the profile it was built for (None without a profile).
    estimate_s: float | None = None
    needle_in_radius_mm: float = 0.0
    needle_out_radius_mm: float = 0.0
    preview_plane: ClassVar[Literal["axes", "board"]] = "board"

    def _move_indices(self) -> np.ndarray:
        return np.flatnonzero(self.kind_codes == _KIND_CODES[OpKind.MOVE])

    def path(self, axes: Sequence[str]) -> ProgramPath:
        names = tuple(axes)
        moves = self._move_indices()
        coords = np.full((len(moves), len(names)), np.nan)
        for column, name in enumerate(names):
            if name in _COLUMN:
                coords[:, column] = self.axis_positions[moves, _COLUMN[name]]
        return ProgramPath(coords, moves.astype(np.int64), np.zeros(len(moves), dtype=bool))

    def preview_path(self, x_axis: str, y_axis: str | None) -> ProgramPath:
        """The board plane in mm whatever the axes: x = X·cos A, y = X·sin A; winding is work."""
        moves = self._move_indices()
        angle = np.radians(np.nan_to_num(self.axis_positions[moves, 0]))
        radius = np.nan_to_num(self.axis_positions[moves, 1])
        coords = np.column_stack((radius * np.cos(angle), radius * np.sin(angle)))
        pen = moves > self.wait_index
        return ProgramPath(coords, moves.astype(np.int64), pen)

    def kinds(self) -> frozenset[OpKind]:
        return frozenset(_KINDS[code] for code in np.unique(self.kind_codes))

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
    before, after = half_gaps(angles)
    r_in = float(radii.min()) - settings.needle_in_mm
    r_out = float(radii.max()) + settings.needle_out_mm
    if r_in < 0:
        where = job.param_source("polomer_matrice")
        raise JobFileError(
            where.file,
            where.line,
            f"a board of {job.params.radius_cm:g} cm radius leaves no room for the needle "
            f"{settings.needle_in_mm:g} mm inside the nails",
        )
    b = _Builder()
    nails = job.params.nails
    sequence = job.sequence
    total = len(sequence)
    at_param = job.param_source("pocet_hrebiku")

    b.add(Operation(OpKind.COMMENT, at_param, message=f"drill phase: {nails} nails"), -1, -1)
    for nail in range(nails):
        label = f"drill nail {nail}"
        b.turn_to(float(angles[nail]), at_param, f"{label}: turn the base", nail, -1)
        b.move(at_param, "X", float(radii[nail]), f"{label}: tool to its radius", nail, -1)
        b.move(at_param, "Z", settings.drill_depth_mm, f"{label}: drill", nail, -1)
        b.move(at_param, "Z", 0.0, f"{label}: back out", nail, -1)
    b.move(at_param, "X", r_out, "tool out beyond the nails", -1, -1)

    first = sequence[0]
    at_first = job.entry_source(0)
    b.add(Operation(OpKind.COMMENT, at_first, message=f"winding: {total} connections"), -1, -1)
    wait_index = len(b.ops)
    b.add(
        Operation(
            OpKind.WAIT, at_first, message=f"Insert the nails, tie the thread to nail {first}"
        ),
        first,
        0,
    )
    step_in = f"start at nail {first}"
    b.turn_to(float(angles[first] + after[first]), at_first, f"{step_in}: turn", first, 0)
    b.move(at_first, "X", r_in, f"{step_in}: needle in", first, 0)
    for entry in range(1, total):
        nail = sequence[entry]
        where = job.entry_source(entry)
        label = f"nail {nail} ({entry + 1}/{total})"
        span = float(before[nail] + after[nail])
        if shortest_turn(b.angle, float(angles[nail])) >= 0:  # approached counter-clockwise
            gap, wrap = float(angles[nail] - before[nail]), span
        else:
            gap, wrap = float(angles[nail] + after[nail]), -span
        b.turn_to(gap, where, f"{label}: turn beside it", nail, entry)
        b.move(where, "X", r_out, f"{label}: needle out", nail, entry)
        b.turn_by(wrap, where, f"{label}: round the nail", nail, entry)
        b.move(where, "X", r_in, f"{label}: needle in", nail, entry)
    last = sequence[-1]
    b.add(
        Operation(
            OpKind.COMMENT,
            job.entry_source(total - 1),
            message=f"winding done: tie the thread off at nail {last}",
        ),
        last,
        total - 1,
    )

    operations = tuple(b.ops)
    program = StringArtProgram(
        name=job.name,
        operations=operations,
        source=job.poradi_path,
        notes=(job.summary(),),
        job=job,
        nail_of_op=np.array(b.nails, dtype=np.int64),
        entry_of_op=np.array(b.entries, dtype=np.int64),
        axis_positions=np.array(b.rows, dtype=np.float64).reshape(len(b.rows), 3),
        kind_codes=np.array([_KIND_CODES[op.kind] for op in operations], dtype=np.int8),
        wait_index=wait_index,
        needle_in_radius_mm=r_in,
        needle_out_radius_mm=r_out,
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

    A closed-form estimate from the profile's top speed and acceleration; the
    operator's waits and the link's round trips are not counted.
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
    return float(times.sum())


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
            f"a string-art job needs the winder's axes A, X and Z (profile string-art); "
            f"this machine has {', '.join(axis_names) or 'none'}",
        )
    return build_program(read_string_art(path, params), profile)
