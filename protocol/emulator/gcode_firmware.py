"""Firmware of the G-code machines (plotters, string-art winder), emulated (docs/protocols.md §4).

It is the device side of the ``gcode`` dialect written from the contract and
GRBL 1.1's documented behaviour, so the station's streaming can be tested
against what makes character counting necessary: a receive buffer that
drops what does not fit, and a parser that takes a line out of it only
while the planner has room.  The event log (:attr:`GcodeFirmware.event_log`)
lets a test check what was drawn where, and that the host never had more
than ``rx_buffer - 1`` bytes unacknowledged.

The board powers up in its first control cycle, which ends with the banner;
bytes that arrive before it are lost, as on a board that resets when its
port is opened, so the banner always comes before any reply and a host may
take it as "the board has just (re)started, nothing it had is left".

How a byte travels:

- Real-time bytes (``?``, ``!``, ``~``, 0x18) are acted on the moment they
  arrive and never enter the receive buffer.  The status report goes out at
  the end of the next control cycle (several ``?`` before it make one
  report); hold, resume and reset take effect at once.
- Other bytes enter the ``rx_buffer``-byte receive buffer, which holds one
  byte less than its size (GRBL's ring buffer); bytes that do not fit are
  dropped and counted in :attr:`GcodeFirmware.overflows`.
- At the start of each control cycle the parser takes complete lines out of
  the buffer while the planner has a free block, and answers each at once:
  ``ok`` when its blocks are queued (a line that makes more blocks than
  there is room for, an arc, is answered when its last block is queued),
  ``error:<n>`` when refused.  So a full planner withholds the replies, and
  a host that counts characters sees its window close.  A machine that
  answers once the motion is done (``ok_when_done``, the CoreXY plotter's
  firmware: it executes a line, then prints ``OK``) parses the next line
  only after that answer.
- A line longer than ``max_line`` bytes is answered ``error:11`` (GRBL's
  line overflow) once its end arrives; its bytes leave the buffer as they
  come, so it cannot block the buffer.  A ``\\r`` is whitespace, not a line
  end, so ``\\r\\n`` is one line — except on a GRBL board (``grbl``), which
  reads as GRBL 1.1 does: ``\\r`` and ``\\n`` each end a line (an empty line is
  answered ``ok``), and spaces and comments are dropped as they arrive, so
  only the rest counts towards its 80-byte line (``error:11`` beyond 79).
- :attr:`GcodeFirmware.unacknowledged` counts the bytes received and kept
  whose line has not been answered yet; its maximum is kept.

Decisions the contract leaves open, made here:

- A soft reset stops at once where the tool is (no alarm: the position is
  kept), empties the planner and the receive buffer, resets the modes as
  GRBL does, lifts the pen and sends the banner.  An alarm survives it.
- An alarm (only the ``alarm`` control raises one) stops at once, lifts the
  pen and locks G-code out (``error:9``) until ``$X`` or ``$H``.
- ``$H`` goes to 0 on every axis at the rapid rate (state ``Home``) and is
  answered when queued; like ``$I`` and ``$$`` it needs the machine idle
  (``error:8``).  Unknown ``$`` commands are ``error:3``.  A GRBL board
  takes ``$N=value`` for its settings, idle or in alarm, and answers a bad
  one as GRBL 1.1h does (:mod:`~protocol.emulator.grbl_settings`, checked
  against grbl-sim): ``$10`` (status mask), ``$12``
  (arc tolerance), ``$11`` (junction deviation), ``$20`` (soft limits, off
  by default as in GRBL), ``$22`` (homing: off, ``$H`` is ``error:5``),
  ``$110…`` (rates, mm/min), ``$120…`` (accelerations, mm/s²) and
  ``$130…`` (travel, mm) act; the rest are kept and listed.  The planner
  uses each axis' rate and acceleration along a move's direction, as
  GRBL's does (the step-rate figures kept for the other firmwares are the
  least the settings allow).  ``$C`` toggles check mode
  (lines parsed and answered, nothing moves); leaving it resets the board.
- Status reports carry ``MPos`` (``WPos``, machine position minus the work
  offset, with ``$10`` bit 0 clear), ``FS`` and, with ``$10`` bit 1, ``Bf``
  (free planner blocks, free receive-buffer bytes, as GRBL counts them).  A
  GRBL board adds ``WCO:`` (its work offset: the active G54…G59 system's
  plus G92's, :mod:`~protocol.emulator.gcode_work_systems`) as GRBL 1.1
  does: in the first report after a reset or an offset change, then every
  10th report while idle and every 30th while running, holding or jogging;
  and ``Ov:`` (its feed, rapid and spindle overrides,
  :mod:`~protocol.emulator.gcode_overrides`) on GRBL's own schedule.  ``$#``
  lists the offsets (G54…G59 as stored, ``G10 L2``/``L20`` set them; G28 and
  G30 are 0).  (A difference: a ``G10`` naming a system not in use sends
  ``WCO:`` in the next report too; GRBL waits for its turn.)
- A GRBL board acts on the override bytes 0x90…0x97 at the start of the next
  control cycle, each kind once however often it came, as GRBL's real-time
  pass does; a change re-plans the queued moves at once.
- GRBL answers ``G4`` and ``G92``/``G92.1`` only once the motion before
  them is done (it synchronises its planner; ``G4`` then dwells before
  answering), and reads no line meanwhile; the GRBL board does the same.
- The emulated GRBL plotter is set ``$10=3``, ``$22=1`` (it has end
  switches); a fresh GRBL board has ``$10=1``, ``$22=0``.
"""

