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
from collections import deque

from protocol.clock import Clock
from protocol.drill.codec import (
    Command,
    CommandDecoder,
    Rejected,
    Reply,
    ReplyKind,
    encode_reply,
    error_reply,
)
from protocol.drill.timing import DrillTiming
from protocol.emulator.cycles import ControlCycles
from protocol.emulator.drill_config import DrillConfig as DrillConfig
from protocol.emulator.drill_events import CommandDone as CommandDone
from protocol.emulator.drill_events import DrawnSegment as DrawnSegment
from protocol.emulator.drill_events import DrilledHole as DrilledHole
from protocol.emulator.drill_events import DrillEvent as DrillEvent
from protocol.emulator.drill_events import ExecutedCommand as ExecutedCommand
from protocol.emulator.drill_events import HomedAtPowerOn as HomedAtPowerOn
from protocol.emulator.drill_events import PenEvent as PenEvent
from protocol.emulator.drill_events import StalledAtFrame as StalledAtFrame
from protocol.emulator.drill_events import event_log_line as event_log_line
from protocol.emulator.drill_procedures import DrillProcedures, Procedure
from protocol.mechanism import Axis, AxisLimits

#: Tolerance for comparing times built from float sums.
_EPS = 1e-9
#: Entries kept in each log, bounded for an emulator left running for days.
LOG_LENGTH = 10_000
#: The DrillConfig fields a DrillTiming sets.
_TIMED = frozenset(
    {"step_periods", "down_pause", "down_pause_every", "dwell", "after_wait", "return_full_steps"}
)
#: An acceleration high enough never to matter: speeds are jumped to anyway.
_NO_RAMP = 1e12


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
        self._procedure: Procedure | None = None
        self._current: Command | None = None
        self._step_left = 0.0
        #: Time already run into the present cycle (procedure steps end mid-cycle).
        self._into_cycle = 0.0
        #: Microsteps from the home sensor's edge to the far frame, X and Y.
        switch_spans = (
            cfg.travel[0] + cfg.zero_offsets[0] + 1,
            cfg.travel[1] + cfg.zero_offsets[1] + 1,
        )
        x = self._make_axis(switch_spans[0], cfg.power_on[0])
        y = self._make_axis(switch_spans[1], cfg.power_on[1])
        z = self._make_axis(2 * cfg.drill_depth, 0)
        self._axes = (x, y, z)
        #: What each command does to the axes, and what that leaves set (drill_procedures.py).
        self._procedures = DrillProcedures(self._axes, cfg, switch_spans, self._now, self._log)
        self._command_log: deque[ExecutedCommand] = deque(maxlen=LOG_LENGTH)
        self._drill_log: deque[DrilledHole] = deque(maxlen=LOG_LENGTH)
        self._pen_log: deque[PenEvent] = deque(maxlen=LOG_LENGTH)
        self._drawing_log: deque[DrawnSegment] = deque(maxlen=LOG_LENGTH)
        self._event_log: deque[DrillEvent] = deque(maxlen=LOG_LENGTH)
        if cfg.home_at_power_on:
            # Started now, run from the first control cycle on, like any procedure.
            self._procedure = self._procedures.home()
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
            self._procedures.set_config(self.config)

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
            return self._procedures.homed

    @property
    def motors_on(self) -> bool:
        """The stepper drivers are enabled: off at power-on and after ``P``."""
        with self._lock:
            return self._procedures.motors_on

    @property
    def pen_down(self) -> bool:
        with self._lock:
            return self._procedures.pen_down

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
        self._procedure = self._procedures.for_command(self._current)
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
