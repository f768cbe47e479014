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

from protocol.clock import Clock
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
    Move,
    Pause,
    PenChange,
    Planner,
    SetOffset,
    SetPosition,
)
from protocol.emulator.gcode_readouts import GcodeEvent
from protocol.emulator.gcode_system_commands import (
    CRITICAL_ALARMS,
    RESETTING_ALARMS,
    GcodeSystemCommands,
)
from protocol.gcode.codec import CYCLE_START, FEED_HOLD, JOG_CANCEL, SOFT_RESET, STATUS_QUERY
from protocol.gcode.words import WordError, grbl_text, split_words, strip_comments

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

# GRBL's error codes the firmware itself gives (the parser's are in the interpreter;
# the ``$`` commands' in :mod:`~protocol.emulator.gcode_system_commands`).
GCODE_LOCKED = 9
LINE_OVERFLOW = 11
#: GRBL 1.1's line buffer (LINE_BUFFER_SIZE): at most 79 characters kept per line.
GRBL_LINE = 80

_LINE_END = 0x0A
#: Bytes of an arriving line the ``line`` event keeps: a host that never ends its line
#: cannot grow the log's memory without bound (the parser has refused such a line anyway).
_ARRIVING_KEPT = 1024


def grbl_line(raw: bytes) -> str | None:
    """What GRBL 1.1 keeps of a received line, upper-cased; None when it overflows its buffer.

    Whitespace and control characters, ``/`` and comments (``(...)`` and ``;``
    to the end) are dropped as they arrive and never count towards the line.
    """
    text = raw.decode("latin-1").replace("\r", "\n").split("\n", 1)[0]
    kept = grbl_text(text)
    return kept if len(kept) <= GRBL_LINE - 1 else None


def event_log_line(event: GcodeEvent) -> str:
    """One line of the emulator's ``--log`` file: the event as compact JSON."""
    return json.dumps(event, separators=(",", ":"))


