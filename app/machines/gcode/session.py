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

import logging
from collections.abc import Sequence
from itertools import count

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.link import Link
from app.machine import LinkState, MachineModel
from app.machines.envelope import Envelope
from app.machines.gcode.byte_count import ByteCount
from app.machines.gcode.console_gate import SETTING_DISABLED as SETTING_DISABLED
from app.machines.gcode.console_gate import ConsoleGate, refusal_hint
from app.machines.gcode.feeder import (
    STALE,
    WROTE,
    Answer,
    BannerSeen,
    LineFeeder,
    Received,
    ReportSeen,
    merged,
)
from app.machines.gcode.hand_zeroing import HandZeroing
from app.machines.gcode.hand_zeroing import zeroes_by_hand as zeroes_by_hand
from app.machines.gcode.job_feed import JobFeed, JobSource
from app.machines.gcode.jogger import JOG_BLOCKS_AHEAD as JOG_BLOCKS_AHEAD
from app.machines.gcode.jogger import JOG_RESOLUTION as JOG_RESOLUTION
from app.machines.gcode.jogger import JOG_SPEED_SHARE as JOG_SPEED_SHARE
from app.machines.gcode.jogger import JOG_STEP_S as JOG_STEP_S
from app.machines.gcode.jogger import GcodeJogger, reports_moving
from app.machines.gcode.lines import SentLine as SentLine
from app.machines.gcode.lost_answers import AnswersLost, LostAnswerWatch, StreamWaits, pauses
from app.machines.gcode.planned_path import PlannedPath
from app.machines.gcode.stuck_line import StuckLineWatch
from app.machines.motion_gate import Refusal
from app.machines.session import PENDING, MachineSession
from app.machines.supervision import MotionFault, fault_text
from app.profiles import GcodeSettings
from protocol.clock import Clock
from protocol.gcode.codec import (
    CYCLE_START,
    FEED_HOLD,
    SOFT_RESET,
    STATUS_QUERY,
    AlarmReply,
    Banner,
    ErrorReply,
    Feedback,
    Ok,
    Rejected,
    StatusReport,
    encode_line,
    make_decoder,
    with_work_offset,
)
from protocol.gcode.streaming import LineStreamer, StreamMode

_log = logging.getLogger(__name__)

#: No reply to status queries for this long: the link is lost (a job pauses) and the board is
#: asked on until it answers.  A board that answers a status query within milliseconds and
#: then goes silent for seconds has stopped listening, but a few seconds can be a host's or a
#: USB bridge's hiccup that loses nothing: a 2.5 s freeze of the board's replies mid-job must
#: not pause the job (the lamp is amber meanwhile, after :data:`STALE_QUERIES`).
SILENCE_S = 4.0
#: Status queries unanswered before the link is shown stale (amber), and the least time.
STALE_QUERIES = 3
STALE_AFTER_MIN_S = 0.5
#: A stop resets the device this long after its hold at the latest, standing or not.
RESET_AFTER_S = 2.0


def reply_bytes(reply: object) -> bytes:
    """The reply as a line again, for the frame log (the decoder keeps no raw bytes)."""
    if isinstance(reply, Ok):
        return b"ok"
    if isinstance(reply, ErrorReply):
        return f"error:{reply.code}".encode()
    if isinstance(reply, AlarmReply):
        return f"ALARM:{reply.code}".encode()
    if isinstance(reply, StatusReport):
        fields = "|".join(f"{k}:{v}" for k, v in reply.fields.items())
        return f"<{reply.state}|{fields}>".encode()
    if isinstance(reply, Banner | Feedback):
        return reply.text.encode("ascii", "replace")
    return repr(reply).encode("ascii", "replace")


