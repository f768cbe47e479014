"""Where the machine may be, given what the station sent: the envelope of the moves in flight.

No wire in the machines' dialects carries a checksum, so a corrupted byte can
turn a short move into a run of a kilometre (a usb3 count with a digit
changed) and dropped bytes can turn a G-code line into another valid one.
The station cannot see the bytes arrive wrong, but it can see the motion:
every position the machine reports must lie on the path of the moves the
station sent, from the last point it confirmed through each move's target,
within a tolerance.  A report off that path, past the last target, or outside
the travel means the machine is doing something nobody asked for, and the
session stops it.

This module is the geometry alone (no Qt, no wire), so property tests can ask
it anything.  The path is a list of *legs*: a straight segment (a line move)
or a box (an arc's bounding region, or moves whose order is no longer known).
A report is matched to the earliest leg still ahead that it lies within
tolerance of, and the legs before that one are behind the machine for good:
a machine never goes back along the path it was sent.  Matching the earliest
leg, not the nearest, keeps a path that crosses itself from skipping ahead.

Sessions decide when the path is known (:meth:`Envelope.anchor` at a position
the machine confirmed with nothing in flight) and when it is not
(:meth:`Envelope.release`: homing, probing, an offset the station cannot
follow), in which case nothing is judged until the next anchor.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Sequence
from dataclasses import dataclass

Point = tuple[float, ...]

#: The tolerance when a profile names none (mm): a few steps and a rounded report.
DEFAULT_TOLERANCE_MM = 0.5


class Fault(enum.Enum):
    """What was wrong with a report (the message says it to the operator)."""

    OUTSIDE_TRAVEL = "outside the travel"
    PAST_TARGET = "past the target"
    OFF_PATH = "off the path"
    MOVED_AT_REST = "moved while nothing was sent"


@dataclass(frozen=True)
class Leg:
    """One move of the path: a segment ``start``→``end``, or the box ``low``…``high``."""

    start: Point
    end: Point
    label: str
    tag: object = None
    #: Judged as a box (an arc, or moves whose course is not known): ``low``/``high`` bound it.
    low: Point | None = None
    high: Point | None = None

    def distance(self, point: Point) -> float:
        if self.low is not None and self.high is not None:
            return _box_distance(point, self.low, self.high)
        return _segment_distance(point, self.start, self.end)

    def nearest(self, point: Point) -> Point:
        if self.low is not None and self.high is not None:
            return tuple(
                min(h, max(lo, p)) for p, lo, h in zip(point, self.low, self.high, strict=True)
            )
        return _segment_nearest(point, self.start, self.end)


@dataclass(frozen=True)
class Deviation:
    """A report the envelope does not allow: what was seen against what was expected."""

    fault: Fault
    seen: Point
    #: The nearest point the machine was allowed to be at (on the path, or where it rests).
    expected: Point
    distance: float
    #: The move the machine was on (of the leg it was last seen on and the next, the one
    #: nearer to what was seen), or the last one sent when the machine ran past it.
    label: str
    tag: object = None


class Envelope:
    """The path of one machine's moves in flight, in ``len(limits)`` coordinates.

    ``limits`` are the travel per coordinate (``-inf``/``inf`` for one that turns
    freely); ``tolerance`` is how far a report may stray from the path.
    ``hold_at_rest``: with nothing in flight, the machine must stay at the
    anchor (a machine with no controls of its own); otherwise, at rest, a
    report moves the anchor (a joystick on the machine).
    """

    def __init__(
        self,
        limits: Sequence[tuple[float, float]],
        tolerance: float = DEFAULT_TOLERANCE_MM,
        *,
        hold_at_rest: bool = True,
        travel_at_rest: bool = False,
    ) -> None:
        if not tolerance > 0 or not math.isfinite(tolerance):
            raise ValueError(f"the tolerance must be a positive length, not {tolerance}")
        self.limits = tuple(limits)
        self.tolerance = tolerance
        self.hold_at_rest = hold_at_rest
        # Not holding at rest, a report outside the travel still deviates (usb3: a move
        # nobody sent, its count changed on the wire, ran off at rest: relay seed 134).
        self.travel_at_rest = travel_at_rest
        self._anchor: Point | None = None
        self._legs: list[Leg] = []
        self._serial = 0  # serial of _legs[0]: legs are numbered as they are added

    # --- what the envelope knows ----------------------------------------------------

    @property
    def dims(self) -> int:
        return len(self.limits)

    @property
    def known(self) -> bool:
        """Whether the path is known (else every report passes until an anchor)."""
        return self._anchor is not None

    @property
    def legs(self) -> tuple[Leg, ...]:
        """The legs still ahead of the machine, the one it is on first."""
        return tuple(self._legs)

    @property
    def in_flight(self) -> int:
        """Legs not yet known to be behind the machine."""
        return len(self._legs)

    @property
    def next_serial(self) -> int:
        """The serial number the next leg added will have (for :meth:`behind`)."""
        return self._serial + len(self._legs)

    @property
    def end(self) -> Point | None:
        """Where the moves sent end (the anchor with nothing in flight); None: not known."""
        if self._legs:
            return self._legs[-1].end
        return self._anchor

    # --- what the session tells it --------------------------------------------------

    def anchor(self, point: Sequence[float]) -> None:
        """The machine stands at ``point`` and nothing it was sent is still to run."""
        self._anchor = self._point(point)
        self._serial += len(self._legs)
        self._legs = []

    def release(self) -> None:
        """The machine goes where the station cannot follow: nothing is judged until an anchor."""
        self._anchor = None
        self._serial += len(self._legs)
        self._legs = []

    def add_line(self, target: Sequence[float], label: str, tag: object = None) -> int | None:
        """A straight move from where the last one ends to ``target``; its serial number.

        None when the path is not known (nothing to add it to).
        """
        start = self.end
        if start is None:
            return None
        self._legs.append(Leg(start, self._point(target), label, tag))
        return self._serial + len(self._legs) - 1

    def jump(self, point: Sequence[float], label: str, tag: object = None) -> int | None:
        """The machine's own coordinates jump to ``point`` once the moves before are done
        (a plotter firmware's ``G92``): the path goes on from there, nothing moves between."""
        if self.end is None:
            return None
        here = self._point(point)
        self._legs.append(Leg(here, here, label, tag))
        return self._serial + len(self._legs) - 1

    def add_box(
        self,
        low: Sequence[float],
        high: Sequence[float],
        target: Sequence[float],
        label: str,
        tag: object = None,
    ) -> int | None:
        """A move known only by a region it stays in (an arc's bounding box) and its end.

        The box is widened to hold where the move starts and ends.
        """
        start = self.end
        if start is None:
            return None
        end = self._point(target)
        lo = tuple(min(a, b, c) for a, b, c in zip(self._point(low), start, end, strict=True))
        hi = tuple(max(a, b, c) for a, b, c in zip(self._point(high), start, end, strict=True))
        self._legs.append(Leg(start, end, label, tag, lo, hi))
        return self._serial + len(self._legs) - 1

    def loosen(self, label: str, tag: object = None) -> None:
        """The moves in flight run in a way no longer known (one was refused, say): from here
        on the machine is judged only by the box around all of them, until the next anchor."""
        if not self._legs:
            return
        points = [self._legs[0].start] + [leg.end for leg in self._legs]
        for leg in self._legs:
            if leg.low is not None and leg.high is not None:
                points += [leg.low, leg.high]
        low = tuple(min(c) for c in zip(*points, strict=True))
        high = tuple(max(c) for c in zip(*points, strict=True))
        start, end = self._legs[0].start, self._legs[-1].end
        self._serial += len(self._legs) - 1
        self._legs = [Leg(start, end, label, tag, low, high)]

    def behind(self, serial: int) -> None:
        """Legs numbered below ``serial`` are known to be done (the machine is past them)."""
        drop = min(len(self._legs), max(0, serial - self._serial))
        if drop:
            self._anchor = self._legs[drop - 1].end
            del self._legs[:drop]
            self._serial += drop

    # --- judging a report -----------------------------------------------------------

    def check(self, seen: Sequence[float]) -> Deviation | None:
        """Judge a reported position; None when it is where the moves sent allow.

        A report that fits moves the machine along the path (the legs before
        the one it is on are dropped); one that does not is returned as a
        :class:`Deviation` and changes nothing.
        """
        point = self._point(seen)
        anchor = self._anchor
        if anchor is None or not all(math.isfinite(p) for p in point):
            return None if anchor is None else self._deviation(point)
        if not self._legs:
            if _distance(point, anchor) <= self.tolerance:
                return None
            if not self.hold_at_rest and not (self.travel_at_rest and self._outside(point)):
                self._anchor = point  # moved by its own controls: it rests there now
                return None
            return self._deviation(point)
        if _distance(point, anchor) <= self.tolerance:
            return None  # still where the last leg behind it ended (before a jump, say)
        for i, leg in enumerate(self._legs):
            if leg.distance(point) <= self.tolerance:
                # At a leg's end it is at the next one's start: on it from here.  Kept on
                # the first, a path that turns back along itself (usb3: 3200 → 1600 after
                # 0 → 3200) would let it run on down the first leg unseen (relay usb3
                # seed 103: a repeated move took Y to 0, and the job said done).
                while (
                    i + 1 < len(self._legs)
                    and _distance(point, self._legs[i].end) <= self.tolerance
                ):
                    i += 1
                if i:
                    self._anchor = self._legs[i - 1].end
                    del self._legs[:i]
                    self._serial += i
                return None
        return self._deviation(point)

    def _outside(self, point: Point) -> bool:
        tolerance = self.tolerance
        return any(
            p < low - tolerance or p > high + tolerance
            for p, (low, high) in zip(point, self.limits, strict=True)
        )

    def _deviation(self, point: Point) -> Deviation:
        anchor = self._anchor
        assert anchor is not None
        outside = self._outside(point)
        if not self._legs:
            fault = Fault.OUTSIDE_TRAVEL if outside else Fault.MOVED_AT_REST
            return Deviation(fault, point, anchor, _distance(point, anchor), "", None)
        # The move it was on: the last one it was seen on, or the next (a report further
        # ahead would name a move the machine never reached, one that passes nearby).
        nearest = min(self._legs[:2], key=lambda leg: leg.distance(point))
        last = self._legs[-1]
        expected = nearest.nearest(point)
        distance = nearest.distance(point)
        if outside:
            fault = Fault.OUTSIDE_TRAVEL
        elif _beyond(point, last):
            fault, nearest, expected = Fault.PAST_TARGET, last, last.end
        else:
            fault = Fault.OFF_PATH
        return Deviation(fault, point, expected, distance, nearest.label, nearest.tag)

    def _point(self, values: Sequence[float]) -> Point:
        point = tuple(map(float, values))
        if len(point) != self.dims:
            raise ValueError(f"{len(point)} coordinates for a path of {self.dims}")
        return point


# --- geometry ----------------------------------------------------------------------------


def _distance(a: Point, b: Point) -> float:
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b, strict=True)))


