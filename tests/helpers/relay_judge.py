"""What a machine did in a fault-relay run, from the emulator's ``--log`` alone, and the verdict.

The station's account (its messages, its progress, its exit status) says
only how the run *ended*; what the machine *did* is read from the device's
own log: pen-down strokes on the plotters, holes on the drill, move targets
on the usb3 unit and the XY stage.  A run is then one of:

* **exact** — the station said done, and every operation happened exactly
  once, in order;
* **clean stop** — the station stopped with a message, and what happened
  is a prefix of the operations (the last one possibly cut short), with
  nothing more done after the station ended;
* **wrong** — anything else: an operation twice, one skipped, one out of
  order, one that is not in the job, "done" with operations missing, the
  machine going on after the stop, a stop without a word, a crash;
* **hung** — the operations so far are a clean prefix, but the station
  never ended.

:func:`judge` is a pure function of the expected operations, the ones seen
when the station ended and the ones seen once the device settled; the
``*_ops`` readers turn a log's text into operations.
"""

from __future__ import annotations

import enum
import json
import math
import operator
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Generic, TypeVar

Op = TypeVar("Op")
Exp = TypeVar("Exp")

#: The station's exit statuses that mean "stopped, and said why" (refused; failed or aborted).
STOP_STATUSES = frozenset({2, 3})


class Verdict(enum.Enum):
    EXACT = "exact"
    STOPPED = "clean stop"
    WRONG = "wrong"
    HUNG = "hung"


@dataclass(frozen=True)
class Judgement:
    verdict: Verdict
    reason: str

    def __str__(self) -> str:
        return f"{self.verdict.value}: {self.reason}"


@dataclass(frozen=True)
class Track(Generic[Op, Exp]):
    """One sequence of operations to judge: the job's, and the log's at two moments."""

    expected: Sequence[Exp]
    #: What the log showed when the station ended (or was given up on).
    at_exit: Sequence[Op]
    #: What the log showed once the device had settled after that.
    final: Sequence[Op]
    #: Whether an observed operation is the expected one.
    same: Callable[[Op, Exp], bool] = operator.eq
    #: Whether an observed operation is the expected one cut short (a stroke stopped midway).
    part_of: Callable[[Op, Exp], bool] | None = None


def _name(value: object) -> str:
    return str(value)


def _prefix_error(track: Track[Any, Any]) -> tuple[str | None, int, bool]:
    """Why ``final`` is no prefix of ``expected`` (None if it is), its length, and if cut short."""
    expected, seen = track.expected, track.final
    for index, op in enumerate(seen):
        if index < len(expected) and track.same(op, expected[index]):
            continue
        last = index == len(seen) - 1
        if (
            last
            and index < len(expected)
            and track.part_of is not None
            and track.part_of(op, expected[index])
        ):
            return None, index, True
        if index >= len(expected):
            return (
                f"operation {index + 1} {_name(op)} is beyond the job's {len(expected)}",
                0,
                False,
            )
        if any(track.same(op, e) for e in expected[:index]):
            return (
                f"operation {index + 1} is {_name(op)} again (done before); "
                f"expected {_name(expected[index])}",
                0,
                False,
            )
        if any(track.same(op, e) for e in expected[index + 1 :]):
            return (
                f"operation {index + 1} is {_name(op)}, out of order: "
                f"expected {_name(expected[index])} first",
                0,
                False,
            )
        if track.part_of is not None and any(track.part_of(op, e) for e in expected):
            return (
                f"operation {index + 1} {_name(op)} is an operation cut short, then more was done; "
                f"expected {_name(expected[index])}",
                0,
                False,
            )
        return (
            f"operation {index + 1} {_name(op)} is not in the job; "
            f"expected {_name(expected[index])}",
            0,
            False,
        )
    return None, len(seen), False


