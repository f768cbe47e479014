"""What the G-code board says, as the session hears it: answers, reports, alarms, banners.

The feeder decodes and matches every read on the transport's reader thread
(:mod:`app.machines.gcode.feeder`); this reader takes its verdicts on the GUI
thread, in the order read, and tells the session's parts: an answer to its
line (and the job, once per batch of counted answers), a status report to the
:class:`~app.machines.gcode.status_follower.StatusFollower`, a banner nobody
asked for as the board's own reset.  The session composes it.
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from app.listened import listened
from app.machines.gcode.console_gate import refusal_hint
from app.machines.gcode.feeder import STALE, WROTE, Answer, BannerSeen, Received, ReportSeen
from app.machines.gcode.lines import SentLine
from app.machines.gcode.meanings import alarm_meaning, error_meaning
from protocol.gcode.codec import (
    AlarmReply,
    Banner,
    ErrorReply,
    Feedback,
    Ok,
    Rejected,
    StatusReport,
)

if TYPE_CHECKING:
    from app.machines.gcode.ports import GcodeCore

_log = logging.getLogger(__name__)


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


class ReplyReader:
    """The replies of one G-code session's board (GUI thread)."""

    def __init__(self, session: GcodeCore) -> None:
        self._session = session

    def on_received(self, received: Received[SentLine]) -> None:
        """A read from the device, decoded and matched on the reader thread (the feeder)."""
        session = self._session
        if received.failure is not None:
            self.reading_failed(received.failure)
            return
        session.heard_unrecognised(received.data)  # kept until the device answers: whose words?
        advanced = False
        # Asked once a batch: with nothing connected (no frame log) no emit per reply.
        frames = listened(session, "frameReceived")
        # The job's answers one behind the other (most of a batch): the first one did
        # everything but the frame for all of them (heard now, the link up, an answer heard).
        streak = False
        for reply, verdict in received.replies:
            if streak and isinstance(verdict, Answer) and verdict.counted:
                self._streak_answer(reply, verdict, frames=frames)
                continue
            streak = False
            if reply is WROTE:
                session.follower.written(verdict)  # type: ignore[arg-type]
                continue
            if isinstance(reply, Rejected):
                session.frameReceived.emit(reply, reply.raw)
                session.model.message.emit(
                    QCoreApplication.translate(
                        "GcodeSession", "Garbage from the device dropped: {0}"
                    ).format(repr(reply.raw))
                )
                continue
            session.last_heard = session.clock.now()
            if session.silent_since is not None and session.heard_again_at is None:
                session.heard_again_at = session.last_heard
            session.device_replied(proof=False)  # after a silence, a status report decides
            session.limit_lock.heard(reply)
            if frames:
                session.frameReceived.emit(reply, reply_bytes(reply))
            if verdict is STALE:
                continue  # an answer from before the reset: the line it was for is gone
            if isinstance(verdict, Answer) and verdict.counted:
                self.answered(None, verdict.entry, counted=True)
                advanced = streak = True
                continue
            if advanced:  # the job hears of its answers before whatever came after them
                advanced = False
                session.jobAdvanced.emit()
            if isinstance(reply, Ok | ErrorReply):
                entry = verdict.entry if isinstance(verdict, Answer) else None
                self.answered(reply if isinstance(reply, ErrorReply) else None, entry)
            elif isinstance(reply, StatusReport):
                if isinstance(verdict, ReportSeen):
                    if session.follower.count_broken(
                        reply, verdict.unanswered, verdict.unanswered_bytes
                    ) or session.follower.bytes_lost(reply, verdict):
                        continue
                    session.follower.apply(
                        reply, verdict.unanswered, verdict.job, idle_then=verdict.idle
                    )
                else:
                    session.follower.apply(reply)
            elif isinstance(reply, AlarmReply):
                session.envelope.release()  # stopped by itself; it may have lost its position
                session.follower.pen.alarmed()  # and its spindle (the pen) stopped
                session.replyText.emit(f"ALARM:{reply.code} ({alarm_meaning(reply.code)})")
                if session.alarm.heard(reply.code):  # once while it stays in that alarm
                    session.model.message.emit(
                        QCoreApplication.translate("GcodeSession", "Machine alarm {0}: {1}").format(
                            reply.code, alarm_meaning(reply.code)
                        )
                    )
                    session.alarmed.emit(reply.code)  # before sending may go on
                session.follower.written(session.feeder.release())
            elif isinstance(reply, Banner):
                ours = isinstance(verdict, BannerSeen) and verdict.ours
                if session.silent_since is not None and not ours:
                    session.restarted_in_silence = True
                session.replyText.emit(reply.text)
                session.query_status()  # a board just started: where is it, how big its planner
                if ours:
                    session.follower.pen.restarted(reply.text)
                    session.pump()  # our reset's banner: what waited for it goes now
                    continue
                lost = session.links.forget_stream(by_device=True)
                session.follower.pen.restarted(reply.text)
                if isinstance(verdict, BannerSeen):
                    lost = verdict.lost + lost  # the feeder forgot them when it read the banner
                if lost:
                    session.model.message.emit(
                        QCoreApplication.translate(
                            "GcodeSession", "The device reset: {0} unanswered line(s) were not run"
                        ).format(len(lost))
                    )
            elif isinstance(reply, Feedback):
                session.replyText.emit(reply.text)
        session.follower.written(received.written)
        if advanced:
            session.jobAdvanced.emit()

    def reading_failed(self, failure: Exception) -> None:
        """A bug in matching replies to lines: the count may be wrong, so the machine stops.

        The feeder holds the sending meanwhile; the stop takes back what is queued.
        """
        session = self._session
        _log.error("G-code replies could not be read", exc_info=failure)
        session.model.message.emit(
            QCoreApplication.translate(
                "GcodeSession", "The device's replies could not be read ({0}): stopping"
            ).format(failure)
        )
        session.stop_all()
        session.follower.written(session.feeder.release())

    def _streak_answer(self, reply: object, verdict: Answer[SentLine], *, frames: bool) -> None:
        """One of the job's answers after the first of a streak: the pen watch and the frame."""
        session = self._session
        if verdict.entry is not None:  # a pen line among them is proven run now
            session.follower.pen.answered(verdict.entry[1], True)
        if frames:
            session.frameReceived.emit(reply, reply_bytes(reply))

    def answered(
        self,
        error: ErrorReply | None,
        entry: tuple[bytes, SentLine] | None,
        *,
        counted: bool = False,
    ) -> None:
        """The reply to the oldest line, ``entry`` as the feeder matched it.

        ``counted``: a job's line the job has counted already (told by :attr:`jobAdvanced`).
        """
        session = self._session
        session.follower.lost_answers.answer_heard()
        if entry is None:
            session.model.message.emit(
                QCoreApplication.translate("GcodeSession", "A reply arrived for no line (ignored)")
            )
            if error is not None:
                session.follower.written(session.feeder.release())
            return
        _, sent = entry
        session.follower.pen.answered(sent, error is None)
        if session.seen_idle:  # only this thread sets it True: already False, no hold per answer
            with session.feeder.lock:
                session.seen_idle = False
        if sent.origin == "jog":
            session.jogger.answered(error is None)
        if error is None:
            if sent.origin in ("console", "intent"):
                session.replyText.emit(f"ok  ← {sent.text}")
            if not counted:
                session.lineAcknowledged.emit(sent)
                session.pump()
        else:
            session.errors += 1
            session.envelope.release()  # the refused line runs not: the path is not known
            meaning = error_meaning(error.code)
            session.replyText.emit(f"error:{error.code} ({meaning})  ← {sent.text}")
            if sent.origin != "job":
                session.model.message.emit(
                    QCoreApplication.translate(
                        "GcodeSession", "{0} refused: error {1}, {2}"
                    ).format(repr(sent.text), error.code, meaning)
                    + refusal_hint(sent.text, error.code)
                )
            session.lineFailed.emit(sent, error.code, meaning)
            # Seen and handled (a failed job has taken back its queue): sending may go on.
            session.follower.written(session.feeder.release())
