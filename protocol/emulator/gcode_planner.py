"""The emulated G-code board's planner: blocks run strictly in order on the emulated clock.

Two firmwares, two planners:

* A GRBL board (``Junctions`` given: GRBL's ``$11`` and per-axis
  accelerations) plans as GRBL 1.1 does (:mod:`protocol.gcode.junctions`):
  every move is timed in mm along its path at the speed and acceleration its
  axes allow in its direction; consecutive moves join at the junction speed
  of their corner, and the blocks in the planner are planned again whenever
  one is added, the newest able to stop at its end.  The move under way is
  re-profiled from its present speed when a newer block raises its exit
  speed.  A dwell, a pen (spindle) change, a pause, ``G92`` and ``M18`` stop
  the motion first: GRBL empties its planner before them, so a move before
  one ends at rest and the move after starts from rest.
* The other firmwares (the CoreXY plotter, the winder) start and end every
  move at rest: a trapezoid (or a triangle, when too short to reach its top
  rate) on the steps of the motor that makes the most, or with an infinite
  acceleration one step interval throughout.

The tool is placed linearly along the block by the share of its length (or
lead-motor steps) made.  Feed hold brakes the running move at its
acceleration (on GRBL through as many following moves as braking takes)
and keeps the rest; resuming plans the rest again from rest.  A dwell stops
counting while held; a pen movement finishes before the hold takes effect.
Time is handed in by :meth:`Planner.run`, which ends blocks exactly when
they end (the next starts at once), never at a step boundary.
"""

from __future__ import annotations

import enum
import math
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from protocol.gcode.junctions import junction_speed_sqr, max_entry_sqr, profile, replan

#: Seconds: a block with less than this left has ended (rounding of float sums).
TIME_EPS = 1e-9
#: GRBL's MINIMUM_FEED_RATE (1 mm/min), in units/s: an override never plans slower.
_MINIMUM_SPEED = 1.0 / 60.0


@dataclass(frozen=True, slots=True)
class Ramp:
    """The lead motor's motion as phases ``(start speed, acceleration, seconds)``, in steps."""

    phases: tuple[tuple[float, float, float], ...]

    @property
    def duration(self) -> float:
        return sum(phase[2] for phase in self.phases)

    @property
    def distance(self) -> float:
        return self.at(self.duration)[0]

    def at(self, t: float) -> tuple[float, float]:
        """Steps made and step rate ``t`` seconds into the ramp (held at its end after it)."""
        made = 0.0
        speed = 0.0
        for v0, accel, seconds in self.phases:
            dt = min(max(t, 0.0), seconds)
            made += v0 * dt + 0.5 * accel * dt * dt
            speed = v0 + accel * dt
            t -= seconds
            if t <= 0:
                break
        return made, max(speed, 0.0)


def trapezoid(steps: float, top_rate: float, accel: float) -> Ramp:
    """From rest to rest over ``steps``: ramp up to ``top_rate``, cruise, ramp down.

    Too short to reach the top rate it is a triangle peaking at ``sqrt(steps * accel)``.
    An infinite ``accel`` is a machine without ramps (the CoreXY plotter's firmware steps
    at one interval from the first step to the last): the top rate throughout.
    """
    if steps <= 0:
        return Ramp(())
    if math.isinf(accel):
        return Ramp(((top_rate, 0.0, steps / top_rate),))
    ramp_steps = top_rate * top_rate / (2.0 * accel)
    if 2.0 * ramp_steps <= steps:
        t_ramp = top_rate / accel
        cruise = (steps - 2.0 * ramp_steps) / top_rate
        return Ramp(((0.0, accel, t_ramp), (top_rate, 0.0, cruise), (top_rate, -accel, t_ramp)))
    peak = math.sqrt(steps * accel)
    t_ramp = peak / accel
    return Ramp(((0.0, accel, t_ramp), (peak, -accel, t_ramp)))


def brake(speed: float, accel: float) -> Ramp:
    """From ``speed`` to rest at ``accel`` (at once without ramps)."""
    if math.isinf(accel):
        return Ramp(())
    return Ramp(((speed, -accel, speed / accel),)) if speed > 0 else Ramp(())