def judge(tracks: Mapping[str, Track[Any, Any]], status: int | None, said: str) -> Judgement:
    """The verdict on a run: ``tracks`` from the log, the station's exit ``status`` and words.

    ``status`` is None when the station had not ended by the run's deadline.
    """
    done: list[str] = []
    complete = True
    for name, track in tracks.items():
        error, count, cut = _prefix_error(track)
        if error is not None:
            return Judgement(Verdict.WRONG, f"{name}: {error}")
        total = len(track.expected)
        done.append(f"{name} {count}/{total}" + (" (+1 cut short)" if cut else ""))
        complete = complete and count == total and not cut
    summary = ", ".join(done)
    if status is None:
        return Judgement(Verdict.HUNG, f"the station never ended; {summary}")
    if "Traceback (most recent call last)" in said:
        return Judgement(Verdict.WRONG, f"the station crashed (status {status}); {summary}")
    if status == 0:
        if complete:
            return Judgement(Verdict.EXACT, summary)
        return Judgement(Verdict.WRONG, f"the station said done after {summary}")
    if status not in STOP_STATUSES:
        return Judgement(Verdict.WRONG, f"the station ended with status {status}; {summary}")
    if not said.strip():
        return Judgement(Verdict.WRONG, f"the station stopped without a word; {summary}")
    for name, track in tracks.items():
        if len(track.final) != len(track.at_exit) or any(
            not _equal(a, b) for a, b in zip(track.at_exit, track.final, strict=False)
        ):
            return Judgement(
                Verdict.WRONG,
                f"{name}: the machine went on after the station stopped "
                f"({len(track.at_exit)} then {len(track.final)} operations)",
            )
    return Judgement(Verdict.STOPPED, f"{summary}; said: {last_words(said)}")


def _equal(a: object, b: object) -> bool:
    return a == b


def last_words(said: str) -> str:
    """The station's last non-empty line, shortened: what the table shows of a stop."""
    lines = [line.strip() for line in said.splitlines() if line.strip()]
    return lines[-1][:160] if lines else ""


# --- pen plotters: pen-down strokes ---------------------------------------------------------------

Point = tuple[float, float]
Stroke = tuple[Point, Point]
#: Positions are compared to a micrometre; the emulator logs them to six decimals.
EPS_MM = 1e-3


def _near(a: Point, b: Point, eps: float = EPS_MM) -> bool:
    return abs(a[0] - b[0]) <= eps and abs(a[1] - b[1]) <= eps


def _on_segment(p: Point, a: Point, b: Point) -> bool:
    """Whether ``p`` lies on the segment from ``a`` to ``b`` (within EPS_MM)."""
    ax, ay = b[0] - a[0], b[1] - a[1]
    length = math.hypot(ax, ay)
    if length <= EPS_MM:
        return _near(p, a)
    px, py = p[0] - a[0], p[1] - a[1]
    across = abs(ax * py - ay * px) / length
    along = (ax * px + ay * py) / length
    return across <= EPS_MM and -EPS_MM <= along <= length + EPS_MM


def in_box(p: Point, a: Point, b: Point, eps: float = EPS_MM) -> bool:
    """Whether ``p`` lies in the rectangle ``a`` and ``b`` span (within EPS_MM).

    The CoreXY plotter's firmware steps both motors at one rate, so a move
    is straight only at its ends: where a stop caught it is somewhere in
    this rectangle, not on the line.
    """
    return all(min(a[i], b[i]) - EPS_MM <= p[i] <= max(a[i], b[i]) + EPS_MM for i in (0, 1))


#: Whether a point lies on the way from one point to another: straight, or anywhere between.
Between = Callable[[Point, Point, Point], bool]


def same_stroke(a: Stroke, b: Stroke) -> bool:
    return _near(a[0], b[0]) and _near(a[1], b[1])


def stroke_part_of(part: Stroke, whole: Stroke) -> bool:
    """A stroke begun as ``whole`` and stopped on the way."""
    return _near(part[0], whole[0]) and _on_segment(part[1], whole[0], whole[1])


def corexy_stroke_part_of(part: Stroke, whole: Stroke) -> bool:
    """A CoreXY stroke begun as ``whole`` and stopped on the way (see :func:`in_box`)."""
    return _near(part[0], whole[0]) and in_box(part[1], whole[0], whole[1])


#: grbl-sim reports a block's end at the next block's first report, a few steps on.
GRBL_SIM_EPS_MM = 0.05


def grbl_sim_same_stroke(a: Stroke, b: Stroke) -> bool:
    return _near(a[0], b[0], GRBL_SIM_EPS_MM) and _near(a[1], b[1], GRBL_SIM_EPS_MM)


