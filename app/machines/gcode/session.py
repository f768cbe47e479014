"""The G-code session: plotters and the string-art winder (docs/protocols.md §4).

Lines are streamed, not sent one by one: with *character counting* the
session keeps up to 127 unacknowledged bytes in the device's 128-byte
receive buffer, so the device never waits for the host between lines; with
*ping-pong* (profiles whose firmware has no such buffer) the next line goes
only after the ``ok`` of the last.  Every ``ok``/``error:n`` answers the
oldest unacknowledged line, which is how a reply is tied to its line (and a
job's error to its file line).

Real-time bytes bypass the stream: ``?`` every ``status_ms`` keeps positions
and the machine state fresh (and proves the device alive: three unanswered
show the link stale, amber, and :data:`SILENCE_S` without a reply lost, red), ``!`` holds,
``~`` resumes, 0x18 resets.  A board given up as silent keeps its port
open (reopening an Arduino's port restarts it) and is asked on; its state is
intact when its first status report after the silence follows no banner (it
did not restart) and shows no alarm.  A stop is a feed hold followed by a soft reset
once the machine stands, which throws away what the device had buffered
without losing its position.

Every status report's machine position is judged against the path of the
lines written (:mod:`app.machines.gcode.planned_path`): a line mangled on the
wire into another valid one (G-code has no checksum) shows as a report off
that path, past its end or outside the travel, and the session stops the
machine (feed hold, then the reset) and names the line.  A wrong line whose
motion stays within the tolerance of the path sent cannot be told apart.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import count

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.link import Link
from app.machine import MachineModel
from app.machines.envelope import Envelope
from app.machines.gcode import timing
from app.machines.gcode.alarm_notice import AlarmNotice
from app.machines.gcode.console_gate import SETTING_DISABLED as SETTING_DISABLED
from app.machines.gcode.console_gate import ConsoleGate
from app.machines.gcode.feeder import LineFeeder, merged, settles
from app.machines.gcode.hand_zeroing import HandZeroing
from app.machines.gcode.hand_zeroing import zeroes_by_hand as zeroes_by_hand
from app.machines.gcode.job_feed import JobFeed, JobSource
from app.machines.gcode.jogger import JOG_BLOCKS_AHEAD as JOG_BLOCKS_AHEAD
from app.machines.gcode.jogger import JOG_RESOLUTION as JOG_RESOLUTION
from app.machines.gcode.jogger import JOG_SPEED_SHARE as JOG_SPEED_SHARE
from app.machines.gcode.jogger import JOG_STEP_S as JOG_STEP_S
from app.machines.gcode.jogger import GcodeJogger
from app.machines.gcode.limit_lock import LimitLock
from app.machines.gcode.lines import SentLine as SentLine
from app.machines.gcode.link_events import LinkEvents
from app.machines.gcode.overrides import OverrideControl
from app.machines.gcode.reply_reader import ReplyReader
from app.machines.gcode.reply_reader import reply_bytes as reply_bytes
from app.machines.gcode.status_follower import StatusFollower
from app.machines.gcode.stop_sequence import RESET_AFTER_S as RESET_AFTER_S
from app.machines.gcode.stop_sequence import StopSequence
from app.machines.gcode.work_zero import WorkZero
from app.machines.session import PENDING, MachineSession
from app.profiles import GcodeSettings
from protocol.clock import Clock
from protocol.gcode.codec import (
    CYCLE_START,
    FEED_HOLD,
    SOFT_RESET,
    STATUS_QUERY,
    StatusReport,
    encode_line,
    make_decoder,
)
from protocol.gcode.streaming import LineStreamer, StreamMode

#: No reply for this long: the link is lost (:mod:`~app.machines.gcode.timing`).
SILENCE_S = timing.SILENCE_S
#: Status queries unanswered before the link is shown stale (amber), and the least time.
STALE_QUERIES = 3
STALE_AFTER_MIN_S = 0.5


class GcodeSession(MachineSession):
    """frameSent carries the line text (or the real-time byte's name), frameReceived a reply."""

    lineSent = Signal(object)  # SentLine
    #: The lines of one write, in order (list[SentLine]): what hears every line of a running
    #: job listens here, once a batch, not once a line.
    linesSent = Signal(object)
    lineAcknowledged = Signal(object)  # SentLine (not a job's line the job counted)
    #: Lines of the followed job were answered (counted there): once per batch of replies.
    jobAdvanced = Signal()
    lineFailed = Signal(object, int, str)  # SentLine, error code, meaning
    statusChanged = Signal(object)  # StatusReport
    #: A reply line worth showing the operator (the console): its text.
    replyText = Signal(str)
    #: The device was reset (banner seen or reset sent): whatever was unanswered is gone.
    reset = Signal()
    # The board went into alarm ``ALARM:<code>`` (said once while it stays in it).
    alarmed = Signal(int)

    def __init__(
        self,
        model: MachineModel,
        link: Link,
        clock: Clock,
        settings: GcodeSettings,
        *,
        autotick: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(model, link, clock, parent)
        self.settings = settings
        self.decoder = make_decoder()
        mode = StreamMode.COUNTING if settings.streaming == "counting" else StreamMode.PING_PONG
        # Room for one line more than counted: a line or an ok that arrives twice overflows
        # nothing (no checksum on the wire; see LineStreamer).
        self.streamer: LineStreamer[SentLine] = LineStreamer(
            mode, settings.rx_buffer, spare_line=True
        )
        #: The streaming loop and its ``ok`` accounting, on the transport's reader thread.
        self.feeder: LineFeeder[SentLine] = LineFeeder(
            self.streamer,
            self.decoder,
            clock,
            link.write,
            link.write_from_tap,
            holds_on_refusal=lambda sent: sent.origin in ("job", "setup", "resume"),
        )
        self.status: StatusReport | None = None
        self.errors = 0
        self.alarm = AlarmNotice()  # the alarm said, while the board stays in it
        #: Line serials, taken under the feeder's lock: both threads number lines.
        self.serials = count(1)
        #: A status report since the last line was answered showed the machine idle
        #: (written under the feeder's lock: a job's line queued on the reader thread clears it).
        self.seen_idle = True
        self.status_asked_at: float | None = None  # an unanswered "?", for a status soon
        self.last_heard = clock.now()
        #: Silence shown amber: a few status queries (one each ``status_ms``) unanswered.
        self.stale_after_s = max(STALE_AFTER_MIN_S, STALE_QUERIES * settings.status_ms / 1000)
        self.jogger = GcodeJogger(self, with_command="$J" in settings.words)
        self.console = ConsoleGate(model, self.gate)
        self.zeroing = HandZeroing(self)
        #: GRBL's lock after a hard or soft limit: silent until a reset (limit_lock.py).
        self.limit_lock = LimitLock(self)
        #: Whether the last :attr:`reset` was the board's own (a banner nobody here asked
        #: for: its reset button, a power dip), not a soft reset the station sent.
        self.reset_by_device = False
        #: The board's work coordinate offset last reported (GRBL's WCO:), None before any.
        self.work_offset: tuple[float, ...] | None = None
        #: What the followed job had as the last status report was read (its snapshot).
        self.job_at_report: object = None
        # The path of the lines written, which every status report must follow.
        self.envelope: Envelope = Envelope(
            [self.gate.limits(axis) for axis in range(self.axis_count)],
            model.profile.supervision_tolerance_mm,
            # At rest a report moves the anchor (a board that came back, say): only the lines
            # written are judged, and each is, through the report that shows it run.
            hold_at_rest=False,
        )
        #: After a silence: when the board was first heard again, the first status report
        #: made after that had settled, and whether a banner came meanwhile.
        self.heard_again_at: float | None = None
        self.report_after_silence: StatusReport | None = None
        self.restarted_in_silence = False
        # The parts along the session's seams; each holds this session (GUI thread).
        self.stops = StopSequence(self)
        self.follower = StatusFollower(self)
        self.replies = ReplyReader(self)
        self.links = LinkEvents(self)
        # GRBL's feed/rapid overrides and work systems (available as the registry says).
        self.overrides = OverrideControl(self)
        self.work = WorkZero(self)
        self.autotick = autotick
        self.discounts_stalls = autotick  # a real-time timer ticks: its lateness is ours
        self.timer = QTimer(self)
        self.timer.setInterval(settings.status_ms)
        self.timer.timeout.connect(self.tick)
        link.connected.connect(self.links.connected)
        link.disconnected.connect(self.links.disconnected)
        link.received.connect(self.replies.on_received)
        link.set_tap(self.feeder.receive, merged, settles)

    # --- state the widgets and the runner read ---------------------------------

    @property
    def rejected(self) -> int:
        return self.decoder.rejected

    @property
    def period_ms(self) -> int:
        return self.settings.status_ms

    @property
    def machine_state(self) -> str:
        """The device's last reported state (Idle, Run, Hold, Home, Alarm), or "" before any."""
        return self.status.state if self.status is not None else ""

    @property
    def settled(self) -> bool:
        """Everything sent is answered and a status report since then shows the machine idle.

        Both read in one hold: a job's line queued on the reader thread changes both.
        """
        with self.feeder.lock:
            return self.streamer.idle and self.seen_idle

    # --- lines --------------------------------------------------------------------

    def send_line(
        self,
        text: str,
        origin: str = "console",
        op_index: int | None = None,
        *,
        confirmed: bool = False,
    ) -> bool:
        """Queue one line for the device; a line it could never take is refused here.

        A console line that would move past the travel goes only ``confirmed``
        (the console asks the operator first): the console is raw access, not
        a way around the gate.
        """
        line = text.strip()
        if not line:
            return False
        # Any line after the release may move an axis (switching its driver on): a zero
        # declared after it would no longer be where the operator put the axes.
        with self.feeder.lock:
            self.zeroing.line_queued()
        if origin == "console" and not confirmed:
            refusal = self.console.beyond_travel(line)
            if refusal is not None:
                self.model.message.emit(
                    QCoreApplication.translate(
                        "GcodeSession", "Not sent without confirmation: {0}"
                    ).format(refusal)
                )
                return False
        try:
            raw = encode_line(line)
        except ValueError as exc:
            self.model.message.emit(
                QCoreApplication.translate("GcodeSession", "Not sent: {0} ({1})").format(
                    repr(line), exc
                )
            )
            return False
        if not self.link.is_open:
            self.model.message.emit(
                QCoreApplication.translate("GcodeSession", "Not sent: {0} (not connected)").format(
                    repr(line)
                )
            )
            return False
        # One hold from the serial to the notes: a job's line pulled on the reader thread
        # meanwhile goes wholly before or after this one (see app.machines.gcode.job_feed).
        with self.feeder.lock:
            sent = SentLine(next(self.serials), line, origin, op_index)
            try:
                self.streamer.queue(raw, sent)
            except ValueError as exc:
                problem: ValueError | None = exc
            else:
                problem = None
                self.note_queued(line, origin)
        if problem is not None:
            self.model.message.emit(
                QCoreApplication.translate("GcodeSession", "Not sent: {0} ({1})").format(
                    repr(line), problem
                )
            )
            return False
        self.pump()
        return True

    def note_queued(self, line: str, origin: str) -> None:
        """What a line queued implies (under the feeder's lock: a job's lines are queued on
        the reader thread): the board is busy again, a release for zeroing by hand is over,
        and the distance mode the board will be in is the line's (the console judges in it).
        """
        self.seen_idle = False
        self.zeroing.released = False
        # A job's line without a 9 names neither G90 nor G91: job lines skip the parse on that.
        if origin != "job" or "9" in line:
            self.console.note(line)

    def start_job(self, source: JobSource) -> JobFeed:
        """A running job's lines go through the feed made here (:mod:`~app.machines.gcode.
        job_feed`); its answers are counted where they are read, it is not pulled yet."""
        feed = JobFeed(self, source, compact=self.settings.compact_lines)
        self.feeder.follow(feed)
        return feed

    def pump(self) -> None:
        """Write every queued line that fits now (bytes sent while the board restarts are
        lost by the board itself: the feeder waits for its banner)."""
        # Bytes sent while the board restarts are lost by the board itself: the feeder waits.
        self.follower.written(self.feeder.pump())

    def send_realtime(self, byte: bytes, name: str) -> None:
        """A real-time byte (it bypasses the stream), shown in the frame log as ``name``."""
        if self.link.is_open:
            self.link.write(byte)
            self.frameSent.emit(name, byte)

    def query_status(self) -> None:
        with self.feeder.lock:  # behind exactly the lines noted (byte_shortfall.py)
            self.feeder.marks.asked()
            self.send_realtime(STATUS_QUERY, "?")
        self.status_asked_at = self.clock.now()

    @property
    def planner_size(self) -> int:
        """Planner blocks the device has, learned from its ``Bf:`` reports (0: unknown)."""
        return self.follower.planner_size

    def feed_hold(self) -> None:
        self.send_realtime(FEED_HOLD, "! (feed hold)")

    def cycle_start(self) -> None:
        self.send_realtime(CYCLE_START, "~ (resume)")

    def soft_reset(self) -> list[SentLine]:
        """Reset the device: its buffers are emptied, so nothing unanswered will be answered.

        GRBL may still answer a line it was parsing (a stray ``ok`` after the reset):
        until its banner, answers belong to no line and new lines wait.
        """
        with self.feeder.lock:  # no line goes between the reset and its note
            self.send_realtime(SOFT_RESET, "Ctrl-X (soft reset)")
            if self.link.is_open:
                self.feeder.reset_sent_at = self.clock.now()
            return self.links.forget_stream(by_device=False)

    def discard_queued(self) -> list[SentLine]:
        """Drop lines not yet sent (the ones the device has stay and will be answered).

        Under the feeder's lock: once this returns the reader thread sends none of them.
        """
        return self.feeder.discard_queued()

    # --- intents ------------------------------------------------------------------

    def stop_all(self, *, keep_jog: bool = False, quiet: bool = False) -> None:
        """Hold at once; reset once the machine stands, so buffered lines are dropped.

        A reset while the axes still move makes GRBL raise ALARM:3 and forget its
        position, so the reset waits for a status report saying the hold is
        complete (``Hold:0``) or the machine idle — or for :data:`RESET_AFTER_S`.
        ``quiet``: the stop ends a jog, no "lines not run" message for it
        (:class:`~app.machines.gcode.stop_sequence.StopSequence`).
        """
        self.stops.stop(keep_jog=keep_jog, quiet=quiet)

    def motion_stopped(self) -> bool:
        """Still, by the board's reports, and no stop waiting for its hold to complete."""
        return not self.stopping and not self.model.any_moving

    @property
    def stopping(self) -> bool:
        """A stop was asked for and its reset has not gone out yet."""
        return self.stops.requested_at is not None

    def move_absolute(self, axis: int, position: float) -> bool:
        """To the machine position ``position``: sent as the work position GRBL takes it for."""
        if self._refuse_motion() or not 0 <= axis < self.axis_count:
            return False
        if self.gate.refuse(self.gate.refuse_target(axis, position)):
            return False
        name = self.model.profile.axes[axis].name
        work = position - self.model.axes[axis].offset
        return self.send_line(f"G90 G0 {name}{work:.3f}", "intent")

    def move_relative(self, axis: int, delta: float) -> bool:
        """Sent as the absolute target it reaches, so the machine's distance mode stays G90."""
        if self._refuse_motion() or not 0 <= axis < self.axis_count:
            return False
        if self.gate.refuse(self.gate.refuse_relative(axis, delta)):
            return False
        return self.move_absolute(axis, self.model.axes[axis].position + delta)

    def home(self, axis: int) -> bool:
        if self._refuse_motion():
            return False
        return self.send_line("$H" if "$H" in self.settings.words else "G28", "intent")

    def pen(self, down: bool) -> bool:
        return self.send_line(self.settings.pen_down if down else self.settings.pen_up, "intent")

    def set_jog(self, directions: Sequence[int]) -> None:
        """Held arrows become short moves kept a little ahead of the machine, inside the travel
        (:class:`GcodeJogger`)."""
        wanted = self._jog_wanted(directions)
        if wanted == self._jog:
            return
        previous, self._jog = self._jog, wanted
        self._jog_started()
        self.jogger.changed(tuple(previous), tuple(wanted))

    # --- time -----------------------------------------------------------------------

    def tick(self) -> None:
        """Ask for the status; notice a device that stopped answering (or never did)."""
        if not self.link.is_open:
            return
        self._check_answer()
        self._check_deadman()
        if self.feeder.reset_sent_at is not None and not self.feeder.awaiting_banner():
            self.pump()  # no banner after the reset: send what waited anyway
        now = self.clock.now()
        self.stops.due(now)
        self.query_status()
        # Time the station itself was not running is nobody's silence (a busy computer).
        self.last_heard = min(now, self.last_heard + self._station_stall(now))
        if self.limit_lock.silence_is_expected():
            self.last_heard = now  # GRBL's lock after a limit says nothing until a reset
        silent = now - self.last_heard
        self._watch_silence(silent, self.stale_after_s, timing.SILENCE_S)
        if self.device_answered and silent > timing.SILENCE_S:
            # The link status says it ("lost — no reply for 2.2 s"): no second message.
            self.last_heard = now

    # --- a silent board ----------------------------------------------------------------

    def _silence_began(self) -> str:
        """What was under way is forgotten as when the link goes: a job looks at the board
        again before it goes on (the port stays open, so the board may still answer it)."""
        self.heard_again_at = None
        self.report_after_silence = None
        self.restarted_in_silence = False
        # A stop under way is kept: it is carried out once the board is heard again.
        lost = self.links.forget_jog_and_lines()
        return (
            QCoreApplication.translate("GcodeSession", "; {0} unanswered line(s)").format(len(lost))
            if lost
            else ""
        )

    def _back_after_silence(self) -> None:
        """A stop asked for before or during the silence is carried out now: its hold may
        have been lost on the way, so it goes again, and the reset follows once it holds."""
        self.stops.after_silence()

    def _recovery_verdict(self) -> object:
        """Intact: no banner came, and a status report made once the board's held-back
        replies were through (a report from before a restart would prove nothing) shows no
        alarm."""
        report = self.report_after_silence
        if self.restarted_in_silence:
            return QCoreApplication.translate(
                "GcodeSession", "it restarted meanwhile (its banner came), so what it had is gone"
            )
        if report is None:
            return PENDING
        if report.state == "Alarm":
            return QCoreApplication.translate("GcodeSession", "it is in alarm")
        return None

    def shutdown(self) -> None:
        """Stop timers; a stop still waiting for its hold resets now (the link is closing)."""
        self.timer.stop()
        if self.stopping and self.link.is_open:
            self.stops.reset_now()

    # --- replies -------------------------------------------------------

    def receive_injected(self, data: bytes) -> None:
        """Bytes a developer injects as the device's (developer pane): handled as if read."""
        self.replies.on_received(self.feeder.receive(data))
