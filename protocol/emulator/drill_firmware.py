"""Firmware of the PCB drilling/drawing plotter, emulated (docs/protocols.md §3).

It is the device side of the ``drill`` dialect written from the contract
alone, so the station's drill session and the Excellon jobs can be run and
tested with no machine attached, and so a test can check which holes were
really drilled where (:attr:`DrillFirmware.drill_log`).

The axes are the mechanism :class:`~protocol.mechanism.Axis` run in
*microstep* units instead of micrometres.  The reference machine steps every
axis at one constant period per microstep (no ramps), so each Axis gets its
speed as its start speed: it jumps to full speed and stops dead, and a move of
``n`` microsteps takes exactly ``n`` periods.

Decisions the contract leaves open, made here:

- One procedure at a time.  ``R<letter>`` goes out at the end of the control
  cycle in which the line arrived, even while another procedure runs; the
  command is then *queued* and its procedure starts the moment the previous
  one is done, so ``D`` replies come in command order.  The host is supposed
  to wait for ``D``; queueing (rather than refusing) is what a firmware with
  a receive buffer does when it is not.
- A malformed line is answered ``E<its first letter, or ?>`` at once and
  changes nothing; it does not disturb a procedure in progress.  Empty lines
  (and an LF after the CR) are ignored.
- ``X``/``Y`` move one axis at a time.  Each axis has one sensor, at the home
  end, read only by ``N`` ("Kazdy pohyb je ukoncen v jednom smeru cidlem",
  FIDELITY S2-29).  The reference firmware has no soft limits: a target past
  the far end of the travel runs the carriage into the frame, where it
  stalls while the firmware steps on; the move takes every step's period,
  the counter ends at the target, the steps the carriage did not make are
  lost (logged as :class:`StalledAtFrame`), and the next ``N`` finds the
  zero again.
- ``N`` homes X, then Y: run to the end switch at 0, back off until it opens
  (one microstep, the switches' hysteresis), then step the zero offset and
  call that 0.  So the zero lies ``offset + 1`` microsteps off the switch
  edge and the high end of the travel sits exactly at the other switch.
- At power-on the firmware homes on its own, as the original did ("Je to
  prvni procedura po spusteni mikrokontroleru", FIDELITY S2-19): the ``N``
  procedure runs from the first control cycle, with no reply (nobody asked),
  logged as :class:`HomedAtPowerOn`.  Commands arriving meanwhile are answered
  ``R`` and queued behind it.  With :attr:`DrillConfig.home_at_power_on` off
  (tests of the procedures themselves) the step counters count from wherever
  the carriage stood at power-on (:attr:`DrillConfig.power_on`) until the
  first ``N``; :attr:`DrillFirmware.homed` says whether they count from the
  machine's zero yet.
- ``V`` as the original's ``Vrtat`` (FIDELITY S2-22/S2-23, the timing in
  :mod:`protocol.drill.timing`): Z goes down one microstep per period until
  the optical sensor (:attr:`DrillConfig.sensor_depth`) and 12 microsteps
  more, pausing 10 ms after every second microstep; it waits 100 ms at the
  bottom, comes back 39 full steps (``z_microsteps_per_step`` microsteps per
  period) and waits 100 ms more.  The return is shorter than the first way
  down from the top, so Z then hovers above the board and later strokes are
  short.  The hole is logged at the bottom of the stroke, at the X/Y position
  it was drilled at.
- ``K``/``Z`` (the original's ``Kresli``/``Zvedni``, FIDELITY S2-12/S2-24)
  are the two halves of ``V``: ``K`` brings the pen down as ``V`` brings the
  drill (to the sensor and the overtravel, with the pauses and the wait at the
  bottom), ``Z`` takes it back up as ``V`` does (the 39 full steps and the
  wait after).  While the pen is down every ``X``/``Y`` move draws: each is
  logged as a :class:`DrawnSegment` from where the pen was to where it
  stopped, so with one axis moving at a time a diagonal between two
  coordinates is drawn as two strokes, X first, as the original's
  ``Popojed X``/``Popojed Y`` drew it.
- ``P`` runs X to 0, then Y to the back (its travel), then switches the motors
  off.  Any later motion switches them on again; the counters are kept (an
  idle stepper does not lose its position unless pushed).

Time only moves in :meth:`DrillFirmware.run_until`, in whole control cycles:
commands that arrived since the previous cycle are answered and queued at its
start, the procedure advances through the cycle (one procedure step ending
mid-cycle lets the next one start at once, so durations are exact, not
rounded to cycles), and the replies go out at the cycle's end.  On a
:class:`~protocol.clock.ManualClock` a procedure of duration ``d`` started at
a cycle boundary says ``D`` at the end of the cycle in which ``d`` elapses.
"""