def grbl_sim_part_of(part: Stroke, whole: Stroke) -> bool:
    return _near(part[0], whole[0], GRBL_SIM_EPS_MM) and in_box(
        part[1], whole[0], whole[1], GRBL_SIM_EPS_MM
    )


def merge_strokes(
    pieces: Sequence[tuple[Stroke, bool]], between: Between = _on_segment
) -> list[Stroke]:
    """Pieces of one move, as the one stroke they draw; each piece says if a stop cut it.

    A move held, or stopped by a reset and finished from where it stopped, is
    logged in pieces; on paper it is one line.  Only a piece a stop cut short
    is joined to the next, when that one goes on from where it stopped
    towards a place ``between`` allows (the line; :func:`in_box` for the
    CoreXY plotter).  A move that ended is a stroke of its own, whatever follows.
    """
    merged: list[Stroke] = []
    open_end = False
    for stroke, cut in pieces:
        if merged and open_end:
            a, b = merged[-1]
            if _near(stroke[0], b) and between(b, a, stroke[1]) and not _near(a, stroke[1]):
                merged[-1] = (a, stroke[1])
                open_end = cut
                continue
        merged.append(stroke)
        open_end = cut
    return merged


def _events(log: str) -> list[dict[str, Any]]:
    found = []
    for line in log.splitlines():
        try:
            event = json.loads(line)
        except ValueError:
            continue  # a line cut by the process's end
        if isinstance(event, dict):
            found.append(event)
    return found


def _xy(pos: Mapping[str, float]) -> Point:
    return (round(float(pos["X"]), 4), round(float(pos["Y"]), 4))


def gcode_strokes(log: str, between: Between = _on_segment) -> list[Stroke]:
    """Every stretch the pen went down on, from the G-code firmware's JSON log, merged.

    The tool stands at each event's ``pos``; between two events it went
    straight (the firmware logs the end of every move, and where a hold, a
    reset or an alarm caught it).  Ink goes down while the pen is down: a
    ``move`` says so itself, a ``pen`` event changes it.
    """
    where: Point | None = None
    pen = False
    drawn: list[tuple[Stroke, bool]] = []
    for event in _events(log):
        kind = event.get("event")
        pos = event.get("pos")
        if kind in ("setpos", "offset", "boot"):
            where = _xy(pos) if kind == "setpos" and pos else None  # a new frame: no ink
            continue
        if not isinstance(pos, dict) or "X" not in pos:
            continue
        end = _xy(pos)
        down = bool(event["pen"]) if kind == "move" else pen
        if down and where is not None and not _near(where, end):
            drawn.append(((where, end), kind != "move"))  # not a move's end: a stop's
        where = end
        if kind == "pen":
            pen = bool(event.get("down"))
        elif kind == "move":
            pen = bool(event["pen"])
    return merge_strokes(drawn, between)


# --- the drill: holes -------------------------------------------------------------------------

_HOLE = re.compile(r"^\s*\d+(?:\.\d+)?\s+hole\s+X(-?\d+)\s+Y(-?\d+)\s*$")


def drill_holes(log: str) -> list[tuple[int, int]]:
    """Each hole the drill made, in microsteps, in order."""
    return [
        (int(m.group(1)), int(m.group(2)))
        for m in (_HOLE.match(line) for line in log.splitlines())
        if m is not None
    ]


# --- the XY stage: absolute move targets per axis ------------------------------------------------


def stage_targets(log: str, axes: int = 2) -> dict[int, list[int]]:
    """The MOVE_ABS targets (µm) the stage accepted, per axis, a target sent again counted once.

    The targets are absolute: a move sent again after a lost link goes to the
    same place, so it is the same operation.
    """
    targets: dict[int, list[int]] = {axis: [] for axis in range(axes)}
    for line in log.splitlines():
        fields = line.split()
        if len(fields) != 5 or fields[2] != "MOVE_ABS" or fields[4] != "1":
            continue
        axis, target = int(fields[1]), int(fields[3])
        seq = targets.setdefault(axis, [])
        if not seq or seq[-1] != target:
            seq.append(target)
    return targets


# --- the usb3 unit: relative moves as the places they go to --------------------------------------

