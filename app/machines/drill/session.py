"""The PCB drill/plotter's session (docs/protocols.md §3).

The plotter takes one-letter procedures, one at a time: the host sends a
command, the device answers ``R<letter>`` when it has it and ``D<letter>``
when the procedure is over, and only then does the host send the next one.
So every intent goes into a queue and the queue is fed one command per
``D``.  An ``E`` means the device refused the command in flight: whatever was
queued after it is dropped rather than run out of its context (a ``V`` after
a refused ``X`` would drill in the wrong place).

The device answers ``R`` at once and ``D`` when the procedure ends, so a
silent link shows as a missing reply: the session gives the ``R`` a second
and the ``D`` twice the procedure's expected time plus a margin
(:mod:`protocol.drill.timing`), then reports the link lost (a running job
pauses) and asks the drill ``I`` every second until it answers: no command
has that letter, so the drill answers ``E`` and moves nothing, with the port
kept open.  Before that, a reply merely late (an ``R`` after half its
time, a ``D`` a second past the expected time) shows
the link stale, amber, and turns it green again when it comes.  An idle
drill is asked nothing, so its silence means nothing.

Positions are absolute microsteps from the machine's zero; the session
converts millimetres with the profile's constants (steps per revolution x
microsteps ÷ lead) and does all the rounding, half away from zero, in
decimal so that 12.5 mm x 19.8 is 247.5 exactly and becomes 248.

The drill jogs by absolute moves too, in whole microsteps clamped inside
the travel and judged by the motion gate like any other.  It has no stop
command, so a held jog is never one long move cancelled on release (a
release that never came would run it to the travel's end): it is a chain of
short steps, each sent only when the previous one is done and the holding
still shows signs of life (the dead-man).  A release, a lost focus or a
silent key therefore lets at most one short step finish.
"""

from __future__ import annotations

from collections import deque

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, QTimer, Signal

from app.link import Link
from app.machine import LinkState, MachineModel
from app.machines.drill.conversion import profile_microsteps_per_mm
from app.machines.drill.jogging import JOG_SLOW_SHARE as JOG_SLOW_SHARE  # re-exported
from app.machines.drill.jogging import JOG_STEP_S as JOG_STEP_S
from app.machines.drill.jogging import DrillJogging
from app.machines.drill.queue import MAX_POSITION as MAX_POSITION
from app.machines.drill.queue import RECEIPT_LATE_SHARE as RECEIPT_LATE_SHARE
from app.machines.drill.queue import RECEIPT_TIMEOUT_S as RECEIPT_TIMEOUT_S
from app.machines.drill.unasked import ReplyLedger
from app.machines.session import PENDING
from protocol.clock import Clock
from protocol.drill.codec import (
    DRILL,
    HOME,
    PARK,
    PEN_DOWN,
    PEN_UP,
    POSITION_LETTERS,
    Command,
    Rejected,
    Reply,
    ReplyDecoder,
    ReplyKind,
    decode_command,
    encode_command,
    encode_reply,
)

#: The ``D`` may take this much longer than expected (x) and then this many seconds more.
DONE_FACTOR = 2.0
DONE_MARGIN_S = 3.0
#: A reply is late (the link shown stale) this long after a procedure's expected end (the
#: receipt's share is in :mod:`app.machines.drill.queue`).
DONE_LATE_S = 1.0
TICK_MS = 100
#: Sent once a link opens, to hear the drill answer: no command has this letter.
PROBE_LETTER = "I"
PROBE = f"{PROBE_LETTER}\r".encode("ascii")

#: What each procedure is called in messages.
PROCEDURES = {
    "N": str(QT_TRANSLATE_NOOP("DrillSession", "home")),
    "X": str(QT_TRANSLATE_NOOP("DrillSession", "move X")),
    "Y": str(QT_TRANSLATE_NOOP("DrillSession", "move Y")),
    "V": str(QT_TRANSLATE_NOOP("DrillSession", "drill")),
    "K": str(QT_TRANSLATE_NOOP("DrillSession", "pen down")),
    "Z": str(QT_TRANSLATE_NOOP("DrillSession", "pen up")),
    "P": str(QT_TRANSLATE_NOOP("DrillSession", "park")),
}