from __future__ import annotations

import json
from collections import deque
from dataclasses import replace
from typing import Any

from protocol.clock import Clock
from protocol.emulator import grbl_settings
from protocol.emulator.cycles import ControlCycles
from protocol.emulator.gcode_interpreter import Interpreter
from protocol.emulator.gcode_machine import (
    GcodeConfig,
    PenMapping,
    corexy_plotter_config,
    grbl_plotter_config,
    string_art_config,
)
from protocol.emulator.gcode_overrides import OverrideState
from protocol.emulator.gcode_planner import (
    Block,
    DriversOff,
    Dwell,
    HoldState,
    Junctions,
    Move,
    Pause,
    PenChange,
    Planner,
    SetOffset,
    SetPosition,
)
from protocol.emulator.servo_pwm import pulse_width_s
from protocol.gcode.codec import CYCLE_START, FEED_HOLD, JOG_CANCEL, SOFT_RESET, STATUS_QUERY
from protocol.gcode.words import Word, WordError, grbl_text, split_words, strip_comments

__all__ = [
    "LOG_LENGTH",
    "GcodeConfig",
    "GcodeEvent",
    "GcodeFirmware",
    "PenMapping",
    "corexy_plotter_config",
    "event_log_line",
    "grbl_plotter_config",
    "string_art_config",
]

#: Entries kept in the event log, bounded for an emulator left running for days.
LOG_LENGTH = 20_000

#: One event: ``{"t": seconds, "event": kind, ...}``, JSON-serialisable as it is.
GcodeEvent = dict[str, Any]

# GRBL's error codes the firmware itself gives (the parser's are in the interpreter).
INVALID_STATEMENT = 3
NOT_IDLE = 8
UNDEFINED_FEED = 22
#: GRBL 1.1: a ``$J=`` line with a word a jog may not have (error:16).
INVALID_JOG = 16
#: The G words a jog line may carry (GRBL's jogging documentation); F is required.
_JOG_G_WORDS = frozenset({20.0, 21.0, 53.0, 90.0, 91.0})
GCODE_LOCKED = 9
LINE_OVERFLOW = 11
SETTING_DISABLED = 5
#: GRBL 1.1's line buffer (LINE_BUFFER_SIZE): at most 79 characters kept per line.
GRBL_LINE = 80
#: GRBL 1.1h's default settings, those the emulated board does not derive from its machine.
_GRBL_DEFAULTS: dict[int, float] = {
    0: 10, 1: 25, 2: 0, 3: 0, 4: 0, 5: 0, 6: 0, 10: 1, 11: 0.010, 12: 0.002, 13: 0,
    20: 0, 21: 0, 22: 0, 23: 0, 24: 25.0, 25: 500.0, 26: 250, 27: 1.0, 30: 1000, 31: 0, 32: 0,
}  # fmt: skip

_LINE_END = 0x0A
#: Bytes of an arriving line the ``line`` event keeps: a host that never ends its line
#: cannot grow the log's memory without bound (the parser has refused such a line anyway).
_ARRIVING_KEPT = 1024
#: What follows ``$`` in GRBL 1.1's own commands; anything else is read as ``$N=value``.
_GRBL_COMMAND_LETTERS = "$#CGHIJNRSX"
_HELP = "[HLP:$$ $# $G $I $H $X ~ ! ? ctrl-x]"
#: GRBL 1.1's REPORT_WCO_REFRESH_BUSY_COUNT and _IDLE_COUNT: reports between two ``WCO:``.
WCO_REFRESH_BUSY = 30
WCO_REFRESH_IDLE = 10


def grbl_line(raw: bytes) -> str | None:
    """What GRBL 1.1 keeps of a received line, upper-cased; None when it overflows its buffer.

    Whitespace and control characters, ``/`` and comments (``(...)`` and ``;``
    to the end) are dropped as they arrive and never count towards the line.
    """
    text = raw.decode("latin-1").replace("\r", "\n").split("\n", 1)[0]
    kept = grbl_text(text)
    return kept if len(kept) <= GRBL_LINE - 1 else None


def _axis_values(values: tuple[float, ...]) -> str:
    """GRBL's comma-separated axis values, three decimals (mm)."""
    return ",".join(f"{round(v, 3) + 0.0:.3f}" for v in values)


def event_log_line(event: GcodeEvent) -> str:
    """One line of the emulator's ``--log`` file: the event as compact JSON."""
    return json.dumps(event, separators=(",", ":"))