def _segment_nearest(point: Point, start: Point, end: Point) -> Point:
    direction = [e - s for s, e in zip(start, end, strict=True)]
    length2 = sum(d * d for d in direction)
    if length2 == 0.0:
        return start
    along = sum((p - s) * d for p, s, d in zip(point, start, direction, strict=True)) / length2
    t = min(1.0, max(0.0, along))
    return tuple(s + t * d for s, d in zip(start, direction, strict=True))


def _segment_distance(point: Point, start: Point, end: Point) -> float:
    return _distance(point, _segment_nearest(point, start, end))


def _box_distance(point: Point, low: Point, high: Point) -> float:
    return math.sqrt(
        sum(max(lo - p, 0.0, p - hi) ** 2 for p, lo, hi in zip(point, low, high, strict=True))
    )


def _beyond(point: Point, leg: Leg) -> bool:
    """Whether ``point`` lies past ``leg``'s end in the leg's own direction (ran on)."""
    direction = [e - s for s, e in zip(leg.start, leg.end, strict=True)]
    return sum((p - e) * d for p, e, d in zip(point, leg.end, direction, strict=True)) > 0.0


def arc_box(
    start: Sequence[float], end: Sequence[float], centre: Sequence[float], plane: tuple[int, int]
) -> tuple[Point, Point]:
    """The bounding box of a G2/G3 arc: its circle's square in ``plane``, the rest from the ends.

    The whole circle's square holds the arc whichever way it turns; it is
    looser than the arc, never tighter, so a healthy arc never trips.
    """
    first, second = plane
    radius = math.hypot(start[first] - centre[first], start[second] - centre[second])
    radius = max(radius, math.hypot(end[first] - centre[first], end[second] - centre[second]))
    low = [min(a, b) for a, b in zip(start, end, strict=True)]
    high = [max(a, b) for a, b in zip(start, end, strict=True)]
    for axis in plane:
        low[axis] = min(low[axis], centre[axis] - radius)
        high[axis] = max(high[axis], centre[axis] + radius)
    return tuple(low), tuple(high)