# -- blocks --------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Move:
    """A straight move; ``kind`` is what made it (``G0``, ``G1``, ``G2``, ``G3``, ``home``).

    ``steps`` are the lead motor's, ``rate`` its top step rate (the feed
    rate, or the motors' limit if lower), ``length`` the path in units.  A
    GRBL board plans along the path instead: ``speed`` (units/s, the feed or
    what the axes allow in this direction), ``path_accel`` (units/s², what
    the axes allow in this direction) and ``unit``, the direction.
    """

    start: tuple[float, ...]
    end: tuple[float, ...]
    steps: int
    rate: float
    accel: float
    length: float
    kind: str
    speed: float = 0.0
    path_accel: float = 0.0
    unit: tuple[float, ...] = ()
    #: GRBL: the speed the line asked for (units/s, before the axes' limits) and the rapid
    #: rate in this direction; the feed override scales the one, capped by the other.
    programmed: float = 0.0
    rapid: float = 0.0


@dataclass(frozen=True, slots=True)
class Dwell:
    seconds: float


@dataclass(frozen=True, slots=True)
class PenChange:
    """The pen goes down or up, taking ``seconds``; ``spindle`` is the S level reported."""

    down: bool
    seconds: float
    spindle: float = 0.0
    #: ``M4``: GRBL reports the spindle turning counter-clockwise (``A:C``, not ``A:S``).
    ccw: bool = False


@dataclass(frozen=True, slots=True)
class Pause:
    """``M0``: the program waits here, held, until cycle start."""


@dataclass(frozen=True, slots=True)
class SetPosition:
    """``G92``: from here on the tool is said to be at ``position``."""

    position: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class SetOffset:
    """GRBL's ``G92``/``G92.1``: the work offset becomes ``offset``; the tool does not move.

    Queued so that it takes effect once the motion before it is done (GRBL
    synchronises its planner on a work-offset change).
    """

    offset: tuple[float, ...]
    #: GRBL's ``M2``/``M30``: G54 again, and the overrides back to 100 %.
    program_end: bool = False


@dataclass(frozen=True, slots=True)
class DriversOff:
    """``M18``: the drivers of these axes (indices) lose their holding current until a move."""

    axes: tuple[int, ...]


Block = Move | Dwell | PenChange | Pause | SetPosition | SetOffset | DriversOff


class HoldState(enum.Enum):
    RUNNING = "running"
    #: Feed hold asked: braking, or finishing a pen movement (GRBL's ``Hold:1``).
    STOPPING = "stopping"
    #: Standing still until resumed (``Hold:0``).
    HELD = "held"


#: Called when a block has ended, with the seconds into the present ``run`` it ended at.
BlockDone = Callable[[Block, float], None]


@dataclass(frozen=True, slots=True)
class Junctions:
    """GRBL's planning settings: ``$11`` (mm) and the axes' accelerations (``$120…``, mm/s²)."""

    deviation: float
    accelerations: tuple[float, ...]


@dataclass(slots=True)
class _Slot:
    """A queued block and, for a GRBL move, its entry speed² limit and planned entry speed²."""

    block: Block
    limit_sqr: float = 0.0
    entry_sqr: float = 0.0
    #: The corner's own limit (GRBL's max_junction_speed_sqr), kept for an override change.
    junction_sqr: float = math.inf