from __future__ import annotations

import dataclasses
import math
from collections import deque
from collections.abc import Iterator
from dataclasses import dataclass

from protocol.clock import Clock
from protocol.drill import timing
from protocol.drill.codec import (
    Command,
    CommandDecoder,
    Rejected,
    Reply,
    ReplyKind,
    encode_reply,
    error_reply,
)
from protocol.drill.timing import DRILL_OVERTRAVEL, DrillTiming
from protocol.emulator.cycles import ControlCycles
from protocol.mechanism import Axis, AxisLimits

#: Tolerance for comparing times built from float sums.
_EPS = 1e-9
#: Seconds added to a motion's computed duration.  Advancing an axis by exactly
#: its ``time_to_idle`` can leave it a rounding error short of the event that
#: ends the motion (homing's switch opening), still moving; the next step would
#: then re-plan it and homing would never set its zero.  Far below a step
#: period and below ``_EPS``, so it never shifts a reply into another cycle.
_SLOP = 1e-10
#: Entries kept in each log, bounded for an emulator left running for days.
LOG_LENGTH = 10_000
#: The DrillConfig fields a DrillTiming sets.
_TIMED = frozenset(
    {"step_periods", "down_pause", "down_pause_every", "dwell", "after_wait", "return_full_steps"}
)
#: An acceleration high enough never to matter: speeds are jumped to anyway.
_NO_RAMP = 1e12


@dataclass(frozen=True)
class DrillConfig:
    """What differs between machines; the defaults describe the reference plotter.

    Lengths are microsteps, times seconds.  ``travel`` is the range of
    positions reachable from the machine's zero (X 4200 and Y 3000 are about
    212 by 152 mm at 19.8 and 19.7 microsteps per mm: the original drills
    boards "do velikosti A5 (148mm x 210mm)", FIDELITY S2-27).
    """

    travel: tuple[int, int] = (4200, 3000)
    #: Seconds per microstep of X, Y and Z.
    step_periods: tuple[float, float, float] = (
        timing.STEP_PERIODS_S["X"],
        timing.STEP_PERIODS_S["Y"],
        timing.STEP_PERIODS_S["Z"],
    )
    #: Microsteps from where each end switch opens to the zero, X and Y.
    zero_offsets: tuple[int, int] = (timing.ZERO_OFFSETS["X"], timing.ZERO_OFFSETS["Y"])
    #: Where the carriage stands at power-on, microsteps from the X/Y switch edges.
    power_on: tuple[int, int] = (1200, 900)
    #: Z microsteps from the top to where the optical sensor sees the board.
    sensor_depth: int = timing.SENSOR_DEPTH
    #: Microsteps in one full step of Z (half-step drive): the return goes that many a period.
    z_microsteps_per_step: int = timing.Z_MICROSTEPS_PER_FULL_STEP
    #: Full steps of the return stroke.
    return_full_steps: int = timing.RETURN_FULL_STEPS
    #: Going down, a pause of ``down_pause`` seconds after every ``down_pause_every`` microsteps.
    down_pause: float = timing.DOWN_PAUSE_S
    down_pause_every: int = timing.DOWN_PAUSE_EVERY
    #: Seconds the drill stays at the bottom of the stroke, and waits after the return.
    dwell: float = timing.BOTTOM_WAIT_S
    after_wait: float = timing.AFTER_WAIT_S
    control_cycle: float = 0.005
    #: Run the ``N`` procedure at power-on, before any command, as the original does.
    home_at_power_on: bool = True

    def __post_init__(self) -> None:
        if any(t <= 0 for t in self.travel):
            raise ValueError(f"travel must be positive, got {self.travel!r}")
        if any(not p > 0 for p in self.step_periods):
            raise ValueError(f"step periods must be positive, got {self.step_periods!r}")
        if any(o < 0 for o in self.zero_offsets):
            raise ValueError(f"zero offsets must be >= 0, got {self.zero_offsets!r}")
        for start, travel, offset in zip(
            self.power_on, self.travel, self.zero_offsets, strict=True
        ):
            if not 0 <= start <= travel + offset + 1:
                raise ValueError(f"power-on position {start} is outside the switches")
        if self.sensor_depth <= 0 or self.z_microsteps_per_step <= 0:
            raise ValueError("the sensor depth and the Z full step must be positive")
        if self.return_full_steps <= 0 or self.down_pause_every <= 0:
            raise ValueError("the return stroke and the pause interval must be positive")
        if min(self.dwell, self.after_wait, self.down_pause) < 0 or not (self.control_cycle > 0):
            raise ValueError("times must be >= 0 and the control cycle positive")

    @classmethod
    def with_timing(cls, drill_timing: DrillTiming, **others: object) -> DrillConfig:
        """A machine with ``drill_timing``'s constants (a profile's ``[timing]``, S2-06)."""
        t = drill_timing
        return cls(
            step_periods=(t.x_period_s, t.y_period_s, t.z_period_s),
            down_pause=t.down_pause_s,
            down_pause_every=t.down_pause_every,
            dwell=t.bottom_wait_s,
            after_wait=t.after_wait_s,
            return_full_steps=t.return_full_steps,
            **others,  # type: ignore[arg-type]
        )

    @property
    def drill_depth(self) -> int:
        """Z microsteps from the top to the bottom of a drilling stroke."""
        return self.sensor_depth + DRILL_OVERTRAVEL