_USB3_DIRECTION = re.compile(r"SetDirection\(signs=\((-?1), (-?1), (-?1)\)\)")
_USB3_MOVE = re.compile(r"Move\(axis=<AxisId\.(\w): \d>, count=(\d+)\)")
#: The emulator logs where an axis in motion came to rest (its ``--log``, AxisStopped).
_USB3_STOPPED = re.compile(r"Stopped\(axis=<AxisId\.(\w): \d>, count=(-?\d+)\)")
#: ``M`` as the emulator logs it: each axis's step size (1/2^m step; the value is m).
_USB3_STEP_SIZES = re.compile(
    r"StepSizes\(sizes=\(<StepSize\.\w+: (\d)>, <StepSize\.\w+: (\d)>, <StepSize\.\w+: (\d)>\)\)"
)
#: The emulated unit's power-on step size (1/8 step: a pulse is 4 counts), unless ``M`` says.
_USB3_POWER_ON_COUNTS_PER_PULSE = 4


@dataclass(frozen=True)
class Span:
    """Where a usb3 axis went, in counts: known exactly, or within ``lo…hi`` after a stop.

    ``S;`` stops a move somewhere the commands do not say, so the next relative
    move goes somewhere in a range; it counts as finishing the stopped move
    when that move's target is in the range.  (The emulator also logs where
    each axis stopped: then the place is exact, see :class:`Cut`.)
    """

    lo: int
    hi: int

    def __contains__(self, count: object) -> bool:
        return isinstance(count, int) and self.lo <= count <= self.hi

    def __str__(self) -> str:
        return str(self.lo) if self.lo == self.hi else f"{self.lo}…{self.hi}"


@dataclass(frozen=True)
class Cut(Span):
    """A move that stopped short of where it was sent (``S;``, a switch): where it stopped,
    and where it began.  It is the job's move cut short when it stopped on the way from
    its start to that move's target (:func:`usb3_part_of`)."""

    start: int = 0
    aimed: int = 0

    def __str__(self) -> str:
        return f"{self.lo} (stopped on the way from {self.start} to {self.aimed})"


def usb3_targets(log: str) -> dict[str, list[Span]]:
    """Per axis, the places (counts from the power-on zero) the unit's moves went to.

    A move that picks up a stopped one (its range holds the stopped one's
    target) is the same operation: it is not listed again.  Where the log says
    where an axis stopped short of a move's end, that move is listed as a
    :class:`Cut` at that place.
    """
    signs = {"X": 1, "Y": 1, "Z": 1}
    per_pulse = dict.fromkeys("XYZ", _USB3_POWER_ON_COUNTS_PER_PULSE)
    at = {axis: Span(0, 0) for axis in "XYZ"}  # where each axis is (or will be, moving)
    began = dict(at)  # where its last move began
    stopped: dict[str, int | None] = dict.fromkeys("XYZ")  # the target of a stopped move
    moved_from = dict(at)  # where the last move listed began (a stop leaves it)
    targets: dict[str, list[Span]] = {axis: [] for axis in "XYZ"}
    for line in log.splitlines():
        if (direction := _USB3_DIRECTION.search(line)) is not None:
            signs = dict(zip("XYZ", (int(s) for s in direction.groups()), strict=True))
        elif (sizes := _USB3_STEP_SIZES.search(line)) is not None:
            per_pulse = {a: 32 >> int(m) for a, m in zip("XYZ", sizes.groups(), strict=True)}
        elif (rest := _USB3_STOPPED.search(line)) is not None:
            axis, count = rest.group(1), int(rest.group(2))
            seq, here = targets[axis], at[axis]
            if (here.lo, here.hi) == (count, count) or not seq:
                continue  # at the end of its moves (or a joystick run: not the station's)
            aimed = stopped[axis] if stopped[axis] is not None else seq[-1].hi
            start = moved_from[axis].lo
            if count == aimed:
                seq[-1] = Span(count, count)  # it had got there before the stop
                stopped[axis] = None
            else:
                seq[-1] = Cut(count, count, start, aimed)
                stopped[axis] = aimed
            at[axis] = began[axis] = Span(count, count)
        elif "StopAll()" in line:
            for axis in at:
                # Somewhere between where the last move began and its end.
                start, end = began[axis], at[axis]
                if (start.lo, start.hi) != (end.lo, end.hi):
                    at[axis] = Span(min(start.lo, end.lo), max(start.hi, end.hi))
                    stopped[axis] = end.hi if end.lo == end.hi else None
                began[axis] = at[axis]
        elif "ZeroAll()" in line:
            at = {axis: Span(0, 0) for axis in "XYZ"}
            began = dict(at)
            moved_from = dict(at)
            stopped = dict.fromkeys("XYZ")
        elif (move := _USB3_MOVE.search(line)) is not None and (
            # The unit moves whole pulses, the count rounded down: less than one is no move.
            whole := int(move.group(2)) // per_pulse[move.group(1)] * per_pulse[move.group(1)]
        ):
            axis = move.group(1)
            delta = signs[axis] * whole
            reach = Span(at[axis].lo + delta, at[axis].hi + delta)
            began[axis] = at[axis]
            picked_up = stopped[axis]
            stopped[axis] = None
            if picked_up is not None and picked_up in reach:
                at[axis] = Span(picked_up, picked_up)  # the stopped move, finished
                seq = targets[axis]
                if seq and isinstance(seq[-1], Cut):
                    seq[-1] = Span(picked_up, picked_up)
                continue
            targets[axis].append(reach)
            moved_from[axis] = at[axis]
            at[axis] = reach
    return {axis: seq for axis, seq in targets.items() if seq}