class Planner:
    """A bounded queue of blocks and the one that is running.

    ``capacity`` counts the running block too: a board frees a planner slot
    only when its block has been executed.  With ``junctions`` moves are
    planned as GRBL plans them; without, each starts and ends at rest.
    """

    def __init__(
        self, position: tuple[float, ...], capacity: int, junctions: Junctions | None = None
    ) -> None:
        self.capacity = capacity
        self.junctions = junctions
        self._slots: deque[_Slot] = deque()
        self._position = position
        self._hold = HoldState.RUNNING
        # The running block (the head of the queue) and its progress, in the block's
        # measure: mm along the path on GRBL, lead-motor steps otherwise.
        self._started = False
        self._ramp = Ramp(())
        self._t = 0.0
        self._done = 0.0
        self._released = False
        #: GRBL: the speed the last move ended at, which the next one starts from.
        self._carry = 0.0
        #: A hold's braking ramp ends inside the running move (not at its end).
        self._stops_inside = False
        #: GRBL's feed and rapid overrides in force, percent (gcode_overrides.py).
        self.feed_override = 100
        self.rapid_override = 100

    # -- the queue -------------------------------------------------------------------------

    @property
    def free(self) -> int:
        return self.capacity - len(self._slots)

    def __len__(self) -> int:
        return len(self._slots)

    def push(self, block: Block) -> None:
        if self.free <= 0:
            raise OverflowError("the planner is full")  # the firmware checks free first
        slot = _Slot(block)
        if self.junctions is not None and isinstance(block, Move):
            # GRBL drops a move that goes nowhere: it neither stops nor limits the motion.
            slot.limit_sqr = self._entry_limit(block, slot) if block.length > 0 else math.inf
        self._slots.append(slot)
        if self.junctions is not None and isinstance(block, Move):
            self._replan()

    def extend(self, blocks: Iterable[Block]) -> None:
        for block in blocks:
            self.push(block)

    @property
    def current(self) -> Block | None:
        """The block being executed, if one has started."""
        return self._slots[0].block if self._slots and self._started else None

    @property
    def hold_state(self) -> HoldState:
        return self._hold

    # -- where the tool is -------------------------------------------------------------------

    def position(self) -> tuple[float, ...]:
        block = self.current
        if not isinstance(block, Move) or self._measure(block) == 0:
            return self._position
        made, _ = self._ramp.at(self._t)
        fraction = min((self._done + made) / self._measure(block), 1.0)
        return tuple(a + (b - a) * fraction for a, b in zip(block.start, block.end, strict=True))

    def feed(self) -> float:
        """Present speed along the path in units/min (what ``FS:`` reports)."""
        block = self.current
        if not isinstance(block, Move) or self._measure(block) == 0:
            return 0.0
        _, rate = self._ramp.at(self._t)
        return rate / self._measure(block) * block.length * 60.0

    # -- feed hold, resume, stop -------------------------------------------------------------

    def hold(self) -> None:
        """Feed hold: brake the running move, freeze a dwell, let a pen movement finish."""
        if self._hold is not HoldState.RUNNING:
            return
        block = self.current
        if isinstance(block, Move):
            made, rate = self._ramp.at(self._t)
            self._done += made
            self._t = 0.0
            self._hold = HoldState.STOPPING if rate > 0 else HoldState.HELD
            if self.junctions is None:
                self._ramp = brake(rate, block.accel)
                self._stops_inside = True
            else:
                self._brake_from(rate, block)
        elif isinstance(block, PenChange):
            self._hold = HoldState.STOPPING
        else:
            self._hold = HoldState.HELD

    def resume(self) -> bool:
        """Cycle start: go on from a completed hold (or an ``M0``); False if not held."""
        if self._hold is not HoldState.HELD:
            return False
        self._hold = HoldState.RUNNING
        block = self.current
        if isinstance(block, Move):
            self._t = 0.0
            if self.junctions is None:
                self._ramp = trapezoid(block.steps - self._done, block.rate, block.accel)
            else:
                self._replan()  # from rest, as GRBL plans again after a hold
                self._ramp = Ramp(self._profile(block, 0.0))
        elif isinstance(block, Pause):
            self._released = True
        return True

    def place(self, position: tuple[float, ...]) -> None:
        """The tool is at ``position`` now, with nothing run to get there (moved by hand).

        Only while no block is queued: a motion under way would jump.
        """
        if self._slots:
            raise RuntimeError("the tool is placed only while nothing is queued")
        self._position = tuple(position)

    def stop(self) -> None:
        """Stop at once where the tool is and forget every block (soft reset, alarm)."""
        self._position = self.position()
        self._slots.clear()
        self._started = False
        self._hold = HoldState.RUNNING
        self._carry = 0.0

    # -- running -----------------------------------------------------------------------------

    def run(self, seconds: float, on_done: BlockDone) -> None:
        """Execute blocks for ``seconds``; ``on_done`` may push more blocks meanwhile."""
        into = 0.0
        while self._hold is not HoldState.HELD and self._slots:
            if not self._started and self._start():
                break  # an M0 reached: held
            left = self._time_left()
            budget = seconds - into
            if left > budget + TIME_EPS:
                self._t += budget
                return
            self._t += left
            into = min(into + left, seconds)
            if self._braking_done():
                continue
            block = self._slots.popleft().block
            self._finish(block)
            if self._hold is HoldState.STOPPING and not isinstance(block, Move):
                self._hold = HoldState.HELD  # a pen movement ends into a hold
            on_done(block, into)

    def _start(self) -> bool:
        """Start the head block; True if it holds the program there (``M0``)."""
        block = self._slots[0].block
        self._started = True
        self._t = 0.0
        self._done = 0.0
        self._released = False
        match block:
            case Move() if self.junctions is not None:
                if self._hold is HoldState.STOPPING:
                    self._brake_from(self._carry, block)  # a hold braking on into this move
                else:
                    self._ramp = Ramp(self._profile(block, self._carry))
            case Move():
                self._ramp = trapezoid(block.steps, block.rate, block.accel)
            case Dwell() | PenChange():
                self._ramp = Ramp(((0.0, 0.0, block.seconds),))
            case _:
                self._ramp = Ramp(())
        if isinstance(block, Pause):
            self._hold = HoldState.HELD
            return True
        return False

    def _time_left(self) -> float:
        if isinstance(self._slots[0].block, Pause) and not self._released:
            return math.inf
        return max(self._ramp.duration - self._t, 0.0)

    def _braking_done(self) -> bool:
        """A move braked to a standstill by a hold: it stays, held, with the rest to go."""
        if self._hold is not HoldState.STOPPING or not isinstance(self._slots[0].block, Move):
            return False
        if not self._stops_inside:
            return False  # braking goes on into the next move
        self._done += self._ramp.distance
        self._ramp = Ramp(())
        self._t = 0.0
        self._carry = 0.0
        self._hold = HoldState.HELD
        return True

    def _finish(self, block: Block) -> None:
        self._started = False
        if isinstance(block, Move) and self.junctions is not None:
            if block.length > 0:
                self._carry = self._ramp.at(self._ramp.duration)[1]
        else:
            self._carry = 0.0
        self._ramp = Ramp(())
        self._t = 0.0
        if isinstance(block, Move):
            self._position = block.end
        elif isinstance(block, SetPosition):
            self._position = block.position

    # -- GRBL's planning -----------------------------------------------------------------------

    def _measure(self, block: Move) -> float:
        """How a move's progress is counted: mm on GRBL, lead-motor steps otherwise."""
        return block.length if self.junctions is not None else float(block.steps)

    def _entry_limit(self, block: Move, new: _Slot) -> float:
        """The block's max entry speed²: from rest into an empty planner or after a stop."""
        assert self.junctions is not None
        previous: Block | None = None
        for slot in reversed(self._slots):
            previous = slot.block
            if not isinstance(previous, Move) or previous.length > 0:
                break
        if not isinstance(previous, Move) or previous.length <= 0:
            new.junction_sqr = 0.0
            return 0.0
        new.junction_sqr = junction_speed_sqr(
            previous.unit, block.unit, self.junctions.accelerations, self.junctions.deviation
        )
        return max_entry_sqr(new.junction_sqr, self.nominal(block), self.nominal(previous))

    # -- GRBL's overrides ------------------------------------------------------------------

    def nominal(self, block: Move) -> float:
        """GRBL's ``plan_compute_profile_nominal_speed``: a rapid scaled by the rapid
        override, a feed move by the feed override (no faster than the rapid rate), homing
        and jogs as they are; never below GRBL's 1 mm/min."""
        if not block.programmed:
            return block.speed  # a move planned without overrides in mind
        if block.kind in ("G0", "G28"):
            speed = block.speed * self.rapid_override / 100.0
        elif block.kind in ("home", "jog"):
            speed = block.speed
        else:
            speed = min(block.programmed * self.feed_override / 100.0, block.rapid)
        return max(speed, _MINIMUM_SPEED)

    def set_overrides(self, feed: int, rapid: int) -> None:
        """New overrides: every queued move's limits again (GRBL's
        ``plan_update_velocity_profile_parameters``), then the plan from the speed the tool
        has now (``plan_cycle_reinitialize``): the move under way speeds up or slows down at
        its acceleration."""
        self.feed_override, self.rapid_override = feed, rapid
        if self.junctions is None:
            return
        previous: float | None = None
        for slot in self._slots:
            block = slot.block
            if not isinstance(block, Move):
                previous = None
                continue
            if block.length <= 0:
                continue
            nominal = self.nominal(block)
            slower = nominal if previous is None else min(nominal, previous)
            slot.limit_sqr = min(slower * slower, slot.junction_sqr)
            previous = nominal
        self._replan()
        head = self.current
        if isinstance(head, Move) and self._hold is HoldState.RUNNING:
            made, speed = self._ramp.at(self._t)
            self._done += made
            self._t = 0.0
            self._ramp = Ramp(self._profile(head, speed))

    def _replan(self) -> None:
        """Plan the moves from the running one (or the last stop) to the newest again."""
        first = 0
        for i in range(len(self._slots) - 1, -1, -1):
            if not isinstance(self._slots[i].block, Move):
                first = i + 1
                break
        moves = list(self._slots)[first:]
        if not moves:
            return
        running = first == 0 and self._started
        head = moves[0].block
        assert isinstance(head, Move)
        lengths = [slot.block.length for slot in moves]  # type: ignore[union-attr]
        accels = [slot.block.path_accel for slot in moves]  # type: ignore[union-attr]
        limits = [slot.limit_sqr for slot in moves]
        speed = 0.0
        if running:
            made, speed = self._ramp.at(self._t)
            if self._hold is not HoldState.RUNNING:
                speed = 0.0  # planned again from rest on resume
            lengths[0] = max(head.length - self._done - made, 0.0)
            first_entry = speed * speed
        else:
            first_entry = moves[0].entry_sqr = min(moves[0].limit_sqr, self._carry**2)
        entries = replan(first_entry, lengths, accels, limits)
        old_exit = moves[1].entry_sqr if len(moves) > 1 else 0.0
        for slot, entry in zip(moves[1:], entries[1:], strict=True):
            slot.entry_sqr = entry
        new_exit = entries[1] if len(entries) > 1 else 0.0
        if running and self._hold is HoldState.RUNNING and new_exit != old_exit:
            made, speed = self._ramp.at(self._t)
            self._done += made
            self._t = 0.0
            self._ramp = Ramp(self._profile(head, speed))

    def _profile(self, block: Move, entry: float) -> tuple[tuple[float, float, float], ...]:
        """The rest of the running move from ``entry`` to its planned exit speed."""
        exit_sqr = self._slots[1].entry_sqr if len(self._slots) > 1 else 0.0
        if len(self._slots) > 1 and not isinstance(self._slots[1].block, Move):
            exit_sqr = 0.0
        rest = max(block.length - self._done, 0.0)
        nominal, accel = self.nominal(block), block.path_accel
        if entry > nominal and rest > 0 and accel > 0:
            # An override lowered the speed under way: brake to the new one first (GRBL's
            # RAMP_DECELERATE_OVERRIDE), then go on as planned.
            slowing = (entry * entry - nominal * nominal) / (2.0 * accel)
            if slowing >= rest:
                low = math.sqrt(max(entry * entry - 2.0 * accel * rest, 0.0))
                return ((entry, -accel, (entry - low) / accel),)
            first = (entry, -accel, (entry - nominal) / accel)
            exit_speed = min(math.sqrt(exit_sqr), nominal)
            return (first, *profile(rest - slowing, nominal, exit_speed, nominal, accel))
        return profile(rest, entry, math.sqrt(exit_sqr), nominal, accel)

    def _brake_from(self, speed: float, block: Move) -> None:
        """A hold's braking over the rest of ``block``: within it, or on through its end."""
        rest = max(block.length - self._done, 0.0)
        accel = block.path_accel
        after = self._slots[1].block if len(self._slots) > 1 else None
        if speed * speed > 2.0 * accel * rest and isinstance(after, Move):
            low = math.sqrt(speed * speed - 2.0 * accel * rest)
            self._ramp = Ramp(((speed, -accel, (speed - low) / accel),))
            self._stops_inside = False
        else:
            seconds = speed / accel if speed > 0 else 0.0
            if speed * speed > 2.0 * accel * rest:  # nothing to brake on into: stop at its end
                seconds = (speed - math.sqrt(max(speed * speed - 2 * accel * rest, 0.0))) / accel
            self._ramp = Ramp(((speed, -accel, seconds),)) if seconds > 0 else Ramp(())
            self._stops_inside = True