class GcodeFirmware(ControlCycles):
    """A GRBL-like board: receive buffer, parser, planner, pen, on fixed control cycles.

    Thread-safe: the loopback's ticker thread runs cycles while the GUI
    thread reads the position and the log, so every public method and
    property takes the same re-entrant lock.
    """

    def __init__(self, clock: Clock, config: GcodeConfig | None = None) -> None:
        self.config = config if config is not None else grbl_plotter_config()
        super().__init__(clock, self.config.control_cycle)
        origin = (0.0,) * len(self.config.axes)
        # GRBL's planner keeps one block of its ring free, as its receive buffer does a byte.
        self._planner = Planner(origin, self.config.planner_blocks - 1, self._junctions())
        self._interpreter = Interpreter(self.config, origin)
        self._rx = bytearray()
        self._rx_capacity = self.config.rx_buffer - 1
        #: Bytes of a too-long line already taken out of the buffer, awaiting its end.
        self._overlong = 0
        #: Blocks of the line being queued that did not fit yet, and its answer.
        self._pending: deque[Block] = deque()
        self._pending_line: tuple[int, str] | None = None
        #: The pending line synchronises (GRBL's G4, G92): answered once the planner is empty.
        self._pending_sync = False
        #: GRBL's G92 work offset in effect (machine minus work position), and the status
        #: reports left before the next ``WCO:`` field (0: the next one carries it).
        self._work_offset = origin
        self._wco_countdown = 0
        #: ``ok_when_done``: the line whose blocks run, answered when the planner is empty.
        self._running_line: tuple[int, str] | None = None
        self._status_wanted = False
        self._alarm: int | None = None
        self._pen_down = False
        self._spindle = 0.0
        self._overflows = 0
        self._unacked = 0
        self._max_unacked = 0
        self._outbox: list[bytes] = []
        self._events: deque[GcodeEvent] = deque(maxlen=LOG_LENGTH)
        self._booted = False
        self._lost_booting = 0
        #: 0x85 came during a jog: brake, then drop the jog's blocks once it stands.
        self._jog_cancelling = False
        #: Axes whose drivers ``M18`` switched off (a move switches them on again).
        self._drivers_off: set[str] = set()
        #: The white button was pressed once: the next press sets the zero (S0-24).
        self._white_pressed = False
        #: GRBL's feed and rapid overrides (a GRBL board only: the others ignore the bytes).
        self._overrides = OverrideState()
        #: GRBL's settings ($$), kept only on a GRBL board; its check mode ($C).
        self._settings_table = self._initial_settings()
        self._check_mode = False
        self._reset_after_answer = False
        self._raw_text = ""
        #: A GRBL board's line so far, past what the receive buffer holds (it reads on).
        self._partial = bytearray()
        #: The line arriving, every byte the receive buffer took since the last line end: the
        #: ``line`` event logs it whole, however many reads it came in.
        self._arriving = bytearray()
        self._send_banner()

    # -- EmulatedDevice --------------------------------------------------------------------

    def receive(self, data: bytes) -> None:
        with self._lock:
            if not self._booted:
                self._lost_booting += len(data)
                return
            for byte in data:
                if byte == STATUS_QUERY[0]:
                    self._status_wanted = True
                elif byte == FEED_HOLD[0]:
                    self.feed_hold()
                elif byte == CYCLE_START[0]:
                    self.cycle_start()
                elif byte == SOFT_RESET[0]:
                    self.soft_reset()
                elif byte == JOG_CANCEL[0] and self.config.jogging:
                    self.jog_cancel()
                elif byte >= 0x80 and self.config.grbl:
                    self._overrides.received(byte)  # never in a line (gcode_overrides.py)
                elif len(self._rx) >= self._rx_capacity:
                    self._overflows += 1
                else:
                    self._rx.append(byte)
                    if len(self._arriving) < _ARRIVING_KEPT:
                        self._arriving.append(byte)
                    self._unacked += 1
                    self._max_unacked = max(self._max_unacked, self._unacked)
                    if byte == _LINE_END or (byte == 0x0D and self.config.grbl):
                        self._log_arrival()

    # -- the machine's own controls, and the real-time commands ---------------------------

    def feed_hold(self) -> None:
        """``!``: brake to a stop and hold; ignored in alarm and while homing."""
        with self._lock:
            if self._alarm is not None or self.state == "Home":
                return
            if self._planner.hold_state is HoldState.RUNNING:
                self._planner.hold()
                self._log("hold", pos=self._where())

    def cycle_start(self) -> None:
        """``~``: resume from a completed hold or an ``M0``."""
        with self._lock:
            if self._alarm is None and self._planner.resume():
                self._log("resume", pos=self._where())

    def jog_cancel(self) -> None:
        """0x85: a jog brakes to a stop and the jog blocks queued behind it are dropped."""
        with self._lock:
            if self.state == "Jog" and not self._jog_cancelling:
                self._jog_cancelling = True
                self._planner.hold()
                self._log("jog cancel", pos=self._where())

    def _finish_jog_cancel(self) -> None:
        """The cancelled jog stands: forget its blocks, keep the position, back to Idle."""
        if not self._jog_cancelling or self._planner.hold_state is not HoldState.HELD:
            return
        self._jog_cancelling = False
        if self._pending_line is not None:  # a jog line half queued is answered all the same
            self._answer(self.config.reply_ok, *self._pending_line)
        self._planner.stop()
        self._pending.clear()
        self._pending_line = None
        self._interpreter.position = self._planner.position()
        self._log("jog cancelled", pos=self._where())

    def soft_reset(self) -> None:
        """0x18: stop at once, forget every line and block, keep the position, say the banner."""
        with self._lock:
            self._stop()
            self._jog_cancelling = False
            self._rx.clear()
            self._partial.clear()
            self._arriving.clear()
            self._check_mode = False
            self._overlong = 0
            self._unacked = 0
            self._status_wanted = False
            self._interpreter.reset(self._planner.position())
            self._work_offset = self._interpreter.work_offset()
            self._wco_countdown = 0
            self._overrides.reset()
            self._planner.set_overrides(100, 100)
            self._log("reset", pos=self._where())
            self._send_banner()
            if self._alarm is not None:
                self._send_line("[MSG:'$H'|'$X' to unlock]")

    def white_button(self) -> str:
        """The winder's white button (FIDELITY S0-24); returns what the press did.

        "první stisknutí tlačítka … vypne udržovací proud … druhé stisknutí …
        nastaví současnou pozici jako nulovou": the first press switches every
        driver's holding current off, so the operator can turn the base and
        move the needle by hand (:meth:`turn_by_hand`); the second declares
        where they stand :attr:`GcodeConfig.hand_zero` ("nulovou pozici
        lineárního pojezdu, která je nastavena na polomer_matrice": X is the
        board radius).  A press while the machine runs or holds a program does
        nothing (the original reads its buttons only while it waits), nor on
        a machine without the buttons.
        """
        with self._lock:
            zero = self.config.hand_zero
            if zero is None or self.state != "Idle" or self._pending_line is not None:
                self._log("white button ignored")
                return "ignored"
            if not self._white_pressed:
                self._white_pressed = True
                self._drivers_off.update(self.config.axes)
                self._log("drivers off", axes="".join(self.config.axes), by="white button")
                return "drivers off"
            self._white_pressed = False
            self._planner.place(zero)
            self._interpreter.position = zero
            self._log("setpos", pos=self._where(zero), by="white button")
            return "zero set"

    def turn_by_hand(self, axis: str, delta: float) -> bool:
        """The operator turns an axis whose driver is off by ``delta`` of its units.

        A driver that holds resists: only an axis with its driver off turns
        (False otherwise), and a linear one only within its travel, where its
        mechanics end.  The emulator keeps one position for the mechanism and
        the step counter, so its reports follow the hand; the original's
        counter does not see a shaft turned by hand, which is why it is zeroed
        afterwards (and so is the emulator, by the second press or ``G92``).
        """
        with self._lock:
            if axis not in self._drivers_off or self.state != "Idle":
                return False
            index = self.config.index(axis)
            position = list(self._planner.position())
            target = position[index] + delta
            limits = self.config.travel[index]
            if limits is not None:
                target = min(max(target, limits[0]), limits[1])
            position[index] = target
            self._planner.place(tuple(position))
            self._interpreter.position = tuple(position)
            self._log("by hand", pos=self._where())
            return True

    def trigger_alarm(self, code: int = 1) -> None:
        """Enter the alarm state (``ALARM:<code>``), as a limit switch would."""
        with self._lock:
            for line in (self._pending_line, self._running_line):
                if line is not None:
                    self._answer(f"{self.config.reply_error}:{GCODE_LOCKED}", *line)
            self._stop()
            self._interpreter.position = self._planner.position()
            self._interpreter.pen_down = False
            self._interpreter.spindle_level = 0.0
            self._alarm = code
            self._send_line(f"ALARM:{code}")
            self._log("alarm", code=code, pos=self._where())

    # -- introspection ---------------------------------------------------------------------

    def position(self) -> dict[str, float]:
        """Where the tool is now, per axis, in the machine's units."""
        with self._lock:
            return dict(zip(self.config.axes, self._planner.position(), strict=True))

    def work_offset(self) -> dict[str, float]:
        """GRBL's G92 offset in effect (machine minus work position); 0 on the other firmwares."""
        with self._lock:
            return dict(zip(self.config.axes, self._work_offset, strict=True))

    @property
    def overrides(self) -> tuple[int, int]:
        """GRBL's feed and rapid overrides in force, percent (100, 100 elsewhere)."""
        with self._lock:
            return self._overrides.values.feed, self._overrides.values.rapid

    def motor_counts(self) -> tuple[int, ...]:
        """Each motor's step counter: CoreXY (a, b, z), otherwise one per axis."""
        with self._lock:
            return self.config.motor_counts(self._planner.position())

    @property
    def pen_down(self) -> bool:
        with self._lock:
            return self._pen_down

    @property
    def state(self) -> str:
        """``Idle``, ``Run``, ``Hold``, ``Home`` or ``Alarm`` (without Hold's substate)."""
        with self._lock:
            if self._alarm is not None:
                return "Alarm"
            if self._check_mode:
                return "Check"
            current = self._planner.current
            jogging = isinstance(current, Move) and current.kind == "jog"
            if self._jog_cancelling or (jogging and self._planner.hold_state is HoldState.RUNNING):
                return "Jog"
            if self._planner.hold_state is not HoldState.RUNNING:
                return "Hold"
            if isinstance(current, Move) and current.kind == "home":
                return "Home"
            busy = len(self._planner) or self._pending or self._running_line
            return "Run" if busy else "Idle"

    @property
    def alarm(self) -> int | None:
        """The alarm code while in alarm."""
        with self._lock:
            return self._alarm

    @property
    def busy(self) -> bool:
        """A line waits to be parsed or a block to be executed."""
        with self._lock:
            return b"\n" in self._rx or bool(len(self._planner) or self._pending)

    @property
    def overflows(self) -> int:
        """Bytes dropped because the receive buffer was full (a correct host causes none)."""
        with self._lock:
            return self._overflows

    @property
    def unacknowledged(self) -> int:
        """Bytes received whose line has not been answered yet."""
        with self._lock:
            return self._unacked

    @property
    def max_unacknowledged(self) -> int:
        with self._lock:
            return self._max_unacked

    @property
    def planner_free(self) -> int:
        with self._lock:
            return self._planner.free

    @property
    def step_rate(self) -> float:
        """Top step rate of the motors, steps/s (``M98`` sets it on the plotter)."""
        with self._lock:
            return self._interpreter.step_rate

    @property
    def servo_level(self) -> float | None:
        """The last ``M99`` level, if any."""
        with self._lock:
            return self._interpreter.servo_level

    @property
    def servo_pulse_s(self) -> float | None:
        """The pen servo's pulse, seconds, at the last ``M99`` level (50 Hz PWM, S1-11)."""
        with self._lock:
            level = self._interpreter.servo_level
        return None if level is None else pulse_width_s(level)

    @property
    def drivers_off(self) -> frozenset[str]:
        """The axes whose drivers are off (``M18``) until a move of that axis."""
        with self._lock:
            return frozenset(self._drivers_off)

    @property
    def event_log(self) -> tuple[GcodeEvent, ...]:
        """Lines, replies, moves, pen changes, dwells, holds and resets, in order (``--log``)."""
        with self._lock:
            return tuple(self._events)

    def status_report(self) -> str:
        """What ``?`` answers now, ``<Run|MPos:1.000,2.000,0.000|FS:600,0>``."""
        with self._lock:
            state = self.state
            hold = self._planner.hold_state
            if state == "Hold":
                state += ":0" if hold is HoldState.HELD else ":1"
            position = self._planner.position()
            mask = self.config.status_mask
            kind = "MPos" if mask & 1 else "WPos"
            if not mask & 1:
                position = tuple(p - o for p, o in zip(position, self._work_offset, strict=True))
            where = _axis_values(position)
            feed = self._planner.feed()
            free_rx = self.config.rx_buffer - len(self._rx)
            buffers = f"|Bf:{self._planner.free},{free_rx}" if mask & 2 else ""
            wco = ""
            if self.config.grbl:
                busy = state.split(":")[0] in ("Run", "Hold", "Home", "Jog")
                if self._wco_countdown > 0:
                    self._wco_countdown -= 1
                else:
                    self._wco_countdown = (WCO_REFRESH_BUSY if busy else WCO_REFRESH_IDLE) - 1
                    wco = "|WCO:" + _axis_values(self._work_offset)
                    self._overrides.wco_reported()
                wco += self._overrides.report_field(busy)
            return f"<{state}|{kind}:{where}{buffers}|FS:{feed:.0f},{self._spindle:.0f}{wco}>"

    # -- the control cycle -----------------------------------------------------------------

    def _overrides_changed(self, t: float | None = None) -> None:
        values = self._overrides.values
        self._planner.set_overrides(values.feed, values.rapid)
        self._log("override", t, feed=values.feed, rapid=values.rapid)

    def _run_cycle(self) -> None:
        if self._overrides.run_pass():  # GRBL's real-time pass acts on the bytes received
            self._overrides_changed()
        self._take_lines()
        self._planner.run(self.config.control_cycle, self._block_done)
        self._finish_jog_cancel()
        if self._status_wanted:
            self._status_wanted = False
            self._send_line(self.status_report())
        self._cycles += 1
        if not self._booted:
            self._booted = True
            self._log("boot", lost=self._lost_booting)
        self._flush()

    def _take_lines(self, t: float | None = None) -> None:
        """Parse waiting lines into free planner slots (``t``: mid-cycle, as a block ends).

        GRBL parses the next line as soon as its step-segment preparation frees a
        planner slot, not once per control cycle: with blocks shorter than a
        cycle (0.1 mm at 50 mm/s is 2 ms) reading only at the cycle's start left
        its look-ahead 2 or 3 blocks short, and 1500 x 0.1 mm ran 6 % longer than
        on grbl-sim (G7-11).  Mid-cycle, a ``$`` line waits for the cycle's start
        (it may reset the board or stop the planner that is running).
        """
        if self._jog_cancelling:
            # GRBL reads no line while a cancelled jog brakes (its suspend loop): a jog line
            # that came behind the 0x85 waits, then runs as a new jog.
            return
        when = self.time if t is None else t
        self._queue_pending(when)
        while not self._pending and self._planner.free > 0 and self._running_line is None:
            if t is not None and bytes(self._partial + self._rx).lstrip()[:1] == b"$":
                return
            line = self._next_line()
            if line is None:
                return
            self._execute(*line, t=t)

    def _next_line(self) -> tuple[int, bytes | None] | None:
        """The next complete line and its length; None as the line of a too-long one."""
        if self.config.grbl:
            return self._next_grbl_line()
        end = self._rx.find(_LINE_END)
        if end < 0:
            if len(self._rx) >= self.config.max_line:
                # No line end within a line's length: it overflows, and it must not
                # hold the buffer hostage while the rest of it comes.
                self._overlong += len(self._rx)
                self._rx.clear()
            return None
        raw = bytes(self._rx[: end + 1])
        del self._rx[: end + 1]
        if self._overlong:
            length = self._overlong + len(raw)
            self._overlong = 0
            return length, None
        return len(raw), raw

    def _next_grbl_line(self) -> tuple[int, bytes | None] | None:
        """GRBL 1.1's reading: CR or LF ends a line; spaces and comments never count."""
        ends = [i for i in (self._rx.find(b"\n"), self._rx.find(b"\r")) if i >= 0]
        if not ends:
            # GRBL reads its buffer byte by byte into the line: a long line never blocks it.
            self._partial += self._rx
            self._rx.clear()
            return None
        end = min(ends)
        raw = bytes(self._partial + self._rx[: end + 1])
        del self._rx[: end + 1]
        self._partial.clear()
        line = grbl_line(raw)
        self._raw_text = raw.decode("ascii", errors="replace").strip()  # for the log
        return len(raw), (None if line is None else line.encode("ascii", "replace"))

    def _execute(self, length: int, raw: bytes | None, t: float | None = None) -> None:
        text = "" if raw is None else raw.decode("ascii", errors="replace").strip()
        result: list[Block] | int
        if self.config.grbl and raw is None:
            result = LINE_OVERFLOW
        elif self.config.grbl and not text:
            result = []  # an empty or comment line: ok, for syncing
        elif raw is None or (length > self.config.max_line and not self.config.grbl):
            result = LINE_OVERFLOW
        elif text.startswith("$"):
            result = self._system(text.replace(" ", "").upper())
        else:
            result = self._gcode(text)
        if self.config.grbl:
            text = self._raw_text  # the log shows the line as sent
        if isinstance(result, int):
            self._answer(f"{self.config.reply_error}:{result}", length, text, t)
            return
        self._pending.extend(result)
        self._pending_line = (length, text)
        self._pending_sync = self.config.grbl and any(
            isinstance(b, (Dwell, SetOffset)) for b in result
        )
        self._queue_pending(self.time if t is None else t)
        if self._reset_after_answer:
            self._reset_after_answer = False
            self.soft_reset()

    def _gcode(self, text: str) -> list[Block] | int:
        body = strip_comments(text).strip()
        if not body:
            return []  # GRBL answers an empty or comment line ok, for syncing
        if self._alarm is not None:
            return GCODE_LOCKED
        words = split_words(body)
        if isinstance(words, WordError):
            return words.code
        result = self._interpreter.execute(words)
        return [] if self._check_mode and not isinstance(result, int) else result

    def _system(self, command: str) -> list[Block] | int:
        """A ``$`` line; feedback lines go out before its ``ok``."""
        idle = self.state in ("Idle", "Alarm")
        if command == "$":
            self._send_line(_HELP)
        elif command == "$$":
            if self.state in ("Run", "Hold", "Home"):
                return NOT_IDLE
            for line in self._settings():
                self._send_line(line)
        elif command == "$G":
            self._send_line(self._interpreter.modes())
        elif command == "$#" and self.config.grbl:
            zeros = _axis_values((0.0,) * len(self.config.axes))
            for number, stored in enumerate(self._interpreter.systems.stored):
                self._send_line(f"[G{54 + number}:{_axis_values(stored)}]")
            for name in ("G28", "G30"):
                self._send_line(f"[{name}:{zeros}]")
            self._send_line(f"[G92:{_axis_values(self._interpreter.offset)}]")
            self._send_line("[TLO:0.000]")
            self._send_line(f"[PRB:{zeros}:0]")
        elif command == "$I":
            if not idle:
                return NOT_IDLE
            self._send_line("[VER:1.1h.20190825:StepDeck emulator]")
            self._send_line(f"[OPT:V,{self._planner.capacity},{self.config.rx_buffer}]")
        elif command.startswith("$J=") and self.config.jogging:
            return self._jog(command[3:])
        elif command == "$X":
            if self._alarm is not None:
                self._alarm = None
                self._send_line("[MSG:Caution: Unlocked]")
                self._log("unlock")
        elif command == "$H":
            if not self.config.homing:
                return SETTING_DISABLED
            if not idle:
                return NOT_IDLE
            self._alarm = None
            start = self._interpreter.position
            home = (0.0,) * len(start)
            self._interpreter.position = home
            return [] if start == home else [self._interpreter.move(start, home, "home", None)]
        elif command == "$C" and self.config.grbl:
            return self._toggle_check_mode()
        elif self.config.grbl and command[1:2] and command[1:2] not in _GRBL_COMMAND_LETTERS:
            return self._set(command)
        else:
            return INVALID_STATEMENT
        return []

    def _toggle_check_mode(self) -> list[Block] | int:
        """``$C``: parse without moving; leaving check mode resets the board, as GRBL does."""
        if self._check_mode:
            self._check_mode = False
            self._send_line("[MSG:Disabled]")
            self._reset_after_answer = True
        elif self.state != "Idle":
            return NOT_IDLE
        else:
            self._check_mode = True
            self._send_line("[MSG:Enabled]")
        return []

    def _set(self, line: str) -> list[Block] | int:
        """``$N=value``: GRBL's settings (:mod:`~protocol.emulator.grbl_settings`); those that
        shape the machine act at once."""
        code = grbl_settings.store(self._settings_table, line, idle=self.state in ("Idle", "Alarm"))
        if code:
            return code
        self._apply_settings()
        return []

    def _initial_settings(self) -> dict[int, float]:
        if not self.config.grbl:
            return {}
        cfg = self.config
        table = dict(_GRBL_DEFAULTS)
        table.update({10: cfg.status_mask, 12: cfg.arc_tolerance})
        if cfg.junction_deviation is not None:
            table[11] = cfg.junction_deviation
        table.update({20: float(cfg.soft_limits), 22: float(cfg.homing)})
        for i, steps in enumerate(cfg.steps_per_unit):
            limits = cfg.travel[i]
            table[100 + i] = steps
            table[110 + i] = cfg.rates()[i] * 60.0
            table[120 + i] = cfg.accelerations()[i]
            table[130 + i] = 0.0 if limits is None else limits[1] - limits[0]
        return table

    def _apply_settings(self) -> None:
        table, cfg = self._settings_table, self.config
        count = len(cfg.axes)
        steps = tuple(table[100 + i] or cfg.steps_per_unit[i] for i in range(count))
        rate = min(table[110 + i] * s / 60.0 for i, s in enumerate(steps))
        acceleration = min(table[120 + i] * s for i, s in enumerate(steps))
        travel = tuple(
            None
            if cfg.travel[i] is None
            else (0.0, table[130 + i])
            if table[130 + i] > 0
            else cfg.travel[i]
            for i in range(count)
        )
        self.config = replace(
            cfg,
            steps_per_unit=steps,
            max_rate=rate if rate > 0 else cfg.max_rate,
            acceleration=acceleration if acceleration > 0 else cfg.acceleration,
            travel=travel,
            status_mask=int(table[10]),
            arc_tolerance=table[12] or cfg.arc_tolerance,
            soft_limits=bool(table[20]),
            homing=bool(table[22]),
            junction_deviation=None if cfg.junction_deviation is None else table[11],
            axis_rates=tuple(
                table[110 + i] / 60.0 if table[110 + i] > 0 else cfg.rates()[i]
                for i in range(count)
            ),
            axis_accelerations=tuple(
                table[120 + i] if table[120 + i] > 0 else cfg.accelerations()[i]
                for i in range(count)
            ),
        )
        self._planner.junctions = self._junctions()
        self._interpreter.config = self.config
        self._interpreter.step_rate = self.config.max_rate

    def _junctions(self) -> Junctions | None:
        """GRBL's planning settings, or None on a firmware whose moves start and end at rest."""
        cfg = self.config
        if cfg.junction_deviation is None:
            return None
        return Junctions(cfg.junction_deviation, cfg.accelerations())

    def _jog(self, body: str) -> list[Block] | int:
        """``$J=``: a move run as a jog, which leaves the parser's modal state as it was.

        Only G20/G21, G90/G91 and G53 may stand in it, and F is required; it is
        taken while idle or jogging, and its blocks report the ``Jog`` state.
        """
        if self.state not in ("Idle", "Jog"):
            return NOT_IDLE
        words = split_words(body)
        if isinstance(words, WordError):
            return words.code
        if any(w.letter == "G" and w.value not in _JOG_G_WORDS for w in words):
            return INVALID_JOG
        if any(w.letter not in ("G", "F", *self.config.axes) for w in words):
            return INVALID_JOG
        if not any(w.letter == "F" for w in words):
            return UNDEFINED_FEED
        saved = replace(self._interpreter.modal)
        result = self._interpreter.execute([Word("G", 1.0, "G1"), *words])
        self._interpreter.modal = saved
        if isinstance(result, int):
            return result
        return [replace(b, kind="jog") if isinstance(b, Move) else b for b in result]

    def _settings(self) -> list[str]:
        """``$$``: a few GRBL settings, per axis in the machine's axis order; all on GRBL."""
        if self._settings_table:
            return grbl_settings.setting_lines(self._settings_table)
        cfg = self.config
        lines = [f"$12={cfg.arc_tolerance:.3f}", "$13=0", "$20=1", "$22=1"]
        for group, values in (
            (100, cfg.steps_per_unit),
            (110, [cfg.max_rate / s * 60.0 for s in cfg.steps_per_unit]),
            (120, [cfg.acceleration / s for s in cfg.steps_per_unit]),
            (130, [0.0 if t is None else t[1] - t[0] for t in cfg.travel]),
        ):
            lines += [f"${group + i}={v:.3f}" for i, v in enumerate(values)]
        return lines

    def _queue_pending(self, t: float) -> None:
        """Move waiting blocks into free planner slots; answer their line once all are in."""
        while self._pending and self._planner.free > 0:
            self._planner.push(self._pending.popleft())
        if not self._pending and self._pending_line is not None:
            length, text = self._pending_line
            self._pending_line = None
            if (self.config.ok_when_done or self._pending_sync) and len(self._planner):
                self._running_line = (length, text)  # OK once its motion is done
            else:
                self._answer(self.config.reply_ok, length, text, t)

    def _block_done(self, block: Block, into: float) -> None:
        t = self.time + into
        match block:
            case Move():
                moved = {
                    axis
                    for axis, a, b in zip(self.config.axes, block.start, block.end, strict=True)
                    if a != b
                }
                if moved & self._drivers_off:
                    self._log("drivers on", t, axes="".join(sorted(moved & self._drivers_off)))
                    self._drivers_off -= moved
                self._log(
                    "move", t, kind=block.kind, pos=self._where(block.end), pen=self._pen_down
                )
            case DriversOff():
                names = [self.config.axes[i] for i in block.axes]
                self._drivers_off.update(names)
                self._log("drivers off", t, axes="".join(names))
            case PenChange():
                self._set_pen(block.down, block.spindle, t)
            case Dwell():
                self._log("dwell", t, seconds=block.seconds)
            case Pause():
                self._log("pause", t)
            case SetPosition():
                self._log("setpos", t, pos=self._where(block.position))
            case SetOffset():
                if block.program_end and self._overrides.reset():
                    self._overrides_changed(t)
                self._work_offset = block.offset
                self._wco_countdown = 0  # GRBL: the next report carries WCO
                self._log("offset", t, offset=self._where(block.offset))
        if self._running_line is not None and not len(self._planner):
            length, text = self._running_line
            self._running_line = None
            self._answer(self.config.reply_ok, length, text, t)
        if self.config.grbl:
            self._take_lines(t)
        else:
            self._queue_pending(t)

    def _stop(self) -> None:
        """Stop every motion at once and forget the queued blocks; lift the pen."""
        self._planner.stop()
        self._pending.clear()
        self._pending_line = None
        self._running_line = None
        self._set_pen(False, 0.0, self.time)

    def _set_pen(self, down: bool, spindle: float, t: float) -> None:
        self._spindle = spindle
        if down != self._pen_down:
            self._pen_down = down
            self._log("pen", t, down=down, pos=self._where())

    # -- replies and the log ------------------------------------------------------------------

    def _answer(self, reply: str, length: int, line: str, t: float | None = None) -> None:
        self._send_line(reply)
        self._unacked = max(self._unacked - length, 0)
        self._log("reply", t, text=reply, line=line)

    def _send_line(self, text: str) -> None:
        self._outbox.append(text.encode("ascii") + b"\r\n")

    def _send_banner(self) -> None:
        self._outbox.append(b"\r\n" + self.config.banner.encode("ascii") + b"\r\n")

    def _flush(self) -> None:
        if not self._outbox:
            return
        data = b"".join(self._outbox)
        self._outbox.clear()
        self._send_to_host(data)

    def _where(self, position: tuple[float, ...] | None = None) -> dict[str, float]:
        where = self._planner.position() if position is None else position
        return {axis: round(p, 6) + 0.0 for axis, p in zip(self.config.axes, where, strict=True)}

    def _log_arrival(self) -> None:
        """Log the line that has just ended, whole: all the bytes kept since the last line end.

        Looking back in the receive buffer would find only the last read's piece once the
        parser has taken the line's head out of it (GRBL reads on into its line buffer).
        """
        text = bytes(self._arriving[:-1]).decode("ascii", errors="replace").strip()
        self._arriving.clear()
        self._log("line", text=text, unacknowledged=self._unacked)

    def _log(self, event: str, t: float | None = None, **fields: Any) -> None:
        when = self.time if t is None else t
        self._events.append({"t": round(when, 6), "event": event, **fields})