@dataclass(frozen=True, slots=True)
class ExecutedCommand:
    """One line the device received, when: accepted ones were answered ``R``, the rest ``E``."""

    time: float
    command: Command | Rejected
    accepted: bool


@dataclass(frozen=True, slots=True)
class CommandDone:
    """A procedure finished and was answered ``D``, at ``time``."""

    time: float
    command: Command


@dataclass(frozen=True, slots=True)
class DrilledHole:
    """A hole the drill actually made: at the bottom of its stroke, at (x, y) microsteps."""

    time: float
    x: int
    y: int

    @property
    def position(self) -> tuple[int, int]:
        return self.x, self.y


@dataclass(frozen=True, slots=True)
class PenEvent:
    """The pen finished going down (``down``) or up, at (x, y) microsteps."""

    time: float
    down: bool
    x: int
    y: int


@dataclass(frozen=True, slots=True)
class DrawnSegment:
    """The pen, down, moved from (x0, y0) to (x1, y1) microsteps: a stroke on the paper."""

    time: float
    x0: int
    y0: int
    x1: int
    y1: int


@dataclass(frozen=True, slots=True)
class HomedAtPowerOn:
    """The power-on homing finished (no command asked for it, so no reply), at ``time``."""

    time: float


@dataclass(frozen=True, slots=True)
class StalledAtFrame:
    """A move ran the carriage into the frame (FIDELITY S2-29): it stood there while the
    firmware stepped on, so its counter reads ``lost`` microsteps past where the carriage is.

    ``axis`` is ``"X"`` or ``"Y"``, ``end`` ``"far"`` (the frame opposite the sensor) or
    ``"home"`` (the frame behind the sensor, reached when lost steps made the counter lie).
    """

    time: float
    axis: str
    end: str
    lost: int
    counter: int


DrillEvent = (
    ExecutedCommand
    | CommandDone
    | DrilledHole
    | PenEvent
    | DrawnSegment
    | HomedAtPowerOn
    | StalledAtFrame
)
"""Everything :attr:`DrillFirmware.event_log` records, in the order it happened."""


def event_log_line(event: DrillEvent) -> str:
    """One line of text for the emulator's ``--log`` file, time first."""
    match event:
        case ExecutedCommand(time, Rejected(raw), _):
            return f"{time:.6f} refused {raw!r}"
        case ExecutedCommand(time, Command(letter, value), _):
            return f"{time:.6f} received {letter}{'' if value is None else value}"
        case CommandDone(time, Command(letter, value)):
            return f"{time:.6f} done {letter}{'' if value is None else value}"
        case DrilledHole(time, x, y):
            return f"{time:.6f} hole X{x} Y{y}"
        case PenEvent(time, down, x, y):
            return f"{time:.6f} pen {'down' if down else 'up'} X{x} Y{y}"
        case DrawnSegment(time, x0, y0, x1, y1):
            return f"{time:.6f} drawn X{x0} Y{y0} to X{x1} Y{y1}"
        case HomedAtPowerOn(time):
            return f"{time:.6f} homed at power-on"
        case StalledAtFrame(time, axis, end, lost, counter):
            return (
                f"{time:.6f} stalled {axis} at the {end} frame: {lost} steps lost, "
                f"counter {axis}{counter}"
            )
    raise TypeError(f"not a drill event: {event!r}")


