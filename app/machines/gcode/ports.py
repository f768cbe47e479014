"""What the G-code session's parts see of it and of each other (typing only).

The session composes a stop sequence, a status follower, a reply reader and
the link events (:mod:`~app.machines.gcode.session`); each holds the session
and reaches the others through it.  Typed against these protocols rather than
the session class, the parts import no module that imports them, so the
package stays free of import cycles (an import contract checks it).  The
attributes marked *shared* are written by more than one part; what the reader
thread also writes is written under ``feeder.lock`` (see
:mod:`app.machines.gcode.job_feed`).
"""

from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QTimer, SignalInstance

from app.link import Link
from app.machine import MachineModel
from app.machines.envelope import Envelope
from app.machines.gcode.alarm_notice import AlarmNotice
from app.machines.gcode.byte_count import ByteCount
from app.machines.gcode.console_gate import ConsoleGate
from app.machines.gcode.feeder import LineFeeder, Received, ReportSeen
from app.machines.gcode.hand_zeroing import HandZeroing
from app.machines.gcode.jogger import GcodeJogger
from app.machines.gcode.lines import SentLine
from app.machines.gcode.lost_answers import LostAnswerWatch
from app.machines.gcode.pen_watch import PenWatch
from app.machines.gcode.planned_path import PlannedPath
from app.machines.supervision import MotionFault
from app.profiles import GcodeSettings
from protocol.clock import Clock
from protocol.framing import LineDecoder
from protocol.gcode.codec import ErrorReply, GcodeReply, StatusReport
from protocol.gcode.streaming import LineStreamer


class LimitLockPort(Protocol):
    """GRBL's lock after a limit (:class:`~app.machines.gcode.limit_lock.LimitLock`)."""

    waiting: bool

    def heard(self, reply: object) -> None: ...


class StopsPort(Protocol):
    """The stop under way (:class:`~app.machines.gcode.stop_sequence.StopSequence`)."""

    quiet: bool
    requested_at: float | None

    def reported(self, report: StatusReport) -> None: ...
    def confirm(self, report: StatusReport) -> None: ...


class FollowerPort(Protocol):
    """The reports against the lines written
    (:class:`~app.machines.gcode.status_follower.StatusFollower`)."""

    planned: PlannedPath
    byte_count: ByteCount
    lost_answers: LostAnswerWatch
    pen: PenWatch

    def written(self, written: list[tuple[bytes, SentLine]]) -> None: ...
    def apply(
        self,
        report: StatusReport,
        unanswered: list[SentLine] | None = None,
        job: object = None,
        *,
        idle_then: bool | None = None,
    ) -> None: ...
    def count_broken(
        self, report: StatusReport, unanswered: list[SentLine], unanswered_bytes: int | None
    ) -> bool: ...
    def bytes_lost(self, report: StatusReport, seen: ReportSeen[SentLine]) -> bool: ...


class RepliesPort(Protocol):
    """The board's replies (:class:`~app.machines.gcode.reply_reader.ReplyReader`)."""

    def on_received(self, received: Received[SentLine]) -> None: ...
    def answered(
        self,
        error: ErrorReply | None,
        entry: tuple[bytes, SentLine] | None,
        *,
        counted: bool = False,
    ) -> None: ...


class LinksPort(Protocol):
    """What a reset or a lost link forgets (:class:`~app.machines.gcode.link_events.
    LinkEvents`)."""

    def forget_stream(self, *, by_device: bool) -> list[SentLine]: ...
    def forget_jog_and_lines(self) -> list[SentLine]: ...


class SessionParts(Protocol):
    """The session's parts, and what it was made with and holds for good."""

    @property
    def stops(self) -> StopsPort: ...
    @property
    def follower(self) -> FollowerPort: ...
    @property
    def replies(self) -> RepliesPort: ...
    @property
    def links(self) -> LinksPort: ...
    @property
    def jogger(self) -> GcodeJogger: ...
    @property
    def console(self) -> ConsoleGate: ...
    @property
    def zeroing(self) -> HandZeroing: ...
    @property
    def limit_lock(self) -> LimitLockPort: ...

    @property
    def model(self) -> MachineModel: ...
    @property
    def link(self) -> Link: ...
    @property
    def clock(self) -> Clock: ...
    @property
    def settings(self) -> GcodeSettings: ...
    @property
    def feeder(self) -> LineFeeder[SentLine]: ...
    @property
    def streamer(self) -> LineStreamer[SentLine]: ...
    @property
    def decoder(self) -> LineDecoder[GcodeReply]: ...
    @property
    def envelope(self) -> Envelope: ...
    @property
    def timer(self) -> QTimer: ...
    @property
    def axis_count(self) -> int: ...
    @property
    def autotick(self) -> bool: ...
    @property
    def stale_after_s(self) -> float: ...


class SessionSignals(Protocol):
    """What the session tells the station, the runner and the developer pane."""

    @property
    def frameSent(self) -> SignalInstance: ...
    @property
    def frameReceived(self) -> SignalInstance: ...
    @property
    def lineSent(self) -> SignalInstance: ...
    @property
    def linesSent(self) -> SignalInstance: ...
    @property
    def lineAcknowledged(self) -> SignalInstance: ...
    @property
    def lineFailed(self) -> SignalInstance: ...
    @property
    def jobAdvanced(self) -> SignalInstance: ...
    @property
    def statusChanged(self) -> SignalInstance: ...
    @property
    def replyText(self) -> SignalInstance: ...
    @property
    def reset(self) -> SignalInstance: ...
    @property
    def alarmed(self) -> SignalInstance: ...


class GcodeCore(SessionParts, SessionSignals, Protocol):
    """The G-code session as its parts use it: its shared state and its operations."""

    status: StatusReport | None
    work_offset: tuple[float, ...] | None
    job_at_report: object
    status_asked_at: float | None
    seen_idle: bool
    last_heard: float
    heard_again_at: float | None
    report_after_silence: StatusReport | None
    restarted_in_silence: bool
    reset_by_device: bool
    errors: int
    alarm: AlarmNotice

    @property
    def silent_since(self) -> float | None: ...
    @property
    def stopping(self) -> bool: ...

    def query_status(self) -> None: ...
    def feed_hold(self) -> None: ...
    def soft_reset(self) -> list[SentLine]: ...
    def send_line(
        self,
        text: str,
        origin: str = "console",
        op_index: int | None = None,
        *,
        confirmed: bool = False,
    ) -> bool: ...
    def pump(self) -> None: ...
    def stop_all(self, *, keep_jog: bool = False, quiet: bool = False) -> None: ...
    def forget_jog(self) -> None: ...
    def stop_for_fault(self, fault: MotionFault) -> None: ...
    def check_recovery(self) -> None: ...
    def device_replied(self, *, proof: bool = True) -> None: ...
    def heard_unrecognised(self, raw: bytes) -> None: ...
    def await_device(self) -> None: ...