def usb3_same(span: Span, target: int) -> bool:
    return not isinstance(span, Cut) and target in span


def usb3_joined(seen: Sequence[Span], expected: Sequence[int], start: int = 0) -> list[Span]:
    """``seen`` with each move that ended short on its way, and was then finished, as one.

    A count changed on the wire to a smaller one (``Y…1600;`` arriving as ``Y…1400;``)
    ends the move short of the job's target, on its way there; the station sees the
    axis stand short of the target (taken for an end switch), the job pauses, and its
    resume moves it on from there to that target.  The axis went only along the job's
    path, each target once and in order: one operation in two pieces, as a move stopped
    by ``S;`` and finished is (:func:`usb3_targets`).  Only a place strictly between
    the previous target and the next, followed at once by that next target, is joined.
    """
    joined: list[Span] = []
    index, before = 0, start
    for position, span in enumerate(seen):
        if index < len(expected) and usb3_same(span, expected[index]):
            joined.append(span)
            before, index = expected[index], index + 1
            continue
        if index < len(expected) and position + 1 < len(seen):
            target, low, high = expected[index], *sorted((before, expected[index]))
            short = not isinstance(span, Cut) and span.lo == span.hi and low < span.lo < high
            if short and span.lo != target and usb3_same(seen[position + 1], target):
                continue  # the first piece: the next one finishes it
        joined.append(span)
        index = len(expected)  # off the job from here: the rest is judged as it is
    return joined


def usb3_part_of(span: Span, target: int) -> bool:
    """A move stopped on its way to ``target``: from its start toward it, short of it."""
    if not isinstance(span, Cut):
        return False
    low, high = sorted((span.start, target))
    return low <= span.lo <= high and span.lo != target


# --- the string-art winder: nails drilled, then nails wound --------------------------------------

#: Angles within this (degrees) and radii within this (mm) are the same place.
ANGLE_EPS_DEG = 0.01
RADIUS_EPS_MM = 0.01
Z_EPS_MM = 0.05


def _turn(current: float, target: float) -> float:
    return (target - current + 180.0) % 360.0 - 180.0


@dataclass(frozen=True)
class NailBoard:
    """The nails as the job places them (polar: degrees and mm), and the drill's depth in Z."""

    angles: Sequence[float]
    radii: Sequence[float]
    bottom_z: float

    def at(self, a: float, x: float) -> list[int]:
        return [
            k
            for k, (angle, radius) in enumerate(zip(self.angles, self.radii, strict=True))
            if abs(_turn(a, angle)) <= ANGLE_EPS_DEG and abs(x - radius) <= RADIUS_EPS_MM
        ]

    def inside(self, start: float, end: float) -> list[int]:
        """The nails strictly inside the turn from ``start`` to ``end`` (unwrapped degrees)."""
        low, high = min(start, end), max(start, end)
        middle = (low + high) / 2
        return [
            k for k, angle in enumerate(self.angles) if low < middle + _turn(middle, angle) < high
        ]

    def side(self, x: float) -> str:
        if x < min(self.radii):
            return "in"
        if x > max(self.radii):
            return "out"
        return "ring"