#: A procedure: a generator that starts each step and yields how long it takes.
_Procedure = Iterator[float]


class DrillFirmware(ControlCycles):
    """The plotter's control loop: X, Y and the drill's Z, a pen, one procedure at a time.

    Thread-safe: the loopback's ticker thread runs cycles while the GUI thread
    reads positions and logs, so every public method and property takes the
    same re-entrant lock.
    """

    def __init__(self, clock: Clock, config: DrillConfig | None = None) -> None:
        self.config = config if config is not None else DrillConfig()
        super().__init__(clock, self.config.control_cycle)
        cfg = self.config
        self._decoder = CommandDecoder()
        self._inbox: deque[Command | Rejected] = deque()
        self._pending: deque[Command] = deque()
        self._outbox: list[bytes] = []
        #: The procedure running, its command, and the time left in its present step.
        self._procedure: _Procedure | None = None
        self._current: Command | None = None
        self._step_left = 0.0
        #: Time already run into the present cycle (procedure steps end mid-cycle).
        self._into_cycle = 0.0
        #: Microsteps from the home sensor's edge to the far frame, X and Y.
        self._switch_spans = (
            cfg.travel[0] + cfg.zero_offsets[0] + 1,
            cfg.travel[1] + cfg.zero_offsets[1] + 1,
        )
        x = self._make_axis(self._switch_spans[0], cfg.power_on[0])
        y = self._make_axis(self._switch_spans[1], cfg.power_on[1])
        z = self._make_axis(2 * cfg.drill_depth, 0)
        self._axes = (x, y, z)
        self._speeds = tuple(1.0 / p for p in cfg.step_periods)
        self._homed = False
        self._motors_on = False
        self._pen_down = False
        self._command_log: deque[ExecutedCommand] = deque(maxlen=LOG_LENGTH)
        self._drill_log: deque[DrilledHole] = deque(maxlen=LOG_LENGTH)
        self._pen_log: deque[PenEvent] = deque(maxlen=LOG_LENGTH)
        self._drawing_log: deque[DrawnSegment] = deque(maxlen=LOG_LENGTH)
        self._event_log: deque[DrillEvent] = deque(maxlen=LOG_LENGTH)
        if cfg.home_at_power_on:
            # Started now, run from the first control cycle on, like any procedure.
            self._procedure = self._home()
            self._step_left = next(self._procedure)

    @staticmethod
    def _make_axis(switch_span: int, physical: int) -> Axis:
        """An axis in microsteps whose counter reads 0 where it stands at power-on."""
        axis = Axis(
            AxisLimits(travel_um=float(switch_span), microstep_um=1.0),
            acceleration=_NO_RAMP,
            start_speed=0.0,
            position_um=float(physical),
        )
        axis.set_position(0.0)
        return axis

    def set_timing(self, drill_timing: DrillTiming) -> None:
        """Run ``drill_timing``'s constants from the next procedure step on (S2-06)."""
        with self._lock:
            t = drill_timing
            self.config = dataclasses.replace(
                DrillConfig.with_timing(t),
                **{
                    f.name: getattr(self.config, f.name)
                    for f in dataclasses.fields(DrillConfig)
                    if f.name not in _TIMED
                },
            )
            self._speeds = tuple(1.0 / p for p in self.config.step_periods)

    # -- EmulatedDevice --------------------------------------------------------

    def receive(self, data: bytes) -> None:
        with self._lock:
            self._inbox.extend(self._decoder.feed(data))

    # -- introspection -----------------------------------------------------------

    @property
    def positions(self) -> tuple[int, int, int]:
        """X, Y and Z step counters in microsteps (Z: 0 at the top, positive down)."""
        with self._lock:
            x, y, z = (axis.microsteps for axis in self._axes)
            return x, y, z

    @property
    def axes(self) -> tuple[Axis, ...]:
        """The X, Y and Z mechanisms, in microsteps."""
        with self._lock:
            return self._axes

    @property
    def homed(self) -> bool:
        """True once ``N`` has run: the counters count from the machine's zero."""
        with self._lock:
            return self._homed

    @property
    def motors_on(self) -> bool:
        """The stepper drivers are enabled: off at power-on and after ``P``."""
        with self._lock:
            return self._motors_on

    @property
    def pen_down(self) -> bool:
        with self._lock:
            return self._pen_down

    @property
    def busy(self) -> bool:
        """A ``D`` is still to come: a procedure runs or is queued, or its line is unread."""
        with self._lock:
            return (
                self._procedure is not None
                or bool(self._pending)
                or any(isinstance(line, Command) for line in self._inbox)
            )

    @property
    def rejected(self) -> int:
        """Lines answered with ``E`` since power-on."""
        with self._lock:
            return self._decoder.rejected

    @property
    def command_log(self) -> tuple[ExecutedCommand, ...]:
        """The latest lines received, oldest first (a snapshot, safe from any thread)."""
        with self._lock:
            return tuple(self._command_log)

    @property
    def drill_log(self) -> tuple[DrilledHole, ...]:
        """The holes drilled, oldest first."""
        with self._lock:
            return tuple(self._drill_log)

    @property
    def pen_log(self) -> tuple[PenEvent, ...]:
        """Pen movements, oldest first."""
        with self._lock:
            return tuple(self._pen_log)

    @property
    def drawing(self) -> tuple[DrawnSegment, ...]:
        """What the pen drew, stroke by stroke, oldest first."""
        with self._lock:
            return tuple(self._drawing_log)

    @property
    def event_log(self) -> tuple[DrillEvent, ...]:
        """Commands received and done, holes and pen movements, in order (for ``--log``)."""
        with self._lock:
            return tuple(self._event_log)

    # -- the control cycle ---------------------------------------------------------

    def _now(self) -> float:
        return self._cycle_time(self._cycles) + self._into_cycle

    def _run_cycle(self) -> None:
        self._into_cycle = 0.0
        while self._inbox:
            self._accept(self._inbox.popleft())
        budget = self.config.control_cycle
        while True:
            if self._procedure is None and not self._start_next():
                break
            if self._step_left > budget + _EPS:
                self._advance(budget)
                self._step_left -= budget
                budget = 0.0
                break
            # The step ends inside this cycle: run exactly to its end, then go on.
            used = self._step_left
            self._advance(used)
            budget = max(budget - used, 0.0)
            self._next_step()
        if budget > 0:
            self._advance(budget)
        self._cycles += 1
        self._into_cycle = 0.0
        self._flush()

    def _advance(self, dt: float) -> None:
        for axis in self._axes:
            axis.advance(dt)
        self._into_cycle += dt

    def _accept(self, line: Command | Rejected) -> None:
        accepted = isinstance(line, Command)
        self._log(ExecutedCommand(self._now(), line, accepted))
        if isinstance(line, Rejected):
            self._reply(error_reply(line))
            return
        self._reply(Reply(ReplyKind.RECEIVED, line.letter))
        self._pending.append(line)

    def _start_next(self) -> bool:
        """Start the first queued procedure; False if none is waiting."""
        if not self._pending:
            return False
        self._current = self._pending.popleft()
        self._procedure = self._procedure_for(self._current)
        self._next_step()
        return True

    def _next_step(self) -> None:
        """Start the running procedure's next step, or finish it with ``D``."""
        assert self._procedure is not None
        try:
            self._step_left = next(self._procedure)
        except StopIteration:
            if self._current is None:  # the power-on homing: nobody to answer
                self._log(HomedAtPowerOn(self._now()))
                self._procedure = None
                self._step_left = 0.0
                return
            self._log(CommandDone(self._now(), self._current))
            self._reply(Reply(ReplyKind.DONE, self._current.letter))
            self._procedure = None
            self._current = None
            self._step_left = 0.0

    def _reply(self, reply: Reply) -> None:
        self._outbox.append(encode_reply(reply))

    def _flush(self) -> None:
        if not self._outbox:
            return
        data = b"".join(self._outbox)
        self._outbox.clear()
        self._send_to_host(data)

    def _log(self, event: DrillEvent) -> None:
        self._event_log.append(event)
        match event:
            case ExecutedCommand():
                self._command_log.append(event)
            case DrilledHole():
                self._drill_log.append(event)
            case PenEvent():
                self._pen_log.append(event)
            case DrawnSegment():
                self._drawing_log.append(event)

    # -- procedures ----------------------------------------------------------------

    def _procedure_for(self, command: Command) -> _Procedure:
        match command.letter:
            case "N":
                return self._home()
            case "X" | "Y":
                assert command.value is not None
                return self._move("XY".index(command.letter), command.value)
            case "V":
                return self._drill()
            case "K":
                return self._pen(down=True)
            case "Z":
                return self._pen(down=False)
            case "P":
                return self._park()
        raise AssertionError(f"no procedure for {command!r}")

    def _until_idle(self, index: int) -> float:
        """Seconds until the axis has surely stopped (its moves are never open-ended)."""
        left = self._axes[index].time_to_idle()
        assert left is not None
        return left + _SLOP if left > 0 else 0.0

    def _move(self, index: int, target: int) -> _Procedure:
        """Step the counter to ``target``; the carriage follows until a frame stops it.

        The original has one sensor per axis, at the home end, read only while homing
        ("Kazdy pohyb je ukoncen v jednom smeru cidlem"): a move past the far end of the
        travel runs the carriage into the frame, where it stalls while the firmware steps
        on, so the move takes every step's period and the counter ends ``lost`` microsteps
        past the carriage (FIDELITY S2-29).  Lost steps make later targets lie as well.
        """
        self._motors_on = True
        axis = self._axes[index]
        axis.start_speed = self._speeds[index]
        x0, y0, _ = self.positions
        # Where the frames are in the counter's frame: the far one at the physical end of
        # the travel, the home one behind the sensor at physical 0.
        offset = axis.position_um - axis.physical_um
        far = math.floor(self._switch_spans[index] + offset + 1e-9)
        home = math.ceil(offset - 1e-9)
        reach = min(max(target, home), far)
        axis.move_to(float(reach), self._speeds[index])
        yield self._until_idle(index)
        x1, y1, _ = self.positions  # where the pen got to: the frame stops it too
        lost = abs(target - reach)
        if lost:
            yield lost / self._speeds[index]  # the firmware steps on, the carriage stands
            axis.set_position(float(axis.microsteps + target - reach))
            end = "far" if target > reach else "home"
            self._log(StalledAtFrame(self._now(), "XY"[index], end, lost, axis.microsteps))
        if self._pen_down and (x1, y1) != (x0, y0):
            self._log(DrawnSegment(self._now(), x0, y0, x1, y1))

    def _home(self) -> _Procedure:
        self._motors_on = True
        for index in (0, 1):
            axis = self._axes[index]
            axis.start_speed = self._speeds[index]
            axis.home(self._speeds[index])  # to the switch, and off it until it opens
            yield self._until_idle(index)
            axis.move_to(float(self.config.zero_offsets[index]), self._speeds[index])
            yield self._until_idle(index)
            axis.set_position(0.0)
        self._homed = True

    def _drill(self) -> _Procedure:
        yield from self._z_down(hole=True)
        yield from self._z_up()

    def _z_down(self, *, hole: bool) -> _Procedure:
        """``Vrtat``'s first half (and all of ``Kresli``): down to the bottom, and the wait.

        ``hole``: a drill is in, so the bottom of the stroke makes a hole (logged there).
        """
        self._motors_on = True
        cfg = self.config
        z = self._axes[2]
        down = 1.0 / cfg.step_periods[2]
        z.start_speed = down
        # To the sensor, then the overtravel, a pause after every second microstep.
        bottom = cfg.drill_depth
        while (here := z.microsteps) < bottom:
            z.move_to(float(min(here + cfg.down_pause_every, bottom)), down)
            yield self._until_idle(2)
            if z.microsteps == bottom:
                break
            yield cfg.down_pause
        if hole:
            x, y, _ = self.positions
            self._log(DrilledHole(self._now(), x, y))
        if here < bottom and bottom - here == cfg.down_pause_every:
            yield cfg.down_pause  # the pause after the last pair of microsteps
        yield cfg.dwell

    def _z_up(self) -> _Procedure:
        """``Vrtat``'s second half (and all of ``Zvedni``): the return, and the wait after."""
        cfg = self.config
        z = self._axes[2]
        up = cfg.z_microsteps_per_step / cfg.step_periods[2]
        z.start_speed = up
        climb = cfg.return_full_steps * cfg.z_microsteps_per_step
        z.move_to(float(max(z.microsteps - climb, 0)), up)
        yield self._until_idle(2)
        yield cfg.after_wait

    def _pen(self, *, down: bool) -> _Procedure:
        if down:
            yield from self._z_down(hole=False)
        else:
            yield from self._z_up()
        self._pen_down = down
        x, y, _ = self.positions
        self._log(PenEvent(self._now(), down, x, y))

    def _park(self) -> _Procedure:
        yield from self._move(0, 0)
        yield from self._move(1, self.config.travel[1])
        self._motors_on = False
