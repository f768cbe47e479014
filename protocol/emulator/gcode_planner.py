"""The emulated G-code board's planner: blocks run strictly in order on the emulated clock.

Real boards plan junction speeds across blocks; this one starts and ends
every move at rest, which makes a job slower than on the machine but keeps
every duration a closed form a test can work out by hand.  A move is timed
as a trapezoid (or a triangle, when too short to reach its top rate) on the
steps of the motor that makes the most, and the tool is placed linearly
along the block by the fraction of those steps made.

Feed hold brakes the running move at the motors' acceleration and keeps the
rest of it; resuming runs the rest as a new trapezoid from rest.  A dwell
stops counting while held; a pen movement finishes before the hold takes
effect.  Time is handed in by :meth:`Planner.run`, which ends blocks exactly
when they end (the next starts at once), never at a step boundary.
"""

from __future__ import annotations

import enum
import math
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass

#: Seconds: a block with less than this left has ended (rounding of float sums).
TIME_EPS = 1e-9


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
    rate, or the motors' limit if lower), ``length`` the path in units.
    """

    start: tuple[float, ...]
    end: tuple[float, ...]
    steps: int
    rate: float
    accel: float
    length: float
    kind: str


@dataclass(frozen=True, slots=True)
class Dwell:
    seconds: float


@dataclass(frozen=True, slots=True)
class PenChange:
    """The pen goes down or up, taking ``seconds``; ``spindle`` is the S level reported."""

    down: bool
    seconds: float
    spindle: float = 0.0


@dataclass(frozen=True, slots=True)
class Pause:
    """``M0``: the program waits here, held, until cycle start."""


@dataclass(frozen=True, slots=True)
class SetPosition:
    """``G92``: from here on the tool is said to be at ``position``."""

    position: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class DriversOff:
    """``M18``: the drivers of these axes (indices) lose their holding current until a move."""

    axes: tuple[int, ...]


Block = Move | Dwell | PenChange | Pause | SetPosition | DriversOff


class HoldState(enum.Enum):
    RUNNING = "running"
    #: Feed hold asked: braking, or finishing a pen movement (GRBL's ``Hold:1``).
    STOPPING = "stopping"
    #: Standing still until resumed (``Hold:0``).
    HELD = "held"


#: Called when a block has ended, with the seconds into the present ``run`` it ended at.
BlockDone = Callable[[Block, float], None]


class Planner:
    """A bounded queue of blocks and the one that is running.

    ``capacity`` counts the running block too: a board frees a planner slot
    only when its block has been executed.
    """

    def __init__(self, position: tuple[float, ...], capacity: int) -> None:
        self.capacity = capacity
        self._blocks: deque[Block] = deque()
        self._position = position
        self._hold = HoldState.RUNNING
        # The running block (the head of the queue) and its progress.
        self._started = False
        self._ramp = Ramp(())
        self._t = 0.0
        self._done_steps = 0.0
        self._released = False

    # -- the queue -------------------------------------------------------------------------

    @property
    def free(self) -> int:
        return self.capacity - len(self._blocks)

    def __len__(self) -> int:
        return len(self._blocks)

    def push(self, block: Block) -> None:
        if self.free <= 0:
            raise OverflowError("the planner is full")  # the firmware checks free first
        self._blocks.append(block)

    def extend(self, blocks: Iterable[Block]) -> None:
        for block in blocks:
            self.push(block)

    @property
    def current(self) -> Block | None:
        """The block being executed, if one has started."""
        return self._blocks[0] if self._blocks and self._started else None

    @property
    def hold_state(self) -> HoldState:
        return self._hold

    # -- where the tool is -------------------------------------------------------------------

    def position(self) -> tuple[float, ...]:
        block = self.current
        if not isinstance(block, Move) or block.steps == 0:
            return self._position
        made, _ = self._ramp.at(self._t)
        fraction = min((self._done_steps + made) / block.steps, 1.0)
        return tuple(a + (b - a) * fraction for a, b in zip(block.start, block.end, strict=True))

    def feed(self) -> float:
        """Present speed along the path in units/min (what ``FS:`` reports)."""
        block = self.current
        if not isinstance(block, Move) or block.steps == 0:
            return 0.0
        _, rate = self._ramp.at(self._t)
        return rate / block.steps * block.length * 60.0

    # -- feed hold, resume, stop -------------------------------------------------------------

    def hold(self) -> None:
        """Feed hold: brake the running move, freeze a dwell, let a pen movement finish."""
        if self._hold is not HoldState.RUNNING:
            return
        block = self.current
        if isinstance(block, Move):
            made, rate = self._ramp.at(self._t)
            self._done_steps += made
            self._ramp = brake(rate, block.accel)
            self._t = 0.0
            self._hold = HoldState.STOPPING if rate > 0 else HoldState.HELD
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
            self._ramp = trapezoid(block.steps - self._done_steps, block.rate, block.accel)
            self._t = 0.0
        elif isinstance(block, Pause):
            self._released = True
        return True

    def stop(self) -> None:
        """Stop at once where the tool is and forget every block (soft reset, alarm)."""
        self._position = self.position()
        self._blocks.clear()
        self._started = False
        self._hold = HoldState.RUNNING

    # -- running -----------------------------------------------------------------------------

    def run(self, seconds: float, on_done: BlockDone) -> None:
        """Execute blocks for ``seconds``; ``on_done`` may push more blocks meanwhile."""
        into = 0.0
        while self._hold is not HoldState.HELD and self._blocks:
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
            block = self._blocks.popleft()
            self._finish(block)
            if self._hold is HoldState.STOPPING:  # a pen movement ends into a hold
                self._hold = HoldState.HELD
            on_done(block, into)

    def _start(self) -> bool:
        """Start the head block; True if it holds the program there (``M0``)."""
        block = self._blocks[0]
        self._started = True
        self._t = 0.0
        self._done_steps = 0.0
        self._released = False
        match block:
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
        if isinstance(self._blocks[0], Pause) and not self._released:
            return math.inf
        return max(self._ramp.duration - self._t, 0.0)

    def _braking_done(self) -> bool:
        """A move braked to a standstill by a hold: it stays, held, with the rest to go."""
        if self._hold is not HoldState.STOPPING or not isinstance(self._blocks[0], Move):
            return False
        self._done_steps += self._ramp.distance
        self._ramp = Ramp(())
        self._t = 0.0
        self._hold = HoldState.HELD
        return True

    def _finish(self, block: Block) -> None:
        self._started = False
        self._ramp = Ramp(())
        self._t = 0.0
        if isinstance(block, Move):
            self._position = block.end
        elif isinstance(block, SetPosition):
            self._position = block.position