def command_text(command: Command) -> str:
    """The command as the terminal shows it, without its CR: ``X248``, ``N``."""
    return encode_command(command).decode("ascii").rstrip("\r")


def wire_text(raw: bytes) -> str:
    """Bytes on the wire as one terminal line: never raises, whatever the drill sent."""
    return raw.decode("ascii", "replace").rstrip("\r\n")


def parse_line(text: str) -> Command | None:
    """A typed terminal line as the one command it spells, or None when it is none."""
    try:
        raw = text.strip().encode("ascii") + b"\r"
    except UnicodeEncodeError:
        return None
    used, command = decode_command(raw)
    return command if isinstance(command, Command) and used == len(raw) else None


class DrillSession(DrillJogging):
    """frameSent carries :class:`Command`, frameReceived :class:`Reply` or :class:`Rejected`."""

    #: The device acknowledged the command in flight (``R``); the command's text.
    commandReceived = Signal(str)
    #: The command in flight has finished (``D``); the command's text.
    commandDone = Signal(str)
    #: The device refused the command in flight (``E``); the queue was cleared.
    commandFailed = Signal(str)
    #: The last queued command is done and nothing is waiting.
    idle = Signal()
    #: The drill acknowledged or finished what the station did not send, in a way that can
    #: harm (a drill cycle run twice, another procedure): the message says what was heard.
    commandUnasked = Signal(str)
    #: A line for the terminal: ``> X248`` as sent, ``< RX`` as heard (the text decoded here,
    #: so the page only shows it).
    terminalLine = Signal(str)

    def __init__(
        self,
        model: MachineModel,
        link: Link,
        clock: Clock,
        *,
        autotick: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(model, link, clock, parent)
        self.decoder = ReplyDecoder()
        self._ledger = ReplyLedger()
        self._queue: deque[Command] = deque()
        self._in_flight: Command | None = None
        self._received = False
        #: Station-clock time by which the device must have answered the command in flight.
        self._deadline: float | None = None
        #: Since when the reply due has been awaited, and from when on it is late.
        self._waiting_since: float | None = None
        self._late_at: float | None = None
        #: Probes (``I``) written and not yet answered ``EI``.
        self._probes_out = 0
        #: After a silence: until when the drill may still be running the command it had.
        self._quiet_after: float | None = None
        self._autotick = autotick
        self.discounts_stalls = autotick  # a real-time timer ticks: its lateness is ours
        self._timer = QTimer(self)
        self._timer.setInterval(TICK_MS)
        self._timer.timeout.connect(self.tick)
        self._refused_lines = 0
        self._homed_here = False
        self._slow = False  # Shift held: the held jog's steps are short
        self._jog_turn = 0  # a diagonal jog alternates its axes, this one next
        self._jog_told_end = False
        self._per_mm = [profile_microsteps_per_mm(axis) for axis in model.profile.axes]
        link.connected.connect(self._on_connected)
        link.disconnected.connect(self._on_disconnected)
        link.dataReceived.connect(self._on_data)
        self.frameSent.connect(self._tell_sent)
        self.frameReceived.connect(self._tell_received)

    def _tell_sent(self, command: object, raw: bytes) -> None:
        line = "> " + wire_text(raw)
        if command == PROBE_LETTER or getattr(command, "letter", None) == PROBE_LETTER:
            line += QCoreApplication.translate("DrillPanel", "   (link check: is the drill there?)")
        self.terminalLine.emit(line)

    def _tell_received(self, reply: object, raw: bytes) -> None:
        line = "< " + wire_text(raw)
        if (
            isinstance(reply, Reply)
            and reply.kind is ReplyKind.ERROR
            and reply.letter == PROBE_LETTER
        ):
            # The drill answers the unknown letter I with EI: its "I am here", not a failure.
            line += QCoreApplication.translate(
                "DrillPanel", "  (link check answered: the drill is there)"
            )
        self.terminalLine.emit(line)

    # --- state the widgets read ------------------------------------------------

    @property
    def rejected(self) -> int:
        """Garbage replies dropped so far."""
        return self.decoder.rejected

    @property
    def refused_lines(self) -> int:
        """Terminal lines refused here because they are no command (never sent)."""
        return self._refused_lines

    @property
    def homed_since_connect(self) -> bool:
        """An ``N`` has finished since this link opened.

        The drill reports nothing but ``R``/``D``/``E`` (docs/protocols.md §3): it
        cannot say whether it homed at power-on, nor whether it was switched
        off and on while the link was down.  So the station counts only what
        it saw itself, and a new link starts unhomed.
        """
        return self._homed_here

    @property
    def homes_before_job(self) -> bool:
        return not self._homed_here

    @property
    def in_flight(self) -> Command | None:
        return self._in_flight

    @property
    def queued(self) -> tuple[Command, ...]:
        return tuple(self._queue)

    # --- intents ----------------------------------------------------------------

    def move_absolute(self, axis: int, position: float) -> bool:
        if not 0 <= axis < self.axis_count:
            return self._unsupported(
                QCoreApplication.translate("DrillSession", "axis {0}").format(axis + 1)
            )
        name = self.model.profile.axes[axis].name
        if name not in POSITION_LETTERS:
            return self._unsupported(
                QCoreApplication.translate("DrillSession", "moves of {0}").format(name)
            )
        if self.gate.refuse(self.gate.refuse_target(axis, position)):
            return False
        return self._enqueue(Command(name, self.to_microsteps(axis, position)))

    def home(self, axis: int) -> bool:
        """``N`` homes X then Y, whichever axis was asked for."""
        return self._enqueue(HOME)

    def drill(self) -> bool:
        return self._enqueue(DRILL)

    def pen(self, down: bool) -> bool:
        return self._enqueue(PEN_DOWN if down else PEN_UP)

    def park(self) -> bool:
        return self._enqueue(PARK)

    def send_command(self, command: Command) -> bool:
        return self._enqueue(command)

    def send_line(self, text: str) -> bool:
        """A terminal line: queued if it is a command, otherwise refused here and counted."""
        line = text.strip()
        try:
            raw = line.encode("ascii") + b"\r"
        except UnicodeEncodeError:
            return self._refuse_line(line, "not ASCII")
        used, result = decode_command(raw)
        if isinstance(result, Rejected):
            return self._refuse_line(line, result.reason)
        if result is None or used != len(raw):
            return self._refuse_line(line, "not one command")
        return self._enqueue(result)

    def stop_all(self) -> None:
        self._jog = [0] * self.axis_count
        self._jog_started()
        dropped = len(self._queue)
        self._queue.clear()
        running = self._in_flight
        if running is not None:
            text = QCoreApplication.translate(
                "DrillSession",
                "The drill has no stop command: {0} queued command(s) dropped; "
                "{1} finishes its procedure",
            ).format(dropped, command_text(running))
        else:
            text = QCoreApplication.translate(
                "DrillSession", "The drill has no stop command: {0} queued command(s) dropped"
            ).format(dropped)
        self.model.message.emit(text)
        if running is None and dropped:
            self.idle.emit()

    # --- time --------------------------------------------------------------------

    def tick(self) -> None:
        """A late reply shows the link stale; one not come in time means a silent link.

        And a held jog with no sign of life for too long ends (the dead-man).
        """
        now = self.clock.now()
        stall = self._station_stall(now)
        if stall and self._waiting_since is not None:
            # The station was not running: the reply due may be waiting to be read.
            self._late_at = (self._late_at or now) + stall
            self._deadline = (self._deadline or now) + stall
        self._check_answer()
        self._feed_jog()
        since, late_at, deadline = self._waiting_since, self._late_at, self._deadline
        if since is None or late_at is None or deadline is None:
            return
        command = self._in_flight
        what = command_text(command) if command is not None else "the last command"
        waited = "its receipt" if not self._received else "the end of its procedure"
        if now >= deadline:
            # Lost, whatever the state was (amber or still green).
            self._lost_to_silence(f"no reply for {now - since:.1f} s ({what}: {waited})")
        elif now >= late_at:
            self._watch_silence(now - since, 0.0, deadline - since, f"{what}: {waited}")

    def line_expected_s(self, text: str) -> float:
        """How long the X or Y move a terminal line spells should run (0 for anything else)."""
        command = parse_line(text)
        if command is None or command.letter not in POSITION_LETTERS:
            return 0.0
        return self.expected_s(command)

    def expected_s(self, command: Command) -> float:
        """How long ``command``'s procedure should take, by the profile's timing constants."""
        timing = self.model.profile.drill_timing
        periods = timing.step_periods
        letter = command.letter
        if letter in POSITION_LETTERS and command.value is not None:
            axes = self._axes_named(letter)
            if not axes:
                return 0.0
            here = self.to_microsteps(axes[0], self.model.axes[axes[0]].position)
            return abs(command.value - here) * periods.get(letter, 0.0)
        if letter == "V":
            return timing.first_cycle_s  # the longest stroke: the drill may start at the top
        if letter == "K":
            # Vrtat's way down (S2-24), the longest: the pen may start at the top.
            return timing.down_s(timing.first_down_microsteps)
        if letter == "Z":
            return timing.up_s()
        # Home and park run the axes across their whole travel.
        return sum(
            self.to_microsteps(axis, self.model.profile.axes[axis].travel)
            * periods.get(self.model.profile.axes[axis].name, 0.0)
            for axis in self._axes_named(POSITION_LETTERS)
        )

    def shutdown(self) -> None:
        self._timer.stop()

    # --- a silent drill ------------------------------------------------------------

    def _silence_began(self) -> str:
        """The command in flight and the queue go, as with the link: a job re-examines them.

        The drill may still be running the command it had (its ``R`` was lost,
        say): until that would be over, the drill is not called back, so the
        next command is not queued behind it to be mistaken for it.
        """
        command = self._in_flight
        dropped = len(self._queue) + (command is not None)
        if command is not None and self._waiting_since is not None:
            self._quiet_after = self._waiting_since + self.expected_s(command) + DONE_LATE_S
        self._clear()
        self._show_stopped()
        return (
            QCoreApplication.translate("DrillSession", "; {0} command(s) dropped").format(dropped)
            if dropped
            else ""
        )

    def _probe(self) -> None:
        """A letter that is no command: the drill answers ``E`` and moves nothing."""
        self._probes_out += 1
        self.link.write(PROBE)
        self.frameSent.emit(PROBE.decode("ascii").strip(), PROBE)

    def _recovery_verdict(self) -> object:
        """The drill cannot say where it is: it answered, and is done with what it had."""
        quiet_after = self._quiet_after
        if quiet_after is not None and self.clock.now() < quiet_after:
            return PENDING
        self._quiet_after = None
        return None

    # --- link events and replies ------------------------------------------------

    def _on_connected(self) -> None:
        self._homed_here = False
        self.decoder.reset()
        self._clear()
        self.await_device()
        if self._autotick:
            self._timer.start()
        # The drill speaks only when spoken to: a letter that is no command is answered
        # E, which proves a drill is there and moves nothing.
        self._probes_out = 0
        self._quiet_after = None
        self._probe()
        for axis in range(self.axis_count):
            self.model.update_axis(axis, status_text="idle", moving=False, velocity=0.0)

    def _on_disconnected(self, reason: object) -> None:
        self._timer.stop()
        dropped = len(self._queue) + (self._in_flight is not None)
        self._end_held_jog("link closed")
        self._clear()
        self._show_stopped()
        if reason is None:
            self.model.set_link_state(LinkState.DISCONNECTED)
        else:
            self.model.set_link_state(LinkState.LOST, str(reason))
            self.model.message.emit(
                QCoreApplication.translate(
                    "DrillSession", "Link lost: {0}; {1} command(s) dropped"
                ).format(reason, dropped)
                if dropped
                else QCoreApplication.translate("DrillSession", "Link lost: {0}").format(reason)
            )

    def _on_data(self, data: bytes) -> None:
        self.heard_unrecognised(data)  # kept until the device answers: whose words?
        for reply in self.decoder.feed(data):
            if isinstance(reply, Rejected):
                self.frameReceived.emit(reply, reply.raw)
                self.model.message.emit(
                    QCoreApplication.translate(
                        "DrillSession", "Garbage from the drill dropped: {0}"
                    ).format(repr(reply.raw))
                )
                continue
            self.frameReceived.emit(reply, encode_reply(reply))
            self.device_replied()
            if self._probes_out and reply.kind is ReplyKind.ERROR and reply.letter == PROBE_LETTER:
                self._probes_out -= 1  # the answer to a probe, not to a command
                continue
            self._on_reply(reply)

    def _on_reply(self, reply: Reply) -> None:
        command = self._in_flight
        # One command at a time: an E while one is out refuses that one, whatever letter it
        # names (a line corrupted on the way is named by its corrupted first letter).
        refused = reply.kind is ReplyKind.ERROR
        if command is None or (reply.letter != command.letter and not refused):
            got = f"{reply.kind.value}{reply.letter}"
            heard = (
                QCoreApplication.translate(
                    "DrillSession", "Unexpected reply {0} from the drill (waiting for {1})"
                ).format(got, command.letter)
                if command is not None
                else QCoreApplication.translate(
                    "DrillSession", "Unexpected reply {0} from the drill"
                ).format(got)
            )
            self.model.message.emit(heard)
            why = self._ledger.unasked(
                reply.kind, reply.letter, command.letter if command is not None else None
            )
            if why is not None:
                self.commandUnasked.emit(
                    QCoreApplication.translate("DrillSession", "{0}: it {1}").format(
                        heard, QCoreApplication.translate("DrillSession", why)
                    )
                )
            return
        text = command_text(command)
        if reply.kind is ReplyKind.RECEIVED and self._received:
            why = self._ledger.again(reply.letter)
            if why is not None:
                self.commandUnasked.emit(
                    QCoreApplication.translate("DrillSession", "The drill {0} ({1})").format(
                        QCoreApplication.translate("DrillSession", why), text
                    )
                )
            return
        if reply.kind is ReplyKind.RECEIVED:
            self._received = True
            takes = self.expected_s(command)
            self._expect(takes + DONE_LATE_S, DONE_FACTOR * takes + DONE_MARGIN_S)
            self.commandReceived.emit(text)
        elif reply.kind is ReplyKind.DONE:
            self._ledger.done(reply.letter)
            self._in_flight = None
            self._expect(None)
            self._show_done(command)
            self.commandDone.emit(text)
            if self._queue:
                self._send_next()
            elif not self._feed_jog():  # a held jog goes on with its next step
                self.idle.emit()
        else:
            dropped = len(self._queue)
            self._clear()
            self._end_held_jog("refused")
            self._show_stopped()
            procedure = QCoreApplication.translate("DrillSession", PROCEDURES[command.letter])
            refused_text = QCoreApplication.translate(
                "DrillSession", "The drill refused {0} ({1})"
            ).format(text, procedure)
            if dropped:
                refused_text += QCoreApplication.translate(
                    "DrillSession", "; {0} queued command(s) dropped"
                ).format(dropped)
            self.model.message.emit(refused_text)
            self.commandFailed.emit(text)