def string_art_ops(log: str, board: NailBoard) -> list[tuple[str, int | str]]:
    """Every nail drilled (``("nail", k)``) and wound round (``("wrap", k)``), in order.

    A plunge counts once Z reaches the hole's bottom at a nail.  A wrap is the
    needle going out past the nails at one angle and back in at another: the
    one nail it turned across is wound (out and in at one angle, as a resumed
    job may do, winds nothing; the first way in, beside the first nail, too).
    A plunge or a wrap that names no single nail is listed as ``("at", where)``
    and is in no job.
    """
    ops: list[tuple[str, int | str]] = []
    previous: dict[str, float] | None = None
    side: str | None = None
    out_at: float | None = None
    started = False
    for event in _events(log):
        pos = event.get("pos")
        if event.get("event") not in ("move", "reset", "hold", "alarm") or not isinstance(
            pos, dict
        ):
            continue
        a, x, z = float(pos["A"]), float(pos["X"]), float(pos["Z"])
        if side is None:
            side = board.side(x)
        if previous is not None and abs(z - previous["Z"]) > Z_EPS_MM:
            if abs(z - board.bottom_z) <= Z_EPS_MM and previous["Z"] < z:
                nails = board.at(a, x)
                ops.append(("nail", nails[0]) if len(nails) == 1 else ("at", f"plunge A{a} X{x}"))
        elif previous is not None and abs(a - previous["A"]) <= ANGLE_EPS_DEG:
            now = board.side(x)
            if now != "ring" and now != side:
                if now == "out":
                    out_at = a
                elif not started:
                    started = True
                elif out_at is not None and abs(out_at - a) > ANGLE_EPS_DEG:
                    across = board.inside(out_at, a)
                    ops.append(
                        ("wrap", across[0])
                        if len(across) == 1
                        else ("at", f"wrap A{out_at}→{a} across {across}")
                    )
                side = now
        previous = {"A": a, "X": x, "Z": z}
    return ops


# --- real GRBL (grbl-sim): where the machine stood, block by block -------------------------------

#: Written to grbl-sim's step log when the board restarts: its position starts again from 0
#: while the machine stays where it is.
BOOT_MARK = "# boot"
_STEP_LINE = re.compile(r"^\s*[\d.]+\s+(-?\d+),\s*(-?\d+),\s*(-?\d+),\s*(\d+)\s*$")


def grbl_sim_strokes(steps: str, steps_per_mm: float) -> list[Stroke]:
    """The pen-down strokes from grbl-sim's step reports (``-r``), merged as :func:`merge_strokes`.

    Each block's reports are where the machine stood while running it, the
    last one where it ended (or stopped); the spindle's PWM while it ran says
    whether the pen was down (the report at a block's end may already show
    the next block's).  After a restart the board counts from 0 again, so
    positions are taken from where the machine stood then.
    """
    origin: Point = (0.0, 0.0)
    where: Point = (0.0, 0.0)
    block: list[tuple[Point, int]] = []
    pieces: list[tuple[Stroke, bool]] = []

    def close_block() -> None:
        nonlocal where
        if not block:
            return
        pen = block[0][1] > 0 if len(block) > 1 else block[-1][1] > 0
        for point, _ in block:
            if pen and not _near(where, point):
                pieces.append(((where, point), True))
            where = point
        block.clear()

    for line in steps.splitlines():
        if line.startswith(BOOT_MARK):
            close_block()
            origin = where
        elif line.startswith("# block number"):
            close_block()
        elif (match := _STEP_LINE.match(line)) is not None:
            x, y = int(match.group(1)) / steps_per_mm, int(match.group(2)) / steps_per_mm
            point = (round(origin[0] + x, 4), round(origin[1] + y, 4))
            block.append((point, int(match.group(4))))
    close_block()
    return merge_strokes(pieces, lambda p, a, b: in_box(p, a, b, GRBL_SIM_EPS_MM))