class GcodeSession(MachineSession):
    """frameSent carries the line text (or the real-time byte's name), frameReceived a reply."""

    lineSent = Signal(object)  # SentLine
    lineAcknowledged = Signal(object)  # SentLine (not a job's line the job counted)
    #: Lines of the followed job were answered (counted there): once per batch of replies.
    jobAdvanced = Signal()
    lineFailed = Signal(object, int, str)  # SentLine, error code, meaning
    statusChanged = Signal(object)  # StatusReport
    #: A reply line worth showing the operator (the console): its text.
    replyText = Signal(str)
    #: The device was reset (banner seen or reset sent): whatever was unanswered is gone.
    reset = Signal()

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
        self.streamer: LineStreamer[SentLine] = LineStreamer(mode, settings.rx_buffer)
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
        self._serials = count(1)
        #: A status report since the last line was answered showed the machine idle.
        self._seen_idle = True
        self._status_asked_at: float | None = None  # an unanswered "?", for request_status
        self._last_heard = clock.now()
        self.jogger = GcodeJogger(self, with_command="$J" in settings.words)
        self.console = ConsoleGate(model, self.gate)
        self.zeroing = HandZeroing(self)
        self._lost_answers = LostAnswerWatch(settings.rx_buffer)
        #: Whether the last :attr:`reset` was the board's own (a banner nobody here asked
        #: for: its reset button, a power dip), not a soft reset the station sent.
        self.reset_by_device = False
        #: The board's work coordinate offset last reported (GRBL's WCO:), None before any.
        self.work_offset: tuple[float, ...] | None = None
        #: The stop under way ends a jog: no "lines not run" message for it.
        self._quiet_stop = False
        self._reset_requested_at: float | None = None
        self._dropped_by_stop = 0
        self._planner_size = 0
        #: A line cut on the wire, its start stuck in the board's buffer (stuck_line.py).
        self._stuck = StuckLineWatch(clock, settings.rx_buffer)
        #: The board's buffer against the bytes counted unanswered (byte_count.py).
        self._byte_count = ByteCount(settings.rx_buffer)
        #: What the followed job had as the last status report was read (its snapshot).
        self.job_at_report: object = None
        # The path of the lines written, which every status report must follow.
        self.envelope = Envelope(
            [self.gate.limits(axis) for axis in range(self.axis_count)],
            model.profile.supervision_tolerance_mm,
            # At rest a report moves the anchor (a board that came back, say): only the lines
            # written are judged, and each is, through the report that shows it run.
            hold_at_rest=False,
        )
        self._planned = PlannedPath(
            self.envelope,
            tuple(axis.name for axis in model.profile.axes),
            grbl="$J" in settings.words,
        )
        #: A stop went out and no report since its reset has shown the board standing: on a
        #: silent line its hold and reset may both have been lost.
        self._stop_unconfirmed = False
        #: After a silence: when the board was first heard again, the first status report
        #: made after that had settled, and whether a banner came meanwhile.
        self._heard_again_at: float | None = None
        self._report_after_silence: StatusReport | None = None
        self._restarted_in_silence = False
        self._autotick = autotick
        self.discounts_stalls = autotick  # a real-time timer ticks: its lateness is ours
        self._timer = QTimer(self)
        self._timer.setInterval(settings.status_ms)
        self._timer.timeout.connect(self.tick)
        link.connected.connect(self._on_connected)
        link.disconnected.connect(self._on_disconnected)
        link.received.connect(self._on_received)
        link.set_tap(self.feeder.receive, merged)

    # --- state the widgets and the runner read ---------------------------------

    @property
    def rejected(self) -> int:
        return self.decoder.rejected

    @property
    def period_ms(self) -> int:
        return self.settings.status_ms

    @property
    def stale_after_s(self) -> float:
        """Silence shown amber: a few status queries (one each ``status_ms``) unanswered."""
        return max(STALE_AFTER_MIN_S, STALE_QUERIES * self.settings.status_ms / 1000)

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
            return self.streamer.idle and self._seen_idle

    # --- lines --------------------------------------------------------------------

    def beyond_travel(self, text: str) -> Refusal | None:
        """Why a console line would move the machine past its travel (:class:`ConsoleGate`)."""
        return self.console.beyond_travel(text)

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
            refusal = self.beyond_travel(line)
            if refusal is not None:
                self.model.message.emit(f"Not sent without confirmation: {refusal}")
                return False
        try:
            raw = encode_line(line)
        except ValueError as exc:
            self.model.message.emit(f"Not sent: {line!r} ({exc})")
            return False
        if not self.link.is_open:
            self.model.message.emit(f"Not sent: {line!r} (not connected)")
            return False
        # One hold from the serial to the notes: a job's line pulled on the reader thread
        # meanwhile goes wholly before or after this one (see app.machines.gcode.job_feed).
        with self.feeder.lock:
            sent = SentLine(self.next_serial(), line, origin, op_index)
            try:
                self.streamer.queue(raw, sent)
            except ValueError as exc:
                problem: ValueError | None = exc
            else:
                problem = None
                self.note_queued(line, origin)
        if problem is not None:
            self.model.message.emit(f"Not sent: {line!r} ({problem})")
            return False
        self.pump()
        return True

    def next_serial(self) -> int:
        """The next line's serial (under the feeder's lock: both threads number lines)."""
        return next(self._serials)

    def note_queued(self, line: str, origin: str) -> None:
        """What a line queued implies (under the feeder's lock: a job's lines are queued on
        the reader thread): the board is busy again, a release for zeroing by hand is over,
        and the distance mode the board will be in is the line's (the console judges in it).
        """
        self._seen_idle = False
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

    @property
    def queued(self) -> int:
        """Lines waiting for room in the device's buffer."""
        return self.streamer.queued

    @property
    def unanswered(self) -> int:
        """Lines sent and not yet answered."""
        return self.streamer.in_flight

    def pump(self) -> None:
        """Write every queued line that fits now (bytes sent while the board restarts are
        lost by the board itself: the feeder waits for its banner)."""
        # Bytes sent while the board restarts are lost by the board itself: the feeder waits.
        self.tell_written(self.feeder.pump())

    def tell_written(self, written: list[tuple[bytes, SentLine]]) -> None:
        for raw, sent in written:
            try:
                self._planned.line(raw.decode("ascii").rstrip(), sent.text, sent.op_index)
            except (ValueError, ArithmeticError):
                # A line this reading cannot place is not followed; the stream goes on.
                _log.exception("the path of %r could not be followed", sent.text)
                self.envelope.release()
            self.frameSent.emit(sent.text, raw)
            self.lineSent.emit(sent)

    def send_realtime(self, byte: bytes, name: str) -> None:
        """A real-time byte (it bypasses the stream), shown in the frame log as ``name``."""
        if self.link.is_open:
            self.link.write(byte)
            self.frameSent.emit(name, byte)

    def query_status(self) -> None:
        self.send_realtime(STATUS_QUERY, "?")
        self._status_asked_at = self.clock.now()

    def request_status(self) -> None:
        """A status report soon: asks now unless a question is already on its way."""
        asked = self._status_asked_at
        if asked is None or self.clock.now() - asked > self.settings.status_ms / 1000:
            self.query_status()

    @property
    def planner_size(self) -> int:
        """Planner blocks the device has, learned from its ``Bf:`` reports (0: unknown)."""
        return self._planner_size

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
            return self._forget_stream(by_device=False)

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
        ``quiet``: the stop ends a jog, no "lines not run" message for it.
        """
        if quiet:
            self._quiet_stop = True
        if not keep_jog:
            self._jog = [0] * self.axis_count
            self.jogger.forget()
            # A job owns the machine (its jog lock): the job says what ran, in its operations;
            # a count of lines here beside it read as a second, different figure.
            self._quiet_stop = self.model.jog_lock_reason is not None
        if not self.link.is_open:
            return
        with self.feeder.lock:  # nothing more is fed from here on
            self._dropped_by_stop = len(self.feeder.discard_queued())
            self.feed_hold()
        self._reset_requested_at = self.clock.now()
        self._stop_unconfirmed = True  # until a report shows the board standing
        self.query_status()

    def motion_stopped(self) -> bool:
        """Still, by the board's reports, and no stop waiting for its hold to complete."""
        return not self.stopping and not self.model.any_moving

    @property
    def stopping(self) -> bool:
        """A stop was asked for and its reset has not gone out yet."""
        return self._reset_requested_at is not None

    def _reset_after_stop(self) -> None:
        self._reset_requested_at = None
        lost = len(self.soft_reset()) + self._dropped_by_stop
        self._dropped_by_stop = 0
        quiet, self._quiet_stop = self._quiet_stop, False
        if lost and not quiet:
            self.model.message.emit(
                QCoreApplication.translate("GcodeSession", "Stopped: {0} line(s) not run").format(
                    lost
                )
            )

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
        requested = self._reset_requested_at
        if requested is not None and now - requested > RESET_AFTER_S and self.silent_since is None:
            self._reset_after_stop()  # no report of a finished hold came: reset anyway
        self.query_status()
        # Time the station itself was not running is nobody's silence (a busy computer).
        self._last_heard = min(now, self._last_heard + self._station_stall(now))
        silent = now - self._last_heard
        self._watch_silence(silent, self.stale_after_s, SILENCE_S)
        if self.device_answered and silent > SILENCE_S:
            # The link status says it ("lost — no reply for 2.2 s"): no second message.
            self._last_heard = now

    # --- a silent board ----------------------------------------------------------------

    def _silence_began(self) -> str:
        """What was under way is forgotten as when the link goes: a job looks at the board
        again before it goes on (the port stays open, so the board may still answer it)."""
        self._heard_again_at = None
        self._report_after_silence = None
        self._restarted_in_silence = False
        # A stop under way is kept: it is carried out once the board is heard again.
        lost = self._forget_jog_and_lines()
        return (
            QCoreApplication.translate("GcodeSession", "; {0} unanswered line(s)").format(len(lost))
            if lost
            else ""
        )

    def _forget_jog_and_lines(self) -> list[SentLine]:
        """A jog under way ends and the unanswered lines are handed back (as not run): the
        board may have lost them, so nothing counts them until it is looked at again."""
        self._jog = [0] * self.axis_count
        self.jogger.forget_cancel()
        self._quiet_stop = False
        self._byte_count.forget()
        with self.feeder.lock:
            return self.feeder.clear()

    def _back_after_silence(self) -> None:
        """A stop asked for before or during the silence is carried out now: its hold may
        have been lost on the way, so it goes again, and the reset follows once it holds."""
        if (self.stopping or self._stop_unconfirmed) and self.link.is_open:
            self.feed_hold()
            self._reset_requested_at = self.clock.now()
            self.query_status()

    def _recovery_verdict(self) -> object:
        """Intact: no banner came, and a status report made once the board's held-back
        replies were through (a report from before a restart would prove nothing) shows no
        alarm."""
        report = self._report_after_silence
        if self._restarted_in_silence:
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
        self._timer.stop()
        if self.stopping and self.link.is_open:
            self._reset_after_stop()

    # --- link events and replies -------------------------------------------------------

    def _forget_stream(self, *, by_device: bool) -> list[SentLine]:
        self.reset_by_device = by_device
        # GRBL forgets its G92 offset on a reset; its next report carries the offset it has.
        self.work_offset = None
        self.envelope.release()  # judged again from where it stands once idle
        self._planned.reset_modes()
        with self.feeder.lock:
            self.console.reset()  # GRBL's power-on and reset mode is G90
            lost = self.feeder.clear()
            self._seen_idle = False
        self._byte_count.forget()
        self.jogger.lines_gone()
        self.reset.emit()
        return lost

    def _on_connected(self) -> None:
        # The decoder is not reset here: the reader thread may already have decoded the
        # board's first words (a banner, a status) before this runs, and a reset now
        # would cut a reply in half.  It starts fresh, and is reset when a link ends.
        with self.feeder.lock:
            self.feeder.clear()
            self.feeder.reset_halt()
            self._seen_idle = False
            self.feeder.reset_sent_at = None
            self.zeroing.released = False
        self._byte_count.forget()
        self._status_asked_at = None
        self._reset_requested_at = None
        self.envelope.release()
        self._planned.reset_modes()
        self._last_heard = self.clock.now()
        self._await_device()
        if self._autotick:
            self._timer.start()
        self.query_status()

    def _on_disconnected(self, reason: object) -> None:
        self._timer.stop()
        self._reset_requested_at = None
        with self.feeder.lock:
            self.feeder.reset_sent_at = None
        lost = self._forget_jog_and_lines()
        with self.feeder.lock:
            # No reader runs until the station opens the link again (after this): a reply
            # cut by the loss is not glued to the next link's first bytes.
            self.decoder.reset()
        for axis in range(self.axis_count):
            self.model.update_axis(axis, moving=False, velocity=0.0)
        if reason is None:
            self.model.set_link_state(LinkState.DISCONNECTED)
        else:
            self.model.set_link_state(LinkState.LOST, str(reason))
            if lost:
                text = QCoreApplication.translate(
                    "GcodeSession", "Link lost: {0}; {1} unanswered line(s)"
                ).format(reason, len(lost))
            else:
                text = QCoreApplication.translate("GcodeSession", "Link lost: {0}").format(reason)
            self.model.message.emit(text)

    def receive_injected(self, data: bytes) -> None:
        """Bytes a developer injects as the device's (developer pane): handled as if read."""
        self._on_received(self.feeder.receive(data))

    def _on_received(self, received: Received[SentLine]) -> None:
        """A read from the device, decoded and matched on the reader thread (the feeder)."""
        if received.failure is not None:
            self._reading_failed(received.failure)
            return
        self._heard_unrecognised(received.data)  # kept until the device answers: whose words?
        advanced = False
        for reply, verdict in received.replies:
            if reply is WROTE:
                self.tell_written(verdict)  # type: ignore[arg-type]
                continue
            if isinstance(reply, Rejected):
                self.frameReceived.emit(reply, reply.raw)
                self.model.message.emit(f"Garbage from the device dropped: {reply.raw!r}")
                continue
            self._last_heard = self.clock.now()
            if self.silent_since is not None and self._heard_again_at is None:
                self._heard_again_at = self._last_heard
            self._device_answered(proof=False)  # after a silence, a status report decides
            self.frameReceived.emit(reply, reply_bytes(reply))
            if verdict is STALE:
                continue  # an answer from before the reset: the line it was for is gone
            if isinstance(verdict, Answer) and verdict.counted:
                self._answered(None, verdict.entry, counted=True)
                advanced = True
                continue
            if advanced:  # the job hears of its answers before whatever came after them
                advanced = False
                self.jobAdvanced.emit()
            if isinstance(reply, Ok | ErrorReply):
                entry = verdict.entry if isinstance(verdict, Answer) else None
                self._answered(reply if isinstance(reply, ErrorReply) else None, entry)
            elif isinstance(reply, StatusReport):
                if isinstance(verdict, ReportSeen):
                    if self._count_broken(reply, verdict.unanswered, verdict.unanswered_bytes):
                        continue
                    self._apply_status(
                        reply, verdict.unanswered, verdict.job, idle_then=verdict.idle
                    )
                else:
                    self._apply_status(reply)
            elif isinstance(reply, AlarmReply):
                self.envelope.release()  # stopped by itself; it may have lost its position
                self.replyText.emit(f"ALARM:{reply.code} ({reply.meaning})")
                self.model.message.emit(
                    QCoreApplication.translate("GcodeSession", "Machine alarm {0}: {1}").format(
                        reply.code, reply.meaning
                    )
                )
                self.tell_written(self.feeder.release())
            elif isinstance(reply, Banner):
                ours = isinstance(verdict, BannerSeen) and verdict.ours
                if self.silent_since is not None and not ours:
                    self._restarted_in_silence = True
                self.replyText.emit(reply.text)
                self.query_status()  # a board that just started: where is it, how big its planner
                if ours:
                    self.pump()  # our reset's banner: what waited for it goes now
                    continue
                lost = self._forget_stream(by_device=True)
                if isinstance(verdict, BannerSeen):
                    lost = verdict.lost + lost  # the feeder forgot them when it read the banner
                if lost:
                    self.model.message.emit(
                        f"The device reset: {len(lost)} unanswered line(s) were not run"
                    )
            elif isinstance(reply, Feedback):
                self.replyText.emit(reply.text)
        self.tell_written(received.written)
        if advanced:
            self.jobAdvanced.emit()

    def _reading_failed(self, failure: Exception) -> None:
        """A bug in matching replies to lines: the count may be wrong, so the machine stops.

        The feeder holds the sending meanwhile; the stop takes back what is queued.
        """
        _log.error("G-code replies could not be read", exc_info=failure)
        self.model.message.emit(f"The device's replies could not be read ({failure}): stopping")
        self.stop_all()
        self.tell_written(self.feeder.release())

    def _answered(
        self,
        error: ErrorReply | None,
        entry: tuple[bytes, SentLine] | None,
        *,
        counted: bool = False,
    ) -> None:
        """The reply to the oldest line, ``entry`` as the feeder matched it.

        ``counted``: a job's line the job has counted already (told by :attr:`jobAdvanced`).
        """
        self._lost_answers.answer_heard()
        if entry is None:
            self.model.message.emit("A reply arrived for no line (ignored)")
            if error is not None:
                self.tell_written(self.feeder.release())
            return
        _, sent = entry
        if self._seen_idle:  # only this thread sets it True: already False, no hold per answer
            with self.feeder.lock:
                self._seen_idle = False
        if sent.origin == "jog":
            self.jogger.answered(error is None)
        if error is None:
            if sent.origin in ("console", "intent"):
                self.replyText.emit(f"ok  ← {sent.text}")
            if not counted:
                self.lineAcknowledged.emit(sent)
                self.pump()
        else:
            self.errors += 1
            self.envelope.release()  # the refused line runs not: the path is not known
            self.replyText.emit(f"error:{error.code} ({error.meaning})  ← {sent.text}")
            if sent.origin != "job":
                self.model.message.emit(
                    f"{sent.text!r} refused: error {error.code}, {error.meaning}"
                    + refusal_hint(sent.text, error.code)
                )
            self.lineFailed.emit(sent, error.code, error.meaning)
            # Seen and handled (a failed job has taken back its queue): sending may go on.
            self.tell_written(self.feeder.release())

    def _check_lost_answers(
        self,
        report: StatusReport,
        planner_empty: bool,
        unanswered: list[SentLine] | None = None,
    ) -> None:
        """An ``ok`` lost on the wire would stall the stream for ever (:class:`LostAnswerWatch`).

        ``unanswered``: the lines unanswered when the report was read (None: now).
        """
        if unanswered is None:
            unanswered = self.streamer.unanswered_tags()
        pausing = any(pauses(sent.text) for sent in unanswered)
        stuck = self._stuck.stuck(report, planner_empty=planner_empty, pausing=pausing)
        if stuck is not None:
            self._lost_answers.forget()
            self.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "The board holds {0} byte(s) of a line whose end never came (lost on the "
                    "way) and waits for it: it stands idle, so it is reset, keeping its "
                    "position, and what it ran is looked at again",
                ).format(stuck)
            )
            self.soft_reset()
            return
        verdict = self._lost_answers.judge(
            report, unanswered, self._planner_size, planner_empty, self.clock.now(), SILENCE_S
        )
        if isinstance(verdict, StreamWaits):
            self.model.message.emit(
                f"{verdict.count} line(s) unanswered while the board stands idle; "
                "waiting for its answer (without Bf: in its reports it cannot show it has them)"
            )
        if not isinstance(verdict, AnswersLost):
            return
        if self._short_of_lines_sent(report):
            # Not their answers but the lines themselves were lost: the board stands
            # short of where they end.  Reset (it stands: its position stays) and let
            # the job look at it and go on from what is proven.
            self.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "{0} line(s) sent never reached the board: it has taken every byte "
                    "it got and stands idle short of where they end; it is reset, "
                    "keeping its position, and what it ran is looked at again",
                ).format(len(verdict.lines))
            )
            self.soft_reset()
            return
        self.model.message.emit(
            f"{len(verdict.lines)} answer(s) from the board were lost on the way; it has "
            "taken and run every line sent, so they count as answered"
        )
        advanced = False
        for sent in verdict.lines:
            with self.feeder.lock:
                tags = self.streamer.unanswered_tags()
                if not tags or tags[0] != sent:
                    break  # answered meanwhile after all
                answer = self.feeder.acknowledge()
            self._answered(None, answer.entry, counted=answer.counted)
            advanced = advanced or answer.counted
        if advanced:
            self.jobAdvanced.emit()
            self.pump()

    def _apply_status(
        self,
        report: StatusReport,
        unanswered: list[SentLine] | None = None,
        job: object = None,
        *,
        idle_then: bool | None = None,
    ) -> None:
        """``unanswered``, ``job`` and ``idle_then``: the lines unanswered, the job's snapshot
        and whether nothing waited to go, as the report was read (on the reader thread;
        None: read now)."""
        self._status_asked_at = None
        self.job_at_report = job
        # A work position without any offset heard yet is no machine position.
        placed = not report.work_reported or report.wco is not None or self.work_offset is not None
        # GRBL sends its work offset (WCO:) only now and then: the last one heard completes
        # the reports between, so both the machine and the work position are always known.
        if report.wco is not None:
            self.work_offset = report.wco
        report = with_work_offset(report, self.work_offset)
        self.status = report
        if placed:
            self._supervise(report)
        if self._reset_requested_at is not None:
            held = report.state == "Hold" and report.substate in (None, "0")
            if held or report.state in ("Idle", "Alarm"):
                self._reset_after_stop()
            else:
                self.request_status()  # still braking: ask again at once
        if report.state == "Idle" and report.planner_free is not None and self.streamer.idle:
            # Free blocks of an idle machine with nothing on its way: the planner's size.
            self._planner_size = report.planner_free
        self.jogger.reported(report)
        moving = reports_moving(report)
        for axis in range(min(self.axis_count, len(report.mpos))):
            self.model.update_axis(
                axis,
                position=report.mpos[axis],
                offset=report.mpos[axis] - report.wpos[axis],
                status_text=report.state.lower(),
                moving=moving,
            )
        # Replies and reports share one ordered stream, so with every line answered this
        # report was made after the last line was planned.  A board that has planned a
        # block but not yet started it still says Idle; its Bf then shows the block.
        planner_empty = (
            report.planner_free is None
            or not self._planner_size
            or report.planner_free >= self._planner_size
        )
        # Idle as it was read too: a report read before the last lines went (a burst of held
        # replies, handled here after the reader thread sent them and counted their answers)
        # says nothing of them.
        with self.feeder.lock:  # nothing queued between the look and the note
            idle = self.streamer.idle and idle_then is not False
            at_rest = report.state == "Idle" and idle and planner_empty
            if at_rest:
                self._seen_idle = True
        if at_rest:
            # A GRBL board's offset is known once a WCO: came (the next lines' targets need it).
            offset_known = self.work_offset is not None or not self.jogger.with_command
            if (
                placed
                and offset_known
                and not self.stopping
                and len(report.mpos) >= self.axis_count
            ):
                # Standing with every line answered: where the next lines start from.
                self._planned.anchor(report.mpos, report.wco or ())
        self._check_lost_answers(report, planner_empty, unanswered)
        self.statusChanged.emit(report)
        self.jogger.feed()
        if (
            self._stop_unconfirmed
            and self.silent_since is None
            and not self.stopping
            and report.state in ("Idle", "Alarm")
        ):
            self._stop_unconfirmed = False  # held and reset: it stands
        if self.silent_since is not None:
            heard = self._heard_again_at
            # Replies held back on the way come first: the board's state is judged from a
            # report made a few queries after it was heard again.
            if heard is not None and self.clock.now() - heard >= self.stale_after_s:
                self._report_after_silence = report
            self._check_recovery()

    def _short_of_lines_sent(self, report: StatusReport) -> bool:
        """Whether an idle board stands off where the lines written end (as far as known)."""
        end = self.envelope.end
        if end is None or len(report.mpos) < self.axis_count:
            return False
        here = report.mpos[: self.axis_count]
        return any(abs(a - b) > self.envelope.tolerance for a, b in zip(here, end, strict=False))

    def _count_broken(
        self, report: StatusReport, unanswered: list[SentLine], unanswered_bytes: int | None
    ) -> bool:
        """The board holds more than was sent and not answered: stop before it runs it."""
        extra = self._byte_count.excess(report, unanswered_bytes)
        if extra is None or self.stopping:
            return False
        self._byte_count.forget()  # one stop, one message
        job = next((s.op_index for s in unanswered if s.origin == "job"), None)
        text = QCoreApplication.translate(
            "GcodeSession",
            "The board holds {0} byte(s) more than were sent and not answered (a line or an "
            "answer arrived twice on the way): the lines it holds may be garbled, so it is "
            "stopped before it runs them",
        ).format(extra)
        self._stop_for_fault(MotionFault(text, job))
        return True

    def _supervise(self, report: StatusReport) -> None:
        """A report off the path of the lines written stops the machine, naming the line."""
        if report.state in ("Home", "Alarm") or len(report.mpos) < self.axis_count:
            return
        deviation = self.envelope.check(report.mpos[: self.axis_count])
        if deviation is None:
            return
        self.envelope.release()  # one stop, one message: judged again once it stands
        names = [axis.name for axis in self.model.profile.axes]
        tag = deviation.tag if isinstance(deviation.tag, int) else None
        self._stop_for_fault(MotionFault(fault_text(deviation, names), tag))