class GcodeFirmware(GcodeSystemCommands):
    """A GRBL-like board: receive buffer, parser, planner, pen, on fixed control cycles.

    Thread-safe: the loopback's ticker thread runs cycles while the GUI
    thread reads the position and the log, so every public method and
    property takes the same re-entrant lock.  Its readouts, replies and log
    are in :class:`~protocol.emulator.gcode_readouts.GcodeReadouts`, its ``$``
    commands in :class:`~protocol.emulator.gcode_system_commands.GcodeSystemCommands`.
    """

    def __init__(self, clock: Clock, config: GcodeConfig | None = None) -> None:
        self.config = config if config is not None else grbl_plotter_config()
        self._factory_config = self.config
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
        #: GRBL answers a pen line once its spindle change ran, not its motion (None: at the end).
        self._sync_until: Block | None = None
        #: GRBL's G92 work offset in effect (machine minus work position), and the status
        #: reports left before the next ``WCO:`` field (0: the next one carries it).
        self._work_offset = origin
        self._wco_countdown = 0
        #: ``ok_when_done``: the line whose blocks run, answered when the planner is empty.
        self._running_line: tuple[int, str] | None = None
        self._status_wanted = False
        self._alarm: int | None = None
        #: After a hard or soft limit GRBL waits in its critical-event loop for a 0x18 (protocol.c):
        #: the line it was taking, answered ``ok`` once the reset ends the loop; None when none.
        self._critical_line: tuple[int, str] | None = None
        self._critical_wait = False
        self._pen_down = False
        self._spindle = 0.0
        self._spindle_ccw = False
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
                if self._critical_wait and byte != SOFT_RESET[0]:
                    continue  # in GRBL's lock: its flags and read buffer are cleared by the reset
                if byte == STATUS_QUERY[0]:
                    self._status_wanted = True
                elif byte == FEED_HOLD[0]:
                    self.feed_hold()
                elif byte == CYCLE_START[0]:
                    self.cycle_start()
                elif byte == SOFT_RESET[0]:
                    self._reset_alarm()
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
        """0x18: stop at once, forget every line and block, keep the position, say the banner.

        Called alone it is the board's own reset (its button): no alarm.  A 0x18 that
        arrives on the wire goes through GRBL's mc_reset first (:meth:`_reset_alarm`).
        """
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
            if self._critical_wait:
                self._critical_wait = False
                if (
                    self._critical_line is not None
                ):  # its gc_execute_line returns once the lock ends
                    self._answer(self.config.reply_ok, *self._critical_line)
                    self._critical_line = None
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
        """Enter the alarm state (``ALARM:<code>``), as a limit switch would.

        What follows is GRBL 1.1h's (protocol.c): after a hard or soft limit (1, 2)
        ``[MSG:Reset to continue]``, then silence, not even a status report, and every byte
        but 0x18 lost, until that reset (its ``EXEC_CRITICAL_EVENT`` loop; grbl-sim agrees,
        ``test_e2e_grbl_resets_vs_grbl_sim.py``); an alarm GRBL raises through its reset (3, 6…10: a
        reset in motion, a homing failure) is followed by that reset, its banner and
        ``[MSG:'$H'|'$X' to unlock]``, every line it held dropped unanswered.
        """
        with self._lock:
            if self.config.grbl and code in RESETTING_ALARMS:
                self._alarm = code
                self._send_line(f"ALARM:{code}")
                self._log("alarm", code=code, pos=self._where())
                self.soft_reset()
                return
            critical = self.config.grbl and code in CRITICAL_ALARMS
            if self.config.grbl:
                # GRBL reports the alarm first (protocol_execute_realtime), then the line it
                # was waiting in (a pen change or dwell syncing, a move waiting for room) ends.
                self._send_line(f"ALARM:{code}")
            for line in (self._pending_line, self._running_line):
                if line is not None and critical:
                    self._critical_line = line
                elif line is not None:
                    self._answer(f"{self.config.reply_error}:{GCODE_LOCKED}", *line)
            self._stop()
            self._interpreter.position = self._planner.position()
            self._interpreter.pen_down = False
            self._interpreter.spindle_level = 0.0
            self._alarm = code
            if not self.config.grbl:
                self._send_line(f"ALARM:{code}")
            if critical:
                self._send_line("[MSG:Reset to continue]")
                self._critical_wait = True
                self._status_wanted = False
            self._log("alarm", code=code, pos=self._where())

    # -- the control cycle -----------------------------------------------------------------

    def _overrides_changed(self, t: float | None = None) -> None:
        values = self._overrides.values
        self._planner.set_overrides(values.feed, values.rapid)
        self._log("override", t, feed=values.feed, rapid=values.rapid)

    def _run_cycle(self) -> None:
        if (
            self._critical_wait and self._booted
        ):  # GRBL's critical-event loop: nothing runs, nothing is said
            self._cycles += 1
            self._flush()
            return
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
        # GRBL synchronises the planner before a dwell, an offset change and a spindle change
        # (spindle_sync): the ok of an M3/M5 line comes once the pen has moved.
        self._pending_sync = self.config.grbl and any(
            isinstance(b, (Dwell, SetOffset, PenChange)) for b in result
        )
        waits = any(isinstance(b, (Dwell, SetOffset)) for b in result)
        pen = [b for b in result if isinstance(b, PenChange)]
        self._sync_until = pen[0] if self.config.grbl and pen and not waits else None
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
        coolant = self._interpreter.modal.coolant
        result = self._interpreter.execute(words)
        if self.config.grbl and self._interpreter.modal.coolant != coolant:
            self._overrides.refresh()  # coolant_set_state: A: is reported at once
        return [] if self._check_mode and not isinstance(result, int) else result

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
                self._set_pen(block.down, block.spindle, t, ccw=block.ccw)
                if self.config.grbl:
                    self._overrides.refresh()  # spindle_set_state: A: is reported at once
            case Dwell():
                self._log("dwell", t, seconds=block.seconds)
            case Pause():
                self._log("pause", t)
            case SetPosition():
                self._log("setpos", t, pos=self._where(block.position))
            case SetOffset():
                if block.program_end and self._overrides.reset():
                    self._overrides_changed(t)
                if block.program_end:
                    self._overrides.refresh()  # its spindle_set_state(SPINDLE_DISABLE)
                self._work_offset = block.offset
                self._wco_countdown = 0  # GRBL: the next report carries WCO
                self._log("offset", t, offset=self._where(block.offset))
        until = self._sync_until
        if self._running_line is not None and (not len(self._planner) or block is until):
            self._sync_until = None
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

    def _set_pen(self, down: bool, spindle: float, t: float, *, ccw: bool = False) -> None:
        self._spindle = spindle
        self._spindle_ccw = ccw
        if down != self._pen_down:
            self._pen_down = down
            self._log("pen", t, down=down, pos=self._where())
